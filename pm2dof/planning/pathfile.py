# Path files (TOML) for `pm2dof plan --path`: segments of a TaskPath, and the kinematic limits.
"""Read a path file: a :class:`TaskPath` made of segments, one after the other.

::

    [path]
    name = "pick_and_place"          # optional; default the file's stem
    description = "..."              # optional
    [kinematic]                      # optional: limits of the kinematic S-curve, m/s, m/s^2, m/s^3
    v_max = 0.5
    a_max = 10.0
    j_max = 400.0
    [[segments]]
    kind = "line"                    # start, end
    start = [0.22, 0.29]
    end = [0.27, 0.24]
    [[segments]]
    kind = "arc"                     # center, radius, angle0, angle1 (rad)
    [[segments]]
    kind = "polyline"                # points, blend_radius (default 0: stops at the corners)
    [[segments]]
    kind = "spline"                  # waypoints (C2, through every point)

A shipped path is named by its stem (``pm2dof plan --path pick_and_place``); anything with a
``/`` or ending in ``.toml`` is a file. Errors are :class:`pm2dof.PlanError` naming the file,
the key and the reason.
"""
import tomllib
from pathlib import Path

from ..core.errors import PlanError
from ..core.task import orientation_length
from .paths import TaskPath

__all__ = ["SHIPPED_PATHS", "shipped_paths", "resolve_path_file", "read_path_file",
           "model_move_path"]

SHIPPED_PATHS = Path(__file__).resolve().parent / "shipped"
_SEGMENTS = {"line": ("start", "end"), "arc": ("center", "radius", "angle0", "angle1"),
             "polyline": ("points", "blend_radius"), "spline": ("waypoints",)}
_OPTIONAL = {"blend_radius"}


def shipped_paths():
    """{name: path} of the shipped path files."""
    return {p.stem: p for p in sorted(SHIPPED_PATHS.glob("*.toml"))}


def resolve_path_file(ref, relative_to=None):
    """The path file ``ref`` names: a shipped name or a file path (relative to the folder
    ``relative_to`` when given, e.g. the model file's folder, else the working directory)."""
    s = str(ref)
    if "/" not in s and not s.endswith(".toml"):
        shipped = shipped_paths()
        if s not in shipped:
            raise PlanError(f"no shipped path named {s!r}; shipped: {sorted(shipped)} (or give "
                            f"a file: ./{s}.toml)")
        return shipped[s]
    p = Path(s).expanduser()
    return p if p.is_absolute() or relative_to is None else Path(relative_to) / p


def _fail(path, key, reason):
    raise PlanError(f"{path}: {key}: {reason}")


def _unknown(path, where, table, allowed):
    extra = sorted(set(table) - set(allowed))
    if extra:
        _fail(path, f"{where}{extra[0]}", f"unknown key; allowed here: {sorted(allowed)}")


def read_path_file(ref, relative_to=None):
    """Read a path file (``relative_to``: see :func:`resolve_path_file`).

    Returns
    -------
    dict
        ``name``, ``description``, ``path`` (TaskPath), ``kinematic`` (dict of v_max, a_max,
        j_max, or None), ``file`` (pathlib.Path).
    """
    path = resolve_path_file(ref, relative_to)
    try:
        data = tomllib.loads(path.read_text())
    except OSError as exc:
        raise PlanError(f"cannot read path file {path}: {exc.strerror or exc}") from None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise PlanError(f"{path}: not valid TOML: {exc}") from None
    _unknown(path, "", data, {"path", "kinematic", "segments"})
    head = data.get("path", {})
    if not isinstance(head, dict):
        _fail(path, "path", "must be a table")
    _unknown(path, "path.", head, {"name", "description"})
    kin = data.get("kinematic")
    if kin is not None:
        if not isinstance(kin, dict):
            _fail(path, "kinematic", "must be a table")
        _unknown(path, "kinematic.", kin, {"v_max", "a_max", "j_max"})
        for key in ("v_max", "a_max", "j_max"):
            v = kin.get(key)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not v > 0:
                _fail(path, f"kinematic.{key}", f"must be a number > 0, got {v!r}")
        kin = {k: float(kin[k]) for k in ("v_max", "a_max", "j_max")}
    segs = data.get("segments")
    if not isinstance(segs, list) or not segs:
        _fail(path, "segments", "need at least one [[segments]] table")
    parts = []
    for i, seg in enumerate(segs):
        where = f"segments[{i}]"
        if not isinstance(seg, dict):
            _fail(path, where, "must be a table")
        kind = seg.get("kind")
        if kind not in _SEGMENTS:
            _fail(path, f"{where}.kind", f"must be one of {sorted(_SEGMENTS)}, got {kind!r}")
        keys = _SEGMENTS[kind]
        _unknown(path, f"{where}.", seg, {"kind", *keys})
        missing = [k for k in keys if k not in seg and k not in _OPTIONAL]
        if missing:
            _fail(path, f"{where}.{missing[0]}", f"missing (a {kind} needs {list(keys)})")
        try:
            parts.append(getattr(TaskPath, kind)(*[seg[k] for k in keys if k in seg]))
        except PlanError as exc:
            _fail(path, where, str(exc))
    try:
        joined = TaskPath.concat(*parts)
    except PlanError as exc:
        _fail(path, "segments", str(exc))
    return {"name": str(head.get("name", path.stem)), "description": str(head.get("description", "")),
            "path": joined, "kinematic": kin, "file": path}


def model_move_path(model, name):
    """The model file's move ``[trajectories.<name>]`` as a path: ``{name, path (TaskPath),
    kinematic (v_max, a_max, j_max, or None), file}``.

    A line move (``start``, ``end``) is :meth:`TaskPath.line`; a path move (``path = "..."``: a
    shipped path's name or a path file relative to the model file) is that file's path, with
    the move's kinematic limits where it gives them, else the file's ``[kinematic]``.
    """
    spec = getattr(model, "spec", model)
    moves = spec.trajectories
    if name not in moves:
        raise PlanError(f"no move {name!r} in [trajectories] of {spec.path}; have "
                        f"{sorted(moves)}")
    mv = moves[name]
    lim = {k: float(mv[k]) for k in ("v_max", "a_max", "j_max") if k in mv}
    if "path" not in mv:
        line = TaskPath.line(mv["start"], mv["end"], orientation_length(spec))   # (x, y[, phi])
        return {"name": name, "path": line, "kinematic": lim, "file": None}
    f = read_path_file(mv["path"], relative_to=Path(spec.path).parent)
    kin = lim if len(lim) == 3 else ({**(f["kinematic"] or {}), **lim} or None)
    if kin is not None and len(kin) != 3:
        raise PlanError(f"{spec.path}: [trajectories.{name}] gives {sorted(lim)} and its path "
                        f"file {f['file']} no [kinematic] table: give all of v_max, a_max, "
                        f"j_max")
    return {"name": name, "path": f["path"], "kinematic": kin, "file": f["file"]}
