# The robot drawn to scale for any leg kind (RRR, PRR, RPR) and end effector (point, platform).
"""Geometry of the drawn robot, from the model file's legs and a pose.

Leg i at the joint coordinates q (2n,) = [qa, qb], as the derivation defines them
(pm2dof/derive/kinematics.py): RRR base A_i, elbow A_i + la u(qa_i), tip + lb u(qb_i); PRR the
slider A_i + qa_i d_i on its rail, tip + lb u(qb_i); RPR the leg from its base pivot A_i to
A_i + qa_i u(qb_i), qa_i its length. A platform is the polygon through its attachment points
P_i = p + R(phi) a_i.
"""
import numpy as np

from .style import label_bases

__all__ = ["anchors", "fixed_points", "draw_fixed", "leg_points", "barrels", "platform_polygon",
           "fixed_key"]


def _u(a):
    return np.array([np.cos(a), np.sin(a)])


def _rail(leg):
    """(start, end) (2, 2) of a PRR leg's rail, m."""
    return np.array([leg.base, leg.rail_end], dtype=float)


def anchors(model):
    """(n, 2) m: where each leg's name A_i is written: its base (RRR, RPR) or the middle of its
    rail (PRR: rails may share a start)."""
    return np.array([_rail(leg).mean(axis=0) if leg.kind == "PRR" else leg.base
                     for leg in model.spec.legs], dtype=float)


def fixed_points(model):
    """(k, 2) m: every fixed point drawn (bases and both ends of each rail), for the axes'
    limits."""
    pts = [_rail(leg) if leg.kind == "PRR" else np.array([leg.base], dtype=float)
           for leg in model.spec.legs]
    return np.vstack(pts)


def draw_fixed(ax, model, ms=7, fontsize=8, offset=8.0, label=None):
    """The fixed part of the robot: a triangle at each base of an RRR or RPR leg, a grey bar
    for each PRR rail, and the names A1, A2, ... beside them (:func:`anchors`). ``label``:
    legend label of the bases' markers (the first artist drawn)."""
    legs = model.spec.legs
    pivots = np.array([leg.base for leg in legs if leg.kind != "PRR"], dtype=float)
    if len(pivots):
        ax.plot(pivots[:, 0], pivots[:, 1], "k^", ms=ms, label=label)
        label = None
    for leg in legs:
        if leg.kind == "PRR":
            r = _rail(leg)
            ax.plot(r[:, 0], r[:, 1], "-", color="0.35", lw=4, solid_capstyle="butt",
                    label=label)
            label = None
    label_bases(ax, anchors(model), fontsize=fontsize, offset=offset)


def fixed_key(model, marks=True):
    """The words for :func:`draw_fixed`'s marks, e.g. "triangles: the bases A1, A2, ..." (or,
    ``marks=False``, "bases A1, A2, ...", a legend's label)."""
    kinds = {leg.kind for leg in model.spec.legs}
    if kinds == {"PRR"}:
        return "grey bars: the rails A1, A2, ..." if marks else "rails A1, A2, ..."
    if "PRR" in kinds:
        return ("triangles: the bases, grey bars: the rails (A1, A2, ...)" if marks
                else "bases and rails A1, A2, ...")
    return "triangles: the bases A1, A2, ..." if marks else "bases A1, A2, ..."


def leg_points(model, q):
    """list of n arrays (k, 2) m: the polyline of each leg's moving links at the pose q (2n,):
    RRR base -> elbow -> tip; PRR slider -> tip; RPR base pivot -> tip (the whole leg)."""
    n, out = model.n_legs, []
    for i, leg in enumerate(model.spec.legs):
        a = np.asarray(leg.base, dtype=float)
        if leg.kind == "RRR":
            b = a + leg.la * _u(q[i])
            out.append(np.array([a, b, b + leg.lb * _u(q[n + i])]))
        elif leg.kind == "PRR":
            r = _rail(leg)
            d = (r[1] - r[0]) / np.hypot(*(r[1] - r[0]))
            s = a + q[i] * d
            out.append(np.array([s, s + leg.lb * _u(q[n + i])]))
        else:
            out.append(np.array([a, a + q[i] * _u(q[n + i])]))
    return out


def barrels(model, q):
    """{leg index: (2, 2) m} the cylinder of each RPR leg at the pose q: from its base pivot
    along the leg, as long as the shortest stroke (the rod slides out of it)."""
    n = model.n_legs
    return {i: np.array([leg.base, np.asarray(leg.base, dtype=float)
                         + min(leg.stroke) * _u(q[n + i])])
            for i, leg in enumerate(model.spec.legs) if leg.kind == "RPR"}


def platform_polygon(model, xe):
    """(n, 2) m: a platform's attachment points P_i = p + R(phi) a_i at the pose xe (3,), in
    the order of their angle about their centroid (a simple polygon, drawn as the body); None
    for a point end effector."""
    if model.dof == 2:
        return None
    c, s = np.cos(xe[2]), np.sin(xe[2])
    a = np.array([leg.attach for leg in model.spec.legs], dtype=float)
    d = a - a.mean(axis=0)
    a = a[np.argsort(np.arctan2(d[:, 1], d[:, 0]))]
    return np.asarray(xe[:2], dtype=float) + a @ np.array([[c, s], [-s, c]])
