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

__all__ = ["ModelSpec", "Leg", "read_model_file", "FRICTION_MODELS", "ELBOWS"]

# friction model -> its per-leg parameters after the inertial ones (eq. 2 and extensions)
FRICTION_MODELS = {
    "coulomb_viscous": ("fv", "fc"),                 # eq. 2, sign(0) = +1
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


def _fail(path, key, reason):
    raise ModelFileError(f"{path}: [{key}] {reason}")


def _number(path, key, value, *, positive=False, nonnegative=False):
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        _fail(path, key, f"must be a number, got {type(value).__name__} {value!r}")
    try:
        value = float(value)
    except OverflowError:
        _fail(path, key, f"is too large for a float: {str(value)[:20]}...")
    if not math.isfinite(value):
        _fail(path, key, f"must be finite, got {value}")
    if positive and value <= 0:
        _fail(path, key, f"must be > 0, got {value}")
    if nonnegative and value < 0:
        _fail(path, key, f"must be >= 0, got {value}")
    return value


def _table(path, doc, key, required=True):
    value = doc.get(key)
    if value is None:
        if required:
            _fail(path, key, "missing section")
        return {}
    if not isinstance(value, dict):
        _fail(path, key, f"must be a table, got {type(value).__name__}")
    return value


def _check_keys(path, where, table, allowed, required):
    unknown = sorted(set(table) - set(allowed))
    if unknown:
        _fail(path, where, f"unknown key(s) {unknown}; allowed: {sorted(allowed)}")
    missing = sorted(set(required) - set(table))
    if missing:
        _fail(path, where, f"missing key(s) {missing}")


def _choice(path, key, value, choices):
    """A string that must be one of ``choices`` (a dict), as its mapped value."""
    if not isinstance(value, str) or value not in choices:
        _fail(path, key, f"must be one of {sorted(choices)}, got {value!r}")
    return choices[value]


def _read_leg(path, i, leg):
    where = f"legs[{i}]"
    if not isinstance(leg, dict):
        _fail(path, where, "each [[legs]] entry must be a table")
    _check_keys(path, where, leg, _LEG_KEYS, _LEG_KEYS)
    base = leg["base"]
    if not isinstance(base, list) or len(base) != 2:
        _fail(path, f"{where}.base", f"must be [x, y] in m, got {base!r}")
    base = tuple(_number(path, f"{where}.base", v) for v in base)
    la = _number(path, f"{where}.la", leg["la"], positive=True)
    lb = _number(path, f"{where}.lb", leg["lb"], positive=True)
    return Leg(base=base, la=la, lb=lb, elbow=_choice(path, f"{where}.elbow", leg["elbow"], ELBOWS))


def _read_nominal(path, nominal, n, friction):
    names = INERTIAL + FRICTION_MODELS[friction]
    _check_keys(path, "nominal", nominal, names, names)
    values = {}
    for key in names:
        vec = nominal[key]
        if not isinstance(vec, list) or len(vec) != n:
            _fail(path, f"nominal.{key}", f"must be a list of {n} numbers (one per leg), got {vec!r}")
        values[key] = [_number(path, f"nominal.{key}[{i}]", v, positive=key in INERTIAL,
                               nonnegative=key not in INERTIAL) for i, v in enumerate(vec)]
    for i in range(n):  # M_i positive definite: alpha, gamma > 0 and beta^2 < alpha gamma
        a, b, g = values["alpha"][i], values["beta"][i], values["gamma"][i]
        if b * b >= a * g:
            _fail(path, f"nominal.beta[{i}]",
                  f"leg {i + 1} inertia is not positive definite: beta^2 = {b * b:.6g} >= "
                  f"alpha*gamma = {a * g:.6g}")
    param_names = tuple(f"{key}{i + 1}" for key in names for i in range(n))
    theta = np.array([values[key][i] for key in names for i in range(n)], dtype=float)
    theta.setflags(write=False)
    return param_names, theta


# run-time sections: key -> (length: None for a scalar, "n" per leg, "p" per parameter, or int;
#                             constraint: "pos" > 0, "nonneg" >= 0, "any")
_SCHEMA = {
    "sensing": {"sample_period": (None, "pos"), "encoder_counts_per_rev": (None, "nonneg"),
                "velocity_filter_hz": (None, "nonneg")},
    "gains.na": {"Kd": (2, "pos"), "Q": (2, "pos"), "Gamma": ("p", "nonneg")},
    "gains.apd": {"Kp": (2, "pos"), "Kv": (2, "pos")},
    "plant": {"alpha": ("n", "pos"), "beta": ("n", "any"), "gamma": ("n", "pos"),
              "payload_mass": (None, "nonneg"), "payload_leg": (None, "pos"),
              "fv": ("n", "nonneg"), "fc": ("n", "nonneg"), "fs": ("n", "nonneg"),
              "stribeck_velocity": (None, "pos"), "coulomb_smoothing_velocity": (None, "pos")},
    "trajectory": {"start": (2, "any"), "end": (2, "any"), "v_max": (None, "pos"),
                   "a_max": (None, "pos"), "j_max": (None, "pos")},
}


def _read_section(path, where, table, schema, n, p):
    if not isinstance(table, dict):
        _fail(path, where, f"must be a table, got {type(table).__name__}")
    _check_keys(path, where, table, schema, schema)
    out = {}
    for key, (length, rule) in schema.items():
        kw = {"positive": rule == "pos", "nonnegative": rule == "nonneg"}
        value = table[key]
        if length is None:
            out[key] = _number(path, f"{where}.{key}", value, **kw)
            continue
        size = {"n": n, "p": p}.get(length, length)
        if not isinstance(value, list) or len(value) != size:
            _fail(path, f"{where}.{key}", f"must be a list of {size} numbers, got {value!r}")
        out[key] = np.array([_number(path, f"{where}.{key}[{i}]", v, **kw)
                             for i, v in enumerate(value)])
        out[key].setflags(write=False)
    return out


def default_closure_tolerance(legs, encoder_counts_per_rev):
    """[sensing] closure_tolerance when a model file does not set it, m: five encoder steps at
    the longest active link, at least 1 um. (One step moves an elbow by la * 2 pi / counts;
    quantised angles over the paper robot's workspace give residuals up to 0.8 of that, and
    up to 1.3 with a full step of error: tests/test_closure.py measures it.)"""
    if encoder_counts_per_rev <= 0:
        return CLOSURE_FLOOR
    step = 2 * math.pi / encoder_counts_per_rev
    return max(CLOSURE_FLOOR, 5 * max(leg.la for leg in legs) * step)


def _read_runtime(path, doc, n, p, legs):
    """Validate the run-time sections: sensing, gains, plant truth, trajectories."""
    sensing_raw = _table(path, doc, "sensing")
    sensing_raw = dict(sensing_raw) if isinstance(sensing_raw, dict) else sensing_raw
    closure = (sensing_raw.pop("closure_tolerance", None) if isinstance(sensing_raw, dict)
               else None)
    sensing = _read_section(path, "sensing", sensing_raw, _SCHEMA["sensing"], n, p)
    if sensing["encoder_counts_per_rev"] != int(sensing["encoder_counts_per_rev"]):
        _fail(path, "sensing.encoder_counts_per_rev", "must be a whole number (0: no quantisation)")
    sensing["closure_tolerance"] = (
        default_closure_tolerance(legs, sensing["encoder_counts_per_rev"]) if closure is None
        else _number(path, "sensing.closure_tolerance", closure, positive=True))
    gains_raw = _table(path, doc, "gains")
    _check_keys(path, "gains", gains_raw, {"na", "apd"}, {"na", "apd"})
    gains = {law: _read_section(path, f"gains.{law}", gains_raw[law], _SCHEMA[f"gains.{law}"], n, p)
             for law in ("na", "apd")}
    plant = _read_section(path, "plant", _table(path, doc, "plant"), _SCHEMA["plant"], n, p)
    leg = plant["payload_leg"]
    if leg != int(leg) or not 1 <= leg <= n:
        _fail(path, "plant.payload_leg", f"must be a leg number 1..{n}, got {leg}")
    for i in range(n):
        a, b, g = plant["alpha"][i], plant["beta"][i], plant["gamma"][i]
        if b * b >= a * g:
            _fail(path, f"plant.beta[{i}]", f"leg {i + 1} inertia is not positive definite: "
                                            f"beta^2 = {b * b:.6g} >= alpha*gamma = {a * g:.6g}")
    trajs_raw = _table(path, doc, "trajectories")
    if not trajs_raw:
        _fail(path, "trajectories", "needs at least one [trajectories.<name>] table")
    trajs = {name: _read_section(path, f"trajectories.{name}", t, _SCHEMA["trajectory"], n, p)
             for name, t in trajs_raw.items()}
    for name, t in trajs.items():  # the legs must meet: every end point within every leg's reach
        for end in ("start", "end"):
            for i, lg in enumerate(legs):
                dist = float(np.hypot(*(t[end] - np.asarray(lg.base))))
                lo, hi = abs(lg.la - lg.lb), lg.la + lg.lb
                if not lo <= dist <= hi:
                    _fail(path, f"trajectories.{name}.{end}",
                          f"the legs cannot meet at {t[end].tolist()}: leg {i + 1} is {dist:.4g} m "
                          f"from its base, its reach is [{lo:.4g}, {hi:.4g}] m")
        if np.array_equal(t["start"], t["end"]):
            _fail(path, f"trajectories.{name}", "start and end are the same point")
    return sensing, gains, plant, trajs


def _read_control(path, doc, n, tau_max):
    """[control] (optional): the torque split and the preload split's signs and levels."""
    raw = doc.get("control", {})
    if not isinstance(raw, dict):
        _fail(path, "control", f"must be a table, got {type(raw).__name__}")
    _check_keys(path, "control", raw, {"split", "preload", "preload_sign"}, set())
    split = raw.get("split", "min_norm")
    _choice(path, "control.split", split, {k: k for k in SPLITS})
    out = {"split": split}
    for key, default in (("preload", [0.0] * n), ("preload_sign", [1] * n)):
        value = raw.get(key, default)
        if not isinstance(value, list) or len(value) != n:
            _fail(path, f"control.{key}", f"must be a list of {n} numbers, got {value!r}")
        arr = np.array([_number(path, f"control.{key}[{i}]", v, nonnegative=key == "preload")
                        for i, v in enumerate(value)])
        arr.setflags(write=False)
        out[key] = arr
    if not np.all(np.isin(out["preload_sign"], (1.0, -1.0))):
        _fail(path, "control.preload_sign", f"each entry must be +1 or -1, got {raw['preload_sign']}")
    if np.any(out["preload"] >= tau_max):
        _fail(path, "control.preload", f"must stay below limits.tau_max {tau_max.tolist()}, got "
                                       f"{out['preload'].tolist()}")
    return out


def read_model_file(path):
    """Read and validate a model file.

    Parameters
    ----------
    path : str or pathlib.Path
        A TOML model file (see ``models/shang2010.toml`` for the documented format).

    Returns
    -------
    ModelSpec

    Raises
    ------
    ModelFileError
        Naming the file, the key and the reason, for unreadable content, missing or unknown
        keys, wrong types and non-physical values.
    """
    path = Path(path)
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise ModelFileError(f"{path}: cannot read model file: {exc.strerror or exc}") from None
    nul = raw.find(b"\x00")
    if nul >= 0:
        raise ModelFileError(f"{path}: binary content (NUL byte at offset {nul}), "
                             f"not a TOML model file")
    try:
        doc = tomllib.loads(raw.decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise ModelFileError(f"{path}: not a text (UTF-8) file: {exc.reason} at byte {exc.start}") from None
    except tomllib.TOMLDecodeError as exc:
        raise ModelFileError(f"{path}: not valid TOML: {exc}") from None
    unknown = sorted(set(doc) - _TOP_KEYS)
    if unknown:
        _fail(path, "<top>", f"unknown section(s) {unknown}; allowed: {sorted(_TOP_KEYS)}")
    model = _table(path, doc, "model")
    _check_keys(path, "model", model, _MODEL_KEYS, {"name", "friction"})
    name = model["name"]
    if not isinstance(name, str) or not name.isidentifier() or not name.isascii():
        _fail(path, "model.name", f"must be an ASCII identifier (it prefixes C symbols), got {name!r}")
    if not isinstance(model.get("description", ""), str):
        _fail(path, "model.description", f"must be a string, got {type(model['description']).__name__}")
    friction = model["friction"]
    _choice(path, "model.friction", friction, {k: k for k in FRICTION_MODELS})
    constants = {}
    for key in FRICTION_CONSTANTS[friction]:
        if key not in model:
            _fail(path, f"model.{key}", f"required by friction = {friction!r}")
        constants[key] = _number(path, f"model.{key}", model[key], positive=True)
    legs_raw = doc.get("legs")
    if not isinstance(legs_raw, list) or len(legs_raw) < 2:
        _fail(path, "legs", "needs at least two [[legs]] tables (a planar 2-DOF mechanism)")
    legs = tuple(_read_leg(path, i, leg) for i, leg in enumerate(legs_raw))
    fk_branch = model.get("fk_branch", "left")
    _choice(path, "model.fk_branch", fk_branch, FK_BRANCHES)
    if len(legs) == 2 and "fk_branch" not in model:
        _fail(path, "model.fk_branch", "a two-leg mechanism must choose its forward-kinematics "
                                       "branch ('left' or 'right' of the line B1 -> B2)")
    substeps = model.get("rk4_substeps", 4)
    if isinstance(substeps, bool) or not isinstance(substeps, int) or not 1 <= substeps <= 100:
        _fail(path, "model.rk4_substeps", f"must be an integer in [1, 100], got {substeps!r}")
    param_names, theta = _read_nominal(path, _table(path, doc, "nominal"), len(legs), friction)
    limits_raw = _table(path, doc, "limits")
    limits_raw = dict(limits_raw) if isinstance(limits_raw, dict) else limits_raw
    parallel = (limits_raw.pop("parallel_singularity_threshold", DEFAULT_PARALLEL_THRESHOLD)
                if isinstance(limits_raw, dict) else None)
    limits = _read_section(path, "limits", limits_raw,
                           {"singularity_threshold": (None, "pos"), "tau_max": ("n", "pos")},
                           len(legs), len(param_names))
    limits["parallel_singularity_threshold"] = _number(
        path, "limits.parallel_singularity_threshold", parallel, positive=True)
    for key in ("singularity_threshold", "parallel_singularity_threshold"):
        if limits[key] >= 1:  # both measures lie in [0, 1]
            _fail(path, f"limits.{key}", f"bounds a measure in [0, 1], must be < 1, got "
                                         f"{limits[key]}")
    sensing, gains, plant, trajs = _read_runtime(path, doc, len(legs), len(param_names), legs)
    control = _read_control(path, doc, len(legs), limits["tau_max"])
    spec = ModelSpec(
        path=str(path), name=name, description=str(model.get("description", "")),
        friction=friction, friction_constants=constants, fk_branch=FK_BRANCHES[fk_branch], rk4_substeps=substeps,
        legs=legs, param_names=param_names, theta_nominal=theta,
        limits=limits, sensing=sensing, gains=gains, plant=plant, trajectories=trajs,
        control=control,
        file_sha256=hashlib.sha256(raw).hexdigest())
    formulation = json.dumps(spec.formulation(), sort_keys=True, separators=(",", ":"))
    object.__setattr__(spec, "formulation_sha256", hashlib.sha256(formulation.encode()).hexdigest())
    return spec
