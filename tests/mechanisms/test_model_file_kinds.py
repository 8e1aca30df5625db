"""Issue 26: the model file's new keys (end_effector, gravity, leg kinds, [platform]) and the
bad inputs of the issue, each one line naming the file, the table and the key."""
import re

import pytest

from pm2dof.core import paths
from pm2dof.core.errors import ModelFileError
from pm2dof.core.model_file import read_model_file
from tests.mechanisms.models import model_path

NEW_MODELS = ["rrr3_platform", "rrr4_platform", "prr3_platform", "prr_point", "rpr3_platform",
              "shang2010_vertical"]


def _text(model):
    return model_path(model).read_text()


def _error(tmp_path, text):
    path = tmp_path / "robot.toml"
    path.write_text(text)
    with pytest.raises(ModelFileError) as info:
        read_model_file(path)
    return path, str(info.value)


def _one_line(msg, path, key, *words):
    assert "\n" not in msg, msg
    assert msg.startswith(f"{path}: [{key}]"), msg
    for w in words:
        assert w in msg, msg


@pytest.mark.parametrize("model", NEW_MODELS)
def test_shipped_models_read(model):
    spec = read_model_file(model_path(model))
    platform = spec.end_effector == "platform"
    assert spec.dof == (3 if platform else 2)
    assert spec.task_names == (("x", "y", "phi") if platform else ("x", "y"))
    assert (spec.home is not None) == platform
    assert len(spec.gains["na"]["Kd"]) == spec.dof
    assert len(spec.gains["na"]["Gamma"]) == len(spec.param_names) == len(spec.theta_nominal)
    for t in spec.trajectories.values():
        assert len(t["start"]) == spec.dof


def test_theta_names_follow_kinds_platform_and_gravity():
    names = {m: read_model_file(model_path(m)).param_names for m in NEW_MODELS}
    assert names["shang2010_vertical"][9:12] == ("kappa1", "kappa2", "kappa3")
    assert names["rrr3_platform"][9:13] == ("m_p", "mx_p", "my_p", "I_p")
    assert not any(n.startswith("kappa") for n in names["prr3_platform"])


def test_today_formulation_hash_unchanged():
    """Keys at their defaults stay out of the formulation: today's manifests stay valid."""
    import json
    for model in ("shang2010", "fivebar", "fourleg", "unequal"):
        spec = read_model_file(model_path(model))
        manifest = json.loads((paths.SHIPPED_GENERATED / model / "manifest.json").read_text())
        assert spec.formulation_sha256 == manifest["formulation_sha256"], model


def test_platform_without_attachment_point(tmp_path):
    text = _text("rrr3_platform")
    text = text.replace("attach = [0.0433, -0.025]\n", "", 1)
    path, msg = _error(tmp_path, text)
    _one_line(msg, path, "legs.attach (leg 2)", "missing")


def test_point_leg_with_attachment_point(tmp_path):
    text = _text("prr_point").replace('branch = "behind"\n', 'branch = "behind"\nattach = [0.0, 0.0]\n', 1)
    path, msg = _error(tmp_path, text)
    _one_line(msg, path, "legs.attach (leg 1)", "platform")


def test_rail_of_zero_length(tmp_path):
    text = _text("prr3_platform").replace("rail = [[0.0905, -0.2832], [0.2905, 0.0632]]",
                                          "rail = [[0.0905, -0.2832], [0.0905, -0.2832]]")
    path, msg = _error(tmp_path, text)
    _one_line(msg, path, "legs.rail (leg 2)", "zero length")


@pytest.mark.parametrize("model, old, new, key, words", [
    ("rrr3_platform", "end = [0.04, 0.03, 0.2]", "end = [0.04, -0.2, 0.2]",
     "trajectories.low.end", ("leg 3 (RRR)", "its reach is")),
    ("prr3_platform", "end = [0.02, 0.01, 0.1]", "end = [0.05, 0.0, 0.0]",
     "trajectories.low.end", ("leg 1 (PRR)", "from its rail's line")),
    ("rpr3_platform", "end = [0.04, 0.03, 0.2]", "end = [0.0, -0.2, 0.0]",
     "trajectories.low.end", ("leg 3 (RPR)", "stroke")),
    ("prr_point", "start = [0.22, 0.28]", "start = [0.4, 0.25]",
     "trajectories.low.start", ("leg 3 (PRR)", "rail")),
])
def test_leg_that_cannot_reach(tmp_path, model, old, new, key, words):
    text = _text(model)
    assert old in text
    text = text.replace(old, new, 1)
    path, msg = _error(tmp_path, text)
    _one_line(msg, path, key, *words)


def test_platform_home_out_of_stroke(tmp_path):
    text = _text("rpr3_platform").replace("home = [0.0, 0.0, 0.0]", "home = [0.0, -0.2, 0.0]")
    path, msg = _error(tmp_path, text)
    _one_line(msg, path, "platform.home", "leg 3 (RPR)", "stroke")


def test_gravity_with_nan(tmp_path):
    text = _text("shang2010_vertical").replace("gravity = [0.0, -9.81]", "gravity = [nan, -9.81]")
    path, msg = _error(tmp_path, text)
    _one_line(msg, path, "model.gravity (x)", "finite", "nan")


def test_gravity_adds_kappa_to_nominal(tmp_path):
    text = _text("shang2010").replace('friction = "coulomb_viscous"',
                                      'friction = "coulomb_viscous"\ngravity = [0.0, -9.81]', 1)
    path, msg = _error(tmp_path, text)
    assert "[nominal.kappa] missing" in msg and "[plant.kappa] missing" in msg, msg
    assert "gains.na.Gamma" in msg and "kappa1" in msg, msg


def test_platform_needs_three_legs_and_a_home(tmp_path):
    text = _text("rrr3_platform")
    path, msg = _error(tmp_path, re.sub(r"\[platform\]\nhome = [^\n]*\n", "", text))
    _one_line(msg, path, "platform", "missing")


def test_prismatic_actuators_need_a_linear_resolution(tmp_path):
    text = re.sub(r"linear_encoder_resolution = [^\n]*\n", "", _text("prr_point"))
    path, msg = _error(tmp_path, text)
    _one_line(msg, path, "sensing.linear_encoder_resolution", "prismatic")


def test_platform_inertia_must_be_a_rigid_body(tmp_path):
    text = _text("rpr3_platform").replace("mx_p = 0.0\n", "mx_p = 0.1\n", 1)
    path, msg = _error(tmp_path, text)
    _one_line(msg, path, "nominal.I_p", "centre of mass")
