# The generated C of every model vs its SymPy source at 30 digits; the generated files vs their derivation.
"""Tests of ``pm2dof/generated/<name>/``: what ``pm2dof derive`` produced and what the runtime loads.

Every check runs over every ``pm2dof/models/*.toml`` (the ``model`` fixture of ``conftest.py``, ids =
model names), except where marked paper-only (``m``, ``shang2010``):

* The compiled C agrees with the SymPy expressions of ``pm2dof.derive`` evaluated with mpmath at
  30 significant digits (so the reference carries no rounding error at double precision):
  this isolates the CasADi conversion, the code generation and the C compiler. 6 poses for
  the paper's robot, 3 for every other model (the cost is the per-model SymPy derivation
  and lambdify, ~1.5-3.5 s each, not the poses). Paper-only: sign(0) = 0 at an exact zero.
* Regenerating into a temporary folder gives byte-identical files for every model
  (``pm2dof.derive.run.derive(..., build=False)`` in this process, its SymPy derivation shared
  with the 30-digit check: tests/derivations.py); for the paper's robot a second time in a
  fresh interpreter (``python -m pm2dof.derive --no-build``) with another hash seed: the two
  agree byte for byte (deterministic output, also across processes).
* The manifest describes the files and the model file it was derived from; a model file
  whose formulation differs (an edited base, for every model; more edits for the paper's) is
  refused with :class:`pm2dof.StaleGeneratedCodeError`.
* The runtime never imports SymPy, CasADi or ``pm2dof.derive`` (any model).

Tolerance: ``TOL = 1e-12`` relative (max-norm, scale = max-norm of the 30-digit value, or of
the summed terms where the value is a sum that may cancel). The C evaluates straight-line
expressions of a few hundred to a few thousand flops on O(1) inputs, at poses with
min_i |sin(qb_i - qa_i)| > 0.2 (every division by sin(qb - qa) amplifies relative rounding
by at most 5): accumulated rounding ~1e-15..1e-14 relative; 1e-12 is a >= 100x margin.
"""
from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import traceback
from pathlib import Path

import casadi  # the build-time stack is required by these tests (dev dependencies), never skipped
import mpmath
import numpy as np
import pytest
import sympy

import pm2dof
from pm2dof.core.model_file import read_model_file
from pm2dof.core.paths import PACKAGE, SHIPPED_GENERATED, SHIPPED_MODELS
from tests import derivations

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

TOL = 1e-12
DPS = 30
N_POSES_PAPER = 6
N_POSES_OTHER = 3
PAPER = "shang2010"
DEFAULT_MODEL = SHIPPED_MODELS / "shang2010.toml"

# {model: {check: largest err / scale}}, printed at module teardown (-s)
_OBSERVED: dict[str, dict[str, float]] = {}


def _record(model_name, name, ratio):
    d = _OBSERVED.setdefault(model_name, {})
    d[name] = max(d.get(name, 0.0), float(ratio))


@pytest.fixture(scope="module", autouse=True)
def _report_observed():
    yield
    if _OBSERVED:
        print("\n[test_generated] largest observed relative errors (C vs 30-digit SymPy), per model:")
        for model_name in sorted(_OBSERVED):
            print(f"  {model_name}:")
            for k in sorted(_OBSERVED[model_name]):
                print(f"    {k:<28s} {_OBSERVED[model_name][k]:.3e}")


@pytest.fixture(scope="module")
def m():
    """The paper's robot (paper-only checks)."""
    return pm2dof.load_model()


def gen_dir(model):
    return SHIPPED_GENERATED / model.name


def gen_files(model):
    return (f"{model.name}.c", f"{model.name}.h", "manifest.json")


# --------------------------------------------------------------------------------------
# 6'. C against the SymPy expressions at 30 digits (every model)
# --------------------------------------------------------------------------------------

def _sgn(v):
    return int(v > 0) - int(v < 0)  # derive.symbols.sgn: sign with sgn(0) = 0


_LAMBDIFIED: dict = {}


def _sympy_functions(spec):
    """The SymPy derivation of a model, lambdified once per matrix for mpmath (cached)."""
    if spec.formulation_sha256 in _LAMBDIFIED:
        return _LAMBDIFIED[spec.formulation_sha256]
    d = derivations.derivation(spec)      # Derivation(spec), shared with the regeneration
    s, kin, dyn = d.sym, d.kin, d.dyn
    q, qa, xe = list(s.q), list(s.qa), list(s.xe)
    xed, xrd, xrdd = list(s.xed), list(s.xrd), list(s.xrdd)
    theta, tau = list(s.theta), list(s.tau_a)
    qd = list(dyn.qd)
    modules = [{"sgn": _sgn}, "mpmath"]

    # a model with a [design] table: its design symbols at the file's design, exactly
    design = dict(zip(s.design, [sympy.Rational(repr(float(v))) for v in spec.design.values])
                  ) if spec.design is not None else {}

    def lam(args, expr):
        return derivations.lambdify(args, expr.xreplace(design) if design else expr, modules)

    out = {
        "ik": lam([xe], kin.ik()),
        "fk": lam([qa], kin.fk()),
        "H": lam([q], kin.H),
        "A": lam([q], kin.A),
        "W": lam([q], kin.W),
        "S": lam([q], kin.S),
        "Wdot": lam([q, xed], kin.Wdot),
        "M": lam([q, theta], dyn.M),
        "C": lam([q, qd, theta], dyn.C),
        "Me": lam([q, theta], dyn.Me),
        "Ce": lam([q, xed, theta], dyn.Ce),
        "StF": lam([q, xed, theta], dyn.StF),
        "Y": lam([q, xed, xrd, xrdd], dyn.Y),
        "xedd": lam([q, xed, tau, theta], dyn.xedd),
    }
    _LAMBDIFIED[spec.formulation_sha256] = out
    return out


@pytest.fixture(scope="module")
def mp(model):
    """The model's SymPy functions for mpmath (per model; cse lambdify ~0.6-1.2 s)."""
    return _sympy_functions(model.spec)


def _mpv(x):
    """A float vector as exact mpf values (the double inputs, no further rounding)."""
    return [mpmath.mpf(float(v)) for v in np.asarray(x, dtype=float).ravel()]


def _to_float(value):
    """An mpmath matrix (or list) -> float ndarray, rounded once at the end; columns -> (n,)."""
    if isinstance(value, mpmath.matrix):
        a = np.array([[float(value[i, j]) for j in range(value.cols)] for i in range(value.rows)])
        return a[:, 0] if value.cols == 1 else a
    return np.array([float(v) for v in value])


def _wrap(a):
    return -np.remainder(-np.asarray(a, float) + np.pi, 2.0 * np.pi) + np.pi


def _poses(model, sample_xe, random_theta, seed):
    """(xe, xed, xrd, xrdd, theta, tau_a) at admissible poses (conftest.sample_xe): |xed| in
    [0.05, 0.5] m/s, random theta with PD leg inertias, tau_a in [-10, 10] N m."""
    k = N_POSES_PAPER if model.name == PAPER else N_POSES_OTHER
    rng = np.random.default_rng(seed + 1)
    out = []
    for xe in sample_xe(model, seed, k):
        phi = rng.uniform(-np.pi, np.pi)
        xed = rng.uniform(0.05, 0.5) * np.array([np.cos(phi), np.sin(phi)])
        out.append((xe, xed, rng.uniform(-0.5, 0.5, 2), rng.uniform(-10, 10, 2),
                    random_theta(model, rng), rng.uniform(-10, 10, model.n_legs)))
    assert len(out) == k
    return out


def _check(model, name, got, want, scale, info):
    got, want = np.asarray(got, float), np.asarray(want, float).reshape(np.shape(got))
    err = float(np.max(np.abs(got - want)))
    _record(model.name, name, err / scale)
    assert err <= TOL * scale, (f"{model.name}: {name}: C vs 30-digit SymPy: max error {err:.3e} > "
                                f"{TOL:.0e} * {scale:.3e} at {info}\nC=\n{got}\nSymPy=\n{want}")


#: the 30-digit check derives the model in SymPy first (1-2 s each): make test runs it on one
#: model of each kind (the paper's robot, gravity, linear actuators, four legs, the five-bar),
#: make test-slow (CI) on the paper robot's other variants too (Stribeck, smoothed sign, design
#: parameters, unequal links: the same leg kinds; a platform is skipped, as below)
_MP_QUICK = {"shang2010", "shang2010_vertical", "prr_point", "fourleg", "fivebar"}


@pytest.mark.parametrize("model", [
    pytest.param(path, id=path.stem, marks=() if path.stem in _MP_QUICK else pytest.mark.slow)
    for path in sorted(SHIPPED_MODELS.glob("*.toml"))], indirect=True)
def test_C_matches_sympy_at_30_digits(model, mp, sample_xe, random_theta):
    mpmath.mp.dps = DPS
    n = model.n_legs
    for xe, xed, xrd, xrdd, theta, tau in _poses(model, sample_xe, random_theta, 2010):
        info = (f"xe={xe.tolist()}, xed={xed.tolist()}, xrd={xrd.tolist()}, xrdd={xrdd.tolist()}, "
                f"theta={theta.tolist()}, tau_a={tau.tolist()}")
        q = model.ik(xe)
        qd = model.W(q) @ xed
        Q, XED, TH = _mpv(q), _mpv(xed), _mpv(theta)
        # ik: same expression, so the same branch; wrap only guards the atan2 cut at +-pi
        q_mp = list(mp["ik"](_mpv(xe)))
        _check(model, "ik (rad)", _wrap(q - _to_float(q_mp)), np.zeros(2 * n), 1.0, info)
        _check(model, "fk (m)", model.fk(q[:n]), _to_float(mp["fk"](Q[:n])), 1.0, info)
        _check(model, "H (m)", model.H(q), _to_float(mp["H"](Q)), 1.0, info)
        for name, got, want in [
            ("A", model.A(q), mp["A"](Q)),
            ("W", model.W(q), mp["W"](Q)),
            ("S", model.S(q), mp["S"](Q)),
            ("Wdot", model.Wdot(q, xed), mp["Wdot"](Q, XED)),
            ("M", model.M(q, theta), mp["M"](Q, TH)),
            ("C", model.C(q, qd, theta), mp["C"](Q, _mpv(qd), TH)),
            ("Me", model.Me(q, theta), mp["Me"](Q, TH)),
            ("Ce", model.Ce(q, xed, theta), mp["Ce"](Q, XED, TH)),
            ("StF", model.StF(q, xed, theta), mp["StF"](Q, XED, TH)),
            ("Y", model.Y(q, xed, xrd, xrdd), mp["Y"](Q, XED, _mpv(xrd), _mpv(xrdd))),
        ]:
            want = _to_float(want)
            _check(model, name, got, want, max(float(np.max(np.abs(want))), 1e-300), info)
        # forward dynamics: the SymPy xedd is in terms of q; use q = ik(xe) at 30 digits
        # (q_mp, never rounded to double). Scale: |Me^-1| times the summed terms of the
        # right-hand side S^T tau - Ce xed - StF (the sum may cancel).
        want = _to_float(mp["xedd"](list(q_mp), XED, _mpv(tau), TH))
        Me = model.Me(q, theta)
        terms = (np.max(np.abs(model.S(q).T @ tau)) + np.max(np.abs(model.Ce(q, xed, theta) @ xed))
                 + np.max(np.abs(model.StF(q, xed, theta))))
        scale = np.linalg.norm(np.linalg.inv(Me), np.inf) * terms
        _check(model, "forward_dynamics", model.forward_dynamics(xe, xed, tau, theta), want, scale, info)


def test_C_matches_sympy_sign_zero(m):
    """Paper only: at qd_a1 = 0 exactly (qb_1 = 0, xed along y) both sides use sgn(0) = 0."""
    mp = _sympy_functions(m.spec)
    mpmath.mp.dps = DPS
    L, A1 = 0.244, np.array([0.0, 0.25])
    qa1 = -0.3
    xe = A1 + L * np.array([np.cos(qa1), np.sin(qa1)]) + np.array([L, 0.0])
    q = m.ik(xe)
    q[0], q[3] = qa1, 0.0
    xed = np.array([0.0, 0.2])
    theta = np.array(m.theta_nominal)
    info = f"q={q.tolist()}, xed={xed.tolist()}"
    assert m.S(q)[0] @ xed == 0.0, info  # qd_a1 = 0 exactly
    want = _to_float(mp["StF"](_mpv(q), _mpv(xed), _mpv(theta)))
    _check(m, "StF at qd_a = 0", m.StF(q, xed, theta), want, float(np.max(np.abs(want))), info)
    want = _to_float(mp["Y"](_mpv(q), _mpv(xed), _mpv([0, 0]), _mpv([0, 0])))
    _check(m, "Y at qd_a = 0", m.Y(q, xed, np.zeros(2), np.zeros(2)), want,
           float(np.max(np.abs(want))), info)


# --------------------------------------------------------------------------------------
# 8. Regeneration is deterministic and the committed files are up to date (every model)
# --------------------------------------------------------------------------------------

def _first_difference(a: bytes, b: bytes):
    la, lb = a.decode(errors="replace").splitlines(), b.decode(errors="replace").splitlines()
    for i, (x, y) in enumerate(zip(la, lb)):
        if x != y:
            return i + 1, x, y
    return min(len(la), len(lb)) + 1, "<end of file>" if len(la) < len(lb) else la[len(lb)], \
        "<end of file>" if len(lb) < len(la) else lb[len(la)]


def _layout(tmp_path_factory, model_file, label):
    """root/models/<stem>.toml (a copy) and root/generated/<stem>/, as in the package, so the
    manifest's relative model_file path is the same -> (copied model file, output folder)."""
    root = tmp_path_factory.mktemp(f"derive_{model_file.stem}_{label}")
    (root / "models").mkdir()
    shutil.copyfile(model_file, root / "models" / model_file.name)
    return root / "models" / model_file.name, root / "generated" / model_file.stem


def _derive_in_process(model_file, out):
    """``pm2dof.derive.run.derive(MODEL, OUT, build=False)`` in this process, its SymPy
    derivation shared with the 30-digit check (tests/derivations.py) -> (rc, output)."""
    from pm2dof.derive.run import derive
    try:
        with derivations.shared_in_derive():
            derive(model_file, out, build=False, progress=None)
    except Exception:                      # fails only this model's tests, with the traceback
        return 1, traceback.format_exc()
    return 0, ""


def _derive_subprocess(model_file, out, seed):
    """python -m pm2dof derive MODEL --out OUT --no-build with PYTHONHASHSEED=seed
    -> (rc, output)."""
    env = {**os.environ, "PYTHONHASHSEED": seed}
    r = subprocess.run([sys.executable, "-m", "pm2dof", "derive", str(model_file), "--out",
                        str(out), "--no-build"], cwd=out.parent, env=env, capture_output=True, text=True,
                       timeout=600)
    return r.returncode, r.stdout + r.stderr


#: this process's hash seed ("random" unless PYTHONHASHSEED is set) and another, fixed one for
#: the paper's second derivation
OWN_SEED = os.environ.get("PYTHONHASHSEED", "random")
OTHER_SEED = "4242" if OWN_SEED == "0" else "0"


@pytest.fixture(scope="module")
def regenerated(tmp_path_factory):
    """Every model file of models/ regenerated into a temporary folder, in this process (its
    hash seed, OWN_SEED: random unless PYTHONHASHSEED is set), one after the other; the paper's
    robot a second time in a fresh interpreter with PYTHONHASHSEED=OTHER_SEED.

    Returns {(resolved model file, seed): (returncode, output, out_dir)}; a failing
    derivation fails only its own model's tests."""
    out = {}
    for path in sorted(SHIPPED_MODELS.glob("*.toml")):
        model_file, folder = _layout(tmp_path_factory, path.resolve(), "own")
        out[path.resolve(), OWN_SEED] = (*_derive_in_process(model_file, folder), folder)
    model_file, folder = _layout(tmp_path_factory, DEFAULT_MODEL.resolve(), f"seed{OTHER_SEED}")
    folder.mkdir(parents=True)
    out[DEFAULT_MODEL.resolve(), OTHER_SEED] = (*_derive_subprocess(model_file, folder,
                                                                    OTHER_SEED), folder)
    return out


def _regenerated_dir(model, regenerated, seed=OWN_SEED):
    key = (Path(model.spec.path).resolve(), seed)
    assert key in regenerated, f"{model.spec.path} was not regenerated"
    rc, output, out = regenerated[key]
    assert rc == 0, f"derive {model.spec.path} (PYTHONHASHSEED={seed}) failed ({rc}):\n{output}"
    return out


@pytest.mark.slow      # derives every model again (minutes): make test-slow (CI)
def test_regeneration_is_byte_identical(model, regenerated):
    out = _regenerated_dir(model, regenerated)
    problems = []
    for name in gen_files(model):
        new, old = out / name, gen_dir(model) / name
        if not new.is_file():
            problems.append(f"{name} was not written")
            continue
        if new.read_bytes() != old.read_bytes():
            line, a, b = _first_difference(old.read_bytes(), new.read_bytes())
            problems.append(f"generated/{model.name}/{name} differs from a fresh derivation at "
                            f"line {line}:\n  committed:   {a[:200]}\n  regenerated: {b[:200]}")
    assert not problems, (f"the committed generated code of {model.name} is not what `pm2dof "
                          f"derive {model.spec.path}` produces now; run `make derive-all`.\n"
                          + "\n".join(problems))


@pytest.mark.slow      # derives a model under several hash seeds (30 s): make test-slow (CI)
def test_regeneration_is_deterministic_across_hash_seeds(m, regenerated):
    """Paper only (one model suffices: the derivation code is shared): this process's
    derivation against a fresh interpreter's with another hash seed."""
    o1 = _regenerated_dir(m, regenerated, OWN_SEED)
    o2 = _regenerated_dir(m, regenerated, OTHER_SEED)
    for name in gen_files(m):
        a, b = (o1 / name).read_bytes(), (o2 / name).read_bytes()
        if a != b:
            line, x, y = _first_difference(a, b)
            pytest.fail(f"{name} depends on PYTHONHASHSEED ({OWN_SEED} vs {OTHER_SEED}) at line "
                        f"{line}:\n  {x[:200]}\n  {y[:200]}")


def test_generated_code_has_no_timestamp_or_local_path(model):
    text = "".join((gen_dir(model) / name).read_text() for name in gen_files(model))
    assert len(text) > 1000, f"{model.name}: generated files are (nearly) empty"
    for needle in (str(PACKAGE.parent), "/tmp/", str(Path.home())):
        assert needle not in text, f"{model.name}: generated code contains {needle!r} (not reproducible)"
    stamp = re.search(r"\b20\d\d-[01]\d-[0-3]\d\b|\b\d\d:\d\d:\d\d\b", text)
    assert stamp is None, f"{model.name}: generated code contains a timestamp {stamp.group(0)!r}"


# --------------------------------------------------------------------------------------
# The manifest (every model)
# --------------------------------------------------------------------------------------

@pytest.fixture
def manifest(model):
    return json.loads((gen_dir(model) / "manifest.json").read_text())


def test_manifest_formulation_hash(model, manifest):
    spec = read_model_file(model.spec.path)  # a fresh read of the file on disk
    path = Path(model.spec.path).resolve()
    assert manifest["formulation_sha256"] == spec.formulation_sha256, "run make derive-all"
    assert manifest["model_file_sha256"] == spec.file_sha256, \
        f"{path.name} changed since generation; run make derive-all"
    assert manifest["model"] == spec.name == model.name
    # the model file as seen from the generated folder: the pair moves together
    assert manifest["model_file"] == f"../../models/{path.name}"
    assert (gen_dir(model) / manifest["model_file"]).resolve() == path
    assert manifest["param_names"] == list(spec.param_names)


def test_manifest_versions_are_the_installed_ones(model, manifest):
    assert manifest["versions"] == {"sympy": sympy.__version__, "casadi": casadi.__version__}, \
        f"{model.name}: manifest {manifest['versions']} vs installed sympy {sympy.__version__}, " \
        f"casadi {casadi.__version__}: run make derive-all"


def test_manifest_file_hashes_match_the_files(model, manifest):
    assert set(manifest["files"]) == {f"{model.name}.c", f"{model.name}.h"}
    for name, sha in manifest["files"].items():
        got = hashlib.sha256((gen_dir(model) / name).read_bytes()).hexdigest()
        assert got == sha, f"{model.name}: {name}: sha256 {got} != manifest {sha}; run make derive-all"


def test_manifest_derive_sources_hash(model, manifest):
    from pm2dof.core.manifest import derive_sources_sha256
    assert manifest["derive_sources_sha256"] == derive_sources_sha256(), \
        f"{model.name}: derive/*.py changed since generation; run make derive-all"


def test_manifest_signatures_match_the_loaded_functions(model, manifest):
    """Every model function is in the manifest with the signature the loaded C reports."""
    for k in ("ik", "fk", "H", "A", "singularity", "W", "S", "Wdot", "M", "C", "Me", "Ce", "StF",
              "Y", "forward_dynamics"):
        f = model.function(k)
        want = dict(manifest["functions"].get(f"{model.name}_{k}"))
        want.pop("work")                      # the work sizes: tests/core/test_contract.py
        if want["inputs"] and want["inputs"][-1][0] == "design":   # bound to the model's design
            assert f.fixed == tuple(model.design), f"{model.name}_{k}: design not bound"
            want["inputs"] = want["inputs"][:-1]
        else:
            assert f.fixed is None
        have = {"inputs": [[a, n] for a, n in zip(f.names_in, f.sizes_in)],
                "outputs": [[a, n] for a, n in zip(f.names_out, f.sizes_out)]}
        assert want == have, f"{model.name}_{k}: manifest {want} != loaded {have}"
    for key in ("formulation_sha256", "model_file_sha256", "derive_sources_sha256"):
        assert model.manifest[key] == manifest[key], key


# --------------------------------------------------------------------------------------
# Stale generated code is refused
# --------------------------------------------------------------------------------------

_BASE_X = re.compile(r"(base\s*=\s*\[\s*|rail\s*=\s*\[\s*\[\s*)([-+0-9.eE]+)")  # PRR: rail start


def test_edited_base_is_refused(model, tmp_path):
    """Every model: a copy of its model file with leg 1's base (a PRR leg's rail start) moved
    1 mm in x is stale."""
    text = Path(model.spec.path).read_text()
    match = _BASE_X.search(text)
    assert match, f"no `base = [x, y]` in {model.spec.path}"
    x_new = float(match.group(2)) + 0.001
    path = tmp_path / Path(model.spec.path).name
    path.write_text(text[:match.start(2)] + repr(x_new) + text[match.end(2):])
    edited = read_model_file(path)
    # the edit did what it says: leg 1's base moved, nothing else in the legs changed
    assert edited.legs[0].base == (x_new, model.spec.legs[0].base[1])
    assert edited.legs[1:] == model.spec.legs[1:] and edited.name == model.name
    assert edited.formulation_sha256 != model.spec.formulation_sha256
    # the shipped folder holds the shipped file's code: derive the copy into its own folder
    # (`derive --out` the shipped folder would be refused)
    with pytest.raises(pm2dof.StaleGeneratedCodeError, match=re.escape(
            f"Derive this one into its own folder, `pm2dof derive {path}`")) as info:
        pm2dof.load_model(path, generated=gen_dir(model))
    assert "--force" not in str(info.value)


def test_unchanged_copy_loads_with_the_shipped_code(model, tmp_path):
    """A copy of a shipped model file finds no code beside it (the message names the command
    that derives it there) and loads with the shipped code named by ``generated=``."""
    path = tmp_path / Path(model.spec.path).name
    shutil.copy(model.spec.path, path)
    with pytest.raises(pm2dof.StaleGeneratedCodeError,
                       match=re.escape(f"Run `pm2dof derive {path}`")):
        pm2dof.load_model(path)
    loaded = pm2dof.load_model(path, generated=gen_dir(model))
    assert loaded.name == model.name and loaded.n_legs == model.n_legs
    assert loaded.generated == str(gen_dir(model))


def _edited_copy(tmp_path, old, new):
    text = DEFAULT_MODEL.read_text()
    assert text.count(old) == 1, f"{old!r} not found once in the model file"
    path = tmp_path / "shang2010.toml"
    path.write_text(text.replace(old, new))
    return path


@pytest.mark.parametrize("old, new", [
    ("base = [0.433, 0.0]", "base = [0.434, 0.0]"),
    ("base = [0.0, 0.25]", "base = [0.0, 0.2501]"),
    ("la = 0.244              # active", "la = 0.245              # active"),
    ('lb = 0.244              # passive (distal) link, m\nelbow = "right"',
     'lb = 0.244              # passive (distal) link, m\nelbow = "left"'),
], ids=["base2-x", "base1-y", "la1", "elbow1"])
def test_changed_formulation_is_refused(tmp_path, old, new):
    """Paper only: more kinds of edits of the formulation."""
    path = _edited_copy(tmp_path, old, new)
    with pytest.raises(pm2dof.StaleGeneratedCodeError, match="pm2dof derive"):
        pm2dof.load_model(path, generated=SHIPPED_GENERATED / PAPER)


@pytest.mark.parametrize("old, new, check", [
    ("\nsingularity_threshold = 0.1 ", "\nsingularity_threshold = 0.15 ",
     lambda m: m.singularity_threshold == 0.15),
    ("fc    = [0.4976, 0.4570, 0.3006]", "fc    = [0.5, 0.4570, 0.3006]",
     lambda m: m.theta_nominal[12] == 0.5),
    ("# Tables 1-2", "# Tables one and two", lambda m: True),
], ids=["limits", "nominal", "comment"])
def test_run_time_sections_do_not_make_code_stale(tmp_path, old, new, check):
    """Paper only."""
    m = pm2dof.load_model(_edited_copy(tmp_path, old, new), generated=SHIPPED_GENERATED / PAPER)
    assert check(m)


# --------------------------------------------------------------------------------------
# The runtime does not import the build-time stack
# --------------------------------------------------------------------------------------

def test_runtime_never_imports_sympy_casadi_derive():
    """All model files in one subprocess (each loaded and evaluated)."""
    code = (
        "import sys, json, glob, numpy as np\n"
        "import pm2dof\n"
        "done = []\n"
        "for path in sorted(glob.glob('pm2dof/models/*.toml')):\n"
        "    m = pm2dof.load_model(path)\n"
        "    n = m.n_legs\n"
        "    t = next(iter(m.spec.trajectories.values()))\n"
        "    xe = (np.asarray(t['start']) + np.asarray(t['end'])) / 2\n"
        "    q = m.ik(xe)\n"
        "    v, a = np.r_[0.1, 0.2, 0.3][:m.dof], np.r_[1.0, 0.0, 0.5][:m.dof]\n"
        "    Y = m.Y(q, v, v, a)\n"
        "    m.forward_dynamics(xe, v, np.arange(1.0, n + 1), m.theta_nominal)\n"
        "    assert Y.shape == (m.dof, len(m.param_names))\n"
        "    done.append(m.name)\n"
        "bad = sorted(k for k in sys.modules if k.split('.')[0] in ('sympy', 'casadi')\n"
        "             or k.startswith('pm2dof.derive'))\n"
        "print(json.dumps({'bad': bad, 'done': done}))\n"
    )
    r = subprocess.run([sys.executable, "-c", code], cwd=PACKAGE.parent, capture_output=True,
                       text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    res = json.loads(r.stdout.strip().splitlines()[-1])
    want = sorted(read_model_file(p).name for p in SHIPPED_MODELS.glob("*.toml"))
    assert sorted(res["done"]) == want and PAPER in res["done"], res
    assert res["bad"] == [], f"the runtime imported build-time modules: {res['bad']}"
