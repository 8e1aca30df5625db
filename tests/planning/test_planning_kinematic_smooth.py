# plan_kinematic equals the paper's S-curve moves; plan_smooth respects its torque rate and limits.
import numpy as np
import pytest

import pm2dof
from pm2dof import TaskPath
from pm2dof.control.trajectory import line_profile
from pm2dof.planning import plan_kinematic, plan_smooth, plan_time_optimal

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not


@pytest.mark.parametrize("speed", ["low", "high"])
def test_kinematic_line_is_paper_move(speed):
    """On the paper's two lines plan_kinematic gives today's paper_move, sample for sample."""
    mv = pm2dof.PAPER_MOVES[speed]
    plan = plan_kinematic(TaskPath.line(mv["start"], mv["end"]), mv["v_max"], mv["a_max"],
                          mv["j_max"])
    ref = pm2dof.paper_move(speed)
    assert plan.duration == line_profile(**mv).duration == plan.profile.duration
    assert ref.duration == plan.trajectory.duration           # (N - 1) * period, both
    for k in ("t", "xd", "xd_dot", "xd_ddot"):
        a, b = getattr(plan.trajectory, k), getattr(ref, k)
        assert a.shape == b.shape and np.abs(a - b).max() <= 1e-15, k


def test_kinematic_parts_rest_at_the_stops():
    there = TaskPath.line([0.2, 0.25], [0.3, 0.25])
    cycle = TaskPath.concat(there, TaskPath.line([0.3, 0.25], [0.2, 0.25]))
    one = plan_kinematic(there, 0.5, 10.0, 400.0)
    plan = plan_kinematic(cycle, 0.5, 10.0, 400.0)
    assert plan.duration == pytest.approx(2 * one.duration, rel=1e-15)
    k = int(round(one.duration / 0.002))
    tr = plan.trajectory
    assert np.hypot(*tr.xd_dot.T)[k] < 1e-3 and np.allclose(tr.xd[k], [0.3, 0.25], atol=1e-6)
    assert np.allclose(tr.xd[-1], [0.2, 0.25], atol=1e-15)
    assert np.hypot(*tr.xd_dot.T).max() == pytest.approx(0.5, rel=1e-12)


@pytest.fixture(scope="module")
def m():
    return pm2dof.load_model()


@pytest.mark.parametrize("split", ["min_norm", "min_max"])
def test_smooth_respects_rate_and_limits(m, split):
    path = TaskPath.arc([0.245, 0.265], 0.03, 0.0, 2.0)
    rate = 400.0
    plan = plan_smooth(m, path, tau_max=6.0, split=split, grid=120, tau_rate=rate)
    assert plan.info["ipopt_status"] == "Solve_Succeeded"
    strict = plan.info["strict_duration"]
    assert strict <= plan.duration * (1 + 1e-6)
    dt = np.diff(plan.t)
    assert (np.abs(np.diff(plan.tau, axis=0)) <= rate * dt[:, None] * (1 + 1e-6) + 1e-9).all()
    assert (np.abs(plan.tau) <= 6.0 * (1 + 1e-6)).all()
    loose = plan_smooth(m, path, tau_max=6.0, split=split, grid=120, tau_rate=1e6)
    assert loose.duration == pytest.approx(strict, rel=1e-3)       # no rate limit: the optimum
    assert plan.duration > loose.duration


def test_smooth_with_a_nonlinear_friction_law():
    """Stribeck friction (not affine in the speed) enters as a CasADi expression with exact
    derivatives (it went through the generated C with finite differences); the plan is
    feasible on its grid."""
    ms = pm2dof.load_model("shang2010_stribeck")
    th = ms.theta_nominal.copy()
    th[[ms.param_names.index(f"fs{i}") for i in (1, 2, 3)]] = 0.2
    path = TaskPath.line([0.22, 0.29], [0.27, 0.24])
    plan = plan_smooth(ms, path, tau_max=6.0, theta=th, grid=40, tau_rate=2000.0)
    assert plan.info["friction"] == "exact, CasADi"
    # the NLP lands braking intervals anywhere, the strict plan on its bound: at 40 points
    # it may be shorter by that discretisation error
    assert plan.duration >= plan.info["strict_duration"] * (1 - 1e-2)
    ref = plan_time_optimal(ms, path, 6.0, theta=th, grid=40)
    assert ref.duration == pytest.approx(plan.info["strict_duration"], rel=1e-12)
