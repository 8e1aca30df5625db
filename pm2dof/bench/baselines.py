# Baselines and workloads of the benchmark: the NumPy reference and SymPy-lambdify steps, the
# operating point, random step inputs and the long rollout trajectory.
import math
import time

import numpy as np

__all__ = ["reference_geometry", "operating_point", "random_cases", "c_step", "lambdify_step",
           "long_trajectory"]


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
    """Random NA step inputs within 3 cm of ``center`` (m): pose, velocity, estimate, desired
    motion. Poses out of reach or near a singularity are drawn again."""
    n, T = model.n_legs, ctrl.sample_period
    cases = []
    for _ in range(200 * count):
        if len(cases) == count:
            break
        xe = np.asarray(center, dtype=float) + rng.uniform(-0.03, 0.03, 2)
        try:
            q = model.ik(xe)
        except Exception:  # noqa: BLE001 (out of reach: draw again)
            continue
        if np.min(np.abs(model.singularity(q))) < 2 * model.singularity_threshold:
            continue
        qa = q[:n].copy()
        # tracking errors of the size seen on the paper's moves, so that the torques stay
        # below tau_max (a clipped torque would hide differences)
        v = rng.uniform(-0.5, 0.5, 2)
        theta = np.asarray(model.theta_nominal) * rng.uniform(0.7, 1.3, len(model.param_names))
        state = np.concatenate([xe - T * v + rng.normal(0, 1e-6, 2), v, theta])
        xd = xe + rng.normal(0, 2e-4, 2)
        xd_dot = v + rng.normal(0, 0.02, 2)
        cases.append((state, qa, xd, xd_dot, rng.uniform(-10, 10, 2)))
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
    S(q), Y(q, xed, xrd, xrdd), sin(qb - qa). Returns (step, build seconds)."""
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
        return tau_out, np.concatenate([xe, v, theta_out]), status

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
    return Trajectory(np.arange(n_samples) * tr.period, xd, xdd, xddd, tr.period, tr.start,
                      tr.end, tr.profile), speed
