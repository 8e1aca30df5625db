# Generated path dynamics for motion planning: coefficients along a path, TOPP passes, torques.
"""The generated C of the time-optimal path parameterisation (pm2dof.planning).

Along a path p(s) (arc length s, m) the task-space dynamics (eqs. 10-12, 2) become

    u(s, s_d, s_dd) = a(s) s_dd + b(s) s_d^2 + S^T f_a(S p' s_d),
    a = Me p',   b = Me p'' + Ce(q, p') p',

and an actuator split must deliver S^T tau = u with |tau_i| <= tau_max,i. For either split the
feasible forces form a centrally symmetric polygon {u : |N_j . u| <= h_j, j = 1..n}
(:func:`force_polygon`, unit normals N_j):

* ``min_norm`` (eq. 21): tau = P u, P = S (S^T S)^-1; N_j = P_j / |P_j|, h_j = tau_max,j / |P_j|;
* ``min_max`` (any tau with S^T tau = u): the zonotope {S^T tau : |tau_i| <= tau_max,i}, whose
  edges are parallel to its generators g_j = tau_max,j s_j (s_j row j of S): N_j = perp(g_j) /
  |g_j|, h_j = sum_i |g_i . N_j| (its support function; the least h_j is the inradius of
  pm2dof.analysis.maps).

Facet j reads |A_j s_dd + m_j(s_d)| <= h_j - e_j(s_d) with A_j = N_j . a and
m_j = N_j . b s_d^2 + sum_i sigma_i (N_j . s_i) f+_i(|v1_i| s_d): at each (s, s_d) the feasible
s_dd is an interval [L, U] of linear inequalities, exactly, whatever the friction law. v1 = S p'
(rad/m) is the joint velocity per unit path speed; for s_d > 0 (the path is followed forwards)
joint i moves with sign sigma_i = sgn(v1_i), and every friction law of the model files is odd,
f(-v, -sign) = -f(v, sign) (checked), so f_a,i = sigma_i f+_i(|v1_i| s_d) with f+ the positive
branch (Coulomb included: the sign is known). Where joint i reverses between two grid points
(``rho_i`` = 1) its friction may take either sign: it moves from m_j into the worst case
e_j = sum_i |N_j . s_i| f+_i, which tightens both sides of the facet.

Functions (prefix ``<name>_``), all per grid point:

* ``path_coefficients(p, dp, ddp, theta, tau_max) -> a, b, S, v1, N_min_norm, h_min_norm,
  N_min_max, h_min_max, sing``; NaN sing at a point out of reach (or, for two legs, in the
  other assembly mode);
* ``path_mvc(stage, params) -> x_mvc``: the maximum-velocity curve squared, the largest s_d^2 at
  which [L, U] is not empty (-1: not even at rest);
* ``path_backward(x, pair, params) -> x_next, y``: one backward step of the controllable sets
  (TOPP-RA's recursion, exact in the friction) over the interval [s_k, s_k+1], whose ``pair``
  holds the facets leaving s_k and arriving at s_k+1 (the path's left limit there) and the
  arrival facets' maximum-velocity curve: from x, the largest s_d^2 at s_k+1 from which the
  end can be reached, to the largest s_d^2 at s_k with a feasible s_dd that lands between rest
  and it (s_d^2 in [0, x]) with the arrival facets holding there too, capped at ``x_cap``
  (-1: none);
* ``path_forward(x, input, params) -> x_next, y``: one forward step from s_d^2 = x at s_k, the
  greatest s_dd feasible leaving s_k that keeps s_d^2 at s_k+1 within the controllable bound
  (``x_next_max``) and that the arrival facets' U allows at its own landing speed (the
  :data:`ARRIVAL_STEPS` regula falsi steps), never landing below rest; y (layout
  ``path_forward_output``) = [x, s_dd, L, U, Z, arrival_ok] (L, U: the feasible s_dd leaving
  s_k; Z >= 0: the facets parallel to a hold; arrival_ok: 1 if the arrival facets hold too, 0
  where both ends cannot, where the departing ones are kept);
* ``path_torques(stage, sd, sdd, params, tau_max) -> u, tau_min_norm, tau_min_max, ratio``.

The largest s_d with a non-empty interval is found by bisection with :data:`BISECTIONS`
halvings (:data:`MVC_BISECTIONS` for the maximum-velocity curve): the stage sets are intervals
[0, s_d*] for these robots, and the bisection keeps the feasible end, so the result never
exceeds the true bound. For a friction
law affine in |v| (Coulomb + viscous, eq. 2) each facet is a quadratic in s_d whose
coefficients are computed once per point; other laws (Stribeck, smooth sign) are evaluated at
every halving.
"""
import casadi as ca
import sympy as sp

from .dynamics import _friction
from .factored import task_inertia_coriolis
from .layouts import Layout
from .splits import min_max, min_norm
from .symbols import sgn
from .to_casadi import Converter

__all__ = ["path_layouts", "path_functions", "force_polygon", "BISECTIONS", "MVC_BISECTIONS",
           "HINT_SPAN", "HINT_FLOOR", "ARRIVAL_STEPS"]

#: halvings of the bisection for the largest controllable s_d, on a bracket of +-10 % around
#: a hint (braking onto the next point's bound; resolution 5e-8 of it) or, where that does not
#: bracket the answer (a jump of the maximum-velocity curve), on [0, v_top] (2.4e-5 m/s at
#: 100 m/s, on the feasible side); and for the maximum-velocity curve (a
#: diagnostic the passes use only at breakpoints): v_top 2^-20, 1e-4 m/s at 100 m/s
BISECTIONS = 22
MVC_BISECTIONS = 20
HINT_SPAN, HINT_FLOOR = 0.1, 1e-3
#: steps of the forward pass's search (Illinois regula falsi, on the allowed side) for the
#: greatest s_dd that the arrival facets allow at its own landing speed, on the bracket [U there
#: at the uncapped landing, the uncapped s_dd]
ARRIVAL_STEPS = 4
_PARALLEL = 1e-12   # |N_j . a| <= _PARALLEL |a|: facet j does not bound s_dd (it bounds s_d only)


def path_layouts(n, p):
    """Per-grid-point vectors of the path functions (manifest layouts)."""
    stage = Layout([("N", 2 * n), ("h", n), ("a", 2), ("b", 2), ("S", 2 * n), ("v1", n),
                    ("rho", n), ("delta", 1), ("x_cap", 1)])
    # an interval: the point's own stage, the next point's arrival stage (the path's left limit
    # there, the interval's rho) and the largest s_d^2 its facets allow (its MVC)
    pair = Layout([("stage", stage.size), ("next", stage.size), ("next_cap", 1)])
    forward = Layout([("pair", pair.size), ("x_next_max", 1)])
    forward_out = Layout([("x", 1), ("sdd", 1), ("L", 1), ("U", 1), ("Z", 1),
                          ("arrival_ok", 1)])
    params = Layout([("v_top", 1), ("theta", p)])
    return {"path_stage": stage, "path_pair": pair, "path_forward_input": forward,
            "path_forward_output": forward_out, "path_params": params}


def force_polygon(S, w):
    """The feasible task forces {u : |N_j . u| <= h_j} of both splits at a pose, for S (n, 2)
    and limits w (n,): (N_mn (n, 2) row-major as 2n SX, h_mn (n,), N_mm, h_mm)."""
    n = S.shape[0]
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


class _PathFriction:
    """f+_i(v) = f_a,i(v, sign +1), the model's friction law (eq. 2 and its extensions) on the
    positive branch, as SX of theta; ``affine`` when it is f0 + f1 v (Coulomb + viscous)."""

    def __init__(self, d, theta):
        from pm2dof.core.model_file import FRICTION_MODELS
        spec, sym = d.spec, d.sym
        n = spec.n_legs
        v = sp.symbols(f"pv1:{n + 1}", real=True)
        sigma = sp.symbols(f"psigma1:{n + 1}", real=True)
        names = FRICTION_MODELS[spec.friction]
        exprs = [_friction(spec.friction, v[i], sym.leg_params(i, names),
                           spec.friction_constants).replace(sgn, lambda *_: sigma[i])
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
    """The facets of one grid point as functions of s_d (SX), from a ``path_stage`` vector."""

    def __init__(self, n, st, friction):
        self.n, self.st, self.friction = n, st, friction
        N = ca.reshape(st["N"], 2, n).T
        S = ca.reshape(st["S"], 2, n).T
        self.S = S
        v1, rho = st["v1"], st["rho"]
        # sigma_i: the direction joint i moves on the interval ahead (s_d > 0), not the model's
        # sign of a velocity (sign(0) = 0): v1_i = 0 counts as forward, and a neighbour with
        # the other sign makes the interval a reversal (rho_i = 1, both signs; stages.py)
        self.sigma = ca.vertcat(*[ca.if_else(v1[i] >= 0, 1, -1) for i in range(n)])
        self.abs_v1 = ca.fabs(v1)
        A, self.B = N @ st["a"], N @ st["b"]
        Cf = N @ S.T                                  # (n, n): facet j's weight of f_a,i
        an = ca.sqrt(st["a"][0] ** 2 + st["a"][1] ** 2)
        free = [ca.fabs(A[j]) <= _PARALLEL * an for j in range(n)]     # does not bound s_dd
        self.I = [ca.if_else(free[j], 0, 1 / A[j]) for j in range(n)]
        self.aI = [ca.fabs(x) for x in self.I]
        self.pen = [ca.if_else(free[j], ca.inf, 0) for j in range(n)]     # L, U: unbounded
        self.zpen = [ca.if_else(free[j], 0, ca.inf) for j in range(n)]    # Z: only free ones
        self.h = st["h"]
        moving = [1 - rho[i] for i in range(n)]
        self.Wm = [[moving[i] * self.sigma[i] * Cf[j, i] for i in range(n)] for j in range(n)]
        self.We = [[rho[i] * ca.fabs(Cf[j, i]) for i in range(n)] for j in range(n)]
        if friction.affine:   # m_j = B_j sd^2 + m1_j sd + m0_j, e_j = e1_j sd + e0_j
            f0, f1 = friction.f0, friction.f1 * self.abs_v1
            dot = lambda W, f: sum(W[i] * f[i] for i in range(n))
            self.m1 = [dot(self.Wm[j], f1) for j in range(n)]
            self.m0 = [dot(self.Wm[j], f0) for j in range(n)]
            self.e1 = [dot(self.We[j], f1) for j in range(n)]
            self.e0 = [dot(self.We[j], f0) for j in range(n)]

    def _m_e(self, sd):
        n = self.n
        if self.friction.affine:
            return ([self.B[j] * sd * sd + self.m1[j] * sd + self.m0[j] for j in range(n)],
                    [self.e1[j] * sd + self.e0[j] for j in range(n)])
        f = self.friction.positive(self.abs_v1 * sd)
        return ([self.B[j] * sd * sd + sum(self.Wm[j][i] * f[i] for i in range(n))
                 for j in range(n)],
                [sum(self.We[j][i] * f[i] for i in range(n)) for j in range(n)])

    def bounds(self, sd):
        """(L, U, Z) at speed sd: s_dd in [L, U] is feasible, and the facets parallel to a
        need Z >= 0 (-inf / +inf where nothing bounds that side)."""
        m, e = self._m_e(sd)
        L, U, Z = -ca.inf, ca.inf, ca.inf
        for j in range(self.n):
            hh = self.h[j] - e[j]
            c = -m[j] * self.I[j]
            L = ca.fmax(L, c - hh * self.aI[j] - self.pen[j])
            U = ca.fmin(U, c + hh * self.aI[j] + self.pen[j])
            Z = ca.fmin(Z, hh - ca.fabs(m[j]) + self.zpen[j])
        return L, U, Z

    def feasible(self, sd):
        L, U, Z = self.bounds(sd)
        return ca.logic_and(L <= U, Z >= 0), L

    def largest(self, v_top, predicate, halvings, hint=None):
        """(largest sd in [0, v_top] where predicate(sd) holds, holds at 0), by bisection; with
        a ``hint``, on [hint (1 - r), hint (1 + r) + c] (r = HINT_SPAN, c = HINT_FLOOR m/s)
        when that brackets the answer, else on [0, v_top]."""
        ok0, okt = predicate(ca.SX(0)), predicate(v_top)
        lo, hi = ca.SX(0), v_top
        if hint is not None:
            a, b = hint * (1 - HINT_SPAN), hint * (1 + HINT_SPAN) + HINT_FLOOR
            use = ca.logic_and(predicate(a), ca.logic_not(predicate(b)))
            lo, hi = ca.if_else(use, a, lo), ca.if_else(use, b, hi)
        for _ in range(halvings):
            mid = 0.5 * (lo + hi)
            c = predicate(mid)
            lo, hi = ca.if_else(c, mid, lo), ca.if_else(c, hi, mid)
        return ca.if_else(okt, v_top, lo), ok0


def path_functions(d, prefix):
    """``<prefix>_path_coefficients``, ``_path_mvc``, ``_path_backward``, ``_path_forward`` and
    ``_path_torques`` (see the module docstring); each named, with named inputs and outputs."""
    n, p = d.spec.n_legs, len(d.spec.param_names)
    sym = d.sym
    lays = path_layouts(n, p)
    pos, dp, ddp = ca.SX.sym("p", 2), ca.SX.sym("dp", 2), ca.SX.sym("ddp", 2)
    theta, w = ca.SX.sym("theta", p), ca.SX.sym("tau_max", n)
    conv = d.converter_xe(pos)
    Me, Ce_v, S, _ = task_inertia_coriolis(d, conv, dp, [(sym.theta, theta)])   # eq. 12
    sing = d.singularity_measures(conv)
    if n == 2:  # five-bar: the other assembly mode is out of the workspace (model.ik refuses it)
        sing = ca.if_else(conv(d.kin.assembly_side()) * d.spec.fk_branch > 0, sing,
                          ca.DM.nan(2))
    N_mn, h_mn, N_mm, h_mm = force_polygon(S, w)
    out = [ca.Function(
        f"{prefix}_path_coefficients", [pos, dp, ddp, theta, w],
        [Me @ dp, Me @ ddp + Ce_v, ca.vec(S.T), S @ dp, N_mn, h_mn, N_mm, h_mm, sing],
        ["p", "dp", "ddp", "theta", "tau_max"],
        ["a", "b", "S", "v1", "N_min_norm", "h_min_norm", "N_min_max", "h_min_max", "sing"])]

    prm = ca.SX.sym("params", lays["path_params"].size)
    P = lays["path_params"].split(prm)
    friction = _PathFriction(d, P["theta"])
    stage_v = ca.SX.sym("stage", lays["path_stage"].size)
    st = _Stage(n, lays["path_stage"].split(stage_v), friction)
    v_top = P["v_top"]

    y_mvc, ok0 = st.largest(v_top, lambda sd: st.feasible(sd)[0], MVC_BISECTIONS)
    out.append(ca.Function(f"{prefix}_path_mvc", [stage_v, prm],
                           [ca.if_else(ok0, y_mvc * y_mvc, -1)], ["stage", "params"], ["x_mvc"]))

    # one interval [s_k, s_k+1]: the own facets at s_k and the arrival facets at s_k+1
    pair_v = ca.SX.sym("pair", lays["path_pair"].size)
    PR = lays["path_pair"].split(pair_v)
    own = _Stage(n, lays["path_stage"].split(PR["stage"]), friction)
    nxt = _Stage(n, lays["path_stage"].split(PR["next"]), friction)
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
    x_b = ca.if_else(ca.logic_and(ok0, xl >= 0), ca.fmin(y_b * y_b, own.st["x_cap"]), -1)
    out.append(ca.Function(f"{prefix}_path_backward", [x, pair_v, prm], [x_b, x_b],
                           ["x_next_max", "pair", "params"], ["x_max", "y"]))

    fin = ca.SX.sym("input", lays["path_forward_input"].size)
    F = lays["path_forward_input"].split(fin)
    PF = lays["path_pair"].split(F["pair"])
    fown = _Stage(n, lays["path_stage"].split(PF["stage"]), friction)
    fnxt = _Stage(n, lays["path_stage"].split(PF["next"]), friction)
    xk = ca.SX.sym("x")
    L, U, Z = fown.bounds(ca.sqrt(ca.fmax(xk, 0)))
    dlt = fown.st["delta"]
    top = ca.fmin(U, (ca.fmin(F["x_next_max"], PF["next_cap"]) - xk) / (2 * dlt))
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
    out.append(ca.Function(f"{prefix}_path_forward", [xk, fin, prm], [xk + 2 * dlt * sdd, y],
                           ["x", "input", "params"], ["x_next", "y"]))

    sd, sdd = ca.SX.sym("sd"), ca.SX.sym("sdd")
    S2 = st.S
    u = st.st["a"] * sdd + st.st["b"] * sd * sd \
        + S2.T @ friction.signed(st.st["v1"] * sd, st.sigma)
    t_mm, ratio = min_max(S2, u, w)
    out.append(ca.Function(f"{prefix}_path_torques", [stage_v, sd, sdd, prm, w],
                           [u, min_norm(S2, u), t_mm, ratio],
                           ["stage", "sd", "sdd", "params", "tau_max"],
                           ["u", "tau_min_norm", "tau_min_max", "min_max_ratio"]))
    return out
