# Torque distribution among n redundant actuators: S^T tau = u, exact optima by finite enumeration.
"""Exact redundancy resolutions of S^T tau_a = u (eqs. 10, 21) as straight-line CasADi code.

Every option returns a tau with S^T tau = u (to rounding): the task-space behaviour is the
minimum-norm split's. The optima are exact because each problem is a linear (LP) or convex
quadratic (QP) programme whose optimum lies at one of finitely many "vertices", each fixed by
a choice of active constraints and one m x m linear solve (m = 2 for a point end effector,
3 for a platform: the task dimension, the number of columns of S); all are enumerated and the
feasible one with the best objective is kept (the first in enumeration order among equals).

* ``min_norm``  eq. 21: tau = S (S^T S)^-1 u.
* ``min_max``   the LP min t s.t. S^T tau = u, |tau_i| <= t w_i (w = tau_max), solved through
  its m-D dual: the optimum lies on one of the facet normals of the zonotope
  {S^T tau : |tau_i| <= w_i} -- for m = 2 the n directions perp(w_j s_j), for m = 3 the
  n (n - 1) / 2 cross products (w_i s_i) x (w_j s_j) -- and complementary slackness gives tau
  (see :func:`min_max`).
* ``preload``   the QP min |tau|^2 s.t. S^T tau = u, p_i <= sigma_i tau_i <= w_i (each
  actuator keeps the sign sigma_i with at least the preload p_i). At the optimum some bounds
  are active (tau_A fixed) and the free torques are the minimum-norm solution of the rest:
  tau_F = S_F (S_F^T S_F)^-1 (u - S_A^T tau_A); all active sets of size <= n - m are
  enumerated. If no torque within the limits keeps the preload, the fallback is the LP
  max mu s.t. S^T tau = u, sigma_i tau_i - p_i >= mu, |tau_i| <= w_i: the largest worst-case
  preload margin the limits allow (vertices: m - 1 indices free with the others at a margin
  or a limit, or one index at both a margin and a limit and m free). If even the limits
  cannot be met, the min-max torques are used (and clipped: status "saturated").

Candidate feasibility allows a violation of 1e-10 w_i (rounding at degenerate vertices).
"""
import itertools

import casadi as ca

from .factored import solve_small

__all__ = ["min_norm", "min_max", "preload", "preload_function"]

# the splits' names and their functions' suffixes: pm2dof.core.contract.SPLITS
_TOL = 1e-10  # relative to w_i: admitted bound violation of a candidate (rounding only)
_FREE = 1e-12  # |g_i.l| <= _FREE |g_i| |l|: g_i counts as parallel to g_j (min_max)


def _solve_columns(cols, rhs):
    """(x_1..x_m, det) with sum_k x_k cols_k = rhs (m = 2 or 3 columns), by Cramer's rule."""
    if len(cols) == 2:
        a, b = cols
        det = a[0] * b[1] - a[1] * b[0]
        return [(rhs[0] * b[1] - rhs[1] * b[0]) / det, (a[0] * rhs[1] - a[1] * rhs[0]) / det], det
    det = _triple(*cols)
    return [_triple(*[rhs if k == j else c for k, c in enumerate(cols)]) / det
            for j in range(3)], det


def _dot(a, b):
    return sum(a[k] * b[k] for k in range(a.shape[0]))


def _cross(a, b):
    return ca.vertcat(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                      a[0] * b[1] - a[1] * b[0])


def _triple(a, b, c):
    """det [a b c] = a . (b x c)."""
    return _dot(a, _cross(b, c))


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
    """tau = S (S^T S)^-1 u, the minimum-norm actuator torques (eq. 21), m x m in closed form."""
    return S @ solve_small(S.T @ S, u)


def min_max(S, u, w):
    """The exact min over S^T tau = u of max_i |tau_i| / w_i. Returns (tau, t*).

    With g_i = w_i s_i (s_i row i of S) and tau_i = w_i y_i this is min |y|_inf s.t.
    sum_i y_i g_i = u, whose LP dual is max u.l s.t. sum_i |g_i.l| <= 1. The dual objective
    u.l / sum_i |g_i.l| is linear-fractional on each cone between the kinks g_i.l = 0, so its
    maximum lies on an edge of that arrangement: for m = 2 a kink l = perp(g_j) (n candidates,
    :func:`_min_max_2d`), for m = 3 the intersection of two kink planes, l = g_i x g_j (the
    normal of a facet of the zonotope, n (n - 1) / 2 candidates, :func:`_min_max_3d`).
    Candidates are compared by cross-multiplying (one division). Complementary slackness gives
    the primal: y_i = t* sign(g_i.l) where g_i.l != 0; the free y_i (g_i.l = 0) deliver the
    remaining force, which lies in the free generators' span, with |y_i| <= t* (the optimality
    makes that feasible): for m = 2 shared equally in magnitude along g_j, for m = 3 by the
    same problem one dimension down, in the plane l^perp.
    """
    n, m = S.shape
    if n == m:  # no redundancy: the torques are unique
        tau = min_norm(S, u)
        return tau, ca.mmax(ca.fabs(tau) / w)
    g = [w[i] * S[i, :].T for i in range(n)]
    if m == 2:
        y, t = _min_max_2d(g, u)
    elif m == 3:
        y, t = _min_max_3d(g, u)
    else:
        raise NotImplementedError(f"min_max split for task dimension {m}: only 2 and 3")
    return ca.vertcat(*[w[i] * y[i] for i in range(n)]), t


def _min_max_2d(g, u, first=None):
    """min |y|_inf s.t. sum_i y_i g_i = u for 2-vectors g_i (see :func:`min_max`): (y, t*).
    ``first``: the dual direction to start from (default perp(g_0)), which must be nonzero."""
    n = len(g)
    best_num, best_den = ca.SX(0), ca.SX(1)
    best_p = ca.vertcat(-g[0][1], g[0][0]) if first is None else first
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
    return y, t


def _min_max_3d(g, u):
    """min |y|_inf s.t. sum_i y_i g_i = u for 3-vectors g_i (see :func:`min_max`): (y, t*).

    The dual optimum l is a facet normal g_i x g_j of the zonotope (pairs of parallel
    generators, |l| <= _FREE |g_i| |g_j|, are never taken). The free generators (g_k.l = 0: i, j and any
    coplanar with them) carry the rest r, which lies in the plane l^perp; there it is the 2-D
    problem in the basis e1 = g_i / |g_i|, e2 = l x e1 / |l|. u = 0 gives tau = 0."""
    n = len(g)
    best_num, best_den = ca.SX(0), ca.SX(1)
    best_l, best_gi = _cross(g[0], g[1]), g[0]
    for i in range(n):
        for j in range(i + 1, n):
            l = _cross(g[i], g[j])                           # a facet normal, |g_i| |g_j| sin
            num = ca.fabs(_dot(u, l))
            den = sum(ca.fabs(_dot(g[k], l)) for k in range(n) if k not in (i, j))
            # t_ij > t_best (first of equals); a parallel pair's l is rounding noise: no facet
            facet = _dot(l, l) > _FREE ** 2 * _dot(g[i], g[i]) * _dot(g[j], g[j])
            take = ca.logic_and(facet, num * best_den > best_num * den)
            best_num = ca.if_else(take, num, best_num)
            best_den = ca.if_else(take, den, best_den)
            best_l = ca.if_else(take, l, best_l)
            best_gi = ca.if_else(take, g[i], best_gi)
    t = best_num / best_den
    lam = best_l * ca.sign(_dot(u, best_l))                  # the dual direction
    l2 = _dot(best_l, best_l)
    a = [_dot(g[k], lam) for k in range(n)]
    free = [a[k] ** 2 <= _FREE ** 2 * _dot(g[k], g[k]) * l2 for k in range(n)]
    y_act = [ca.if_else(free[k], 0, t * ca.sign(a[k])) for k in range(n)]
    r = u - sum(y_act[k] * g[k] for k in range(n))           # in the plane l^perp
    e1 = best_gi / ca.sqrt(_dot(best_gi, best_gi))
    e2 = _cross(best_l, e1) / ca.sqrt(l2)
    h = [ca.if_else(free[k], ca.vertcat(_dot(g[k], e1), _dot(g[k], e2)), ca.DM.zeros(2))
         for k in range(n)]
    first = ca.vertcat(0, ca.sqrt(_dot(best_gi, best_gi)))   # perp of g_i in (e1, e2)
    y_free, _ = _min_max_2d(h, ca.vertcat(_dot(r, e1), _dot(r, e2)), first)
    at_rest = ca.logic_and(ca.logic_and(u[0] == 0, u[1] == 0), u[2] == 0)
    y = [ca.if_else(at_rest, 0, ca.if_else(free[k], y_free[k], y_act[k])) for k in range(n)]
    return y, t


def _within(tau, lo, hi, w):
    """lo_i <= tau_i <= hi_i for all i, with the rounding allowance."""
    ok = ca.SX(1)
    for i in range(tau.shape[0]):
        ok = ca.logic_and(ok, ca.logic_and(tau[i] >= lo[i] - _TOL * w[i],
                                           tau[i] <= hi[i] + _TOL * w[i]))
    return ok


def _det(G):
    """det G for the m x m Gram matrices of the splits (m = 2, 3)."""
    if G.shape[0] == 2:
        return G[0, 0] * G[1, 1] - G[0, 1] * G[1, 0]
    return _triple(G[:, 0], G[:, 1], G[:, 2])


def _min_norm_on(S, u, fixed):
    """Minimum-norm tau with tau_i = value for (i, value) in ``fixed`` and S^T tau = u."""
    n, m = S.shape
    free = [i for i in range(n) if i not in fixed]
    rhs = u - sum((S[i, :].T * v for i, v in fixed.items()), ca.DM.zeros(m))
    SF = ca.vertcat(*[S[i, :] for i in free])
    G = SF.T @ SF
    det = _det(G)
    tF = SF @ solve_small(G, rhs)
    out = [None] * n
    for k, i in enumerate(free):
        out[i] = tF[k]
    for i, v in fixed.items():
        out[i] = v
    return ca.vertcat(*out), det


def _max_margin(S, u, w, sigma, p):
    """The LP max mu s.t. S^T tau = u, sigma_i tau_i - p_i >= mu, |tau_i| <= w_i:
    (tau, mu, found). A vertex has n + 1 - m active inequalities: m - 1 indices free and the
    others each at a margin or a limit, or one index at both (which fixes mu) and m free."""
    n, m = S.shape
    s = [S[i, :].T for i in range(n)]
    cands = []

    def add(tau, mu, det):
        margins = ca.vertcat(*[sigma[i] * tau[i] - p[i] for i in range(n)])
        valid = ca.logic_and(det != 0, _within(tau, -w, w, w))
        valid = ca.logic_and(valid, ca.mmin(margins) >= mu - _TOL * ca.mmax(w))
        cands.append((valid, -mu, tau))

    states = ("margin", "upper", "lower")
    for F in itertools.combinations(range(n), m - 1):   # free; the others at a margin or a limit
        rest = [i for i in range(n) if i not in F]
        for combo in itertools.product(states, repeat=len(rest)):
            st = dict(zip(rest, combo))
            M = [i for i in rest if st[i] == "margin"]
            fixed = {i: (w[i] if st[i] == "upper" else -w[i]) for i in rest if st[i] != "margin"}
            rhs = u - sum((s[i] * v for i, v in fixed.items()), ca.DM.zeros(m)) \
                - sum((s[i] * sigma[i] * p[i] for i in M), ca.DM.zeros(m))
            a = sum((s[i] * sigma[i] for i in M), ca.DM.zeros(m))  # tau_i = sigma_i (p_i + mu)
            (mu, *tF), det = _solve_columns([a] + [s[f] for f in F], rhs)
            tau = ca.vertcat(*[tF[F.index(i)] if i in F else fixed[i] if i in fixed
                               else sigma[i] * (p[i] + mu) for i in range(n)])
            add(tau, mu, det)
    for j in range(n):                       # index j at a margin and a limit: mu is fixed
        for lim in (1, -1):
            mu = sigma[j] * lim * w[j] - p[j]
            rest = [i for i in range(n) if i != j]
            for free in itertools.combinations(rest, m):
                others = [i for i in rest if i not in free]
                for combo in itertools.product(states, repeat=len(others)):
                    fixed = {j: lim * w[j]}
                    for i, state in zip(others, combo):
                        fixed[i] = {"upper": w[i], "lower": -w[i],
                                    "margin": sigma[i] * (p[i] + mu)}[state]
                    rhs = u - sum((s[i] * v for i, v in fixed.items()), ca.DM.zeros(m))
                    x, det = _solve_columns([s[f] for f in free], rhs)
                    tau = ca.vertcat(*[x[free.index(i)] if i in free else fixed[i]
                                       for i in range(n)])
                    add(tau, mu, det)
    tau, neg_mu, found = _best(cands, n)
    return tau, -neg_mu, found


def preload(S, u, w, sigma, p):
    """Least-norm tau with S^T tau = u and p_i <= sigma_i tau_i <= w_i (sigma_i = +-1, p_i >= 0).

    Returns (tau, mode): mode 0 the preload holds, 1 the preload cannot be kept within the
    limits (the max-margin torques), 2 not even the limits can be met (min-max torques).
    """
    n, m = S.shape
    lo = ca.vertcat(*[ca.if_else(sigma[i] > 0, p[i], -w[i]) for i in range(n)])
    hi = ca.vertcat(*[ca.if_else(sigma[i] > 0, w[i], -p[i]) for i in range(n)])
    cands = []
    for k in range(0, n - m + 1):            # active sets of size k <= n - m
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


def preload_function(n, prefix, m):
    """``preload`` as one CasADi Function (S (n, m), u, w, sigma, p) -> (tau, mode), for call
    nodes that are never inlined: its enumeration (up to a few hundred candidates for four legs)
    then appears once in the generated C, shared by every step that uses it."""
    S, u = ca.SX.sym("S", n, m), ca.SX.sym("u", m)
    w, sigma, p = ca.SX.sym("tau_max", n), ca.SX.sym("preload_sign", n), ca.SX.sym("preload", n)
    tau, mode = preload(S, u, w, sigma, p)
    return ca.Function(f"{prefix}_split_preload", [S, u, w, sigma, p], [tau, mode],
                       ["S", "u", "tau_max", "preload_sign", "preload"], ["tau_a", "mode"])
