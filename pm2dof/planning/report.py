# What `pm2dof plan` computes and prints: timings per split, the kinematic S-curve, the closed loop.
"""The numbers of ``pm2dof plan``, as plain data (for ``--json``) and as text.

:func:`plan_paths` plans each path with the kinematic S-curve and time-optimally with each
split (optionally the smoothed variant); :func:`closed_loop` tracks time-optimal plans with NA
and APD in simulation at several margins; :func:`csv_text` is a plan's trajectory with the
split's torques as CSV (its columns named and given their units by :func:`csv_columns`);
:func:`format_report` renders all of it. Every effort is in its actuator's unit
(:func:`effort_units`: N m for a revolute actuator, N for a linear one).
"""
import numpy as np

from ..control.controllers import APDController, NAController
from ..control.simulate import simulate
from ..core.errors import ArgumentError, PlanError
from ..core.task import per_actuator
from ..infra.results import provenance
from .check import check_path, require
from .kinematic import plan_kinematic
from .stages import limits
from .topp import plan_time_optimal
from .torques import path_torques

__all__ = ["plan_paths", "closed_loop", "csv_text", "csv_columns", "format_report",
           "model_moves", "plan_provenance", "run_plan", "write_plan_csvs", "effort_units",
           "CSV_KEYS"]


def effort_units(model):
    """Each actuator's effort unit, one per leg: "N m" (a revolute actuator's torque) or "N"
    (a linear actuator's force: PRR sliders, RPR cylinders). A model may mix them."""
    return [per_actuator([leg.actuator], "N m", "N") for leg in model.spec.legs]


def _units(model):
    """The ``units`` entry of :func:`plan_paths`' results: the unit of each actuator's entry of
    every effort there (``tau_max``, ``tau_peak``, ``tau_rate``), one per actuator."""
    eff = effort_units(model)
    return {"tau_max": eff, "tau_peak": eff, "tau_rate": [f"{u}/s" for u in eff]}


def model_moves(model):
    """The model file's moves as paths: [:class:`.pathfile.NamedPath`] (line moves as lines,
    path moves from their path files)."""
    from .pathfile import model_move_path
    return [model_move_path(model, name) for name in model.spec.trajectories]


def _at_samples(plan):
    """(s, s_d, s_dd) of a plan at its trajectory's samples."""
    if plan.method == "kinematic":         # its profile arrays are the samples already
        return plan.s, plan.sdot, plan.sddot
    return plan.profile.evaluate(plan.trajectory.t)


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
               theta=None, smooth=False, tau_rate=None, progress=None):
    """Plan every item (:class:`.pathfile.NamedPath`: name, path, kinematic limits)
    kinematically and time-optimally (``smooth``: also :func:`.smooth.plan_smooth`).

    ``progress`` (a callable taking one-line messages, e.g. a
    :class:`pm2dof.infra.progress.Progress`; None: silent) hears a line per path and, with
    ``smooth``, IPOPT's progress for each split (:func:`.smooth.plan_smooth`).

    Returns
    -------
    (dict, dict)
        The JSON-able results ``{"model", "tau_max", "margin", "grid", "units", "provenance",
        "paths": [...]}`` (``provenance``: :func:`plan_provenance`; ``units``: each actuator's
        unit of ``tau_max``, ``tau_peak`` and ``tau_rate``, "N m" and "N m/s" for a revolute
        actuator, "N" and "N/s" for a linear one) and the Plan objects
        ``{(name, method_or_split): Plan}``. Each timing's peak efforts are ``tau_peak`` (one
        per actuator, in ``units``), and under their old name ``tau_peak_N_m`` (the same
        values, whatever the unit).
    """
    tau_lim = limits(model, tau_max, 1.0)
    res = {"model": model.name, "tau_max": tau_lim.tolist(), "margin": float(margin),
           "grid": int(grid), "units": _units(model),
           "provenance": plan_provenance(model, tau_lim, margin, splits, theta), "paths": []}
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


def plan_provenance(model, tau_max, margin, splits, theta=None, base=None):
    """Where a plan came from: ``base`` or :func:`pm2dof.infra.results.provenance` (the
    pm2dof version, the model file, the generated folder, hashes, git commit, command line)
    with the planning inputs: ``tau_max`` (n,) N m (the actuators' limits, before the margin),
    ``margin``, the ``splits`` and ``theta`` ("nominal": the model's Tables 1-2, else the 5n
    values)."""
    th = model.theta_nominal if theta is None else np.asarray(theta, dtype=float)
    nominal = np.array_equal(th, model.theta_nominal)
    return {**(base or provenance(model)), "tau_max": np.asarray(tau_max, dtype=float).tolist(),
            "margin": float(margin), "splits": list(splits),
            "theta": "nominal" if nominal else np.asarray(th, dtype=float).tolist()}


#: the provenance keys a CSV's header lines carry, in order
CSV_KEYS = ("model", "model_file", "model_file_sha256", "generated", "pm2dof", "git_commit",
            "tau_max", "margin", "split", "theta")


def csv_columns(model):
    """The columns of a plan CSV (:func:`csv_text`) of ``model``, in order: ``[(name, unit)]``.

    t (s); s, sdot, sddot (the arc length, m, and its rates); the pose, named by the model's
    task coordinates (``Model.task_names``: x, y, and a platform's phi), then its velocity
    (``v`` + the name: vx, vy, vphi) and acceleration (``a`` + the name: ax, ay, aphi), m and
    rad, m/s and rad/s, m/s^2 and rad/s^2; then each actuator's effort of the plan's split,
    tau1..taun, N m for a revolute actuator, N for a linear one.
    """
    task = list(model.task_names)
    unit = ["rad" if nm == "phi" else "m" for nm in task]
    return ([("t", "s"), ("s", "m"), ("sdot", "m/s"), ("sddot", "m/s^2")]
            + list(zip(task, unit)) + [(f"v{nm}", f"{u}/s") for nm, u in zip(task, unit)]
            + [(f"a{nm}", f"{u}/s^2") for nm, u in zip(task, unit)]
            + [(f"tau{i + 1}", u) for i, u in enumerate(effort_units(model))])


def csv_text(model, plan, prov=None):
    """``plan``'s trajectory as CSV text: ``# key = value`` lines (the provenance: model, model
    file and its hash, generated folder, pm2dof version, git commit, tau_max (the actuators'
    limits), margin, split, theta ("nominal" or the values); then method, duration,
    sample_period, and ``units``: one unit per column, in the columns' order), the column
    names, then the columns of :func:`csv_columns` (t, s, sdot, sddot, the pose, its velocity
    and acceleration, e.g. x, y, vx, vy, ax, ay for a point and x, y, phi, vx, vy, vphi, ax,
    ay, aphi for a platform, and the actuator efforts of its split, tau1..taun: inverse
    dynamics at the samples with the plan's theta). ``prov``: :func:`provenance`'s dict if the
    caller has it (else computed). Read it with ``csv.DictReader`` over the lines that do not
    start with ``#``, ``np.loadtxt(f, delimiter=",", skiprows=1 + the number of ``#`` lines)``
    or any CSV reader that skips ``#`` comments."""
    tr = plan.trajectory
    s, sd, sdd = _at_samples(plan)
    split = plan.split or "min_norm"
    theta = plan.info.get("theta")
    tau = path_torques(model, plan.path, s, sd, sdd, theta, plan.tau_max)[split]
    cols = np.column_stack([tr.t, s, sd, sdd, tr.xd, tr.xd_dot, tr.xd_ddot, tau])
    names = csv_columns(model)
    if cols.shape[1] != len(names):         # the header must name every column
        raise PlanError(f"plan CSV of model {model.name!r}: {cols.shape[1]} columns, "
                        f"{len(names)} names {[nm for nm, _ in names]}")
    head = ",".join(nm for nm, _ in names)
    tau_lim = plan.info.get("tau_max_actuators", model.spec.limits["tau_max"])
    info = {**plan_provenance(model, tau_lim, plan.margin, [split], theta, prov), "split": split}
    meta = "".join(f"# {k} = {info[k]}\n" for k in CSV_KEYS if k in info)
    meta += (f"# method = {plan.method}\n# duration = {plan.duration!r}\n"
             f"# sample_period = {tr.period!r}\n"
             f"# units = {', '.join(u for _, u in names)}\n")
    rows = "".join(",".join(repr(float(x)) for x in row) + "\n" for row in cols)
    return meta + head + "\n" + rows        # the shortest exact decimals, as logs write them


def _efforts(values, units, fmt=".3f"):
    """The largest of ``values`` (one per actuator) with its unit, for the text: "3.000 N m";
    with actuators of both kinds, the largest of each kind: "3.000 N m, 40.000 N"."""
    by_unit = {}
    for v, u in zip(values, units):
        by_unit[u] = max(by_unit.get(u, v), v)
    return ", ".join(f"{v:{fmt}} {u}" for u, v in by_unit.items())


def format_report(res, loops=None, unit=None):
    """The text ``pm2dof plan`` prints. Every effort carries its actuator's unit, from
    ``res["units"]`` (:func:`plan_paths`: N m for a revolute actuator, N for a linear one; a
    model with both prints the largest of each kind); ``unit`` (one for all actuators) serves
    results without ``units``."""
    n = len(res["tau_max"])
    units = res.get("units", {}).get("tau_max") or [unit or "N m"] * n
    if len(set(units)) == 1:
        lims = f"{res['tau_max']} {units[0]}"
    else:
        lims = "[" + ", ".join(f"{v} {u}" for v, u in zip(res["tau_max"], units)) + "]"
    lines = [f"model {res['model']}: tau_max {lims}, margin {res['margin']}, grid {res['grid']}"]
    for row in res["paths"]:
        lines.append(f"\n{row['name']}: {row['length_m']:.4f} m ({'+'.join(row['kinds'])}; "
                     f"{len(row['stops_m']) - 2} interior stop(s))")
        k = row.get("kinematic")
        if k:
            lim = ", ".join(f"{sp} {'within' if ok else 'BEYOND'} limits"
                            for sp, ok in k["within_limits"].items())
            lines.append(f"  kinematic S-curve ({k['v_max']:g} m/s, {k['a_max']:g} m/s^2, "
                         f"{k['j_max']:g} m/s^3): {k['duration_s']:.4f} s; peak |tau| "
                         f"{_efforts(k['tau_peak']['min_norm'], units)} min-norm ({lim})")
        for split in ("min_norm", "min_max"):
            r = row.get(split)
            if r and "infeasible" in r:
                lines.append(f"  time-optimal, {split:8s}: infeasible: {r['infeasible']}")
            elif r:
                lines.append(f"  time-optimal, {split:8s}: {r['duration_s']:.4f} s (peak |tau| "
                             f"{_efforts(r['tau_peak'], units)}, top speed "
                             f"{r['max_speed_m_s']:.3f} m/s; {r['compute_ms']:.1f} ms, "
                             f"{r['grid']} grid points)")
        if "saving_min_max_percent" in row:
            lines.append(f"  the redundancy (min-max over min-norm) saves "
                         f"{row['saving_min_max_percent']:.1f} % of the time")
        for split in ("min_norm", "min_max"):
            r = row.get(f"smooth_{split}")
            if r:
                rates = _efforts(r["tau_rate"], [f"{u}/s" for u in units], ".0f")
                lines.append(f"  smoothed, {split:8s}: {r['duration_s']:.4f} s vs strict "
                             f"{r['strict_duration_s']:.4f} s on its {r['grid']}-point grid "
                             f"(+{100 * (r['duration_s'] / r['strict_duration_s'] - 1):.1f} %, "
                             f"|dtau/dt| <= {rates}; IPOPT {r['solve_time_s']:.2f} s)")
    for name, rows in (loops or {}).items():
        lines.append(f"\nclosed loop on {name} (plant truth of the model file, quantised "
                     f"encoders):")
        for r in rows:
            for law in ("na", "apd"):
                c = r[law]
                lines.append(f"  margin {r['margin']:.2f} ({r['duration_s']:.4f} s) "
                             f"{law.upper():3s}: RMSE {c['rmse_m']:.3e} m, max error "
                             f"{c['max_error_m']:.3e} m, peak |tau| "
                             f"{_efforts(c['tau_peak'], units)}, {c['saturated']} saturated "
                             f"samples, {c['outcome']}")
    return "\n".join(lines)



def run_plan(model, *, path=None, move=None, tau_max=None, margin=1.0, grid=1000,
             splits=("min_norm", "min_max"), kinematic=None, smooth=False, tau_rate=None,
             closed_loop_margins=None, progress=None):
    """``pm2dof plan``: plan a path file (``path``: a shipped name or a TOML file) or the model
    file's moves (``move``: only that one), with the kinematic limits ``kinematic`` ({v_max,
    a_max, j_max}, None for the path's own) overriding the paths' (the model's last move's
    where a path has none), and with ``closed_loop_margins``, NA and APD tracking the plan of
    the last split at each margin (:func:`closed_loop`). ``progress``: stage lines, as
    :func:`plan_paths` (None: silent).

    Returns
    -------
    (dict, dict, dict)
        :func:`plan_paths`' results (with ``closed_loop``: {path name: rows} when simulated)
        and plans, and the closed-loop rows by path name (for :func:`format_report`).
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
                            tau_rate=tau_rate, progress=progress)
    loops = {}
    if closed_loop_margins is not None:
        for it in items:
            said = None if progress is None else (
                lambda msg, name=it.name: progress(f"{name}: {msg}"))
            loops[it.name] = closed_loop(model, it.path, tau_max, splits[-1],
                                         closed_loop_margins, grid, progress=said)
        res["closed_loop"] = loops
    return res, plans, loops


def write_plan_csvs(out, model, plans):
    """Each plan of :func:`run_plan` as ``out/plan_<path>_<split>.csv`` (:func:`csv_text`);
    returns the paths written."""
    from pathlib import Path

    from ..infra.results import write_atomic
    return [write_atomic(Path(out) / f"plan_{name}_{key}.csv", csv_text(model, p).encode())
            for (name, key), p in plans.items()]
