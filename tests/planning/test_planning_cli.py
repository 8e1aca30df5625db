# `pm2dof plan`: the model's moves, a shipped or user path file, JSON, CSV and figures, errors.
import json

import numpy as np
import pytest

from pm2dof.cli import main
from pm2dof.planning.pathfile import read_path_file, shipped_paths


def test_plan_the_model_moves_as_json(capsys):
    assert main(["plan", "--move", "high", "--tau-max", "6", "--grid", "300", "--json"]) == 0
    res = json.loads(capsys.readouterr().out)
    (row,) = res["paths"]
    assert row["name"] == "high" and res["tau_max"] == [6.0, 6.0, 6.0]
    assert row["kinematic"]["duration_s"] == pytest.approx(0.2164, abs=1e-4)
    assert row["min_max"]["duration_s"] <= row["min_norm"]["duration_s"]
    assert row["saving_min_max_percent"] > 0


def test_plan_a_path_file_writes_csv_and_figures(tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["plan", "--path", "pick_and_place", "--split", "min_max",
                 "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "pick_and_place" in text and "time-optimal, min_max" in text
    csv = out / "plan_pick_and_place_min_max.csv"
    head = [ln for ln in csv.read_text().splitlines() if ln.startswith("t,")][0]
    data = np.loadtxt(csv, delimiter=",", comments="#", skiprows=7)
    assert head.split(",")[-3:] == ["tau1", "tau2", "tau3"] and np.isfinite(data).all()
    assert np.abs(data[:, -3:]).max() <= 30.0 * 1.04      # the discretisation error (README)
    for kind in ("phase", "torques", "map"):
        assert (out / f"plan_pick_and_place_{kind}.png").stat().st_size > 10_000


def test_path_file_errors(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    cases = {
        '[[segments]]\nkind = "circle"\n': "segments[0].kind",
        '[[segments]]\nkind = "line"\nstart = [0.2, 0.2]\n': "segments[0].end: missing",
        '[[segments]]\nkind = "line"\nstart = [0.2, 0.2]\nend = [0.3, 0.2]\nspeed = 1\n':
            "segments[0].speed: unknown key",
        '[[segments]]\nkind = "line"\nstart = [0.2, 0.2]\nend = [0.3, 0.2]\n'
        '[[segments]]\nkind = "line"\nstart = [0.3, 0.3]\nend = [0.3, 0.4]\n': "path 1 starts at",
        '[kinematic]\nv_max = -1\n[[segments]]\nkind = "line"\nstart = [0, 0]\nend = [1, 0]\n':
            "kinematic.v_max",
        'segments = 3': "segments",
        'not toml [': "not valid TOML",
    }
    for text, match in cases.items():
        bad.write_text(text)
        assert main(["plan", "--path", str(bad)]) == 2
        err = capsys.readouterr().err
        assert str(bad) in err and match in err, (text, err)
    assert main(["plan", "--path", "no_such_path"]) == 2
    assert "no shipped path" in capsys.readouterr().err
    assert main(["plan", "--move", "fast"]) == 2
    assert "moves are" in capsys.readouterr().err


def test_shipped_paths_read():
    for name in shipped_paths():
        r = read_path_file(name)
        assert r["path"].length > 0 and r["kinematic"]
