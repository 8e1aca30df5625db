# Is a path inside the workspace and clear of both singularities? Errors name the arc length and point.
"""``check_path(model, path)``: the planner's first question, asked of the generated C."""
import numpy as np

from ..core.errors import PlanError, SingularityError, WorkspaceError

__all__ = ["check_path", "raise_at"]

STEP = 5e-4   # m: default sample spacing of check_path


def _where(s, p):
    return f"s = {s:.6g} m, point ({p[0]:.6g}, {p[1]:.6g}) m"


def raise_at(model, s, p, sing=None):
    """Raise the error of the pose at arc length ``s`` and point ``p``: WorkspaceError (a leg
    cannot reach it; the message of ``model.ik``) or SingularityError (``sing`` = its two
    measures, below a threshold)."""
    try:
        q = model.ik(p)
    except WorkspaceError as exc:
        raise WorkspaceError(f"the path leaves the workspace at {_where(s, p)}: {exc}") from None
    if sing is None or not np.isfinite(sing).all():
        sing = model.singularity_measures(q)
    raise SingularityError(f"the path comes too close to a singularity at {_where(s, p)}: "
                           f"{model.singularity_message(sing)}")


def first_bad(model, sing):
    """Index of the first row of ``sing`` (k, 2) that is NaN or below a threshold, or None."""
    ok = (sing[:, 0] >= model.singularity_threshold) & \
         (sing[:, 1] >= model.parallel_singularity_threshold)
    return None if ok.all() else int(np.argmin(ok))


def check_path(model, path, step=STEP):
    """Check that every point of ``path`` is reachable in the model's assembly mode and at
    least each singularity threshold away from a singularity (``[limits]``).

    Parameters
    ----------
    model : Model
    path : TaskPath
    step : float
        Sample spacing along the path, m (default 0.5 mm); the breakpoints are sampled too.

    Raises
    ------
    WorkspaceError
        At the first sample some leg cannot reach (names the arc length, the point and the leg).
    SingularityError
        At the first sample closer to a type I or type II singularity than its threshold
        (names the arc length, the point, the kind, the measure and the ``[limits]`` key).
    """
    try:
        h = float(step)
    except (TypeError, ValueError):
        h = float("nan")
    if not h > 0 or not np.isfinite(h):
        raise PlanError(f"step must be a finite length > 0 m, got {step!r}")
    n = max(2, int(np.ceil(path.length / h)) + 1)
    s = np.union1d(np.linspace(0.0, path.length, n), path.breakpoints)
    p = np.ascontiguousarray(path.evaluate(s)[0])
    K, nq = len(s), 2 * model.n_legs
    q = np.empty((K, nq))
    model.function("ik").map(K, p, q)
    sing = np.full((K, 2), np.nan)      # ik's NaN rows: out of reach (or the other mode)
    ok = np.isfinite(q).all(axis=1)
    if ok.any():
        sing_ok = np.empty((int(ok.sum()), 2))
        model.function("singularity_measures").map(len(sing_ok), np.ascontiguousarray(q[ok]),
                                                   sing_ok)
        sing[ok] = sing_ok
    k = first_bad(model, sing)          # the first sample out of reach or too close
    if k is not None:
        raise_at(model, s[k], p[k], sing[k])
