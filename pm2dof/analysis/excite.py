# Excite the simulated plant and record what a real set-up would log: encoder angles and torques.
"""``pm2dof identify --excite``: an excitation run on the simulated robot, written as a log.

The plant runs with its truth (``[plant]`` of the model file, or ``truth``), its encoders
quantise the active angles, and a controller with the nominal model (Tables 1-2) tracks the
excitation. The log holds only what a real set-up records: the encoder angles the controller
read at t_k (quantised) and the torque it commanded at t_k, held until t_k+1. Nothing of the
truth is written into the log.
"""
import numpy as np

from ..core.errors import ArgumentError
from ..control.controllers import APDController, NAController
from ..control.simulate import plant_vector, simulate
from .ident_log import IdentLog

__all__ = ["excite", "measured_angles"]


def measured_angles(model, xe, quantise=True, truth=None):
    """The encoder readings (N, n), rad, of true positions ``xe`` (N, 2): the generated
    ``measure`` (quantised to ``[sensing].encoder_counts_per_rev`` unless ``quantise`` is
    false), exactly what the controller read."""
    plant = plant_vector(model, truth, quantise)
    measure = model.function("measure")
    qa = np.empty((len(xe), model.n_legs))
    for k, x in enumerate(np.ascontiguousarray(xe)):
        measure(x, plant, qa[k])
    return qa


def excite(model, trajectory, *, truth=None, quantise=True, controller="apd"):
    """Run ``trajectory`` on the simulated plant and return its log.

    Parameters
    ----------
    model : Model
    trajectory : object with t, xd, xd_dot, xd_ddot (N, 2) and period
        The excitation, e.g. :func:`pm2dof.analysis.identify.excitation` or
        :func:`pm2dof.analysis.excitation_design.trajectory_of`; the robot starts at rest at
        its first point. Its ``max_hz`` (highest frequency, Hz), if it has one, is written into
        the log's metadata (``excitation_max_hz``) for the filter design of ``--data``.
    truth : dict, optional
        Plant truth (default :func:`pm2dof.plant_truth`).
    quantise : bool
        Quantise the encoders (False: exact angles, a noise-free log).
    controller : {"apd", "na"}
        Tracking controller, with the nominal model (Tables 1-2); NA adapts as in the paper.

    Returns
    -------
    IdentLog
        t (N,), qa (N, n) as measured, tau (N, n) as applied; meta names the model, the sample
        period, the controller, the encoders and the excitation band.
    """
    if controller not in ("apd", "na"):
        raise ArgumentError(f"controller must be 'apd' or 'na', got {controller!r}")
    ctrl = (APDController if controller == "apd" else NAController)(model, on_singular="zero")
    r = simulate(model, ctrl, trajectory, truth=truth, quantise=quantise)
    if r.n_singular or r.n_non_finite:
        raise ArgumentError(f"the excitation run left the safe region ({r.n_singular} singular, "
                         f"{r.n_non_finite} non-finite samples): reduce its amplitude")
    counts = model.spec.sensing["encoder_counts_per_rev"]
    meta = {"model": model.name, "n_legs": model.n_legs, "sample_period": trajectory.period,
            "source": "simulated plant ([plant] of the model file)" if truth is None
            else "simulated plant (a given truth)",
            "controller": f"{controller} with Tables 1-2",
            "encoders": f"{int(counts)} counts/rev" if (quantise and counts > 0) else "exact",
            "saturated_samples": r.n_saturated,
            "tracking_rmse_m": f"{r.rmse:.4g}"}
    if getattr(trajectory, "max_hz", None):
        meta["excitation_max_hz"] = f"{trajectory.max_hz:.6g}"
    return IdentLog(t=r.t, qa=measured_angles(model, r.xe, quantise, truth), tau=r.tau_a,
                    meta=meta)


def run_excite(model, out, *, excitation_file=None, duration=4.0, quantise=True,
               controller="apd", echo=print, progress=None):
    """``pm2dof identify --excite --out LOG``: run an excitation on the simulated plant and
    write its log (CSV or Parquet by the suffix of ``out``). Without ``excitation_file`` the
    multi-sine of :func:`pm2dof.analysis.identify.excitation` (``duration`` s) runs."""
    from .excitation_design import excitation_trajectory
    from .ident_log import write_log
    traj, what = excitation_trajectory(model, excitation_file, duration)
    if progress:
        progress(f"running {what} on the simulated plant ({controller.upper()} tracking, "
                 f"{'17-bit' if quantise else 'exact'} encoders)")
    log = excite(model, traj, quantise=quantise, controller=controller)
    write_log(out, log)
    echo(f"wrote {out}: {len(log.t)} samples, {log.duration:.3f} s at T = {log.period * 1e3:g} ms, "
         f"{model.n_legs} legs; peak |tau| {np.abs(log.tau).max():.3f} N m "
         f"({log.meta['saturated_samples']} saturated samples), tracking RMSE "
         f"{log.meta['tracking_rmse_m']} m, excitation up to "
         f"{log.meta.get('excitation_max_hz', '?')} Hz")
    return log
