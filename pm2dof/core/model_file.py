# Model files (TOML): read, validate, and split into the derivation's formulation and run-time data.
"""Read and validate a pm2dof model file.

A model file describes one planar parallel manipulator: legs of kind RRR, PRR or RPR
(``[[legs]]``) joined at a point or at a moving platform (``[model] end_effector``), an optional
gravity vector, its friction model, its nominal parameters (the paper's Tables 1-2) and run-time
data (limits, gains, plant truth, trajectories). docs/model-file.md is the reference. Only
``[model]`` and ``[[legs]]`` enter the generated C; their canonical hash
(:attr:`ModelSpec.formulation_sha256`) guards generated code against staleness.

This module reads and checks; the rules of the mechanism it checks against (leg kinds, theta's
layout, lumped parameters from links, reach) are :mod:`pm2dof.core.mechanism`'s. It is pure
Python and is shared by ``derive/`` and the runtime.
"""
import hashlib
import json
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from . import contract
from .design import read_design
from .errors import ModelFileError
from .measures import TYPE_I_MEASURES, TYPE_II_MEASURES, pose_measures
from .mechanism import (
    ACTUATORS,
    END_EFFECTORS,
    FIRST_MOMENT,
    FRICTION_CONSTANTS,
    FRICTION_MODELS,
    INERTIAL,
    LEG_KINDS,
    LINK_BODIES,
    PLATFORM_PARAMS,
    ROD_LENGTH,
    default_closure_tolerance,
    inertia_problem,
    lumped_from_links,
    platform_from_body,
    platform_inertia_problem,
    reach_problems,
    theta_groups,
    theta_names,
)
from .validate import RULES, Problems, entry

__all__ = ["ModelSpec", "Leg", "read_model_file", "ELBOWS", "FK_BRANCHES", "PRR_BRANCHES",
           "SPLITS", "DEFAULT_PARALLEL_THRESHOLD"]

#: PRR branch: the slider ahead of (+1) or behind (-1) the foot of the perpendicular from the
#: attachment point onto the rail, along the rail's direction
PRR_BRANCHES = {"ahead": 1, "behind": -1}
#: [limits] parallel_singularity_threshold when a model file does not set it (type II measure,
#: see Model.singularity_measures; 0.1 is about 8 degrees between a five-bar's distal links)
DEFAULT_PARALLEL_THRESHOLD = 0.1
ELBOWS = {"left": 1, "right": -1}
FK_BRANCHES = {"left": 1, "right": -1}

_MODEL_KEYS = {"name", "description", "friction", "fk_branch", "stribeck_velocity",
               "sign_smoothing_velocity", "rk4_substeps", "end_effector", "gravity"}
# per leg kind: (required keys, optional keys); "attach" is required on a platform
_LEG_KEYS = {"RRR": ({"base", "la", "lb", "elbow"}, {"kind", "attach"}),
             "PRR": ({"kind", "rail", "lb", "branch"}, {"attach"}),
             "RPR": ({"kind", "base", "stroke"}, {"attach"})}
_TOP_KEYS = {"model", "legs", "nominal", "limits", "sensing", "gains", "plant", "trajectories",
             "control", "platform", "design"}
#: torque distributions among the actuators (S^T tau_a = u; pm2dof.core.contract)
SPLITS = tuple(contract.SPLITS)


@dataclass(frozen=True)
class Leg:
    """One leg. ``kind`` "RRR" (today's leg): base ``A`` (2,) in m, link lengths ``la``, ``lb`` in
    m, elbow +1 left / -1 right. "PRR": rail from ``base`` to ``rail_end`` (the slider's
    coordinate qa runs from 0 at ``base`` to the rail's length), link ``lb``, ``elbow`` the
    branch (+1 "ahead", -1 "behind"), ``la`` None. "RPR": ``base`` the passive base pivot,
    ``stroke`` (min, max) of the actuated length qa, ``la``, ``lb``, ``elbow`` None.
    ``attach``: the attachment point in the platform frame (a platform's legs), else None."""
    base: tuple
    la: object
    lb: object
    elbow: object
    kind: str = "RRR"
    attach: object = None
    rail_end: object = None
    stroke: object = None

    @property
    def actuator(self):
        """"revolute" (RRR: qa an angle, rad) or "prismatic" (PRR, RPR: qa a length, m)."""
        return ACTUATORS[self.kind]

    @property
    def rail_length(self):
        """PRR: the rail's length, m (None for other kinds)."""
        if self.rail_end is None:
            return None
        return math.hypot(self.rail_end[0] - self.base[0], self.rail_end[1] - self.base[1])

    def formulation(self, designed=None):
        """This leg's entry of :meth:`ModelSpec.formulation` (today's RRR point legs: unchanged).
        ``designed``: {(field, component): design variable} of this leg's designed values, each
        written as {"design": name} instead of its number (Design.variable_of)."""
        designed = designed or {}

        def value(fld, comp=None):
            name = designed.get((fld, comp))
            if name is not None:
                return {"design": name}
            return getattr(self, fld) if comp is None else getattr(self, fld)[comp]

        def point(fld):
            return [value(fld, 0), value(fld, 1)]

        if self.kind == "RRR":
            out = {"base": point("base"), "la": value("la"), "lb": value("lb"),
                   "elbow": self.elbow}
        elif self.kind == "PRR":
            out = {"kind": "PRR", "rail": [point("base"), point("rail_end")], "lb": value("lb"),
                   "branch": self.elbow}
        else:
            out = {"kind": "RPR", "base": point("base"), "stroke": list(self.stroke)}
        if self.attach is not None:
            out["attach"] = point("attach")
        return out


@dataclass(frozen=True)
class ModelSpec:
    """A validated model file. Immutable; arrays are read-only copies."""
    path: str
    name: str
    description: str
    friction: str
    friction_constants: dict
    fk_branch: int
    rk4_substeps: int
    legs: tuple
    param_names: tuple
    theta_nominal: np.ndarray
    limits: dict
    sensing: dict = field(repr=False)
    gains: dict = field(repr=False)         # {"na": {...}, "apd": {...}}
    plant: dict = field(repr=False)
    trajectories: dict = field(repr=False)  # {"low": {...}, "high": {...}}
    control: dict = field(repr=False, default_factory=dict)  # split, preload, preload_sign
    file_sha256: str = ""
    formulation_sha256: str = ""
    end_effector: str = "point"
    gravity: tuple = (0.0, 0.0)             # m/s^2 in the base frame; (0, 0): horizontal plane
    home: object = None                     # platform: the fk seed pose (x, y, phi), else None
    design: object = None                   # a Design ([design]), else None
    # the legs' bodies when some body is a uniform rod, else None: {"nominal": tuple or None,
    # "plant": tuple or None}, per leg {body: {mass, com, inertia} or {density}}; a design
    # recomputes the inertial entries of theta of the legs with a rod (spec_at_design)
    links: object = field(repr=False, default=None)

    @property
    def n_legs(self):
        return len(self.legs)

    @property
    def task_names(self):
        """("x", "y") for a point end effector, ("x", "y", "phi") for a platform."""
        return END_EFFECTORS[self.end_effector]

    @property
    def dof(self):
        """m, the task-space dimension: 2 (point) or 3 (platform)."""
        return len(self.task_names)

    @property
    def has_gravity(self):
        return any(g != 0.0 for g in self.gravity)

    @property
    def bases(self):
        return np.array([leg.base for leg in self.legs], dtype=float)

    @property
    def actuators(self):
        """Each leg's actuated joint, "revolute" or "prismatic" (:attr:`Leg.actuator`)."""
        return tuple(leg.actuator for leg in self.legs)

    def formulation(self):
        """The part of the model that enters the generated code, as canonical JSON-able data."""
        of = self.design.variable_of() if self.design is not None else {}
        out = {
            "name": self.name,
            "friction": self.friction,
            "friction_constants": dict(sorted(self.friction_constants.items())),
            "fk_branch": self.fk_branch,
            "rk4_substeps": self.rk4_substeps,
            "legs": [leg.formulation({(f, c): v for (j, f, c), v in of.items() if j == i})
                     for i, leg in enumerate(self.legs)],
        }
        # keys with their default value stay out, so today's files keep their hash
        if self.end_effector != "point":
            out["end_effector"] = self.end_effector
        if self.has_gravity:
            out["gravity"] = list(self.gravity)
        if self.design is not None:     # a file without [design] keeps its hash
            out["design"] = self.design.formulation()
        return out


def _frozen(values):
    """A read-only float array of ``values``."""
    out = np.array(values, dtype=float)
    out.setflags(write=False)
    return out


def _size(length, n, param_names, task_names=("x", "y")):
    """Labels and message text of an array of ``length``: "n" per leg (legs numbered from 1,
    as in the paper), "p" per parameter, "m" per task coordinate (x, y or x, y, phi), or 2
    (a pair x, y)."""
    if length == "n":
        return [f"leg {i + 1}" for i in range(n)], f", one per leg (the file has {n} [[legs]])"
    if length == "p":
        return ([f"entry {k + 1}, {name}" for k, name in enumerate(param_names)],
                f", one per parameter of theta, in the order of param_names: "
                f"{', '.join(param_names)}")
    if length == "m":
        return list(task_names), f" [{', '.join(task_names)}]"
    return ["x", "y"], " [x, y]"


def _read_model(pr, model):
    """[model]: name, friction and its constants, fk_branch, rk4_substeps, end_effector and
    gravity (None where invalid)."""
    if model is None:
        return None, None, {}, None, None, "point", (0.0, 0.0)
    pr.keys("model", model, _MODEL_KEYS, ("name", "friction"))
    name = model.get("name")
    if "name" in model and not (isinstance(name, str) and name.isidentifier() and name.isascii()):
        name = pr.add("model.name", f"must be an ASCII identifier (it prefixes C symbols), got "
                                    f"{name!r}")
    pr.text("model.description", model.get("description", ""))
    friction = model.get("friction")
    if "friction" in model:
        friction = pr.choice("model.friction", friction, {k: k for k in FRICTION_MODELS})
    constants = {}
    for key in FRICTION_CONSTANTS.get(friction, ()):
        if key not in model:
            pr.add(f"model.{key}", f"required by friction = {friction!r}")
        else:
            constants[key] = pr.number(f"model.{key}", model[key], **RULES["pos"])
    fk_branch = pr.choice("model.fk_branch", model.get("fk_branch", "left"), FK_BRANCHES)
    substeps = model.get("rk4_substeps", 4)
    if isinstance(substeps, bool) or not isinstance(substeps, int) or not 1 <= substeps <= 100:
        substeps = pr.add("model.rk4_substeps", f"must be an integer in [1, 100], got {substeps!r}")
    effector = pr.choice("model.end_effector", model.get("end_effector", "point"),
                         {k: k for k in END_EFFECTORS})
    gravity = pr.vector("model.gravity", model.get("gravity", [0.0, 0.0]), ["x", "y"],
                        meaning=" [g_x, g_y] in m/s^2, in the base frame")
    return name, friction, constants, fk_branch, substeps, effector, gravity


def _read_leg(pr, i, leg, effector):
    """One [[legs]] table (leg i + 1) of a mechanism with this end effector: a Leg, or None."""
    label = f"leg {i + 1}"
    if not isinstance(leg, dict):
        return pr.add(entry("legs", label), f"each [[legs]] entry must be a table, got "
                                            f"{type(leg).__name__}")
    kind = pr.choice(entry("legs.kind", label), leg.get("kind", "RRR"), {k: k for k in LEG_KINDS})
    if kind is None:
        return None
    required, optional = _LEG_KEYS[kind]
    if effector == "platform":
        required = required | {"attach"}
    ok = pr.keys("legs", leg, required | optional, required, label=label)
    if effector == "point" and "attach" in leg:
        ok = pr.add(entry("legs.attach", label), "only a platform's legs have an attachment point "
                                                 "(set [model] end_effector = \"platform\")")
    at = {k: entry(f"legs.{k}", label) for k in leg}
    attach = pr.point(at["attach"], leg["attach"]) if "attach" in leg else None
    if kind == "RRR":
        base = pr.point(at["base"], leg["base"]) if "base" in leg else None
        la, lb = (pr.number(at[k], leg[k], **RULES["pos"]) if k in leg else None
                  for k in ("la", "lb"))
        elbow = pr.choice(at["elbow"], leg["elbow"], ELBOWS) if "elbow" in leg else None
        if not ok or None in (base, la, lb, elbow):
            return None
        return Leg(base=base, la=la, lb=lb, elbow=elbow, attach=attach)
    if kind == "PRR":
        rail = _rail(pr, at.get("rail"), leg.get("rail"))
        lb = pr.number(at["lb"], leg["lb"], **RULES["pos"]) if "lb" in leg else None
        branch = pr.choice(at["branch"], leg["branch"], PRR_BRANCHES) if "branch" in leg else None
        if not ok or None in (rail, lb, branch):
            return None
        return Leg(base=rail[0], la=None, lb=lb, elbow=branch, kind="PRR", attach=attach,
                   rail_end=rail[1])
    base = pr.point(at["base"], leg["base"]) if "base" in leg else None
    stroke = _stroke(pr, at.get("stroke"), leg.get("stroke"))
    if not ok or None in (base, stroke):
        return None
    return Leg(base=base, la=None, lb=None, elbow=None, kind="RPR", attach=attach, stroke=stroke)


def _rail(pr, key, value):
    """A PRR rail [[x0, y0], [x1, y1]] in m, of positive length: (start, end), or None."""
    if value is None:
        return None
    if not (isinstance(value, list) and len(value) == 2):
        return pr.add(key, f"must be [[x0, y0], [x1, y1]], the rail's two ends in m, got "
                           f"{value!r}")
    ends = [pr.point(key, v) for v in value]
    if None in ends:
        return None
    if ends[0] == ends[1]:
        return pr.add(key, f"the rail has zero length (both ends at {list(ends[0])}): the slider "
                           f"has no direction to move in")
    return tuple(ends)


def _stroke(pr, key, value):
    """An RPR stroke [min, max] of the leg's length in m, 0 < min < max: a tuple, or None."""
    if value is None:
        return None
    if not (isinstance(value, list) and len(value) == 2):
        return pr.add(key, f"must be [min, max], the leg's shortest and longest length in m, got "
                           f"{value!r}")
    lo, hi = (pr.number(key, v, **RULES["pos"]) for v in value)
    if None in (lo, hi):
        return None
    if not lo < hi:
        return pr.add(key, f"the shortest length must be below the longest, got [{lo}, {hi}]")
    return (lo, hi)


#: bound of each theta key in [nominal] and [plant] (validate.RULES)
_THETA_RULES = {"alpha": ("pos", "pos"), "beta": ("pos", "any"), "gamma": ("pos", "pos"),
                "kappa": ("any", "any"), "m_p": ("pos", "pos"), "mx_p": ("any", "any"),
                "my_p": ("any", "any"), "I_p": ("pos", "pos")}


def _read_theta(pr, section, table, groups, plant=False):
    """The theta entries of ``groups`` from [nominal] or [plant]: {key: tuple or float}, the
    valid ones only; every leg's M_i and the platform checked positive definite."""
    values = {}
    for key, idx in groups:
        if key not in table:
            continue
        rule = _THETA_RULES.get(key, ("nonneg", "nonneg"))[plant]
        if idx is None:
            values[key] = pr.number(f"{section}.{key}", table[key], **RULES[rule])
        else:
            labels = [f"leg {i + 1}" for i in idx]
            meaning = (f", one per leg (the file has {len(idx)} [[legs]])" if len(idx) ==
                       max(len(g[1]) for g in groups if g[1] is not None)
                       else f", one per leg that has one: {', '.join(labels)}")
            values[key] = pr.vector(f"{section}.{key}", table[key], labels, meaning=meaning,
                                    **RULES[rule])
    if all(values.get(k) is not None for k in INERTIAL):
        for i in range(len(values["alpha"])):
            why = inertia_problem(*(float(values[k][i]) for k in INERTIAL))
            if why is not None:
                pr.add(entry(f"{section}.beta", f"leg {i + 1}"), f"leg {i + 1} {why}")
    if all(values.get(k) is not None for k in PLATFORM_PARAMS) and any(
            idx is None for _, idx in groups):
        why = platform_inertia_problem(*(values[k] for k in PLATFORM_PARAMS))
        if why is not None:
            pr.add(f"{section}.I_p", why)
    return {k: v for k, v in values.items() if v is not None}


def _flatten(groups, values):
    return [values[key] if idx is None else values[key][j] for key, idx in groups
            for j in (range(len(idx)) if idx is not None else [0])]


_BODY_RULES = {"mass": "pos", "com": "any", "inertia": "nonneg", "density": "pos"}


def _read_bodies(pr, where, kind, raw):
    """One leg's bodies {body: {key: float}} from its [[<section>.links]] table, or None. A
    body with a length (ROD_LENGTH) may be a uniform rod {density}, kept as such."""
    if not isinstance(raw, dict):
        return pr.add(where, f"must be a table of the leg's bodies {sorted(LINK_BODIES[kind])}, "
                             f"got {type(raw).__name__}")
    if not pr.keys(where, raw, LINK_BODIES[kind], LINK_BODIES[kind]):
        return None
    out = {}
    for body, keys in LINK_BODIES[kind].items():
        table = raw[body]
        if not isinstance(table, dict):
            return pr.add(f"{where}.{body}", f"must be a table {{ {', '.join(keys)} }}, got "
                                             f"{table!r}")
        if "density" in table:
            if body not in ROD_LENGTH.get(kind, {}):
                return pr.add(f"{where}.{body}.density",
                              f"only a body with a length (RRR proximal and distal, PRR link) "
                              f"may be a uniform rod {{ density }}; give a {kind} {body}'s "
                              f"{', '.join(keys)}")
            keys = ("density",)
        if not pr.keys(f"{where}.{body}", table, keys, keys):
            return None
        values = {k: pr.number(f"{where}.{body}.{k}", table[k], **RULES[_BODY_RULES[k]])
                  for k in keys}
        if None in values.values():
            return None
        out[body] = values
    return out


def _expand_links(pr, section, table, legs, groups, kept=None):
    """``table`` with [[<section>.links]] (one table per leg) and [<section>.platform] (mass,
    com, inertia) replaced by theta's inertial entries they give (lumped_from_links,
    platform_from_body), and the keys they claim but could not give (invalid bodies, reported).
    Giving an entry both ways is a problem. ``kept[section]``: the legs' bodies (a tuple, rods
    as {density}), when they are valid and some body is a rod (ModelSpec.links)."""
    if not isinstance(table, dict) or not ({"links", "platform"} & set(table)):
        return table, set()
    out, claimed = dict(table), set()
    per_leg = [k for k, idx in groups if idx is not None and k in INERTIAL + (FIRST_MOMENT,)]
    scalars = [k for k, idx in groups if idx is None]
    if "links" in out:
        links = out.pop("links")
        claimed.update(per_leg)
        given = [k for k in per_leg if k in out]
        for k in given:   # reported once; the links' value is checked
            out.pop(k)
            pr.add(f"{section}.{k}", f"given twice: by this key and by [[{section}.links]]")
        if not (isinstance(links, list) and len(links) == len(legs)):
            pr.add(f"{section}.links", f"must be one [[{section}.links]] table per leg (the file "
                                       f"has {len(legs)} [[legs]]), got {links!r}"[:300])
        elif None not in legs:   # (an invalid leg is reported already)
            bodies = [_read_bodies(pr, entry(f"{section}.links", f"leg {i + 1}"), leg.kind, raw)
                      for i, (leg, raw) in enumerate(zip(legs, links))]
            if None not in bodies:
                if kept is not None and any("density" in body for b in bodies
                                            for body in b.values()):
                    kept[section] = tuple(bodies)
                lumped = [lumped_from_links(leg, b) for leg, b in zip(legs, bodies)]
                for key, idx in groups:
                    if key in per_leg:
                        out[key] = [lumped[i][key] for i in idx]
    if "platform" in out and scalars:
        body = out.pop("platform")
        claimed.update(scalars)
        where = f"{section}.platform"
        for k in scalars:
            if k in out:
                out.pop(k)
                pr.add(f"{section}.{k}", f"given twice: by this key and by [{where}]")
        if isinstance(body, dict) and pr.keys(where, body, ("mass", "com", "inertia"),
                                              ("mass", "com", "inertia")):
            mass = pr.number(f"{where}.mass", body["mass"], **RULES["pos"])
            com = pr.point(f"{where}.com", body["com"])
            inertia = pr.number(f"{where}.inertia", body["inertia"], **RULES["pos"])
            if None not in (mass, com, inertia):
                out.update(zip(PLATFORM_PARAMS, platform_from_body(mass, com, inertia)))
        elif not isinstance(body, dict):
            pr.add(where, f"must be a table {{ mass, com, inertia }}, got {body!r}")
    # keys the links claim but could not give (their problems are reported): not "missing"
    return out, claimed - set(out)


def _read_nominal(pr, nominal, groups, legs, kept=None):
    """[nominal]: theta's names and values (None when invalid); ``kept``: as _expand_links."""
    param_names = theta_names(groups)
    if nominal is None:
        return param_names, None
    nominal, unknown = _expand_links(pr, "nominal", nominal, legs, groups, kept)
    keys = [key for key, _ in groups]
    pr.keys("nominal", nominal, keys, set(keys) - unknown)
    values = _read_theta(pr, "nominal", nominal, groups)
    if any(values.get(key) is None for key in keys):
        return param_names, None
    return param_names, _frozen(_flatten(groups, values))


# run-time sections: key -> (length: None for a scalar, "n" per leg, "p" per parameter, "m"
#                             per task coordinate; rule: a validate.RULES key;
#                             default: a third entry makes the key optional, None: the
#                             caller fills it in)
_SCHEMA = {
    "limits": {"singularity_threshold": (None, "pos"), "tau_max": ("n", "pos"),
               "parallel_singularity_threshold": (None, "pos", DEFAULT_PARALLEL_THRESHOLD)},
    "sensing": {"sample_period": (None, "pos"), "encoder_counts_per_rev": (None, "nonneg"),
                "velocity_filter_hz": (None, "nonneg"),
                "closure_tolerance": (None, "pos", None),    # default: default_closure_tolerance
                # m per count of the prismatic actuators' encoders (0: exact); required when a
                # leg has one (PRR, RPR)
                "linear_encoder_resolution": (None, "nonneg", None)},
    "gains.na": {"Kd": ("m", "pos"), "Q": ("m", "pos"), "Gamma": ("p", "nonneg")},
    "gains.apd": {"Kp": ("m", "pos"), "Kv": ("m", "pos")},
    # optional: computed torque (1/s^2, 1/s) and the LQR's weights (1/m^2, s^2/m^2, 1/(N m)^2)
    "gains.ctc": {"Kp": ("m", "pos"), "Kv": ("m", "pos")},
    "gains.lqr": {"Q_position": ("m", "pos"), "Q_velocity": ("m", "pos"), "R": ("n", "pos")},
    # and theta's inertial entries (theta_groups, read by _read_theta)
    "plant": {"payload_mass": (None, "nonneg"), "payload_leg": (None, "pos"),
              "fv": ("n", "nonneg"), "fc": ("n", "nonneg"), "fs": ("n", "nonneg"),
              "stribeck_velocity": (None, "pos"), "coulomb_smoothing_velocity": (None, "pos")},
    "trajectory": {"start": ("m", "any"), "end": ("m", "any"), "v_max": (None, "pos"),
                   "a_max": (None, "pos"), "j_max": (None, "pos")},
    # a move along a path file (pm2dof.planning): the kinematic limits are optional (default:
    # the path file's [kinematic]); `path` is read separately (a string)
    "path_move": {"v_max": (None, "pos", None), "a_max": (None, "pos", None),
                  "j_max": (None, "pos", None)},
}


def _read_section(pr, where, table, schema, n, param_names, task=("x", "y"), extra=()):
    """A table of numbers and arrays by ``schema``: {key: float or read-only array}, holding
    only the valid entries (and the defaults of absent optional ones); None for no table.
    ``task``: the task coordinates' names; ``extra``: more keys, required, read by the caller."""
    if table is None:
        return None
    pr.keys(where, table, set(schema) | set(extra),
            {k for k, spec in schema.items() if len(spec) == 2} | set(extra))
    out = {}
    for key, (length, rule, *default) in schema.items():
        if key not in table:
            if default and default[0] is not None:
                out[key] = default[0]
            continue
        if length is None:
            value = pr.number(f"{where}.{key}", table[key], **RULES[rule])
        else:
            labels, meaning = _size(length, n, param_names, task)
            value = pr.vector(f"{where}.{key}", table[key], labels, meaning=meaning, **RULES[rule])
            value = None if value is None else _frozen(value)
        if value is not None:
            out[key] = value
    return out


def _read_limits(pr, doc, n, param_names):
    limits = _read_section(pr, "limits", pr.table("limits", doc.get("limits")),
                           _SCHEMA["limits"], n, param_names)
    for key in ("singularity_threshold", "parallel_singularity_threshold"):
        if limits is not None and limits.get(key, 0) >= 1:  # both measures lie in [0, 1]
            pr.add(f"limits.{key}", f"bounds a measure in [0, 1], must be < 1, got {limits[key]}")
    return limits


def _read_runtime(pr, doc, n, param_names, legs, groups, effector, kept=None):
    """The run-time sections [sensing], [gains.*], [plant]; ``kept``: as _expand_links."""
    task = END_EFFECTORS.get(effector, ("x", "y"))
    sensing_raw = pr.table("sensing", doc.get("sensing"))
    sensing = _read_section(pr, "sensing", sensing_raw, _SCHEMA["sensing"], n, param_names)
    counts = (sensing or {}).get("encoder_counts_per_rev")
    if counts is not None and counts != int(counts):
        counts = pr.add("sensing.encoder_counts_per_rev", f"must be a whole number (0: no "
                                                          f"quantisation), got {counts}")
    linear = (sensing or {}).get("linear_encoder_resolution")
    prismatic = [i + 1 for i, leg in enumerate(legs) if leg is not None and leg.actuator != "revolute"]
    if sensing is not None and prismatic and "linear_encoder_resolution" not in sensing_raw:
        pr.add("sensing.linear_encoder_resolution",
               f"required: legs {prismatic} have prismatic actuators (m per count, 0: exact)")
    if (sensing is not None and "closure_tolerance" not in sensing_raw and counts is not None
            and None not in legs and (linear is not None or not prismatic)):
        sensing["closure_tolerance"] = default_closure_tolerance(legs, counts, linear)
    gains_raw = pr.table("gains", doc.get("gains"))
    gains = {}
    if gains_raw is not None:
        pr.keys("gains", gains_raw, contract.LAWS, ("na", "apd"))
        for law in contract.LAWS:
            if law not in gains_raw and law in ("ctc", "lqr"):    # optional: code defaults
                continue
            gains[law] = _read_section(
                pr, f"gains.{law}", pr.table(f"gains.{law}", gains_raw.get(law), required=False),
                _SCHEMA[f"gains.{law}"], n, param_names, task)
    plant = _read_plant(pr, pr.table("plant", doc.get("plant")), n, param_names, groups, effector,
                        legs, kept)
    return sensing, gains, plant


def _read_plant(pr, raw, n, param_names, groups, effector, legs, kept=None):
    """[plant]: theta's inertial entries (the truth), the payload and the plant's friction.
    A platform carries its payload at its origin; a point end effector books it to a leg.
    ``kept``: as _expand_links."""
    schema = dict(_SCHEMA["plant"])
    if effector == "platform":
        del schema["payload_leg"]
    inertial = [(key, idx) for key, idx in groups if key not in FRICTION_MODELS[
        "coulomb_viscous_stribeck"]]
    raw, unknown = _expand_links(pr, "plant", raw, legs, inertial, kept)
    plant = _read_section(pr, "plant", raw, schema, n, param_names,
                          extra=[key for key, _ in inertial if key not in unknown])
    if plant is None:
        return None
    values = _read_theta(pr, "plant", raw, inertial, plant=True)
    plant.update({k: v if isinstance(v, float) else _frozen(v) for k, v in values.items()})
    leg = plant.get("payload_leg")
    if leg is not None and (leg != int(leg) or not 1 <= leg <= n):
        shown = int(leg) if leg == int(leg) else leg       # read as a float: 9, not 9.0
        pr.add("plant.payload_leg", f"must be a leg number 1..{n} (1-based), got {shown}")
    return plant


def _read_trajectories(pr, doc, n, param_names, legs, task):
    """[trajectories.<name>]: at least one move, whose end poses every leg reaches."""
    raw = pr.table("trajectories", doc.get("trajectories"))
    if raw is None:
        return None
    if not raw:
        pr.add("trajectories", "needs at least one [trajectories.<name>] table")
    trajs = {}
    for name, t in raw.items():
        t = pr.table(f"trajectories.{name}", t)
        if isinstance(t, dict) and "path" in t:   # a path file, planned by pm2dof.planning
            rest = {k: v for k, v in t.items() if k != "path"}
            move = _read_section(pr, f"trajectories.{name}", rest, _SCHEMA["path_move"], n,
                                 param_names, task)
            ref = pr.text(f"trajectories.{name}.path", t["path"], nonempty=True)
            trajs[name] = None if move is None or ref is None else {**move, "path": ref}
            continue
        trajs[name] = _read_section(pr, f"trajectories.{name}", t, _SCHEMA["trajectory"], n,
                                    param_names, task)
    for name, t in trajs.items():  # the legs must meet: every end pose within every leg's reach
        for end in ("start", "end"):
            if t is not None and end in t:
                _check_reach(pr, f"trajectories.{name}.{end}", legs, t[end])
        if t is not None and "start" in t and "end" in t and np.array_equal(t["start"], t["end"]):
            pr.add(f"trajectories.{name}", "start and end are the same point")
    return trajs


def _check_reach(pr, key, legs, pose):
    """One problem per leg that cannot reach the task pose (x, y) or (x, y, phi)."""
    if None in legs or (len(pose) == 3 and any(leg.attach is None for leg in legs)):
        return
    pose = [float(v) for v in pose]
    for i, why in reach_problems(legs, pose):
        what = "the legs cannot meet" if len(pose) == 2 else "the platform is out of reach"
        pr.add(key, f"{what} at {pose}: leg {i + 1} ({legs[i].kind}) {why}")


def _read_platform(pr, doc, effector, legs, limits):
    """[platform] (a platform only): ``home``, the pose (x, y, phi) that seeds fk, within
    every leg's reach and clear of both singularities by ``limits``' thresholds."""
    raw = doc.get("platform")
    if effector != "platform":
        if raw is not None:
            pr.add("platform", "only for [model] end_effector = \"platform\"")
        return None
    raw = pr.table("platform", raw)
    if raw is None:
        return None
    pr.keys("platform", raw, ("home",), ("home",))
    if "home" not in raw:
        return None
    home = pr.vector("platform.home", raw["home"], ["x", "y", "phi"],
                     meaning=" [x, y, phi] in m, m, rad")
    if home is not None:
        found = len(pr)
        _check_reach(pr, "platform.home", legs, home)
        if len(pr) == found:
            _check_home_clear(pr, legs, home, limits or {})
    return home


def _check_home_clear(pr, legs, home, limits):
    """A problem for a home within a singularity threshold, naming the measure, its value at
    home and the threshold. fk's Gauss-Newton starts at home: at a type II singularity its
    normal equations are singular (every fk fails), and a leg at a type I singularity there
    has no working mode to read (Model._fk_same_mode). The measures are computed from the
    file's geometry (pm2dof.core.measures), the same as the generated singularity_measures."""
    if None in legs or any(leg.attach is None for leg in legs):
        return
    type1, type2, per_leg = pose_measures(legs, home)
    thr = limits.get("parallel_singularity_threshold")
    if thr is not None and thr < 1 and not type2 >= thr:      # (a threshold >= 1 is reported)
        pr.add("platform.home", f"{list(home)} is too close to a type II (parallel) "
                                f"singularity, where the legs' lines of action are concurrent "
                                f"or all parallel and the actuators lose a direction of the "
                                f"platform: the measure {TYPE_II_MEASURES['platform']} is "
                                f"{type2:.3g} < limits.parallel_singularity_threshold = {thr:g}. "
                                f"fk's Gauss-Newton starts at home and cannot converge from "
                                f"there; choose another home")
    thr = limits.get("singularity_threshold")
    low = [(i, leg, value) for i, (leg, value) in enumerate(zip(legs, per_leg))
           if thr is not None and thr < 1 and not value >= thr]
    if low:
        which = "; ".join(
            f"leg{'s' if len(group) > 1 else ''} {', '.join(str(i + 1) for i, _ in group)} "
            f"({kind}; 0 at {TYPE_I_MEASURES[kind][1]}): {TYPE_I_MEASURES[kind][0]} = "
            f"{', '.join(f'{v:.3g}' for _, v in group)}"
            for kind in LEG_KINDS
            if (group := [(i, v) for i, leg, v in low if leg.kind == kind]))
        pr.add("platform.home", f"{list(home)} is too close to a type I singularity: {which}; "
                                f"below limits.singularity_threshold = {thr:g}. fk reads each "
                                f"leg's working mode at home; choose another home")


def _read_control(pr, doc, n, tau_max):
    """[control] (optional): the torque split and the preload split's signs and levels."""
    raw = pr.table("control", doc.get("control"), required=False)
    if raw is None:
        if "control" in doc:  # not a table: reported
            return None
        raw = {}
    pr.keys("control", raw, ("split", "preload", "preload_sign"))
    out = {"split": pr.choice("control.split", raw.get("split", "min_norm"),
                              {k: k for k in SPLITS})}
    labels, meaning = _size("n", n, ())
    for key, fill, rule in (("preload", 0.0, "nonneg"), ("preload_sign", 1, "any")):
        value = pr.vector(f"control.{key}", raw.get(key, [fill] * n), labels, meaning=meaning,
                          **RULES[rule])
        out[key] = None if value is None else _frozen(value)
    sign, preload = out["preload_sign"], out["preload"]
    for i in range(n):
        if sign is not None and sign[i] not in (1.0, -1.0):
            pr.add(entry("control.preload_sign", f"leg {i + 1}"),
                   f"must be +1 or -1, got {sign[i]:g}")
        if preload is not None and tau_max is not None and preload[i] >= tau_max[i]:
            pr.add(entry("control.preload", f"leg {i + 1}"),
                   f"must stay below limits.tau_max (leg {i + 1}) = {tau_max[i]:g} N m, got "
                   f"{preload[i]:g}")
    return out


def read_model_file(path):
    """Read and validate a model file.

    Parameters
    ----------
    path : str or pathlib.Path
        A TOML model file (see ``pm2dof/models/shang2010.toml``, or docs/model-file.md, for the format).

    Returns
    -------
    ModelSpec

    Raises
    ------
    ModelFileError
        Listing every problem of the file at once (also as ``exc.problems``), each naming the
        key and the reason: missing or unknown keys, wrong types, arrays whose length does
        not match the number of ``[[legs]]`` or of parameters (the message gives the length
        and, for per-parameter arrays, the order ``param_names``), non-physical values. Legs
        are numbered from 1 (``nominal.alpha (leg 2)``). Unreadable or non-TOML content, fewer
        than two legs and an unknown friction model stop the checks early.
    """
    path = Path(path)
    pr = Problems(path, ModelFileError)
    raw, doc = _read_toml(pr, path)
    pr.keys("", doc, _TOP_KEYS)
    model = pr.table("model", doc.get("model"))
    name, friction, constants, fk_branch, substeps, effector, gravity = _read_model(pr, model)
    effector = effector or "point"
    if gravity is None:  # invalid (reported): theta's names as with gravity, for the checks
        gravity = (math.nan, math.nan)
    m = len(END_EFFECTORS[effector])
    legs_raw = doc.get("legs")
    if not isinstance(legs_raw, list) or len(legs_raw) < m:
        what = ("two [[legs]] tables (a planar 2-DOF mechanism)" if m == 2 else
                "three [[legs]] tables (a platform has 3 degrees of freedom)")
        pr.stop("legs", f"needs at least {what}")
    n = len(legs_raw)
    legs = tuple(_read_leg(pr, i, leg, effector) for i, leg in enumerate(legs_raw))
    if n == 2 and m == 2 and model is not None and "fk_branch" not in model:
        pr.add("model.fk_branch", "a two-leg mechanism must choose its forward-kinematics branch "
                                  "('left' or 'right' of the line B1 -> B2)")
    if friction is None:  # theta's names and size depend on it
        pr.raise_if_any()
    # theta's names depend on the legs' kinds (an invalid leg: the kind its table names)
    kinds = [leg if leg is not None else Leg(None, None, None, None, kind=str(
        table.get("kind", "RRR")) if isinstance(table, dict) else "RRR")
        for leg, table in zip(legs, legs_raw)]
    groups = theta_groups(kinds, effector, gravity, friction)
    kept = {}     # the bodies of [[nominal.links]], [[plant.links]] with a rod (ModelSpec.links)
    param_names, theta = _read_nominal(pr, pr.table("nominal", doc.get("nominal")), groups, legs,
                                       kept)
    limits = _read_limits(pr, doc, n, param_names)
    sensing, gains, plant = _read_runtime(pr, doc, n, param_names, legs, groups, effector, kept)
    sensing_raw = doc.get("sensing")
    design = read_design(pr, doc.get("design"), legs, effector, closure_default=not (
        isinstance(sensing_raw, dict) and "closure_tolerance" in sensing_raw))
    home = _read_platform(pr, doc, effector, legs, limits)
    trajs = _read_trajectories(pr, doc, n, param_names, legs, END_EFFECTORS[effector])
    control = _read_control(pr, doc, n, (limits or {}).get("tau_max"))
    pr.raise_if_any()
    spec = ModelSpec(
        path=str(path), name=name, description=str(model.get("description", "")),
        friction=friction, friction_constants=constants, fk_branch=fk_branch,
        rk4_substeps=substeps, legs=legs, param_names=param_names, theta_nominal=theta,
        limits=limits, sensing=sensing, gains=gains, plant=plant, trajectories=trajs,
        control=control, file_sha256=hashlib.sha256(raw).hexdigest(), end_effector=effector,
        gravity=tuple(gravity), home=None if home is None else tuple(home), design=design,
        links={"nominal": kept.get("nominal"), "plant": kept.get("plant")} if kept else None)
    formulation = json.dumps(spec.formulation(), sort_keys=True, separators=(",", ":"))
    object.__setattr__(spec, "formulation_sha256", hashlib.sha256(formulation.encode()).hexdigest())
    return spec


def _read_toml(pr, path):
    """The file's bytes and its TOML document; unreadable or undecodable content stops here."""
    return pr.read_toml("model file")
