# Bad input to the planner: each a typed error naming what and where; nothing comes back NaN.
import re

import numpy as np
import pytest

import pm2dof
from pm2dof import (
    ArgumentError,
    ArgumentTypeError,
    PlanError,
    SingularityError,
    TaskPath,
    WorkspaceError,
)
from pm2dof.planning import check_path, plan_kinematic, plan_smooth, plan_time_optimal
from pm2dof.planning.problem import PlanProblem
from pm2dof.planning.stages import GRID_MAX, grid_points, params, stages

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
    path = read_path_file("pick_and_place").path
    s = grid_points(path, 300)
    prm, th = params(m, None)
    stage, _ = stages(PlanProblem(m, path, np.ones(3), th, "min_norm", prm), s)
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
    ({"grid": GRID_MAX + 1}, f"from 2 to {GRID_MAX}"), ({"grid": 10 ** 9}, "grid"),
    ({"margin": 0.0}, "margin"), ({"margin": -0.5}, "margin"),
    ({"margin": float("nan")}, "margin"), ({"margin": "x"}, "margin"),
    ({"margin": 2.0}, r"margin must be a number in \(0, 1\]"),
    ({"margin": 1.0000001}, "margin"),
    ({"tau_max": [1.0, 2.0]}, "tau_max"), ({"tau_max": -1.0}, "tau_max"),
    ({"tau_max": [6.0, float("inf"), 6.0]}, "tau_max"), ({"tau_max": "six"}, "tau_max"),
    ({"split": "preload"}, "split"),
])
def test_bad_arguments(m, kw, match):
    """Refused before any work (grid 10^9 was killed for its memory; margin 2 planned at twice
    the motors' limits)."""
    with pytest.raises(PlanError, match=match):
        plan_time_optimal(m, LINE, **kw)


@pytest.mark.parametrize("theta", [np.zeros(3), np.full(15, np.nan), "x", np.ones((3, 5))])
def test_bad_theta_is_the_controllers_error(m, theta):
    """theta is checked by Model.checked_theta (the one check, as the controllers'):
    ArgumentError naming theta and the parameters."""
    with pytest.raises(ArgumentError, match=r"theta must be 15 finite numbers \(alpha1"):
        plan_time_optimal(m, LINE, theta=theta)


def _edited(m, **entries):
    th = m.theta_nominal.copy()
    for name, value in entries.items():
        th[m.param_names.index(name)] = value
    return th


@pytest.mark.parametrize("edit, match", [
    ("negated", r"leg 1 alpha and gamma must be > 0, got alpha = -0.0932"),
    ("zero", r"leg 1 alpha and gamma must be > 0, got alpha = 0,"),
    ({"beta2": 0.05}, r"leg 2 inertia is not positive definite: beta\^2 = 0.0025 >= "),
    ({"gamma3": -1e-3}, r"leg 3 alpha and gamma must be > 0"),
    ({"fv2": -0.1}, r"fv2 = -0.1 < 0 \(friction must dissipate\)"),
    ({"fc3": -1e-9}, r"fc3 = -1e-09 < 0"),
])
def test_unphysical_theta_is_refused(m, edit, match):
    """A plan needs Me positive definite (every leg's M_i, eq. 1) and friction that dissipates.
    Before this check -theta planned the same duration as theta (u is odd in theta, the torque
    box symmetric) and theta = 0 planned 0.7 ms: answers for a robot that cannot exist."""
    th = {"negated": -m.theta_nominal, "zero": 0.0 * m.theta_nominal}.get(edit) \
        if isinstance(edit, str) else _edited(m, **edit)
    with pytest.raises(ArgumentError, match="theta is not physical: " + match):
        plan_time_optimal(m, LINE, theta=th)


def test_physical_edge_is_accepted(m):
    """The rule is the model file's: friction 0 is physical (a frictionless robot), and an
    inertia matrix just inside positive definiteness plans."""
    a, g = m.theta_nominal[m.param_names.index("alpha2")], m.theta_nominal[m.param_names.index("gamma2")]
    th = _edited(m, fv1=0.0, fc1=0.0, beta2=0.999 * np.sqrt(a * g))
    plan = plan_time_optimal(m, LINE, theta=th, grid=200)
    assert np.isfinite(plan.duration) and plan.duration > 0


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


# --------------------------------------------------------------------------------------
# Arguments that crashed with a plain Python error
# --------------------------------------------------------------------------------------

def test_an_empty_or_foreign_task_path_is_refused():
    with pytest.raises(PlanError, match="one or more pieces, got none"):
        TaskPath([])                                        # planned as IndexError before
    with pytest.raises(ArgumentTypeError, match=r"got \['int'\]"):
        TaskPath([1])
    with pytest.raises(PlanError, match="stop_junctions must be junction indices from 0 to 1"):
        TaskPath(LINE._pieces, [5])
    with pytest.raises(PlanError, match="arc lengths s must be finite numbers"):
        LINE.evaluate("a")                                  # ValueError before


@pytest.mark.parametrize("call, match", [
    (lambda m: check_path(m, [0, 1]), "path must be a pm2dof.TaskPath"),
    (lambda m: check_path("shang2010", LINE), "model must be a pm2dof.Model"),
    (lambda m: plan_time_optimal(m, [0, 1]), "path must be a pm2dof.TaskPath"),
    (lambda m: plan_time_optimal(None, LINE), "model must be a pm2dof.Model"),
    (lambda m: plan_kinematic([1], 0.5, 10.0, 400.0), r"path must be a pm2dof.TaskPath .*list"),
    (lambda m: plan_smooth(m, "line"), "path must be a pm2dof.TaskPath"),
])
def test_a_wrong_argument_type_is_named(m, call, match):
    """AttributeError before; now ArgumentTypeError naming the argument and the type."""
    with pytest.raises(ArgumentTypeError, match=match):
        call(m)


def test_check_path_step_bounds(m):
    """The step has documented bounds: STEP_MIN 1e-6 m, STEP_MAX 0.01 m, and at most
    SAMPLES_MAX samples (a tiny step once ran out of memory)."""
    from pm2dof.planning.check import SAMPLES_MAX, STEP_MAX, STEP_MIN
    for step in (0.0, -1.0, float("nan"), STEP_MIN / 2, STEP_MAX * 1.5, "x", None):
        with pytest.raises(PlanError, match="step must be a length from 1e-06 m to 0.01 m"):
            check_path(m, LINE, step=step)
    check_path(m, LINE, step=STEP_MIN)                 # 7e4 samples: accepted
    check_path(m, LINE, step=STEP_MAX)
    square = [[0.2, 0.22], [0.3, 0.22], [0.3, 0.3], [0.2, 0.3]]
    cycle = TaskPath.polyline(square * 3 + [[0.2, 0.23]], 0.01)          # three laps, 1.03 m
    assert cycle.length / STEP_MIN > SAMPLES_MAX
    with pytest.raises(PlanError, match=r"more than 1000000: use step >= 1\.\d+e-06 m"):
        check_path(m, cycle, step=STEP_MIN)


@pytest.mark.parametrize("kw, match", [
    ({"max_iter": -1}, "max_iter must be a whole number of IPOPT iterations from 1 to 100000"),
    ({"max_iter": 0}, "max_iter"), ({"max_iter": 2.5}, "max_iter"), ({"max_iter": True},
                                                                      "max_iter"),
    ({"max_iter": 10 ** 6}, "max_iter"),
    ({"tau_rate": [1.0, 2.0]}, "tau_rate must be one value or 3"), ({"tau_rate": -1.0},
                                                                     "tau_rate"),
    ({"tau_rate": "x"}, "tau_rate"), ({"tau_rate": float("inf")}, "tau_rate"),
    ({"margin": 1.5}, "margin"), ({"grid": 1}, "grid"),
])
def test_plan_smooth_checks_its_options_before_ipopt(m, kw, match, capfd):
    """A negative max_iter reached IPOPT, which printed its own text on stdout and raised a
    CasADi RuntimeError; now PlanError before any solver runs, and nothing is printed."""
    with pytest.raises(PlanError, match=match):
        plan_smooth(m, LINE, **kw)
    out = capfd.readouterr()
    assert out.out == "" and out.err == ""


def test_check_path_and_check_trajectory_are_one_check(m):
    """check_path uses the model's test (Model.poses_clear, check_trajectory's too, with its
    1e-12 relative slack for rounding), so a path ends where simulate's check_trajectory would
    end it: a line ending where the type I measure is 5e-13 below its threshold (within the
    slack) is accepted by both, one ending 1e-9 below by both refused."""
    from pm2dof.control.simulate import check_trajectory
    thr = m.singularity_threshold
    a, b = np.array([0.25, 0.25]), np.array([0.02, 0.25])     # towards base A1: leg 1 folds

    def measure(lam):
        return float(m.pose_measures([a + lam * (b - a)])[0][0])
    lo, hi = 0.0, 1.0
    for _ in range(200):                                      # the crossing of the threshold
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if measure(mid) >= thr else (lo, mid)

    def end_at(rel):                    # the point on the line where measure = thr (1 - rel)
        l0, l1 = lo, 1.0
        for _ in range(200):
            mid = 0.5 * (l0 + l1)
            l0, l1 = (mid, l1) if measure(mid) >= thr * (1 - rel) else (l0, mid)
        return a + l0 * (b - a)
    near, beyond = end_at(5e-13), end_at(1e-9)
    assert thr * (1 - 1e-12) <= measure(np.hypot(*(near - a)) / np.hypot(*(b - a))) < thr
    for end, ok in ((near, True), (beyond, False)):
        path = TaskPath.line(a, end)
        traj = pm2dof.plan_kinematic(path, 0.5, 10.0, 400.0).trajectory
        if ok:
            check_path(m, path)
            check_trajectory(m, traj)
        else:
            with pytest.raises(SingularityError):
                check_path(m, path)
            with pytest.raises(SingularityError):
                check_trajectory(m, traj)


def test_path_messages_name_the_value():
    with pytest.raises(PlanError, match=r"angle1 \(rad\) must be a finite number, got nan"):
        TaskPath.arc([0.25, 0.26], 0.02, 0.0, np.nan)
    with pytest.raises(PlanError, match=r"radius \(m\) must be a finite number > 0, got -1"):
        TaskPath.arc([0.25, 0.26], -1, 0.0, 1.0)
    with pytest.raises(PlanError, match=r"arc lengths s must be finite, got s\[1\] = nan"):
        LINE.evaluate([0.0, np.nan])
    with pytest.raises(PlanError, match=r"arc length s = -1 m is outside the path \[0, 0.07071"):
        LINE.evaluate([-1.0, 10.0])
