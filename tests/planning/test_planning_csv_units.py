# A plan's CSV names every column and gives each its unit; efforts carry their actuator's unit
# in the CSV, the JSON, the text and the torque figure (linear actuators: N, not N m).
"""The plan CSV of a platform had 13 names over 16 values (``t,s,sdot,sddot,x,y,vx,vy,ax,ay,
tau1,tau2,tau3``): ``csv.DictReader`` read ax as tau1. Here every CSV is read back by name
with ``csv.DictReader`` and checked against what the test computes itself: the pose, velocity
and acceleration from the path (p(s), p' s_d, p' s_dd + p'' s_d^2) and the efforts from
``Model.inverse_dynamics`` and ``Model.torque_splits`` (not the planner's ``path_torques``)."""
import csv
import io
import json

import numpy as np
import pytest

import pm2dof
from pm2dof.cli import main
from pm2dof.core.errors import PlanError
from pm2dof.core.task import orientation_length
from pm2dof.planning.jobs import run_plan, write_plan_csvs
from pm2dof.planning.pathfile import read_path_file
from pm2dof.planning.report import format_report

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

#: a 3-D path (x, y, phi): two lines with a stop at the corner, within reach of every platform
PLATFORM_PATH = ('[[segments]]\nkind = "polyline"\n'
                 'points = [[0.0, 0.0, 0.0], [0.02, 0.01, 0.1], [0.0, 0.02, -0.05]]\n')
#: the paper's line, as a path file (x, y)
POINT_PATH = '[[segments]]\nkind = "line"\nstart = [0.22, 0.29]\nend = [0.27, 0.24]\n'


def _read(path):
    """(comment lines, DictReader rows) of a plan CSV."""
    lines = path.read_text().splitlines()
    comments = [ln for ln in lines if ln.startswith("#")]
    body = "\n".join(ln for ln in lines if not ln.startswith("#"))
    return comments, list(csv.DictReader(io.StringIO(body)))


def _check_rows(model, path, rows, tau_max):
    """Each column, read by its name, against the path and Model's inverse dynamics."""
    names = model.task_names
    assert all(None not in r and None not in r.values() for r in rows)   # a name per value
    s = np.array([float(r["s"]) for r in rows])
    sd = np.array([float(r["sdot"]) for r in rows])
    sdd = np.array([float(r["sddot"]) for r in rows])
    p, dp, ddp = path.evaluate(s)
    for j, nm in enumerate(names):
        np.testing.assert_allclose([float(r[nm]) for r in rows], p[:, j], atol=1e-12)
        np.testing.assert_allclose([float(r[f"v{nm}"]) for r in rows], dp[:, j] * sd,
                                   atol=1e-9)
        np.testing.assert_allclose([float(r[f"a{nm}"]) for r in rows],
                                   dp[:, j] * sdd + ddp[:, j] * sd * sd, atol=1e-6)
    moving = np.flatnonzero(sd > 1e-3)       # friction's sign at rest: its own convention
    assert moving.size > 10
    n = model.n_legs
    for k in moving[:: max(1, moving.size // 25)]:
        r = rows[k]
        xe = np.array([float(r[nm]) for nm in names])
        xed = np.array([float(r[f"v{nm}"]) for nm in names])
        xedd = np.array([float(r[f"a{nm}"]) for nm in names])
        u = model.inverse_dynamics(xe, xed, xedd, model.theta_nominal)
        want = model.torque_splits(model.ik(xe), u, tau_max)["min_norm"]
        got = [float(r[f"tau{i + 1}"]) for i in range(n)]
        np.testing.assert_allclose(got, want, rtol=1e-6, atol=1e-6 * max(tau_max),
                                   err_msg=f"{model.name}, t = {r['t']} s")


def _units(comments):
    (line,) = [c for c in comments if c.startswith("# units = ")]
    return line.removeprefix("# units = ").split(", ")


def test_a_linear_platforms_csv_read_by_name(tmp_path, capsys):
    """The issue's command: `plan --model prr3_platform --path <3-D path> --tau-max 60
    --out D`, then csv.DictReader."""
    f = tmp_path / "p3.toml"
    f.write_text(PLATFORM_PATH)
    out = tmp_path / "D"
    assert main(["plan", "--model", "prr3_platform", "--path", str(f), "--tau-max", "60",
                 "--split", "min_norm", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "N m" not in text and "peak |tau| 60.000 N," in text
    m = pm2dof.load_model("prr3_platform")
    comments, rows = _read(out / "plan_p3_min_norm.csv")
    assert list(rows[0]) == ["t", "s", "sdot", "sddot", "x", "y", "phi", "vx", "vy", "vphi",
                             "ax", "ay", "aphi", "tau1", "tau2", "tau3"]
    assert _units(comments) == ["s", "m", "m/s", "m/s^2", "m", "m", "rad", "m/s", "m/s",
                                "rad/s", "m/s^2", "m/s^2", "rad/s^2", "N", "N", "N"]
    path = read_path_file(f, orientation_length=orientation_length(m)).path
    _check_rows(m, path, rows, np.full(3, 60.0))


@pytest.mark.parametrize("name, text, tau", [("rrr3_platform", PLATFORM_PATH, 20.0),
                                             ("rpr3_platform", PLATFORM_PATH, 300.0),
                                             ("shang2010", POINT_PATH, 30.0),
                                             ("shang2010_vertical", POINT_PATH, 30.0)],
                         ids=["rrr3_platform", "rpr3_platform", "shang2010", "shang2010_vertical"])
def test_every_kinds_csv_read_by_name(tmp_path, name, text, tau):
    """A revolute platform, a linear one, the paper's robot and the gravity model: every
    column where its name says, in the unit the units line gives it."""
    f = tmp_path / "p.toml"
    f.write_text(text)
    m = pm2dof.load_model(name)
    run = run_plan(m, path=str(f), splits=("min_norm",), grid=300)
    plans = run.plans
    (csv_file,) = write_plan_csvs(run, tmp_path / "out")
    comments, rows = _read(csv_file)
    _check_rows(m, plans["p", "min_norm"].path, rows, np.full(m.n_legs, tau))
    units = _units(comments)
    assert len(units) == len(rows[0])
    eff = "N" if name == "rpr3_platform" else "N m"
    assert units[-m.n_legs:] == [eff] * m.n_legs
    angles = [u for nm, u in zip(rows[0], units) if nm in ("phi", "vphi", "aphi")]
    assert angles == (["rad", "rad/s", "rad/s^2"] if m.dof == 3 else [])


def test_json_names_efforts_without_a_unit_and_gives_units(capsys):
    """`tau_peak_N_m` on a linear actuator held newtons: `tau_peak` beside it (the old key
    kept) and a `units` field, per actuator."""
    assert main(["plan", "--model", "prr3_platform", "--move", "low", "--tau-max", "60",
                 "--grid", "200", "--json", "--quiet"]) == 0
    res = json.loads(capsys.readouterr().out)
    assert res["units"] == {"tau_max": ["N"] * 3, "tau_peak": ["N"] * 3,
                            "tau_rate": ["N/s"] * 3}
    row = res["paths"][0]
    for key in ("min_norm", "min_max"):
        assert row[key]["tau_peak"] == row[key]["tau_peak_N_m"]
        assert 60.0 * (1 - 1e-6) <= max(row[key]["tau_peak"]) <= 60.0 * (1 + 1e-9)
    assert row["kinematic"]["tau_peak"] == row["kinematic"]["tau_peak_N_m"]
    assert main(["plan", "--move", "high", "--grid", "200", "--json", "--quiet"]) == 0
    assert json.loads(capsys.readouterr().out)["units"]["tau_peak"] == ["N m"] * 3


def test_text_gives_each_kind_its_unit():
    """A model with both kinds (one revolute, two linear actuators): the limits and every peak
    by kind, never one unit for all."""
    peak = [5.0, 40.0, 50.0]
    res = {"model": "mixed", "tau_max": [6.0, 60.0, 60.0], "margin": 1.0, "grid": 10,
           "units": {"tau_max": ["N m", "N", "N"], "tau_peak": ["N m", "N", "N"],
                     "tau_rate": ["N m/s", "N/s", "N/s"]},
           "paths": [{"name": "p", "length_m": 0.1, "kinds": ["line"], "stops_m": [0, 0.1],
                      "min_max": {"duration_s": 0.2, "tau_peak": peak, "compute_ms": 1.0,
                                  "grid": 10, "max_speed_m_s": 1.0},
                      "smooth_min_max": {"duration_s": 0.3, "strict_duration_s": 0.2,
                                         "grid": 10, "tau_rate": [300.0, 3000.0, 3000.0],
                                         "solve_time_s": 1.0}}]}
    res["closed_loop"] = {"p": [{"margin": 1.0, "duration_s": 0.2,
                    **{law: {"rmse_m": 1e-4, "max_error_m": 2e-4, "tau_peak": peak,
                             "saturated": 0, "outcome": "completed"} for law in ("na", "apd")}}]}
    text = format_report(res)
    assert text.startswith("model mixed: tau_max [6.0 N m, 60.0 N, 60.0 N], margin")
    assert "(peak |tau| 5.000 N m, 50.000 N, top speed" in text
    assert "|dtau/dt| <= 300 N m/s, 3000 N/s;" in text
    assert text.count("peak |tau| 5.000 N m, 50.000 N,") == 3         # the plan, NA and APD


def test_torque_figure_axis_and_messages_by_kind():
    from pm2dof.figures.experiment import _plt
    from pm2dof.figures.planning import _torques
    plt = _plt()
    for name, label in (("rrr3_platform", "torque (N m)"), ("prr3_platform", "force (N)")):
        m = pm2dof.load_model(name)
        mv = m.spec.trajectories["low"]
        path = pm2dof.TaskPath.line(mv["start"], mv["end"], orientation_length(m))
        plan = pm2dof.plan_time_optimal(m, path, grid=100, split="min_norm")
        fig = _torques(plt, m, "low", {"min_norm": plan}, plan.tau_max)
        assert [ax.get_ylabel() for ax in fig.axes] == [label]
        plt.close(fig)
    with pytest.raises(PlanError, match=r"finite limits > 0 N \(one per actuator\)"):
        pm2dof.plan_time_optimal(m, path, tau_max=[1.0, -1.0, 1.0])
    with pytest.raises(PlanError, match=r"finite rates > 0 N/s, got"):
        pm2dof.plan_smooth(m, path, tau_rate=-1.0)
