# pm2dof.core.mechanism: the mechanism's rules in one home, against docs/model-file.md's words.
"""The rules of a mechanism (leg kinds, theta's layout, lumped parameters, payload, reach) live
in :mod:`pm2dof.core.mechanism`, and the model file's reader only reads and checks.

* Each rule is defined there and imported from there, never from the model file's reader
  (a static scan of pm2dof/ and tests/).
* The leg kinds are spelled as a set once (a static scan for a literal of all three).
* theta's layout and the actuators follow the rules as docs/model-file.md states them, written
  out here by hand on a point, a platform, linear actuators and gravity.
"""
import ast
from pathlib import Path

import pytest

from pm2dof.core import mechanism, model_file
from pm2dof.core.mechanism import (
    ACTUATORS,
    LEG_KINDS,
    attachment_points,
    payload_increments,
    theta_groups,
    theta_names,
)
from pm2dof.core.model_file import Leg, read_model_file
from pm2dof.core.paths import SHIPPED_MODELS

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

ROOT = Path(__file__).resolve().parents[2]
SOURCES = sorted(p for p in (ROOT / "pm2dof").rglob("*.py") if "generated" not in p.parts)
TESTS = sorted((ROOT / "tests").rglob("*.py"))
#: (file, name) left to later; none: pm2dof/derive/*.py imports the rules from the mechanism too
_DERIVE_STILL: set = set()


def test_every_rule_is_defined_in_the_mechanism_module_and_not_offered_by_the_reader():
    for name in mechanism.__all__:
        obj = getattr(mechanism, name)
        if callable(obj):
            assert obj.__module__ == "pm2dof.core.mechanism", name
        assert name not in model_file.__all__, f"model_file still offers {name}"
    for name in ("payload_increments", "leg_reach_problem", "attachment_points",
                 "inertia_problem", "theta_groups", "lumped_from_links", "LEG_KINDS"):
        assert name in mechanism.__all__, name


def _imports_from_the_reader(path):
    """(name, line) of every name imported from pm2dof.core.model_file in ``path``."""
    out = []
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.ImportFrom) and (node.module or "").endswith("model_file"):
            out += [(a.name, node.lineno) for a in node.names]
    return out


def test_no_module_imports_a_mechanism_rule_from_the_model_file_reader():
    rules = set(mechanism.__all__)
    bad = []
    for path in SOURCES + TESTS:
        rel = path.relative_to(ROOT / "pm2dof") if path.is_relative_to(ROOT / "pm2dof") else path
        for name, line in _imports_from_the_reader(path):
            if name in rules and (str(rel), name) not in _DERIVE_STILL:
                bad.append(f"{path.relative_to(ROOT)}:{line}: {name}")
    assert not bad, "import these from pm2dof.core.mechanism:\n" + "\n".join(bad)


def _all_kinds_literals(path):
    """Lines of tuple, list or set literals holding exactly the three leg kinds' names."""
    kinds = {"RRR", "PRR", "RPR"}
    return [node.lineno for node in ast.walk(ast.parse(path.read_text(), str(path)))
            if isinstance(node, (ast.Tuple, ast.List, ast.Set)) and node.elts
            and all(isinstance(e, ast.Constant) for e in node.elts)
            and {e.value for e in node.elts} == kinds]


def test_the_leg_kinds_are_spelled_as_a_set_once():
    """Only the mechanism module lists the kinds (as ACTUATORS' keys); everyone else imports
    LEG_KINDS (model.py's platform working modes index it)."""
    found = {str(p.relative_to(ROOT)): lines for p in SOURCES if (lines := _all_kinds_literals(p))}
    assert found == {}, found
    assert LEG_KINDS == ("RRR", "PRR", "RPR")


def test_each_kinds_actuator_is_the_documented_one():
    """docs/model-file.md, [[legs]]: RRR an actuated revolute at the base, PRR an actuated
    prismatic along its rail, RPR an actuated length (a cylinder)."""
    documented = {"RRR": "revolute", "PRR": "prismatic", "RPR": "prismatic"}
    assert ACTUATORS == documented
    for path in sorted(SHIPPED_MODELS.glob("*.toml")):
        for leg in read_model_file(path).legs:
            assert leg.actuator == documented[leg.kind], path


# theta's names as docs/model-file.md ([nominal]) lists them, written out by hand
_LEGS3 = [f"{k}{i}" for k in ("alpha", "beta", "gamma") for i in (1, 2, 3)]
_FRICTION3 = [f"{k}{i}" for k in ("fv", "fc") for i in (1, 2, 3)]
_PLATFORM = ["m_p", "mx_p", "my_p", "I_p"]
_EXPECTED = {
    "shang2010": _LEGS3 + _FRICTION3,
    "shang2010_stribeck": _LEGS3 + _FRICTION3 + ["fs1", "fs2", "fs3"],
    "shang2010_vertical": _LEGS3 + ["kappa1", "kappa2", "kappa3"] + _FRICTION3,
    "prr_point": _LEGS3 + _FRICTION3,
    "rrr3_platform": _LEGS3 + _PLATFORM + _FRICTION3,
    "prr3_platform": _LEGS3 + _PLATFORM + _FRICTION3,
    "rpr3_platform": _LEGS3 + _PLATFORM + _FRICTION3,
}


@pytest.mark.parametrize("name", sorted(_EXPECTED))
def test_theta_layout_is_the_documented_one(name):
    spec = read_model_file(SHIPPED_MODELS / f"{name}.toml")
    groups = theta_groups(spec.legs, spec.end_effector, spec.gravity, spec.friction)
    assert list(theta_names(groups)) == _EXPECTED[name]
    assert spec.param_names == theta_names(groups)


def _legs():
    return (Leg(base=(0.0, 0.0), la=0.2, lb=0.25, elbow=1),
            Leg(base=(0.5, 0.0), la=None, lb=0.3, elbow=-1, kind="PRR", rail_end=(0.5, 0.4)),
            Leg(base=(0.25, 0.5), la=None, lb=None, elbow=None, kind="RPR", stroke=(0.1, 0.6)))


def test_kappa_only_for_the_kinds_whose_potential_energy_needs_one():
    """Under gravity an RRR and an RPR leg get kappa, a PRR leg not (its potential energy is
    in alpha, beta: docs/model-file.md); in a horizontal plane none does."""
    legs = _legs()
    names = theta_names(theta_groups(legs, "point", (0.0, -9.81), "coulomb_viscous"))
    assert [n for n in names if n.startswith("kappa")] == ["kappa1", "kappa3"]
    flat = theta_names(theta_groups(legs, "point", (0.0, 0.0), "coulomb_viscous"))
    assert not [n for n in flat if n.startswith("kappa")]


def test_payload_increments_and_attachment_points_by_hand():
    """docs/model-file.md [plant]: a point mass m at the tip, each kind's increments; a
    platform's attachment point p + R(phi) a at phi = 90 degrees."""
    rrr, prr, rpr = _legs()
    m = 0.5
    assert payload_increments(rrr, "point", m) == pytest.approx(
        {"alpha": 0.5 * 0.04, "beta": 0.5 * 0.05, "gamma": 0.5 * 0.0625, "kappa": 0.5 * 0.2})
    assert payload_increments(prr, "point", m) == pytest.approx(
        {"alpha": 0.5, "beta": 0.5 * 0.3, "gamma": 0.5 * 0.09})
    assert payload_increments(rpr, "point", m) == {"alpha": 0.5}
    assert payload_increments(rrr, "platform", m) == {"m_p": 0.5}
    leg = Leg(base=(0.0, 0.0), la=0.2, lb=0.2, elbow=1, attach=(0.03, 0.0))
    (x, y), = attachment_points([leg], (0.1, 0.2, 1.5707963267948966))
    assert (x, y) == pytest.approx((0.1, 0.23), abs=1e-15)
    assert attachment_points([leg, leg], (0.1, 0.2)) == [(0.1, 0.2), (0.1, 0.2)]
