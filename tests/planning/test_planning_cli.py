# `pm2dof plan`: the model's moves, a shipped or user path file, JSON, CSV and figures, errors.
import json

import numpy as np
import pytest

import pm2dof
from pm2dof.cli import main
from pm2dof.planning.pathfile import read_path_file, shipped_paths
from pm2dof.planning.report import CSV_KEYS, csv_text
from pm2dof.planning.topp import BETWEEN_TOL

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not


def test_plan_the_model_moves_as_json(capsys):
    assert main(["plan", "--move", "high", "--tau-max", "6", "--grid", "300", "--json"]) == 0
    res = json.loads(capsys.readouterr().out)
    (row,) = res["paths"]
    assert row["name"] == "high" and res["tau_max"] == [6.0, 6.0, 6.0]
    assert row["kinematic"]["duration_s"] == pytest.approx(0.2164, abs=1e-4)
    assert row["min_max"]["duration_s"] <= row["min_norm"]["duration_s"]
    assert row["saving_min_max_percent"] > 0
    prov = res["provenance"]                    # every results file says its source
    assert prov["pm2dof"] == pm2dof.__version__ and prov["model"] == "shang2010"
    assert prov["model_file"].endswith("shang2010.toml") and prov["generated"]
    assert prov["tau_max"] == [6.0, 6.0, 6.0] and prov["margin"] == 1.0
    assert prov["splits"] == ["min_norm", "min_max"] and prov["theta"] == "nominal"
    assert prov["command_line"][:2] == ["pm2dof", "plan"]


def _csv(path):
    """({key: value} of the '# key = value' lines, column names, data) of a plan CSV."""
    lines = path.read_text().splitlines()
    meta = dict(ln[2:].split(" = ", 1) for ln in lines if ln.startswith("# ") and " = " in ln)
    n_comments = sum(ln.startswith("#") for ln in lines)
    head = lines[n_comments].split(",")
    return meta, head, np.loadtxt(path, delimiter=",", skiprows=n_comments + 1)


def test_plan_a_path_file_writes_csv_and_figures(tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["plan", "--path", "pick_and_place", "--split", "min_max",
                 "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "pick_and_place" in text and "time-optimal, min_max" in text
    meta, head, data = _csv(out / "plan_pick_and_place_min_max.csv")
    assert head[-3:] == ["tau1", "tau2", "tau3"] and np.isfinite(data).all()
    # the CSV's torques are the inverse dynamics at the 2 ms samples, between the grid points:
    # the planner holds every interval's midpoint to tau_max (1 + BETWEEN_TOL), and the
    # feasibility check measures at most 0.08 % at 10 points per interval on this path at 1000
    # points; measured here 29.9997 N m
    assert np.abs(data[:, -3:]).max() <= 30.0 * (1 + BETWEEN_TOL)
    for kind in ("phase", "torques", "map"):
        assert (out / f"plan_pick_and_place_{kind}.png").stat().st_size > 10_000


def test_plan_csv_says_where_it_came_from(tmp_path, capsys):
    """Provenance in every CSV: pm2dof version, model file and its hash, generated
    folder, git commit, tau_max (the actuators' limits), margin, split, theta."""
    from pm2dof.infra.results import provenance
    out = tmp_path / "out"
    assert main(["plan", "--move", "high", "--tau-max", "6", "--margin", "0.9", "--grid", "200",
                 "--split", "min_norm", "--out", str(out)]) == 0
    capsys.readouterr()
    m = pm2dof.load_model()
    prov = provenance(m)
    meta, _, _ = _csv(out / "plan_high_min_norm.csv")
    assert list(meta)[:len(CSV_KEYS)] == list(CSV_KEYS)
    assert meta["pm2dof"] == pm2dof.__version__ and meta["model"] == "shang2010"
    assert meta["model_file"] == str(prov["model_file"]) and meta["generated"] == prov["generated"]
    assert meta["model_file_sha256"] == prov["model_file_sha256"]
    assert meta["tau_max"] == "[6.0, 6.0, 6.0]" and meta["margin"] == "0.9"
    assert meta["split"] == "min_norm" and meta["theta"] == "nominal"
    kin, _, _ = _csv(out / "plan_high_kinematic.csv")
    assert kin["method"] == "kinematic" and kin["tau_max"] == "[6.0, 6.0, 6.0]"
    th = m.theta_nominal * 1.1                            # an identified theta is written out
    plan = pm2dof.plan_time_optimal(m, pm2dof.TaskPath.line([0.22, 0.29], [0.27, 0.24]),
                                    grid=100, theta=th)
    text = csv_text(m, plan, prov)
    assert f"# theta = {th.tolist()}" in text and "# tau_max = [30.0, 30.0, 30.0]" in text


def test_path_file_errors(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    cases = {
        '[[segments]]\nkind = "circle"\n': "[segments.kind (segment 1)] must be one of",
        '[[segments]]\nkind = "line"\nstart = [0.2, 0.2]\n': "[segments.end (segment 1)] missing",
        '[[segments]]\nkind = "line"\nstart = [0.2, 0.2]\nend = [0.3, 0.2]\nspeed = 1\n':
            "[segments.speed (segment 1)] unknown key",
        '[[segments]]\nkind = "line"\nstart = [0.2, 0.2]\nend = [0.3, 0.2]\n'
        '[[segments]]\nkind = "line"\nstart = [0.3, 0.3]\nend = [0.3, 0.4]\n': "[segments (segment 2)] segment 2 starts at (0.3, 0.3) m",
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


def test_path_file_problems_are_counted_from_1_and_listed_at_once(tmp_path):
    """Path files counted segments from 0 and stopped at the first problem; model and study
    files count from 1 and list every problem: one reader for all three."""
    from pm2dof.core.errors import InputFileError, PlanError
    bad = tmp_path / "bad.toml"
    bad.write_text('colour = "red"\n[kinematic]\nv_max = -1\na_max = 10.0\n'
                   '[[segments]]\nkind = "line"\nstart = [0.22, 0.29]\nend = [0.27, 0.24]\n'
                   '[[segments]]\nkind = "circle"\n'
                   '[[segments]]\nkind = "line"\nstart = [0.2, 0.2]\nspeed = 3\n')
    with pytest.raises(PlanError) as exc:
        read_path_file(bad)
    assert isinstance(exc.value, InputFileError)
    assert [tuple(p) for p in exc.value.problems] == [
        ("colour", "unknown key; allowed here: ['kinematic', 'path', 'segments']"),
        ("kinematic.j_max", "missing (required)"),
        ("kinematic.v_max", "must be > 0, got -1"),
        ("segments.kind (segment 2)",
         "must be one of ['arc', 'line', 'polyline', 'spline'], got 'circle'"),
        ("segments.speed (segment 3)", "unknown key; allowed here: ['end', 'kind', 'start']"),
        ("segments.end (segment 3)", "missing (required)")]
    assert str(exc.value).splitlines()[0] == f"{bad}: 6 problems:"


def test_shipped_paths_read():
    for name in shipped_paths():
        r = read_path_file(name)
        assert r.path.length > 0 and r.kinematic


def test_both_splits_report_the_feasible_one(tmp_path, capsys):
    """At 0.5 N m min-norm cannot even balance the Coulomb friction near rest, min-max can:
    `plan` prints the min-max plan and names min-norm infeasible (it used to fail whole)."""
    assert main(["plan", "--move", "high", "--tau-max", "0.5", "--grid", "300", "--json",
                 "--out", str(tmp_path)]) == 0
    row = json.loads(capsys.readouterr().out)["paths"][0]
    assert "Coulomb friction" in row["min_norm"]["infeasible"]
    assert row["min_max"]["duration_s"] > 1.0
    assert max(row["min_max"]["tau_peak_N_m"]) <= 0.5 * (1 + 1e-6)
    assert "saving_min_max_percent" not in row
    assert sorted(p.name for p in tmp_path.glob("*.csv")) == ["plan_high_kinematic.csv",
                                                              "plan_high_min_max.csv"]
    # one split asked for, and infeasible: the error, as before
    assert main(["plan", "--move", "high", "--tau-max", "0.5", "--split", "min_norm"]) == 2
    assert "no feasible deceleration" in capsys.readouterr().err


def test_tau_rate_needs_smooth(capsys):
    assert main(["plan", "--move", "high", "--tau-rate", "5"]) == 2
    assert "add --smooth" in capsys.readouterr().err
