# A design evaluated at run time (Model.at_design) against the same design picked, written as a
# plain model file and derived conventionally: every objective and its counterparts agree.
"""For one seeded random design of each shipped design model (the paper's robot: a point on
RRR legs; rrr4_platform_design: a platform whose rods' inertia follows the lengths), the file
``design pick`` writes (:func:`pm2dof.synthesis.pick.text_at_design`) is derived and compiled
like a user's model file. On the two models, to 1e-9:

* the capability maps (``workspace_maps``: every field, NaN where NaN);
* ``plan_time_optimal`` on the model's first move (duration and torques), both splits;
* ``simulate`` with NA and APD on the high move (RMSE, torques);
* ``torque_splits`` at poses along the move;
* every measure of the design study objectives (``evaluate_design``).
"""
import numpy as np
import pytest

import pm2dof
from pm2dof.control.trajectory import line_moves
from pm2dof.core.paths import SHIPPED_MODELS
from pm2dof.derive.run import derive
from pm2dof.planning.pathfile import model_move_path
from pm2dof.synthesis.objectives import MEASURES, evaluate_design
from pm2dof.synthesis.pick import text_at_design
from pm2dof.synthesis.spec import find_design_study, read_design_study

pytestmark = pytest.mark.slow     # two derivations and compiles: make test-slow (CI)

CASES = {"shang2010_design": "paper_legs", "rrr4_platform_design": "rrr4_platform_legs"}
TOL = 1e-9


def _close(a, b, what):
    a, b = np.asarray(a, float), np.asarray(b, float)
    assert a.shape == b.shape, what
    assert np.array_equal(np.isnan(a), np.isnan(b)), what
    ok = ~np.isnan(a)
    scale = max(1.0, float(np.max(np.abs(b[ok]))) if ok.any() else 1.0)
    err = float(np.max(np.abs(a[ok] - b[ok]))) if ok.any() else 0.0
    assert err <= TOL * scale, f"{what}: {err:.3e} > {TOL} * {scale:.3g}"


@pytest.fixture(scope="module", params=sorted(CASES))
def pair(request, tmp_path_factory):
    name = request.param
    m = pm2dof.load_model(name)
    rng = np.random.default_rng(38)
    for _ in range(20):       # a random design whose moves and home are reachable
        values = {k: float(rng.uniform(lo, hi))
                  for k, (lo, hi) in zip(m.design_names, m.design_bounds)}
        try:
            m2 = m.at_design(values)
            break
        except pm2dof.DesignError:
            continue
    folder = tmp_path_factory.mktemp(name)
    path = folder / "picked.toml"
    path.write_text(text_at_design((SHIPPED_MODELS / f"{name}.toml").read_text(), values)[0])
    derive(path, progress=lambda *a: None)
    return name, m2, pm2dof.load_model(str(path))


def test_theta_and_geometry_are_the_conventional_files(pair):
    _, m2, c = pair
    _close(m2.theta_nominal, c.theta_nominal, "theta_nominal")
    assert m2.spec.legs == c.spec.legs
    assert m2.spec.sensing["closure_tolerance"] == c.spec.sensing["closure_tolerance"]


def test_maps(pair):
    _, m2, c = pair
    a, b = pm2dof.workspace_maps(m2, resolution=15), pm2dof.workspace_maps(c, resolution=15)
    assert set(a) == set(b)
    for k, v in a.items():
        if isinstance(v, np.ndarray) and v.dtype.kind == "f":
            _close(v, b[k], f"maps {k}")


@pytest.mark.parametrize("split", ["min_max", "min_norm"])
def test_plan_time_optimal(pair, split):
    _, m2, c = pair
    move = line_moves(m2)[0]
    pa, pb = model_move_path(m2, move).path, model_move_path(c, move).path
    a = pm2dof.plan_time_optimal(m2, pa, split=split, grid=300)
    b = pm2dof.plan_time_optimal(c, pb, split=split, grid=300)
    _close(a.duration, b.duration, "duration")
    _close(a.tau, b.tau, "plan torques")


@pytest.mark.parametrize("law", ["NAController", "APDController"])
def test_simulate(pair, law):
    _, m2, c = pair
    ra = pm2dof.simulate(m2, getattr(pm2dof, law)(m2), pm2dof.model_move(m2, "high"))
    rb = pm2dof.simulate(c, getattr(pm2dof, law)(c), pm2dof.model_move(c, "high"))
    _close(ra.rmse, rb.rmse, "rmse")
    _close(ra.tau_a, rb.tau_a, "simulated torques")
    _close(ra.xe, rb.xe, "simulated poses")


def test_torque_splits(pair):
    _, m2, c = pair
    move = pm2dof.model_move(m2, "high")
    for k in range(0, len(move.t), max(1, len(move.t) // 7)):
        q = m2.ik(move.xd[k])
        _close(q, c.ik(move.xd[k]), "ik")
        u = np.linspace(-3.0, 3.0, m2.dof)
        a, b = m2.torque_splits(q, u), c.torque_splits(q, u)
        for key in a:
            _close(a[key], b[key], f"torque_splits {key}")


def test_every_measure_of_the_design_study(pair):
    name, m2, c = pair
    study = read_design_study(find_design_study(CASES[name]))
    conv = read_design_study(find_design_study(CASES[name]), model=c.spec.path,
                             check_design=False)
    a, b = evaluate_design(m2, study), evaluate_design(c, conv)
    assert a.keys() == b.keys()
    for k in a:
        _close(a[k], b[k], k)
    assert {o.measure for o in study.objectives + study.constraints} <= set(MEASURES)
