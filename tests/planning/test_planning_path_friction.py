# path_friction (plan_smooth's g(y) in CasADi) against the generated path_torques, every law.
"""``pm2dof.planning.path_friction`` writes each friction law's speed-dependent part in CasADi,
so that IPOPT gets exact derivatives (it took the generated C through ``casadi.external`` with
finite differences: minutes per smoothed plan). The independent reference is the generated
``path_torques`` (derived by SymPy from pm2dof/derive/dynamics.py): its u at s_dd = 0 less
b y^2 is g(y). Checked on a model of every law, a platform with linear actuators and a model
with gravity, at the departing and the arriving stage rows of a move's grid (joints moving
both ways), at speeds from rest through the smoothing velocity to 3 m/s; the derivative
dg/dy against central differences of the same C. Both ways of forming g: by the law
(``law_friction``, every case) and as plan_smooth does (``path_friction``: the affine laws from
the C alone, as before).

Tolerances: the value, 1e-12 of the force's scale (the same sums in another order: a few
roundings of terms up to that size); the derivative, central differences with h = 1e-6 m/s,
truncation h^2 |g'''| / 6 and rounding 1e-16 |g| / h: 1e-6 of the scale, both well inside,
while an error in a coefficient (fv, fc, eps, the sign) is of the order of the scale itself."""
from types import SimpleNamespace

import numpy as np
import pytest

import pm2dof
from pm2dof.core.errors import PlanError
from pm2dof.core.mechanism import FRICTION_MODELS
from pm2dof.core.task import orientation_length
from pm2dof.planning import path_friction as pf
from pm2dof.planning.problem import PlanProblem
from pm2dof.planning.stages import grid_points, stages

casadi = pytest.importorskip("casadi")

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

#: (model, theta overrides): every friction law, a platform with linear actuators
#: (rpr3_platform), a platform with revolute ones, a point with sliders, gravity
CASES = [("shang2010", {}), ("shang2010_stribeck", {"fs": 0.2}), ("shang2010_smooth", {}),
         ("rpr3_platform", {}), ("rrr3_platform", {}), ("prr_point", {}),
         ("shang2010_vertical", {})]


def _problem(name, overrides):
    m = pm2dof.load_model(name)
    th = m.theta_nominal.copy()
    for key, value in overrides.items():
        th[[m.param_names.index(f"{key}{i + 1}") for i in range(m.n_legs)]] = value
    mv = m.spec.trajectories["low"]
    path = pm2dof.TaskPath.line(mv["start"], mv["end"], orientation_length(m))
    problem = PlanProblem.create(m, path, theta=th)
    s = grid_points(path, 40)
    stage, coef = stages(problem, s, [0, len(s) - 1])
    return problem, np.vstack([stage[:-1], coef["arrive"][1:]])


def _generated(problem, rows, y):
    """g(y) (K, m) from the generated path_torques: u(s_dd = 0) - b y^2."""
    m = problem.model
    K = len(rows)
    u = np.empty((K, m.dof))
    m.function("path_torques").map(K, rows, np.ascontiguousarray(y), 0.0, problem.params,
                                   problem.tau_max, u, None, None, None)
    return u - m.layout("path_stage").unpack(rows)["b"] * (y * y)[:, None]


def _speeds(K, rng):
    """K path speeds, m/s: rest, near the smoothing velocity (5 mm/s) and up to 3 m/s."""
    y = np.concatenate([np.zeros(3), rng.uniform(0, 0.02, K // 3), rng.uniform(0, 3.0, K)])
    return y[:K]


def _check(problem, rows, formed, name):
    """``formed(ysym)``: the m expressions of g; against the generated C, value and dg/dy."""
    K, dof = len(rows), problem.model.dof
    ysym = casadi.SX.sym("y", K)
    G = casadi.horzcat(*formed(ysym))
    g = casadi.Function("g", [ysym], [G])
    dg = casadi.Function("dg", [ysym], [casadi.jacobian(G.reshape((-1, 1)), ysym)])
    y = _speeds(K, np.random.default_rng(7))
    ref = _generated(problem, rows, y)
    scale = max(1.0, np.abs(ref).max())
    err = np.abs(np.array(g(y)) - ref).max()
    assert err <= 1e-12 * scale, (name, err, scale)
    moving = ref - _generated(problem, rows, np.zeros(K))   # the speed does change g
    assert np.abs(moving).max() > 1e-3 * scale
    h = 1e-6
    yc = np.maximum(y, h)                                   # the one-sided law at rest
    fd = (_generated(problem, rows, yc + h) - _generated(problem, rows, yc - h)) / (2 * h)
    J = np.array(dg(yc))                                     # (K m, K): d g[k, c] / d y_k
    d = np.array([[J[c * K + k, k] for c in range(dof)] for k in range(K)])
    off = J.copy()
    for c in range(dof):
        off[c * K + np.arange(K), np.arange(K)] = 0.0
    assert not off.any()                                    # g_k depends on y_k alone
    assert np.abs(d - fd).max() <= 1e-6 * max(scale, np.abs(fd).max()), name


@pytest.mark.parametrize("name,overrides", CASES, ids=[c[0] for c in CASES])
def test_the_law_equals_the_generated_torques(name, overrides):
    """Every law written in CasADi (law_friction), on every case, affine ones included."""
    problem, rows = _problem(name, overrides)
    v1 = problem.model.layout("path_stage").unpack(rows)["v1"]
    assert (v1 > 0).any() and (v1 < 0).any()          # joints moving both ways
    g0 = _generated(problem, rows, np.zeros(len(rows)))
    _check(problem, rows, lambda ys: pf.law_friction(problem, rows, ys, g0), name)


@pytest.mark.parametrize("name,overrides", CASES, ids=[c[0] for c in CASES])
def test_path_friction_equals_the_generated_torques(name, overrides):
    """What plan_smooth uses: affine laws from the C alone (as before: those plans unchanged
    to the bit), the others by the law."""
    problem, rows = _problem(name, overrides)
    affine = problem.model.spec.friction == "coulomb_viscous"
    assert pf.path_friction(problem, rows, casadi.SX.sym("y", len(rows)))[1] == (
        pf.AFFINE if affine else pf.BY_LAW)
    _check(problem, rows, lambda ys: pf.path_friction(problem, rows, ys)[0], name)


def test_a_stribeck_term_of_zero_is_affine():
    """shang2010_stribeck's [nominal] fs = 0: g is Coulomb + viscous, formed from the C."""
    problem, rows = _problem("shang2010_stribeck", {})
    assert pf.path_friction(problem, rows, casadi.SX.sym("y", len(rows)))[1] == pf.AFFINE


def test_every_friction_law_has_a_casadi_form():
    """A law added to FRICTION_MODELS must be written in path_friction.py too."""
    assert set(pf.LAWS) == set(FRICTION_MODELS)


def test_an_unknown_law_is_a_plan_error():
    fake = SimpleNamespace(spec=SimpleNamespace(friction="dahl", friction_constants={}))
    with pytest.raises(PlanError, match=r"friction law 'dahl' has no CasADi form in "
                                        r"pm2dof/planning/path_friction.py \(known: "):
        pf.moving_friction(fake, [], casadi.SX.sym("v"), 1.0, 0)
