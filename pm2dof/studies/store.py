# A study's output folder: study.json, and one Parquet file per finished chunk, written atomically.
"""The output folder of a study run.

``DIR/results/chunk-NNNNNN.parquet`` holds the rows of one chunk. Each is written to a
temporary name and renamed, so a chunk file exists only complete; its schema metadata carries
the study's identity. ``pyarrow.dataset.dataset(DIR / "results")`` reads all of them as one
table. ``DIR/study.json`` holds the study file, its identity, the provenance and, once every
chunk is in, the row count. A rerun with the same study skips the chunks already there; a
different study on a non-empty folder is refused.
"""
import json
import os
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq

from ..core.errors import Pm2dofError
from ..infra.results import provenance, write_atomic, write_json
from .spec import StudyFileError

__all__ = ["StudyOutError", "prepare_out", "write_chunk", "finish_out", "changed_inputs",
           "read_results", "chunk_path"]

_NULLABLE = ("theta_error",)   # null where it does not apply (APD) or the rollout diverged


class StudyOutError(Pm2dofError, ValueError):
    """The output folder cannot be used: not writable, or it holds another study."""


def chunk_path(out, i):
    return Path(out) / "results" / f"chunk-{i:06d}.parquet"


def prepare_out(out, study, model, command_line=None):
    """Create or reopen ``out`` for ``study``; returns the set of finished chunk indices.
    ``out/study.json`` records the study and its provenance (``command_line``: the command it
    records, None: ``sys.argv``).

    Raises StudyOutError when ``out`` is not a writable folder or holds results of a study
    with another identity. Leftover temporary files of an interrupted run are removed.
    """
    out = Path(out)
    results = out / "results"
    try:
        results.mkdir(parents=True, exist_ok=True)
        probe = results / f".write-test-{os.getpid()}"
        probe.write_bytes(b"")
        probe.unlink()
    except OSError as exc:
        raise StudyOutError(f"--out {out}: cannot write there ({exc.strerror or exc})") from None
    meta = out / "study.json"
    have = sorted(results.glob("chunk-*.parquet"))
    if meta.exists():
        try:
            old = json.loads(meta.read_text())
        except (OSError, ValueError) as exc:
            raise StudyOutError(f"--out {out}: unreadable study.json ({exc}); use another "
                                f"folder") from None
        if old.get("identity") != study.identity and have:
            raise StudyOutError(
                f"--out {out} holds {len(have)} chunk(s) of "
                f"{'this study' if old.get('study_file') == study.path else 'another study'} "
                f"({old.get('name')!r}, from {old.get('study_file')}) made with other inputs: "
                f"{changed_inputs(old.get('inputs'), study.canonical())}. Use an empty --out, "
                f"or delete {out} to start over")
    elif have:
        raise StudyOutError(f"--out {out} holds results but no study.json; use an empty folder")
    for tmp in results.glob(".chunk-*"):      # an interrupted write
        tmp.unlink(missing_ok=True)
    done = set()
    for p in have:
        try:
            md = pq.read_schema(p).metadata or {}
        except (OSError, pa.ArrowInvalid):
            p.unlink()                          # cannot happen with atomic writes; be safe
            continue
        if md.get(b"pm2dof_study") != study.identity.encode():
            raise StudyOutError(f"{p} belongs to another study; use an empty --out")
        done.add(int(p.stem.split("-")[1]))
    write_json(meta, {"name": study.name, "identity": study.identity,
                      "inputs": study.canonical(),
                      "study_file": study.path, "study_text": study.text, "quick": study.quick,
                      "rollouts": study.n_rollouts, "chunks": study.n_chunks,
                      "runs": study.runs, "payload_change": study.payload_change,
                      "complete": False, "rows": None, "provenance": provenance(model, command_line)})
    return done


def changed_inputs(old, new):
    """What differs between two studies' inputs (:meth:`Study.canonical`), in words."""
    if not isinstance(old, dict):
        return ("the study file, its [quick] choice or the model file's values differ (the "
                "folder's study.json does not record which)")
    out = []
    for k in sorted(set(old) | set(new)):
        a, b = old.get(k), json.loads(json.dumps(new.get(k)))
        if a == b:
            continue
        if k == "model_values" and isinstance(a, dict):
            tables = sorted(t for t in set(a) | set(b) if a.get(t) != b.get(t))
            out.append("the model file's values in " + ", ".join(f"[{t}]" for t in tables))
        elif k == "quick":
            out.append(f"the [quick] choice ({a} then, {b} now)")
        else:
            out.append(f"the study's {k} ({a!r} then, {b!r} now)")
    return "; ".join(out) or "the study's inputs"


def _table(columns, study):
    arrays, names = [], []
    for k, v in columns.items():
        if k in _NULLABLE or k in study.grid_keys:
            arrays.append(pa.array(v, mask=np.isnan(v)))
        elif v.dtype == object:
            arrays.append(pa.array(v.tolist(), pa.string()))
        else:
            arrays.append(pa.array(v))
        names.append(k)
    return pa.table(arrays, names=names).replace_schema_metadata(
        {"pm2dof_study": study.identity, "pm2dof_study_name": study.name})


def write_chunk(out, i, columns, study):
    """Write chunk ``i``'s rows (``columns``: {name: ndarray}) atomically; returns the path."""
    sink = pa.BufferOutputStream()
    pq.write_table(_table(columns, study), sink, compression="zstd")
    return write_atomic(chunk_path(out, i), sink.getvalue().to_pybytes())


def finish_out(out, study):
    """Record completion in study.json once every chunk is present; returns the row count."""
    meta = Path(out) / "study.json"
    info = json.loads(meta.read_text())
    files = sorted((Path(out) / "results").glob("chunk-*.parquet"))
    rows = sum(pq.read_metadata(p).num_rows for p in files)
    info.update(complete=len(files) == study.n_chunks and rows == study.n_rollouts, rows=rows)
    write_json(meta, info)
    return rows


def read_results(out):
    """(study.json dict, pyarrow Table of every row sorted by rollout) of a study folder."""
    import pyarrow.dataset as ds
    out = Path(out)
    meta = out / "study.json"
    if not meta.exists():
        raise StudyFileError(f"{out}: no study.json; is this the --out of `pm2dof study run`?")
    info = json.loads(meta.read_text())
    table = ds.dataset(out / "results", format="parquet").to_table()
    return info, table.sort_by("rollout")
