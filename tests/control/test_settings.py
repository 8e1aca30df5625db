# The settings every controller shares (pm2dof.control.settings): one home for defaults and checks.
"""``ControlSettings.from_spec`` is where a controller's sample period, velocity filter, effort
limits, split, preload and the model file's thresholds default and are checked; the
controllers take one (``settings=``) or build one from their keywords; ``law_params`` packs a
law's default parameter vector without building a controller (what ``pm2dof export`` writes);
``actuator_limits`` is the one default and check of ``tau_max`` for the planner, the maps and
the splits. The expected values are read from the model files themselves (tomllib), not from
pm2dof's reader."""
import tomllib
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof.control import controllers
from pm2dof.control.settings import ControlSettings, actuator_limits
from pm2dof.control.trajectory import line_moves
from pm2dof.core.errors import ArgumentError, ArgumentTypeError, PlanError

MODELS = Path(pm2dof.__file__).resolve().parent / "models"
#: a platform, linear actuators (a platform and a point) and gravity
KINDS = ["rrr4_platform", "prr3_platform", "prr_point", "shang2010_vertical"]


def _toml(name):
    with open(MODELS / f"{name}.toml", "rb") as fh:
        return tomllib.load(fh)


def _per_leg(value, n):
    return np.broadcast_to(np.asarray(value, dtype=float), (n,))


@pytest.fixture(scope="module", params=KINDS)
def model(request):
    return pm2dof.load_model(request.param)


def test_the_defaults_are_the_model_files(model):
    raw = _toml(model.name)
    n = model.n_legs
    s = ControlSettings.from_spec(model.spec)
    assert s.sample_period == raw["sensing"]["sample_period"]
    assert s.velocity_filter_hz == raw["sensing"]["velocity_filter_hz"]
    assert np.array_equal(s.tau_max, _per_leg(raw["limits"]["tau_max"], n))
    assert s.singularity_threshold == raw["limits"]["singularity_threshold"]
    ctl = raw.get("control", {})
    assert s.split == ctl.get("split", "min_norm")
    assert np.array_equal(s.preload, _per_leg(ctl.get("preload", 0.0), n))
    assert np.array_equal(s.preload_sign, _per_leg(ctl.get("preload_sign", 1.0), n))
    # the velocity gain of a first-order low-pass: T / (T + 1 / (2 pi fc))
    fc, T = s.velocity_filter_hz, s.sample_period
    assert s.vel_alpha == pytest.approx(1.0 if fc == 0 else T / (T + 1 / (2 * np.pi * fc)),
                                        rel=1e-15)
    for a in (s.tau_max, s.preload, s.preload_sign):
        assert not a.flags.writeable


def test_overrides_are_checked_with_who_names_them(model):
    n = model.n_legs
    s = ControlSettings.from_spec(model.spec, tau_max=7.0, sample_period=0.001, split="min_max")
    assert np.array_equal(s.tau_max, np.full(n, 7.0)) and s.sample_period == 0.001
    assert s.split == "min_max"
    unit = "N m" if model.name != "prr3_platform" and model.name != "prr_point" else "N"
    with pytest.raises(ArgumentError, match=rf"^Robot: tau_max\[1\] \(leg 2\) = -1.0 {unit} "
                                            rf"must be in \(0, 1e\+06\]"):
        ControlSettings.from_spec(model.spec, tau_max=[5.0, -1.0] + [5.0] * (n - 2),
                                  who="Robot")
    with pytest.raises(ArgumentError, match=r"sample_period = 2.0 s must be in \[1e-06, 1\]"):
        ControlSettings.from_spec(model.spec, sample_period=2.0)
    with pytest.raises(ArgumentError, match=r"split must be one of \['min_norm', 'min_max', "
                                            r"'preload'\], got 'fast'"):
        ControlSettings.from_spec(model.spec, split="fast")
    for key in ("sample_period", "velocity_filter_hz"):
        with pytest.raises(ArgumentTypeError, match=rf"^Robot: {key} must be a real number, "
                                                    rf"got 'fast'"):
            ControlSettings.from_spec(model.spec, **{key: "fast"}, who="Robot")


def test_every_controller_takes_the_settings_object(model):
    s = ControlSettings.from_spec(model.spec, tau_max=9.0, velocity_filter_hz=0,
                                  split="preload")
    kw = dict(tau_max=9.0, velocity_filter_hz=0, split="preload")
    for C in (pm2dof.NAController, pm2dof.APDController, pm2dof.CTCController):
        a, b = C(model, settings=s), C(model, **kw)
        assert np.array_equal(a.params, b.params), C.__name__
        assert a.settings is s and a.split == "preload" and a.sample_period == s.sample_period
    with pytest.raises(ArgumentError, match=r"NAController: give settings or tau_max, not both"):
        pm2dof.NAController(model, settings=s, tau_max=9.0)
    with pytest.raises(ArgumentTypeError, match=r"APDController: settings must be a "
                                                r"pm2dof.control.settings.ControlSettings"):
        pm2dof.APDController(model, settings={"tau_max": 9.0})
    other = pm2dof.load_model("rrr3_platform" if model.n_legs != 3 else "rrr4_platform")
    with pytest.raises(ArgumentError, match=r"CTCController: the settings are for "):
        pm2dof.CTCController(model, settings=ControlSettings.from_spec(other.spec))


def test_law_params_packs_the_model_files_gains_and_settings(model):
    raw = _toml(model.name)
    n, m = model.n_legs, model.dof
    for law, gains in (("na", ("Kd", "Q", "Gamma")), ("apd", ("Kp", "Kv")), ("lqr", ())):
        p = model.layout(f"{law}_params").unpack(controllers.law_params(model, law))
        assert p["T"] == raw["sensing"]["sample_period"]
        assert np.array_equal(p["tau_max"], _per_leg(raw["limits"]["tau_max"], n))
        assert p["sing_threshold"] == raw["limits"]["singularity_threshold"]
        for g in gains:
            size = len(model.param_names) if g == "Gamma" else m
            assert np.array_equal(p[g], _per_leg(raw["gains"][law][g], size)), (law, g)
    na = model.layout("na_params").unpack(controllers.law_params(model, "na"))
    assert na["freeze_saturated"] == 0.0           # the paper's law


def test_export_reads_the_defaults_without_building_controllers(monkeypatch):
    """``pm2dof export``'s default parameter vectors come from the settings and the model
    file, not from controller objects (which bind C steps to read three numbers)."""
    from pm2dof.export import project
    model = pm2dof.load_model("prr3_platform")
    want = {"na": pm2dof.NAController(model).params, "apd": pm2dof.APDController(model).params,
            "ctc": pm2dof.CTCController(model).params}

    def refuse(*args, **kwargs):
        raise AssertionError("export built a controller")
    for C in (pm2dof.NAController, pm2dof.APDController, pm2dof.CTCController):
        monkeypatch.setattr(C, "__init__", refuse)
    got = project._law_params(model)
    for law, p in want.items():
        assert np.array_equal(got[law], p), law
    lqr = model.layout("lqr_params").unpack(got["lqr"])
    na = model.layout("na_params").unpack(want["na"])
    assert all(np.array_equal(lqr[f], na[f]) for f in lqr)


@pytest.mark.parametrize("name", ["rrr4_platform", "prr3_platform", "shang2010_vertical"])
def test_tau_max_has_one_default_and_one_check(name):
    """The planner, the maps, the splits and the path torques take ``tau_max`` from
    ``actuator_limits``: the model file's by default, one value for every actuator, and a
    limit outside (0, 1e6] refused with a typed error naming it (the maps and the path
    torques computed with a negative limit before)."""
    model = pm2dof.load_model(name)
    raw = _toml(name)
    n = model.n_legs
    assert np.array_equal(actuator_limits(model.spec), _per_leg(raw["limits"]["tau_max"], n))
    assert np.array_equal(actuator_limits(model.spec, 3.0), np.full(n, 3.0))
    bad = [2.0] * (n - 1) + [-2.0]
    start = raw["trajectories"][line_moves(model)[0]]["start"]
    q = model.ik(np.asarray(start, dtype=float))
    from pm2dof.analysis.maps import capability
    from pm2dof.analysis.splits import run_splits
    from pm2dof.figures.maps import maps_note
    from pm2dof.planning.stages import limits
    with pytest.raises(ArgumentError, match=rf"capability: tau_max\[{n - 1}\] \(leg {n}\) = "
                                            r"-2.0"):
        capability(model, q, tau_max=bad)
    with pytest.raises(ArgumentError, match=r"maps: tau_max"):
        maps_note(model, tau_max=bad)
    with pytest.raises(ArgumentError, match=r"splits: tau_max"):
        run_splits(model, tau_max=bad)
    with pytest.raises(PlanError, match=r"finite limits > 0 N?( m)? \(one per actuator\), at "
                                        r"most 1e\+06"):
        limits(model, 2e6, 1.0)
    assert np.array_equal(limits(model, None, 0.5), 0.5 * _per_leg(raw["limits"]["tau_max"], n))
