# What `pm2dof identify fit` does: read or simulate a log, identify, add Table 3, save.
"""The job of ``pm2dof identify fit [LOG]``: :func:`run_fit` reads the log (or runs an
excitation on the simulated plant first) and identifies theta from it; :func:`with_table3`
adds Table 3 run with the identified theta (numbers computed by the caller: the paper's
experiment is :mod:`pm2dof.analysis`, beside this layer); :func:`save_fit` writes the result
with its provenance. Each returns or takes a :class:`FitRun`; its text is
:func:`.report.format_fit`."""
import dataclasses
from dataclasses import dataclass

from ..core.errors import ArgumentError
from .fit import identify_log
from .log import LogError, log_folder, read_log
from .report import plant_comparison, summary

__all__ = ["run_fit", "FitRun", "with_table3", "save_fit"]


@dataclass(frozen=True)
class FitRun:
    """What ``pm2dof identify fit`` found (:func:`run_fit`; its text:
    :func:`.report.format_fit`).

    Attributes
    ----------
    model : Model
        The model identified: the one the log records, or ``--model``.
    log : IdentLog
        The log read, or simulated.
    result : Identification
        :func:`~pm2dof.identification.fit.identify_log`'s result.
    summary : dict
        The command's ``--json`` (:func:`.report.summary`; with ``table3`` and
        ``table3_comparison`` after :func:`with_table3`).
    seed_warning : str or None
        The warning of Table 3's comparison (:func:`.report.plant_comparison`), if any.
    """
    model: object
    log: object
    result: object
    summary: dict
    seed_warning: object = None


def run_fit(log=None, *, model=None, generated=None, excitation_file=None, duration=None,
            quantise=True, controller=None, cutoff_hz=None, min_joint_speed=None,
            time_tolerance=1e-3, progress=None):
    """``pm2dof identify fit [LOG]``: identify theta from a log; returns a :class:`FitRun`.

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
    cutoff_hz, min_joint_speed, time_tolerance :
        See :func:`~pm2dof.identification.fit.identify_log` and ``read_log``.
    progress : callable(str), optional
        Stage lines (None: silent).

    Returns
    -------
    FitRun
        The model resolved, the log, :func:`~pm2dof.identification.fit.identify_log`'s result
        and the summary.
    """
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
    return FitRun(model, log, res, summary(model, log, res))


def with_table3(run, table3):
    """``run`` with Table 3 run on the model file's ``[plant]`` by controllers with Tables 1-2
    and with the identified theta (``--seed-na``), and what that comparison can say
    (:func:`.report.plant_comparison`; its warning, if any, also among the summary's).

    Parameters
    ----------
    run : FitRun
    table3 : dict
        {speed: {"nominal": ..., "identified": ...}}:
        :func:`pm2dof.analysis.experiment.seeded_table3` of ``run.model`` and
        ``run.result.theta0``.

    Returns
    -------
    FitRun
    """
    s = {**run.summary, "table3": table3}
    s["table3_comparison"], warn = plant_comparison(run.model, run.log, run.result)
    if warn:
        s["warnings"] = [*s["warnings"], warn]
    return dataclasses.replace(run, summary=s, seed_warning=warn)


def save_fit(run, path, command_line=None):
    """Write ``run``'s summary (``param_names``, ``theta0``, ...; ``fit --save``) with its
    provenance (:func:`pm2dof.infra.results.provenance`; ``command_line``: the command it
    records, None: ``sys.argv``) as JSON to ``path``; returns the path written."""
    from ..infra.results import provenance, write_json
    return write_json(path, {**run.summary, "provenance": provenance(run.model, command_line)})
