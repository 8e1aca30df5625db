# core/csplit.py + build.py: a CasADi file cut into translation units compiled in parallel.
"""A CasADi-generated C file is compiled as several translation units (pm2dof.core.csplit) on
every processor, then linked. The library must be the one compiling the file whole gives: the
same exported entry points (and no other symbol), the same results bit for bit. Here on a small
file CasADi writes (a hot function calling another, a function off the hot paths calling the
same one from another unit); the shipped models' libraries are checked by the whole suite (every
pinned number) and, whole against cut, by tests/core/test_csplit_shipped.py (slow)."""
import ctypes
import shutil
import subprocess

import numpy as np
import pytest

from pm2dof.core import build, csplit

ca = pytest.importorskip("casadi")


def _toy_c(tmp_path, name="toy"):
    """A CasADi file like a model's: ``toy_na_step`` (hot) and ``toy_fk`` (cold) both call
    ``toy_helper`` (an embedded call: its own ``casadi_fN``), each through CodeGenerator."""
    x = ca.SX.sym("x", 3)
    helper = ca.Function(f"{name}_helper", [x], [ca.sin(x) * ca.sqrt(1 + x ** 2) / 3])
    xm = ca.MX.sym("x", 3)
    ym = ca.MX.sym("y", 2)
    hot = ca.Function(f"{name}_na_step", [xm, ym],
                      [helper(xm)[:2] * ym + ca.cos(helper(2 * xm)[1:]), ca.sum1(helper(xm))])
    cold = ca.Function(f"{name}_fk", [xm], [helper(xm - 1) * xm[0] + ca.fabs(xm)])
    cg = ca.CodeGenerator(f"{name}.c", {"with_header": True, "verbose": False})
    for f in (hot, cold):
        cg.add(f)
    cg.generate(str(tmp_path) + "/")
    return tmp_path / f"{name}.c", {"na_step": hot, "fk": cold}


def _call(lib, fname, ins, n_out):
    """Call a CasADi entry point of ``lib`` through ctypes: outputs as NumPy arrays."""
    f = getattr(lib, fname)
    dbl = ctypes.POINTER(ctypes.c_double)
    ins = [np.ascontiguousarray(a, dtype=float) for a in ins]
    outs = [np.zeros(k) for k in n_out]
    arg = (dbl * 8)(*[a.ctypes.data_as(dbl) for a in ins])
    res = (dbl * 8)(*[o.ctypes.data_as(dbl) for o in outs])
    iw = (ctypes.c_longlong * 64)()
    w = (ctypes.c_double * 256)()
    assert f(arg, res, iw, w, 0) == 0
    return outs


def _exported(path):
    if shutil.which("nm") is None:
        pytest.skip("nm (binutils) is not installed")
    out = subprocess.run(["nm", "-D", "--defined-only", str(path)], capture_output=True,
                         text=True, check=True).stdout
    return {line.split()[-1] for line in out.splitlines() if line.strip()}


def test_a_casadi_file_is_cut_into_blocks_that_cover_it(tmp_path):
    c, _ = _toy_c(tmp_path)
    text = c.read_text()
    s = csplit.split_casadi_c(text, str(c))
    assert s is not None
    assert [b.name for b in s.blocks] == ["toy_helper", "toy_na_step", "toy_fk"]
    helper = s.blocks[0].fn
    assert s.blocks[1].calls == s.blocks[2].calls == {helper}
    for b in s.blocks:      # each block at its line of the file, "static" dropped if called
        first = text.splitlines()[b.line - 1]
        assert b.text.startswith(first)
        assert (f"static int {b.fn}(" in b.text) == (b.fn != helper)
    assert f"int {helper}(" in s.head and f"int {s.blocks[1].fn}(" not in s.head
    assert csplit.hot_blocks(s, "toy_") == {s.blocks[0].fn, s.blocks[1].fn}
    assert "toy_casadi_version" in s.config and "toy_casadi_version" not in s.head
    # every block in exactly one unit; hot and cold apart
    plan = csplit.plan_units(s, csplit.hot_blocks(s, "toy_"), unit_bytes=1, min_units=2)
    assert sorted(b.fn for _, blocks in plan for b in blocks) == sorted(b.fn for b in s.blocks)
    assert [(hot, [b.name for b in blocks]) for hot, blocks in plan] == [
        (True, ["toy_na_step"]), (True, ["toy_helper"]), (False, ["toy_fk"])]


def test_other_c_is_not_cut():
    assert csplit.split_casadi_c("double twice(double x) { return 2 * x; }\n") is None


def test_the_cut_library_equals_the_whole_one_bit_for_bit(tmp_path):
    """Compiled in 3 units (na_step, the helper, fk at -O1: each calls the helper in another
    unit) and compiled whole as before: the same exported symbols but CasADi's internal helpers
    (casadi_sq, ...: now each unit's own), the same bits."""
    c, funcs = _toy_c(tmp_path)
    whole = tmp_path / "libwhole.so"
    subprocess.run([*build._compiler(), *build.FLAGS, "-o", str(whole), str(c), "-lm"],
                   check=True)
    seen = []
    cut = build.compile_library(c, tmp_path / "libtoy.so", progress=seen.append, jobs=2)
    assert " units (" in seen[0] and seen[1].startswith(f"compiled {cut} in ")
    record = __import__("json").loads(build.stamp_path(cut).read_text())
    assert record["units"] == 3 and record["cold_units"] == 1 and record["flags"][0] == "-O3"
    assert record["cold_flags"][0] == build.COLD_OPT
    exported = _exported(cut)
    assert {"toy_na_step", "toy_fk", "toy_na_step_work", "toy_casadi_version"} <= exported
    assert "toy_helper" not in exported          # embedded only, as in the whole library
    assert not any(s.startswith("toy_f") and s[5:].isdigit() for s in exported)   # casadi_fN
    assert exported == {s for s in _exported(whole) if s not in
                        {"toy_sq", "toy_fabs", "toy_fmax", "toy_fmin", "toy_sign", "toy_copy",
                         "toy_clear", "toy_fill", "toy_densify", "toy_trans", "toy_project",
                         "toy_mtimes_dense", "toy_mtimes_dense_sparse"}}
    la, lb = ctypes.CDLL(str(whole)), ctypes.CDLL(str(cut))
    rng = np.random.default_rng(1)
    for _ in range(50):
        x, y = rng.normal(size=3) * 3, rng.normal(size=2)
        for short, ins in (("na_step", [x, y]), ("fk", [x])):
            f = funcs[short]
            n_out = [f.size_out(i)[0] * f.size_out(i)[1] for i in range(f.n_out())]
            a = _call(la, f"toy_{short}", ins, n_out)
            b = _call(lb, f"toy_{short}", ins, n_out)
            ref = f(*ins)
            ref = [np.ravel(np.array(r if isinstance(r, ca.DM) else ref, dtype=float))
                   for r in (ref if isinstance(ref, (list, tuple)) else [ref])]
            for oa, ob, r in zip(a, b, ref):
                assert np.array_equal(oa.view(np.int64), ob.view(np.int64))
                assert np.allclose(oa, r, rtol=1e-14, atol=1e-15)


def test_a_compiler_error_in_a_unit_names_the_original_file_and_line(tmp_path):
    c, _ = _toy_c(tmp_path)
    lines = c.read_text().splitlines(keepends=True)
    at = next(i for i, ln in enumerate(lines) if "_fk(const casadi_real** arg" in ln)
    lines.insert(at, "int broken = undeclared_thing;\n")
    c.write_text("".join(lines))
    with pytest.raises(build.BuildError) as info:
        build.compile_library(c, tmp_path / "libtoy.so", jobs=2)
    msg = str(info.value)
    assert "undeclared_thing" in msg and f"{c}:{at + 1}:" in msg, msg
    assert sorted(p.name for p in tmp_path.iterdir()) == ["toy.c", "toy.h"]   # nothing left


def test_several_libraries_share_one_pool(tmp_path):
    pairs = []
    for name in ("one", "two"):
        d = tmp_path / name
        d.mkdir()
        c, _ = _toy_c(d, name)
        pairs.append((c, d / f"lib{name}.so"))
    libs = build.compile_libraries(pairs, jobs=3)
    assert libs == [p[1] for p in pairs]
    for lib, (c, _) in zip(libs, pairs):
        assert build.library_is_fresh(c, lib) and f"{c.stem}_na_step" in _exported(lib)
    assert build.compile_libraries([]) == []


def test_build_jobs_reads_the_environment(monkeypatch):
    monkeypatch.setenv(build.JOBS_ENV, "3")
    assert build.build_jobs() == 3
    monkeypatch.setenv(build.JOBS_ENV, "zero")
    assert build.build_jobs() >= 1
