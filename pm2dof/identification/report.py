# `pm2dof identify fit [LOG]`: run the identification pipeline on a log, print, save theta.
"""Text and JSON reports of :func:`pm2dof.identification.fit.identify_log`, and
``pm2dof identify fit``: a log read from a file and a simulated excitation run go through the
same pipeline and the same report."""
import dataclasses
from dataclasses import dataclass

import numpy as np

from ..control.plant import theta_truth
from ..core.errors import ArgumentError
from .fit import MODEL_ERROR_CHOICES, SPEED_LEVER, identify_log, speed_phrase
from .log import LogError, log_folder, read_log

__all__ = ["format_identification", "summary", "run_fit", "FitReport", "format_fit",
           "load_theta", "plant_comparison", "SIMULATED_SOURCE", "INTERVAL_NOTE"]

#: metadata ``source`` of a log simulated with the model file's [plant] (then the truth is known)
SIMULATED_SOURCE = "simulated plant ([plant] of the model file)"


#: what the printed interval is (the line under the table)
INTERVAL_NOTE = ("+-interval: 2 sigma (noise; Newey-West) + the shifts of the estimate when the "
                 "cutoff is halved, the joint-speed threshold doubled and the sample rate halved "
                 "(discretisation and friction outside eq. 2, which 2 sigma misses); how often it "
                 "covers the truth for an excitation: pm2dof identify monte-carlo")


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
    if log.meta.get("source") == SIMULATED_SOURCE:
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
    the filter and the residual statistics; the plant truth if the log is simulated with the
    model file's [plant])."""
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
           "residual_rms_N": res.rms, "r2": res.r2, "residual_lag1": res.lag1,
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
    if log.meta.get("source") == SIMULATED_SOURCE:
        out["truth"] = res.base.fold(theta_truth(model))
    return out


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
        f"residual: rms {s['residual_rms_N'][0]:.4g} N (x), {s['residual_rms_N'][1]:.4g} N (y); "
        f"R^2 {s['r2'][0]:.6f}, {s['r2'][1]:.6f}; lag-1 autocorrelation {s['residual_lag1']:.2f} "
        f"(sigma from a Newey-West covariance); condition number {s['condition_number']:.4g}",
        "",
    ]
    truth = s.get("truth")
    phys = s.get("physical")
    head = f"{'base parameter':38s} {'estimate':>10s} {'+-interval':>10s} {'nominal':>10s}"
    head += f" {'physical':>10s}" if phys else ""
    head += f" {'truth':>10s}" if truth is not None else ""
    lines.append(head)
    for k, name in enumerate(s["base_parameters"]):
        row = (f"{name[:38]:38s} {s['estimate'][k]:10.5f} {s['interval'][k]:10.5f} "
               f"{s['nominal'][k]:10.5f}")
        row += f" {phys['base'][k]:10.5f}" if phys else ""
        if truth is not None:
            row += f" {truth[k]:10.5f}"
            if abs(s["estimate"][k] - truth[k]) > s["interval"][k]:
                row += "  (truth outside the interval)"
        lines.append(row)
    lines.append(INTERVAL_NOTE)
    if truth is not None:
        lines.append("truth: the simulated plant's ([plant] of the model file, payload booked to "
                     "its leg), shown because this log says it was simulated; the Stribeck "
                     "excess has no coordinate in eq. 2")
    if phys:
        act = ", ".join(phys["active_constraints"]) or "none"
        how = ("the least-squares base parameters are physical as they are" if
               phys["ipopt_status"][0].startswith("not needed") else
               f"constrained least squares, IPOPT: {phys['ipopt_status'][0]}; active "
               f"constraints: {act}; residual increase {phys['objective_increase']:.3g} "
               f"(relative)")
        lines += ["", f"physical theta (every leg's [[alpha, beta], [beta, gamma]] >= 0, friction "
                  f">= 0; CasADi + IPOPT): {how}",
                  "the directions no data can see (point masses at the common tip booked to one "
                  "leg or another) are fixed closest to the nominal theta (Tables 1-2)"]
    lines.append("theta0 (full, for NAController/APDController(theta0=...) and [nominal]):")
    lines += [f"  {n:8s} {v:10.6f}" for n, v in zip(s["param_names"], s["theta0"])]
    for w in s["warnings"]:
        lines.append(f"warning: {w}")
    return "\n".join(lines)


@dataclass(frozen=True)
class FitReport:
    """What ``pm2dof identify fit`` found (:func:`run_fit`; its text: :func:`format_fit`).

    ``result`` is :func:`~pm2dof.identification.fit.identify_log`'s, ``summary`` the
    command's ``--json`` (:func:`summary`, with Table 3 when seeded), ``seed_warning`` the
    warning of the seeded Table 3's comparison, if any."""
    model: object
    log: object
    result: dict
    summary: dict
    seed_warning: object = None


def format_fit(r):
    """A :class:`FitReport` as ``pm2dof identify fit`` prints it."""
    from .monte_carlo import format_seeded_table3
    text = format_identification(r.model, r.log, r.result)
    if "table3" in r.summary:
        text += "\n\n" + "\n".join([format_seeded_table3(r.summary["table3"]),
                                      r.summary["table3_comparison"]]
                                     + ([f"warning: {r.seed_warning}"] if r.seed_warning else []))
    return text


def run_fit(log=None, *, model=None, generated=None, excitation_file=None, duration=None,
            quantise=True, controller=None, save=None, cutoff_hz=None,
            min_joint_speed=None, time_tolerance=1e-3, seed=None, progress=None):
    """``pm2dof identify fit [LOG]``: identify, optionally save; returns a :class:`FitReport`.

    Parameters
    ----------
    log : str or Path, optional
        A log file (:func:`~pm2dof.identification.log.read_log`). Its model is the one it
        records unless ``model`` is given, and then it must be that one. Without a log, an
        excitation runs on the simulated plant first
        (:func:`~pm2dof.identification.excitation.simulated_log`: ``excitation_file``, else the
        default multi-sine of ``duration`` s; ``quantise``; ``controller`` "apd" (default) or
        "na"), and that log is identified the same way.
    model, generated : optional
        ``--model`` (a name, a model file or a Model), ``--generated``.
    save : path, optional
        Write ``{"param_names", "theta0", ...}`` and the provenance as JSON.
    seed : callable(model, theta) -> dict, optional
        Also Table 3 with APD and NA using the identified theta: the CLI's ``--seed-na``
        passes :func:`pm2dof.analysis.experiment.seeded_table3` (identification does not
        import the paper's experiment).
    cutoff_hz, min_joint_speed, time_tolerance :
        See :func:`~pm2dof.identification.fit.identify_log` and ``read_log``.

    Returns
    -------
    FitReport
        :func:`~pm2dof.identification.fit.identify_log`'s result and the summary.
    """
    from ..infra.results import provenance, write_json
    from .excitation import model_of_excitation, simulated_log
    from .fit import MIN_JOINT_SPEED
    from .model_ref import model_for
    from .signals import DEFAULT_DURATION
    if log is not None:
        simulated = {"--excitation": excitation_file is not None,
                     "--duration": duration is not None, "--exact-encoders": not quantise,
                     "--controller": controller is not None}
        given = [k for k, v in simulated.items() if v]
        if given:
            raise ArgumentError(f"{', '.join(given)}: options of a simulated excitation run, "
                                f"which fit runs only without a LOG (got LOG {log})")
        path = log
        log = read_log(path, time_tolerance=time_tolerance)
        assumed = model is None and "model" not in log.meta
        model = model_for(log.meta, log_folder(log), str(path), model=model, generated=generated,
                          error=LogError)
        if assumed:
            assumed = (f"model {model.name!r} ({model.spec.path}) assumed: {path} records no "
                       f"model and no --model was given")
        if progress:
            progress(f"read {path}: {len(log.t)} rows; filtering, stacking the base regressor, "
                     f"weighted and physically constrained least squares")
    else:
        assumed = False
        model = model_of_excitation(excitation_file, duration, model=model, generated=generated)
        log = simulated_log(model, excitation_file,
                            DEFAULT_DURATION if duration is None else duration,
                            quantise=quantise, controller=controller or "apd", progress=progress)
        if progress:
            progress(f"{len(log.t)} rows; filtering, stacking the base regressor, weighted and "
                     f"physically constrained least squares")
    try:
        res = identify_log(model, log, cutoff_hz=cutoff_hz,
                           min_joint_speed=MIN_JOINT_SPEED if min_joint_speed is None
                           else min_joint_speed)
    except LogError as exc:
        if assumed:
            raise LogError(f"{exc} ({assumed})") from None
        raise
    if assumed:
        res = dataclasses.replace(res, warnings=(assumed, *res.warnings))
    s = summary(model, log, res)
    warn = None
    if seed:
        if progress:
            progress("Table 3 with Tables 1-2 and with the identified theta")
        s["table3"] = seed(model, res.theta0)
        s["table3_comparison"], warn = plant_comparison(model, log, res)
        if warn:
            s["warnings"] = [*s["warnings"], warn]
    if save:
        write_json(save, {**s, "provenance": provenance(model)})
    return FitReport(model, log, res, s, warn)


def load_theta(path, model):
    """theta0 (p,) from a JSON written by ``pm2dof identify fit --save`` (checks the names)."""
    import json
    d = json.loads(open(path).read())
    if list(d.get("param_names", [])) != list(model.param_names):
        raise ArgumentError(f"{path}: param_names {d.get('param_names')} do not match model "
                         f"{model.name!r} ({list(model.param_names)})")
    th = np.asarray(d["theta0"], dtype=float)
    if th.shape != (len(model.param_names),) or not np.isfinite(th).all():
        raise ArgumentError(f"{path}: theta0 must be {len(model.param_names)} finite numbers")
    return th
