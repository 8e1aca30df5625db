# The design's per-sample model outputs over the Fourier coefficients, differentiated by the chain rule.
"""The excitation design's torque and singularity constraints at K samples, as one CasADi
Function of the coefficients z with its Jacobian built by the chain rule.

The motion (x, xd, xdd) at sample k is linear in z (:func:`fourier_basis`), so the Jacobian of
a per-sample output h(x_k, xd_k, xdd_k) is dh/d(x, xd, xdd) (3 m columns) times that constant
map (3 m x len(z)). CasADi's own AD of the mapped graph pushes len(z) directions (42 for a point
at 10 harmonics, 63 for a platform) through every sample; the per-sample Jacobian needs 3 m (6 or
9), exact when the per-sample function is SX (:mod:`.c_graph`). :func:`sampled_outputs` hands
CasADi this Jacobian (``custom_jacobian``), so IPOPT's constraint Jacobian is the same matrix
computed from fewer derivative sweeps.

Coefficient layout (:mod:`.design`): z = [a (m L, axis after axis), b (m L), c (m)], a
harmonic's a, b in m/s (rad/s for phi), c in m (rad).
"""
import numpy as np

__all__ = ["fourier_basis", "motion_matrices", "sampled_outputs"]


def fourier_basis(f0, L, t):
    """(pos_a, pos_b, vel_a, vel_b, acc_a, acc_b), each (N, L), at times t (N,) s of the series
    with base frequency f0 (Hz) and L harmonics: x = pos_a @ a + pos_b @ b + c (m), xd =
    vel_a @ a + vel_b @ b (m/s), xdd = acc_a @ a + acc_b @ b (m/s^2), a, b (L,) m/s."""
    w = 2 * np.pi * f0 * np.arange(1, L + 1)
    t = np.asarray(t, dtype=float)[:, None]
    s, c = np.sin(w * t), np.cos(w * t)
    return s / w, -c / w, c, s, -s * w, c * w


def motion_matrices(f0, L, m, t):
    """The constant maps z -> (x_j, xd_j, xdd_j) at times t (K,), j = 0..m-1: a list of 3 m
    arrays (K, 2 m L + m), in the order x_0..x_{m-1}, xd_0.., xdd_0.. (the inputs of the
    per-sample function, stacked)."""
    Pa, Pb, Va, Vb, Aa, Ab = fourier_basis(f0, L, t)
    K, n_z = len(Pa), 2 * m * L + m
    out = []
    for ma, mb, with_c in ((Pa, Pb, True), (Va, Vb, False), (Aa, Ab, False)):
        for j in range(m):
            d = np.zeros((K, n_z))
            d[:, j * L:(j + 1) * L] = ma
            d[:, m * L + j * L:m * L + (j + 1) * L] = mb
            if with_c:
                d[:, 2 * m * L + j] = 1.0
            out.append(d)
    return out


def sampled_outputs(per_sample, outputs, f0, L, m, t, name="sampled"):
    """A CasADi Function z (2 m L + m) -> h: the outputs ``outputs`` (indices into
    ``per_sample``'s) of ``per_sample`` (x, xd, xdd) (each (m,)) at the K times ``t``, each
    output ``vec``-ed over the samples (sample after sample) and stacked in the order given;
    with its Jacobian by the chain rule (module docstring).

    Parameters
    ----------
    per_sample : casadi.Function
        (x, xd, xdd) -> column-vector outputs.
    outputs : sequence of int
    f0 : float
        Base frequency, Hz. L : int, harmonics. m : int, task dimension.
    t : array (K,)
        Sample times, s.
    """
    import casadi as ca
    z = ca.MX.sym("z", 2 * m * L + m)
    t = np.asarray(t, float)
    K = len(t)
    D = motion_matrices(f0, L, m, t)
    W = [ca.mtimes(ca.DM(d), z) for d in D]                  # each (K,): x_j, xd_j, xdd_j
    args = [ca.horzcat(*W[i * m:(i + 1) * m]).T for i in range(3)]   # (m, K) each
    sym = ca.SX.sym if per_sample.is_a("SXFunction") else ca.MX.sym
    x, v, a = (sym(s, m) for s in ("x", "v", "a"))
    h1 = ca.vertcat(*[per_sample(x, v, a)[i] for i in outputs])
    w = ca.vertcat(x, v, a)
    # SX: one reverse sweep per output row (measured: 20 % fewer operations than CasADi's
    # choice for a platform's 5 rows x 9 inputs); MX (finite differences): CasADi's choice
    jac1 = ca.Function("jac1", [x, v, a], [
        ca.vertcat(*[ca.gradient(h1[i], w).T for i in range(h1.numel())])
        if sym is ca.SX.sym else ca.jacobian(h1, w)])
    val1 = ca.Function("val1", [x, v, a], [h1])
    sizes = [per_sample.size1_out(i) for i in outputs]
    H = val1.map(K)(*args)                                   # (sum sizes, K)
    rows, start = [], 0
    for s in sizes:                                          # each output vec-ed over samples
        rows.append(ca.vec(H[start:start + s, :]))
        start += s
    h = ca.vertcat(*rows)
    J = jac1.map(K)(*args)                                   # (sum sizes, 3 m K)
    # J holds sample k's (s x 3m) Jacobian in its columns k 3m .. k 3m + 3m - 1; read as a
    # block-diagonal (s K x 3m K) matrix (the same nonzeros in the same order) and multiplied
    # by the stacked maps (3m K x len(z)), row k s + i is sample k's output i: the vec order
    stacked = ca.DM(np.stack(D, axis=1).reshape(K * 3 * m, -1))    # row k 3m + j = D_j[k]
    blocks, start = [], 0
    for s in sizes:
        Jk = ca.densify(J[start:start + s, :])
        block_diag = ca.sparsity_cast(Jk, ca.diagcat(*[ca.Sparsity.dense(s, 3 * m)] * K))
        blocks.append(ca.mtimes(block_diag, stacked))
        start += s
    out_name = "h"
    jac = ca.Function(f"jac_{name}", [z, ca.MX.sym("out_h", h.sparsity())],
                      [ca.vertcat(*blocks)], ["z", f"out_{out_name}"],
                      [f"jac_{out_name}_z"])
    return ca.Function(name, [z], [h], ["z"], [out_name],
                       {"custom_jacobian": jac, "jac_penalty": 0})
