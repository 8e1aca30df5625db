# The two singularity measures of one pose from a model file's geometry, in NumPy (no generated C).
"""Singularity measures of a pose computed from the legs of a model file alone.

The model-file check (:func:`pm2dof.core.model_file.read_model_file`) runs before any code is
derived, so it cannot call the generated ``singularity_measures``. These are the same
measures, written again in NumPy from their definitions (docs/model-file.md,
"Singularities"; derive/kinematics.py ``leg_measure`` and ``parallel_measure``,
derive/model_functions.py ``singularity_measures``):

* type I, a leg: min over the legs of an RRR leg's |sin(qb_i - qa_i)| (its two links
  aligned), a PRR leg's |d_i . u(qb_i)| (the cosine between rail and link: zero with the link
  across the rail), an RPR leg's 1 (never singular within its stroke);
* type II, the actuation: from the lines along which the legs push, u(qb_i). Legs meeting at
  a point: sqrt(1 - |z| / n), z = sum_i exp(2 i qb_i) (0 when every distal link is parallel).
  A platform: (det U^T U)^(1/3) / (n / 3), U's rows (u(qb_i), ((R(phi) a_i) x u(qb_i)) / L)
  scaled to unit length, L the RMS distance of the attachment points a_i from the platform's
  origin (0 when the lines are concurrent or all parallel).

Each leg is placed in its model file's branch (``elbow``, ``branch``), as the generated ``ik``
places it.
"""
import math

import numpy as np

from .mechanism import attachment_points

__all__ = ["TYPE_I_MEASURES", "TYPE_II_MEASURES", "leg_lines", "pose_measures",
           "singularity_words"]

#: each leg kind's type I measure and what is singular at 0, as messages name them
TYPE_I_MEASURES = {"RRR": ("|sin(qb_i - qa_i)|", "a leg's links aligned"),
                   "PRR": ("|d_i . u(qb_i)|", "a PRR leg's link across its rail, d_i . u(qb_i) "
                                              "the cosine between them"),
                   "RPR": ("1", "none within an RPR leg's stroke")}
#: each end effector's type II measure, as messages name it
TYPE_II_MEASURES = {
    "point": "sigma_min(S with unit rows) / sqrt(n/2) = sqrt(1 - |sum_i exp(2 i qb_i)| / n)",
    "platform": "(det U^T U)^(1/3) / (n/3) of the legs' unit wrench lines U"}


def singularity_words(legs, end_effector):
    """How messages name the two singularities of a mechanism and their measures.

    Parameters
    ----------
    legs : sequence of pm2dof.core.model_file.Leg
        The model file's legs (their ``kind``).
    end_effector : str
        "point" or "platform".

    Returns
    -------
    tuple of two (str, str)
        (kind, measure) for type I and for type II, e.g. ("type I (a leg's links aligned)",
        "min_i |sin(qb_i - qa_i)|") for RRR legs; a mixture of kinds names each kind's measure
        with its legs.
    """
    kinds = [leg.kind for leg in legs]
    present = [k for k in ("RRR", "PRR") if k in kinds]    # an RPR leg's measure is 1
    if not present:
        one = ("type I (a leg; none within an RPR leg's stroke)", "min_i 1")
    elif len(present) == 1:
        expr, why = TYPE_I_MEASURES[present[0]]
        one = (f"type I ({why})", f"min_i {expr}")
    else:
        def legs_of(k):
            ids = [str(i + 1) for i, kind in enumerate(kinds) if kind == k]
            return f"{k} leg{'s' if len(ids) > 1 else ''} {', '.join(ids)}"
        one = ("type I (" + " or ".join(TYPE_I_MEASURES[k][1] for k in present) + ")",
               "min over the legs of " + " and ".join(
                   f"{TYPE_I_MEASURES[k][0]} ({legs_of(k)})" for k in present))
    if end_effector == "platform":
        two = ("type II (parallel: the legs' lines of action concurrent or all parallel, the "
               "actuators lose a direction of the platform)", TYPE_II_MEASURES["platform"])
    else:
        lines = "all distal links aligned" if "RPR" not in kinds else \
            "the legs' lines of action all parallel"
        two = (f"type II (parallel: {lines}, the actuators lose a task direction)",
               TYPE_II_MEASURES["point"])
    return one, two


def leg_lines(legs, pose):
    """Each leg's line of action and type I measure at ``pose``, in its configured branch.

    Parameters
    ----------
    legs : sequence of pm2dof.core.model_file.Leg
        The model file's legs (a platform's with their ``attach``).
    pose : sequence of float (m,)
        (x, y) in m for legs meeting at a point, (x, y, phi) in m, m, rad for a platform.

    Returns
    -------
    list of (float, ndarray (2,), ndarray (2,))
        Per leg: its type I measure (see the module docstring), u(qb_i) (the unit direction
        of its distal link, or of an RPR leg) and P_i (its attachment point, m). NaN where
        its geometry has no solution (an RRR leg outside its annulus, a PRR leg farther than
        lb from its rail's line); an RPR leg's stroke and a PRR rail's ends are not checked
        here (:func:`pm2dof.core.mechanism.leg_reach_problem` does).
    """
    out = []
    with np.errstate(invalid="ignore", divide="ignore"):
        for leg, point in zip(legs, attachment_points(legs, pose)):
            p = np.array(point, dtype=float)
            d = p - np.asarray(leg.base, dtype=float)
            dist = math.hypot(*d)
            if leg.kind == "RRR":     # law of cosines at the base, the model file's elbow
                c = (leg.la ** 2 + dist ** 2 - leg.lb ** 2) / (2 * leg.la * dist)
                s = leg.elbow * math.sqrt(1 - c * c) if abs(c) <= 1 else math.nan
                dh = d / dist
                ua = c * dh + s * np.array([-dh[1], dh[0]])
                ub = (d - leg.la * ua) / leg.lb
                measure = abs(ua[0] * ub[1] - ua[1] * ub[0])            # |sin(qb - qa)|
            elif leg.kind == "PRR":   # the slider ahead of / behind the foot of the perpendicular
                r = (np.asarray(leg.rail_end, dtype=float) - leg.base) / leg.rail_length
                h = r[0] * d[1] - r[1] * d[0]
                root = leg.lb ** 2 - h * h
                qa = r @ d + leg.elbow * (math.sqrt(root) if root >= 0 else math.nan)
                ub = (d - qa * r) / leg.lb
                measure = abs(r @ ub)                                   # |d . u(qb)|
            else:                     # RPR: the leg's own line
                ub = d / dist
                measure = 1.0 if dist > 0 else math.nan
            out.append((float(measure), ub, p))
    return out


def pose_measures(legs, pose):
    """The type I and type II singularity measures at ``pose`` (see the module docstring).

    Parameters
    ----------
    legs : sequence of pm2dof.core.model_file.Leg
        The model file's legs.
    pose : sequence of float (m,)
        (x, y) for legs meeting at a point, (x, y, phi) for a platform; m, rad.

    Returns
    -------
    type1 : float
        min over the legs of each leg's type I measure, in [0, 1].
    type2 : float
        The type II measure, in [0, 1].
    per_leg : list of float (n,)
        Each leg's type I measure. NaN throughout where some leg's geometry has no
        solution (:func:`leg_lines`).
    """
    lines = leg_lines(legs, pose)
    per_leg = [m for m, _, _ in lines]
    n = len(legs)
    type1 = min(per_leg) if not any(math.isnan(m) for m in per_leg) else math.nan
    u = np.array([ub for _, ub, _ in lines])
    if len(pose) == 2:
        z = np.sum((u[:, 0] + 1j * u[:, 1]) ** 2)                     # sum_i exp(2 i qb_i)
        type2 = math.sqrt(max(1.0 - abs(z) / n, 0.0)) if np.isfinite(z) else math.nan
    else:
        a = np.array([leg.attach for leg in legs], dtype=float)
        L = math.sqrt(float(np.mean(np.sum(a ** 2, axis=1))))           # RMS |a_i|, m
        arm = np.array([p for _, _, p in lines]) - np.asarray(pose[:2], dtype=float)
        moment = arm[:, 0] * u[:, 1] - arm[:, 1] * u[:, 0]              # (R a_i) x u(qb_i)
        U = np.column_stack([u, moment / L])
        U = U / np.linalg.norm(U, axis=1, keepdims=True)
        det = float(np.linalg.det(U.T @ U)) if np.isfinite(U).all() else math.nan
        type2 = max(det, 0.0) ** (1 / 3) * 3 / n if not math.isnan(det) else math.nan
    if math.isnan(type1):
        type2 = math.nan
    return type1, type2, per_leg
