# The model-file loader (pm2dof.model_file.read_model_file): fuzzed, then one test per rule.
"""Tests of model-file validation and of the generated-code staleness guard.

* A fuzz test (hypothesis, derandomised) starts from ``models/shang2010.toml`` and applies
  random mutations, structured (delete a key or list element, add an unknown key, replace a
  value by one of another type or by a negative / zero / NaN / infinite / huge number, change
  a list's length) and byte-level (truncate at a random byte, flip random bytes, insert NUL
  bytes, random garbage, the empty file). The loader must either return a ModelSpec that
  satisfies the physical invariants it promises, or raise ModelFileError naming the file;
  never any other exception.
* Targeted tests, one per validation rule: the message names the file, the key and the reason.
* StaleGeneratedCodeError: a model file whose formulation (legs) differs from the one its
  generated code was derived from, or a model name with no generated code at all, is refused
  with a message that names the ``pm2dof derive ...`` command to run; a copy that differs only in comments or
  run-time data loads (the positive control that makes the negative tests meaningful).
"""
from __future__ import annotations

import copy
import json
import math
import re
import shutil
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import pm2dof
from pm2dof.core.errors import ModelFileError, StaleGeneratedCodeError
from pm2dof.core.model_file import ModelSpec, read_model_file
from pm2dof.core.paths import SHIPPED_GENERATED, SHIPPED_MODELS

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

REPO = Path(__file__).resolve().parent.parent
PAPER = SHIPPED_MODELS / "shang2010.toml"
FIVEBAR = SHIPPED_MODELS / "fivebar.toml"
SRC = PAPER.read_text()
SRC_BYTES = PAPER.read_bytes()
DOC = tomllib.loads(SRC)


# --------------------------------------------------------------------------------------
# A minimal TOML writer (the standard library only reads TOML)
# --------------------------------------------------------------------------------------

def _value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)  # JSON escapes are valid TOML basic-string escapes
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k} = {_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(type(v))


def _is_table_array(v):
    return isinstance(v, list) and v and all(isinstance(x, dict) for x in v)


def dump(doc, prefix=""):
    """TOML text of ``doc``: scalars and inline values first, then [tables] and [[arrays]]."""
    lines = [f"{k} = {_value(v)}" for k, v in doc.items()
             if not isinstance(v, dict) and not _is_table_array(v)]
    for k, v in doc.items():
        name = f"{prefix}{k}"
        if isinstance(v, dict):
            lines += ["", f"[{name}]", dump(v, name + ".")]
        elif _is_table_array(v):
            for item in v:  # nested tables inside array elements: inline
                lines += ["", f"[[{name}]]"] + [f"{kk} = {_value(vv)}" for kk, vv in item.items()]
    return "\n".join(lines)


def write(tmp_path, content, name="model.toml"):
    p = Path(tmp_path) / name
    if isinstance(content, bytes):
        p.write_bytes(content)
    else:
        p.write_text(content, encoding="utf-8")
    return p


def mutated(**edits):
    """A deep copy of the paper's model document with ``edits``: {"a.b.c": value or DELETE}."""
    doc = copy.deepcopy(DOC)
    for dotted, value in edits.items():
        *parents, last = _split(dotted)
        node = doc
        for k in parents:
            node = node[k]
        if value is DELETE:
            del node[last]
        else:
            node[last] = value
    return dump(doc)


DELETE = object()


def _split(dotted):
    """'legs.0.base' -> ['legs', 0, 'base']."""
    return [int(k) if k.isdigit() else k for k in dotted.split(".")]


def load_error(tmp_path, content, name="model.toml"):
    """The ModelFileError the loader raises for ``content`` (fails if it loads)."""
    p = write(tmp_path, content, name)
    with pytest.raises(ModelFileError) as info:
        read_model_file(p)
    return p, str(info.value)


def assert_names(msg, path, key, *reasons):
    assert str(path) in msg, f"message does not name the file {path}: {msg!r}"
    assert f"[{key}]" in msg, f"message does not name the key [{key}]: {msg!r}"
    for r in reasons:
        assert r in msg, f"message does not give the reason {r!r}: {msg!r}"


# --------------------------------------------------------------------------------------
# The writer itself (so that the fuzz and targeted tests mutate what they think they do)
# --------------------------------------------------------------------------------------

def test_writer_round_trips_the_paper_model(tmp_path):
    text = dump(DOC)
    assert tomllib.loads(text) == DOC, "the test's TOML writer does not round-trip the model"
    spec = read_model_file(write(tmp_path, text))
    ref = read_model_file(PAPER)
    assert spec.formulation_sha256 == ref.formulation_sha256
    assert np.array_equal(spec.theta_nominal, ref.theta_nominal)
    assert spec.param_names == ref.param_names


# --------------------------------------------------------------------------------------
# Fuzz
# --------------------------------------------------------------------------------------

def _paths(node, prefix=()):
    """Every (path) to a value inside the document (dict keys and list indices)."""
    out = []
    items = node.items() if isinstance(node, dict) else enumerate(node)
    for k, v in items:
        out.append(prefix + (k,))
        if isinstance(v, (dict, list)):
            out += _paths(v, prefix + (k,))
    return out


def _containers(node, prefix=()):
    out = [prefix] if isinstance(node, dict) else []
    items = node.items() if isinstance(node, dict) else enumerate(node)
    for k, v in items:
        if isinstance(v, (dict, list)):
            out += _containers(v, prefix + (k,))
    return out


def _get(doc, path):
    for k in path:
        doc = doc[k]
    return doc


PATHS = _paths(DOC)
LIST_PATHS = [p for p in PATHS if isinstance(_get(DOC, p), list)]
NUMBER_PATHS = [p for p in PATHS if isinstance(_get(DOC, p), (int, float))
                and not isinstance(_get(DOC, p), bool)]
TABLE_PATHS = _containers(DOC)

_scalar = st.one_of(
    st.booleans(),
    st.integers(-10**6, 10**6),
    st.sampled_from([0, -1, 10**400, -10**400, 2**63, 0.0, -0.0, -1e-300, 1e308, -1e308,
                     math.nan, math.inf, -math.inf, 1e-320]),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(alphabet="abcxyz_ 019.-\"\\é", max_size=8),
    st.sampled_from(["left", "right", "up", "coulomb_viscous", "smooth_sign", "", "nan"]),
)
_weird = st.recursive(
    _scalar,
    lambda inner: st.one_of(st.lists(inner, max_size=6),
                            st.dictionaries(st.sampled_from(["a", "la", "base", "x1"]), inner,
                                            max_size=3)),
    max_leaves=8)


@st.composite
def structured_mutation(draw):
    doc = copy.deepcopy(DOC)
    n = draw(st.integers(1, 3))
    log = []
    for _ in range(n):
        kind = draw(st.sampled_from(["delete", "replace", "unknown", "length", "scale"]))
        if kind == "delete":
            path = draw(st.sampled_from(PATHS))
            try:
                parent = _get(doc, path[:-1])
                del parent[path[-1]]
            except (KeyError, IndexError, TypeError):
                continue
        elif kind == "replace":
            path = draw(st.sampled_from(PATHS))
            try:
                _get(doc, path[:-1])[path[-1]] = draw(_weird)
            except (KeyError, IndexError, TypeError):
                continue
        elif kind == "unknown":
            path = draw(st.sampled_from(TABLE_PATHS))
            try:
                node = _get(doc, path)
            except (KeyError, IndexError, TypeError):
                continue
            if isinstance(node, dict):
                node[draw(st.sampled_from(["bogus", "mass", "tau_min", "Kp"]))] = draw(_scalar)
        elif kind == "length":
            path = draw(st.sampled_from(LIST_PATHS))
            try:
                node = _get(doc, path)
            except (KeyError, IndexError, TypeError):
                continue
            if isinstance(node, list):
                if node and draw(st.booleans()):
                    node.pop()
                else:
                    node.append(copy.deepcopy(node[-1]) if node else 1.0)
        else:  # scale a number: sign flip, zero, huge, tiny, NaN
            path = draw(st.sampled_from(NUMBER_PATHS))
            try:
                parent = _get(doc, path[:-1])
                v = parent[path[-1]]
                parent[path[-1]] = v * draw(st.sampled_from([-1.0, 0.0, 1e300, 1e-300, math.nan,
                                                              -1e300, 1e6]))
            except (KeyError, IndexError, TypeError):
                continue
        log.append((kind, path))
    return dump(doc), log


@st.composite
def byte_mutation(draw):
    raw = bytearray(SRC_BYTES)
    kind = draw(st.sampled_from(["truncate", "flip", "nul", "garbage", "empty", "splice"]))
    if kind == "truncate":
        raw = raw[:draw(st.integers(0, len(raw) - 1))]
    elif kind == "flip":
        for _ in range(draw(st.integers(1, 8))):
            i = draw(st.integers(0, len(raw) - 1))
            raw[i] ^= draw(st.integers(1, 255))
    elif kind == "nul":
        for _ in range(draw(st.integers(1, 3))):
            raw.insert(draw(st.integers(0, len(raw))), 0)
    elif kind == "garbage":
        raw = bytearray(draw(st.binary(max_size=200)))
    elif kind == "empty":
        raw = bytearray()
    else:  # replace a span by random bytes
        i = draw(st.integers(0, len(raw) - 1))
        j = draw(st.integers(i, min(len(raw), i + 40)))
        raw[i:j] = draw(st.binary(max_size=20))
    return bytes(raw), kind


def check_spec_invariants(spec, where):
    """What a ModelSpec promises: finite, physical values."""
    assert isinstance(spec, ModelSpec), where
    n = spec.n_legs
    assert n >= 2, where
    th = np.asarray(spec.theta_nominal)
    assert th.shape == (len(spec.param_names),) and np.isfinite(th).all(), where
    a, b, g = th[0:n], th[n:2 * n], th[2 * n:3 * n]
    assert (a > 0).all() and (g > 0).all() and (b * b < a * g).all(), f"{where}: theta {th}"
    friction = np.array([k.startswith(("fv", "fc", "fs")) for k in spec.param_names])
    assert (th[friction] >= 0).all(), f"{where}: negative friction in {th}"
    for leg in spec.legs:   # by kind (docs/model-file.md)
        assert all(math.isfinite(c) for c in leg.base), where
        if leg.kind == "RRR":
            assert leg.la > 0 and leg.lb > 0 and leg.elbow in (1, -1), where
        elif leg.kind == "PRR":
            assert leg.rail_length > 0 and leg.lb > 0 and leg.elbow in (1, -1), where
        else:
            assert 0 < leg.stroke[0] < leg.stroke[1], where
        assert (leg.attach is not None) == (spec.end_effector == "platform"), where
    assert 0 < spec.limits["singularity_threshold"] < 1, where
    assert (np.asarray(spec.limits["tau_max"]) > 0).all(), where
    assert spec.sensing["sample_period"] > 0, where
    p = spec.plant
    assert (p["alpha"] > 0).all() and (p["gamma"] > 0).all(), where
    assert (p["beta"] ** 2 < p["alpha"] * p["gamma"]).all(), where
    for k in ("fv", "fc", "fs"):
        assert (p[k] >= 0).all(), where
    assert spec.trajectories, where
    for t in spec.trajectories.values():
        for k in ("v_max", "a_max", "j_max"):
            assert t[k] > 0, where


def _load_or_model_file_error(path, where):
    try:
        spec = read_model_file(path)
    except ModelFileError as exc:
        assert str(path) in str(exc), f"ModelFileError does not name the file: {exc} ({where})"
        return None
    except Exception as exc:  # noqa: BLE001 - the property under test
        raise AssertionError(f"read_model_file raised {type(exc).__name__}: {exc} for {where}; "
                             f"content written to {path}") from exc
    check_spec_invariants(spec, where)
    return spec


@pytest.fixture(scope="module")
def fuzz_dir(tmp_path_factory):
    return tmp_path_factory.mktemp("fuzz")


@settings(derandomize=True, max_examples=400, deadline=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(case=structured_mutation())
def test_fuzz_structured_mutations(fuzz_dir, case):
    text, log = case
    p = write(fuzz_dir, text, "structured.toml")
    _load_or_model_file_error(p, f"mutations {log}")


@settings(derandomize=True, max_examples=400, deadline=None)
@given(case=byte_mutation())
def test_fuzz_byte_mutations(fuzz_dir, case):
    raw, kind = case
    p = write(fuzz_dir, raw, "bytes.toml")
    _load_or_model_file_error(p, f"byte mutation {kind}: {raw[:80]!r}...")


@pytest.mark.parametrize("value", [["right"], {"a": 1}, []], ids=["list", "table", "empty"])
@pytest.mark.parametrize("key", ["legs.0.elbow", "model.friction", "model.fk_branch"])
def test_unhashable_enum_values_are_model_file_errors(tmp_path, key, value):
    """Enumerated keys given a list or a table: a ModelFileError, not a TypeError."""
    p = write(tmp_path, mutated(**{key: value}))
    try:
        read_model_file(p)
    except ModelFileError as exc:
        where = "legs.elbow (leg 1)" if key == "legs.0.elbow" else key
        assert_names(str(exc), p, where, "must be one of")
    except Exception as exc:  # noqa: BLE001
        raise AssertionError(f"{key} = {value!r}: read_model_file raised {type(exc).__name__}: "
                             f"{exc} instead of ModelFileError") from exc
    else:
        raise AssertionError(f"{key} = {value!r} was accepted")


@pytest.mark.parametrize("key", ["legs.0.la", "plant.payload_leg", "nominal.alpha.0",
                                 "sensing.encoder_counts_per_rev", "limits.tau_max.1"])
def test_huge_integers_are_model_file_errors(tmp_path, key):
    """An integer too large for a float (TOML has no size limit in tomllib): ModelFileError."""
    p = write(tmp_path, mutated(**{key: 10 ** 400}))
    try:
        read_model_file(p)
    except ModelFileError as exc:
        assert str(p) in str(exc), str(exc)
        head = _split(key)
        assert head[0] in str(exc), f"{key}: message does not name the key: {exc}"
    except Exception as exc:  # noqa: BLE001
        raise AssertionError(f"{key} = 10**400: read_model_file raised {type(exc).__name__}: "
                             f"{exc} instead of ModelFileError") from exc
    else:
        raise AssertionError(f"{key} = 10**400 was accepted")


# --------------------------------------------------------------------------------------
# One test per rule
# --------------------------------------------------------------------------------------

@pytest.mark.parametrize("key, where", [
    ("nominal.fc", "nominal.fc"),
    ("model.name", "model.name"),
    ("legs.1.lb", "legs.lb (leg 2)"),
    ("gains.apd.Kv", "gains.apd.Kv"),
    ("trajectories.low.j_max", "trajectories.low.j_max"),
    ("plant.fs", "plant.fs"),
])
def test_missing_key(tmp_path, key, where):
    p, msg = load_error(tmp_path, mutated(**{key: DELETE}))
    assert_names(msg, p, where, "missing (required)")


@pytest.mark.parametrize("section", ["sensing", "limits", "nominal", "plant", "gains"])
def test_missing_section(tmp_path, section):
    p, msg = load_error(tmp_path, mutated(**{section: DELETE}))
    assert_names(msg, p, section, "missing")


def test_missing_legs(tmp_path):
    p, msg = load_error(tmp_path, mutated(legs=DELETE))
    assert_names(msg, p, "legs", "at least two")


@pytest.mark.parametrize("key, where, allowed", [
    ("legs.0.mass", "legs.mass (leg 1)", "la"),
    ("model.colour", "model.colour", "friction"),
    ("nominal.fs", "nominal.fs", "fc"),          # a Stribeck term under coulomb_viscous
    ("gains.na.Kp", "gains.na.Kp", "Gamma"),
    ("sensing.jitter", "sensing.jitter", "sample_period"),
    ("extra", "extra", "trajectories"),
])
def test_unknown_key(tmp_path, key, where, allowed):
    value = [0.1, 0.1, 0.1] if key == "nominal.fs" else ({"a": 1} if key == "extra" else 1.0)
    p, msg = load_error(tmp_path, mutated(**{key: value}))
    assert_names(msg, p, where, "unknown key; allowed here:", repr(allowed))


@pytest.mark.parametrize("key, where, value, reason", [
    ("legs.0.la", "legs.la (leg 1)", "0.244", "must be a number, got str"),
    ("legs.2.base", "legs.base (leg 3)", 0.5, "must be a point [x, y] in m"),
    ("limits.singularity_threshold", "limits.singularity_threshold", True, "must be a number"),
    ("nominal.alpha", "nominal.alpha", 0.0932, "must be a list of 3"),
    ("sensing.sample_period", "sensing.sample_period", [0.002], "must be a number"),
    ("gains.na", "gains.na", 3, "must be a table"),
    ("model.name", "model.name", 42, "ASCII identifier"),
    ("model.rk4_substeps", "model.rk4_substeps", 2.5, "integer"),
    ("plant.payload_mass", "plant.payload_mass", "heavy", "must be a number, got str"),
    ("trajectories.low.start", "trajectories.low.start", {"x": 0.2, "y": 0.3},
     "must be a list of 2"),
])
def test_wrong_type(tmp_path, key, where, value, reason):
    p, msg = load_error(tmp_path, mutated(**{key: value}))
    assert_names(msg, p, where, reason)


def test_wrong_type_description(tmp_path):
    """[model].description is text; a number or a list is a wrong type like any other."""
    p, msg = load_error(tmp_path, mutated(**{"model.description": ["a", "b"]}))
    assert_names(msg, p, "model.description")


@pytest.mark.parametrize("key, where, value, reason", [
    ("legs.0.la", "legs.la (leg 1)", 0.0, "must be > 0"),
    ("legs.1.lb", "legs.lb (leg 2)", -0.244, "must be > 0"),
    ("nominal.alpha.2", "nominal.alpha (leg 3)", -0.01, "must be > 0"),
    ("limits.tau_max.0", "limits.tau_max (leg 1)", 0.0, "must be > 0"),
    ("limits.singularity_threshold", "limits.singularity_threshold", 1.0, "must be < 1"),
    ("sensing.sample_period", "sensing.sample_period", math.nan, "must be finite"),
    ("sensing.encoder_counts_per_rev", "sensing.encoder_counts_per_rev", 1000.5, "whole number"),
    ("gains.na.Gamma.3", "gains.na.Gamma (entry 4, beta1)", math.inf, "must be finite"),
    ("gains.apd.Kp.1", "gains.apd.Kp (y)", -35000.0, "must be > 0"),
    ("trajectories.high.v_max", "trajectories.high.v_max", 0.0, "must be > 0"),
    ("plant.payload_leg", "plant.payload_leg", 4, "leg number 1..3"),
    ("model.stribeck_velocity", "model.stribeck_velocity", -1.0, None),
])
def test_non_physical_value(tmp_path, key, where, value, reason):
    if key == "model.stribeck_velocity":  # only checked where the friction model needs it
        text = mutated(**{"model.friction": "coulomb_viscous_stribeck", key: value,
                          "nominal.fs": [0.1, 0.1, 0.1]})
        reason = "must be > 0"
    else:
        text = mutated(**{key: value})
    p, msg = load_error(tmp_path, text)
    assert_names(msg, p, where, reason)


@pytest.mark.parametrize("section", ["nominal", "plant"])
def test_beta_squared_not_below_alpha_gamma(tmp_path, section):
    """beta^2 >= alpha gamma (a leg's inertia block not positive definite), nominal and plant."""
    # leg 2: beta^2 = 0.03^2 = 9e-4 > alpha gamma = 0.0427 * 0.0111 = 4.7e-4
    p, msg = load_error(tmp_path, mutated(**{f"{section}.beta.1": 0.03}))
    assert_names(msg, p, f"{section}.beta (leg 2)", "leg 2", "not positive definite", "beta^2")


@pytest.mark.parametrize("section", ["nominal", "plant"])
def test_beta_squared_equal_alpha_gamma_is_refused(tmp_path, section):
    """The boundary beta^2 == alpha gamma (exact in binary: 0.125^2 = 0.25 * 0.0625) is
    singular, not positive definite: refused."""
    p, msg = load_error(tmp_path, mutated(**{f"{section}.alpha.0": 0.25,
                                              f"{section}.gamma.0": 0.0625,
                                              f"{section}.beta.0": 0.125}))
    assert_names(msg, p, f"{section}.beta (leg 1)", "leg 1", "not positive definite")


@pytest.mark.parametrize("key", ["nominal.fc.0", "nominal.fv.2", "plant.fv.1", "plant.fs.0",
                                 "plant.fc.2"])
def test_negative_friction(tmp_path, key):
    p, msg = load_error(tmp_path, mutated(**{key: -0.1}))
    section, name, i = _split(key)
    assert_names(msg, p, f"{section}.{name} (leg {i + 1})", "must be >= 0", "-0.1")


def test_legs_that_cannot_meet(tmp_path):
    """Base A2 moved 5 m away: no trajectory end point is within leg 2's reach."""
    p, msg = load_error(tmp_path, mutated(**{"legs.1.base": [5.0, 0.0]}))
    assert_names(msg, p, "trajectories.low.start", "cannot meet", "leg 2")
    assert re.search(r"is \d+(\.\d+)? m from its base", msg), msg


def test_trajectory_start_equals_end(tmp_path):
    p, msg = load_error(tmp_path, mutated(**{"trajectories.high.end": [0.22, 0.29]}))
    assert_names(msg, p, "trajectories.high", "same point")


@pytest.mark.parametrize("offset", [0, 100, len(SRC_BYTES)])
def test_binary_content(tmp_path, offset):
    raw = SRC_BYTES[:offset] + b"\x00\x01\x02" + SRC_BYTES[offset:]
    p, msg = load_error(tmp_path, raw)
    assert str(p) in msg and "binary content" in msg and f"offset {offset}" in msg, msg


def test_unreadable_path(tmp_path):
    p = tmp_path / "does_not_exist.toml"
    with pytest.raises(ModelFileError) as info:
        read_model_file(p)
    assert str(p) in str(info.value) and "cannot read" in str(info.value), str(info.value)
    with pytest.raises(ModelFileError) as info:  # a directory
        read_model_file(tmp_path)
    assert str(tmp_path) in str(info.value) and "cannot read" in str(info.value), str(info.value)


def test_load_model_unreadable_path_is_model_file_error(tmp_path):
    with pytest.raises(ModelFileError):
        pm2dof.load_model(tmp_path / "nope.toml")


def test_not_utf8(tmp_path):
    raw = SRC_BYTES.replace(b"# Units: SI", b"# Units \xff\xfe: SI", 1)
    assert raw != SRC_BYTES
    p, msg = load_error(tmp_path, raw)
    assert str(p) in msg and "UTF-8" in msg, msg


@pytest.mark.parametrize("text", ["la = = 1\n", "[model\nname = 'x'\n", SRC + "\n[model]\n",
                                  SRC.replace('name = "shang2010"', "name = shang2010")])
def test_invalid_toml(tmp_path, text):
    p, msg = load_error(tmp_path, text)
    assert str(p) in msg and "not valid TOML" in msg, msg


def test_empty_file(tmp_path):
    p, msg = load_error(tmp_path, b"")
    assert_names(msg, p, "model", "missing")


@pytest.mark.parametrize("elbow", ["up", "Left", "", 1])
def test_bad_elbow(tmp_path, elbow):
    p, msg = load_error(tmp_path, mutated(**{"legs.2.elbow": elbow}))
    assert_names(msg, p, "legs.elbow (leg 3)", "must be one of", "'left'", "'right'")


def test_bad_fk_branch_and_friction(tmp_path):
    p, msg = load_error(tmp_path, mutated(**{"model.fk_branch": "middle"}))
    assert_names(msg, p, "model.fk_branch", "must be one of", "'middle'")
    p, msg = load_error(tmp_path, mutated(**{"model.friction": "dry"}))
    assert_names(msg, p, "model.friction", "must be one of", "'dry'")


def test_two_leg_model_without_fk_branch(tmp_path):
    src = FIVEBAR.read_text()
    assert re.search(r"^fk_branch\s*=", src, re.M), "fivebar.toml has no fk_branch to remove"
    text = re.sub(r"^fk_branch\s*=.*$", "", src, count=1, flags=re.M)
    read_model_file(write(tmp_path, src, "fivebar_ok.toml"))  # the original loads
    p, msg = load_error(tmp_path, text, "fivebar.toml")
    assert_names(msg, p, "model.fk_branch", "two-leg")


@pytest.mark.parametrize("length", [14, 16, 0])
def test_gamma_of_the_wrong_length(tmp_path, length):
    p, msg = load_error(tmp_path, mutated(**{"gains.na.Gamma": [5e-4] * length}))
    assert_names(msg, p, "gains.na.Gamma", "must be a list of 15")


def test_stribeck_friction_needs_its_velocity(tmp_path):
    p, msg = load_error(tmp_path, mutated(**{"model.friction": "coulomb_viscous_stribeck"}))
    assert_names(msg, p, "model.stribeck_velocity", "required")


# --------------------------------------------------------------------------------------
# Every problem of a file in one error; legs numbered from 1
# --------------------------------------------------------------------------------------

FOURTH_LEG = """
[[legs]]
base = [0.6, 0.25]      # A4, m (the fourth leg of fourleg.toml)
la = 0.244
lb = 0.244
elbow = "right"
"""
#: theta's order for n legs, written out from the paper's notes (alpha1..alphan, beta.., gamma..,
#: fv.., fc..), not from the loader
def _theta_order(n):
    return ", ".join(f"{k}{i}" for k in ("alpha", "beta", "gamma", "fv", "fc")
                     for i in range(1, n + 1))


def test_a_fourth_leg_reports_every_three_entry_array_at_once(tmp_path):
    """A fourth [[legs]] table added to the paper's model file (and a [control]
    table with per-leg arrays) leaves 15 arrays with 3 entries. One read names all of them,
    each with the length the leg count implies; fixing exactly the named keys makes it load."""
    control = ('\n[control]\nsplit = "preload"\npreload = [1.0, 1.0, 1.0]\n'
               'preload_sign = [1, -1, 1]\n')
    text = SRC.replace("\n# Tables 1-2", FOURTH_LEG + "\n# Tables 1-2", 1) + control
    assert len(re.findall(r"^\[\[legs\]\]", text, re.M)) == 4
    p = write(tmp_path, text, "four.toml")
    with pytest.raises(ModelFileError) as info:
        read_model_file(p)
    exc, msg = info.value, str(info.value)
    per_leg = ([f"nominal.{k}" for k in ("alpha", "beta", "gamma", "fv", "fc")]
               + ["limits.tau_max"]
               + [f"plant.{k}" for k in ("alpha", "beta", "gamma", "fv", "fc", "fs")]
               + ["control.preload", "control.preload_sign"])
    keys = [pr.key for pr in exc.problems]
    assert sorted(keys) == sorted(per_leg + ["gains.na.Gamma"]), keys
    for pr in exc.problems:
        if pr.key == "gains.na.Gamma":
            assert pr.reason.startswith("must be a list of 20 numbers, one per parameter of "
                                        f"theta, in the order of param_names: {_theta_order(4)}, "
                                        "got 15: "), pr.reason
        else:
            assert pr.reason.startswith("must be a list of 4 numbers, one per leg (the file has "
                                        "4 [[legs]]), got 3: "), pr
    lines = msg.splitlines()
    assert lines[0] == f"{p}: 15 problems:", lines[0]
    assert len(lines) == 16 and all(f"[{k}]" in msg for k in keys), msg
    # positive control: extend exactly the named arrays, and the file loads
    doc = tomllib.loads(text)
    for key in keys:
        *parents, last = key.split(".")
        node = doc
        for k in parents:
            node = node[k]
        node[last] = node[last] + node[last][-1:] if last != "Gamma" else [5e-4] * 20
    spec = read_model_file(write(tmp_path, dump(doc), "four_fixed.toml"))
    assert spec.n_legs == 4 and ", ".join(spec.param_names) == _theta_order(4)


@pytest.mark.parametrize("length", [14, 16])
def test_gamma_message_gives_the_parameter_order(tmp_path, length):
    p, msg = load_error(tmp_path, mutated(**{"gains.na.Gamma": [5e-4] * length}))
    assert_names(msg, p, "gains.na.Gamma", f"must be a list of 15 numbers, one per parameter of "
                 f"theta, in the order of param_names: {_theta_order(3)}, got {length}")


def test_independent_problems_of_several_sections_are_reported_together(tmp_path):
    """Problems in [[legs]], [sensing], [gains.apd], [plant] and [trajectories]: one error,
    one line each, also as exc.problems (key, reason), in the file's order."""
    text = mutated(**{"legs.0.la": 0.0, "sensing.sample_period": -0.002,
                      "gains.apd.Kp.1": "35000", "plant.fc.2": -0.1,
                      "trajectories.low.v_max": math.nan, "limits.colour": 1})
    p = write(tmp_path, text)
    with pytest.raises(ModelFileError) as info:
        read_model_file(p)
    exc = info.value
    assert [(pr.key, pr.reason) for pr in exc.problems] == [
        ("legs.la (leg 1)", "must be > 0, got 0.0"),
        ("limits.colour", "unknown key; allowed here: ['parallel_singularity_threshold', "
                          "'singularity_threshold', 'tau_max']"),
        ("sensing.sample_period", "must be > 0, got -0.002"),
        ("gains.apd.Kp (y)", "must be a number, got str '35000'"),
        ("plant.fc (leg 3)", "must be >= 0, got -0.1"),
        ("trajectories.low.v_max", "must be finite, got nan"),
    ]
    assert str(exc).splitlines() == [f"{p}: 6 problems:"] + [
        f"  [{pr.key}] {pr.reason}" for pr in exc.problems]
    assert exc.path == str(p)
    import pickle  # the problems survive pickling (errors cross Dask workers)
    again = pickle.loads(pickle.dumps(exc))
    assert type(again) is ModelFileError and again.problems == exc.problems
    assert str(again) == str(exc) and again.path == exc.path


def test_a_single_problem_is_one_line(tmp_path):
    p, msg = load_error(tmp_path, mutated(**{"plant.payload_mass": -1.0}))
    assert msg == f"{p}: [plant.payload_mass] must be >= 0, got -1.0"


@pytest.mark.parametrize("leg", [0, 1, 2])
@pytest.mark.parametrize("key", ["legs.{i}.la", "nominal.alpha.{i}", "nominal.fc.{i}",
                                 "limits.tau_max.{i}", "plant.gamma.{i}", "plant.fs.{i}"])
def test_legs_are_numbered_from_one(tmp_path, key, leg):
    """The (i+1)-th leg's bad entry is reported as "leg i+1", never with a
    0-based index (legs[0], alpha[0])."""
    dotted = key.format(i=leg)
    p, msg = load_error(tmp_path, mutated(**{dotted: -1.0}))
    section, name = (dotted.split(".")[0], dotted.split(".")[2]) if key.startswith("legs") else \
        dotted.split(".")[:2]
    assert_names(msg, p, f"{section}.{name} (leg {leg + 1})", "must be > 0" if name != "fc"
                 and name != "fs" else "must be >= 0")
    assert not re.search(r"\[\d\]", msg) and f"leg {leg}]" not in msg.replace(
        f"leg {leg + 1}", ""), msg


def test_payload_leg_is_one_based(tmp_path):
    """[plant] payload_leg counts from 1: 0 is refused, n is the last leg."""
    p, msg = load_error(tmp_path, mutated(**{"plant.payload_leg": 0}))
    assert_names(msg, p, "plant.payload_leg", "must be")
    p, msg = load_error(tmp_path, mutated(**{"plant.payload_leg": 9}))
    assert msg.endswith("got 9"), msg            # the number as written, not 9.0
    assert read_model_file(write(tmp_path, mutated(**{"plant.payload_leg": 3}), "ok.toml")
                           ).plant["payload_leg"] == 3


def test_every_shipped_model_file_loads():
    for path in sorted(SHIPPED_MODELS.glob("*.toml")):
        check_spec_invariants(read_model_file(path), str(path))


def test_the_friction_comments_say_the_sign_the_code_uses():
    """A shipped model file that comments "sign(0) = ..." on its friction law says what the
    generated friction does at rest: S^T f_a(S xed) at xed = 0 is 0 with sign(0) = 0 and the
    limit from above, S^T fc, with sign(0) = +1 (shang2010_vertical.toml said +1; the code
    gives 0)."""
    checked = []
    for path in sorted(SHIPPED_MODELS.glob("*.toml")):
        said = re.findall(r"sign\(0\) = ([-+]?\d)", path.read_text())
        if not said:
            continue
        m = pm2dof.load_model(path)
        q = m.ik(m.spec.trajectories["low"]["start"])
        at_rest = m.StF(q, np.zeros(m.dof), m.theta_nominal)
        from_above = m.StF(q, np.full(m.dof, 1e-12), m.theta_nominal)
        assert np.abs(from_above).max() > 0.1, (path.name, from_above)
        for value in said:
            want = 0 * from_above if int(value) == 0 else from_above
            assert np.abs(at_rest - want).max() < 1e-9, (path.name, value, at_rest)
        checked.append(path.stem)
    assert {"shang2010", "shang2010_vertical", "fivebar"} <= set(checked), checked


# --------------------------------------------------------------------------------------
# Generated code: missing or stale -> StaleGeneratedCodeError ("pm2dof derive ...")
# --------------------------------------------------------------------------------------

def test_error_hierarchy():
    assert issubclass(ModelFileError, ValueError)
    assert issubclass(StaleGeneratedCodeError, RuntimeError)
    assert issubclass(pm2dof.WorkspaceError, ValueError)
    assert issubclass(pm2dof.SingularityError, ValueError)


def test_copy_with_only_comments_and_runtime_data_changed_loads(tmp_path):
    """Positive control: the guard compares the formulation ([model], [[legs]]), not bytes:
    the rewritten document (no comments) with other gains loads."""
    text = "# a copy\n" + mutated(**{"gains.na.Kd": [190.0, 190.0]})
    m = pm2dof.load_model(write(tmp_path, text, "copy.toml"), generated=SHIPPED_GENERATED / "shang2010")
    assert m.name == "shang2010" and m.spec.gains["na"]["Kd"].tolist() == [190.0, 190.0]
    assert m.spec.file_sha256 != read_model_file(PAPER).file_sha256


def test_changed_base_is_stale(tmp_path):
    x, y = DOC["legs"][0]["base"]
    text = mutated(**{"legs.0.base": [x + 0.001, y]})
    p = write(tmp_path, text, "moved.toml")
    spec = read_model_file(p)  # a valid model file ...
    assert spec.bases[0].tolist() == [x + 0.001, y]
    gen = SHIPPED_GENERATED / "shang2010"
    with pytest.raises(StaleGeneratedCodeError) as info:  # ... whose generated code is stale
        pm2dof.load_model(p, generated=gen)
    msg = str(info.value)
    assert "different formulation" in msg and f"another model file, {PAPER.resolve()}" in msg
    assert f"`pm2dof derive {p}` (generated/<stem>/ beside it" in msg, msg
    assert "--force" not in msg, msg        # never: overwrite the shipped models' code


def test_a_folder_of_another_model_file_suggests_a_folder_of_its_own(tmp_path):
    """--generated naming a user's folder derived from another model file: `derive --out` that
    folder would be refused ("holds code generated from another model file"), so the message
    suggests the default folder, or --force."""
    gen = tmp_path / "generated" / "other"
    gen.mkdir(parents=True)
    (gen / "manifest.json").write_text('{"formulation_sha256": "0", "model_file": '
                                       '"../../other.toml"}')
    p = write(tmp_path, SRC, "mine.toml")
    with pytest.raises(StaleGeneratedCodeError) as info:
        pm2dof.load_model(p, generated=gen)
    msg = str(info.value)
    assert f"another model file, {tmp_path / 'other.toml'}" in msg, msg
    assert f"`pm2dof derive {p}`" in msg and f"`pm2dof derive {p} --out {gen} --force`" in msg
    (gen / "manifest.json").write_text('{"formulation_sha256": "0", "model_file": '
                                       '"../../mine.toml"}')       # its own folder: re-derive
    with pytest.raises(StaleGeneratedCodeError, match=f"Run `pm2dof derive {p} --out {gen}`"):
        pm2dof.load_model(p, generated=gen)


@pytest.mark.parametrize("edits", [
    {"legs.0.elbow": "left"},
    {"legs.2.la": 0.245},
    {"model.friction": "smooth_sign", "model.sign_smoothing_velocity": 0.01},
    {"model.rk4_substeps": DOC["model"].get("rk4_substeps", 4) + 1},
], ids=["elbow", "la", "friction", "rk4_substeps"])
def test_other_formulation_changes_are_stale(tmp_path, edits):
    p = write(tmp_path, mutated(**edits), "changed.toml")
    read_model_file(p)
    with pytest.raises(StaleGeneratedCodeError) as info:
        pm2dof.load_model(p, generated=SHIPPED_GENERATED / "shang2010")
    assert "pm2dof derive" in str(info.value), str(info.value)


def test_model_without_generated_code(tmp_path):
    text = SRC.replace('name = "shang2010"', 'name = "nonexistent_model"')
    p = write(tmp_path, text, "nonexistent.toml")
    assert read_model_file(p).name == "nonexistent_model"
    with pytest.raises(StaleGeneratedCodeError) as info:
        pm2dof.load_model(p)
    msg = str(info.value)
    assert f"Run `pm2dof derive {p}`" in msg and str(tmp_path / "generated" / "nonexistent") in msg, msg


def test_manifest_mismatch_in_a_copied_generated_dir(tmp_path):
    """Model(spec, gen_dir): a generated folder whose manifest names another formulation."""
    from pm2dof.core.model import Model
    gen = tmp_path / "gen"
    shutil.copytree(SHIPPED_GENERATED / "shang2010", gen)
    man = json.loads((gen / "manifest.json").read_text())
    man["formulation_sha256"] = "0" * 64
    (gen / "manifest.json").write_text(json.dumps(man))
    with pytest.raises(StaleGeneratedCodeError) as info:
        Model(read_model_file(PAPER), gen)
    assert "pm2dof derive" in str(info.value), str(info.value)
    (gen / "manifest.json").unlink()
    with pytest.raises(StaleGeneratedCodeError) as info:
        Model(read_model_file(PAPER), gen)
    assert "pm2dof derive" in str(info.value) and "manifest.json" in str(info.value)
