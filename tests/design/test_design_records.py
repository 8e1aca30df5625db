# A model at a design records it where files record their model, and a command reloads it there.
"""Identification files record their model (identification/model_ref.py); a model with a
[design] table at another design (Model.at_design) also records ``design``. A command reading
the file loads the file's model at that design; a model given at another design is refused,
naming both designs."""
import json

import pytest

import pm2dof
from pm2dof.identification.model_ref import mismatch, model_entries, model_for


@pytest.fixture(scope="module")
def models():
    m = pm2dof.load_model("shang2010_design")
    return m, m.at_design({"la": 0.25, "lb": 0.26})


def test_a_design_is_recorded_and_applied(models):
    m, m2 = models
    entries = model_entries(m2)
    assert json.loads(entries["design"]) == {"la": 0.25, "lb": 0.26, "b2x": 0.433}
    again = model_for(entries)                      # the file's model, at the file's design
    assert again.design.tolist() == [0.25, 0.26, 0.433]
    assert mismatch(m2, entries) is None


def test_another_design_is_refused(models):
    m, m2 = models
    msg = mismatch(m, model_entries(m2))
    assert msg and "'la': 0.25" in msg and "'la': 0.244" in msg
    with pytest.raises(pm2dof.ArgumentError, match="at design"):
        model_for(model_entries(m2), model=m)


def test_a_fixed_model_records_no_design():
    assert "design" not in model_entries(pm2dof.load_model("shang2010"))
