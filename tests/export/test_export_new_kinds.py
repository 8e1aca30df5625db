# pm2dof export on the other kinds: a platform (task x, y, phi), linear actuators (N, m) and gravity.
"""One CMake build for the module, at -O0 as in test_export_project.py: a super-project holding
two exports, prr3_platform (a moving platform, m = 3, on PRR legs: linear actuators) and
shang2010_vertical (the paper's robot under gravity), warnings as errors on the hand-written
files. Each ctest compares its C closed loop with pm2dof.simulate (RMSE to 1e-12 relative,
efforts bit for bit), replays pm2dof's encoder readings, checks one LQR step with a gain of
N_LEGS x 2 TASK_DIM entries, NaN inputs and fk(ik(x)). Without a compiler: the headers of
rrr3_platform and prr_point say their task dimension, their K's size and their units, and
single precision is refused for prr_point with the reason.
"""
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof.export import ExportError, export_project
from tests.export.c_guards import check_guard_output

pytestmark = pytest.mark.slow     # long runs (builds, full benches, Dask clusters): make test-slow (CI)

needs_cmake = pytest.mark.skipif(shutil.which("cmake") is None or shutil.which("cc") is None,
                                 reason="needs cmake and a C compiler")

BUILT = ("prr3_platform", "shang2010_vertical")
SUPER = ("cmake_minimum_required(VERSION 3.13)\nproject(new_kinds C)\ninclude(CTest)\n"
         + "".join(f"add_subdirectory({name})\n" for name in BUILT))


def _run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=600, **kw)
    assert r.returncode == 0, f"{' '.join(map(str, cmd))}\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}"
    return r


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    root = tmp_path_factory.mktemp("export_new_kinds")
    for name in BUILT:
        export_project(name, root / name, measure_stack=False)
    (root / "CMakeLists.txt").write_text(SUPER)
    build = root / "build"
    _run(["cmake", "-S", root, "-B", build, "-DCMAKE_BUILD_TYPE=Debug",
          "-DCMAKE_C_FLAGS_DEBUG=-O0",
          *(f"-D{name.upper()}_PM2DOF_WERROR=ON" for name in BUILT)])
    _run(["cmake", "--build", build, "-j", "2"])
    return root, build


@needs_cmake
def test_ctest_of_a_platform_with_linear_actuators_and_of_gravity_passes(built):
    root, build = built
    r = _run(["ctest", "--test-dir", build, "--output-on-failure"])
    assert f"100% tests passed out of {2 * len(BUILT)}" in r.stdout, r.stdout


@needs_cmake
@pytest.mark.parametrize("name", BUILT)
def test_c_closed_loop_gives_the_rmse_and_efforts_of_simulate(built, name):
    """Independently of the C's own check: the RMSE it prints (17 digits) against
    pm2dof.simulate run here (x, y only, eq. 41, for the platform too), the efforts bit for
    bit, and the LQR check ran (its K has N_LEGS x 2 m entries)."""
    root, build = built
    out = _run([build / name / f"{name}_test"]).stdout
    m = pm2dof.load_model(name)
    move = pm2dof.model_move(m, "high")
    unit = "N" if name == "prr3_platform" else "N m"
    for law, cls in (("na", pm2dof.NAController), ("apd", pm2dof.APDController),
                     ("ctc", pm2dof.CTCController)):
        got = float(re.search(rf"^{law} +RMSE ([0-9.e+-]+) m", out, re.M)[1])
        want = pm2dof.simulate(m, cls(m), move).rmse
        assert got == pytest.approx(want, rel=1e-12, abs=0), (law, got, want)
        assert re.search(rf"^{law} +RMSE .* largest torque difference 0 {unit}$", out, re.M), out
    assert "FAIL" not in out and re.search(r"(\d+) of \1 checks passed", out), out
    header = (root / name / "include" / f"{name}_pm2dof.h").read_text()
    assert f"#define {name.upper()}_PM2DOF_LQR_K_SIZE (2 * {m.dof} * {m.n_legs})" in header
    assert f"{name.upper()}_PM2DOF_HAVE_LQR 1" in header


@needs_cmake
@pytest.mark.parametrize("name", BUILT)
def test_the_ctests_guards_are_pm2dofs(built, name):
    """As for shang2010 (test_export_project.py): NA's blocked robot with the paper's law, the
    projection and the freeze equals NAController's steps bit for bit (a platform on linear
    actuators, gravity), init's refusals, status strings and version are pm2dof's."""
    root, build = built
    out = _run([build / name / f"{name}_test"]).stdout
    assert "FAIL" not in out and re.search(r"(\d+) of \1 checks passed", out), out[-3000:]
    check_guard_output(out, name)


def test_the_exported_step_holds_the_vertical_robot_against_gravity():
    """What the export's reference and ctest run (the generated NA step) holds the gravity
    term: at rest on the reference (e = 0, xd_dot = xd_ddot = 0, sign(0) = 0) its task force
    S^T tau_a is Ge of the pose, eq. 10, which is not small for this robot."""
    m = pm2dof.load_model("shang2010_vertical")
    q = m.ik(pm2dof.model_move(m, "high").xd[0])
    c = pm2dof.NAController(m)
    c.reset(q[:m.n_legs])
    xe = m.fk(q[:m.n_legs])
    tau = c.step(q[:m.n_legs], xe, np.zeros(2), np.zeros(2))
    ge = m.Ge(m.ik(xe), m.theta_nominal)
    S = m.W(m.ik(xe))[:m.n_legs]
    np.testing.assert_allclose(S.T @ tau, ge, rtol=1e-9, atol=1e-12)
    assert np.linalg.norm(ge) > 1.0                     # N


@pytest.mark.parametrize("name, dim, units", [
    ("rrr3_platform", 3, ("poses           m (x, y), rad (phi)", "(N_LEGS, rad)",
                          "efforts tau_a        N m (torques)", "N m s/rad (phi), K_d of eq. 29")),
    ("prr_point", 2, ("(TASK_DIM, m)", "(N_LEGS, m)", "efforts tau_a        N (forces)",
                      "[N_LEGS] out: the efforts, N,", "N, limit per actuator"))])
def test_the_header_says_the_models_dimension_and_units(tmp_path, name, dim, units):
    out = export_project(name, tmp_path / name, measure_stack=False)
    header = (out / "include" / f"{name}_pm2dof.h").read_text()
    assert f"#define {name.upper()}_PM2DOF_TASK_DIM {dim} " in header
    assert f"LQR_K_SIZE (2 * {dim} * 3)" in header
    assert f"K[{name.upper()}_PM2DOF_LQR_K_SIZE]" in header
    for text in units:
        assert text in header, (text, header[:3000])
    ref = (out / "tests" / f"{name}_reference.h").read_text()
    assert f"ref_xd[REF_N][{dim}]" in ref and f"ref_lqr_K[{2 * dim * 3}]" in ref


def test_deploying_table_of_the_new_kinds_is_simulates():
    """docs/deploying.md's table of the new kinds: its double column is pm2dof.simulate's NA
    RMSE on the high-speed move (the exported C equals it, the ctests above)."""
    page = (Path(__file__).resolve().parents[2] / "docs" / "deploying.md").read_text()
    page = page[page.index("| model | kind |"):]          # that table (others name models too)
    page = page[:page.index("\n\n")]
    names = ("rrr3_platform", "rrr4_platform", "prr3_platform", "rpr3_platform", "prr_point",
             "shang2010_vertical")
    rows = [line for line in page.splitlines() if line.split("|")[1:2] and
            line.split("|")[1].strip() in names]
    assert len(rows) == 6, rows
    for row in rows:
        name = row.split("|")[1].strip()
        m = pm2dof.load_model(name)
        r = pm2dof.simulate(m, pm2dof.NAController(m), pm2dof.model_move(m, "high")).rmse
        assert row.split("|")[3].strip() == f"{r:.4e} m", (name, f"{r:.4e}")


def test_single_precision_is_refused_where_the_closure_check_needs_more(tmp_path):
    """prr_point's closure tolerance (5e-6 m) is below float's resolution of its closure
    (64 FLT_EPSILON x the rail plus the link): refused with the reason, nothing written."""
    with pytest.raises(ExportError, match="closure_tolerance = 5e-06 m is below float"):
        export_project("prr_point", tmp_path / "out", precision="single")
    assert not (tmp_path / "out").exists()
