# Computed torque with an exact model: the error follows the sampled recursion, not the ODE.
"""CTCController's docstring: with the controller's model as the plant, a step in the reference
gives an error that follows the linear recursion of the 2 ms loop (zero-order hold, backward-
difference velocity), written here independently, to 6e-8 m; the continuous edd + Kv edot +
Kp e = 0 is off by 9.4 % of the step."""
import numpy as np
import pytest

import pm2dof
from pm2dof import CTCController, Trajectory, plant_truth, simulate

N = 400                          # 0.8 s: the error has settled
E0 = np.array([1e-3, -0.5e-3])   # m


def _truth_from_theta(m, theta):
    """plant_truth with the inertial and friction parameters of theta, by name."""
    fields = {}
    for name, v in zip(m.param_names, theta):
        fields.setdefault(name.rstrip("0123456789"), []).append(v)
    t = plant_truth(m, payload_mass=0.0, **{k: np.array(v) for k, v in fields.items()})
    t["fs"] = np.zeros(m.n_legs)
    return t


@pytest.fixture(scope="module")
def run():
    m = pm2dof.load_model()
    theta = np.array(m.theta_nominal, dtype=float)
    theta[[i for i, n in enumerate(m.param_names) if n[:2] in ("fv", "fc")]] = 0.0
    c = CTCController(m, theta0=theta, velocity_filter_hz=0.0)
    T = c.sample_period
    x0 = np.asarray(pm2dof.model_move(m, "high").xd[0])
    xd = np.tile(x0 + E0, (N, 1))
    xd[0] = x0                    # at rest at x0; the reference steps by E0 at t_1
    traj = Trajectory.from_samples(xd, np.zeros((N, 2)), np.zeros((N, 2)), T)
    r = simulate(m, c, traj, truth=_truth_from_theta(m, theta), quantise=False)
    P = c.params_layout.unpack(c.params)
    return r, xd, x0, T, P["Kp"], P["Kv"]


def test_the_error_follows_the_sampled_recursion(run):
    r, xd, x0, T, Kp, Kv = run
    assert np.all(r.status == pm2dof.Status.OK)
    x, xdot, x_prev = x0.copy(), np.zeros(2), x0.copy()
    e = np.empty((N, 2))
    for k in range(N):
        e[k] = xd[k] - x
        v = (x - x_prev) / T                       # backward difference (zero at k = 0)
        a = Kv * (0.0 - v) + Kp * (xd[k] - x)      # xd_dot = xd_ddot = 0
        x_prev = x.copy()
        x, xdot = x + T * xdot + 0.5 * T * T * a, xdot + T * a
    dev = np.max(np.linalg.norm(r.e - e, axis=1))
    assert dev < 1e-7, dev                         # measured 6.2e-8 m


def test_the_continuous_error_dynamics_are_off_by_a_tenth(run):
    r, xd, x0, T, Kp, Kv = run
    w = np.sqrt(Kp)
    assert np.allclose(Kv, 2 * w)                  # critically damped: e = e0 (1 + w t) e^-wt
    t = (np.arange(N) - 1) * T                     # from the step at t_1
    cont = np.outer((1 + w[0] * t) * np.exp(-w[0] * t), E0)
    cont[0] = 0.0
    dev = np.max(np.linalg.norm(r.e - cont, axis=1)) / np.linalg.norm(E0)
    assert round(dev, 3) == 0.094, dev
