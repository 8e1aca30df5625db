# pm2dof/reference/control.py
#
# Plain-NumPy reference of the generated controller steps, truth plant, encoder and
# closed-loop rollout of Shang & Cong (2010), built on pm2dof.reference.model (never on the
# generated C). Used only by tests and benchmarks to cross-check derive/controllers.py
# and derive/plant.py; it favours clarity over speed.
#
# Equation numbers refer to the paper as restated in docs/paper.md of the pm2dof repository:
#   eq. 2   friction f_ai = sign(qd_ai) fc_i + fv_i qd_ai (sign(0) = 0)
#   eq. 10  Me xedd + Ce xed + S^T f_a = S^T tau_a
#   eq. 13  Y(q, qd, xrd, xrdd) theta = Me xrdd + Ce xrd + S^T f_a
#   eqs. 14-17  e = xd - xe, s = edot + Q e, xrd = xd_dot + Q e, xrdd = xd_ddot + Q edot
#   eq. 21  tau_a = S (S^T S)^-1 u      (minimum-norm split of the task force u)
#   eq. 28  d theta_hat / dt = Gamma Y^T s   (explicit Euler over one sample here)
#   eq. 29  u = Y theta_hat + Kd s      (NA)
#   eq. 40  u = Y(q, qd, xd_dot, xd_ddot) theta0 + Kp e + Kv edot   (APD)
#   CTC     u = Me (xd_ddot + Kv edot + Kp e) + Ce xed + S^T f_a     (computed torque)
#   LQR     u = S^T (tau_ff - K [xe - xd, v - xd_dot])                (time-varying LQR)
#
# Flat vectors (state, params, plant, closed-loop state and output) use the same layouts
# as the generated C; :func:`layouts` writes them down independently of derive/ and the
# tests check them against the manifest.
"""Plain-NumPy reference of the generated controller steps, plant and closed loop.

Mirrors, operation for operation where it matters for rounding, the generated C of
``derive/controllers.py`` (``na_step``, ``apd_step``) and ``derive/plant.py``
(``plant_xedd``, ``plant_step``, ``measure``, ``*_closed_loop``), but computes every
kinematic and dynamic quantity with :mod:`pm2dof.reference.model`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..core.layout import Layout
from ..core.status import Status
from . import model as ref

__all__ = [
    "STATUS",
    "layouts",
    "passive_angles",
    "na_step",
    "apd_step",
    "ctc_step",
    "lqr_step",
    "truth_friction",
    "plant_xedd",
    "plant_step",
    "measure",
    "initial_state",
    "rollout",
]

#: Status codes of a controller step (same as the manifest's ``status_codes``).
STATUS = Status.codes()
#: alpha, gamma floor of the optional projection of theta_hat, kg*m^2
PROJECTION_FLOOR = 1e-6


def layouts(n: int) -> dict:
    """The flat-vector layouts for ``n`` legs (p = 5n parameters).

    Parameters
    ----------
    n : int
        Number of legs (= actuators).

    Returns
    -------
    dict of str -> pm2dof.core.layout.Layout
        ``ctrl_state`` (xe_prev 2, v 2, theta_hat p); ``na_params`` (Kd 2, Q 2, Gamma p,
        freeze_saturated (1: theta_hat held on a saturated sample), T, vel_alpha,
        sing_threshold, parallel_sing_threshold, tau_max n, preload_sign n, preload n,
        closure_tol); ``apd_params`` and ``ctc_params`` (Kp 2, Kv 2, and the same);
        ``lqr_params`` (the same without gains); the reference steps are the
        min_norm split (eq. 21; tests/control/test_splits.py checks the other splits); ``plant`` (alpha, beta, gamma, fv, fc, fs
        each n, stribeck_velocity, coulomb_smoothing_velocity, encoder_step);
        ``cl_state`` (xe 2, xed 2, ctrl_state); ``cl_input`` (xd 2, xd_dot 2,
        xd_ddot 2), ``lqr_cl_input`` (the same, K 4n, tau_ff n); ``cl_output`` (xe 2, xed 2, tau_a n, status 1, theta_hat p);
        ``diag``, a step's signal processing (xe 2, v 2, e 2, edot 2, sing 2: type I, type II).
    """
    p = 5 * n
    common = [("T", 1), ("vel_alpha", 1), ("sing_threshold", 1), ("parallel_sing_threshold", 1),
              ("tau_max", n), ("preload_sign", n), ("preload", n), ("closure_tol", 1)]
    state = [("xe_prev", 2), ("v", 2), ("theta_hat", p)]
    fields = {
        "ctrl_state": state,
        "na_params": [("Kd", 2), ("Q", 2), ("Gamma", p), ("freeze_saturated", 1)] + common,
        "apd_params": [("Kp", 2), ("Kv", 2)] + common,
        "ctc_params": [("Kp", 2), ("Kv", 2)] + common,
        "lqr_params": common,
        "plant": [(k, n) for k in ("alpha", "beta", "gamma", "fv", "fc", "fs")]
        + [("stribeck_velocity", 1), ("coulomb_smoothing_velocity", 1), ("encoder_step", 1)],
        "cl_state": [("xe", 2), ("xed", 2), ("ctrl_state", 4 + p)],
        "cl_input": [("xd", 2), ("xd_dot", 2), ("xd_ddot", 2)],
        "lqr_cl_input": [("xd", 2), ("xd_dot", 2), ("xd_ddot", 2), ("K", 4 * n), ("tau_ff", n)],
        "cl_output": [("xe", 2), ("xed", 2), ("tau_a", n), ("status", 1), ("theta_hat", p)],
        "diag": [("xe", 2), ("v", 2), ("e", 2), ("edot", 2), ("sing", 2)],
    }
    return {name: Layout(name, f) for name, f in fields.items()}


def _n(g: Any) -> int:
    return int(np.asarray(g.bases).shape[0])


def passive_angles(g: Any, qa: np.ndarray, xe: np.ndarray) -> np.ndarray:
    """Passive angles from geometry (Fig. 2): qb_i = atan2(O - B_i), B_i = A_i + la_i u(qa_i).

    Parameters
    ----------
    g : Geometry-like
    qa : array_like, shape (n,)
        Active angles, rad.
    xe : array_like, shape (2,)
        Tip O = fk(qa), m.

    Returns
    -------
    qb : ndarray, shape (n,), rad in (-pi, pi].
    """
    bases = np.asarray(g.bases, dtype=float)
    la = np.asarray(g.la, dtype=float)
    qa = np.asarray(qa, dtype=float)
    B = bases + la[:, None] * np.stack([np.cos(qa), np.sin(qa)], axis=-1)
    d = np.asarray(xe, dtype=float)[None, :] - B
    return np.arctan2(d[:, 1], d[:, 0])


def project_theta(theta: np.ndarray, n: int) -> np.ndarray:
    """theta (5n,) onto physical values: alpha, gamma >= floor, |beta| <= sqrt(alpha gamma),
    fv, fc >= 0 (the optional projection of the NA update)."""
    th = np.array(theta, dtype=float)
    a = np.maximum(th[0:n], PROJECTION_FLOOR)
    g = np.maximum(th[2 * n:3 * n], PROJECTION_FLOOR)
    bmax = np.sqrt(a * g)
    th[0:n], th[2 * n:3 * n] = a, g
    th[n:2 * n] = np.minimum(np.maximum(th[n:2 * n], -bmax), bmax)
    th[3 * n:] = np.maximum(th[3 * n:], 0.0)
    return th


def _min_norm_torque(Sq: np.ndarray, u: np.ndarray) -> np.ndarray:
    """Eq. 21: tau_a = S (S^T S)^-1 u, the minimum-norm torques with S^T tau_a = u."""
    return Sq @ np.linalg.solve(Sq.T @ Sq, u)


def _step(law: str, g: Any, state, qa, xd, xd_dot, xd_ddot, params, project=False,
          K=None, tau_ff=None):
    n = _n(g)
    lay = layouts(n)
    st = lay["ctrl_state"].unpack(np.asarray(state, dtype=float))
    P = lay[f"{law}_params"].unpack(np.asarray(params, dtype=float))
    qa = np.asarray(qa, dtype=float).reshape(n)
    xd, xd_dot, xd_ddot = (np.asarray(a, dtype=float).reshape(2) for a in (xd, xd_dot, xd_ddot))
    T, a = P["T"][0], P["vel_alpha"][0]
    # Fig. 2 signal processing: fk from qa; first-order low-pass on the backward difference
    # (written exactly as the generated C: v + a ((xe - xe_prev) / T - v))
    try:
        xe = ref.fk(g, qa)
    except ValueError:                   # no assembly of the legs at all
        xe = np.full(2, np.nan)
    with np.errstate(invalid="ignore"):  # the extra legs check the encoders (closure)
        consistent = bool(np.max(np.abs(ref.closure_residuals(g, qa, xe))) <= P["closure_tol"][0])
    v = st["v"] + a * ((xe - st["xe_prev"]) / T - st["v"])
    e = xd - xe                                                   # eq. 14
    edot = xd_dot - v
    theta = st["theta_hat"].copy()
    q = np.concatenate([qa, passive_angles(g, qa, xe)])
    if law == "na":
        xrd = xd_dot + P["Q"] * e                                 # eq. 16
        xrdd = xd_ddot + P["Q"] * edot                            # eq. 17
        s = xrd - v                                               # eq. 15
    elif law == "ctc":                                            # computed torque
        xrd, xrdd = v, xd_ddot + P["Kv"] * edot + P["Kp"] * e
    else:
        xrd, xrdd = xd_dot, xd_ddot                               # eq. 40: feedforward
    Yq = ref.Y(g, q, v, xrd, xrdd) if law != "lqr" else None      # eq. 13, (2, 5n)
    if law == "lqr":                                              # tau_ff - K (x - x_d)
        K = np.asarray(K, dtype=float).reshape(n, 4)
        u = ref.S(g, q).T @ (np.asarray(tau_ff, dtype=float)
                             - K @ np.concatenate([xe - xd, v - xd_dot]))
        theta_next = theta
    elif law == "ctc":                                            # Me a + Ce v + S^T f_a
        u = Yq @ theta
        theta_next = theta
    elif law == "na":
        u = Yq @ theta + P["Kd"] * s                              # eq. 29
        theta_next = theta + T * P["Gamma"] * (Yq.T @ s)          # eq. 28, explicit Euler
        if project:
            theta_next = project_theta(theta_next, n)
    else:
        u = Yq @ theta + P["Kp"] * e + P["Kv"] * edot             # eq. 40
        theta_next = theta
    tau = _min_norm_torque(ref.S(g, q), u)                        # eq. 21
    tau_max = P["tau_max"]
    with np.errstate(invalid="ignore"):
        sing, sing_parallel = _measures(q, n)
    finite = bool(np.isfinite(np.concatenate([tau, theta_next, xe, v])).all())
    regular = sing >= P["sing_threshold"][0] and sing_parallel >= P["parallel_sing_threshold"][0]
    if not consistent:  # encoders that do not close the loops: safe torque, keep the state
        status, tau_out, theta_out = Status.INCONSISTENT_ENCODERS, np.zeros(n), theta
    elif not regular:  # singular (or NaN measure): safe torque, no update
        status, tau_out, theta_out = Status.SINGULAR, np.zeros(n), theta
    elif not finite:                       # non-finite: safe torque, keep the whole state
        status, tau_out, theta_out = Status.NON_FINITE, np.zeros(n), theta
    else:
        status = Status.SATURATED if np.max(np.abs(tau) - tau_max) > 0 else Status.OK
        tau_out = np.minimum(np.maximum(tau, -tau_max), tau_max)
        # NA's freeze_saturated: no update on a saturated sample (0: the paper's law)
        frozen = status == Status.SATURATED and P.get("freeze_saturated", [0.0])[0] != 0
        theta_out = theta if frozen else theta_next
    if not (finite and consistent):
        xe, v = st["xe_prev"].copy(), st["v"].copy()
    state_next = np.concatenate([xe, v, theta_out])      # ctrl_state layout
    diag = {"xe": xe, "v": v, "e": e, "edot": edot, "sing": sing, "sing_parallel": sing_parallel,
            "q": q}
    return tau_out, state_next, status, diag


def _measures(q, n):
    """(type I, type II) from the joint angles: min_i |sin(qb_i - qa_i)| and the normalised
    smallest singular value of the distal directions U = [u(qb_i)] (rows), by SVD. NaN angles
    give NaN measures (the C's NaN-keeping min); a NaN anywhere is singular."""
    if not np.isfinite(q).all():
        return np.nan, np.nan
    U = np.stack([np.cos(q[n:]), np.sin(q[n:])], axis=1)
    sv = np.linalg.svd(U, compute_uv=False)
    return float(np.min(np.abs(np.sin(q[n:] - q[:n])))), float(sv[-1] / np.sqrt(n / 2))


_STEP_DOC = """One control sample of the {what}, as the generated ``{law}_step``.

    Parameters
    ----------
    g : Geometry-like
        ``pm2dof.reference.model.Geometry`` (bases, la, lb, elbow) of n legs.
    state : array_like, shape (4 + 5n,)
        Controller state ``ctrl_state``: xe_prev (2,) m, v (2,) m/s, theta_hat (5n,).
    qa : array_like, shape (n,)
        Measured active angles, rad.
    xd, xd_dot, xd_ddot : array_like, shape (2,)
        Desired position m, velocity m/s, acceleration m/s^2.
    params : array_like
        ``{law}_params`` (see :func:`layouts`).

    Returns
    -------
    tau_a : ndarray, shape (n,)
        Actuator torques, N m: eq. 21 clipped to +-tau_max, zero if singular.
    state_next : ndarray, shape (4 + 5n,)
        xe_prev = fk(qa), the filtered v, and theta_hat ({update}); theta_hat is unchanged
        at a singular sample.
    status : int
        0 ok, 1 singular (min_i |sin(qb_i - qa_i)| < sing_threshold, or the type II
        measure < parallel_sing_threshold), 2 saturated
        (some |tau_i| > tau_max_i before clipping), 3 non-finite (zero torque, state kept).
    diag : dict
        xe (2,), v (2,), e (2,), edot (2,) (the C's ``diag`` = [xe, v, e, edot, sing,
        sing_parallel]), sing (type I), sing_parallel (type II) and q (2n,) (the angles used).
"""


def na_step(g, state, qa, xd, xd_dot, xd_ddot, params, project=False):
    """NA step (eqs. 14-29); ``project=True`` mirrors the generated ``<name>_na_proj_step``."""
    return _step("na", g, state, qa, xd, xd_dot, xd_ddot, params, project)


def apd_step(g, state, qa, xd, xd_dot, xd_ddot, params):
    return _step("apd", g, state, qa, xd, xd_dot, xd_ddot, params)


def ctc_step(g, state, qa, xd, xd_dot, xd_ddot, params):
    return _step("ctc", g, state, qa, xd, xd_dot, xd_ddot, params)


def lqr_step(g, state, qa, xd, xd_dot, xd_ddot, params, K, tau_ff):
    """LQR step: the sample's gain ``K`` (n, 4) (or its n*4 row-major entries) and feedforward
    ``tau_ff`` (n,) N m after the common arguments; otherwise as :func:`na_step`."""
    return _step("lqr", g, state, qa, xd, xd_dot, xd_ddot, params, K=K, tau_ff=tau_ff)


na_step.__doc__ = _STEP_DOC.format(
    what="NA controller (eqs. 14-29)", law="na",
    update="theta_hat + T Gamma Y^T s, eq. 28 by explicit Euler")
apd_step.__doc__ = _STEP_DOC.format(
    what="APD controller (eq. 40)", law="apd", update="unchanged: the fixed model")
ctc_step.__doc__ = _STEP_DOC.format(
    what="computed-torque controller (u = Me (xd_ddot + Kv edot + Kp e) + Ce xed + S^T f_a)",
    law="ctc", update="unchanged: the fixed model")


def _truth_theta(truth: dict) -> np.ndarray:
    return np.concatenate([np.asarray(truth[k], dtype=float).ravel()
                           for k in ("alpha", "beta", "gamma", "fv", "fc")])


def truth_friction(va, truth: dict) -> np.ndarray:
    """Friction torques of the simulated plant at the actuated joints, N m.

    Parameters
    ----------
    va : array_like, shape (n,)
        Active joint velocities, rad/s.
    truth : dict
        fv, fc, fs (n,), stribeck_velocity vs and coulomb_smoothing_velocity eps (scalars).

    Returns
    -------
    f : ndarray, shape (n,)
        (fc + fs / (1 + (va/vs)^2)) va / sqrt(va^2 + eps^2) + fv va: eq. 2 with a Stribeck
        excess fs (Lorentzian decay) and sign(va) smoothed over eps (as derive/plant.py).
        With fs = 0 and |va| >> eps this is eq. 2 (the relative gap is eps^2 / (2 va^2)).
    """
    va = np.asarray(va, dtype=float)
    fc, fs, fv = (np.asarray(truth[k], dtype=float) for k in ("fc", "fs", "fv"))
    vs = float(np.ravel(truth["stribeck_velocity"])[0])
    eps = float(np.ravel(truth["coulomb_smoothing_velocity"])[0])
    smooth_sign = va / np.sqrt(va * va + eps * eps)
    stribeck = fs / (1.0 + (va / vs) ** 2)
    return (fc + stribeck) * smooth_sign + fv * va


def plant_xedd(g: Any, xe, xed, tau_a, truth: dict) -> np.ndarray:
    """Truth task-space acceleration of the plant (eq. 10 with the truth friction).

    Parameters
    ----------
    g : Geometry-like
    xe, xed : array_like, shape (2,)
        True tip position m and velocity m/s.
    tau_a : array_like, shape (n,)
        Actuator torques, N m.
    truth : dict
        alpha, beta, gamma, fv, fc, fs (n,) and stribeck_velocity, coulomb_smoothing_velocity
        (as :func:`pm2dof.plant_truth`; an ``encoder_step`` key is ignored).

    Returns
    -------
    xedd : ndarray, shape (2,), m/s^2
        Me^-1 (S^T (tau_a - f) - Ce xed), f = :func:`truth_friction` (S xed).
    """
    q = ref.ik(g, xe)
    xed = np.asarray(xed, dtype=float).reshape(2)
    theta = _truth_theta(truth)
    Sq = ref.S(g, q)
    va = Sq @ xed
    fric = truth_friction(va, truth)
    rhs = Sq.T @ (np.asarray(tau_a, dtype=float) - fric) - ref.Ce(g, q, xed, theta) @ xed
    return np.linalg.solve(ref.Me(g, q, theta), rhs)


def plant_step(g: Any, x, tau_a, truth: dict, h: float) -> np.ndarray:
    """One classical RK4 step of length ``h`` s of z = (xe, xed) under constant ``tau_a``.

    Parameters
    ----------
    x : array_like, shape (4,)
        (xe m, xed m/s).

    Returns
    -------
    x_next : ndarray, shape (4,)
    """
    x = np.asarray(x, dtype=float).reshape(4)

    def f(z):
        return np.concatenate([z[2:4], plant_xedd(g, z[0:2], z[2:4], tau_a, truth)])

    k1 = f(x)
    k2 = f(x + h / 2 * k1)
    k3 = f(x + h / 2 * k2)
    k4 = f(x + h * k3)
    return x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)


def measure(g: Any, xe, encoder_step: float) -> np.ndarray:
    """Encoder reading of the active angles at the true tip ``xe`` (2,) m.

    Returns
    -------
    qa : ndarray, shape (n,), rad
        The active angles of ik(xe), wrapped to (-pi, pi] (as atan2), then rounded to the
        nearest multiple of ``encoder_step`` (step floor(qa/step + 1/2)); 0: exact.
    """
    n = _n(g)
    qa = ref.ik(g, xe)[:n]
    qa = np.arctan2(np.sin(qa), np.cos(qa))
    if encoder_step > 0:
        qa = encoder_step * np.floor(qa / encoder_step + 0.5)
    return qa


def initial_state(g: Any, xe0, theta_hat0, encoder_step: float = 0.0) -> np.ndarray:
    """Closed-loop state (``cl_state``) at rest at ``xe0``, as :func:`pm2dof.simulate`.

    xe = xe0, xed = 0, xe_prev = fk(measure(xe0)), v = 0, theta_hat = theta_hat0.
    """
    lay = layouts(_n(g))
    ctrl = lay["ctrl_state"].pack(xe_prev=ref.fk(g, measure(g, xe0, encoder_step)),
                                  v=np.zeros(2), theta_hat=theta_hat0)
    return lay["cl_state"].pack(xe=xe0, xed=np.zeros(2), ctrl_state=ctrl)


def rollout(g: Any, law: str, params, truth: dict, encoder_step: float, traj_u, x0,
            substeps: int = 4) -> np.ndarray:
    """Closed-loop rollout, one sample at a time in the order of the generated closed loop.

    Each sample k: qa = measure(xe_k); (tau_k, ctrl_{k+1}, status_k) = step(ctrl_k, qa, u_k);
    the plant takes ``substeps`` RK4 steps of h = T / substeps under tau_k (zero-order hold);
    y_k = (xe_k, xed_k, tau_k, status_k, theta_hat of ctrl_{k+1}).

    Parameters
    ----------
    g : Geometry-like
    law : {"na", "apd"}
    params : array_like
        ``<law>_params`` (its T is the sample period).
    truth : dict
        Plant truth (see :func:`plant_xedd`).
    encoder_step : float
        Encoder quantum, rad (0: exact angles).
    traj_u : array_like, shape (N, 6)
        Rows (xd, xd_dot, xd_ddot) per sample.
    x0 : array_like, shape (8 + 5n,)
        Initial ``cl_state`` (xe, xed, ctrl_state); see :func:`initial_state`.
    substeps : int
        RK4 steps per sample (the manifest's ``rk4_substeps``).

    Returns
    -------
    y : ndarray, shape (N, 5 + n + 5n)
        ``cl_output`` rows: xe (2), xed (2), tau_a (n), status (1), theta_hat (5n).
    """
    if law not in ("na", "apd"):
        raise ValueError(f"law must be 'na' or 'apd', got {law!r}")
    step = na_step if law == "na" else apd_step
    n = _n(g)
    lay = layouts(n)
    params = np.asarray(params, dtype=float)
    T = lay[f"{law}_params"].unpack(params)["T"][0]
    h = T / substeps
    U = np.asarray(traj_u, dtype=float)
    x = np.array(x0, dtype=float)
    X = lay["cl_state"].unpack(x)
    z = np.concatenate([X["xe"], X["xed"]])
    ctrl = X["ctrl_state"].copy()
    y = np.empty((U.shape[0], lay["cl_output"].size))
    for k in range(U.shape[0]):
        qa = measure(g, z[0:2], encoder_step)
        tau, ctrl_next, status, _ = step(g, ctrl, qa, U[k, 0:2], U[k, 2:4], U[k, 4:6], params)
        y[k] = np.concatenate([z, tau, [status], ctrl_next[4:]])    # cl_output layout
        for _ in range(substeps):
            z = plant_step(g, z, tau, truth, h)
        ctrl = ctrl_next
    return y
