# What `pm2dof identify fit` prints and saves: the identification's numbers, its text, the truth.
"""Text and JSON reports of :func:`pm2dof.identification.fit.identify_log` (``pm2dof identify
fit``, run by :func:`.jobs.run_fit`): a log read from a file and a simulated excitation run get
the same report, with the truth of the plant that wrote the log when the log tells it."""
from dataclasses import dataclass

import numpy as np

from ..control.plant import plant_truth, theta_truth
from .base import parameter_units
from .fit import MODEL_ERROR_CHOICES, SPEED_LEVER, joint_speed_floor, speed_phrase
from .log import LogError

__all__ = ["format_identification", "summary", "format_fit", "plant_comparison",
           "recorded_plant", "RecordedPlant", "invisible_directions", "SIMULATED_SOURCE",
           "INTERVAL_NOTE"]

#: metadata ``source`` of a log simulated with the model file's [plant] (then the truth is known)
SIMULATED_SOURCE = "simulated plant ([plant] of the model file)"


#: what the printed interval is (the line under the table)
INTERVAL_NOTE = ("+-interval: 2 sigma (noise; Newey-West) + the shifts of the estimate when the "
                 "cutoff is halved, the joint-speed threshold doubled and the sample rate halved "
                 "(discretisation and friction outside eq. 2, which 2 sigma misses); how often it "
                 "covers the truth for an excitation: pm2dof identify monte-carlo")


@dataclass(frozen=True)
class RecordedPlant:
    """The plant that wrote a log, as far as the log tells (:func:`recorded_plant`).

    Attributes
    ----------
    theta : ndarray (p,) or None
        Its theta (``model.param_names`` order), or None for a log that records no plant and
        was not simulated with the model file's [plant] (a real robot's log).
    source : str or None
        Where ``theta`` comes from, in words ("as its header records it (plant_theta)").
    changed : bool or None
        For a log simulated with the model file's [plant]: whether that [plant] has changed
        since (its ``plant_sha256`` against today's); None when it cannot be told.
    line : str or None
        The one line the report prints about it, or None.
    """
    theta: object
    source: object
    changed: object
    line: object


def _plant_theta(model, text, src):
    """theta (p,) from a log's ``plant_theta`` ("alpha1=0.09 alpha2=...")."""
    names, values = [], []
    for item in str(text).split():
        name, eq, value = item.partition("=")
        try:
            values.append(float(value) if eq else float("nan"))
        except ValueError:
            values.append(float("nan"))
        names.append(name)
    th = np.array(values)
    if names != list(model.param_names) or not np.isfinite(th).all():
        raise LogError(f"{src}: its plant_theta must be name=value for every parameter of "
                       f"{model.name!r} in order ({', '.join(model.param_names)}), with finite "
                       f"values; got {str(text)[:120]!r}")
    return th


def recorded_plant(model, log):
    """The plant that wrote ``log``: what the report's truth column compares with.

    ``identify excite`` records it in the log's header (``plant_theta``, ``plant_sha256``:
    :func:`pm2dof.identification.excitation.plant_entries`), so that a later edit of the model
    file's [plant] does not change the truth of a log already written. A simulated log that
    does not record its plant (written by an older pm2dof) is refused.

    Parameters
    ----------
    model : Model
    log : IdentLog

    Returns
    -------
    RecordedPlant

    Raises
    ------
    LogError
        A ``plant_theta`` that does not list the model's parameters with finite values; a
        simulated log without ``plant_theta``.
    """
    from .excitation import plant_sha256
    meta = log.meta
    with_plant = meta.get("source") == SIMULATED_SOURCE
    if "plant_theta" in meta:
        theta = _plant_theta(model, meta["plant_theta"], log.source)
        changed = (meta["plant_sha256"] != plant_sha256(plant_truth(model))
                   if with_plant and "plant_sha256" in meta else None)
        line = ("the model file's [plant] has changed since this log was written: the truth "
                "column is the plant the log records (plant_theta), not today's [plant]"
                if changed else None)
        return RecordedPlant(theta, "as its header records it (plant_theta)", changed, line)
    if with_plant:
        raise LogError(f"{log.source}: a log of the simulated plant that does not record it "
                       f"(plant_theta, plant_sha256): written by an older pm2dof, whose log "
                       f"format this version does not read; write it again with `pm2dof "
                       f"identify excite`")
    return RecordedPlant(None, None, None, None)


def invisible_directions(model):
    """What the directions no data can see are, in words, by the model's end effector: point
    masses at a point robot's common tip booked to one leg or another; at a platform's
    attachment points, booked to a leg or to the platform."""
    if model.dof == 3:
        return ("point masses at the platform's attachment points booked to a leg or to the "
                "platform")
    return "point masses at the common tip booked to one leg or another"


def _task_force_units(model):
    """The unit of each task axis's force, as printed: N for x and y, N m for phi."""
    return ["N m" if n == "phi" else "N" for n in model.task_names]


def plant_comparison(model, log, res):
    """What ``fit --seed-na``'s Table 3 compares, and whether it can be read as a verdict.

    Table 3 runs on the model file's ``[plant]``. For a log simulated with that plant it is the
    robot that wrote the log; for any other log it is a guess, and the table says how the
    identified theta controls *that* robot, not the log's.

    Returns
    -------
    (str, str or None)
        The line saying what the comparison is; a one-line warning when the identified theta
        is outside [plant]'s interval on a well-determined base parameter (|estimate| > its
        interval), else None.
    """
    plant = res.base.fold(theta_truth(model))
    est, half = res.estimate, res.interval
    if log.meta.get("source") == SIMULATED_SOURCE and not recorded_plant(model, log).changed:
        return ("Table 3 runs on the model file's [plant], the robot this log was simulated "
                "with", None)
    what = (f"Table 3 runs on the model file's [plant], not on the robot that wrote {log.source}: "
            f"it shows how each theta controls [plant], which is only a guess of that robot")
    sure = np.abs(est) > half
    far = sure & (np.abs(est - plant) > half)
    if not far.any():
        return what, None
    k = int(np.argmax(np.where(far, np.abs(est - plant) / half, -np.inf)))
    return what, (f"the identified theta is outside its interval of [plant]'s on {int(far.sum())} "
                  f"of {int(sure.sum())} well-determined base parameters (e.g. "
                  f"{res.names[k]}: {est[k]:.4g} +- {half[k]:.2g}, [plant] {plant[k]:.4g}): "
                  f"the log's robot is not [plant], so Table 3 is no verdict on the "
                  f"identification")


def summary(model, log, res):
    """JSON-ready numbers of one identification (the base parameters, the physical theta,
    the filter and the residual statistics; the truth of the plant that wrote the log when
    the log records it or was simulated with the model file's [plant]: :func:`recorded_plant`).

    Keys that name a unit (``residual_rms_N``, ``min_joint_speed_rad_s``) have a unit-free
    twin (``residual_rms``, ``joint_speed_floor``) whose units, by each axis's or actuator's
    kind, are in ``units``, as are those of the base parameters and of theta0."""
    c = res.consistent
    out = {"log": log.source, "model": model.name, "rows": len(log.t),
           "duration_s": log.duration, "sample_period_s": log.period,
           "filter": {"kind": "Butterworth, zero-phase (scipy.signal.sosfiltfilt)",
                      "order": 4, "cutoff_hz": res.cutoff_hz, "band_hz": res.band_hz,
                      "band_from": res.band_from, "decimate": res.decimate},
           "samples_used": res.samples, "samples_left_out_slow": res.left_out_slow,
           "min_joint_speed_rad_s": res.min_joint_speed,
           **({"min_linear_speed_m_s": res.min_joint_speed * SPEED_LEVER}
              if any(leg.actuator == "prismatic" for leg in model.spec.legs) else {}),
           "joint_speed_floor": joint_speed_floor(model, res.min_joint_speed),
           "task_axes": list(model.task_names),
           "residual_rms_N": res.rms, "residual_rms": res.rms, "r2": res.r2,
           "residual_lag1": res.lag1,
           "condition_number": res.condition_number,
           "base_parameters": res.names, "estimate": res.estimate,
           "two_sigma": 2 * res.std, "interval": res.interval,
           "model_error": {c: d for c, d in zip(MODEL_ERROR_CHOICES, res.model_error)},
           "nominal": res.nominal,
           "param_names": list(model.param_names), "theta0": res.theta0,
           "theta_least_squares": res.theta_ls, "warnings": list(res.warnings)}
    if c is not None:
        out["physical"] = {"base": c["base"], "active_constraints": c["active"],
                           "ipopt_status": list(c["status"]),
                           "objective_increase": c["objective"] - c["unconstrained_objective"]}
    plant = recorded_plant(model, log)
    if plant.theta is not None:
        out["truth"] = res.base.fold(plant.theta)
        out["truth_from"] = plant.source
        if plant.changed is not None:
            out["plant_changed_since_log"] = plant.changed
        if plant.line:
            out["plant_note"] = plant.line
    bunits = parameter_units(model, res.independent_names)
    out["units"] = {"joint_speed_floor": _speed_units(model),
                    "residual_rms": _task_force_units(model),
                    **{k: bunits for k in ("estimate", "two_sigma", "interval", "nominal",
                                           "truth") if k in out},
                    "theta0": parameter_units(model), "theta_least_squares": parameter_units(model)}
    return out


def _speed_units(model):
    return ["rad/s" if leg.actuator == "revolute" else "m/s" for leg in model.spec.legs]


def format_identification(model, log, res):
    """The printed report of ``pm2dof identify fit``."""
    s = summary(model, log, res)
    f = s["filter"]
    band = (f"{f['cutoff_hz']:.4g} Hz = {f['cutoff_hz'] / f['band_hz']:.3g} x the excitation "
            f"band {f['band_hz']:.4g} Hz ({f['band_from']})" if f["band_hz"] else
            f"{f['cutoff_hz']:.4g} Hz (given)")
    lines = [
        f"identification from {log.source}: {len(log.t)} rows, {log.duration:.3f} s at T = "
        f"{log.period * 1e3:.4g} ms, model {model.name!r} ({model.n_legs} legs)",
        f"filter: 4th-order Butterworth, zero-phase (sosfiltfilt), cutoff {band}; the same "
        f"filter on every regressor column and on S^T tau, then decimated by {f['decimate']}",
        f"samples: {s['samples_used']} used ({2 * s['samples_used']} equations), "
        f"{s['samples_left_out_slow']} left out (a joint slower than "
        f"{speed_phrase(model, s['min_joint_speed_rad_s'])})",
        "residual: rms " + ", ".join(f"{v:.4g} {u} ({a})" for v, u, a in zip(
            s["residual_rms"], s["units"]["residual_rms"], s["task_axes"]))
        + "; R^2 " + ", ".join(f"{v:.6f}" for v in s["r2"])
        + f"; lag-1 autocorrelation {s['residual_lag1']:.2f} (sigma from a Newey-West "
        f"covariance); condition number {s['condition_number']:.4g}",
        "",
    ]
    truth = s.get("truth")
    phys = s.get("physical")
    units = s["units"]["estimate"]
    wn = max(len("base parameter"), *(len(n) for n in s["base_parameters"]))
    wu = max(len("unit"), *(len(u) for u in units))
    head = (f"{'base parameter':{wn}s} {'unit':{wu}s} {'estimate':>10s} {'+-interval':>10s} "
            f"{'nominal':>10s}")
    head += f" {'physical':>10s}" if phys else ""
    head += f" {'truth':>10s}" if truth is not None else ""
    lines.append(head)
    for k, name in enumerate(s["base_parameters"]):
        row = (f"{name:{wn}s} {units[k]:{wu}s} {s['estimate'][k]:10.5f} "
               f"{s['interval'][k]:10.5f} {s['nominal'][k]:10.5f}")
        row += f" {phys['base'][k]:10.5f}" if phys else ""
        if truth is not None:
            row += f" {truth[k]:10.5f}"
            if abs(s["estimate"][k] - truth[k]) > s["interval"][k]:
                row += "  (truth outside the interval)"
        lines.append(row)
    lines.append(INTERVAL_NOTE)
    if truth is not None:
        payload = ("to the platform's m_p" if model.dof == 3 else "to its leg")
        lines.append(f"truth: the plant that wrote this log, {s['truth_from']} (payload booked "
                     f"{payload}), shown because this log says it was simulated; the Stribeck "
                     f"excess has no coordinate in eq. 2")
    plant_line = recorded_plant(model, log).line
    if plant_line:
        lines.append(plant_line)
    if phys:
        act = ", ".join(phys["active_constraints"]) or "none"
        how = ("the least-squares base parameters are physical as they are" if
               phys["ipopt_status"][0].startswith("not needed") else
               f"constrained least squares, IPOPT: {phys['ipopt_status'][0]}; active "
               f"constraints: {act}; residual increase {phys['objective_increase']:.3g} "
               f"(relative)")
        lines += ["", f"physical theta (every leg's [[alpha, beta], [beta, gamma]] >= 0, friction "
                  f">= 0; CasADi + IPOPT): {how}",
                  f"the directions no data can see ({invisible_directions(model)}) are fixed "
                  f"closest to the nominal theta (Tables 1-2)"]
    lines.append("theta0 (full, for NAController/APDController(theta0=...) and [nominal]):")
    lines += [f"  {n:8s} {v:10.6f} {u}" for n, v, u in zip(s["param_names"], s["theta0"],
                                                           s["units"]["theta0"])]
    for w in s["warnings"]:
        lines.append(f"warning: {w}")
    return "\n".join(lines)


def format_fit(r):
    """A :class:`.jobs.FitRun` as ``pm2dof identify fit`` prints it."""
    from .monte_carlo import format_seeded_table3
    text = format_identification(r.model, r.log, r.result)
    if "table3" in r.summary:
        text += "\n\n" + "\n".join([format_seeded_table3(r.summary["table3"]),
                                      r.summary["table3_comparison"]]
                                     + ([f"warning: {r.seed_warning}"] if r.seed_warning else []))
    return text
