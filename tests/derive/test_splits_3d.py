# The splits of derive/splits.py for a platform's task dimension m = 3, against HiGHS and SLSQP.
"""The redundancy resolutions for S (n, 3), as CasADi functions of the derivation, against
independent solvers (the 2-D case is tests/control/test_splits.py, through the generated C):

* min-max: the optimum t* of the LP min t s.t. S^T tau = u, |tau_i| <= t w_i (HiGHS), at random
  poses and at degenerate ones the random cases never hit (two generators parallel, three
  coplanar: several torques free at the dual optimum), and u = 0;
* the 3-D zonotope's facets (derive/planning.force_polygon): max_j |N_j . u| / h_j is t*
  (the zonotope's gauge), and the min-norm slabs hold exactly the min-norm torques' limits;
* preload: S^T tau = u always; where the preload holds, the optimum of the QP (SLSQP, and the
  KKT certificate); where it cannot, the LP's largest worst-case margin (HiGHS).
"""
import functools

import casadi as ca
import numpy as np
import pytest
from scipy.optimize import linprog, lsq_linear, minimize

from pm2dof.derive.planning import facet_count, force_polygon
from pm2dof.derive.splits import min_max, min_norm, preload

pytestmark = pytest.mark.slow     # LP checks of the 3-D min-max split: make test-slow (CI)

M = 3
HIGHS = {"primal_feasibility_tolerance": 1e-10, "dual_feasibility_tolerance": 1e-10}


@functools.lru_cache(maxsize=None)
def _functions(n):
    """The splits as CasADi functions of S (n, 3), built once per n (n = 5: ~1.3 s; a CasADi
    Function is immutable, so the tests may share it)."""
    S, u, w = ca.SX.sym("S", n, M), ca.SX.sym("u", M), ca.SX.sym("w", n)
    sigma, p = ca.SX.sym("sigma", n), ca.SX.sym("p", n)
    tau_pl, mode = preload(S, u, w, sigma, p)
    return (ca.Function("mm", [S, u, w], list(min_max(S, u, w))),
            ca.Function("mn", [S, u], [min_norm(S, u)]),
            ca.Function("pl", [S, u, w, sigma, p], [tau_pl, mode]),
            ca.Function("poly", [S, w], list(force_polygon(S, w))))


def _np(*values):
    return [np.asarray(v, dtype=float).ravel() for v in values]


def _lp_min_max(S, u, w):
    n = len(w)
    A = np.zeros((2 * n, n + 1))
    for i in range(n):
        A[2 * i, [i, n]] = 1.0, -w[i]
        A[2 * i + 1, [i, n]] = -1.0, -w[i]
    r = linprog(np.r_[np.zeros(n), 1.0], A_ub=A, b_ub=np.zeros(2 * n),
                A_eq=np.c_[S.T, np.zeros(M)], b_eq=u, bounds=[(None, None)] * (n + 1),
                method="highs", options=HIGHS)
    assert r.status == 0, r.message
    return r.fun


def _lp_max_margin(S, u, w, pre, sign):
    n = len(w)
    r = linprog(np.r_[np.zeros(n), -1.0], A_ub=np.c_[-np.diag(sign), np.ones(n)], b_ub=-pre,
                A_eq=np.c_[S.T, np.zeros(M)], b_eq=u, bounds=[(-a, a) for a in w] + [(None, None)],
                method="highs", options=HIGHS)
    return -r.fun if r.status == 0 else None


def _kkt_residual(S, tau, lo, hi, w):
    """Zero (to rounding) exactly when tau satisfies the KKT conditions of min |tau|^2 s.t.
    S^T tau = u, lo <= tau <= hi (bounded least squares over the multipliers)."""
    n = len(tau)
    at_lo, at_hi = tau <= lo + 1e-9 * w, tau >= hi - 1e-9 * w
    E = np.eye(n)
    A = np.c_[S, E[:, at_lo], -E[:, at_hi]]
    k = int(at_lo.sum() + at_hi.sum())
    r = lsq_linear(A, 2 * tau, bounds=([-np.inf] * M + [0.0] * k, [np.inf] * (M + k)),
                   method="bvls", tol=1e-14)
    return np.abs(A @ r.x - 2 * tau).max() / (2 * np.abs(tau).max())


def _check_min_max(f, S, u, w):
    tau, t = _np(*f(S, u, w))
    t_lp = _lp_min_max(S, u, w)
    info = (S.tolist(), u.tolist(), w.tolist())
    assert t[0] == pytest.approx(t_lp, rel=1e-9, abs=1e-12), info
    assert np.abs(S.T @ tau - u).max() <= 1e-11 * (np.abs(S).max() * np.abs(tau).max()
                                                   + np.abs(u).max()), info
    assert np.max(np.abs(tau) / w) <= t_lp * (1 + 1e-9) + 1e-12, info
    return tau, t_lp


@pytest.mark.parametrize("n", [4, 5])
def test_min_max_in_three_dimensions_is_the_lp_optimum(n):
    mm, mn, _, poly = _functions(n)
    rng = np.random.default_rng(n)
    for _ in range(150):
        S = rng.normal(size=(n, M))
        w = rng.uniform(5.0, 30.0, n)
        u = rng.normal(size=M) * rng.choice([5.0, 30.0, 100.0])
        tau, t_lp = _check_min_max(mm, S, u, w)
        tau_mn = _np(mn(S, u))[0]
        assert np.max(np.abs(tau) / w) <= np.max(np.abs(tau_mn) / w) * (1 + 1e-12)
        # the zonotope's facets: its gauge max_j |N_j . u| / h_j is the min-max ratio
        N_mn, h_mn, N_mm, h_mm = _np(*poly(S, w))
        F = facet_count(n, M)
        assert len(h_mm) == F and len(h_mn) == F
        N_mm, N_mn = N_mm.reshape(F, M), N_mn.reshape(F, M)
        np.testing.assert_allclose(np.linalg.norm(N_mm, axis=1), 1, rtol=1e-12)
        assert np.max(np.abs(N_mm @ u) / h_mm) == pytest.approx(t_lp, rel=1e-9)
        # the min-norm slabs: |N_j . u| / h_j = |tau_mn,j| / w_j
        assert np.max(np.abs(N_mn @ u) / h_mn) == pytest.approx(np.max(np.abs(tau_mn) / w),
                                                                rel=1e-9)


@pytest.mark.parametrize("n", [4, 5])
def test_min_max_in_three_dimensions_at_degenerate_poses(n):
    """Two generators parallel, or three coplanar (a free pair or triple at the dual optimum,
    the 2-D sub-problem in the facet's plane), and u = 0."""
    mm, _, _, poly = _functions(n)
    rng = np.random.default_rng(10 + n)
    free_seen = 0
    for k in range(200):
        S = rng.normal(size=(n, M))
        if k % 2:
            S[1] = S[0] * rng.choice([-1.0, 1.0]) * rng.uniform(0.5, 2.0)    # parallel pair
        else:
            S[2] = S[0] * rng.normal() + S[1] * rng.normal()                 # coplanar triple
        w = rng.uniform(5.0, 30.0, n)
        normal = np.cross(S[0], S[2] if k % 2 else S[1])                     # a facet's normal
        u = (rng.normal(size=M) * 30 if k % 4 < 2
             else np.cross(normal, rng.normal(size=M)) + rng.normal(size=M) * rng.choice([0, 1e-3]))
        tau, t_lp = _check_min_max(mm, S, u, w)
        free_seen += int(np.sum(np.abs(tau) < w * t_lp * (1 - 1e-6)) >= 2)
        N_mn, h_mn, N_mm, h_mm = _np(*poly(S, w))
        assert np.all(np.isfinite(N_mm)) and np.all(np.isfinite(h_mm))
        assert np.max(np.abs(N_mm.reshape(-1, M) @ u) / h_mm) == pytest.approx(t_lp, rel=1e-9)
    assert free_seen >= 20, f"the free-generator branch was exercised only {free_seen} times"
    tau, t = _np(*mm(rng.normal(size=(n, M)), np.zeros(M), np.full(n, 10.0)))
    assert t[0] == 0 and np.all(tau == 0)


def test_min_max_without_redundancy_is_the_unique_solution():
    mm, mn, _, _ = _functions(3)
    rng = np.random.default_rng(3)
    S, u, w = rng.normal(size=(3, M)), rng.normal(size=M), rng.uniform(1, 2, 3)
    tau, t = _np(*mm(S, u, w))
    np.testing.assert_allclose(tau, np.linalg.solve(S.T, u), rtol=1e-12)
    assert t[0] == pytest.approx(np.max(np.abs(tau) / w), rel=1e-14)


@pytest.mark.parametrize("n", [4, 5])
def test_preload_in_three_dimensions(n):
    _, _, pl, _ = _functions(n)
    rng = np.random.default_rng(20 + n)
    modes = [0, 0, 0]
    for _ in range(80):
        S = rng.normal(size=(n, M))
        w = rng.uniform(5.0, 30.0, n)
        u = rng.normal(size=M) * rng.choice([5.0, 30.0, 100.0])
        pre = rng.uniform(0, 0.3, n) * w
        sign = rng.choice([-1.0, 1.0], n)
        tau, mode = _np(*pl(S, u, w, sign, pre))
        mode = int(mode[0])
        modes[mode] += 1
        info = (S.tolist(), u.tolist(), w.tolist(), pre.tolist(), sign.tolist())
        assert np.abs(S.T @ tau - u).max() <= 1e-10 * (np.abs(S).max() * np.abs(tau).max()
                                                       + np.abs(u).max()), info
        lo, hi = np.where(sign > 0, pre, -w), np.where(sign > 0, w, -pre)
        margin = _lp_max_margin(S, u, w, pre, sign)
        if mode == 0:
            assert margin is not None and margin >= -1e-9 * w.max(), info
            assert np.all(tau >= lo - 1e-9 * w) and np.all(tau <= hi + 1e-9 * w), info
            assert _kkt_residual(S, tau, lo, hi, w) <= 1e-8, info
            r = minimize(lambda t: t @ t, np.clip(tau, lo, hi), jac=lambda t: 2 * t,
                         bounds=list(zip(lo, hi)), method="SLSQP",
                         constraints=[dict(type="eq", fun=lambda t: S.T @ t - u,
                                           jac=lambda t: S.T)],
                         options=dict(ftol=1e-15, maxiter=500))
            if r.status == 0 and np.abs(S.T @ r.x - u).max() < 1e-8:
                assert tau @ tau <= r.fun * (1 + 1e-8), info
        elif mode == 1:
            assert margin is not None and margin < 1e-9 * w.max(), info
            assert np.all(np.abs(tau) <= w * (1 + 1e-9)), info
            assert np.min(sign * tau - pre) == pytest.approx(margin, abs=1e-8 * w.max()), info
        else:
            assert margin is None and _lp_min_max(S, u, w) > 1, info
    assert min(modes) >= 3, f"every preload mode must be exercised: {modes}"
