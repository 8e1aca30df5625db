# The demo's "plant truth = nominal model" row: theta set by name on every kind of model.
import tomllib
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof.analysis.experiment import sensitivity_variants, table3
from pm2dof.control.controllers import APDController, NAController
from pm2dof.control.trajectory import model_move

LABEL = "plant truth = nominal model"


def _nominal_from_the_file(m):
    """The plant written straight from the model file's [nominal] table (read here with
    tomllib, field by field, never through theta's order): no payload, no Stribeck excess."""
    with open(m.spec.path, "rb") as f:
        nominal = tomllib.load(f)["nominal"]
    return pm2dof.plant_truth(m, payload_mass=0.0, fs=[0.0] * m.n_legs, **nominal)


@pytest.mark.parametrize("name", ["rrr4_platform", "rpr3_platform", "shang2010_vertical",
                                  "shang2010"])
def test_the_nominal_row_is_the_plant_written_from_the_nominal_table(name):
    """A platform's m_p, mx_p, ... and the gravity term's kappa sit between gamma and fv in
    theta: sliced as [alpha, beta, gamma, fv, fc], fv received them (the 4-RRR's demo row was
    refused as an unstable plant, the 3-RPR's and the vertical robot's were another plant)."""
    m = pm2dof.load_model(name)
    kw = dict(sensitivity_variants(m))[LABEL]
    want = _nominal_from_the_file(m)
    truth = kw["truth"]
    assert sorted(truth) == sorted(want)
    for k in want:
        np.testing.assert_array_equal(np.asarray(truth[k]), np.asarray(want[k]), err_msg=k)
    # the row itself: the demo's rollouts equal simulate() with that plant, bit for bit
    row = table3(m, speeds=["low"], **kw)["low"]
    traj = model_move(m, "low")
    for law, ctrl in (("apd", APDController(m)), ("na", NAController(m))):
        assert row[law].rmse == pm2dof.simulate(m, ctrl, traj, truth=want).rmse, law
    assert np.isfinite(row["apd"].rmse) and row["apd"].rmse < 1e-4, row["apd"].rmse
    if name != "shang2010":        # docs/results-paper.md quotes the new kinds' APD numbers
        page = " ".join((Path(__file__).resolve().parents[2] / "docs" / "results-paper.md")
                        .read_text().split())
        assert f"`{name}` {row['apd'].rmse:.2e}".replace("e-0", "e-") + " m" in page
