# Task-space paths parameterised by arc length: lines, arcs, blended polylines, C2 splines, joins,
# and for a platform the orientation along them.
"""Geometric paths p(s) of the end-effector, s the arc length (m), 0 <= s <= ``length``.

A :class:`TaskPath` is a chain of pieces (line, circular arc, C2 spline); ``evaluate(s)``
returns p(s), p'(s) (unit tangent) and p''(s) (curvature vector). Where two pieces meet with
different tangents the robot must be at rest: those arc lengths are the path's ``stops``
(the ends always are). ``breakpoints`` are all piece junctions: the planner puts a grid point
on each, so no grid interval straddles a jump of curvature.

A path has the task dimension ``dim`` of its points: 2 (x, y) for a point end effector, 3
(x, y, phi) for a platform. **Arc length with an orientation** (docs/using-planning.md): s is the
length in the metric ds^2 = dx^2 + dy^2 + (l dphi)^2, where l (m, ``orientation_length``)
turns an angle into a length; for a model, :func:`pm2dof.core.task.orientation_length` (the
platform's radius, the largest distance of an attachment point from the platform frame's
origin: ds/dt then bounds every attachment point's speed within a factor sqrt(2)). Along each
piece phi is linear in the position's arc length, so a piece of planar length L_p turning by
dphi has length sqrt(L_p^2 + (l dphi)^2), and a pure rotation (L_p = 0) has length l |dphi|.
The tangent p'(s) is a unit vector in that metric; p'' (x, y rows 1/m, phi row 1/m^2) is the
planar piece's curvature scaled by (L_p / L)^2.
"""
import math
import numbers

import numpy as np

from ..core.errors import ArgumentTypeError, PlanError
from . import _pathc
from .pathtable import pack
from .spline import SplinePiece

__all__ = ["TaskPath", "point_text", "gap_message"]

GAP = 1e-9          # m: largest gap between pieces that concat() accepts
_TANGENT = 1e-9     # |t_out - t_in| above this: a corner (a stop)


def point_text(p):
    """A task point for messages: (x, y) m, or a platform's (x, y, phi) m, rad."""
    return f"({', '.join(f'{v:.6g}' for v in p)}) m" + (", rad" if len(p) == 3 else "")


def _is_real(v):
    """A real number: not a bool (TOML's true is no coordinate), not text, not complex."""
    return isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_))


def _non_number(p):
    """(v,): the first entry of the nested sequences ``p`` that is not a real number, or ()."""
    if isinstance(p, np.ndarray) and p.dtype != object:
        return () if p.dtype.kind in "iuf" else (p,)
    if isinstance(p, np.ndarray) and p.ndim == 0:       # a 0-d object array: its one entry
        return _non_number(p.item())
    if isinstance(p, (list, tuple, np.ndarray)):
        return next((bad for v in p for bad in [_non_number(v)] if bad), ())
    return () if _is_real(p) else (p,)


def _array(name, p, want):
    """``p`` (nested sequences of real numbers, or a numeric ndarray) as a float array;
    PlanError "``name`` must be ``want``" naming a bool, a text, a complex number or ragged
    nesting, before NumPy would coerce it or refuse it with its own error."""
    if not isinstance(p, (list, tuple, np.ndarray)) and not _is_real(p):
        raise PlanError(f"{name} must be {want}, got {type(p).__name__} {p!r}")
    bad = _non_number(p)
    if bad:
        raise PlanError(f"{name} must be {want}, got {p!r}: {bad[0]!r} "
                        f"({type(bad[0]).__name__}) is not a number")
    try:
        return np.array(p, dtype=float)
    except OverflowError:       # an int beyond float's range (10**400): not finite
        raise PlanError(f"{name} must be {want}, got {p!r}: a number beyond float's "
                        f"range") from None
    except ValueError:
        raise PlanError(f"{name} must be {want}, got {p!r}: ragged (rows of different "
                        f"lengths)") from None


def _point(name, p, dims=(2,), want=None):
    """A finite point of ``dims`` coordinates; ``want`` describes it in the message (default
    (x, y) in m, or (x, y, phi) in m and rad)."""
    if want is None:
        want = "a finite point (x, y)" + (" or (x, y, phi), m and rad" if 3 in dims
                                          else " in m")
    a = _array(name, p, want)
    if a.ndim != 1 or a.size not in dims or not np.isfinite(a).all():
        raise PlanError(f"{name} must be {want}, got {p!r}")
    return a


def _orientation_length(value):
    """The length l (m) that converts phi to arc length: required for a path with phi."""
    if value is None:
        raise PlanError("a path with an orientation (x, y, phi) needs orientation_length, the "
                        "length l in m that turns phi into arc length (ds^2 = dx^2 + dy^2 + "
                        "(l dphi)^2); for a model: pm2dof.core.task.orientation_length(model)")
    return _number("orientation_length (m)", value, positive=True)


def _number(name, x, positive=False, nonnegative=False):
    try:
        v = float(x) if _is_real(x) or (isinstance(x, np.ndarray) and x.dtype.kind in "iuf"
                                        and x.ndim == 0) else math.nan
    except (TypeError, ValueError, OverflowError):     # OverflowError: an int like 10**400
        v = math.nan
    if not math.isfinite(v) or (positive and v <= 0) or (nonnegative and v < 0):
        want = " > 0" if positive else " >= 0" if nonnegative else ""
        got = repr(x) if _is_real(x) else f"{type(x).__name__} {x!r}"   # a bool, a text
        raise PlanError(f"{name} must be a finite number{want}, got {got}")
    return v


class _Line:
    kind = "line"

    def __init__(self, p0, p1):
        self.p0, self.p1 = p0, p1
        self.length = float(np.hypot(*(p1 - p0)))
        self.u = (p1 - p0) / self.length

    def evaluate(self, s):
        """p, dp, ddp (len(s), 2) at its own arc lengths ``s``, in NumPy: the formulas
        _pathc.c evaluates (TaskPath.evaluate), kept as its reference."""
        lam = (s / self.length)[:, None]
        k = len(s)
        p = (1.0 - lam) * self.p0 + lam * self.p1      # as pm2dof.line: exact at both ends
        return p, np.broadcast_to(self.u, (k, 2)).copy(), np.zeros((k, 2))


class _Arc:
    kind = "arc"

    def __init__(self, center, radius, a0, a1):
        self.c, self.r, self.a0 = center, radius, a0
        self.d = 1.0 if a1 > a0 else -1.0
        self.length = radius * abs(a1 - a0)

    def evaluate(self, s):
        """p, dp, ddp (len(s), 2) at its own arc lengths ``s`` (as :meth:`_Line.evaluate`)."""
        phi = self.a0 + self.d * s / self.r
        e = np.stack([np.cos(phi), np.sin(phi)], axis=1)
        dp = np.stack([self.d * -e[:, 1], self.d * e[:, 0]], axis=1)
        return self.c + self.r * e, dp, -e / self.r


class _Oriented:
    """A planar piece (or a fixed point, for a pure rotation) with phi linear in its planar arc
    length, parameterised by the metric arc length of the module docstring."""

    def __init__(self, planar, point, phi0, phi1, ell):
        self.planar, self.point, self.phi0, self.dphi = planar, point, phi0, phi1 - phi0
        self.kind = planar.kind if planar is not None else "rotation"
        lp = planar.length if planar is not None else 0.0
        self.length = math.hypot(lp, ell * self.dphi)
        self.c = lp / self.length                       # d(planar arc length) / ds

    def evaluate(self, s):
        k = len(s)
        p, dp, ddp = np.empty((k, 3)), np.empty((k, 3)), np.zeros((k, 3))
        if self.planar is None:
            p[:, :2], dp[:, :2] = self.point, 0.0
        else:
            p[:, :2], dp[:, :2], ddp[:, :2] = self.planar.evaluate(self.c * s)
            dp[:, :2] *= self.c
            ddp[:, :2] *= self.c * self.c
        p[:, 2] = self.phi0 + self.dphi * (s / self.length)
        dp[:, 2] = self.dphi / self.length
        return p, dp, ddp


_PIECES = (_Line, _Arc, SplinePiece, _Oriented)


def _oriented(planar, point, phi0, phi1, orientation_length):
    """The piece with orientation: phi from phi0 to phi1 along ``planar`` (None: a rotation
    at ``point``)."""
    ell = _orientation_length(orientation_length)
    return _Oriented(planar, point, float(phi0), float(phi1), ell)


class TaskPath:
    """A path in the task plane, parameterised by arc length. Immutable; build it with
    :meth:`line`, :meth:`arc`, :meth:`polyline`, :meth:`spline` or :meth:`concat`.

    Attributes
    ----------
    length : float
        Arc length, m.
    dim : int
        Task dimension of the points: 2 (x, y) or 3 (x, y, phi; arc length as in the module
        docstring).
    start, end : ndarray (dim,)
        First and last point, m (phi in rad).
    breakpoints : ndarray
        Arc lengths of the piece junctions, 0 and ``length`` included, m.
    stops : ndarray
        Arc lengths where the tangent jumps (a sharp corner or a reversal): the robot must be
        at rest there. 0 and ``length`` included, m.
    kinds : tuple of str
        The pieces, in order ("line", "arc", "spline").

    Examples
    --------
    >>> import numpy as np, pm2dof
    >>> path = pm2dof.TaskPath.line([0.22, 0.29], [0.27, 0.24])
    >>> p, dp, ddp = path.evaluate(np.array([0.0, path.length]))
    >>> p.round(6).tolist(), round(path.length, 6)
    ([[0.22, 0.29], [0.27, 0.24]], 0.070711)
    """

    __slots__ = ("_pieces", "_ends", "_stops", "_table")

    def __init__(self, pieces, stop_junctions=()):
        """``pieces``: one or more line/arc/spline pieces in order (as the constructors make
        them); ``stop_junctions``: indices j of the junctions (arc length ``breakpoints[j]``)
        where the robot must rest. PlanError for no pieces or a junction index out of range,
        ArgumentTypeError for anything else than pieces.

        Parameters
        ----------
        pieces : sequence of pieces
            The line, arc and spline pieces in order, each starting where the one before
            ends.
        stop_junctions : sequence of int, optional
            Indices j of the junctions (between piece j and j + 1) where the robot rests.
        """
        try:
            pieces = tuple(pieces)
        except TypeError:
            pieces = (pieces,)
        if not pieces:
            raise PlanError("a TaskPath needs one or more pieces, got none: build paths with "
                            "TaskPath.line, .arc, .polyline, .spline or .concat")
        bad = [type(pc).__name__ for pc in pieces if not isinstance(pc, _PIECES)]
        if bad:
            raise ArgumentTypeError(f"TaskPath pieces must be lines, arcs or splines as "
                                    f"TaskPath.line, .arc, .polyline, .spline make them, got "
                                    f"{bad}")
        dims = sorted({3 if isinstance(pc, _Oriented) else 2 for pc in pieces})
        if len(dims) > 1:
            raise PlanError("a TaskPath's pieces must all have an orientation (x, y, phi) or "
                            "none (x, y), got both")
        try:
            junctions = np.asarray(stop_junctions, dtype=int).ravel()
        except (TypeError, ValueError):
            junctions = np.array([-1])
        if ((junctions < 0) | (junctions > len(pieces))).any():
            raise PlanError(f"stop_junctions must be junction indices from 0 to {len(pieces)}, "
                            f"got {stop_junctions!r}")
        object.__setattr__(self, "_pieces", pieces)
        ends = np.concatenate([[0.0], np.cumsum([pc.length for pc in pieces])])
        ends.setflags(write=False)
        object.__setattr__(self, "_ends", ends)
        st = np.unique(np.concatenate([[0, len(pieces)], junctions]))
        object.__setattr__(self, "_stops", st)
        dim = 3 if isinstance(pieces[0], _Oriented) else 2
        object.__setattr__(self, "_table", pack(pieces, ends, dim))   # for _pathc.evaluate

    def __setattr__(self, key, value):
        raise AttributeError(f"TaskPath is immutable (tried to set {key!r})")

    def __reduce__(self):       # pickle (Dask, multiprocessing): rebuilt from its pieces
        return TaskPath, (self._pieces, self._stops.tolist())

    length = property(lambda self: float(self._ends[-1]), doc="arc length, m")
    breakpoints = property(lambda self: self._ends, doc="piece junctions (arc lengths), m")
    stops = property(lambda self: self._ends[self._stops],
                     doc="arc lengths where the robot must rest, m")
    kinds = property(lambda self: tuple(pc.kind for pc in self._pieces))
    dim = property(lambda self: 3 if isinstance(self._pieces[0], _Oriented) else 2,
                   doc="task dimension of the points: 2 (x, y) or 3 (x, y, phi)")
    start = property(lambda self: self.evaluate(np.zeros(1))[0][0])
    end = property(lambda self: self.evaluate(np.array([self.length]))[0][0])

    def __repr__(self):
        return (f"<TaskPath {'+'.join(self.kinds)}: {self.length:.6g} m, "
                f"{len(self._stops) - 2} interior stop(s)>")

    def evaluate(self, s, side="right"):
        """p(s), p'(s), p''(s) at arc lengths ``s``.

        Parameters
        ----------
        s : array_like (k,) or float
            Arc lengths, m, within [0, ``length``] (rounding beyond the ends is clipped).
        side : {"right", "left"}
            At a junction of two pieces, the following piece (the derivatives leaving the
            junction) or the preceding one (arriving at it).

        Returns
        -------
        p, dp, ddp : ndarray (k, dim)
            Position (m; phi in rad), unit tangent (1; phi's entry rad/m) and curvature
            vector p'' (1/m).
        """
        try:
            s = np.atleast_1d(np.asarray(s, dtype=float))
        except (TypeError, ValueError):
            raise PlanError(f"arc lengths s must be finite numbers (m), got {s!r}") from None
        L = self.length
        if s.ndim != 1:
            raise PlanError(f"arc lengths s must be a 1-D array, got shape {s.shape}")
        if not np.isfinite(s).all():
            k = int(np.flatnonzero(~np.isfinite(s))[0])
            raise PlanError(f"arc lengths s must be finite, got s[{k}] = {float(s[k])}")
        tol = 1e-9 * max(L, 1.0)
        bad = (s < -tol) | (s > L + tol)
        if bad.any():
            raise PlanError(f"arc length s = {float(s[bad][0]):.9g} m is outside the path "
                            f"[0, {L:.9g}] m")
        if side not in ("right", "left"):
            raise PlanError(f"side must be 'right' or 'left', got {side!r}")
        out = tuple(np.empty((len(s), self.dim)) for _ in range(3))
        _pathc.evaluate(self._table, np.ascontiguousarray(s), side == "right", *out)
        return out

    # --- constructors -----------------------------------------------------------------
    @classmethod
    def line(cls, p0, p1, orientation_length=None):
        """The straight segment from ``p0`` to ``p1`` (each (2,), m; distinct).

        With an orientation, each is (x, y, phi) (m, rad) and ``orientation_length`` l (m) is
        required: phi turns linearly along the segment; equal positions give a pure rotation
        about (x, y) of length l |phi1 - phi0| (module docstring).

        Parameters
        ----------
        p0, p1 : array_like (2,) or (3,)
            Start and end, (x, y) m or (x, y, phi) (m, rad).
        orientation_length : float, optional
            l, m: the length a turn of phi counts for in the arc length (s = l |dphi| for a
            pure rotation); required with an orientation, else unused.
        """
        a, b = _point("p0", p0, (2, 3)), _point("p1", p1, (2, 3))
        if a.size != b.size:
            raise PlanError(f"line: p0 {point_text(a)} and p1 {point_text(b)} must both be "
                            f"(x, y) or both (x, y, phi)")
        if np.array_equal(a, b):
            raise PlanError(f"line: p0 and p1 coincide at {point_text(a)}: zero length")
        if a.size == 3:
            planar = _Line(a[:2], b[:2]) if not np.array_equal(a[:2], b[:2]) else None
            return cls([_oriented(planar, a[:2], a[2], b[2], orientation_length)])
        return cls([_Line(a, b)])

    @classmethod
    def arc(cls, center, radius, angle0, angle1, phi=None, orientation_length=None):
        """The circular arc around ``center`` (2,) m of ``radius`` m from ``angle0`` to
        ``angle1`` (rad, from +x; counter-clockwise if angle1 > angle0, else clockwise).

        ``phi`` = (phi0, phi1), rad: a platform's orientation, linear along the arc (then
        ``orientation_length`` is required, see :meth:`line`).

        Parameters
        ----------
        center : array_like (2,)
            The arc's centre, m.
        radius : float
            m, > 0.
        angle0, angle1 : float
            Start and end angles, rad, from +x.
        phi : array_like (2,), optional
            (phi0, phi1), rad: the orientation at the start and the end; None for an (x, y)
            path.
        orientation_length : float, optional
            l, m: the length a turn of phi counts for in the arc length (s = l |dphi| for a
            pure rotation); required with an orientation, else unused.
        """
        c = _point("center", center)
        r = _number("radius (m)", radius, positive=True)
        a0, a1 = _number("angle0 (rad)", angle0), _number("angle1 (rad)", angle1)
        if a0 == a1:
            raise PlanError(f"arc: angle0 == angle1 == {a0}: zero length")
        if phi is None:
            return cls([_Arc(c, r, a0, a1)])
        f0, f1 = _point("phi", phi, want="(phi0, phi1): the orientation at the start and the "
                        "end, two finite angles in rad")
        return cls([_oriented(_Arc(c, r, a0, a1), None, f0, f1, orientation_length)])

    @classmethod
    def polyline(cls, points, blend_radius=0.0, orientation_length=None):
        """Straight segments through ``points`` (m, 2), m >= 2, each corner blended by a
        circular arc of ``blend_radius`` m tangent to both segments (C1; the curvature jumps
        at the tangent points). ``blend_radius = 0``: sharp corners, where the robot stops.

        Points (m, 3) (x, y, phi) give segments with orientation (:meth:`line`, which needs
        ``orientation_length``), each corner a stop: blending is for (x, y) paths only.

        Raises PlanError for repeated points, a blend that does not fit between two corners
        (names the segment and the largest radius that fits) or a corner that turns back
        (180 degrees: no arc is tangent to both; stop there with blend_radius 0).

        Parameters
        ----------
        points : array_like (m, 2) or (m, 3)
            The corners, (x, y) m or (x, y, phi) (m, rad), m >= 2.
        blend_radius : float
            Radius of the corner arcs, m, >= 0 (0: sharp corners, stops).
        orientation_length : float, optional
            l, m: the length a turn of phi counts for in the arc length (s = l |dphi| for a
            pure rotation); required with an orientation, else unused.
        """
        want = "a finite (m, 2) or (m, 3) array with m >= 2"
        P = _array("polyline: points", points, want)
        if P.ndim == 2 and P.shape[1] == 3 and len(P) >= 2:
            if _number("blend_radius (m)", blend_radius, nonnegative=True) != 0.0:
                raise PlanError("polyline: blend_radius applies to (x, y) points only; with an "
                                "orientation (x, y, phi) use blend_radius=0 (stops at corners)")
            return cls.concat(*[cls.line(P[i], P[i + 1], orientation_length)
                                for i in range(len(P) - 1)])
        if P.ndim != 2 or P.shape[1:] != (2,) or len(P) < 2 or not np.isfinite(P).all():
            raise PlanError(f"polyline: points must be {want}, got {points!r}")
        r = _number("blend_radius (m)", blend_radius, nonnegative=True)
        seg = np.diff(P, axis=0)
        lens = np.hypot(*seg.T)
        if (lens == 0).any():
            i = int(np.argmax(lens == 0))
            raise PlanError(f"polyline: points {i + 1} and {i + 2} coincide at "
                            f"{point_text(P[i])} (points numbered from 1)")
        d = seg / lens[:, None]
        turn = np.array([math.atan2(d[i, 0] * d[i + 1, 1] - d[i, 1] * d[i + 1, 0],
                                    float(d[i] @ d[i + 1])) for i in range(len(d) - 1)])
        if r == 0.0:
            return cls.concat(*[cls.line(P[i], P[i + 1]) for i in range(len(P) - 1)])
        for i, phi in enumerate(turn):
            if abs(phi) > math.pi - 1e-9:
                raise PlanError(f"polyline: corner {i + 1} (point {i + 2}, "
                                f"{point_text(P[i + 1])}; corners and points numbered from 1) "
                                f"turns back (180 deg): no blend arc fits; use blend_radius=0 "
                                f"to stop there")
        cut = np.concatenate([[0.0], r * np.tan(np.abs(turn) / 2), [0.0]])   # per point
        for i in range(len(lens)):
            if cut[i] + cut[i + 1] > lens[i] * (1 + 1e-12):
                t = np.tan(np.abs(np.concatenate([[0.0], turn, [0.0]]))[[i, i + 1]] / 2).sum()
                raise PlanError(f"polyline: blend_radius {r:g} m does not fit on line {i + 1} "
                                f"(points {i + 1} -> {i + 2}, {point_text(P[i])} -> "
                                f"{point_text(P[i + 1])}, {lens[i]:.6g} m; lines and points "
                                f"numbered from 1): its corners cut {cut[i] + cut[i + 1]:.6g} m;"
                                f" at most {lens[i] / t:.6g} m fits")
        pieces, start = [], P[0]
        for i in range(len(lens)):
            end = P[i + 1] - cut[i + 1] * d[i]
            if np.hypot(*(end - start)) > GAP:
                pieces.append(_Line(start, end))
            if i < len(turn) and turn[i] != 0.0:
                phi = turn[i]
                nl = np.array([-d[i, 1], d[i, 0]])                  # left normal of the segment
                c = end + math.copysign(r, phi) * nl
                a0 = math.atan2(*(end - c)[::-1])
                pieces.append(_Arc(c, r, a0, a0 + phi))
                start = P[i + 1] + cut[i + 1] * d[i + 1]
            else:
                start = end
        return cls(pieces)

    @classmethod
    def spline(cls, waypoints):
        """A C2 cubic spline through ``waypoints`` (m, 2), m >= 2 (natural: no curvature at
        the ends; two points give the line). See :mod:`pm2dof.planning.spline`. Planar only:
        waypoints with an orientation (x, y, phi) are refused (PlanError; use
        :meth:`polyline`).

        Parameters
        ----------
        waypoints : array_like (m, 2)
            The points the spline passes through, in order, m; m >= 2, consecutive points
            distinct.
        """
        want = "a finite (m, 2) array with m >= 2"
        P = _array("spline: waypoints", waypoints, want)
        if P.ndim == 2 and P.shape[1:] == (3,):
            raise PlanError("spline: a C2 spline is planar (x, y); waypoints with an orientation "
                            "(x, y, phi) have no spline yet: use TaskPath.polyline (lines with "
                            "phi, stops at the corners)")
        if P.ndim != 2 or P.shape[1:] != (2,) or len(P) < 2 or not np.isfinite(P).all():
            raise PlanError(f"spline: waypoints must be {want}, got {waypoints!r}")
        gaps = np.hypot(*np.diff(P, axis=0).T)
        if (gaps == 0).any():
            i = int(np.argmax(gaps == 0))
            raise PlanError(f"spline: waypoints {i + 1} and {i + 2} coincide at "
                            f"{point_text(P[i])} (waypoints numbered from 1)")
        if len(P) == 2:
            return cls.line(P[0], P[1])
        return cls([SplinePiece(P)])

    @classmethod
    def concat(cls, *paths):
        """The paths one after the other. Each must start where the previous ends (within
        1e-9 m); where the tangents differ the joined path has a stop.

        Parameters
        ----------
        *paths : TaskPath
            One or more paths, all (x, y) or all (x, y, phi).
        """
        if not paths or not all(isinstance(p, TaskPath) for p in paths):
            raise PlanError(f"concat takes one or more TaskPath, got "
                            f"{[type(p).__name__ for p in paths]}")
        if len({p.dim for p in paths}) > 1:
            raise PlanError(f"concat: the paths must all be (x, y) or all (x, y, phi), got "
                            f"dimensions {[p.dim for p in paths]}")
        pieces, stops = [], []
        for k, path in enumerate(paths):
            if k:
                prev = paths[k - 1]
                _, t_out, _ = prev.evaluate(np.array([prev.length]))
                _, t_in, _ = path.evaluate(np.zeros(1))
                gap = gap_message(prev, path, f"path {k + 1}", f"path {k}")
                if gap:
                    raise PlanError(f"concat: {gap} (paths numbered from 1)")
                if np.linalg.norm(t_out[0] - t_in[0]) > _TANGENT:
                    stops.append(len(pieces))
            stops += [len(pieces) + j for j in path._stops[1:-1]]
            pieces += path._pieces
        return cls(pieces, stops)


def gap_message(before, after, name_after, name_before):
    """None if TaskPath ``after`` starts where ``before`` ends (within GAP), else the message
    "<name_after> starts at (x, y) m, <gap> m from where <name_before> ends ((x, y) m)"."""
    p0, p1 = after.start, before.end
    gap = float(np.linalg.norm(p0 - p1))
    if gap <= GAP:
        return None
    return (f"{name_after} starts at {point_text(p0)}, {gap:.3g} m from where {name_before} "
            f"ends ({point_text(p1)})")
