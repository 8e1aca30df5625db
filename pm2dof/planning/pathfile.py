# Path files (TOML) for `pm2dof plan --path`: segments of a TaskPath, and the kinematic limits.
"""Read a path file: a :class:`TaskPath` made of segments, one after the other.

::

    [path]
    name = "pick_and_place"          # optional; default the file's stem
    description = "..."              # optional
    orientation_length = 0.05        # optional, m: for (x, y, phi) points (default the model's)
    [kinematic]                      # optional: limits of the kinematic S-curve, m/s, m/s^2, m/s^3
    v_max = 0.5
    a_max = 10.0
    j_max = 400.0
    [[segments]]
    kind = "line"                    # start, end: [x, y] or [x, y, phi]
    start = [0.22, 0.29]
    end = [0.27, 0.24]
    [[segments]]
    kind = "arc"                     # center, radius, angle0, angle1 (rad), phi = [phi0, phi1]
    [[segments]]
    kind = "polyline"                # points, blend_radius (default 0: stops at the corners)
    [[segments]]
    kind = "spline"                  # waypoints (C2, through every point; (x, y) only)

Points with an orientation (x, y, phi) (and an arc's ``phi``) need the orientation length
l (m, :func:`pm2dof.core.task.orientation_length`): the caller passes the model's, and
``[path] orientation_length`` overrides it.

A shipped path is named by its stem (``pm2dof plan --path pick_and_place``); anything with a
``/`` or ending in ``.toml`` is a file. A bad file is one :class:`PathFileError` (a
:class:`pm2dof.PlanError`) naming the file and listing every problem, each with its key and
reason, segments numbered from 1, as model and study files (:class:`pm2dof.core.validate.Problems`):
every unknown or missing key and every value its constructor would refuse (a misspelt key hides
no bad value beside it); the checks between a segment's values (a blend that does not fit, equal
angles) and the joins between segments once its values are right.
"""
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..core.errors import InputFileError, PlanError
from ..core.task import orientation_length as model_orientation_length
from ..core.validate import Problems, entry
from .paths import TaskPath, _array, _number, _point, gap_message

__all__ = ["SHIPPED_PATHS", "shipped_paths", "resolve_path_file", "read_path_file",
           "model_move_path", "PathFileError", "NamedPath"]

SHIPPED_PATHS = Path(__file__).resolve().parent / "shipped"
#: each segment kind's keys: {file key: TaskPath constructor's argument}
_SEGMENTS = {"line": {"start": "p0", "end": "p1"},
             "arc": {"center": "center", "radius": "radius", "angle0": "angle0",
                     "angle1": "angle1", "phi": "phi"},
             "polyline": {"points": "points", "blend_radius": "blend_radius"},
             "spline": {"waypoints": "waypoints"}}
_OPTIONAL = {"blend_radius", "phi"}


def _points(name, value):
    """``value`` as an (m, 2) or (m, 3) array of finite numbers, m >= 2; PlanError otherwise
    (as the constructors: a bool, a text or a complex number is no coordinate)."""
    want = "a list of two or more points [x, y] or [x, y, phi] (m, rad)"
    P = _array(name, value, want)
    if P.ndim != 2 or P.shape[1] not in (2, 3) or len(P) < 2 or not np.isfinite(P).all():
        raise PlanError(f"{name} must be {want}, got {value!r}")
    return P


#: each segment key's own check, the one its TaskPath constructor makes (PlanError "<name>
#: must be ..."): run on every key a segment gives, so that one bad key hides no other
_VALUE_CHECKS = {
    "start": lambda v: _point("start", v, (2, 3)),
    "end": lambda v: _point("end", v, (2, 3)),
    "center": lambda v: _point("center", v),
    "radius": lambda v: _number("radius (m)", v, positive=True),
    "angle0": lambda v: _number("angle0 (rad)", v),
    "angle1": lambda v: _number("angle1 (rad)", v),
    "phi": lambda v: _point("phi", v, want="[phi0, phi1]: the orientation at the start and "
                            "the end, two finite angles in rad"),
    "points": lambda v: _points("points", v),
    "blend_radius": lambda v: _number("blend_radius (m)", v, nonnegative=True),
    "waypoints": lambda v: _points("waypoints", v),
}


def _check_values(pr, kind, seg, label):
    """One problem per key of segment ``seg`` (a ``kind`` segment, numbered by ``label``)
    whose value its constructor would refuse, named ``segments.<key> (<label>)``: every
    bad value, whatever else is wrong with the segment (a misspelt or missing key)."""
    for key in _SEGMENTS[kind]:
        if key in seg:
            try:
                _VALUE_CHECKS[key](seg[key])
            except PlanError as exc:
                pr.add(entry(f"segments.{key}", label), str(exc))


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


class PathFileError(PlanError, InputFileError):
    """A path file that cannot be used: every problem of the file, one line each, naming the
    key (segments numbered from 1, ``segments.end (segment 2)``), as model and study files."""


_KINEMATIC = ("v_max", "a_max", "j_max")


@dataclass(frozen=True)
class NamedPath:
    """A path to plan, with its name and kinematic limits: what :func:`read_path_file` reads
    from a path file and :func:`model_move_path` makes of a model file's move.

    Attributes
    ----------
    name : str
    path : TaskPath
    kinematic : dict or None
        v_max (m/s), a_max (m/s^2), j_max (m/s^3) of the kinematic S-curve, or None.
    file : pathlib.Path or None
        The path file (None: a model file's line move).
    description : str
    segment_ends : tuple of float
        Arc length (m) at the end of each of the path file's segments (empty: no file).
    """

    name: str
    path: TaskPath
    kinematic: object
    file: object
    description: str = ""
    segment_ends: tuple = ()

    def where(self, s=None):
        """The path in words for messages: ``path file <file>``, with the segment (numbered
        from 1) holding arc length ``s`` (m) when given; None for a path with no file."""
        if self.file is None:
            return None
        if s is None or not self.segment_ends:
            return f"path file {self.file}"
        k = min(int(np.searchsorted(self.segment_ends, s)), len(self.segment_ends) - 1)
        return f"path file {self.file}, segment {k + 1}"


def _has_orientation(kind, seg):
    """Whether segment table ``seg`` gives an orientation: (x, y, phi) points or an arc's phi."""
    pts = {"line": [seg.get("start"), seg.get("end")], "polyline": seg.get("points"),
           "arc": [], "spline": []}[kind]
    return ("phi" in seg if kind == "arc" else
            isinstance(pts, list) and any(isinstance(p, list) and len(p) == 3 for p in pts))


def read_path_file(ref, relative_to=None, orientation_length=None):
    """Read a path file (``relative_to``: see :func:`resolve_path_file`).

    ``orientation_length`` (m): l for points (x, y, phi), the model's
    (:func:`pm2dof.core.task.orientation_length`); the file's ``[path] orientation_length``
    overrides it. Without either, a segment with an orientation is a problem of the file.

    Returns
    -------
    NamedPath
        ``name``, ``description``, ``path`` (TaskPath), ``kinematic`` (dict of v_max, a_max,
        j_max, or None), ``file`` (pathlib.Path), ``segment_ends``.

    Raises
    ------
    PathFileError
        (a PlanError and an InputFileError) listing every problem of the file at once.
    """
    path = resolve_path_file(ref, relative_to)
    pr = Problems(path, PathFileError)
    _, data = pr.read_toml("path file")
    pr.keys("", data, {"path", "kinematic", "segments"})
    head = pr.table("path", data.get("path"), required=False) or {}
    pr.keys("path", head, {"name", "description", "orientation_length"})
    name = pr.text("path.name", head.get("name", path.stem), nonempty=True)
    description = pr.text("path.description", head.get("description", ""))
    ell = orientation_length
    if "orientation_length" in head:
        ell = pr.number("path.orientation_length", head["orientation_length"], low=0.0,
                        low_ok=False)
    kin = pr.table("kinematic", data.get("kinematic"), required=False)
    if kin is not None:
        pr.keys("kinematic", kin, _KINEMATIC, _KINEMATIC)
        kin = {k: pr.number(f"kinematic.{k}", kin[k], low=0.0, low_ok=False)
               for k in _KINEMATIC if k in kin}
    segs = data.get("segments")
    if not isinstance(segs, list) or not segs:
        pr.add("segments", "need at least one [[segments]] table")
        segs = []
    parts = []
    for i, seg in enumerate(segs):
        label = f"segment {i + 1}"
        if not isinstance(seg, dict):
            pr.add(entry("segments", label), "must be a table")
            continue
        kind = pr.choice(entry("segments.kind", label), seg.get("kind"),
                         {k: k for k in _SEGMENTS})
        if kind is None:
            continue
        keys = _SEGMENTS[kind]
        before = len(pr)
        pr.keys("segments", seg, {"kind", *keys}, [k for k in keys if k not in _OPTIONAL],
                label=label)
        _check_values(pr, kind, seg, label)
        if len(pr) > before:            # the constructor would stop at the first of them
            continue
        if ell is None and _has_orientation(kind, seg) and "orientation_length" not in head:
            pr.add(entry("segments", label), "an orientation (x, y, phi) needs the orientation "
                   "length (m) that turns phi into arc length: plan with a platform model "
                   "(--model, which gives its own) or set [path] orientation_length")
            continue
        args = {arg: seg[k] for k, arg in keys.items() if k in seg}
        if kind != "spline":
            args["orientation_length"] = ell
        try:
            parts.append(getattr(TaskPath, kind)(**args))
        except PlanError as exc:
            pr.add(entry("segments", label), str(exc))
    if parts and len(parts) == len(segs):
        for i in range(1, len(parts)):          # each segment starts where the one before ends
            gap = gap_message(parts[i - 1], parts[i], f"segment {i + 1}", f"segment {i}")
            if gap:
                pr.add(entry("segments", f"segment {i + 1}"), gap)
    if len(pr) == 0:
        try:
            joined = TaskPath.concat(*parts)
        except PlanError as exc:
            pr.add("segments", str(exc))
    pr.raise_if_any()
    ends = tuple(np.cumsum([part.length for part in parts]).tolist())
    return NamedPath(str(name), joined, kin, path, str(description), ends)


def model_move_path(model, name):
    """The model file's move ``[trajectories.<name>]`` as a :class:`NamedPath` (``name``,
    ``path``, ``kinematic``: v_max, a_max, j_max or None, ``file``: its path file or None).

    A line move (``start``, ``end``) is :meth:`TaskPath.line`; a path move (``path = "..."``: a
    shipped path's name or a path file relative to the model file) is that file's path, with
    the move's kinematic limits where it gives them, else the file's ``[kinematic]``.

    Parameters
    ----------
    model : Model
        The model whose file holds the move (its ``spec`` is read).
    name : str
        The move's name, a key of the model file's ``[trajectories]``.
    """
    spec = model.spec
    moves = spec.trajectories
    if name not in moves:
        raise PlanError(f"no move {name!r} in [trajectories] of {spec.path}; have "
                        f"{sorted(moves)}")
    mv = moves[name]
    lim = {k: float(mv[k]) for k in ("v_max", "a_max", "j_max") if k in mv}
    if "path" not in mv:
        ell = model_orientation_length(model)
        line = TaskPath.line(mv["start"], mv["end"], ell)   # (x, y[, phi])
        return NamedPath(name, line, lim, None)
    f = read_path_file(mv["path"], relative_to=Path(spec.path).parent,
                       orientation_length=model_orientation_length(model))
    kin = lim if len(lim) == 3 else ({**(f.kinematic or {}), **lim} or None)
    if kin is not None and len(kin) != 3:
        raise PlanError(f"{spec.path}: [trajectories.{name}] gives {sorted(lim)} and its path "
                        f"file {f.file} no [kinematic] table: give all of v_max, a_max, "
                        f"j_max")
    return NamedPath(name, f.path, kin, f.file)
