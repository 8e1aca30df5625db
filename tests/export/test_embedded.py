# make embedded's results (pm2dof.export.embedded): the JSON fields and the table, without QEMU.
"""What ``make embedded`` writes into ``results.json`` for a target's comparison with the host,
and the table it prints from them: the largest effort difference under a unit-free key with its
unit, and under its former key (``max_abs_diff_Nm``, which a linear actuator's forces in N
contradicted) beside it. The runs themselves need arm-none-eabi-gcc and QEMU (docs/deploying.md
gives their numbers); these tests build the records the way ``run_embedded`` does."""
import json

import pytest

import pm2dof
from pm2dof.core.task import effort_unit
from pm2dof.export.embedded import _agreement, format_results

#: (model, its actuators' effort unit): revolute (the paper's robot), a platform on linear
#: actuators, the paper's robot under gravity
KINDS = [("shang2010", "N m"), ("prr3_platform", "N"), ("shang2010_vertical", "N m")]


@pytest.mark.parametrize("name, unit", KINDS)
def test_the_difference_has_a_unit_free_key_with_its_unit(name, unit):
    assert effort_unit(pm2dof.load_model(name)) == unit
    rec = json.loads(json.dumps(_agreement(216, 330, 0.043, True, 3, unit)))
    assert rec["max_abs_diff"] == 0.043
    assert rec["max_abs_diff_Nm"] == 0.043                # the former key, kept beside it
    assert rec["units"] == {"max_abs_diff": unit, "max_abs_diff_Nm": unit}
    assert (rec["bit_identical"], rec["samples"], rec["statuses_equal"],
            rec["coulomb_flips"]) == (216, 330, True, 3)


@pytest.mark.parametrize("name, unit", KINDS)
def test_the_table_prints_the_difference_in_its_unit(name, unit):
    run = {"target": "Cortex-M4F (mps2-an386)", "precision": "single",
           **_agreement(141, 189, 0.043, True, 0, unit), "controller_code_bytes": 2048,
           "stack_painted_bytes": 672, "stack_static_bytes": {"na": 600},
           "instructions_per_step": {"na": {"min": 4000.0, "max": 4448.0, "mean": 4200.0}}}
    table = format_results({"runs": {"m4f-single": run}, "effort_unit": unit})
    assert f"141/189 identical, max 0.043 {unit} |" in table, table
