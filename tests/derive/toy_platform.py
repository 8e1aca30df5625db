# A hand-built 3-DOF mechanism of the derivation's interface (task x, y, phi), for the tests.
"""A synthetic platform with task dimension m = 3, written for the tests without the
derivation's mechanics code: it has the interface of ``derive.symbols.Symbols``,
``derive.kinematics.Kinematics`` and ``derive.dynamics.Dynamics`` that the rest of
``pm2dof.derive`` consumes, so every generated function can be built and checked for m = 3.

Four legs, q = [qa_1..qa_4, qb_1..qb_4]: qa_1 = x and qa_2 = y are prismatic (sliders), the
others are angles given in closed form by the pose (``IK``); fk solves the first three for the
pose, the fourth actuator is redundant. Kinetic energy: the legs' joint-space RR/PR form of
eq. 1 plus the platform's, whose centre of mass is off its origin (first moment mx along the
platform's x axis): 1/2 mp (xd^2 + yd^2) + mx phid (-sin(phi) xd + cos(phi) yd) + 1/2 Ip phid^2;
potential energy V = g (mp y + mx sin(phi) + sum_i lg_i sin qb_i) (gravity along -y). The
platform's terms name the pose phi itself (not only q), as a platform's derivation may. Every
task-space quantity follows from T and V as eq. 12 builds it (Me = W^T M W + Mp(phi),
Ce = W^T (M Wdot + C W) + Cp, Ge = W^T dV/dq + dV/dxe), so T + V is conserved along the forward
dynamics without torque and friction.
"""
import sympy as sp

from pm2dof.derive.dynamics import _friction
from pm2dof.derive.model_functions import Derivation

N_LEGS, GRAVITY = 4, sp.Rational(981, 100)
PARAMS = tuple(f"{b}{i}" for b in ("alpha", "beta", "gamma", "fv", "fc", "lg")
               for i in range(1, N_LEGS + 1)) + ("mp", "mx", "Ip")


class Spec:
    name, n_legs, friction, friction_constants = "toy3", N_LEGS, "coulomb_viscous", {}
    fk_branch, rk4_substeps, dof, task_names = 1, 2, 3, ("x", "y", "phi")
    design = None           # no [design] table: every function without a design input
    param_names = PARAMS
    # the leg kinds the plant's layout reads: legs 1-2 actuated by lengths (angular False)
    legs = tuple(type("Leg", (), {"kind": k})() for k in ["PRR"] * 2 + ["RRR"] * (N_LEGS - 2))


class Symbols:
    def __init__(self, n, names):
        self.n, self.m = n, 3
        self.qa = sp.Matrix(sp.symbols(f"qa1:{n + 1}", real=True))
        self.qb = sp.Matrix(sp.symbols(f"qb1:{n + 1}", real=True))
        self.q = self.qa.col_join(self.qb)
        self.xe = sp.Matrix(sp.symbols("x y phi", real=True))
        self.xed = sp.Matrix(sp.symbols("xd yd phid", real=True))
        self.xrd = sp.Matrix(sp.symbols("xrd yrd phird", real=True))
        self.xrdd = sp.Matrix(sp.symbols("xrdd yrdd phirdd", real=True))
        self.tau_a = sp.Matrix(sp.symbols(f"tau_a1:{n + 1}", real=True))
        for name, a, b in (("qd", "qda", "qdb"), ("qdr", "qdra", "qdrb"), ("qddr", "qddra", "qddrb")):
            setattr(self, name, sp.Matrix(sp.symbols(f"{a}1:{n + 1}", real=True)
                                          + sp.symbols(f"{b}1:{n + 1}", real=True)))
        self.theta = sp.Matrix(sp.symbols(" ".join(names), real=True))
        self.param = dict(zip(names, self.theta))
        self.design, self.design_of = sp.Matrix([]), {}     # no [design] variables

    def leg_params(self, i, names):
        return [self.param[f"{name}{i + 1}"] for name in names]


def ik_of(xe):
    """q (8,) of the pose xe = (x, y, phi)."""
    x, y, phi = xe
    return sp.Matrix([x, y, phi + sp.atan2(y, x + 2), sp.atan2(y - 1, x - 2) + phi / 2,
                      sp.atan2(y + 2, x), sp.atan2(y, x - 3) + phi, phi, sp.atan2(y + 1, x + 1)])


class Kinematics:
    def __init__(self, spec, sym):
        self.sym, n = sym, spec.n_legs
        self.angular = [False, False] + [True] * (2 * n - 2)
        self.IK = ik_of(sym.xe)
        self.pose_of_q = dict(zip(sym.xe, self.fk()))
        self.W = self.IK.jacobian(sym.xe).subs(self.pose_of_q, simultaneous=True)   # dq/dxe
        self.S = self.W[:n, :]
        qd = self.W * sym.xed
        self.Wdot = sp.Matrix(2 * n, 3, lambda r, c: sum(
            sp.diff(self.W[r, c], sym.q[k]) * qd[k] for k in range(2 * n)))
        rest = [k for k in range(2 * n) if k not in (0, 1, 2)]
        self.H = sp.Matrix([sym.q[k] - self.IK[k].subs(self.pose_of_q, simultaneous=True)
                            for k in rest])
        self.A = self.H.jacobian(sym.q)

    def ik(self):
        return self.IK

    def fk(self):
        qa = self.sym.qa
        return sp.Matrix([qa[0], qa[1], qa[2] - sp.atan2(qa[1], qa[0] + 2)])

    def closure_residuals(self, O):
        return sp.Matrix([sp.sin(self.sym.qa[i] - ik_of(O)[i]) for i in range(N_LEGS)])

    def sin_ab(self, i):
        return sp.Rational(1, 2) + sp.cos(self.sym.qb[i]) / 4

    def leg_measure(self, i):          # the derivation's type I measure of leg i
        return self.sin_ab(i)

    def unit_vectors_from_xe(self):
        return {s: (sp.cos(e), sp.sin(e)) for s, e, a in zip(self.sym.q, self.IK, self.angular) if a}

    def unit_vectors_from_qa(self, O):
        q_O = ik_of(O)
        return {self.sym.qb[i]: (sp.cos(q_O[N_LEGS + i]), sp.sin(q_O[N_LEGS + i]))
                for i in range(N_LEGS)}


def _solve3(A, b):
    """A^-1 b by the adjugate, without SymPy's simplification."""
    cof = sp.Matrix(3, 3, lambda i, j: A[(i + 1) % 3, (j + 1) % 3] * A[(i + 2) % 3, (j + 2) % 3]
                    - A[(i + 1) % 3, (j + 2) % 3] * A[(i + 2) % 3, (j + 1) % 3])
    det = sum(A[0, j] * cof[0, j] for j in range(3))
    return cof.T * b / det


class Dynamics:
    def __init__(self, spec, sym, kin):
        n, q, qd = spec.n_legs, sym.q, sym.qd
        self.qd = qd
        T_legs = 0
        for i in range(n):
            alpha, beta, gamma = sym.leg_params(i, ("alpha", "beta", "gamma"))
            c = sp.cos(q[n + i]) if not kin.angular[i] else sp.cos(q[i] - q[n + i])
            T_legs += alpha * qd[i] ** 2 / 2 + beta * c * qd[i] * qd[n + i] + gamma * qd[n + i] ** 2 / 2
        mp, mx, Ip = sym.param["mp"], sym.param["mx"], sym.param["Ip"]
        xd, phi = sym.xed, sym.xe[2]
        Mp = sp.Matrix([[mp, 0, -mx * sp.sin(phi)], [0, mp, mx * sp.cos(phi)],
                        [-mx * sp.sin(phi), mx * sp.cos(phi), Ip]])
        self.T = T_legs + (xd.T * Mp * xd)[0] / 2
        self.V = GRAVITY * (mp * q[1] + mx * sp.sin(phi)
                            + sum(sym.param[f"lg{i + 1}"] * sp.sin(q[n + i]) for i in range(n)))
        self.M = sp.hessian(T_legs, qd)
        N = len(q)
        dM = [self.M.diff(q[i]) for i in range(N)]
        self.C = sp.Matrix(N, N, lambda k, j: sum(
            (dM[i][k, j] + dM[j][k, i] - dM[k][i, j]) * qd[i] / 2 for i in range(N)))
        W, S, Wdot = kin.W, kin.S, kin.Wdot
        on_motion = dict(zip(qd, W * sym.xed))
        self.f_a = sp.Matrix([_friction(spec.friction, qd[i], sym.leg_params(i, ("fv", "fc")), {})
                              for i in range(n)])
        x = sym.xe
        dMp = [Mp.diff(x[i]) for i in range(3)]
        Cp = sp.Matrix(3, 3, lambda k, j: sum(
            (dMp[i][k, j] + dMp[j][k, i] - dMp[k][i, j]) * xd[i] / 2 for i in range(3)))
        self.Me = W.T * self.M * W + Mp
        self.Ce = W.T * (self.M * Wdot + self.C.subs(on_motion) * W) + Cp
        self.Ge = W.T * sp.Matrix([sp.diff(self.V, s) for s in q]) + sp.Matrix(
            [sp.diff(self.V, s) for s in x])
        self.StF = S.T * self.f_a.subs(on_motion)
        tau = self.Me * sym.xrdd + self.Ce * sym.xrd + self.StF + self.Ge
        self.Y = tau.jacobian(sym.theta)
        self.xedd = _solve3(self.Me, S.T * sym.tau_a - self.Ce * sym.xed - self.StF - self.Ge)
        self.potential_energy = self.V      # the name the derivation reads (dynamics.py)


def derivation():
    """The toy platform's :class:`pm2dof.derive.model_functions.Derivation`."""
    spec = Spec()
    sym = Symbols(spec.n_legs, spec.param_names)
    kin = Kinematics(spec, sym)
    return Derivation.from_parts(spec, sym, kin, Dynamics(spec, sym, kin))
