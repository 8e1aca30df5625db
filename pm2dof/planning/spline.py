# A C2 cubic spline through waypoints in the task plane, re-parameterised by its arc length.
"""The piece behind :meth:`pm2dof.TaskPath.spline`.

A natural cubic spline c(u) through the waypoints, u the cumulative chord length (C2, zero
curvature at both ends), then p(s) = c(u(s)) with s the arc length:

    p' = c' / |c'|,   p'' = (c'' - (c'' . p') p') / |c'|^2,

so |p'| = 1 exactly and p'' is the curvature vector. s(u) is integrated with 4-point
Gauss-Legendre on 4096 sub-intervals of every span (|c'| is smooth: to rounding), and u(s) is
the cubic Hermite interpolant of that table (du/ds = 1 / |c'| at its nodes): p within 1.5e-15 m
of the table 256 times coarser polished by two Newton steps (each a Gauss-Legendre integral)
that an earlier version used, which this evaluates ~10x faster (building a spline takes ~10 ms). c and
its derivatives are each span's cubic in u - u_j by Horner's rule.
"""
import numpy as np

from ..core.errors import PlanError

__all__ = ["SplinePiece"]

_GL_X, _GL_W = np.polynomial.legendre.leggauss(4)
_SUB = 4096       # sub-intervals per span for the arc-length table


def _natural_second_derivatives(u, P):
    """c''(u_i) (m, 2) of the natural cubic spline through P (m, 2) at knots u (m,)."""
    m = len(u)
    h = np.diff(u)
    A = np.zeros((m, m))
    rhs = np.zeros((m, 2))
    A[0, 0] = A[-1, -1] = 1.0
    for i in range(1, m - 1):
        A[i, i - 1], A[i, i], A[i, i + 1] = h[i - 1], 2 * (h[i - 1] + h[i]), h[i]
        rhs[i] = 6 * ((P[i + 1] - P[i]) / h[i] - (P[i] - P[i - 1]) / h[i - 1])
    return np.linalg.solve(A, rhs)


class SplinePiece:
    """C2 spline through ``waypoints`` (m, 2), m >= 3, as an arc-length piece."""

    kind = "spline"

    def __init__(self, waypoints):
        P = np.asarray(waypoints, dtype=float)
        chord = np.hypot(*np.diff(P, axis=0).T)
        u = np.concatenate([[0.0], np.cumsum(chord)])
        self.P, self.u, self.M = P, u, _natural_second_derivatives(u, P)
        h, M0, M1 = np.diff(u)[:, None], self.M[:-1], self.M[1:]
        # c(u) on span j: P_j + k1 B + k2 B^2 + k3 B^3, B = u - u_j (c'' linear from M_j to M_j+1)
        self.k1 = (P[1:] - P[:-1]) / h - h * (2 * M0 + M1) / 6
        self.k2, self.k3 = M0 / 2, (M1 - M0) / (6 * h)
        # arc-length table at _SUB sub-nodes per span
        nodes = np.concatenate([np.linspace(u[j], u[j + 1], _SUB + 1)[:-1]
                                for j in range(len(u) - 1)] + [[u[-1]]])
        a, b = nodes[:-1], nodes[1:]
        seg = np.cumsum(self._integral(a, b))
        self.nodes, self.s_nodes = nodes, np.concatenate([[0.0], seg])
        self.du_ds = 1.0 / np.hypot(*self._derivs(nodes)[1].T)
        self.length = float(self.s_nodes[-1])
        speed = np.hypot(*self._derivs(np.linspace(0, u[-1], 64 * len(u)))[1].T)
        if not speed.min() > 1e-6 * max(1.0, speed.max()):
            raise PlanError("spline: the waypoints make the spline turn back on itself (its "
                            "parameter speed vanishes): space the waypoints more evenly")

    def _derivs(self, u, order=2):
        """c, c', c'' (k, 2) at parameters u (k,) (``order`` 1: c' alone), from each span's
        cubic in B = u - u_j (Horner)."""
        j = np.clip(np.searchsorted(self.u, u, side="right") - 1, 0, len(self.u) - 2)
        B = (u - self.u[j])[:, None]
        k1, k2, k3 = self.k1[j], self.k2[j], self.k3[j]
        d1 = (3 * k3 * B + 2 * k2) * B + k1
        if order == 1:
            return d1
        c = ((k3 * B + k2) * B + k1) * B + self.P[j]
        return c, d1, 6 * k3 * B + 2 * k2

    def _integral(self, a, b):
        """Arc length of c between parameters a and b (arrays), Gauss-Legendre."""
        mid, half = 0.5 * (a + b), 0.5 * (b - a)
        x = mid[:, None] + half[:, None] * _GL_X[None, :]
        sp = np.hypot(*self._derivs(x.ravel(), 1).T).reshape(x.shape)
        return half * (sp @ _GL_W)

    def evaluate(self, s):
        """p, p', p'' (k, 2) at local arc lengths s (k,) in [0, length]."""
        k = np.clip(np.searchsorted(self.s_nodes, s, side="right") - 1, 0, len(self.nodes) - 2)
        s0, s1 = self.s_nodes[k], self.s_nodes[k + 1]
        u0, u1 = self.nodes[k], self.nodes[k + 1]
        h = s1 - s0
        t = (s - s0) / h                        # cubic Hermite of u(s) on the table interval
        t2, t3 = t * t, t * t * t
        u = ((2 * t3 - 3 * t2 + 1) * u0 + (t3 - 2 * t2 + t) * h * self.du_ds[k]
             + (-2 * t3 + 3 * t2) * u1 + (t3 - t2) * h * self.du_ds[k + 1])
        c, d1, d2 = self._derivs(u)
        speed = np.hypot(*d1.T)[:, None]
        t = d1 / speed
        ddp = (d2 - np.sum(d2 * t, axis=1, keepdims=True) * t) / speed ** 2
        return c, t, ddp
