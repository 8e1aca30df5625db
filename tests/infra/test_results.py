# Results the CLI writes: atomic writes (temp file + rename) and provenance in JSON and PNG.
"""Tests of :mod:`pm2dof.infra.results` and of the files the CLI writes.

* ``write_atomic``: the target holds either its old content or the complete new content, never
  a partial file, and no temporary file is left behind, whether the failure comes from the
  write itself, from the rename, from a bad payload or from an interrupt.
* ``write_json``: parses back; numpy arrays and scalars are converted; an unserialisable object
  fails before the target is touched.
* ``pm2dof table3 --save`` / ``identify fit --save`` / ``figures``: the JSON carries the numbers and
  the provenance (model file hash = the model spec's ``file_sha256``, formulation hash, git
  commit, versions, command line); every PNG carries the provenance in its text chunk.
"""
from __future__ import annotations

import json
import os
import stat
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof import cli
from pm2dof.core.model_file import read_model_file
from pm2dof.core.paths import SHIPPED_MODELS
from pm2dof.infra import results
from pm2dof.infra.results import provenance, save_figure, write_atomic, write_json

pytestmark = pytest.mark.slow     # runs CLI commands that write files: make test-slow (CI)

REPO = Path(__file__).resolve().parents[2]
PAPER = SHIPPED_MODELS / "shang2010.toml"
TABLE3_KEYS = ("apd_rmse", "na_rmse", "na_no_adaptation_rmse", "rpe_percent",
               "trajectory_duration_s")
PROVENANCE_KEYS = ("model", "model_file", "model_file_sha256", "formulation_sha256",
                   "generated_with", "git_commit", "pm2dof", "python", "numpy",
                   "command_line")


@pytest.fixture(scope="module")
def model():
    return pm2dof.load_model()


def listing(folder):
    return sorted(p.name for p in Path(folder).iterdir())


# --------------------------------------------------------------------------------------
# write_atomic
# --------------------------------------------------------------------------------------

def test_write_atomic_writes_and_leaves_no_temporary(tmp_path):
    target = tmp_path / "sub" / "dir" / "r.bin"  # parents are created
    data = bytes(range(256)) * 100
    assert write_atomic(target, data) == target
    assert target.read_bytes() == data
    assert listing(target.parent) == ["r.bin"], listing(target.parent)
    write_atomic(target, b"second")  # overwrite
    assert target.read_bytes() == b"second"
    assert listing(target.parent) == ["r.bin"]


def test_write_atomic_failed_rename_keeps_the_old_file(tmp_path, monkeypatch):
    target = tmp_path / "r.json"
    target.write_bytes(b"old content")

    def boom(src, dst):
        assert Path(src).parent == target.parent, "the temporary must be in the same folder"
        assert Path(src).read_bytes() == b"new content" * 1000, "temp file not complete"
        raise OSError("simulated failure in os.replace")

    monkeypatch.setattr(results.os, "replace", boom)
    with pytest.raises(OSError, match="simulated failure"):
        write_atomic(target, b"new content" * 1000)
    assert target.read_bytes() == b"old content"
    assert listing(tmp_path) == ["r.json"], f"temporary left behind: {listing(tmp_path)}"


def test_write_atomic_failure_mid_write_keeps_the_old_file(tmp_path, monkeypatch):
    target = tmp_path / "r.json"
    target.write_bytes(b"old content")
    real_fdopen = os.fdopen

    class HalfWriter:
        def __init__(self, fh):
            self.fh = fh

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.fh.close()
            return False

        def write(self, data):
            self.fh.write(data[:len(data) // 2])
            self.fh.flush()
            raise OSError("simulated disk full")

    monkeypatch.setattr(results.os, "fdopen", lambda fd, mode: HalfWriter(real_fdopen(fd, mode)))
    with pytest.raises(OSError, match="disk full"):
        write_atomic(target, b"x" * 10000)
    assert target.read_bytes() == b"old content"
    assert listing(tmp_path) == ["r.json"], f"temporary left behind: {listing(tmp_path)}"


def test_write_atomic_interrupt_cleans_up(tmp_path, monkeypatch):
    target = tmp_path / "r.json"
    target.write_bytes(b"old")

    def interrupted(src, dst):
        raise KeyboardInterrupt

    monkeypatch.setattr(results.os, "replace", interrupted)
    with pytest.raises(KeyboardInterrupt):
        write_atomic(target, b"new")
    assert target.read_bytes() == b"old" and listing(tmp_path) == ["r.json"]


def test_write_atomic_bad_payload_leaves_nothing(tmp_path):
    target = tmp_path / "r.json"
    with pytest.raises(TypeError):
        write_atomic(target, "text, not bytes")
    assert listing(tmp_path) == [], listing(tmp_path)


def test_write_atomic_onto_a_directory_fails_cleanly(tmp_path):
    (tmp_path / "d").mkdir()
    (tmp_path / "d" / "inside").write_text("keep")
    with pytest.raises(OSError):
        write_atomic(tmp_path / "d", b"data")
    assert listing(tmp_path) == ["d"] and (tmp_path / "d" / "inside").read_text() == "keep"


def test_write_atomic_file_mode_follows_the_umask(tmp_path):
    """A result file gets the permissions any other new file would (0666 & ~umask), not the
    private 0600 of the temporary file it was renamed from."""
    plain = tmp_path / "plain"
    plain.write_bytes(b"x")
    target = write_atomic(tmp_path / "atomic", b"x")
    want = stat.S_IMODE(plain.stat().st_mode)
    got = stat.S_IMODE(target.stat().st_mode)
    assert got == want, f"write_atomic made mode {oct(got)}, a plain write {oct(want)}"


# --------------------------------------------------------------------------------------
# write_json
# --------------------------------------------------------------------------------------

def test_write_json_round_trips_numpy(tmp_path):
    obj = {"a": np.arange(3.0), "b": np.float64(0.5), "c": np.int64(7), "d": [np.bool_(True)],
           "e": {"nested": np.eye(2)}, "s": "text", "n": None}
    p = write_json(tmp_path / "x.json", obj)
    back = json.loads(p.read_text())
    assert back == {"a": [0.0, 1.0, 2.0], "b": 0.5, "c": 7, "d": [True],
                    "e": {"nested": [[1.0, 0.0], [0.0, 1.0]]}, "s": "text", "n": None}
    assert p.read_text().endswith("\n")
    assert listing(tmp_path) == ["x.json"]


def test_write_json_unserialisable_leaves_the_old_file(tmp_path):
    target = tmp_path / "x.json"
    target.write_text('{"old": 1}\n')
    with pytest.raises(TypeError, match="not JSON serialisable"):
        write_json(target, {"bad": object()})
    assert json.loads(target.read_text()) == {"old": 1}
    assert listing(tmp_path) == ["x.json"]


def test_provenance_fields(model):
    prov = provenance(model)
    head = _head()
    missing = [k for k in PROVENANCE_KEYS if k not in prov
               and not (k == "git_commit" and head is None)]
    assert not missing, f"provenance lacks {missing}: {prov}"
    spec = read_model_file(PAPER)
    assert prov["model_file_sha256"] == spec.file_sha256 == model.spec.file_sha256
    assert prov["formulation_sha256"] == spec.formulation_sha256
    assert prov["numpy"] == np.__version__
    assert prov["python"] == ".".join(map(str, sys.version_info[:3]))
    assert dict(prov["generated_with"]) == dict(model.manifest["versions"])
    json.dumps(prov)  # JSON-able as it is


def test_provenance_records_the_command_line_it_is_given(model):
    assert provenance(model, ["pm2dof", "plan", "--json"])["command_line"] == \
        ["pm2dof", "plan", "--json"]
    assert provenance(model, ("pm2dof", "x"))["command_line"] == ["pm2dof", "x"]   # a list
    assert provenance(model)["command_line"] == sys.argv       # a script: its own argv


def test_a_python_call_after_the_cli_records_its_own_command_line(model, capsys):
    """The CLI passes its command line down; it set a module global before, which stayed
    behind: a later call from Python recorded the CLI's last command, not its own."""
    assert cli.main(["models"]) == 0
    capsys.readouterr()
    assert provenance(model)["command_line"] == sys.argv
    assert not hasattr(results, "COMMAND_LINE")


def test_every_file_the_cli_writes_records_its_own_command_line(tmp_path, capsys):
    """Passed explicitly from ``cli.main`` to each writer: maps.json and the maps' PNGs, a
    plan's JSON and its figures, a saved identification, on a platform, a linear-actuator
    model and the gravity model."""
    for name, argv in (
            ("prr3_platform", ["maps", "--model", "prr3_platform", "--resolution", "11",
                               "--out", str(tmp_path / "maps")]),
            ("shang2010_vertical", ["plan", "--model", "shang2010_vertical", "--move", "low",
                                    "--grid", "100", "--out", str(tmp_path / "plan")]),
            ("rrr3_platform", ["identify", "fit", "--model", "rrr3_platform", "--duration", "2",
                               "--save", str(tmp_path / "fit.json")])):
        m = pm2dof.load_model(name)
        assert cli.main(argv) == 0, capsys.readouterr().err
        capsys.readouterr()
        provs = []
        if argv[0] == "maps":
            provs.append(json.loads((tmp_path / "maps" / "maps.json").read_text())["provenance"])
            provs += [json.loads(_png_text(f)["Description"])
                      for f in sorted((tmp_path / "maps").glob("*.png"))]
        elif argv[0] == "plan":
            provs += [json.loads(_png_text(f)["Description"])
                      for f in sorted((tmp_path / "plan").glob("*.png"))]
        else:
            provs.append(json.loads((tmp_path / "fit.json").read_text())["provenance"])
        assert len(provs) >= 1, argv
        for prov in provs:
            check_provenance(prov, m)
            assert prov["command_line"] == ["pm2dof", *argv], (prov["command_line"], argv)


def _head():
    try:
        out = subprocess.run(["git", "rev-parse", "HEAD"], cwd=REPO, capture_output=True,
                             text=True, timeout=10)
    except (OSError, subprocess.SubprocessError):
        return None
    return out.stdout.strip() if out.returncode == 0 else None


def check_provenance(prov, model, argv_words=()):
    head = _head()
    missing = [k for k in PROVENANCE_KEYS if k not in prov
               and not (k == "git_commit" and head is None)]
    assert not missing, f"provenance lacks {missing}: {prov}"
    assert prov["model_file_sha256"] == model.spec.file_sha256, prov
    assert prov["formulation_sha256"] == model.spec.formulation_sha256, prov
    assert prov["model"] == model.name
    if head is None:
        assert "git_commit" not in prov      # an installed package: omitted, not None
    else:
        assert prov["git_commit"] in (head, head + "+dirty"), (prov["git_commit"], head)
    assert prov["python"] and prov["numpy"] and prov["generated_with"], prov
    cmd = prov["command_line"]
    assert isinstance(cmd, list) and all(isinstance(w, str) for w in cmd), cmd
    for w in argv_words:
        assert w in cmd, f"command line {cmd} lacks {w!r}"


# --------------------------------------------------------------------------------------
# The CLI's files
# --------------------------------------------------------------------------------------

def test_cli_table3_save_json(tmp_path, model, capsys):
    out = tmp_path / "t.json"
    assert cli.main(["table3", "--save", str(out)]) == 0
    capsys.readouterr()
    assert listing(tmp_path) == ["t.json"], listing(tmp_path)
    d = json.loads(out.read_text())
    for speed in ("low", "high"):
        assert speed in d, list(d)
        missing = [k for k in TABLE3_KEYS if k not in d[speed]]
        assert not missing, f"{speed} lacks {missing}: {d[speed]}"
        for k in TABLE3_KEYS:
            assert isinstance(d[speed][k], float) and np.isfinite(d[speed][k]), (speed, k)
        assert d[speed]["apd_rmse"] > 0 and d[speed]["na_rmse"] > 0
        rpe = 100 * (d[speed]["apd_rmse"] - d[speed]["na_rmse"]) / d[speed]["apd_rmse"]
        assert d[speed]["rpe_percent"] == pytest.approx(rpe, rel=1e-12)
    check_provenance(d["provenance"], model)


def test_cli_table3_save_records_its_own_command_line(tmp_path, model, capsys):
    """main(argv) called from Python: the provenance's command line is that argv, not the
    caller's sys.argv (here pytest's)."""
    out = tmp_path / "t.json"
    assert cli.main(["table3", "--save", str(out)]) == 0
    capsys.readouterr()
    check_provenance(json.loads(out.read_text())["provenance"], model,
                     argv_words=("table3", "--save", str(out)))


def test_cli_table3_save_from_a_shell(tmp_path, model):
    out = tmp_path / "t.json"
    env = dict(os.environ, PYTHONPATH=str(REPO) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    r = subprocess.run([sys.executable, "-m", "pm2dof", "table3", "--json", "--save", str(out)],
                       cwd=REPO, env=env, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    d = json.loads(out.read_text())
    printed = json.loads(r.stdout)
    assert {k: d[k] for k in printed} == printed, "saved numbers differ from the printed ones"
    check_provenance(d["provenance"], model, argv_words=("table3", "--save", str(out)))
    assert listing(tmp_path) == ["t.json"]


def test_cli_identify_save(tmp_path, model, capsys):
    out = tmp_path / "id.json"
    assert cli.main(["identify", "fit", "--duration", "3", "--save", str(out)]) == 0
    capsys.readouterr()
    d = json.loads(out.read_text())
    assert d["param_names"] == list(model.param_names)
    assert len(d["theta0"]) == len(model.param_names) and np.isfinite(d["theta0"]).all()
    check_provenance(d["provenance"], model)
    assert listing(tmp_path) == ["id.json"]


def _png_text(path):
    from PIL import Image
    with Image.open(path) as im:
        im.load()
        assert im.format == "PNG", im.format
        return dict(im.text)


def test_save_figure_carries_provenance(tmp_path, model):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots()
    ax.plot([0, 1], [1, 0])
    prov = provenance(model)
    p = save_figure(fig, tmp_path / "f.png", prov)
    plt.close(fig)
    text = _png_text(p)
    assert text.get("Software") == "pm2dof", text
    assert json.loads(text["Description"]) == json.loads(json.dumps(prov)), text
    assert listing(tmp_path) == ["f.png"]


def test_save_figure_failed_rename_keeps_the_old_png(tmp_path, model, monkeypatch):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    target = tmp_path / "f.png"
    target.write_bytes(b"old png")
    fig = plt.figure()
    monkeypatch.setattr(results.os, "replace", lambda s, d: (_ for _ in ()).throw(OSError("no")))
    with pytest.raises(OSError):
        save_figure(fig, target, provenance(model))
    plt.close(fig)
    assert target.read_bytes() == b"old png" and listing(tmp_path) == ["f.png"]


def test_cli_figures_carry_provenance(tmp_path, model, capsys):
    out = tmp_path / "figs"
    assert cli.main(["figures", "--out", str(out), "--runs", "0"]) == 0
    capsys.readouterr()
    pngs = sorted(out.glob("*.png"))
    assert {p.name for p in pngs} >= {"errors_low.png", "errors_high.png", "torques.png",
                                      "theta_hat.png"}, listing(out)
    assert listing(out) == [p.name for p in pngs], f"stray files: {listing(out)}"
    for p in pngs:
        text = _png_text(p)
        assert text.get("Software") == "pm2dof", (p.name, text)
        check_provenance(json.loads(text["Description"]), model)
