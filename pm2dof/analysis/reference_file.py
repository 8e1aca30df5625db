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

from ..control.trajectory import Trajectory, TrajectoryError
from ..infra.tables import read_columns

__all__ = ["read_trajectory", "ReferenceFileError", "TASK_COLUMNS", "PERIOD_TOLERANCE"]

#: the task coordinates a reference may have: (x, y) for a point, (x, y, phi) for a platform
TASK_COLUMNS = ("x", "y", "phi")
#: largest relative deviation of a time step from the file's period (t[-1] - t[0]) / (N - 1)
PERIOD_TOLERANCE = 1e-6


class ReferenceFileError(TrajectoryError):
    """A reference trajectory file that cannot be read: one line naming the file and, where it
    applies, the row (1-based, data rows) and the column."""


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
    """The period of the regular time grid ``t``, s."""
    if len(t) < 2:
        raise ReferenceFileError(f"{path}: one row: a reference needs two or more samples "
                                 f"(the period is their time step)")
    T = (t[-1] - t[0]) / (len(t) - 1)
    steps = np.diff(t)
    bad = np.flatnonzero(~(np.abs(steps - T) <= PERIOD_TOLERANCE * T)) if T > 0 else [0]
    if len(bad):
        k = int(bad[0])
        raise ReferenceFileError(
            f"{path}: row {k + 2}, column t: t must increase by one period every row (period "
            f"(t_last - t_first) / (N - 1) = {T:.9g} s), but t[{k + 2}] - t[{k + 1}] = "
            f"{steps[k]:.9g} s")
    return float(T)


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
        (a :class:`pm2dof.TrajectoryError`) One line naming the file and, where it applies,
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
    _, cols = read_columns(path, ReferenceFileError)
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
