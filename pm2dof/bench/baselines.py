# Baselines and workloads of the benchmark: the NumPy reference and SymPy-lambdify steps, the
# operating point, random step inputs and the long rollout trajectory.
import math
import time

import numpy as np

from ..core.errors import Pm2dofError, UnsupportedMechanismError
from ..core.mechanism import is_friction_param
from ..core.task import is_rr_point, mechanism

__all__ = ["reference_geometry", "reference_problem", "lambdify_problem", "peer_problem",
           "friction_free", "theta_by_name", "operating_point", "random_cases", "c_step",
           "lambdify_step", "long_trajectory"]

#: the friction law the NumPy reference writes (eq. 2, sign(0) = 0)
REFERENCE_FRICTION = "coulomb_viscous"


def reference_problem(model):
    """Why the NumPy reference (:mod:`pm2dof.reference`) cannot compute ``model``'s NA step, or
    None when it can: that formulation is the paper's (RR legs meeting at a point, no
    gravity, theta = (alpha, beta, gamma, fv, fc) per leg under eq. 2's sign friction), and
    its flat vectors must be the model's, field by field."""
    from ..reference.control import layouts
    from ..reference.model import Geometry
    try:
        Geometry.of_model(model)
    except UnsupportedMechanismError as exc:
        return str(exc)
    n = model.n_legs
    want = tuple(f"{k}{i + 1}" for k in ("alpha", "beta", "gamma", "fv", "fc") for i in range(n))
    if tuple(model.param_names) != want:
        extra = [k for k in model.param_names if k not in want]
        return (f"the NumPy reference's theta is alpha, beta, gamma, fv, fc per leg (eq. 1, "
                f"eq. 2); model {model.name!r} has " + (
                    f"also {', '.join(extra)}" if extra else f"{', '.join(model.param_names)}")
                + (" (gravity)" if model.spec.has_gravity else ""))
    if model.spec.has_gravity:
        return (f"the NumPy reference has no gravity term; model {model.name!r} has gravity "
                f"{list(model.spec.gravity)} m/s^2")
    if model.spec.friction != REFERENCE_FRICTION:
        return (f"the NumPy reference writes eq. 2's friction ({REFERENCE_FRICTION!r}, "
                f"sign(0) = 0); model {model.name!r} has friction {model.spec.friction!r}")
    ref = layouts(n)
    for name in ("ctrl_state", "na_params"):
        if tuple(map(tuple, model.manifest["layouts"][name])) != tuple(ref[name].fields):
            return (f"the NumPy reference's {name} layout {list(ref[name].fields)} is not the "
                    f"model's {model.manifest['layouts'][name]}")
    return None


def lambdify_problem(model):
    """Why the SymPy-lambdify step (:func:`lambdify_step`) cannot compose ``model``'s NA step,
    or None when it can: it composes the step of RR legs meeting at a point (the closed-form
    fk of the paper's family, the type I measure sin(qb - qa), the type II measure of the
    distal directions); theta, gravity and friction are the model's own (its regressor Y)."""
    if is_rr_point(model.spec):
        return None
    return (f"the lambdify baseline composes the step of RRR legs meeting at a point (closed-"
            f"form fk, type I measure sin(qb - qa)); model {model.name!r} has "
            f"{mechanism(model.spec)}")


def peer_problem(model):
    """Why the peers (Pinocchio, MuJoCo: :mod:`.pinocchio_baseline`, :mod:`.mujoco_baseline`)
    cannot model ``model``, or None when they can: they build RR legs meeting at a point from
    eq. 1's alpha, beta, gamma, in a horizontal plane (no gravity)."""
    if not is_rr_point(model.spec):
        return (f"model {model.name!r} has {mechanism(model.spec)}, not RR legs with a point "
                f"end effector (the peers' robot)")
    if model.spec.has_gravity:
        return (f"model {model.name!r} has gravity {list(model.spec.gravity)} m/s^2: the peers' "
                f"robot is built from alpha, beta, gamma only, in a horizontal plane")
    missing = [f"{k}{i + 1}" for k in ("alpha", "beta", "gamma") for i in range(model.n_legs)
               if f"{k}{i + 1}" not in model.param_names]
    if missing:
        return f"model {model.name!r} has no {', '.join(missing)} (the peers' link inertias)"
    return None


def friction_free(model, theta=None):
    """``theta`` (default: the model's nominal) with every friction parameter (those of its
    friction law: fv, fc, ..., by name) zero; the inertial ones, a platform's and gravity's
    included, as they are."""
    th = np.array(model.theta_nominal if theta is None else theta, dtype=float)
    for j, name in enumerate(model.param_names):
        if is_friction_param(name, model.spec.friction):
            th[j] = 0.0
    return th


def theta_by_name(model, theta, *keys):
    """The entries of ``theta`` (p,) named ``<key>1..<key>n`` for each key, in leg order: a
    tuple of (n,) arrays (e.g. ``theta_by_name(model, th, "alpha", "beta", "gamma")``)."""
    index = {k: j for j, k in enumerate(model.param_names)}
    th = np.asarray(theta, dtype=float)
    return tuple(np.array([th[index[f"{k}{i + 1}"]] for i in range(model.n_legs)])
                 for k in keys)


def reference_geometry(model):
    from ..reference.model import Geometry
    return Geometry.of_model(model)      # RR legs at a point only: others refused, saying why


def operating_point(model, ctrl, traj, k):
    """A representative NA state: the controller run along ``traj`` to sample k with qa from
    ik(xd) (perfect tracking), so v and theta_hat are those of a real move. Returns
    (state, qa, xd, xd_dot, xd_ddot) for sample k, state in the ``ctrl_state`` layout."""
    n = model.n_legs
    ctrl.reset(model.ik(traj.xd[0])[:n])
    for i in range(k):
        ctrl.step(model.ik(traj.xd[i])[:n], traj.xd[i], traj.xd_dot[i], traj.xd_ddot[i])
    state = ctrl.state_layout.pack(**ctrl.state)
    return (state, model.ik(traj.xd[k])[:n].copy(), traj.xd[k].copy(), traj.xd_dot[k].copy(),
            traj.xd_ddot[k].copy())


def random_cases(model, ctrl, rng, count, center):
    """Random NA step inputs within 3 cm (a platform's phi: 0.03 rad) of ``center`` (m,): pose,
    velocity, estimate, desired motion, each task vector of the model's m = ``model.dof``
    coordinates, the estimate by the model's parameter names (each nominal value scaled by
    0.7-1.3), the state packed by the controller's ``ctrl_state`` layout. Poses out of reach
    or within twice a singularity threshold (type I or II) are drawn again."""
    n, m, T = model.n_legs, model.dof, ctrl.sample_period
    center = np.asarray(center, dtype=float).reshape(m)
    thresholds = np.array([model.singularity_threshold, model.parallel_singularity_threshold])
    theta_nominal = dict(zip(model.param_names, model.theta_nominal, strict=True))
    cases = []
    for _ in range(200 * count):
        if len(cases) == count:
            break
        xe = center + rng.uniform(-0.03, 0.03, m)
        try:
            q = model.ik(xe)
        except Pm2dofError:  # out of reach: draw again
            continue
        if np.any(model.singularity_measures(q) < 2 * thresholds):
            continue
        qa = q[:n].copy()
        # tracking errors of the size seen on the paper's moves, so that the torques stay
        # below tau_max (a clipped torque would hide differences)
        v = rng.uniform(-0.5, 0.5, m)
        theta = np.array([theta_nominal[k] * rng.uniform(0.7, 1.3) for k in model.param_names])
        state = ctrl.state_layout.pack(xe_prev=xe - T * v + rng.normal(0, 1e-6, m), v=v,
                                       theta_hat=theta)
        xd = xe + rng.normal(0, 2e-4, m)
        xd_dot = v + rng.normal(0, 0.02, m)
        cases.append((state, qa, xd, xd_dot, rng.uniform(-10, 10, m)))
    return cases


def c_step(f, params, case, n):
    tau, s1, st, dg = np.empty(n), np.empty(len(case[0])), np.empty(1), np.empty(f.sizes_out[3])
    f(*case, params, tau, s1, st, dg)
    return tau, s1, int(st[0])


def _import_derive():
    """pm2dof.derive is build-time code (the [derive] extra); import it lazily for the bench."""
    import pm2dof.derive.model_functions as dmf
    return dmf


_LAMBDIFY_CACHE = {}


def lambdify_step(model, layouts):
    """One NA step composed in NumPy from SymPy expressions turned into functions by
    sympy.lambdify (numpy backend, cse=True): fk(qa), the passive unit vectors (qa, xe),
    S(q), Y(q, xed, xrd, xrdd), sin(qb - qa). Returns (step, build seconds);
    UnsupportedMechanismError for a model :func:`lambdify_problem` gives a reason for."""
    why = lambdify_problem(model)
    if why is not None:
        raise UnsupportedMechanismError(why)
    key = (model.name, model.spec.formulation_sha256)
    if key in _LAMBDIFY_CACHE:
        return _LAMBDIFY_CACHE[key], 0.0
    t0 = time.perf_counter()
    import sympy as sp
    dmf = _import_derive()
    d = dmf.Derivation(model.spec)
    sym, kin, dyn = d.sym, d.kin, d.dyn
    n = model.n_legs
    qa_s, q_s = list(sym.qa), list(sym.q)
    modules = [{"sgn": np.sign}, "numpy"]  # sgn(0) = 0, as the C

    def lam(args, expr):
        return sp.lambdify(args, expr, modules, cse=True)

    fk = lam([qa_s], kin.fk())
    uv = kin.unit_vectors_from_qa(sym.xe)
    ub = lam([qa_s, list(sym.xe)],
             sp.Matrix([[uv[sym.qb[i]][0] for i in range(n)],
                        [uv[sym.qb[i]][1] for i in range(n)]]))
    S = lam([q_s], kin.S)
    Y = lam([q_s, list(sym.xed), list(sym.xrd), list(sym.xrdd)], dyn.Y)
    sab = lam([q_s], sp.Matrix([kin.sin_ab(i) for i in range(n)]))
    st_lay, p_lay = layouts["ctrl_state"], layouts["na_params"]

    def step(state, qa, xd, xd_dot, xd_ddot, params):
        st, P = st_lay.unpack(state), p_lay.unpack(params)
        T, a = P["T"][0], P["vel_alpha"][0]
        xe = np.asarray(fk(qa), dtype=float).ravel()
        v = st["v"] + a * ((xe - st["xe_prev"]) / T - st["v"])
        e = xd - xe
        edot = xd_dot - v
        theta = st["theta_hat"]
        c, s = np.asarray(ub(qa, xe), dtype=float)
        q = np.concatenate([qa, np.arctan2(s, c)])
        xrd = xd_dot + P["Q"] * e
        xrdd = xd_ddot + P["Q"] * edot
        sv = xrd - v
        Yq = np.asarray(Y(q, v, xrd, xrdd), dtype=float)
        Sq = np.asarray(S(q), dtype=float)
        u = Yq @ theta + P["Kd"] * sv
        theta_next = theta + T * P["Gamma"] * (Yq.T @ sv)
        G = Sq.T @ Sq
        tau = Sq @ np.linalg.solve(G, u)
        tau_max = P["tau_max"]
        U = np.stack([np.cos(q[n:]), np.sin(q[n:])], axis=1)   # distal directions (type II)
        kappa = np.linalg.svd(U, compute_uv=False)[-1] / np.sqrt(n / 2)
        ok = (float(np.min(np.abs(np.asarray(sab(q), dtype=float)))) >= P["sing_threshold"][0]
              and kappa >= P["parallel_sing_threshold"][0])
        if ok:
            status = 2 if np.max(np.abs(tau) - tau_max) > 0 else 0
            tau_out, theta_out = np.minimum(np.maximum(tau, -tau_max), tau_max), theta_next
        else:
            status, tau_out, theta_out = 1, np.zeros(n), theta
        return tau_out, st_lay.pack(xe_prev=xe, v=v, theta_hat=theta_out), status

    _LAMBDIFY_CACHE[key] = step
    return step, time.perf_counter() - t0


def long_trajectory(model, n_samples):
    """The high-speed move forward and back (reversed in time), tiled to ``n_samples``."""
    from ..control.trajectory import Trajectory, line_moves, model_move
    moves = line_moves(model)
    speed = "high" if "high" in moves else moves[0]
    tr = model_move(model, speed)
    xd = np.vstack([tr.xd, tr.xd[::-1]])
    xdd = np.vstack([tr.xd_dot, -tr.xd_dot[::-1]]) + 0.0
    xddd = np.vstack([tr.xd_ddot, tr.xd_ddot[::-1]])
    reps = math.ceil(n_samples / len(xd))
    xd, xdd, xddd = (np.tile(a, (reps, 1))[:n_samples] for a in (xd, xdd, xddd))
    return Trajectory(np.arange(n_samples) * tr.period, xd, xdd, xddd, tr.period), speed
