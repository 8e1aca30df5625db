# core/csplit.py + build.py: a CasADi file cut into translation units compiled in parallel.
"""A CasADi-generated C file is compiled as several translation units (pm2dof.core.csplit) on
every processor, then linked. The library must be the one compiling the file whole gives: the
same exported entry points (and no other symbol), the same results bit for bit. Here on a small
file CasADi writes (functions calling one helper from other units, one with a loop, so at
another optimisation level); the shipped models' libraries are checked by the whole suite
(every pinned number) and, whole against cut, by tests/core/test_csplit_shipped.py (slow)."""
import ctypes
import platform
import shutil
import subprocess

import numpy as np
import pytest

from pm2dof.core import build, csplit

ca = pytest.importorskip("casadi")


def _toy_c(tmp_path, name="toy"):
    """A CasADi file like a model's: ``toy_na_step`` (hot) and ``toy_fk`` (cold) both call
    ``toy_helper`` (an embedded call: its own ``casadi_fN``), each through CodeGenerator;
    ``toy_plant_step`` (hot) calls it four times in a loop (a fold, as the plant's substeps)."""
    x = ca.SX.sym("x", 3)
    helper = ca.Function(f"{name}_helper", [x], [ca.sin(x) * ca.sqrt(1 + x ** 2) / 3])
    xm = ca.MX.sym("x", 3)
    ym = ca.MX.sym("y", 2)
    hot = ca.Function(f"{name}_na_step", [xm, ym],
                      [helper(xm)[:2] * ym + ca.cos(helper(2 * xm)[1:]), ca.sum1(helper(xm))])
    cold = ca.Function(f"{name}_fk", [xm], [helper(xm - 1) * xm[0] + ca.fabs(xm)])
    plant = ca.Function(f"{name}_plant_step", [xm], [helper.fold(4)(xm)])
    cg = ca.CodeGenerator(f"{name}.c", {"with_header": True, "verbose": False})
    for f in (hot, cold, plant):
        cg.add(f)
    cg.generate(str(tmp_path) + "/")
    return tmp_path / f"{name}.c", {"na_step": hot, "fk": cold, "plant_step": plant}


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
    names = [b.name for b in s.blocks]
    assert names == ["toy_helper", "toy_na_step", "toy_fk", "fold_toy_helper", "toy_plant_step"]
    fn = {b.name: b.fn for b in s.blocks}
    helper = fn["toy_helper"]
    assert s.blocks[1].calls == s.blocks[2].calls == s.blocks[3].calls == {helper}
    assert s.blocks[4].calls == {fn["fold_toy_helper"]}
    called = {helper, fn["fold_toy_helper"]}
    for b in s.blocks:      # each block at its line of the file, "static" dropped if called
        first = text.splitlines()[b.line - 1]
        assert b.text.startswith(first)
        assert (f"static int {b.fn}(" in b.text) == (b.fn not in called)
    assert f"int {helper}(" in s.head and f"int {fn['toy_na_step']}(" not in s.head
    assert "static casadi_real casadi_sq(" in s.head and "static void casadi_copy(" in s.head
    assert "toy_casadi_version" in s.config and "toy_casadi_version" not in s.head
    # a block with a loop (its own, or a helper's that loops) at LOOP_OPT, the rest at
    # STRAIGHT_OPT
    loops = {b.fn for b in s.blocks if csplit.has_loop(s, b)}
    assert fn["fold_toy_helper"] in loops and helper not in loops     # a copy loop; pure SX
    assert "for (" not in s.blocks[3].text and "casadi_copy(" in s.blocks[3].text
    levels = csplit.opt_levels(s)
    assert levels == {b.fn: csplit.LOOP_OPT if b.fn in loops else csplit.STRAIGHT_OPT
                      for b in s.blocks}
    # every block in exactly one unit, each unit at its blocks' level, costliest first
    plan = csplit.plan_units(s, levels, unit_bytes=1)
    assert sorted(b.fn for _, blocks, _ in plan for b in blocks) == sorted(b.fn for b in s.blocks)
    assert all(levels[b.fn] == opt for opt, blocks, _ in plan for b in blocks)
    costs = [cost for _, _, cost in plan]
    assert costs == sorted(costs, reverse=True)
    for opt, blocks, cost in plan:
        assert cost == csplit.OPT_COST[opt] * (len(s.head) + sum(len(b.text) for b in blocks))
    # one unit per level when the units may be large
    assert sorted(opt for opt, _, _ in csplit.plan_units(s, levels)) == sorted(set(levels.values()))


def test_other_c_is_not_cut():
    assert csplit.split_casadi_c("double twice(double x) { return 2 * x; }\n") is None


def test_the_cut_library_equals_the_whole_one_bit_for_bit(tmp_path):
    """Compiled in units (one per level: the blocks with a loop at -O3, the helper and the
    others at -O2: blocks call the helper in another unit) and compiled whole as before: the
    same exported symbols but CasADi's internal helpers (casadi_sq, ...: now each unit's own),
    the same bits."""
    c, funcs = _toy_c(tmp_path)
    whole = tmp_path / "libwhole.so"
    subprocess.run([*build._compiler(), *build.FLAGS, "-o", str(whole), str(c), "-lm"],
                   check=True)
    seen = []
    cut = build.compile_library(c, tmp_path / "libtoy.so", progress=seen.append, jobs=2)
    assert " units (" in seen[0] and seen[1].startswith(f"compiled {cut} in ")
    record = __import__("json").loads(build.stamp_path(cut).read_text())
    assert record["flags"][0] == "-O3"
    levels = csplit.opt_levels(csplit.split_casadi_c(c.read_text()))
    assert record["unit_levels"] == {" ".join(opt): 1 for opt in set(levels.values())}
    assert record["units"] == 2 == len(set(levels.values()))
    exported = _exported(cut)
    assert {"toy_na_step", "toy_fk", "toy_plant_step", "toy_na_step_work",
            "toy_casadi_version"} <= exported
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
        for short, ins in (("na_step", [x, y]), ("fk", [x]), ("plant_step", [x])):
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


def test_inline_fmax_and_fmin_give_libms_bits_on_every_special_value(tmp_path):
    """CasADi's fmax and fmin call libm; in a cut library on x86-64 with glibc they are inline
    (csplit.MINMAX_PRELUDE): the bits of libm's fmax(x, y), fmin(x, y) (called through ctypes,
    in the C's order) on every pair of zeros of both signs, infinities, NaNs of both signs,
    subnormals and the largest double, in both orders. The whole file's library may call libm
    with the operands swapped (gcc 12 does: it takes fmax and fmin as commutative, which C
    allows, the sign of a zero they return being unspecified): each result is libm's bits in
    one order or the other, which differ on a tie of zeros of opposite signs and on two NaNs."""
    import ctypes.util
    x = ca.SX.sym("x", 2)
    f = ca.Function("mm_step", [x], [ca.vertcat(ca.fmax(x[0], x[1]), ca.fmin(x[0], x[1]))])
    cg = ca.CodeGenerator("mm.c", {"with_header": True, "verbose": False})
    cg.add(f)
    cg.generate(str(tmp_path) + "/")
    c = tmp_path / "mm.c"
    assert "casadi_fmax(a0,a1)" in c.read_text() and "casadi_fmin(a0,a1)" in c.read_text()
    whole = tmp_path / "libwhole.so"
    subprocess.run([*build._compiler(), *build.FLAGS, "-o", str(whole), str(c), "-lm"],
                   check=True)
    cut = build.compile_library(c, tmp_path / "libmm.so", progress=None, jobs=1)

    def imports(lib):
        return subprocess.run(["nm", "-D", "--undefined-only", str(lib)], capture_output=True,
                              text=True, check=True).stdout.split()
    def calls_libm(lib):
        return {s.split("@")[0] for s in imports(lib)} >= {"fmax", "fmin"}
    inline = build._X86 and platform.libc_ver()[0] == "glibc"
    assert calls_libm(whole) and calls_libm(cut) != inline
    libm = ctypes.CDLL(ctypes.util.find_library("m"))
    for fn in (libm.fmax, libm.fmin):
        fn.restype, fn.argtypes = ctypes.c_double, (ctypes.c_double, ctypes.c_double)
    la, lb = ctypes.CDLL(str(whole)), ctypes.CDLL(str(cut))
    special = [0.0, -0.0, 1.0, -1.0, np.inf, -np.inf, np.nan, -np.nan, 5e-324, -5e-324,
               np.finfo(float).max, 2.5]
    swapped = 0
    for a in special:
        for b in special:
            ins = [np.array([a, b])]
            want = np.array([libm.fmax(a, b), libm.fmin(a, b)]).view(np.int64)
            other = np.array([libm.fmax(b, a), libm.fmin(b, a)]).view(np.int64)
            wa = _call(la, "mm_step", ins, [2])[0].view(np.int64)
            wb = _call(lb, "mm_step", ins, [2])[0].view(np.int64)
            assert np.array_equal(wb, want), (a, b, wb, want)
            assert np.all((wa == want) | (wa == other)), (a, b, wa)   # each, one order
            swapped += int(np.sum(want != other))
    if inline:                   # glibc: fmax, fmin differ with the order on 0 and -0, nan
        assert swapped == 2 * 2 * 2      # and -nan, each in both orders
