# pm2dof export (issue 27): the exported C project builds, passes its ctest, links beside another
# model's library, and bad requests are refused with one clear line.
"""One CMake build for the module, at -O0 for the compile time: a super-project holding two
exports, shang2010 and fivebar, with warnings as errors on the hand-written files. Its ctest
compares each C closed loop with pm2dof.simulate (RMSE to 1e-12 relative in double, torques
bit for bit, NaN encoder angles); then it is installed and a third project finds both
libraries with find_package and links them into one program (no symbol clashes). The
bad-input tests need no compiler.
"""
import json
import re
import shutil
import subprocess

import numpy as np
import pytest

import pm2dof
from pm2dof.cli import main
from pm2dof.core.errors import ArgumentError, OutputError, StaleGeneratedCodeError
from pm2dof.export import ExportError, export_project
from pm2dof.export.single import to_single

needs_cmake = pytest.mark.skipif(shutil.which("cmake") is None or shutil.which("cc") is None,
                                 reason="needs cmake and a C compiler")

SUPER = """cmake_minimum_required(VERSION 3.13)
project(two_models C)
include(CTest)
add_subdirectory(shang2010)
add_subdirectory(fivebar)
"""
CONSUMER_CMAKE = """cmake_minimum_required(VERSION 3.13)
project(consumer C)
find_package(shang2010_pm2dof REQUIRED)
find_package(fivebar_pm2dof REQUIRED)
add_executable(two_robots main.c)
target_link_libraries(two_robots PRIVATE pm2dof::shang2010_pm2dof pm2dof::fivebar_pm2dof)
"""
CONSUMER_MAIN = r"""#include <stdio.h>
#include "shang2010_pm2dof.h"
#include "fivebar_pm2dof.h"
int main(void)
{
    static shang2010_pm2dof_na a;     /* two robots, two models, one program */
    static fivebar_pm2dof_na b;
    shang2010_pm2dof_work wa;
    fivebar_pm2dof_work wb;
    shang2010_pm2dof_real xa[2] = {0.25, 0.26}, qa[SHANG2010_PM2DOF_N_Q], ya[2];
    fivebar_pm2dof_real xb[2] = {%s, %s}, qb[FIVEBAR_PM2DOF_N_Q], yb[2];
    int s = shang2010_pm2dof_na_init(&a, NULL) + fivebar_pm2dof_na_init(&b, NULL);
    s += shang2010_pm2dof_ik(xa, qa, &wa) + shang2010_pm2dof_fk(qa, ya, NULL, &wa);
    s += fivebar_pm2dof_ik(xb, qb, &wb) + fivebar_pm2dof_fk(qb, yb, NULL, &wb);
    printf("%%d %%.17g %%.17g %%.17g %%.17g\n", s, ya[0], ya[1], yb[0], yb[1]);
    return s;
}
"""


def _run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=600, **kw)
    assert r.returncode == 0, f"{' '.join(map(str, cmd))}\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}"
    return r


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    root = tmp_path_factory.mktemp("export")
    export_project("shang2010", root / "shang2010", measure_stack=False)
    export_project("fivebar", root / "fivebar", controllers=("na", "apd"), measure_stack=False)
    (root / "CMakeLists.txt").write_text(SUPER)
    build = root / "build"
    # -O0: a quarter of the compile time of -O2, and the same IEEE results (no FMA on
    # x86-64's baseline, -ffp-contract=off elsewhere); make embedded builds with -O2
    _run(["cmake", "-S", root, "-B", build, "-DCMAKE_BUILD_TYPE=Debug",
          "-DCMAKE_C_FLAGS_DEBUG=-O0", "-DSHANG2010_PM2DOF_WERROR=ON",
          "-DFIVEBAR_PM2DOF_WERROR=ON"])
    _run(["cmake", "--build", build, "-j", "2"])
    return root, build


@needs_cmake
def test_ctest_of_both_exports_passes(built):
    root, build = built
    r = _run(["ctest", "--test-dir", build, "--output-on-failure"])
    assert "100% tests passed out of 4" in r.stdout, r.stdout


@needs_cmake
def test_c_closed_loop_gives_the_rmse_of_simulate(built):
    """Independently of the C's own check: the RMSE the C prints (17 digits) against
    pm2dof.simulate computed here, and the torques bit for bit."""
    root, build = built
    out = _run([build / "shang2010" / "shang2010_test"]).stdout
    m = pm2dof.load_model()
    for law, cls in (("na", pm2dof.NAController), ("apd", pm2dof.APDController)):
        got = float(re.search(rf"^{law} +RMSE ([0-9.e+-]+) m", out, re.M)[1])
        want = pm2dof.simulate(m, cls(m), pm2dof.paper_move("high")).rmse
        assert got == pytest.approx(want, rel=1e-12, abs=0), (law, got, want)
        assert re.search(rf"^{law} +RMSE .* largest torque difference 0 N m", out, re.M), out
    assert "FAIL" not in out and re.search(r"(\d+) of \1 checks passed", out), out


@needs_cmake
def test_c_step_given_a_nan_encoder_angle_is_refused_as_in_python(built):
    """The C: status NON_FINITE, zero torque, state unchanged (checked inside the ctest, which
    passes); Python: the step refuses the NaN (ArgumentError) and keeps its state."""
    root, build = built
    out = _run([build / "shang2010" / "shang2010_test"]).stdout
    assert "FAIL" not in out
    header = (root / "shang2010" / "include" / "shang2010_pm2dof.h").read_text()
    assert f"SHANG2010_PM2DOF_NON_FINITE = {int(pm2dof.Status.NON_FINITE)}," in header
    m = pm2dof.load_model()
    c = pm2dof.NAController(m)
    q = m.ik([0.245, 0.265])
    c.reset(q[:3])
    before = c.state
    with pytest.raises(ArgumentError):
        c.step(np.array([np.nan, q[1], q[2]]), np.array([0.245, 0.265]), np.zeros(2),
               np.zeros(2))
    assert all(np.array_equal(before[k], v) for k, v in c.state.items())


@needs_cmake
def test_two_models_installed_and_found_link_into_one_program(built, tmp_path):
    root, build = built
    prefix = tmp_path / "prefix"
    _run(["cmake", "--install", build, "--prefix", prefix])
    fb = pm2dof.load_model("fivebar")
    xb = [float(v) for v in fb.spec.trajectories["high"]["start"]]
    (tmp_path / "consumer").mkdir()
    (tmp_path / "consumer" / "CMakeLists.txt").write_text(CONSUMER_CMAKE)
    (tmp_path / "consumer" / "main.c").write_text(CONSUMER_MAIN % (repr(xb[0]), repr(xb[1])))
    _run(["cmake", "-S", tmp_path / "consumer", "-B", tmp_path / "cb",
          f"-DCMAKE_PREFIX_PATH={prefix}", "-DCMAKE_C_FLAGS=-Wall -Wextra -Werror"])
    _run(["cmake", "--build", tmp_path / "cb"])
    s, *v = _run([tmp_path / "cb" / "two_robots"]).stdout.split()
    assert s == "0"
    np.testing.assert_allclose([float(x) for x in v], [0.25, 0.26, *xb], rtol=0, atol=1e-12)


def test_exporting_a_stale_model_names_pm2dof_derive(tmp_path):
    src = pm2dof.load_model()
    text = (pm2dof.core.paths.SHIPPED_MODELS / "shang2010.toml").read_text()
    shutil.copytree(src.generated, tmp_path / "generated" / "shang2010")
    (tmp_path / "shang2010.toml").write_text(text.replace("la = 0.244", "la = 0.245", 1))
    with pytest.raises(StaleGeneratedCodeError, match="pm2dof derive"):
        export_project(tmp_path / "shang2010.toml", tmp_path / "out")
    (tmp_path / "other.toml").write_text(text.replace('name = "shang2010"', 'name = "other"'))
    with pytest.raises(StaleGeneratedCodeError, match="pm2dof derive"):     # never derived
        export_project(tmp_path / "other.toml", tmp_path / "out")
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("args, what", [(["--precision", "quad"], "unknown precision 'quad'"),
                                        (["--controllers", "na,pid"], "unknown controller 'pid'")])
def test_unknown_controller_or_precision_is_one_line(tmp_path, capsys, args, what):
    assert main(["export", "--out", str(tmp_path / "p"), *args]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and what in err and err.startswith("pm2dof: error: "), err
    assert not (tmp_path / "p").exists()


def test_a_non_empty_out_is_refused_unless_force(tmp_path, capsys):
    out = tmp_path / "p"
    out.mkdir()
    (out / "mine.c").write_text("/* the user's */")
    assert main(["export", "--out", str(out), "--controllers", "na"]) == 2
    err = capsys.readouterr().err
    assert "exists and is not empty" in err and "--force" in err and err.count("\n") == 1, err
    assert sorted(p.name for p in out.iterdir()) == ["mine.c"]
    assert main(["export", "--out", str(out), "--controllers", "na", "--force", "--no-stack"]) == 0
    record = json.loads((out / "pm2dof_export.json").read_text())
    assert record["controllers"] == ["na"] and (out / "mine.c").is_file()
    with pytest.raises(OutputError):
        export_project("shang2010", out / "mine.c")      # a file, not a folder


def test_single_precision_is_refused_where_float_is_not_enough(tmp_path):
    """The min-max split decides with tolerances of 1e-10: refused in single, with the reason."""
    src = pm2dof.load_model()
    text = (pm2dof.core.paths.SHIPPED_MODELS / "shang2010.toml").read_text()
    assert "[control]" not in text or 'split = "min_norm"' in text
    shutil.copytree(src.generated, tmp_path / "generated" / "shang2010")
    (tmp_path / "shang2010.toml").write_text(
        text + '\n[control]\nsplit = "min_max"\n' if "[control]" not in text
        else text.replace('split = "min_norm"', 'split = "min_max"'))
    with pytest.raises(ExportError, match="min_max.*1e-10.*float"):
        export_project(tmp_path / "shang2010.toml", tmp_path / "out", precision="single")
    assert not (tmp_path / "out").exists()


def test_single_precision_rewrite_keeps_names_and_marks_every_literal():
    src = ("/* CasADi 3.8.2 */\n#define casadi_real double\ncasadi_real casadi_sq(casadi_real x)"
           " { return x*x;}\n  a1=casadi_fabs(a0); a2=sin(a1); a3=(a2*2.4399999999999999e-01);"
           " a4=sqrt(1.); a5=atan2(a4,3e-5);\n")
    out = to_single(src)
    assert "#define casadi_real float" in out and "CasADi 3.8.2" in out
    assert "casadi_fabs(a0)" in out and "sinf(a1)" in out and "sqrtf(1.f)" in out
    assert "2.4399999999999999e-01f" in out and "atan2f(a4,3e-5f)" in out
    assert not re.search(r"(?<![\w.])(sin|sqrt|atan2)\(", out)
