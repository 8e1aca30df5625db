# The planner's grid, refined in place, and the NumPy reference of its passes (run in C).
"""The time-optimal planner's grid, refined in place: :class:`Grid`.

A refinement adds points inside some intervals. What the plan needs is recomputed where an
added point can change it, and equals what the whole computation on the refined grid gives,
bit for bit (every generated function is evaluated per point or per interval, with the same
inputs):

* each point's coefficients (``path_coefficients``) depend on its arc length alone: only the
  new points are evaluated;
* the passes (a point's ``path_stage`` row linked to its neighbours, the maximum-velocity
  curve, the backward and the forward pass) are one C call (:func:`.cpasses.solve_c`,
  pm2dof/planning/_passes.c) that takes from the previous solve what the added points cannot
  have changed: the curve where a row is the same, the backward pass above the last interval
  whose input changed, the forward pass before the first, and each step where the pass meets
  the previous one again (the same interval from the same bound or speed: the previous step,
  not evaluated). :func:`passes` is the whole computation in NumPy around the
  generated C: the reference, and what names the place where a grid fails;
* an interval's midpoint check is recomputed where the interval is new or its speeds or
  acceleration changed.
"""
import numpy as np

from ..core.errors import PlanError
from .check import point_text
from .cpasses import Linking, solve_c
from .plan import PathProfile, grid_times, sampled
from .stages import junction_left, link, point_stages
from .workspace import Workspace, workspace

__all__ = ["Grid", "passes", "row_max"]

_TOL = 1e-9   # relative slack of the forward pass's own checks (rounding)


def at(p, s, k):
    """Where grid point ``k`` is, for messages: its arc length and point."""
    return f"s = {s[k]:.6g} m, point {point_text(p[k])}"


def row_max(a):
    """a.max(axis=1) of ``a`` (K, n), column by column: the same values, at a tenth of the
    cost for a few columns (numpy reduces a short last axis row by row)."""
    out = a[:, 0].copy()
    for col in a.T[1:]:
        np.maximum(out, col, out=out)
    return out


def _same_rows(a, b):
    return (a == b).all(axis=1)


def _check_forward(p, s, x, sdd, L, U, Z, h, x_mvc):
    """PlanError naming the first interval where the forward pass broke one of its own
    conditions (rounding aside; none is known to happen since the backward pass keeps every
    landing at or above rest): s_dd within [L, U] leaving s_k, the facets that do not bound
    s_dd held (Z >= 0), s_d^2 >= 0 at s_k+1."""
    scale = np.maximum(1.0, np.abs(sdd))
    below, above = sdd < L - _TOL * scale, sdd > U + _TOL * scale
    held = Z < -_TOL * h
    landed = x[1:] < -_TOL * np.maximum(x_mvc[1:], 1e-12)
    wrong = below | above | held | landed
    if not wrong.any():
        return
    k = int(np.argmax(wrong))
    if landed[k]:
        what = (f"its path acceleration s_dd = {sdd[k]:.6g} m/s^2 from s_d^2 = {x[k]:.6g} "
                f"m^2/s^2 lands at s_d^2 = {x[k + 1]:.6g} < 0 at s = {s[k + 1]:.6g} m (the "
                f"robot would stop inside the interval)")
    elif held[k]:
        what = (f"a torque facet parallel to the path's acceleration is violated at s_d^2 = "
                f"{x[k]:.6g} m^2/s^2 (by {-Z[k]:.6g} N)")
    else:
        what = (f"s_dd = {sdd[k]:.6g} m/s^2 is outside its feasible interval "
                f"[{L[k]:.6g}, {U[k]:.6g}] m/s^2 at s_d^2 = {x[k]:.6g} m^2/s^2")
    raise PlanError(f"the time-optimal forward pass failed on the interval leaving "
                    f"{at(p, s, k)}: {what}; a finer grid may avoid it")


def _mvc(problem, rows):
    out = np.empty(len(rows))
    if len(rows):
        problem.model.function("path_mvc").map(len(rows), np.ascontiguousarray(rows),
                                               problem.params, out)
    return out


def passes(problem, stage, arrive, s, p, ws=None):
    """The maximum-velocity curve and the backward and forward passes of ``problem``
    (:class:`.problem.PlanProblem`) over the grid ``s`` (K,) (``stage``, ``arrive``:
    :func:`pm2dof.planning.stages.link`; ``p`` (K, m) its points, for messages), in NumPy
    around the generated C: the reference of :func:`.cpasses.solve_c`, which the planner runs,
    and what raises the PlanError naming where a grid fails. ``ws``: the
    :class:`.workspace.Workspace` holding the passes' inputs (default a fresh one); nothing
    returned lives in it.

    Returns (x (K,), sdd (K,), x_mvc (K,), relaxed): relaxed the intervals whose arrival facets
    could not hold together with the departing ones (only the departing ones are met there:
    collocation's O(delta) error)."""
    K, model, prm = len(s), problem.model, problem.params
    ws = Workspace() if ws is None else ws
    sl = model.layout("path_stage").slices
    x_mvc = _mvc(problem, stage)
    bad = np.flatnonzero(x_mvc < 0)
    if bad.size:
        k = int(bad[0])
        raise PlanError(f"the torque limits cannot move the robot along the path at "
                        f"{at(p, s, k)}: even at rest no path acceleration keeps every "
                        f"|tau_i| within tau_max (Coulomb friction and the split's force "
                        f"polygon leave no feasible force along the path)")
    x_cap = stage[:, sl["x_cap"]].ravel()
    interior = np.flatnonzero((x_mvc <= 0) & (x_cap > 0))
    if interior.size:
        k = int(interior[0])
        raise PlanError(f"zero feasible velocity at {at(p, s, k)}: the torque limits hold "
                        f"the path there only at rest (the maximum-velocity curve touches 0)")
    # the arrival facets' own maximum-velocity curve where they differ from the point's own
    cap = x_mvc.copy()
    todo = np.flatnonzero(np.any(arrive != stage, axis=1))
    cap[todo] = _mvc(problem, arrive[todo])
    fin = model.layout("path_forward_input")
    inp = ws.take("forward", (K - 1, fin.size))   # per interval: pair, x_next_max, memo
    F = fin.unpack(inp)
    P = inp[:, fin.slices["pair"]]
    pair = model.layout("path_pair").unpack(P)
    pair["stage"][:], pair["next"][:], pair["next_cap"][:, 0] = stage[:-1], arrive[1:], cap[1:]
    # backward: controllable bounds, from rest at the end (the memo columns, for reusing a
    # previous pass's steps, unused: zero)
    bl = model.layout("path_backward_input")
    rows = ws.take("backward", (K - 1, bl.size))
    rows[:, bl.slices["pair"]] = P[::-1]
    rows[:, bl.slices["pair"].stop:] = 0.0
    back = ws.take("back", (K - 1,))
    model.function("path_backward").accumulate(np.array([0.0]), rows, prm, back)
    hi = np.append(back[::-1], 0.0)
    if hi[0] < 0:
        k = int(np.flatnonzero(hi < 0)[-1])
        raise PlanError(f"the robot cannot reach the end of the path at rest from "
                        f"{at(p, s, k)} with these torque limits: no feasible deceleration "
                        f"(even near rest the motors must balance the Coulomb friction; a larger "
                        f"tau_max, or the min_max split, leaves more room)")
    # forward: greedy from rest at the start
    F["x_next_max"][:, 0] = hi[1:]
    for key in ("same", "x_in", "x_out"):
        F[key][:] = 0.0
    out = model.layout("path_forward_output")
    y = np.empty((K - 1, out.size))
    xf = np.array([0.0])
    model.function("path_forward").accumulate(xf, inp, prm, y)
    x_raw = np.append(y[:, out.slices["x"]][:, 0], xf[0])
    Y = {k: v[:, 0] for k, v in out.unpack(y).items()}
    sdd, L, U, Z = Y["sdd"], Y["L"], Y["U"], Y["Z"]
    relaxed = np.flatnonzero(Y["arrival_ok"] == 0)  # the arrival facets do not hold there
    _check_forward(p, s, x_raw, sdd, L, U, Z, stage[:-1, sl["h"]].max(axis=1), x_mvc)
    x = np.maximum(x_raw, 0.0)
    x[x_cap == 0] = 0.0
    return x, np.concatenate([sdd, sdd[-1:]]), x_mvc, relaxed


class Grid:
    """The planner's grid of ``problem``'s path (:class:`.problem.PlanProblem`; arc lengths
    ``s`` with ``ev`` = path.evaluate(s)) and each point's coefficients; :meth:`insert` adds
    points, :meth:`solve` runs the passes, :meth:`check_midpoints` checks the intervals'
    midpoints and :meth:`check_samples` the trajectory, each recomputing only what the points
    added since its previous call can change."""

    def __init__(self, problem, s, ev):
        self.problem = problem
        self.s, self.ev = s, tuple(np.ascontiguousarray(e) for e in ev)
        self.base, outs = point_stages(problem, s, self.ev)
        self.v1 = outs["v1"]
        self.left = junction_left(problem)
        self.linking = Linking(problem, self.left)
        self.memo = self.mid = None
        self.ws = workspace()
        self.stage = self.arrive = None

    def insert(self, new, ev_new=None):
        """Add the arc lengths ``new`` (each inside an interval; ``ev_new`` their
        path.evaluate, if known). Raises WorkspaceError or SingularityError at one that is not
        clear (:func:`point_stages`)."""
        ev_new = tuple(np.ascontiguousarray(e)
                       for e in (ev_new or self.problem.path.evaluate(new)))
        base, outs = point_stages(self.problem, new, ev_new)
        s = np.concatenate([self.s, new])
        order = np.argsort(s, kind="stable")
        at = np.empty_like(order)            # where each old, then each new, point goes
        at[order] = np.arange(len(s))
        old, added = at[:len(self.s)], at[len(self.s):]

        def merged(a, b):       # scattered into one new array: no concatenated temporary
            out = np.empty((len(s),) + a.shape[1:])
            out[old], out[added] = a, b
            return out

        self.s = s[order]
        self.ev = tuple(merged(e, f) for e, f in zip(self.ev, ev_new))
        self.base = merged(self.base, base)
        self.v1 = merged(self.v1, outs["v1"])

    def coarse_relaxed(self, every):
        """Where the arrival facets will not hold, found cheaply: the passes on every
        ``every``-th grid point (the breakpoints and stops kept), whose relaxed intervals are
        mapped back to this grid. Returns (lo, hi) (M,) each: the grid indices that bound each
        relaxed interval of the coarse grid (hi - lo <= ``every``), or None where the coarse
        grid is this grid (nothing saved). Nothing of the coarse solve is kept."""
        K = len(self.s)
        keep = np.zeros(K, dtype=bool)
        keep[::every] = True
        keep[-1] = True
        keep[np.searchsorted(self.s, self.problem.path.breakpoints)] = True
        idx = np.flatnonzero(keep)
        if len(idx) == K:
            return None
        s = self.s[idx]
        stops = np.searchsorted(s, self.problem.path.stops)
        relaxed = solve_c(self.linking, s, self.base[idx], self.v1[idx], stops)
        if relaxed is None:     # the grid itself decides (and names what fails)
            raise PlanError("the coarse grid cannot be planned")
        relaxed = relaxed[4]         # nothing of the coarse solve is kept
        return idx[relaxed], idx[relaxed + 1]

    def stops(self):
        stops = self.problem.path.stops
        return np.searchsorted(self.s, stops) if len(stops) else np.array([], dtype=int)

    def solve(self):
        """The passes on the current grid, in one C call (:func:`.cpasses.solve_c`, taking the
        previous solve's results where the added points cannot have changed them): (x, sdd,
        x_mvc, relaxed). Where they fail, the NumPy passes (:func:`passes`) raise their
        PlanError."""
        stops = self.stops()
        out = solve_c(self.linking, self.s, self.base, self.v1, stops, self.memo)
        if out is None:
            self.stage, self.arrive = link(self.problem, self.s, self.base, self.v1, stops,
                                           self.left)
            passes(self.problem, self.stage, self.arrive, self.s, self.ev[0], self.ws)
            raise RuntimeError("the planner's passes in C failed where the NumPy passes did "
                               "not: please report this with the path and the model")
        self.stage, x, sdd, x_mvc, relaxed, self.memo = out
        return x, sdd, x_mvc, relaxed

    def _ratio(self, stage, sd, sdd):
        """max_i |tau_i| / tau_max,i of the split at the rows ``stage`` (M, size)."""
        pb = self.problem
        M, n = len(stage), pb.model.n_legs
        tau_mn, ratio = np.empty((M, n)), np.empty(M)
        if M:
            pb.model.function("path_torques").map(M, np.ascontiguousarray(stage), sd,
                                                  np.ascontiguousarray(sdd), pb.params,
                                                  pb.tau_max, None, tau_mn, None, ratio)
        if pb.split == "min_norm":
            ratio = row_max(np.abs(tau_mn / pb.tau_max))
        return ratio

    def check_midpoints(self, x, sdd):
        """The plan between its grid points: each interval's midpoint (K-1,), its p, p', p''
        and the excess of the split's torques over the limits there, max_i |tau_i| / tau_max,i - 1
        (K-1,), at s_d^2 = (x_k + x_k+1) / 2 (linear in s on the interval) and the interval's
        s_dd. Intervals of the previous call reuse its midpoint's coefficients, and its excess
        where their speeds and acceleration are the same."""
        s = self.s
        a, b = s[:-1], s[1:]
        mid = 0.5 * (a + b)
        key = np.column_stack([x[:-1], x[1:], sdd[:-1]])
        M = len(mid)
        c = self.mid
        if c is not None:
            j = np.minimum(np.searchsorted(c["a"], a), len(c["a"]) - 1)
            hit = (c["a"][j] == a) & (c["b"][j] == b)
        else:
            j, hit = np.zeros(M, dtype=int), np.zeros(M, dtype=bool)
        miss = np.flatnonzero(~hit)
        if len(miss) == M:          # nothing to reuse: the new arrays as they come
            ev = self.problem.path.evaluate(mid)
            stage = point_stages(self.problem, mid, ev, check=False)[0]
        else:
            ev = tuple(np.empty((M, e.shape[1])) for e in self.ev)
            stage = np.empty((M, self.base.shape[1]))
            for e, o in zip(ev, c["ev"]):
                e[hit] = o[j[hit]]
            stage[hit] = c["stage"][j[hit]]
            if miss.size:
                ev_miss = self.problem.path.evaluate(mid[miss])
                for e, f in zip(ev, ev_miss):
                    e[miss] = f
                stage[miss] = point_stages(self.problem, mid[miss], ev_miss, check=False)[0]
        excess = np.empty(M)
        same = hit & _same_rows(key, c["key"][j]) if c is not None else hit
        excess[same] = c["excess"][j[same]] if c is not None else 0.0
        todo = np.flatnonzero(~same)
        sd = np.sqrt(np.maximum(0.5 * (key[todo, 0] + key[todo, 1]), 0.0))
        rows = stage if len(todo) == M else stage[todo]     # every row: no gathered copy
        excess[todo] = self._ratio(rows, sd, key[todo, 2]) - 1.0
        excess[~np.isfinite(excess)] = np.inf   # out of reach between two grid points: refined,
        self.mid = {"a": a, "b": b, "ev": ev, "stage": stage, "key": key,   # and the new grid
                    "excess": excess}                                       # point names it
        return mid, ev, excess

    def check_samples(self, x, sdd, period):
        """The trajectory at ``period`` (what ``simulate`` receives) and its torques: (profile,
        trajectory, excess (N,) of the split's torques over the limits at each sample before
        the end, interval (N,) the grid interval of each)."""
        sdot = np.sqrt(x)
        profile = PathProfile(self.s, sdot, sdd, grid_times(self.s, sdot))
        traj, (s, sd, u), ev = sampled(self.problem.path, profile, period)
        moving = np.flatnonzero(traj.t < profile.duration)
        st = point_stages(self.problem, s[moving], tuple(e[moving] for e in ev), check=False)[0]
        excess = self._ratio(st, sd[moving], u[moving]) - 1.0
        excess[~np.isfinite(excess)] = np.inf
        k = np.clip(np.searchsorted(profile.t, traj.t[moving], side="right") - 1, 0,
                    len(self.s) - 2)
        return profile, traj, excess, k
