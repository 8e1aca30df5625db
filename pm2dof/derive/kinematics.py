# SymPy kinematics of a planar parallel manipulator with RRR, PRR or RPR legs joined at a point or
# at a platform: ik, fk, H (eq. 5), A (eq. 6), W, Wdot, S (eqs. 7-9).
import sympy as sp

from .symbols import solve2, solve_small

__all__ = ["Kinematics", "FK_NEWTON_STEPS", "FK_TRACKING_STEPS", "FK_NEWTON_TOL"]

#: Gauss-Newton steps of a platform's fk from its seed pose (fk_newton_step). From the previous
#: sample's pose (about 1 mm and 0.005 rad away at 0.5 m/s and 2 ms) 3 steps reach rounding;
#: 8 reach it from seeds up to 0.05 m and 0.2 rad away on the shipped platforms; 0.1 m and
#: 0.3 rad can diverge, which the closure residual reports (tests/mechanisms/test_independent.py)
FK_NEWTON_STEPS = 8
#: Gauss-Newton steps of the controllers' fk from the previous sample's pose (Fig. 2 signal
#: processing). Along every shipped platform's moves at both speeds (NA, APD, CTC in closed loop,
#: exact and quantised encoders) at most 3 steps are larger than FK_NEWTON_TOL, so 5 give the
#: same pose as FK_NEWTON_STEPS (the steps after the first one below the tolerance are not
#: taken); 5 reach rounding from seeds 0.02 m and 0.08 rad off, 5x a sample's motion at 0.5 m/s
FK_TRACKING_STEPS = 5
#: m (rad for phi): a Gauss-Newton step this small is not taken (converged); far below an
#: encoder count's motion (~1e-5 m), far above rounding (~1e-17)
FK_NEWTON_TOL = 1e-12


def _exact(value):
    """The decimal the model file gives, as an exact rational (so mpmath checks see no rounding)."""
    return sp.Rational(repr(float(value)))


def _u(angle):
    return sp.Matrix([sp.cos(angle), sp.sin(angle)])


def _perp(v):
    """v turned by +90 degrees."""
    return sp.Matrix([-v[1], v[0]])


def _cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def _norm(v):
    return sp.sqrt(v[0] ** 2 + v[1] ** 2)


class Kinematics:
    """Closed-form kinematics derived from the leg geometry of a :class:`ModelSpec`.

    Every matrix is a SymPy expression in the symbols of ``sym`` (joint coordinates ``q``,
    task pose ``xe`` and velocity ``xed``). Nothing here is typed from the paper: W comes
    from inverting each leg's tip Jacobian, Wdot from differentiating W along qd = W xed.

    Leg i's tip, from its two coordinates (qa_i actuated, qb_i passive):

    * RRR: A_i + la_i u(qa_i) + lb_i u(qb_i) (qa_i, qb_i angles: today's leg, Fig. 1);
    * PRR: A_i + qa_i d_i + lb_i u(qb_i) (qa_i the slider's position along the rail's unit
      direction d_i, m; qb_i the link's angle);
    * RPR: A_i + qa_i u(qb_i) (qa_i the leg's length, m; qb_i its angle at the base).

    The tip meets the end effector's point P_i(xe): xe itself for a point, p + R(phi) a_i for a
    platform with pose xe = (x, y, phi) and attachment a_i in its frame. Differentiating,
    J_i (qd_ai, qd_bi) = G_i xed with J_i = d tip_i / d(qa_i, qb_i) and G_i = d P_i / d xe, so
    rows (i, n+i) of W are J_i^-1 G_i (eq. 7).
    """

    def __init__(self, spec, sym):
        self.spec, self.sym = spec, sym
        n, self.m = spec.n_legs, sym.m
        self.platform = spec.end_effector == "platform"
        legs = spec.legs
        self.kinds = [leg.kind for leg in legs]
        #: which coordinates of q are angles (get a cos/sin in the converters); prismatic
        #: coordinates (PRR, RPR actuators) are lengths
        self.angular = [k == "RRR" for k in self.kinds] + [True] * n
        self.A_base = [sp.Matrix(self._point(i, "base")) for i in range(n)]
        self.la = [self._geom(i, "la") if leg.la is not None else None for i, leg in enumerate(legs)]
        self.lb = [self._geom(i, "lb") if leg.lb is not None else None for i, leg in enumerate(legs)]
        self.rail = [self._rail_direction(i) for i in range(n)]      # PRR: unit d_i
        self.P = [self._attachment(i) for i in range(n)]              # P_i(xe)
        self.tips = [self._tip(i) for i in range(n)]
        if not self.platform:
            self.H = sp.Matrix.vstack(*[self.tips[0] - self.tips[i] for i in range(1, n)])  # eq. 5
        else:  # a platform's closure needs its pose: tip_i(q) = P_i(xe) for every leg
            self.H = sp.Matrix.vstack(*[self.tips[i] - self.P[i] for i in range(n)])
        self.A = self.H.jacobian(sym.q)                                             # eq. 6
        # each leg's tip Jacobian J_i = d tip_i / d(qa_i, qb_i) and its rate along qd
        self.J = [self.tips[i].jacobian([sym.qa[i], sym.qb[i]]) for i in range(n)]
        self.Jdot = [J.diff(sym.qa[i]) * sym.qd[i] + J.diff(sym.qb[i]) * sym.qd[n + i]
                     for i, J in enumerate(self.J)]
        # G_i = d P_i / d xe (2, m) and its rate along xed (zero for a point)
        self.G = [P.jacobian(sym.xe) for P in self.P]
        self.Gdot = [sum((G.diff(sym.xe[j]) * sym.xed[j] for j in range(self.m)),
                         sp.zeros(2, self.m)) for G in self.G]
        self.W = self._W()                                                          # eq. 7
        self.S = self.W[:n, :]                                                      # eq. 8
        qd = self.W * sym.xed

        def rate(r, c):                                                             # eq. 9
            out = sum(sp.diff(self.W[r, c], sym.q[k]) * qd[k] for k in range(2 * n))
            if self.platform:  # W also depends on the platform's orientation through G_i
                out += sum(sp.diff(self.W[r, c], sym.xe[j]) * sym.xed[j] for j in range(self.m))
            return out
        self.Wdot = sp.Matrix(2 * n, self.m, rate)

    # ---- geometry per leg kind ----

    def _geom(self, i, field, comp=None):
        """Leg i's geometric number ``field`` (entry ``comp`` of a point): the exact decimal of the
        model file, or the symbol of the [design] variable that sets it (a run-time input)."""
        designed = self.sym.design_of.get((i, field, comp))
        if designed is not None:
            return designed
        value = getattr(self.spec.legs[i], field)
        return _exact(value if comp is None else value[comp])

    def _point(self, i, field):
        """Leg i's point ``field`` ("base", "attach", "rail_end") as [x, y] (:meth:`_geom`)."""
        return [self._geom(i, field, 0), self._geom(i, field, 1)]

    def _rail_direction(self, i):
        leg = self.spec.legs[i]
        if leg.kind != "PRR":
            return None
        d = [e - b for e, b in zip(self._point(i, "rail_end"), self._point(i, "base"))]
        length = sp.sqrt(d[0] ** 2 + d[1] ** 2)
        return sp.Matrix([d[0] / length, d[1] / length])

    def _attachment(self, i):
        """P_i(xe): the point leg i's tip must reach."""
        xe = self.sym.xe
        if not self.platform:
            return xe
        a = self._point(i, "attach")
        c, s = sp.cos(xe[2]), sp.sin(xe[2])
        return sp.Matrix([xe[0] + c * a[0] - s * a[1], xe[1] + s * a[0] + c * a[1]])

    def _tip(self, i):
        sym, kind, A = self.sym, self.kinds[i], self.A_base[i]
        if kind == "RRR":  # Fig. 1
            return A + self.la[i] * _u(sym.qa[i]) + self.lb[i] * _u(sym.qb[i])
        if kind == "PRR":
            return A + sym.qa[i] * self.rail[i] + self.lb[i] * _u(sym.qb[i])
        return A + sym.qa[i] * _u(sym.qb[i])                                    # RPR

    def _W(self):
        """Rows (i, n+i) of W: J_i^-1 G_i, J_i leg i's tip Jacobian d tip_i / d(qa_i, qb_i)."""
        sym, n = self.sym, self.spec.n_legs
        W = sp.zeros(2 * n, self.m)
        for i in range(n):
            J = self.tips[i].jacobian([sym.qa[i], sym.qb[i]])
            Jinv = J.adjugate() / J.det()
            if self.platform:
                Jinv = Jinv * self.G[i]
            W[i, :] = Jinv[0, :]
            W[n + i, :] = Jinv[1, :]
        return W

    def pose_from_q(self):
        """The task pose as a function of all joint coordinates q (the legs' tips): a point is
        tip_1; a platform's angle is that of tip_2 - tip_1 less that of a_2 - a_1, its origin
        tip_1 - R(phi) a_1. Functions of q that also depend on the pose (a platform's W,
        Me, ...) bind xe to this."""
        t1, t2 = self.tips[0], self.tips[1]
        if not self.platform:
            return t1
        a1, a2 = (self._point(i, "attach") for i in (0, 1))
        da = sp.Matrix([a2[0] - a1[0], a2[1] - a1[1]])
        dt = t2 - t1
        phi = sp.atan2(_cross(da, dt), (da.T * dt)[0])
        c, s = sp.cos(phi), sp.sin(phi)
        return sp.Matrix([t1[0] - (c * a1[0] - s * a1[1]), t1[1] - (s * a1[0] + c * a1[1]), phi])

    # ---- singularity measures ----

    def sin_ab(self, i):
        """The singularity measure of RRR leg i: sin(qb_i - qa_i) (its tip Jacobian is singular at 0)."""
        return sp.sin(self.sym.qb[i] - self.sym.qa[i])

    def leg_measure(self, i):
        """Leg i's type I measure in [-1, 1], zero where its tip Jacobian J_i is singular:
        RRR sin(qb_i - qa_i) (links aligned); PRR d_i . u(qb_i), the cosine between rail and
        link (link across the rail); RPR 1 (det J_i = qa_i, the leg's length, which the
        stroke keeps above its minimum)."""
        kind = self.kinds[i]
        if kind == "RRR":
            return self.sin_ab(i)
        if kind == "PRR":
            d, qb = self.rail[i], self.sym.qb[i]
            return d[0] * sp.cos(qb) + d[1] * sp.sin(qb)
        return sp.Integer(1)

    def wrench_lines(self):
        """(n, m): row i is the direction of the force leg i's actuator can exert on the end
        effector, u(qb_i) (along the distal link, or along an RPR leg), and for a platform
        its moment about the platform's origin, (R(phi) a_i) x u(qb_i) in m. Row i of S is
        this row times a scalar (eq. 8), so S loses rank exactly when these rows do (type II)."""
        sym, n, rows = self.sym, self.spec.n_legs, []
        for i in range(n):
            ub = _u(sym.qb[i])
            row = [ub[0], ub[1]]
            if self.platform:
                row.append(_cross(self.P[i] - sym.xe[:2, 0], ub))
            rows.append(row)
        return sp.Matrix(rows)

    def moment_length(self):
        """L, m: the platform's characteristic length, the RMS distance of its attachment points
        from its origin. Type II scales moments by 1/L to compare them with forces."""
        if any(key[1] == "attach" for key in self.sym.design_of):
            a = [self._point(i, "attach") for i in range(self.spec.n_legs)]
            return sp.sqrt(sum(x ** 2 + y ** 2 for x, y in a) / len(a))
        a2 = [leg.attach[0] ** 2 + leg.attach[1] ** 2 for leg in self.spec.legs]
        return _exact((sum(a2) / len(a2)) ** 0.5)   # a scale: its rounding does not matter

    def parallel_measure(self):
        """A platform's type II measure in [0, 1]: (det U^T U)^(1/3) / (n/3), U (n, 3) the
        wrench lines (wrench_lines) with moments over moment_length() and each row of unit
        length. trace U^T U = n, so the measure is 1 for isotropic lines and 0 exactly when S
        loses rank (lines concurrent or all parallel). (A point end effector keeps the closed
        form sqrt(1 - |z|/n) of model_functions.singularity_measures.)"""
        if not self.platform:
            raise ValueError("parallel_measure is a platform's; a point's is closed-form")
        L, rows = self.moment_length(), []
        for i in range(self.spec.n_legs):
            u = self.wrench_lines()[i, :]
            r = sp.Matrix([[u[0], u[1], u[2] / L]])
            rows.append(r / sp.sqrt(1 + (u[2] / L) ** 2))   # |u[:2]| = 1
        U = sp.Matrix.vstack(*rows)
        G = U.T * U
        det = (G[0, 0] * (G[1, 1] * G[2, 2] - G[1, 2] * G[2, 1])
               - G[0, 1] * (G[1, 0] * G[2, 2] - G[1, 2] * G[2, 0])
               + G[0, 2] * (G[1, 0] * G[2, 1] - G[1, 1] * G[2, 0]))
        # max(det, 0) keeping NaN (rounding can leave -1e-17 at a singularity)
        return ((det + sp.Abs(det)) / 2) ** sp.Rational(1, 3) * sp.Rational(3, self.spec.n_legs)

    # ---- inverse kinematics ----

    def _leg_ik(self, i):
        """(qa_i, qb_i, (cos, sin) of qa_i or None, (cos, sin) of qb_i) from xe, for leg i's
        configured branch; the unit vectors from geometry alone (no trig)."""
        leg, kind, A = self.spec.legs[i], self.kinds[i], self.A_base[i]
        d = self.P[i] - A
        dist = _norm(d)
        if kind == "RRR":
            # law of cosines at the base: angle between A_i->O and the active link
            c = (self.la[i] ** 2 + dist ** 2 - self.lb[i] ** 2) / (2 * self.la[i] * dist)
            psi = sp.acos(c)
            qa = sp.atan2(d[1], d[0]) + leg.elbow * psi
            e = self.P[i] - (A + self.la[i] * _u(qa))
            s = leg.elbow * sp.sqrt(1 - c ** 2)
            dh = d / dist
            ua = c * dh + s * _perp(dh)
            ub = (d - self.la[i] * ua) / self.lb[i]
            return qa, sp.atan2(e[1], e[0]), (ua[0], ua[1]), (ub[0], ub[1])
        if kind == "PRR":
            r = self.rail[i]
            h = _cross(r, d)                        # signed distance of P_i from the rail's line
            qa = (r.T * d)[0] + leg.elbow * sp.sqrt(self.lb[i] ** 2 - h ** 2)
            e = d - qa * r                          # slider -> P_i
            return qa, sp.atan2(e[1], e[0]), None, (e[0] / self.lb[i], e[1] / self.lb[i])
        return dist, sp.atan2(d[1], d[0]), None, (d[0] / dist, d[1] / dist)     # RPR

    def ik(self):
        """All 2n joint coordinates from the task pose xe, for each leg's configured branch."""
        legs = [self._leg_ik(i) for i in range(self.spec.n_legs)]
        return sp.Matrix([leg[0] for leg in legs] + [leg[1] for leg in legs])

    def unit_vectors_from_xe(self):
        """(cos, sin) of every angular joint coordinate as functions of xe, from geometry alone
        (no trig). RRR: the active link makes the angle psi_i with A_i -> P_i (law of cosines),
        turned left for elbow +1; the passive link direction is then (P_i - B_i) / lb_i."""
        table, sym = {}, self.sym
        for i in range(self.spec.n_legs):
            _, _, ua, ub = self._leg_ik(i)
            if ua is not None:
                table[sym.qa[i]] = ua
            table[sym.qb[i]] = ub
        return table

    def prismatic_from_xe(self):
        """{qa_i: its value as a function of xe} for the prismatic coordinates (PRR, RPR)."""
        sym = self.sym
        return {sym.qa[i]: self._leg_ik(i)[0] for i in range(self.spec.n_legs)
                if not self.angular[i]}

    def assembly_side(self):
        """For two legs: cross(B2 - B1, O - B1) at the pose ik gives for xe, B_i the centre of
        leg i's circle (centres()). Its sign is the assembly mode (+: O left of the line
        B1 -> B2); fk returns the side ``fk_branch``. Zero on the parallel singularity (distal
        links aligned), which separates the two modes."""
        sym, uv = self.sym, self.unit_vectors_from_xe()
        values = self.prismatic_from_xe()
        B = []
        for i in range(2):
            if self.kinds[i] == "RRR":
                B.append(self.A_base[i] + self.la[i] * sp.Matrix(uv[sym.qa[i]]))
            else:
                B.append(self.centres()[i].xreplace(values))
        d, e = B[1] - B[0], sym.xe - B[0]
        return d[0] * e[1] - d[1] * e[0]

    # ---- forward kinematics ----

    def centres(self):
        """Given the actuated coordinates, P_i lies on a circle: its centre B_i(qa_i). RRR: the
        elbow A_i + la_i u(qa_i); PRR: the slider A_i + qa_i d_i; RPR: the base A_i."""
        sym, out = self.sym, []
        for i, kind in enumerate(self.kinds):
            if kind == "RRR":
                out.append(self.A_base[i] + self.la[i] * _u(sym.qa[i]))
            elif kind == "PRR":
                out.append(self.A_base[i] + sym.qa[i] * self.rail[i])
            else:
                out.append(self.A_base[i])
        return out

    def radii(self):
        """The circles' radii: lb_i (RRR, PRR) or the leg's length qa_i (RPR)."""
        return [self.sym.qa[i] if k == "RPR" else self.lb[i] for i, k in enumerate(self.kinds)]

    def elbows(self):
        """Elbow points B_i = A_i + la_i u(qa_i), from the active angles only (RRR legs)."""
        return self.centres()

    def fk(self):
        """Task position of a point end effector from the actuated coordinates: O is at distance
        r_i from every centre B_i (centres(), radii()). A platform has no closed form: see
        fk_newton_step."""
        if self.platform:
            raise ValueError("a platform's fk is iterative: use fk_newton_step from a seed pose")
        B, r, n = self.centres(), self.radii(), self.spec.n_legs
        if n == 2:  # five-bar: intersect two circles, pick the configured branch
            d = B[1] - B[0]
            D2 = d[0] ** 2 + d[1] ** 2
            a = (r[0] ** 2 - r[1] ** 2 + D2) / (2 * D2)                   # along d, as fraction
            h = sp.sqrt(r[0] ** 2 / D2 - a ** 2)                          # across d, as fraction
            perp = sp.Matrix([-d[1], d[0]])
            return B[0] + a * d + self.spec.fk_branch * h * perp
        # n >= 3: subtract leg 1's circle from the others -> linear G O = h; least squares
        G = sp.Matrix.vstack(*[2 * (B[j] - B[0]).T for j in range(1, n)])
        h = sp.Matrix([(B[j].T * B[j])[0] - (B[0].T * B[0])[0] - r[j] ** 2 + r[0] ** 2
                       for j in range(1, n)])
        return solve2(G.T * G, G.T * h)

    def fk_residual(self):
        """(n,) |P_i(xe) - B_i(qa)|^2 - r_i^2, m^2: zero when the pose xe closes every leg."""
        out = []
        for P, B, r in zip(self.P, self.centres(), self.radii()):
            d = P - B
            out.append(d[0] ** 2 + d[1] ** 2 - r ** 2)
        return sp.Matrix(out)

    def fk_newton_step(self):
        """One Gauss-Newton step of a platform's fk: the pose xe - (Jr^T Jr)^-1 Jr^T r, with r
        = fk_residual() and Jr = d r / d xe, as an expression of the current estimate xe and
        qa. fk for the chosen assembly mode is FK_NEWTON_STEPS of these from a seed pose (the
        previous pose, or [platform] home): the solution nearest the seed. closure_residuals
        at the result report non-convergence."""
        r = self.fk_residual()
        Jr = r.jacobian(self.sym.xe)
        return self.sym.xe - solve_small(Jr.T * Jr, Jr.T * r)

    def closure_residuals(self, O):
        """|P_i(O) - B_i| - r_i for every leg, m: how far the pose O misses each leg's circle.

        Zero when the actuated coordinates are consistent. With more legs than task
        coordinates, fk fits O to all circles by least squares, so a residual measures how
        inconsistent the encoders are: the extra legs are a check. (A five-bar's fk meets both
        circles exactly: residuals are zero; a platform's also reports a Newton that has not
        converged.)
        """
        out = []
        for P, B, r in zip(self._at(O), self.centres(), self.radii()):
            d = P - B
            out.append(sp.sqrt(d[0] ** 2 + d[1] ** 2) - r)
        return sp.Matrix(out)

    def _at(self, O):
        """P_i at the pose O (a point: O itself)."""
        if not self.platform:
            return [O] * self.spec.n_legs
        return [P.xreplace(dict(zip(self.sym.xe, O))) for P in self.P]

    def unit_vectors_from_qa(self, O):
        """(cos, sin) of the passive angles from the actuated coordinates and the pose O = fk(qa).

        Normalised by |P_i - B_i| rather than r_i: the same as qb_i = atan2(P_i - B_i) even when
        quantised encoders make the legs slightly inconsistent (|P_i - B_i| != r_i).
        """
        out = {}
        for i, (P, B) in enumerate(zip(self._at(O), self.centres())):
            d = P - B
            r = sp.sqrt(d[0] ** 2 + d[1] ** 2)
            out[self.sym.qb[i]] = (d[0] / r, d[1] / r)
        return out
