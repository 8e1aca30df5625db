# The planning numbers docs/results-planning.md quotes, recomputed: none can go stale.
"""The durations table (1000 grid points), the closed-loop table and the numbers quoted beside
them, and the smoothed variant's durations are recomputed here and must appear in the page as
it prints them. Timings (compute time, IPOPT's solve time, the benchmark) depend on the machine
and are not checked: the page quotes one run with its command."""
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof.planning.jobs import closed_loop, plan_paths
from pm2dof.planning.pathfile import NamedPath, read_path_file

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

PAGE = (Path(__file__).resolve().parents[2] / "docs" / "results-planning.md").read_text()
FLAT = " ".join(PAGE.split())
#: the table's rows, in order: (path, tau_max)
ROWS = [("line", 30.0), ("line", 6.0), ("pick_and_place", 30.0), ("pick_and_place", 6.0),
        ("curve", 30.0), ("curve", 6.0)]



@pytest.fixture(scope="module")
def m(paper_model):
    return paper_model


def _item(m, name):
    if name == "line":
        mv = m.spec.trajectories["high"]
        kin = {k: mv[k] for k in ("v_max", "a_max", "j_max")}
        return NamedPath(name, pm2dof.TaskPath.line(mv["start"], mv["end"]), kin, None)
    return read_path_file(name)


@pytest.fixture(scope="module")
def table(m):
    out = {}
    for name, tau in ROWS:
        res, _ = plan_paths(m, [_item(m, name)], tau_max=tau, grid=1000)
        out[name, tau] = res["paths"][0]
    return out


def _cells(row):
    return [c.strip() for c in row.strip().strip("|").split("|")]


def test_the_durations_table(table):
    head = PAGE.index("| path | τ_max |")
    rows = [ln for ln in PAGE[head:].splitlines()[2:2 + len(ROWS)]]
    for (name, tau), row in zip(ROWS, rows):
        r = table[name, tau]
        cells = _cells(row)
        assert cells[1] == f"{tau:g} N·m", (name, cells)
        kin = r["kinematic"]
        peak = max(kin["tau_peak_N_m"]["min_norm"])
        assert cells[2].startswith(f"{kin['duration_s']:.4f} s"), (name, tau, cells[2])
        assert f"{peak:.3g} N·m" in cells[2] and (("infeasible" in cells[2]) == (peak > tau))
        assert cells[3] == f"{r['min_norm']['duration_s']:.4f} s", (name, tau, cells[3])
        assert cells[4] == f"{r['min_max']['duration_s']:.4f} s", (name, tau, cells[4])
        assert cells[5].strip("*") == f"{r['saving_min_max_percent']:.1f} %", (name, tau)
    length = {n: table[n, 30.0]["length_m"] for n in ("line", "pick_and_place", "curve")}
    assert f"{length['line']:.4f} m" in rows[0] and f"{length['pick_and_place']:.3f} m" in rows[2]
    assert f"{length['curve']:.3f} m" in rows[4]


def test_the_numbers_quoted_beside_the_table(table):
    line6, line30 = table["line", 6.0], table["line", 30.0]
    save = {k: table[k]["saving_min_max_percent"] for k in table}
    assert (f"the time-optimal plan takes {line6['min_max']['duration_s']:.3f} s with the whole "
            f"redundancy" in FLAT)
    assert f"min-max buys {save['line', 30.0]:.1f}–{save['line', 6.0]:.1f} %" in FLAT
    assert (f"**{save['pick_and_place', 30.0]:.1f} % at 30 N·m and "
            f"{save['pick_and_place', 6.0]:.1f} % at 6 N·m**" in FLAT)
    kin = line30["kinematic"]["duration_s"]
    assert round(kin / line30["min_max"]["duration_s"]) == 4 and "made 4× faster" in FLAT


def test_the_closed_loop_numbers(m, sci):
    """The table at 6 N m on the paper's line (NA and APD, min-max, margins 1.0 0.9 0.8), the
    errors at 30 N m, and NA on the pick-and-place cycle at 6 N m."""
    line = _item(m, "line").path
    rows = closed_loop(m, line, 6.0, "min_max", (1.0, 0.9, 0.8))
    for r in rows:
        na, apd = r["na"], r["apd"]
        want = (f"| {r['margin']:.1f} | {r['duration_s']:.4f} s | {sci(na['rmse_m'])} m, "
                f"{sci(na['max_error_m'])} m | {na['saturated']} | {sci(apd['rmse_m'])} m, "
                f"{sci(apd['max_error_m'])} m | {apd['saturated']} |")
        assert want in PAGE, want
        assert max(na["tau_peak_N_m"] + apd["tau_peak_N_m"]) == pytest.approx(6.0, abs=5e-4)
    fast = closed_loop(m, line, 30.0, "min_max", (1.0, 0.9))
    assert (f"At 30 N·m ({fast[0]['duration_s']:.4f} s) the errors are "
            f"{sci(fast[0]['na']['rmse_m'], 1)} m (margin 1.0) and "
            f"{sci(fast[1]['na']['rmse_m'], 1)} m (0.9)" in FLAT)
    pick = closed_loop(m, read_path_file("pick_and_place").path, 6.0, "min_max", (1.0, 0.9))
    assert (f"NA: {sci(pick[0]['na']['rmse_m'])} m at margin 1.0, "
            f"{sci(pick[1]['na']['rmse_m'])} m at 0.9" in FLAT)


def test_the_smoothed_variant(m):
    """plan_smooth (IPOPT, 200 requested points, the default tau_rate) against the strict plan
    on the same grid: the paper's line at 6 and 30 N m, the cycle at 6 N m."""
    line = _item(m, "line").path
    cycle = read_path_file("pick_and_place").path
    got = {key: pm2dof.plan_smooth(m, path, tau, "min_max")
           for key, path, tau in (("line6", line, 6.0), ("line30", line, 30.0),
                                  ("cycle6", cycle, 6.0))}

    def pct(p):
        return 100 * (p.duration / p.info["strict_duration"] - 1)
    a, b, c = got["line6"], got["line30"], got["cycle6"]
    assert (f"the paper's line at 6 N·m takes {a.duration:.4f} s instead of "
            f"{a.info['strict_duration']:.4f} s (+{pct(a):.1f} %" in FLAT)
    assert (f"at 30 N·m (1500 N·m/s) {b.duration:.4f} s instead of "
            f"{b.info['strict_duration']:.4f} s (+{pct(b):.1f} %)" in FLAT)
    assert (f"the pick-and-place cycle at 6 N·m {c.duration:.3f} s instead of "
            f"{c.info['strict_duration']:.4f} s on its {c.info['grid']}-point grid "
            f"(+{pct(c):.1f} %" in FLAT)
    assert np.isfinite([p.duration for p in got.values()]).all()


def test_what_a_coarse_grid_gives_is_stated_with_its_numbers(m):
    """The page said "a coarse grid gives a longer plan, never a shorter one",
    which two coarse grids of a user's spline contradicted; it now states what holds and the
    counterexample, recomputed here (the statement itself: test_planning_refine.py)."""
    assert "never a shorter one" not in FLAT
    spline = pm2dof.TaskPath.spline([(0.18, 0.20), (0.22, 0.13), (0.27, 0.21), (0.31, 0.15)])
    d2, d5 = (pm2dof.plan_time_optimal(m, spline, 5.0, "min_max", grid=g).duration
              for g in (2, 5))
    assert d2 < d5
    assert f"2 points give {d2:.4f} s and 5 points {d5:.4f} s" in FLAT
