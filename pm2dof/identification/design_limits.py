# The excitation design's limits at a chosen set of samples, and which samples break them.
"""The constraints of :func:`~pm2dof.identification.design.design_excitation`, in two kinds:

* the **kinematic** limits, on the Fourier series itself: (x, y) speed^2, acceleration^2 and
  radius^2, and a platform's phid, phidd and phi - phi_c. Each is a trigonometric polynomial in
  t of degree L (phi's) or 2 L (the squares), so its values at M equispaced samples per period
  bound it everywhere (Ehlich & Zeller 1964: |p(t)| <= max_k |p(t_k)| / cos(pi d / M) for degree
  d < M / 2). :func:`kinematic_samples` picks M so that the ``safety`` fraction imposed at the
  samples covers that factor: the limits then hold at every instant, not only at the samples.
  These rows are at the same M samples in every solve.
* the **model** limits, through the model's ik, S and Y: each leg's torque and both
  singularity measures, at ``constraint_samples`` instants per period (K). They are no
  polynomials, so they are checked at all K samples: IPOPT first sees a subset (every
  ``stride``-th sample); :func:`sample_violations` then evaluates them at all K samples, and
  the samples outside the subset that do worse than the worst IPOPT saw are added and IPOPT
  solves again from there. A solution that no sample breaks more than the subset's samples is
  a KKT point of the problem on all K samples (the multipliers of the constraints it did not
  see are zero): the same problem, solved with fewer rows.

IPOPT's cost per iteration grows with the rows it sees (each a dense row in the coefficients).

Constraint layout: the kinematic rows at the M samples t_kin (speed^2 (M), acceleration^2 (M),
radius^2 (M) of (x, y); a platform's phid, phidd, phi - phi_c (M each)); then the model rows at
the samples t (k = 0..N-1): the torque of every leg (n N, sample after sample), both
singularity measures (2 N, sample after sample).
"""
import math
from dataclasses import dataclass

import numpy as np

from .sampled import fourier_basis, sampled_outputs

__all__ = ["Limits", "kinematic_constraints", "kinematic_samples", "model_constraints",
           "rest_constraints", "sample_violations", "sample_slack", "carry_multipliers"]


@dataclass(frozen=True)
class Limits:
    """The design's limits as imposed at the samples (already with ``safety``).

    Attributes
    ----------
    v_max, a_max, radius : float
        (x, y) speed (m/s), acceleration (m/s^2), distance from ``center`` (m).
    tau : ndarray (n,)
        |tau_i| bound, N m or N.
    sing_min : ndarray (2,)
        Lower bounds of both singularity measures.
    center : ndarray (m,)
        c0, the region's centre (m, rad).
    phi : dict
        A platform's ``phi_v_max``, ``phi_a_max``, ``phi_range`` (rad/s, rad/s^2, rad); empty
        for a point.
    """
    v_max: float
    a_max: float
    radius: float
    tau: np.ndarray
    sing_min: np.ndarray
    center: np.ndarray
    phi: dict


def _rows_per_sample(n):
    """Model rows per sample, by block: torque (n), singularity measures (2)."""
    return [n, 2]


def kinematic_samples(K, L, safety):
    """M, the kinematic limits' samples per period: the fewest that bound them everywhere, a
    squared limit (degree 2 L) imposed at ``safety``^2 of its bound at M equispaced samples
    holding at every instant when cos(2 pi L / M) >= safety^2 (module docstring; a phi limit,
    degree L at ``safety``, then holds too): 223 for L = 10 and safety 0.98. Each sample is
    6 dense rows for IPOPT (3 for a point), so no more than that. At most K: with a margin too
    small for K samples (``safety`` 1: none), the limits at the K constraint samples.

    Parameters
    ----------
    K : int
        Constraint samples per period.
    L : int
        Harmonics of the series.
    safety : float
        In (0, 1].
    """
    if safety >= 1:
        return int(K)
    need = math.floor(2 * math.pi * L / math.acos(safety ** 2)) + 1
    return int(min(need, K))


def rest_constraints(z, m, L, base_hz):
    """(g, lbg, ubg): the 2 m equalities sum_l a_jl = 0 and sum_l w_l b_jl = 0 (rest at t =
    0), g an MX of the coefficients z."""
    import casadi as ca
    A = ca.reshape(z[:m * L], L, m)
    B = ca.reshape(z[m * L:2 * m * L], L, m)
    w = 2 * np.pi * base_hz * np.arange(1, L + 1)
    return (ca.vertcat(ca.vec(ca.sum1(A)), ca.mtimes(B.T, ca.DM(w))), np.zeros(2 * m),
            np.zeros(2 * m))


def kinematic_constraints(z, limits, *, base_hz, L, m, t):
    """(g, lbg, ubg): the kinematic limits at times ``t`` (M,) s (module docstring's layout),
    g an MX of the coefficients z."""
    import casadi as ca
    N = len(t)
    A = ca.reshape(z[:m * L], L, m)
    B = ca.reshape(z[m * L:2 * m * L], L, m)
    c = z[2 * m * L:]
    Pa, Pb, Va, Vb, Aa, Ab = (ca.DM(M) for M in fourier_basis(base_hz, L, t))
    X = ca.mtimes(Pa, A) + ca.mtimes(Pb, B) + ca.repmat(c.T, N, 1)
    V, Acc = ca.mtimes(Va, A) + ca.mtimes(Vb, B), ca.mtimes(Aa, A) + ca.mtimes(Ab, B)
    lim = limits
    g = [ca.sum2(V[:, :2] ** 2), ca.sum2(Acc[:, :2] ** 2),
         ca.sum2((X[:, :2] - ca.repmat(ca.DM(lim.center[:2]).T, N, 1)) ** 2)]
    lbg = [np.zeros(N), np.zeros(N), np.zeros(N)]
    ubg = [np.full(N, lim.v_max ** 2), np.full(N, lim.a_max ** 2), np.full(N, lim.radius ** 2)]
    if lim.phi:                     # a platform's phi: its own bounds, linear in z
        g += [V[:, 2], Acc[:, 2], X[:, 2] - lim.center[2]]
        for key in ("phi_v_max", "phi_a_max", "phi_range"):
            lbg.append(np.full(N, -lim.phi[key]))
            ubg.append(np.full(N, lim.phi[key]))
    return ca.vertcat(*g), np.concatenate(lbg), np.concatenate(ubg)


def model_constraints(z, per_sample, limits, *, base_hz, L, m, t):
    """(g, lbg, ubg): the model limits at times ``t`` (N,) s (module docstring's layout), g an
    MX of the coefficients z: ``per_sample``'s outputs 1 (torque) and 2 (singularity
    measures) with their Jacobian by the chain rule (:func:`.sampled.sampled_outputs`)."""
    N = len(t)
    g = sampled_outputs(per_sample, (1, 2), base_hz, L, m, t)(z)
    lbg = np.concatenate([-np.tile(limits.tau, N), np.tile(limits.sing_min, N)])
    ubg = np.concatenate([np.tile(limits.tau, N), np.full(2 * N, np.inf)])
    return g, lbg, ubg


def _per_sample(rowwise, n, reduce):
    """``reduce`` (np.max or np.min) over each sample's rows of a per-row array in the model
    rows' layout of :func:`model_constraints` (N samples)."""
    rows = _rows_per_sample(n)
    N = len(rowwise) // sum(rows)
    out, start = [], 0
    for r in rows:
        out.append(reduce(rowwise[start:start + r * N].reshape(N, r), axis=1))
        start += r * N
    return reduce(np.column_stack(out), axis=1)


def sample_violations(values, lbg, ubg, n):
    """Each sample's worst violation (N,), >= 0: the largest of lbg - g and g - ubg over its
    rows, for ``values`` of :func:`model_constraints` at N samples (its layout; n legs)."""
    values, lbg, ubg = (np.asarray(a, float).ravel() for a in (values, lbg, ubg))
    over = np.maximum(np.maximum(lbg - values, values - ubg), 0.0)
    return _per_sample(over, n, np.max)


def sample_slack(values, lbg, ubg, n):
    """Each sample's smallest relative slack (N,): over its rows, the distance of g to its
    nearer bound over the width of its bounds (|lbg| for a row without an upper bound);
    negative where a limit is broken. Layout as :func:`sample_violations`."""
    values, lbg, ubg = (np.asarray(a, float).ravel() for a in (values, lbg, ubg))
    width = np.where(np.isfinite(ubg), ubg - lbg, np.abs(lbg))
    slack = np.minimum(values - lbg, ubg - values) / np.maximum(width, 1e-300)
    return _per_sample(slack, n, np.min)


def carry_multipliers(lam, seen, now, n):
    """The multipliers ``lam`` of :func:`model_constraints` at the samples ``seen`` (sorted
    indices), placed at the same samples of the constraints at ``now`` (sorted indices), 0 at
    the samples not in ``seen``; those of samples not in ``now`` are dropped. IPOPT's warm
    start when samples are added and dropped."""
    lam, seen, now = np.asarray(lam, float).ravel(), np.asarray(seen), np.asarray(now)
    common, i_seen, i_now = np.intersect1d(seen, now, return_indices=True)
    out, start_old = [], 0
    for r in _rows_per_sample(n):
        block = np.zeros((len(now), r))
        block[i_now] = lam[start_old:start_old + r * len(seen)].reshape(len(seen), r)[i_seen]
        out.append(block.ravel())
        start_old += r * len(seen)
    return np.concatenate(out)
