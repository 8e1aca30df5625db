# The factored W, Y, Me, Ce xed of a platform's hot paths against the monolithic SymPy matrices.
"""derive/factored.py composes a platform's W = rows J_i^-1 G_i, Wdot, Y = W^T Y_joint +
S^T Y_friction + Y_platform, Me = W^T M W + Mp and Ce xed = W^T (M Wdot xed + C qd) + Cp xed
(eqs. 7, 9, 12, 13) for the controller steps and the plant. The monolithic Dynamics.Y, .Me,
.Ce and Kinematics.W (which tests/derive/test_generated.py checks against mpmath) are the
reference: both forms, built from the same derivation, must agree to rounding at random
states (pose, velocity, reference motion, parameters) of every shipped platform."""
import casadi as ca
import numpy as np
import pytest

from pm2dof.core.model_file import read_model_file
from pm2dof.core.paths import SHIPPED_MODELS
from pm2dof.derive.factored import factored, regressor, task_inertia_coriolis
from tests import derivations

pytestmark = pytest.mark.slow     # derives platforms two ways with SymPy: make test-slow (CI)

PLATFORMS = [s for s in (read_model_file(p) for p in sorted(SHIPPED_MODELS.glob("*.toml")))
             if s.end_effector == "platform"]
RTOL = 1e-12        # relative to the largest entry of each matrix: rounding, not a model error


def _forms(d, monolithic):
    """CasADi function (xe, v, xrd, xrdd, theta) -> (W, Y, Me, Ce v) in one form."""
    m, p = d.m, len(d.spec.param_names)
    xe, v, xrd, xrdd = (ca.SX.sym(k, m) for k in ("xe", "v", "xrd", "xrdd"))
    theta = ca.SX.sym("theta", p)
    d.dyn.factored = False if monolithic else None
    try:
        Y, _, W = regressor(d, d.converter_xe(xe), v, xrd, xrdd)
        Me, Ce_v, _, _ = task_inertia_coriolis(d, d.converter_xe(xe), v, [(d.sym.theta, theta)])
    finally:
        del d.dyn.factored
    # a model with [design]: its design input too, set to the file's design by the caller
    return d.function("forms", [xe, v, xrd, xrdd, theta], [W, Y, Me, Ce_v],
                      ["xe", "v", "xrd", "xrdd", "theta"], ["W", "Y", "Me", "Ce_v"])


@pytest.mark.parametrize("spec", PLATFORMS, ids=[s.name for s in PLATFORMS])
def test_factored_platform_matches_monolithic(spec):
    assert PLATFORMS, "no shipped platform model"
    d = derivations.derivation(spec)   # shared with test_generated (tests/derivations.py)
    assert factored(d), f"{spec.name}: the hot paths should use the factored forms"
    f_fac, f_mono = _forms(d, monolithic=False), _forms(d, monolithic=True)
    rng = np.random.default_rng(26)
    home = np.asarray(spec.home, float)
    design = [] if spec.design is None else [np.array(spec.design.values)]
    checked = 0
    for _ in range(200):
        xe = home + rng.uniform([-0.03, -0.03, -0.15], [0.03, 0.03, 0.15])
        v, xrd, xrdd = (rng.uniform(-1, 1, 3) * s for s in ([0.5, 0.5, 2], [0.5, 0.5, 2], [10, 10, 40]))
        theta = rng.uniform(0.001, 1.0, len(spec.param_names))
        a = [np.asarray(x) for x in f_fac(xe, v, xrd, xrdd, theta, *design)]
        b = [np.asarray(x) for x in f_mono(xe, v, xrd, xrdd, theta, *design)]
        if not all(np.all(np.isfinite(x)) for x in b):
            continue                       # out of some leg's reach: no reference here
        for name, x, y in zip(("W", "Y", "Me", "Ce xed"), a, b):
            err = np.max(np.abs(x - y)) / np.max(np.abs(y))
            assert err < RTOL, f"{spec.name} {name} at xe={xe}: relative error {err:.2e}"
        checked += 1
        if checked == 20:
            return
    raise AssertionError(f"{spec.name}: only {checked} of 20 poses in reach")
