# The friction (and gravity) force along a path as a CasADi expression of the path speed.
"""``path_friction``: what :func:`pm2dof.plan_smooth` adds to a u = a s_dd + b s_d^2 at each
end of every grid interval, g(y) = S^T f_a(v1 y, sigma) + G (m,) at path speed y (m/s), as a
CasADi expression of y with exact derivatives (IPOPT's Jacobian and Hessian).

v1 = S p' (rad/m or m/m) and S are the ``path_stage`` entries the generated ``path_torques``
takes, sigma_i = +1 where v1_i >= 0, else -1: the direction joint i moves for y > 0 (the
limit y -> 0+ at rest), as ``path_torques`` (pm2dof/derive/planning.py). The value at rest,
g(0) = S^T f_a(0, sigma) + G (Coulomb in the direction of motion, gravity), is that generated
function's, evaluated once; only f_a(v, sigma) - f_a(0, sigma) is written here, for each law
of :data:`pm2dof.core.mechanism.FRICTION_MODELS` (pm2dof/derive/dynamics.py, eq. 2):

* ``coulomb_viscous``: fv v;
* ``coulomb_viscous_stribeck``: fv v - sigma fs r / (1 + r), r = (v / vs)^2;
* ``smooth_sign``: fc v / sqrt(v^2 + eps^2) + fv v.

Where g is affine in y (Coulomb + viscous; Stribeck with fs = 0) it is formed from the
generated C alone, g(0) + (g(1) - g(0)) y, as before, so that those plans do not change by a
bit. Before, a law not affine in v entered as the generated C through ``casadi.external`` with
finite-difference derivatives, and each Hessian of IPOPT's Lagrangian took 0.7-1.4 s on
200 grid points (3-RPR): minutes per smoothed plan. tests/planning/test_planning_path_friction.py
compares g and dg/dy with the generated ``path_torques`` on every law, by both ways.
"""
import numpy as np

from ..core.errors import PlanError

__all__ = ["path_friction", "law_friction", "moving_friction", "LAWS", "AFFINE", "BY_LAW"]

#: the friction laws written here (a new key of FRICTION_MODELS needs its line in
#: :func:`moving_friction`; a test checks that every key has one)
LAWS = ("coulomb_viscous", "coulomb_viscous_stribeck", "smooth_sign")
#: how :func:`path_friction` formed g (``Plan.info["friction"]`` of a smoothed plan)
AFFINE, BY_LAW = "affine, exact", "exact, CasADi"


def _leg_values(model, theta, key):
    """theta's ``key`` of every leg (n,), by name (fv1, fv2, ...)."""
    names = model.param_names
    th = np.asarray(theta, dtype=float).ravel()
    return np.array([th[names.index(f"{key}{i + 1}")] for i in range(model.n_legs)])


def moving_friction(model, theta, v, sigma, leg):
    """f_a(v, sigma) - f_a(0, sigma) of actuator ``leg`` (0-based) at joint velocities ``v``
    (a CasADi expression, rad/s or m/s, elementwise) with Coulomb signs ``sigma`` (+-1, one
    per entry of v), N m or N: the part of the model's friction law that changes with the
    speed, with theta's coefficients (5n or more values, ``model.param_names``).

    Raises
    ------
    PlanError
        A friction law not in :data:`LAWS`.
    """
    law, const = model.spec.friction, model.spec.friction_constants
    if law not in LAWS:
        raise PlanError(f"plan_smooth: the friction law {law!r} has no CasADi form in "
                        f"pm2dof/planning/path_friction.py (known: {', '.join(LAWS)})")
    fv = float(_leg_values(model, theta, "fv")[leg])
    if law == "coulomb_viscous":
        return fv * v
    if law == "coulomb_viscous_stribeck":
        fs = float(_leg_values(model, theta, "fs")[leg])
        r = (v / float(const["stribeck_velocity"])) ** 2
        return fv * v - sigma * fs * r / (1 + r)
    import casadi as ca
    fc = float(_leg_values(model, theta, "fc")[leg])
    eps = float(const["sign_smoothing_velocity"])
    return fc * v / ca.sqrt(v * v + eps * eps) + fv * v


def _generated(problem, rows, speed):
    """g(speed) (K, m) from the generated ``path_torques``: u at s_dd = 0 less b speed^2."""
    model = problem.model
    K = len(rows)
    u = np.empty((K, model.dof))
    model.function("path_torques").map(K, rows, np.full(K, float(speed)), 0.0, problem.params,
                                       problem.tau_max, u, None, None, None)
    return u - model.layout("path_stage").unpack(rows)["b"] * (speed * speed)


def law_friction(problem, rows, y, g0):
    """g(y) = g0 + S^T (f_a(v1 y, sigma) - f_a(0, sigma)) by the model's law
    (:func:`moving_friction`): m CasADi column expressions (K, 1); ``g0`` (K, m) the value at
    rest."""
    import casadi as ca
    model = problem.model
    K, n, m = len(rows), model.n_legs, model.dof
    R = model.layout("path_stage").unpack(rows)
    S, v1 = R["S"].reshape(K, n, m), R["v1"]
    sigma = np.where(v1 >= 0, 1.0, -1.0)
    df = [moving_friction(model, problem.theta, ca.DM(v1[:, i]) * y, ca.DM(sigma[:, i]), i)
          for i in range(n)]
    return [ca.DM(g0[:, c]) + sum(ca.DM(S[:, i, c]) * df[i] for i in range(n))
            for c in range(m)]


def path_friction(problem, rows, y):
    """g(y) at each of K grid points: m CasADi column expressions (K, 1) of the path speeds
    ``y`` (a (K, 1) CasADi expression, m/s), N (N m for phi), and how it was formed.

    Where g is affine in y at these rows (Coulomb + viscous, eq. 2, or a Stribeck term with
    fs = 0: g(1/2) is the mean of g(0) and g(1) to 1e-9 of their difference), it is g(0) +
    (g(1) - g(0)) y from the generated C, as plan_smooth always formed it ("affine, exact");
    otherwise g(0) from the C and the rest by the law (:func:`law_friction`, "exact, CasADi").

    Parameters
    ----------
    problem : PlanProblem
        The model, theta (its ``params``, and ``theta`` for the coefficients) and tau_max.
    rows : ndarray (K, stage size)
        ``path_stage`` vectors (:func:`pm2dof.planning.stages.stages`; the arrival ones at
        the end of an interval).
    y : casadi.MX or casadi.SX (K, 1)

    Returns
    -------
    (list of m CasADi expressions, str)
    """
    import casadi as ca
    rows = np.ascontiguousarray(rows)
    g0, g1, gh = (_generated(problem, rows, v) for v in (0.0, 1.0, 0.5))
    scale = max(1.0, float(np.abs(g1 - g0).max()))
    if np.abs(gh - 0.5 * (g0 + g1)).max() <= 1e-9 * scale:
        return [ca.DM(g0[:, c]) + ca.DM(g1[:, c] - g0[:, c]) * y
                for c in range(problem.model.dof)], AFFINE
    return law_friction(problem, rows, y, g0), BY_LAW
