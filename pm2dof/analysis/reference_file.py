# A desired trajectory sampled elsewhere: read from a CSV or Parquet file (docs/reference-format.md).
"""``read_trajectory(path)``: a reference trajectory file as a :class:`pm2dof.Trajectory`.

Columns (docs/reference-format.md): ``t`` (s, a regular grid), the task coordinates ``x``,
``y`` (m) and, for a platform, ``phi`` (rad); optionally their rates ``<c>_dot`` and
accelerations ``<c>_ddot``. Three documented subsets:

* positions only: the rates and accelerations are differentiated
  (:func:`numpy.gradient`, second-order central differences inside, second-order one-sided at
  the ends);
* positions and rates: the accelerations are differentiated from the rates;
* positions, rates and accelerations: used as they are.

A rate or acceleration column present for one coordinate must be present for every one.
Any other column is refused (a misspelt ``x_dd`` would otherwise be silently differentiated).
"""
import numpy as np

from ..control.controllers import APDController, NAController
from ..control.simulate import check_trajectory, moving_start, simulate
from ..control.trajectory import Trajectory, TrajectoryError
from ..core.errors import InputFileError, SingularityError, WorkspaceError
from ..core.model import require_model
from ..core.task import effort_unit
from ..infra.tables import read_columns
from .experiment import _extra_controller, phi_rmse

__all__ = ["read_trajectory", "ReferenceFileError", "TASK_COLUMNS", "PERIOD_TOLERANCE",
           "simulate_reference", "reference_summary", "format_reference_summary", "LAWS"]

#: the controllers ``pm2dof simulate`` runs: the paper's two, computed torque, LQR
LAWS = ("na", "apd", "ctc", "lqr")

#: the task coordinates a reference may have: (x, y) for a point, (x, y, phi) for a platform
TASK_COLUMNS = ("x", "y", "phi")
#: largest relative deviation of a time step from the first one
PERIOD_TOLERANCE = 1e-6


class ReferenceFileError(TrajectoryError, InputFileError):
    """A reference trajectory file that cannot be read: one line naming the file and, where it
    applies, the row (1-based, data rows) and the column. A TrajectoryError (the reference it
    would have been) and an InputFileError (a user's file, as model, study, path, log and
    excitation files): its first problem stops the reading, since each one (a missing column,
    a bad cell, an irregular grid) leaves nothing further to check."""


def _derivative(values, T):
    """d/dt of samples at period T (second order everywhere; two samples: their slope)."""
    if len(values) < 3:
        return np.gradient(values, T, axis=0, edge_order=1)
    return np.gradient(values, T, axis=0, edge_order=2)


def _task(path, cols):
    names = ["x", "y"] + (["phi"] if "phi" in cols else [])
    missing = [c for c in ("t", "x", "y") if c not in cols]
    if missing:
        raise ReferenceFileError(f"{path}: no column {', '.join(missing)} (a reference has t, "
                                 f"x, y [, phi] and optionally <c>_dot, <c>_ddot)")
    known = {"t", *names, *(f"{c}_dot" for c in names), *(f"{c}_ddot" for c in names)}
    unknown = [c for c in cols if c not in known]
    if unknown:
        raise ReferenceFileError(f"{path}: unknown column(s) {', '.join(unknown)}; a reference "
                                 f"has t, {', '.join(names)} and optionally their _dot, _ddot "
                                 f"(docs/reference-format.md)")
    return names


def _grid(path, t):
    """The period of the regular time grid ``t``, s: (t_last - t_first) / (N - 1), once every
    step is the first one within :data:`PERIOD_TOLERANCE`."""
    if len(t) < 2:
        raise ReferenceFileError(f"{path}: one row: a reference needs two or more samples "
                                 f"(the period is their time step)")
    steps = np.diff(t)
    T0 = steps[0]
    if T0 <= 0 or not np.isfinite(T0):
        raise ReferenceFileError(
            f"{path}: row 2, column t: t must increase from row to row by one period, but it "
            f"goes from {t[0]:.9g} s in row 1 to {t[1]:.9g} s in row 2")
    bad = np.flatnonzero(~(np.abs(steps - T0) <= PERIOD_TOLERANCE * T0))
    if len(bad):
        k = int(bad[0])
        raise ReferenceFileError(
            f"{path}: row {k + 2}, column t: t must increase by one period every row (the "
            f"first step is {T0:.9g} s), but it increases by {steps[k]:.9g} s from row {k + 1}")
    return float((t[-1] - t[0]) / (len(t) - 1))


def read_trajectory(path):
    """Read a reference trajectory from a CSV or Parquet file.

    Parameters
    ----------
    path : str or pathlib.Path
        A ``.csv`` or ``.parquet`` file with columns ``t`` (s, a regular grid; it may start
        at any time), ``x``, ``y`` (m), ``phi`` (rad, a platform only) and optionally their
        rates ``x_dot``, ... (m/s, rad/s) and accelerations ``x_ddot``, ... (m/s^2, rad/s^2);
        missing rates and accelerations are differentiated (docs/reference-format.md).

    Returns
    -------
    Trajectory
        :meth:`pm2dof.Trajectory.from_samples` of the samples (t re-based to 0), its period
        the file's time step; m = 2 columns (x, y) or 3 (x, y, phi). Simulate it on a model
        with that task dimension (:func:`pm2dof.simulate` checks it and every sample's pose).

    Raises
    ------
    ReferenceFileError
        (a :class:`pm2dof.TrajectoryError` and a :class:`pm2dof.InputFileError`) One line naming the file and, where it applies,
        the row and the column: not CSV or Parquet, a missing or unknown column, a rate or
        acceleration column missing for some coordinate, a cell that is not a finite number,
        ragged rows, t not on a regular grid.

    Examples
    --------
    >>> import pathlib, tempfile, pm2dof
    >>> f = pathlib.Path(tempfile.mkdtemp()) / "ref.csv"
    >>> _ = f.write_text("t,x,y\\n0,0.25,0.26\\n0.002,0.25,0.26\\n0.004,0.25,0.26\\n")
    >>> traj = pm2dof.read_trajectory(f)
    >>> traj.xd.shape, traj.period
    ((3, 2), 0.002)
    """
    _, cols = read_columns(path, ReferenceFileError, "a reference")
    names = _task(path, cols)
    T = _grid(path, cols["t"])
    levels = [np.stack([cols[c] for c in names], axis=1)]
    for suffix in ("_dot", "_ddot"):
        have = [f"{c}{suffix}" for c in names if f"{c}{suffix}" in cols]
        if have and len(have) < len(names):
            lack = [f"{c}{suffix}" for c in names if f"{c}{suffix}" not in cols]
            raise ReferenceFileError(f"{path}: column(s) {', '.join(have)} without "
                                     f"{', '.join(lack)}: give every coordinate's {suffix} "
                                     f"column or none (then it is differentiated)")
        levels.append(np.stack([cols[f"{c}{suffix}"] for c in names], axis=1) if have
                      else _derivative(levels[-1], T))
    return Trajectory.from_samples(*levels, T)


def simulate_reference(model, path, laws=("na", "apd"), *, split=None, settle_time=0.0,
                       quantise=True):
    """Each controller of ``laws`` along the reference file ``path``: {law: SimResult}.

    Parameters
    ----------
    model : Model
        The robot; the file's task coordinates must be its ``task_names`` and its time step
        its ``[sensing] sample_period``.
    path : str or pathlib.Path
        The reference (:func:`read_trajectory`).
    laws : sequence of str
        Of :data:`LAWS`: "na", "apd" (gains of the model file), "ctc", "lqr" (the LQR is
        planned along the reference; python-control and SciPy, the control extra).
    split : {"min_norm", "min_max", "preload"}, optional
        The torque split of every controller (default ``[control] split``).
    settle_time : float
        Seconds of rest at the last sample after the reference (not in the RMSE).
    quantise : bool
        Quantise the encoders (``[sensing] encoder_counts_per_rev``).

    Raises
    ------
    ReferenceFileError
        The file cannot be read, its task coordinates or time step are not the model's, or it
        does not start at rest (:func:`pm2dof.control.simulate.moving_start`: the simulated
        robot does).
    """
    require_model(model)
    unknown = [x for x in laws if x not in LAWS]
    if unknown or not laws:
        raise ReferenceFileError(f"laws must be some of {list(LAWS)}, got {list(laws)}")
    traj = read_trajectory(path)
    m, T = traj.xd.shape[1], model.spec.sensing["sample_period"]
    if m != model.dof:
        raise ReferenceFileError(
            f"{path}: a reference in ({', '.join(TASK_COLUMNS[:m])}), model {model.name!r} has "
            f"task dimension m = {model.dof} ({', '.join(model.task_names)})")
    if abs(traj.period - T) > 1e-9 * T:
        raise ReferenceFileError(
            f"{path}: time step {traj.period:.9g} s, but model {model.name!r}'s controllers run "
            f"at [sensing] sample_period = {T:g} s: resample the reference to that period")
    try:                    # reach and singularities, before any controller: the file named
        check_trajectory(model, traj)
    except (TrajectoryError, WorkspaceError, SingularityError) as exc:
        raise type(exc)(f"{path}: {exc}") from None
    moving = moving_start(traj, model.task_names)
    if moving is not None:  # the robot starts at rest: a file must too (docs/reference-format.md)
        raise ReferenceFileError(f"{path}: {moving}; start the reference at rest (or simulate "
                                 f"it with pm2dof.simulate, which warns)")
    kw = {} if split is None else {"split": split}
    out = {}
    for law in laws:
        ctrl = ({"na": NAController, "apd": APDController}[law](model, **kw) if law in
                ("na", "apd") else _extra_controller(model, law, traj, kw))
        out[law] = simulate(model, ctrl, traj, settle_time=settle_time, quantise=quantise)
    return out


def reference_summary(results, model=None):
    """The numbers of :func:`simulate_reference`, {law: {...}}: ``rmse`` (eq. 41, position, m),
    ``max_error`` (largest position error, m), for a platform ``phi_rmse`` and
    ``max_phi_error`` (rad), ``peak_tau`` (N m, N for a linear actuator) and the status counts,
    ``samples``, ``outcome`` (SimResult's, with its message), and ``units`` naming the unit of
    each. The former keys ``rmse_m``, ``max_error_m``, ``max_phi_error_rad`` are kept beside
    them. ``model`` (the simulated one) gives ``peak_tau``'s unit by the actuators' kind."""
    effort = ("N m (revolute actuators), N (linear actuators)" if model is None
              else effort_unit(model))
    out = {}
    for law, r in results.items():
        e = r.e[:r.n_move]
        err = float(np.max(np.hypot(e[:, 0], e[:, 1])))
        row = {"rmse_m": r.rmse, "max_error_m": err,
               "peak_tau": r.peak_tau, "n_saturated": r.n_saturated,
               "n_singular": r.n_singular, "samples": r.n_move, "outcome": r.outcome,
               "outcome_message": r.outcome_message, "rmse": r.rmse, "max_error": err}
        units = {"rmse": "m", "max_error": "m", "rmse_m": "m", "max_error_m": "m",
                 "peak_tau": effort, "n_saturated": "1", "n_singular": "1", "samples": "1"}
        if e.shape[1] == 3:
            row["max_phi_error_rad"] = row["max_phi_error"] = float(np.max(np.abs(e[:, 2])))
            row["phi_rmse"] = phi_rmse(r)
            units.update(max_phi_error_rad="rad", max_phi_error="rad", phi_rmse="rad")
        row["units"] = units
        out[law] = row
    return out


def format_reference_summary(summary):
    """:func:`reference_summary` as the table ``pm2dof simulate`` prints."""
    phi = all("phi_rmse" in r for r in summary.values()) and bool(summary)
    lines = [f"{'law':5s} {'RMSE m':>11s} {'max err m':>11s} "
             + (f"{'phi RMSE rad':>12s} " if phi else "")
             + f"{'peak tau':>9s} {'saturated':>9s}  outcome"]
    for law, r in summary.items():
        lines.append(f"{law:5s} {r['rmse']:11.4e} {r['max_error']:11.4e} "
                     + (f"{r['phi_rmse']:12.4e} " if phi else "")
                     + f"{r['peak_tau']:9.4g} {r['n_saturated']:9d}  {r['outcome_message']}")
    units = {r["units"]["peak_tau"] for r in summary.values()}
    if units:
        lines.append(f"RMSE: eq. 41 (the position); peak tau: the largest |tau_i|, "
                     f"{', '.join(sorted(units))}.")
    return "\n".join(lines)
