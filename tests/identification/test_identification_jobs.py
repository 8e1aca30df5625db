# The job of `pm2dof identify fit`: the model it resolves, Table 3 handed in as numbers, --save.
"""``pm2dof.identification.jobs``: :func:`run_fit` returns a :class:`FitRun` carrying the Model
it resolved (from the log, when no model is given), :func:`with_table3` takes Table 3's
numbers (not a callback into the paper's experiment), :func:`save_fit` records the command
line it is given. The text and JSON stay in :mod:`pm2dof.identification.report`."""
import inspect
import json

import numpy as np
import pytest

import pm2dof
from pm2dof import cli
from pm2dof.identification import report
from pm2dof.identification.jobs import FitRun, run_fit, save_fit, with_table3
from pm2dof.infra.results import dumps


def test_run_fit_carries_the_model_its_log_records(tmp_path, capsys):
    """A linear-actuator model's log, fitted without naming a model: the run carries the model
    the log records, and its summary is the one `identify fit LOG --json` prints."""
    log = tmp_path / "run.csv"
    assert cli.main(["identify", "excite", "--model", "prr_point", "--duration", "2",
                     "--out", str(log)]) == 0
    capsys.readouterr()
    r = run_fit(log)
    assert isinstance(r, FitRun) and isinstance(r.model, pm2dof.Model)
    assert r.model.name == "prr_point" and r.summary["model"] == "prr_point"
    assert r.model.spec.formulation_sha256 == \
        pm2dof.load_model("prr_point").spec.formulation_sha256
    assert r.log.source == str(log) and r.seed_warning is None
    assert cli.main(["identify", "fit", str(log), "--json"]) == 0
    assert json.loads(capsys.readouterr().out) == json.loads(dumps(r.summary))


@pytest.mark.parametrize("name", ["shang2010_vertical", "rrr3_platform"])
def test_table3_is_handed_in_as_numbers_and_save_records_the_command_line(name, tmp_path):
    """The gravity model and a platform, simulated runs: Table 3's numbers (whatever computed
    them) go into the summary with the comparison of a log simulated with [plant]; the saved
    file carries the command line given to it."""
    assert not {"seed", "save"} & set(inspect.signature(run_fit).parameters)   # no callback
    r = run_fit(model=name, duration=2)
    assert r.model.name == name and "table3" not in r.summary
    numbers = {"high": {"nominal": {"apd_rmse": 1e-4}, "identified": {"apd_rmse": 2e-4}}}
    seeded = with_table3(r, numbers)
    assert seeded.summary["table3"] is numbers and seeded.model is r.model
    assert seeded.summary["table3_comparison"] == ("Table 3 runs on the model file's [plant], "
                                                   "the robot this log was simulated with")
    assert seeded.seed_warning is None and "table3" not in r.summary      # r is unchanged
    out = save_fit(seeded, tmp_path / "fit.json", ["pm2dof", "identify", "fit", "--save", "x"])
    d = json.loads(out.read_text())
    assert d["provenance"]["command_line"] == ["pm2dof", "identify", "fit", "--save", "x"]
    assert d["provenance"]["model"] == name and d["param_names"] == list(r.model.param_names)
    np.testing.assert_array_equal(d["theta0"], r.result.theta0)
    assert d["table3"] == numbers


def test_the_report_module_holds_no_job():
    """run_fit (a job) left the report module; load_theta (unused) is gone."""
    for name in ("run_fit", "FitReport", "load_theta"):
        assert not hasattr(report, name), name
