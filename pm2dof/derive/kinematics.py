# SymPy kinematics of an n-leg planar RR parallel manipulator: ik, fk, H (eq. 5), A (eq. 6), W, Wdot, S (eqs. 7-9).
import sympy as sp

from .symbols import solve2

__all__ = ["Kinematics"]


def _exact(value):
    """The decimal the model file gives, as an exact rational (so mpmath checks see no rounding)."""
    return sp.Rational(repr(float(value)))


def _u(angle):
    return sp.Matrix([sp.cos(angle), sp.sin(angle)])


class Kinematics:
    """Closed-form kinematics derived from the leg geometry of a :class:`ModelSpec`.

    Every matrix is a SymPy expression in the symbols of ``sym`` (joint angles ``q``,
    task position ``xe`` and velocity ``xed``). Nothing here is typed from the paper: W comes
    from inverting each leg's tip Jacobian, Wdot from differentiating W along qd = W xed.
    """

    def __init__(self, spec, sym):
        self.spec, self.sym = spec, sym
        n = spec.n_legs
        self.A_base = [sp.Matrix([_exact(c) for c in leg.base]) for leg in spec.legs]
        self.la = [_exact(leg.la) for leg in spec.legs]
        self.lb = [_exact(leg.lb) for leg in spec.legs]
        # tip of leg i as a function of its two absolute angles (Fig. 1)
        self.tips = [self.A_base[i] + self.la[i] * _u(sym.qa[i]) + self.lb[i] * _u(sym.qb[i])
                     for i in range(n)]
        self.H = sp.Matrix.vstack(*[self.tips[0] - self.tips[i] for i in range(1, n)])  # eq. 5
        self.A = self.H.jacobian(sym.q)                                             # eq. 6
        self.W = self._W()                                                          # eq. 7
        # each leg's tip Jacobian J_i = d tip_i / d(qa_i, qb_i) and its rate along qd
        self.J = [self.tips[i].jacobian([sym.qa[i], sym.qb[i]]) for i in range(n)]
        self.Jdot = [J.diff(sym.qa[i]) * sym.qd[i] + J.diff(sym.qb[i]) * sym.qd[n + i]
                     for i, J in enumerate(self.J)]
        self.S = self.W[:n, :]                                                      # eq. 8
        qd = self.W * sym.xed
        self.Wdot = sp.Matrix(2 * n, 2, lambda r, c: sum(                           # eq. 9
            sp.diff(self.W[r, c], sym.q[k]) * qd[k] for k in range(2 * n)))

    def _W(self):
        """Rows (i, n+i) of W: the inverse of leg i's tip Jacobian d tip_i / d(qa_i, qb_i)."""
        sym, n = self.sym, self.spec.n_legs
        W = sp.zeros(2 * n, 2)
        for i in range(n):
            J = self.tips[i].jacobian([sym.qa[i], sym.qb[i]])
            Jinv = J.adjugate() / J.det()
            W[i, :] = Jinv[0, :]
            W[n + i, :] = Jinv[1, :]
        return W

    def sin_ab(self, i):
        """The singularity measure of leg i: sin(qb_i - qa_i) (its tip Jacobian is singular at 0)."""
        return sp.sin(self.sym.qb[i] - self.sym.qa[i])

    def ik(self):
        """All 2n joint angles from the task position xe, for each leg's configured elbow."""
        sym, out_a, out_b = self.sym, [], []
        for i, leg in enumerate(self.spec.legs):
            d = sym.xe - self.A_base[i]
            dist = sp.sqrt(d[0] ** 2 + d[1] ** 2)
            # law of cosines at the base: angle between A_i->O and the active link
            psi = sp.acos((self.la[i] ** 2 + dist ** 2 - self.lb[i] ** 2) / (2 * self.la[i] * dist))
            qa = sp.atan2(d[1], d[0]) + leg.elbow * psi
            elbow_point = self.A_base[i] + self.la[i] * _u(qa)
            e = sym.xe - elbow_point
            out_a.append(qa)
            out_b.append(sp.atan2(e[1], e[0]))
        return sp.Matrix(out_a + out_b)

    def assembly_side(self):
        """For two legs: cross(B2 - B1, O - B1) at the pose ik gives for xe. Its sign is the
        assembly mode (+: O left of the line B1 -> B2); fk returns the side ``fk_branch``. Zero on
        the parallel singularity (distal links aligned), which separates the two modes."""
        sym, uv = self.sym, self.unit_vectors_from_xe()
        B = [self.A_base[i] + self.la[i] * sp.Matrix(uv[sym.qa[i]]) for i in range(2)]
        d, e = B[1] - B[0], sym.xe - B[0]
        return d[0] * e[1] - d[1] * e[0]

    def elbows(self):
        """Elbow points B_i = A_i + la_i u(qa_i), from the active angles only."""
        return [self.A_base[i] + self.la[i] * _u(self.sym.qa[i]) for i in range(self.spec.n_legs)]

    def fk(self):
        """Task position from the active angles: O is at distance lb_i from every elbow B_i."""
        B, n = self.elbows(), self.spec.n_legs
        if n == 2:  # five-bar: intersect two circles, pick the configured branch
            d = B[1] - B[0]
            D2 = d[0] ** 2 + d[1] ** 2
            a = (self.lb[0] ** 2 - self.lb[1] ** 2 + D2) / (2 * D2)       # along d, as fraction
            h = sp.sqrt(self.lb[0] ** 2 / D2 - a ** 2)                    # across d, as fraction
            perp = sp.Matrix([-d[1], d[0]])
            return B[0] + a * d + self.spec.fk_branch * h * perp
        # n >= 3: subtract leg 1's circle from the others -> linear G O = h; least squares
        G = sp.Matrix.vstack(*[2 * (B[j] - B[0]).T for j in range(1, n)])
        h = sp.Matrix([(B[j].T * B[j])[0] - (B[0].T * B[0])[0] - self.lb[j] ** 2 + self.lb[0] ** 2
                       for j in range(1, n)])
        return solve2(G.T * G, G.T * h)

    def closure_residuals(self, O):
        """|O - B_i| - lb_i for every leg, m: how far the tip O misses each elbow's circle.

        Zero when the active angles are consistent. With n >= 3 legs, fk fits O to all circles
        by least squares, so a residual measures how inconsistent the encoders are: the extra
        legs are a check. (A five-bar's fk meets both circles exactly: residuals are zero.)
        """
        out = []
        for i, B in enumerate(self.elbows()):
            d = O - B
            out.append(sp.sqrt(d[0] ** 2 + d[1] ** 2) - self.lb[i])
        return sp.Matrix(out)

    def unit_vectors_from_xe(self):
        """(cos, sin) of every joint angle as functions of xe, from geometry alone (no trig).

        The active link of leg i makes the angle psi_i with A_i -> O (law of cosines), turned
        left for elbow +1; the passive link direction is then (O - B_i) / lb_i.
        """
        sym, table = self.sym, {}
        for i, leg in enumerate(self.spec.legs):
            d = sym.xe - self.A_base[i]
            dist = sp.sqrt(d[0] ** 2 + d[1] ** 2)
            c = (self.la[i] ** 2 + dist ** 2 - self.lb[i] ** 2) / (2 * self.la[i] * dist)
            s = leg.elbow * sp.sqrt(1 - c ** 2)
            dh = d / dist
            ua = c * dh + s * sp.Matrix([-dh[1], dh[0]])
            ub = (d - self.la[i] * ua) / self.lb[i]
            table[sym.qa[i]] = (ua[0], ua[1])
            table[sym.qb[i]] = (ub[0], ub[1])
        return table

    def unit_vectors_from_qa(self, O):
        """(cos, sin) of the passive angles from the active ones and the tip O = fk(qa).

        Normalised by |O - B_i| rather than lb_i: the same as qb_i = atan2(O - B_i) even when
        quantised angles make the legs slightly inconsistent (|O - B_i| != lb_i).
        """
        out = {}
        for i, B in enumerate(self.elbows()):
            d = O - B
            r = sp.sqrt(d[0] ** 2 + d[1] ** 2)
            out[self.sym.qb[i]] = (d[0] / r, d[1] / r)
        return out
