# Generated controller steps: Fig. 2 signal processing + NA law (eqs. 14-29), APD law (eq. 40),
# computed torque (CTC) or time-varying LQR tracking.

from typing import NamedTuple

import casadi as ca

from pm2dof.core.contract import SPLITS, STEP_INPUTS, STEP_OUTPUTS, STEPS, diag_layout
from pm2dof.core.status import Status

from .factored import joint_W, regressor
from .kinematics import FK_TRACKING_STEPS
from .layouts import Layout
from .splits import min_max, min_norm

__all__ = ["controller_layouts", "controller_functions", "per_sample_inputs", "STATUS"]

# status codes of a step (also in the manifest): what the step did with this sample
STATUS = Status.codes()
# smallest alpha, gamma the optional projection of theta_hat allows, kg*m^2
PROJECTION_FLOOR = 1e-6


def controller_layouts(n, p, m):
    """Flat-vector layouts: the controller state and each controller's parameters (task-space
    vectors and gains have the task dimension m)."""
    state = Layout([("xe_prev", m), ("v", m), ("theta_hat", p)])
    # sing_threshold: type I (legs), parallel_sing_threshold: type II (actuation)
    # preload_sign, preload: the "preload" split's sign per actuator (+-1) and least |tau|, N*m
    # closure_tol: largest |O - B_i| - lb_i of the measured pose, m ([sensing] closure_tolerance)
    # freeze_saturated (NA): 1 holds theta_hat on a saturated sample, 0 adapts (the paper)
    common = [("T", 1), ("vel_alpha", 1), ("sing_threshold", 1), ("parallel_sing_threshold", 1),
              ("tau_max", n), ("preload_sign", n), ("preload", n), ("closure_tol", 1)]
    na = Layout([("Kd", m), ("Q", m), ("Gamma", p), ("freeze_saturated", 1)] + common)
    apd = Layout([("Kp", m), ("Kv", m)] + common)
    ctc = Layout([("Kp", m), ("Kv", m)] + common)       # 1/s^2, 1/s: Me multiplies them
    lqr = Layout(common)                                 # its gains are per-sample inputs
    return {"ctrl_state": state, "na_params": na, "apd_params": apd, "ctc_params": ctc,
            "lqr_params": lqr, "diag": Layout(diag_layout(m))}


#: per-sample inputs of a law's step after its params (name, size for n legs, task dimension
#: m): LQR's gain K_k (n x 2m, row-major) and feedforward torque tau_ff_k (n), planned along
#: the trajectory
def per_sample_inputs(law, n, m):
    return [("K", 2 * m * n), ("tau_ff", n)] if law == "lqr" else []


def _project(theta, param_names, n, friction_names):
    """theta_hat onto physically consistent values: alpha, gamma >= PROJECTION_FLOOR,
    beta^2 <= alpha gamma (each RR leg's inertia block PSD), friction parameters >= 0; the
    other parameters (e.g. first moments, which gravity makes signed) are left as they are."""
    idx = {name: k for k, name in enumerate(param_names)}
    out = [theta[k] for k in range(theta.numel())]
    for i in range(1, n + 1):
        if not all(f"{b}{i}" in idx for b in ("alpha", "beta", "gamma")):
            continue
        a = ca.fmax(theta[idx[f"alpha{i}"]], PROJECTION_FLOOR)
        g = ca.fmax(theta[idx[f"gamma{i}"]], PROJECTION_FLOOR)
        bmax = ca.sqrt(a * g)
        out[idx[f"alpha{i}"]], out[idx[f"gamma{i}"]] = a, g
        out[idx[f"beta{i}"]] = ca.fmin(ca.fmax(theta[idx[f"beta{i}"]], -bmax), bmax)
    for name, k in idx.items():
        if name.rstrip("0123456789") in friction_names:
            out[k] = ca.fmax(theta[k], 0)
    return ca.vertcat(*out)


def _all_finite(x):
    """1 if every element of x is finite: a NaN or inf anywhere makes the sum NaN or inf, and
    |sum| < inf is false for both (a sum that overflows from finite values also counts as
    non-finite: values near 1e308 are no torques)."""
    return ca.fabs(ca.sum1(x)) < ca.inf


def _split(d, split, S, u, P):
    """tau_a with S^T tau_a = u by the named split (derive/splits.py) and its status flags
    (saturated, preload_infeasible) before clipping to tau_max."""
    w = P["tau_max"]
    if split == "min_norm":
        tau = min_norm(S, u)                                       # eq. 21
        return tau, ca.mmax(ca.fabs(tau) - w) > 0, ca.SX(0)
    if split == "min_max":
        tau, t = min_max(S, u, w)
        return tau, t > 1, ca.SX(0)
    tau, mode = d.preload(S, u, w, P["preload_sign"], P["preload"])
    return tau, mode == 2, mode == 1


def _law(d, law, base, P, theta, xe, v, e, edot, xd, xd_dot, xd_ddot, extra):
    """The task force u = S^T tau_a of one law, theta_hat after the sample, and S (n, m).

    na (eqs. 15-17, 28-29), apd (eq. 40), ctc (computed torque with the model's theta:
    u = Me (xd_ddot + Kv edot + Kp e) + Ce xed + S^T f_a, i.e. Y(q, v, v, a) theta, eq. 13),
    lqr (u = S^T (tau_ff - K [xe - xd, v - xd_dot]) with the planned per-sample K, tau_ff).
    """
    n = d.spec.n_legs
    if law == "lqr":
        W, _ = joint_W(d, base)                          # eq. 7 at the measured pose
        S = W[:n, :]
        x_err = ca.vertcat(xe - xd, v - xd_dot)          # state error [xe; xed] - [xd; xd_dot]
        ex = dict(extra)
        K = ca.reshape(ex["K"], 2 * d.m, n).T            # (n, 2m), row-major input
        return S.T @ (ex["tau_ff"] - K @ x_err), theta, S
    if law == "na":
        xrd = xd_dot + P["Q"] * e                        # eq. 16: reference velocity
        xrdd = xd_ddot + P["Q"] * edot                   # eq. 17: reference acceleration
        s = xrd - v                                      # eq. 15: s = edot + Q e
    elif law == "ctc":
        xrd, xrdd = v, xd_ddot + P["Kv"] * edot + P["Kp"] * e    # computed torque
    else:
        xrd, xrdd = xd_dot, xd_ddot                      # eq. 40: nominal feedforward
    Y, S, _ = regressor(d, base, v, xrd, xrdd)           # eq. 13, factored (derive/factored.py)
    if law == "na":
        u = Y @ theta + P["Kd"] * s                      # eq. 29: S^T tau_a
        return u, theta + P["T"] * P["Gamma"] * (Y.T @ s), S   # eq. 28, explicit Euler
    if law == "ctc":
        return Y @ theta, theta, S
    return Y @ theta + P["Kp"] * e + P["Kv"] * edot, theta, S  # eq. 40


def controller_functions(d, prefix):
    """``<prefix>_<law><split>_step`` for law na, na_proj (theta_hat projected after each
    update), apd, ctc (computed torque) and lqr (time-varying LQR tracking), and split ""
    (min_norm, eq. 21), "_minmax", "_preload" (derive/splits.py): one 2 ms sample each, all
    in C.

    Inputs: state (xe_prev, v, theta_hat), qa (measured active angles), xd, xd_dot, xd_ddot
    (desired position, velocity, acceleration), params (see controller_layouts), and for lqr
    the sample's K (n x 2m, row-major) and tau_ff (n) (:func:`per_sample_inputs`); task-space
    vectors have the task dimension m.
    Outputs: tau_a (n), state_next, status (STATUS), diag (the ``diag`` layout,
    :func:`pm2dof.core.contract.diag_layout`: xe, v, e, edot (m each), sing (2): type I, type
    II).
    A bad sample (encoders that do not close the loops, a singular pose, or any non-finite
    intermediate) gives the safe torque zero and leaves theta_hat unchanged; inconsistent
    encoders and a non-finite sample also keep xe_prev and v (a wrong pose is not carried on).
    NA's ``freeze_saturated`` parameter (1) also leaves theta_hat unchanged on a saturated
    sample (status SATURATED: the torque was clipped, so the law's u was not applied and eq.
    28's update would integrate an error the actuators could not act on); 0 is the paper's
    law.
    """
    from pm2dof.core.mechanism import FRICTION_MODELS
    n, p, m = d.spec.n_legs, len(d.spec.param_names), d.m
    kin = d.kin
    lay = controller_layouts(n, p, m)
    state = ca.SX.sym("state", lay["ctrl_state"].size)
    qa = ca.SX.sym("qa", n)
    xd, xd_dot, xd_ddot = ca.SX.sym("xd", m), ca.SX.sym("xd_dot", m), ca.SX.sym("xd_ddot", m)
    st = lay["ctrl_state"].split(state)
    functions = []

    # Fig. 2 signal processing: position by fk from qa only, velocity by a first-order
    # low-pass on the backward difference, passive joints from geometry (unit vectors)
    # a platform's fk from the last pose (kinematics.FK_TRACKING_STEPS: from one sample
    # away as exact as FK_NEWTON_STEPS from far). The same for every law and split: converted
    # once, every function's graph takes these nodes (the C is the same as when each function
    # converted its own copy)
    base = d.converter_qa(qa, seed=st["xe_prev"], steps=FK_TRACKING_STEPS)
    O = d.fk_of_qa()
    xe = base(O)
    sing = d.singularity_measures(base)                            # [type I, type II]
    for name, law, project in STEPS:             # pm2dof.core.contract
        params = ca.SX.sym("params", lay[f"{law}_params"].size)   # one law's, every split's
        P = lay[f"{law}_params"].split(params)
        extra = [(k, ca.SX.sym(k, size)) for k, size in per_sample_inputs(law, n, m)]
        # the extra legs are a check: every leg's residual within tolerance (false for NaN)
        consistent = ca.mmax(ca.fabs(base(kin.closure_residuals(O)))) <= P["closure_tol"]
        v = st["v"] + P["vel_alpha"] * ((xe - st["xe_prev"]) / P["T"] - st["v"])
        e = xd - xe                                     # eq. 14
        edot = xd_dot - v
        theta = st["theta_hat"]
        u, theta_next, S = _law(d, law, base, P, theta, xe, v, e, edot, xd, xd_dot, xd_ddot,
                                extra)
        if project:  # <prefix>_na_proj_step: optional, off by default (as in the paper)
            theta_next = _project(theta_next, d.spec.param_names, n,
                                  FRICTION_MODELS[d.spec.friction])
        for split, suffix in SPLITS.items():
            nodes = StepNodes(S, u, P, theta, theta_next, xe, v, e, edot, sing, consistent, st)
            functions.append(_step_function(d, prefix, lay, f"{name}{suffix}", split, nodes,
                                            [state, qa, xd, xd_dot, xd_ddot, params], extra))
    return functions


class StepNodes(NamedTuple):
    """One law's graph nodes that every split's step shares (:func:`controller_functions`):
    S (n, m), the task force u = S^T tau_a, the parameters P (by field), theta_hat before and
    after the update, the pose xe, velocity v, e, edot (eq. 14), the singularity measures, the
    encoders' consistency and the state st (by field)."""
    S: object
    u: object
    P: dict
    theta: object
    theta_next: object
    xe: object
    v: object
    e: object
    edot: object
    sing: object
    consistent: object
    st: dict


def _step_function(d, prefix, lay, name, split, nodes, inputs, extra):
    """``<prefix>_<name>_step`` of one law and split from its shared ``nodes``
    (:class:`StepNodes`): the split, saturation, the safe torque on a bad sample, the status
    and the next state (:func:`controller_functions`)."""
    S, u, P, theta, theta_next, xe, v, e, edot, sing, consistent, st = nodes
    n = d.spec.n_legs
    tau, saturated, unpreloaded = _split(d, split, S, u, P)       # eq. 21 or another split
    tau_sat = ca.fmin(ca.fmax(tau, -P["tau_max"]), P["tau_max"])
    regular = ca.logic_and(sing[0] >= P["sing_threshold"],     # false for NaN too
                           sing[1] >= P["parallel_sing_threshold"])
    finite = _all_finite(ca.vertcat(tau, theta_next, xe, v))
    good = ca.logic_and(consistent, ca.logic_and(regular, finite))
    tau_out = ca.if_else(good, tau_sat, ca.DM.zeros(n))        # safe torque: zero
    update = good                                              # no update on a bad sample
    if "freeze_saturated" in P:   # NA's option: no update while an actuator saturates either
        update = ca.logic_and(good, ca.logic_not(ca.logic_and(P["freeze_saturated"] != 0,
                                                              saturated)))
    theta_out = ca.if_else(update, theta_next, theta)
    status = ca.if_else(consistent, ca.if_else(regular, ca.if_else(finite, ca.if_else(
        saturated, STATUS["saturated"], ca.if_else(
            unpreloaded, STATUS["preload_infeasible"], STATUS["ok"])), STATUS["non_finite"]),
        STATUS["singular"]), STATUS["inconsistent_encoders"])
    carry = ca.logic_and(consistent, finite)                   # a pose worth remembering
    state_next = lay["ctrl_state"].pack(xe_prev=ca.if_else(carry, xe, st["xe_prev"]),
                                        v=ca.if_else(carry, v, st["v"]), theta_hat=theta_out)
    diag = lay["diag"].pack(xe=xe, v=v, e=e, edot=edot, sing=sing)
    return d.function(
        f"{prefix}_{name}_step", inputs + [sx for _, sx in extra],
        [tau_out, state_next, status, diag],
        list(STEP_INPUTS) + [k for k, _ in extra], list(STEP_OUTPUTS))
