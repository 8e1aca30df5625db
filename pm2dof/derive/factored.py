# Task-space quantities composed from small joint-space pieces (eqs. 7-13) for the hot paths.
"""Factored forms of W, Wdot, Y, Me and Ce for the generated controller steps and plant.

The monolithic SymPy matrices (Dynamics.Y, .Me, .Ce) are the reference: the model functions
export them as they are, and the tests check them against mpmath and an independent NumPy
formulation. For the per-sample hot paths the same quantities are composed in CasADi from
pieces SymPy derived for one leg or in joint space, which is much cheaper:
  W        rows (i, n+i) = J_i^-1, J_i the tip Jacobian of leg i            (eq. 7)
  Wdot a   = -J_i^-1 Jdot_i(q, qd) (W a)_leg i                            (eq. 9)
  Y        = W^T Y_joint(q, qd, W xrd, W xrdd + Wdot xrd) + S^T Y_friction  (eq. 13)
  Me       = W^T M W,   Ce xed = W^T (M Wdot xed + C(q, qd) qd)            (eq. 12)
with Y_joint = d(M qdd^r + C qd^r)/d theta and Y_friction = d f_a / d theta derived by SymPy.
"""
import casadi as ca

__all__ = ["joint_W", "Wdot_times", "regressor", "task_inertia_coriolis", "solve2"]


def solve2(A, b):
    """A^-1 b for a 2x2 A by Cramer's rule (closed form, one division per entry)."""
    det = A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0]
    return ca.vertcat(A[1, 1] * b[0] - A[0, 1] * b[1], A[0, 0] * b[1] - A[1, 0] * b[0]) / det


def _inv2(J):
    det = J[0, 0] * J[1, 1] - J[0, 1] * J[1, 0]
    return ca.vertcat(ca.horzcat(J[1, 1], -J[0, 1]), ca.horzcat(-J[1, 0], J[0, 0])) / det


def joint_W(d, conv):
    """W (2n, 2) and the legs' J_i^-1 from each leg's tip Jacobian (eq. 7)."""
    n = d.spec.n_legs
    Jinv = [_inv2(ca.reshape(conv(J), 2, 2).T) for J in d.kin.J]
    rows = [Jinv[i][0, :] for i in range(n)] + [Jinv[i][1, :] for i in range(n)]
    return ca.vertcat(*rows), Jinv


def Wdot_times(d, conv, Jinv, qd, a):
    """Wdot a (2n,) along the joint velocity qd, for a task vector a (eq. 9)."""
    n = d.spec.n_legs
    conv_qd = conv.extended([(d.sym.qd, qd)])
    W_a = ca.vertcat(*[Jinv[i] @ a for i in range(n)])  # per leg: (qa_i, qb_i) rates
    out_a, out_b = [], []
    for i in range(n):
        Jdot = ca.reshape(conv_qd(d.kin.Jdot[i]), 2, 2).T
        r = -Jinv[i] @ (Jdot @ W_a[2 * i:2 * i + 2])
        out_a.append(r[0])
        out_b.append(r[1])
    return ca.vertcat(*out_a, *out_b), conv_qd


def regressor(d, conv, v, xrd, xrdd):
    """Y (2, p), S (n, 2) and W at the pose of ``conv`` (eq. 13), measured task velocity v."""
    n, p = d.spec.n_legs, len(d.spec.param_names)
    sym, dyn = d.sym, d.dyn
    W, Jinv = joint_W(d, conv)
    qd = W @ v
    Wdot_xrd, conv_qd = Wdot_times(d, conv, Jinv, qd, xrd)
    c = conv_qd.extended([(sym.qdr, W @ xrd), (sym.qddr, W @ xrdd + Wdot_xrd)])
    Y_joint = ca.reshape(c(dyn.Y_joint), p, 2 * n).T
    Y_fric = ca.reshape(c(dyn.Y_friction), p, n).T
    S = W[:n, :]
    return W.T @ Y_joint + S.T @ Y_fric, S, W


def task_inertia_coriolis(d, conv, v, theta_pairs):
    """Me (2, 2), Ce v (2,), S and W at the pose of ``conv`` with task velocity v (eq. 12).

    ``theta_pairs``: (sympy symbols, SX) pairs binding the inertial parameters.
    """
    n = d.spec.n_legs
    W, Jinv = joint_W(d, conv)
    qd = W @ v
    Wdot_v, conv_qd = Wdot_times(d, conv, Jinv, qd, v)
    c = conv_qd.extended(theta_pairs)
    M = ca.reshape(c(d.dyn.M), 2 * n, 2 * n).T
    C = ca.reshape(c(d.dyn.C), 2 * n, 2 * n).T
    Me = W.T @ M @ W
    Ce_v = W.T @ (M @ Wdot_v + C @ qd)
    return Me, Ce_v, W[:n, :], W
