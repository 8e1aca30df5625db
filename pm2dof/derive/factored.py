# Task-space quantities composed from small joint-space pieces (eqs. 7-13) for the hot paths.
"""Factored forms of W, Wdot, Y, Me and Ce for the generated controller steps and plant.

The monolithic SymPy matrices (Dynamics.Y, .Me, .Ce) are the reference: the model functions
export them as they are, and the tests check them against mpmath and an independent NumPy
formulation. For the per-sample hot paths the same quantities are composed in CasADi from
pieces SymPy derived for one leg or in joint space, which is much cheaper:
  W        rows (i, n+i) = J_i^-1, J_i the tip Jacobian of leg i            (eq. 7)
  Wdot a   = -J_i^-1 Jdot_i(q, qd) (W a)_leg i                            (eq. 9)
  Y        = W^T Y_joint(q, qd, W xrd, W xrdd + Wdot xrd) + S^T Y_friction  (eq. 13)
             (with gravity Y_joint includes d g_q / d theta, so W^T Y_joint carries Ge's part)
  Me       = W^T M W,   Ce xed = W^T (M Wdot xed + C(q, qd) qd)            (eq. 12)
with Y_joint = d(M qdd^r + C qd^r)/d theta and Y_friction = d f_a / d theta derived by SymPy.

The factoring holds for a point end effector (task dimension m = 2), where each leg's tip is
the task point: :func:`factored`. Otherwise (a platform, m = 3, whose own inertia and pose
enter Me beyond W^T M W) the same functions convert the monolithic W, Wdot, Me, Ce and Y,
which are correct for any mechanism; a Dynamics may choose either with ``factored``.
"""
import casadi as ca

__all__ = ["factored", "joint_W", "Wdot_times", "regressor", "task_inertia_coriolis",
           "task_gravity", "has_gravity", "solve_small"]


def solve_small(A, b):
    """A^-1 b for the m x m task-space matrices (m = 2, 3) by Cramer's rule (closed form, one
    division per entry); larger A by CasADi's symbolic QR."""
    m = A.shape[0]
    if m == 2:
        det = A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0]
        return ca.vertcat(A[1, 1] * b[0] - A[0, 1] * b[1], A[0, 0] * b[1] - A[1, 0] * b[0]) / det
    if m == 3:
        cof = [[A[(i + 1) % 3, (j + 1) % 3] * A[(i + 2) % 3, (j + 2) % 3]
                - A[(i + 1) % 3, (j + 2) % 3] * A[(i + 2) % 3, (j + 1) % 3] for j in range(3)]
               for i in range(3)]                       # cofactors C_ij
        det = A[0, 0] * cof[0][0] + A[0, 1] * cof[0][1] + A[0, 2] * cof[0][2]
        return ca.vertcat(*[sum(cof[j][i] * b[j] for j in range(3)) for i in range(3)]) / det
    return ca.solve(A, b)


def _inv2(J):
    det = J[0, 0] * J[1, 1] - J[0, 1] * J[1, 0]
    return ca.vertcat(ca.horzcat(J[1, 1], -J[0, 1]), ca.horzcat(-J[1, 0], J[0, 0])) / det


def factored(d):
    """True where the per-leg factored forms hold: a point end effector (m = 2) whose legs'
    tip Jacobians ``kin.J`` the kinematics provides; a Dynamics may decide with ``factored``."""
    choice = getattr(d.dyn, "factored", None)
    if choice is not None:
        return bool(choice)
    return d.m == 2 and hasattr(d.kin, "J")


def _rows(conv, expr, nrow, ncol):
    """A SymPy matrix (nrow, ncol) converted by ``conv`` (row-major flat) back to a matrix."""
    return ca.reshape(conv(expr), ncol, nrow).T


def joint_W(d, conv):
    """W (2n, m) and the legs' J_i^-1 from each leg's tip Jacobian (eq. 7); (W, None) where
    the forms are not factored (W converted as derived)."""
    n = d.spec.n_legs
    if not factored(d):
        return _rows(conv, d.kin.W, 2 * n, d.m), None
    Jinv = [_inv2(ca.reshape(conv(J), 2, 2).T) for J in d.kin.J]
    rows = [Jinv[i][0, :] for i in range(n)] + [Jinv[i][1, :] for i in range(n)]
    return ca.vertcat(*rows), Jinv


def Wdot_times(d, conv, Jinv, qd, a, v):
    """Wdot a (2n,) along the joint velocity qd = W v, for a task vector a (eq. 9), and the
    converter with qd (and the task velocity v) bound."""
    n = d.spec.n_legs
    conv_qd = conv.extended([(d.sym.qd, qd)])
    if Jinv is None:   # Wdot as derived, along qd = W xed with xed = v
        conv_qd = conv_qd.extended([(d.sym.xed, v)])
        return _rows(conv_qd, d.kin.Wdot, 2 * n, d.m) @ a, conv_qd
    W_a = ca.vertcat(*[Jinv[i] @ a for i in range(n)])  # per leg: (qa_i, qb_i) rates
    out_a, out_b = [], []
    for i in range(n):
        Jdot = ca.reshape(conv_qd(d.kin.Jdot[i]), 2, 2).T
        r = -Jinv[i] @ (Jdot @ W_a[2 * i:2 * i + 2])
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
    W, Jinv = joint_W(d, conv)
    S = W[:n, :]
    if Jinv is None:
        c = conv.extended([(sym.xed, v), (sym.xrd, xrd), (sym.xrdd, xrdd)])
        return _rows(c, dyn.Y, m, p), S, W
    qd = W @ v
    Wdot_xrd, conv_qd = Wdot_times(d, conv, Jinv, qd, xrd, v)
    c = conv_qd.extended([(sym.qdr, W @ xrd), (sym.qddr, W @ xrdd + Wdot_xrd)])
    Y_joint = ca.reshape(c(dyn.Y_joint), p, 2 * n).T
    Y_fric = ca.reshape(c(dyn.Y_friction), p, n).T
    # with gravity, Y_joint holds d g_q / d theta, and W^T g_q is Ge (derive/dynamics.py): the
    # gravity term's regressor is in W^T Y_joint already (adding d Ge / d theta here doubled it)
    Y = W.T @ Y_joint + S.T @ Y_fric
    return Y, S, W


def task_inertia_coriolis(d, conv, v, theta_pairs):
    """Me (m, m), Ce v (m,), S and W at the pose of ``conv`` with task velocity v (eq. 12).

    ``theta_pairs``: (sympy symbols, SX) pairs binding the inertial parameters.
    """
    n, m = d.spec.n_legs, d.m
    W, Jinv = joint_W(d, conv)
    if Jinv is None:
        c = conv.extended([(d.sym.xed, v)] + list(theta_pairs))
        return _rows(c, d.dyn.Me, m, m), _rows(c, d.dyn.Ce, m, m) @ v, W[:n, :], W
    qd = W @ v
    Wdot_v, conv_qd = Wdot_times(d, conv, Jinv, qd, v, v)
    c = conv_qd.extended(theta_pairs)
    M = ca.reshape(c(d.dyn.M), 2 * n, 2 * n).T
    C = ca.reshape(c(d.dyn.C), 2 * n, 2 * n).T
    Me = W.T @ M @ W
    Ce_v = W.T @ (M @ Wdot_v + C @ qd)
    return Me, Ce_v, W[:n, :], W
