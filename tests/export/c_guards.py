# What the exported ctest prints about its guards, checked against pm2dof's own Python.
"""Helpers of tests/export: the ctest (tests/test_<name>.c) prints

* ``blocked qa ...`` and ``blocked project P freeze F: ... theta_hat ...``: NA on a robot held
  at its start while the reference moves on at 0.05 m/s along x for 10 s;
* ``refused <law> <what>: <rule text>``: what init refused, with the rule it names;
* ``status <code> <label>`` and ``version <pm2dof> <formulation>``.

:func:`check_guard_output` compares each with what pm2dof computes in Python (NAController's
step with the same inputs, pm2dof.control.rules, pm2dof.Status, the version and the
formulation hash), and :func:`rule_driver` writes a C program that applies the exported init
to parameter vectors at and around every rule's bounds.
"""
import math
import re

import numpy as np

import pm2dof
from pm2dof.control import rules
from pm2dof.core.layout import Layout
from pm2dof.core.version import __version__

SPEED = 0.05                     # m/s, as BLOCKED_SPEED of the ctest


def blocked_theta(model, qa, project, freeze):
    """theta_hat after NAController's steps of the ctest's blocked robot (same inputs)."""
    c = pm2dof.NAController(model, project=project, freeze_when_saturated=freeze,
                            on_singular="zero")
    move = pm2dof.model_move(model, "high")
    T = move.period
    x0 = np.array(move.xd[0])
    c.reset(np.array(qa))
    xd_dot = np.zeros(model.dof)
    xd_dot[0] = SPEED
    zero = np.zeros(model.dof)
    for k in range(int(10.0 / T + 0.5)):
        xd = x0.copy()
        xd[0] = x0[0] + SPEED * k * T
        c.step(np.array(qa), xd, xd_dot, zero)
    return c.theta_hat


def check_guard_output(out, name):
    """Assert that the ctest's printed guards (module doc) are pm2dof's."""
    m = pm2dof.load_model(name)
    qa = [float(v) for v in re.search(r"^blocked qa (.*)$", out, re.M)[1].split()]
    runs = re.findall(r"^blocked project (\d) freeze (\d): (\d+) of (\d+) samples saturated, "
                      r"(\d+) of them moved theta_hat; theta_hat (.*)$", out, re.M)
    assert len(runs) == 3, out[-3000:]
    for project, freeze, n_sat, n, moved, theta in runs:
        got = np.array([float(v) for v in theta.split()])
        want = blocked_theta(m, qa, project == "1", freeze == "1")
        np.testing.assert_array_equal(got, want, err_msg=f"{name} project {project} freeze "
                                                         f"{freeze}")
        assert int(n_sat) > 0.9 * int(n) and (int(moved) == 0) == (freeze == "1")
    refused = re.findall(r"^refused (\w+) (.*?): (.*)$", out, re.M)
    assert len(refused) >= 16, out[-3000:]
    for law, what, text in refused:
        field = text.split(":")[0]
        assert text == f"{field}: every entry finite and {rules.rule(law, field).condition}"
    labels = dict(re.findall(r"^status (-?\d+) (\w+)$", out, re.M))
    want = {str(int(s)): s.label for s in pm2dof.Status}
    want.update({"-1": "not_reset", "-2": "bad_params", "-3": "unknown", "6": "unknown",
                 "7": "unknown"})
    assert labels == want
    assert re.search(r"^version (\S+) (\S+)$", out, re.M).groups() == (
        __version__, m.spec.formulation_sha256)


def _cases(layout, law, defaults):
    """(offset, value) pairs at and around every rule's bounds, for the first and last entry of
    each field."""
    out = []
    for field, size in layout.fields:
        r = rules.rule(law, field)
        values = [math.nan, math.inf, -math.inf, 0.0, -1.0, 0.5, 1.0, 2.0, 1e-30, 1e30]
        for b in ([r.lo, r.hi] + list(r.values)):
            if math.isfinite(b):
                values += [b, math.nextafter(b, -math.inf), math.nextafter(b, math.inf)]
        for i in {0, size - 1}:
            off = layout.slices[field].start + i
            vals = list(values)
            if r.below:                       # preload against its tau_max
                t = defaults[layout.slices[r.below].start + i]
                vals += [t, math.nextafter(t, -math.inf)]
            out += [(off, v) for v in vals]
    return out


def _c_value(v):
    if math.isnan(v):
        return "(real)NAN"
    if math.isinf(v):
        return "(real)INFINITY" if v > 0 else "(real)-INFINITY"
    return f"(real){v.hex()}"


def rule_driver(name, laws):
    """(C source of a program that prints init's bad_param for each case, the offsets pm2dof's
    rules give in the same order): the parameter vector is the defaults with one entry
    changed."""
    m = pm2dof.load_model(name)
    ctrl = {"na": pm2dof.NAController(m), "apd": pm2dof.APDController(m),
            "ctc": pm2dof.CTCController(m)}
    lines = ["#include <math.h>", "#include <stdio.h>", f'#include "{name}_pm2dof.h"',
             f"typedef {name}_pm2dof_real real;", "int main(void)", "{"]
    want = []
    for law in laws:
        layout = Layout(law, m.manifest["layouts"][f"{law}_params"])
        if law in ctrl:
            defaults = np.array(ctrl[law].params)
        else:                           # the LQR's: the NA parameters' common fields
            na = ctrl["na"].params_layout.unpack(ctrl["na"].params)
            defaults = layout.pack(**{f: na[f] for f, _ in layout.fields})
        lines += ["    {", f"        static {name}_pm2dof_{law} c;",
                  f"        {name}_pm2dof_{law}_params p;"]
        for off, v in _cases(layout, law, defaults):
            lines += [f"        {name}_pm2dof_{law}_default_params(&p);",
                      f"        p.p[{off}] = {_c_value(v)};",
                      f"        {name}_pm2dof_{law}_init(&c, &p);",
                      f'        printf("%d\\n", {name}_pm2dof_{law}_bad_param(&c));']
            p = defaults.copy()
            p[off] = v
            bad = rules.violations(law, layout, p)
            want.append(layout.slices[bad[0][0]].start + bad[0][1] if bad else -1)
        lines.append("    }")
    lines += ["    return 0;", "}"]
    return "\n".join(lines) + "\n", want
