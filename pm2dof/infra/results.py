# Writing results: atomically (temp file + rename), each carrying its provenance.
import json
import os
import platform
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

from ..core.errors import OutputError

__all__ = ["provenance", "output_path", "output_folder", "write_atomic", "write_json", "dumps", "save_figure"]

REPO = Path(__file__).resolve().parents[2]   # the source checkout, when pm2dof runs from one


def _git_commit():
    if not (REPO / ".git").exists():            # an installed package: no checkout
        return None
    try:
        out = subprocess.run(["git", "rev-parse", "HEAD"], cwd=REPO, capture_output=True,
                             text=True, timeout=5)
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"],
                               cwd=REPO, capture_output=True, text=True, timeout=5).stdout.strip()
        return out.stdout.strip() + ("+dirty" if dirty else "") if out.returncode == 0 else None
    except (OSError, subprocess.SubprocessError):
        return None


def provenance(model, command_line=None):
    """Where a result came from: the pm2dof version, the model file and the generated code
    (paths, hashes, whether shipped with pm2dof), git commit (only from a checkout), versions,
    command line.

    Parameters
    ----------
    model : Model
    command_line : sequence of str, optional
        The command that produced the result, recorded as given: ``pm2dof`` passes its own
        (``["pm2dof", "table3", "--save", "t.json"]``) down to whatever writes a file. None:
        this process's ``sys.argv`` (a script calling pm2dof).
    """
    from ..core.paths import is_shipped
    from ..core.version import __version__
    out = {
        "model": model.name,
        "model_file": model.spec.path,
        "model_shipped": is_shipped(model.spec.path),
        "model_file_sha256": model.spec.file_sha256,
        "formulation_sha256": model.spec.formulation_sha256,
        "generated": model.generated,
        "library": model.library,
        "generated_with": dict(model.manifest["versions"]),
        "git_commit": _git_commit(),
        "pm2dof": __version__,
        "python": platform.python_version(),
        "numpy": np.__version__,
        "machine": f"{platform.machine()} {platform.system()}, {os.cpu_count()} cores",
        "command_line": list(sys.argv if command_line is None else command_line),
    }
    if out["git_commit"] is None:    # an installed package: no checkout, no key
        del out["git_commit"]
    return out


def output_path(path):
    """``path`` as a Path whose folder exists (created if missing), ready to be written.

    Raises OutputError naming the problem: ``path`` is a folder, a part of its folder is a
    file, or the folder cannot be created.
    """
    path = Path(path)
    if path.is_dir():
        raise OutputError(f"cannot write {path}: it is a folder (name a file in it)")
    for parent in path.parents:
        if parent.exists():
            if not parent.is_dir():
                raise OutputError(f"cannot write {path}: {parent} is a file, not a folder")
            break
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot write {path}: {exc.strerror or exc}") from None
    return path


def output_folder(path):
    """``path`` as a Path that is, or can become, a folder (nothing is created): OutputError
    if it or a part of it is a file. Commands check their ``--out DIR`` with it before any work."""
    path = Path(path)
    for part in (path, *path.parents):
        if part.exists():
            if not part.is_dir():
                raise OutputError(f"cannot write into {path}: {part} is a file, not a folder")
            break
    return path


def write_atomic(path, data):
    """Write bytes to ``path`` through a temporary file in the same folder and a rename
    (OutputError if it cannot: :func:`output_path`, or the disk refuses)."""
    path = output_path(path)
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    except OSError as exc:
        raise OutputError(f"cannot write {path}: {exc.strerror or exc}") from None
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # as a plain open() would (mkstemp makes it 0600)
        os.replace(tmp, path)
    except BaseException as exc:
        if os.path.exists(tmp):
            os.unlink(tmp)
        if isinstance(exc, OSError):
            raise OutputError(f"cannot write {path}: {exc.strerror or exc}") from None
        raise
    return path


def dumps(obj):
    """JSON text of results holding NumPy arrays and scalars (indent 1).

    Valid JSON always: a non-finite number (the ``inf`` RMSE of a run that did not complete)
    is written as ``null``; the record's outcome says why (JSON has no inf or NaN).
    """
    return json.dumps(_finite(obj), indent=1, default=_jsonable, allow_nan=False)


def _finite(x):
    """``x`` with every non-finite float (also inside arrays) replaced by None."""
    if isinstance(x, dict):
        return {k: _finite(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_finite(v) for v in x]
    if isinstance(x, np.ndarray):
        return _finite(x.tolist()) if x.dtype.kind == "f" else x
    if isinstance(x, (float, np.floating)) and not np.isfinite(x):
        return None
    return x


def write_json(path, obj):
    """Write ``obj`` (NumPy arrays allowed) as JSON, atomically."""
    return write_atomic(path, (dumps(obj) + "\n").encode())


def _jsonable(x):
    if isinstance(x, np.ndarray):
        return x.tolist()
    if isinstance(x, np.generic):
        return x.item()
    raise TypeError(f"not JSON serialisable: {type(x).__name__}")


def save_figure(fig, path, prov):
    """Save a matplotlib figure as PNG atomically, with the provenance in its text chunks."""
    import io
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110,
                metadata={"Software": "pm2dof", "Description": json.dumps(prov, default=_jsonable)})
    return write_atomic(path, buf.getvalue())
