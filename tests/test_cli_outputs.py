# Outputs that cannot be written are refused before any work, one line, exit 2 (review findings).
import re

import pytest

import pm2dof
from pm2dof import cli
from pm2dof.analysis.splits import preload_settings
from pm2dof.infra.results import output_folder, output_path, write_atomic


@pytest.fixture
def a_file(tmp_path):
    f = tmp_path / "afile"
    f.write_text("not a folder")
    return f


@pytest.mark.parametrize("argv, match", [
    (["table3", "--save", "{dir}"], "cannot write {dir}: it is a folder"),
    (["identify", "excite", "--out", "{dir}"], "cannot write {dir}: it is a folder"),
    (["animate", "--out", "{file}/x.gif"], "cannot write {file}/x.gif: {file} is a file, not a folder"),
    (["animate", "--out", "{dir}/x.jpg"], r"out must name a .gif file \(the animation\) or a "
                                          r"\.png file"),
    (["animate", "--out", "{file}/x.png"], "cannot write {file}/x.png: {file} is a file, not a folder"),
    (["maps", "--out", "{file}"], "cannot write into {file}: {file} is a file, not a folder"),
    (["plan", "--out", "{file}/sub"], "cannot write into {file}/sub: {file} is a file"),
    (["splits", "--preload-sign", "1", "1"], r"preload_sign must be one finite number or 3 "
                                             r"\(one per actuator\), got \[1.0, 1.0\]"),
])
def test_cli_refuses_an_output_it_cannot_write(argv, match, tmp_path, a_file, capsys):
    fill = {"dir": str(tmp_path), "file": str(a_file)}
    rc = cli.main([a.format(**fill) for a in argv] + ["--quiet"] * (argv[0] != "identify"))
    err = capsys.readouterr().err
    assert rc == 2, err
    assert err.count("\n") == 1 and err.startswith("pm2dof: error: ")
    assert re.search(match.format(**fill), err), err


def test_write_atomic_names_what_is_in_the_way(tmp_path, a_file):
    with pytest.raises(pm2dof.OutputError, match="it is a folder"):
        write_atomic(tmp_path, b"x")
    with pytest.raises(pm2dof.OutputError, match=f"{a_file} is a file, not a folder"):
        write_atomic(a_file / "deeper" / "x.json", b"x")
    assert write_atomic(tmp_path / "new" / "x.json", b"x").read_bytes() == b"x"
    assert output_folder(tmp_path / "not" / "yet") == tmp_path / "not" / "yet"
    assert not (tmp_path / "not").exists()          # checked, not created
    assert output_path(tmp_path / "made" / "f.txt").parent.is_dir()


def test_preload_settings_broadcast_one_value_and_refuse_a_wrong_count():
    m = pm2dof.load_model()
    pre, sgn = preload_settings(m, preload=2.0, preload_sign=[1, -1, 1])
    assert pre.tolist() == [2.0, 2.0, 2.0] and sgn.tolist() == [1.0, -1.0, 1.0]
    with pytest.raises(pm2dof.ArgumentError, match="preload must be one finite number or 3"):
        preload_settings(m, preload=[1.0, 2.0])


def _moved_model(tmp_path):
    """The paper's robot with its moves elsewhere (trajectories are not in the formulation, so
    the shipped generated code serves it)."""
    from pm2dof.core.paths import SHIPPED_MODELS
    text = (SHIPPED_MODELS / "shang2010.toml").read_text()
    text = text.replace("start = [0.22, 0.29]", "start = [0.30, 0.20]").replace(
        "end = [0.27, 0.24]", "end = [0.32, 0.22]")
    path = tmp_path / "moved.toml"
    path.write_text(text)
    return str(path), str(SHIPPED_MODELS.parent / "generated" / "shang2010")


def test_report_evaluates_at_a_pose_of_the_models_own(tmp_path, capsys, monkeypatch):
    """It used the paper's path midpoint (0.245, 0.265) for every model."""
    path, gen = _moved_model(tmp_path)
    assert cli.main(["report", "--model", path, "--generated", gen]) == 0
    out = capsys.readouterr().out
    assert "at xe = [0.31, 0.21] m (midpoint of the model's move 'low')" in out
    from pm2dof.analysis import report
    m = pm2dof.load_model()
    monkeypatch.setattr(report, "line_moves", lambda m: ())     # a model with path moves only
    xe, what = report.report_pose(m)
    assert what == "the grid point farthest from both singularities"
    sing = m.singularity_measures(m.ik(xe))
    assert sing[0] > m.singularity_threshold and sing[1] > m.parallel_singularity_threshold


def test_table3_prints_the_papers_columns_only_for_the_papers_robot():
    from pm2dof.analysis.experiment import format_table3, is_paper_robot
    numbers = {s: {"apd_rmse": 1e-4, "na_rmse": 5e-5, "na_no_adaptation_rmse": 6e-5,
                   "rpe_percent": 50.0} for s in ("low", "high")}
    assert is_paper_robot(pm2dof.load_model()) and not is_paper_robot(pm2dof.load_model("fivebar"))
    assert not is_paper_robot(pm2dof.load_model("unequal"))
    assert "APD paper" in format_table3(numbers) and "1.3738e-04" in format_table3(numbers)
    other = format_table3(numbers, paper=False)
    assert "APD paper" not in other and "1.3738e-04" not in other and "not shown" in other


def test_make_dist_needs_only_the_build_frontend():
    """`make dist` installed the whole dev extra first (3 min): now every command it
    runs installs the build frontend only (python -m build brings the backend itself)."""
    import shutil
    import subprocess
    from pathlib import Path
    if shutil.which("make") is None:
        pytest.skip("no make")
    root = Path(__file__).resolve().parent.parent
    r = subprocess.run(["make", "-n", "-B", "dist"], cwd=root, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    installs = [ln for ln in lines if "pip install" in ln]
    assert installs and all("'build>=1.0'" in ln and "[dev]" not in ln and " -e " not in ln
                            for ln in installs), lines
    assert any("-m build --outdir dist" in ln for ln in lines)


# ---- smaller fixes ----

def test_derive_without_a_model_suggests_models_copy(capsys):
    assert cli.main(["derive"]) == 2
    err = capsys.readouterr().err
    assert "pm2dof models --copy shang2010" in err and len(err.strip().splitlines()) == 1


def test_derive_refuses_generated_instead_of_ignoring_it(capsys, tmp_path):
    assert cli.main(["derive", "fivebar", "--generated", str(tmp_path)]) == 2
    assert "writes into --out DIR, not --generated" in capsys.readouterr().err
    assert not any(tmp_path.iterdir())


@pytest.mark.parametrize("argv", [["report", "--json"], ["study", "show", "--bogus"]])
def test_an_unknown_option_gets_its_commands_usage(argv, capsys):
    """argparse's top level would print `usage: pm2dof [-h] ...` for an option the command
    does not have; the command's own usage line says which options it has."""
    with pytest.raises(SystemExit) as stop:
        cli.main(argv)
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert err.startswith(f"usage: pm2dof {' '.join(argv[:-1])} ")
    assert f"pm2dof {' '.join(argv[:-1])}: error: unrecognized arguments: {argv[-1]}" in err


def test_no_generated_code_mentions_generated(tmp_path):
    from pm2dof.core.paths import SHIPPED_MODELS
    copy = tmp_path / "robot.toml"
    copy.write_text((SHIPPED_MODELS / "shang2010.toml").read_text())
    with pytest.raises(pm2dof.StaleGeneratedCodeError, match=r"pass --generated DIR"):
        pm2dof.load_model(copy)


def test_version_prints_what_getting_started_says(capsys):
    from pathlib import Path

    from pm2dof.core.version import __version__
    with pytest.raises(SystemExit):
        cli.main(["--version"])
    assert capsys.readouterr().out.strip() == f"pm2dof {__version__}"
    doc = (Path(__file__).resolve().parent.parent / "docs" / "getting-started.md").read_text()
    assert f"`pm2dof --version` prints the version (`pm2dof {__version__}`)" in doc


def test_installed_package_outputs_omit_git_commit(monkeypatch):
    from pm2dof.infra import results
    monkeypatch.setattr(results, "_git_commit", lambda: None)
    prov = results.provenance(pm2dof.load_model())
    assert "git_commit" not in prov and prov["pm2dof"]


def test_plan_csv_writes_shortest_decimals_and_json_names_the_unit(tmp_path):
    from pm2dof.planning.jobs import plan_paths
    from pm2dof.planning.pathfile import NamedPath
    from pm2dof.planning.report import csv_text
    m = pm2dof.load_model()
    path = pm2dof.TaskPath.line([0.22, 0.29], [0.27, 0.24])
    plan = pm2dof.plan_time_optimal(m, path, grid=100)
    rows = [ln for ln in csv_text(m, plan).splitlines() if ln and not ln.startswith("#")][1:]
    fields = [f for ln in rows for f in ln.split(",")]
    assert fields and all(f == repr(float(f)) for f in fields)          # was %.17g
    assert any(len(f) < 17 for f in fields)
    res, _ = plan_paths(m, [NamedPath("line", path, None, None)], grid=100)
    row = res["paths"][0]
    # the unit-free name, with the unit in `units` (N for a linear actuator), beside the old key
    assert row["min_norm"]["tau_peak"] == row["min_norm"]["tau_peak_N_m"]
    assert len(row["min_norm"]["tau_peak"]) == 3 and res["units"]["tau_peak"] == ["N m"] * 3


def test_save_and_out_both_create_missing_folders(tmp_path, capsys):
    save = tmp_path / "a" / "b" / "t.json"
    out = tmp_path / "c" / "d" / "run.csv"
    assert cli.main(["table3", "--save", str(save)]) == 0
    assert cli.main(["identify", "excite", "--duration", "0.5", "--out", str(out)]) == 0
    assert save.is_file() and out.is_file()
