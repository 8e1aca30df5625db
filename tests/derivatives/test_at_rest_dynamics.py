# Issue 25: the model's dynamics at rest (eq. 2 with sign(0) = 0) and their linearisation there.
"""The model at rest, on every model file.

* ``forward_dynamics(xe, 0, tau, theta)`` = Me^-1 S^T tau (Me, S from the model functions):
  no friction at zero velocity, so with tau = 0 it is exactly zero. (With sign(0) = +1 the
  paper's robot got xedd = (0.345, -0.446) m/s^2.)
* ``linearize`` at rest against differences taken symmetrically about the state:
  - the pose and torque columns of (A, B), continuous, and the pose columns of the discrete
    (A, B) equal central differences of ``forward_dynamics`` / ``sampled_step``;
  - at zero torque every pose at rest is an equilibrium of this planar (gravity-free) model,
    so d xedd / d xe = 0 and the discrete step's d x_next / d xe = [I; 0] (with sign(0) = +1
    the pose derivative of -Me^-1 S^T fc was there instead);
  - the state is the midpoint of its symmetric neighbours in every direction, velocities
    included: (f(x + h d) + f(x - h d)) / 2 = f(x) + O(h^2). With sign(0) = +1 the Coulomb
    jump put f(x) at one side of it, off by Me^-1 S^T fc.
  - velocity columns (and the discrete B, whose RK4 stages leave v = 0 with the torque's
    sign): a central difference across v = 0 of a Coulomb law sees its jump (2 fc / 2h),
    which no Jacobian has; the Jacobian is that of the smooth part (the sign's derivative
    is 0), so it equals central differences with the Coulomb (and Stribeck) parameters set
    to zero. The smooth-sign model has no jump: its columns are compared with central
    differences as they are.
"""
import numpy as np
import pytest

COULOMB = ("fc", "fs")          # the parameters of the sign term of eq. 2 and its extension


def _smooth_part(model, theta):
    """theta with the sign term's parameters zeroed (the law's smooth part), unless the law
    has no jump (smooth_sign)."""
    if model.spec.friction == "smooth_sign":
        return theta
    th = np.array(theta, dtype=float)
    for j, name in enumerate(model.param_names):
        if name.rstrip("0123456789") in COULOMB:
            th[j] = 0.0
    return th


def _poses(model, sample_xe):
    return sample_xe(model, 77, 4)


def test_forward_dynamics_at_rest_has_no_friction(model, sample_xe, random_theta):
    rng = np.random.default_rng(7)
    n = model.n_legs
    for xe in _poses(model, sample_xe):
        theta = random_theta(model, rng)
        q = model.ik(xe)
        acc = model.forward_dynamics(xe, np.zeros(2), np.zeros(n), theta)
        assert np.all(acc == 0.0), f"{model.name} at {xe.tolist()}: xedd = {acc}"
        tau = rng.uniform(-1.0, 1.0, n)
        expected = np.linalg.solve(model.Me(q, theta), model.S(q).T @ tau)   # eq. 10 at rest
        np.testing.assert_allclose(model.forward_dynamics(xe, np.zeros(2), tau, theta),
                                   expected, rtol=1e-10, atol=1e-12 * np.abs(expected).max(),
                                   err_msg=f"{model.name} at {xe.tolist()}")


def _central(f, x0, h):
    """Columns (f(x0 + h e_j) - f(x0 - h e_j)) / 2h."""
    cols = []
    for j in range(len(x0)):
        d = np.zeros(len(x0))
        d[j] = h
        cols.append((f(x0 + d) - f(x0 - d)) / (2 * h))
    return np.array(cols).T


def _velocity_step(model):
    """h for velocity differences, m/s: well inside the smooth-sign law's width."""
    eps = model.spec.friction_constants.get("sign_smoothing_velocity")
    return 1e-6 if eps is None else 1e-4 * eps


@pytest.mark.parametrize("torque", ["zero", "random"])
def test_continuous_linearize_at_rest_matches_symmetric_differences(model, sample_xe, torque):
    n, theta = model.n_legs, model.theta_nominal
    rng = np.random.default_rng(11)
    for xe in _poses(model, sample_xe):
        tau = np.zeros(n) if torque == "zero" else rng.uniform(-1.0, 1.0, n)
        v0 = np.zeros(2)
        A, B = model.linearize(xe, v0, tau, theta)
        info = f"{model.name} at {xe.tolist()}, tau {tau.tolist()}"
        fd = lambda x_, v_, t_, th=theta: model.forward_dynamics(x_, v_, t_, th)
        d_xe = _central(lambda z: fd(z, v0, tau), xe, 1e-6)
        d_tau = _central(lambda z: fd(xe, v0, z), tau, 1e-4)
        scale = max(np.abs(A[2:4]).max(), 1.0)
        np.testing.assert_allclose(A[2:4, 0:2], d_xe, rtol=1e-6, atol=1e-6 * scale,
                                   err_msg=f"d xedd / d xe, {info}")
        np.testing.assert_allclose(B[2:4], d_tau, rtol=1e-6, atol=1e-8 * np.abs(B).max(),
                                   err_msg=f"d xedd / d tau, {info}")
        if torque == "zero":           # an equilibrium at every pose: no pose dependence
            assert np.all(A[2:4, 0:2] == 0.0), f"{info}: A[2:4, 0:2] = {A[2:4, 0:2]}"
        # the velocity columns: central differences of the smooth part of the law
        hv = _velocity_step(model)
        th_s = _smooth_part(model, theta)
        d_v = _central(lambda z: fd(xe, z, tau, th_s), v0, hv)
        np.testing.assert_allclose(A[2:4, 2:4], d_v, rtol=1e-5, atol=1e-6 * scale,
                                   err_msg=f"d xedd / d xed, {info}")
        # the state is the midpoint of its symmetric neighbours in velocity (the Coulomb
        # term is odd, Ce xed even and O(h^2)): f(v) + f(-v) = 2 f(0) + O(h^2)
        f0 = fd(xe, v0, tau)
        for d in np.vstack([np.eye(2), rng.normal(size=(4, 2))]):
            mid = 0.5 * (fd(xe, v0 + hv * d, tau) + fd(xe, v0 - hv * d, tau))
            np.testing.assert_allclose(mid, f0, rtol=0, atol=1e-9 * max(1.0, np.abs(f0).max()),
                                       err_msg=f"midpoint along xed {d.tolist()}, {info}")


def test_discrete_linearize_at_rest_is_an_equilibrium(model, sample_xe):
    n, theta = model.n_legs, model.theta_nominal
    for xe in _poses(model, sample_xe):
        x0, tau = np.concatenate([xe, np.zeros(2)]), np.zeros(n)
        np.testing.assert_array_equal(model.sampled_step(x0, tau, theta), x0,
                                      err_msg=f"{model.name}: rest at zero torque moved")
        A, B = model.linearize(xe, np.zeros(2), tau, theta, discrete=True)
        info = f"{model.name} at {xe.tolist()}"
        step = lambda x, t, th=theta: model.sampled_step(x, t, th)
        dx = _central(lambda z: step(np.concatenate([z, np.zeros(2)]), tau), xe, 1e-6)
        # a torque step from rest moves the RK4 stages off v = 0 with the torque's sign: the
        # Coulomb jump again, so B is compared with the smooth part's differences
        th_s = _smooth_part(model, theta)
        du = _central(lambda z: step(x0, z, th_s), tau, 1e-4)
        np.testing.assert_allclose(A[:, 0:2], dx, rtol=1e-6, atol=1e-9, err_msg=info)
        np.testing.assert_allclose(B, du, rtol=1e-5, atol=1e-6 * np.abs(B).max(), err_msg=info)
        np.testing.assert_array_equal(A[:, 0:2], np.vstack([np.eye(2), np.zeros((2, 2))]),
                                      err_msg=f"{info}: d x_next / d xe at rest, zero torque")
