# Linearisation along trajectories, python-control state space, and the closed-loop check.
"""``linearize_trajectory``, ``statespace`` and what the linear model predicts.

The closed-loop check: computed torque at rest on the smooth-friction model, against a plant
whose truth is that model (so the linear model describes the plant). The sampled closed loop
is linear in the perturbation: the plant's discrete (A, B), the encoder (exact), the
backward-difference velocity (the previous pose is a state) and the law's Jacobians (Me,
d u / d xed from ``inverse_dynamics_jacobians``). Its eigenvalues give the response to a small
step of the set point; ``simulate`` must follow it to the second order of the step.
"""
import numpy as np
import pytest

import pm2dof


@pytest.fixture(scope="module")
def m():
    return pm2dof.load_model()


def test_linearize_trajectory_is_the_pointwise_linearisation(m):
    traj = pm2dof.model_move(m, "high")
    for discrete in (True, False):
        lin = pm2dof.linearize_trajectory(m, traj, discrete=discrete)
        K = len(traj.t)
        assert lin.A.shape == (K, 4, 4) and lin.B.shape == (K, 4, m.n_legs)
        for k in (0, K // 3, K // 2, K - 1):
            A, B = m.linearize(traj.xd[k], traj.xd_dot[k], lin.tau_a[k], discrete=discrete)
            np.testing.assert_array_equal(lin.A[k], A, err_msg=f"sample {k}")
            np.testing.assert_array_equal(lin.B[k], B, err_msg=f"sample {k}")
    # the operating torques realise the desired acceleration in the model (eqs. 10-12)
    for k in range(0, K, 7):
        q = m.ik(traj.xd[k])
        np.testing.assert_allclose(m.S(q).T @ lin.tau_a[k], lin.u[k], rtol=1e-12, atol=1e-10)
        xedd = m.forward_dynamics(traj.xd[k], traj.xd_dot[k], lin.tau_a[k], m.theta_nominal)
        np.testing.assert_allclose(xedd, traj.xd_ddot[k], atol=1e-9, err_msg=f"sample {k}")


def test_linearize_trajectory_refuses_bad_input(m):
    traj = pm2dof.model_move(m, "low")
    with pytest.raises(pm2dof.ArgumentError, match="split"):
        pm2dof.linearize_trajectory(m, traj, split="fastest")
    with pytest.raises(pm2dof.ArgumentError, match="theta"):
        pm2dof.linearize_trajectory(m, traj, theta=np.full(3, np.nan))
    far = pm2dof.line([0.22, 0.29], [0.9, 0.9], 0.5, 10.0, 400.0)
    with pytest.raises((pm2dof.WorkspaceError, pm2dof.SingularityError)):
        pm2dof.linearize_trajectory(m, far)


def test_statespace_has_named_states_and_inputs(m):
    control = pytest.importorskip("control")
    xe, xed, tau = [0.245, 0.265], [0.1, -0.05], np.array([0.5, -0.2, 0.1])
    for discrete in (False, True):
        sys = pm2dof.statespace(m, xe, xed, tau, discrete=discrete)
        A, B = m.linearize(xe, xed, tau, discrete=discrete)
        np.testing.assert_array_equal(sys.A, A)
        np.testing.assert_array_equal(sys.B, B)
        assert sys.state_labels == ["x", "y", "xd", "yd"]
        assert sys.input_labels == ["tau1", "tau2", "tau3"]
        assert sys.dt == (m.spec.sensing["sample_period"] if discrete else 0)
        assert isinstance(sys, control.StateSpace)


def _smooth_setup(first_point):
    """The smooth-friction model, a plant whose truth is that model, a rest pose."""
    m = pm2dof.load_model("shang2010_smooth")
    n, th = m.n_legs, np.asarray(m.theta_nominal)
    truth = pm2dof.plant_truth(
        m, alpha=th[0:n], beta=th[n:2 * n], gamma=th[2 * n:3 * n], fv=th[3 * n:4 * n],
        fc=th[4 * n:5 * n], fs=[0.0] * n, payload_mass=0.0,
        coulomb_smoothing_velocity=m.spec.friction_constants["sign_smoothing_velocity"])
    return m, truth, first_point(m)


def test_closed_loop_eigenvalues_predict_the_sampled_closed_loop(first_point):
    m, truth, x0 = _smooth_setup(first_point)
    n, T, th = m.n_legs, m.spec.sensing["sample_period"], m.theta_nominal
    w = 2 * np.pi * 15
    ctc = pm2dof.CTCController(m, Kp=w * w, Kv=2 * 0.7 * w)
    # a set point step of delta at sample 1
    delta, N = np.array([2e-6, -1e-6]), 120
    xd = np.tile(x0 + delta, (N, 1))
    xd[0] = x0
    z = np.zeros((N, 2))
    traj = pm2dof.Trajectory(np.arange(N) * T, xd, z, z, T)
    r = pm2dof.simulate(m, ctc, traj, truth=truth, quantise=False)
    # the linear closed loop: xi_k = [dxe, dxed, dxe_{k-1}] about the set point
    Ad, Bd = m.linearize(x0, [0, 0], np.zeros(n), th, discrete=True)
    q = m.ik(x0)
    Me, S = m.Me(q, th), m.S(q)
    Du = m.inverse_dynamics_jacobians(x0, [0, 0], [0, 0], th).d_xed   # Ce, friction slope
    split = S @ np.linalg.inv(S.T @ S)                                  # eq. 21
    Kp, Kv = np.diag(ctc.params[0:2]), np.diag(ctc.params[2:4])
    # u = Me (-Kp dxe - Kv v) + Du v, with v = (dxe - dxe_prev) / T (exact encoders, no filter)
    G_xe = Me @ (-Kp) + (Du - Me @ Kv) / T
    G_prev = -(Du - Me @ Kv) / T
    Acl = np.zeros((6, 6))
    Acl[0:4, 0:4] = Ad + Bd @ split @ np.hstack([G_xe, np.zeros((2, 2))])
    Acl[0:4, 4:6] = Bd @ split @ G_prev
    Acl[4:6, 0:2] = np.eye(2)
    lam = np.linalg.eigvals(Acl)
    xi = np.concatenate([-delta, [0, 0], -delta])   # sample 1: at x0, at rest, error -delta
    pred = []
    for _ in range(1, N):
        pred.append(xi[0:2].copy())
        xi = Acl @ xi
    err_sim = r.xe[1:] - (x0 + delta)
    gap = np.max(np.abs(err_sim - np.array(pred)))
    assert gap < 2e-3 * np.abs(delta).max(), (gap, lam)
    # the eigenvalues: stable, and the slowest (oscillating) pair's modulus is the simulated
    # envelope's decay per sample: peaks of |e| one oscillation period P apart
    slow = lam[np.argmax(np.abs(lam))]
    rho, P = abs(slow), int(round(2 * np.pi / abs(np.angle(slow))))
    assert rho < 1 and 10 + 2 * P <= len(err_sim), lam
    e = np.linalg.norm(err_sim, axis=1)
    peak1, peak2 = e[10:10 + P].max(), e[10 + P:10 + 2 * P].max()
    rate = (peak2 / peak1) ** (1 / P)
    assert abs(rate - rho) < 0.01, (rate, rho, P, lam)
