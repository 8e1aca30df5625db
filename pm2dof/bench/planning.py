# Benchmark of the time-optimal planner: pm2dof.plan_time_optimal beside toppra on the same problem.
"""How fast ``plan_time_optimal`` is, and how it compares with TOPP-RA (``toppra``, the
reference time-optimal path parameterisation) on the same friction-free problem.

The problem: the model's fastest move (its start/end as a line, a platform's with phi:
dimension m = ``model.dof``), 1,000 grid points (toppra is
given pm2dof's grid), the min-max split's force polygon (the zonotope's facets from the
generated ``path_coefficients``) as toppra's ``F u <= g`` at both ends of every interval
(toppra's default interpolation scheme, pm2dof's discretisation), and theta with every
friction entry zero (toppra's convex formulation cannot take viscous friction). Two toppra
timings:

* ``toppra_ms``: what a user runs, ``TOPPRA(...)`` with a ``SecondOrderConstraint`` whose
  inverse dynamics are pm2dof's generated Me and Ce, and Ge under gravity (one C call each
  per point) and ``compute_parameterization``;
* ``toppra_solve_ms``: the same with the constraint coefficients precomputed (toppra's solver
  alone, its Cython Seidel LP).

Each timed run follows an untimed run of the same (:func:`pm2dof.bench.timing.warm_then_time`):
a pm2dof plan that directly follows toppra's run pays 0.8-1 ms more (the paper's line 2.8 ->
3.7 ms, the caches and branch predictors refilled after toppra's ~40 ms of Python), a cost of
the run before it that the next plan no longer pays; toppra gets the same warm start. Timed
straight after toppra, as before November 2026, that cost counted in the refined plan's time
but not in the unrefined one's.

toppra is optional: without it those keys are None and ``notes`` says why.
"""
import time
from functools import partial

import numpy as np

from ..control.trajectory import line_moves
from ..planning import TaskPath, plan_time_optimal
from ..planning.pathfile import model_move_path
from ..planning.problem import PlanProblem
from ..planning.smooth import plan_smooth
from ..planning.stages import grid_points, limits, params, stages
from .baselines import friction_free
from .timing import stats, warm_then_time

__all__ = ["bench_planning", "bench_refinement", "bench_paths", "toppra_runner", "ToppraPath",
           "friction_free"]


class ToppraPath:
    """A :class:`pm2dof.TaskPath` as a toppra geometric path (dof: the path's dimension, x, y
    and a platform's phi)."""

    def __init__(self, path):
        self.path = path
        self.dof = path.dim
        self.path_interval = np.array([0.0, path.length])
        self.waypoints = None

    def __call__(self, s, order=0):
        scalar = np.ndim(s) == 0
        out = self.path.evaluate(np.atleast_1d(s))[order]
        return out[0] if scalar else out


def _toppra_constraints(model, theta, N_of, h_of, precomputed=None):
    """toppra's SecondOrderConstraint (Me, Ce from the generated C; F u <= g from N_of/h_of) in
    its default interpolation scheme (both ends of every interval, like pm2dof's), or with
    ``precomputed`` = (a, b, c, F, g) at the grid points a constraint that only hands over
    their interpolation form."""
    import toppra
    from toppra.constraint import DiscretizationType, LinearConstraint
    from toppra.constraint.linear_constraint import canlinear_colloc_to_interpolate
    if precomputed is not None:
        class Given(LinearConstraint):
            def __init__(self):
                super().__init__()
                self.discretization_type = DiscretizationType.Interpolation
                self.identical = False

            def compute_constraint_params(self, path, gridpoints):
                return canlinear_colloc_to_interpolate(*precomputed, None, None, gridpoints)
        return Given()

    gravity = model.spec.has_gravity

    def inv_dyn(p, v, a):     # eq. 10's task force without friction: Me a + Ce v (+ Ge)
        q = model.ik(p)
        u = model.Me(q, theta) @ a + model.Ce(q, v, theta) @ v
        return u + model.Ge(q, theta) if gravity else u

    return toppra.constraint.SecondOrderConstraint(
        inv_dyn, N_of, h_of, dof=model.dof,
        discretization_scheme=DiscretizationType.Interpolation)


def _toppra_duration(sd, s):
    return float(np.sum(2 * np.diff(s) / (sd[:-1] + sd[1:])))


#: grid points of the smoothed plan (IPOPT) in the full run and in the quick one (the quick
#: run keeps the code path, not the size; on rrr3_platform 0.15 s at 30 points, 0.6 s at 200,
#: since the friction's derivatives are exact: 13 s at 30 points with finite differences)
SMOOTH_GRID, SMOOTH_GRID_QUICK = 200, 15

#: the paths of the refinement rows: besides the model's fastest move, a half circle, a user's
#: spline in the paper's workspace (the planner once exceeded tau_max on it between its
#: samples) and the shipped path files
ARC = dict(center=[0.245, 0.265], radius=0.03, angle0=0.0, angle1=np.pi)
SPLINE = [[0.18, 0.20], [0.22, 0.13], [0.27, 0.21], [0.31, 0.15]]
SHIPPED = ("pick_and_place", "curve")


def bench_paths(model, line):
    """{name: TaskPath} of the refinement rows that the model can follow (the extra paths are
    sized for the paper's robot: another model gets the ones inside its workspace)."""
    from ..planning import check_path
    from ..planning.pathfile import read_path_file
    out = {"line": line, "half_circle": TaskPath.arc(**ARC),
           "spline": TaskPath.spline(SPLINE)}
    out.update({k: read_path_file(k).path for k in SHIPPED})
    usable = {}
    for name, path in out.items():
        try:
            check_path(model, path)
        except Exception:   # noqa: BLE001 (WorkspaceError, SingularityError: not this robot's)
            continue
        usable[name] = path
    return usable


def toppra_runner(model, path, s, split, theta):
    """A function running toppra end to end (its SecondOrderConstraint with the generated Me,
    Ce and the split's polygon at both ends of every interval) on the grid ``s``, returning
    toppra's s_d (K,)."""
    import toppra
    import toppra.algorithm
    w = limits(model, None, 1.0)
    f_pc, m = model.function("path_coefficients"), model.dof
    bufs = [np.empty(k) for k in f_pc.sizes_out]
    unit, zero = np.eye(m)[0], np.zeros(m)      # p' and p'' do not enter N and h
    j_N, j_h = (f_pc.names_out.index(f"{k}_{split}") for k in ("N", "h"))

    def F_of(p):     # the split's force polygon at p: one call into the generated C
        f_pc(np.ascontiguousarray(p), unit, zero, theta, w, *bufs)
        Nk = bufs[j_N].reshape(-1, m)             # F facet normals (F = n when m = 2)
        return np.vstack([Nk, -Nk])

    def g_of(p):
        f_pc(np.ascontiguousarray(p), unit, zero, theta, w, *bufs)
        return np.concatenate([bufs[j_h], bufs[j_h]])

    tpath = ToppraPath(path)

    def run():
        cons = _toppra_constraints(model, theta, F_of, g_of)
        algo = toppra.algorithm.TOPPRA([cons], tpath, gridpoints=s, solver_wrapper="seidel")
        return algo.compute_parameterization(0, 0, return_data=True)[1]
    return run


def bench_refinement(model, line, repeats, say):
    """Refined plans beside unrefined ones of the same grid and beside toppra: on
    each path of :func:`bench_paths`, both splits, with friction (the nominal theta) and
    without, ``plan_time_optimal`` at 1,000 points (refined as it needs) and
    :func:`pm2dof.planning.topp.plan_on_grid` on the refined plan's final grid (the passes and
    checks once, the same grid size); without friction, toppra end to end on the initial
    1,000-point grid. All interleaved, medians. Returns (rows, summary): rows[path][case] =
    {grid, refinements, refined_ms, unrefined_ms, refined_over_unrefined, toppra_ms,
    speedup_vs_toppra}; the summary's worst ratios are the targets' values."""
    from ..planning.topp import plan_on_grid
    try:
        import toppra
        toppra.setup_logging("WARNING") if hasattr(toppra, "setup_logging") else None
    except ImportError:
        toppra = None
    rows, th0 = {}, friction_free(model)
    for name, path in bench_paths(model, line).items():
        say(f"planning: refined and unrefined plans on {name}" +
            (", and toppra" if toppra else ""))
        rows[name] = {}
        for split in ("min_norm", "min_max"):
            for friction, theta in (("friction", None), ("friction_free", th0)):
                plan = plan_time_optimal(model, path, split=split, theta=theta)
                run_t = None
                if toppra is not None and theta is not None:
                    s0 = grid_points(path, 1000)
                    run_t = toppra_runner(model, path, s0, split, params(model, theta)[1])
                    run_t()
                times = {"refined": [], "unrefined": [], "toppra": []}
                for _ in range(repeats):
                    if run_t is not None:
                        times["toppra"].append(warm_then_time(run_t)[1])
                    times["refined"].append(warm_then_time(partial(
                        plan_time_optimal, model, path, split=split, theta=theta))[1])
                    times["unrefined"].append(warm_then_time(partial(
                        plan_on_grid, model, path, plan.s, split=split, theta=theta))[1])
                med = {k: stats([1e3 * x for x in v])["median"] if v else None
                       for k, v in times.items()}
                rows[name][f"{split}_{friction}"] = {
                    "grid": plan.info["grid"], "refinements": plan.info["refinements"],
                    "split_before": plan.info["split_before"],
                    "refined_ms": med["refined"], "unrefined_ms": med["unrefined"],
                    "refined_over_unrefined": med["refined"] / med["unrefined"],
                    "toppra_ms": med["toppra"],
                    "speedup_vs_toppra": (med["toppra"] / med["refined"]
                                          if med["toppra"] is not None else None)}
    cases = [c for r in rows.values() for c in r.values()]
    refined = [c for c in cases if c["refinements"] > 0 or c["split_before"] > 0]
    speed = [c["speedup_vs_toppra"] for c in cases if c["speedup_vs_toppra"] is not None]
    summary = {
        "plan_refined_over_unrefined_max": max(
            (c["refined_over_unrefined"] for c in refined), default=None),
        "plan_refined_cases": len(refined),
        "speedup_vs_toppra_min": min(speed) if speed else None}
    return rows, summary


def bench_planning(model, quick=False, progress=None):
    """Time ``plan_time_optimal`` (1,000 grid points) and toppra on the same friction-free
    problem, interleaved, plus the smoothed variant's IPOPT solve. Returns a JSON-able dict
    (``plan_time_optimal_ms`` median, ``toppra_ms``, ``toppra_solve_ms``, ``speedup_vs_toppra``
    and ``speedup_vs_toppra_solve``, the durations each finds, ``plan_smooth_*`` (on
    ``plan_smooth_grid`` points: :data:`SMOOTH_GRID`, a quick run :data:`SMOOTH_GRID_QUICK`),
    ``notes``;
    ``plan_paths``, ``plan_refined_over_unrefined_max`` and ``speedup_vs_toppra_min`` from
    :func:`bench_refinement`)."""
    say = progress or (lambda msg: None)
    repeats = 3 if quick else 7
    moves = {k: model.spec.trajectories[k] for k in line_moves(model)}
    name = max(moves, key=lambda k: moves[k]["v_max"])
    path = model_move_path(model, name).path       # a platform's line carries phi
    grid = 1000
    res = {"plan_path": f"the {name} move as a line", "plan_grid": grid, "notes": {}}
    th0 = friction_free(model)

    say(f"planning: plan_time_optimal on the {name} move, {grid} grid points, both splits")
    t_end = time.perf_counter() + (0.1 if quick else 0.5)
    while time.perf_counter() < t_end:          # warm up (caches, the CPU's clock)
        plan_time_optimal(model, path, grid=grid)
    per = {"min_max": [], "min_norm": []}
    for _ in range(repeats * 3):                 # the splits interleaved
        for split, times in per.items():
            t0 = time.perf_counter()
            plan_time_optimal(model, path, split=split, grid=grid)
            times.append((time.perf_counter() - t0) * 1e3)
    for split, times in per.items():
        st = stats(times)
        res[f"plan_time_optimal_{split}_ms"] = st["median"]
        res[f"plan_time_optimal_{split}_ms_min"] = st["min"]
    res["plan_time_optimal_ms"] = res["plan_time_optimal_min_max_ms"]
    res["plan_time_optimal_ms_min"] = res["plan_time_optimal_min_max_ms_min"]

    try:
        import toppra
        import toppra.algorithm
    except ImportError as exc:
        toppra = None
        res["notes"]["toppra"] = f"toppra is not installed ({exc}): pip install toppra"
    for key in ("toppra_ms", "toppra_solve_ms", "plan_friction_free_ms", "speedup_vs_toppra",
                "speedup_vs_toppra_solve"):
        res[key] = None
    if toppra is not None:
        say("planning: toppra on the same friction-free problem (interleaved with pm2dof)")
        toppra.setup_logging("WARNING") if hasattr(toppra, "setup_logging") else None
        problem = PlanProblem.create(model, path, None, "min_max", th0)
        s = grid_points(path, grid)
        th = problem.theta
        coef = stages(problem, s)[1]
        tpath = ToppraPath(path)
        a, b = coef["a"], coef["b"]
        c = coef.get("g", np.zeros_like(a))        # the gravity term (a model with gravity)
        F = np.concatenate([coef["N"], -coef["N"]], axis=1)
        g = np.concatenate([coef["h"], coef["h"]], axis=1)
        end_to_end = toppra_runner(model, path, s, "min_max", th)

        def run_toppra(given):
            if not given:
                return end_to_end()
            cons = _toppra_constraints(model, th0, None, None, (a, b, c, F, g))
            algo = toppra.algorithm.TOPPRA([cons], tpath, gridpoints=s, solver_wrapper="seidel")
            return algo.compute_parameterization(0, 0, return_data=True)[1]

        per = {"toppra": [], "toppra_solve": [], "pm2dof": []}
        for _ in range(repeats):
            sd_t, dt = warm_then_time(partial(run_toppra, False))
            per["toppra"].append(dt * 1e3)
            sd_g, dt = warm_then_time(partial(run_toppra, True))
            per["toppra_solve"].append(dt * 1e3)
            pl, dt = warm_then_time(partial(plan_time_optimal, model, path, theta=th0,
                                            split="min_max", grid=grid))
            per["pm2dof"].append(dt * 1e3)
        res["toppra_ms"] = stats(per["toppra"])["median"]
        res["toppra_solve_ms"] = stats(per["toppra_solve"])["median"]
        res["plan_friction_free_ms"] = stats(per["pm2dof"])["median"]
        res["speedup_vs_toppra"] = res["toppra_ms"] / res["plan_friction_free_ms"]
        res["speedup_vs_toppra_solve"] = res["toppra_solve_ms"] / res["plan_friction_free_ms"]
        res["plan_duration_friction_free_s"] = pl.duration
        res["toppra_duration_s"] = _toppra_duration(sd_t, s)
        res["toppra_given_duration_s"] = _toppra_duration(sd_g, s)
        res["plan_vs_toppra_rel_diff"] = abs(res["toppra_duration_s"] / pl.duration - 1)

    rows, summary = bench_refinement(model, path, 1 if quick else 7, say)
    res["plan_paths"] = rows
    res.update(summary)

    smooth_grid = SMOOTH_GRID_QUICK if quick else SMOOTH_GRID
    res["plan_smooth_grid"] = smooth_grid
    say(f"planning: the smoothed variant (IPOPT, {smooth_grid} grid points)")
    keys = ("plan_smooth_total_s", "plan_smooth_solve_s", "plan_smooth_iterations",
            "plan_smooth_duration_s", "plan_smooth_strict_duration_s")
    try:
        t0 = time.perf_counter()
        sm = plan_smooth(model, path, split="min_max", grid=smooth_grid)
        vals = (time.perf_counter() - t0, sm.info["solve_time_s"], sm.info["iterations"],
                sm.duration, sm.info["strict_duration"])
    except ImportError as exc:
        vals = (None,) * len(keys)
        res["notes"]["plan_smooth"] = f"casadi is not importable ({exc})"
    res.update(zip(keys, vals))
    return res
