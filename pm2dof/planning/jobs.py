# What `pm2dof plan` does: plan the paths, track the plans in closed loop, write the CSVs.
"""The jobs of ``pm2dof plan``: :func:`run_plan` reads the paths (a path file or the model
file's moves), plans each with the kinematic S-curve and time-optimally with each split
(:func:`plan_paths`, optionally smoothed), tracks the plans with NA and APD in simulation at
several margins (:func:`closed_loop`), and returns a :class:`PlanRun`; :func:`write_plan_csvs`
writes its plans. The text and the CSV format: :mod:`.report`.
"""
from dataclasses import dataclass

import numpy as np

from ..control.controllers import APDController, NAController
from ..control.simulate import simulate
from ..core.errors import ArgumentError, PlanError
from ..infra.results import provenance
from .check import check_path, require
from .kinematic import plan_kinematic
from .report import _at_samples, csv_text, effort_units, plan_provenance
from .stages import limits
from .topp import plan_time_optimal
from .torques import path_torques

__all__ = ["run_plan", "PlanRun", "plan_paths", "closed_loop", "write_plan_csvs", "model_moves"]


@dataclass(frozen=True)
class PlanRun:
    """What ``pm2dof plan`` found (:func:`run_plan`).

    Attributes
    ----------
    model : Model
        The model the paths were planned on.
    summary : dict
        The numbers, the command's ``--json`` (:func:`plan_paths`' results; with
        ``closed_loop``, {path name: rows of :func:`closed_loop`}, when simulated). Its text:
        :func:`.report.format_report`.
    plans : dict
        ``{(path name, "kinematic" or the split, or "smooth_" + the split): Plan}``.
    provenance : dict
        :func:`pm2dof.infra.results.provenance` of the run (its command line included): what
        the CSVs (:func:`write_plan_csvs`) and the figures carry.
    """
    model: object
    summary: dict
    plans: dict
    provenance: dict

    @property
    def closed_loop(self):
        """The closed-loop rows by path name (``summary["closed_loop"]``), {} when not
        simulated."""
        return self.summary.get("closed_loop", {})


def _units(model):
    """The ``units`` entry of :func:`plan_paths`' results: the unit of each actuator's entry
    of every effort there (``tau_max``, ``tau_peak``, ``tau_rate``), one per actuator."""
    eff = effort_units(model)
    return {"tau_max": eff, "tau_peak": eff, "tau_rate": [f"{u}/s" for u in eff]}


def model_moves(model):
    """The model file's moves as paths: [:class:`.pathfile.NamedPath`] (line moves as lines,
    path moves from their path files)."""
    from .pathfile import model_move_path
    return [model_move_path(model, name) for name in model.spec.trajectories]


def _peaks(model, plan, tau_lim):
    """Peak |tau_i| of a timed plan for each split by inverse dynamics at its samples."""
    r = path_torques(model, plan.path, *_at_samples(plan), None, tau_lim)
    return {sp: np.abs(r[sp]).max(axis=0).tolist() for sp in ("min_norm", "min_max")}


def _check_item(model, item):
    """PlanError unless ``item``'s path has the model's task dimension; WorkspaceError or
    SingularityError where it leaves the workspace or nears a singularity
    (:func:`.check.check_path`), each naming the path file and its segment."""
    try:
        require(model, item.path)
    except PlanError as exc:
        where = item.where()
        raise PlanError(f"{where}: {exc}" if where else str(exc)) from None
    check_path(model, item.path, where=item.where if item.file is not None else None)


def plan_paths(model, items, tau_max=None, margin=1.0, grid=1000, splits=("min_norm", "min_max"),
               theta=None, smooth=False, tau_rate=None, progress=None, command_line=None):
    """Plan every item (:class:`.pathfile.NamedPath`: name, path, kinematic limits)
    kinematically and time-optimally (``smooth``: also :func:`.smooth.plan_smooth`).

    ``progress`` (a callable taking one-line messages, e.g. a
    :class:`pm2dof.infra.progress.Progress`; None: silent) hears a line per path and, with
    ``smooth``, IPOPT's progress for each split (:func:`.smooth.plan_smooth`).
    ``command_line``: the command its provenance records
    (:func:`pm2dof.infra.results.provenance`; None: ``sys.argv``).

    Returns
    -------
    (dict, dict)
        The JSON-able results ``{"model", "tau_max", "margin", "grid", "units", "provenance",
        "paths": [...]}`` (``provenance``: :func:`.report.plan_provenance`; ``units``: each actuator's
        unit of ``tau_max``, ``tau_peak`` and ``tau_rate``, "N m" and "N m/s" for a revolute
        actuator, "N" and "N/s" for a linear one) and the Plan objects
        ``{(name, method_or_split): Plan}``. Each timing's peak efforts are ``tau_peak`` (one
        per actuator, in ``units``), and under their old name ``tau_peak_N_m`` (the same
        values, whatever the unit).
    """
    tau_lim = limits(model, tau_max, 1.0)
    res = {"model": model.name, "tau_max": tau_lim.tolist(), "margin": float(margin),
           "grid": int(grid), "units": _units(model),
           "provenance": plan_provenance(model, tau_lim, margin, splits, theta,
                                         command_line=command_line), "paths": []}
    plans = {}
    for item in items:        # before anything evaluates a path on the model
        _check_item(model, item)
    for item in items:
        path = item.path
        if progress is not None:
            progress(f"planning {item.name} ({path.length:.4g} m): "
                     f"{'the kinematic S-curve, ' if item.kinematic else ''}time-optimal with "
                     f"{' and '.join(splits)}{', then smoothed' if smooth else ''}")
        row = {"name": item.name, "length_m": path.length, "kinds": list(path.kinds),
               "stops_m": path.stops.tolist()}
        kin = item.kinematic
        if kin:
            kp = plan_kinematic(path, kin["v_max"], kin["a_max"], kin["j_max"],
                                model.spec.sensing["sample_period"])
            peaks = _peaks(model, kp, tau_lim)
            row["kinematic"] = {**kin, "duration_s": kp.duration, "tau_peak": peaks,
                                "tau_peak_N_m": peaks,
                                "within_limits": {sp: bool(np.all(np.array(v) <= tau_lim))
                                                  for sp, v in peaks.items()}}
            kp.info["tau_max_actuators"] = tau_lim.tolist()     # the limits its CSV reports
            plans[item.name, "kinematic"] = kp
        feasible, refused = [], []
        for split in splits:
            try:
                p = plan_time_optimal(model, path, tau_max, split, theta, margin, grid)
            except PlanError as exc:      # with both splits, one may be feasible alone
                refused.append(exc)
                row[split] = {"infeasible": str(exc)}
                continue
            feasible.append(split)
            plans[item.name, split] = p
            row[split] = {"duration_s": p.duration, "tau_peak": p.tau_peak.tolist(),
                          "tau_peak_N_m": p.tau_peak.tolist(),
                          "compute_ms": p.compute_time_s * 1e3, "grid": p.info["grid"],
                          "max_speed_m_s": float(p.sdot.max())}
        if not feasible:
            raise refused[0]
        if all(sp in feasible for sp in ("min_norm", "min_max")):
            row["saving_min_max_percent"] = 100 * (1 - row["min_max"]["duration_s"]
                                                   / row["min_norm"]["duration_s"])
        if smooth:
            from .smooth import plan_smooth
            for split in feasible:
                sp = plan_smooth(model, path, tau_max, split, theta, margin, tau_rate=tau_rate,
                                 progress=progress)
                plans[item.name, f"smooth_{split}"] = sp
                row[f"smooth_{split}"] = {
                    "duration_s": sp.duration, "strict_duration_s": sp.info["strict_duration"],
                    "grid": sp.info["grid"], "tau_rate": sp.info["tau_rate"],
                    "solve_time_s": sp.info["solve_time_s"], "ipopt": sp.info["ipopt_status"]}
        res["paths"].append(row)
    return res, plans


def closed_loop(model, path, tau_max=None, split="min_max", margins=(1.0, 0.9), grid=1000,
                settle_time=0.1, progress=None):
    """NA and APD tracking the time-optimal plan of ``path`` at each margin, in simulation (the
    model file's plant, quantised encoders). The controllers use the split of the plan and clip
    at the full limits; the plan uses tau_max * margin. ``progress`` (a callable taking
    one-line messages; None: silent) hears a line per margin.

    Returns
    -------
    list of dict
        One per margin: ``margin``, ``duration_s`` and for ``na``/``apd``: ``rmse_m``,
        ``max_error_m``, ``tau_peak`` (and the same under its old name ``tau_peak_N_m``; N m
        for a revolute actuator, N for a linear one), ``saturated`` (samples clipped),
        ``outcome``.
    """
    tau_lim = limits(model, tau_max, 1.0)
    out = []
    for m in margins:
        plan = plan_time_optimal(model, path, tau_lim, split, None, m, grid)
        if progress is not None:
            progress(f"closed loop at margin {m:g}: NA and APD tracking the {split} plan "
                     f"({plan.duration:.4f} s)")
        row = {"margin": float(m), "duration_s": plan.duration}
        for law, cls in (("na", NAController), ("apd", APDController)):
            ctrl = cls(model, split=split, tau_max=tau_lim)
            r = simulate(model, ctrl, plan.trajectory, settle_time=settle_time)
            e = r.xd[:r.n_move] - r.xe[:r.n_move]     # the position's error, as eq. 41's rmse
            row[law] = {"rmse_m": float(r.rmse), "max_error_m": float(np.max(np.hypot(
                e[:, 0], e[:, 1]))), "tau_peak": np.abs(r.tau_a).max(axis=0).tolist(),
                "tau_peak_N_m": np.abs(r.tau_a).max(axis=0).tolist(),
                "saturated": int(r.n_saturated), "outcome": r.outcome}
        out.append(row)
    return out


def run_plan(model, *, path=None, move=None, tau_max=None, margin=1.0, grid=1000,
             splits=("min_norm", "min_max"), kinematic=None, smooth=False, tau_rate=None,
             closed_loop_margins=None, progress=None, command_line=None):
    """``pm2dof plan``: plan a path file (``path``: a shipped name or a TOML file) or the model
    file's moves (``move``: only that one), with the kinematic limits ``kinematic`` ({v_max,
    a_max, j_max}, None for the path's own) overriding the paths' (the model's last move's
    where a path has none), and with ``closed_loop_margins``, NA and APD tracking the plan of
    the last split at each margin (:func:`closed_loop`). ``progress``: stage lines, as
    :func:`plan_paths` (None: silent). ``command_line``: the command the provenance records
    (None: ``sys.argv``).

    Returns
    -------
    PlanRun
        The model, the numbers (:func:`plan_paths`' results, with ``closed_loop``: {path name:
        rows} when simulated; the text: :func:`.report.format_report`), the plans and their
        provenance.
    """
    if path:
        from ..core.task import orientation_length
        from .pathfile import read_path_file
        items = [read_path_file(path, orientation_length=orientation_length(model))]
    else:
        items = [mv for mv in model_moves(model) if move in (None, mv.name)]
        if not items:
            raise ArgumentError(f"--move {move!r}: the model file's moves are "
                                f"{sorted(model.spec.trajectories)}")
    kin = kinematic or {}
    if any(v is not None for v in kin.values()):     # the options override the item's limits
        from dataclasses import replace

        def given(it):
            base = it.kinematic or model_moves(model)[-1].kinematic
            return replace(it, kinematic={k: (base[k] if v is None else v)
                                          for k, v in kin.items()})
        items = [given(it) for it in items]
    res, plans = plan_paths(model, items, tau_max, margin, grid, splits, smooth=smooth,
                            tau_rate=tau_rate, progress=progress, command_line=command_line)
    if closed_loop_margins is not None:
        loops = res["closed_loop"] = {}
        for it in items:
            said = None if progress is None else (
                lambda msg, name=it.name: progress(f"{name}: {msg}"))
            loops[it.name] = closed_loop(model, it.path, tau_max, splits[-1],
                                         closed_loop_margins, grid, progress=said)
    return PlanRun(model, res, plans, provenance(model, command_line))


def write_plan_csvs(run, out):
    """Each plan of ``run`` (a :class:`PlanRun`) as ``out/plan_<path>_<split>.csv``
    (:func:`.report.csv_text`, headed by ``run.provenance``); returns the paths written."""
    from pathlib import Path

    from ..infra.results import write_atomic
    return [write_atomic(Path(out) / f"plan_{name}_{key}.csv",
                         csv_text(run.model, p, run.provenance).encode())
            for (name, key), p in run.plans.items()]
