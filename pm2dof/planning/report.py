# What `pm2dof plan` prints and writes: the text report, each plan's CSV, their provenance.
"""The text and the files of ``pm2dof plan``: :func:`format_report` renders the numbers of
:func:`.jobs.run_plan` (:func:`.jobs.plan_paths`, :func:`.jobs.closed_loop`); :func:`csv_text`
is a plan's trajectory with the split's torques as CSV (its columns named and given their units
by :func:`csv_columns`), headed by :func:`plan_provenance`. Every effort is in its actuator's
unit (:func:`effort_units`: N m for a revolute actuator, N for a linear one).
"""
import numpy as np

from ..core.errors import PlanError
from ..core.task import per_actuator
from ..infra.results import provenance
from .torques import path_torques

__all__ = ["csv_text", "csv_columns", "format_report", "plan_provenance", "effort_units",
           "CSV_KEYS"]


def effort_units(model):
    """Each actuator's effort unit, one per leg: "N m" (a revolute actuator's torque) or "N"
    (a linear actuator's force: PRR sliders, RPR cylinders). A model may mix them."""
    return [per_actuator([leg.actuator], "N m", "N") for leg in model.spec.legs]


def _at_samples(plan):
    """(s, s_d, s_dd) of a plan at its trajectory's samples."""
    if plan.method == "kinematic":         # its profile arrays are the samples already
        return plan.s, plan.sdot, plan.sddot
    return plan.profile.evaluate(plan.trajectory.t)


def plan_provenance(model, tau_max, margin, splits, theta=None, base=None, command_line=None):
    """Where a plan came from: ``base`` or :func:`pm2dof.infra.results.provenance` (the
    pm2dof version, the model file, the generated folder, hashes, git commit, ``command_line``)
    with the planning inputs: ``tau_max`` (n,) (the actuators' limits, before the margin; N m
    for a revolute actuator, N for a linear one), ``margin``, the ``splits`` and ``theta``
    ("nominal": the model's Tables 1-2, else its values)."""
    th = model.theta_nominal if theta is None else np.asarray(theta, dtype=float)
    nominal = np.array_equal(th, model.theta_nominal)
    return {**(base or provenance(model, command_line)), "tau_max": np.asarray(tau_max, dtype=float).tolist(),
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


def format_report(res, unit=None):
    """The text ``pm2dof plan`` prints of its numbers ``res`` (:attr:`.jobs.PlanRun.summary`:
    the plans, and the closed loop under ``closed_loop`` when simulated). Every effort carries
    its actuator's unit, from ``res["units"]`` (:func:`.jobs.plan_paths`: N m for a revolute
    actuator, N for a linear one; a model with both prints the largest of each kind); ``unit``
    (one for all actuators) serves results without ``units``."""
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
    for name, rows in res.get("closed_loop", {}).items():
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


