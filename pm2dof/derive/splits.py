# Torque distribution among n redundant actuators: S^T tau = u, exact optima by finite enumeration.
"""Exact redundancy resolutions of S^T tau_a = u (eqs. 10, 21) as straight-line CasADi code.

Every option returns a tau with S^T tau = u (to rounding): the task-space behaviour is the
minimum-norm split's. The optima are exact because each problem is a linear (LP) or convex
quadratic (QP) programme whose optimum lies at one of finitely many "vertices", each fixed by
a choice of active constraints and one 2x2 linear solve; all are enumerated and the feasible
one with the best objective is kept (the first in enumeration order among equals).

* ``min_norm``  eq. 21: tau = S (S^T S)^-1 u.
* ``min_max``   the LP min t s.t. S^T tau = u, |tau_i| <= t w_i (w = tau_max), solved through
  its 2-D dual: the optimum lies on one of the n kink directions perp(w_j s_j), and
  complementary slackness gives tau (see :func:`min_max`).
* ``preload``   the QP min |tau|^2 s.t. S^T tau = u, p_i <= sigma_i tau_i <= w_i (each
  actuator keeps the sign sigma_i with at least the preload p_i). At the optimum some bounds
  are active (tau_A fixed) and the free torques are the minimum-norm solution of the rest:
  tau_F = S_F (S_F^T S_F)^-1 (u - S_A^T tau_A); all active sets of size <= n - 2 are
  enumerated. If no torque within the limits keeps the preload, the fallback is the LP
  max m s.t. S^T tau = u, sigma_i tau_i - p_i >= m, |tau_i| <= w_i: the largest worst-case
  preload margin the limits allow (vertices: one index free with the others at a margin or a
  limit, or one index at both a margin and a limit and two free). If even the limits cannot
  be met, the min-max torques are used (and clipped: status "saturated").

Candidate feasibility allows a violation of 1e-10 w_i (rounding at degenerate vertices).
"""
import itertools

import casadi as ca

from .factored import solve2

__all__ = ["SPLITS", "min_norm", "min_max", "preload", "preload_function"]

#: split name -> suffix of the generated function names (<law><suffix>_step)
SPLITS = {"min_norm": "", "min_max": "_minmax", "preload": "_preload"}
_TOL = 1e-10  # relative to w_i: admitted bound violation of a candidate (rounding only)
_FREE = 1e-12  # |g_i.l| <= _FREE |g_i| |l|: g_i counts as parallel to g_j (min_max)


def _solve2(a, b, rhs):
    """(x, y) with x a + y b = rhs (2-vectors), by Cramer's rule, and det."""
    det = a[0] * b[1] - a[1] * b[0]
    return (rhs[0] * b[1] - rhs[1] * b[0]) / det, (a[0] * rhs[1] - a[1] * rhs[0]) / det, det


def _best(cands, n):
    """The valid candidate with the smallest score (the first of equals): (tau, score, found)."""
    tau, score, found = ca.DM.zeros(n), ca.SX(ca.inf), ca.SX(0)
    for valid, sc, t in cands:
        take = ca.logic_and(valid, sc < score)   # NaN scores are never taken
        tau = ca.if_else(take, t, tau)
        score = ca.if_else(take, sc, score)
        found = ca.logic_or(found, valid)
    return tau, score, found


def min_norm(S, u):
    """tau = S (S^T S)^-1 u, the minimum-norm actuator torques (eq. 21), 2x2 in closed form."""
    return S @ solve2(S.T @ S, u)


def min_max(S, u, w):
    """The exact min over S^T tau = u of max_i |tau_i| / w_i. Returns (tau, t*).

    With g_i = w_i s_i (s_i row i of S) and tau_i = w_i y_i this is min |y|_inf s.t.
    sum_i y_i g_i = u, whose LP dual is max u.l s.t. sum_i |g_i.l| <= 1. The dual objective
    u.l / sum_i |g_i.l| is linear-fractional on each cone between the kinks g_i.l = 0, so its
    maximum lies on a kink, l = perp(g_j): t* = max_j |u.p_j| / sum_i |g_i.p_j|, n candidates
    (compared by cross-multiplying: one division). Complementary slackness gives the primal:
    y_i = t* sign(g_i.l) where g_i.l != 0, and the free y_i (g_i parallel to g_j, j included)
    share the remaining force along g_j equally in magnitude, which the optimality makes
    feasible (|y_i| <= t*).
    """
    n = S.shape[0]
    if n == 2:  # no redundancy: the torques are unique
        tau = min_norm(S, u)
        return tau, ca.mmax(ca.fabs(tau) / w)
    g = [w[i] * S[i, :].T for i in range(n)]
    best_num, best_den, best_p = ca.SX(0), ca.SX(1), ca.vertcat(-g[0][1], g[0][0])
    for j in range(n):
        p = ca.vertcat(-g[j][1], g[j][0])                    # perp(g_j), length |g_j|
        num = ca.fabs(u[0] * p[0] + u[1] * p[1])
        den = sum(ca.fabs(g[i][0] * p[0] + g[i][1] * p[1]) for i in range(n) if i != j)
        take = num * best_den > best_num * den               # t_j > t_best; first of equals
        best_num = ca.if_else(take, num, best_num)
        best_den = ca.if_else(take, den, best_den)
        best_p = ca.if_else(take, p, best_p)
    t = best_num / best_den
    lam = best_p * ca.sign(u[0] * best_p[0] + u[1] * best_p[1])   # the dual direction
    gp2 = best_p[0] ** 2 + best_p[1] ** 2
    a = [g[i][0] * lam[0] + g[i][1] * lam[1] for i in range(n)]
    gg = [g[i][0] ** 2 + g[i][1] ** 2 for i in range(n)]
    free = [a[i] ** 2 <= _FREE ** 2 * gg[i] * gp2 for i in range(n)]   # g_i parallel to g_j
    y_act = [ca.if_else(free[i], 0, t * ca.sign(a[i])) for i in range(n)]
    r = u - sum(y_act[i] * g[i] for i in range(n))             # parallel to g_j (optimality)
    gj = ca.vertcat(best_p[1], -best_p[0])                     # g_j back from its perp
    b = [(g[i][0] * gj[0] + g[i][1] * gj[1]) for i in range(n)]
    share = (r[0] * gj[0] + r[1] * gj[1]) / sum(ca.if_else(free[i], ca.fabs(b[i]), 0)
                                               for i in range(n))
    y = [ca.if_else(free[i], ca.sign(b[i]) * share, y_act[i]) for i in range(n)]
    return ca.vertcat(*[w[i] * y[i] for i in range(n)]), t


def _within(tau, lo, hi, w):
    """lo_i <= tau_i <= hi_i for all i, with the rounding allowance."""
    ok = ca.SX(1)
    for i in range(tau.shape[0]):
        ok = ca.logic_and(ok, ca.logic_and(tau[i] >= lo[i] - _TOL * w[i],
                                           tau[i] <= hi[i] + _TOL * w[i]))
    return ok


def _min_norm_on(S, u, fixed):
    """Minimum-norm tau with tau_i = value for (i, value) in ``fixed`` and S^T tau = u."""
    n = S.shape[0]
    free = [i for i in range(n) if i not in fixed]
    rhs = u - sum((S[i, :].T * v for i, v in fixed.items()), ca.DM.zeros(2))
    SF = ca.vertcat(*[S[i, :] for i in free])
    G = SF.T @ SF
    det = G[0, 0] * G[1, 1] - G[0, 1] * G[1, 0]
    tF = SF @ solve2(G, rhs)
    out = [None] * n
    for k, i in enumerate(free):
        out[i] = tF[k]
    for i, v in fixed.items():
        out[i] = v
    return ca.vertcat(*out), det


def _max_margin(S, u, w, sigma, p):
    """The LP max m s.t. S^T tau = u, sigma_i tau_i - p_i >= m, |tau_i| <= w_i: (tau, m, found)."""
    n = S.shape[0]
    s = [S[i, :].T for i in range(n)]
    cands = []

    def add(tau, m, det):
        margins = ca.vertcat(*[sigma[i] * tau[i] - p[i] for i in range(n)])
        valid = ca.logic_and(det != 0, _within(tau, -w, w, w))
        valid = ca.logic_and(valid, ca.mmin(margins) >= m - _TOL * ca.mmax(w))
        cands.append((valid, -m, tau))

    states = ("margin", "upper", "lower")
    for f in range(n):                       # one index free, the others at a margin or a limit
        rest = [i for i in range(n) if i != f]
        for combo in itertools.product(states, repeat=n - 1):
            st = dict(zip(rest, combo))
            M = [i for i in rest if st[i] == "margin"]
            fixed = {i: (w[i] if st[i] == "upper" else -w[i]) for i in rest if st[i] != "margin"}
            rhs = u - sum((s[i] * v for i, v in fixed.items()), ca.DM.zeros(2)) \
                - sum((s[i] * sigma[i] * p[i] for i in M), ca.DM.zeros(2))
            a = sum((s[i] * sigma[i] for i in M), ca.DM.zeros(2))  # tau_i = sigma_i (p_i + m)
            m, tf, det = _solve2(a, s[f], rhs)
            tau = ca.vertcat(*[tf if i == f else fixed[i] if i in fixed
                               else sigma[i] * (p[i] + m) for i in range(n)])
            add(tau, m, det)
    for j in range(n):                       # index j at a margin and a limit: m is fixed
        for lim in (1, -1):
            m = sigma[j] * lim * w[j] - p[j]
            rest = [i for i in range(n) if i != j]
            for free in itertools.combinations(rest, 2):
                others = [i for i in rest if i not in free]
                for combo in itertools.product(states, repeat=len(others)):
                    fixed = {j: lim * w[j]}
                    for i, state in zip(others, combo):
                        fixed[i] = {"upper": w[i], "lower": -w[i],
                                    "margin": sigma[i] * (p[i] + m)}[state]
                    rhs = u - sum((s[i] * v for i, v in fixed.items()), ca.DM.zeros(2))
                    x, y, det = _solve2(s[free[0]], s[free[1]], rhs)
                    tau = ca.vertcat(*[x if i == free[0] else y if i == free[1] else fixed[i]
                                       for i in range(n)])
                    add(tau, m, det)
    tau, neg_m, found = _best(cands, n)
    return tau, -neg_m, found


def preload(S, u, w, sigma, p):
    """Least-norm tau with S^T tau = u and p_i <= sigma_i tau_i <= w_i (sigma_i = +-1, p_i >= 0).

    Returns (tau, mode): mode 0 the preload holds, 1 the preload cannot be kept within the
    limits (the max-margin torques), 2 not even the limits can be met (min-max torques).
    """
    n = S.shape[0]
    lo = ca.vertcat(*[ca.if_else(sigma[i] > 0, p[i], -w[i]) for i in range(n)])
    hi = ca.vertcat(*[ca.if_else(sigma[i] > 0, w[i], -p[i]) for i in range(n)])
    cands = []
    for k in range(0, n - 1):                # active sets of size k <= n - 2
        for act in itertools.combinations(range(n), k):
            for sides in itertools.product(("lo", "hi"), repeat=k):
                fixed = {i: (lo[i] if side == "lo" else hi[i]) for i, side in zip(act, sides)}
                tau, det = _min_norm_on(S, u, fixed)
                valid = ca.logic_and(det != 0, _within(tau, lo, hi, w))
                cands.append((valid, ca.sumsqr(tau), tau))
    tau_q, _, held = _best(cands, n)
    tau_m, _, limited = _max_margin(S, u, w, sigma, p)
    tau_x, _ = min_max(S, u, w)
    tau = ca.if_else(held, tau_q, ca.if_else(limited, tau_m, tau_x))
    mode = ca.if_else(held, 0, ca.if_else(limited, 1, 2))
    return tau, mode


def preload_function(n, prefix):
    """``preload`` as one CasADi Function (S (n, 2), u, w, sigma, p) -> (tau, mode), for call
    nodes that are never inlined: its enumeration (up to a few hundred candidates for four legs)
    then appears once in the generated C, shared by every step that uses it."""
    S, u = ca.SX.sym("S", n, 2), ca.SX.sym("u", 2)
    w, sigma, p = ca.SX.sym("tau_max", n), ca.SX.sym("preload_sign", n), ca.SX.sym("preload", n)
    tau, mode = preload(S, u, w, sigma, p)
    return ca.Function(f"{prefix}_split_preload", [S, u, w, sigma, p], [tau, mode],
                       ["S", "u", "tau_max", "preload_sign", "preload"], ["tau_a", "mode"])
