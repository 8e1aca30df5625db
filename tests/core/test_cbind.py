"""Tests of pm2dof.core._cbind (calling CasADi-generated C) and pm2dof.core.build (compiling it).

CasADi is used at test time only: it generates C code for a few toy functions, which
``pm2dof.core.build.compile_library`` turns into a shared library that ``_cbind`` loads.
A small hand-written C file that mimics CasADi's external API covers what generated
code cannot easily produce (error return codes, missing symbols, lifecycle counters).

CasADi stores matrices column-major; the binding is layout-agnostic and passes flat
buffers through, so a matrix argument is given as its column-major entries.
"""

from __future__ import annotations

import array
import ctypes
import gc
import json
import os
import pathlib
import platform
import re
import subprocess
import sys
import threading
import time

import casadi as ca
import numpy as np
import pytest

from pm2dof.core import _cbind, build

# --------------------------------------------------------------------------------------
# Fixtures: one library of CasADi-generated functions, one hand-written stub library
# --------------------------------------------------------------------------------------

A_STEP = np.array([[0.9, 0.1, 0.0], [-0.1, 0.8, 0.05], [0.0, 0.02, 0.95]])
B_STEP = np.array([[1.0, 0.0], [0.5, 0.25], [0.0, 1.0]])
C_STEP = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, -1.0]])


def _casadi_functions() -> dict[str, ca.Function]:
    x = ca.SX.sym("x", 3)
    y = ca.SX.sym("y", 2, 2)
    s = ca.SX.sym("s")
    toy = ca.Function(
        "toy",
        [x, y, s],
        [x * s, ca.densify(y @ y), ca.sum1(x)],
        ["x", "y", "s"],
        ["xs", "yy", "sum"],
    )
    q = ca.SX.sym("q", 4)
    p = ca.SX.sym("p", 2)
    nl = ca.Function(
        "nl",
        [q, p],
        [
            ca.vertcat(
                ca.sin(q[0]) * p[0] + ca.cos(q[1] * p[1]) * q[2],
                ca.sqrt(q[1] ** 2 + q[3] ** 2 + 1.0) * p[1] + q[0] * q[1] + q[2],
                ca.exp(-q[3] ** 2) * ca.atan2(q[2], p[0] + 3.0),
            ),
            ca.densify(ca.horzcat(q[0:2] * p[0], q[2:4] * q[0] + p[1], ca.sin(q[1:3]))),
        ],
        ["q", "p"],
        ["v", "M"],
    )
    xs_ = ca.SX.sym("x", 3)
    u = ca.SX.sym("u", 2)
    k = ca.SX.sym("k")
    step = ca.Function(
        "step",
        [xs_, u, k],
        [ca.DM(A_STEP) @ xs_ + ca.DM(B_STEP) @ u * k, ca.DM(C_STEP) @ xs_],
        ["x", "u", "p"],
        ["x_next", "y"],
    )
    x2 = ca.SX.sym("x", 2)
    u0 = ca.SX.sym("u", 0, 1)
    k2 = ca.SX.sym("p")
    nu0 = ca.Function("nu0", [x2, u0, k2], [x2 * k2, x2[0]], ["x", "u", "p"], ["x_next", "y"])
    sparse_out = ca.Function("sparse_out", [x], [ca.diag(x)], ["x"], ["D"])
    q6 = ca.SX.sym("q", 6)
    one = ca.Function("one", [q6], [ca.reshape(ca.vertcat(q6, 2 * q6), 3, 4)], ["q"], ["W"])
    return {
        "toy": toy,
        "nl": nl,
        "step": step,
        "nu0": nu0,
        "sparse_out": sparse_out,
        "one": one,
    }


@pytest.fixture(scope="module")
def generated(tmp_path_factory):
    """(library, {name: casadi.Function}) for CasADi-generated code."""
    d = tmp_path_factory.mktemp("gen")
    funcs = _casadi_functions()
    cg = ca.CodeGenerator("toy.c", {"with_header": True})
    for f in funcs.values():
        cg.add(f)
    cg.generate(str(d) + "/")
    so = build.compile_library(d / "toy.c", d / "libtoy.so")
    return _cbind.Library(str(so)), funcs


@pytest.fixture(scope="module")
def lib(generated):
    return generated[0]


@pytest.fixture(scope="module")
def toy(lib):
    return _cbind.Function(lib, "toy")


@pytest.fixture(scope="module")
def step(lib):
    return _cbind.Function(lib, "step")


STUB_C = r"""
/* Hand-written stand-in for CasADi-generated code (same external C API). */
#include <math.h>
typedef long long int casadi_int;
typedef double casadi_real;

static const casadi_int sp_v2[3] = {2, 1, 1};          /* dense 2x1, abbreviated */
static const casadi_int sp_s1[5] = {1, 1, 0, 1, 0};    /* dense 1x1, canonical */
static const casadi_int sp_diag[7] = {2, 2, 0, 1, 2, 0, 1}; /* sparse: diagonal 2x2 */

/* Lifecycle counters, read from the tests through ctypes. */
int n_incref, n_decref, n_checkout, n_release;
int stub_counter(int i) {
  return i == 0 ? n_incref : i == 1 ? n_decref : i == 2 ? n_checkout : n_release;
}

/* fail(i0[2], i1[1]) -> (o0[2]); returns 7 if i0[0] > i1. No name_in/name_out. */
int fail(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)iw; (void)w; (void)mem;
  if (arg[0][0] > arg[1][0]) return 7;
  if (res[0]) { res[0][0] = arg[0][0]; res[0][1] = arg[0][1]; }
  return 0;
}
casadi_int fail_n_in(void) { return 2; }
casadi_int fail_n_out(void) { return 1; }
const casadi_int* fail_sparsity_in(casadi_int i) { return i == 0 ? sp_v2 : i == 1 ? sp_s1 : 0; }
const casadi_int* fail_sparsity_out(casadi_int i) { return i == 0 ? sp_v2 : 0; }
int fail_work(casadi_int* a, casadi_int* r, casadi_int* iw, casadi_int* w) {
  if (a) *a = 2; if (r) *r = 1; if (iw) *iw = 0; if (w) *w = 0; return 0;
}
int fail_checkout(void) { n_checkout++; return 0; }
void fail_release(int mem) { (void)mem; n_release++; }
void fail_incref(void) { n_incref++; }
void fail_decref(void) { n_decref++; }

/* walk(x[2], u[1], lim[1]) -> (x_next[2], y[1]): x_next = x + u, y = x[0];
   returns 5 when x[0] > lim. */
int walk(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)iw; (void)w; (void)mem;
  if (arg[0][0] > arg[2][0]) return 5;
  res[0][0] = arg[0][0] + arg[1][0];
  res[0][1] = arg[0][1] + arg[1][0];
  if (res[1]) res[1][0] = arg[0][0];
  return 0;
}
casadi_int walk_n_in(void) { return 3; }
casadi_int walk_n_out(void) { return 2; }
const casadi_int* walk_sparsity_in(casadi_int i) { return i == 0 ? sp_v2 : i <= 2 ? sp_s1 : 0; }
const casadi_int* walk_sparsity_out(casadi_int i) { return i == 0 ? sp_v2 : i == 1 ? sp_s1 : 0; }
int walk_work(casadi_int* a, casadi_int* r, casadi_int* iw, casadi_int* w) {
  if (a) *a = 3; if (r) *r = 2; if (iw) *iw = 0; if (w) *w = 0; return 0;
}
static const char* walk_names_in[3] = {"x", "u", "lim"};
static const char* walk_names_out[2] = {"x_next", "y"};
const char* walk_name_in(casadi_int i) { return i >= 0 && i < 3 ? walk_names_in[i] : 0; }
const char* walk_name_out(casadi_int i) { return i >= 0 && i < 2 ? walk_names_out[i] : 0; }

/* sparse(D[2x2 diagonal]) -> (o0[2]) */
int sparse(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)res; (void)iw; (void)w; (void)mem; return 0;
}
casadi_int sparse_n_in(void) { return 1; }
casadi_int sparse_n_out(void) { return 1; }
const casadi_int* sparse_sparsity_in(casadi_int i) { return i == 0 ? sp_diag : 0; }
const casadi_int* sparse_sparsity_out(casadi_int i) { return i == 0 ? sp_v2 : 0; }
int sparse_work(casadi_int* a, casadi_int* r, casadi_int* iw, casadi_int* w) {
  if (a) *a = 1; if (r) *r = 1; if (iw) *iw = 0; if (w) *w = 0; return 0;
}

/* int4: like fail but claims to be generated with a 4-byte casadi_int. */
int int4(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  return fail(arg, res, iw, w, mem);
}
casadi_int int4_n_in(void) { return 2; }
casadi_int int4_n_out(void) { return 1; }
const casadi_int* int4_sparsity_in(casadi_int i) { return fail_sparsity_in(i); }
const casadi_int* int4_sparsity_out(casadi_int i) { return fail_sparsity_out(i); }
int int4_work(casadi_int* a, casadi_int* r, casadi_int* iw, casadi_int* w) {
  return fail_work(a, r, iw, w);
}
int int4_casadi_int_size(void) { return 4; }

/* halfway: has the evaluation routine and n_in, nothing else. */
int halfway(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)arg; (void)res; (void)iw; (void)w; (void)mem; return 0;
}
casadi_int halfway_n_in(void) { return 0; }
"""


@pytest.fixture(scope="module")
def stub_path(tmp_path_factory):
    d = tmp_path_factory.mktemp("stub")
    (d / "stub.c").write_text(STUB_C)
    return build.compile_library(d / "stub.c", d / "libstub.so", extra_flags=["-Wall"])


@pytest.fixture(scope="module")
def stub(stub_path):
    return _cbind.Library(str(stub_path))


def _held_exports_free(*objs) -> None:
    """Assert that no buffer export of ``objs`` is still held (each can be resized)."""
    for o in objs:
        if isinstance(o, array.array):
            o.append(0.0)  # BufferError if an export is still held
            o.pop()
        elif isinstance(o, memoryview):
            o.release()  # BufferError if an export of the memoryview is still held


# --------------------------------------------------------------------------------------
# build.py
# --------------------------------------------------------------------------------------


def test_flags_constant_has_documented_flags_and_no_fast_math():
    assert build.FLAGS[:2] == ("-O3", "-march=native")
    for flag in ("-fPIC", "-shared", "-fno-math-errno", "-ffp-contract=off"):
        assert flag in build.FLAGS
    assert not any("fast-math" in flag for flag in build.FLAGS)
    assert set(build.__all__) == {"compile_library", "compile_libraries", "library_is_fresh",
                                  "BuildError", "STALE_TMP_AGE_S", "FLAGS", "PORTABLE_FLAGS",
                                  "SPLIT_FLAGS", "COMPILE_SECONDS_PER_MB",
                                  "compile_estimate", "build_jobs"}
    if platform.machine().lower() in ("x86_64", "amd64"):   # GCC's vfmaddsub despite contract=off
        assert "-mno-fma" in build.FLAGS and "-mno-fma" in build.PORTABLE_FLAGS
    assert build.PORTABLE_FLAGS == tuple(f for f in build.FLAGS if f != "-march=native")
    assert issubclass(build.BuildError, RuntimeError)


def test_compile_library_returns_absolute_path_and_leaves_no_temp_files(tmp_path, monkeypatch):
    (tmp_path / "a.c").write_text("double twice(double x) { return 2 * x; }\n")
    monkeypatch.chdir(tmp_path)
    out = build.compile_library("a.c", "sub/liba.so")
    assert out == tmp_path / "sub" / "liba.so"
    assert out.is_absolute() and out.is_file()
    # Rebuilding replaces the file atomically and leaves nothing else behind.
    inode_before = out.stat().st_ino
    build.compile_library(tmp_path / "a.c", out)
    assert out.stat().st_ino != inode_before
    assert sorted(p.name for p in out.parent.iterdir()) == ["liba.so", "liba.so.json"]
    twice = ctypes.CDLL(str(out)).twice
    twice.restype, twice.argtypes = ctypes.c_double, [ctypes.c_double]
    assert twice(21.0) == 42.0


def test_compile_library_says_what_it_compiles_with_an_estimate_and_then_the_time(tmp_path):
    """A line before the compiler starts (the file, its size, the estimate at
    COMPILE_SECONDS_PER_MB on an idle processor) and one after it (the elapsed time). A 1.5 MB
    C file (mostly a comment: compiled in well under a second) is estimated at 1.5 x 16 = 24 s,
    the time a generated file of that size took (prr3_platform, 1.51 MB: 21.6 s)."""
    c = tmp_path / "big.c"
    c.write_text("/*" + "x" * (1_500_000 - 50) + "*/\ndouble twice(double x) { return 2 * x; }\n")
    size = c.stat().st_size
    seen = []

    def progress(msg):
        seen.append((msg, (tmp_path / "libbig.so").exists()))
    t0 = time.monotonic()
    build.compile_library(c, tmp_path / "libbig.so", progress=progress)
    elapsed = time.monotonic() - t0
    assert [exists for _, exists in seen] == [False, True], seen
    first, last = seen[0][0], seen[1][0]
    assert first.startswith(f"compiling big.c ({size / 1e6:.1f} MB of C) with ") and \
        "-O3: about 24 s on an idle processor" in first, first
    assert abs(build.compile_estimate(c) - size * 16e-6) < 1e-9
    match = re.fullmatch(rf"compiled {re.escape(str(tmp_path / 'libbig.so'))} in (\S+) s", last)
    assert match and 0 <= float(match.group(1)) <= elapsed + 0.05, (last, elapsed)


def test_killed_build_leftovers_are_removed_by_the_next_build_and_ignored_by_git(tmp_path):
    """A build killed between compiling and renaming leaves .lib<name>.so.*.tmp: the next build
    removes those older than STALE_TMP_AGE_S (younger ones may be a concurrent build's), and
    git does not show them under pm2dof/generated/."""
    (tmp_path / "a.c").write_text("double twice(double x) { return 2 * x; }\n")
    old, young = tmp_path / ".liba.so.killed1.tmp", tmp_path / ".liba.so.running.tmp"
    other = tmp_path / ".libb.so.killed2.tmp"  # another library's: not this build's business
    for f in (old, young, other):
        f.write_bytes(b"half a library")
    stale = time.time() - build.STALE_TMP_AGE_S - 60
    os.utime(old, (stale, stale))
    os.utime(other, (stale, stale))
    build.compile_library(tmp_path / "a.c", tmp_path / "liba.so")
    assert not old.exists() and young.exists() and other.exists()
    repo = pathlib.Path(__file__).resolve().parents[2]
    probe = "pm2dof/generated/shang2010/.libshang2010.so.abc123.tmp"
    r = subprocess.run(["git", "check-ignore", "-q", probe], cwd=repo)
    assert r.returncode == 0, f"git does not ignore {probe}"


def test_compile_library_invalid_c_raises_build_error_with_command_and_stderr(tmp_path):
    (tmp_path / "bad.c").write_text("int f(void) { return undeclared_thing; }\n")
    with pytest.raises(build.BuildError) as info:
        build.compile_library(tmp_path / "bad.c", tmp_path / "bad.so")
    msg = str(info.value)
    assert "command:" in msg and "-O3" in msg and str(tmp_path / "bad.c") in msg
    assert "undeclared_thing" in msg  # the compiler's stderr
    assert not (tmp_path / "bad.so").exists()
    assert list(tmp_path.iterdir()) == [tmp_path / "bad.c"]  # temp file removed


def test_compile_library_uses_cc_environment_variable(tmp_path, monkeypatch):
    (tmp_path / "a.c").write_text("int one(void) { return 1; }\n")
    monkeypatch.setenv("CC", "/nonexistent/bin/my-cc -pipe")
    with pytest.raises(build.BuildError, match=r"(?s)no C compiler found.*apt install gcc.*"
                                               r"command: /nonexistent/bin/my-cc -pipe -O3"):
        build.compile_library(tmp_path / "a.c", tmp_path / "a.so")


def test_build_record_says_which_source_the_library_came_from(tmp_path):
    """library_is_fresh: true after a build; false when the source changes (even if the
    library looks newer), when the record or library is missing; true for an older-looking
    library whose record matches the source (installers do not keep file times)."""
    c, lib = tmp_path / "a.c", tmp_path / "liba.so"
    c.write_text("int one(void) { return 1; }\n")
    assert not build.library_is_fresh(c, lib)
    build.compile_library(c, lib, portable=True)
    record = json.loads((tmp_path / "liba.so.json").read_text())
    assert "-march=native" not in record["flags"] and record["source"] == "a.c"
    sha = record["source_sha256"]
    assert build.library_is_fresh(c, lib, sha) and build.library_is_fresh(c, lib)
    os.utime(lib, (1e9, 1e9))                        # older than the source, same content
    assert build.library_is_fresh(c, lib, sha)
    os.utime(lib, None)
    c.write_text("int one(void) { return 2; }\n")   # new content, newer than the library
    assert not build.library_is_fresh(c, lib, sha)
    os.utime(c, (1e9, 1e9))          # older-looking: without the manifest's hash, hashed anyway
    assert not build.library_is_fresh(c, lib)
    build.compile_library(c, lib)
    assert build.library_is_fresh(c, lib)
    (tmp_path / "liba.so.json").unlink()
    assert not build.library_is_fresh(c, lib)


@pytest.mark.parametrize("flags", [None, "-O3", ["-O3", "-fPIC"], "dropped"])
def test_a_library_built_without_this_versions_flags_is_stale(tmp_path, flags):
    """The build record's flags must hold every portable flag: a record from before a flag
    that decides the results (-mno-fma), or with none, makes the library stale."""
    c, lib = tmp_path / "a.c", tmp_path / "liba.so"
    c.write_text("int one(void) { return 1; }\n")
    build.compile_library(c, lib)
    assert build.library_is_fresh(c, lib)
    stamp = tmp_path / "liba.so.json"
    record = json.loads(stamp.read_text())
    if flags is None:
        del record["flags"]
    elif flags == "dropped":        # one result-deciding flag missing
        record["flags"] = [f for f in record["flags"] if f != "-ffp-contract=off"]
    else:
        record["flags"] = flags
    stamp.write_text(json.dumps(record))
    assert not build.library_is_fresh(c, lib)
    assert not build.library_is_fresh(c, lib, record["source_sha256"])


def test_compile_library_missing_source(tmp_path):
    with pytest.raises(FileNotFoundError, match="nothere.c"):
        build.compile_library(tmp_path / "nothere.c", tmp_path / "x.so")


# --------------------------------------------------------------------------------------
# Library / Function construction
# --------------------------------------------------------------------------------------


def test_library_load_failure_names_path(tmp_path):
    missing = tmp_path / "missing.so"
    with pytest.raises(OSError, match=r"cannot load shared library .*missing\.so"):
        _cbind.Library(str(missing))
    notalib = tmp_path / "notalib.so"
    notalib.write_text("not an ELF file")
    with pytest.raises(OSError, match="notalib.so"):
        _cbind.Library(notalib)  # os.PathLike accepted too


def test_metadata_and_repr(lib, toy):
    assert lib.path.endswith("libtoy.so")
    assert repr(lib) == f"<Library {lib.path!r}>"
    assert toy.name == "toy"
    assert toy.library is lib
    assert (toy.n_in, toy.n_out) == (3, 3)
    assert toy.names_in == ("x", "y", "s")
    assert toy.names_out == ("xs", "yy", "sum")
    assert toy.sizes_in == (3, 4, 1)
    assert toy.sizes_out == (3, 4, 1)
    assert toy.shapes_in == ((3, 1), (2, 2), (1, 1))
    assert toy.shapes_out == ((3, 1), (2, 2), (1, 1))
    assert repr(toy) == "<Function toy(x[3], y[4], s[1]) -> (xs[3], yy[4], sum[1])>"
    with pytest.raises(AttributeError):
        toy.n_in = 5  # read-only
    one = _cbind.Function(lib, "one")
    assert repr(one) == "<Function one(q[6]) -> (W[12])>"
    assert one.shapes_out == ((3, 4),) and one.sizes_out == (12,)


def test_missing_function_raises_lookup_error(lib):
    with pytest.raises(LookupError, match=r"symbol 'nosuchfn' not found in .*libtoy\.so"):
        _cbind.Function(lib, "nosuchfn")


def test_missing_required_symbol_is_named(stub):
    with pytest.raises(LookupError, match=r"symbol 'halfway_n_out' not found in .*libstub"):
        _cbind.Function(stub, "halfway")


def test_sparse_arguments_are_rejected(lib, stub):
    with pytest.raises(ValueError, match=r"sparse_out: output 'D' \(#0\) is sparse \(3x3 with 3"):
        _cbind.Function(lib, "sparse_out")
    with pytest.raises(ValueError, match=r"sparse: input 'i0' \(#0\) is sparse"):
        _cbind.Function(stub, "sparse")


def test_wrong_casadi_int_size_is_rejected(stub):
    with pytest.raises(ValueError, match="casadi_int of 4 bytes"):
        _cbind.Function(stub, "int4")


def test_stub_defaults_for_missing_names_and_canonical_dense_pattern(stub):
    f = _cbind.Function(stub, "fail")
    assert f.names_in == ("i0", "i1") and f.names_out == ("o0",)
    assert f.sizes_in == (2, 1) and f.shapes_in == ((2, 1), (1, 1))


def test_lifecycle_incref_checkout_release_decref(stub_path, stub):
    counters = ctypes.CDLL(str(stub_path)).stub_counter  # same loaded object as `stub`

    def state():
        return [counters(i) for i in range(4)]  # incref, decref, checkout, release

    before = state()
    f = _cbind.Function(stub, "fail")
    assert [a - b for a, b in zip(state(), before)] == [1, 0, 1, 0]
    del f
    gc.collect()
    assert [a - b for a, b in zip(state(), before)] == [1, 1, 1, 1]


def test_function_keeps_library_alive(generated, tmp_path):
    _, funcs = generated
    so = build.compile_library(
        pathlib.Path(generated[0].path).parent / "toy.c", tmp_path / "own.so"
    )
    lib = _cbind.Library(str(so))
    f = _cbind.Function(lib, "step")
    del lib
    gc.collect()
    out = np.empty(3)
    f(np.ones(3), np.ones(2), 1.0, out, None)
    expected = np.array(funcs["step"](np.ones(3), np.ones(2), 1.0)[0]).ravel()
    np.testing.assert_array_equal(out, expected)


# --------------------------------------------------------------------------------------
# Calling
# --------------------------------------------------------------------------------------


def test_toy_matches_casadi_column_major(generated, toy):
    _, funcs = generated
    rng = np.random.default_rng(1)
    for _ in range(20):
        x = rng.standard_normal(3)
        Y = rng.standard_normal((2, 2))
        s = float(rng.standard_normal())
        xs, yy, sm = np.empty(3), np.empty(4), np.empty(1)
        # CasADi is column-major: pass the matrix's column-major entries.
        toy(x, Y.ravel(order="F"), s, xs, yy, sm)
        ref = [np.asarray(r) for r in funcs["toy"](x, Y, s)]
        np.testing.assert_allclose(xs, ref[0].ravel(), rtol=0, atol=1e-14)
        np.testing.assert_allclose(yy.reshape(2, 2, order="F"), ref[1], rtol=0, atol=1e-14)
        np.testing.assert_allclose(yy.reshape(2, 2, order="F"), Y @ Y, rtol=0, atol=1e-14)
        np.testing.assert_allclose(sm, ref[2].ravel(), rtol=0, atol=1e-14)


def test_layout_agnostic_c_ordered_matrix_is_read_as_its_transpose(toy):
    Y = np.array([[1.0, 2.0], [3.0, 4.0]])
    yy = np.empty((2, 2))
    toy(np.zeros(3), Y, 1.0, np.empty(3), yy, np.empty(1))  # any ndim, flat memory
    # The C-ordered memory [1, 2, 3, 4] read column-major is Y.T; the output memory
    # read column-major (= yy.T in C order) is Y.T @ Y.T.
    np.testing.assert_array_equal(yy.T, Y.T @ Y.T)


def test_nonlinear_function_agrees_bit_for_bit_with_casadi(generated, lib):
    # -ffp-contract=off keeps the compiled code from fusing a*b+c into FMAs, so the
    # generated code rounds exactly like CasADi's own evaluation.
    _, funcs = generated
    nl = _cbind.Function(lib, "nl")
    rng = np.random.default_rng(2)
    for _ in range(200):
        q, p = rng.standard_normal(4), rng.standard_normal(2)
        v, M = np.empty(3), np.empty(6)
        nl(q, p, v, M)
        ref_v, ref_M = (np.asarray(r) for r in funcs["nl"](q, p))
        np.testing.assert_array_equal(v, ref_v.ravel())
        np.testing.assert_array_equal(M, ref_M.ravel(order="F"))


def test_none_outputs_are_not_computed(toy):
    xs = np.full(3, -7.0)
    yy = np.full(4, -7.0)
    sm = np.full(1, -7.0)
    assert toy(np.array([1.0, 2.0, 3.0]), np.arange(4.0), 2.0, None, yy, None) is None
    np.testing.assert_array_equal(yy, [2.0, 3.0, 6.0, 11.0])
    toy(np.array([1.0, 2.0, 3.0]), np.arange(4.0), 2.0, xs, None, sm)
    np.testing.assert_array_equal(xs, [2.0, 4.0, 6.0])
    np.testing.assert_array_equal(sm, [6.0])
    np.testing.assert_array_equal(yy, [2.0, 3.0, 6.0, 11.0])  # untouched this time


def test_vector_input_must_be_one_dimensional(toy):
    """A vector input given as a 2-D array of the right size is refused, with both shapes."""
    x = np.array([1.0, -2.0, 4.0])
    for bad in (x[None, :].copy(), x[:, None].copy()):
        with pytest.raises(ValueError, match=r"toy: input 'x' \(#0\) must have shape \(3,\), "
                           r"got shape \((1, 3|3, 1)\)"):
            toy(bad, np.zeros(4), 2.0, np.empty(3), None, None)
    with pytest.raises(ValueError, match=r"input 's' \(#2\) must have shape \(1,\), got shape "
                       r"\(1, 1\)"):
        toy(x, np.zeros(4), np.array([[2.5]]), np.empty(3), None, None)


@pytest.mark.parametrize(
    "scalar", [2.5, 3, True, np.float64(2.5), np.array(2.5), np.array([2.5]), [2.5]]
)
def test_scalar_input_forms(toy, scalar):
    x = np.array([1.0, -2.0, 4.0])
    xs = np.empty(3)
    if isinstance(scalar, list):  # lists are not buffers
        with pytest.raises(TypeError, match=r"input 's' \(#2\) must be a C-contiguous float64 "
                           r"buffer or a Python float, got list"):
            toy(x, np.zeros(4), scalar, xs, None, None)
        return
    toy(x, np.zeros(4), scalar, xs, None, None)
    np.testing.assert_array_equal(xs, x * float(np.asarray(scalar).ravel()[0]))


def test_other_buffer_exporters(toy):
    x = (ctypes.c_double * 3)(1.0, 2.0, 3.0)  # format '<d'
    y = array.array("d", [0.0, 1.0, 2.0, 3.0])  # format 'd'
    out = memoryview(bytearray(24)).cast("d")
    yy = np.empty(4)
    toy(x, y, 2.0, out, yy, None)
    assert out.tolist() == [2.0, 4.0, 6.0]
    np.testing.assert_array_equal(yy, [2.0, 3.0, 6.0, 11.0])
    _held_exports_free(y, out)
    # numpy arrays before other exporters (pointers of arrays bound without an export
    # are re-taken after the other exporters ran): same results, nothing left held.
    xs = np.empty(3)
    toy(np.array([1.0, 2.0, 3.0]), y, 2.0, xs, memoryview(bytearray(32)).cast("d"), None)
    np.testing.assert_array_equal(xs, [2.0, 4.0, 6.0])
    _held_exports_free(y)


def test_wrong_argument_count(toy):
    with pytest.raises(
        TypeError,
        match=r"^toy\(x\[3\], y\[4\], s\[1\]\) -> \(xs\[3\], yy\[4\], sum\[1\]\) takes 6 "
        r"arguments \(3 inputs, 3 outputs\), got 5$",
    ):
        toy(np.zeros(3), np.zeros(4), 1.0, np.empty(3), np.empty(4))
    one = _cbind.Function(toy.library, "one")
    with pytest.raises(
        TypeError, match=r"^one\(q\[6\]\) -> \(W\[12\]\) takes 2 arguments \(1 input, 1 output\), "
        r"got 3$"
    ):
        one(np.zeros(6), np.empty(12), np.empty(12))
    with pytest.raises(TypeError, match=r"takes 2 arguments \(1 input, 1 output\), got 0$"):
        one()


def test_keyword_arguments_rejected(toy):
    with pytest.raises(TypeError, match=r"toy\(\) takes no keyword arguments"):
        toy(np.zeros(3), np.zeros(4), 1.0, np.empty(3), np.empty(4), s=np.empty(1))


@pytest.mark.parametrize(
    "bad, exc, pattern",
    [
        (np.zeros(3, np.float32), TypeError,
         r"^toy: input 'x' \(#0\) must have dtype float64 \(buffer format 'd'\), got format 'f'"),
        (np.zeros(3, np.int64), TypeError, r"input 'x' \(#0\) must have dtype float64"),
        (np.zeros(3, ">f8"), TypeError, r"input 'x' \(#0\) must have dtype float64.*'>d'"),
        (np.zeros(4), ValueError, r"^toy: input 'x' \(#0\) must have 3 float64 elements, got 4$"),
        (np.zeros((3, 2))[:, 0], ValueError, r"^toy: input 'x' \(#0\) must be C-contiguous"),
        (np.zeros((3, 2), order="F"), ValueError, r"input 'x' \(#0\) must be C-contiguous"),
        (np.zeros((3, 3)).T[0], ValueError, r"must be C-contiguous"),
        (np.frombuffer(bytearray(33), dtype=np.float64, count=3, offset=1), ValueError,
         r"input 'x' \(#0\) must be 8-byte aligned"),
        (None, TypeError, r"input 'x' \(#0\) cannot be None"),
        ([1.0, 2.0, 3.0], TypeError,
         r"^toy: input 'x' \(#0\) must be a C-contiguous float64 buffer, got list$"),
        (b"\0" * 24, TypeError, r"got format 'B'"),
    ],
)
def test_bad_input_errors(toy, bad, exc, pattern):
    y = np.zeros(4)
    with pytest.raises(exc, match=pattern):
        toy(bad, y, 1.0, np.empty(3), np.empty(4), np.empty(1))


@pytest.mark.parametrize(
    "bad, exc, pattern",
    [
        (np.empty(3, np.float32), TypeError, r"^toy: output 'yy' \(#1\) must have dtype float64"),
        (np.empty(5), ValueError, r"^toy: output 'yy' \(#1\) must have 4 float64 elements, got 5$"),
        (np.empty((4, 2))[:, 1], ValueError, r"output 'yy' \(#1\) must be C-contiguous"),
        (b"\0" * 32, ValueError, r"^toy: output 'yy' \(#1\) must be writable, got a read-only bytes$"),
        (2.0, TypeError, r"output 'yy' \(#1\) must be a C-contiguous float64 buffer, got float"),
    ],
)
def test_bad_output_errors(toy, bad, exc, pattern):
    with pytest.raises(exc, match=pattern):
        toy(np.zeros(3), np.zeros(4), 1.0, np.empty(3), bad, np.empty(1))


def test_read_only_numpy_output(toy):
    ro = np.zeros(4)
    ro.setflags(write=False)
    with pytest.raises(ValueError, match=r"output 'yy' \(#1\) must be writable, got a read-only "
                       r"numpy\.ndarray"):
        toy(np.zeros(3), np.zeros(4), 1.0, np.empty(3), ro, np.empty(1))
    np.testing.assert_array_equal(ro, 0.0)


@pytest.mark.parametrize("value, text", [(np.nan, "nan"), (np.inf, "inf"), (-np.inf, "-inf")])
def test_non_finite_inputs(toy, value, text):
    x = np.array([1.0, value, 3.0])
    out = np.full(3, 5.0)
    with pytest.raises(
        ValueError, match=rf"^toy: input 'x' \(#0\) has a non-finite value at index 1 \({text}\)$"
    ):
        toy(x, np.zeros(4), 1.0, out, None, None)
    np.testing.assert_array_equal(out, 5.0)  # nothing was evaluated
    with pytest.raises(ValueError, match=r"input 's' \(#2\) has a non-finite value at index 0"):
        toy(np.zeros(3), np.zeros(4), value, out, None, None)
    y = np.zeros((2, 2))
    y[1, 1] = value
    with pytest.raises(ValueError, match=r"input 'y' \(#1\) has a non-finite value at index 3"):
        toy(np.zeros(3), y, 1.0, out, None, None)


def test_non_finite_outputs_are_allowed_as_destinations(toy):
    out = np.full(3, np.nan)
    toy(np.ones(3), np.zeros(4), 2.0, out, None, None)
    np.testing.assert_array_equal(out, 2.0)


def test_huge_int_scalar(toy):
    with pytest.raises(OverflowError, match=r"input 's' \(#2\) is an int too large"):
        toy(np.zeros(3), np.zeros(4), 10**400, np.empty(3), None, None)


def test_output_aliasing_an_input_is_rejected(toy):
    x = np.ones(3)
    with pytest.raises(ValueError, match=r"output 'xs' \(#0\) shares memory with input 'x' \(#0\)"):
        toy(x, np.zeros(4), 2.0, x, None, None)
    np.testing.assert_array_equal(x, 1.0)
    buf = np.zeros(8)
    with pytest.raises(ValueError, match=r"output 'yy' \(#1\) shares memory with output 'xs'"):
        toy(np.ones(3), np.zeros(4), 2.0, buf[:3], buf[2:6], None)


def test_buffers_released_after_success_and_every_error(toy):
    x = array.array("d", [1.0, 2.0, 3.0])
    y = array.array("d", [0.0, 1.0, 2.0, 3.0])
    xs = memoryview(bytearray(24)).cast("d")
    yy = np.empty(4)
    sm = np.empty(1)
    args_ok = (x, y, 2.0, xs, yy, sm)
    bad_calls = [
        (x, y, 2.0, xs, yy, np.empty(2)),  # wrong count, after 4 exports
        (x, y, 2.0, xs, yy, np.empty(1, np.float32)),  # wrong dtype
        (x, y, 2.0, xs, yy, b"\0" * 8),  # read-only
        (x, y, float("nan"), xs, yy, sm),  # non-finite, after all exports
        (x, y, 2.0, xs, yy[:3], sm),
        (x, y, 2.0, xs, np.empty((4, 2))[:, 0], sm),
    ]
    refs = [sys.getrefcount(o) for o in (x, y, xs, yy, sm)]
    for _ in range(3):
        toy(*args_ok)
        for bad in bad_calls:
            with pytest.raises((ValueError, TypeError)):
                toy(*bad)
            with pytest.raises((ValueError, TypeError)):
                toy.time_calls(2, 1, *bad)
    assert [sys.getrefcount(o) for o in (x, y, xs, yy, sm)] == refs
    yy.resize(10, refcheck=False)  # numpy arrays can be resized afterwards
    _held_exports_free(x, y, xs)


def test_no_reference_leaks_on_the_fast_path(toy):
    x, y, xs, yy, sm = np.ones(3), np.ones(4), np.empty(3), np.empty(4), np.empty(1)
    s = 2.0
    before = [sys.getrefcount(o) for o in (x, y, s, xs, yy, sm)]
    for _ in range(1000):
        toy(x, y, s, xs, yy, sm)
    assert [sys.getrefcount(o) for o in (x, y, s, xs, yy, sm)] == before


def test_eval_error_names_function_and_code(stub):
    f = _cbind.Function(stub, "fail")
    out = np.empty(2)
    f(np.array([1.0, 2.0]), 5.0, out)
    np.testing.assert_array_equal(out, [1.0, 2.0])
    assert issubclass(_cbind.EvalError, RuntimeError)
    with pytest.raises(_cbind.EvalError, match=r"^fail: CasADi function returned error code 7$"):
        f(np.array([6.0, 2.0]), 5.0, out)
    with pytest.raises(_cbind.EvalError, match=r"error code 7"):
        f.time_calls(3, 2, np.array([6.0, 2.0]), 5.0, out)


# --------------------------------------------------------------------------------------
# time_calls
# --------------------------------------------------------------------------------------


def test_time_calls_returns_positive_ns_per_call(toy):
    x, yy = np.ones(3), np.empty(4)
    times = toy.time_calls(1000, 4, x, np.ones(4), 2.0, np.empty(3), yy, np.empty(1))
    assert isinstance(times, list) and len(times) == 4
    assert all(isinstance(t, float) and 0.0 < t < 1e6 for t in times)
    np.testing.assert_array_equal(yy, [2.0, 2.0, 2.0, 2.0])  # really evaluated


def test_time_calls_argument_errors(toy):
    args = (np.ones(3), np.ones(4), 2.0, np.empty(3), np.empty(4), np.empty(1))
    with pytest.raises(ValueError, match=r"toy\.time_calls: n_inner must be >= 1, got 0"):
        toy.time_calls(0, 1, *args)
    with pytest.raises(ValueError, match=r"n_repeat must be >= 1, got -2"):
        toy.time_calls(1, -2, *args)
    with pytest.raises(TypeError, match=r"n_inner must be a positive int"):
        toy.time_calls(1.5, 1, *args)
    with pytest.raises(TypeError, match=r"takes 8 arguments \(2 counts, 3 inputs, 3 outputs\), "
                       r"got 7"):
        toy.time_calls(1, 1, *args[:-1])
    with pytest.raises(ValueError, match=r"^toy\.time_calls: input 'x' \(#0\) has a non-finite"):
        toy.time_calls(1, 1, np.array([np.nan, 0, 0]), *args[1:])


# --------------------------------------------------------------------------------------
# accumulate
# --------------------------------------------------------------------------------------


def _python_rollout(f, x0, u_seq, p, nu, ny):
    x = np.array(x0, dtype=float)
    n = len(u_seq) // nu
    ys = np.empty(n * ny)
    for k in range(n):
        x_next = np.empty_like(x)
        f(x, u_seq[k * nu:(k + 1) * nu], p, x_next, ys[k * ny:(k + 1) * ny])
        x = x_next
    return x, ys


def test_accumulate_equals_python_loop_bit_for_bit(generated, step):
    _, funcs = generated
    rng = np.random.default_rng(3)
    n = 500
    u_seq = rng.standard_normal((n, 2))
    x0 = rng.standard_normal(3)
    x_ref, y_ref = _python_rollout(step, x0, u_seq.ravel(), 0.7, 2, 2)

    x = x0.copy()
    y_seq = np.empty((n, 2))
    assert step.accumulate(x, u_seq, 0.7, y_seq) is None
    np.testing.assert_array_equal(x, x_ref)
    np.testing.assert_array_equal(y_seq.ravel(), y_ref)
    # and against CasADi itself for the first steps
    xc = x0.copy()
    for k in range(3):
        xn, yk = funcs["step"](xc, u_seq[k], 0.7)
        np.testing.assert_allclose(y_seq[k], np.asarray(yk).ravel(), rtol=0, atol=1e-14)
        xc = np.asarray(xn).ravel()


def test_accumulate_odd_and_even_step_counts_and_none_y(step):
    for n in (1, 2, 3):
        u_seq = np.arange(2.0 * n)
        x = np.array([1.0, -1.0, 0.5])
        x_ref, y_ref = _python_rollout(step, x, u_seq, 0.3, 2, 2)
        y_seq = np.empty(2 * n)
        step.accumulate(x, u_seq, np.array([0.3]), y_seq)
        np.testing.assert_array_equal(x, x_ref)
        np.testing.assert_array_equal(y_seq, y_ref)
        x2 = np.array([1.0, -1.0, 0.5])
        step.accumulate(x2, u_seq, 0.3, None)  # y not computed
        np.testing.assert_array_equal(x2, x_ref)


def test_accumulate_argument_errors(toy, step, lib):
    x, u, y = np.zeros(3), np.zeros(10), np.zeros(10)
    with pytest.raises(TypeError, match=r"toy\.accumulate requires a function with 3 inputs.*"
                       r"toy\(x\[3\], y\[4\], s\[1\]\)"):
        toy.accumulate(x, u, 1.0, y)
    with pytest.raises(TypeError, match=r"step\.accumulate\(x, u_seq, p, y_seq\) takes 4 "
                       r"arguments, got 3"):
        step.accumulate(x, u, 1.0)
    with pytest.raises(ValueError, match=r"argument 'u_seq' \(input 'u' #1\) must have N \* 2 "
                       r"float64 elements with N >= 1, got 9"):
        step.accumulate(x, np.zeros(9), 1.0, y)
    with pytest.raises(ValueError, match=r"must have N \* 2 float64 elements with N >= 1, got 0"):
        step.accumulate(x, np.zeros(0), 1.0, np.zeros(0))
    with pytest.raises(ValueError, match=r"^step\.accumulate: argument 'y_seq' \(output 'y' #1\) "
                       r"must have 10 float64 elements, got 8$"):
        step.accumulate(x, u, 1.0, np.zeros(8))
    with pytest.raises(ValueError, match=r"argument 'x' \(input 'x' #0\) must have 3 float64"):
        step.accumulate(np.zeros(2), u, 1.0, y)
    ro = np.zeros(3)
    ro.setflags(write=False)
    with pytest.raises(ValueError, match=r"argument 'x' \(input 'x' #0\) must be writable"):
        step.accumulate(ro, u, 1.0, y)
    with pytest.raises(ValueError, match=r"argument 'u_seq' \(input 'u' #1\) has a non-finite "
                       r"value at index 7 \(nan\)"):
        step.accumulate(x, np.where(np.arange(10) == 7, np.nan, 0.0), 1.0, y)
    with pytest.raises(ValueError, match=r"argument 'x' \(input 'x' #0\) has a non-finite value "
                       r"at index 2 \(-inf\)"):
        step.accumulate(np.array([0.0, 0.0, -np.inf]), u, 1.0, y)
    with pytest.raises(ValueError, match=r"argument 'p' \(input 'p' #2\) has a non-finite"):
        step.accumulate(x, u, float("inf"), y)
    with pytest.raises(ValueError, match=r"must not share memory"):
        step.accumulate(x, u, 1.0, u)
    with pytest.raises(ValueError, match=r"nu == 0 is not supported"):
        _cbind.Function(lib, "nu0").accumulate(np.zeros(2), np.zeros(0), 1.0, np.zeros(0))


def test_accumulate_releases_buffers_after_errors(step):
    x = array.array("d", [0.0, 0.0, 0.0])
    u = array.array("d", [0.0] * 9)
    y = array.array("d", [0.0] * 8)
    with pytest.raises(ValueError):
        step.accumulate(x, u, 1.0, y)
    u.pop()
    with pytest.raises(ValueError):
        step.accumulate(x, u, float("nan"), y)
    _held_exports_free(x, u, y)
    step.accumulate(x, u, 1.0, y)  # 4 steps of nu=2, ny=2: valid now
    _held_exports_free(x, u, y)


def test_accumulate_eval_error_leaves_last_good_state(stub):
    walk = _cbind.Function(stub, "walk")
    assert repr(walk) == "<Function walk(x[2], u[1], lim[1]) -> (x_next[2], y[1])>"
    x = np.array([0.0, 10.0])
    y = np.full(6, -1.0)
    # x0 goes 0, 1, 2, 3, 4: the step with x[0] = 4 > 3.5 fails (step 4 of 6).
    with pytest.raises(_cbind.EvalError, match=r"^walk: CasADi function returned error code 5 "
                       r"at step 4 of 6"):
        walk.accumulate(x, np.ones(6), 3.5, y)
    np.testing.assert_array_equal(x, [4.0, 14.0])
    np.testing.assert_array_equal(y, [0.0, 1.0, 2.0, 3.0, -1.0, -1.0])


def test_accumulate_from_threads_shares_one_function_safely(step):
    # The GIL is released during the rollout; concurrent users of the same Function get
    # their own work area, so every rollout still matches the single-threaded result.
    rng = np.random.default_rng(4)
    n = 20000
    u_seq = rng.standard_normal(2 * n) * 0.01
    x0 = np.array([0.1, 0.2, 0.3])
    x_ref = x0.copy()
    y_ref = np.empty(2 * n)
    step.accumulate(x_ref, u_seq, 0.9, y_ref)

    results = [None] * 4
    errors = []

    def worker(i):
        try:
            for _ in range(5):
                x = x0.copy()
                y = np.empty(2 * n)
                step.accumulate(x, u_seq, 0.9, y)
                assert np.array_equal(x, x_ref) and np.array_equal(y, y_ref)
            results[i] = True
        except BaseException as exc:  # pragma: no cover - reported below
            errors.append(exc)

    threads = [threading.Thread(target=worker, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    single = np.empty(3)
    for _ in range(2000):  # plain calls on the main thread meanwhile
        step(x0, u_seq[:2], 0.9, single, None)
    for t in threads:
        t.join()
    assert errors == []
    assert results == [True] * 4
    expected = np.empty(3)
    step(x0, u_seq[:2], 0.9, expected, None)
    np.testing.assert_array_equal(single, expected)


# --------------------------------------------------------------------------------------
# accumulate_batch: K rollouts of one input sequence in one call
# --------------------------------------------------------------------------------------


def test_accumulate_batch_equals_accumulate_per_row_bit_for_bit(step):
    rng = np.random.default_rng(11)
    n, K = 7, 5
    u_seq = rng.standard_normal((n, 2))
    X0 = rng.standard_normal((K, 3))
    P = rng.uniform(0.1, 0.9, (K, 1))
    X, Y = X0.copy(), np.empty((K, n, 2))
    assert step.accumulate_batch(X, u_seq, P, Y) is None
    for r in range(K):
        x, y = X0[r].copy(), np.empty((n, 2))
        step.accumulate(x, u_seq, P[r], y)
        np.testing.assert_array_equal(X[r], x)
        np.testing.assert_array_equal(Y[r], y)
    X2 = X0.copy()
    step.accumulate_batch(X2, u_seq, P, None)          # outputs not computed
    np.testing.assert_array_equal(X2, X)


def test_accumulate_batch_argument_errors(toy, step):
    u = np.zeros((4, 2))
    with pytest.raises(TypeError, match=r"toy\.accumulate_batch requires a function"):
        toy.accumulate_batch(np.zeros(3), u, np.zeros(1), None)
    with pytest.raises(TypeError, match=r"takes 4 positional arguments"):
        step.accumulate_batch(np.zeros(3), u, np.zeros(1))
    with pytest.raises(ValueError, match=r"argument 'P' .*must have K \* 1 float64 elements "
                       r"with K >= 1, got 0"):
        step.accumulate_batch(np.zeros(0), u, np.zeros(0), None)
    with pytest.raises(ValueError, match=r"argument 'X' .*must have 6 float64"):
        step.accumulate_batch(np.zeros(3), u, np.zeros(2), None)
    with pytest.raises(ValueError, match=r"argument 'Y_seq' .*must have 16 float64"):
        step.accumulate_batch(np.zeros(6), u, np.zeros(2), np.zeros(15))
    with pytest.raises(ValueError, match=r"argument 'P' .*non-finite value at index 1"):
        step.accumulate_batch(np.zeros(6), u, np.array([0.0, np.nan]), None)
    buf = np.zeros(16)
    with pytest.raises(ValueError, match=r"must not share memory"):
        step.accumulate_batch(buf[:6], u, np.zeros(2), buf)


# --------------------------------------------------------------------------------------
# map: K points in one call
# --------------------------------------------------------------------------------------

def test_map_equals_one_call_per_point_with_broadcast_inputs_and_none_outputs():
    import pm2dof
    m = pm2dof.load_model()
    f = m.function("Ce")                                     # (q, xed, theta) -> (Ce, sing)
    rng = np.random.default_rng(5)
    K = 37
    Q = np.array([m.ik([0.245, 0.265] + rng.uniform(-0.02, 0.02, 2)) for _ in range(K)])
    V = rng.normal(0, 0.3, (K, 2))
    out, sing = np.empty((K, 4)), np.empty((K, 2))
    f.map(K, Q, V, m.theta_nominal, out, sing)               # theta: one value for all points
    for k in range(K):
        o, s = np.empty(4), np.empty(2)
        f(Q[k], V[k], m.theta_nominal, o, s)
        assert np.array_equal(out[k], o) and np.array_equal(sing[k], s), k
    out2 = np.empty((K, 4))
    f.map(K, Q, V, m.theta_nominal, out2, None)              # an output may be skipped
    assert np.array_equal(out, out2)
    one = np.empty((1, 4))
    f.map(1, Q[0], V[0], m.theta_nominal, one, None)         # K = 1: every input is per point
    assert np.array_equal(one[0], out[0])


def test_map_refuses_bad_arguments_by_name():
    import pm2dof
    m = pm2dof.load_model()
    f = m.function("Me")
    q = np.tile(m.ik([0.245, 0.265]), (4, 1))
    out = np.empty((4, 4))
    with pytest.raises(ValueError, match=r"map: input 'q' \(#0\) must have 6 float64 elements "
                                         r"\(one value for all points\) or K \* 6 = 24"):
        f.map(4, q[:3], m.theta_nominal, out, None)
    with pytest.raises(ValueError, match=r"map: K must be >= 1"):
        f.map(0, q, m.theta_nominal, out, None)
    bad = q.copy()
    bad[2, 1] = np.nan
    with pytest.raises(ValueError, match=r"map: input 'q' \(#0\) has a non-finite value at "
                                         r"index 13"):
        f.map(4, bad, m.theta_nominal, out, None)
    with pytest.raises(ValueError, match=r"map: output 'Me' \(#0\) must have 16"):
        f.map(4, q, m.theta_nominal, np.empty((3, 4)), None)
    with pytest.raises(TypeError, match=r"takes 5 arguments \(K, 2 inputs, 2 outputs\), got 4"):
        f.map(4, q, m.theta_nominal, out)
    shared = q.ravel().copy()       # finite (np.empty's garbage could hold a NaN, refused first)
    with pytest.raises(ValueError, match="shares memory with input 'q'"):
        f.map(4, shared, m.theta_nominal, shared[:16], None)


@pytest.mark.parametrize("K", [1, 2, 3, 5])
def test_map_names_every_non_finite_input_element_of_a_long_input(K):
    """map's inputs (6 K elements: long ones are tested whole first, then searched) name the
    first NaN, +inf or -inf wherever it is, the last elements and a lone one included."""
    import pm2dof
    m = pm2dof.load_model()
    f = m.function("Me")
    q = np.tile(m.ik([0.245, 0.265]), (K, 1))
    out = np.empty((K, 4))
    f.map(K, q, m.theta_nominal, out, None)
    for i in range(q.size):
        for v, word in ((np.nan, "nan"), (np.inf, "inf"), (-np.inf, "-inf")):
            bad = q.copy()
            bad.flat[i] = v
            if i + 3 < q.size:          # a later one too: the first is named
                bad.flat[i + 3] = np.nan
            with pytest.raises(ValueError, match=rf"map: input 'q' \(#0\) has a non-finite "
                                                 rf"value at index {i} \({word}\)"):
                f.map(K, bad, m.theta_nominal, out, None)


def test_map_names_the_point_of_a_non_finite_output():
    import pm2dof
    m = pm2dof.load_model()
    f = m.function("Me")
    q = np.tile(m.ik([0.245, 0.265]), (3, 1))
    theta = np.tile(m.theta_nominal, (3, 1))
    theta[1, :3] = 1e308                                      # alpha overflows Me at point 1
    assert f.check_outputs
    with pytest.raises(_cbind.NonFiniteOutputError, match=r"Me\.map: output 'Me' \(#0\) is not "
                                                          r"finite at point 1"):
        f.map(3, q, theta, np.empty((3, 4)), np.empty((3, 2)))
