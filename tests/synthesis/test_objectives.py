# Each design objective equals its counterpart computed directly on a shipped fixed model.
"""The measures of pm2dof.synthesis.objectives against the functions they stand for.

On one model of every kind (the paper's point RRR, a 4-RRR platform, a PRR point and a PRR
platform with linear actuators, the paper's robot under gravity), ``evaluate_design(m, study)``
must equal what ``workspace_maps`` / ``maps_summary``, ``plan_time_optimal``, ``simulate`` and
``Model.torque_splits`` give when called directly, to 1e-9. The region measures are also
checked point by point (the batched capability against ``capability`` pose by pose), and the
failure rules: no NaN, worst values, statuses. ``evaluate_batch`` runs end to end with a shim
``at_design`` (the fixed model itself at its file's geometry, a DesignError elsewhere).
"""
import math

import numpy as np
import pytest

import pm2dof
from pm2dof.analysis.maps import _grid, capability, maps_summary, workspace_maps
from pm2dof.control.trajectory import model_move
from pm2dof.planning import model_move_path, plan_kinematic, plan_time_optimal
from pm2dof.planning.torques import REST
from pm2dof.synthesis import evaluate_batch, evaluate_design, evaluate_with_status
from pm2dof.synthesis import objectives as obj
from pm2dof.synthesis.spec import read_design_study

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

KINDS = ["shang2010", "rrr4_platform", "prr_point", "prr3_platform", "rpr3_platform",
         "shang2010_vertical"]
RES = 13          # the maps' grid: points per axis
TOL = 1e-9


@pytest.fixture(scope="module")
def models():
    return {}


def _model(models, name):
    if name not in models:
        models[name] = pm2dof.load_model(name)
    return models[name]


def _f(x):
    return repr(float(x))


def _study(tmp_path, model, body, name="s"):
    p = tmp_path / f"{name}.toml"
    p.write_text(f'[study]\nname = "{name}"\nmodel = "{model}"\n' + body)
    return read_design_study(p, check_design=False)


def _maps_region(m):
    """The maps' own grid as a study region (a platform at its home orientation)."""
    phi = None if m.dof == 2 else float(m.spec.home[2])
    x, y = _grid(m, RES, phi)
    reg = f"x = [{_f(x[0])}, {_f(x[-1])}], y = [{_f(y[0])}, {_f(y[-1])}], n = {RES}"
    if phi is not None:
        reg += f", phi = [{_f(phi)}, {_f(phi)}]"
    return "[task]\nregion = { " + reg + " }\n"


def _close(a, b, what):
    assert abs(a - b) <= TOL * max(1.0, abs(b)), f"{what}: {a!r} vs {b!r}"


@pytest.mark.parametrize("name", KINDS)
def test_region_measures_equal_the_maps(models, name, tmp_path):
    m = _model(models, name)
    body = _maps_region(m) + "".join(
        f'[[objectives]]\nname = "{k}"\nmeasure = "{k}"\n'
        for k in ("clear_area", "dexterity_min", "dexterity_mean"))
    for split in ("min_max", "min_norm"):
        for q in ("force", "accel"):
            body += f'[[objectives]]\nname = "{q}_{split}"\nmeasure = "{q}"\nsplit = "{split}"\n'
    study = _study(tmp_path, name, body)
    values, status = evaluate_with_status(m, study)
    assert status == "ok"
    maps = workspace_maps(m, resolution=RES)
    summary = maps_summary(m, maps)
    _close(values["clear_area"], summary["clear_area"], "clear_area")
    # reachability: the generated ik over the grid against the maps' own test
    r = obj._region(study, m, {})
    assert np.array_equal(r["reach"].reshape(RES, RES), maps["reachable"]), name
    type2 = np.where(maps["reachable"], maps["type2"], 0.0)
    _close(values["dexterity_min"], float(type2.min()), "dexterity_min")
    _close(values["dexterity_mean"], float(type2.mean()), "dexterity_mean")
    for split in ("min_max", "min_norm"):
        caps = obj._capability(study, m, {"split": split}, {})
        for q in ("force", "accel"):
            want = np.nan_to_num(maps[f"{q}_{split}"], nan=0.0).ravel()
            got = caps[f"{q}_{split}"]
            assert np.allclose(got, want, rtol=TOL, atol=TOL), \
                (name, q, split, float(np.max(np.abs(got - want))))
            _close(values[f"{q}_{split}"], float(want.min()), f"{q}_{split}")


def _inner_region(m):
    """A small region around the model's first move, inside the workspace."""
    mv = next(iter(m.spec.trajectories.values()))
    a, b = np.asarray(mv["start"], float), np.asarray(mv["end"], float)
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    reg = (f"x = [{_f(lo[0])}, {_f(hi[0])}], y = [{_f(lo[1])}, {_f(hi[1])}], n = 5")
    if m.dof == 3:
        reg += f", phi = [{_f(lo[2])}, {_f(hi[2])}], n_phi = 2"
    return reg


@pytest.mark.parametrize("name", KINDS)
def test_capability_inside_the_workspace_pose_by_pose(models, name, tmp_path):
    """Where every point is reachable, force and accel are the least of ``capability`` over
    the grid's poses, computed one by one."""
    m = _model(models, name)
    study = _study(tmp_path, name, "[task]\nregion = { " + _inner_region(m) + " }\n"
                   '[[objectives]]\nmeasure = "force"\n'
                   '[[objectives]]\nmeasure = "accel"\nsplit = "min_norm"\n')
    values = evaluate_design(m, study)
    from pm2dof.synthesis.region import grid_points
    pts, _, _ = grid_points(study.region, m)
    each = [capability(m, m.ik(p)) for p in pts]
    _close(values["force"], min(c["force_min_max"] for c in each), "force")
    _close(values["accel"], min(c["accel_min_norm"] for c in each), "accel")
    assert values["force"] > 0 and values["accel"] > 0


def _margin_each(m, pts):
    """min over points of min(type I - thr, type II - thr), -1 out of reach, pose by pose."""
    worst = math.inf
    for p in pts:
        try:
            q = m.ik(p)
        except pm2dof.WorkspaceError:
            worst = min(worst, -1.0)
            continue
        s = m.singularity_measures(q)
        worst = min(worst, s[0] - m.singularity_threshold,
                    s[1] - m.parallel_singularity_threshold)
    return worst


@pytest.mark.parametrize("name", KINDS)
def test_time_optimal_rollout_torques_and_margin(models, name, tmp_path):
    """duration = plan_time_optimal, rmse = simulate, peak torque and preload margin from
    Model.torque_splits sample by sample, margin from ik and singularity_measures."""
    m = _model(models, name)
    body = ("[task]\nregion = { " + _inner_region(m) + " }\n"
            '[[objectives]]\nmeasure = "duration"\npath = "high"\ngrid = 200\n'
            '[[objectives]]\nname = "duration_mn"\nmeasure = "duration"\npath = "low"\n'
            'split = "min_norm"\ngrid = 200\n'
            '[[objectives]]\nmeasure = "rmse"\nlaw = "na"\npath = "high"\n'
            '[[objectives]]\nmeasure = "peak_torque"\npath = "high"\n'
            '[[objectives]]\nname = "peak_mn"\nmeasure = "peak_torque"\npath = "high"\n'
            'split = "min_norm"\n'
            '[[constraints]]\nmeasure = "preload_margin"\npath = "high"\nge = 0.0\n'
            '[[constraints]]\nmeasure = "margin"\npaths = ["low"]\nge = 0.0\n')
    study = _study(tmp_path, name, body)
    values, status = evaluate_with_status(m, study)
    assert status == "ok", status
    high = model_move_path(m, "high")
    want = plan_time_optimal(m, high.path, split="min_max", grid=200).duration
    assert values["duration"] == want
    want = plan_time_optimal(m, model_move_path(m, "low").path, split="min_norm",
                             grid=200).duration
    assert values["duration_mn"] == want
    r = pm2dof.simulate(m, pm2dof.NAController(m), model_move(m, "high"))
    assert values["rmse"] == r.rmse
    # the inverse dynamics of the high move's S-curve, then the splits, sample by sample
    plan = plan_kinematic(high.path, period=m.sample_period, **high.kinematic)
    _, dp, ddp = high.path.evaluate(plan.s)
    th = m.theta_nominal
    peak = {"min_max": 0.0, "min_norm": 0.0}
    margin = math.inf
    sgn = np.broadcast_to(np.asarray(m.spec.control["preload_sign"], float), (m.n_legs,))
    pre = np.broadcast_to(np.asarray(m.spec.control["preload"], float), (m.n_legs,))
    for k, (p, s_d, s_dd) in enumerate(zip(plan.trajectory.xd, plan.sdot, plan.sddot)):
        q = m.ik(p)
        v = dp[k] * max(s_d, REST)
        acc = dp[k] * s_dd + ddp[k] * s_d ** 2
        u = m.Me(q, th) @ acc + (m.Ce(q, v, th) @ v if s_d > 0 else 0.0) + m.StF(q, v, th)
        if m.spec.has_gravity:
            u = u + m.Ge(q, th)
        t = m.torque_splits(q, u)
        for split in peak:
            peak[split] = max(peak[split], float(np.max(np.abs(t[split]))))
        margin = min(margin, float(np.min(t["preload"] * sgn - pre)))
    _close(values["peak_torque"], peak["min_max"], "peak_torque")
    _close(values["peak_mn"], peak["min_norm"], "peak_torque min_norm")
    _close(values["preload_margin"], margin, "preload_margin")
    # margin: the region's points and the low move's samples every 0.5 mm
    from pm2dof.synthesis.region import grid_points
    low = model_move_path(m, "low").path
    n = max(2, int(np.ceil(low.length / 5e-4)) + 1)
    s = np.union1d(np.linspace(0.0, low.length, n), low.breakpoints)
    pts = np.concatenate([grid_points(study.region, m)[0], low.evaluate(s)[0]])
    _close(values["margin"], _margin_each(m, pts), "margin")
    assert values["margin"] > 0
    linear = {leg.actuator for leg in m.spec.legs} == {"prismatic"}     # PRR and RPR legs
    assert obj.measure_unit("peak_torque", m) == ("N" if linear else "N m")


@pytest.mark.parametrize("law", ["apd", "ctc", "lqr"])
def test_rmse_of_every_law(models, law, tmp_path):
    m = _model(models, "shang2010")
    study = _study(tmp_path, "shang2010", f'[[objectives]]\nmeasure = "rmse"\nlaw = "{law}"\n'
                   f'path = "low"\nsplit = "min_norm"\nquantise = false\n')
    from pm2dof.studies.evaluate import make_controller
    from pm2dof.studies.spec import Variant
    traj = model_move(m, "low")
    ctrl = make_controller(m, Variant(law, law, (("split", "min_norm"),), ()), traj)
    assert evaluate_design(m, study)["rmse"] == pm2dof.simulate(m, ctrl, traj,
                                                               quantise=False).rmse


def test_a_study_path_file(models, tmp_path):
    """A path of [task] paths: duration and peak torque along it (the shipped curve)."""
    m = _model(models, "shang2010")
    study = _study(tmp_path, "shang2010", '[task]\npaths = ["curve"]\n'
                   '[[objectives]]\nmeasure = "duration"\npath = "curve"\ngrid = 200\n'
                   '[[objectives]]\nmeasure = "rmse"\nlaw = "apd"\npath = "curve"\n'
                   '[[constraints]]\nmeasure = "margin"\nregion = false\nge = 0.0\n')
    values, status = evaluate_with_status(m, study)
    assert status == "ok"
    curve = pm2dof.planning.pathfile.read_path_file("curve")
    assert values["duration"] == plan_time_optimal(m, curve.path, grid=200).duration
    traj = plan_kinematic(curve.path, period=m.sample_period, **curve.kinematic).trajectory
    assert values["rmse"] == pm2dof.simulate(m, pm2dof.APDController(m), traj).rmse
    assert 0 < values["margin"] < 1


def test_out_of_reach_and_failures_give_worst_values(models, tmp_path):
    """A region reaching beyond the workspace: 0 capability and dexterity, margin -1; a plan
    the limits cannot hold: FAILED with the reason in the status; never NaN."""
    m = _model(models, "shang2010")
    study = _study(tmp_path, "shang2010",
                   "[task]\nregion = { x = [0.0, 0.6], y = [0.0, 0.6], n = 9 }\n"
                   '[[objectives]]\nmeasure = "dexterity_min"\n'
                   '[[objectives]]\nmeasure = "dexterity_mean"\n'
                   '[[objectives]]\nmeasure = "force"\n'
                   '[[objectives]]\nmeasure = "clear_fraction"\n'
                   '[[objectives]]\nmeasure = "duration"\npath = "high"\ntau_max = 0.01\n'
                   '[[objectives]]\nname = "slowest"\nmeasure = "duration"\npath = "high"\n'
                   'tau_max = 0.01\nsense = "max"\n'
                   '[[constraints]]\nmeasure = "margin"\nge = 0.0\n'
                   '[[constraints]]\nname = "quick_enough"\nmeasure = "duration"\npath = "high"\n'
                   'tau_max = 0.01\nle = 0.3\n')
    values, status = evaluate_with_status(m, study)
    assert all(math.isfinite(v) for v in values.values()), values
    assert values["dexterity_min"] == 0.0 and values["force"] == 0.0
    assert values["margin"] == -1.0
    assert 0 < values["clear_fraction"] < 1 and 0 < values["dexterity_mean"] < 1
    assert values["duration"] == obj.FAILED and values["quick_enough"] == obj.FAILED
    assert values["slowest"] == -obj.FAILED
    assert status.startswith("failed: duration: ") and "quick_enough" in status


def test_evaluate_batch_with_a_shim_design(models, tmp_path, monkeypatch):
    """F minimises (max negated), G is pymoo's (<= 0 met), rows carry the design and the
    status; a design the model refuses gets worst values and a design_error status."""
    import dataclasses
    m = _model(models, "shang2010")
    study = _study(tmp_path, "shang2010",
                   "[task]\nregion = { x = [0.22, 0.27], y = [0.24, 0.29], n = 5 }\n"
                   '[[objectives]]\nmeasure = "dexterity_mean"\n'
                   '[[objectives]]\nmeasure = "link_length"\n'
                   '[[constraints]]\nmeasure = "margin"\nge = 0.05\n'
                   '[[constraints]]\nname = "short"\nmeasure = "link_length"\nle = 1.5\n')
    study = dataclasses.replace(study, variables=("la",), bounds=((0.18, 0.32),))

    def at_design(self, values):
        if values != {"la": 0.244}:
            raise pm2dof.DesignError(f"design variable 'la' = {values['la']} (shim: only the "
                                     f"file's 0.244)")
        return self
    monkeypatch.setattr(type(m), "at_design", at_design, raising=False)
    monkeypatch.setattr(obj, "base_model", lambda st: m)
    F, G, rows = evaluate_batch(study, [[0.244], [0.3]])
    want = evaluate_design(m, study)
    assert F.shape == (2, 2) and G.shape == (2, 2)
    assert F[0].tolist() == [-want["dexterity_mean"], want["link_length"]]
    assert G[0].tolist() == [0.05 - want["margin"], want["link_length"] - 1.5]
    assert (G[0] <= 0).all()
    assert rows[0] == {"la": 0.244, **want, "status": "ok"}
    assert rows[1]["status"].startswith("design_error: design variable 'la' = 0.3")
    assert F[1].tolist() == [-0.0, obj.FAILED] and G[1].tolist() == [0.05 + 1.0,
                                                                      obj.FAILED - 1.5]
    assert np.isfinite(F).all() and np.isfinite(G).all()
    with pytest.raises(pm2dof.ArgumentError, match="one column per design variable"):
        evaluate_batch(study, [[0.244, 0.2]])


def test_link_length_and_moving_mass():
    spec = pm2dof.load_model("shang2010").spec
    assert obj.link_length(spec) == pytest.approx(6 * 0.244, abs=1e-15)
    with pytest.raises(pm2dof.ArgumentError, match="lumped"):
        obj.moving_mass(spec)

    class WithBodies:                      # a spec whose links are bodies, one of them a rod
        def __init__(self, spec, bodies):
            self._spec, self.links = spec, {"nominal": bodies, "plant": None}

        def __getattr__(self, k):
            return getattr(self._spec, k)
    bodies = [{"proximal": {"density": 2.0}, "distal": {"mass": 0.3, "com": 0.1,
                                                        "inertia": 0.001}}] * 3
    assert obj.moving_mass(WithBodies(spec, bodies)) == pytest.approx(3 * (2.0 * 0.244 + 0.3),
                                                                      abs=1e-15)
    plat = pm2dof.load_model("rrr4_platform").spec
    assert obj.link_length(plat) == pytest.approx(4 * 0.4, abs=1e-15)
    bodies = [{"proximal": {"mass": 0.6}, "distal": {"mass": 0.4}}] * 4
    m_p = float(plat.theta_nominal[plat.param_names.index("m_p")])
    assert obj.moving_mass(WithBodies(plat, bodies)) == pytest.approx(4.0 + m_p, abs=1e-15)
