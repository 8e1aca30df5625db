# The torque splits in closed loop (issue 11, part 4): the comparison docs/results-redundancy.md reports.
import json

import numpy as np

import pm2dof
from pm2dof.analysis.splits import split_comparison, tau_max_sweep
from pm2dof.cli import main


def test_min_max_uses_less_peak_torque_and_delays_saturation():
    m = pm2dof.load_model()
    free = split_comparison(m, speeds=["high"], splits=("min_norm", "min_max"))["high"]
    for ctrl in ("apd", "na"):
        mn, mm = free[ctrl]["min_norm"], free[ctrl]["min_max"]
        assert mn["n_saturated"] == mm["n_saturated"] == 0
        assert mm["peak_tau"] < mn["peak_tau"]
    # a limit between the two peaks: min-norm must clip, min-max need not
    na = free["na"]
    level = 0.5 * (na["min_norm"]["peak_tau"] + na["min_max"]["peak_tau"])
    r = split_comparison(m, level, speeds=["high"], splits=("min_norm", "min_max"),
                         controllers=("na",))["high"]["na"]
    assert r["min_norm"]["n_saturated"] > 0
    assert r["min_max"]["n_saturated"] == 0
    assert r["min_max"]["peak_tau"] <= level


def test_preload_keeps_its_floor_and_costs_torque():
    m = pm2dof.load_model()
    r = split_comparison(m, preload=[1.0, 1.0, 1.0], speeds=["high"], splits=("min_norm", "preload"),
                         controllers=("na",))["high"]["na"]
    assert r["preload"]["n_preload_infeasible"] == 0
    assert r["preload"]["rms_tau"] > r["min_norm"]["rms_tau"]


def test_sweep_marks_preloads_that_do_not_fit():
    m = pm2dof.load_model()
    sw = tau_max_sweep(m, [0.8, 7.0], preload=[1.0, 1.0, 1.0], controllers=("na",))
    assert np.isnan(sw["na"]["preload"]["rmse"][0]) and np.isfinite(sw["na"]["preload"]["rmse"][1])
    assert sw["na"]["min_norm"]["n_saturated"][0] > sw["na"]["min_norm"]["n_saturated"][1]


def test_splits_command(tmp_path, capsys):
    assert main(["splits", "--tau-max", "7.0", "--preload", "1.0", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert set(out["results"]["high"]["na"]) == {"min_norm", "min_max", "preload"}
    assert out["tau_max"] == [7.0, 7.0, 7.0]
    assert main(["splits", "--tau-max", "0.5", "--preload", "1.0"]) == 2
    assert "preload" in capsys.readouterr().err
