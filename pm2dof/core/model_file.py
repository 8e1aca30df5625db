# Model files (TOML): read, validate, and split into the derivation's formulation and run-time data.
"""Read and validate a pm2dof model file.

A model file describes one planar parallel manipulator made of RR legs (``[[legs]]``), its
friction model, its nominal parameters (the paper's Tables 1-2) and run-time data (limits,
gains, plant truth, trajectories). Only ``[model]`` and ``[[legs]]`` enter the generated C;
their canonical hash (:attr:`ModelSpec.formulation_sha256`) guards generated code against
staleness. This module is pure Python and is shared by ``derive/`` and the runtime.
"""
import hashlib
import json
import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .errors import ModelFileError
from .validate import RULES, Problems, entry

__all__ = ["ModelSpec", "Leg", "read_model_file", "FRICTION_MODELS", "ELBOWS"]

# friction model -> its per-leg parameters after the inertial ones (eq. 2 and extensions)
FRICTION_MODELS = {
    "coulomb_viscous": ("fv", "fc"),                 # eq. 2, sign(0) = 0
    "coulomb_viscous_stribeck": ("fv", "fc", "fs"),  # + fs sign(v) / (1 + (v/vs)^2)
    "smooth_sign": ("fv", "fc"),                     # sign(v) -> v / sqrt(v^2 + eps^2)
}
FRICTION_CONSTANTS = {  # formulation constants each friction model needs in [model]
    "coulomb_viscous": (),
    "coulomb_viscous_stribeck": ("stribeck_velocity",),
    "smooth_sign": ("sign_smoothing_velocity",),
}
INERTIAL = ("alpha", "beta", "gamma")
#: [limits] parallel_singularity_threshold when a model file does not set it (type II measure,
#: see Model.singularity_measures; 0.1 is about 8 degrees between a five-bar's distal links)
DEFAULT_PARALLEL_THRESHOLD = 0.1
ELBOWS = {"left": 1, "right": -1}
#: smallest default [sensing] closure_tolerance, m (exact encoders still meet rounding)
CLOSURE_FLOOR = 1e-6
FK_BRANCHES = {"left": 1, "right": -1}

_MODEL_KEYS = {"name", "description", "friction", "fk_branch", "stribeck_velocity",
               "sign_smoothing_velocity", "rk4_substeps"}
_LEG_KEYS = {"base", "la", "lb", "elbow"}
_TOP_KEYS = {"model", "legs", "nominal", "limits", "sensing", "gains", "plant", "trajectories",
             "control"}
#: torque distributions among the actuators (S^T tau_a = u; derive/splits.py)
SPLITS = ("min_norm", "min_max", "preload")


@dataclass(frozen=True)
class Leg:
    """One RR leg: base ``A`` (2,) in m, link lengths ``la``, ``lb`` in m, elbow +1 left / -1 right."""
    base: tuple
    la: float
    lb: float
    elbow: int


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

    @property
    def n_legs(self):
        return len(self.legs)

    @property
    def bases(self):
        return np.array([leg.base for leg in self.legs], dtype=float)

    def formulation(self):
        """The part of the model that enters the generated code, as canonical JSON-able data."""
        return {
            "name": self.name,
            "friction": self.friction,
            "friction_constants": dict(sorted(self.friction_constants.items())),
            "fk_branch": self.fk_branch,
            "rk4_substeps": self.rk4_substeps,
            "legs": [{"base": list(l.base), "la": l.la, "lb": l.lb, "elbow": l.elbow}
                     for l in self.legs],
        }


def _frozen(values):
    """A read-only float array of ``values``."""
    out = np.array(values, dtype=float)
    out.setflags(write=False)
    return out


def _size(length, n, param_names):
    """Labels and message text of an array of ``length``: "n" per leg (legs numbered from 1,
    as in the paper), "p" per parameter, or 2 (a task-space pair x, y)."""
    if length == "n":
        return [f"leg {i + 1}" for i in range(n)], f", one per leg (the file has {n} [[legs]])"
    if length == "p":
        return ([f"entry {k + 1}, {name}" for k, name in enumerate(param_names)],
                f", one per parameter of theta, in the order of param_names: "
                f"{', '.join(param_names)}")
    return ["x", "y"], " [x, y]"


def _read_model(pr, model):
    """[model]: name, friction and its constants, fk_branch, rk4_substeps (None where invalid)."""
    if model is None:
        return None, None, {}, None, None
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
    return name, friction, constants, fk_branch, substeps


def _read_leg(pr, i, leg):
    """One [[legs]] table (leg i + 1): a Leg, or None."""
    label = f"leg {i + 1}"
    if not isinstance(leg, dict):
        return pr.add(entry("legs", label), f"each [[legs]] entry must be a table, got "
                                            f"{type(leg).__name__}")
    ok = pr.keys("legs", leg, _LEG_KEYS, _LEG_KEYS, label=label)
    base = pr.point(entry("legs.base", label), leg["base"]) if "base" in leg else None
    la, lb = (pr.number(entry(f"legs.{k}", label), leg[k], **RULES["pos"]) if k in leg else None
              for k in ("la", "lb"))
    elbow = pr.choice(entry("legs.elbow", label), leg["elbow"], ELBOWS) if "elbow" in leg else None
    if not ok or None in (base, la, lb, elbow):
        return None
    return Leg(base=base, la=la, lb=lb, elbow=elbow)


def inertia_problem(alpha, beta, gamma):
    """Why one leg's M_i (eq. 1) is not positive definite for every c_i, or None: the rule for
    [nominal] and for any theta a plan takes (alpha, gamma > 0, beta^2 < alpha gamma)."""
    if not (alpha > 0 and gamma > 0):
        return f"alpha and gamma must be > 0, got alpha = {alpha:.6g}, gamma = {gamma:.6g}"
    if beta * beta >= alpha * gamma:
        return (f"inertia is not positive definite: beta^2 = {beta * beta:.6g} >= "
                f"alpha*gamma = {alpha * gamma:.6g}")
    return None


def _check_inertia(pr, section, values, n):
    """M_i positive definite (alpha, gamma > 0 are checked apart, so only beta^2 < alpha gamma
    can still fail here)."""
    if any(values.get(k) is None for k in INERTIAL):
        return
    for i in range(n):
        why = inertia_problem(*(float(values[k][i]) for k in INERTIAL))
        if why is not None:
            pr.add(entry(f"{section}.beta", f"leg {i + 1}"), f"leg {i + 1} {why}")


def _read_nominal(pr, nominal, n, friction):
    """[nominal]: theta's names and values (None when invalid)."""
    names = INERTIAL + FRICTION_MODELS[friction]
    param_names = tuple(f"{key}{i + 1}" for key in names for i in range(n))
    if nominal is None:
        return param_names, None
    pr.keys("nominal", nominal, names, names)
    labels, meaning = _size("n", n, param_names)
    values = {key: pr.vector(f"nominal.{key}", nominal[key], labels, meaning=meaning,
                             **RULES["pos" if key in INERTIAL else "nonneg"])
              for key in names if key in nominal}
    _check_inertia(pr, "nominal", values, n)
    if any(values.get(key) is None for key in names):
        return param_names, None
    return param_names, _frozen([values[key][i] for key in names for i in range(n)])


# run-time sections: key -> (length: None for a scalar, "n" per leg, "p" per parameter, or 2
#                             for a task-space pair; rule: a validate.RULES key;
#                             default: a third entry makes the key optional, None: the
#                             caller fills it in)
_SCHEMA = {
    "limits": {"singularity_threshold": (None, "pos"), "tau_max": ("n", "pos"),
               "parallel_singularity_threshold": (None, "pos", DEFAULT_PARALLEL_THRESHOLD)},
    "sensing": {"sample_period": (None, "pos"), "encoder_counts_per_rev": (None, "nonneg"),
                "velocity_filter_hz": (None, "nonneg"),
                "closure_tolerance": (None, "pos", None)},   # default: default_closure_tolerance
    "gains.na": {"Kd": (2, "pos"), "Q": (2, "pos"), "Gamma": ("p", "nonneg")},
    "gains.apd": {"Kp": (2, "pos"), "Kv": (2, "pos")},
    # optional: computed torque (1/s^2, 1/s) and the LQR's weights (1/m^2, s^2/m^2, 1/(N m)^2)
    "gains.ctc": {"Kp": (2, "pos"), "Kv": (2, "pos")},
    "gains.lqr": {"Q_position": (2, "pos"), "Q_velocity": (2, "pos"), "R": ("n", "pos")},
    "plant": {"alpha": ("n", "pos"), "beta": ("n", "any"), "gamma": ("n", "pos"),
              "payload_mass": (None, "nonneg"), "payload_leg": (None, "pos"),
              "fv": ("n", "nonneg"), "fc": ("n", "nonneg"), "fs": ("n", "nonneg"),
              "stribeck_velocity": (None, "pos"), "coulomb_smoothing_velocity": (None, "pos")},
    "trajectory": {"start": (2, "any"), "end": (2, "any"), "v_max": (None, "pos"),
                   "a_max": (None, "pos"), "j_max": (None, "pos")},
    # a move along a path file (pm2dof.planning): the kinematic limits are optional (default:
    # the path file's [kinematic]); `path` is read separately (a string)
    "path_move": {"v_max": (None, "pos", None), "a_max": (None, "pos", None),
                  "j_max": (None, "pos", None)},
}


def _read_section(pr, where, table, schema, n, param_names):
    """A table of numbers and arrays by ``schema``: {key: float or read-only array}, holding
    only the valid entries (and the defaults of absent optional ones); None for no table."""
    if table is None:
        return None
    pr.keys(where, table, schema, {k for k, spec in schema.items() if len(spec) == 2})
    out = {}
    for key, (length, rule, *default) in schema.items():
        if key not in table:
            if default and default[0] is not None:
                out[key] = default[0]
            continue
        if length is None:
            value = pr.number(f"{where}.{key}", table[key], **RULES[rule])
        else:
            labels, meaning = _size(length, n, param_names)
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


def default_closure_tolerance(legs, encoder_counts_per_rev):
    """[sensing] closure_tolerance when a model file does not set it, m: five encoder steps at
    the longest active link, at least 1 um. (One step moves an elbow by la * 2 pi / counts;
    quantised angles over the paper robot's workspace give residuals up to 0.8 of that, and
    up to 1.3 with a full step of error: tests/core/test_closure.py measures it.)"""
    if encoder_counts_per_rev <= 0:
        return CLOSURE_FLOOR
    step = 2 * math.pi / encoder_counts_per_rev
    return max(CLOSURE_FLOOR, 5 * max(leg.la for leg in legs) * step)


def _read_runtime(pr, doc, n, param_names, legs):
    """The run-time sections [sensing], [gains.*], [plant]."""
    sensing_raw = pr.table("sensing", doc.get("sensing"))
    sensing = _read_section(pr, "sensing", sensing_raw, _SCHEMA["sensing"], n, param_names)
    counts = (sensing or {}).get("encoder_counts_per_rev")
    if counts is not None and counts != int(counts):
        counts = pr.add("sensing.encoder_counts_per_rev", f"must be a whole number (0: no "
                                                          f"quantisation), got {counts}")
    if (sensing is not None and "closure_tolerance" not in sensing_raw and counts is not None
            and None not in legs):
        sensing["closure_tolerance"] = default_closure_tolerance(legs, counts)
    gains_raw = pr.table("gains", doc.get("gains"))
    gains = {}
    if gains_raw is not None:
        pr.keys("gains", gains_raw, ("na", "apd", "ctc", "lqr"), ("na", "apd"))
        for law in ("na", "apd", "ctc", "lqr"):
            if law not in gains_raw and law in ("ctc", "lqr"):    # optional: code defaults
                continue
            gains[law] = _read_section(
                pr, f"gains.{law}", pr.table(f"gains.{law}", gains_raw.get(law), required=False),
                _SCHEMA[f"gains.{law}"], n, param_names)
    plant = _read_section(pr, "plant", pr.table("plant", doc.get("plant")), _SCHEMA["plant"], n,
                          param_names)
    leg = (plant or {}).get("payload_leg")
    if leg is not None and (leg != int(leg) or not 1 <= leg <= n):
        pr.add("plant.payload_leg", f"must be a leg number 1..{n} (1-based), got {leg}")
    if plant is not None:
        _check_inertia(pr, "plant", plant, n)
    return sensing, gains, plant


def _read_trajectories(pr, doc, n, param_names, legs):
    """[trajectories.<name>]: at least one move, whose end points every leg reaches."""
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
                                 param_names)
            ref = pr.text(f"trajectories.{name}.path", t["path"], nonempty=True)
            trajs[name] = None if move is None or ref is None else {**move, "path": ref}
            continue
        trajs[name] = _read_section(pr, f"trajectories.{name}", t, _SCHEMA["trajectory"], n,
                                    param_names)
    for name, t in trajs.items():  # the legs must meet: every end point within every leg's reach
        for end in ("start", "end"):
            if t is None or end not in t or None in legs:
                continue
            for i, lg in enumerate(legs):
                dist = float(np.hypot(*(t[end] - np.asarray(lg.base))))
                lo, hi = abs(lg.la - lg.lb), lg.la + lg.lb
                if not lo <= dist <= hi:
                    pr.add(f"trajectories.{name}.{end}",
                           f"the legs cannot meet at {t[end].tolist()}: leg {i + 1} is "
                           f"{dist:.4g} m from its base, its reach is [{lo:.4g}, {hi:.4g}] m")
        if t is not None and "start" in t and "end" in t and np.array_equal(t["start"], t["end"]):
            pr.add(f"trajectories.{name}", "start and end are the same point")
    return trajs


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
    name, friction, constants, fk_branch, substeps = _read_model(pr, model)
    legs_raw = doc.get("legs")
    if not isinstance(legs_raw, list) or len(legs_raw) < 2:
        pr.stop("legs", "needs at least two [[legs]] tables (a planar 2-DOF mechanism)")
    n = len(legs_raw)
    legs = tuple(_read_leg(pr, i, leg) for i, leg in enumerate(legs_raw))
    if n == 2 and model is not None and "fk_branch" not in model:
        pr.add("model.fk_branch", "a two-leg mechanism must choose its forward-kinematics branch "
                                  "('left' or 'right' of the line B1 -> B2)")
    if friction is None:  # theta's names and size depend on it
        pr.raise_if_any()
    param_names, theta = _read_nominal(pr, pr.table("nominal", doc.get("nominal")), n, friction)
    limits = _read_limits(pr, doc, n, param_names)
    sensing, gains, plant = _read_runtime(pr, doc, n, param_names, legs)
    trajs = _read_trajectories(pr, doc, n, param_names, legs)
    control = _read_control(pr, doc, n, (limits or {}).get("tau_max"))
    pr.raise_if_any()
    spec = ModelSpec(
        path=str(path), name=name, description=str(model.get("description", "")),
        friction=friction, friction_constants=constants, fk_branch=fk_branch,
        rk4_substeps=substeps, legs=legs, param_names=param_names, theta_nominal=theta,
        limits=limits, sensing=sensing, gains=gains, plant=plant, trajectories=trajs,
        control=control, file_sha256=hashlib.sha256(raw).hexdigest())
    formulation = json.dumps(spec.formulation(), sort_keys=True, separators=(",", ":"))
    object.__setattr__(spec, "formulation_sha256", hashlib.sha256(formulation.encode()).hexdigest())
    return spec


def _read_toml(pr, path):
    """The file's bytes and its TOML document; unreadable or undecodable content stops here."""
    try:
        raw = path.read_bytes()
    except OSError as exc:
        pr.stop(None, f"cannot read model file: {exc.strerror or exc}")
    nul = raw.find(b"\x00")
    if nul >= 0:
        pr.stop(None, f"binary content (NUL byte at offset {nul}), not a TOML model file")
    try:
        return raw, tomllib.loads(raw.decode("utf-8"))
    except UnicodeDecodeError as exc:
        pr.stop(None, f"not a text (UTF-8) file: {exc.reason} at byte {exc.start}")
    except tomllib.TOMLDecodeError as exc:
        pr.stop(None, f"not valid TOML: {exc}")
