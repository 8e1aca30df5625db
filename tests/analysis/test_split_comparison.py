# The torque splits in closed loop: the comparison docs/results-redundancy.md reports.
import json

import numpy as np

import pm2dof
from pm2dof.analysis.splits import split_comparison, tau_max_sweep
from pm2dof.cli import main
from pm2dof.control.trajectory import model_move


def test_min_max_uses_less_peak_torque_and_delays_saturation():
    """Min-max is the least peak per sample (tests/control/test_splits.py), not over a closed
    loop: each sample's torques change the tracking and so the later samples' demands. On the
    high move APD's min-max run peaks lower (6.90 against 7.11 N m, docs/results-redundancy.md),
    NA's higher (7.56 against 7.41 N m). Where it peaks lower, a limit between the two peaks
    clips min-norm and not min-max."""
    m = pm2dof.load_model()
    free = split_comparison(m, speeds=["high"], splits=("min_norm", "min_max"))["high"]
    for ctrl in ("apd", "na"):
        mn, mm = free[ctrl]["min_norm"], free[ctrl]["min_max"]
        assert mn["n_saturated"] == mm["n_saturated"] == 0
    lower = [c for c in ("apd", "na")
             if free[c]["min_max"]["peak_tau"] < free[c]["min_norm"]["peak_tau"]]
    assert "apd" in lower, {c: (free[c]["min_norm"]["peak_tau"], free[c]["min_max"]["peak_tau"])
                            for c in free}
    for ctrl in lower:
        # a limit between the two peaks: min-norm must clip, min-max need not
        c = free[ctrl]
        level = 0.5 * (c["min_norm"]["peak_tau"] + c["min_max"]["peak_tau"])
        r = split_comparison(m, level, speeds=["high"], splits=("min_norm", "min_max"),
                             controllers=(ctrl,))["high"][ctrl]
        assert r["min_norm"]["n_saturated"] > 0, ctrl
        assert r["min_max"]["n_saturated"] == 0, ctrl
        assert r["min_max"]["peak_tau"] <= level, ctrl


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


def test_zero_preload_rows_say_what_they_count(capsys):
    """With the default preload 0 at 6 N m the preload rows of the low-speed
    move count infeasible samples and peak at exactly tau_max while nothing is clipped. That is
    the split keeping the signs (+, +, +), and its fallback (largest worst-case margin) putting an
    actuator at the limit: the table must say so, and its margin column shows the reversal."""
    assert main(["splits", "--tau-max", "6.0"]) == 0
    out = capsys.readouterr().out
    assert "every tau_i keeps the sign (+, +, +) with |tau_i| >= [0.0, 0.0, 0.0] N m" in out
    assert "a preload of 0 still keeps the signs" in out
    assert "largest worst-case margin" in out and "without clipping it" in out
    rows = [line.split() for line in out.splitlines() if line.startswith("low ")]
    preload = [r for r in rows if r[2] == "preload"]
    assert len(preload) == 2
    for r in preload:
        saturated, infeasible, margin, peak = int(r[5]), int(r[6]), float(r[7]), float(r[8])
        assert saturated == 0 and infeasible > 0 and margin < 0 and peak == 6.0, r
    assert all(r[7] == "-" for r in rows if r[2] != "preload")


def test_preload_margin_is_the_least_signed_margin_of_the_torques():
    """``preload_margin`` against the run's own torques; >= 0 exactly when no sample is
    preload-infeasible (low-speed move, preload 0: feasible at 30 N m, not at 6 N m)."""
    m = pm2dof.load_model()
    sign = np.array([1.0, 1.0, 1.0])
    for level, feasible in ((None, True), (6.0, False)):
        r = split_comparison(m, level, preload=0.0, preload_sign=sign, speeds=["low"],
                             splits=("preload",), controllers=("na",))["low"]["na"]["preload"]
        assert (r["n_preload_infeasible"] == 0) == feasible
        assert (r["preload_margin"] >= -1e-9) == feasible, r
    ctrl = pm2dof.NAController(m, tau_max=np.full(3, 6.0), split="preload",
                               preload=np.zeros(3), preload_sign=sign)
    run = pm2dof.simulate(m, ctrl, model_move(m, "low"))
    assert r["preload_margin"] == np.min(run.tau_a[:run.n_move] * sign)


def test_splits_json_names_the_signs(capsys):
    assert main(["splits", "--tau-max", "7.0", "--preload-sign", "1", "1", "1", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["preload_sign"] == [1.0, 1.0, 1.0] and out["preload"] == [0.0, 0.0, 0.0]
    assert "preload_margin" in out["results"]["low"]["na"]["preload"]
    assert "preload_margin" not in out["results"]["low"]["na"]["min_norm"]
