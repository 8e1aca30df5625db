# The generated C against its SymPy source at 30 digits, and the generated files against their derivation.
"""Tests of ``generated/shang2010/``: what ``make derive`` produced and what the runtime loads.

* The compiled C agrees with the SymPy expressions of ``derive/`` evaluated with mpmath at
  30 significant digits (so the reference carries no rounding error at double precision):
  this isolates the CasADi conversion, the code generation and the C compiler.
* Regenerating into a temporary folder gives byte-identical files (deterministic output,
  independent of Python's hash seed, and the committed files are up to date).
* The manifest describes the files and the model file it was derived from; a model file
  whose formulation differs is refused with :class:`pm2dof.StaleGeneratedCodeError`.
* The runtime never imports SymPy, CasADi or ``derive``.

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
from pathlib import Path

import casadi  # the build-time stack is required by these tests (dev dependencies), never skipped
import mpmath
import numpy as np
import pytest
import sympy

import pm2dof
from pm2dof.model import DEFAULT_MODEL, GENERATED, REPO
from pm2dof.model_file import read_model_file

TOL = 1e-12
DPS = 30
N_POSES = 6
GEN = GENERATED / "shang2010"
FILES = ("shang2010.c", "shang2010.h", "manifest.json")

_OBSERVED: dict[str, float] = {}


def _record(name, ratio):
    _OBSERVED[name] = max(_OBSERVED.get(name, 0.0), float(ratio))


@pytest.fixture(scope="module", autouse=True)
def _report_observed():
    yield
    if _OBSERVED:
        print("\n[test_generated] largest observed relative errors (C vs 30-digit SymPy):")
        for k in sorted(_OBSERVED):
            print(f"  {k:<28s} {_OBSERVED[k]:.3e}")


@pytest.fixture(scope="module")
def m():
    return pm2dof.load_model()


# --------------------------------------------------------------------------------------
# 6'. C against the SymPy expressions at 30 digits
# --------------------------------------------------------------------------------------

def _sgn(v):
    return 1 if v >= 0 else -1  # derive.symbols.sgn: sign with sgn(0) = +1


@pytest.fixture(scope="module")
def mp():
    """The SymPy derivation, lambdified once per matrix for mpmath (cse: ~0.2 s each)."""
    from derive.model_functions import Derivation

    d = Derivation(read_model_file(DEFAULT_MODEL))
    s, kin, dyn = d.sym, d.kin, d.dyn
    q, qa, xe = list(s.q), list(s.qa), list(s.xe)
    xed, xrd, xrdd = list(s.xed), list(s.xrd), list(s.xrdd)
    theta, tau = list(s.theta), list(s.tau_a)
    qd = list(dyn.qd)
    modules = [{"sgn": _sgn}, "mpmath"]

    def lam(args, expr):
        return sympy.lambdify(args, expr, modules=modules, cse=True)

    return {
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


def _poses(m, seed, k=N_POSES):
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < k:
        xe = np.array([rng.uniform(0.17, 0.32), rng.uniform(0.18, 0.34)])
        try:
            q = m.ik(xe)
        except pm2dof.WorkspaceError:
            continue
        if np.min(np.abs(m.singularity(q))) > 0.2:
            phi = rng.uniform(-np.pi, np.pi)
            xed = rng.uniform(0.05, 0.5) * np.array([np.cos(phi), np.sin(phi)])
            alpha, gamma = rng.uniform(0.005, 0.15, 3), rng.uniform(0.005, 0.08, 3)
            beta = rng.uniform(-0.95, 0.95, 3) * np.sqrt(alpha * gamma)
            theta = np.concatenate([alpha, beta, gamma, rng.uniform(0, 5, 3), rng.uniform(0, 1, 3)])
            out.append((xe, xed, rng.uniform(-0.5, 0.5, 2), rng.uniform(-10, 10, 2), theta,
                        rng.uniform(-10, 10, 3)))
    return out


def _check(name, got, want, scale, info):
    got, want = np.asarray(got, float), np.asarray(want, float).reshape(np.shape(got))
    err = float(np.max(np.abs(got - want)))
    _record(name, err / scale)
    assert err <= TOL * scale, (f"{name}: C vs 30-digit SymPy: max error {err:.3e} > {TOL:.0e} * "
                                f"{scale:.3e} at {info}\nC=\n{got}\nSymPy=\n{want}")


def test_C_matches_sympy_at_30_digits(m, mp):
    mpmath.mp.dps = DPS
    for xe, xed, xrd, xrdd, theta, tau in _poses(m, 2010):
        info = (f"xe={xe.tolist()}, xed={xed.tolist()}, xrd={xrd.tolist()}, xrdd={xrdd.tolist()}, "
                f"theta={theta.tolist()}, tau_a={tau.tolist()}")
        q = m.ik(xe)
        qd = m.W(q) @ xed
        Q, XED, TH = _mpv(q), _mpv(xed), _mpv(theta)
        # ik: same expression, so the same branch; wrap only guards the atan2 cut at +-pi
        q_mp = list(mp["ik"](_mpv(xe)))
        _check("ik (rad)", _wrap(q - _to_float(q_mp)), np.zeros(6), 1.0, info)
        _check("fk (m)", m.fk(q[:3]), _to_float(mp["fk"](Q[:3])), 1.0, info)
        _check("H (m)", m.H(q), _to_float(mp["H"](Q)), 1.0, info)
        for name, got, want in [
            ("A", m.A(q), mp["A"](Q)),
            ("W", m.W(q), mp["W"](Q)),
            ("S", m.S(q), mp["S"](Q)),
            ("Wdot", m.Wdot(q, xed), mp["Wdot"](Q, XED)),
            ("M", m.M(q, theta), mp["M"](Q, TH)),
            ("C", m.C(q, qd, theta), mp["C"](Q, _mpv(qd), TH)),
            ("Me", m.Me(q, theta), mp["Me"](Q, TH)),
            ("Ce", m.Ce(q, xed, theta), mp["Ce"](Q, XED, TH)),
            ("StF", m.StF(q, xed, theta), mp["StF"](Q, XED, TH)),
            ("Y", m.Y(q, xed, xrd, xrdd), mp["Y"](Q, XED, _mpv(xrd), _mpv(xrdd))),
        ]:
            want = _to_float(want)
            _check(name, got, want, max(float(np.max(np.abs(want))), 1e-300), info)
        # forward dynamics: the SymPy xedd is in terms of q; use q = ik(xe) at 30 digits
        # (q_mp, never rounded to double). Scale: |Me^-1| times the summed terms of the
        # right-hand side S^T tau - Ce xed - StF (the sum may cancel).
        want = _to_float(mp["xedd"](list(q_mp), XED, _mpv(tau), TH))
        Me = m.Me(q, theta)
        terms = (np.max(np.abs(m.S(q).T @ tau)) + np.max(np.abs(m.Ce(q, xed, theta) @ xed))
                 + np.max(np.abs(m.StF(q, xed, theta))))
        scale = np.linalg.norm(np.linalg.inv(Me), np.inf) * terms
        _check("forward_dynamics", m.forward_dynamics(xe, xed, tau, theta), want, scale, info)


def test_C_matches_sympy_sign_zero(m, mp):
    """At qd_a1 = 0 exactly (qb_1 = 0, xed along y) both sides use sgn(0) = +1."""
    mpmath.mp.dps = DPS
    L, A1 = 0.244, np.array([0.0, 0.25])
    qa1 = -0.3
    xe = A1 + L * np.array([np.cos(qa1), np.sin(qa1)]) + np.array([L, 0.0])
    q = m.ik(xe)
    q[0], q[3] = qa1, 0.0
    xed = np.array([0.0, 0.2])
    theta = np.array(m.theta_nominal)
    info = f"q={q.tolist()}, xed={xed.tolist()}"
    want = _to_float(mp["StF"](_mpv(q), _mpv(xed), _mpv(theta)))
    _check("StF at qd_a = 0", m.StF(q, xed, theta), want, float(np.max(np.abs(want))), info)
    want = _to_float(mp["Y"](_mpv(q), _mpv(xed), _mpv([0, 0]), _mpv([0, 0])))
    _check("Y at qd_a = 0", m.Y(q, xed, np.zeros(2), np.zeros(2)), want,
           float(np.max(np.abs(want))), info)


# --------------------------------------------------------------------------------------
# 8. Regeneration is deterministic and the committed files are up to date
# --------------------------------------------------------------------------------------

def _first_difference(a: bytes, b: bytes):
    la, lb = a.decode(errors="replace").splitlines(), b.decode(errors="replace").splitlines()
    for i, (x, y) in enumerate(zip(la, lb)):
        if x != y:
            return i + 1, x, y
    return min(len(la), len(lb)) + 1, "<end of file>" if len(la) < len(lb) else la[len(lb)], \
        "<end of file>" if len(lb) < len(la) else lb[len(la)]


@pytest.fixture(scope="module")
def regenerated(tmp_path_factory):
    """Two regenerations (``python -m derive ... --no-build``) with different hash seeds."""
    outs, procs = [], []
    for seed in ("0", "4242"):
        out = tmp_path_factory.mktemp(f"derive_seed{seed}")
        env = {**os.environ, "PYTHONHASHSEED": seed,
               "PYTHONPATH": os.pathsep.join([str(REPO), os.environ.get("PYTHONPATH", "")])}
        procs.append(subprocess.Popen(
            [sys.executable, "-m", "derive", str(REPO / "models" / "shang2010.toml"),
             "--out", str(out), "--no-build"],
            cwd=REPO, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE))
        outs.append((seed, out))
    for (seed, out), p in zip(outs, procs):
        so, se = p.communicate(timeout=300)
        assert p.returncode == 0, (f"python -m derive (PYTHONHASHSEED={seed}) failed "
                                   f"({p.returncode}):\n{so.decode()}\n{se.decode()}")
    return outs


def test_regeneration_is_byte_identical(regenerated):
    problems = []
    for seed, out in regenerated:
        for name in FILES:
            new, old = out / name, GEN / name
            if not new.is_file():
                problems.append(f"PYTHONHASHSEED={seed}: {name} was not written")
                continue
            if new.read_bytes() != old.read_bytes():
                line, a, b = _first_difference(old.read_bytes(), new.read_bytes())
                problems.append(f"PYTHONHASHSEED={seed}: generated/shang2010/{name} differs from a "
                                f"fresh derivation at line {line}:\n  committed:   {a[:200]}\n"
                                f"  regenerated: {b[:200]}")
    assert not problems, ("the committed generated code is not what `python -m derive` produces "
                          "now; run `make derive`.\n" + "\n".join(problems))


def test_regeneration_is_deterministic_across_hash_seeds(regenerated):
    (s1, o1), (s2, o2) = regenerated
    for name in FILES:
        a, b = (o1 / name).read_bytes(), (o2 / name).read_bytes()
        if a != b:
            line, x, y = _first_difference(a, b)
            pytest.fail(f"{name} depends on PYTHONHASHSEED ({s1} vs {s2}) at line {line}:\n"
                        f"  {x[:200]}\n  {y[:200]}")


def test_generated_code_has_no_timestamp_or_local_path():
    text = (GEN / "shang2010.c").read_text() + (GEN / "shang2010.h").read_text() \
        + (GEN / "manifest.json").read_text()
    for needle in (str(REPO), "/tmp/", str(Path.home())):
        assert needle not in text, f"generated code contains {needle!r} (not reproducible)"
    stamp = re.search(r"\b20\d\d-[01]\d-[0-3]\d\b|\b\d\d:\d\d:\d\d\b", text)
    assert stamp is None, f"generated code contains a timestamp {stamp.group(0)!r}"


# --------------------------------------------------------------------------------------
# The manifest
# --------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def manifest():
    return json.loads((GEN / "manifest.json").read_text())


def test_manifest_formulation_hash(manifest):
    spec = read_model_file(DEFAULT_MODEL)
    assert manifest["formulation_sha256"] == spec.formulation_sha256, "run make derive"
    assert manifest["model_file_sha256"] == spec.file_sha256, \
        "models/shang2010.toml changed since generation; run make derive"
    assert manifest["model"] == spec.name == "shang2010"
    assert manifest["param_names"] == list(spec.param_names)


def test_manifest_versions_are_the_installed_ones(manifest):
    assert manifest["versions"] == {"sympy": sympy.__version__, "casadi": casadi.__version__}, \
        f"manifest {manifest['versions']} vs installed sympy {sympy.__version__}, casadi " \
        f"{casadi.__version__}: run make derive"


def test_manifest_file_hashes_match_the_files(manifest):
    assert set(manifest["files"]) == {"shang2010.c", "shang2010.h"}
    for name, sha in manifest["files"].items():
        got = hashlib.sha256((GEN / name).read_bytes()).hexdigest()
        assert got == sha, f"{name}: sha256 {got} != manifest {sha}; run make derive"


def test_manifest_derive_sources_hash(manifest):
    from derive.export import derive_sources_sha256
    assert manifest["derive_sources_sha256"] == derive_sources_sha256(), \
        "derive/*.py changed since generation; run make derive"


def test_manifest_signatures_match_the_loaded_functions(m, manifest):
    """Every model function is in the manifest with the signature the loaded C reports."""
    for k in ("ik", "fk", "H", "A", "singularity", "W", "S", "Wdot", "M", "C", "Me", "Ce", "StF",
              "Y", "forward_dynamics"):
        f = m.function(k)
        want = manifest["functions"].get(f"shang2010_{k}")
        have = {"inputs": [[a, n] for a, n in zip(f.names_in, f.sizes_in)],
                "outputs": [[a, n] for a, n in zip(f.names_out, f.sizes_out)]}
        assert want == have, f"shang2010_{k}: manifest {want} != loaded {have}"
    for key in ("formulation_sha256", "model_file_sha256", "derive_sources_sha256"):
        assert m.manifest[key] == manifest[key], key


# --------------------------------------------------------------------------------------
# Stale generated code is refused
# --------------------------------------------------------------------------------------

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
    path = _edited_copy(tmp_path, old, new)
    with pytest.raises(pm2dof.StaleGeneratedCodeError, match="make derive"):
        pm2dof.load_model(path)


def test_unchanged_copy_loads(tmp_path):
    path = tmp_path / "shang2010.toml"
    shutil.copy(DEFAULT_MODEL, path)
    pm2dof.load_model(path)


@pytest.mark.parametrize("old, new, check", [
    ("singularity_threshold = 0.1 ", "singularity_threshold = 0.15 ",
     lambda m: m.singularity_threshold == 0.15),
    ("fc    = [0.4976, 0.4570, 0.3006]", "fc    = [0.5, 0.4570, 0.3006]",
     lambda m: m.theta_nominal[12] == 0.5),
    ("# Tables 1-2", "# Tables one and two", lambda m: True),
], ids=["limits", "nominal", "comment"])
def test_run_time_sections_do_not_make_code_stale(tmp_path, old, new, check):
    m = pm2dof.load_model(_edited_copy(tmp_path, old, new))
    assert check(m)


# --------------------------------------------------------------------------------------
# The runtime does not import the build-time stack
# --------------------------------------------------------------------------------------

def test_runtime_never_imports_sympy_casadi_derive():
    code = (
        "import sys, json, numpy as np\n"
        "import pm2dof\n"
        "m = pm2dof.load_model()\n"
        "q = m.ik([0.25, 0.26])\n"
        "Y = m.Y(q, [0.1, 0.2], [0.1, 0.0], [1.0, 0.0])\n"
        "m.forward_dynamics([0.25, 0.26], [0.1, 0.2], [1.0, 2.0, 3.0], m.theta_nominal)\n"
        "assert Y.shape == (2, 15)\n"
        "bad = sorted(k for k in sys.modules if k.split('.')[0] in ('sympy', 'casadi', 'derive'))\n"
        "print(json.dumps(bad))\n"
    )
    env = {**os.environ, "PYTHONPATH": str(REPO)}
    r = subprocess.run([sys.executable, "-c", code], cwd=REPO, env=env, capture_output=True,
                       text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    bad = json.loads(r.stdout.strip().splitlines()[-1])
    assert bad == [], f"the runtime imported build-time modules: {bad}"
