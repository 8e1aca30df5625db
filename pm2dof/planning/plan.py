# The result of a planner: the timing along the path, torques, limits, and the sampled Trajectory.
"""A :class:`Plan`: how fast the path is traversed, and the desired motion that results.

The timing is a profile of the path speed s_d over the arc length s on a grid, with constant
path acceleration s_dd on each interval (s_d^2 rises linearly in s):

    s(tau) = s_k + s_d,k tau + s_dd,k tau^2 / 2,   t_k+1 - t_k = 2 delta_k / (s_d,k + s_d,k+1).

:func:`sample` turns it into a :class:`pm2dof.Trajectory` at the controller's period:
xd = p(s), xd_dot = p' s_d, xd_ddot = p' s_dd + p'' s_d^2.
"""
import functools
import math
from dataclasses import dataclass, field

import numpy as np

from ..control.trajectory import Trajectory
from ..core.errors import PlanError

__all__ = ["Plan", "PathProfile", "sample", "sampled", "grid_times"]


def grid_times(s, sdot):
    """Times (K,) s at the grid points of a profile with constant s_dd per interval."""
    v = sdot[:-1] + sdot[1:]
    if not (v > 0).all():
        k = int(np.argmin(v > 0))
        raise PlanError(f"zero feasible velocity on the whole interval s = [{s[k]:.6g}, "
                        f"{s[k + 1]:.6g}] m: the torque limits cannot hold the path at any speed "
                        f"there")
    return np.concatenate([[0.0], np.cumsum(2.0 * np.diff(s) / v)])


@dataclass(frozen=True, eq=False)
class PathProfile:
    """The timing of a path: ``s`` (K,) m, ``sdot`` (K,) m/s, ``sddot`` (K,) m/s^2 (interval k's
    constant value; the last repeats the one before), ``t`` (K,) s. ``duration`` = t[-1].

    Attributes
    ----------
    s : ndarray (K,)
        Arc length at the grid points, m, increasing from 0 to the path's length.
    sdot : ndarray (K,)
        Path speed at the grid points, m/s, >= 0.
    sddot : ndarray (K,)
        Path acceleration on interval k (constant there), m/s^2; the last repeats the one
        before.
    t : ndarray (K,)
        Time at the grid points, s, from 0.
    """

    s: np.ndarray = field(repr=False)
    sdot: np.ndarray = field(repr=False)
    sddot: np.ndarray = field(repr=False)
    t: np.ndarray = field(repr=False)

    def __post_init__(self):                     # read-only float64 copies
        for name in ("s", "sdot", "sddot", "t"):
            a = np.array(getattr(self, name), dtype=float)
            a.setflags(write=False)
            object.__setattr__(self, name, a)

    @property
    def duration(self):
        """Time to traverse the path, s."""
        return float(self.t[-1])

    def evaluate(self, t):
        """s (m), s_d (m/s), s_dd (m/s^2) at times ``t`` (array), at rest outside [0, duration].

        Parameters
        ----------
        t : array_like
            Times, s, any shape; the three results have its shape.
        """
        t = np.asarray(t, dtype=float)
        k = np.clip(np.searchsorted(self.t, t, side="right") - 1, 0, len(self.t) - 2)
        tau = np.clip(t - self.t[k], 0.0, self.t[k + 1] - self.t[k])
        u = self.sddot[k]
        s = np.clip(self.s[k] + self.sdot[k] * tau + 0.5 * u * tau * tau, self.s[k], self.s[k + 1])
        sd = np.maximum(self.sdot[k] + u * tau, 0.0)
        after = t >= self.t[-1]
        s = np.where(after, self.s[-1], np.where(t <= 0, self.s[0], s))
        sd = np.where(after | (t < 0), 0.0, sd)
        sdd = np.where(after | (t < 0), 0.0, u)
        return s, sd, sdd


def sample(path, profile, period):
    """The :class:`pm2dof.Trajectory` of ``profile`` along ``path`` at ``period`` s: samples at
    k * period, k = 0 .. ceil(duration / period); the last one at rest at the end."""
    return sampled(path, profile, period)[0]


def sampled(path, profile, period):
    """:func:`sample`'s trajectory, with the profile at its samples, (s, s_d, s_dd), and the
    path there, (p, p', p'')."""
    n = math.ceil(profile.duration / period)
    n += int(n * period < profile.duration)
    t = np.arange(n + 1) * period
    s, sd, sdd = profile.evaluate(t)
    p, dp, ddp = path.evaluate(s)
    xd_dot = dp * sd[:, None] + 0.0
    xd_ddot = dp * sdd[:, None] + ddp * (sd * sd)[:, None] + 0.0
    traj = Trajectory(t, p, xd_dot, xd_ddot, period)
    return traj, (s, sd, sdd), (p, dp, ddp)


@dataclass(frozen=True, eq=False)
class Plan:
    """A timed path. Arrays are read-only; no field is NaN.

    Attributes
    ----------
    path : TaskPath
    method : str
        "time_optimal", "smooth" or "kinematic".
    split : str or None
        "min_norm" or "min_max": the torque split whose limits the plan respects (None for a
        kinematic plan, which knows no model).
    duration : float
        Time to traverse the path, s (read-only: ``profile.duration``).
    s, sdot, sddot, t : ndarray (K,)
        The profile on its grid (read-only): m, m/s, m/s^2, s. A time-optimal or smooth plan's
        are its :class:`PathProfile`'s own arrays; the kinematic plan's, its S-curve at the
        trajectory's samples (``profile.evaluate(trajectory.t)``, ``t`` = ``trajectory.t``).
    max_velocity : ndarray (K,)
        The maximum-velocity curve: the largest s_d (m/s) at which some s_dd keeps every torque
        within the limits (the kinematic plan: v_max). 0 at a point where only rest is feasible.
    tau : ndarray (K, n) or None
        Actuator efforts of the split at the grid points, N m (N for a linear actuator; the
        model's theta). Where the path speed is 0 (the two ends, an interior stop) friction is
        the one-sided limit s_d -> 0+, the physical value as the robot starts or stops: its
        Coulomb term opposes the motion along the path (at the start and at an interior stop
        the motion that leaves the point, at the end the motion that arrives).
        ``Model.inverse_dynamics`` at that state (velocity 0) takes sign(0) = 0, no Coulomb
        term, and differs by the Coulomb friction through the split: on the paper's robot by
        up to 0.57 N m at a rest point of the shipped paths (1.9 % of tau_max = 30 N m, 9.5 %
        at 6 N m), on ``rrr4_platform`` 0.21 N m (1.0 % of its 20 N m); with a smoothed sign
        (``friction = "smooth_sign"``) the two agree (docs/using-planning.md).
    tau_peak : ndarray (n,) or None
        max_k |tau_k,i|, N m (N for a linear actuator).
    tau_max : ndarray (n,) or None
        The limits the plan respects: the model's (or given) tau_max times ``margin``, N m (N
        for a linear actuator).
    margin : float
    trajectory : Trajectory
        The motion sampled at ``trajectory.period`` (the model's), ready for ``simulate`` and
        both controllers (plain samples: the timing is ``profile``).
    compute_time_s : float
        Wall time of the planner, s.
    info : dict
        Planner details (grid size, solver status, ...).
    profile : PathProfile, SCurve or SCurveChain
        The timing law s(t) that ``trajectory`` samples (``profile.evaluate(t)``); the
        kinematic plan's S-curve (a chain of them for a path with stops).
    """

    path: object = field(repr=False)
    method: str
    split: object
    max_velocity: np.ndarray = field(repr=False)
    tau: object = field(repr=False)
    tau_peak: object
    tau_max: object
    margin: float
    trajectory: Trajectory = field(repr=False)
    compute_time_s: float
    profile: object = field(repr=False)
    info: dict = field(repr=False, default_factory=dict)

    def __post_init__(self):
        for name in ("max_velocity", "tau", "tau_peak", "tau_max"):
            v = getattr(self, name)
            if v is None:
                continue
            a = np.array(v, dtype=float)
            if not np.isfinite(a).all():
                raise PlanError(f"Plan.{name} has non-finite values")   # never handed out
            a.setflags(write=False)
            object.__setattr__(self, name, a)
        for name, a in zip(("s", "sdot", "sddot", "t"), self._grid):
            if not np.isfinite(a).all():
                raise PlanError(f"Plan.{name} has non-finite values")

    @functools.cached_property
    def _grid(self):
        """(s, sdot, sddot, t), read-only: a PathProfile's own arrays, an S-curve's (the
        kinematic plan) at the trajectory's samples."""
        if isinstance(self.profile, PathProfile):
            return self.profile.s, self.profile.sdot, self.profile.sddot, self.profile.t
        t = self.trajectory.t
        out = (*self.profile.evaluate(t)[:3], t)     # an SCurve's evaluate adds the jerk
        for a in out:
            a.setflags(write=False)
        return out

    s = property(lambda self: self._grid[0], doc="Arc length at the grid points, m (K,).")
    sdot = property(lambda self: self._grid[1], doc="Path speed at the grid points, m/s (K,).")
    sddot = property(lambda self: self._grid[2],
                     doc="Path acceleration on each grid interval, m/s^2 (K,).")
    t = property(lambda self: self._grid[3], doc="Time at the grid points, s (K,).")

    @property
    def duration(self):
        """Time to traverse the path, s."""
        return float(self.profile.duration)
