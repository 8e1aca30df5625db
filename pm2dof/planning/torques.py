# Inverse dynamics along a timed path with the model's generated C: Me, Ce, StF, then the split.
"""Actuator torques along a path timed by (s, s_d, s_dd), independently of the planner's own
coefficients: q = ik(p), u = Me (p' s_dd + p'' s_d^2) + Ce(q, p' s_d) p' s_d + S^T f_a(S p' s_d)
(eqs. 10-12, 2), then ``torque_splits`` (eq. 21 and the exact min-max), each over all points in
one ``Function.map`` call. Used to check plans and to report a kinematic plan's torques."""
import numpy as np

from ..control.settings import actuator_limits
from ..core.errors import PlanError
from .paths import point_text

__all__ = ["path_torques", "resample", "plan_torques"]

#: s_d used for friction's sign at rest: the direction of motion (the limit s_d -> 0+)
REST = 1e-12


def path_torques(model, path, s, sd, sdd, theta=None, tau_max=None):
    """Torques of both splits at arc lengths ``s`` (K,) m with path speed ``sd`` (K,) m/s and
    acceleration ``sdd`` (K,) m/s^2.

    Returns
    -------
    dict
        ``u`` (K, m) N (N m for phi), with the gravity term Ge of a model with gravity;
        ``min_norm``, ``min_max`` (K, n) N m; ``min_max_ratio`` (K,) (the
        min-max split's max_i |tau_i| / tau_max,i; ``tau_max`` default ``[limits]``).
    """
    th = np.ascontiguousarray(model.theta_nominal if theta is None else theta, dtype=float)
    tau_lim = actuator_limits(model.spec, tau_max, "path_torques")
    s, sd, sdd = (np.ascontiguousarray(a, dtype=float).ravel() for a in (s, sd, sdd))
    K, n, m = len(s), model.n_legs, model.dof
    p, dp, ddp = path.evaluate(s)
    q = np.empty((K, 2 * n))
    model.function("ik").map(K, np.ascontiguousarray(p), q)
    if not np.isfinite(q).all():
        k = int(np.argmin(np.isfinite(q).all(axis=1)))
        raise PlanError(f"s = {s[k]:.6g} m, point {point_text(p[k])} is out of reach")
    v = np.ascontiguousarray(dp * np.maximum(sd, REST)[:, None])
    acc = np.ascontiguousarray(dp * sdd[:, None] + ddp * (sd * sd)[:, None])
    Me, Ce, F = np.empty((K, m * m)), np.empty((K, m * m)), np.empty((K, m))
    model.function("Me").map(K, q, th, Me, None)
    model.function("Ce").map(K, q, v, th, Ce, None)
    model.function("StF").map(K, q, v, th, F, None)
    u = np.einsum("kij,kj->ki", Me.reshape(K, m, m), acc) \
        + np.einsum("kij,kj->ki", Ce.reshape(K, m, m), v * (sd > 0)[:, None]) + F
    if model.spec.has_gravity:                          # eq. 10's gravity term
        G = np.empty((K, m))
        model.function("Ge").map(K, q, th, G, None)
        u += G
    u = np.ascontiguousarray(u)
    outs = (np.empty((K, n)), np.empty((K, n)), np.empty(K), np.empty((K, n)), np.empty(K),
            np.empty((K, 2)))                         # the last: the two singularity measures
    ctl = model.spec.control
    model.function("torque_splits").map(K, q, u, tau_lim,
                                        np.asarray(ctl["preload_sign"], float),
                                        np.asarray(ctl["preload"], float), *outs)
    return {"u": u, "min_norm": outs[0], "min_max": outs[1], "min_max_ratio": outs[2]}


def resample(plan, factor=10):
    """(s, s_d, s_dd) of ``plan``'s profile at ``factor`` points per grid interval (its own
    constant s_dd; s_d^2 linear in s), the grid points included."""
    s, sdot, sdd = plan.s, plan.sdot, plan.sddot
    frac = np.arange(factor) / factor
    ss = (s[:-1, None] + np.diff(s)[:, None] * frac).ravel()
    x0 = np.repeat(sdot[:-1] ** 2, factor)
    u = np.repeat(sdd[:-1], factor)
    x = np.maximum(x0 + 2 * u * (ss - np.repeat(s[:-1], factor)), 0.0)
    return (np.concatenate([ss, s[-1:]]), np.concatenate([np.sqrt(x), [0.0]]),
            np.concatenate([u, sdd[-1:]]))


def plan_torques(model, plan, factor=10, theta=None):
    """Torques of ``plan``'s split along its profile resampled ``factor`` times finer:
    (s (M,), tau (M, n) N m, ratio (M,) = max_i |tau_i| / tau_max,i of the plan's limits)."""
    s, sd, sdd = resample(plan, factor)
    th = plan.info.get("theta") if theta is None else theta
    r = path_torques(model, plan.path, s, sd, sdd, th, plan.tau_max)
    tau = r[plan.split]
    return s, tau, np.abs(tau / plan.tau_max).max(axis=1)
