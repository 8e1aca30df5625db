# A model file's [design] table and uniform-rod links: reading, formulation hash, spec_at_design.
"""The ``[design]`` table of a model file (pm2dof.core.design) and links given as uniform rods.

* Every shipped model file keeps its formulation hash (the one its committed manifest.json
  records): the new keys change nothing for a file without them.
* With a ``[design]``, the formulation names the variables instead of the designed numbers:
  editing a default or a bound keeps the hash, renaming or re-keying a variable changes it.
* Every problem of a ``[design]`` table is reported at once, naming the key.
* ``spec_at_design`` equals reading the same file with the numbers written into ``[[legs]]``
  (a conventional file, no ``[design]``); a rod's theta entries equal closed forms written out
  here by hand (a uniform rod: m = rho L, c = L/2, I = rho L^3/12 about its centre); the
  default closure tolerance follows la; values out of bounds, unknown names and designs where
  a move or the home cannot be reached are DesignErrors naming the variable, move and leg.
* ``spec_at_design(spec, default)`` is ``spec``, also after a detour through random designs.

The fixtures are shipped files with a ``[design]`` table (and rods) appended, written to tmp.
"""
import dataclasses
import json
import math
import pickle
import re
from types import MappingProxyType

import numpy as np
import pytest

import pm2dof
from pm2dof.core.design import Design, spec_at_design
from pm2dof.core.errors import DesignError, ModelFileError, Pm2dofError
from pm2dof.core.model_file import ModelSpec, read_model_file
from pm2dof.core.paths import SHIPPED_GENERATED, SHIPPED_MODELS

#: the issue's example, on the paper's robot
ISSUE = """
la = { keys = ["legs.1.la", "legs.2.la", "legs.3.la"], bounds = [0.18, 0.32] }
lb = { keys = ["legs.1.lb", "legs.2.lb", "legs.3.lb"], bounds = [0.18, 0.32] }
b2x = { keys = ["legs.2.base.x"], bounds = [0.35, 0.50] }
"""
LA_LB = """
la = { keys = ["legs.1.la", "legs.2.la", "legs.3.la"], bounds = [0.1, 0.3] }
lb = { keys = ["legs.1.lb", "legs.2.lb", "legs.3.lb"], bounds = [0.1, 0.3] }
"""
#: prr_point: leg 2's rail moved sideways (both ends' y tied), leg 3's rail turned (its first
#: end's x), the links' lb tied
PRR = """
lb = { keys = ["legs.1.lb", "legs.2.lb", "legs.3.lb"], bounds = [0.27, 0.31] }
y2 = { keys = ["legs.2.rail.1.y", "legs.2.rail.2.y"], bounds = [0.48, 0.52] }
x3 = { keys = ["legs.3.rail.1.x"], bounds = [-0.03, 0.03] }
"""
RPR = """
b2x = { keys = ["legs.2.base.x"], bounds = [0.22, 0.3] }
a3x = { keys = ["legs.3.attach.x"], bounds = [-0.09, -0.05] }
a3y = { keys = ["legs.3.attach.y"], bounds = [0.02, 0.06] }
"""
_INERTIAL_LINE = re.compile(r"^(alpha|beta|gamma|kappa)\s*=")


def _text(model, design=None, legs=None, rods=None, rod_sections=("nominal", "plant"),
          sensing=None):
    """A shipped model file's text with: ``legs`` {(leg from 1, key): value} written into its
    [[legs]] (key "la", "lb" or "base.x"); [nominal] / [plant] ``rod_sections`` giving links
    ``rods`` (one TOML body table per leg, in place of alpha, beta, gamma, kappa); extra
    ``sensing`` lines; a [design] table ``design``."""
    out, section, leg = [], None, 0
    for line in (SHIPPED_MODELS / f"{model}.toml").read_text().splitlines():
        if line.startswith("["):
            section = line.split("]")[0].strip("[")
            leg += section == "legs"
        if rods is not None and section in rod_sections and _INERTIAL_LINE.match(line):
            continue
        if section == "legs" and legs:
            for (i, key), value in legs.items():
                if i != leg:
                    continue
                if key in ("la", "lb") and re.match(rf"{key}\s*=", line):
                    line = f"{key} = {value!r}"
                if key == "base.x" and line.startswith("base"):
                    y = re.match(r"base\s*=\s*\[[^,]+,\s*([^\]]+)\]", line)[1]
                    line = f"base = [{value!r}, {y}]"
        out.append(line)
        if section == "sensing" and line == "[sensing]" and sensing:
            out.append(sensing)
    text = "\n".join(out) + "\n"
    for sec in (rod_sections if rods is not None else ()):
        text += "".join(f"\n[[{sec}.links]]\n{body}\n" for body in rods)
    if design is not None:
        text += f"\n[design]\n{design}\n"
    return text


def _read(tmp_path, text, name="robot.toml"):
    path = tmp_path / name
    path.write_text(text)
    return read_model_file(path)


def _problems(tmp_path, text):
    with pytest.raises(ModelFileError) as info:
        _read(tmp_path, text)
    return [(p.key, p.reason) for p in info.value.problems]


def _same(a, b):
    """Whether two spec field values are equal: arrays bitwise (and their dtype), mappings and
    sequences entry by entry."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return (isinstance(a, np.ndarray) and isinstance(b, np.ndarray) and a.dtype == b.dtype
                and np.array_equal(a, b))
    if isinstance(a, (dict, MappingProxyType)):
        return (isinstance(b, (dict, MappingProxyType)) and set(a) == set(b)
                and all(_same(a[k], b[k]) for k in a))
    if isinstance(a, (tuple, list)):
        return type(a) is type(b) and len(a) == len(b) and all(map(_same, a, b))
    return type(a) is type(b) and a == b


def _assert_same_spec(a, b, skip=()):
    for f in dataclasses.fields(ModelSpec):
        if f.name not in skip:
            assert _same(getattr(a, f.name), getattr(b, f.name)), f.name


# --------------------------------------------------------------------------------------
# The formulation hash
# --------------------------------------------------------------------------------------

@pytest.mark.parametrize("path", sorted(SHIPPED_MODELS.glob("*.toml")), ids=lambda p: p.stem)
def test_every_shipped_file_keeps_the_hash_of_its_committed_generated_code(path):
    spec = read_model_file(path)
    manifest = json.loads((SHIPPED_GENERATED / path.stem / "manifest.json").read_text())
    assert spec.formulation_sha256 == manifest["formulation_sha256"]
    if path.stem.endswith("_design"):     # the shipped design models: their [design] is kept
        assert spec.design is not None and "design" in spec.formulation()
        assert manifest["design"]["names"] == list(spec.design.names)
    else:
        assert spec.design is None and spec.links is None
        assert "design" not in spec.formulation()


def test_the_issue_example_is_read_into_a_design(tmp_path):
    spec = _read(tmp_path, _text("shang2010", ISSUE))
    d = spec.design
    assert d.names == ("la", "lb", "b2x")
    assert d.keys == (((0, "la", None), (1, "la", None), (2, "la", None)),
                      ((0, "lb", None), (1, "lb", None), (2, "lb", None)),
                      ((1, "base", 0),))
    assert d.labels[2] == ("legs.2.base.x",)
    assert d.bounds == ((0.18, 0.32), (0.18, 0.32), (0.35, 0.5))
    assert d.default == d.values == (0.244, 0.244, 0.433)
    assert d.signs == (1, 1, 1) and d.closure_default
    form = spec.formulation()
    assert form["design"] == [["la", ["legs.1.la", "legs.2.la", "legs.3.la"]],
                              ["lb", ["legs.1.lb", "legs.2.lb", "legs.3.lb"]],
                              ["b2x", ["legs.2.base.x"]]]
    assert form["legs"][1] == {"base": [{"design": "b2x"}, 0.0], "la": {"design": "la"},
                               "lb": {"design": "lb"}, "elbow": -1}
    plain = read_model_file(SHIPPED_MODELS / "shang2010.toml")
    assert spec.formulation_sha256 != plain.formulation_sha256


def test_a_prr_rail_is_designed_by_its_ends_1_and_2(tmp_path):
    spec = _read(tmp_path, _text("prr_point", PRR))
    assert spec.design.keys[1:] == (((1, "base", 1), (1, "rail_end", 1)), ((2, "base", 0),))
    assert spec.design.default == (0.3, 0.5, 0.0)
    assert spec.design.signs == (1, 1, 0)
    assert spec.formulation()["legs"][1]["rail"] == [[0.0, {"design": "y2"}],
                                                     [0.5, {"design": "y2"}]]


def test_editing_a_default_or_a_bound_keeps_the_hash_renaming_or_rekeying_changes_it(tmp_path):
    def sha(text):
        return _read(tmp_path, text).formulation_sha256
    base = sha(_text("shang2010", ISSUE))
    moved = {(i, k): 0.25 for i in (1, 2, 3) for k in ("la", "lb")} | {(2, "base.x"): 0.4}
    assert sha(_text("shang2010", ISSUE, legs=moved)) == base
    assert sha(_text("shang2010", ISSUE.replace("[0.35, 0.50]", "[0.3, 0.55]"))) == base
    assert sha(_text("shang2010", ISSUE.replace("b2x", "base2_x"))) != base
    assert sha(_text("shang2010", ISSUE.replace(', "legs.3.lb"]', "]"))) != base
    # a key left out of [design] is still folded: editing it changes the hash
    la_lb = ISSUE.split("b2x")[0]
    assert sha(_text("shang2010", la_lb, legs={(2, "base.x"): 0.4})) != sha(
        _text("shang2010", la_lb))


# --------------------------------------------------------------------------------------
# Problems of a [design] table: each names its key
# --------------------------------------------------------------------------------------

_K = 'bounds = [0.1, 0.3]'
PROBLEMS = [
    # (model, [design] body, problem key, words of the reason)
    ("shang2010", f'x = {{ keys = ["legs.1.lc"], {_K} }}', "design.x.keys (legs.1.lc)",
     "not a designable key of leg 1 (RRR); allowed: legs.1.la, legs.1.lb, legs.1.base.x"),
    ("shang2010", f'x = {{ keys = ["leg1.la"], {_K} }}', "design.x.keys (leg1.la)",
     'written "legs.<i>.<key>" (legs count from 1'),
    ("shang2010", f'x = {{ keys = ["legs.0.la"], {_K} }}', "design.x.keys (legs.0.la)",
     "legs count from 1"),
    ("shang2010", f'x = {{ keys = ["legs.4.la"], {_K} }}', "design.x.keys (legs.4.la)",
     "there is no leg 4 (the file has 3 [[legs]]"),
    ("shang2010", f'x = {{ keys = [1], {_K} }}', "design.x.keys (entry 1)",
     "must be a key of [[legs]]"),
    ("shang2010", f'x = {{ keys = ["legs.1.la", "legs.1.la"], {_K} }}',
     "design.x.keys (legs.1.la)", "legs.1.la is listed twice in design variable 'x'"),
    ("shang2010", f'x = {{ keys = ["legs.1.la"], {_K} }}\ny = {{ keys = ["legs.1.la"], {_K} }}',
     "design.y.keys (legs.1.la)", "legs.1.la is set by design variables 'x' (legs.1.la) and 'y'"),
    ("shang2010", 'x = { keys = ["legs.1.rail.1.x"], bounds = [-0.1, 0.1] }',
     "design.x.keys (legs.1.rail.1.x)", "not a designable key of leg 1 (RRR)"),
    ("shang2010", f'x = {{ keys = ["legs.1.elbow"], {_K} }}', "design.x.keys (legs.1.elbow)",
     "not a designable key"),
    ("shang2010", f'x = {{ keys = ["legs.1.attach.x"], {_K} }}',
     "design.x.keys (legs.1.attach.x)", "only a platform's legs have an attachment point"),
    ("prr_point", f'x = {{ keys = ["legs.1.la"], {_K} }}', "design.x.keys (legs.1.la)",
     "not a designable key of leg 1 (PRR); allowed: legs.1.lb, legs.1.rail.1.x, "
     "legs.1.rail.1.y, legs.1.rail.2.x, legs.1.rail.2.y"),
    ("prr_point", f'x = {{ keys = ["legs.1.base.x"], {_K} }}', "design.x.keys (legs.1.base.x)",
     "not a designable key of leg 1 (PRR)"),
    ("prr_point", f'x = {{ keys = ["legs.1.rail.start.x"], {_K} }}',
     "design.x.keys (legs.1.rail.start.x)", "allowed: legs.1.lb, legs.1.rail.1.x"),
    ("rpr3_platform", f'x = {{ keys = ["legs.1.stroke.1"], {_K} }}',
     "design.x.keys (legs.1.stroke.1)", "a stroke does not enter the generated C"),
    ("rpr3_platform", f'x = {{ keys = ["legs.1.la"], {_K} }}', "design.x.keys (legs.1.la)",
     "allowed: legs.1.base.x, legs.1.base.y, legs.1.attach.x, legs.1.attach.y"),
    ("shang2010", 'x = { keys = ["legs.1.la"], bounds = [0.1, inf] }', "design.x.bounds",
     "must be finite, got inf"),
    ("shang2010", 'x = { keys = ["legs.1.la"], bounds = [nan, 0.3] }', "design.x.bounds",
     "must be finite, got nan"),
    ("shang2010", 'x = { keys = ["legs.1.la"], bounds = [0.3, 0.2] }', "design.x.bounds",
     "low must be below high, got [0.3, 0.2]"),
    ("shang2010", 'x = { keys = ["legs.1.la"], bounds = [0.2, 0.2] }', "design.x.bounds",
     "low must be below high"),
    ("shang2010", 'x = { keys = ["legs.1.la"], bounds = [0.0, 0.3] }', "design.x.bounds",
     "sets a length (la or lb): low must be > 0, got 0.0"),
    ("shang2010", 'x = { keys = ["legs.1.la"], bounds = [0.1] }', "design.x.bounds",
     "must be [low, high] in m"),
    ("shang2010", 'x = { keys = ["legs.1.la"], bounds = ["a", 0.3] }', "design.x.bounds",
     "must be a number"),
    ("shang2010", 'x = { keys = ["legs.1.la"], bounds = [0.25, 0.3] }', "design.x.bounds",
     "the default legs.1.la = 0.244 (the value in [[legs]]) is outside the bounds [0.25, 0.3]"),
    ("unequal", 'la = { keys = ["legs.1.la", "legs.2.la"], bounds = [0.2, 0.3] }',
     "design.la.keys (legs.2.la)",
     "legs.2.la = 0.24 differs from legs.1.la = 0.25, both set by design variable 'la'"),
    ("shang2010", f'"2x" = {{ keys = ["legs.1.la"], {_K} }}', "design.2x",
     "must be an ASCII identifier"),
    ("shang2010", "x = 0.3", "design.x", "must be a table { keys = [...], bounds"),
    ("shang2010", 'x = { keys = ["legs.1.la"] }', "design.x.bounds", "missing (required)"),
    ("shang2010", f'x = {{ keys = ["legs.1.la"], {_K}, step = 0.01 }}', "design.x.step",
     "unknown key"),
    ("shang2010", f'x = {{ keys = [], {_K} }}', "design.x.keys", "must be a non-empty list"),
    ("shang2010", "", "design", "names no design variable"),
]


@pytest.mark.parametrize("model, body, key, words", PROBLEMS,
                         ids=[f"{i}-{p[2]}" for i, p in enumerate(PROBLEMS)])
def test_each_problem_of_a_design_table_names_its_key(tmp_path, model, body, key, words):
    found = _problems(tmp_path, _text(model, body))
    assert any(k == key and words in reason for k, reason in found), found


def test_a_design_that_is_not_a_table_and_every_problem_at_once(tmp_path):
    text = "design = 3\n" + _text("shang2010")
    assert ("design", "must be a table of design variables, name = { keys = [...], bounds = "
                      "[low, high] }, got int") in _problems(tmp_path, text)
    found = _problems(tmp_path, _text("shang2010", 'x = { keys = ["legs.1.lc"], bounds = '
                                                   '[0.3, 0.2] }\ny = { keys = ["legs.4.la"], '
                                                   'bounds = [0.1, 0.3] }'))
    assert {k for k, _ in found} == {"design.x.keys (legs.1.lc)", "design.x.bounds",
                                     "design.y.keys (legs.4.la)"}


def test_a_coordinate_may_have_bounds_of_any_sign_and_closure_default_follows_the_file(tmp_path):
    spec = _read(tmp_path, _text("shang2010", 'y1 = { keys = ["legs.1.base.y"], '
                                              'bounds = [-0.1, 0.3] }',
                                 sensing="closure_tolerance = 1e-4"))
    assert spec.design.signs == (0,) and not spec.design.closure_default
    spec = _read(tmp_path, _text("rpr3_platform", RPR))
    assert spec.design.signs == (1, -1, 1) and spec.design.default == (0.2598, -0.0693, 0.04)


# --------------------------------------------------------------------------------------
# spec_at_design
# --------------------------------------------------------------------------------------

@pytest.fixture
def paper(tmp_path):
    return _read(tmp_path, _text("shang2010", ISSUE))


def test_a_design_equals_the_conventional_file_with_those_numbers(tmp_path, paper):
    at = spec_at_design(paper, {"la": 0.25, "lb": 0.26, "b2x": 0.45})
    legs = {(i, "la"): 0.25 for i in (1, 2, 3)} | {(i, "lb"): 0.26 for i in (1, 2, 3)}
    plain = _read(tmp_path, _text("shang2010", legs=legs | {(2, "base.x"): 0.45}), "plain.toml")
    _assert_same_spec(at, plain, skip=("path", "file_sha256", "formulation_sha256", "design"))
    assert at.legs[1].base == (0.45, 0.0) and at.legs[0].base == (0.0, 0.25)
    # the default closure tolerance follows la: five encoder steps at la
    assert at.sensing["closure_tolerance"] == pytest.approx(5 * 0.25 * 2 * math.pi / 131072,
                                                            rel=1e-15)
    assert paper.sensing["closure_tolerance"] == pytest.approx(
        5 * 0.244 * 2 * math.pi / 131072, rel=1e-15)
    # the hashes are the file's, and the original spec is unchanged
    assert (at.file_sha256, at.formulation_sha256) == (paper.file_sha256,
                                                       paper.formulation_sha256)
    assert at.design.values == (0.25, 0.26, 0.45) and at.design.default == (0.244, 0.244, 0.433)
    assert paper.legs[0].la == 0.244 and paper.design.values == paper.design.default


def test_a_partial_mapping_keeps_the_others_and_a_sequence_is_in_names_order(paper):
    at = spec_at_design(paper, {"lb": 0.3})
    assert at.design.values == (0.244, 0.3, 0.433)
    assert [(leg.la, leg.lb) for leg in at.legs] == [(0.244, 0.3)] * 3
    again = spec_at_design(at, {"la": 0.2})
    assert again.design.values == (0.2, 0.3, 0.433)
    for values in ([0.2, 0.3, 0.4], (0.2, 0.3, 0.4), np.array([0.2, 0.3, 0.4])):
        at = spec_at_design(paper, values)
        assert at.design.values == (0.2, 0.3, 0.4)
        assert all(type(v) is float for v in at.design.values)
    assert spec_at_design(paper, {"la": np.float64(0.2), "lb": 0.3}).legs[2].la == 0.2


@pytest.mark.parametrize("values, words", [
    ({"la": 0.35}, "design variable 'la' = 0.35 is outside its bounds [0.18, 0.32] "
                   "([design] la)"),
    ([0.2, 0.2, 0.3], "design variable 'b2x' = 0.3 is outside its bounds [0.35, 0.5] "
                      "([design] b2x)"),
    ({"lc": 0.2, "la": 0.2}, "unknown design variable 'lc'; the model file's [design] has "
                             "'la', 'lb', 'b2x'"),
    ({"la": math.nan}, "design variable 'la' = nan is not finite"),
    ({"lb": math.inf}, "design variable 'lb' = inf is not finite"),
    ({"la": "0.2"}, "design variable 'la' must be a number, got '0.2'"),
    ({"la": True}, "design variable 'la' must be a number"),
    ({"la": np.array([0.2])}, "design variable 'la' must be a number"),
    ([0.2, 0.2], "a design has 3 values, in the order (la, lb, b2x), got 2"),
    (0.2, "a design is a mapping {name: value} or a sequence of 3 values"),
    ("la", "a design is a mapping {name: value} or a sequence of 3 values"),
])
def test_a_bad_design_is_a_design_error_naming_the_variable(paper, values, words):
    with pytest.raises(DesignError) as info:
        spec_at_design(paper, values)
    assert words in str(info.value)
    assert isinstance(info.value, (ValueError, Pm2dofError))
    assert isinstance(info.value, pm2dof.DesignError)


def test_a_file_without_design_has_no_design_to_set():
    spec = read_model_file(SHIPPED_MODELS / "shang2010.toml")
    with pytest.raises(DesignError, match=r"has no \[design\] table"):
        spec_at_design(spec, {})


def test_an_unreachable_move_or_home_names_the_move_or_home_and_the_leg(tmp_path, paper):
    # leg 2's base at (0.5, 0) is 0.403 m from the moves' start (0.22, 0.29), beyond la + lb
    with pytest.raises(DesignError) as info:
        spec_at_design(paper, {"la": 0.18, "lb": 0.18, "b2x": 0.5})
    assert ("at this design (la = 0.18, lb = 0.18, b2x = 0.5) the move 'low' start "
            "[0.22, 0.29] is out of reach: leg 2 (RRR) is 0.4031 m from its base, its reach "
            "is [0, 0.36] m") in str(info.value)
    # rrr3_platform: home (0, 0, 0) puts each attachment point 0.24 m from its base
    platform = _read(tmp_path, _text("rrr3_platform", LA_LB), "platform.toml")
    with pytest.raises(DesignError) as info:
        spec_at_design(platform, {"la": 0.1, "lb": 0.1})
    message = str(info.value)
    assert "[platform] home [0.0, 0.0, 0.0] is out of reach: leg 1 (RRR) is 0.24" in message
    assert "leg 2 (RRR)" in message and "leg 3 (RRR)" in message
    # home reachable (0.24 m < la + lb = 0.25 m), the moves' end not (leg 1: 0.2906 m)
    with pytest.raises(DesignError) as info:
        spec_at_design(platform, {"la": 0.12, "lb": 0.13})
    assert ("the move 'low' end [0.04, 0.03, 0.2] is out of reach: leg 1 (RRR) is 0.2906 m "
            "from its base, its reach is [0.01, 0.25] m") in str(info.value)
    spec_at_design(platform, {"la": 0.15, "lb": 0.16})


def test_a_prr_rail_moves_turns_and_may_not_shrink_to_a_point(tmp_path):
    spec = _read(tmp_path, _text("prr_point", PRR))
    at = spec_at_design(spec, {"y2": 0.51, "x3": 0.03, "lb": 0.31})
    assert at.legs[1].base == (0.0, 0.51) and at.legs[1].rail_end == (0.5, 0.51)
    assert at.legs[2].base == (0.03, 0.0) and at.legs[2].rail_end == (0.0, 0.5)
    assert at.legs[0] == dataclasses.replace(spec.legs[0], lb=0.31)
    # linear actuators: the default closure tolerance is five linear steps, whatever lb
    assert at.sensing["closure_tolerance"] == spec.sensing["closure_tolerance"] == 5 * 1e-6
    zero = _read(tmp_path, _text("prr_point", 'e1 = { keys = ["legs.1.rail.2.x"], '
                                              'bounds = [0.0, 0.6] }'), "zero.toml")
    with pytest.raises(DesignError, match=r"leg 1's rail has zero length \(both ends at "
                                          r"\[0.0, 0.0\]\), set by design variable 'e1'"):
        spec_at_design(zero, {"e1": 0.0})


def test_a_platform_attachment_point_is_designed(tmp_path):
    spec = _read(tmp_path, _text("rpr3_platform", RPR))
    at = spec_at_design(spec, {"a3x": -0.06, "a3y": 0.05, "b2x": 0.25})
    assert at.legs[2].attach == (-0.06, 0.05) and at.legs[1].base == (0.25, -0.15)
    assert at.legs[0] is spec.legs[0]
    _assert_same_spec(at, spec, skip=("legs", "design"))      # no rods: theta as given


# --------------------------------------------------------------------------------------
# Links as uniform rods
# --------------------------------------------------------------------------------------

RRR_RODS = ["proximal = { density = 3.0 }\ndistal = { density = 2.0 }"] * 3


def _rrr_rod_theta(rho_a, rho_b, la, lb):
    """alpha, beta, gamma, kappa of an RRR leg of two uniform rods, by hand: the proximal rod
    about A (rho_a la^3/3), the distal rod's mass at B; beta = m_b la c_b with c_b = lb/2."""
    return (rho_a * la ** 3 / 3 + rho_b * lb * la ** 2, rho_b * la * lb ** 2 / 2,
            rho_b * lb ** 3 / 3, rho_a * la ** 2 / 2 + rho_b * lb * la)


def test_rods_give_the_theta_of_the_equivalent_bodies_and_of_the_shipped_comment(tmp_path):
    rods = _read(tmp_path, _text("rrr3_platform", rods=RRR_RODS), "rods.toml")
    la = lb = 0.2
    body = (f"proximal = {{ mass = {3.0 * la!r}, com = {la / 2!r}, inertia = "
            f"{3.0 * la ** 3 / 12!r} }}\ndistal = {{ mass = {2.0 * lb!r}, com = {lb / 2!r}, "
            f"inertia = {2.0 * lb ** 3 / 12!r} }}")
    solid = _read(tmp_path, _text("rrr3_platform", rods=[body] * 3), "solid.toml")
    np.testing.assert_allclose(rods.theta_nominal, solid.theta_nominal, rtol=1e-15, atol=0)
    for key in ("alpha", "beta", "gamma"):
        np.testing.assert_allclose(rods.plant[key], solid.plant[key], rtol=1e-15, atol=0)
    # the shipped file's lumped numbers (rounded there to 5 significant digits)
    shipped = read_model_file(SHIPPED_MODELS / "rrr3_platform.toml")
    np.testing.assert_allclose(rods.theta_nominal, shipped.theta_nominal, rtol=1e-5, atol=0)
    assert solid.links is None
    assert rods.links["nominal"][0]["proximal"] == {"density": 3.0}
    assert rods.links["plant"][2]["distal"] == {"density": 2.0}
    # a spec crosses processes (Dask workers): it pickles, with its links and its design
    again = pickle.loads(pickle.dumps(rods))
    _assert_same_spec(again, rods)


def test_theta_follows_the_lengths_of_rod_links_at_a_design(tmp_path):
    spec = _read(tmp_path, _text("rrr3_platform", LA_LB, rods=RRR_RODS), "rods.toml")
    at = spec_at_design(spec, {"la": 0.22, "lb": 0.25})
    alpha, beta, gamma, _ = _rrr_rod_theta(3.0, 2.0, 0.22, 0.25)
    names = at.param_names
    for i in (1, 2, 3):
        for key, want in (("alpha", alpha), ("beta", beta), ("gamma", gamma)):
            assert at.theta_nominal[names.index(f"{key}{i}")] == pytest.approx(want, rel=1e-14)
            assert at.plant[key][i - 1] == pytest.approx(want, rel=1e-14)
    # the platform and the friction stay as given
    for name in ("m_p", "I_p", "fv1", "fc3"):
        assert at.theta_nominal[names.index(name)] == spec.theta_nominal[names.index(name)]
    assert at.plant["payload_mass"] == spec.plant["payload_mass"]
    assert not at.theta_nominal.flags.writeable and not at.plant["alpha"].flags.writeable
    # and equal to the conventional file with rods at those lengths
    legs = {(i, "la"): 0.22 for i in (1, 2, 3)} | {(i, "lb"): 0.25 for i in (1, 2, 3)}
    plain = _read(tmp_path, _text("rrr3_platform", rods=RRR_RODS, legs=legs), "plain.toml")
    _assert_same_spec(at, plain, skip=("path", "file_sha256", "formulation_sha256", "design"))


def test_only_the_legs_and_sections_with_a_rod_follow(tmp_path):
    solid = "proximal = { mass = 0.6, com = 0.1, inertia = 0.002 }\ndistal = { density = 2.0 }"
    fixed = "proximal = { mass = 0.6, com = 0.1, inertia = 0.002 }\ndistal = { mass = 0.4, " \
            "com = 0.1, inertia = 0.0013333 }"
    spec = _read(tmp_path, _text("rrr3_platform", LA_LB, rods=[RRR_RODS[0], solid, fixed],
                                 rod_sections=("plant",)))
    assert spec.links["nominal"] is None
    at = spec_at_design(spec, {"la": 0.22, "lb": 0.25})
    assert np.array_equal(at.theta_nominal, spec.theta_nominal)      # [nominal]: lumped
    # leg 1: two rods; leg 2: a solid proximal link, a rod distal link; leg 3: solid
    alpha, beta, gamma, _ = _rrr_rod_theta(3.0, 2.0, 0.22, 0.25)
    np.testing.assert_allclose([at.plant[k][0] for k in ("alpha", "beta", "gamma")],
                               [alpha, beta, gamma], rtol=1e-14)
    mb, cb, ib = 2.0 * 0.25, 0.125, 2.0 * 0.25 ** 3 / 12
    np.testing.assert_allclose([at.plant[k][1] for k in ("alpha", "beta", "gamma")],
                               [0.002 + 0.6 * 0.01 + mb * 0.22 ** 2, mb * 0.22 * cb,
                                ib + mb * cb ** 2], rtol=1e-14)
    assert [at.plant[k][2] for k in ("alpha", "beta", "gamma")] == [
        spec.plant[k][2] for k in ("alpha", "beta", "gamma")]


def test_kappa_follows_under_gravity(tmp_path):
    spec = _read(tmp_path, _text("shang2010_vertical", ISSUE, rods=RRR_RODS))
    at = spec_at_design(spec, {"la": 0.2, "lb": 0.3})
    want = _rrr_rod_theta(3.0, 2.0, 0.2, 0.3)
    for i in (1, 2, 3):
        got = [at.theta_nominal[at.param_names.index(f"{k}{i}")]
               for k in ("alpha", "beta", "gamma", "kappa")]
        np.testing.assert_allclose(got, want, rtol=1e-14)
        np.testing.assert_allclose(at.plant["kappa"][i - 1], want[3], rtol=1e-14)


def test_a_prr_link_may_be_a_rod_its_slider_not(tmp_path):
    rods = ["slider = { mass = 1.0 }\nlink = { density = 1.0 }"] * 3
    spec = _read(tmp_path, _text("prr_point", PRR, rods=rods))
    at = spec_at_design(spec, {"lb": 0.31})
    lb = 0.31
    for i in range(3):
        got = [at.theta_nominal[at.param_names.index(f"{k}{i + 1}")]
               for k in ("alpha", "beta", "gamma")]
        np.testing.assert_allclose(got, [1.0 + lb, lb ** 2 / 2, lb ** 3 / 3], rtol=1e-14)
    bad = ["slider = { density = 2.0 }\nlink = { density = 1.0 }"] * 3
    found = _problems(tmp_path, _text("prr_point", rods=bad))
    assert any(k == "nominal.links (leg 1).slider.density"
               and "only a body with a length (RRR proximal and distal, PRR link) may be a "
                   "uniform rod" in r for k, r in found), found


@pytest.mark.parametrize("body, key, words", [
    ("proximal = { density = 0.0 }\ndistal = { density = 2.0 }",
     "nominal.links (leg 1).proximal.density", "must be > 0"),
    ("proximal = { density = 3.0, mass = 0.6 }\ndistal = { density = 2.0 }",
     "nominal.links (leg 1).proximal.mass", "unknown key; allowed here: ['density']"),
])
def test_a_bad_rod_is_reported(tmp_path, body, key, words):
    found = _problems(tmp_path, _text("rrr3_platform", rods=[body] + RRR_RODS[1:]))
    assert any(k == key and words in r for k, r in found), found


def test_rods_of_an_rpr_leg_are_refused(tmp_path):
    body = ("cylinder = { density = 1.0 }\n"
            "rod = { mass = 0.4, com = 0.1, inertia = 0.0012 }")
    found = _problems(tmp_path, _text("rpr3_platform", rods=[body] * 3))
    assert any(k == "nominal.links (leg 1).cylinder.density" for k, _ in found), found


def test_a_lumped_inertia_refused_at_a_design_names_the_leg(tmp_path, monkeypatch):
    spec = _read(tmp_path, _text("rrr3_platform", LA_LB, rods=RRR_RODS))
    from pm2dof.core import design
    monkeypatch.setattr(design, "inertia_problem",
                        lambda a, b, g: "refused" if a > 0.03 else None)
    spec_at_design(spec, {"la": 0.2})
    with pytest.raises(DesignError, match=r"leg 1's \[\[nominal.links\]\] give a lumped "
                                          r"inertia that no leg can have: refused"):
        spec_at_design(spec, {"la": 0.25})


# --------------------------------------------------------------------------------------
# The default design is the file
# --------------------------------------------------------------------------------------

FIXTURES = [("shang2010", ISSUE, None), ("prr_point", PRR, None),
            ("rrr3_platform", LA_LB, RRR_RODS), ("rpr3_platform", RPR, None),
            ("shang2010_vertical", ISSUE, RRR_RODS)]


@pytest.mark.parametrize("model, design, rods", FIXTURES, ids=[f[0] for f in FIXTURES])
def test_the_default_design_gives_the_file_back_also_after_other_designs(tmp_path, model,
                                                                         design, rods):
    spec = _read(tmp_path, _text(model, design, rods=rods))
    assert isinstance(spec.design, Design)
    _assert_same_spec(spec_at_design(spec, spec.design.default), spec)
    _assert_same_spec(spec_at_design(spec, {}), spec)
    rng = np.random.default_rng(7)
    lo, hi = np.array(spec.design.bounds).T
    done = 0
    for _ in range(20):
        values = rng.uniform(lo, hi)
        try:
            at = spec_at_design(spec, values)
        except DesignError:          # a design where a move or home is out of reach
            continue
        done += 1
        assert at.design.values == tuple(values)
        _assert_same_spec(spec_at_design(at, spec.design.default), spec)
    assert done >= 5


def test_the_fast_replace_builds_what_dataclasses_replace_builds():
    """spec_at_design copies the spec's frozen dataclasses with design._replace (no __init__):
    for ModelSpec, Leg and Design it gives the object dataclasses.replace gives, field by
    field (the very objects), and refuses a field the class does not have."""
    from pm2dof.core.design import _replace
    spec = read_model_file(SHIPPED_MODELS / "rrr4_platform_design.toml")
    leg = spec.legs[1]
    cases = [(spec, {"legs": spec.legs[::-1], "sensing": {}}),
             (leg, {"la": 0.31, "base": (1.0, 2.0)}),
             (spec.design, {"values": (0.21, 0.22)}),
             (leg, {})]
    for obj, changes in cases:
        got, want = _replace(obj, **changes), dataclasses.replace(obj, **changes)
        assert type(got) is type(want) and got is not obj
        for f in dataclasses.fields(obj):
            assert getattr(got, f.name) is getattr(want, f.name), f.name
        with pytest.raises(dataclasses.FrozenInstanceError):
            got.name = "x"
    with pytest.raises(TypeError, match="no field 'lc'"):
        _replace(leg, lc=0.2)
