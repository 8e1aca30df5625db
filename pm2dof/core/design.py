# A model file's [design] table: named geometric variables of the legs, kept as a run-time
# input of the generated C (pm2dof.derive keeps them symbolic; Model.at_design rebinds them).
"""The design variables of a model file, and the spec of the same file at another design.

:func:`read_design` reads ``[design]`` for the model file's reader (every problem a
:class:`~pm2dof.core.validate.Problems` entry naming the key); :func:`spec_at_design` gives the
:class:`~pm2dof.core.model_file.ModelSpec` of "the same file with those numbers": legs replaced,
theta's inertial entries recomputed for legs whose links are uniform rods, a defaulted closure
tolerance recomputed, and the file's home and move ends checked within reach.
docs/model-file.md ("[design]") gives the rules in words. Pure Python and NumPy.
"""
import dataclasses
import math
import numbers
import re
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from .errors import DesignError
from .mechanism import (
    FIRST_MOMENT,
    INERTIAL,
    default_closure_tolerance,
    inertia_problem,
    lumped_from_links,
    reach_problems,
    theta_groups,
)
from .validate import entry

__all__ = ["Design", "DESIGN_FIELDS", "read_design", "spec_at_design"]

#: per leg kind, the designable keys of [[legs]] (as a design key writes them after
#: "legs.<i>.") and their internal (field, component): component None for a length, 0/1 for a
#: point's x/y. A PRR rail's ends are 1 (its start, Leg.base, where qa = 0) and 2 (Leg.rail_end),
#: as ``rail = [[x1, y1], [x2, y2]]`` lists them. A stroke does not enter the generated C, so it
#: is not designable.
DESIGN_FIELDS = {
    "RRR": {"la": ("la", None), "lb": ("lb", None),
            "base.x": ("base", 0), "base.y": ("base", 1),
            "attach.x": ("attach", 0), "attach.y": ("attach", 1)},
    "PRR": {"lb": ("lb", None),
            "rail.1.x": ("base", 0), "rail.1.y": ("base", 1),
            "rail.2.x": ("rail_end", 0), "rail.2.y": ("rail_end", 1),
            "attach.x": ("attach", 0), "attach.y": ("attach", 1)},
    "RPR": {"base.x": ("base", 0), "base.y": ("base", 1),
            "attach.x": ("attach", 0), "attach.y": ("attach", 1)},
}
#: the fields that are lengths: their bounds must be > 0
_LENGTHS = ("la", "lb")
_KEY = re.compile(r"legs\.([1-9][0-9]*)\.(.+)")


@dataclass(frozen=True)
class Design:
    """The design variables of a model file, in the file's order.

    ``names`` (k,): the variables; ``keys[j]``: the (leg index from 0, field, component) each
    variable j sets (tied keys take the same value); ``labels[j]``: the same keys as the file
    writes them ("legs.1.la"); ``bounds[j]``: (low, high) in m; ``values``: the current design;
    ``default``: the file's (the values in [[legs]]); ``signs[j]``: +1 if the variable is
    positive over its bounds, -1 if negative, else 0 (the derivation's SymPy assumptions);
    ``closure_default``: [sensing] closure_tolerance was not given, so it follows the design."""
    names: tuple
    keys: tuple
    labels: tuple
    bounds: tuple
    values: tuple
    default: tuple
    signs: tuple
    closure_default: bool = True

    @property
    def size(self):
        return len(self.names)

    def variable_of(self):
        """{(leg, field, component): variable name} for every designed key."""
        return {key: name for name, keys in zip(self.names, self.keys) for key in keys}

    def describe(self):
        """"la = 0.25, lb = 0.24": the current values, 6 significant digits (for messages)."""
        return ", ".join(f"{n} = {v:.6g}" for n, v in zip(self.names, self.values))

    def formulation(self):
        """What enters the generated code: the names and the keys they set (not the values or
        bounds, so editing a default or a bound needs no new derivation)."""
        return [[name, list(labels)] for name, labels in zip(self.names, self.labels)]


# ---- reading [design] ----

def read_design(pr, raw, legs, effector, closure_default=True):
    """The model file's ``[design]`` table as a :class:`Design`, or None (no table, or a
    problem: each recorded in ``pr`` naming the key).

    Parameters
    ----------
    pr : pm2dof.core.validate.Problems
        The model file's problems.
    raw : object
        ``doc.get("design")``: {name: {keys = [...], bounds = [low, high]}}.
    legs : tuple of Leg or None
        The file's legs, None for an invalid one (already reported).
    effector : str
        "point" or "platform" (only a platform's legs have ``attach`` keys).
    closure_default : bool
        Whether [sensing] closure_tolerance was left to its default.
    """
    if raw is None:
        return None
    if not isinstance(raw, dict):
        return pr.add("design", f"must be a table of design variables, name = {{ keys = [...], "
                                f"bounds = [low, high] }}, got {type(raw).__name__}")
    if not raw:
        return pr.add("design", "names no design variable: give at least one name = { keys = "
                                "[...], bounds = [low, high] }, or leave the table out")
    found, seen = len(pr), {}
    names, keys, labels, bounds, default = [], [], [], [], []
    for name, var in raw.items():
        where = f"design.{name}"
        if not (name.isidentifier() and name.isascii()):
            pr.add(where, f"a design variable's name must be an ASCII identifier (it names an "
                          f"entry of the generated C's design input), got {name!r}")
        if not isinstance(var, dict):
            pr.add(where, f"must be a table {{ keys = [...], bounds = [low, high] }}, got "
                          f"{var!r}"[:300])
            continue
        if not pr.keys(where, var, ("keys", "bounds"), ("keys", "bounds")):
            continue
        got = _read_keys(pr, where, name, var["keys"], legs, effector, seen)
        lohi = _read_bounds(pr, where, var["bounds"],
                            length=got is not None and any(f in _LENGTHS for (_, f, _), _ in got))
        if got is None or lohi is None:
            continue
        value = _default(pr, where, name, got, legs, lohi)
        names.append(name)
        keys.append(tuple(key for key, _ in got))
        labels.append(tuple(label for _, label in got))
        bounds.append(lohi)
        default.append(value)
    if len(pr) > found or None in legs:
        return None
    signs = tuple(1 if lo > 0 else -1 if hi < 0 else 0 for lo, hi in bounds)
    return Design(names=tuple(names), keys=tuple(keys), labels=tuple(labels),
                  bounds=tuple(bounds), values=tuple(default), default=tuple(default),
                  signs=signs, closure_default=closure_default)


def _read_keys(pr, where, name, raw, legs, effector, seen):
    """[((leg, field, component), label)] of one variable's ``keys``, or None. ``seen``:
    {(leg, field, component): (variable, label)} of the keys read so far (a key takes one
    variable)."""
    at = f"{where}.keys"
    if not (isinstance(raw, list) and raw):
        return pr.add(at, f"must be a non-empty list of keys of [[legs]] such as \"legs.1.la\", "
                          f"got {raw!r}"[:300])
    out, ok = [], True
    for k, label in enumerate(raw):
        key = entry(at, label if isinstance(label, str) else f"entry {k + 1}")
        parsed = _parse_key(label, legs, effector)
        if isinstance(parsed, str):
            ok = pr.add(key, parsed)
        elif parsed is None:          # an invalid leg: reported by [[legs]]
            ok = False
        elif parsed in seen:
            other, first = seen[parsed]
            ok = pr.add(key, f"{label} is listed twice in design variable '{name}'" if other == name
                        else f"{label} is set by design variables '{other}' ({first}) and "
                             f"'{name}': a key takes one variable")
        else:
            seen[parsed] = (name, label)
            out.append((parsed, label))
    return out if ok else None


def _parse_key(label, legs, effector):
    """(leg index from 0, field, component) of a design key "legs.<i>.<key>", None for an
    invalid leg, or why the key is refused (a str)."""
    match = _KEY.fullmatch(label) if isinstance(label, str) else None
    if match is None:
        return (f"must be a key of [[legs]] written \"legs.<i>.<key>\" (legs count from 1, e.g. "
                f"\"legs.1.la\", \"legs.2.base.x\"), got {label!r}")
    i, key = int(match[1]), match[2]
    if i > len(legs):
        return f"{label}: there is no leg {i} (the file has {len(legs)} [[legs]], counted from 1)"
    leg = legs[i - 1]
    if leg is None:
        return None
    part = key.split(".")[0]
    if part == "stroke":
        return (f"{label}: a stroke does not enter the generated C (it bounds the actuator at "
                f"run time), so it cannot be a design variable; edit legs.{i}.stroke instead")
    if part == "attach" and effector != "platform":
        return (f"{label}: only a platform's legs have an attachment point ([model] "
                f"end_effector = \"{effector}\")")
    allowed = [k for k in DESIGN_FIELDS[leg.kind]
               if effector == "platform" or not k.startswith("attach")]
    if key not in allowed:
        return (f"{label}: not a designable key of leg {i} ({leg.kind}); allowed: "
                f"{', '.join(f'legs.{i}.{k}' for k in allowed)}")
    return (i - 1, *DESIGN_FIELDS[leg.kind][key])


def _read_bounds(pr, where, raw, length):
    """(low, high) of one variable, finite, low < high, low > 0 for a length; or None."""
    at = f"{where}.bounds"
    if not (isinstance(raw, list) and len(raw) == 2):
        return pr.add(at, f"must be [low, high] in m, got {raw!r}"[:300])
    lo, hi = (pr.number(at, v) for v in raw)
    if None in (lo, hi):
        return None
    if not lo < hi:
        return pr.add(at, f"low must be below high, got [{lo!r}, {hi!r}]")
    if length and not lo > 0:
        return pr.add(at, f"the variable sets a length (la or lb): low must be > 0, got {lo!r}")
    return (lo, hi)


def _leg_value(legs, key):
    """The value in [[legs]] of a (leg, field, component) key."""
    leg, fld, comp = key
    value = getattr(legs[leg], fld)
    return float(value if comp is None else value[comp])


def _default(pr, where, name, got, legs, bounds):
    """The default of one variable: its keys' value in [[legs]], which must be equal (tied)
    and within the bounds (each a problem)."""
    if any(legs[i] is None for (i, _, _), _ in got):
        return None
    label0, value = got[0][1], _leg_value(legs, got[0][0])
    for key, label in got[1:]:
        other = _leg_value(legs, key)
        if other != value:
            pr.add(entry(f"{where}.keys", label),
                   f"{label} = {other!r} differs from {label0} = {value!r}, both set by design "
                   f"variable '{name}' (tied keys must be equal in [[legs]])")
    lo, hi = bounds
    if not lo <= value <= hi:
        pr.add(f"{where}.bounds", f"the default {label0} = {value!r} (the value in [[legs]]) is "
                                  f"outside the bounds [{lo!r}, {hi!r}]")
    return value


# ---- the spec at a design ----

def spec_at_design(spec, values):
    """The spec of the same model file with its design variables at ``values``.

    Parameters
    ----------
    spec : pm2dof.core.model_file.ModelSpec
        A spec with a ``[design]`` (``spec.design``).
    values : mapping or sequence of float
        {name: value} (the variables it leaves out keep ``spec.design.values``), or one value
        per variable in ``spec.design.names`` order; m.

    Returns
    -------
    ModelSpec
        ``spec`` with its legs at the design, theta's inertial entries ([nominal] and [plant])
        recomputed for the legs whose links include a uniform rod, a defaulted [sensing]
        closure_tolerance recomputed, and ``design.values`` set. ``file_sha256`` and
        ``formulation_sha256`` are unchanged (the generated code serves every design).

    Raises
    ------
    DesignError
        No [design]; an unknown variable (the known ones listed); a value that is not a finite
        number or lies outside its bounds; a PRR rail of zero length (the leg named); a leg
        whose lumped inertia is not positive definite; [platform] home or a move's start or
        end out of some leg's reach at that design (the pose and the leg named).
    """
    design = spec.design
    if design is None:
        raise DesignError(f"the model file {spec.path} has no [design] table, so it has no "
                          f"design variables")
    new = _values(design, values)
    legs = _legs_at(spec.legs, design, new)
    theta, plant = _inertia_at(spec, legs, lambda: _shown(design, new))
    sensing = spec.sensing
    if design.closure_default and sensing is not None and "closure_tolerance" in sensing:
        sensing = {**sensing, "closure_tolerance": default_closure_tolerance(
            legs, sensing["encoder_counts_per_rev"], sensing.get("linear_encoder_resolution"))}
    _check_reach(spec, legs, design, new)
    return _replace(spec, legs=legs, theta_nominal=theta, plant=plant, sensing=sensing,
                    design=_replace(design, values=new))


_FIELDS = {}


def _replace(obj, **changes):
    """``dataclasses.replace(obj, **changes)`` for the spec's frozen dataclasses (ModelSpec, Leg,
    Design: no ``__post_init__``, no field outside ``__init__``), without ``__init__``'s per-field
    machinery: a tenth of the time, on ``at_design``'s path."""
    cls = type(obj)
    names = _FIELDS.get(cls)
    if names is None:
        names = _FIELDS[cls] = tuple(f.name for f in dataclasses.fields(cls))
    unknown = set(changes).difference(names)
    if unknown:
        raise TypeError(f"{cls.__name__} has no field {sorted(unknown)[0]!r}")
    old = obj.__dict__
    new = object.__new__(cls)
    new.__dict__.update({n: changes[n] if n in changes else old[n] for n in names})
    return new


def _shown(design, values):
    return ", ".join(f"{n} = {v!r}" for n, v in zip(design.names, values))


def _values(design, values):
    """The design's values as a tuple of floats, checked (names, finite, bounds)."""
    names = design.names
    if isinstance(values, Mapping):
        unknown = [k for k in values if k not in names]
        if unknown:
            raise DesignError(f"unknown design variable{'s' if len(unknown) > 1 else ''} "
                              f"{', '.join(repr(k) for k in unknown)}; the model file's [design] "
                              f"has {', '.join(repr(n) for n in names)}")
        given = [values.get(n, v) for n, v in zip(names, design.values)]
    else:
        if isinstance(values, (str, bytes)) or not hasattr(values, "__len__"):
            raise DesignError(f"a design is a mapping {{name: value}} or a sequence of "
                              f"{design.size} values in the order ({', '.join(names)}), got "
                              f"{type(values).__name__}")
        given = list(values)
        if len(given) != design.size:
            raise DesignError(f"a design has {design.size} values, in the order "
                              f"({', '.join(names)}), got {len(given)}")
    out = []
    for name, v, (lo, hi) in zip(names, given, design.bounds):
        if type(v) is not float and (  # a float is a number (the usual case, checked first)
                isinstance(v, (bool, np.bool_)) or not isinstance(v, (numbers.Real, np.ndarray))
                or np.ndim(v) != 0):
            raise DesignError(f"design variable {name!r} must be a number, got {v!r}"[:300])
        v = float(v)
        if not math.isfinite(v):
            raise DesignError(f"design variable {name!r} = {v!r} is not finite")
        if not lo <= v <= hi:
            raise DesignError(f"design variable {name!r} = {v!r} is outside its bounds "
                              f"[{lo!r}, {hi!r}] ([design] {name})")
        out.append(v)
    return tuple(out)


def _legs_at(legs, design, values):
    """The legs with the designed keys at ``values`` (dataclasses.replace)."""
    changes = [{} for _ in legs]
    setters = [set() for _ in legs]
    for name, keys, value in zip(design.names, design.keys, values):
        for i, fld, comp in keys:
            setters[i].add(name)
            if comp is None:
                changes[i][fld] = value
            else:
                point = list(changes[i].get(fld, getattr(legs[i], fld)))
                point[comp] = value
                changes[i][fld] = tuple(point)
    out = tuple(_replace(leg, **ch) if ch else leg for leg, ch in zip(legs, changes))
    for i, leg in enumerate(out):
        if leg.kind == "PRR" and leg.rail_length == 0:
            raise DesignError(f"at this design ({_shown(design, values)}) leg {i + 1}'s rail has "
                              f"zero length (both ends at {list(leg.base)}), set by design "
                              f"variable{'s' if len(setters[i]) > 1 else ''} "
                              f"{', '.join(repr(n) for n in sorted(setters[i]))}: the slider "
                              f"has no direction to move in")
    return out


def _inertia_at(spec, legs, shown):
    """(theta_nominal, plant) with the inertial entries of every leg whose [nominal.links] or
    [plant.links] include a uniform rod recomputed at ``legs``; the others as given. ``shown()``:
    the design, for messages."""
    theta, plant = spec.theta_nominal, spec.plant
    if spec.links is None:
        return theta, plant
    sections, per_leg = _inertia_plan(spec, legs)
    if not sections:
        return theta, plant
    for section, bodies, rods in sections:
        if section == "nominal":
            theta = np.array(theta, dtype=float)
        else:
            plant = {k: np.array(v, dtype=float) if k in per_leg else v
                     for k, v in plant.items()}
        for i, where in rods:
            lumped = lumped_from_links(legs[i], bodies[i])
            why = inertia_problem(*(lumped[k] for k in INERTIAL))
            if why is not None:
                raise DesignError(f"at this design ({shown()}) leg {i + 1}'s [[{section}.links]] "
                                  f"give a lumped inertia that no leg can have: {why}")
            for key, at in where:
                (theta if section == "nominal" else plant[key])[at] = lumped[key]
    if theta is not spec.theta_nominal:
        theta.setflags(write=False)
    if plant is not spec.plant:
        for key in per_leg:
            if isinstance(plant.get(key), np.ndarray):
                plant[key].setflags(write=False)
    return theta, plant


_PLANS = {}


def _inertia_plan(spec, legs):
    """What :func:`_inertia_at` recomputes, found once per model file: ((section, bodies,
    ((leg i, ((key, index into theta or into plant[key]), ...)), ...)), ...) for the sections
    with a rod, and the set of theta's per-leg inertial keys. Kept per [links] table (the
    table itself is held, so its id is not reused) and theta's names."""
    cache_key = (id(spec.links), spec.param_names)
    have = _PLANS.get(cache_key)
    if have is not None and have[0] is spec.links:
        return have[1]
    groups = theta_groups(legs, spec.end_effector, spec.gravity, spec.friction)
    per_leg = {key: idx for key, idx in groups if key in INERTIAL + (FIRST_MOMENT,)}
    sections = []
    for section in ("nominal", "plant"):
        bodies = spec.links.get(section)
        if bodies is None:
            continue
        rods = []
        for i, b in enumerate(bodies):
            if not any("density" in body for body in b.values()):
                continue
            where = tuple((key, spec.param_names.index(f"{key}{i + 1}") if section == "nominal"
                           else idx.index(i)) for key, idx in per_leg.items() if i in idx)
            rods.append((i, where))
        if rods:
            sections.append((section, bodies, tuple(rods)))
    plan = (tuple(sections), frozenset(per_leg))
    _PLANS[cache_key] = (spec.links, plan)
    return plan


def _check_reach(spec, legs, design, values):
    """DesignError naming the pose and the legs if [platform] home or a move's start or end
    (path moves: the planner checks their paths) is out of some leg's reach."""
    poses = [] if spec.home is None else [("[platform] home", spec.home)]
    for name, move in (spec.trajectories or {}).items():
        poses += [(f"the move '{name}' {end}", move[end]) for end in ("start", "end")
                  if end in move]
    seen = set()
    for what, pose in poses:
        pose = [float(v) for v in pose]
        if tuple(pose) in seen:      # the moves of one line at two speeds share their ends
            continue
        seen.add(tuple(pose))
        found = reach_problems(legs, pose)
        if found:
            which = "; ".join(f"leg {i + 1} ({legs[i].kind}) {why}" for i, why in found)
            raise DesignError(f"at this design ({_shown(design, values)}) {what} {pose} is out "
                              f"of reach: {which}")
