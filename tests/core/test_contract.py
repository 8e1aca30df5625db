"""The generated code's contract (pm2dof.core.contract) and its manifest (pm2dof.core.manifest).

Each fact has one home, imported from there by derive, core, control, export and bench:
- the split names and suffixes, the law names, the steps' names: the shipped manifests list
  exactly the functions the contract names, and every layer uses the contract's tables;
- the step's diag layout: in the manifest's layouts, and the controllers' ``diag`` reads it
  (checked against fk, an independent computation of the pose);
- the work sizes: recorded in the manifest at derive time, checked against the compiled
  library's own ``<f>_work`` (called through ctypes) and CasADi's C text;
- one Manifest: load, owner, hashes, used by load_model, up_to_date, derive and export.
On a platform (rrr3_platform), linear actuators (prr3_platform, rpr3_platform, prr_point), a
gravity model (shang2010_vertical) and the paper's robot.
"""
import ctypes
import importlib.util
import json
import re
import shutil

import numpy as np
import pytest

import pm2dof
from pm2dof.core import contract
from pm2dof.core.errors import StaleGeneratedCodeError
from pm2dof.core.manifest import Manifest, derive_sources_sha256
from pm2dof.core.paths import SHIPPED_GENERATED, resolve_model

MODELS = ["rrr3_platform", "prr3_platform", "rpr3_platform", "prr_point", "shang2010_vertical",
          "shang2010"]


def test_one_home_for_the_splits_and_laws():
    from pm2dof.bench import run as bench_run
    from pm2dof.control import controllers
    from pm2dof.core import model_file
    from pm2dof.export import project
    assert contract.SPLITS == {"min_norm": "", "min_max": "_minmax", "preload": "_preload"}
    assert controllers.SPLITS is contract.SPLITS
    assert model_file.SPLITS == tuple(contract.SPLITS)
    assert bench_run.BENCH_SPLITS == tuple(contract.SPLITS)
    assert project.LAWS is contract.LAWS == ("na", "apd", "ctc", "lqr")
    assert contract.step_name("na_proj", "min_max") == "na_proj_minmax_step"
    assert contract.closed_loop_name("lqr", "preload") == "lqr_preload_closed_loop"
    assert {law for _, law, _ in contract.STEPS} == set(contract.LAWS)


def test_derive_uses_the_contract():
    pytest.importorskip("casadi")
    from pm2dof.derive import controllers, plant, splits
    assert controllers.STEPS is contract.STEPS and plant.STEPS is contract.STEPS
    assert not hasattr(splits, "SPLITS") and not hasattr(controllers, "LAWS")
    lay = controllers.controller_layouts(3, 7, 3)["diag"]
    assert lay.to_json() == [list(f) for f in contract.diag_layout(3)]


def test_derive_has_no_main_module():
    """``pm2dof derive`` is the one entry point."""
    assert importlib.util.find_spec("pm2dof.derive.__main__") is None


@pytest.mark.parametrize("name", MODELS)
def test_manifest_lists_exactly_the_contracts_functions(name):
    man = Manifest.read(SHIPPED_GENERATED / name)
    assert sorted(man.function_names()) == sorted(contract.function_names())
    assert len(contract.function_names()) == len(set(contract.function_names())) == 63
    # the model binds what the manifest lists, no more and no less
    model = pm2dof.load_model(name)
    assert sorted(model._f) == sorted(contract.function_names())
    step = model.function("na_step")
    assert step.names_in == contract.STEP_INPUTS and step.names_out == contract.STEP_OUTPUTS


@pytest.mark.parametrize("name", MODELS)
def test_diag_layout_is_in_the_manifest_and_read_by_the_controllers(name):
    model = pm2dof.load_model(name)
    m = model.dof
    assert model.manifest["layouts"]["diag"] == tuple(tuple(f) for f in contract.diag_layout(m))
    assert model.layout("diag").size == model.function("na_step").sizes_out[3] == 4 * m + 2
    ctl = pm2dof.NAController(model)
    xe0 = _a_pose(model)
    qa = model.ik(xe0)[:model.n_legs]
    ctl.reset(qa)
    xd = xe0 + 0.001
    ctl.step(qa, xd, np.zeros(m), np.zeros(m))
    d = ctl.diag
    assert list(d) == ["xe", "v", "e", "edot", "sing", "sing_parallel"]
    np.testing.assert_allclose(d["xe"], model.fk(qa), atol=1e-9)        # independent: fk
    np.testing.assert_allclose(d["e"], xd - d["xe"], atol=1e-12)        # eq. 14
    np.testing.assert_allclose([d["sing"], d["sing_parallel"]],
                               model.singularity_measures(model.ik(model.fk(qa))), atol=1e-9)


def _a_pose(model):
    """A reachable pose: the model's home (a platform) or its first move's start."""
    if model.spec.home is not None:
        return np.array(model.spec.home, dtype=float)
    move = pm2dof.model_move(model, next(iter(model.spec.trajectories)))
    return np.asarray(move.xd[0], dtype=float)


def _c_work(c_text, fname):
    m = re.search(rf"int {fname}_work\([^)]*\) {{\s*if \(sz_arg\) \*sz_arg = (\d+);\s*"
                  rf"if \(sz_res\) \*sz_res = (\d+);\s*if \(sz_iw\) \*sz_iw = (\d+);\s*"
                  rf"if \(sz_w\) \*sz_w = (\d+);", c_text)
    return tuple(int(g) for g in m.groups())


@pytest.mark.parametrize("name", MODELS)
def test_work_sizes_recorded_at_derive_time_are_the_libraries(name):
    """The manifest's work sizes of every function are what the compiled library's
    ``<f>_work`` reports (called here through ctypes) and what the C text declares."""
    model = pm2dof.load_model(name)
    man = Manifest.read(model.generated)
    lib = ctypes.CDLL(model.library)
    c_text = man.c_file.read_text()
    sizes = [ctypes.c_longlong() for _ in range(4)]
    for short in man.function_names():
        fname = f"{man.name}_{short}"
        work = getattr(lib, f"{fname}_work")
        assert work(*(ctypes.byref(s) for s in sizes)) == 0
        have = tuple(s.value for s in sizes)
        assert man.work_sizes(short) == have == _c_work(c_text, fname), fname


def test_export_takes_its_work_sizes_from_the_manifest():
    from pm2dof.export import project
    model = pm2dof.load_model("prr3_platform")
    c_text, h_text, man = project._generated_sources(model)
    sizes = project._work_sizes(man, ["na_step", "fk"], model.spec.path)
    assert sizes["na_step"] == _c_work(c_text, "prr3_platform_na_step")
    assert sizes["fk"] == _c_work(c_text, "prr3_platform_fk")
    broken = Manifest(man.folder, json.loads(json.dumps(man.data)))
    del broken.data["functions"]["prr3_platform_fk"]["work"]
    with pytest.raises(StaleGeneratedCodeError, match="records no work sizes.*pm2dof derive"):
        project._work_sizes(broken, ["fk"], model.spec.path)


def test_manifest_owner_and_hashes(tmp_path):
    """One reader: the owner, the hashes and the files, as load_model, up_to_date, derive and
    export see them (a copied folder pointing at its model file)."""
    from pm2dof.core.generated import up_to_date
    from pm2dof.core.model_file import read_model_file
    model_file = tmp_path / "rpr3_platform.toml"
    shutil.copy(resolve_model("rpr3_platform"), model_file)
    gen = tmp_path / "generated" / "rpr3_platform"
    shutil.copytree(SHIPPED_GENERATED / "rpr3_platform", gen)
    data = json.loads((gen / "manifest.json").read_text())
    data["model_file"] = "../../rpr3_platform.toml"
    (gen / "manifest.json").write_text(json.dumps(data))
    man = Manifest.read(gen)
    spec = read_model_file(model_file)
    assert man.owned_by(model_file) and not man.owned_by(resolve_model("rpr3_platform"))
    assert man.what_changed(spec) == "" and man.files_differing() == []
    assert man.get("derive_sources_sha256") == derive_sources_sha256()
    assert up_to_date(spec, gen) == (True, "")
    with open(gen / "rpr3_platform.h", "a") as f:
        f.write("/* edited */\n")
    assert man.files_differing() == ["rpr3_platform.h"]
    assert up_to_date(spec, gen) == (False, "rpr3_platform.h differs from its manifest")
    (gen / "manifest.json").write_text("{not json")
    assert Manifest.read(gen) is None
    assert up_to_date(spec, gen) == (False, "no readable manifest.json")
    with pytest.raises(StaleGeneratedCodeError, match="manifest.json is unreadable"):
        pm2dof.load_model(model_file, gen)
