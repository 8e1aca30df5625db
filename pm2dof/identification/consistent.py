# Physically consistent theta: least squares on the base parameters under PSD inertia and friction >= 0.
"""Constrained least squares for a full, physically consistent theta (CasADi + IPOPT).

The data determine only the base parameters pi = P theta (P: (r, p), the identity on the
independent columns plus the folding ``beta`` of the dependent ones:
:meth:`pm2dof.identification.base.BaseParameters.matrix`). A theta is physical when every leg's
inertia matrix [[alpha_i, beta_i], [beta_i, gamma_i]] is positive semidefinite (alpha_i >= 0,
gamma_i >= 0, alpha_i gamma_i - beta_i^2 >= 0; the same condition for every leg kind), a
platform's m_p, I_p >= 0 and m_p I_p >= mx_p^2 + my_p^2, and every friction coefficient is
>= 0 (first moments kappa_i are free).

Two stages, each solved by IPOPT:

1. pi* = P theta*, theta* minimising ||A P theta - b||^2 over physical theta. The
   objective is strictly convex in pi (A has full column rank) and the set of physical
   theta is a convex cone, so pi* is unique.
2. Among physical theta with P theta = pi*, the one closest to the nominal theta (Tables
   1-2) in the 2-norm. This fixes the directions the data cannot see (the null space of
   P: point masses at a point robot's common tip booked to one leg or another; at a
   platform's attachment points, booked to a leg or to the platform).

Stage 2 is tried first with pi* = the plain least squares: when it is feasible, the least
squares is already physical and is kept exactly (stage 1 is skipped).
"""
import numpy as np

from ..core.mechanism import INERTIAL as _INERTIAL
from .base import inertial_mask

__all__ = ["physical_constraints", "consistent_theta"]


def _legs(names):
    """[(i_alpha, i_beta, i_gamma)] per leg and the friction indices, from param names."""
    idx = {n: j for j, n in enumerate(names)}
    legs, i = [], 1
    while f"alpha{i}" in idx:
        legs.append(tuple(idx[f"{k}{i}"] for k in _INERTIAL))
        i += 1
    friction = [int(j) for j in np.flatnonzero(~inertial_mask(names))]
    return legs, friction


def physical_constraints(theta, names):
    """g(theta) >= 0 for a physical theta: per leg alpha, gamma, alpha gamma - beta^2, then
    every friction coefficient. Works on NumPy arrays and CasADi symbols.

    Returns
    -------
    list of 3n (+ 3 for a platform) + (number of friction coefficients) expressions, and
    their labels
    """
    legs, friction = _legs(names)
    g, labels = [], []
    for i, (a, b, c) in enumerate(legs):
        g += [theta[a], theta[c], theta[a] * theta[c] - theta[b] * theta[b]]
        labels += [f"alpha{i + 1} >= 0", f"gamma{i + 1} >= 0",
                   f"alpha{i + 1} gamma{i + 1} - beta{i + 1}^2 >= 0"]
    if "m_p" in names:   # the platform: m >= 0, its inertia about its centre of mass >= 0
        m, mx, my, inertia = (theta[names.index(k)] for k in ("m_p", "mx_p", "my_p", "I_p"))
        g += [m, inertia, m * inertia - mx * mx - my * my]
        labels += ["m_p >= 0", "I_p >= 0", "m_p I_p - mx_p^2 - my_p^2 >= 0"]
    for j in friction:
        g.append(theta[j])
        labels.append(f"{names[j]} >= 0")
    return g, labels


def _ipopt(casadi, x, f, g, lbg, ubg, x0, what):
    solver = casadi.nlpsol(what, "ipopt", {"x": x, "f": f, "g": casadi.vertcat(*g)},
                           {"ipopt.print_level": 0, "print_time": False, "ipopt.sb": "yes",
                            "ipopt.tol": 1e-12, "ipopt.acceptable_tol": 1e-10,
                            "ipopt.max_iter": 500, "ipopt.bound_relax_factor": 0.0})
    sol = solver(x0=x0, lbg=lbg, ubg=ubg)
    status = solver.stats()["return_status"]
    return sol, status


def consistent_theta(A, b, base, theta_nominal):
    """The physically consistent least-squares theta.

    Parameters
    ----------
    A : ndarray (m, r)
        Weighted base regressor (rows of all samples), as returned by
        :func:`pm2dof.identification.fit.weighted_ls`.
    b : ndarray (m,)
        Weighted task forces.
    base : BaseParameters
        The base parameters the columns of ``A`` are (:mod:`pm2dof.identification.base`).
    theta_nominal : array_like (p,)
        Tables 1-2: the point closest to which the invisible directions are fixed.

    Returns
    -------
    dict
        ``theta`` (p,) physical, ``base`` (r,) = P theta, ``objective`` ||A base - b||^2 / ||b||^2,
        ``unconstrained_objective`` (the plain least squares), ``active`` (labels of constraints
        at their bound, within 1e-9 of scale), ``g`` (values of the constraints), ``lam_g``
        (IPOPT's multipliers of stage 1: L = f + lam_g . g, so lam_g <= 0 where active),
        ``status`` (IPOPT's return status of each stage), ``moved_from_nominal`` (the
        component of theta - theta_nominal in the null space of P, i.e. what stage 2 chose).
    """
    import casadi
    names = list(base.names)
    P = base.matrix()
    r, p = P.shape
    th0 = np.asarray(theta_nominal, dtype=float)
    AP = A @ P
    nb = float(b @ b)
    H = AP.T @ AP / nb
    c = AP.T @ b / nb
    x = casadi.SX.sym("theta", p)
    f1 = casadi.dot(x, casadi.mtimes(casadi.DM(H), x)) - 2 * casadi.dot(casadi.DM(c), x) + 1.0
    g, labels = physical_constraints(x, names)
    lbg, ubg = np.zeros(len(g)), np.full(len(g), np.inf)
    # the plain least squares; if some physical theta has exactly these base parameters
    # (stage 2 is feasible at pi_ls), it is the constrained optimum and stage 1 is not needed
    pi_ls, *_ = np.linalg.lstsq(A, b, rcond=None)
    x0 = th0 + np.linalg.pinv(P) @ (pi_ls - P @ th0)
    f2 = casadi.sumsqr(x - casadi.DM(th0))
    g2 = g + [casadi.mtimes(casadi.DM(P), x)]

    def stage2(pi, start):
        return _ipopt(casadi, x, f2, g2, np.concatenate([lbg, pi]),
                      np.concatenate([ubg, pi]), start, "closest_to_nominal")

    sol2, st2 = stage2(pi_ls, x0)
    if st2 == "Solve_Succeeded":
        st1, th1, lam1 = "not needed (least squares is physical)", x0, np.zeros(len(g))
    else:
        sol1, st1 = _ipopt(casadi, x, f1, g, lbg, ubg, x0, "physical_ls")
        th1 = np.array(sol1["x"]).ravel()
        lam1 = np.array(sol1["lam_g"]).ravel()
        sol2, st2 = stage2(P @ th1, th1)
    th = np.array(sol2["x"]).ravel()
    gv = np.array([float(v) for v in physical_constraints(th, names)[0]])
    amax = float(np.abs(th).max())
    scale = np.array([amax ** 2 if "^2" in lab else amax for lab in labels])
    res = A @ (P @ th) - b
    res_ls = A @ pi_ls - b
    Pp = np.linalg.pinv(P)
    null = th - th0 - Pp @ (P @ (th - th0))
    return {"theta": th, "base": P @ th, "objective": float(res @ res / nb),
            "unconstrained_objective": float(res_ls @ res_ls / nb),
            "active": [lab for lab, v, s in zip(labels, gv, scale) if v <= 1e-9 * s],
            "g": gv, "labels": labels, "lam_g": lam1,
            "theta_stage1": th1, "status": (st1, st2), "moved_from_nominal": null,
            "P": P}
