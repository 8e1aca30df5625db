# Time-optimal path parameterisation under the actuators' torque limits, friction included, in C.
"""``plan_time_optimal``: the fastest traversal of a path that the motors allow.

The discretisation is TOPP-RA's (Pham & Pham 2018): x_k = s_d^2 at s_k, a constant
s_dd = u_k on [s_k, s_k+1] (x_k+1 = x_k + 2 delta_k u_k), and the torque facets
|N_j (a u + b x + S^T f_a(S p' sqrt(x)))| <= h_j at each end of every interval: at s_k with
(x_k, u_k) and, arriving, at s_k+1 with (x_k+1, u_k). The friction term makes the facets
nonlinear in sqrt(x) (viscous) and sign-dependent (Coulomb), so the stage sets are not
polytopes; every set the recursion needs is one-dimensional, though, and is computed exactly
(to 2.3e-8 m/s) by bisection in generated C (pm2dof/derive/planning.py):

1. the maximum-velocity curve: the largest s_d at each point with a feasible s_dd (``map``);
2. backward from rest at the end: the largest x_k from which a feasible u_k lands in
   [0, x_k+1,max] where the arrival facets hold too (one ``accumulate`` call);
3. forward from rest at the start: the greatest feasible u_k that stays below x_k+1,max and
   that the arrival facets allow at its own landing speed (regula falsi on the allowed side;
   one ``accumulate`` call). Each x_k is the largest reachable and controllable value: the
   time-optimal profile of the discrete problem (agreeing with toppra and with IPOPT on it),
   where the arrival facets bind when braking (landing on the bound) and accelerating.

Around the passes (:func:`plan_time_optimal`) the grid is refined until it resolves the path
(RESOLUTION) and the torques between the grid points (BETWEEN_TOL at each midpoint).
"""
import time

import numpy as np

from ..core.errors import PlanError
from .check import check_path, require
from .plan import Plan, PathProfile, grid_times, sample
from .stages import GRID_MAX, grid_points, limits, params, point_stages, stages

__all__ = ["plan_time_optimal", "solve_profile"]

_TOL = 1e-9   # relative slack of the forward pass's own checks (rounding)
#: where an interval's facets cannot hold at both ends (riding a steep maximum-velocity curve),
#: it and its neighbours are split into SPLIT_INTO parts and the passes rerun, REFINE times
REFINE, SPLIT_INTO = 2, 8
#: no joint angle and no tangent may turn by more than RESOLUTION rad over a grid interval:
#: a coarser grid is refined (halving, RESOLVE_ROUNDS times at most) before the passes
RESOLUTION, RESOLVE_ROUNDS = 0.05, 40
#: between the grid points the torques may exceed the limits by BETWEEN_TOL of tau_max at an
#: interval's midpoint: an interval beyond is halved and the passes rerun, ROUNDS times at most
BETWEEN_TOL, ROUNDS = 1e-3, 12


def _at(coef, s, k):
    p = coef["p"][k]
    return f"s = {s[k]:.6g} m, point ({p[0]:.6g}, {p[1]:.6g}) m"


def _stop_indices(path, s):
    return np.searchsorted(s, path.stops) if len(path.stops) else np.array([], dtype=int)


def _merge(s, ev, new, ev_new):
    """The grid ``s`` with the points ``new`` added, and their evaluations, in order."""
    order = np.argsort(np.concatenate([s, new]), kind="stable")
    return (np.concatenate([s, new])[order],
            tuple(np.concatenate([e, f])[order] for e, f in zip(ev, ev_new)))


def _resolved(model, path, s, ev, w, theta, split):
    """``stages`` on the grid ``s`` (K,) with its ``ev`` = path.evaluate(s), after halving every
    interval over which an active joint or the tangent turns by more than RESOLUTION rad
    (|S p'| (rad/m) and |p''| (1/m), the larger of both ends, times the length): the path's
    dynamics must not change much between two grid points, where no limit is imposed.
    Returns (s, ev, stops, stage, coef)."""
    for _ in range(RESOLVE_ROUNDS):
        stops = _stop_indices(path, s)
        stage, coef = stages(model, path, s, w, theta, split, stops, ev)
        rate = np.maximum(np.abs(coef["v1"]).max(axis=1), np.hypot(*coef["ddp"].T))
        wide = np.maximum(rate[:-1], rate[1:]) * np.diff(s)
        bad = np.flatnonzero(wide > RESOLUTION)
        if not bad.size:
            return s, ev, stops, stage, coef
        if len(s) + bad.size > GRID_MAX:
            break
        new = 0.5 * (s[bad] + s[bad + 1])
        s, ev = _merge(s, ev, new, path.evaluate(new))
    k = int(bad[np.argmax(wide[bad])])
    raise PlanError(f"the path turns too fast for a grid of at most {GRID_MAX} points near "
                    f"{_at(coef, s, k)}: a joint or the tangent turns by {wide[k]:.3g} rad "
                    f"over {s[k + 1] - s[k]:.3g} m after {RESOLVE_ROUNDS} halvings")


def _between(model, path, s, x, sdd, theta, w, split, prm, cache):
    """The plan between its grid points: each interval's midpoint (K-1,), its p, p', p'' (the
    ``cache`` (midpoints, evaluations) of the previous round reused where they match) and the
    excess of the split's torques over the limits there, max_i |tau_i| / w_i - 1 (K-1,), at
    s_d^2 = (x_k + x_k+1) / 2 (linear in s on the interval) and the interval's s_dd."""
    mid = 0.5 * (s[:-1] + s[1:])
    old, old_ev = cache
    j = np.minimum(np.searchsorted(old, mid), max(len(old) - 1, 0))
    hit = (old[j] == mid) if len(old) else np.zeros(len(mid), dtype=bool)
    ev = tuple(np.empty((len(mid), 2)) for _ in range(3))
    if hit.any():
        for e, o in zip(ev, old_ev):
            e[hit] = o[j[hit]]
    if not hit.all():
        for e, f in zip(ev, path.evaluate(mid[~hit])):
            e[~hit] = f
    stage = point_stages(model, mid, ev, theta, w, split, check=False)[0]
    M, n = len(mid), model.n_legs
    sd = np.sqrt(np.maximum(0.5 * (x[:-1] + x[1:]), 0.0))
    tau_mn, ratio = np.empty((M, n)), np.empty(M)
    model.function("path_torques").map(M, stage, sd, np.ascontiguousarray(sdd[:-1]), prm, w,
                                        None, tau_mn, None, ratio)
    if split == "min_norm":
        ratio = np.abs(tau_mn / w).max(axis=1)
    excess = ratio - 1.0
    excess[~np.isfinite(excess)] = np.inf   # out of reach between two grid points: refined,
    return mid, ev, excess                  # and the new grid point's check names it


def _check_forward(coef, s, x, sdd, L, U, Z, h, x_mvc):
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
                    f"{_at(coef, s, k)}: {what}; a finer grid may avoid it")


def solve_profile(model, stage, prm, s, coef):
    """The three passes over one grid. Returns (x (K,), sdd (K,), x_mvc (K,), relaxed): the
    intervals whose arrival facets could not hold together with the departing ones (only the
    departing ones are met there: collocation's O(delta) error)."""
    K = len(s)
    x_mvc = np.empty(K)
    mvc = model.function("path_mvc")
    mvc.map(K, stage, prm, x_mvc)
    bad = np.flatnonzero(x_mvc < 0)
    if bad.size:
        k = int(bad[0])
        raise PlanError(f"the torque limits cannot move the robot along the path at "
                        f"{_at(coef, s, k)}: even at rest no path acceleration keeps every "
                        f"|tau_i| within tau_max (Coulomb friction and the split's force "
                        f"polygon leave no feasible force along the path)")
    sl = model.layout("path_stage").slices
    x_cap = stage[:, sl["x_cap"]].ravel()
    interior = np.flatnonzero((x_mvc <= 0) & (x_cap > 0))
    if interior.size:
        k = int(interior[0])
        raise PlanError(f"zero feasible velocity at {_at(coef, s, k)}: the torque limits hold "
                        f"the path there only at rest (the maximum-velocity curve touches 0)")
    arrive = coef["arrive"]
    cap = x_mvc.copy()                      # the arrival facets' own maximum-velocity curve
    other = np.flatnonzero(np.any(arrive != stage, axis=1))
    if other.size:
        part = np.empty(other.size)
        mvc.map(other.size, np.ascontiguousarray(arrive[other]), prm, part)
        cap[other] = part
    fin = model.layout("path_forward_input")
    inp = np.empty((K - 1, fin.size))             # per interval: pair, then x_next_max
    pair = model.layout("path_pair").unpack(inp[:, fin.slices["pair"]])
    pair["stage"][:], pair["next"][:], pair["next_cap"][:, 0] = stage[:-1], arrive[1:], cap[1:]
    # backward: controllable bounds, from rest at the end
    back = np.empty(K - 1)
    xb = np.zeros(1)
    model.function("path_backward").accumulate(
        xb, np.ascontiguousarray(inp[::-1, fin.slices["pair"]]), prm, back)
    hi = np.concatenate([back[::-1], [0.0]])
    if hi[0] < 0:
        k = int(np.flatnonzero(hi < 0)[-1])
        raise PlanError(f"the robot cannot reach the end of the path at rest from "
                        f"{_at(coef, s, k)} with these torque limits: no feasible deceleration "
                        f"(even near rest the motors must balance the Coulomb friction; a larger "
                        f"tau_max, or the min_max split, leaves more room)")
    # forward: greedy from rest at the start
    inp[:, fin.slices["x_next_max"]] = hi[1:, None]
    out = model.layout("path_forward_output")
    y = np.empty((K - 1, out.size))
    xf = np.zeros(1)
    model.function("path_forward").accumulate(xf, inp, prm, y)
    Y = {k: v[:, 0] for k, v in out.unpack(y).items()}
    x = np.concatenate([Y["x"], xf])
    sdd, L, U, Z = Y["sdd"], Y["L"], Y["U"], Y["Z"]
    relaxed = np.flatnonzero(Y["arrival_ok"] == 0)  # the arrival facets do not hold there
    _check_forward(coef, s, x, sdd, L, U, Z, stage[:-1, sl["h"]].max(axis=1), x_mvc)
    x = np.maximum(x, 0.0)
    x[x_cap == 0] = 0.0
    return x, np.concatenate([sdd, sdd[-1:]]), x_mvc, relaxed


def plan_time_optimal(model, path, tau_max=None, split="min_max", theta=None, margin=1.0,
                      grid=1000):
    """The time-optimal traversal of ``path`` from rest to rest under the torque limits.

    Parameters
    ----------
    model : Model
    path : TaskPath
    tau_max : float or array_like (n,), optional
        Actuator torque limits, N m (default ``[limits] tau_max`` of the model file).
    split : {"min_max", "min_norm"}
        ``"min_norm"``: tau = S (S^T S)^-1 u (eq. 21) within the limits; ``"min_max"``: any tau
        with S^T tau = u within the limits (the force zonotope, exactly).
    theta : array_like (5n,), optional
        Dynamic parameters (default the model's nominal theta, Tables 1-2); friction, viscous
        and Coulomb, is the model's own law with these coefficients. Must be physical, by the
        model file's rule for ``[nominal]``: every leg's M_i (eq. 1) positive definite and
        friction >= 0 (an identified theta: the physically consistent one of ``identify fit``).
    margin : float
        In (0, 1]: the plan uses tau_max * margin (< 1 leaves headroom for feedback; for more
        torque pass a larger ``tau_max``).
    grid : int
        Grid points along the path, 2 to GRID_MAX = 100000 (graded towards the stops,
        breakpoints included). The grid is then refined until it resolves the path and the
        plan: every interval over which an active joint or the tangent turns by more than
        RESOLUTION = 0.05 rad is halved; where an interval's torque facets cannot hold at both
        its ends, it and its neighbours are split in 8 and the plan rerun (at most twice); and
        where the torques at an interval's midpoint exceed the limits by more than
        BETWEEN_TOL = 0.1 %, it is halved and the plan rerun (ROUNDS = 12 rounds in all).
        A coarse grid gives a feasible plan, longer than a fine one.

    Returns
    -------
    Plan
        ``method`` "time_optimal"; torques at the grid points from the generated C;
        ``info``: ``grid`` (the final count), ``refinements``, ``midpoint_excess`` (the largest
        excess over the limits at an interval's midpoint, a fraction of tau_max),
        ``arrival_relaxed`` (arc lengths where only the departing facets hold), ``stops``,
        ``theta``, ``tau_max_actuators`` (tau_max before the margin).

    Raises
    ------
    PlanError
        A grid or margin out of range, bad limits, limits too low to follow the path (names the
        arc length and the point), a path that turns too fast to resolve on GRID_MAX points.
    ArgumentError
        theta not 5n finite numbers, or not physical (:meth:`pm2dof.Model.checked_theta`).
    ArgumentTypeError
        ``model`` not a Model or ``path`` not a TaskPath.
    WorkspaceError, SingularityError
        The path leaves the workspace or comes closer to a singularity than its threshold
        (:func:`check_path`, every 0.5 mm; names s and the point).

    Examples
    --------
    >>> import pm2dof
    >>> m = pm2dof.load_model()
    >>> path = pm2dof.TaskPath.line([0.22, 0.29], [0.27, 0.24])
    >>> plan = pm2dof.plan_time_optimal(m, path, tau_max=6.0, split="min_max", grid=200)
    >>> bool(0.1 < plan.duration < 0.216), bool((plan.tau_peak <= 6.0 + 1e-9).all())
    (True, True)
    """
    t0 = time.perf_counter()
    require(model, path)
    w = limits(model, tau_max, margin)
    s = grid_points(path, grid)
    prm, th = params(model, theta)
    check_path(model, path)             # every 0.5 mm, between the grid points too
    ev = path.evaluate(s)
    cache = (np.empty(0), None)             # midpoints already evaluated, and their p, p', p''
    for attempt in range(ROUNDS + 1):
        s, ev, stops, stage, coef = _resolved(model, path, s, ev, w, th, split)
        x, sdd, x_mvc, relaxed = solve_profile(model, stage, prm, s, coef)
        if relaxed.size and attempt < REFINE:   # split where the arrival facets failed
            ks = np.unique(np.clip(np.concatenate([relaxed - 1, relaxed, relaxed + 1]), 0,
                                   len(s) - 2))
            new = (s[ks, None] + np.diff(s)[ks, None]
                   * (np.arange(1, SPLIT_INTO) / SPLIT_INTO)).ravel()
            s, ev = _merge(s, ev, new, path.evaluate(new))
            continue
        mid, ev_mid, excess = _between(model, path, s, x, sdd, th, w, split, prm, cache)
        cache = (mid, ev_mid)
        over = np.flatnonzero(excess > BETWEEN_TOL)
        if not over.size:
            break
        if attempt == ROUNDS or len(s) + over.size > GRID_MAX:
            k = int(over[np.argmax(excess[over])])
            raise PlanError(f"the torques exceed tau_max by {100 * excess[k]:.3g} % between "
                            f"the grid points s = {s[k]:.6g} and {s[k + 1]:.6g} m (at "
                            f"{_at({'p': ev_mid[0]}, mid, k)}) after {attempt} refinements "
                            f"({len(s)} grid points): the limits cannot be held there within "
                            f"{100 * BETWEEN_TOL:g} % on a grid of at most {GRID_MAX} points")
        s, ev = _merge(s, ev, mid[over], tuple(e[over] for e in ev_mid))   # halve them
    sdot = np.sqrt(x)
    t = grid_times(s, sdot)
    K, n = len(s), model.n_legs
    outs = (np.empty((K, 2)), np.empty((K, n)), np.empty((K, n)), np.empty(K))
    sdd_pt = np.concatenate([sdd[:-1], sdd[-2:-1]])
    model.function("path_torques").map(K, stage, sdot, sdd_pt, prm, w, *outs)
    tau = outs[1] if split == "min_norm" else outs[2]
    profile = PathProfile(s, sdot, sdd, t)
    traj = sample(path, profile, model.spec.sensing["sample_period"])
    return Plan(path=path, method="time_optimal", split=split, duration=float(t[-1]), s=s,
                sdot=sdot, sddot=sdd, t=t, max_velocity=np.sqrt(np.maximum(x_mvc, 0.0)),
                tau=tau, tau_peak=np.abs(tau).max(axis=0), tau_max=w, margin=float(margin),
                trajectory=traj, compute_time_s=time.perf_counter() - t0,
                info={"grid": K, "stops": s[stops].tolist(), "theta": th.tolist(),
                      "tau_max_actuators": limits(model, tau_max, 1.0).tolist(),
                      "arrival_relaxed": s[relaxed].tolist(), "refinements": attempt,
                      "midpoint_excess": float(max(excess.max(), 0.0))})
