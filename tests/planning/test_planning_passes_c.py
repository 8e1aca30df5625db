"""The planner's passes in C (pm2dof/planning/_passes.c, pm2dof.planning.cpasses.solve_c)
against the NumPy ones (stages.link, then grid.passes) on every round of real plans, bit for
bit: a point robot, a platform, linear actuators and gravity, both splits, with and without
friction; and the errors of the C entry point."""
import numpy as np
import pytest

import pm2dof
from pm2dof.bench.baselines import friction_free
from pm2dof.control.trajectory import line_moves
from pm2dof.planning import _passes
from pm2dof.planning import grid as grid_module
from pm2dof.planning.cpasses import solve_c
from pm2dof.planning.pathfile import model_move_path, read_path_file
from pm2dof.planning.problem import PlanProblem
from pm2dof.planning.stages import _coefficients, _fill, link, point_stages

# the paper's robot (with its shipped paths), its vertical variant (gravity), a point robot
# on linear actuators, a 4-RRR platform and a 3-RPR platform (linear actuators)
MODELS = ["shang2010", "shang2010_vertical", "prr_point", "rrr4_platform", "rpr3_platform"]


def _bits(a):
    return np.ascontiguousarray(a).view(np.int64)


def _grid(m, path, s):
    """The planner's Grid of ``path`` on the arc lengths ``s`` (the default problem)."""
    return grid_module.Grid(PlanProblem.create(m, path), s, path.evaluate(s))


@pytest.mark.parametrize("name", MODELS)
def test_every_round_of_the_c_passes_equals_the_numpy_passes(name, monkeypatch):
    m = pm2dof.load_model(name)
    paths = [model_move_path(m, k).path for k in line_moves(m)]
    if name == "shang2010":
        paths += [read_path_file(k).path for k in ("pick_and_place", "curve")]
    rounds, relaxed = [], 0
    solve = grid_module.Grid.solve

    def compared(self):
        out = solve(self)
        stage, arrive = link(self.problem, self.s, self.base, self.v1, self.stops(), self.left)
        ref = grid_module.passes(self.problem, stage, arrive, self.s, self.ev[0])
        for got, want, what in zip(out, ref, ("x", "sdd", "x_mvc")):
            assert np.array_equal(_bits(got), _bits(want)), what
        assert np.array_equal(out[3], ref[3])
        assert np.array_equal(_bits(self.stage), _bits(stage))
        rounds.append(len(self.s))
        return out

    monkeypatch.setattr(grid_module.Grid, "solve", compared)
    for path in paths:
        for split in ("min_max", "min_norm"):
            for theta in (None, friction_free(m)):
                plan = pm2dof.plan_time_optimal(m, path, split=split, theta=theta, grid=300)
                relaxed += len(plan.info["arrival_relaxed"])
    assert len(rounds) >= 4 * len(paths)
    if name == "shang2010":
        assert relaxed > 0      # the rows the arrival facets fail on were compared too


def test_the_c_passes_refuse_wrong_arguments():
    m = pm2dof.load_model()
    path = read_path_file("curve").path
    g = _grid(m, path, pm2dof.plan_time_optimal(m, path, grid=50).s)   # a planner's grid
    ln = g.linking
    assert solve_c(ln, g.s, g.base, g.v1, g.stops()) is not None
    K, S = g.base.shape
    args = [*ln.fns, ln.problem.params, g.s, g.base, g.v1, np.zeros(K), ln.left, ln.junctions,
            ln.offsets, np.empty((K, S)), np.empty(K), np.empty(K), np.empty(K),
            np.empty(K - 1), np.empty(K), np.empty(K), np.empty((K - 1, ln.y_size)),
            np.empty(K), None]
    bad = list(args)
    bad[5] = g.base[:-1]
    with pytest.raises(ValueError, match=r"base must hold \d+ entries, got \d+"):
        _passes.solve(*bad)
    bad = list(args)
    bad[0] = m.function("path_forward")
    with pytest.raises(TypeError, match="expected 2 inputs and 1 outputs"):
        _passes.solve(*bad)
    bad = list(args)
    bad[0] = np.zeros(3)
    with pytest.raises(TypeError, match="expected a pm2dof.core._cbind.Function"):
        _passes.solve(*bad)
    bad = list(args)
    bad[10] = ln.offsets.astype(float)
    with pytest.raises(TypeError, match="offsets must be a contiguous int64 array"):
        _passes.solve(*bad)
    bad = list(args)
    bad[-1] = (g.s,)
    with pytest.raises(TypeError, match=r"prev must be None or \(s, stage"):
        _passes.solve(*bad)
    assert _passes.solve(*args) == 0    # at rest everywhere (x_cap 0): a plan of zeros
    assert not args[12].any()


def test_where_the_c_passes_fail_the_numpy_passes_name_the_place():
    """Limits below the Coulomb friction: the C passes return 1 and the planner raises the
    NumPy passes' PlanError (the arc length and the point)."""
    m = pm2dof.load_model()
    path = read_path_file("curve").path
    with pytest.raises(pm2dof.PlanError, match=r"cannot move the robot along the path at s = "):
        pm2dof.plan_time_optimal(m, path, tau_max=0.05, grid=50)


@pytest.mark.parametrize("name", MODELS)
@pytest.mark.parametrize("split", ["min_max", "min_norm"])
def test_the_c_rows_equal_the_coefficients_placed_by_numpy(name, split):
    """stages.point_stages' rows from one C call (path_coefficients written into each row)
    against the map's outputs placed by stages._fill, bit for bit, and the v1 and the
    singularity measures beside them."""
    m = pm2dof.load_model(name)
    path = model_move_path(m, line_moves(m)[0]).path
    problem = PlanProblem.create(m, path, split=split)
    s = np.linspace(0.0, path.length, 101)
    ev = path.evaluate(s)
    stage, outs = point_stages(problem, s, ev)
    ref = _coefficients(problem, *ev)
    want = np.zeros_like(stage)
    _fill(m, want, ref, split)
    assert np.array_equal(_bits(stage), _bits(want))
    for key in ("v1", "sing"):
        assert np.array_equal(_bits(outs[key]), _bits(ref[key])), key


def test_a_solve_on_the_same_grid_takes_every_step_from_the_previous_one():
    """With a previous solve on the same grid nothing can have changed: the maximum-velocity
    curve, the bounds and every forward step are taken from it, none evaluated again (shown by
    a previous solve whose values were altered: they come back)."""
    m = pm2dof.load_model()
    path = read_path_file("curve").path
    g = _grid(m, path, np.linspace(0.0, path.length, 400))
    stops = g.stops()
    first = solve_c(g.linking, g.s, g.base, g.v1, stops)
    s, stage, x_mvc, cap, hi, y, x_raw = first[5]
    altered = (s, stage, x_mvc * 2, cap, hi, y + 1.0, x_raw)
    again = solve_c(g.linking, g.s, g.base, g.v1, stops, altered)
    assert np.array_equal(again[3], 2 * first[3])               # x_mvc reused
    assert np.array_equal(again[2][:-1], first[2][:-1] + 1.0)    # every forward step reused
    fresh = solve_c(g.linking, g.s, g.base, g.v1, stops, first[5])
    for a, b in zip(fresh[:4], first[:4]):
        assert np.array_equal(_bits(a), _bits(b))


def test_a_point_whose_arriving_interval_changed_gets_its_cap_computed_again():
    """A point added just before the far end of an interval on which a joint reverses makes
    that end's arriving interval one without the reversal: its arrival facets, and so its cap,
    differ from the previous solve's although its own row does not. With every cap of the
    previous solve altered, that point's cap is the one a solve from scratch computes, and a
    point whose rows are both unchanged takes the altered one."""
    m = pm2dof.load_model()
    path = read_path_file("pick_and_place").path
    s0 = np.linspace(0.0, path.length, 300)
    g = _grid(m, path, s0)
    sign = g.v1 >= 0
    reversing = np.flatnonzero((sign[:-1] != sign[1:]).any(axis=1))
    assert reversing.size >= 3
    s, stage, x_mvc, cap, hi, y, x_raw = solve_c(g.linking, g.s, g.base, g.v1, g.stops())[5]
    altered = (s, stage, x_mvc, cap + 1.0, hi, y, x_raw)
    for k in reversing[:3]:
        g2 = _grid(m, path, s0)
        g2.insert(np.array([s0[k + 1] - 1e-4 * (s0[k + 1] - s0[k])]))
        assert ((g2.v1[k + 1] >= 0) == sign[k + 1]).all()   # the added point: k + 1's side
        again = solve_c(g2.linking, g2.s, g2.base, g2.v1, g2.stops(), altered)[5][3]
        fresh = solve_c(g2.linking, g2.s, g2.base, g2.v1, g2.stops())[5][3]
        assert _bits(again[k + 2]) == _bits(fresh[k + 2]) and again[k + 2] != cap[k + 1] + 1.0
        assert again[k + 4] == cap[k + 3] + 1.0          # unchanged rows: the previous cap


def test_no_point_gives_no_row():
    m = pm2dof.load_model()
    path = read_path_file("curve").path
    empty = np.empty((0, 2))
    stage, outs = point_stages(PlanProblem.create(m, path), np.empty(0), (empty,) * 3)
    assert stage.shape == (0, m.layout("path_stage").size) and outs["v1"].shape == (0, 3)
