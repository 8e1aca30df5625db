# Kinematic timing of a path: the jerk-limited S-curve of pm2dof.control along its arc length.
"""``plan_kinematic(path, v_max, a_max, j_max)``: speed, acceleration and jerk limits along the
path, no dynamics. Each rest-to-rest part of the path (between its stops) gets the time-optimal
S-curve :class:`pm2dof.control.trajectory.SCurve` (the paper's profile) of its arc length, one
after the other; on a straight line this is exactly ``pm2dof.line``."""
import math
import time
from dataclasses import dataclass

import numpy as np

from ..control.trajectory import SCurve, Trajectory, TrajectoryError, _positive
from ..core.errors import PlanError
from .check import require
from .plan import Plan

__all__ = ["plan_kinematic", "SCurveChain"]


@dataclass(frozen=True)
class SCurveChain:
    """S-curves of consecutive rest-to-rest parts starting at arc lengths ``starts`` (m)."""

    parts: tuple
    starts: tuple

    @property
    def duration(self):
        """Total time, s."""
        return sum(p.duration for p in self.parts)

    def evaluate(self, t):
        """s (m), s_d (m/s), s_dd (m/s^2) at times ``t`` (array)."""
        t = np.asarray(t, dtype=float)
        ends = np.cumsum([p.duration for p in self.parts])
        k = np.minimum(np.searchsorted(ends, t, side="right"), len(self.parts) - 1)
        s, sd, sdd = np.empty_like(t), np.empty_like(t), np.empty_like(t)
        for i, prof in enumerate(self.parts):
            sel = k == i
            if sel.any():
                t0 = ends[i] - prof.duration
                a, b, c, _ = prof.evaluate(t[sel] - t0)
                s[sel], sd[sel], sdd[sel] = self.starts[i] + a, b, c
        return s, sd, sdd


def plan_kinematic(path, v_max, a_max, j_max, period=0.002):
    """Time ``path`` with the time-optimal rest-to-rest S-curve of its arc length.

    Parameters
    ----------
    path : TaskPath
        A path with interior stops (sharp corners, reversals) is timed part by part, at rest
        at each stop.
    v_max, a_max, j_max : float
        Limits along the path: m/s, m/s^2, m/s^3 (the paper's high-speed move: 0.5, 10, 400).
    period : float
        Sampling period of the trajectory, s (default 2 ms, the paper's).

    Returns
    -------
    Plan
        ``method`` "kinematic", ``split`` None, ``tau``/``tau_peak``/``tau_max`` None (no
        model: ``pm2dof.planning.torques.path_torques`` gives its torques),
        ``max_velocity`` v_max; ``s``, ``sdot``, ``sddot``, ``t`` at the trajectory's samples.

    Raises
    ------
    PlanError
        A limit or the period not a finite number > 0.
    ArgumentTypeError
        ``path`` not a TaskPath.

    Examples
    --------
    >>> import numpy as np, pm2dof
    >>> path = pm2dof.TaskPath.line([0.22, 0.29], [0.27, 0.24])
    >>> plan = pm2dof.plan_kinematic(path, 0.5, 10.0, 400.0)
    >>> round(plan.duration, 4), bool(np.allclose(plan.trajectory.xd,
    ...                                             pm2dof.paper_move("high").xd, atol=1e-15))
    (0.2164, True)
    """
    t0 = time.perf_counter()
    require(path=path)
    try:
        period = _positive("period (s)", period)
        stops = path.stops
        parts = tuple(SCurve.plan(b - a, v_max, a_max, j_max)
                      for a, b in zip(stops[:-1], stops[1:]))
    except TrajectoryError as exc:
        raise PlanError(f"plan_kinematic: {exc}") from None
    chain = SCurveChain(parts, tuple(float(a) for a in stops[:-1]))
    prof = parts[0] if len(parts) == 1 else chain
    n = math.ceil(prof.duration / period)
    n += int(n * period < prof.duration)
    t = np.arange(n + 1) * period
    if len(parts) == 1:
        s, sd, sdd, _ = prof.evaluate(t)
    else:
        s, sd, sdd = chain.evaluate(t)
    p, dp, ddp = path.evaluate(s)
    xd_dot = dp * sd[:, None] + 0.0
    xd_ddot = dp * sdd[:, None] + ddp * (sd * sd)[:, None] + 0.0
    traj = Trajectory(t, p, xd_dot, xd_ddot, period)
    return Plan(path=path, method="kinematic", split=None,
                max_velocity=np.full(len(t), parts[0].v_max),
                tau=None, tau_peak=None, tau_max=None, margin=1.0, trajectory=traj, profile=prof,
                compute_time_s=time.perf_counter() - t0,
                info={"v_max": parts[0].v_max, "a_max": parts[0].a_max,
                      "j_max": parts[0].j_max, "parts": len(parts),
                      "v_peak": [p.v_peak for p in parts], "a_peak": [p.a_peak for p in parts]})
