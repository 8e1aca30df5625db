# The generated Jacobians against central differences of the SymPy dynamics at 50 digits.
"""The C Jacobians (CasADi AD of the factored dynamics) against central differences of the
monolithic xedd of :class:`pm2dof.derive.dynamics.Dynamics` (another expression tree of the
same dynamics, no AD), lambdified for mpmath and evaluated at 50 digits at random states.

d xedd / d xe differentiates xedd(ik(xe)) through SymPy's ik (never W), so the chain rule
through the pose is checked as well. The reference's own error: a central difference with
step h = 1e-15 max(1, |x_j|) is off by h^2 |f'''| / 6 (< 1e-25 of the entries here, whose
third derivatives are at most ~1e8 for the smallest parameters) plus the rounding of 50-digit
arithmetic divided by h (1e-35): far below the tolerance. The C result is double precision
from double inputs: its error is a few ulps times the condition of the computation; 1e-10 of
each block's largest entry (the checks of the model functions use 1e-12 for single
expressions; the Jacobians chain several) is ~1e6 ulps of margin, and a wrong entry is off by
O(1). (SymPy's symbolic Jacobians of xedd took 5-11 s a model to differentiate and lambdify,
for the same check.)

Two models (the paper's and the five-bar; the derivation is the one
tests/derive/test_generated.py builds: tests/derivations.py, the same worker under
``make test``).
"""
import mpmath
import numpy as np
import pytest

import pm2dof
from tests import derivations

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

DPS = 50
STEP = 1e-15   # central differences: h = STEP max(1, |x_j|)
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
    xedd = derivations.lambdify([list(s.q), list(s.xed), list(s.tau_a), list(s.theta)],
                                dyn.xedd, mods)
    ik = derivations.lambdify([list(s.xe)], kin.ik(), mods)
    m, n = len(s.xe), len(s.tau_a)
    cut = np.cumsum([m, m, n])                  # z = [xe, xed, tau_a, theta]

    def f(z):                                   # xedd(ik(xe), xed, tau_a, theta), mpmath
        xe, xed, tau, theta = (list(b) for b in np.split(np.array(z, dtype=object), cut))
        return list(xedd(list(ik(xe)), xed, tau, theta))

    def jacobians(z):
        """{block: d xedd / d block (m, size)} by central differences of f at z (mpmath)."""
        cols = []
        for j in range(len(z)):
            h = mpmath.mpf(STEP) * max(1, abs(z[j]))
            up, down = list(z), list(z)
            up[j] += h
            down[j] -= h
            cols.append([(a - b) / (2 * h) for a, b in zip(f(up), f(down))])
        J = np.array([[float(c[i]) for c in cols] for i in range(m)])
        return dict(zip(("d_xe", "d_xed", "d_tau_a", "d_theta"), np.split(J, cut, axis=1)))
    return model, jacobians


def _mpv(x):
    return [mpmath.mpf(float(v)) for v in np.ravel(x)]


def test_jacobians_match_central_differences_of_sympy_at_50_digits(setup, sample_xe,
                                                                      random_theta):
    model, jacobians = setup
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
        want = jacobians(_mpv(np.concatenate([xe, xed, tau, theta])))
        got = model.forward_dynamics_jacobians(xe, xed, tau, theta)._asdict()
        for key, w in want.items():
            err = float(np.max(np.abs(got[key] - w)))
            scale = float(np.max(np.abs(w)))
            assert err <= TOL * scale, (
                f"{model.name}: {key}: C vs 50-digit differences of SymPy: max error "
                f"{err:.3e} > {TOL:g} * {scale:.3e} at xe={xe.tolist()}, xed={xed.tolist()}, tau={tau.tolist()}, "
                f"theta={theta.tolist()}\nC=\n{got[key]}\nreference=\n{w}")
        checked += 1
        if checked == 3:
            break
    assert checked == 3, f"{model.name}: only {checked} states clear of zero joint velocity"
