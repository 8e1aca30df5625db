# The controllers' parameter rules (pm2dof.control.rules): one table for Python and the export.
"""Every field of every controller's parameter layout has a rule; the Python constructors
refuse what the firmware review found the exported init accepting (a singularity threshold of
-1, closure_tol <= 0, preload_sign 0.5, a preload < 0 or > tau_max, T = 1e-30, tau_max = 1e30),
each with a typed error naming the field, the entry, the value and the rule. The exported C
applies the same table (tests/export)."""
import math

import numpy as np
import pytest

import pm2dof
from pm2dof import APDController, CTCController, NAController
from pm2dof.control import rules
from pm2dof.core.errors import ArgumentError, GainError
from pm2dof.core.layout import Layout


@pytest.fixture(scope="module")
def m():
    return pm2dof.load_model()


@pytest.mark.parametrize("name", ["shang2010", "rrr4_platform", "prr3_platform",
                                  "shang2010_vertical"])
def test_every_parameter_field_has_a_rule(name):
    model = pm2dof.load_model(name)
    for law in ("na", "apd", "ctc", "lqr"):
        for field, _ in model.manifest["layouts"][f"{law}_params"]:
            assert isinstance(rules.rule(law, field), rules.Rule), (law, field)


@pytest.mark.parametrize("kw, text", [
    (dict(sample_period=1e-30), r"NAController: sample_period = 1e-30 s must be in \[1e-06, 1\]"),
    (dict(sample_period=5.0), r"sample_period = 5.0 s must be in \[1e-06, 1\]"),
    (dict(tau_max=1e30), r"tau_max\[0\] \(leg 1\) = 1e\+30 N m must be in \(0, 1e\+06\] \(and 2"),
    (dict(tau_max=[30.0, 30.0, math.inf]), r"tau_max must be one finite number"),
    (dict(preload=[0.0, -1.0, 0.0]), r"preload\[1\] \(leg 2\) = -1.0 N m must be >= 0 and "
                                     r"< tau_max = 30 N m"),
    (dict(preload=[0.0, 0.0, 31.0]), r"preload\[2\] \(leg 3\) = 31.0 N m must be >= 0 and "
                                     r"< tau_max = 30 N m"),
    (dict(preload_sign=[1.0, 0.5, 1.0]), r"preload_sign\[1\] \(leg 2\) = 0.5 must be -1 or \+1"),
])
def test_the_constructors_refuse_what_switches_a_guard_off(m, kw, text):
    for cls in (NAController, APDController, CTCController):
        with pytest.raises(ArgumentError, match=text.replace("NAController", cls.__name__)):
            cls(m, **kw)


def test_a_linear_actuators_limit_is_in_newtons():
    with pytest.raises(ArgumentError, match=r"tau_max\[0\] \(leg 1\) = 2000000.0 N must be"):
        NAController(pm2dof.load_model("prr3_platform"), tau_max=2e6)


@pytest.mark.parametrize("field, value, text", [
    ("sing_threshold", -1.0, r"limits.singularity_threshold = -1.0 must be in \(0, 1\)"),
    ("parallel_sing_threshold", 1.0,
     r"limits.parallel_singularity_threshold = 1.0 must be in \(0, 1\)"),
    ("closure_tol", 0.0, r"sensing.closure_tolerance = 0.0 must be in \(0, 0.1\]"),
    ("closure_tol", -1.0, r"sensing.closure_tolerance = -1.0 must be in \(0, 0.1\]"),
    ("vel_alpha", 0.0, r"velocity filter gain = 0.0 must be in \(0, 1\]"),
    ("freeze_saturated", 0.5, r"freeze_when_saturated = 0.5 must be 0 or 1"),
    ("T", math.nan, r"sample_period = nan must be finite"),
])
def test_a_packed_vector_is_checked_entry_by_entry(m, field, value, text):
    """What the model hands the constructors (thresholds, closure tolerance) and what it derives
    (the velocity gain) is checked too, as the exported init checks it."""
    c = NAController(m)
    p = np.array(c.params)
    p[c.params_layout.slices[field]] = value
    with pytest.raises(ArgumentError, match=text):
        rules.check_params("NAController", "na", c.params_layout, p)
    assert rules.violations("na", c.params_layout, p) == [(field, 0, value)] or math.isnan(value)
    assert rules.violations("na", c.params_layout, c.params) == []


def test_gains_keep_their_error_type_and_reason(m):
    c = NAController(m)
    p = np.array(c.params)
    p[c.params_layout.slices["Gamma"].start + 9] = -1.0
    with pytest.raises(GainError, match=r"Gamma\[9\] \(fv1\) = -1.0 must be >= 0: Gamma must be "
                                        r"positive semi-definite"):
        rules.check_params("NAController", "na", c.params_layout, p,
                           {"Gamma": m.param_names})


def test_violations_list_every_entry_in_layout_order():
    lay = Layout("na_params", [("Kd", 2), ("tau_max", 2), ("preload", 2)])
    p = lay.pack(Kd=[1.0, -1.0], tau_max=[5.0, 2e6], preload=[6.0, 0.0])
    assert rules.violations("na", lay, p) == [("Kd", 1, -1.0), ("tau_max", 1, 2e6),
                                              ("preload", 0, 6.0)]


def test_conditions_read_as_the_docs_say():
    assert rules.rule("na", "Kd").condition == "> 0"
    assert rules.rule("na", "Gamma").condition == ">= 0"
    assert rules.rule("na", "T").condition == "in [1e-06, 1]"
    assert rules.rule("apd", "sing_threshold").condition == "in (0, 1)"
    assert rules.rule("ctc", "preload").condition == ">= 0 and < tau_max"
    assert rules.rule("lqr", "preload_sign").condition == "-1 or +1"
    assert rules.rule("NAController", "freeze_saturated").condition == "0 or 1"
    with pytest.raises(ArgumentError, match="no parameter rule for 'na' field 'K'"):
        rules.rule("na", "K")
