"""The model file's keys of the other kinds (end_effector, gravity, leg kinds, [platform]) and
their bad inputs, each one line naming the file, the table and the key."""
import math
import re

import pytest

from pm2dof.core import paths
from pm2dof.core.errors import ModelFileError
from pm2dof.core.model_file import read_model_file
from tests.mechanisms.models import model_path

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

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


# (model, text replaced, replacement, key named, words of the reason): the bad inputs
BAD = {
    "platform_without_attachment_point": (
        "rrr3_platform", "attach = [0.0433, -0.025]\n", "", "legs.attach (leg 2)", ("missing",)),
    "point_leg_with_attachment_point": (
        "prr_point", 'branch = "behind"\n', 'branch = "behind"\nattach = [0.0, 0.0]\n',
        "legs.attach (leg 1)", ("platform",)),
    "rail_of_zero_length": (
        "prr3_platform", "rail = [[0.0905, -0.2832], [0.2905, 0.0632]]",
        "rail = [[0.0905, -0.2832], [0.0905, -0.2832]]", "legs.rail (leg 2)", ("zero length",)),
    "rrr_leg_cannot_reach": (
        "rrr3_platform", "end = [0.04, 0.03, 0.2]", "end = [0.04, -0.2, 0.2]",
        "trajectories.low.end", ("leg 3 (RRR)", "its reach is")),
    "prr_leg_cannot_reach": (
        "prr3_platform", "end = [0.02, 0.01, 0.1]", "end = [0.05, 0.0, 0.0]",
        "trajectories.low.end", ("leg 1 (PRR)", "from its rail's line")),
    "rpr_leg_cannot_reach": (
        "rpr3_platform", "end = [0.04, 0.03, 0.2]", "end = [0.0, -0.2, 0.0]",
        "trajectories.low.end", ("leg 3 (RPR)", "stroke")),
    "point_prr_leg_cannot_reach": (
        "prr_point", "start = [0.22, 0.28]", "start = [0.4, 0.25]",
        "trajectories.low.start", ("leg 3 (PRR)", "rail")),
    "platform_home_out_of_stroke": (
        "rpr3_platform", "home = [0.0, 0.0, 0.0]", "home = [0.0, -0.2, 0.0]",
        "platform.home", ("leg 3 (RPR)", "stroke")),
    "gravity_with_nan": (
        "shang2010_vertical", "gravity = [0.0, -9.81]", "gravity = [nan, -9.81]",
        "model.gravity (x)", ("finite", "nan")),
    "prismatic_actuators_need_a_linear_resolution": (
        "prr_point", "linear_encoder_resolution = 1e-6", "", "sensing.linear_encoder_resolution",
        ("prismatic",)),
    "platform_inertia_must_be_a_rigid_body": (
        "rpr3_platform", "mx_p = 0.0\n", "mx_p = 0.1\n", "nominal.I_p", ("centre of mass",)),
}


@pytest.mark.parametrize("case", BAD)
def test_one_bad_key_is_one_line_naming_file_table_key(tmp_path, case):
    model, old, new, key, words = BAD[case]
    text = _text(model)
    assert old in text
    path, msg = _error(tmp_path, text.replace(old, new, 1))
    _one_line(msg, path, key, *words)


def test_gravity_adds_kappa_to_nominal(tmp_path):
    text = _text("shang2010").replace('friction = "coulomb_viscous"',
                                      'friction = "coulomb_viscous"\ngravity = [0.0, -9.81]', 1)
    path, msg = _error(tmp_path, text)
    assert "[nominal.kappa] missing" in msg and "[plant.kappa] missing" in msg, msg
    assert "gains.na.Gamma" in msg and "kappa1" in msg, msg


def test_platform_needs_a_home_and_three_legs(tmp_path):
    text = _text("rrr3_platform")
    path, msg = _error(tmp_path, re.sub(r"\[platform\]\nhome = [^\n]*\n", "", text))
    _one_line(msg, path, "platform", "missing")
    two_legs = text[:text.index("[[legs]]", text.index("[[legs]]") + 1)] + text[text.index("[platform]"):]
    path, msg = _error(tmp_path, two_legs)
    _one_line(msg, path, "legs", "at least three")


def _links_text(model, links, platform=None):
    """``model``'s file with [nominal]'s lumped inertial keys replaced by [[nominal.links]]."""
    text = _text(model)
    for key in ("alpha", "beta", "gamma", "kappa", "m_p", "mx_p", "my_p", "I_p"):
        text = re.sub(rf"(\[nominal\][^\[]*?)\n{key}\s*=[^\n]*", r"\1", text, count=1)
    extra = "".join("\n[[nominal.links]]\n" + "".join(f"{body} = {{ {fields} }}\n"
                                                      for body, fields in leg.items())
                    for leg in links)
    if platform:
        extra += f"\n[nominal.platform]\n{platform}\n"
    return text.replace("\n[limits]", extra + "\n[limits]", 1)


def test_links_give_theta_by_the_documented_rule(tmp_path):
    """[[nominal.links]]: each body's mass, com and inertia; theta computed by the rule
    (written again, independently, in tests/mechanisms/independent.lumped_theta)."""
    from tests.mechanisms.independent import lumped_theta
    rrr = {"proximal": "mass = 0.6, com = 0.1, inertia = 0.002",
           "distal": "mass = 0.4, com = 0.1, inertia = 0.0013333"}
    path = tmp_path / "robot.toml"
    path.write_text(_links_text("rrr3_platform", [rrr] * 3,
                                "mass = 0.5\ncom = [0.01, -0.02]\ninertia = 3.125e-4"))
    spec = read_model_file(path)
    legs = [dict(kind="RRR", la=0.2, lb=0.2)] * 3
    links = [dict(ma=0.6, ca=0.1, Ia=0.002, mb=0.4, cb=0.1, Ib=0.0013333)] * 3
    import numpy as np
    want = lumped_theta(legs, links, dict(m=0.5, c=np.array([0.01, -0.02]), I=3.125e-4), False)
    got = dict(zip(spec.param_names, spec.theta_nominal))
    for k, v in want.items():
        assert got[k] == pytest.approx(v, rel=1e-14), k
    # the shipped file's lumped values are these links' (its comments show the arithmetic)
    shipped = read_model_file(model_path("rrr3_platform"))
    for k in ("alpha1", "beta1", "gamma1"):
        assert dict(zip(shipped.param_names, shipped.theta_nominal))[k] == pytest.approx(
            got[k], rel=1e-4)


@pytest.mark.parametrize("model, bodies", [
    ("prr_point", {"slider": "mass = 1.0", "link": "mass = 0.3, com = 0.15, inertia = 0.00225"}),
    ("rpr3_platform", {"cylinder": "mass = 1.0, com = 0.1, inertia = 0.004",
                       "rod": "mass = 0.4, com = 0.1, inertia = 0.0012"}),
])
def test_links_of_prismatic_kinds_match_the_shipped_lumped_values(tmp_path, model, bodies):
    path = tmp_path / "robot.toml"
    platform = "mass = 0.5\ncom = [0.0, 0.0]\ninertia = 8e-4" if "platform" in model else None
    path.write_text(_links_text(model, [bodies] * 3, platform))
    got = read_model_file(path)
    shipped = read_model_file(model_path(model))
    assert got.param_names == shipped.param_names
    assert got.theta_nominal == pytest.approx(shipped.theta_nominal, rel=1e-12)


def test_links_and_lumped_keys_together_are_refused(tmp_path):
    rrr = {"proximal": "mass = 0.6, com = 0.1, inertia = 0.002",
           "distal": "mass = 0.4, com = 0.1, inertia = 0.0013333"}
    text = _links_text("rrr3_platform", [rrr] * 3,
                       "mass = 0.5\ncom = [0.0, 0.0]\ninertia = 3.125e-4")
    path, msg = _error(tmp_path, text.replace("[nominal]\n", "[nominal]\nbeta = [0.1, 0.1, 0.1]\n", 1))
    _one_line(msg, path, "nominal.beta", "given twice")
    bad = {"proximal": "mass = 0.6, com = 0.1", "distal": rrr["distal"]}
    path, msg = _error(tmp_path, _links_text("rrr3_platform", [rrr, bad, rrr],
                                             "mass = 0.5\ncom = [0.0, 0.0]\ninertia = 3.125e-4"))
    _one_line(msg, path, "nominal.links (leg 2).proximal.inertia", "missing")


# --- [platform] home clear of both singularities ----------------------------------------------

#: a redundant 4-RPR: bases on a circle of 0.3 m, attachment points on one of 0.08 m at the same
#: angles (0, 90, 180, 270 degrees): at home every leg's line passes through the platform's
#: origin, so no leg can exert a moment about it (S has rank 2, a type II singularity)
RADIAL_4RPR = """
[model]
name = "rpr4_radial"
friction = "coulomb_viscous"
end_effector = "platform"
{legs}
[platform]
home = [0.0, 0.0, 0.0]

[nominal]
alpha = [0.4, 0.4, 0.4, 0.4]
beta = [0.04, 0.04, 0.04, 0.04]
gamma = [0.0192, 0.0192, 0.0192, 0.0192]
m_p = 0.5
mx_p = 0.0
my_p = 0.0
I_p = 8e-4
fv = [20.0, 20.0, 20.0, 20.0]
fc = [4.0, 4.0, 4.0, 4.0]

[limits]
singularity_threshold = 0.1
tau_max = [300.0, 300.0, 300.0, 300.0]

[sensing]
sample_period = 0.002
encoder_counts_per_rev = 131072
linear_encoder_resolution = 1e-6
velocity_filter_hz = 0.0

[gains.na]
Kd = [150.0, 150.0, 0.76]
Q = [280.0, 280.0, 280.0]
Gamma = [0.02, 0.02, 0.02, 0.02, 5e-4, 5e-4, 5e-4, 5e-4, 5e-5, 5e-5, 5e-5, 5e-5,
         0.02, 0.0, 0.0, 1e-5, 2.0, 2.0, 2.0, 2.0, 0.5, 0.5, 0.5, 0.5]

[gains.apd]
Kp = [25000.0, 25000.0, 127.0]
Kv = [250.0, 250.0, 1.27]

[plant]
alpha = [0.4, 0.4, 0.4, 0.4]
beta = [0.04, 0.04, 0.04, 0.04]
gamma = [0.0192, 0.0192, 0.0192, 0.0192]
m_p = 0.5
mx_p = 0.0
my_p = 0.0
I_p = 8e-4
payload_mass = 0.2
fv = [17.0, 17.0, 17.0, 17.0]
fc = [4.8, 4.8, 4.8, 4.8]
fs = [2.0, 2.0, 2.0, 2.0]
stribeck_velocity = 0.01
coulomb_smoothing_velocity = 0.001

[trajectories.low]
start = [0.0, 0.0, 0.0]
end = [0.04, 0.03, 0.2]
v_max = 0.2
a_max = 5.0
j_max = 200.0
"""


def _radial_4rpr(folder, turn=0.0):
    """The 4-RPR above; ``turn`` (rad) turns every attachment point about the platform's origin
    (0: the lines meet at the origin)."""
    legs = ""
    for k in range(4):
        a = k * math.pi / 2
        legs += (f'\n[[legs]]\nkind = "RPR"\nbase = [{0.3 * math.cos(a)!r}, '
                 f'{0.3 * math.sin(a)!r}]\nstroke = [0.15, 0.4]\n'
                 f'attach = [{0.08 * math.cos(a + turn)!r}, {0.08 * math.sin(a + turn)!r}]\n')
    path = folder / "rpr4_radial.toml"
    path.write_text(RADIAL_4RPR.format(legs=legs))
    return path


def test_a_home_where_the_legs_lines_meet_is_refused(tmp_path):
    """Every fk of such a file used to fail ("no assembly of the legs has active angles qa =
    [0.22, ...] rad": the Gauss-Newton from home had singular normal equations) after `derive`
    accepted it. The file check names the measure, its value (0 up to rounding: the lines
    meet exactly) and the threshold; `pm2dof derive` stops there, exit 2, one line."""
    path = _radial_4rpr(tmp_path)
    with pytest.raises(ModelFileError) as info:
        read_model_file(path)
    msg = str(info.value)
    _one_line(msg, path, "platform.home", "type II", "(det U^T U)^(1/3) / (n/3)",
              "concurrent or all parallel", "< limits.parallel_singularity_threshold = 0.1")
    value = float(re.search(r"wrench lines U is (\S+) <", msg).group(1))
    assert 0.0 <= value < 1e-5, msg
    (tmp_path / "turned").mkdir()
    read_model_file(_radial_4rpr(tmp_path / "turned", turn=0.5))   # the lines no longer meet
    import subprocess
    import sys
    r = subprocess.run([sys.executable, "-m", "pm2dof", "derive", str(path), "--no-build"],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 2 and "[platform.home]" in r.stderr and "type II" in r.stderr, \
        (r.returncode, r.stdout, r.stderr)
    assert not (tmp_path / "generated").exists()


def _with_limit(text, key, value):
    text = re.sub(rf"\n{key} = [^\n]*", "", text)
    return text.replace("[limits]\n", f"[limits]\n{key} = {value!r}\n", 1)


@pytest.mark.parametrize("name", ["rrr3_platform", "prr3_platform", "rpr3_platform"])
def test_home_type_ii_measure_is_the_generated_one(tmp_path, name):
    """A threshold 0.1 % above the generated singularity_measures at ik(home) refuses home,
    naming that value; 0.1 % below accepts it."""
    import pm2dof
    m = pm2dof.load_model(name)
    value = m.singularity_measures(m.ik(m.spec.home))[1]
    text = _text(name)
    path, msg = _error(tmp_path, _with_limit(text, "parallel_singularity_threshold",
                                             float(value * 1.001)))
    _one_line(msg, path, "platform.home", "type II", f"is {value:.3g} <")
    path.write_text(_with_limit(text, "parallel_singularity_threshold", float(value * 0.999)))
    assert read_model_file(path).home == tuple(m.spec.home)


@pytest.mark.parametrize("name", ["rrr3_platform", "prr3_platform"])
def test_home_type_i_names_the_leg_and_its_kinds_measure(tmp_path, name):
    """A leg at a type I singularity at home has no working mode for fk to read. Each leg's
    measure written here from the generated ik at home: RRR |sin(qb - qa)|, PRR |d . u(qb)|."""
    import numpy as np

    import pm2dof
    m = pm2dof.load_model(name)
    n, q = m.n_legs, m.ik(m.spec.home)
    per_leg = []
    for i, leg in enumerate(m.spec.legs):
        if leg.kind == "RRR":
            per_leg.append(abs(math.sin(q[n + i] - q[i])))
        else:
            d = np.subtract(leg.rail_end, leg.base) / leg.rail_length
            per_leg.append(abs(d @ [math.cos(q[n + i]), math.sin(q[n + i])]))
    worst = int(np.argmin(per_leg))
    path, msg = _error(tmp_path, _with_limit(_text(name), "singularity_threshold",
                                             float(per_leg[worst] * 1.001)))
    measure = "|sin(qb_i - qa_i)|" if m.spec.legs[worst].kind == "RRR" else "|d_i . u(qb_i)|"
    low = [i for i, v in enumerate(per_leg) if v < per_leg[worst] * 1.001]
    _one_line(msg, path, "platform.home", "type I singularity",
              f"leg{'s' if len(low) > 1 else ''} {', '.join(str(i + 1) for i in low)} "
              f"({m.spec.legs[worst].kind}; 0 at ", f"{measure} = {per_leg[worst]:.3g}",
              "below limits.singularity_threshold")
