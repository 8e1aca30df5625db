# pm2dof export: the exported C project builds, passes its ctest, links beside another
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
from tests.export.c_guards import check_guard_output, rule_driver

pytestmark = pytest.mark.slow     # builds and runs exported C projects: make test-slow (CI)

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


@needs_cmake
@pytest.mark.parametrize("name", ["shang2010", "fivebar"])
def test_the_ctests_guards_are_pm2dofs(built, name):
    """What the ctest prints of its guards (tests/export/c_guards.py): NA's blocked robot (the
    paper's law, the projection, the freeze) equals NAController's steps bit for bit, init's
    refusals name pm2dof's rules, the status strings are pm2dof.Status's labels, the version
    and formulation are pm2dof's."""
    root, build = built
    out = _run([build / name / f"{name}_test"]).stdout
    assert "FAIL" not in out and re.search(r"(\d+) of \1 checks passed", out), out[-3000:]
    check_guard_output(out, name)


@needs_cmake
def test_init_applies_pm2dofs_rules_at_every_bound(built, tmp_path):
    """The exported init against pm2dof.control.rules: each parameter entry at, just inside and
    just outside its bounds, NaN and infinities; init's bad_param is the offset of the first
    entry pm2dof's rules refuse (-1 when they accept), for every law."""
    root, build = built
    src, want = rule_driver("shang2010", ("na", "apd", "ctc", "lqr"))
    (tmp_path / "driver.c").write_text(src)
    lib = next((build / "shang2010").glob("*shang2010_pm2dof.a"))
    _run(["cc", "-std=c99", "-Wall", "-Werror", "-I", root / "shang2010" / "include",
          tmp_path / "driver.c", lib, "-lm", "-o", tmp_path / "driver"])
    got = [int(v) for v in _run([tmp_path / "driver"]).stdout.split()]
    assert len(got) == len(want) > 500
    bad = [(i, g, w) for i, (g, w) in enumerate(zip(got, want)) if g != w]
    assert not bad, bad[:10]
    assert want.count(-1) > 50 and len(set(want)) > 20      # accepted and refused cases both


FAKE_STEP = r"""/* the generated NA step replaced: it writes the status it is told */
double fake_status;
int fake_na_step(const double **arg, double **res, long long *iw, double *w, int mem)
{
    int i;
    (void)iw; (void)w; (void)mem;
    for (i = 0; i < SHANG2010_PM2DOF_N_LEGS; i++)
        res[0][i] = 1.0;
    for (i = 0; i < SHANG2010_PM2DOF_STATE_SIZE; i++)
        res[1][i] = arg[0][i] + 1.0;
    *res[2] = fake_status;
    for (i = 0; i < SHANG2010_PM2DOF_DIAG_SIZE; i++)
        res[3][i] = 0.0;
    return 0;
}
"""
FAKE_DRIVER = r"""#include <math.h>
#include <stdio.h>
#include <string.h>
#include "shang2010_pm2dof.h"
extern double fake_status;
int main(void)
{
    static shang2010_pm2dof_na c;
    static const double values[] = {2.5, 6.0, -1.0, -2.0, NAN, INFINITY, 1e300, 2.0};
    shang2010_pm2dof_work w;
    double x[2] = {0.245, 0.265}, q[6], z[2] = {0, 0}, tau[3], before[SHANG2010_PM2DOF_STATE_SIZE];
    shang2010_pm2dof_na_params p;
    unsigned k;
    int s, project;
    shang2010_pm2dof_ik(x, q, &w);
    for (project = 0; project < 2; project++) {    /* the paper's law, the projected one */
        shang2010_pm2dof_na_default_params(&p);
        p.project = project;
        shang2010_pm2dof_na_init(&c, &p);
        shang2010_pm2dof_na_reset(&c, q, NULL);
        for (k = 0; k < sizeof values / sizeof values[0]; k++) {
            memcpy(before, shang2010_pm2dof_state(&c.core), sizeof before);
            fake_status = values[k];
            s = shang2010_pm2dof_na_step(&c, q, x, z, z, tau);
            printf("%d %g %d %g %d\n", project, values[k], s,
                   fabs(tau[0]) + fabs(tau[1]) + fabs(tau[2]),
                   memcmp(before, shang2010_pm2dof_state(&c.core), sizeof before) != 0);
        }
    }
    return 0;
}
"""


@needs_cmake
def test_a_status_that_is_no_code_gives_non_finite_and_keeps_the_state(built, tmp_path):
    """The generated step writes its status as a real. The API takes it only when it is exactly
    a code: 2.5, 6, -1, NaN, ... (the generated steps replaced by one that writes them) give
    NON_FINITE, zero torque and the state kept (a cast to int made 2.5 SATURATED with the
    step's torque); 2.0 gives SATURATED. The same with NA's projection on: the check is the
    step's, whichever generated step it calls."""
    root, build = built
    inc = ["-I", root / "shang2010" / "include", "-I", root / "shang2010" / "src"]
    # the API's source with its two calls of the generated NA steps (the paper's law, the
    # projected one) sent to the fake; the generated steps are static in its one translation
    # unit, so the calls are redirected in the text, not by a macro that would rename them too
    api = (root / "shang2010" / "src" / "shang2010_pm2dof.c").read_text()
    for gen in ("shang2010_na_step", "shang2010_na_proj_step"):
        call = f"{gen}(arg, res,"
        assert api.count(call) == 1, gen
        api = api.replace(call, "fake_na_step(arg, res,")
    api = api.replace('#include "shang2010_generated.inc"\n',
                      '#include "shang2010_generated.inc"\nint fake_na_step(const double **arg, '
                      'double **res, long long *iw, double *w, int mem);\n')
    (tmp_path / "api.c").write_text(api)
    (tmp_path / "fake.c").write_text('#include "shang2010_pm2dof.h"\n' + FAKE_STEP)
    (tmp_path / "driver.c").write_text(FAKE_DRIVER)
    for src, obj, extra in ((tmp_path / "api.c", "api.o", ["-Wno-unused-function"]),
                            (tmp_path / "fake.c", "fake.o", []),
                            (tmp_path / "driver.c", "driver.o", [])):
        _run(["cc", "-std=c99", "-Wall", "-Werror", "-c", *inc, *extra, src, "-o",
              tmp_path / obj])
    _run(["cc", *(tmp_path / o for o in ("driver.o", "api.o", "fake.o")), "-lm", "-o",
          tmp_path / "driver"])
    rows = [line.split() for line in _run([tmp_path / "driver"]).stdout.splitlines()]
    non_finite, saturated = int(pm2dof.Status.NON_FINITE), int(pm2dof.Status.SATURATED)
    values = ["2.5", "6", "-1", "-2", "nan", "inf", "1e+300", "2"]
    assert [r[:2] for r in rows] == [[p, v] for p in "01" for v in values]
    for project in (rows[:8], rows[8:]):
        for _, value, status, tau, changed in project[:-1]:
            assert (int(status), float(tau), changed) == (non_finite, 0.0, "0"), value
        assert (int(project[-1][2]), float(project[-1][3]), project[-1][4]) == (saturated, 3.0,
                                                                                "1")


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("cc") is None, reason="needs a C compiler")
@pytest.mark.parametrize("name", ["shang2010", "rrr4_platform"])
def test_the_library_refuses_to_compile_with_fast_math(tmp_path, name):
    """-ffast-math and -ffinite-math-only let the compiler drop the NaN and singularity
    guards: the API source stops with an #error that says so; without them it compiles."""
    out = export_project(name, tmp_path / name, controllers=("na",))
    api = out / "src" / f"{name}_pm2dof.c"
    cmd = ["cc", "-std=c99", "-c", "-I", out / "include", "-I", out / "src", api, "-o",
           tmp_path / "api.o"]
    _run(cmd)
    for flag in ("-ffast-math", "-ffinite-math-only"):
        r = subprocess.run(cmd + [flag], capture_output=True, text=True, timeout=600)
        assert r.returncode != 0, flag
        assert (f"{name}_pm2dof: compile this library without -ffast-math and "
                f"-ffinite-math-only: they remove its NaN and singularity guards") in r.stderr, (
            flag, r.stderr)


@pytest.mark.skipif(shutil.which("cc") is None or shutil.which("nm") is None,
                    reason="needs a C compiler and nm")
def test_the_api_holds_no_writable_data(tmp_path):
    """The API's object, position-independent (where a table of pointers would land in
    writable .data.rel.ro): code and read-only data only (nm: no d, D, b, B symbol)."""
    out = export_project("shang2010", tmp_path / "p", controllers=("na", "apd", "ctc", "lqr"))
    for opt in ("-O0", "-O2"):
        _run(["cc", "-std=c99", opt, "-fPIC", "-c", "-I", out / "include", "-I", out / "src",
              out / "src" / "shang2010_pm2dof.c", "-o", tmp_path / "api.o"])
        symbols = _run(["nm", tmp_path / "api.o"]).stdout.splitlines()
        assert symbols and not [s for s in symbols if s.split()[-2:-1] in (["d"], ["D"], ["b"],
                                                                         ["B"])], symbols


def test_the_export_record_names_the_model_file_not_the_machines_folders(tmp_path):
    src = pm2dof.load_model()
    shutil.copytree(src.generated, tmp_path / "robots" / "generated" / "shang2010")
    shutil.copy(pm2dof.core.paths.SHIPPED_MODELS / "shang2010.toml", tmp_path / "robots")
    out = export_project(tmp_path / "robots" / "shang2010.toml", tmp_path / "out",
                         controllers=("na",))
    text = (out / "pm2dof_export.json").read_text()
    record = json.loads(text)
    assert record["model_file"] == "shang2010.toml"
    assert str(tmp_path) not in text and "/robots" not in text
    header = (out / "include" / "shang2010_pm2dof.h").read_text()
    assert f'#define SHANG2010_PM2DOF_VERSION "{pm2dof.__version__}"' in header
    assert (f'#define SHANG2010_PM2DOF_FORMULATION "{src.spec.formulation_sha256}"'
            in header)


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
