# pm2dof export of a model with a [design] table, at a design other than the file's.
"""A model with [design] exports at its design (:meth:`pm2dof.Model.at_design`): the public
generated functions set their input ``design`` from a constant array (export/design.py), so the
library is that robot. The exported ctest (the C closed loop against the reference that
pm2dof computes at the design) passes, and its RMSEs equal :func:`pm2dof.simulate` of the
design model, which differ from the file's design's (the geometry reached the C)."""
import re
import shutil
import subprocess

import pytest

import pm2dof
from pm2dof.core.manifest import Manifest
from pm2dof.export import export_project
from pm2dof.export.design import bind_design

pytestmark = pytest.mark.slow     # a CMake build: make test-slow (CI)

DESIGN = {"la": 0.26, "lb": 0.25}


def _run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, f"{' '.join(map(str, cmd))}\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}"
    return r


def test_bind_design_sets_the_design_input_of_every_function_that_takes_it():
    m = pm2dof.load_model("shang2010_design").at_design(DESIGN)
    gen = Manifest.read(m.generated)
    text = (gen.folder / f"{m.name}.c").read_text()
    bound = bind_design(text, m, gen)
    takes = [s for s in gen.function_names() if gen.signature(s)["inputs"][-1][0] == "design"]
    assert len(takes) > 40
    assert bound.count("static const casadi_real design[3] = {0.26, 0.25, 0.433};") == len(takes)
    fixed = pm2dof.load_model("shang2010")
    assert bind_design(text, fixed, gen) is text      # no [design]: unchanged


@pytest.mark.skipif(shutil.which("cmake") is None or shutil.which("cc") is None,
                    reason="needs cmake and a C compiler")
def test_exported_design_runs_the_designs_closed_loop(tmp_path):
    m = pm2dof.load_model("shang2010_design").at_design(DESIGN)
    root, build = tmp_path / "proj", tmp_path / "build"
    export_project(m, root, measure_stack=False)
    _run(["cmake", "-S", root, "-B", build, "-DCMAKE_BUILD_TYPE=Debug",
          "-DCMAKE_C_FLAGS_DEBUG=-O0"])
    _run(["cmake", "--build", build, "-j", "2"])
    r = _run(["ctest", "--test-dir", build, "--output-on-failure"])
    assert "100% tests passed" in r.stdout, r.stdout
    out = _run([build / f"{m.name}_test"]).stdout
    move = pm2dof.model_move(m, "high")
    at_file = pm2dof.load_model("shang2010_design")
    for law, cls in (("na", pm2dof.NAController), ("apd", pm2dof.APDController)):
        got = float(re.search(rf"^{law} +RMSE ([0-9.e+-]+) m", out, re.M)[1])
        want = pm2dof.simulate(m, cls(m), move).rmse
        assert got == pytest.approx(want, rel=1e-12, abs=0), (law, got, want)
        other = pm2dof.simulate(at_file, cls(at_file), pm2dof.model_move(at_file, "high")).rmse
        assert abs(other - want) > 1e-9 * want, law     # another robot, another RMSE
