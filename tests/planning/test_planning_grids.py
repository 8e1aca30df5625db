# Any grid from 2 to 1000 points gives a feasible, conservative plan: the passes on coarse grids.
"""``plan_time_optimal`` raised "the forward pass found no feasible path
acceleration ... (s_dd -15.1 below its lower bound -121.4)" on valid input at moderate grids
(pick_and_place at <= 100 points, curve at 20-40, the paper's line at 2-3). The condition that
failed was a landing below rest, s_d^2 < 0 at the next grid point, for two reasons in the
generated passes: the backward pass accepted a speed from which every feasible s_dd stops the
robot before the next point (near a coarse grid's maximum-velocity curve viscous friction makes
even the greatest s_dd strongly negative), and the forward pass capped s_dd by the arrival
facets' U at the landing speed of its previous guess (three fixed-point steps), which
undershoots by the fall of U across the interval. Coarse grids were also unsafe between their
points (the limits exceeded by up to 6x on the spline): the planner now refines such grids.
"""
import numpy as np
import pytest

import pm2dof
from pm2dof.derive.planning import MVC_BISECTIONS
from pm2dof.planning import TaskPath, plan_time_optimal
from pm2dof.planning.grid import _check_forward
from pm2dof.planning.pathfile import read_path_file
from pm2dof.planning.problem import PlanProblem
from pm2dof.planning.stages import V_TOP, grid_points, limits, params, stages
from pm2dof.planning.topp import BETWEEN_TOL, RESOLUTION, solve_profile
from pm2dof.planning.torques import plan_torques

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

PATHS = {"line": TaskPath.line([0.22, 0.29], [0.27, 0.24]),            # the paper's line
         "arc": TaskPath.arc([0.245, 0.265], 0.04, -0.5, 1.5),
         "pick_and_place": read_path_file("pick_and_place").path,
         "curve": read_path_file("curve").path,
         # a user's spline (coarse grids were not ordered on it)
         "user_spline": TaskPath.spline([(0.18, 0.20), (0.22, 0.13), (0.27, 0.21), (0.31, 0.15)])}
GRIDS = (2, 3, 4, 6, 10, 20, 40, 100, 250, 1000)
#: between the grid points: the planner holds every interval's midpoint to BETWEEN_TOL (1e-3)
#: of tau_max; elsewhere in an interval this sweep measures at most 1.1e-3 (10 points per
#: interval; the curve at 6 N m), so 1.5e-3 leaves room for rounding only
BETWEEN_MEASURED = 1.5e-3


@pytest.fixture(scope="module")
def m():
    return pm2dof.load_model()


@pytest.mark.parametrize("name", list(PATHS))
def test_any_grid_gives_a_feasible_conservative_plan(m, name):
    """Both splits, tau_max 30 (the model file's) and 6 N m, grids 2 ... 1000: never an error;
    every |tau_i| within tau_max at the grid points (to rounding) and between them (at 10
    points per interval, within BETWEEN_MEASURED); and never faster than the 1000-point plan:
    a coarse grid is conservative, not optimistic."""
    path = PATHS[name]
    for tau_max in (30.0, 6.0):
        for split in ("min_norm", "min_max"):
            d = {}
            for grid in GRIDS:
                plan = plan_time_optimal(m, path, tau_max, split, grid=grid)
                what = (name, tau_max, split, grid)
                assert (np.abs(plan.tau) <= plan.tau_max * (1 + 1e-9)).all(), what
                _, _, ratio = plan_torques(m, plan, factor=10)
                assert ratio.max() <= 1 + BETWEEN_MEASURED, (what, ratio.max())
                assert plan.info["midpoint_excess"] <= BETWEEN_TOL, what
                assert (plan.sdot >= 0).all() and plan.sdot[0] == plan.sdot[-1] == 0, what
                d[grid] = plan.duration
            assert min(d.values()) >= d[1000] * (1 - 1e-9), (name, tau_max, split, d)


@pytest.mark.parametrize("name, grid, tau_max, split", [
    ("line", 2, 30.0, "min_max"), ("line", 3, 30.0, "min_norm"),
    ("reviewer_line", 2, 30.0, "min_max"), ("reviewer_line", 3, 30.0, "min_norm"),
    ("pick_and_place", 100, 30.0, "min_max"), ("pick_and_place", 20, 30.0, "min_norm"),
    ("pick_and_place", 160, 6.0, "min_max"), ("curve", 20, 30.0, "min_max"),
    ("curve", 15, 6.0, "min_max"), ("curve", 40, 30.0, "min_norm")])
def test_the_passes_on_the_reviewers_coarse_grids(m, name, grid, tau_max, split):
    """The generated passes alone on the grids that failed (no refinement by the planner):
    each interval's s_dd lies in its feasible interval [L, U] leaving s_k and lands at or above
    rest, and every s_d^2 is finite, >= 0 and 0 at the stops."""
    path = PATHS.get(name) or TaskPath.line([0.2, 0.25], [0.3, 0.25])
    s = grid_points(path, grid)
    w = limits(m, tau_max, 1.0)
    prm, th = params(m, None)
    stops = np.searchsorted(s, path.stops)
    problem = PlanProblem(m, path, w, th, split, prm)
    stage, coef = stages(problem, s, stops)
    x, sdd, x_mvc, relaxed = solve_profile(problem, stage, s, coef)      # raised PlanError
    assert np.isfinite(x).all() and (x >= 0).all() and (x[stops] == 0).all()
    land = x[:-1] + 2 * np.diff(s) * sdd[:-1]
    assert (land >= -1e-9 * np.maximum(x_mvc[1:], 1e-12)).all()
    # under the maximum-velocity curve, to its bisection's resolution (v_top 2^-20: 1e-4 m/s)
    assert (np.sqrt(x) <= np.sqrt(np.maximum(x_mvc, 0)) + V_TOP * 2.0 ** -MVC_BISECTIONS).all()


def test_a_forward_failure_names_the_condition_that_failed():
    """The message names what went wrong, with its numbers (it once said "s_dd -15.1 below its
    lower bound -121.4" when the landing s_d^2 < 0 had failed)."""
    s = np.array([0.0, 0.1, 0.2])
    coef = {"p": np.array([[0.2, 0.25], [0.25, 0.25], [0.3, 0.25]])}
    h, mvc = np.ones(2), np.ones(3)
    ok = dict(x=np.array([0.0, 0.5, 0.0]), sdd=np.array([2.5, -2.5]), L=np.array([-9.0, -9.0]),
              U=np.array([9.0, 9.0]), Z=np.array([1.0, 1.0]))
    _check_forward(coef["p"], s, h=h, x_mvc=mvc, **ok)                        # consistent: silent
    cases = [(dict(x=np.array([0.0, 0.5, -0.1])), r"lands at s_d\^2 = -0.1 < 0 at s = 0.2 m"),
             (dict(sdd=np.array([2.5, -9.5])), r"s_dd = -9.5 m/s\^2 is outside its feasible "
                                               r"interval \[-9, 9\]"),
             (dict(sdd=np.array([9.5, -2.5])), r"s_dd = 9.5 m/s\^2 is outside"),
             (dict(Z=np.array([1.0, -0.25])), r"parallel to the path.s acceleration .* \(by 0.25 N\)")]
    for change, match in cases:
        with pytest.raises(pm2dof.PlanError, match=match) as e:
            _check_forward(coef["p"], s, h=h, x_mvc=mvc, **{**ok, **change})
        assert "interval leaving s = " in str(e.value)


def test_a_coarse_grid_is_refined_where_the_path_turns(m):
    """The planner halves every interval over which a joint angle or the tangent turns by more
    than RESOLUTION rad, before the passes: the plan's grid resolves the path, whatever was
    asked (the 0.57 m pick-and-place cycle at 2 points comes back with hundreds)."""
    path = PATHS["pick_and_place"]
    plan = plan_time_optimal(m, path, 6.0, grid=2)
    s = plan.s
    p, _, ddp = path.evaluate(s)
    q = np.array([m.ik(x) for x in p])
    dq = np.abs(np.angle(np.exp(1j * np.diff(q, axis=0)))).max(axis=1)
    kappa = np.hypot(*ddp.T)
    turn = np.maximum(kappa[:-1], kappa[1:]) * np.diff(s)
    assert np.maximum(dq, turn).max() <= RESOLUTION and plan.info["grid"] > 100
    assert plan_time_optimal(m, PATHS["line"], 6.0, grid=1000).info["grid"] == 1000
