# Generated path dynamics for motion planning: coefficients along a path, TOPP passes, torques.
"""The generated C of the time-optimal path parameterisation (pm2dof.planning).

Along a path p(s) in the model's task space (m = 2: the point's x, y; m = 3: a platform's
x, y, phi; s the path parameter the planner chooses, arc length for a point) the task-space
dynamics (eqs. 10-12, 2) become

    u(s, s_d, s_dd) = a(s) s_dd + b(s) s_d^2 + S^T f_a(S p' s_d) + g(s),
    a = Me p',   b = Me p'' + Ce(q, p') p',   g = Ge (gravity; absent in a horizontal plane),

and an actuator split must deliver S^T tau = u with |tau_i| <= tau_max,i. For either split the
feasible forces form a centrally symmetric polytope {u : |N_j . u| <= h_j, j = 1..F}
(:func:`force_polygon`, unit normals N_j; F = n facet pairs for m = 2, F = max(n, n (n - 1) / 2)
for m = 3, a split with fewer repeating its first facet):

* ``min_norm`` (eq. 21): tau = P u, P = S (S^T S)^-1; N_j = P_j / |P_j|, h_j = tau_max,j / |P_j|;
* ``min_max`` (any tau with S^T tau = u): the zonotope {S^T tau : |tau_i| <= tau_max,i} of the
  generators g_j = tau_max,j s_j (s_j row j of S), whose facets are normal to perp(g_j) for
  m = 2 and to g_i x g_j for m = 3: N_j that unit normal, h_j = sum_i |g_i . N_j| (its support
  function; the least h_j is the inradius of pm2dof.analysis.maps).

Facet j reads |A_j s_dd + m_j(s_d)| <= h_j - e_j(s_d) with A_j = N_j . a and
m_j = N_j . b s_d^2 + sum_i sigma_i (N_j . s_i) f+_i(|v1_i| s_d) (+ N_j . g): at each (s, s_d) the feasible
s_dd is an interval [L, U] of linear inequalities, exactly, whatever the friction law. v1 = S p'
(rad/m) is the joint velocity per unit path speed; for s_d > 0 (the path is followed forwards)
joint i moves with sign sigma_i = sgn(v1_i), and every friction law of the model files is odd,
f(-v, -sign) = -f(v, sign) (checked), so f_a,i = sigma_i f+_i(|v1_i| s_d) with f+ the positive
branch (Coulomb included: the sign is known). Where joint i reverses between two grid points
(``rho_i`` = 1) its friction may take either sign: it moves from m_j into the worst case
e_j = sum_i |N_j . s_i| f+_i, which tightens both sides of the facet.

Functions (prefix ``<name>_``), all per grid point:

* ``path_coefficients(p, dp, ddp, theta, tau_max) -> a, b, S, v1, N_min_norm, h_min_norm,
  N_min_max, h_min_max, sing`` (and ``g`` after ``b`` with gravity); NaN sing at a point out
  of reach (or, without redundancy, in the other assembly mode);
* ``path_mvc(stage, params) -> x_mvc``: the maximum-velocity curve squared, the largest s_d^2
  such that [L, U] is not empty at every speed up to it (-1: not even at rest);
* ``path_backward(x, pair, params) -> x_next, y``: one backward step of the controllable sets
  (TOPP-RA's recursion, exact in the friction) over the interval [s_k, s_k+1], whose ``pair``
  holds the facets leaving s_k and arriving at s_k+1 (the path's left limit there) and the
  arrival facets' maximum-velocity curve: from x, the largest s_d^2 at s_k+1 from which the
  end can be reached, to the largest s_d^2 at s_k with a feasible s_dd that lands between rest
  and it (s_d^2 in [0, x]) with the arrival facets holding there too, capped at ``x_cap``
  (-1: none); its input (layout ``path_backward_input``) is the pair and a previous pass's
  step over the same interval (``same``, ``x_in``, ``x_out``: :func:`_reusing`);
* ``path_forward(x, input, params) -> x_next, y``: one forward step from s_d^2 = x at s_k, the
  greatest s_dd feasible leaving s_k that keeps s_d^2 at s_k+1 within the controllable bound
  (``x_next_max``) and that the arrival facets' U allows at its own landing speed (the
  :data:`ARRIVAL_STEPS` regula falsi steps), never landing below rest; y (layout
  ``path_forward_output``) = [x, s_dd, L, U, Z, arrival_ok] (L, U: the feasible s_dd leaving
  s_k; Z >= 0: the facets parallel to a hold; arrival_ok: 1 if the arrival facets hold too, 0
  where both ends cannot, where the departing ones are kept); landing on the bound lands on
  it exactly; a previous pass's step is reused as in ``path_backward``;
* ``path_torques(stage, sd, sdd, params, tau_max) -> u, tau_min_norm, tau_min_max, ratio``.

The maximum-velocity curve of a friction law affine in |v| (Coulomb + viscous, eq. 2: every
condition a quadratic in s_d) is in closed form, the least first crossing of the quadratics
(:meth:`_Stage.largest_exact`, exact to rounding); for the other laws (Stribeck, smooth sign)
it is found by bisection with :data:`MVC_BISECTIONS` halvings, which keeps the feasible end.
Where the feasible speeds at a point are two intervals (near some stops: the speed at which
b s_d^2 balances again), the curve is the top of the first. The backward step's largest
controllable s_d is found by bisection with :data:`BISECTIONS` halvings: the stage sets are
intervals [0, s_d*] for these robots, and the bisection keeps the feasible end, so the result
never exceeds the true bound. The backward step reads the bisection's result off its lattice next to
an estimate (Newton steps from the hint) where 4 evaluations show it there, and bisects only
where they do not (:meth:`_Stage.at_hint`, a CasADi switch). For a friction
law affine in |v| (Coulomb + viscous, eq. 2) each facet is a quadratic in s_d whose
coefficients are computed once per point; other laws (Stribeck, smooth sign) are evaluated at
every halving.
"""
import math

import casadi as ca
import sympy as sp

from .dynamics import _friction
from .factored import solve_small, task_gravity, task_inertia_coriolis
from .layouts import Layout
from .model_functions import assembly_guard
from .splits import _cross, _dot, min_max, min_norm
from .symbols import sgn
from .to_casadi import Converter

__all__ = ["path_layouts", "path_functions", "force_polygon", "BISECTIONS", "MVC_BISECTIONS",
           "HINT_SPAN", "HINT_FLOOR", "ARRIVAL_STEPS", "LATTICE_BITS"]

#: halvings of the bisection for the largest controllable s_d, on a bracket of +-10 % around
#: a hint (braking onto the next point's bound), on a lattice of 2^-LATTICE_BITS of the hint's
#: power of two (resolution 6e-8 to 1.2e-7 of it; converged for hints above HINT_FLOOR) or,
#: where that does not bracket the answer (a jump of the maximum-velocity curve), on
#: [0, v_top] (3e-6 m/s at 100 m/s, on the feasible side); and for the maximum-velocity curve
#: of a friction law that is not affine in |v| (the affine ones: closed form): v_top 2^-20,
#: 1e-4 m/s at 100 m/s
BISECTIONS = 25
MVC_BISECTIONS = 20
LATTICE_BITS = 24
HINT_SPAN, HINT_FLOOR = 0.1, 1e-3
#: steps of the forward pass's search (Illinois regula falsi, on the allowed side) for the
#: greatest s_dd that the arrival facets allow at its own landing speed, on the bracket [U there
#: at the uncapped landing, the uncapped s_dd]
ARRIVAL_STEPS = 4
_PARALLEL = 1e-12   # |N_j . a| <= _PARALLEL |a|: facet j does not bound s_dd (it bounds s_d only)


def facet_count(n, m):
    """F, the facet pairs of a stage's force polytope (both splits padded to the larger)."""
    return n if m == 2 else max(n, n * (n - 1) // 2)


def path_layouts(n, p, m, gravity=False):
    """Per-grid-point vectors of the path functions (manifest layouts), task dimension m; a
    model with gravity has its gravity force g in the stage."""
    F = facet_count(n, m)
    g = [("g", m)] if gravity else []
    stage = Layout([("N", m * F), ("h", F), ("a", m), ("b", m)] + g + [("S", m * n), ("v1", n),
                    ("rho", n), ("delta", 1), ("x_cap", 1)])
    # an interval: the point's own stage, the next point's arrival stage (the path's left limit
    # there, the interval's rho) and the largest s_d^2 its facets allow (its MVC)
    pair = Layout([("stage", stage.size), ("next", stage.size), ("next_cap", 1)])
    forward_out = Layout([("x", 1), ("sdd", 1), ("L", 1), ("U", 1), ("Z", 1),
                          ("arrival_ok", 1)])
    # a step of a previous pass over the same interval with the same input (same = 1): where
    # it started from x_in too, its result x_out is the step's, and is returned (with y = [x,
    # 0, ...]: the caller has the previous y)
    backward = Layout([("pair", pair.size), ("same", 1), ("x_in", 1), ("x_out", 1)])
    forward = Layout([("pair", pair.size), ("x_next_max", 1), ("same", 1), ("x_in", 1),
                      ("x_out", 1)])
    params = Layout([("v_top", 1), ("theta", p)])
    return {"path_stage": stage, "path_pair": pair, "path_backward_input": backward,
            "path_forward_input": forward, "path_forward_output": forward_out,
            "path_params": params}


def force_polygon(S, w):
    """The feasible task forces {u : |N_j . u| <= h_j} of both splits at a pose, for S (n, m)
    and limits w (n,): (N_mn (F, m) row-major as F m SX, h_mn (F,), N_mm, h_mm), F facets
    (:func:`facet_count`)."""
    n, m = S.shape
    if m != 2:
        return _force_polytope(S, w)
    G = S.T @ S
    P = S @ ca.vertcat(ca.horzcat(G[1, 1], -G[0, 1]), ca.horzcat(-G[1, 0], G[0, 0])) / (
        G[0, 0] * G[1, 1] - G[0, 1] * G[1, 0])                       # S (S^T S)^-1, eq. 21
    mn, hmn, mm, hmm = [], [], [], []
    for i in range(n):
        norm = ca.sqrt(P[i, 0] ** 2 + P[i, 1] ** 2)
        mn += [P[i, 0] / norm, P[i, 1] / norm]
        hmn.append(w[i] / norm)
    g = [w[i] * S[i, :] for i in range(n)]
    for j in range(n):
        norm = ca.sqrt(g[j][0] ** 2 + g[j][1] ** 2)
        nj = (-g[j][1] / norm, g[j][0] / norm)                       # perp(g_j), unit
        mm += list(nj)
        hmm.append(sum(ca.fabs(g[i][0] * nj[0] + g[i][1] * nj[1]) for i in range(n)))
    return ca.vertcat(*mn), ca.vertcat(*hmn), ca.vertcat(*mm), ca.vertcat(*hmm)


def _force_polytope(S, w):
    """:func:`force_polygon` for m = 3: the min-norm slabs of P = S (S^T S)^-1 and the
    zonotope's facets, normal to g_i x g_j (i < j). Where g_i and g_j are parallel that normal
    is undefined and the pair's facet is another facet's duplicate; its place holds the
    zonotope's supporting slab normal to g_i (valid, never cutting). Padding to F repeats the
    first facet."""
    n, m = S.shape
    F = facet_count(n, m)
    P = S @ ca.horzcat(*[solve_small(S.T @ S, ca.DM.eye(m)[:, k]) for k in range(m)])  # eq. 21
    mn, hmn = [], []
    for i in range(n):
        norm = ca.sqrt(ca.sumsqr(P[i, :]))
        mn.append(P[i, :].T / norm)
        hmn.append(w[i] / norm)
    g = [w[i] * S[i, :].T for i in range(n)]
    mm, hmm = [], []
    for i in range(n):
        for j in range(i + 1, n):
            l = _cross(g[i], g[j])
            ln, gn = ca.sqrt(_dot(l, l)), ca.sqrt(_dot(g[i], g[i]) * _dot(g[j], g[j]))
            N = ca.if_else(ln > _PARALLEL * gn, l / ln, g[i] / ca.sqrt(_dot(g[i], g[i])))
            mm.append(N)
            hmm.append(sum(ca.fabs(_dot(g[k], N)) for k in range(n)))   # support function
    mn, hmn = mn + [mn[0]] * (F - len(mn)), hmn + [hmn[0]] * (F - len(hmn))
    mm, hmm = mm + [mm[0]] * (F - len(mm)), hmm + [hmm[0]] * (F - len(hmm))
    return ca.vertcat(*mn), ca.vertcat(*hmn), ca.vertcat(*mm), ca.vertcat(*hmm)


def _norm(v, m):
    """|v| of an m-vector (for m = 2 as sqrt(v0^2 + v1^2))."""
    out = v[0] ** 2
    for k in range(1, m):
        out = out + v[k] ** 2
    return ca.sqrt(out)


class _PathFriction:
    """f+_i(v) = f_a,i(v, sign +1), the model's friction law (eq. 2 and its extensions) on the
    positive branch, as SX of theta; ``affine`` when it is f0 + f1 v (Coulomb + viscous)."""

    def __init__(self, d, theta):
        from pm2dof.core.mechanism import FRICTION_MODELS
        spec, sym = d.spec, d.sym
        n = spec.n_legs
        v = sp.symbols(f"pv1:{n + 1}", real=True)
        sigma = sp.symbols(f"psigma1:{n + 1}", real=True)
        names = FRICTION_MODELS[spec.friction]
        exprs = [_friction(spec.friction, v[i], sym.leg_params(i, names),
                           spec.friction_constants).replace(sgn, lambda *_: sigma[i])  # noqa: B023
                 for i in range(n)]
        for i, e in enumerate(exprs):
            odd = sp.simplify(e + e.subs({v[i]: -v[i], sigma[i]: -sigma[i]}, simultaneous=True))
            if odd != 0:
                raise NotImplementedError(f"friction law {spec.friction!r} of joint {i + 1} is "
                                          f"not odd in (v, sign v): {e}")
        self.plus = [e.subs(sigma[i], 1) for i, e in enumerate(exprs)]    # f+_i(v)
        self.affine = all(sp.diff(e, v[i], 2) == 0 for i, e in enumerate(self.plus))
        self.v, self.sigma, self.exprs = v, sigma, exprs
        self.conv = Converter(dict(zip(sym.theta, ca.vertsplit(theta))))
        if self.affine:   # f+_i = f0_i + f1_i v
            self.f0 = ca.vertcat(*[self.conv(e.subs(v[i], 0)) for i, e in enumerate(self.plus)])
            self.f1 = ca.vertcat(*[self.conv(sp.diff(e, v[i])) for i, e in enumerate(self.plus)])

    def positive(self, v):
        """(n,) f+_i(v_i) at speeds v (n,) >= 0."""
        c = self.conv.extended([(self.v, v)])
        return ca.vertcat(*[c(e) for e in self.plus])

    def signed(self, v, sigma):
        """(n,) f_a,i at velocities v (n,) with Coulomb signs sigma (n,)."""
        c = self.conv.extended([(self.v, v), (self.sigma, sigma)])
        return ca.vertcat(*[c(e) for e in self.exprs])


class _Stage:
    """The facets of one grid point as functions of s_d (SX), from a ``path_stage`` vector:
    n actuators, task dimension m, F facets (:func:`facet_count`)."""

    def __init__(self, n, st, friction, m):
        F = facet_count(n, m)
        self.n, self.F, self.st, self.friction = n, F, st, friction
        N = ca.reshape(st["N"], m, F).T
        S = ca.reshape(st["S"], m, n).T
        self.S = S
        v1, rho = st["v1"], st["rho"]
        # sigma_i: the direction joint i moves on the interval ahead (s_d > 0), not the model's
        # sign of a velocity (sign(0) = 0): v1_i = 0 counts as forward, and a neighbour with
        # the other sign makes the interval a reversal (rho_i = 1, both signs; stages.py)
        self.sigma = ca.vertcat(*[ca.if_else(v1[i] >= 0, 1, -1) for i in range(n)])
        self.abs_v1 = ca.fabs(v1)
        A, self.B = N @ st["a"], N @ st["b"]
        Cf = N @ S.T                                  # (F, n): facet j's weight of f_a,i
        an = _norm(st["a"], m)
        free = [ca.fabs(A[j]) <= _PARALLEL * an for j in range(F)]     # does not bound s_dd
        self.I = [ca.if_else(free[j], 0, 1 / A[j]) for j in range(F)]
        self.aI = [ca.fabs(x) for x in self.I]
        self.pen = [ca.if_else(free[j], ca.inf, 0) for j in range(F)]     # L, U: unbounded
        self.zpen = [ca.if_else(free[j], 0, ca.inf) for j in range(F)]    # Z: only free ones
        self.h = st["h"]
        self.G = N @ st["g"] if "g" in st else None   # facet j's share of gravity, N_j . g
        moving = [1 - rho[i] for i in range(n)]
        self.Wm = [[moving[i] * self.sigma[i] * Cf[j, i] for i in range(n)] for j in range(F)]
        self.We = [[rho[i] * ca.fabs(Cf[j, i]) for i in range(n)] for j in range(F)]
        if friction.affine:   # m_j = B_j sd^2 + m1_j sd + m0_j, e_j = e1_j sd + e0_j
            f0, f1 = friction.f0, friction.f1 * self.abs_v1
            dot = lambda W, f: sum(W[i] * f[i] for i in range(n))
            self.m1 = [dot(self.Wm[j], f1) for j in range(F)]
            self.m0 = [dot(self.Wm[j], f0) for j in range(F)]
            if self.G is not None:
                self.m0 = [self.m0[j] + self.G[j] for j in range(F)]
            self.e1 = [dot(self.We[j], f1) for j in range(F)]
            self.e0 = [dot(self.We[j], f0) for j in range(F)]

    def _m_e(self, sd):
        n, F = self.n, self.F
        if self.friction.affine:
            return ([self.B[j] * sd * sd + self.m1[j] * sd + self.m0[j] for j in range(F)],
                    [self.e1[j] * sd + self.e0[j] for j in range(F)])
        f = self.friction.positive(self.abs_v1 * sd)
        m = [self.B[j] * sd * sd + sum(self.Wm[j][i] * f[i] for i in range(n)) for j in range(F)]
        if self.G is not None:
            m = [m[j] + self.G[j] for j in range(F)]
        return m, [sum(self.We[j][i] * f[i] for i in range(n)) for j in range(F)]

    def bounds(self, sd):
        """(L, U, Z) at speed sd: s_dd in [L, U] is feasible, and the facets parallel to a
        need Z >= 0 (-inf / +inf where nothing bounds that side)."""
        m, e = self._m_e(sd)
        L, U, Z = -ca.inf, ca.inf, ca.inf
        for j in range(self.F):
            hh = self.h[j] - e[j]
            c = -m[j] * self.I[j]
            L = ca.fmax(L, c - hh * self.aI[j] - self.pen[j])
            U = ca.fmin(U, c + hh * self.aI[j] + self.pen[j])
            Z = ca.fmin(Z, hh - ca.fabs(m[j]) + self.zpen[j])
        return L, U, Z

    def feasible(self, sd):
        L, U, Z = self.bounds(sd)
        return ca.logic_and(L <= U, Z >= 0), L

    def _quadratics(self):
        """For a friction law affine in |v|: the conditions of :meth:`feasible` as quadratics
        c2 sd^2 + c1 sd + c0 >= 0, [(c2, c1, c0, active)]: lower_i <= upper_j for every pair of
        facets bounding s_dd (L <= U) and h_j - e_j -+ m_j >= 0 for the ones that do not
        (Z >= 0); ``active`` 0 where the facet's kind makes the condition void."""
        F, I, aI = self.F, self.I, self.aI
        free = [self.pen[j] > 0 for j in range(F)]
        hh = [(-self.e1[j], self.h[j] - self.e0[j]) for j in range(F)]     # h_j - e_j
        m = [(self.B[j], self.m1[j], self.m0[j]) for j in range(F)]       # m_j (eq. 2)
        # upper_j, lower_j = -m_j I_j +- (h_j - e_j) |I_j|
        up = [(-m[j][0] * I[j], -m[j][1] * I[j] + hh[j][0] * aI[j],
               -m[j][2] * I[j] + hh[j][1] * aI[j]) for j in range(F)]
        lo = [(-m[j][0] * I[j], -m[j][1] * I[j] - hh[j][0] * aI[j],
               -m[j][2] * I[j] - hh[j][1] * aI[j]) for j in range(F)]
        out = []
        for i in range(F):
            for j in range(F):
                both = ca.logic_not(ca.logic_or(free[i], free[j]))
                out.append((up[j][0] - lo[i][0], up[j][1] - lo[i][1], up[j][2] - lo[i][2],
                            both))
        for j in range(F):
            for s in (1, -1):
                out.append((-s * m[j][0], hh[j][0] - s * m[j][1], hh[j][1] - s * m[j][2],
                            free[j]))
        return out

    def largest_exact(self, v_top):
        """(largest sd in [0, v_top] with [0, sd] feasible, feasible at 0) for a friction law
        affine in |v|: the least first crossing below zero of the quadratics of
        :meth:`_quadratics` (each >= 0 at rest), exact to rounding. q = c2 sd^2 + c1 sd + c0,
        c0 >= 0, first turns negative at 2 c0 / (D - c1) for c1 < 0 (D = sqrt(c1^2 - 4 c2 c0),
        none if D is not real: c2 > 0 and q > 0 throughout) and at (c1 + D) / (-2 c2) for
        c1 >= 0 > c2 (neither form cancels); never for c1 >= 0 <= c2."""
        ok0 = self.feasible(ca.SX(0))[0]
        sd = v_top
        for c2, c1, c0, active in self._quadratics():
            c0 = ca.fmax(c0, 0)                       # rounding of a condition that holds at rest
            disc = c1 * c1 - 4 * c2 * c0
            D = ca.sqrt(ca.fmax(disc, 0))
            falling = 2 * c0 / (D - c1)
            rising = (c1 + D) / (-2 * c2)
            r = ca.if_else(c1 < 0, ca.if_else(disc >= 0, falling, ca.inf),
                           ca.if_else(c2 < 0, rising, ca.inf))
            sd = ca.if_else(active, ca.fmin(sd, r), sd)
        return sd, ok0

    def largest(self, v_top, predicate, halvings, hint=None):
        """(largest sd in [0, v_top] where predicate(sd) holds, holds at 0), by bisection; with
        a ``hint``, on [hint (1 - r), hint (1 + r) + c] (r = HINT_SPAN, c = HINT_FLOOR m/s)
        when that brackets the answer, else on [0, v_top]. The bisection keeps to a lattice,
        multiples of q = v_top 2^-halvings on [0, v_top], of q = 2^(e - LATTICE_BITS) on the
        hint's bracket (2^e <= hint < 2^(e+1)), rounded outwards onto it: where it converges
        (the bracket at most 2^halvings steps: any hint above HINT_FLOOR) the result is the
        largest lattice point where the predicate holds, whatever the hint's exact value (a
        pass whose bound changed in its last bits meets the unchanged one again)."""
        ok0, okt = predicate(ca.SX(0)), predicate(v_top)
        lo, hi, q = ca.SX(0), v_top, v_top * 2.0 ** -halvings
        if hint is not None:
            h = ca.fmax(hint, 1e-30)      # a speed, m/s; 1e-30: a normal float (pm2dof export --precision single)
            qh = 2 ** (ca.floor(ca.log(h) / math.log(2)) - LATTICE_BITS)
            a = ca.floor(h * (1 - HINT_SPAN) / qh) * qh
            b = ca.ceil((h * (1 + HINT_SPAN) + HINT_FLOOR) / qh) * qh
            use = ca.logic_and(predicate(a), ca.logic_not(predicate(b)))
            lo, hi, q = ca.if_else(use, a, lo), ca.if_else(use, b, hi), ca.if_else(use, qh, q)
        for _ in range(halvings):
            mid = lo + ca.floor((hi - lo) / (2 * q)) * q
            c = predicate(mid)
            lo, hi = ca.if_else(c, mid, lo), ca.if_else(c, hi, mid)
        return ca.if_else(okt, v_top, lo), ok0

    def at_hint(self, v_top, predicate, halvings, hint, estimate):
        """:meth:`largest`'s result with a ``hint`` where it can be read off the lattice (of
        the hint's bracket) next to ``estimate`` (a closer guess of the answer): r the largest
        multiple of q at or below the estimate. Returns (found, sd, holds at 0): found where
        the predicate holds at v_top (sd = v_top), or where the hint's bracket converges and
        holds r' in {r - q, r, r + q} with the predicate true at r' and false at r' + q: for a
        predicate true on [0, sd*] the largest lattice point where it holds, :meth:`largest`'s
        bisection's own result, bit for bit, from 6 evaluations instead of halvings + 4."""
        ok0, okt = predicate(ca.SX(0)), predicate(v_top)
        h = ca.fmax(hint, 1e-30)
        qh = 2 ** (ca.floor(ca.log(h) / math.log(2)) - LATTICE_BITS)
        a = ca.floor(h * (1 - HINT_SPAN) / qh) * qh
        b = ca.ceil((h * (1 + HINT_SPAN) + HINT_FLOOR) / qh) * qh
        r = ca.floor(estimate / qh) * qh
        p = [predicate(r + k * qh) for k in (-1, 0, 1, 2)]
        inside = ca.logic_and(ca.logic_and(r - qh >= a, r + 2 * qh <= b),
                              b - a <= 2.0 ** halvings * qh)
        edge = [ca.logic_and(p[k], ca.logic_not(p[k + 1])) for k in range(3)]
        sd = ca.if_else(edge[1], r, ca.if_else(edge[0], r - qh, r + qh))
        hit = ca.logic_and(inside, ca.logic_or(ca.logic_or(edge[0], edge[1]), edge[2]))
        return ca.logic_or(okt, hit), ca.if_else(okt, v_top, sd), ok0


def _verified(name, fast, step):
    """``step`` (x, input, params) -> x_next as an MX Function that first evaluates ``fast``
    (same inputs) -> (found, x_next) and returns its x_next where found, else ``step``'s (a
    CasADi switch: the generated C evaluates the full step only where the fast one failed)."""
    sx = [ca.SX.sym(f"a{i}", step.size1_in(i)) for i in range(3)]
    v = ca.SX.sym("v")
    switch = ca.Function.conditional(f"{name}_or", [ca.Function(f"{name}_found", [v] + sx, [v])],
                                     ca.Function(f"{name}_bisect", [v] + sx, [step(*sx)]))
    mx = [ca.MX.sym(f"m{i}", step.size1_in(i)) for i in range(3)]
    found, value = fast(*mx)
    return ca.Function(name, mx, [switch(ca.if_else(found, 0, 1), value, *mx)])


def _reusing(name, step, layout, names_in, names_out):
    """``step`` (x, input, params) -> outputs (``input``: the layout's ``pair``, or the whole
    layout) as a Function of (x, layout, params) that returns a previous pass's result where
    the layout says the interval and its input are the same (``same``) and the pass arrives
    with the same state (x == x_in): x_next = x_out, the step's own result, bit for bit,
    without evaluating it (a CasADi switch: the generated C evaluates one branch), and y =
    [x, 0, ...] (the caller has the previous one). Outputs (x_next, y)."""
    mx = not step.is_a("SXFunction")
    sym = ca.MX.sym if mx else ca.SX.sym
    sx = [sym(f"a{i}", n) for i, n in enumerate((step.size1_in(0), layout.size,
                                                   step.size1_in(2)))]
    U = layout.split(sx[1])
    arg = sx[1] if step.size1_in(1) == layout.size else U["pair"]
    full = step(sx[0], arg, sx[2])
    if isinstance(full, (list, tuple)):        # (x_next, y): y's first entry x, the rest 0
        kept = [U["x_out"], ca.vertcat(sx[0], ca.SX.zeros(full[1].numel() - 1))]
    else:                                       # x_next, which is y too
        full, kept = [full, full], [U["x_out"], U["x_out"]]
    switch = ca.Function.conditional(f"{name}_switch",
                                     [ca.Function(f"{name}_reuse", sx, kept)],
                                     ca.Function(f"{name}_full", sx, full))
    x, u, prm = (ca.MX.sym(f"m{i}", s.numel()) for i, s in enumerate(sx))
    Um = layout.split(u)
    case = ca.if_else(ca.logic_and(Um["same"] != 0, x == Um["x_in"]), 0, 1)
    return ca.Function(name, [x, u, prm], switch(case, x, u, prm), names_in, names_out)


def path_functions(d, prefix):
    """``<prefix>_path_coefficients``, ``_path_mvc``, ``_path_backward``, ``_path_forward`` and
    ``_path_torques`` (see the module docstring); each named, with named inputs and outputs."""
    n, p, m = d.spec.n_legs, len(d.spec.param_names), d.m
    sym = d.sym
    pos, dp, ddp = ca.SX.sym("p", m), ca.SX.sym("dp", m), ca.SX.sym("ddp", m)
    theta, w = ca.SX.sym("theta", p), ca.SX.sym("tau_max", n)
    conv = d.converter_xe(pos)
    Me, Ce_v, S, _ = task_inertia_coriolis(d, conv, dp, [(sym.theta, theta)])   # eq. 12
    g = task_gravity(d, conv, [(sym.theta, theta)])                             # eq. 10
    lays = path_layouts(n, p, m, gravity=g is not None)
    sing = d.singularity_measures(conv)
    # without redundancy the other assembly mode is out of the workspace (model.ik refuses it)
    sing = assembly_guard(d, conv, sing, 2)
    N_mn, h_mn, N_mm, h_mm = force_polygon(S, w)
    gravity = [] if g is None else [("g", g)]
    outs = [("a", Me @ dp), ("b", Me @ ddp + Ce_v)] + gravity + [
        ("S", ca.vec(S.T)), ("v1", S @ dp), ("N_min_norm", N_mn), ("h_min_norm", h_mn),
        ("N_min_max", N_mm), ("h_min_max", h_mm), ("sing", sing)]
    out = [d.function(
        f"{prefix}_path_coefficients", [pos, dp, ddp, theta, w], [v for _, v in outs],
        ["p", "dp", "ddp", "theta", "tau_max"], [k for k, _ in outs])]

    prm = ca.SX.sym("params", lays["path_params"].size)
    P = lays["path_params"].split(prm)
    friction = _PathFriction(d, P["theta"])
    stage_v = ca.SX.sym("stage", lays["path_stage"].size)
    st = _Stage(n, lays["path_stage"].split(stage_v), friction, m)
    v_top = P["v_top"]

    if friction.affine:     # each condition a quadratic in s_d: the curve in closed form
        y_mvc, ok0 = st.largest_exact(v_top)
    else:
        y_mvc, ok0 = st.largest(v_top, lambda sd: st.feasible(sd)[0], MVC_BISECTIONS)
    out.append(ca.Function(f"{prefix}_path_mvc", [stage_v, prm],
                           [ca.if_else(ok0, y_mvc * y_mvc, -1)], ["stage", "params"], ["x_mvc"]))

    # one interval [s_k, s_k+1]: the own facets at s_k and the arrival facets at s_k+1
    pair_v = ca.SX.sym("pair", lays["path_pair"].size)
    PR = lays["path_pair"].split(pair_v)
    own = _Stage(n, lays["path_stage"].split(PR["stage"]), friction, m)
    nxt = _Stage(n, lays["path_stage"].split(PR["next"]), friction, m)
    delta = own.st["delta"]

    x = ca.SX.sym("x_next_max")                 # controllable bound at s_k+1
    xl = ca.fmin(x, PR["next_cap"])             # ... and where the arrival facets allow
    L_next = nxt.bounds(ca.sqrt(ca.fmax(xl, 0)))[0]

    def reaches(sd):       # a feasible s_dd lands in [0, xl], feasible there too
        L, U, Z = own.bounds(sd)
        ok = ca.logic_and(L <= U, Z >= 0)
        # braking as hard as both ends allow lands at or below xl, and accelerating as hard as
        # s_k allows lands at or above rest (s_d^2 >= 0): near a coarse grid's maximum-velocity
        # curve viscous friction drives U far below 0 and every feasible s_dd would stop the
        # robot before s_k+1
        return ca.logic_and(ca.logic_and(ok, sd * sd + 2 * delta * ca.fmax(L, L_next) <= xl),
                            sd * sd + 2 * delta * U >= 0)
    # the hint: braking from xl at the arrival end's deceleration (exact where that binds)
    hint = ca.sqrt(ca.fmin(ca.fmax(xl - 2 * delta * L_next, 0), 4 * ca.fmax(xl, 0) + 1))
    y_b, ok0 = own.largest(v_top, reaches, BISECTIONS, hint=hint)

    def landing(y, ok0):
        return ca.if_else(ca.logic_and(ok0, xl >= 0), ca.fmin(y * y, own.st["x_cap"]), -1)
    step = ca.Function(f"{prefix}_path_backward_step", [x, pair_v, prm], [landing(y_b, ok0)])
    # the estimate: two Newton steps from the hint on braking as hard as both ends allow,
    # landing on xl (where that binds: the own end's deceleration, which falls with the speed,
    # binds as well as the arrival end's; elsewhere the fast step fails and bisects)
    sdv = ca.SX.sym("sd")
    brake = sdv * sdv + 2 * delta * ca.fmax(own.bounds(sdv)[0], L_next) - xl
    newton = ca.Function("newton", [sdv, x, pair_v, prm],
                         [sdv - brake / ca.jacobian(brake, sdv)])
    estimate = newton(newton(hint, x, pair_v, prm), x, pair_v, prm)
    # where the own facets' maximum-velocity curve binds below that (L > U there): two Newton
    # steps on U - L from it
    Lv, Uv = own.bounds(sdv)[:2]
    room = ca.Function("room", [sdv, pair_v, prm],
                       [Uv - Lv, sdv - (Uv - Lv) / ca.jacobian(Uv - Lv, sdv)])
    gap, after = room(estimate, pair_v, prm)
    estimate = ca.if_else(gap < 0, room(after, pair_v, prm)[1], estimate)
    found, y_f, ok0_f = own.at_hint(v_top, reaches, BISECTIONS, hint, estimate)
    fast = ca.Function(f"{prefix}_path_backward_hint", [x, pair_v, prm],
                       [found, landing(y_f, ok0_f)])
    step = _verified(f"{prefix}_path_backward_step", fast, step)
    out.append(_reusing(f"{prefix}_path_backward", step, lays["path_backward_input"],
                        ["x_next_max", "input", "params"], ["x_max", "y"]))

    fin = ca.SX.sym("input", lays["path_forward_input"].size)
    F = lays["path_forward_input"].split(fin)
    PF = lays["path_pair"].split(F["pair"])
    fown = _Stage(n, lays["path_stage"].split(PF["stage"]), friction, m)
    fnxt = _Stage(n, lays["path_stage"].split(PF["next"]), friction, m)
    xk = ca.SX.sym("x")
    L, U, Z = fown.bounds(ca.sqrt(ca.fmax(xk, 0)))
    dlt = fown.st["delta"]
    x_land = ca.fmin(F["x_next_max"], PF["next_cap"])
    on_bound = (x_land - xk) / (2 * dlt)     # the s_dd landing on the controllable bound
    top = ca.fmin(U, on_bound)
    floor = ca.fmax(L, -xk / (2 * dlt))     # the least s_dd: own facets, landing at rest or above

    def room(sdd):         # the arrival facets' U at the landing speed, less sdd (>= 0: allowed)
        return fnxt.bounds(ca.sqrt(ca.fmax(xk + 2 * dlt * sdd, 0)))[1] - sdd
    # the greatest sdd in [floor, top] under the arrival facets' U at its own landing speed:
    # U falls with the speed (viscous friction, b s_d^2), so its value at ``top``'s landing
    # brackets the answer from below; the Illinois variant of regula falsi keeps a bracket
    # [a (allowed), b (not)] and returns a. (Capping sdd by U at the landing speed of the
    # previous guess instead undershoots by the fall of U across the interval: on a coarse
    # grid below -s_d^2 / (2 delta), landing at s_d^2 < 0.)
    f_top = room(top)
    guess = ca.fmax(floor, ca.fmin(top, f_top + top))
    f_guess = room(guess)
    ok_guess = f_guess >= 0          # else U rises with the speed here: search from floor
    a, fa = ca.if_else(ok_guess, guess, floor), ca.if_else(ok_guess, f_guess, room(floor))
    b, fb = top, f_top
    side = ca.SX(0)
    for _ in range(ARRIVAL_STEPS):
        c = ca.fmin(ca.fmax((a * fb - b * fa) / (fb - fa), a), b)
        fc = room(c)
        left = fc >= 0                          # c is allowed: the bracket's low end moves
        a, fa = ca.if_else(left, c, a), ca.if_else(left, fc, fa)
        b, fb = ca.if_else(left, b, c), ca.if_else(left, fb, fc)
        fb = ca.if_else(ca.logic_and(left, side > 0), 0.5 * fb, fb)     # Illinois: halve the
        fa = ca.if_else(ca.logic_and(left == 0, side < 0), 0.5 * fa, fa)  # end that stays
        side = ca.if_else(left, 1, -1)
    sdd = ca.if_else(f_top >= 0, top, ca.if_else(fa >= 0, a, floor))
    sdd = ca.fmax(sdd, floor)  # where both ends cannot hold (riding a coarse grid's MVC): own
    Ln, Un, Zn = fnxt.bounds(ca.sqrt(ca.fmax(xk + 2 * dlt * sdd, 0)))
    scale = ca.fmax(1, ca.fabs(sdd))
    arrival_ok = ca.logic_and(ca.logic_and(sdd >= Ln - 1e-9 * scale, sdd <= Un + 1e-9 * scale),
                              Zn >= -1e-9 * ca.mmax(fnxt.h))
    y = lays["path_forward_output"].pack(x=xk, sdd=sdd, L=L, U=U, Z=Z, arrival_ok=arrival_ok)
    # landing on the bound lands on it exactly (not within a rounding of it, which would depend
    # on x_k): a forward pass whose speed changed somewhere meets the unchanged one there
    x_next = ca.if_else(sdd == on_bound, x_land, xk + 2 * dlt * sdd)
    step = ca.Function(f"{prefix}_path_forward_step", [xk, fin, prm], [x_next, y])
    out.append(_reusing(f"{prefix}_path_forward", step, lays["path_forward_input"],
                        ["x", "input", "params"], ["x_next", "y"]))

    sd, sdd = ca.SX.sym("sd"), ca.SX.sym("sdd")
    S2 = st.S
    u = st.st["a"] * sdd + st.st["b"] * sd * sd \
        + S2.T @ friction.signed(st.st["v1"] * sd, st.sigma)
    if "g" in st.st:                                   # gravity (eq. 10)
        u = u + st.st["g"]
    t_mm, ratio = min_max(S2, u, w)
    out.append(ca.Function(f"{prefix}_path_torques", [stage_v, sd, sdd, prm, w],
                           [u, min_norm(S2, u), t_mm, ratio],
                           ["stage", "sd", "sdd", "params", "tau_max"],
                           ["u", "tau_min_norm", "tau_min_max", "min_max_ratio"]))
    return out
