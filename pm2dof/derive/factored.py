# Task-space quantities composed from small joint-space pieces (eqs. 7-13) for the hot paths.
"""Factored forms of W, Wdot, Y, Me and Ce for the generated controller steps and plant.

The monolithic SymPy matrices (Dynamics.Y, .Me, .Ce) are the reference: the model functions
export them as they are, and the tests check them against mpmath and an independent NumPy
formulation. For the per-sample hot paths the same quantities are composed in CasADi from
pieces SymPy derived for one leg or in joint space, which is much cheaper:
  W        rows (i, n+i) = J_i^-1 G_i, J_i the tip Jacobian of leg i, G_i = d P_i / d xe
           the rate of its attachment point (the identity for a point)           (eq. 7)
  Wdot a   = J_i^-1 (Gdot_i(xed) a - Jdot_i(q, qd) (W a)_leg i)                   (eq. 9)
  Y        = W^T Y_joint(q, qd, W xrd, W xrdd + Wdot xrd) + S^T Y_friction
             + Y_platform(xe, xed, xrd, xrdd)                                    (eq. 13)
             (with gravity Y_joint includes d g_q / d theta, so W^T Y_joint carries Ge's part)
  Me       = W^T M W + Mp,   Ce xed = W^T (M Wdot xed + C(q, qd) qd) + Cp xed     (eq. 12)
with Y_joint = d(M qdd^r + C qd^r)/d theta, Y_friction = d f_a / d theta and a platform's own
Mp, Cp, Y_platform (zero for a point) derived by SymPy.

The factoring holds wherever the kinematics gives each leg's tip Jacobian ``kin.J`` (a point,
m = 2, or a platform, whose dynamics also gives Y_platform): :func:`factored`. Otherwise (e.g.
the tests' hand-built m = 3 mechanism) the same functions convert the monolithic W, Wdot, Me,
Ce and Y, which are correct for any mechanism; a Dynamics may choose either with ``factored``.
"""
import casadi as ca

__all__ = ["factored", "joint_W", "Wdot_times", "regressor", "task_inertia_coriolis",
           "task_gravity", "has_gravity", "solve_small"]


def _cofactors3(A):
    """The cofactors C_ij of a 3 x 3 matrix, as nested lists [i][j]."""
    return [[A[(i + 1) % 3, (j + 1) % 3] * A[(i + 2) % 3, (j + 2) % 3]
             - A[(i + 1) % 3, (j + 2) % 3] * A[(i + 2) % 3, (j + 1) % 3] for j in range(3)]
            for i in range(3)]


def solve_small(A, b):
    """A^-1 b for the m x m task-space matrices (m = 2, 3) by Cramer's rule (closed form, one
    division per entry); larger A by CasADi's symbolic QR."""
    m = A.shape[0]
    if m == 2:
        det = A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0]
        return ca.vertcat(A[1, 1] * b[0] - A[0, 1] * b[1], A[0, 0] * b[1] - A[1, 0] * b[0]) / det
    if m == 3:
        cof = _cofactors3(A)
        det = A[0, 0] * cof[0][0] + A[0, 1] * cof[0][1] + A[0, 2] * cof[0][2]
        return ca.vertcat(*[sum(cof[j][i] * b[j] for j in range(3)) for i in range(3)]) / det
    return ca.solve(A, b)


def inverse_small(A):
    """A^-1 of the m x m task-space matrices (m = 2, 3) in closed form: the adjugate times one
    reciprocal of the determinant (Cramer's rule); larger A by CasADi's symbolic QR."""
    m = A.shape[0]
    if m == 2:
        r = 1 / (A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0])
        return ca.vertcat(ca.horzcat(A[1, 1] * r, -A[0, 1] * r),
                          ca.horzcat(-A[1, 0] * r, A[0, 0] * r))
    if m == 3:
        cof = _cofactors3(A)
        r = 1 / (A[0, 0] * cof[0][0] + A[0, 1] * cof[0][1] + A[0, 2] * cof[0][2])
        return ca.vertcat(*[ca.horzcat(*[cof[j][i] * r for j in range(3)]) for i in range(3)])
    return ca.solve(A, ca.SX.eye(m))


def _inv2(J):
    det = J[0, 0] * J[1, 1] - J[0, 1] * J[1, 0]
    return ca.vertcat(ca.horzcat(J[1, 1], -J[0, 1]), ca.horzcat(-J[1, 0], J[0, 0])) / det


def _platform(d):
    """True for a platform end effector (kinematics ``platform``: pose x, y, phi)."""
    return bool(getattr(d.kin, "platform", False))


def factored(d):
    """True where the per-leg factored forms hold: the kinematics provides the legs' tip
    Jacobians ``kin.J`` and the task dimension is 2 (a point end effector), or it is a platform
    whose dynamics gives its own part of Y (``Y_platform``); a Dynamics may decide with
    ``factored``."""
    choice = getattr(d.dyn, "factored", None)
    if choice is not None:
        return bool(choice)
    if not hasattr(d.kin, "J"):
        return False
    return d.m == 2 or (_platform(d) and getattr(d.dyn, "Y_platform", None) is not None)


def _rows(conv, expr, nrow, ncol):
    """A SymPy matrix (nrow, ncol) converted by ``conv`` (row-major flat) back to a matrix."""
    return ca.reshape(conv(expr), ncol, nrow).T


def joint_W(d, conv):
    """W (2n, m) and each leg's (J_i^-1, rows (i, n+i) of W = J_i^-1 G_i) from the legs' tip
    Jacobians (eq. 7); (W, None) where the forms are not factored (W converted as derived)."""
    n = d.spec.n_legs
    if not factored(d):
        return _rows(conv, d.kin.W, 2 * n, d.m), None
    legs = []
    for i in range(n):
        Jinv = _inv2(ca.reshape(conv(d.kin.J[i]), 2, 2).T)
        # a platform: qd_leg = J_i^-1 G_i xed; a point's G_i is the identity
        legs.append((Jinv, Jinv @ _rows(conv, d.kin.G[i], 2, d.m) if _platform(d) else Jinv))
    rows = [legs[i][1][0, :] for i in range(n)] + [legs[i][1][1, :] for i in range(n)]
    return ca.vertcat(*rows), legs


def Wdot_times(d, conv, legs, qd, a, v):
    """Wdot a (2n,) along the joint velocity qd = W v, for a task vector a (eq. 9), and the
    converter with qd and the task velocity v bound."""
    n = d.spec.n_legs
    conv_qd = conv.extended([(d.sym.qd, qd), (d.sym.xed, v)])
    if legs is None:   # Wdot as derived, along qd = W xed with xed = v
        return _rows(conv_qd, d.kin.Wdot, 2 * n, d.m) @ a, conv_qd
    out_a, out_b = [], []
    for i, (Jinv, W_leg) in enumerate(legs):
        Jdot = ca.reshape(conv_qd(d.kin.Jdot[i]), 2, 2).T
        rate = Jdot @ (W_leg @ a)                       # d/dt (J_i^-1) = -J_i^-1 Jdot_i J_i^-1
        if _platform(d):                                # and d/dt G_i along xed = v
            r = Jinv @ (_rows(conv_qd, d.kin.Gdot[i], 2, d.m) @ a - rate)
        else:
            r = -Jinv @ rate
        out_a.append(r[0])
        out_b.append(r[1])
    return ca.vertcat(*out_a, *out_b), conv_qd


def has_gravity(d):
    """True when the model's dynamics has a nonzero gravity term Ge."""
    return _gravity(d) is not None


def _gravity(d):
    """The gravity term Ge (m,) of the dynamics, or None where it is zero (no gravity)."""
    Ge = getattr(d.dyn, "Ge", None)
    if Ge is None or all(e == 0 for e in Ge):
        return None
    return Ge


def task_gravity(d, conv, theta_pairs):
    """Ge (m,) at the pose of ``conv`` with the parameters bound by ``theta_pairs``, or None
    when the model has no gravity (a horizontal plane: nothing is added anywhere)."""
    Ge = _gravity(d)
    return None if Ge is None else conv.extended(theta_pairs)(Ge)


def regressor(d, conv, v, xrd, xrdd):
    """Y (m, p), S (n, m) and W at the pose of ``conv`` (eq. 13), measured task velocity v."""
    n, p, m = d.spec.n_legs, len(d.spec.param_names), d.m
    sym, dyn = d.sym, d.dyn
    W, legs = joint_W(d, conv)
    S = W[:n, :]
    if legs is None:
        c = conv.extended([(sym.xed, v), (sym.xrd, xrd), (sym.xrdd, xrdd)])
        return _rows(c, dyn.Y, m, p), S, W
    qd = W @ v
    Wdot_xrd, conv_qd = Wdot_times(d, conv, legs, qd, xrd, v)
    c = conv_qd.extended([(sym.qdr, W @ xrd), (sym.qddr, W @ xrdd + Wdot_xrd)])
    Y_joint = ca.reshape(c(dyn.Y_joint), p, 2 * n).T
    Y_fric = ca.reshape(c(dyn.Y_friction), p, n).T
    # with gravity, Y_joint holds d g_q / d theta, and W^T g_q is Ge (derive/dynamics.py): the
    # gravity term's regressor is in W^T Y_joint already (adding d Ge / d theta here doubled it)
    Y = W.T @ Y_joint + S.T @ Y_fric
    if _platform(d):   # the platform's own Mp xrdd + Cp xrd (+ g_p), in the task coordinates
        Y = Y + _rows(c.extended([(sym.xrd, xrd), (sym.xrdd, xrdd)]), dyn.Y_platform, m, p)
    return Y, S, W


def task_inertia_coriolis(d, conv, v, theta_pairs):
    """Me (m, m), Ce v (m,), S and W at the pose of ``conv`` with task velocity v (eq. 12).

    ``theta_pairs``: (sympy symbols, SX) pairs binding the inertial parameters.
    """
    n, m = d.spec.n_legs, d.m
    W, legs = joint_W(d, conv)
    if legs is None:
        c = conv.extended([(d.sym.xed, v)] + list(theta_pairs))
        return _rows(c, d.dyn.Me, m, m), _rows(c, d.dyn.Ce, m, m) @ v, W[:n, :], W
    qd = W @ v
    Wdot_v, conv_qd = Wdot_times(d, conv, legs, qd, v, v)
    c = conv_qd.extended(theta_pairs)
    M = ca.reshape(c(d.dyn.M), 2 * n, 2 * n).T
    C = ca.reshape(c(d.dyn.C), 2 * n, 2 * n).T
    Me = W.T @ M @ W
    Ce_v = W.T @ (M @ Wdot_v + C @ qd)
    if _platform(d):   # the platform's own inertia and Coriolis terms (eq. 12)
        Me = Me + _rows(c, d.dyn.Mp, m, m)
        Ce_v = Ce_v + _rows(c, d.dyn.Cp, m, m) @ v
    return Me, Ce_v, W[:n, :], W
