# `pm2dof report` on platforms, linear actuators, gravity: it crashed on a platform (ik of (x, y)).
import re

import numpy as np
import pytest

import pm2dof
from pm2dof.analysis.report import model_report, report_pose


@pytest.mark.parametrize("name", ["rpr3_platform", "prr_point"])
def test_report_prints_the_models_own_Me_and_the_rank_of_Y(name):
    m = pm2dof.load_model(name)
    text = model_report(m, samples=40)
    xe, _ = report_pose(m)
    assert len(xe) == m.dof
    Me = m.Me(m.ik(xe), m.theta_nominal)
    printed = re.search(r"Me = \[(\[.*?\])\] kg", text).group(1)
    rows = [[float(v) for v in r.split(", ")] for r in re.findall(r"\[([^\[\]]+)\]", printed)]
    np.testing.assert_allclose(rows, Me, atol=5e-5)          # printed to 4 decimals
    rank = re.search(r"rank (\d+) of (\d+)", text)
    assert int(rank.group(2)) == len(m.param_names) and 0 < int(rank.group(1)) <= len(m.param_names)


def test_printed_efforts_carry_the_actuators_unit():
    """A linear actuator's effort is a force: `plan` and `identify excite` printed "N m"."""
    from pm2dof.core.task import effort_unit
    from pm2dof.planning.report import format_report
    assert effort_unit(pm2dof.load_model("shang2010")) == "N m"
    assert effort_unit(pm2dof.load_model("rpr3_platform")) == "N"
    res = {"model": "prr_point", "tau_max": [300.0] * 3, "margin": 1.0, "grid": 10, "paths": []}
    assert format_report(res, effort_unit(pm2dof.load_model("prr_point"))).startswith(
        "model prr_point: tau_max [300.0, 300.0, 300.0] N, margin")
