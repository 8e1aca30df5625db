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

from .contract import ENERGY_FUNCTIONS  # the generated energies
from .errors import ArgumentError, StaleGeneratedCodeError, UnsupportedMechanismError
from .paths import derive_command

__all__ = ["effort_unit", "per_actuator", "active_coordinates", "POINT_TASK_NAMES", "ENERGY_FUNCTIONS", "spec_task_names", "is_rr_point",
           "require_rr_point", "require_generated", "task_vector", "mechanism",
           "orientation_length"]

#: the task coordinates of a point end effector (the paper's robot)
POINT_TASK_NAMES = ("x", "y")


def spec_task_names(spec, m):
    """The task coordinates' names of a model file's spec whose generated code has task
    dimension ``m``: the spec's own ``task_names`` (model files with an
    ``end_effector``), else (a spec without them: a point end effector) ``("x", "y")`` for m = 2."""
    names = getattr(spec, "task_names", None)
    if names is None:
        names = POINT_TASK_NAMES + ("phi",) if m == 3 else POINT_TASK_NAMES
    return tuple(names)


def mechanism(spec):
    """One phrase for a model's mechanism, e.g. "3 RRR legs at a point" (for messages)."""
    kinds = sorted({getattr(leg, "kind", "RRR") for leg in spec.legs})
    effector = getattr(spec, "end_effector", "point")
    return (f"{spec.n_legs} {'/'.join(kinds)} legs at a "
            f"{'point' if effector == 'point' else 'moving platform'}")


def is_rr_point(spec):
    """True for the paper's family: RRR legs (actuated revolute, passive elbow) whose distal
    links meet at one point, task (x, y). Closed-form geometry (reach annuli, elbow angles by
    the law of cosines) holds for these only."""
    return (getattr(spec, "end_effector", "point") == "point"
            and all(getattr(leg, "kind", "RRR") == "RRR" for leg in spec.legs))


def require_rr_point(model, what):
    """``model`` (a Model or a ModelSpec), or :class:`UnsupportedMechanismError` naming
    ``what`` (the capability) unless its mechanism is RRR legs meeting at a point."""
    spec = getattr(model, "spec", model)
    if not is_rr_point(spec):
        raise UnsupportedMechanismError(
            f"{what} covers RRR legs meeting at a point only (the paper's family, task x, y); "
            f"model {spec.name!r} has {mechanism(spec)}")
    return model


def require_generated(model, short):
    """Refuse a model whose generated code has no ``<name>_<short>`` (derived before the
    derivation added the gravity term Ge and the energies): StaleGeneratedCodeError naming the command
    that re-derives it."""
    if f"{model.name}_{short}" not in model.manifest["functions"]:
        raise StaleGeneratedCodeError(
            f"model {model.name!r}: its generated code in {model.generated} has no {short} "
            f"(derived before the gravity term and the energies were generated); re-derive "
            f"the model: "
            f"`{derive_command(model.spec.path, model.generated)}`")


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
    end effector (no phi)."""
    spec = getattr(model, "spec", model)
    if getattr(spec, "end_effector", "point") == "point":
        return None
    return max(float(np.hypot(*leg.attach)) for leg in spec.legs)


def per_actuator(kinds, revolute, prismatic, mixed=None):
    """The phrase for a model's actuators: ``revolute`` when every actuator is revolute (RRR
    legs), ``prismatic`` when every one is linear (PRR sliders, RPR cylinders), else ``mixed``
    (default "<revolute> (revolute actuators), <prismatic> (linear actuators)"). ``kinds``:
    each leg's ``actuator`` ("revolute" or "prismatic"), or a Model."""
    if hasattr(kinds, "spec"):
        kinds = [leg.actuator for leg in kinds.spec.legs]
    kinds = set(kinds)
    if kinds == {"revolute"}:
        return revolute
    if kinds == {"prismatic"}:
        return prismatic
    return (f"{revolute} (revolute actuators), {prismatic} (linear actuators)" if mixed is None
            else mixed)


def effort_unit(model):
    """The unit of the actuators' efforts, for printed text: "N m" (revolute actuators), "N"
    (linear ones: PRR sliders, RPR cylinders) or "N m or N" (both)."""
    return per_actuator(model, "N m", "N", "N m or N")


def active_coordinates(model, qa):
    """``qa`` (n,) as printed text with each actuator's unit: "[0.1, 0.2, 0.3] rad" (revolute
    actuators: angles), "[0.22, 0.22, 0.22] m" (linear ones: a PRR slider's position, an RPR
    leg's length), or "[0.1, 0.2, 0.3] (rad for legs 1, 2; m for leg 3)" for a mixture.
    ``model``: a Model or a ModelSpec."""
    legs = getattr(model, "spec", model).legs
    values = np.asarray(qa, dtype=float).reshape(-1).tolist()

    def legs_of(kind):
        ids = [str(i + 1) for i, leg in enumerate(legs) if leg.actuator == kind]
        return f"leg{'s' if len(ids) > 1 else ''} {', '.join(ids)}"
    return f"{values} " + per_actuator([leg.actuator for leg in legs], "rad", "m", (
        f"(rad for {legs_of('revolute')}; m for {legs_of('prismatic')})"))
