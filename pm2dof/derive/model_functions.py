# The model's CasADi functions (kinematics, dynamics, regressor) built from the SymPy derivation.
import casadi as ca
import sympy as sp

from .dynamics import Dynamics
from .kinematics import Kinematics
from .splits import min_max, min_norm, preload_function
from .symbols import Symbols
from .to_casadi import Converter

__all__ = ["Derivation", "model_functions", "energy_functions", "assembly_guard"]


class Derivation:
    """The SymPy derivation of one model, and converters from it to CasADi SX."""

    def __init__(self, spec):
        self.spec = spec
        self.sym = Symbols(spec.n_legs, spec.param_names,
                           tuple(spec.task_names), spec.design)
        self.kin = Kinematics(spec, self.sym)
        self.dyn = Dynamics(spec, self.sym, self.kin)
        self._setup()

    @classmethod
    def from_parts(cls, spec, sym, kin, dyn):
        """A derivation of given symbols, kinematics and dynamics (e.g. a test's own mechanism)."""
        d = cls.__new__(cls)
        d.spec, d.sym, d.kin, d.dyn = spec, sym, kin, dyn
        d._setup()
        return d

    def _setup(self):
        #: task dimension m (2: a point end effector, 3: a platform's x, y, phi)
        self.m = len(self.sym.xe)
        #: which of q = [qa; qb] are angles (cos/sin from a table); the others (prismatic
        #: coordinates, m) enter as values
        self.angular = list(getattr(self.kin, "angular", [True] * len(self.sym.q)))
        self._preload = None
        self._pose = None
        # the [design] variables: one SX input ``design`` (k,) of every function whose graph
        # depends on them (:meth:`function`); none without [design]
        design = list(self.sym.design)
        self.design_sx = ca.SX.sym("design", len(design)) if design else None
        self._g = dict(zip(design, ca.vertsplit(self.design_sx))) if design else {}

    def converter(self, symbols, trig=None, lazy=None):
        """A Converter of ``symbols`` that also knows the [design] symbols."""
        return Converter({**self._g, **symbols}, trig, lazy)

    def function(self, name, ins, outs, names_in, names_out):
        """``ca.Function(name, ins, outs, names_in, names_out)``, with the input ``design``
        appended when an output depends on it (an SX function; without [design]: unchanged)."""
        if self.design_sx is not None and any(ca.depends_on(o, self.design_sx) for o in outs):
            ins, names_in = list(ins) + [self.design_sx], list(names_in) + ["design"]
        return ca.Function(name, ins, outs, names_in, names_out)

    def design_args(self, f, design):
        """[design] when ``f``'s last input is ``design`` (pass it on in a call), else []."""
        takes = f.n_in() > 0 and f.name_in(f.n_in() - 1) == "design"
        return [design] if takes else []

    def pose_of_qa(self):
        """{task symbol: its expression by fk in the active coordinates}: where a matrix of q
        (W, Me, ...) also names the pose (a platform's phi), converters bind it on first use."""
        if self._pose is None:   # a platform: its pose from all of q (closed form)
            self._pose = dict(zip(self.sym.xe, self.kin.pose_from_q()
                                  if getattr(self.kin, "platform", False) else self.kin.fk()))
        return self._pose

    def fk_of_qa(self):
        """The pose fk(qa) as SymPy, for a converter from :meth:`converter_qa`: a point's closed
        form (kin.fk()); a platform's task symbols xe, which converter_qa binds to its
        Gauss-Newton fk."""
        return self.sym.xe if getattr(self.kin, "platform", False) else self.kin.fk()

    def _platform_fk(self, symbols, trig, seed, steps):
        """A platform's fk as CasADi: ``steps`` Gauss-Newton steps (kinematics.fk_newton_step)
        from ``seed`` (m,), in the measured qa of ``symbols``."""
        from .kinematics import FK_NEWTON_TOL
        xe = ca.SX.sym("xe_newton", self.m)
        conv = self.converter({**symbols, **dict(zip(self.sym.xe, ca.vertsplit(xe)))}, dict(trig))
        step = conv(self.kin.fk_newton_step())
        O = seed
        for _ in range(steps):
            O_next = ca.substitute(step, xe, O)
            # a converged step (|dO| <= FK_NEWTON_TOL) is not taken: unchanged encoder readings
            # give the seed (the previous pose) back exactly, so a robot at rest measures zero
            # velocity, not rounding noise that sign(v) of eq. 2 would turn into +-fc
            O = ca.if_else(ca.norm_inf(O_next - O) > FK_NEWTON_TOL, O_next, O)
        return O

    def preload(self, S, u, w, sigma, p):
        """The preload split (derive/splits.py) as a call of one shared, never-inlined
        function of this model: (tau, mode)."""
        if self._preload is None:
            self._preload = preload_function(self.spec.n_legs, self.spec.name, self.m)
        return self._preload.call([S, u, w, sigma, p], False, True)

    def sx(self, name, n):
        return ca.SX.sym(name, n)

    def _angles(self, syms):
        """The angles among ``syms`` (entries of q)."""
        index = {s: k for k, s in enumerate(self.sym.q)}
        return [s for s in syms if self.angular[index[s]]]

    def converter_q(self, q, extra=()):
        """Converter for functions of the joint coordinates q: one cos/sin per angle."""
        sym = self.sym
        symbols = {**self._g, **dict(zip(sym.q, ca.vertsplit(q)))}
        trig = {s: (ca.cos(symbols[s]), ca.sin(symbols[s])) for s in self._angles(sym.q)}
        for syms, value in extra:
            symbols.update(zip(syms, ca.vertsplit(value)))
        return Converter(symbols, trig, self.pose_of_qa())

    def converter_xe(self, xe, extra=()):
        """Converter for functions of the task pose: joint directions from geometry, no trig;
        prismatic coordinates from the inverse kinematics."""
        symbols = {**self._g, **dict(zip(self.sym.xe, ca.vertsplit(xe)))}
        for syms, value in extra:
            symbols.update(zip(syms, ca.vertsplit(value)))
        base = Converter(symbols)
        trig = {s: (base(c), base(si)) for s, (c, si) in self.kin.unit_vectors_from_xe().items()}
        lengths = [s for s in self.sym.q if s not in self._angles([s])]
        if lengths:
            ik = dict(zip(self.sym.q, self.kin.ik()))
            symbols.update({s: base(ik[s]) for s in lengths})
        return Converter(symbols, trig)

    def converter_qa(self, qa, extra=(), seed=None, steps=None):
        """Converter for functions of the measured active coordinates: trig of the active
        angles, passive coordinates from the pose fk(qa) (a platform's by ``steps`` Gauss-Newton
        steps, default FK_NEWTON_STEPS, from ``seed``, an SX pose; default [platform] home)."""
        from .kinematics import FK_NEWTON_STEPS
        sym = self.sym
        symbols = {**self._g, **dict(zip(sym.qa, ca.vertsplit(qa)))}
        for syms, value in extra:
            symbols.update(zip(syms, ca.vertsplit(value)))
        trig = {s: (ca.cos(symbols[s]), ca.sin(symbols[s])) for s in self._angles(sym.qa)}
        base = Converter(symbols, trig)
        if getattr(self.kin, "platform", False):    # Gauss-Newton from the seed pose
            seed = ca.DM(self.spec.home) if seed is None else seed
            symbols.update(zip(sym.xe, ca.vertsplit(self._platform_fk(
                symbols, trig, seed, FK_NEWTON_STEPS if steps is None else steps))))
            base = Converter(symbols, trig)
        O = self.fk_of_qa()
        trig.update({s: (base(c), base(si)) for s, (c, si)
                     in self.kin.unit_vectors_from_qa(O).items()})
        lengths = [s for s in sym.qb if s not in self._angles([s])]
        if lengths:   # passive prismatic coordinates: the inverse kinematics at the pose O
            at_O = base.extended([(sym.xe, base(O))])
            ik = dict(zip(sym.q, self.kin.ik()))
            symbols.update({s: at_O(ik[s]) for s in lengths})
        return Converter(symbols, trig, self.pose_of_qa())

    def singularity_measures(self, conv):
        """[type I, type II] singularity measures at the pose, each 0 at its singularity:

        * type I (a leg): min_i |leg_measure_i| (kinematics.leg_measure: an RRR leg's
          sin(qb_i - qa_i), zero where its links align; a PRR leg's cosine between rail and
          link; 1 for an RPR leg);
        * type II (the actuation, parallel): the smallest singular value of S with its rows
          normalised, divided by its largest possible value sqrt(n/2). Row i of S is
          u_bi^T / (la_i sin(qb_i - qa_i)) (eq. 8): normalising the rows removes the legs'
          type I factors and leaves U = [u_b1; ..; u_bn], the distal links' directions. U loses
          rank -- S^T tau cannot produce every task force -- exactly when all distal links are
          parallel. With U^T U = n/2 I + 1/2 [[Re z, Im z], [Im z, -Re z]], z = sum_i e^(2 i qb_i),
          sigma_min(U)^2 = (n - |z|)/2, so the measure is sqrt(1 - |z|/n) in [0, 1]: 1 for
          isotropic directions, sqrt(1 - |cos(qb_1 - qb_2)|) for a five-bar.

        For a platform (m = 3) the type II measure is kinematics.parallel_measure,
        (det U^T U)^(1/3) / (n/3) of the unit wrench lines. For another m = 3 kinematics (the
        tests' toy platform) it is the same sigma_min of S with unit rows
        over its largest possible value sqrt(n/m), from the least eigenvalue of U^T U (3 x 3,
        closed form, :func:`_least_eigenvalue`); S's columns are first divided by the
        kinematics' ``task_scale`` (reference lengths of x, y, phi; default 1) so that force
        and moment directions compare.

        NaN propagates through both (a pose out of reach stays NaN).
        """
        n, sym = self.spec.n_legs, self.sym
        values = [ca.fabs(conv(self.kin.leg_measure(i))) for i in range(n)]
        type1 = values[0]
        for v in values[1:]:  # min(a, b) = (a + b - |a - b|) / 2: unlike C's fmin, keeps NaN
            type1 = (type1 + v - ca.fabs(type1 - v)) / 2
        if self.m != 2 and getattr(self.kin, "platform", False):   # a platform's pose (x, y, phi)
            return ca.vertcat(type1, conv(self.kin.parallel_measure()))
        if self.m != 2:
            return ca.vertcat(type1, self._type2_general(conv))
        re, im = 0, 0
        for i in range(n):
            c, s = conv(sp.cos(sym.qb[i])), conv(sp.sin(sym.qb[i]))
            re, im = re + (c * c - s * s), im + 2 * c * s      # e^(2 i qb) = (c^2 - s^2, 2 c s)
        a = 1 - ca.sqrt(re * re + im * im) * (1.0 / n)         # multiplications, not divisions
        type2 = ca.sqrt((a + ca.fabs(a)) * 0.5)                 # max(a, 0), keeping NaN
        return ca.vertcat(type1, type2)

    def _type2_general(self, conv):
        """sigma_min(U) / sqrt(n/m), U = S (columns over ``task_scale``) with unit rows."""
        n, m = self.spec.n_legs, self.m
        S = ca.reshape(conv(self.kin.S), m, n).T
        scale = getattr(self.kin, "task_scale", None)
        if scale is not None:
            S = S @ ca.diag(ca.DM([1.0 / float(c) for c in scale]))
        U = ca.vertcat(*[S[i, :] / ca.sqrt(ca.sumsqr(S[i, :])) for i in range(n)])
        lam = _least_eigenvalue(U.T @ U)
        return ca.sqrt((lam + ca.fabs(lam)) * 0.5 * (m / n))      # max(lam, 0), keeping NaN


def _least_eigenvalue(G):
    """The least eigenvalue of a symmetric 3 x 3 G in closed form (the trigonometric solution
    of its characteristic cubic); NaN in G gives NaN."""
    if G.shape[0] != 3:
        raise NotImplementedError(f"type II singularity measure for task dimension "
                                  f"{G.shape[0]}: only 2 and 3 are derived")
    q = (G[0, 0] + G[1, 1] + G[2, 2]) / 3
    off = G[0, 1] ** 2 + G[0, 2] ** 2 + G[1, 2] ** 2
    p = ca.sqrt(((G[0, 0] - q) ** 2 + (G[1, 1] - q) ** 2 + (G[2, 2] - q) ** 2 + 2 * off) / 6)
    B = G - q * ca.SX.eye(3)
    det = (B[0, 0] * (B[1, 1] * B[2, 2] - B[1, 2] * B[2, 1])
           - B[0, 1] * (B[1, 0] * B[2, 2] - B[1, 2] * B[2, 0])
           + B[0, 2] * (B[1, 0] * B[2, 1] - B[1, 1] * B[2, 0]))
    r = ca.if_else(p > 0, det / (2 * p ** 3), 0)                  # isotropic G: p = 0
    phi = ca.acos(ca.fmin(ca.fmax(r, -1), 1)) / 3
    return q + 2 * p * ca.cos(phi + 2 * ca.pi / 3)


def assembly_guard(d, conv, value, size):
    """``value`` where the pose ``conv`` binds is in the model's assembly mode, else NaN (size
    entries). Only a non-redundant robot (n = m) has other modes that fk cannot reach; its
    kinematics says which side it is on with ``assembly_side`` (the five-bar's: the sign of
    cross(B2 - B1, O - B1) against ``fk_branch``). Other robots: ``value`` unchanged (a
    non-redundant platform's fk is a Gauss-Newton from a seed pose: it stays in the seed's
    mode, and its wrench lines' measure vanishes between modes)."""
    if d.spec.n_legs != d.m or d.m != 2 or not hasattr(d.kin, "assembly_side"):
        return value
    return ca.if_else(conv(d.kin.assembly_side()) * d.spec.fk_branch > 0, value,
                      ca.DM.nan(size))


def model_functions(d, prefix):
    """The model-level functions of the runtime API, each named and with named inputs/outputs.

    Matrices are returned flattened row-major. ``sing`` holds the two singularity measures at the
    pose, [type I (legs), type II (actuation)] (:meth:`Derivation.singularity_measures`).
    Task-space inputs and outputs have the task dimension m (see also :func:`energy_functions`).
    """
    n, p, m = d.spec.n_legs, len(d.spec.param_names), d.m
    sym, kin, dyn = d.sym, d.kin, d.dyn
    q, xe, qa = d.sx("q", 2 * n), d.sx("xe", m), d.sx("qa", n)
    xed, xrd, xrdd = d.sx("xed", m), d.sx("xrd", m), d.sx("xrdd", m)
    qd, theta, tau_a = d.sx("qd", 2 * n), d.sx("theta", p), d.sx("tau_a", n)
    f = []

    def add(name, ins, outs):
        f.append(d.function(f"{prefix}_{name}", [v for _, v in ins], [v for _, v in outs],
                            [k for k, _ in ins], [k for k, _ in outs]))

    cv = d.converter(dict(zip(sym.xe, ca.vertsplit(xe))))
    add("ik", [("xe", xe)], [("q", assembly_guard(d, cv, cv(kin.ik()), 2 * n))])
    cqa = d.converter_qa(qa)
    O = d.fk_of_qa()
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
    u, w, sgn, pre = d.sx("u", m), d.sx("tau_max", n), d.sx("preload_sign", n), d.sx("preload", n)
    S = ca.reshape(cq(kin.S), m, n).T                                           # eq. 8
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


def energy_functions(d, prefix):
    """``<prefix>_Ge(q, theta) -> (Ge, sing)``: the gravity term of eq. 10 (zero in a horizontal
    plane); ``<prefix>_kinetic_energy(xe, xed, theta) -> T`` = 1/2 xed^T Me xed and
    ``<prefix>_potential_energy(xe, theta) -> V`` (zero without gravity): the derivation's own
    energies. (Generated after every other function, so adding them appended to the C.)"""
    n, p, m = d.spec.n_legs, len(d.spec.param_names), d.m
    sym, kin, dyn = d.sym, d.kin, d.dyn
    q, xe, xed, theta = d.sx("q", 2 * n), d.sx("xe", m), d.sx("xed", m), d.sx("theta", p)
    cq = d.converter_q(q, [(sym.theta, theta)])
    ce = d.converter_xe(xe, [(sym.xed, xed), (sym.theta, theta)])
    ce = ce.extended([(sym.qd, ca.reshape(ce(kin.W), m, 2 * n).T @ xed)])    # qd = W xed, eq. 7
    # the legs' T in (q, qd) plus a platform's own T in xed; V of the legs and the platform
    # (dynamics.py: potential_energy, zero in a horizontal plane)
    T = dyn.T + getattr(dyn, "T_platform", sp.Integer(0))
    V = getattr(dyn, "potential_energy", sp.Integer(0))
    return [d.function(f"{prefix}_Ge", [q, theta],
                       [cq(_gravity_term(d)), d.singularity_measures(cq)],
                       ["q", "theta"], ["Ge", "sing"]),
            d.function(f"{prefix}_kinetic_energy", [xe, xed, theta], [ce(T)],
                       ["xe", "xed", "theta"], ["T"]),
            d.function(f"{prefix}_potential_energy", [xe, theta], [ce(V)],
                       ["xe", "theta"], ["V"])]


def _gravity_term(d):
    """Ge (m,): the gravity term of the task-space dynamics, zero without gravity."""
    Ge = getattr(d.dyn, "Ge", None)
    return sp.zeros(d.m, 1) if Ge is None else Ge
