# SymPy dynamics: M, C (eqs. 1, 3) from kinetic energy; Me, Ce (eq. 12) with the platform's own
# terms; the gravity term Ge; friction (eq. 2); Y (eq. 13); the energies T and V.
import sympy as sp

from .linear import linear_jacobian
from .symbols import sgn, solve_small

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


def _christoffel(M, q, qd):
    """C_kj = sum_i 1/2 (dM_kj/dq_i + dM_ki/dq_j - dM_ij/dq_k) qd_i, so Mdot - 2C is skew."""
    N = len(q)
    dM = [M.diff(q[i]) for i in range(N)]
    return sp.Matrix(N, N, lambda k, j: sum(
        (dM[i][k, j] + dM[j][k, i] - dM[k][i, j]) * qd[i] / 2 for i in range(N)))


class Dynamics:
    """Joint- and task-space dynamics of the model, linear in the parameters theta.

    Leg i's kinetic energy has one form for every kind, with the lumped parameters alpha_i,
    beta_i, gamma_i (docs/model-file.md gives them from the links' masses, centres of mass and
    inertias):

    * RRR: 1/2 alpha qd_a^2 + beta cos(qa - qb) qd_a qd_b + 1/2 gamma qd_b^2 (eq. 1);
    * PRR: 1/2 alpha qd_a^2 + beta (d . u'(qb)) qd_a qd_b + 1/2 gamma qd_b^2, d the rail's unit
      direction, u' = du/dqb;
    * RPR: 1/2 alpha qd_a^2 + 1/2 (gamma - 2 beta qa + alpha qa^2) qd_b^2.

    A platform adds 1/2 m_p |pd|^2 + phid pd . (R'(phi) [mx_p, my_p]) + 1/2 I_p phid^2 in the
    task coordinates. Gravity g (base frame) adds the potential V = -g . (sum of first moments):
    RRR -(kappa g.u(qa) + beta/la g.u(qb)); PRR -(alpha qa g.d + beta g.u(qb)); RPR
    -(kappa - beta + alpha qa) g.u(qb); platform -g.(m_p p + R(phi) [mx_p, my_p]).

    M is the legs' Hessian in qd and C their Christoffel symbols, so Mdot - 2C is
    skew-symmetric; with qd = W xed (eq. 7), Me = W^T M W + Mp, Ce = W^T (M Wdot + C W) + Cp
    (eq. 12, Mp and Cp the platform's own), Ge = W^T dV/dq + dV/dxe.
    """

    def __init__(self, spec, sym, kin):
        from pm2dof.core.mechanism import FRICTION_MODELS
        self.spec, self.sym, self.kin = spec, sym, kin
        n = spec.n_legs
        q = sym.q
        self.qd = sym.qd
        self.gravity = spec.has_gravity
        g = sp.Matrix([sp.Rational(repr(float(c))) for c in spec.gravity])
        T, V = 0, 0
        for i in range(n):
            T += self._leg_T(i)
            if self.gravity:
                V += self._leg_V(i, g)
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
        self.g_q = sp.Matrix([sp.diff(V, qk) for qk in q]) if self.gravity else None
        # the platform's own task-space terms (zero for a point end effector)
        self.T_platform, self.V_platform = self._platform_energies(g)
        self.Mp = sp.hessian(self.T_platform, sym.xed) if kin.platform else None
        self.Cp = _christoffel(self.Mp, sym.xe, sym.xed) if kin.platform else None
        self.g_p = (sp.Matrix([sp.diff(self.V_platform, x) for x in sym.xe])
                    if kin.platform and self.gravity else None)
        if kin.platform:
            self.Me = self.Me + self.Mp
            self.Ce = self.Ce + self.Cp
        self.Ge = sp.zeros(sym.m, 1)                                        # gravity term
        if self.g_q is not None:
            self.Ge = W.T * self.g_q
        if self.g_p is not None:
            self.Ge = self.Ge + self.g_p
        tau = self.Me * sym.xrdd + self.Ce * sym.xrd + self.StF              # eq. 13
        if self.gravity:
            tau = tau + self.Ge
        self.Y = linear_jacobian(tau, sym.theta)                             # eq. 13: Y = d tau / d theta
        rhs = S.T * sym.tau_a - self.Ce * sym.xed - self.StF               # eq. 10
        if self.gravity:
            rhs = rhs - self.Ge
        # joint-space factors of Y (used by the generated controller steps): with qd, qd^r,
        # qdd^r as free symbols, Y = W^T Y_joint + S^T Y_friction + Y_platform (eqs. 9, 12, 13)
        joint = self.M * sym.qddr + self.C * sym.qdr
        if self.g_q is not None:
            joint = joint + self.g_q
        self.Y_joint = linear_jacobian(joint, sym.theta)
        self.Y_friction = linear_jacobian(self.f_a, sym.theta)
        #: the platform's part of Y, a function of xe, xed, xrd, xrdd (None for a point)
        self.Y_platform = None
        if kin.platform:
            own = self.Mp * sym.xrdd + self.Cp * sym.xrd
            if self.g_p is not None:
                own = own + self.g_p
            self.Y_platform = linear_jacobian(own, sym.theta)
        self.xedd = solve_small(self.Me, rhs)                               # Me xedd = rhs
        # the energies as functions of the task state (q stands for ik(xe), qd for W xed)
        self.kinetic_energy = self.T.subs(on_motion) + self.T_platform
        self.potential_energy = V + self.V_platform

    def _leg_T(self, i):
        """Leg i's kinetic energy (class docstring), linear in its alpha, beta, gamma."""
        sym, n, kind = self.sym, self.spec.n_legs, self.kin.kinds[i]
        alpha, beta, gamma = sym.leg_params(i, ("alpha", "beta", "gamma"))
        qa, qb = sym.q[i], sym.q[n + i]
        qda, qdb = self.qd[i], self.qd[n + i]
        if kind == "RRR":  # eq. 1
            return (alpha * qda ** 2 / 2 + beta * sp.cos(qa - qb) * qda * qdb
                    + gamma * qdb ** 2 / 2)
        if kind == "PRR":
            d = self.kin.rail[i]
            # the slider's velocity d qd_a against the link's u'(qb) qd_b: d . u'(qb) = d1 cos(qb) - d0 sin(qb)
            return (alpha * qda ** 2 / 2 + beta * (d[1] * sp.cos(qb) - d[0] * sp.sin(qb)) * qda * qdb
                    + gamma * qdb ** 2 / 2)
        return alpha * qda ** 2 / 2 + (gamma - 2 * beta * qa + alpha * qa ** 2) * qdb ** 2 / 2

    def _leg_V(self, i, g):
        """Leg i's potential energy in gravity g (class docstring), linear in theta."""
        sym, n, kind = self.sym, self.spec.n_legs, self.kin.kinds[i]
        alpha, beta = sym.leg_params(i, ("alpha", "beta"))
        qa, qb = sym.q[i], sym.q[n + i]
        g_ub = g[0] * sp.cos(qb) + g[1] * sp.sin(qb)                        # g . u(qb)
        if kind == "RRR":
            kappa = sym.param[f"kappa{i + 1}"]
            g_ua = g[0] * sp.cos(qa) + g[1] * sp.sin(qa)
            return -(kappa * g_ua + beta / self.kin.la[i] * g_ub)
        if kind == "PRR":
            d = self.kin.rail[i]
            return -(alpha * qa * (g[0] * d[0] + g[1] * d[1]) + beta * g_ub)
        kappa = sym.param[f"kappa{i + 1}"]
        return -(kappa - beta + alpha * qa) * g_ub

    def _platform_energies(self, g):
        """(T, V) of the platform in the task coordinates; (0, 0) for a point."""
        if not self.kin.platform:
            return sp.Integer(0), sp.Integer(0)
        sym, P = self.sym, self.sym.param
        m, mx, my, inertia = P["m_p"], P["mx_p"], P["my_p"], P["I_p"]
        phi = sym.xe[2]
        xd, yd, phid = sym.xed
        c, s = sp.cos(phi), sp.sin(phi)
        Rc = sp.Matrix([c * mx - s * my, s * mx + c * my])       # R(phi) [mx, my]
        dRc = sp.Matrix([-s * mx - c * my, c * mx - s * my])     # d/dphi of it
        T = m * (xd ** 2 + yd ** 2) / 2 + phid * (xd * dRc[0] + yd * dRc[1]) + inertia * phid ** 2 / 2
        V = -(g[0] * (m * sym.xe[0] + Rc[0]) + g[1] * (m * sym.xe[1] + Rc[1])) if self.gravity \
            else sp.Integer(0)
        return T, V

    def _christoffel(self):
        """C_kj = sum_i 1/2 (dM_kj/dq_i + dM_ki/dq_j - dM_ij/dq_k) qd_i."""
        return _christoffel(self.M, self.sym.q, self.qd)
