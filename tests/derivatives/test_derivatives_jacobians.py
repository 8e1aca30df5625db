# The generated Jacobians against central differences of the generated functions themselves,
# structural identities, and bad input.
"""Checks of :mod:`pm2dof.core.derivatives` on every shipped model.

Finite differences: central, f'(z) ~ (f(z + h) - f(z - h)) / 2h. Its error is the truncation
h^2 f'''/6 plus the rounding eps |f| / h. The dynamics vary on the scale of the links
(L ~ 0.1 m, 0.2 m/s, 1 N m), |f| <= ~1e2, so with h = 1e-6 of each variable's scale the
truncation is ~1e-12 |f| / L^2 ~ 1e-10 |f| and the rounding ~2e-16 * 1e2 / 1e-6 = 2e-8:
both below 1e-7 relative to the block's largest entry. The tolerance, 1e-6 of the block's
largest entry, leaves a factor of 10 over that bound; a wrong entry (a missed chain-rule
term, a transposed block) is off by O(1). Joint velocities stay >= 0.05 rad/s, far from the
sign(v) jump of eq. 2 (an h of 1e-6 moves them by ~1e-5 rad/s).
"""
import numpy as np
import pytest

import pm2dof

H_REL = 1e-6        # the step, relative to each variable's scale
TOL = 1e-6          # of the block's largest entry (see the module docstring)
SCALE = {"xe": 0.1, "xed": 0.2, "tau_a": 1.0, "theta": None, "x": None}
N_STATES = 4


def scales(model, task_scale, key):
    """(m,) each task coordinate's scale of ``key`` ("xe" or "xed"): SCALE[key] for x, y;
    phi as conftest.PHI_PER_M says (0.3 rad, 0.6 rad/s: smaller than the ~1 rad phi varies on,
    so the truncation bound above holds, and a larger step than x's, so the rounding one)."""
    return task_scale(model, SCALE[key])


def states(model, sample_xe, random_theta, task_scale, seed):
    """(xe, xed, tau_a, theta) at admissible poses, every |S xed|_i >= 0.05 (rad/s, or m/s for
    a prismatic actuator); xed is a random unit direction of R^m times 0.5-2 task scales."""
    rng = np.random.default_rng(seed)
    out = []
    for xe in sample_xe(model, seed, 20 * N_STATES):
        q = model.ik(xe)
        S = model.S(q)
        u = rng.normal(size=model.dof)
        xed = rng.uniform(0.5, 2.0) * scales(model, task_scale, "xed") * u / np.linalg.norm(u)
        if np.min(np.abs(S @ xed)) < 0.05:
            continue
        out.append((xe, xed, rng.uniform(-3, 3, model.n_legs), random_theta(model, rng)))
        if len(out) == N_STATES:
            return out
    raise AssertionError(f"{model.name}: too few states with |S xed| >= 0.05 rad/s")


def central(f, z, h):
    """d f / d z (m, k) by central differences with steps h (k,)."""
    cols = []
    for i in range(len(z)):
        zp, zm = z.copy(), z.copy()
        zp[i] += h[i]
        zm[i] -= h[i]
        cols.append((f(zp) - f(zm)) / (2 * h[i]))
    return np.stack(cols, axis=-1)


def assert_close(name, got, want, info):
    scale = max(float(np.max(np.abs(want))), 1e-300)
    err = float(np.max(np.abs(got - want)))
    assert err <= TOL * scale, (f"{name}: AD vs central difference: max error {err:.3e} > "
                                f"{TOL:g} * {scale:.3e} at {info}\nAD=\n{got}\nFD=\n{want}")


def test_forward_dynamics_jacobians_match_central_differences(model, sample_xe, random_theta,
                                                              task_scale):
    n = model.n_legs
    for xe, xed, tau, theta in states(model, sample_xe, random_theta, task_scale, 21):
        info = f"{model.name}: xe={xe.tolist()}, xed={xed.tolist()}, tau={tau.tolist()}"
        J = model.forward_dynamics_jacobians(xe, xed, tau, theta)
        args = {"xe": xe, "xed": xed, "tau_a": tau, "theta": theta}
        for key, got in zip(("xe", "xed", "tau_a", "theta"), J):
            h = (scales(model, task_scale, key) * H_REL if key in ("xe", "xed")
                 else np.full(len(args[key]), SCALE[key] * H_REL) if SCALE[key]
                 else H_REL * np.maximum(np.abs(theta), 1e-3))

            def f(v, key=key):
                return model.forward_dynamics(**{**args, key: v})
            assert_close(f"d xedd / d {key}", got, central(f, args[key].copy(), h), info)
        m = model.dof
        assert J.d_tau_a.shape == (m, n) and J.d_theta.shape == (m, len(theta))


def test_d_xedd_d_tau_is_Me_inverse_S_transpose(model, sample_xe, random_theta, task_scale):
    """Structural: xedd is affine in tau_a with slope Me^-1 S^T (eq. 10)."""
    for xe, xed, tau, theta in states(model, sample_xe, random_theta, task_scale, 22):
        q = model.ik(xe)
        want = np.linalg.solve(model.Me(q, theta), model.S(q).T)
        got = model.forward_dynamics_jacobians(xe, xed, tau, theta).d_tau_a
        np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12 * np.abs(want).max(),
                                   err_msg=f"{model.name}: xe={xe.tolist()}")


def test_d_xedd_d_theta_is_minus_Me_inverse_Y(model, sample_xe, random_theta, task_scale):
    """Structural: Y(q, xed, xed, xedd) theta = S^T tau_a for every theta (eqs. 10, 13), so
    Y + Me d xedd / d theta = 0."""
    for xe, xed, tau, theta in states(model, sample_xe, random_theta, task_scale, 23):
        q = model.ik(xe)
        xedd = model.forward_dynamics(xe, xed, tau, theta)
        want = -np.linalg.solve(model.Me(q, theta), model.Y(q, xed, xed, xedd))
        got = model.forward_dynamics_jacobians(xe, xed, tau, theta).d_theta
        np.testing.assert_allclose(got, want, rtol=1e-9, atol=1e-10 * np.abs(want).max(),
                                   err_msg=f"{model.name}: xe={xe.tolist()}")


def test_inverse_dynamics_inverts_forward_dynamics_and_its_jacobians(model, sample_xe,
                                                                      random_theta, task_scale):
    for xe, xed, tau, theta in states(model, sample_xe, random_theta, task_scale, 24):
        info = f"{model.name}: xe={xe.tolist()}, xed={xed.tolist()}"
        q = model.ik(xe)
        xedd = model.forward_dynamics(xe, xed, tau, theta)
        u = model.inverse_dynamics(xe, xed, xedd, theta)
        want_u = model.S(q).T @ tau
        np.testing.assert_allclose(u, want_u, rtol=1e-10, atol=1e-10 * np.abs(want_u).max(),
                                   err_msg=info)
        J = model.inverse_dynamics_jacobians(xe, xed, xedd, theta)
        for key, got in zip(("xe", "xed"), J):
            args = {"xe": xe, "xed": xed, "xedd": xedd, "theta": theta}

            def f(v, key=key):
                return model.inverse_dynamics(**{**args, key: v})
            h = scales(model, task_scale, key) * H_REL
            assert_close(f"d u / d {key}", got, central(f, args[key].copy(), h), info)


def test_sampled_step_and_its_jacobians(model, sample_xe, random_theta, task_scale, rk4_numpy):
    """x_next against RK4 in NumPy; d_x, d_tau_a (the discrete A, B) against central
    differences of the generated sampled step (steps as above; x_next's entries differ from x
    by O(T), so the same relative tolerance applies)."""
    T = model.spec.sensing["sample_period"]
    for xe, xed, tau, theta in states(model, sample_xe, random_theta, task_scale, 25):
        x = np.concatenate([xe, xed])
        info = f"{model.name}: x={x.tolist()}, tau={tau.tolist()}"
        x_next = model.sampled_step(x, tau, theta)
        np.testing.assert_allclose(x_next, rk4_numpy(model, x, tau, theta, T), rtol=1e-12,
                                   atol=1e-13, err_msg=info)
        J = model.sampled_step_jacobians(x, tau, theta)
        A, B = model.linearize(xe, xed, tau, theta, discrete=True)
        np.testing.assert_array_equal(A, J.d_x)
        np.testing.assert_array_equal(B, J.d_tau_a)
        hx = np.concatenate([scales(model, task_scale, "xe"),
                             scales(model, task_scale, "xed")]) * H_REL
        assert_close("d x_next / d x", J.d_x,
                     central(lambda v: model.sampled_step(v, tau, theta), x.copy(), hx), info)
        assert_close("d x_next / d tau_a", J.d_tau_a,
                     central(lambda v: model.sampled_step(x, v, theta), tau.copy(),
                             np.full(len(tau), H_REL)), info)


def test_continuous_linearisation_is_the_state_space_form(model, sample_xe, random_theta,
                                                          task_scale):
    m = model.dof
    for xe, xed, tau, theta in states(model, sample_xe, random_theta, task_scale, 26):
        J = model.forward_dynamics_jacobians(xe, xed, tau, theta)
        A, B = model.linearize(xe, xed, tau, theta)
        np.testing.assert_array_equal(A[:m], np.hstack([np.zeros((m, m)), np.eye(m)]))
        np.testing.assert_array_equal(A[m:], np.hstack([J.d_xe, J.d_xed]))
        np.testing.assert_array_equal(B, np.vstack([np.zeros((m, model.n_legs)), J.d_tau_a]))
    A0, _ = model.linearize(xe, xed, tau)     # theta defaults to Tables 1-2
    A1, _ = model.linearize(xe, xed, tau, model.theta_nominal)
    np.testing.assert_array_equal(A0, A1)


def test_out_writes_into_the_callers_arrays(model, sample_xe, random_theta, task_scale):
    xe, xed, tau, theta = states(model, sample_xe, random_theta, task_scale, 27)[0]
    J = model.forward_dynamics_jacobians(xe, xed, tau, theta)
    mine = tuple(np.zeros_like(a) for a in J)
    got = model.forward_dynamics_jacobians(xe, xed, tau, theta, out=mine)
    assert all(a is b for a, b in zip(got, mine))
    for a, b in zip(got, J):
        np.testing.assert_array_equal(a, b)
    x = np.concatenate([xe, xed])
    buf = np.empty(2 * model.dof)
    assert model.sampled_step(x, tau, theta, out=buf) is buf
    with pytest.raises(pm2dof.ArgumentError, match="out must be a tuple of 4"):
        model.forward_dynamics_jacobians(xe, xed, tau, theta,
                                         out=(np.empty((model.dof, model.dof)),) * 4)
