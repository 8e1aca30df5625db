# The measures a design study optimises, each computed from the generated C at one design.
"""The objectives and constraints of a design study (docs/design-study-file.md).

Each measure is computed on a :class:`pm2dof.Model` at one design (``model.at_design``), through
the same functions as its counterpart elsewhere in pm2dof, and equals it:

========================  ==================================================================
measure                   what, and its counterpart
========================  ==================================================================
``clear_area``            m^2 of the region (x, y) reachable in the working modes with both
                          singularity measures at or above their thresholds; a platform's
                          averaged over the region's orientations (``maps_summary``'s
                          ``clear_area`` on the maps' grid)
``clear_fraction``        the same as a fraction of the region's grid points
``margin``                min over the region's points and the listed paths' samples (every
                          0.5 mm, as ``check_path``) of min(type I - its threshold, type II -
                          its threshold); -1 at a point out of reach. >= 0: the task is inside
                          and clear (a constraint)
``dexterity_min``,        min and mean over the region of the type II measure (0 where out of
``dexterity_mean``        reach): the ``type2`` map of ``workspace_maps``
``force``, ``accel``      min over the region of the force (acceleration at rest) the actuators
                          guarantee in every direction with the ``split`` (under gravity, once
                          the robot is held; 0 out of reach or within 1e-6 of a singularity):
                          the ``force_*`` / ``accel_*`` maps
``duration``              the time-optimal duration of a path under tau_max with a ``split``
                          (``plan_time_optimal``)
``rmse``                  a controller's RMSE (eq. 41) on a move in closed loop against the
                          model file's ``[plant]`` at the design (``simulate``)
``peak_torque``           largest |tau_i| along a move timed by its kinematic S-curve, the
                          inverse dynamics split by ``split`` (``torque_splits``)
``preload_margin``        min over that move's samples and the actuators of
                          sigma_i tau_i - p_i, the preload split's torques (``torque_splits``)
``link_length``           total length of the legs' links: RRR la + lb, PRR lb, RPR its
                          longest stroke, m
``moving_mass``           the legs' bodies' masses and the platform's, kg (a model file whose
                          links are given as bodies)
========================  ==================================================================

**Failure.** Nothing here returns NaN or raises for a design that the model accepts. Points
out of reach count as documented above (0, or -1 for ``margin``). A measure that cannot be
computed at all (a path out of reach or too close to a singularity for the planner, a rollout
that leaves the workspace, a controller that refuses the design) takes its *worst value* for
the direction the study needs: a measure with a floor (the region measures) its floor, else
``-FAILED`` or ``+FAILED`` (FAILED = 1e9 in the measure's unit); the status says why.
"""
import functools
import math
import os
import threading
import warnings

import numpy as np

from ..core.errors import Pm2dofError
from .region import NEAR_SINGULAR, capability_batch, grid_points, pose_batch

__all__ = ["MEASURES", "FAILED", "evaluate_design", "evaluate_with_status", "evaluate_batch",
           "measure_unit", "units", "worst_value", "link_length", "moving_mass",
           "study_paths", "base_model"]

#: the finite value of a measure that could not be computed, in the measure's unit
FAILED = 1e9

# measure -> (natural sense, options, floor or None, needs). options: name -> kind.
_SPLIT = ("min_max", "min_norm")
_CONTROLLER = {"law": "law", "path": "name", "split": "split", "tau_max": "efforts",
               "Kp": "gains", "Kv": "gains", "Kd": "gains", "Q": "gains",
               "Gamma_scale": "nonneg", "project": "bool", "velocity_filter_hz": "nonneg",
               "Q_position": "gains", "Q_velocity": "gains", "R": "gains", "quantise": "bool"}
#: every measure: (its natural sense, its options {key: kind}, the value it takes at worst
#: when it has a floor, else None; what it needs: "region", "path" or "")
MEASURES = {
    "clear_area": ("max", {}, 0.0, "region"),
    "clear_fraction": ("max", {}, 0.0, "region"),
    "margin": ("max", {"paths": "names", "region": "bool"}, -1.0, ""),
    "dexterity_min": ("max", {}, 0.0, "region"),
    "dexterity_mean": ("max", {}, 0.0, "region"),
    "force": ("max", {"split": _SPLIT, "tau_max": "efforts"}, 0.0, "region"),
    "accel": ("max", {"split": _SPLIT, "tau_max": "efforts"}, 0.0, "region"),
    "duration": ("min", {"path": "name", "split": _SPLIT, "tau_max": "efforts",
                         "margin": "fraction", "grid": "grid"}, None, "path"),
    "rmse": ("min", _CONTROLLER, None, "path"),
    "peak_torque": ("min", {"path": "name", "split": ("min_max", "min_norm", "preload"),
                            "tau_max": "efforts"}, None, "path"),
    "preload_margin": ("max", {"path": "name", "preload": "efforts_nonneg",
                               "preload_sign": "signs"}, None, "path"),
    "link_length": ("min", {}, None, ""),
    "moving_mass": ("min", {}, None, ""),
}
#: option defaults
DEFAULTS = {"split": "min_max", "margin": 1.0, "grid": 1000, "region": True, "quantise": True}
#: the laws of ``rmse`` (those of the studies)
LAWS = ("na", "apd", "ctc", "lqr")
_UNITS = {"clear_area": "m^2", "clear_fraction": "1", "margin": "1", "dexterity_min": "1",
          "dexterity_mean": "1", "duration": "s", "rmse": "m", "link_length": "m",
          "moving_mass": "kg"}


def measure_unit(measure, model):
    """The unit of ``measure``'s values on ``model``, for printed text: efforts by the
    actuators' kind ("N m", "N" or "N m or N"), a platform's force and acceleration as balls in
    (x, y, phi) ("N, N m (phi)", "m/s^2, rad/s^2 (phi)").

    Parameters
    ----------
    measure : str
        A key of :data:`MEASURES`.
    model : Model
        The robot.
    """
    from ..analysis.maps import field_units
    from ..core.task import effort_unit
    if measure in ("peak_torque", "preload_margin"):
        return effort_unit(model)
    if measure in ("force", "accel"):
        return field_units(model)[f"{measure}_min_max"]
    return _UNITS[measure]


def units(study, model):
    """{objective or constraint name: unit} of ``study`` on ``model``.

    Parameters
    ----------
    study : DesignStudy
    model : Model
    """
    return {o.name: measure_unit(o.measure, model) for o in study.objectives + study.constraints}


def worst_value(entry):
    """The value ``entry`` (an objective or a constraint) takes when its measure cannot be
    computed: the worst for the direction the study wants (the module docstring).

    Parameters
    ----------
    entry : pm2dof.synthesis.spec.Objective
    """
    low_is_bad = entry.sense == "max" or entry.op == "ge"
    floor = MEASURES[entry.measure][2]
    if low_is_bad:
        return floor if floor is not None else -FAILED
    return FAILED


# ---- geometry and mass: no generated call -------------------------------------------------

def link_length(spec):
    """Total length of the legs' links, m: RRR la + lb, PRR lb, RPR the longest stroke.

    Parameters
    ----------
    spec : pm2dof.core.model_file.ModelSpec
        The model file at the design (``model.spec``).
    """
    total = 0.0
    for leg in spec.legs:
        total += (leg.la + leg.lb if leg.kind == "RRR" else leg.lb if leg.kind == "PRR"
                  else max(leg.stroke))
    return float(total)


#: the bodies with a length (a uniform rod {density} takes it): RRR proximal la, distal lb;
#: PRR link lb
_ROD_LENGTH = {("RRR", "proximal"): "la", ("RRR", "distal"): "lb", ("PRR", "link"): "lb"}


def moving_mass(spec):
    """The moving mass, kg: every body of the legs (``[[nominal.links]]``; a rod of density rho
    kg/m weighs rho L at the design's length L) and the platform's m_p when it has one.

    Parameters
    ----------
    spec : pm2dof.core.model_file.ModelSpec
        The model file at the design; its links must be given as bodies (``spec.links``).

    Raises
    ------
    ArgumentError
        The model file gives lumped parameters only (no body masses).
    """
    from ..core.errors import ArgumentError
    links = spec.links
    bodies = None if links is None else links.get("nominal")
    if bodies is None:
        raise ArgumentError(f"moving_mass: model {spec.name!r} gives its legs' inertia as lumped "
                            f"parameters; give [[nominal.links]] bodies (mass, or a rod's "
                            f"density) to weigh them")
    total = 0.0
    for leg, leg_bodies in zip(spec.legs, bodies):
        for name, body in leg_bodies.items():
            total += (body["density"] * getattr(leg, _ROD_LENGTH[leg.kind, name])
                      if "density" in body else body["mass"])
    if "m_p" in spec.param_names:
        total += float(spec.theta_nominal[spec.param_names.index("m_p")])
    return float(total)


# ---- paths ---------------------------------------------------------------------------------

@functools.lru_cache(maxsize=64)
def _read_path(file, ell):
    from ..planning.pathfile import read_path_file
    return read_path_file(file, orientation_length=ell)


def study_paths(study, model):
    """{name: NamedPath} of the study's path files, read for ``model`` (a platform's
    orientation length follows its attachment points).

    Parameters
    ----------
    study : DesignStudy
    model : Model
    """
    from ..core.task import orientation_length
    ell = orientation_length(model)
    out = {}
    for f in study.paths:
        p = _read_path(str(f), ell)
        out[p.name] = p
    return out


def _paths(study, model, cache):
    """:func:`study_paths`, once per evaluation."""
    if "paths" not in cache:
        cache["paths"] = study_paths(study, model)
    return cache["paths"]


def _named(study, model, name, cache):
    """The path ``name``: a study path, else a model file's move (a NamedPath)."""
    key = ("path", name)
    if key not in cache:
        paths = _paths(study, model, cache)
        if name in paths:
            cache[key] = paths[name]
        else:
            from ..planning.pathfile import model_move_path
            cache[key] = model_move_path(model, name)
    return cache[key]


def _trajectory(study, model, name, cache):
    """The desired motion of ``name`` at the model's sample period: a model file's line move
    as ``model_move`` samples it, any other path timed by its kinematic S-curve."""
    key = ("traj", name)
    if key not in cache:
        spec = model.spec
        if name in spec.trajectories and "path" not in spec.trajectories[name] \
                and name not in _paths(study, model, cache):
            from ..control.trajectory import model_move
            cache[key] = model_move(model, name)
        else:
            cache[key] = _kinematic(study, model, name, cache).trajectory
    return cache[key]


def _kinematic(study, model, name, cache):
    """The kinematic plan (S-curve) of the path ``name``."""
    key = ("kin", name)
    if key not in cache:
        from ..core.errors import PlanError
        from ..planning.kinematic import plan_kinematic
        p = _named(study, model, name, cache)
        if not p.kinematic:
            raise PlanError(f"path {name!r} gives no [kinematic] limits (v_max, a_max, j_max) "
                            f"to time it")
        cache[key] = plan_kinematic(p.path, period=model.sample_period, **p.kinematic)
    return cache[key]


# ---- the region ----------------------------------------------------------------------------

def _region(study, model, cache):
    """The region grid's poses, q, reach and measures (cached per evaluation)."""
    if "region" not in cache:
        pts, cell, shape = grid_points(study.region, model)
        q, reach, sing = pose_batch(model, pts)
        cache["region"] = {"pts": pts, "cell": cell, "shape": shape, "q": q, "reach": reach,
                           "sing": sing}
    return cache["region"]


def _clear(model, r):
    """The region's points reachable with both measures at or above their thresholds (as
    ``maps_summary``), computed once per evaluation (``r``: :func:`_region`'s)."""
    if "clear" not in r:
        with np.errstate(invalid="ignore"):
            r["clear"] = r["reach"] & (r["sing"][:, 0] >= model.singularity_threshold) & \
                (r["sing"][:, 1] >= model.parallel_singularity_threshold)
    return r["clear"]


def _dexterity(r):
    """The region's type II measure, 0 out of reach (once per evaluation)."""
    if "dexterity" not in r:
        r["dexterity"] = np.where(r["reach"], r["sing"][:, 1], 0.0)
    return r["dexterity"]


def _capability(study, model, options, cache):
    """The capability maps over the region (0 out of reach and near a singularity)."""
    tau = options.get("tau_max")
    key = ("cap", None if tau is None else tuple(np.atleast_1d(tau).tolist()))
    if key not in cache:
        r = _region(study, model, cache)
        with np.errstate(invalid="ignore"):
            ok = r["reach"] & (r["sing"][:, 0] > NEAR_SINGULAR) & (r["sing"][:, 1] > NEAR_SINGULAR)
        caps = capability_batch(model, r["q"][ok], tau_max=tau)
        full = {}
        for k, v in caps.items():
            full[k] = np.zeros(len(ok))
            full[k][ok] = v
        cache[key] = full
    return cache[key]


def _path_samples(study, model, name, cache):
    """The samples of path ``name`` every 0.5 mm (its breakpoints among them), as
    ``check_path`` takes them."""
    from ..planning.check import STEP
    path = _named(study, model, name, cache).path
    n = max(2, int(np.ceil(path.length / STEP)) + 1)
    s = np.union1d(np.linspace(0.0, path.length, n), path.breakpoints)
    return np.ascontiguousarray(path.evaluate(s)[0])


def _margin_of(model, reach, sing):
    """min over points of min(type I - threshold, type II - threshold); -1 out of reach."""
    m = np.minimum(sing[:, 0] - model.singularity_threshold,
                   sing[:, 1] - model.parallel_singularity_threshold)
    return float(np.min(np.where(reach, m, -1.0), initial=np.inf))


# ---- each measure ----------------------------------------------------------------------------

def _m_clear_area(study, model, o, cache):
    r = _region(study, model, cache)
    n_phi = r["shape"][0] if len(r["shape"]) == 3 else 1
    return float(np.count_nonzero(_clear(model, r)) * r["cell"] / n_phi)


def _m_clear_fraction(study, model, o, cache):
    r = _region(study, model, cache)
    return float(np.count_nonzero(_clear(model, r)) / len(r["reach"]))


def _m_margin(study, model, o, cache):
    worst = math.inf
    if o.get("region", True) and study.region is not None:
        r = _region(study, model, cache)
        worst = min(worst, _margin_of(model, r["reach"], r["sing"]))
    names = o.get("paths")
    if names is None:
        names = list(_paths(study, model, cache))
    for name in names:
        _, reach, sing = pose_batch(model, _path_samples(study, model, name, cache))
        worst = min(worst, _margin_of(model, reach, sing))
    return float(worst)


def _m_dexterity_min(study, model, o, cache):
    r = _region(study, model, cache)
    return float(np.min(_dexterity(r)))


def _m_dexterity_mean(study, model, o, cache):
    r = _region(study, model, cache)
    return float(np.mean(_dexterity(r)))


def _m_force(study, model, o, cache):
    return float(_capability(study, model, o, cache)[f"force_{o.get('split', 'min_max')}"].min())


def _m_accel(study, model, o, cache):
    return float(_capability(study, model, o, cache)[f"accel_{o.get('split', 'min_max')}"].min())


def _m_duration(study, model, o, cache):
    from ..planning.topp import plan_time_optimal
    p = _named(study, model, o["path"], cache)
    plan = plan_time_optimal(model, p.path, tau_max=o.get("tau_max"),
                             split=o.get("split", DEFAULTS["split"]),
                             margin=o.get("margin", DEFAULTS["margin"]),
                             grid=o.get("grid", DEFAULTS["grid"]))
    return float(plan.duration)


def _controller(model, o, traj):
    """The controller of an ``rmse`` entry (the studies' :func:`make_controller`)."""
    from ..studies.evaluate import make_controller
    from ..studies.spec import Variant
    opts = {k: (tuple(v) if isinstance(v, list) else v) for k, v in o.items()
            if k not in ("law", "path", "quantise")}
    return make_controller(model, Variant(o["law"], o["law"], tuple(sorted(opts.items())), ()),
                           traj)


def _m_rmse(study, model, o, cache):
    from ..control.simulate import simulate
    traj = _trajectory(study, model, o["path"], cache)
    ctrl = _controller(model, o, traj)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")       # the outcome is in the result
        r = simulate(model, ctrl, traj, quantise=o.get("quantise", DEFAULTS["quantise"]))
    if r.outcome != "completed":
        raise _Failed(f"the rollout did not complete: {r.outcome_message}")
    return float(r.rmse)


def _splits_along(study, model, o, cache):
    """Every split's torques along the move's kinematic timing: one ``map`` per function
    (the inverse dynamics of ``path_torques``, then ``torque_splits`` with every output)."""
    from ..control.settings import actuator_limits, per_actuator
    from ..planning.torques import path_torques
    plan = _kinematic(study, model, o["path"], cache)
    tau = actuator_limits(model.spec, o.get("tau_max"), "peak_torque")
    u = path_torques(model, plan.path, plan.s, plan.sdot, plan.sddot, tau_max=tau)["u"]
    n, K = model.n_legs, len(u)
    ctl = model.spec.control
    sgn = per_actuator("preload_sign", o.get("preload_sign", ctl["preload_sign"]), n)
    pre = per_actuator("preload", o.get("preload", ctl["preload"]), n)
    q = np.empty((K, 2 * n))
    model.function("ik").map(K, np.ascontiguousarray(plan.trajectory.xd), q)
    outs = (np.empty((K, n)), np.empty((K, n)), np.empty(K), np.empty((K, n)), np.empty(K),
            np.empty((K, 2)))
    model.function("torque_splits").map(K, q, np.ascontiguousarray(u), tau,
                                        np.ascontiguousarray(sgn, dtype=float),
                                        np.ascontiguousarray(pre, dtype=float), *outs)
    return {"min_norm": outs[0], "min_max": outs[1], "preload": outs[3], "sign": sgn,
            "pre": pre}


def _m_peak_torque(study, model, o, cache):
    t = _splits_along(study, model, o, cache)[o.get("split", DEFAULTS["split"])]
    return float(np.max(np.abs(t)))


def _m_preload_margin(study, model, o, cache):
    t = _splits_along(study, model, o, cache)
    return float(np.min(t["preload"] * t["sign"] - t["pre"]))


def _m_link_length(study, model, o, cache):
    return link_length(model.spec)


def _m_moving_mass(study, model, o, cache):
    return moving_mass(model.spec)


_COMPUTE = {name: globals()[f"_m_{name}"] for name in MEASURES}


class _Failed(Exception):
    """A measure that cannot be computed at this design (its reason)."""


def _check_finite(name, value):
    if not math.isfinite(value):
        raise _Failed(f"{name} is not finite ({value})")
    return value


def evaluate_with_status(model, study):
    """Every objective and constraint of ``study`` at ``model``'s design, and a status.

    Parameters
    ----------
    model : Model
        The robot at the design (``model.at_design(...)``, or a conventionally derived model
        of the same task).
    study : DesignStudy

    Returns
    -------
    values : dict
        {name: float}, finite; a measure that could not be computed has its
        :func:`worst_value`.
    status : str
        "ok", or "failed: <name>: <reason>; ..." naming each measure that could not be
        computed.
    """
    cache, values, failed = {}, {}, []
    for entry in study.objectives + study.constraints:
        try:
            v = _check_finite(entry.name, _COMPUTE[entry.measure](study, model,
                                                                  dict(entry.options), cache))
        except (Pm2dofError, _Failed, np.linalg.LinAlgError) as exc:
            failed.append(f"{entry.name}: {exc}".splitlines()[0])
            v = worst_value(entry)
        values[entry.name] = float(v)
    return values, ("ok" if not failed else "failed: " + "; ".join(failed))


def evaluate_design(model, study):
    """{objective or constraint name: float} of ``study`` at ``model``'s design (finite;
    :func:`evaluate_with_status` also says which measures failed).

    Parameters
    ----------
    model : Model
        The robot at the design.
    study : DesignStudy
    """
    return evaluate_with_status(model, study)[0]


_MODELS = {}


def base_model(study):
    """The study's model as its file gives it, loaded once per thread and model file version (a
    Model must not serve two threads at once; a worker keeps it between batches, and a design
    run's client between runs; an edited model file is read again).

    Parameters
    ----------
    study : DesignStudy

    Returns
    -------
    Model
    """
    from ..core.model import load_model
    key = (study.model_path, threading.get_ident())
    try:
        st = os.stat(study.model_path)
        version = (st.st_mtime_ns, st.st_size)
    except OSError:
        version = None                       # load_model names the problem
    have = _MODELS.get(key)
    if have is None or have[0] != version:
        have = _MODELS[key] = (version, load_model(study.model_path))
    return have[1]


def evaluate_batch(study, X):
    """Evaluate the designs ``X`` for an optimiser: objectives to minimise, pymoo constraints.

    Parameters
    ----------
    study : DesignStudy
    X : array_like (N, k)
        Designs, one row each, in ``study.variables`` order (m); the model's other design
        variables keep the file's values.

    Returns
    -------
    F : ndarray (N, n_obj)
        The objectives, ``max`` ones negated: every column is minimised.
    G : ndarray (N, n_con)
        pymoo's constraints, <= 0 where met: ``limit - value`` for ``ge``, ``value - limit``
        for ``le``.
    rows : list of dict
        Per design: {variable: value, objective or constraint name: value (unnegated),
        "status": "ok" | "failed: ..." | "design_error: ..."}. A design the model refuses
        (``pm2dof.DesignError``: out of bounds, the home or a move out of reach) has every
        entry at its :func:`worst_value`.
    """
    from ..core.errors import DesignError
    X = np.atleast_2d(np.asarray(X, dtype=float))
    if X.shape[1] != len(study.variables):
        from ..core.errors import ArgumentError
        raise ArgumentError(f"X must have one column per design variable "
                            f"{list(study.variables)}, got shape {X.shape}")
    model = base_model(study)
    entries = study.objectives + study.constraints
    F = np.empty((len(X), len(study.objectives)))
    G = np.empty((len(X), len(study.constraints)))
    rows = []
    for i, x in enumerate(X):
        design = {v: float(x[j]) for j, v in enumerate(study.variables)}
        try:
            m = model.at_design(design) if design else model
            values, status = evaluate_with_status(m, study)
        except DesignError as exc:
            values = {e.name: worst_value(e) for e in entries}
            status = f"design_error: {exc}".splitlines()[0]
        F[i] = [values[o.name] * (-1.0 if o.sense == "max" else 1.0) for o in study.objectives]
        G[i] = [(c.limit - values[c.name]) if c.op == "ge" else (values[c.name] - c.limit)
                for c in study.constraints]
        rows.append({**design, **values, "status": status})
    return F, G, rows
