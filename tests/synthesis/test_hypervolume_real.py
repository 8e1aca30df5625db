# NSGA-II against exhaustive search on two real two-variable design problems.
"""NSGA-II's front reaches >= 99 % of the hypervolume of a 100 x 100 grid's front on two real
design problems, each with both runs' objectives computed by the same functions
(``objectives.evaluate_batch``, every design a ``Model.at_design``) and one reference point for
both fronts (``front.reference_point`` over the two):

* the paper's robot with la and lb each tied across its three legs (``shang2010_design``; b2x at
  the file's value), over the shipped ``paper_legs`` bounds [0.18, 0.32] m;
* the 4-RRR platform's la and lb, each tied across its four legs (``rrr4_platform_design``),
  over [0.15, 0.26] m.

The objectives are cheap but real and in conflict: the mean type II measure (dexterity) over a
7 x 7 grid of the shipped study's region (a platform at its home orientation), maximised,
against the total link length, minimised. The grid's 10,000 designs take about 10 to 20 s per
problem here. Besides the ratio, the test checks what makes it meaningful: both fronts hold many
designs, each evaluated (status "ok": the platform's smallest designs cannot reach its home or
moves, a DesignError with the worst values), and the link length of each front point is its la
and lb summed over the legs.
"""
import dataclasses

import numpy as np
import pytest

from pm2dof.synthesis.front import front_indices, hypervolume, reference_point
from pm2dof.synthesis.objectives import evaluate_batch
from pm2dof.synthesis.optimize import optimize
from pm2dof.synthesis.spec import FrozenMapping, Objective, find_design_study, read_design_study

pytestmark = pytest.mark.slow     # 2 x 10,000 designs and 2 x 1,600: make test-slow

#: problem -> (shipped study, legs)
PROBLEMS = {"paper robot, la and lb": ("paper_legs", 3),
            "4-RRR platform, la and lb": ("rrr4_platform_legs", 4)}


def _study(name):
    st = read_design_study(find_design_study(name))
    region = FrozenMapping({"x": tuple(st.region["x"]), "y": tuple(st.region["y"]), "n": 7,
                            "phi": None, "n_phi": 1})
    objs = (Objective("dexterity_mean", "dexterity_mean", "max", FrozenMapping({})),
            Objective("link_length", "link_length", "min", FrozenMapping({})))
    return dataclasses.replace(st, region=region, objectives=objs, constraints=(), paths=())


@pytest.mark.parametrize("problem", sorted(PROBLEMS))
def test_nsga2_reaches_99_percent_of_the_100x100_grid_hypervolume(problem):
    name, legs = PROBLEMS[problem]
    st = _study(name)
    assert st.variables == ("la", "lb")
    statuses = {"grid": [], "nsga2": []}

    def evaluate(label):
        def run(X):
            F, G, rows = evaluate_batch(st, X)
            statuses[label].extend(r["status"] for r in rows)
            return F, G
        return run

    grid = optimize(evaluate("grid"), st.bounds, 2, 0, kind="grid", grid=100)
    nsga = optimize(evaluate("nsga2"), st.bounds, 2, 0, kind="nsga2", population=40,
                    generations=40, seed=1)
    assert len(grid.X) == 10000 and len(nsga.X) <= 1600
    fronts = {}
    for label, res in (("grid", grid), ("nsga2", nsga)):
        i = front_indices(res.F, res.feasible, res.X)
        assert len(i) >= 20, (label, len(i))                       # a front, not a point
        # every front design was evaluated (a design the model refuses, its home or a move
        # out of reach, has the worst values and is dominated)
        assert {statuses[label][j] for j in i} == {"ok"}
        # the second objective is the link length: legs * (la + lb)
        np.testing.assert_allclose(res.F[i, 1], legs * res.X[i].sum(axis=1), rtol=1e-12)
        fronts[label] = res.F[i]
    ref = reference_point(fronts["grid"], fronts["nsga2"])
    hv_grid = hypervolume(fronts["grid"], ref)
    hv_nsga = hypervolume(fronts["nsga2"], ref)
    assert hv_grid > 0
    assert hv_nsga >= 0.99 * hv_grid, (problem, hv_nsga / hv_grid)
