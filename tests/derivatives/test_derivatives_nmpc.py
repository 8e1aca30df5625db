# The nonlinear MPC example runs in simulate as a Python-level controller.
"""examples/nmpc.py: its prediction model is the generated sampled step with the generated
Jacobians (checked against them), and it tracks in ``pm2dof.simulate`` (a short run)."""
import importlib.util
from pathlib import Path

import casadi as ca
import numpy as np
import pytest

import pm2dof

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "nmpc.py"


@pytest.fixture(scope="module")
def nmpc():
    spec = importlib.util.spec_from_file_location("nmpc_example", EXAMPLE)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_prediction_model_and_its_custom_jacobian(nmpc):
    m = pm2dof.load_model()
    th, T = m.theta_nominal, m.spec.sensing["sample_period"]
    F = nmpc.prediction_model(m, th, T)
    x, tau = np.array([0.245, 0.265, 0.1, -0.2]), np.array([1.0, -0.5, 0.3])
    np.testing.assert_array_equal(np.asarray(F(x, tau)).ravel(), m.sampled_step(x, tau, th))
    X, U = ca.MX.sym("X", 4), ca.MX.sym("U", 3)
    jac = ca.Function("j", [X, U], [ca.jacobian(F(X, U), X), ca.jacobian(F(X, U), U)])
    A, B = (np.asarray(a) for a in jac(x, tau))
    J = m.sampled_step_jacobians(x, tau, th)
    np.testing.assert_array_equal(A, J.d_x)
    np.testing.assert_array_equal(B, J.d_tau_a)


def test_nmpc_tracks_in_simulate(nmpc):
    m = pm2dof.load_model()
    traj = pm2dof.line([0.22, 0.29], [0.23, 0.28], 0.2, 5.0, 200.0)      # a short move
    ctrl = nmpc.NMPCController(m, traj, horizon=4)
    r = pm2dof.simulate(m, ctrl, traj, settle_time=0.02)
    lqr = pm2dof.simulate(m, pm2dof.LQRController(m, traj), traj, settle_time=0.02)
    assert r.outcome == "completed" and r.controller == "nmpc"
    assert len(ctrl.solve_times) == len(r.t)
    # the LQR's weights and terminal cost, no active bound: close to the LQR's tracking
    assert r.rmse < 1.5 * lqr.rmse + 1e-6, (r.rmse, lqr.rmse)
