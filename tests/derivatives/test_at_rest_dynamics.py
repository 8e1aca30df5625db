# The model's dynamics at rest (eq. 2 with sign(0) = 0) and their linearisation there.
"""The model at rest, on every model file (m = model.dof task coordinates, any leg kind).

* ``forward_dynamics(xe, 0, tau, theta)`` = Me^-1 (S^T tau - Ge) (eq. 10 at rest, Me, S, Ge
  from the model functions): no friction at zero velocity. At the holding torque (S^T tau =
  Ge, :func:`_holding_torque`) the result is zero: exactly in a horizontal plane, where that
  torque is 0 and Ge = 0; under gravity to the rounding of S^T tau - Ge. (With sign(0) = +1
  the paper's robot got xedd = (0.345, -0.446) m/s^2.)
* ``linearize`` at rest against differences taken symmetrically about the state:
  - the pose and torque columns of (A, B), continuous, and the pose columns of the discrete
    (A, B) equal central differences of ``forward_dynamics`` / ``sampled_step``;
  - at the holding torque every pose at rest is an equilibrium, so d xedd / d xe =
    Me^-1 d(S^T tau - Ge)/d xe at fixed tau (Me^-1's derivative multiplies zero): exactly 0 in
    a horizontal plane (with sign(0) = +1 the pose derivative of -Me^-1 S^T fc was there
    instead), the gravity stiffness otherwise, checked against differences of S and Ge;
  - the discrete step keeps rest at the holding torque, and its Jacobian there is RK4's
    stability polynomial of the continuous one (every stage is the rest state): d x_next /
    d xe = [I; 0] exactly in a horizontal plane;
  - the state is the midpoint of its symmetric neighbours in every direction, velocities
    included: (f(x + h d) + f(x - h d)) / 2 = f(x) + O(h^2). With sign(0) = +1 the Coulomb
    jump put f(x) at one side of it, off by Me^-1 S^T fc.
  - velocity columns (and the discrete B, whose RK4 stages leave v = 0 with the torque's
    sign): a central difference across v = 0 of a Coulomb law sees its jump (2 fc / 2h),
    which no Jacobian has; the Jacobian is that of the smooth part (the sign's derivative
    is 0), so it equals central differences with the Coulomb (and Stribeck) parameters set
    to zero. The smooth-sign model has no jump: its columns are compared with central
    differences as they are.
* Under gravity the holding torque balances Ge only to rounding (~1e-15 m/s^2 left), and a
  joint velocity of 1e-19 in an RK4 stage already engages eq. 2's whole Coulomb force (the
  law has no stiction): one sample of shang2010_vertical at that torque moves the velocity by
  ~1e-4 m/s. The discrete checks at the holding torque therefore take the law's smooth part
  under gravity (:func:`_hold_theta`); the generated step's sign(0) = 0 under gravity is
  checked from rest at zero torque against RK4 over ``forward_dynamics`` instead.
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


def _hold_theta(model, theta):
    """theta for the discrete step held at rest: theta itself in a horizontal plane (the
    holding torque is exactly 0), the smooth part under gravity (module docstring)."""
    return _smooth_part(model, theta) if model.spec.has_gravity else theta


def _holding_torque(model, q, theta):
    """tau_a (n,) that holds the robot at rest: the minimum-norm solution of S^T tau = Ge
    (eq. 21 with u = Ge), S (S^T S)^-1 Ge; exactly 0 in a horizontal plane (Ge = 0)."""
    S = model.S(q)
    return S @ np.linalg.solve(S.T @ S, model.Ge(q, theta))


def _free_fall(model, q, theta):
    """max |Me^-1 Ge|, m/s^2: the scale of the rounding left at the holding torque (0 in a
    horizontal plane, so a bound 1e-12 times it demands exact zeros there)."""
    return float(np.abs(np.linalg.solve(model.Me(q, theta), model.Ge(q, theta))).max())


def _poses(model, sample_xe):
    return sample_xe(model, 77, 4)


def test_forward_dynamics_at_rest_has_no_friction(model, sample_xe, random_theta):
    rng = np.random.default_rng(7)
    n, v0 = model.n_legs, np.zeros(model.dof)
    for xe in _poses(model, sample_xe):
        theta = random_theta(model, rng)
        q = model.ik(xe)
        info = f"{model.name} at {xe.tolist()}"
        Ge, bound = model.Ge(q, theta), 1e-12 * _free_fall(model, q, theta)
        # the holding torque, ours and the model's own min-norm split of Ge
        for tau in (_holding_torque(model, q, theta), model.torque_splits(q, Ge)["min_norm"]):
            acc = model.forward_dynamics(xe, v0, tau, theta)
            assert np.abs(acc).max() <= bound, f"{info}, tau {tau.tolist()}: xedd = {acc}"
        for tau in (np.zeros(n), rng.uniform(-1.0, 1.0, n)):
            expected = np.linalg.solve(model.Me(q, theta), model.S(q).T @ tau - Ge)  # eq. 10
            np.testing.assert_allclose(model.forward_dynamics(xe, v0, tau, theta), expected,
                                       rtol=1e-10, atol=1e-12 * np.abs(expected).max(),
                                       err_msg=f"{info}, tau {tau.tolist()}")


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


@pytest.mark.parametrize("torque", ["holding", "random"])
def test_continuous_linearize_at_rest_matches_symmetric_differences(model, sample_xe, torque):
    n, m, theta = model.n_legs, model.dof, model.theta_nominal
    rng = np.random.default_rng(11)
    for xe in _poses(model, sample_xe):
        q = model.ik(xe)
        tau = (_holding_torque(model, q, theta) if torque == "holding"
               else rng.uniform(-1.0, 1.0, n))
        v0 = np.zeros(m)
        A, B = model.linearize(xe, v0, tau, theta)
        info = f"{model.name} at {xe.tolist()}, tau {tau.tolist()}"
        fd = lambda x_, v_, t_, th=theta: model.forward_dynamics(x_, v_, t_, th)
        d_xe = _central(lambda z: fd(z, v0, tau), xe, 1e-6)
        d_tau = _central(lambda z: fd(xe, v0, z), tau, 1e-4)
        scale = max(np.abs(A[m:]).max(), 1.0)
        np.testing.assert_allclose(A[m:, :m], d_xe, rtol=1e-6, atol=1e-6 * scale,
                                   err_msg=f"d xedd / d xe, {info}")
        np.testing.assert_allclose(B[m:], d_tau, rtol=1e-6, atol=1e-8 * np.abs(B).max(),
                                   err_msg=f"d xedd / d tau, {info}")
        if torque == "holding" and not model.spec.has_gravity:   # tau = 0: no pose dependence
            assert np.all(A[m:, :m] == 0.0), f"{info}: A[m:, :m] = {A[m:, :m]}"
        elif torque == "holding":      # the gravity stiffness Me^-1 d(S^T tau - Ge)/d xe
            def net(z):
                qz = model.ik(z)
                return model.S(qz).T @ tau - model.Ge(qz, theta)
            stiffness = np.linalg.solve(model.Me(q, theta), _central(net, xe, 1e-6))
            np.testing.assert_allclose(A[m:, :m], stiffness, rtol=1e-6, atol=1e-6 * scale,
                                       err_msg=f"d xedd / d xe at the holding torque, {info}")
        # the velocity columns: central differences of the smooth part of the law
        hv = _velocity_step(model)
        th_s = _smooth_part(model, theta)
        d_v = _central(lambda z: fd(xe, z, tau, th_s), v0, hv)
        np.testing.assert_allclose(A[m:, m:], d_v, rtol=1e-5, atol=1e-6 * scale,
                                   err_msg=f"d xedd / d xed, {info}")
        # the state is the midpoint of its symmetric neighbours in velocity: friction (the
        # Coulomb term included) is odd in v, Ce(v) v even and exactly quadratic, so
        # (f(v) + f(-v)) / 2 = f(0) - Me^-1 Ce(v) v (O(h^2); ~2e-9 for a platform's phi)
        f0 = fd(xe, v0, tau)
        Me = model.Me(q, theta)
        for d in np.vstack([np.eye(m), rng.normal(size=(4, m))]):
            v = hv * d
            mid = 0.5 * (fd(xe, v, tau) + fd(xe, -v, tau))
            want = f0 - np.linalg.solve(Me, model.Ce(q, v, theta) @ v)
            np.testing.assert_allclose(mid, want, rtol=0,
                                       atol=1e-9 * max(1.0, np.abs(f0).max()),
                                       err_msg=f"midpoint along xed {d.tolist()}, {info}")


def _rk4_polynomials(model, A_c, B_c, T):
    """(A_d, B_d) of rk4_substeps RK4 steps of h = T / s linearised about an equilibrium, where
    every stage is the equilibrium: R = I + hA + (hA)^2/2 + (hA)^3/6 + (hA)^4/24 per substep,
    P h B_c its input (P = I + hA/2 + (hA)^2/6 + (hA)^3/24); A_d = R^s, B_d = sum_k R^k P h B_c."""
    s = model.spec.rk4_substeps
    hA = T / s * A_c
    eye = np.eye(len(A_c))
    hA2 = hA @ hA
    R = eye + hA + hA2 / 2 + hA2 @ hA / 6 + hA2 @ hA2 / 24
    PB = (eye + hA / 2 + hA2 / 6 + hA2 @ hA / 24) @ (T / s * B_c)
    A_d, B_d = eye, np.zeros_like(PB)
    for _ in range(s):
        B_d = R @ B_d + PB
        A_d = R @ A_d
    return A_d, B_d


def test_discrete_linearize_at_rest_is_an_equilibrium(model, sample_xe, rk4_numpy):
    n, m, theta = model.n_legs, model.dof, model.theta_nominal
    T = model.spec.sensing["sample_period"]
    th = _hold_theta(model, theta)
    for xe in _poses(model, sample_xe):
        q = model.ik(xe)
        x0, tau = np.concatenate([xe, np.zeros(m)]), _holding_torque(model, q, th)
        info = f"{model.name} at {xe.tolist()}, tau {tau.tolist()}"
        moved = np.abs(model.sampled_step(x0, tau, th) - x0).max()
        assert moved <= 1e-12 * T * _free_fall(model, q, th), f"{info}: rest moved by {moved}"
        A, B = model.linearize(xe, np.zeros(m), tau, th, discrete=True)
        step = lambda x, t: model.sampled_step(x, t, th)
        dx = _central(lambda z: step(np.concatenate([z, np.zeros(m)]), tau), xe, 1e-6)
        # a torque step from rest moves the RK4 stages off v = 0 with the torque's sign: the
        # Coulomb jump again, so B is compared with the smooth part's differences
        th_s = _smooth_part(model, th)
        du = _central(lambda z: model.sampled_step(x0, z, th_s), tau, 1e-4)
        np.testing.assert_allclose(A[:, :m], dx, rtol=1e-6, atol=1e-9, err_msg=info)
        np.testing.assert_allclose(B, du, rtol=1e-5, atol=1e-6 * np.abs(B).max(), err_msg=info)
        A_c, B_c = model.linearize(xe, np.zeros(m), tau, th)
        A_r, B_r = _rk4_polynomials(model, A_c, B_c, T)
        np.testing.assert_allclose(A, A_r, rtol=0, atol=1e-12 * np.abs(A_r).max(),
                                   err_msg=f"{info}: A vs RK4's polynomial of the continuous A")
        np.testing.assert_allclose(B, B_r, rtol=0, atol=1e-12 * np.abs(B_r).max(),
                                   err_msg=f"{info}: B vs RK4's polynomial of the continuous B")
        if not model.spec.has_gravity:
            np.testing.assert_array_equal(A[:, :m], np.vstack([np.eye(m), np.zeros((m, m))]),
                                          err_msg=f"{info}: d x_next / d xe at rest, zero torque")
        # the generated step's sign(0) = 0 with the whole law: from rest at zero torque (a fall
        # under gravity; rest in a horizontal plane) as RK4 over forward_dynamics
        np.testing.assert_allclose(model.sampled_step(x0, np.zeros(n), theta),
                                   rk4_numpy(model, x0, np.zeros(n), theta, T), rtol=1e-12,
                                   atol=1e-13, err_msg=f"{info}: from rest at zero torque")
