# Identification logs: the measured encoder angles and torques of a run, read, written and checked.
"""The log format of ``pm2dof identify fit LOG`` (docs/log-format.md).

A log is a table with one row per control sample:

=============  ========  ===================================================================
column         unit      meaning
=============  ========  ===================================================================
``t``          s         sample time, increasing, on a regular grid (period T)
``qa1..qan``   rad, m    active joints: an angle (rad, absolute from +x) or, for a linear
                         actuator (PRR, RPR legs), a length (m), as in the model file
``tau1..taun`` N*m, N    effort commanded at t and held until the next sample (zero-order
                         hold): a torque, or a linear actuator's force
``qb1..qbn``   rad       optional: passive angles, if the robot measures them
=============  ========  ===================================================================

CSV (``.csv``: optional ``# key = value`` lines, then a header row, then numbers) or Parquet
(``.parquet``: the same columns, metadata in the schema as ``pm2dof.<key>``). Column order is
free. Metadata keys written by ``pm2dof identify excite``: the model (``model``: a shipped model's
name or the model file's path relative to the log's folder; ``model_name``,
``formulation_sha256``: :mod:`.model_ref`), ``n_legs``, ``sample_period`` and what produced
the log.

:func:`read_log` checks the format (columns, numbers, time); :func:`log_poses` checks the log
against a model (leg count, the recorded model, every row inside the workspace and clear of
both singularity thresholds, encoders consistent with the geometry). Both raise
:class:`LogError` naming the file, the row (1-based, data rows) and the column.
"""
import csv
import io
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..core.errors import ClosureError, InputFileError, WorkspaceError
from ..core.validate import Problems
from ..infra.results import write_atomic
from ..infra.tables import decode_text
from .model_ref import mismatch, rebase

__all__ = ["LogError", "IdentLog", "read_log", "write_log", "log_poses", "log_folder",
           "header_units", "MIN_ROWS"]

#: fewest rows a log may have (the zero-phase filter needs a few hundred samples to settle)
MIN_ROWS = 50
_FAMILY = re.compile(r"(qa|qb|tau)(\d+)$")


class LogError(InputFileError):
    """A log that cannot be used: names the file, the row (1-based data row) and the column.

    A log file's format problems are listed all at once (one per line, as model and study
    files list theirs: :class:`~pm2dof.core.errors.InputFileError`), up to a problem that makes
    the rest meaningless (no such file, a row that does not parse, missing columns)."""


@dataclass(frozen=True)
class IdentLog:
    """One identification log (arrays read-only).

    Attributes
    ----------
    t : ndarray (N,)
        Sample times, s.
    qa : ndarray (N, n)
        Measured active joints: rad, or m for a linear actuator.
    tau : ndarray (N, n)
        Effort applied over [t_k, t_k+1): N*m, or N for a linear actuator.
    qb : ndarray (N, n) or None
        Measured passive angles, rad, if the log has them.
    meta : dict
        Metadata (str -> str), e.g. ``model``, ``sample_period``, ``excitation_max_hz``.
    source : str
        File the log was read from (or ``"<memory>"``), for messages.
    ignored : tuple of str
        Columns of the file that are not part of the format (not used).
    """
    t: np.ndarray
    qa: np.ndarray
    tau: np.ndarray
    qb: np.ndarray = None
    meta: dict = field(default_factory=dict)
    source: str = "<memory>"
    ignored: tuple = ()

    def __post_init__(self):
        t = np.array(self.t, dtype=float)
        qa, tau = np.array(self.qa, dtype=float), np.array(self.tau, dtype=float)
        if t.ndim != 1 or qa.ndim != 2 or tau.shape != qa.shape or qa.shape[0] != len(t):
            raise LogError(f"{self.source}: need t (N,), qa and tau (N, n); got shapes {t.shape}, "
                           f"{qa.shape}, {tau.shape}")
        arrays = {"t": t, "qa": qa, "tau": tau}
        if self.qb is not None:
            qb = np.array(self.qb, dtype=float)
            if qb.shape != qa.shape:
                raise LogError(f"{self.source}: qb has shape {qb.shape}, qa {qa.shape}")
            arrays["qb"] = qb
        for k, v in arrays.items():
            v.setflags(write=False)
            object.__setattr__(self, k, v)
        object.__setattr__(self, "meta", {str(k): str(v) for k, v in dict(self.meta).items()})

    n_legs = property(lambda self: self.qa.shape[1], doc="number of legs (encoder columns)")
    period = property(lambda self: float(np.median(np.diff(self.t))), doc="sample period T, s")
    duration = property(lambda self: float(self.t[-1] - self.t[0]), doc="s")

    def columns(self):
        """Column name -> (N,) array, in the file's order (t, qa.., tau.., qb..)."""
        n, out = self.n_legs, {"t": self.t}
        for name, arr in (("qa", self.qa), ("tau", self.tau), ("qb", self.qb)):
            if arr is not None:
                out.update({f"{name}{i + 1}": arr[:, i] for i in range(n)})
        return out


def log_folder(log):
    """The folder of the file ``log`` was read from (where its relative ``model`` path starts),
    or None for a log that was not read from a file."""
    p = Path(log.source)
    return p.parent if p.is_file() else None


def _row(log_t, k):
    return f"row {k + 1} (t = {log_t[k]:.6g} s)"


def _from_columns(cols, meta, source, time_tolerance):
    """Build and check an IdentLog from name -> float array; every problem names the column,
    and every problem found is raised at once (one :class:`LogError`)."""
    pr = Problems(source, LogError)
    fam = {}
    for name in cols:
        m = _FAMILY.fullmatch(name)
        if m:
            fam.setdefault(m.group(1), []).append(int(m.group(2)))
    extra = sorted(c for c in cols if c != "t" and not _FAMILY.fullmatch(c))
    missing = [c for c in ("t",) if c not in cols]
    if "qa" not in fam:
        missing.append("qa1..qan")
    if "tau" not in fam:
        missing.append("tau1..taun")
    unknown = (f"; not recognised: {', '.join(extra)} (names are lower case, no separator: "
               f"qa1, tau1, qb1)" if extra else "")
    if missing:
        pr.stop(None, f"missing column(s) {', '.join(missing)} (have "
                      f"{', '.join(cols) or 'none'}; the format is t, qa1..qan, tau1..taun, "
                      f"optionally qb1..qbn){unknown}")
    n = max(fam["qa"])
    for name, idx in fam.items():
        want = set(range(1, n + 1))
        if set(idx) != want:
            gap = sorted(want - set(idx)) or sorted(set(idx) - want)
            pr.add(None, f"columns {name}1..{name}{n} expected (qa1..qa{n} give {n} legs), but "
                         f"{name}{gap[0]} is {'missing' if gap[0] <= n else 'extra'}{unknown}")
    pr.raise_if_any()
    ncol = {k: np.asarray(v, dtype=float) for k, v in cols.items()}
    N = len(ncol["t"])
    names = ["t"] + [f"{f}{i}" for f in ("qa", "tau", "qb") if f in fam for i in range(1, n + 1)]
    for c in names:
        bad = np.flatnonzero(~np.isfinite(ncol[c]))
        if bad.size:
            k = int(bad[0])
            pr.add(None, f"column {c} is not finite at row {k + 1} ({float(ncol[c][k])!r}; "
                         f"{bad.size} such row(s)): NaN rows cannot be used, cut the log or "
                         f"fill the gap before identifying")
    if N < MIN_ROWS:
        pr.add(None, f"too short: {N} rows, need at least {MIN_ROWS}")
    t = ncol["t"]
    if N >= 2 and np.isfinite(t).all():
        _check_time(pr, t, meta, time_tolerance)
    pr.raise_if_any()
    log = IdentLog(t=t, qa=np.column_stack([ncol[f"qa{i}"] for i in range(1, n + 1)]),
                   tau=np.column_stack([ncol[f"tau{i}"] for i in range(1, n + 1)]),
                   qb=(np.column_stack([ncol[f"qb{i}"] for i in range(1, n + 1)])
                       if "qb" in fam else None),
                   meta=meta, source=source, ignored=tuple(extra))
    return log


def _check_time(pr, t, meta, time_tolerance):
    """Record in ``pr`` a column t that is not increasing, not in s (against the log's
    ``sample_period``) or irregular beyond ``time_tolerance``."""
    dt = np.diff(t)
    bad = np.flatnonzero(dt <= 0)
    if bad.size:
        k = int(bad[0]) + 1
        return pr.add(None, f"column t is not increasing at {_row(t, k)}: the row before has "
                            f"t = {t[k - 1]:.6g} s ({bad.size} such row(s)); sort the log or "
                            f"remove repeated samples")
    T = float(np.median(dt))
    try:
        T_meta = float(meta.get("sample_period", "nan"))
    except ValueError:
        T_meta = math.nan
    if math.isfinite(T_meta) and T_meta > 0 and abs(T / T_meta - 1) > 0.01:
        pr.add(None, f"column t steps {T:.6g} s (median) but the log's sample_period is "
                     f"{T_meta:g} s: t must be in s (a log in ms steps 1000 times too far)")
    dev = np.abs(dt - T) / T
    bad = np.flatnonzero(dev > time_tolerance)
    if bad.size:
        k = int(bad[0]) + 1
        pr.add(None, f"column t is irregular at {_row(t, k)}: step {dt[k - 1]:.6g} s against "
                     f"the median period {T:.6g} s ({bad.size} irregular step(s), largest "
                     f"{dev.max():.3g} T; allowed {time_tolerance:g} T; --time-tolerance, or "
                     f"read_log(time_tolerance=...), allows more). The filter and the "
                     f"differences need a regular grid: resample the log, or cut it at the gap")


def _decode(path, raw):
    """The text of a CSV log (:func:`pm2dof.infra.tables.decode_text`, the reader of reference
    files too): UTF-8, a Latin-1 ``#`` comment line read as such, binary junk a LogError naming
    the line."""
    return decode_text(path, raw, LogError, "a log")


def _read_csv(path):
    pr = Problems(path, LogError)
    text = _decode(path, Path(path).read_bytes())
    meta, lines = {}, text.splitlines()
    k = 0
    while k < len(lines) and (lines[k].startswith("#") or not lines[k].strip()):
        m = re.match(r"#\s*([\w.]+)\s*=\s*(.*?)\s*$", lines[k])
        if m:
            meta[m.group(1)] = m.group(2)
        k += 1
    reader = csv.reader(io.StringIO("\n".join(lines[k:])))
    try:
        header = [h.strip() for h in next(reader)]
    except StopIteration:
        pr.stop(None, "no header row (expected t, qa1..qan, tau1..taun)")
    if len(set(header)) != len(header):
        dup = sorted({h for h in header if header.count(h) > 1})
        pr.stop(None, f"column(s) {', '.join(dup)} appear more than once")
    cols = {h: [] for h in header}
    for r, row in enumerate(reader):
        if not row or all(not c.strip() for c in row):
            continue
        if len(row) != len(header):
            pr.stop(None, f"row {r + 1} (line {k + r + 2}) has {len(row)} fields, the header "
                          f"{len(header)}")
        for h, c in zip(header, row):
            try:
                cols[h].append(float(c))
            except ValueError:
                pr.stop(None, f"row {r + 1} (line {k + r + 2}), column {h}: {c!r} is not a "
                              f"number")
    return cols, meta


def _read_parquet(path):
    import pyarrow.parquet as pq
    pr = Problems(path, LogError)
    try:
        table = pq.read_table(path)
    except Exception as exc:  # pyarrow raises its own types for corrupt files
        pr.stop(None, f"not a readable Parquet file ({exc})")
    meta = {k.decode()[len("pm2dof."):]: v.decode()
            for k, v in (table.schema.metadata or {}).items() if k.startswith(b"pm2dof.")}
    cols = {}
    for name in table.column_names:
        try:
            cols[name] = np.asarray(table.column(name).to_numpy(zero_copy_only=False),
                                    dtype=float)
        except (TypeError, ValueError) as exc:
            pr.add(None, f"column {name} is not numeric ({exc})")
    pr.raise_if_any()
    return cols, meta


def read_log(path, *, time_tolerance=1e-3):
    """Read a log file (``.csv`` or ``.parquet``) and check its format.

    Parameters
    ----------
    path : str or Path
    time_tolerance : float
        Largest allowed |t_k+1 - t_k - T| / T, T the median period (default 1e-3: timestamps
        written with a few digits pass, a dropped sample does not).

    Returns
    -------
    IdentLog

    Raises
    ------
    LogError
        Missing or duplicate columns, a qa/tau/qb family that is not 1..n, a non-number or a
        non-finite value (names the row and column), time not increasing or irregular (names the
        row), fewer than :data:`MIN_ROWS` rows.
    """
    path = Path(path)
    if not path.is_file():
        Problems(path, LogError).stop(None, "no such log file")
    suffix = path.suffix.lower()
    if suffix == ".csv":
        cols, meta = _read_csv(path)
    elif suffix in (".parquet", ".pq"):
        cols, meta = _read_parquet(path)
    else:
        Problems(path, LogError).stop(None, f"unknown log format {suffix!r} (use .csv or "
                                            f".parquet)")
    return _from_columns(cols, meta, str(path), time_tolerance)


def header_units(meta):
    """The units of a log's columns, for its first comment line: by each leg's actuator when the
    metadata ``actuators`` lists them ("revolute" or "prismatic", comma-separated, as
    ``identify excite`` writes it), else by kind in words.

    Parameters
    ----------
    meta : dict
        The log's metadata (str -> str).

    >>> header_units({"actuators": "prismatic, prismatic"})
    't s, qa m, tau N (held until the next row), qb rad'
    >>> header_units({"actuators": "revolute, prismatic"})
    't s, qa1 rad, qa2 m, tau1 N*m, tau2 N (held until the next row), qb rad'
    """
    kinds = [k.strip() for k in str(meta.get("actuators", "")).split(",") if k.strip()]
    if not kinds or not set(kinds) <= {"revolute", "prismatic"}:
        qa, tau = "qa rad (m: linear actuator)", "tau N*m (N: linear actuator)"
    elif len(set(kinds)) == 1:
        lin = kinds[0] == "prismatic"
        qa, tau = f"qa {'m' if lin else 'rad'}", f"tau {'N' if lin else 'N*m'}"
    else:
        qa = ", ".join(f"qa{i + 1} {'m' if k == 'prismatic' else 'rad'}"
                       for i, k in enumerate(kinds))
        tau = ", ".join(f"tau{i + 1} {'N' if k == 'prismatic' else 'N*m'}"
                        for i, k in enumerate(kinds))
    return f"t s, {qa}, {tau} (held until the next row), qb rad"


def write_log(path, log):
    """Write ``log`` (an :class:`IdentLog`) as CSV or Parquet (by the suffix), atomically.

    Numbers are written as the shortest decimal that reads back as the same float64 (Python's
    repr), so reading the file gives the same values bit for bit. A model file recorded in the
    metadata (``model``) is written relative to the new file's folder (:mod:`.model_ref`).

    Parameters
    ----------
    path : str or pathlib.Path
        The file to write: ``.csv`` or ``.parquet``.
    log : IdentLog
        The samples and their metadata.
    """
    path = Path(path)
    cols = log.columns()
    meta = dict(log.meta)
    if "model" in meta:
        meta["model"] = rebase(meta["model"], log_folder(log), path.parent)
    suffix = path.suffix.lower()
    if suffix == ".csv":
        buf = io.StringIO()
        buf.write(f"# pm2dof identification log: {header_units(meta)}\n")
        for k, v in meta.items():
            buf.write(f"# {k} = {v}\n")
        buf.write(",".join(cols) + "\n")
        data = np.column_stack(list(cols.values()))
        for row in data:
            buf.write(",".join(repr(float(x)) for x in row) + "\n")   # shortest exact
        write_atomic(path, buf.getvalue().encode())
    elif suffix in (".parquet", ".pq"):
        import pyarrow as pa
        import pyarrow.parquet as pq
        table = pa.table({k: pa.array(np.asarray(v)) for k, v in cols.items()},
                         metadata={f"pm2dof.{k}".encode(): str(v).encode()
                                   for k, v in meta.items()})
        sink = pa.BufferOutputStream()
        pq.write_table(table, sink)
        write_atomic(path, sink.getvalue().to_pybytes())
    else:
        raise LogError(f"{path}: unknown log format {suffix!r} (use .csv or .parquet)")
    return path


def log_poses(model, log, *, encoder_tolerance=2e-3):
    """Check ``log`` against ``model`` and return its poses.

    Every row's active angles must assemble (fk), in the model's assembly mode (ik), clear of
    both singularity thresholds; with more encoders than degrees of freedom, each encoder must
    agree with the angle the pose implies (``encoder_tolerance`` rad: quantisation is far
    below it; an encoder offset, a sign flip or another robot's log is not), and so must the
    passive angles if the log has them.

    Returns
    -------
    xe : ndarray (N, m)
        fk of each row's measured active angles, m (phi in rad; m = ``model.dof``).
    q : ndarray (N, 2n)
        ik of xe: [qa, qb] consistent with the geometry, rad.

    Raises
    ------
    LogError
        Another leg count, another recorded model (by name or formulation hash:
        :func:`.model_ref.mismatch`), a row outside the workspace or too close to a
        singularity, an encoder inconsistent with the others (names the row and column).
    """
    src, n = log.source, model.n_legs
    if log.n_legs != n:
        raise LogError(f"{src}: the log has {log.n_legs} legs (qa1..qa{log.n_legs}), model "
                       f"{model.name!r} has {n}: a log of another robot")
    msg = mismatch(model, log.meta, log_folder(log), src)
    if msg:
        raise LogError(msg)
    N = len(log.t)
    xe, q = np.empty((N, model.dof)), np.empty((N, 2 * n))
    sing = np.empty(2)
    for k in range(N):
        where = f"{src}: {_row(log.t, k)}"
        try:
            model.fk(log.qa[k], out=xe[k])
            model.ik(xe[k], out=q[k])
        except ClosureError as exc:
            raise LogError(f"{where}: the encoders qa1..qa{n} do not close the loops of "
                           f"{model.name!r} ({exc}). An encoder offset or sign (with more "
                           f"encoders than degrees of freedom one bad encoder shows on all of "
                           f"them), another robot's log, or angles not in rad (angles must be "
                           f"in rad, absolute from +x, as in the model file)") from None
        except WorkspaceError as exc:
            raise LogError(f"{where}: active angles qa = {log.qa[k].tolist()} rad give no pose "
                           f"of {model.name!r} in its working modes ({exc}); angles must be in "
                           f"rad, absolute from +x, as in the model file") from None
        model.singularity_measures(q[k], out=sing)
        if not (sing[0] >= model.singularity_threshold
                and sing[1] >= model.parallel_singularity_threshold):
            raise LogError(f"{where}: {model.singularity_message(sing)} at xe = "
                           f"{xe[k].tolist()} m")
    checks = [("qa", log.qa, q[:, :n])] + ([("qb", log.qb, q[:, n:])] if log.qb is not None else [])
    for fam, measured, implied in checks:
        d = np.abs(np.angle(np.exp(1j * (measured - implied))))   # wrapped to [0, pi]
        if d.max() > encoder_tolerance:
            k, i = np.unravel_index(int(np.argmax(d)), d.shape)
            what = (f"the encoders qa1..qa{n} do not close the loops of {model.name!r}: "
                    f"column qa{i + 1} is" if fam == "qa" else
                    f"column qb{i + 1} disagrees with the geometry of {model.name!r}: it is")
            raise LogError(f"{src}: {what} {d[k, i]:.3g} rad from the angle the pose fk(qa) "
                           f"implies at {_row(log.t, k)} (allowed {encoder_tolerance:g} rad). "
                           f"An encoder offset or sign (with more encoders than degrees of "
                           f"freedom one bad encoder shows on all of them), another assembly "
                           f"mode, or another robot's log")
    return xe, q
