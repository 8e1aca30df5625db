# The path's dynamics at every grid point, in one call into the generated C (path_coefficients).
"""Grid and per-point coefficients of the time-optimal planner.

Along p(s) the task force is u = a s_dd + b s_d^2 + S^T f_a(S p' s_d) (eqs. 10-12, 2) with
a = Me p', b = Me p'' + Ce(q, p') p', and the split's feasible forces are {u : N u <= h}
(pm2dof/derive/planning.py). :func:`stages` evaluates all of it at every grid point with one
``Function.map`` call and packs the ``path_stage`` vectors the generated passes take.
"""
import math
import numbers

import numpy as np

from ..control.rules import TAU_MAX_LIMIT
from ..control.settings import actuator_limits
from ..core.errors import ArgumentError, PlanError
from ..core.task import effort_unit
from . import _passes
from .check import first_bad, raise_at

__all__ = ["SPLITS", "GRID_MAX", "grid_points", "limits", "stages", "point_stages", "params",
           "junction_left", "link"]

SPLITS = ("min_norm", "min_max")
V_TOP = 100.0   # m/s: the bisection's upper bracket; a maximum-velocity curve above it reads V_TOP
#: the most grid points a plan may ask for (about 40 MB of stage vectors; a plan takes ~0.3 s)
GRID_MAX = 100_000


RAMP = 0.15    # fraction of each rest-to-rest segment, at either end, graded quadratically


def _graded(n):
    """n + 1 points on [0, 1]: quadratic (s ~ xi^2) over the first and last RAMP of the length,
    uniform between, C1. From rest the path speed grows like sqrt(s), so equal steps of xi are
    about equal steps of speed there: the friction's change over an interval stays small."""
    xi = np.linspace(0.0, 1.0, n + 1)
    xr = 2 * RAMP / (1 + 2 * RAMP)             # the ramps' share of the points
    c, slope = RAMP / xr ** 2, 2 * RAMP / xr
    g = np.where(xi < xr, c * xi * xi, RAMP + slope * (xi - xr))
    g = np.where(xi > 1 - xr, 1 - c * (1 - xi) ** 2, g)
    g[0], g[-1] = 0.0, 1.0
    return g


def grid_points(path, grid):
    """About ``grid`` arc lengths (m): each rest-to-rest segment graded by :func:`_graded`
    (fine near the stops, where the speed changes fastest), every breakpoint a grid point (no
    interval straddles a jump of curvature)."""
    if isinstance(grid, bool) or not isinstance(grid, numbers.Integral) or \
            not 2 <= grid <= GRID_MAX:
        raise PlanError(f"grid must be a whole number of grid points from 2 to {GRID_MAX}, got "
                        f"{grid!r}")
    stops, L = path.stops, path.length
    pts = []
    for a, b in zip(stops[:-1], stops[1:]):
        k = max(2, int(round((grid - 1) * (b - a) / L)))
        pts.append(a + (b - a) * _graded(k)[:-1])
    s = np.concatenate(pts + [[L]])
    bp = path.breakpoints
    spacing = np.diff(s)
    k = np.clip(np.searchsorted(s, bp), 1, len(s) - 1)
    near = np.minimum(bp - s[k - 1], s[np.minimum(k, len(s) - 1)] - bp)
    local = spacing[k - 1]
    drop = np.zeros(len(s), dtype=bool)
    for j, b in enumerate(bp):          # a grid point very close to a breakpoint gives way
        if near[j] < 0.3 * local[j]:
            i = k[j] - 1 if b - s[k[j] - 1] < s[k[j]] - b else k[j]
            drop[i] = s[i] != b
    return np.union1d(s[~drop], bp)


def limits(model, tau_max, margin):
    """The torque limits the plan may use, tau_max * margin (n,), N m (N for a linear
    actuator), checked: tau_max positive and finite, 0 < margin <= 1 (a margin above 1 would
    plan beyond the motors' limits: pass a larger tau_max instead)."""
    return limits_and_actuators(model, tau_max, margin)[0]


def limits_and_actuators(model, tau_max, margin):
    """(:func:`limits`, the actuators' limits before the margin (n,)), checked once."""
    n = model.n_legs
    try:
        m = float(margin)
    except (TypeError, ValueError):
        m = math.nan
    if not (math.isfinite(m) and 0 < m <= 1):
        raise PlanError(f"margin must be a number in (0, 1], the fraction of tau_max the plan "
                        f"may use (< 1 leaves headroom for feedback), got {margin!r}")
    try:
        tau = actuator_limits(model.spec, tau_max, "plan")
    except ArgumentError as exc:
        raise PlanError(f"tau_max must be one value or {n} finite limits > 0 "
                        f"{effort_unit(model)} (one per actuator), at most {TAU_MAX_LIMIT:g}, "
                        f"got {tau_max!r} ({exc})") from None
    return tau * m, tau


def params(model, theta):
    """The ``path_params`` vector and theta (5n,), default the model's nominal (Tables 1-2);
    ArgumentError unless 5n finite numbers and physical (:meth:`pm2dof.Model.checked_theta`,
    the one check): a plan needs Me positive definite and friction that dissipates."""
    th = model.checked_theta(theta, physical=True)
    return model.layout("path_params").pack(v_top=V_TOP, theta=th), th


def _coefficients(problem, p, dp, ddp):
    """One ``path_coefficients`` map over the points of ``problem``'s path at (p, dp, ddp):
    dict of its outputs (the other split's polygon not computed)."""
    model, split = problem.model, problem.split
    K, f = len(p), model.function("path_coefficients")
    other = "min_max" if split == "min_norm" else "min_norm"
    # a, b (g with gravity) (m,), S (n m,), v1 (n,), the facets N (m F,), h (F,), sing (2,)
    outs = {k: (None if k.endswith(other) else np.empty((K, size)))
            for k, size in zip(f.names_out, f.sizes_out)}
    f.map(K, p, dp, ddp, problem.theta, problem.tau_max, *outs.values())
    return outs


def _fill(model, stage, outs, split):
    st = model.layout("path_stage").unpack(stage)
    st["N"][:], st["h"][:] = outs[f"N_{split}"], outs[f"h_{split}"]
    for key in ("a", "b", "g", "S", "v1"):
        if key in st:                       # g: a model with gravity
            st[key][:] = outs[key]


def point_stages(problem, s, evaluated, check=True):
    """The ``path_stage`` vectors (K, size) of ``problem`` (:class:`.problem.PlanProblem`) at
    the arc lengths ``s`` (K,) with their ``path.evaluate(s)`` (p, dp, ddp): the facets and
    coefficients of each point alone (rho, delta and x_cap unset: zero), with the outputs of
    ``path_coefficients`` (dict). With ``check``, raises WorkspaceError or SingularityError at
    the first point out of reach or too close to a singularity (the thresholds of ``Model.poses_clear``);
    without, such rows are NaN."""
    model, split = problem.model, problem.split
    if split not in SPLITS:
        raise PlanError(f"split must be one of {list(SPLITS)}, got {split!r}")
    p, dp, ddp = (np.ascontiguousarray(x) for x in evaluated)
    K, lay = len(p), model.layout("path_stage")
    stage, v1, sing = np.empty((K, lay.size)), np.empty((K, model.n_legs)), np.empty((K, 2))
    _passes.rows(model.function("path_coefficients"), p, dp, ddp, problem.theta,
                 problem.tau_max, _row_map(model, split), stage, v1, sing)
    st = lay.unpack(stage)
    outs = {key: st[key] for key in ("a", "b", "g", "S") if key in st}
    outs.update({"v1": v1, "sing": sing, f"N_{split}": st["N"], f"h_{split}": st["h"]})
    if check:
        k = first_bad(model, sing)
        if k is not None or not (np.isfinite(outs["a"]).all() and np.isfinite(outs["b"]).all()):
            bad = ~np.isfinite(outs["a"]).all(axis=1) | ~np.isfinite(outs["b"]).all(axis=1)
            k = k if k is not None else int(np.argmax(bad))
            raise_at(model, s[k], p[k], sing[k])
    return stage, outs


def _row_map(model, split):
    """Where ``_passes.rows`` writes each output of path_coefficients in a path_stage row (the
    row offset, -1: not computed, -2: the singularity measures), then v1's offset and length
    (as :func:`_fill` places them)."""
    sl = model.layout("path_stage").slices
    place = {"a": "a", "b": "b", "g": "g", "S": "S", "v1": "v1", f"N_{split}": "N",
             f"h_{split}": "h"}
    names = model.function("path_coefficients").names_out
    out = [sl[place[k]].start if k in place else -2 if k == "sing" else -1 for k in names]
    return np.array(out + [sl["v1"].start, sl["v1"].stop - sl["v1"].start], dtype=np.int64)


def stages(problem, s, stops=(), evaluated=None):
    """Evaluate the path's dynamics at the arc lengths ``s`` (K,) in one C call.

    Parameters
    ----------
    problem : PlanProblem
        The model, path, torque limits (margin applied), theta and split
        (:class:`pm2dof.planning.problem.PlanProblem`).
    s : ndarray (K,)
        Arc lengths, m.
    stops : array_like of int
        Grid indices where the robot must be at rest (x_cap = 0).
    evaluated : tuple of ndarray, optional
        ``path.evaluate(s)`` if the caller has it (p, dp, ddp), to save evaluating again.

    Returns
    -------
    stage : ndarray (K, size of ``path_stage``)
        The packed per-point vectors (see the manifest layout ``path_stage``): the facets of
        the interval that starts at each point.
    coef : dict
        ``a``, ``b`` (K, m) N per m/s^2 and per (m/s)^2 (phi's row N m), ``g`` (K, m) N, the
        gravity term (a model with gravity only), ``S`` (K, n, m), ``v1`` (K, n) rad/m, ``N``
        (K, F, m) and ``h`` (K, F) N: the split's force polytope |N_j . u| <= h_j (F facet
        pairs: pm2dof.derive.planning.facet_count), ``sing`` (K, 2), ``p``, ``dp``, ``ddp``
        (K, m); and ``arrive`` (K, size of ``path_stage``):
        the facets at each point for the interval that ends there (the path's left limit at a
        breakpoint, that interval's rho; row 0 unused).

    Raises
    ------
    WorkspaceError, SingularityError
        At the first grid point out of reach or too close to a singularity.
    """
    p, dp, ddp = (np.ascontiguousarray(x) for x in (evaluated or problem.path.evaluate(s)))
    K, n, m, split = len(s), problem.model.n_legs, problem.model.dof, problem.split
    base, outs = point_stages(problem, s, (p, dp, ddp))
    left = junction_left(problem)
    stage, arrive = link(problem, s, base, outs["v1"], stops, left)
    outs = {k: np.ascontiguousarray(v) for k, v in outs.items()}   # views of the rows
    h = outs[f"h_{split}"]
    coef = {"a": outs["a"], "b": outs["b"], "S": outs["S"].reshape(K, n, m), "v1": outs["v1"],
            "N": outs[f"N_{split}"].reshape(K, h.shape[1], m), "h": h,
            "sing": outs["sing"], "p": p, "dp": dp, "ddp": ddp, "arrive": arrive}
    if "g" in outs:                                    # a model with gravity
        coef["g"] = outs["g"]
    return stage, coef


def junction_left(problem):
    """The ``path_coefficients`` outputs (dict) at the path's interior breakpoints with the
    preceding piece (the path's left limit there), in order; None if it has none."""
    bp = problem.path.breakpoints[1:-1]
    if not bp.size:
        return None
    pl, dpl, ddpl = (np.ascontiguousarray(x) for x in problem.path.evaluate(bp, "left"))
    return _coefficients(problem, pl, dpl, ddpl)


def link(problem, s, base, v1, stops, left):
    """The ``path_stage`` rows of the grid ``s`` (K,) from its points' own rows ``base`` (K,
    size; :func:`point_stages`) and their v1 (K, n): (stage, arrive), both (K, size). stage:
    rho (a joint reverses on [s_k, s_k+1]), delta = s_k+1 - s_k and x_cap (0 at the grid indices
    ``stops``) set; arrive: the facets at each point for the interval that ends there (that
    interval's rho; at an interior breakpoint the preceding piece's, ``left`` of
    :func:`junction_left`). Every row depends on its point and its neighbours alone."""
    model = problem.model
    lay = model.layout("path_stage")
    stage = base.copy()
    st = lay.unpack(stage)
    sign = np.where(v1 >= 0, 1.0, -1.0)       # direction of motion, as path_stage's sigma
    st["rho"][:-1] = sign[:-1] != sign[1:]             # a joint reverses on [s_k, s_k+1]
    st["rho"][-1] = 0.0
    st["delta"][:-1, 0] = np.diff(s)
    st["delta"][-1, 0] = st["delta"][-2, 0]
    st["x_cap"][:] = V_TOP ** 2
    st["x_cap"][list(stops)] = 0.0
    arrive = stage.copy()
    lay.unpack(arrive)["rho"][1:] = st["rho"][:-1]
    bp = problem.path.breakpoints[1:-1]
    junction = np.flatnonzero(np.isin(s, bp))
    if left is not None and junction.size:      # arriving at a breakpoint: the preceding piece
        which = np.searchsorted(bp, s[junction])
        part = arrive[junction]
        _fill(model, part, {k: None if v is None else v[which] for k, v in left.items()},
              problem.split)
        arrive[junction] = part
    return stage, arrive
