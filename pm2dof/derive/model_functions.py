# The model's CasADi functions (kinematics, dynamics, regressor) built from the SymPy derivation.
import casadi as ca
import sympy as sp

from .dynamics import Dynamics
from .kinematics import Kinematics
from .splits import min_max, min_norm, preload_function
from .symbols import Symbols
from .to_casadi import Converter

__all__ = ["Derivation", "model_functions"]


class Derivation:
    """The SymPy derivation of one model, and converters from it to CasADi SX."""

    def __init__(self, spec):
        self.spec = spec
        self.sym = Symbols(spec.n_legs, spec.param_names)
        self.kin = Kinematics(spec, self.sym)
        self.dyn = Dynamics(spec, self.sym, self.kin)
        self._preload = None

    def preload(self, S, u, w, sigma, p):
        """The preload split (derive/splits.py) as a call of one shared, never-inlined
        function of this model: (tau, mode)."""
        if self._preload is None:
            self._preload = preload_function(self.spec.n_legs, self.spec.name)
        return self._preload.call([S, u, w, sigma, p], False, True)

    def sx(self, name, n):
        return ca.SX.sym(name, n)

    def converter_q(self, q, extra=()):
        """Converter for functions of the joint angles q: one cos/sin per angle."""
        sym = self.sym
        symbols = dict(zip(sym.q, ca.vertsplit(q)))
        trig = {s: (ca.cos(v), ca.sin(v)) for s, v in symbols.items()}
        for syms, value in extra:
            symbols.update(zip(syms, ca.vertsplit(value)))
        return Converter(symbols, trig)

    def converter_xe(self, xe, extra=()):
        """Converter for functions of the task position: joint directions from geometry, no trig."""
        symbols = dict(zip(self.sym.xe, ca.vertsplit(xe)))
        for syms, value in extra:
            symbols.update(zip(syms, ca.vertsplit(value)))
        base = Converter(symbols)
        trig = {s: (base(c), base(si)) for s, (c, si) in self.kin.unit_vectors_from_xe().items()}
        return Converter(symbols, trig)

    def converter_qa(self, qa, extra=()):
        """Converter for functions of the measured active angles: trig of qa, passive from fk."""
        sym = self.sym
        symbols = dict(zip(sym.qa, ca.vertsplit(qa)))
        for syms, value in extra:
            symbols.update(zip(syms, ca.vertsplit(value)))
        trig = {s: (ca.cos(v), ca.sin(v)) for s, v in zip(sym.qa, ca.vertsplit(qa))}
        base = Converter(symbols, trig)
        O = self.kin.fk()
        trig.update({s: (base(c), base(si)) for s, (c, si)
                     in self.kin.unit_vectors_from_qa(O).items()})
        return Converter(symbols, trig)

    def singularity_measures(self, conv):
        """[type I, type II] singularity measures at the pose, each 0 at its singularity:

        * type I (a leg): min_i |sin(qb_i - qa_i)|, zero where leg i's tip Jacobian is singular
          (its links aligned);
        * type II (the actuation, parallel): the smallest singular value of S with its rows
          normalised, divided by its largest possible value sqrt(n/2). Row i of S is
          u_bi^T / (la_i sin(qb_i - qa_i)) (eq. 8): normalising the rows removes the legs'
          type I factors and leaves U = [u_b1; ..; u_bn], the distal links' directions. U loses
          rank -- S^T tau cannot produce every task force -- exactly when all distal links are
          parallel. With U^T U = n/2 I + 1/2 [[Re z, Im z], [Im z, -Re z]], z = sum_i e^(2 i qb_i),
          sigma_min(U)^2 = (n - |z|)/2, so the measure is sqrt(1 - |z|/n) in [0, 1]: 1 for
          isotropic directions, sqrt(1 - |cos(qb_1 - qb_2)|) for a five-bar.

        NaN propagates through both (a pose out of reach stays NaN).
        """
        n, sym = self.spec.n_legs, self.sym
        values = [ca.fabs(conv(self.kin.sin_ab(i))) for i in range(n)]
        type1 = values[0]
        for v in values[1:]:  # min(a, b) = (a + b - |a - b|) / 2: unlike C's fmin, keeps NaN
            type1 = (type1 + v - ca.fabs(type1 - v)) / 2
        re, im = 0, 0
        for i in range(n):
            c, s = conv(sp.cos(sym.qb[i])), conv(sp.sin(sym.qb[i]))
            re, im = re + (c * c - s * s), im + 2 * c * s      # e^(2 i qb) = (c^2 - s^2, 2 c s)
        a = 1 - ca.sqrt(re * re + im * im) * (1.0 / n)         # multiplications, not divisions
        type2 = ca.sqrt((a + ca.fabs(a)) * 0.5)                 # max(a, 0), keeping NaN
        return ca.vertcat(type1, type2)


def model_functions(d, prefix):
    """The model-level functions of the runtime API, each named and with named inputs/outputs.

    Matrices are returned flattened row-major. ``sing`` holds the two singularity measures at the
    pose, [type I (legs), type II (actuation)] (:meth:`Derivation.singularity_measures`).
    """
    n, p = d.spec.n_legs, len(d.spec.param_names)
    sym, kin, dyn = d.sym, d.kin, d.dyn
    q, xe, qa = d.sx("q", 2 * n), d.sx("xe", 2), d.sx("qa", n)
    xed, xrd, xrdd = d.sx("xed", 2), d.sx("xrd", 2), d.sx("xrdd", 2)
    qd, theta, tau_a = d.sx("qd", 2 * n), d.sx("theta", p), d.sx("tau_a", n)
    f = []

    def add(name, ins, outs):
        f.append(ca.Function(f"{prefix}_{name}", [v for _, v in ins], [v for _, v in outs],
                             [k for k, _ in ins], [k for k, _ in outs]))

    cv = Converter(dict(zip(sym.xe, ca.vertsplit(xe))))
    q_ik = cv(kin.ik())
    if n == 2:  # five-bar: refuse (NaN) a pose of the other assembly mode, which fk cannot reach
        q_ik = ca.if_else(cv(kin.assembly_side()) * d.spec.fk_branch > 0, q_ik, ca.DM.nan(2 * n))
    add("ik", [("xe", xe)], [("q", q_ik)])
    cqa = d.converter_qa(qa)
    O = kin.fk()
    add("fk", [("qa", qa)], [("xe", cqa(O)), ("residual", cqa(kin.closure_residuals(O)))])
    cq = d.converter_q(q)
    add("H", [("q", q)], [("H", cq(kin.H))])                                   # eq. 5
    add("A", [("q", q)], [("A", cq(kin.A))])                                   # eq. 6
    add("singularity", [("q", q)], [("sin_ab", cq(sp.Matrix([kin.sin_ab(i) for i in range(n)])))])
    sing = d.singularity_measures(cq)
    add("singularity_measures", [("q", q)], [("sing", sing)])
    add("W", [("q", q)], [("W", cq(kin.W)), ("sing", sing)])                   # eq. 7
    add("S", [("q", q)], [("S", cq(kin.S)), ("sing", sing)])                   # eq. 8
    cqx = d.converter_q(q, [(sym.xed, xed)])
    add("Wdot", [("q", q), ("xed", xed)], [("Wdot", cqx(kin.Wdot)), ("sing", sing)])  # eq. 9
    cqt = d.converter_q(q, [(sym.theta, theta), (dyn.qd, qd)])
    add("M", [("q", q), ("theta", theta)], [("M", cqt(dyn.M))])                # eq. 3
    add("C", [("q", q), ("qd", qd), ("theta", theta)], [("C", cqt(dyn.C))])    # eq. 3
    cqxt = d.converter_q(q, [(sym.xed, xed), (sym.theta, theta)])
    add("Me", [("q", q), ("theta", theta)], [("Me", cqxt(dyn.Me)), ("sing", sing)])  # eq. 12
    add("Ce", [("q", q), ("xed", xed), ("theta", theta)],
        [("Ce", cqxt(dyn.Ce)), ("sing", sing)])                                 # eq. 12
    add("StF", [("q", q), ("xed", xed), ("theta", theta)],
        [("StF", cqxt(dyn.StF)), ("sing", sing)])                               # eqs. 2, 10
    cy = d.converter_q(q, [(sym.xed, xed), (sym.xrd, xrd), (sym.xrdd, xrdd)])
    add("Y", [("q", q), ("xed", xed), ("xrd", xrd), ("xrdd", xrdd)],
        [("Y", cy(dyn.Y)), ("sing", sing)])                                     # eq. 13
    u, w, sgn, pre = d.sx("u", 2), d.sx("tau_max", n), d.sx("preload_sign", n), d.sx("preload", n)
    S = ca.reshape(cq(kin.S), 2, n).T                                           # eq. 8
    t_mm, ratio = min_max(S, u, w)
    t_pl, mode = d.preload(S, u, w, sgn, pre)
    add("torque_splits", [("q", q), ("u", u), ("tau_max", w), ("preload_sign", sgn),
                          ("preload", pre)],
        [("tau_min_norm", min_norm(S, u)), ("tau_min_max", t_mm), ("min_max_ratio", ratio),
         ("tau_preload", t_pl), ("preload_mode", mode), ("sing", sing)])       # S^T tau = u
    cfd = d.converter_xe(xe, [(sym.xed, xed), (sym.tau_a, tau_a), (sym.theta, theta)])
    add("forward_dynamics", [("xe", xe), ("xed", xed), ("tau_a", tau_a), ("theta", theta)],
        [("xedd", cfd(dyn.xedd)), ("sing", d.singularity_measures(cfd))])       # eqs. 10-12
    return f
