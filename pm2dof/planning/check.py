# Is a path inside the workspace and clear of both singularities? Errors name the arc length and point.
"""``check_path(model, path)``: the planner's first question, asked of the generated C (ik and
the singularity measures) and answered by the model's test of a desired motion
(``Model.poses_clear``, which ``simulate``'s check uses: the thresholds with the same slack),
so that a path the planner accepts is one ``simulate`` accepts."""
import numpy as np

from ..core.errors import ArgumentTypeError, PlanError, SingularityError, WorkspaceError
from ..core.model import require_model
from .paths import TaskPath, point_text

__all__ = ["check_path", "raise_at", "first_bad", "require", "point_text", "STEP", "STEP_MIN",
           "STEP_MAX", "SAMPLES_MAX"]

STEP = 5e-4         # m: default sample spacing of check_path
STEP_MIN = 1e-6     # m: the finest spacing check_path takes
STEP_MAX = 1e-2     # m: the coarsest (coarser could step over a singular region)
SAMPLES_MAX = 1_000_000    # samples along one path (the step is refused beyond)


_UNSET = object()


def require(model=_UNSET, path=_UNSET):
    """ArgumentTypeError unless ``model`` is a :class:`pm2dof.Model` and ``path`` a
    :class:`pm2dof.TaskPath` (each checked when given); PlanError unless the path's dimension
    is the model's task dimension m (both given)."""
    if model is not _UNSET:
        require_model(model)
    if path is not _UNSET and not isinstance(path, TaskPath):
        raise ArgumentTypeError(f"path must be a pm2dof.TaskPath (TaskPath.line, .arc, "
                                f".polyline, .spline, .concat), got {type(path).__name__}")
    if model is not _UNSET and path is not _UNSET and path.dim != model.dof:
        raise PlanError(f"the path has task dimension {path.dim}, model {model.name!r} m = "
                        f"{model.dof} ({', '.join(model.task_names)}): a path's points must "
                        f"have the model's task coordinates")


def _where(s, p, where=None):
    place = f" ({where(s)})" if where is not None else ""
    return f"s = {s:.6g} m, point {point_text(p)}{place}"


def raise_at(model, s, p, sing=None, where=None):
    """Raise the error of the pose at arc length ``s`` and point ``p``: WorkspaceError (a leg
    cannot reach it; the message of ``model.ik``) or SingularityError (``sing`` = its two
    measures, below a threshold). ``where``: as :func:`check_path`'s."""
    try:
        q = model.ik(p)
    except WorkspaceError as exc:
        raise WorkspaceError(f"the path leaves the workspace at {_where(s, p, where)}: "
                             f"{exc}") from None
    if sing is None or not np.isfinite(sing).all():
        sing = model.singularity_measures(q)
    raise SingularityError(f"the path comes too close to a singularity at "
                           f"{_where(s, p, where)}: {model.singularity_message(sing)}")


def first_bad(model, sing):
    """Index of the first row of ``sing`` (k, 2) (the generated measures) that is NaN or below
    a threshold, or None."""
    ok = model.poses_clear(sing[:, 0], sing[:, 1])
    return None if ok.all() else int(np.argmin(ok))


def check_path(model, path, step=STEP, *, where=None):
    """Check that every point of ``path`` is reachable in the model's assembly mode and at
    least each singularity threshold away from a singularity (``[limits]``).

    Parameters
    ----------
    model : Model
    path : TaskPath
    step : float
        Sample spacing along the path, m (default 0.5 mm), from STEP_MIN = 1e-6 m to
        STEP_MAX = 0.01 m and at most SAMPLES_MAX = 10^6 samples along the path; the
        breakpoints are sampled too.
    where : callable, optional
        s (m) -> the place on the path in words (a path file and its segment:
        :meth:`.pathfile.NamedPath.where`), added to the error's message.

    Raises
    ------
    WorkspaceError
        At the first sample some leg cannot reach (names the arc length, the point and the leg).
    SingularityError
        At the first sample closer to a type I or type II singularity than its threshold
        (names the arc length, the point, the kind, the measure and the ``[limits]`` key).
    PlanError
        A step outside its bounds.
    ArgumentTypeError
        ``model`` not a Model or ``path`` not a TaskPath.
    """
    require(model, path)
    try:
        h = float(step)
    except (TypeError, ValueError):
        h = float("nan")
    if not STEP_MIN <= h <= STEP_MAX:
        raise PlanError(f"step must be a length from {STEP_MIN:g} m to {STEP_MAX:g} m, got "
                        f"{step!r}")
    n = max(2, int(np.ceil(path.length / h)) + 1)
    if n > SAMPLES_MAX:
        raise PlanError(f"step {h:g} m gives {n} samples along the {path.length:.6g} m path, "
                        f"more than {SAMPLES_MAX}: use step >= {path.length / SAMPLES_MAX:.3g} m")
    s = np.union1d(np.linspace(0.0, path.length, n), path.breakpoints)
    p = np.ascontiguousarray(path.evaluate(s)[0])
    K, nq = len(s), 2 * model.n_legs
    q = np.empty((K, nq))
    model.function("ik").map(K, p, q)   # NaN rows: out of reach, or the other assembly mode
    sing = np.full((K, 2), np.nan)
    ok = np.isfinite(q).all(axis=1)
    if ok.any():
        sing_ok = np.empty((int(ok.sum()), 2))
        model.function("singularity_measures").map(len(sing_ok), np.ascontiguousarray(q[ok]),
                                                   sing_ok)
        sing[ok] = sing_ok
    k = first_bad(model, sing)          # the first sample out of reach or too close
    if k is not None:
        raise_at(model, s[k], p[k], sing[k], where)
