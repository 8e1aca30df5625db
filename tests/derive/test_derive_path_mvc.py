# The maximum-velocity curve in closed form (affine friction) against the bisection it replaced.
"""For a friction law affine in |v| (Coulomb + viscous, eq. 2) every condition of a stage's
feasibility is a quadratic in s_d, and ``path_mvc`` is their least first crossing
(:meth:`pm2dof.derive.planning._Stage.largest_exact`). Here, on the stage rows of the bench
paths (both splits, friction and none, two torque limits, reversing joints):

* it is the bisection's answer (the predicate :meth:`_Stage.feasible` halved 44 times) where
  that one lands on the same stretch [0, s_d*] (the feasible set an interval there), to the
  bisection's resolution; elsewhere (the set is two intervals, near the stops of some paths)
  the bisection lands on another edge, and the closed form is at or below it;
* the predicate holds on all of [0, s_d*] (sampled) and fails just above it;
* the compiled ``path_mvc`` of the shipped model returns the same numbers.

An independent check (a linear program, friction-free) is in
tests/planning/test_planning_coefficients.py.
"""
import casadi as ca
import numpy as np
import pytest

import pm2dof
from pm2dof.bench.planning import bench_paths, friction_free
from pm2dof.core.model_file import read_model_file
from pm2dof.core.paths import SHIPPED_MODELS
from pm2dof.derive.planning import _PathFriction, _Stage, path_layouts
from pm2dof.planning.problem import PlanProblem
from pm2dof.planning.stages import grid_points, limits, params, stages
from tests import derivations

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

HALVINGS = 44


@pytest.fixture(scope="module")
def paper():
    """(model, exact, bisection, feasible): CasADi functions of (stage, params) of the paper's
    robot, from its shared derivation."""
    d = derivations.derivation(read_model_file(SHIPPED_MODELS / "shang2010.toml"))
    model = pm2dof.load_model("shang2010")
    n, m = d.spec.n_legs, d.m
    lays = path_layouts(n, len(d.spec.param_names), m)
    stage_v = ca.SX.sym("stage", lays["path_stage"].size)
    prm = ca.SX.sym("params", lays["path_params"].size)
    P = lays["path_params"].split(prm)
    friction = _PathFriction(d, P["theta"])
    assert friction.affine
    st = _Stage(n, lays["path_stage"].split(stage_v), friction, m)
    sd = ca.SX.sym("sd")
    exact = ca.Function("exact", [stage_v, prm], list(st.largest_exact(P["v_top"])))
    bis = ca.Function("bis", [stage_v, prm],
                      list(st.largest(P["v_top"], lambda v: st.feasible(v)[0], HALVINGS)))
    feas = ca.Function("feas", [stage_v, prm, sd], [st.feasible(sd)[0]])
    return model, exact, bis, feas


def _rows(model):
    """(stage rows, params) pairs: the bench paths' 300-point grids, both splits, nominal and
    friction-free theta, the default limits and 3 N m; with rho set on every fifth row."""
    line = pm2dof.TaskPath.line([0.22, 0.29], [0.27, 0.24])
    out = []
    rho = model.layout("path_stage").slices["rho"]
    for path in bench_paths(model, line).values():
        s = grid_points(path, 300)
        for split in ("min_norm", "min_max"):
            for theta in (None, friction_free(model)):
                for w in (None, 3.0):
                    prm, th = params(model, theta)
                    problem = PlanProblem(model, path, limits(model, w, 1.0), th, split, prm)
                    stage = stages(problem, s)[0]
                    stage[::5, rho] = 1.0
                    out.append((stage, prm))
    return out


def _feasible(feas, stage, prm, rows, v):
    """The predicate at speeds v (M,) of the stage rows ``rows`` (M,): bool (M,)."""
    M = len(rows)
    if not M:
        return np.zeros(0, dtype=bool)
    out = feas.map(M)(stage[rows].T, np.repeat(prm[:, None], M, axis=1), v[None, :])
    return np.asarray(out).ravel() > 0


def test_closed_form_is_the_bisection_and_the_edge_of_the_feasible_set(paper):
    model, exact, bis, feas = paper
    agree = total = 0
    for stage, prm in _rows(model):
        K = len(stage)
        ex = exact.map(K)(stage.T, np.repeat(prm[:, None], K, axis=1))
        bi = bis.map(K)(stage.T, np.repeat(prm[:, None], K, axis=1))
        e, ok0 = np.asarray(ex[0]).ravel(), np.asarray(ex[1]).ravel()
        b = np.asarray(bi[0]).ravel()
        assert np.array_equal(ok0, np.asarray(bi[1]).ravel())
        v_top, q = prm[0], prm[0] * 2.0 ** -HALVINGS
        k = np.flatnonzero(ok0 > 0)
        total += k.size
        # feasible on [0, e] (sampled, and just below e), not just above it
        frac = np.append(np.linspace(0, 1, 30)[:-1], 1 - 1e-9)
        rows, v = np.repeat(k, frac.size), (e[k, None] * frac).ravel()
        assert _feasible(feas, stage, prm, rows, v).all()
        top = k[e[k] < v_top]
        assert not _feasible(feas, stage, prm, top, e[top] * (1 + 1e-7) + 1e-9).any()
        same = k[b[k] <= e[k] + q]            # the bisection found the same edge
        agree += same.size
        assert (b[same] >= e[same] - q - 1e-12 * e[same]).all()
        assert (b[same] <= e[same] * (1 + 1e-12)).all()
        other = np.setdiff1d(k, same)         # another edge above: the set has a gap
        frac = np.linspace(0, 1, 200)[1:-1]
        rows = np.repeat(other, frac.size)
        v = (e[other, None] + (b[other] - e[other])[:, None] * frac).ravel()
        held = _feasible(feas, stage, prm, rows, v).reshape(len(other), frac.size)
        assert not held.all(axis=1).any()
    assert total > 10_000 and agree >= 0.99 * total, (agree, total)


def test_the_compiled_curve_is_the_closed_form(paper):
    model, exact, _, _ = paper
    for stage, prm in _rows(model)[::7]:
        K = len(stage)
        x = np.empty(K)
        model.function("path_mvc").map(K, stage, prm, x)
        e, ok0 = (np.asarray(v).ravel()
                  for v in exact.map(K)(stage.T, np.repeat(prm[:, None], K, axis=1)))
        want = np.where(ok0 > 0, e * e, -1.0)
        np.testing.assert_allclose(x, want, rtol=1e-14, atol=0)
