# The numbers the README and the docs quote, recomputed: a cheap number cannot go stale.
"""Every number in the README comes with the command that reproduces it; the
cheap ones are recomputed here (Table 3, the move durations, the type II minimum on both grids,
the capability ratio) and must appear in the pages, formatted as the pages print them.
Timings (the benchmark) are machine-dependent and are not checked here: the benchmark page
quotes one run with its command.
"""
import re
from pathlib import Path

import pytest

import pm2dof
from pm2dof.analysis.experiment import table3, table3_json
from pm2dof.analysis.maps import maps_summary, workspace_maps
from pm2dof.analysis.report import model_report
from pm2dof.control.trajectory import line_profile

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text()
DOCS = {p.stem: p.read_text() for p in (ROOT / "docs").glob("*.md")}



@pytest.fixture(scope="module")
def m(paper_model):
    return paper_model


@pytest.fixture(scope="module")
def t3(m):
    return table3_json(table3(m))


def test_table3_rows(t3, sci):
    page = DOCS["results-paper"]
    for speed in ("low", "high"):
        r = t3[speed]
        row = next(line for line in page.splitlines() if line.startswith(f"| {speed} ("))
        cells = [c.strip() for c in row.split("|")[2:6]]
        assert cells == [sci(r["apd_rmse"]), sci(r["na_rmse"]), sci(r["na_no_adaptation_rmse"]),
                         f"{r['rpe_percent']:.1f} %"], (speed, cells)


def test_readme_tour_numbers(t3, sci):
    h = t3["high"]
    want = (f"RMSE of {sci(h['na_rmse'])} m against APD's {sci(h['apd_rmse'])} m, a "
            f"{h['rpe_percent']:.1f} % reduction")
    assert want in " ".join(README.split()), want


def test_move_durations(t3):
    page = " ".join(DOCS["results-paper"].split())
    for speed in ("low", "high"):
        traj = pm2dof.paper_move(speed)
        prof = line_profile(**pm2dof.PAPER_MOVES[speed])
        assert f"S-curve {prof.duration:.4f} s" in page, speed
        assert (f"{len(traj.t)} samples, t = 0 … {t3[speed]['trajectory_duration_s']:.3f} s"
                in page), speed


def test_type2_minimum_and_capability_ratio_on_both_grids(m):
    report = model_report(m)
    rep_min = float(re.search(r"type II .*: min ([0-9.]+)", report)[1])
    n_points = int(re.search(r"over (\d+) grid points", report)[1])
    s = maps_summary(m, workspace_maps(m))["over_clear_workspace"]
    guide = " ".join(DOCS["guide"].split())
    assert (f"at or above {rep_min:.3f} on `pm2dof report`'s grid ({n_points} points" in guide)
    assert f"and {s['type2']['min']:.3f} on `pm2dof maps`' finer grid" in guide
    ratio = s["force_ratio"]
    row = next(line for line in DOCS["results-redundancy"].splitlines()
               if line.startswith("| ratio min-max / min-norm"))
    assert [c.strip().strip("*") for c in row.split("|")[2:5]] == \
        [f"{ratio[k]:.3f}" for k in ("min", "median", "max")], row


def test_deploying_double_rmse_is_simulates(m):
    """docs/deploying.md's single-precision table: its double column is pm2dof.simulate's
    (the exported C equals it to 1e-12, tests/export); the single column comes from a C build
    (`pm2dof export --precision single`, its ctest) and is regenerated with it."""
    page = DOCS["deploying"]
    for speed in ("high", "low"):
        for law, cls in (("NA", pm2dof.NAController), ("APD", pm2dof.APDController),
                         ("CTC", pm2dof.CTCController)):
            r = pm2dof.simulate(m, cls(m), pm2dof.paper_move(speed)).rmse
            assert f"| {speed} | {law} | {r:.4e} m |" in page, (speed, law, f"{r:.4e}")


@pytest.mark.parametrize("study, better", [("paper_redesign", {"la": 0.236, "lb": 0.32}),
                                           ("rrr4_platform_legs", {"la": 0.15, "lb": 0.25})])
def test_results_design_tables(study, better, sci):
    """docs/results-design.md's tables: each study's objectives at the model file's own design
    and at the rounded design of the front the page names, with the relative change, as the
    page prints them (the fronts themselves come from runs of minutes, quoted with their
    commands)."""
    from pm2dof.synthesis import evaluate_design, read_design_study
    s = read_design_study(study)
    m = pm2dof.load_model(s.model_path)
    here, there = evaluate_design(m, s), evaluate_design(m.at_design(better), s)
    fmt = {"dexterity_mean": "{:.4f}", "force_min": "{:.1f}" if study == "paper_redesign"
           else "{:.2f}", "duration_high": "{:.5f}"}

    def cell(name, v):
        return sci(v, 3) if name == "rmse_na_high" else fmt[name].format(v)

    page = DOCS["results-design"]
    rows = {line.split("|")[1].strip(): [c.strip() for c in line.split("|")[2:-1]]
            for line in page.splitlines() if line.startswith("| ")}
    names = [o.name for o in s.objectives]
    mine = next(v for k, v in rows.items() if k.startswith("the ") and len(v) == len(names)
                and v[0] == cell(names[0], here[names[0]]))
    assert mine == [cell(n, here[n]) for n in names]
    label = ", ".join(f"{k} = {v:g} m" for k, v in better.items())
    assert rows[label] == [f"{cell(n, there[n])} ({100 * (there[n] - here[n]) / abs(here[n]):+.1f}"
                           f" %)" for n in names], label
