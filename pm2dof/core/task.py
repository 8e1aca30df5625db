# The task space of a model: its dimension m, its coordinate names, and what needs a given mechanism.
"""The task dimension m and what depends on the mechanism.

A model's task space has m = ``Model.dof`` coordinates named ``Model.task_names``: ``("x",
"y")`` for a point end effector (m = 2, the paper's robot), ``("x", "y", "phi")`` for a
moving platform (m = 3, phi its orientation in rad). Every task-space array of the runtime has
m entries; :func:`task_vector` checks one and names m in its message.

Some capabilities hold for one family only (the Python reference formulation, the closed-form
reach of RR legs): :func:`require_rr_point` refuses the others with
:class:`~pm2dof.core.errors.UnsupportedMechanismError` saying why.
"""
import numpy as np

from .errors import ArgumentError, UnsupportedMechanismError

__all__ = ["effort_unit", "per_actuator", "active_coordinates",
           "is_rr_point", "require_rr_point", "task_vector", "mechanism", "orientation_length"]

def mechanism(spec):
    """One phrase for a model file's mechanism (a ModelSpec), e.g. "3 RRR legs at a point"
    (for messages)."""
    kinds = sorted({leg.kind for leg in spec.legs})
    return (f"{spec.n_legs} {'/'.join(kinds)} legs at a "
            f"{'point' if spec.end_effector == 'point' else 'moving platform'}")


def is_rr_point(spec):
    """True for the paper's family (``spec`` a ModelSpec): RRR legs (actuated revolute,
    passive elbow) whose distal links meet at one point, task (x, y). Closed-form geometry
    (reach annuli, elbow angles by the law of cosines) holds for these only."""
    return spec.end_effector == "point" and all(leg.kind == "RRR" for leg in spec.legs)


def require_rr_point(model, what):
    """``model`` (a Model), or :class:`UnsupportedMechanismError` naming ``what`` (the
    capability) unless its mechanism is RRR legs meeting at a point."""
    if not is_rr_point(model.spec):
        raise UnsupportedMechanismError(
            f"{what} covers RRR legs meeting at a point only (the paper's family, task x, y); "
            f"model {model.spec.name!r} has {mechanism(model.spec)}")
    return model


def task_vector(model, name, value):
    """``value`` as a new float64 array (m,), m = ``model.dof``; ArgumentError naming ``name``,
    m and the coordinates otherwise (a wrong length or a non-finite entry)."""
    m = model.dof
    try:
        v = np.array(value, dtype=float)
    except (TypeError, ValueError):
        v = None
    if v is None or v.shape != (m,) or not np.isfinite(v).all():
        raise ArgumentError(f"{name} must be {m} finite numbers ({', '.join(model.task_names)}: "
                            f"model {model.name!r} has task dimension m = {m}), got {value!r}")
    return v


def orientation_length(model):
    """The length l (m) that turns a platform's orientation phi into arc length
    (ds^2 = dx^2 + dy^2 + (l dphi)^2, docs/planning.md): the platform's radius, the largest
    distance of a leg's attachment point from the platform frame's origin. None for a point
    end effector (no phi). ``model``: a Model."""
    if model.spec.end_effector == "point":
        return None
    return max(float(np.hypot(*leg.attach)) for leg in model.spec.legs)


def per_actuator(actuators, revolute, prismatic, mixed=None):
    """The phrase for a model's actuators: ``revolute`` when every actuator is revolute (RRR
    legs), ``prismatic`` when every one is linear (PRR sliders, RPR cylinders), else ``mixed``
    (default "<revolute> (revolute actuators), <prismatic> (linear actuators)").
    ``actuators``: each leg's actuator, "revolute" or "prismatic" (``model.spec.actuators``)."""
    kinds = set(actuators)
    if kinds == {"revolute"}:
        return revolute
    if kinds == {"prismatic"}:
        return prismatic
    return (f"{revolute} (revolute actuators), {prismatic} (linear actuators)" if mixed is None
            else mixed)


def effort_unit(model):
    """The unit of the actuators' efforts, for printed text: "N m" (revolute actuators), "N"
    (linear ones: PRR sliders, RPR cylinders) or "N m or N" (both). ``model``: a Model."""
    return per_actuator(model.spec.actuators, "N m", "N", "N m or N")


def active_coordinates(actuators, qa):
    """``qa`` (n,) as printed text with each actuator's unit: "[0.1, 0.2, 0.3] rad" (revolute
    actuators: angles), "[0.22, 0.22, 0.22] m" (linear ones: a PRR slider's position, an RPR
    leg's length), or "[0.1, 0.2, 0.3] (rad for legs 1, 2; m for leg 3)" for a mixture.
    ``actuators``: each leg's, "revolute" or "prismatic" (``model.spec.actuators``)."""
    values = np.asarray(qa, dtype=float).reshape(-1).tolist()

    def legs_of(kind):
        ids = [str(i + 1) for i, a in enumerate(actuators) if a == kind]
        return f"leg{'s' if len(ids) > 1 else ''} {', '.join(ids)}"
    return f"{values} " + per_actuator(actuators, "rad", "m", (
        f"(rad for {legs_of('revolute')}; m for {legs_of('prismatic')})"))
