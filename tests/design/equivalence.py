# Every generated function of a model, compiled C against a CasADi derivation, at meaningful inputs.
"""Meaningful inputs for every generated function, and the comparison of two implementations.

:func:`function_inputs` gives, by input name and size, the inputs of any function of a model's
manifest at a pose near the model's first move start (both singularity measures > 0.2):
``q = ik(xe)``, ``qa = q[:n]``, task velocities of 0.05-0.5 m/s, ``theta`` = the nominal
parameters, torques within ``tau_max``, the controllers' ``state`` and ``params`` (the model
file's gains and settings, :func:`pm2dof.control.controllers.law_params`, with a small
preload), the closed loops' x, u, p, the plant's vector (:func:`pm2dof.control.plant.plant_vector`), the
planner's stage and pair vectors built from ``path_coefficients`` as pm2dof.planning does, and
the sampled step's x = [xe, xed] with T the sample period.

:func:`compare_all` evaluates every function of the manifest twice with the same inputs: the
model's compiled C (:meth:`pm2dof.Model.function`, its design bound) and a CasADi Function of
a derivation (``pm2dof.derive.run.derive_functions``) evaluated by CasADi's own virtual machine
(no code generation, no compiler). Tolerance per output: ``|a - b| <= 1e-12 max(1, |b|_inf)``,
NaN at the same positions, integer-valued outputs (step status, the preload split's mode, the
closed loop's status, the forward pass's arrival flag) exactly equal. A controller's outputs
(steps, closed loops) pass through its velocity estimate, a difference quotient over one
sample: their scale is at least their terms through it (:func:`_velocity_terms`), as
tests/derive/test_generated.py scales a sum that may cancel. Measured (rrr4_platform_design,
whose fk is a Gauss-Newton solve): fk differs by 1e-15 m between the design-input C and the
conventional graph, the velocity estimate by 5e-14 m/s (1 / T = 500), NA's torque by 3e-12
N m: up to 8.9e-12 of max(1, |b|_inf) over 20 designs, 1e-14 of the terms.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

import pm2dof
from pm2dof.control.controllers import law_params
from pm2dof.control.plant import plant_vector
from pm2dof.core import binding
from pm2dof.core.contract import SPLITS, STEPS

__all__ = ["TOL", "SING_MIN", "Pose", "draw_pose", "function_inputs", "compare_all",
           "Mismatch", "short_names"]

TOL = 1e-12
SING_MIN = 0.2          # both singularity measures above this at every pose (and the path's)
V_TOP = 100.0           # m/s, the planner's path_params v_top (pm2dof.planning.stages.V_TOP)
_LAW_OF = {base: law for base, law, _ in STEPS}


def short_names(model):
    """The short names of every function of ``model``'s manifest, sorted."""
    prefix = model.manifest["model"] + "_"
    return sorted(name[len(prefix):] for name in model.manifest["functions"])


def _law(short):
    """"na_proj_minmax_step" -> ("na_proj", "na"): the step's base and the law of its params."""
    base = short.rsplit("_step", 1)[0] if short.endswith("_step") else \
        short.rsplit("_closed_loop", 1)[0]
    for suffix in sorted((s for s in SPLITS.values() if s), key=len, reverse=True):
        if base.endswith(suffix):
            base = base[:-len(suffix)]
            break
    return base, _LAW_OF[base]


def _call_c(f, args):
    """The compiled function's outputs (list of float arrays) at ``args``; non-finite outputs
    are returned, not raised (the comparison checks their positions)."""
    outs = [np.empty(k) for k in f.sizes_out]
    binding.call(f, [np.ascontiguousarray(a, dtype=float) for a in args], outs)
    return outs


@dataclass
class Pose:
    """One admissible operating point of a model and the inputs derived from it (SI units)."""
    xe: np.ndarray
    q: np.ndarray
    xed: np.ndarray
    xedd: np.ndarray
    tau_a: np.ndarray
    xd: np.ndarray
    xd_dot: np.ndarray
    xd_ddot: np.ndarray
    theta: np.ndarray
    T: float
    direction: np.ndarray     # the path's unit direction at xe (task space)
    ddp: np.ndarray           # the path's second derivative at xe
    preload_sign: np.ndarray
    preload: np.ndarray
    K: np.ndarray             # LQR gain (n x 2m, row-major)
    tau_ff: np.ndarray
    split: str                # the planner's torque split for the stage vectors
    cache: dict = field(default_factory=dict)


def _clear(model, xe):
    """q = ik(xe) if xe is reachable with both singularity measures > SING_MIN, else None."""
    try:
        q = model.ik(xe)
        sing = model.singularity_measures(q)
    except (pm2dof.WorkspaceError, pm2dof.SingularityError):
        return None
    return q if np.all(np.isfinite(q)) and np.all(sing > SING_MIN) else None


def draw_pose(model, rng, tries=200):
    """A :class:`Pose` near ``model``'s first move start (within 0.02 m, 0.05 rad), both
    singularity measures > SING_MIN there and 0.01 m along the path. RuntimeError if none
    is found in ``tries`` draws."""
    move = next(iter(model.spec.trajectories.values()))
    start, end = np.asarray(move["start"], float), np.asarray(move["end"], float)
    m, n = model.dof, model.n_legs
    span = np.array([0.02, 0.02, 0.05][:m])
    d = end - start
    d = d / np.linalg.norm(d) if np.linalg.norm(d) > 0 else np.eye(m)[0]
    tau_max = np.asarray(model.spec.limits["tau_max"], float)
    for _ in range(tries):
        xe = start + rng.uniform(-1, 1, m) * span
        q = _clear(model, xe)
        if q is None or _clear(model, xe + 0.01 * d) is None:
            continue

        def task_vector(lo, hi):
            u = rng.normal(size=m)
            return rng.uniform(lo, hi) * u / np.linalg.norm(u)
        xed = task_vector(0.05, 0.5)
        return Pose(
            xe=xe, q=q, xed=xed, xedd=task_vector(0.1, 2.0),
            tau_a=rng.uniform(-0.5, 0.5, n) * tau_max, xd=xe + task_vector(1e-4, 2e-3),
            xd_dot=xed + task_vector(0.0, 0.05), xd_ddot=task_vector(0.1, 2.0),
            theta=np.array(model.theta_nominal, float),
            T=float(model.spec.sensing["sample_period"]), direction=d,
            ddp=rng.normal(0.0, 1.0, m), **_preload(model, q, rng, tau_max),
            K=rng.uniform(-1, 1, (n, 2 * m)) * np.tile([300.0] * m + [20.0] * m, (n, 1)),
            tau_ff=rng.uniform(-0.2, 0.2, n) * tau_max,
            split=str(rng.choice(["min_norm", "min_max"])))
    raise RuntimeError(f"{model.name}: no pose with singularity measures > {SING_MIN} within "
                       f"{span.tolist()} of {start.tolist()} in {tries} draws")


def _preload(model, q, rng, tau_max):
    """The preload split's settings: with one redundant actuator, the signs of S^T's null
    vector (so a feasible preload exists) and 2-5 % of tau_max; without redundancy none (the
    model file's defaults: sign +1, preload 0)."""
    n, m = model.n_legs, model.dof
    if n - m != 1:
        return {"preload_sign": np.ones(n), "preload": np.zeros(n)}
    null = np.linalg.svd(model.S(q).T)[2][-1]
    return {"preload_sign": np.where(null >= 0, 1.0, -1.0),
            "preload": rng.uniform(0.02, 0.05, n) * tau_max}


# --- the inputs, by function and name ------------------------------------------------------

def _params(model, pose, law):
    """The law's params vector (the model file's gains and settings) with the pose's preload."""
    if ("params", law) not in pose.cache:
        lay = model.layout(f"{law}_params")
        vec = np.array(law_params(model, law))
        f = lay.unpack(vec)
        f["preload"][:], f["preload_sign"][:] = pose.preload, pose.preload_sign
        pose.cache["params", law] = vec
    return pose.cache["params", law]


def _ctrl_state(model, pose):
    """The controller's state: the previous pose estimate one sample back along xed, the
    velocity estimate xed, theta_hat = theta."""
    return model.layout("ctrl_state").pack(xe_prev=pose.xe - pose.T * pose.xed, v=pose.xed,
                                           theta_hat=pose.theta)


def _plant(model, pose):
    if "plant" not in pose.cache:
        pose.cache["plant"] = np.array(plant_vector(model))
    return pose.cache["plant"]


def _step_input(model, pose, short, name):
    base, law = _law(short)
    n = model.n_legs
    return {"state": lambda: _ctrl_state(model, pose), "qa": lambda: pose.q[:n],
            "xd": lambda: pose.xd, "xd_dot": lambda: pose.xd_dot,
            "xd_ddot": lambda: pose.xd_ddot, "params": lambda: _params(model, pose, law),
            "K": lambda: pose.K.ravel(), "tau_ff": lambda: pose.tau_ff}[name]()


def _closed_loop_input(model, pose, short, name):
    base, law = _law(short)
    if name == "x":
        return model.layout("cl_state").pack(xe=pose.xe, xed=pose.xed,
                                             ctrl_state=_ctrl_state(model, pose))
    if name == "u":
        lay = model.layout("lqr_cl_input" if law == "lqr" else "cl_input")
        extra = {"K": pose.K.ravel(), "tau_ff": pose.tau_ff} if law == "lqr" else {}
        return lay.pack(xd=pose.xd, xd_dot=pose.xd_dot, xd_ddot=pose.xd_ddot, **extra)
    if name == "p":
        return np.concatenate([_params(model, pose, law), _plant(model, pose)])
    raise KeyError(name)


def _stages(model, pose):
    """(stage at xe, arrival row at xe + 0.01 d, x_mvc of each, path_params): the planner's
    vectors (pm2dof.planning.stages: point_stages and link) for the straight path from xe
    along the move's direction, arc length 0.01 m, tau_max at 90 %."""
    if "stages" in pose.cache:
        return pose.cache["stages"]
    lay = model.layout("path_stage")
    f = model.function("path_coefficients")
    tau_max = 0.9 * np.asarray(model.spec.limits["tau_max"], float)
    delta = 0.01
    rows = []
    for p in (pose.xe, pose.xe + delta * pose.direction):
        out = dict(zip(f.names_out, _call_c(f, [p, pose.direction, pose.ddp, pose.theta,
                                                  tau_max])))
        row = np.zeros(lay.size)
        st = lay.unpack(row)
        st["N"][:], st["h"][:] = out[f"N_{pose.split}"], out[f"h_{pose.split}"]
        for key in ("a", "b", "g", "S", "v1"):
            if key in st:
                st[key][:] = out[key]
        st["delta"][:], st["x_cap"][:] = delta, V_TOP ** 2
        rows.append(row)
    sign = [np.where(lay.unpack(r)["v1"] >= 0, 1.0, -1.0) for r in rows]
    lay.unpack(rows[0])["rho"][:] = sign[0] != sign[1]     # a joint reverses on the interval
    lay.unpack(rows[1])["rho"][:] = sign[0] != sign[1]     # the arrival row: that interval's
    prm = model.layout("path_params").pack(v_top=V_TOP, theta=pose.theta)
    mvc = model.function("path_mvc")
    caps = [float(_call_c(mvc, [r, prm])[0][0]) for r in rows]
    if min(caps) <= 0:
        raise RuntimeError(f"{model.name}: no feasible path speed at {pose.xe.tolist()}")
    pose.cache["stages"] = rows[0], rows[1], caps, prm, tau_max
    return pose.cache["stages"]


def _path_input(model, pose, short, name):
    stage, arrive, caps, prm, tau_max = _stages(model, pose)
    pair = model.layout("path_pair").pack(stage=stage, next=arrive, next_cap=caps[1])
    memo = {"same": 0.0, "x_in": 0.0, "x_out": 0.0}
    table = {
        "path_coefficients": {"p": pose.xe, "dp": pose.direction, "ddp": pose.ddp,
                              "theta": pose.theta, "tau_max": tau_max},
        "path_mvc": {"stage": stage, "params": prm},
        "path_torques": {"stage": stage, "sd": np.sqrt(0.25 * caps[0]), "sdd": 0.0,
                         "params": prm, "tau_max": tau_max},
        "path_backward": {"x_next_max": 0.5 * caps[1], "params": prm,
                          "input": model.layout("path_backward_input").pack(pair=pair, **memo)},
        "path_forward": {"x": 0.3 * caps[0], "params": prm,
                         "input": model.layout("path_forward_input").pack(
                             pair=pair, x_next_max=0.5 * caps[1], **memo)},
    }
    return table[short][name]


def _other_input(model, pose, short, name):
    n = model.n_legs
    sampled = short.startswith(("sampled_step", "plant_step"))
    if sampled and name == "x":
        return np.concatenate([pose.xe, pose.xed])
    if short == "torque_splits" and name == "u":           # a task force S^T tau, tau in range
        return model.S(pose.q).T @ pose.tau_a
    if name == "h":                                        # one RK4 substep
        return pose.T / model.spec.rk4_substeps
    if name == "plant":
        return _plant(model, pose)
    if name == "qd":
        return model.W(pose.q) @ pose.xed
    if name == "tau_max":
        return np.asarray(model.spec.limits["tau_max"], float)
    if name == "qa":
        return pose.q[:n]
    simple = {"q": pose.q, "xe": pose.xe, "xed": pose.xed, "xedd": pose.xedd,
              "xrd": pose.xd_dot, "xrdd": pose.xd_ddot, "theta": pose.theta,
              "tau_a": pose.tau_a, "preload_sign": pose.preload_sign, "preload": pose.preload,
              "T": pose.T}
    return simple[name]


def function_inputs(model, short, rng, pose=None):
    """The inputs of ``model``'s generated function ``short`` (e.g. "na_minmax_step"), one
    float64 array per input in the order and of the sizes of ``model.function(short)``.

    Parameters
    ----------
    model : pm2dof.Model
    short : str
        A function of the manifest, without the model's prefix.
    rng : numpy.random.Generator
        Draws the pose when ``pose`` is None.
    pose : Pose, optional
        The operating point (:func:`draw_pose`); shared by the functions of one comparison.

    Returns
    -------
    list of ndarray
        KeyError names an input this generator does not know (a new function's input).
    """
    pose = draw_pose(model, rng) if pose is None else pose
    f = model.function(short)
    if short.endswith("_step") and short not in ("plant_step", "sampled_step"):
        source = _step_input
    elif short.endswith("_closed_loop"):
        source = _closed_loop_input
    elif short.startswith("path_"):
        source = _path_input
    else:
        source = _other_input
    args = []
    for name, size in zip(f.names_in, f.sizes_in):
        try:
            a = np.atleast_1d(np.asarray(source(model, pose, short, name), dtype=float)).ravel()
        except KeyError:
            raise KeyError(f"{model.name}: no input generator for {short}({name})") from None
        if a.size != size:
            raise ValueError(f"{model.name}: {short}({name}) needs {size} values, the generator "
                             f"gave {a.size}")
        args.append(np.ascontiguousarray(a))
    return args


# --- the comparison ------------------------------------------------------------------------

@dataclass
class Mismatch:
    """One output of one function that differs: ``error`` the largest |a - b| (inf for NaN
    positions or a missing function), ``bound`` what was allowed."""
    function: str
    output: str
    error: float
    bound: float
    detail: str = ""

    def __str__(self):
        return (f"{self.function}.{self.output}: max error {self.error:.3e} > {self.bound:.1e}"
                f"{' (' + self.detail + ')' if self.detail else ''}")


def _exact_mask(model, short, name, size):
    """Entries of output ``name`` that are integers (flags, status, modes): compared exactly."""
    mask = np.zeros(size, dtype=bool)
    if name in ("status", "preload_mode"):
        mask[:] = True
    elif short.endswith("_closed_loop") and name == "y":
        mask[model.layout("cl_output").slices["status"]] = True
    elif short == "path_forward" and name == "y":
        mask[model.layout("path_forward_output").slices["arrival_ok"]] = True
    return mask


def _casadi_call(fc, args):
    """Evaluate the CasADi Function ``fc`` (its VM) at flat float inputs ``args`` -> flat
    outputs in CasADi's column-major storage (what the generated C writes)."""
    import casadi as ca
    ins = [ca.DM(fc.sparsity_in(i), a.tolist()) for i, a in enumerate(args)]
    return [np.asarray(o.nonzeros(), dtype=float) for o in fc.call(ins)]


def compare_all(model_c, casadi_functions, rng=None, poses=2, observed=None, plain=None):
    """Every function of ``model_c``'s manifest, its compiled C against ``casadi_functions``.

    Parameters
    ----------
    model_c : pm2dof.Model
        The compiled model (at a design, for a design model).
    casadi_functions : iterable of casadi.Function or dict {name: casadi.Function}
        A derivation's functions (``derive_functions(Derivation(spec), spec)``), named as the
        manifest names them (``<model>_<short>``).
    rng : numpy.random.Generator, optional
        Draws the poses (default seeded 0).
    poses : int
        How many poses (:func:`draw_pose`) each function is compared at.
    observed : dict, optional
        Filled with {short name: largest error / scale seen}: scale = max(1, |b|_inf), and
        for a controller step or closed loop at least its terms through the velocity
        estimate (:func:`_velocity_terms`).
    plain : dict, optional
        Filled likewise with error / max(1, |b|_inf) (the same for every function but the
        controllers).

    Returns
    -------
    list of Mismatch
        Empty when every output agrees.
    """
    rng = np.random.default_rng(0) if rng is None else rng
    if not isinstance(casadi_functions, dict):
        casadi_functions = {f.name(): f for f in casadi_functions}
    prefix = model_c.manifest["model"] + "_"
    out = []
    shorts = short_names(model_c)
    for name in sorted(set(casadi_functions) - {prefix + s for s in shorts}):
        out.append(Mismatch(name, "-", np.inf, TOL, "in the derivation, not in the manifest"))
    for _ in range(poses):
        pose = draw_pose(model_c, rng)
        for short in shorts:
            fc = casadi_functions.get(prefix + short)
            f = model_c.function(short)
            if fc is None:
                out.append(Mismatch(short, "-", np.inf, TOL, "not in the derivation"))
                continue
            if list(fc.name_in()) != list(f.names_in) or list(fc.name_out()) != list(f.names_out):
                out.append(Mismatch(short, "-", np.inf, TOL,
                                    f"signatures differ: C {f.names_in} -> {f.names_out}, "
                                    f"CasADi {fc.name_in()} -> {fc.name_out()}"))
                continue
            args = function_inputs(model_c, short, rng, pose)
            got, want = _call_c(f, args), _casadi_call(fc, args)
            terms = _velocity_terms(model_c, short, fc, args, want, pose)
            for oname, a, b, t in zip(f.names_out, got, want, terms):
                out += _compare(model_c, short, oname, a, b, t, observed, plain)
    return out


def _is_controller(short):
    return short.endswith("_closed_loop") or (short.endswith("_step")
                                              and short not in ("plant_step", "sampled_step"))


def _velocity_terms(model, short, fc, args, want, pose, h=1e-7):
    """Per output, the size of its terms through the controller's velocity estimate
    (0 for a function without one).

    A step estimates the velocity by a difference quotient, v = (fk(qa) - xe_prev) / T: a sum
    that cancels, whose terms are of the size of the pose's coordinates over T (the
    mechanism's length scale L = max(|xe|_inf, |bases|_inf), m: fk rounds relative to it). A difference of one rounding in fk between two
    correct implementations reaches an output b through d b / d xe_prev, so b's terms are
    L |d b / d xe_prev|_(row sums), estimated by forward differences of step h (m) on the
    CasADi side. The comparison's scale is then max(1, |b|_inf, these terms): the rule of
    tests/derive/test_generated.py ("the summed terms where the value is a sum that may
    cancel")."""
    if not _is_controller(short):
        return [0.0] * len(want)
    if short.endswith("_step"):
        at = model.layout("ctrl_state").slices["xe_prev"].start
    else:
        at = model.layout("cl_state").slices["ctrl_state"].start \
            + model.layout("ctrl_state").slices["xe_prev"].start
    sens = [np.zeros_like(b) for b in want]
    for j in range(model.dof):
        moved = [a.copy() for a in args]
        moved[0][at + j] += h
        for s, b2, b in zip(sens, _casadi_call(fc, moved), want):
            s += np.abs(b2 - b) / h
    length = max(float(np.max(np.abs(pose.xe))), float(np.max(np.abs(model.bases))))
    return [length * float(np.max(s[np.isfinite(s)], initial=0.0)) for s in sens]


def _compare(model, short, oname, a, b, terms, observed, plain):
    if a.shape != b.shape:
        return [Mismatch(short, oname, np.inf, TOL, f"sizes {a.size} != {b.size}")]
    nan_a, nan_b = np.isnan(a), np.isnan(b)
    if (nan_a != nan_b).any():
        return [Mismatch(short, oname, np.inf, TOL,
                         f"NaN at {np.flatnonzero(nan_a).tolist()} in C, "
                         f"{np.flatnonzero(nan_b).tolist()} in CasADi")]
    ok = ~nan_b
    exact = _exact_mask(model, short, oname, a.size) & ok
    if (a[exact] != b[exact]).any():
        return [Mismatch(short, oname, np.inf, 0.0,
                         f"integer entries differ: C {a[exact].tolist()}, "
                         f"CasADi {b[exact].tolist()}")]
    rest = ok & ~exact
    if not rest.any():
        return []
    inf = np.isinf(a) | np.isinf(b)
    if (a[rest & inf] != b[rest & inf]).any():
        return [Mismatch(short, oname, np.inf, TOL,
                         f"inf entries differ: C {a[rest & inf].tolist()}, "
                         f"CasADi {b[rest & inf].tolist()}")]
    rest &= ~inf
    if not rest.any():
        return []
    size = max(1.0, float(np.max(np.abs(b[rest]))))
    scale = max(size, terms)
    err = float(np.max(np.abs(a[rest] - b[rest])))
    if observed is not None:
        observed[short] = max(observed.get(short, 0.0), err / scale)
    if plain is not None:
        plain[short] = max(plain.get(short, 0.0), err / size)
    return [Mismatch(short, oname, err, TOL * scale)] if err > TOL * scale else []
