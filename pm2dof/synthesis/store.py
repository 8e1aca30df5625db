# A design run's output folder: design.json, and one Parquet file per evaluated chunk of designs.
"""The output folder of ``pm2dof design run``.

``DIR/batches/g<generation>-c<chunk>-<hash>.parquet`` holds the designs of one chunk of one
generation's batch, with their objectives and constraints; ``<hash>`` is the SHA-256 of the
chunk's designs (float64 bytes, :func:`chunk_hash`). Each file is written to a temporary name
and renamed, so it exists only complete; its schema metadata carries the run's identity. A
rerun of the same study (same :func:`identity`) with the same ``--out`` asks the optimiser for
the same designs (same seed), finds each chunk by its generation, index and hash, and reads it
instead of evaluating it again. ``DIR/design.json`` holds the study, its identity, the
objectives and constraints, the provenance and, once the optimiser has finished, the count.

Columns of every file: ``generation``, ``position`` (the design's place in its generation's
batch), one per design variable (its value), one per objective (its value in its own sense:
a maximised objective is not negated), ``g.<constraint>`` (pymoo's constraint value, feasible
when <= 0), ``feasible``, and what the evaluation reports besides (the constraints' measured
values by their names, ``status``), and ``file_design`` (true on the model file's own design,
which the optimiser did not ask for).
"""
import dataclasses
import hashlib
import json
import os
from pathlib import Path

import numpy as np

from ..core.errors import Pm2dofError
from ..infra.results import provenance, write_atomic, write_json

__all__ = ["DesignOutError", "identity", "prepare_out", "chunk_hash", "chunk_path",
           "find_chunk", "write_chunk", "read_chunk", "finish_out", "read_designs",
           "objective_senses", "units", "FILE_DESIGN_GENERATION", "file_design_path"]

#: the ``generation`` of the model file's own design (not one of the optimiser's)
FILE_DESIGN_GENERATION = -1
_FILES = ("g*.parquet", "file-design-*.parquet")


class DesignOutError(Pm2dofError, ValueError):
    """The output folder cannot be used: not writable, holds another run, or no run at all."""


def _plain(x):
    """JSON-ready copy of a study field (mappings, tuples, dataclasses, NumPy scalars)."""
    if dataclasses.is_dataclass(x) and not isinstance(x, type):
        return {f.name: _plain(getattr(x, f.name)) for f in dataclasses.fields(x)}
    if hasattr(x, "items"):
        return {str(k): _plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_plain(v) for v in x]
    if isinstance(x, np.generic):
        return x.item()
    return x


def objective_senses(study):
    """[{"name", "sense"}] of the study's objectives, in order."""
    return [{"name": o.name, "sense": o.sense} for o in study.objectives]


def units(study, model):
    """{objective or constraint name: unit} (:func:`.objectives.units`; {} without a model)."""
    if model is None:
        return {}
    from .objectives import units as of
    return of(study, model)


def _inputs(study, model_sha256=None):
    """What determines a run's designs and values: the study's search and measures, and the
    model file's contents."""
    return _plain({"variables": study.variables, "bounds": study.bounds,
                   "region": study.region, "paths": study.paths,
                   "objectives": study.objectives, "constraints": study.constraints,
                   "optimizer": study.optimizer, "model_path": study.model_path,
                   "model_file_sha256": model_sha256})


def identity(study, model_sha256=None):
    """The SHA-256 of the study's :func:`_inputs` (JSON, sorted keys): equal identities ask for
    the same designs and get the same values."""
    text = json.dumps(_inputs(study, model_sha256), sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()


def chunk_hash(X):
    """The SHA-256 (hex) of a chunk's designs ``X`` (n, k), as C-ordered float64 bytes."""
    return hashlib.sha256(np.ascontiguousarray(X, dtype=np.float64).tobytes()).hexdigest()


def chunk_path(out, generation, chunk, digest):
    """The file of chunk ``chunk`` of generation ``generation`` whose designs hash to
    ``digest``."""
    return Path(out) / "batches" / f"g{generation:05d}-c{chunk:05d}-{digest[:16]}.parquet"


def file_design_path(out, digest):
    """The file of the model file's own design, whose values hash to ``digest``."""
    return Path(out) / "batches" / f"file-design-{digest[:16]}.parquet"


def _stored(batches):
    """Every evaluated file of a run's ``batches`` folder (the chunks, the file's design)."""
    return sorted(p for pattern in _FILES for p in Path(batches).glob(pattern))


def prepare_out(out, study, ident, model=None, command_line=None):
    """Create or reopen ``out`` for the run ``ident`` (:func:`identity`) of ``study``; records
    ``out/design.json`` (``model``: the Model whose provenance it records, or None).

    Raises DesignOutError when ``out`` is not writable, or holds batches of another run.
    Leftover temporary files of an interrupted run are removed.
    """
    import pyarrow.parquet as pq
    out = Path(out)
    batches = out / "batches"
    try:
        batches.mkdir(parents=True, exist_ok=True)
        probe = batches / f".write-test-{os.getpid()}"
        probe.write_bytes(b"")
        probe.unlink()
    except OSError as exc:
        raise DesignOutError(f"--out {out}: cannot write there ({exc.strerror or exc})") \
            from None
    have = _stored(batches)
    meta = out / "design.json"
    if have:
        old = _read_json(meta) if meta.exists() else {}
        if old.get("identity") != ident:
            raise DesignOutError(
                f"--out {out} holds {len(have)} evaluated chunk(s) of another design run "
                f"({old.get('name')!r}, from {old.get('study_file')}): other variables, "
                f"bounds, objectives, optimiser (or --quick, --optimizer, --grid) or model "
                f"file. Use an empty --out, or delete {out} to start over")
    for tmp in (*batches.glob(".g*"), *batches.glob(".file-design*")):   # interrupted writes
        tmp.unlink(missing_ok=True)
    for p in have:
        md = pq.read_schema(p).metadata or {}
        if md.get(b"pm2dof_design") != ident.encode():
            raise DesignOutError(f"{p} belongs to another design run; use an empty --out")
    write_json(meta, {"name": study.name, "identity": ident, "study_file": study.path,
                      "study_text": _text(study.path), "inputs": _inputs(study),
                      "variables": list(study.variables),
                      "bounds": [list(map(float, b)) for b in study.bounds],
                      "objectives": objective_senses(study), "units": units(study, model),
                      "constraints": [{"name": c.name, "op": c.op, "limit": c.limit}
                                      for c in study.constraints],
                      "optimizer": _plain(study.optimizer), "model_file": study.model_path,
                      "complete": False, "designs": None,
                      "provenance": provenance(model, command_line) if model else None})
    return {p.name for p in have}


def _text(path):
    try:
        return Path(path).read_text()
    except OSError:
        return None


def _read_json(meta):
    try:
        return json.loads(Path(meta).read_text())
    except (OSError, ValueError) as exc:
        raise DesignOutError(f"{meta}: unreadable ({exc}); use another --out") from None


def find_chunk(have, out, generation, chunk, digest):
    """The path of an evaluated chunk (``have``: the file names :func:`prepare_out` found and
    this run wrote), or None."""
    p = chunk_path(out, generation, chunk, digest)
    return p if p.name in have else None


def write_chunk(out, generation, chunk, X, F, G, rows, study, ident, start=0,
                file_design=False):
    """Write one evaluated chunk atomically; returns its path.

    Parameters
    ----------
    out : path
        The run's folder.
    generation, chunk : int
        Its generation and its index in that generation's batch.
    X : ndarray, (n, k)
        The designs.
    F : ndarray, (n, n_obj)
        Objectives, minimised (as the optimiser sees them).
    G : ndarray, (n, n_con)
        Constraints, feasible when <= 0.
    rows : list of dict
        What the evaluation reported per design (extra columns).
    study : DesignStudy
        The study (variables, objectives, constraints).
    ident : str
        The run's identity.
    start : int
        The first design's position in its generation.
    file_design : bool
        The chunk is the model file's own design (one row): written to
        :func:`file_design_path`, ``generation`` and ``chunk`` ignored.
    """
    import pyarrow as pa
    import pyarrow.parquet as pq
    n = len(X)
    if file_design:
        generation = FILE_DESIGN_GENERATION
    cols = {"generation": np.full(n, generation, dtype=np.int64),
            "position": np.arange(start, start + n, dtype=np.int64)}
    for j, name in enumerate(study.variables):
        cols[name] = np.asarray(X[:, j], dtype=float)
    for j, o in enumerate(study.objectives):
        cols[o.name] = (-1.0 if o.sense == "max" else 1.0) * np.asarray(F[:, j], dtype=float)
    for j, c in enumerate(study.constraints):
        cols[f"g.{c.name}"] = np.asarray(G[:, j], dtype=float)
    cols["feasible"] = np.all(np.asarray(G).reshape(n, -1) <= 0.0, axis=1)
    cols["file_design"] = np.full(n, bool(file_design))
    extra = [k for r in rows[:1] for k in r if k not in cols]
    for k in extra:
        vals = [r.get(k) for r in rows]
        if all(isinstance(v, str) for v in vals):
            cols[k] = pa.array(vals, pa.string())
        else:
            cols[k] = np.array([np.nan if v is None else v for v in vals], dtype=float)
    table = pa.table(cols).replace_schema_metadata(
        {"pm2dof_design": ident, "pm2dof_design_name": study.name})
    sink = pa.BufferOutputStream()
    pq.write_table(table, sink, compression="zstd")
    digest = chunk_hash(X)
    if file_design:
        return write_atomic(file_design_path(out, digest), sink.getvalue().to_pybytes())
    path = chunk_path(out, generation, chunk, digest)
    for stale in path.parent.glob(f"g{generation:05d}-c{chunk:05d}-*.parquet"):
        if stale.name != path.name:            # another run's designs at this place: replaced
            stale.unlink(missing_ok=True)
    return write_atomic(path, sink.getvalue().to_pybytes())


def read_chunk(path, study):
    """(F minimised, G, rows) of a chunk file, as :func:`write_chunk` stored them."""
    import pyarrow.parquet as pq
    t = pq.read_table(path)
    n = t.num_rows
    F = np.column_stack([(-1.0 if o.sense == "max" else 1.0)
                         * t.column(o.name).to_numpy() for o in study.objectives]) \
        if study.objectives else np.zeros((n, 0))
    G = np.column_stack([t.column(f"g.{c.name}").to_numpy() for c in study.constraints]) \
        if study.constraints else np.zeros((n, 0))
    return F.reshape(n, -1), G.reshape(n, -1), t.to_pylist()


def finish_out(out, designs):
    """Record in design.json that the optimiser finished, with ``designs`` evaluated."""
    meta = Path(out) / "design.json"
    info = _read_json(meta)
    info.update(complete=True, designs=int(designs))
    write_json(meta, info)


def read_designs(out):
    """(design.json dict, {column: ndarray}) of every design a run evaluated, ordered by
    generation and position: the model file's own design first (generation -1, column
    ``file_design`` true; absent from a run of an earlier pm2dof), then the optimiser's.

    Raises
    ------
    DesignOutError
        ``out`` is not the folder of a design run, or holds no designs yet.
    """
    import pyarrow as pa
    import pyarrow.parquet as pq
    out = Path(out)
    meta = out / "design.json"
    if not meta.exists():
        raise DesignOutError(f"{out}: no design.json; is this the --out of `pm2dof design "
                             f"run`?")
    info = _read_json(meta)
    files = _stored(out / "batches")
    if not files:
        raise DesignOutError(f"{out}: no evaluated designs yet; run `pm2dof design run` with "
                             f"--out {out}")
    table = pa.concat_tables([pq.read_table(p).replace_schema_metadata(None) for p in files],
                             promote_options="default")
    table = table.sort_by([("generation", "ascending"), ("position", "ascending")])
    cols = {}
    for name in table.column_names:
        col = table.column(name)
        cols[name] = (np.array(col.to_pylist(), dtype=object) if pa.types.is_string(col.type)
                      else col.to_numpy())
    cols["file_design"] = cols["generation"] == FILE_DESIGN_GENERATION
    return info, cols
