# SymPy dynamics: M, C (eqs. 1, 3) from kinetic energy; Me, Ce (eq. 12); friction (eq. 2); Y (eq. 13).
import sympy as sp

from .symbols import sgn, solve2

__all__ = ["Dynamics"]


def _friction(model, v, params, constants):
    """Friction torque at one actuated joint with velocity v (eq. 2 and its extensions)."""
    if model == "coulomb_viscous":                 # eq. 2
        fv, fc = params
        return fc * sgn(v) + fv * v
    if model == "coulomb_viscous_stribeck":        # eq. 2 + Stribeck excess, linear in fs
        fv, fc, fs = params
        vs = sp.Rational(repr(constants["stribeck_velocity"]))
        return (fc + fs / (1 + (v / vs) ** 2)) * sgn(v) + fv * v
    if model == "smooth_sign":                     # eq. 2 with sign(v) -> v / sqrt(v^2 + eps^2)
        fv, fc = params
        eps = sp.Rational(repr(constants["sign_smoothing_velocity"]))
        return fc * v / sp.sqrt(v ** 2 + eps ** 2) + fv * v
    raise ValueError(f"unknown friction model {model!r}")


class Dynamics:
    """Joint- and task-space dynamics of the model, linear in the parameters theta.

    Leg i has kinetic energy T_i = 1/2 alpha_i qd_ai^2 + beta_i cos(qa_i - qb_i) qd_ai qd_bi
    + 1/2 gamma_i qd_bi^2 (the definition of the lumped parameters, eq. 1). M is its Hessian
    in qd; C comes from the Christoffel symbols of M, so Mdot - 2C is skew-symmetric.
    """

    def __init__(self, spec, sym, kin):
        from pm2dof.core.model_file import FRICTION_MODELS
        self.spec, self.sym, self.kin = spec, sym, kin
        n = spec.n_legs
        q = sym.q
        self.qd = sym.qd
        T = 0
        for i in range(n):
            alpha, beta, gamma = sym.leg_params(i, ("alpha", "beta", "gamma"))
            qda, qdb = self.qd[i], self.qd[n + i]
            T += (alpha * qda ** 2 / 2 + beta * sp.cos(q[i] - q[n + i]) * qda * qdb
                  + gamma * qdb ** 2 / 2)
        self.T = T
        self.M = sp.hessian(T, self.qd)                                     # eq. 3
        self.C = self._christoffel()                                        # eq. 3
        fnames = FRICTION_MODELS[spec.friction]
        v = self.qd[:n, 0]
        self.f_a = sp.Matrix([_friction(spec.friction, v[i], sym.leg_params(i, fnames),
                                        spec.friction_constants) for i in range(n)])  # eq. 2
        # task space, with the measured qd = W xed substituted (eqs. 7, 10-12)
        W, S, Wdot = kin.W, kin.S, kin.Wdot
        on_motion = dict(zip(self.qd, W * sym.xed))
        C_motion = self.C.subs(on_motion)
        self.Me = W.T * self.M * W                                          # eq. 12
        self.Ce = W.T * (self.M * Wdot + C_motion * W)                      # eq. 12
        self.StF = S.T * self.f_a.subs(on_motion)                           # eq. 10
        tau = self.Me * sym.xrdd + self.Ce * sym.xrd + self.StF              # eq. 13
        self.Y = tau.jacobian(sym.theta)                                    # eq. 13: Y = d tau / d theta
        rhs = S.T * sym.tau_a - self.Ce * sym.xed - self.StF               # eq. 10
        # joint-space factors of Y (used by the generated controller steps): with qd, qd^r,
        # qdd^r as free symbols, Y = W^T Y_joint + S^T Y_friction (eqs. 9, 12, 13)
        self.Y_joint = (self.M * sym.qddr + self.C * sym.qdr).jacobian(sym.theta)
        self.Y_friction = self.f_a.jacobian(sym.theta)
        self.xedd = solve2(self.Me, rhs)                                    # Me xedd = rhs

    def _christoffel(self):
        """C_kj = sum_i 1/2 (dM_kj/dq_i + dM_ki/dq_j - dM_ij/dq_k) qd_i."""
        q, qd, M = self.sym.q, self.qd, self.M
        N = len(q)
        dM = [M.diff(q[i]) for i in range(N)]
        return sp.Matrix(N, N, lambda k, j: sum(
            (dM[i][k, j] + dM[j][k, i] - dM[k][i, j]) * qd[i] / 2 for i in range(N)))
