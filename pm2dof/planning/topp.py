# Time-optimal path parameterisation under the actuators' torque limits, friction included, in C.
"""``plan_time_optimal``: the fastest traversal of a path that the motors allow.

The discretisation is TOPP-RA's (Pham & Pham 2018): x_k = s_d^2 at s_k, a constant
s_dd = u_k on [s_k, s_k+1] (x_k+1 = x_k + 2 delta_k u_k), and the torque facets
|N_j (a u + b x + S^T f_a(S p' sqrt(x)))| <= h_j at each end of every interval: at s_k with
(x_k, u_k) and, arriving, at s_k+1 with (x_k+1, u_k). The friction term makes the facets
nonlinear in sqrt(x) (viscous) and sign-dependent (Coulomb), so the stage sets are not
polytopes; every set the recursion needs is one-dimensional, though, and is computed exactly
in generated C (pm2dof/derive/planning.py), in closed form or by bisection (to 2.3e-8 m/s):

1. the maximum-velocity curve: the largest s_d at each point up to which every speed has a
   feasible s_dd (``map``; in closed form for Coulomb + viscous friction, eq. 2);
2. backward from rest at the end: the largest x_k from which a feasible u_k lands in
   [0, x_k+1,max] where the arrival facets hold too (one ``accumulate`` call);
3. forward from rest at the start: the greatest feasible u_k that stays below x_k+1,max and
   that the arrival facets allow at its own landing speed (regula falsi on the allowed side;
   one ``accumulate`` call). Each x_k is the largest reachable and controllable value: the
   time-optimal profile of the discrete problem (agreeing with toppra and with IPOPT on it),
   where the arrival facets bind when braking (landing on the bound) and accelerating.

Around the passes (:func:`plan_time_optimal`) the grid is refined until it resolves the path
(RESOLUTION) and the torques between the grid points (BETWEEN_TOL at each midpoint,
SAMPLE_TOL at each sample of the trajectory), in place: each round evaluates the new points'
coefficients and the midpoints the added points change, and runs the passes in one C call
that reuses what the added points cannot change (:class:`pm2dof.planning.grid.Grid`), equal
bit for bit to the whole computation on the refined grid.
"""
import time

import numpy as np

from ..core.errors import PlanError
from .check import check_path, require
from .grid import Grid, at, passes, row_max
from .plan import Plan
from .problem import PlanProblem
from .stages import GRID_MAX, grid_points, limits_and_actuators, params

__all__ = ["plan_time_optimal", "plan_on_grid", "solve_profile"]

#: where an interval's facets cannot hold at both ends (riding a steep maximum-velocity curve),
#: it is split into RELAXED_INTO parts and its neighbours into SPLIT_INTO, and the passes
#: rerun, REFINE times (once: splitting in 8, twice, took a second round for about the same;
#: 32 parts instead of 64 leave as few rounds but let the torques inside the intervals exceed
#: tau_max by up to 0.15 %, 48 by 0.095 %, 64 by 0.074 % on pick_and_place, 6 and 30 N m)
REFINE, RELAXED_INTO, SPLIT_INTO = 1, 64, 8
#: the relaxed intervals can be predicted before the first solve: the passes on every
#: COARSE-th grid point find them, and each grid interval inside a relaxed coarse one is split
#: as a relaxed one (the neighbours of the run too; relaxed intervals the first solve still
#: finds outside those are split as above). COARSE = 0: not predicted (the default: the
#: coarse passes cost 0.16 of a 1000-point plan, more than they save: docs/results-planning.md)
COARSE = 0
#: no joint angle and no tangent may turn by more than RESOLUTION rad over a grid interval:
#: a coarser grid is refined (halving, RESOLVE_ROUNDS times at most) before the passes
RESOLUTION, RESOLVE_ROUNDS = 0.05, 40
#: between the grid points the torques may exceed the limits by BETWEEN_TOL of tau_max at an
#: interval's midpoint, and by SAMPLE_TOL at a sample of the trajectory (the model's period:
#: what simulate receives): an interval beyond is halved and the passes rerun, ROUNDS times
BETWEEN_TOL, SAMPLE_TOL, ROUNDS = 1e-3, 1e-4, 16


def solve_profile(problem, stage, s, coef):
    """The three passes of ``problem`` (:class:`pm2dof.planning.problem.PlanProblem`) over one
    whole grid (``stage``, ``coef``: :func:`pm2dof.planning.stages.stages`). Returns (x (K,),
    sdd (K,), x_mvc (K,), relaxed): the intervals whose arrival facets could not hold together
    with the departing ones (only the departing ones are met there)."""
    return passes(problem, stage, coef["arrive"], s, coef["p"])[:4]


def _refine_until_resolved(grid):
    """Halve every interval over which an active joint or the tangent turns by more than
    RESOLUTION rad (|S p'| (rad/m) and |p''| (1/m), the larger of both ends, times the
    length): the path's dynamics must not change much between two grid points, where no limit
    is imposed."""
    for _ in range(RESOLVE_ROUNDS):
        s = grid.s
        # |p''| of the planar rows: phi is linear along every piece (p''_phi = 0, paths.py);
        # np.hypot(*ev.T) of a platform's (K, 3) would take the phi row as ``out``, overwrite it
        ddp = grid.ev[2]
        rate = np.maximum(row_max(np.abs(grid.v1)), np.hypot(ddp[:, 0], ddp[:, 1]))
        wide = np.maximum(rate[:-1], rate[1:]) * np.diff(s)
        bad = np.flatnonzero(wide > RESOLUTION)
        if not bad.size:
            return
        if len(s) + bad.size > GRID_MAX:
            break
        grid.insert(0.5 * (s[bad] + s[bad + 1]))
    k = int(bad[np.argmax(wide[bad])])
    raise PlanError(f"the path turns too fast for a grid of at most {GRID_MAX} points near "
                    f"{at(grid.ev[0], s, k)}: a joint or the tangent turns by {wide[k]:.3g} rad "
                    f"over {s[k + 1] - s[k]:.3g} m after {RESOLVE_ROUNDS} halvings")


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
        its ends, it is split in 64 and its neighbours in 8 and the plan rerun (once); and
        where the torques at an interval's midpoint exceed the limits by more than
        BETWEEN_TOL = 0.1 %, or at a sample of the trajectory by more than SAMPLE_TOL =
        0.01 %, it is halved and the plan rerun (ROUNDS = 16 rounds in all). A coarse grid
        gives a feasible plan, no shorter than the 1000-point one on the paths tested (two
        coarse grids are not ordered: docs/results-planning.md).

    Returns
    -------
    Plan
        ``method`` "time_optimal"; torques at the grid points from the generated C;
        ``info``: ``grid`` (the final count), ``refinements``, ``midpoint_excess`` (the largest
        excess over the limits at an interval's midpoint, a fraction of tau_max),
        ``sample_excess`` (the same at the trajectory's samples, <= SAMPLE_TOL),
        ``arrival_relaxed`` (arc lengths where only the departing facets hold),
        ``split_before`` (intervals split before the first solve where COARSE predicts
        relaxed ones; 0 by default), ``stops``,
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
    return _plan(model, path, tau_max, split, theta, margin, grid, None)


def plan_on_grid(model, path, s, tau_max=None, split="min_max", theta=None, margin=1.0):
    """:func:`plan_time_optimal` on the grid ``s`` (arc lengths, increasing, the path's
    breakpoints among them) as it is: the passes and the checks between the grid points once,
    nothing refined (``info["midpoint_excess"]`` and ``["sample_excess"]`` say what the
    refinement would have fixed). The cost of one unrefined plan of a grid, for the bench."""
    return _plan(model, path, tau_max, split, theta, margin, None, np.asarray(s, dtype=float))


def _split(g, ks):
    """Split the intervals ``ks`` of the grid ``g`` in RELAXED_INTO parts and their neighbours
    in SPLIT_INTO (where the arrival facets fail); returns the arc lengths (a, b) each split
    run spans, neighbours included (2, M)."""
    s = g.s
    ks = np.unique(ks)
    near = np.zeros(len(s) - 1, dtype=bool)     # the neighbours not split themselves
    near[np.clip(ks - 1, 0, None)] = near[np.minimum(ks + 1, len(s) - 2)] = True
    near[ks] = False
    nb = np.flatnonzero(near)
    parts = [(ks, RELAXED_INTO), (nb, SPLIT_INTO)]
    g.insert(np.concatenate([(s[k, None] + np.diff(s)[k, None]
                              * (np.arange(1, n) / n)).ravel() for k, n in parts]))
    lo, hi = np.maximum(ks - 1, 0), np.minimum(ks + 2, len(s) - 1)
    return np.array([s[lo], s[hi]])


def _split_predicted(g):
    """Before the first solve: split where the arrival facets will fail, found by the passes
    on every COARSE-th grid point (:meth:`Grid.coarse_relaxed`): each of the grid's intervals
    inside a relaxed coarse interval as :func:`_split` does. Returns (covered, count): the
    arc lengths (2, M) the splits span (None: nothing predicted, the coarse grid being the
    grid itself or not plannable) and the intervals split."""
    if not COARSE:
        return None, 0
    try:
        found = g.coarse_relaxed(COARSE)
    except PlanError:           # the grid itself decides (and names what fails)
        return None, 0
    if found is None:
        return None, 0
    lo, hi = found
    if not lo.size:
        return np.empty((2, 0)), 0
    ks = np.unique(np.concatenate([np.arange(a, b) for a, b in zip(lo, hi)]))
    if len(g.s) + (RELAXED_INTO + 2 * SPLIT_INTO) * ks.size > GRID_MAX:
        return None, 0
    return _split(g, ks), int(ks.size)


def _uncovered(s, relaxed, covered):
    """The intervals of ``relaxed`` (grid ``s``) that no split run ``covered`` (2, M) holds
    (all of them where covered is None)."""
    if covered is None or not relaxed.size:
        return relaxed
    inside = (s[relaxed, None] >= covered[0]) & (s[relaxed + 1, None] <= covered[1])
    return relaxed[~inside.any(axis=1)]


def _unresolved(s, mid, ev_mid, excess, over, attempt):
    """PlanError: the limits could not be held between the grid points (the intervals
    ``over``: at their midpoints beyond BETWEEN_TOL, or at a sample beyond SAMPLE_TOL)."""
    worst = excess[over].max()
    if worst > BETWEEN_TOL:
        k = int(over[np.argmax(excess[over])])
        what = f"by {100 * worst:.3g} % at {at(ev_mid[0], mid, k)}"
        tol = BETWEEN_TOL
    else:
        k = int(over[0])
        what = "at a sample of the trajectory"
        tol = SAMPLE_TOL
    raise PlanError(f"the torques exceed tau_max {what}, between the grid points s = "
                    f"{s[k]:.6g} and {s[k + 1]:.6g} m, after {attempt} refinements ({len(s)} "
                    f"grid points): the limits cannot be held there within {100 * tol:g} % on a "
                    f"grid of at most {GRID_MAX} points")


def _plan(model, path, tau_max, split, theta, margin, grid, given):
    t0 = time.perf_counter()
    require(model, path)
    tau, tau_actuators = limits_and_actuators(model, tau_max, margin)
    s = grid_points(path, grid) if given is None else given
    prm, th = params(model, theta)
    problem = PlanProblem(model, path, tau, th, split, prm)
    check_path(model, path)             # every 0.5 mm, between the grid points too
    g = Grid(problem, s, path.evaluate(s))
    period = model.spec.sensing["sample_period"]
    refine = given is None
    covered, split_before = None, 0
    for attempt in range(ROUNDS + 1):
        if refine:
            _refine_until_resolved(g)
            if attempt == 0:
                covered, split_before = _split_predicted(g)
        x, sdd, x_mvc, relaxed = g.solve()
        s = g.s
        if refine and attempt < REFINE:     # split where the arrival facets fail
            todo = _uncovered(s, relaxed, covered)
            if todo.size:
                _split(g, todo)
                continue
        mid, ev_mid, excess = g.check_midpoints(x, sdd)
        over = np.flatnonzero(excess > BETWEEN_TOL)
        if not over.size or not refine:
            profile, traj, sample_excess, interval = g.check_samples(x, sdd, period)
        if not over.size:
            over = np.unique(interval[sample_excess > SAMPLE_TOL])
        if not over.size or not refine:
            break
        if attempt == ROUNDS or len(s) + over.size > GRID_MAX:
            _unresolved(s, mid, ev_mid, excess, over, attempt)
        g.insert(mid[over], tuple(e[over] for e in ev_mid))   # halve them
    sdot = profile.sdot
    K, n = len(s), model.n_legs
    outs = (np.empty((K, model.dof)), np.empty((K, n)), np.empty((K, n)), np.empty(K))
    sdd_pt = np.concatenate([sdd[:-1], sdd[-2:-1]])
    model.function("path_torques").map(K, g.stage, sdot, sdd_pt, prm, tau, *outs)
    tau_grid = outs[1] if split == "min_norm" else outs[2]
    stops = g.stops()
    return Plan(path=path, method="time_optimal", split=split,
                max_velocity=np.sqrt(np.maximum(x_mvc, 0.0)), tau=tau_grid,
                tau_peak=np.abs(tau_grid).max(axis=0), tau_max=problem.tau_max,
                margin=float(margin),
                trajectory=traj, profile=profile, compute_time_s=time.perf_counter() - t0,
                info={"grid": K, "stops": s[stops].tolist(), "theta": th.tolist(),
                      "tau_max_actuators": tau_actuators.tolist(),
                      "arrival_relaxed": s[relaxed].tolist(), "refinements": attempt,
                      "split_before": split_before,
                      "midpoint_excess": float(max(excess.max(), 0.0)),
                      "sample_excess": float(max(sample_excess.max(initial=0.0), 0.0))})
