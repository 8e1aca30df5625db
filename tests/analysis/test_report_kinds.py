# `pm2dof report` on the new kinds (issue 26): it crashed on a platform (ik given (x, y)).
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
