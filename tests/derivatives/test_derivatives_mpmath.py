# The generated Jacobians against the SymPy derivative evaluated with mpmath at 30 digits.
"""The C Jacobians (CasADi AD of the factored dynamics) against SymPy's own derivative of the
monolithic xedd of :class:`pm2dof.derive.dynamics.Dynamics` (another expression tree of the
same dynamics), lambdified for mpmath and evaluated at 30 digits at random states.

d xedd / d xe is SymPy's d xedd / d q times SymPy's d ik(xe) / d xe (never W), so the chain
rule through the pose is checked as well. The C result is double precision from double
inputs: its error is a few ulps times the condition of the computation; 1e-10 of each block's
largest entry (the checks of the model functions use 1e-12 for single expressions; the
Jacobians chain several) is ~1e6 ulps of margin, and a wrong entry is off by O(1).

Two models (the paper's and the five-bar: the differentiation and lambdify take ~5-11 s each;
the derivation itself is the one tests/derive/test_generated.py builds: tests/derivations.py,
the same worker under ``make test``).
"""
import mpmath
import numpy as np
import pytest
import sympy

import pm2dof
from tests import derivations

DPS = 30
TOL = 1e-10
MODELS = ("shang2010", "fivebar")


def _sgn(v):
    return int(v > 0) - int(v < 0)   # derive.symbols.sgn, sgn(0) = 0; its derivative is 0


@pytest.fixture(scope="module", params=MODELS)
def setup(request):
    model = pm2dof.load_model(request.param)
    d = derivations.derivation(model.spec)   # Derivation(spec), shared (tests/derivations.py)
    s, kin, dyn = d.sym, d.kin, d.dyn
    mods = [{"sgn": _sgn}, "mpmath"]
    jac = sympy.lambdify([list(s.q), list(s.xed), list(s.tau_a), list(s.theta)],
                         [dyn.xedd.jacobian(v) for v in (s.q, s.xed, s.tau_a, s.theta)],
                         modules=mods, cse=True)
    ik = sympy.lambdify([list(s.xe)], [kin.ik(), kin.ik().jacobian(s.xe)], modules=mods,
                        cse=True)
    return model, jac, ik


def _mpv(x):
    return [mpmath.mpf(float(v)) for v in np.ravel(x)]


def _float(m):
    return np.array([[float(m[i, j]) for j in range(m.cols)] for i in range(m.rows)])


def test_jacobians_match_sympy_at_30_digits(setup, sample_xe, random_theta):
    model, jac, ik = setup
    mpmath.mp.dps = DPS
    rng = np.random.default_rng(2121)
    checked = 0
    for xe in sample_xe(model, 2121, 12):
        q = model.ik(xe)
        phi = rng.uniform(-np.pi, np.pi)
        xed = rng.uniform(0.1, 0.4) * np.array([np.cos(phi), np.sin(phi)])
        if np.min(np.abs(model.S(q) @ xed)) < 0.05:    # clear of friction's sign jump
            continue
        tau, theta = rng.uniform(-3, 3, model.n_legs), random_theta(model, rng)
        q_mp, dq_dxe = ik(_mpv(xe))
        Jq, Jv, Jt, Jth = jac(list(q_mp), _mpv(xed), _mpv(tau), _mpv(theta))
        want = {"d_xe": _float(Jq * dq_dxe), "d_xed": _float(Jv), "d_tau_a": _float(Jt),
                "d_theta": _float(Jth)}
        got = model.forward_dynamics_jacobians(xe, xed, tau, theta)._asdict()
        for key, w in want.items():
            err = float(np.max(np.abs(got[key] - w)))
            scale = float(np.max(np.abs(w)))
            assert err <= TOL * scale, (
                f"{model.name}: {key}: C vs 30-digit SymPy: max error {err:.3e} > {TOL:g} * "
                f"{scale:.3e} at xe={xe.tolist()}, xed={xed.tolist()}, tau={tau.tolist()}, "
                f"theta={theta.tolist()}\nC=\n{got[key]}\nSymPy=\n{w}")
        checked += 1
        if checked == 3:
            break
    assert checked == 3, f"{model.name}: only {checked} states clear of zero joint velocity"
