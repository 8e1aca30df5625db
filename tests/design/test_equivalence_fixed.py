# The design check's tools on fixed models: the TOML writer, the conventional file, the inputs, the comparison.
"""Self-checks of tests/design/conventional.py and tests/design/equivalence.py that need no
design variable in the generated code.

* The TOML writer round-trips every shipped model file (and every design fixture) through
  :mod:`tomllib` exactly, and its edge cases (escapes, nested and inline tables, arrays of
  tables at depth, signed zero, infinities, quoted keys).
* :func:`conventional_file` writes each design variable into every key it sets (RRR lengths,
  bases, platform attachments; PRR rail ends, both spellings) and nothing else, and drops
  ``[design]``.
* :func:`function_inputs` gives inputs of the right sizes, finite, for every function of the
  manifest (none skipped), at poses with both singularity measures above 0.2.
* The comparison is right: the shipped compiled C of shang2010 and prr3_platform (rrr3_platform
  in the slow tier) equals, on every function of its manifest at 2 poses, the CasADi functions
  of an in-memory derivation of the same file evaluated by CasADi's VM, to
  1e-12 max(1, |b|_inf) (measured: 0, bit for bit: the same instructions in the same order);
  and the comparison reports another geometry (unequal's C against shang2010's derivation)
  on the functions of the pose.
"""
from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

import pm2dof
from pm2dof.core.model_file import read_model_file
from pm2dof.core.paths import SHIPPED_MODELS
from tests import derivations
from tests.design.conventional import conventional_doc, conventional_file, dumps, set_key
from tests.design.equivalence import (
    SING_MIN,
    TOL,
    compare_all,
    draw_pose,
    function_inputs,
    short_names,
)

pytestmark = pytest.mark.slow     # in-memory derivations (seconds each): make test-slow (CI)

FIXTURES = SHIPPED_MODELS.parent.parent / "tests" / "design" / "models"
TOML_FILES = sorted(SHIPPED_MODELS.glob("*.toml")) + sorted(FIXTURES.glob("*.toml"))

# {model: {function: largest relative error}}, printed at module teardown (-s)
_OBSERVED: dict = {}


@pytest.fixture(scope="module", autouse=True)
def _report_observed():
    yield
    for name, obs in sorted(_OBSERVED.items()):
        worst = max(obs, key=obs.get)
        print(f"\n[test_equivalence_fixed] {name}: {len(obs)} functions, largest relative "
              f"error {obs[worst]:.3e} ({worst})")


# --- the TOML writer ----------------------------------------------------------------------

@pytest.mark.parametrize("path", TOML_FILES, ids=lambda p: p.stem)
def test_writer_round_trips_every_model_file(path):
    with open(path, "rb") as fh:
        doc = tomllib.load(fh)
    assert tomllib.loads(dumps(doc)) == doc


def test_writer_edge_cases():
    doc = {"title": 'a "quoted" \\ back\tslash\nnew line \u00e9 \x01 \x7f',
           "n": 3, "neg": -7, "yes": True, "no": False, "f": 0.1, "tiny": 5e-324,
           "big": 1.7976931348623157e308, "e": 1e-05, "nz": -0.0, "inf": math.inf,
           "ninf": -math.inf, "empty": [], "mixed": [[1, 2], [3.5, "x"]],
           "array_of_inline": [{"a": 1}, {"b": [1.0, 2.0]}],
           "key with space": {"dotted.key": 1, "ok": {"deep": {"deeper": "yes"}}},
           "outer": {"x": 1.0, "list": [{"p": {"density": 3.0}, "q": [{"r": 1}]},
                                        {"p": {"density": 2.0}}],
                     "empty_table": {}},
           "aot": [{"name": "a", "sub": {"k": 1}}, {"name": "b"}]}
    text = dumps(doc)
    back = tomllib.loads(text)
    assert back == doc, text
    assert math.copysign(1.0, back["nz"]) == -1.0
    assert back["tiny"] == 5e-324 and back["big"] == 1.7976931348623157e308
    assert "\x7f" not in text and "\x01" not in text        # control characters escaped


def test_writer_floats_are_exact():
    rng = np.random.default_rng(1)
    values = [float(v) for v in rng.uniform(-1, 1, 200) * 10.0 ** rng.integers(-12, 12, 200)]
    assert tomllib.loads(dumps({"v": values}))["v"] == values


# --- the conventional file ----------------------------------------------------------------

_RRR_DESIGN = """
[design]
la = { keys = ["legs.1.la", "legs.2.la", "legs.3.la"], bounds = [0.18, 0.32] }
b2x = { keys = ["legs.2.base.x"], bounds = [0.35, 0.50] }
b3y = { keys = ["legs.3.base.y"], bounds = [0.4, 0.6] }
"""

_PRR_DESIGN = """
[design]
lb = { keys = ["legs.1.lb", "legs.2.lb", "legs.3.lb"], bounds = [0.15, 0.25] }
side = { keys = ["legs.3.rail.start.y", "legs.3.rail.end.y"], bounds = [0.2, 0.24] }
turn = { keys = ["legs.2.rail.1.x"], bounds = [0.08, 0.1] }
a1y = { keys = ["legs.1.attach.y"], bounds = [-0.05, 0.0] }
"""


def _with_design(tmp_path, name, table):
    src = SHIPPED_MODELS / f"{name}.toml"
    path = tmp_path / f"{name}_design.toml"
    path.write_text(src.read_text() + table)
    with open(src, "rb") as fh:
        return path, tomllib.load(fh)


def test_conventional_file_writes_every_key_and_nothing_else(tmp_path):
    path, plain = _with_design(tmp_path, "shang2010", _RRR_DESIGN)
    out = conventional_file(path, {"la": 0.2512345678901234, "b2x": 0.41}, tmp_path / "c.toml")
    with open(out, "rb") as fh:
        got = tomllib.load(fh)
    assert "design" not in got
    want = plain
    for leg in want["legs"]:
        leg["la"] = 0.2512345678901234
    want["legs"][1]["base"][0] = 0.41            # b3y not given: the file's number stays
    assert got == want
    # a sequence in the file's [design] order
    conventional_file(path, [0.3, 0.36, 0.55], tmp_path / "d.toml")
    with open(tmp_path / "d.toml", "rb") as fh:
        got = tomllib.load(fh)
    assert [leg["la"] for leg in got["legs"]] == [0.3] * 3
    assert got["legs"][1]["base"] == [0.36, 0.0] and got["legs"][2]["base"] == [0.433, 0.55]


def test_conventional_file_prr_rails_and_attachments(tmp_path):
    path, plain = _with_design(tmp_path, "prr3_platform", _PRR_DESIGN)
    values = {"lb": 0.21, "side": 0.23, "turn": 0.1, "a1y": -0.01}
    out = conventional_file(path, values, tmp_path / "c.toml")
    with open(out, "rb") as fh:
        got = tomllib.load(fh)
    want = plain
    for leg in want["legs"]:
        leg["lb"] = 0.21
    want["legs"][2]["rail"][0][1] = want["legs"][2]["rail"][1][1] = 0.23
    want["legs"][1]["rail"][0][0] = 0.1
    want["legs"][0]["attach"][1] = -0.01
    assert got == want
    spec = read_model_file(out)                 # pm2dof reads it as a plain model file
    assert spec.legs[2].base[1] == spec.legs[2].rail_end[1] == 0.23
    assert spec.legs[1].base[0] == 0.1 and spec.legs[0].lb == 0.21


def test_conventional_doc_refuses_unknown_names_and_keys():
    with pytest.raises(KeyError, match="unknown design variable"):
        conventional_doc({"design": {"la": {"keys": ["legs.1.la"]}}, "legs": [{}]}, {"lb": 1.0})
    with pytest.raises(KeyError, match="unknown design key"):
        set_key({"legs": [{"la": 1.0}]}, "legs.1.stroke", 0.2)
    with pytest.raises(KeyError, match="not a"):
        set_key({"legs": []}, "platform.home.x", 0.2)


# --- the inputs and the comparison on the shipped fixed models ----------------------------

_MODELS = {}


def _model(name):
    if name not in _MODELS:
        _MODELS[name] = pm2dof.load_model(name)
    return _MODELS[name]


def _derived(model):
    """The CasADi functions of the shipped file's derivation, in memory (shared per process
    with the other modules that derive it: tests/derivations.py)."""
    spec = read_model_file(model.spec.path)
    return derivations.functions(derivations.derivation(spec), spec)


FIXED = ["shang2010", "prr3_platform",
         pytest.param("rrr3_platform", marks=pytest.mark.slow)]


@pytest.mark.parametrize("name", ["shang2010", "prr3_platform", "rrr3_platform", "rpr3_platform",
                                  "fivebar", "shang2010_vertical"])
def test_function_inputs_cover_every_function(name):
    m = _model(name)
    rng = np.random.default_rng(7)
    pose = draw_pose(m, rng)
    assert np.all(m.singularity_measures(pose.q) > SING_MIN)
    shorts = short_names(m)
    assert len(shorts) == len(m.manifest["functions"]) > 50
    for short in shorts:
        f = m.function(short)
        args = function_inputs(m, short, rng, pose)
        assert [a.size for a in args] == list(f.sizes_in), short
        assert all(np.all(np.isfinite(a)) for a in args), short


@pytest.mark.parametrize("name", FIXED)
def test_compiled_C_equals_an_in_memory_derivation(name):
    m = _model(name)
    observed = _OBSERVED.setdefault(name, {})
    bad = compare_all(m, _derived(m), np.random.default_rng(2010), poses=2, observed=observed)
    assert not bad, f"{name}: compiled C vs CasADi VM, tolerance {TOL:g}:\n" + \
        "\n".join(map(str, bad))
    assert set(observed) == set(short_names(m))      # every function was compared


def test_the_comparison_reports_another_geometry():
    """unequal (the paper's robot, other lengths and bases) against shang2010's derivation,
    its functions renamed: every function of the pose differs, and only those."""
    m = _model("unequal")
    functions = {f.name().replace("shang2010_", "unequal_", 1): f
                 for f in _derived(_model("shang2010"))}
    bad = {b.function for b in compare_all(m, functions, np.random.default_rng(3), poses=1)}
    for short in ("ik", "fk", "H", "W", "S", "Me", "forward_dynamics", "na_step",
                  "apd_minmax_closed_loop", "plant_step", "sampled_step_jacobians",
                  "path_coefficients", "torque_splits", "kinetic_energy", "measure"):
        assert short in bad, f"{short}: another geometry not reported"
    # the planner's passes read only the stage vectors and theta: no geometry in them
    assert not bad & {"path_mvc", "path_backward", "path_forward"}
