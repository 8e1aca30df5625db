# Excite the simulated plant and record what a real set-up would log: encoder angles and torques.
"""Excitation runs on the simulated robot, recorded as logs (``pm2dof identify excite``).

* The excitations themselves (the default multi-sine, the Fourier series :mod:`.design` makes,
  its file) are :mod:`.signals`.
* :func:`excite` runs an excitation on the simulated plant. The plant runs with its truth
  (``[plant]`` of the model file, or ``truth``), its encoders quantise the active angles, and a
  controller with the nominal model (Tables 1-2) tracks the excitation. The log's data are only
  what a real set-up records: the encoder angles the controller read at t_k (quantised) and the
  torque it commanded at t_k, held until t_k+1. Its header records the plant that wrote it
  (:func:`plant_entries`: its theta and a hash of its truth), which the fit uses only for the
  report's truth column, never for the estimate.
* :func:`simulated_log` is what ``pm2dof identify excite`` writes and what ``pm2dof identify
  fit`` without a log fits.
"""
import dataclasses

import numpy as np

from ..control.controllers import APDController, NAController
from ..control.plant import plant_truth, plant_vector, theta_truth
from ..control.simulate import simulate
from ..control.trajectory import require_trajectory
from ..core.errors import ArgumentError
from ..core.task import per_actuator
from .log import IdentLog
from .model_ref import model_entries
from .signals import DEFAULT_DURATION, Signal, load_excitation, multisine, trajectory_of

__all__ = ["excite", "measured_angles", "excitation_signal", "simulated_log",
           "model_of_excitation", "run_excite", "format_excite", "plant_entries",
           "plant_sha256", "encoder_phrase"]


def encoder_phrase(model, quantise=True):
    """The simulated encoders in words, by each actuator's kind: "131072 counts/rev" (rotary),
    "1e-06 m per count" (linear), both for mixed actuators, or "exact" (not quantised).

    Parameters
    ----------
    model : Model
    quantise : bool
        Whether the encoders are quantised.
    """
    sensing = model.spec.sensing
    counts = sensing["encoder_counts_per_rev"]
    step = float(sensing.get("linear_encoder_resolution", 0.0))
    rev = f"{int(counts)} counts/rev" if quantise and counts > 0 else "exact"
    lin = f"{step:g} m per count" if quantise and step > 0 else "exact"
    return per_actuator(model.spec.actuators, rev, lin, f"{rev} (rotary), {lin} (linear)")


def plant_sha256(truth):
    """SHA-256 (hex) of a plant truth (:func:`pm2dof.plant_truth`'s dict): every field's values
    as float64 in key order. Two truths hash alike iff every field is the same bit for bit."""
    import hashlib
    import json
    canon = {str(k): np.asarray(v, dtype=float).ravel().tolist() for k, v in truth.items()}
    return hashlib.sha256(json.dumps(canon, sort_keys=True).encode()).hexdigest()


def plant_entries(model, truth=None):
    """The log header's record of the plant that wrote it: ``plant_theta`` (its theta,
    :func:`pm2dof.control.plant.theta_truth`, as ``name=value`` pairs, each value the shortest
    decimal that reads back as the same float64) and ``plant_sha256`` (:func:`plant_sha256` of
    the whole truth, the Stribeck excess and the smoothing included).

    Parameters
    ----------
    model : Model
    truth : dict, optional
        The plant truth (default the model file's ``[plant]``: :func:`pm2dof.plant_truth`).
    """
    truth = plant_truth(model) if truth is None else truth
    th = theta_truth(model, truth)
    return {"plant_theta": " ".join(f"{n}={float(v)!r}" for n, v in zip(model.param_names, th)),
            "plant_sha256": plant_sha256(truth)}

def measured_angles(model, xe, quantise=True, truth=None):
    """The encoder readings (N, n), rad, of true poses ``xe`` (N, m): the generated
    ``measure`` (quantised to ``[sensing].encoder_counts_per_rev`` unless ``quantise`` is
    false), exactly what the controller read."""
    plant = plant_vector(model, truth, quantise)
    measure = model.function("measure")
    qa = np.empty((len(xe), model.n_legs))
    for k, x in enumerate(np.ascontiguousarray(xe)):
        measure(x, plant, qa[k])
    return qa


def excite(model, excitation, *, truth=None, quantise=True, controller="apd"):
    """Run ``excitation`` on the simulated plant and return its log.

    Parameters
    ----------
    model : Model
    excitation : Signal or Trajectory
        An excitation signal (:mod:`.signals`: :func:`~.signals.multisine`, a
        :class:`~.signals.FourierExcitation`), sampled at the model's period, its ``max_hz``
        (highest frequency, Hz) written into the log's metadata (``excitation_max_hz``) for the
        filter of :func:`pm2dof.identification.fit.identify_log`; or a
        :class:`pm2dof.Trajectory`, run as it is, its band not recorded. The robot starts at
        rest at its first point.
    truth : dict, optional
        Plant truth (default :func:`pm2dof.plant_truth`).
    quantise : bool
        Quantise the encoders (False: exact angles, a noise-free log).
    controller : {"apd", "na"}
        Tracking controller, with the nominal model (Tables 1-2); NA adapts as in the paper.

    Returns
    -------
    IdentLog
        t (N,), qa (N, n) as measured, tau (N, n) as applied; meta names the model
        (:mod:`.model_ref`; a model file by its absolute path until the log is written), the
        sample period, the controller, the encoders, each leg's actuator ("revolute" or
        "prismatic"), the plant (:func:`plant_entries`) and the excitation band.
    """
    if controller not in ("apd", "na"):
        raise ArgumentError(f"controller must be 'apd' or 'na', got {controller!r}")
    ctrl = (APDController if controller == "apd" else NAController)(model, on_singular="zero")
    if isinstance(excitation, Signal):
        trajectory, max_hz = trajectory_of(model, excitation), excitation.max_hz
    else:
        trajectory, max_hz = require_trajectory(excitation), None
    r = simulate(model, ctrl, trajectory, truth=truth, quantise=quantise)
    if r.n_singular or r.n_non_finite:
        raise ArgumentError(f"the excitation run left the safe region ({r.n_singular} singular, "
                            f"{r.n_non_finite} non-finite samples): reduce its amplitude")
    meta = {**model_entries(model), "n_legs": model.n_legs, "sample_period": trajectory.period,
            "source": "simulated plant ([plant] of the model file)" if truth is None
            else "simulated plant (a given truth)",
            "controller": f"{controller} with Tables 1-2",
            "encoders": encoder_phrase(model, quantise),
            "saturated_samples": r.n_saturated,
            "tracking_rmse_m": f"{r.rmse:.4g}",
            "actuators": ", ".join(leg.actuator for leg in model.spec.legs),
            **plant_entries(model, truth)}
    if max_hz:
        meta["excitation_max_hz"] = f"{max_hz:.6g}"
    return IdentLog(t=r.t, qa=measured_angles(model, r.xe, quantise, truth), tau=r.tau_a,
                    meta=meta)


def excitation_signal(model, excitation=None, duration=DEFAULT_DURATION):
    """(signal, description): an excitation (a :class:`~.signals.FourierExcitation`, or the
    path of its file, read for ``model``), or without one the default
    :func:`~.signals.multisine` lasting ``duration`` s."""
    if excitation is None:
        return multisine(model, duration=duration), f"the default {duration:g} s multi-sine"
    if isinstance(excitation, (str, bytes)) or hasattr(excitation, "__fspath__"):
        return load_excitation(excitation, model), str(excitation)
    return excitation, "the excitation"


def simulated_log(model, excitation=None, duration=DEFAULT_DURATION, *, quantise=True,
                  controller="apd", progress=None):
    """An excitation run on the simulated plant, as a log (:func:`excite`); its ``source``
    says what ran. ``excitation``, ``duration``: :func:`excitation_signal`."""
    signal, what = excitation_signal(model, excitation, duration)
    if progress:
        progress(f"running {what} on the simulated plant ({controller.upper()} tracking, "
                 f"{encoder_phrase(model, quantise)} encoders)")
    log = excite(model, signal, quantise=quantise, controller=controller)
    return dataclasses.replace(log, source=f"<simulated run of {what}>")


def model_of_excitation(excitation_file=None, duration=None, *, model=None, generated=None):
    """The model of a command that runs ``excitation_file`` (the one the file records, unless
    ``model`` is given, and then it must be that one: :func:`.model_ref.model_for`), or
    without a file ``model`` (default the paper's robot). ``duration`` (of the default
    multi-sine) cannot go with a file."""
    from pathlib import Path

    from .model_ref import model_for
    if excitation_file is None:
        return model_for({}, model=model, generated=generated)
    if duration is not None:
        raise ArgumentError("--duration is the length of the default multi-sine: not with "
                            "--excitation (the file sets its duration)")
    from .signals import ExcitationError
    return model_for(load_excitation(excitation_file).model, Path(excitation_file).parent,
                     str(excitation_file), model=model, generated=generated,
                     error=ExcitationError)


def run_excite(out, *, model=None, generated=None, excitation_file=None, duration=None,
               quantise=True, controller=None, progress=None):
    """``pm2dof identify excite --out LOG``: run an excitation on the simulated plant and
    write its log (CSV or Parquet by the suffix of ``out``), the model recorded relative to it.

    Without ``excitation_file`` the default :func:`~.signals.multisine` (``duration`` s, default
    :data:`DEFAULT_DURATION`) runs on ``model`` (default the paper's robot); with one, see
    :func:`model_of_excitation`. ``controller``: "apd" (default) or "na". Returns the log
    (:func:`format_excite`: what the command prints of it).
    """
    from .log import write_log
    model = model_of_excitation(excitation_file, duration, model=model, generated=generated)
    log = simulated_log(model, excitation_file, DEFAULT_DURATION if duration is None else duration,
                        quantise=quantise, controller=controller or "apd", progress=progress)
    write_log(out, log)
    return log


def format_excite(out, log, unit="N m"):
    """The line ``pm2dof identify excite`` prints of the simulated ``log`` written to ``out``;
    ``unit``: the efforts' (:func:`pm2dof.core.task.effort_unit`: N for linear actuators)."""
    return (f"wrote {out}: {len(log.t)} samples, {log.duration:.3f} s at T = "
            f"{log.period * 1e3:g} ms, {log.qa.shape[1]} legs; peak |tau| "
            f"{np.abs(log.tau).max():.3f} {unit} ({log.meta['saturated_samples']} saturated "
            f"samples), tracking RMSE {log.meta['tracking_rmse_m']} m, excitation up to "
            f"{log.meta.get('excitation_max_hz', '?')} Hz")
