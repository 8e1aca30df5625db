# The job of `pm2dof plan`: a PlanRun carrying its model, the closed loop once, its provenance.
"""``pm2dof.planning.jobs.run_plan`` returns a :class:`PlanRun`: the model it planned on, the
numbers (the command's ``--json``) with the closed loop in them once (``run.closed_loop`` is
that entry, not a second copy), the plans and the provenance the CSVs and figures carry (with
the command line given to it). The text and the CSV format stay in
:mod:`pm2dof.planning.report`."""
import pytest

import pm2dof
from pm2dof.planning import report
from pm2dof.planning.jobs import PlanRun, run_plan, write_plan_csvs


@pytest.mark.parametrize("name", ["rrr3_platform", "prr_point", "shang2010_vertical"])
def test_run_plan_carries_its_model_and_the_closed_loop_once(name, tmp_path):
    """A platform, a linear-actuator model and the gravity model: their first move, min-max,
    tracked in closed loop at one margin."""
    m = pm2dof.load_model(name)
    move = next(iter(m.spec.trajectories))
    cmd = ["pm2dof", "plan", "--model", name, "--closed-loop"]
    r = run_plan(m, move=move, grid=100, splits=("min_max",), closed_loop_margins=(1.0,),
                 command_line=cmd)
    assert isinstance(r, PlanRun) and r.model is m
    assert r.closed_loop is r.summary["closed_loop"] and list(r.closed_loop) == [move]
    assert [row["margin"] for row in r.closed_loop[move]] == [1.0]
    kinematic = "kinematic" in r.summary["paths"][0]
    assert set(r.plans) == {(move, "min_max")} | ({(move, "kinematic")} if kinematic else set())
    assert r.summary["provenance"]["command_line"] == r.provenance["command_line"] == cmd
    assert r.provenance["model"] == name
    text = report.format_report(r.summary)
    assert f"closed loop on {move}" in text and text.count(" NA : RMSE ") == 1
    written = write_plan_csvs(r, tmp_path)
    assert sorted(p.name for p in written) == sorted(f"plan_{n}_{k}.csv" for n, k in r.plans)
    head = written[-1].read_text().splitlines()
    assert f"# model = {name}" in head and f"# model_file_sha256 = {m.spec.file_sha256}" in head


def test_without_closed_loop_the_numbers_hold_none():
    m = pm2dof.load_model()
    r = run_plan(m, move="low", grid=100, splits=("min_norm",))
    assert "closed_loop" not in r.summary and r.closed_loop == {}
    assert "closed loop" not in report.format_report(r.summary)


def test_the_report_module_holds_no_job():
    """The jobs left the report module: it renders and writes, it does not plan."""
    for name in ("run_plan", "plan_paths", "closed_loop", "write_plan_csvs", "model_moves"):
        assert not hasattr(report, name), name
