# Printed and JSON units by actuator kind; a platform's phi error in table3; splits on a
# robot without a redundant actuator.
import json
import re
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof.analysis.experiment import format_table3, table3, table3_json
from pm2dof.analysis.maps import maps_summary, workspace_maps
from pm2dof.analysis.reference_file import reference_summary
from pm2dof.analysis.splits import format_splits, run_splits
from pm2dof.infra.results import dumps

DOCS = Path(__file__).resolve().parents[2] / "docs"


def _phi_rmse(r):
    """sqrt(mean (phi_d - phi)^2) over the move's samples, from the rollout's own arrays."""
    d = r.xd[:r.n_move, 2] - r.xe[:r.n_move, 2]
    return float(np.sqrt(np.sum(d ** 2) / len(d)))


@pytest.mark.parametrize("name", ["rrr4_platform", "prr3_platform"])
def test_table3_gives_a_platforms_phi_error_in_rad(name):
    m = pm2dof.load_model(name)
    res = table3(m, speeds=["low"])
    num = table3_json(res)
    low = num["low"]
    for law in ("apd", "na", "na_no_adaptation"):
        assert low[f"{law}_phi_rmse"] == pytest.approx(_phi_rmse(res["low"][law]), rel=1e-12)
        assert low["units"][f"{law}_phi_rmse"] == "rad" and low["units"][f"{law}_rmse"] == "m"
    assert 0 < low["na_phi_rmse"] < 1e-2
    text = format_table3(num, paper=False)
    assert "RMSE of the platform's orientation phi, rad, simulated:" in text
    row = text.splitlines()[text.splitlines().index(
        "RMSE of the platform's orientation phi, rad, simulated:") + 2]
    assert row.split() == ["low", *(f"{low[f'{x}_phi_rmse']:.4e}"
                                    for x in ("apd", "na", "na_no_adaptation"))], row
    json.loads(dumps(num))
    if name == "rrr4_platform":          # the numbers docs/results-paper.md quotes
        page = " ".join((DOCS / "results-paper.md").read_text().split())
        def sci(x):
            return f"{x:.2e}".replace("e-0", "e-")
        assert (f"low-speed move {sci(low['apd_phi_rmse'])} rad (APD) and "
                f"{sci(low['na_phi_rmse'])} rad (NA)") in page


def test_table3_of_a_point_has_no_phi_and_names_its_units():
    m = pm2dof.load_model("shang2010_vertical")
    low = table3_json(table3(m, speeds=["low"]))["low"]
    assert not any("phi" in k for k in low) and not any("phi" in k for k in low["units"])
    assert low["trajectory_duration"] == low["trajectory_duration_s"] > 0
    assert low["units"]["trajectory_duration"] == "s" and low["units"]["apd_rmse"] == "m"
    assert "phi" not in format_table3({"low": low}, paper=False)


@pytest.mark.parametrize("name, unit, redundant", [
    ("prr3_platform", "N", False),       # linear actuators, no redundancy
    ("rrr3_platform", "N m", False),     # revolute, no redundancy
    ("shang2010_vertical", "N m", True),
])
def test_splits_print_each_kinds_unit_and_say_why_splits_agree(name, unit, redundant):
    m = pm2dof.load_model(name)
    res = run_splits(m)
    text = format_splits(res)
    lines = text.splitlines()
    assert "N*m" not in text and "inf." not in text and " inf" not in text
    assert f"tau_max = {np.round(res['tau_max'], 4).tolist()} {unit} (plant" in text
    assert f">= {np.round(res['preload'], 4).tolist()} {unit}" in text
    assert f"margin: the least of that margin over the move, {unit} (" in text
    assert f"peak |tau|, rms tau: {unit}." in text
    assert res["units"]["peak_tau"] == res["units"]["tau_max"] == unit
    assert res["units"]["rmse"] == "m"
    back = json.loads(dumps(res))
    assert back["units"]["preload_margin"] == unit
    if redundant:
        assert "note" not in res and not lines[0].startswith("model ")
        return
    assert lines[0] == res["note"] == (
        f"model {name!r} has no redundant actuator (3 actuators for 3 task coordinates): S^T "
        f"tau = u has one solution, so every split commands the same torques, and the preload "
        f"split cannot choose signs (its 'preload unmet' samples are where that solution "
        f"reverses a sign or falls short of the preload).")
    for speed, by_ctrl in res["results"].items():    # what the note says holds
        for ctrl, by_split in by_ctrl.items():
            assert by_split["min_norm"]["rmse"] == by_split["min_max"]["rmse"], (speed, ctrl)
    if name == "prr3_platform":          # docs/results-redundancy.md's example
        r = res["results"]["low"]["apd"]["preload"]
        page = " ".join((DOCS / "results-redundancy.md").read_text().split())
        assert (f"on `prr3_platform`'s low-speed move {r['n_preload_infeasible']} of its "
                f"samples, margin −{-r['preload_margin']:.1f} N for APD") in page


def test_simulate_json_has_unit_free_keys_and_units(tmp_path):
    m = pm2dof.load_model("prr3_platform")
    low = pm2dof.model_move(m, "low")
    res = {"apd": pm2dof.simulate(m, pm2dof.APDController(m), low)}
    row = reference_summary(res, m)["apd"]
    assert row["rmse"] == row["rmse_m"] == res["apd"].rmse
    assert row["max_error"] == row["max_error_m"]
    assert row["max_phi_error"] == row["max_phi_error_rad"] > 0
    assert row["phi_rmse"] == pytest.approx(_phi_rmse(res["apd"]), rel=1e-12)
    assert row["units"] == {"rmse": "m", "max_error": "m", "rmse_m": "m", "max_error_m": "m",
                            "peak_tau": "N", "n_saturated": "1", "n_singular": "1",
                            "samples": "1", "max_phi_error_rad": "rad", "max_phi_error": "rad",
                            "phi_rmse": "rad"}
    m2 = pm2dof.load_model()
    row2 = reference_summary({"apd": pm2dof.simulate(m2, pm2dof.APDController(m2),
                                                     pm2dof.paper_move("low"))}, m2)["apd"]
    assert row2["units"]["peak_tau"] == "N m" and "phi_rmse" not in row2


def test_maps_json_has_unit_free_area_keys_and_a_platforms_units():
    m = pm2dof.load_model("rpr3_platform")
    s = maps_summary(m, workspace_maps(m, 9))
    assert s["reachable_area"] == s["reachable_area_m2"] and s["clear_area"] == s["clear_area_m2"]
    assert s["units"]["reachable_area"] == s["units"]["clear_area"] == "m^2"
    assert s["units"]["force_min_max"] == "N, N m (phi)"
    assert s["units"]["accel_min_norm"] == "m/s^2, rad/s^2 (phi)"
    p = pm2dof.load_model("fivebar")
    assert maps_summary(p, workspace_maps(p, 9))["units"]["force_min_max"] == "N"


def test_report_help_speaks_of_any_model(capsys):
    from pm2dof import cli
    with pytest.raises(SystemExit):
        cli.main(["report", "--help"])
    out = " ".join(capsys.readouterr().out.split())
    assert "paper's path" not in out and "sin(qb-qa)" not in out
    assert re.search(r"Me at its own pose \(the middle of its first move", out)
