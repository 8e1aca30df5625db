# Desired task-space motion: time-optimal jerk-limited (S-curve) rest-to-rest straight-line moves,
# plain sampled references and holds.
"""Time-optimal rest-to-rest S-curve (jerk ``+j, 0, -j, 0, -j, 0, +j``) along a
straight segment, sampled at the controller period; a plain sampled reference
(:meth:`Trajectory.from_samples`) or a held pose (:meth:`Trajectory.hold`). SI units (m, s)."""
import math
from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np

from ..core.errors import ArgumentTypeError, Pm2dofError
from ..core.model_file import read_model_file
from ..core.paths import DEFAULT_MODEL_NAME, SHIPPED_MODELS
from ..core.task import orientation_length

__all__ = ["TrajectoryError", "SCurve", "Trajectory", "require_trajectory", "line", "line_profile",
           "model_move", "line_moves",
           "PAPER_MOVES",
           "paper_move"]


class TrajectoryError(Pm2dofError, ValueError):
    """Invalid trajectory request (bad limit, period, length, point or name)."""


def _positive(name, value, zero_ok=False):
    """Return ``value`` as a float, or raise unless it is finite and > 0 (>= 0 if ``zero_ok``)."""
    try:
        x = float(value)
    except (TypeError, ValueError):
        x = math.nan
    if not (math.isfinite(x) and (x > 0.0 or (zero_ok and x == 0.0))):
        raise TrajectoryError(f"{name} must be a finite number {'>=' if zero_ok else '>'} 0, "
                              f"got {value!r}")
    return x


@dataclass(frozen=True)
class SCurve:
    """Time-optimal rest-to-rest jerk-limited 1-D profile over a distance ``L``.

    Attributes
    ----------
    L : float
        Distance travelled, m (> 0).
    v_max, a_max, j_max : float
        Limits on speed (m/s), acceleration (m/s^2) and jerk (m/s^3).
    t_j, t_a, t_v : float
        Durations (s) of each jerk segment (4 of them), each constant-acceleration
        segment (2) and the cruise segment (1); ``t_a`` or ``t_v`` may be 0.
    v_peak, a_peak : float
        Peak speed (m/s) and acceleration (m/s^2) actually reached.
    """

    L: float
    v_max: float
    a_max: float
    j_max: float
    t_j: float
    t_a: float
    t_v: float
    v_peak: float
    a_peak: float

    @classmethod
    def plan(cls, L, v_max, a_max, j_max):
        """Plan the time-optimal profile; every limit must be finite and > 0.

        Parameters
        ----------
        L : float
            Distance, m.
        v_max, a_max, j_max : float
            Speed (m/s), acceleration (m/s^2) and jerk (m/s^3) limits.
        """
        L = _positive("L (path length, m)", L)
        v = _positive("v_max (m/s)", v_max)
        a = _positive("a_max (m/s^2)", a_max)
        j = _positive("j_max (m/s^3)", j_max)
        if v * j >= a * a:  # a_max is reached while accelerating to v_max
            t_j, t_a, a_p = a / j, max(v / a - a / j, 0.0), a
        else:
            t_j, t_a = math.sqrt(v / j), 0.0
            a_p = j * t_j
        L_v = v * (2.0 * t_j + t_a)  # shortest distance with v_max reached
        if L >= L_v:
            return cls(L, v, a, j, t_j, t_a, L / v - (2.0 * t_j + t_a), v, a_p)
        if L >= 2.0 * a**3 / j**2:  # no cruise, a_max still reached
            t_j = a / j
            v_p = 2.0 * L / (t_j + math.sqrt(t_j * t_j + 4.0 * L / a))  # v^2/a + t_j v = L
            return cls(L, v, a, j, t_j, max(v_p / a - t_j, 0.0), 0.0, v_p, a)
        t_j = (L / (2.0 * j)) ** (1.0 / 3.0)  # no limit reached: L = 2 j t_j^3
        return cls(L, v, a, j, t_j, 0.0, 0.0, j * t_j * t_j, j * t_j)

    @property
    def duration(self):
        """Total move time, s: ``4 t_j + 2 t_a + t_v``."""
        return 4.0 * self.t_j + 2.0 * self.t_a + self.t_v

    def evaluate(self, t):
        """Position, speed, acceleration and jerk of the path parameter at times ``t``.

        Parameters
        ----------
        t : array_like, shape (...)
            Times, s. Before 0 the profile is at rest at 0, after ``duration`` at
            rest at ``L``.

        Returns
        -------
        s, sd, sdd, sddd : ndarray, shape (...)
            In m, m/s, m/s^2 and m/s^3. Closed-form per segment; the second half
            is the point reflection of the first, so ``s(duration) == L`` exactly.
        """
        t = np.asarray(t, dtype=np.float64)
        T, j, a_p, v_p = self.duration, self.j_max, self.a_peak, self.v_peak
        t1, t3 = self.t_j, 2.0 * self.t_j + self.t_a
        v1, s3 = 0.5 * j * t1 * t1, 0.5 * v_p * t3
        tc = np.clip(t, 0.0, T)
        second = tc > 0.5 * T
        m = np.where(second, T - tc, tc)  # time within the first half
        r = t3 - m  # time left to the end of the acceleration phase
        u = m - t1  # time into the constant-acceleration segment
        seg = np.select([m < t1, m < t1 + self.t_a, m < t3], [0, 1, 2], 3)
        s = np.choose(seg, [j * m**3 / 6.0, j * t1**3 / 6.0 + v1 * u + 0.5 * a_p * u * u,
                            s3 - v_p * r + j * r**3 / 6.0, s3 + v_p * (m - t3)])
        sd = np.choose(seg, [0.5 * j * m * m, v1 + a_p * u, v_p - 0.5 * j * r * r, v_p])
        sdd = np.choose(seg, [j * m, a_p, j * r, 0.0])
        sddd = np.choose(seg, [j, 0.0, -j, 0.0])
        s = np.where(second, self.L - s, s)
        sdd = np.where(second, -sdd, sdd)
        sddd = np.where((t < 0.0) | (t > T), 0.0, sddd)
        return s, sd, sdd, sddd


@dataclass(frozen=True, eq=False)
class Trajectory:
    """Sampled desired task-space motion.

    Plain samples: a line's end points and S-curve belong to its plan (:func:`line_profile`,
    a :class:`pm2dof.planning.Plan`'s ``path`` and ``profile``), not to its samples.

    Attributes
    ----------
    t : ndarray, shape (N,)
        Sample times ``k * period``, s.
    xd, xd_dot, xd_ddot : ndarray, shape (N, m)
        Desired position (m), velocity (m/s) and acceleration (m/s^2); m (the task
        dimension) is taken from ``xd``.
    period : float
        Sampling period, s.
    """

    t: np.ndarray = field(repr=False)
    xd: np.ndarray = field(repr=False)
    xd_dot: np.ndarray = field(repr=False)
    xd_ddot: np.ndarray = field(repr=False)
    period: float

    def __post_init__(self):  # store read-only float64 C-contiguous copies
        n = np.size(self.t)
        if n == 0:
            raise TrajectoryError("a trajectory needs at least one sample (t is empty)")
        if np.ndim(self.xd) != 2:
            raise TrajectoryError(f"xd must have shape (N, m), m the task dimension, got "
                                  f"{np.shape(self.xd)}")
        m = np.shape(self.xd)[1]                                   # the task dimension
        for name, shape in [("t", (n,)), ("xd", (n, m)), ("xd_dot", (n, m)), ("xd_ddot", (n, m))]:
            arr = np.array(getattr(self, name), dtype=np.float64, order="C")
            if arr.shape != shape:
                raise TrajectoryError(f"{name} must have shape {shape}, got {arr.shape}")
            arr.setflags(write=False)
            object.__setattr__(self, name, arr)
        period = _positive("period (s)", self.period)
        gaps = np.diff(self.t)                    # simulate and the controllers use period only
        bad = np.flatnonzero(~(np.abs(gaps - period) <= 1e-9 * period))
        if bad.size:
            k = int(bad[0])
            raise TrajectoryError(f"t must be sampled every period = {period} s; t[{k + 1}] - "
                                  f"t[{k}] = {gaps[k]:.9g} s")

    @classmethod
    def from_samples(cls, xd, xd_dot, xd_ddot, period):
        """A plain sampled reference of any task dimension m (taken from ``xd``).

        Parameters
        ----------
        xd, xd_dot, xd_ddot : array_like, shape (N, m)
            Desired pose (m; rad for an orientation), velocity (m/s) and acceleration (m/s^2)
            at t = k * period, k = 0 .. N-1.
        period : float
            Sampling period, s (> 0).

        Returns
        -------
        Trajectory

        Raises
        ------
        TrajectoryError
            A bad period, mismatched shapes or a non-finite sample (names the array and the
            sample).
        """
        period = _positive("period (s)", period)
        arrays = []
        for name, a in (("xd", xd), ("xd_dot", xd_dot), ("xd_ddot", xd_ddot)):
            try:
                a = np.asarray(a, dtype=np.float64)
            except (TypeError, ValueError):
                raise TrajectoryError(f"{name} must be an (N, m) array of numbers") from None
            if a.ndim != 2 or a.shape[1] == 0:
                raise TrajectoryError(f"{name} must have shape (N, m), got {a.shape}")
            if not np.all(np.isfinite(a)):
                k = int(np.flatnonzero(~np.all(np.isfinite(a), axis=1))[0])
                raise TrajectoryError(f"{name} must be finite; sample {k} is {a[k].tolist()}")
            arrays.append(a)
        return cls(np.arange(len(arrays[0])) * period, *arrays, period)

    @classmethod
    def hold(cls, x, duration, period):
        """Hold one pose: ceil(duration / period) + 1 samples at t = k * period, zero velocity
        and acceleration.

        Parameters
        ----------
        x : array_like, shape (m,)
            The pose held, m (rad for an orientation).
        duration : float
            How long, s (>= 0).
        period : float
            Sampling period, s (> 0).
        """
        try:
            x = np.asarray(x, dtype=np.float64)
        except (TypeError, ValueError):
            raise TrajectoryError(f"x must be a point of the task space, m, got {x!r}") from None
        if x.ndim != 1 or x.size == 0 or not np.all(np.isfinite(x)):
            raise TrajectoryError(f"x must be a finite point (m,) of the task space, m, got "
                                  f"{x.tolist()}")
        period = _positive("period (s)", period)
        k = math.ceil(_positive("duration (s)", duration, zero_ok=True) / period - 1e-9)
        zeros = np.zeros((k + 1, x.size))
        return cls.from_samples(np.broadcast_to(x, zeros.shape), zeros, zeros, period)

    @property
    def duration(self):
        """Time from the first sample to the last, (N - 1) * period, s (a line's S-curve may end
        up to one period earlier: :func:`line_profile` gives its own duration)."""
        return (len(self.t) - 1) * self.period

    def extended(self, settle_time):
        """Copy with rest samples at the last sample (a line's ``end``) appended for at least
        ``settle_time`` s.

        Parameters
        ----------
        settle_time : float
            Extra time, s (finite, >= 0); ``ceil(settle_time / period)`` samples are added.
        """
        ts = _positive("settle_time (s)", settle_time, zero_ok=True)
        k = math.ceil(ts / self.period - 1e-9)  # tolerate 0.1/0.002 = 50.000000000000004
        zeros = np.zeros((k, self.xd.shape[1]))
        return Trajectory(np.arange(len(self.t) + k) * self.period,
                          np.vstack([self.xd, np.broadcast_to(self.xd[-1], zeros.shape)]),
                          np.vstack([self.xd_dot, zeros]), np.vstack([self.xd_ddot, zeros]),
                          self.period)


def require_trajectory(trajectory):
    """``trajectory``, or ArgumentTypeError unless it is a :class:`Trajectory`: the one check
    of every function that takes one."""
    if not isinstance(trajectory, Trajectory):
        raise ArgumentTypeError(f"trajectory must be a pm2dof.Trajectory (pm2dof.paper_move, "
                                f"pm2dof.model_move, Trajectory.from_samples, a Plan's "
                                f".trajectory), got {type(trajectory).__name__}")
    return trajectory


def _point(name, p):
    """Validate a task point (x, y) or (x, y, phi), returning it as a tuple of floats."""
    try:
        arr = np.asarray(p, dtype=np.float64)
    except (TypeError, ValueError):
        raise TrajectoryError(f"{name} must be a point (x, y) in m, got {p!r}") from None
    if arr.shape not in ((2,), (3,)) or not np.all(np.isfinite(arr)):
        raise TrajectoryError(f"{name} must be a finite point (x, y) in m of shape (2,), or "
                              f"(x, y, phi) of shape (3,) for a platform, got {p!r}")
    return tuple(float(v) for v in arr)


def _segment(start, end, v_max, a_max, j_max, orientation_length):
    """The validated end points (tuples) and the :class:`SCurve` of the line from start to end."""
    p0, p1 = _point("start", start), _point("end", end)
    if len(p0) != len(p1):
        raise TrajectoryError(f"start {p0} of shape ({len(p0)},) and end {p1} of shape "
                              f"({len(p1)},) must both be (x, y) or both (x, y, phi)")
    scale = (1.0, 1.0)                         # arc length: phi in units of orientation_length
    if len(p0) == 3:
        if orientation_length is None:
            raise TrajectoryError("a line in (x, y, phi) needs orientation_length, the length in "
                                  "m that turns phi into arc length (docs/planning.md)")
        scale += (_positive("orientation_length (m)", orientation_length),)
    L = math.hypot(*((b - a) * w for a, b, w in zip(p0, p1, scale, strict=True)))
    if L == 0.0:
        raise TrajectoryError(f"start and end coincide at {p0}: zero path length")
    return p0, p1, SCurve.plan(L, v_max, a_max, j_max)


def line_profile(start, end, v_max, a_max, j_max, orientation_length=None):
    """The S-curve of the arc length that :func:`line` samples (its kinematic plan).

    Parameters
    ----------
    start, end : array_like, shape (m,)
        As :func:`line`.
    v_max, a_max, j_max : float
        As :func:`line`.
    orientation_length : float, optional
        As :func:`line`.

    Returns
    -------
    SCurve
        Its ``L`` is the segment's arc length (m) and its ``duration`` the move's own (s), which
        the samples' last time ``ceil(duration / period) * period`` rounds up.
    """
    return _segment(start, end, v_max, a_max, j_max, orientation_length)[2]


def line(start, end, v_max, a_max, j_max, period=0.002, orientation_length=None):
    """S-curve motion along the straight segment from ``start`` to ``end``.

    Parameters
    ----------
    start, end : array_like, shape (m,)
        End points (x, y) in m, or (x, y, phi) for a platform (phi in rad); they must differ.
    v_max, a_max, j_max : float
        Limits along the path: m/s, m/s^2, m/s^3.
    period : float, optional
        Sampling period, s (default 2 ms).
    orientation_length : float, optional
        For (x, y, phi) points only, and required there: the length l, m, that turns phi into
        arc length, L = sqrt(|p1 - p0|^2 + (l dphi)^2) (the arc length of
        :class:`pm2dof.TaskPath`, docs/planning.md; :func:`model_move` takes the model's
        :func:`pm2dof.core.task.orientation_length`). phi moves in proportion to x and y, and
        an equal (x, y) gives a pure rotation.

    Returns
    -------
    Trajectory
        Samples at ``k * period``, ``k = 0 .. ceil(duration / period)``; the last
        one is at rest at ``end`` exactly. The S-curve itself: :func:`line_profile`.
    """
    period = _positive("period (s)", period)
    p0, p1, prof = _segment(start, end, v_max, a_max, j_max, orientation_length)
    L = prof.L
    n = math.ceil(prof.duration / period)
    n += int(n * period < prof.duration)  # guard against rounding in the division
    t = np.arange(n + 1) * period
    s, sd, sdd, _ = prof.evaluate(t)
    a, b = np.array(p0), np.array(p1)
    lam = (s / L)[:, None]
    u = (b - a) / L
    xd = (1.0 - lam) * a + lam * b  # exact at both ends (lam = 0 and lam = 1)
    xd_dot, xd_ddot = sd[:, None] * u + 0.0, sdd[:, None] * u + 0.0  # + 0.0: no -0.0
    return Trajectory(t, xd, xd_dot, xd_ddot, period)


def line_moves(model):
    """Names of the model file's line moves (``start``, ``end``): what :func:`model_move`
    samples. A move that names a path file (``path = ...``) is planned by pm2dof.planning.
    ``model``: a Model."""
    return _line_moves(model.spec)


def _line_moves(spec):
    """:func:`line_moves` of a model file's ``spec`` (a ModelSpec)."""
    return tuple(k for k, t in spec.trajectories.items() if "path" not in t)


def _move_arguments(spec, name):
    """Keyword arguments of :func:`line` for the model file's ``[trajectories.<name>]``."""
    moves = spec.trajectories
    if not isinstance(name, str) or name not in moves:
        raise TrajectoryError(f"no move {name!r} in [trajectories] of {spec.path}; have "
                              f"{sorted(moves)}")
    t = moves[name]
    if "path" in t:
        raise TrajectoryError(
            f"move {name!r} of {spec.path} follows the path {t['path']!r}: time it with "
            f"`pm2dof plan --move {name}`, or pm2dof.planning.model_move_path(model, {name!r}) "
            f"and plan_kinematic / plan_time_optimal (its trajectory simulates as any other)")
    return MappingProxyType({"start": tuple(float(v) for v in t["start"]),
                             "end": tuple(float(v) for v in t["end"]),
                             **{k: float(t[k]) for k in ("v_max", "a_max", "j_max")}})


def model_move(model, name, period=None):
    """The move ``[trajectories.<name>]`` of a model file: its S-curve line, sampled.

    The one reader of a model file's moves (the paper's, in ``shang2010``, are its
    ``low`` and ``high``).

    Parameters
    ----------
    model : Model
    name : str
        A key of the model file's ``[trajectories]``.
    period : float, optional
        Sampling period, s (default ``[sensing] sample_period``).

    Raises
    ------
    TrajectoryError
        No such move (the message lists the file's moves).
    """
    spec = model.spec
    return line(**_move_arguments(spec, name),
                period=spec.sensing["sample_period"] if period is None else period,
                orientation_length=orientation_length(model))


def _paper_moves():
    """The paper's moves, read from the shipped model file of the paper's robot."""
    spec = read_model_file(SHIPPED_MODELS / f"{DEFAULT_MODEL_NAME}.toml")
    return MappingProxyType({k: _move_arguments(spec, k) for k in _line_moves(spec)})


#: read-only {name: keyword arguments of line()}: the paper's low- and high-speed moves (Sect. 5),
#: as the shipped model file ``shang2010`` writes them (their one home)
PAPER_MOVES = _paper_moves()


def paper_move(speed, period=0.002):
    """Desired trajectory of the paper's low- or high-speed experiment.

    Parameters
    ----------
    speed : {"low", "high"}
        Which move of :data:`PAPER_MOVES` (the shipped ``shang2010`` model file's moves).
    period : float, optional
        Sampling period, s.
    """
    if not isinstance(speed, str) or speed not in PAPER_MOVES:
        raise TrajectoryError(f"unknown speed {speed!r}; valid names: {sorted(PAPER_MOVES)}")
    return line(**PAPER_MOVES[speed], period=period)
