# Bad input to the planner: each a typed error naming what and where; nothing comes back NaN.
import re

import numpy as np
import pytest

import pm2dof
from pm2dof import PlanError, SingularityError, TaskPath, WorkspaceError
from pm2dof.planning import check_path, plan_kinematic, plan_time_optimal
from pm2dof.planning.stages import grid_points, params, stages

LINE = TaskPath.line([0.22, 0.29], [0.27, 0.24])


@pytest.fixture(scope="module")
def m():
    return pm2dof.load_model()


def _where(msg):
    """(s, x, y) named by an error message."""
    g = re.search(r"s = ([-\d.e]+) m, point \(([-\d.e]+), ([-\d.e]+)\) m", msg)
    assert g, msg
    return tuple(float(v) for v in g.groups())


def test_unreachable_waypoint(m):
    """A path from an unreachable waypoint fails where it starts (WorkspaceError, the leg); one
    towards an unreachable waypoint fails first where a leg stretches out (SingularityError),
    still inside the workspace, before the waypoint."""
    path = TaskPath.polyline([[0.6, 0.6], [0.27, 0.24], [0.22, 0.29]], 0.01)
    for call in (lambda: check_path(m, path), lambda: plan_time_optimal(m, path, grid=300)):
        with pytest.raises(WorkspaceError, match="leaves the workspace") as e:
            call()
        s, x, y = _where(str(e.value))
        assert "out of reach of leg" in str(e.value) and s == 0.0 and (x, y) == (0.6, 0.6)
    path = TaskPath.polyline([[0.22, 0.29], [0.27, 0.24], [0.6, 0.6]], 0.01)
    for call in (lambda: check_path(m, path), lambda: plan_time_optimal(m, path, grid=300)):
        with pytest.raises(SingularityError, match="type I") as e:
            call()
        s, x, y = _where(str(e.value))
        assert 0.0 < s < path.length
        assert np.allclose(path.evaluate([s])[0][0], [x, y], atol=1e-5)
        assert m.singularity_measures(m.ik([x, y]))[0] < m.singularity_threshold


def test_path_through_a_singular_region(m):
    """Towards base A1 the first leg folds: type I measure below its threshold."""
    path = TaskPath.line([0.25, 0.25], [0.02, 0.25])
    for call in (lambda: check_path(m, path), lambda: plan_time_optimal(m, path, grid=300)):
        with pytest.raises(SingularityError, match="type I") as e:
            call()
        s, x, y = _where(str(e.value))
        assert m.singularity_measures(m.ik([x, y]))[0] < m.singularity_threshold
        assert "limits.singularity_threshold" in str(e.value)
    five = pm2dof.load_model("fivebar")
    with pytest.raises(SingularityError, match="type II"):      # the parallel singularity
        check_path(five, TaskPath.line([0.3, 0.25], [0.3, 0.12]))


def test_limits_too_low_to_move_at_all(m):
    """Below Coulomb friction no actuator can start the move: named at the first point."""
    with pytest.raises(PlanError, match="even at rest") as e:
        plan_time_optimal(m, LINE, tau_max=0.1)
    assert _where(str(e.value))[0] == 0.0


def test_limits_too_low_somewhere_in_the_middle(m):
    """A limit that starts the move but cannot hold the path further on: the error names the
    first grid point where not even rest is feasible (found here by scaling the limits)."""
    from pm2dof.planning.pathfile import read_path_file
    path = read_path_file("pick_and_place")["path"]
    s = grid_points(path, 300)
    prm, th = params(m, None)
    stage, _ = stages(m, path, s, np.ones(3), th, "min_norm")
    h = m.layout("path_stage").slices["h"]
    lo, hi = np.zeros(len(s)), np.full(len(s), 10.0)   # least uniform limit feasible at rest
    x = np.empty(len(s))
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        st = stage.copy()
        st[:, h] *= mid[:, None]
        m.function("path_mvc").map(len(s), st, prm, x)
        ok = x >= 0
        hi, lo = np.where(ok, mid, hi), np.where(ok, lo, mid)
    assert hi[0] < hi.max()
    limit = 0.5 * (hi[0] + hi.max())
    first = int(np.argmax(hi > limit * 1.0000001))
    with pytest.raises(PlanError, match="even at rest") as e:
        plan_time_optimal(m, path, tau_max=limit, split="min_norm", grid=300)
    assert _where(str(e.value))[0] == pytest.approx(s[first], rel=1e-5)   # 6 digits printed


@pytest.mark.parametrize("kw, match", [
    ({"grid": 0}, "grid"), ({"grid": 1}, "grid"), ({"grid": -5}, "grid"),
    ({"grid": 2.5}, "grid"), ({"grid": True}, "grid"), ({"grid": "1000"}, "grid"),
    ({"margin": 0.0}, "margin"), ({"margin": -0.5}, "margin"),
    ({"margin": float("nan")}, "margin"), ({"margin": "x"}, "margin"),
    ({"tau_max": [1.0, 2.0]}, "tau_max"), ({"tau_max": -1.0}, "tau_max"),
    ({"tau_max": [6.0, float("inf"), 6.0]}, "tau_max"), ({"tau_max": "six"}, "tau_max"),
    ({"theta": np.zeros(3)}, "theta"), ({"theta": np.full(15, np.nan)}, "theta"),
    ({"split": "preload"}, "split"),
])
def test_bad_arguments(m, kw, match):
    with pytest.raises(PlanError, match=match):
        plan_time_optimal(m, LINE, **kw)


def test_bad_kinematic_limits_and_step():
    with pytest.raises(PlanError, match="v_max"):
        plan_kinematic(LINE, 0.0, 10.0, 400.0)
    with pytest.raises(PlanError, match="period"):
        plan_kinematic(LINE, 0.5, 10.0, 400.0, period=-1)
    with pytest.raises(PlanError, match="step"):
        check_path(pm2dof.load_model(), LINE, step=0.0)


def test_nothing_comes_back_nan(m):
    arc = TaskPath.arc([0.245, 0.265], 0.04, 0.0, 2.0)
    for plan in (plan_time_optimal(m, arc, 6.0, grid=200),
                 plan_time_optimal(m, arc, 30.0, "min_norm", grid=200),
                 plan_kinematic(arc, 0.5, 10.0, 400.0)):
        for name in ("s", "sdot", "sddot", "t", "max_velocity", "tau", "tau_peak", "tau_max"):
            v = getattr(plan, name)
            assert v is None or np.isfinite(v).all(), name
        tr = plan.trajectory
        assert all(np.isfinite(getattr(tr, k)).all() for k in ("t", "xd", "xd_dot", "xd_ddot"))
        assert np.isfinite(plan.duration) and plan.duration > 0
