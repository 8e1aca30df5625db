# pm2dof/reference/model.py
#
# Plain-NumPy reference implementation of the kinematics and dynamics of the
# redundantly actuated planar parallel manipulator of
#
#     Shang, W.; Cong, S. "Nonlinear adaptive task space control for a 2-DOF
#     redundantly actuated parallel manipulator", Nonlinear Dyn 59:61-72 (2010)
#
# generalised from the paper's 3 legs to n RR legs meeting at one tip O.
# Equation numbers refer to the paper (as restated in docs/paper.md of the pm2dof repository).
#
# This module is an independent, hand-derived formulation used only by tests and
# benchmarks to cross-check the symbolic (SymPy/CasADi) derivation; it favours
# clarity over speed and is never on the controller's hot path.
#
# Conventions
# -----------
# * n legs; leg i has base A_i, active (proximal) link la_i, passive (distal)
#   link lb_i; angles are absolute, measured from +x.
# * q = [qa_1..qa_n, qb_1..qb_n] (2n,), rad.
#   tip_i(q) = A_i + la_i u(qa_i) + lb_i u(qb_i),  u(t) = (cos t, sin t).
# * elbow_i = +1: elbow B_i = A_i + la_i u(qa_i) lies LEFT of the directed line
#   A_i -> O; -1: right.
# * theta (5n,) = (alpha_1..n, beta_1..n, gamma_1..n, fv_1..n, fc_1..n).
# * sign(0) = 0 in the Coulomb friction term (a joint at rest has none).
# * Units: lengths m, angles rad, alpha/beta/gamma kg m^2, fv N m s/rad,
#   fc N m, torques N m.
"""Plain-NumPy reference kinematics and dynamics of the n-leg planar PM.

Independent hand-derived formulation of Shang & Cong (2010), eqs. 1-13,
generalised from 3 to ``n`` RR legs.  See the module header for conventions.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..core.task import require_rr_point

__all__ = [
    "Geometry",
    "ik",
    "fk",
    "closure_residuals",
    "H",
    "A",
    "W",
    "S",
    "Wdot",
    "M",
    "C",
    "friction",
    "Me",
    "Ce",
    "task_friction",
    "Y",
    "singularity_measures",
    "forward_dynamics",
    "forward_dynamics_joint",
]


# --------------------------------------------------------------------------
# Geometry
# --------------------------------------------------------------------------


def _readonly(a: Any, dtype: type = float) -> np.ndarray:
    arr = np.array(a, dtype=dtype, copy=True)
    arr.setflags(write=False)
    return arr


@dataclass(frozen=True)
class Geometry:
    """Geometry of an n-leg planar RR-leg parallel manipulator.

    Parameters
    ----------
    bases : array_like, shape (n, 2)
        Base joint positions A_i, m.
    la : array_like, shape (n,)
        Active (proximal) link lengths, m.
    lb : array_like, shape (n,)
        Passive (distal) link lengths, m.
    elbow : array_like of {+1, -1}, shape (n,)
        Elbow configuration: +1 puts the elbow left of the directed line
        A_i -> O, -1 to the right.
    fk_branch : {+1, -1}
        Only used when n == 2: the forward-kinematics solution is the circle
        intersection on this side (+1 = left) of the directed line B_1 -> B_2.

    Notes
    -----
    Fields are stored as read-only float arrays (``elbow`` as int), so the
    instance is immutable and hashable.
    """

    bases: np.ndarray
    la: np.ndarray
    lb: np.ndarray
    elbow: np.ndarray
    fk_branch: int = 1

    def __post_init__(self) -> None:
        bases = _readonly(self.bases)
        la = _readonly(self.la)
        lb = _readonly(self.lb)
        elbow = _readonly(self.elbow, dtype=int)
        if bases.ndim != 2 or bases.shape[1] != 2 or bases.shape[0] < 2:
            raise ValueError(f"bases must have shape (n, 2) with n >= 2, got {bases.shape}")
        n = bases.shape[0]
        for name, arr in (("la", la), ("lb", lb), ("elbow", elbow)):
            if arr.shape != (n,):
                raise ValueError(f"{name} must have shape ({n},), got {arr.shape}")
        if np.any(la <= 0) or np.any(lb <= 0):
            raise ValueError(f"link lengths must be positive, got la={la}, lb={lb}")
        if not np.all(np.abs(elbow) == 1):
            raise ValueError(f"elbow entries must be +1 or -1, got {elbow}")
        if self.fk_branch not in (1, -1):
            raise ValueError(f"fk_branch must be +1 or -1, got {self.fk_branch}")
        object.__setattr__(self, "bases", bases)
        object.__setattr__(self, "la", la)
        object.__setattr__(self, "lb", lb)
        object.__setattr__(self, "elbow", elbow)
        object.__setattr__(self, "fk_branch", int(self.fk_branch))

    def _key(self) -> tuple:
        return (
            self.bases.tobytes(),
            self.la.tobytes(),
            self.lb.tobytes(),
            self.elbow.tobytes(),
            self.bases.shape,
            self.fk_branch,
        )

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Geometry):
            return NotImplemented
        return self._key() == other._key()

    def __hash__(self) -> int:
        return hash(self._key())

    @property
    def n(self) -> int:
        """Number of legs."""
        return int(self.bases.shape[0])

    @classmethod
    def of_model(cls, model: Any) -> "Geometry":
        """The geometry of a :class:`pm2dof.Model`. This formulation is of RR legs meeting at a
        point (eqs. 1-13 as the paper writes them): any other mechanism (prismatic legs, a
        platform) raises :class:`~pm2dof.core.errors.UnsupportedMechanismError` saying so."""
        require_rr_point(model, "the Python reference formulation (pm2dof.reference)")
        spec = model.spec
        legs = spec.legs
        return cls(bases=spec.bases, la=[leg.la for leg in legs], lb=[leg.lb for leg in legs],
                   elbow=[leg.elbow for leg in legs], fk_branch=spec.fk_branch)

    @classmethod
    def paper(cls) -> "Geometry":
        """The robot of Shang & Cong (2010), Sect. 2 / Fig. 1.

        Bases (0, 0.25), (0.433, 0), (0.433, 0.5) m; all six links 0.244 m;
        elbows (-1, -1, -1); ``fk_branch`` = +1 (unused for n = 3).
        """
        return cls(
            bases=[[0.0, 0.25], [0.433, 0.0], [0.433, 0.5]],
            la=[0.244, 0.244, 0.244],
            lb=[0.244, 0.244, 0.244],
            elbow=[-1, -1, -1],
            fk_branch=1,
        )


def _geom(g: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, int]:
    """Return (bases (n,2), la (n,), lb (n,), elbow (n,), n) as float arrays."""
    bases = np.asarray(g.bases, dtype=float)
    la = np.asarray(g.la, dtype=float)
    lb = np.asarray(g.lb, dtype=float)
    elbow = np.asarray(g.elbow, dtype=float)
    return bases, la, lb, elbow, bases.shape[0]


def _u(t: np.ndarray) -> np.ndarray:
    """Unit vectors u(t) = (cos t, sin t); shape t.shape + (2,)."""
    t = np.asarray(t, dtype=float)
    return np.stack([np.cos(t), np.sin(t)], axis=-1)


def _up(t: np.ndarray) -> np.ndarray:
    """Derivative du/dt = (-sin t, cos t); shape t.shape + (2,)."""
    t = np.asarray(t, dtype=float)
    return np.stack([-np.sin(t), np.cos(t)], axis=-1)


def _split(g: Any, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    n = np.asarray(g.bases).shape[0]
    q = np.asarray(q, dtype=float)
    if q.shape != (2 * n,):
        raise ValueError(f"q must have shape ({2 * n},), got {q.shape}")
    return q[:n], q[n:]


def _theta(g: Any, theta: np.ndarray) -> tuple[np.ndarray, ...]:
    """Split theta (5n,) into alpha, beta, gamma, fv, fc, each (n,)."""
    n = np.asarray(g.bases).shape[0]
    theta = np.asarray(theta, dtype=float)
    if theta.shape != (5 * n,):
        raise ValueError(f"theta must have shape ({5 * n},), got {theta.shape}")
    return tuple(theta.reshape(5, n))


def _tips(g: Any, q: np.ndarray) -> np.ndarray:
    """Tip positions of all legs, (n, 2), m: A_i + la_i u(qa_i) + lb_i u(qb_i)."""
    bases, la, lb, _, _ = _geom(g)
    qa, qb = _split(g, q)
    return bases + la[:, None] * _u(qa) + lb[:, None] * _u(qb)


def _wrap(a: np.ndarray) -> np.ndarray:
    """Wrap angles to (-pi, pi]."""
    return -np.remainder(-np.asarray(a) + np.pi, 2.0 * np.pi) + np.pi


# --------------------------------------------------------------------------
# Kinematics
# --------------------------------------------------------------------------


def ik(g: Any, xe: np.ndarray) -> np.ndarray:
    """Inverse kinematics: joint angles of every leg for a tip position.

    Parameters
    ----------
    g : Geometry-like
        Object with ``bases`` (n,2), ``la`` (n,), ``lb`` (n,), ``elbow`` (n,).
    xe : array_like, shape (2,)
        Tip (end-effector) position O, m.

    Returns
    -------
    q : ndarray, shape (2n,)
        [qa_1..qa_n, qb_1..qb_n], rad (absolute). qa_i = atan2(O - A_i) +
        elbow_i psi_i with psi_i in [0, pi]; qb_i - qa_i lies in (-pi, pi].

    Raises
    ------
    ValueError
        If some leg cannot reach O (distance outside [|la-lb|, la+lb]); for n == 2, if the
        pose is not in the assembly mode ``g.fk_branch`` (O on the other side of B_1 -> B_2,
        where :func:`fk` cannot return).

    Notes
    -----
    Inverts the tip equation of Sect. 2 / eq. 5 leg by leg (law of cosines).
    """
    bases, la, lb, elbow, n = _geom(g)
    xe = np.asarray(xe, dtype=float).reshape(2)
    d = xe[None, :] - bases  # (n, 2) vectors A_i -> O
    r = np.hypot(d[:, 0], d[:, 1])
    for i in range(n):
        if not (abs(la[i] - lb[i]) <= r[i] <= la[i] + lb[i]) or r[i] == 0.0:
            raise ValueError(
                f"ik: leg {i + 1} cannot reach xe={xe.tolist()}: distance from base "
                f"{r[i]:.6g} m not in [{abs(la[i] - lb[i]):.6g}, {la[i] + lb[i]:.6g}] m"
            )
    # law of cosines: lb^2 = la^2 + r^2 - 2 la r cos(psi)
    cpsi = np.clip((la**2 + r**2 - lb**2) / (2.0 * la * r), -1.0, 1.0)
    psi = np.arccos(cpsi)
    qa = np.arctan2(d[:, 1], d[:, 0]) + elbow * psi
    elb = bases + la[:, None] * _u(qa)  # elbows B_i
    e = xe[None, :] - elb  # B_i -> O, length lb_i
    qb = qa + _wrap(np.arctan2(e[:, 1], e[:, 0]) - qa)
    if n == 2:
        d12 = elb[1] - elb[0]
        side = d12[0] * e[0, 1] - d12[1] * e[0, 0]  # cross(B2 - B1, O - B1)
        if not side * int(getattr(g, "fk_branch", 1)) > 0:
            raise ValueError(f"ik: xe={xe.tolist()} is in the other assembly mode than "
                             f"fk_branch={getattr(g, 'fk_branch', 1)}")
    return np.concatenate([qa, qb])


def fk(g: Any, qa: np.ndarray) -> np.ndarray:
    """Forward kinematics from the active angles only.

    Parameters
    ----------
    g : Geometry-like
        Needs ``bases``, ``la``, ``lb``; and ``fk_branch`` when n == 2.
    qa : array_like, shape (n,)
        Active joint angles, rad.

    Returns
    -------
    xe : ndarray, shape (2,)
        Tip position O, m: the point at distance lb_i from every elbow
        B_i = A_i + la_i u(qa_i).

    Raises
    ------
    ValueError
        n == 2 and the two circles do not intersect; or n >= 3 and the
        elbows are (numerically) collinear so the linear system is singular.

    Notes
    -----
    n >= 3: |O - B_i|^2 = lb_i^2 minus the same for leg 1 gives
    2 (B_i - B_1) . O = |B_i|^2 - |B_1|^2 - lb_i^2 + lb_1^2 (i = 2..n),
    solved by least squares (exact for consistent input; for n = 3 with equal
    lb this is the circumcentre of B_1 B_2 B_3, Sect. 2).
    n == 2: circle-circle intersection on side ``g.fk_branch`` of B_1 -> B_2.
    """
    bases, la, lb, _, n = _geom(g)
    qa = np.asarray(qa, dtype=float)
    if qa.shape != (n,):
        raise ValueError(f"qa must have shape ({n},), got {qa.shape}")
    B = bases + la[:, None] * _u(qa)  # elbows (n, 2)
    if n == 2:
        e = B[1] - B[0]
        dist = float(np.hypot(*e))
        r1, r2 = lb
        if dist == 0.0 or dist > r1 + r2 or dist < abs(r1 - r2):
            raise ValueError(
                f"fk: circles around the elbows do not intersect for qa={qa.tolist()} "
                f"(elbow distance {dist:.6g} m, radii {r1:.6g}, {r2:.6g} m)"
            )
        e = e / dist
        a = (dist**2 + r1**2 - r2**2) / (2.0 * dist)  # along B1->B2
        h = np.sqrt(max(r1**2 - a**2, 0.0))  # perpendicular offset
        left = np.array([-e[1], e[0]])  # left normal of B1 -> B2
        return B[0] + a * e + int(g.fk_branch) * h * left
    # circle-difference linear system (n-1 equations, 2 unknowns)
    Ls = 2.0 * (B[1:] - B[0])
    rhs = np.sum(B[1:] ** 2, axis=1) - np.sum(B[0] ** 2) - lb[1:] ** 2 + lb[0] ** 2
    sol, _, rank, sv = np.linalg.lstsq(Ls, rhs, rcond=None)
    if rank < 2 or sv[-1] <= 1e-12 * max(sv[0], 1e-300):
        raise ValueError(
            f"fk: elbows are collinear for qa={qa.tolist()}; tip is not determined"
        )
    return sol


def closure_residuals(g: Any, qa: np.ndarray, xe: np.ndarray) -> np.ndarray:
    """How far the tip ``xe`` (2,) misses each elbow circle: |O - B_i| - lb_i (n,), m, with
    B_i = A_i + la_i u(qa_i). Zero for consistent active angles; the extra legs of a
    redundant robot make it a check of the encoders."""
    bases, la, lb, _, n = _geom(g)
    B = bases + la[:, None] * _u(np.asarray(qa, dtype=float))
    return np.hypot(*(np.asarray(xe, dtype=float)[None, :] - B).T) - lb


def H(g: Any, q: np.ndarray) -> np.ndarray:
    """Loop-closure constraints, eq. 5.

    Parameters
    ----------
    g : Geometry-like
    q : array_like, shape (2n,)
        Joint angles, rad.

    Returns
    -------
    h : ndarray, shape (2(n-1),)
        [tip_1 - tip_2; tip_1 - tip_3; ...; tip_1 - tip_n], m; zero when closed.
    """
    t = _tips(g, q)
    return (t[0][None, :] - t[1:]).reshape(-1)  # eq. 5


def _tip_jac(g: Any, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per-leg tip Jacobians: d tip_i/d qa_i and d tip_i/d qb_i, each (n, 2)."""
    _, la, lb, _, _ = _geom(g)
    qa, qb = _split(g, q)
    return la[:, None] * _up(qa), lb[:, None] * _up(qb)


def A(g: Any, q: np.ndarray) -> np.ndarray:
    """Constraint Jacobian A = dH/dq, eq. 6 (analytic).

    Parameters
    ----------
    g : Geometry-like
    q : array_like, shape (2n,)

    Returns
    -------
    A : ndarray, shape (2(n-1), 2n)
        Block row k-1 (k = 2..n) is d(tip_1 - tip_k)/dq, m/rad.
    """
    _, _, _, _, n = _geom(g)
    Ja, Jb = _tip_jac(g, q)
    out = np.zeros((2 * (n - 1), 2 * n))
    for k in range(1, n):
        rows = slice(2 * (k - 1), 2 * k)
        # eq. 6: d tip_i/d qa_i = la_i u'(qa_i), d tip_i/d qb_i = lb_i u'(qb_i)
        out[rows, 0] += Ja[0]
        out[rows, n] += Jb[0]
        out[rows, k] -= Ja[k]
        out[rows, n + k] -= Jb[k]
    return out


def _Adot_qd(g: Any, q: np.ndarray, qd: np.ndarray) -> np.ndarray:
    """(dA/dt) qd, shape (2(n-1),): velocity-product terms of d^2 H/dt^2.

    d/dt(la u'(qa)) qda = -la u(qa) qda^2 (same for the passive link), so the
    centripetal part of tip_i's acceleration is c_i = -la_i u(qa_i) qda_i^2
    - lb_i u(qb_i) qdb_i^2 and (Adot qd) block k-1 = c_1 - c_k.
    """
    _, la, lb, _, _ = _geom(g)
    qa, qb = _split(g, q)
    qda, qdb = _split(g, qd)
    c = -(la * qda**2)[:, None] * _u(qa) - (lb * qdb**2)[:, None] * _u(qb)
    return (c[0][None, :] - c[1:]).reshape(-1)


def W(g: Any, q: np.ndarray) -> np.ndarray:
    """Task-to-joint velocity map qd = W xed, eq. 7 (generalised to n legs).

    Parameters
    ----------
    g : Geometry-like
    q : array_like, shape (2n,)
        Closed-chain joint angles, rad.

    Returns
    -------
    W : ndarray, shape (2n, 2), rad/m
        Row i:   u(qb_i)^T / (la_i sin(qb_i - qa_i));
        row n+i: -u(qa_i)^T / (lb_i sin(qb_i - qa_i)).

    Notes
    -----
    From xed = la u'(qa) qda + lb u'(qb) qdb, dot with u(qb) (u(qb).u'(qb)=0,
    u(qb).u'(qa) = sin(qb-qa)) and with u(qa) (u(qa).u'(qb) = -sin(qb-qa)).
    Singular when sin(qb_i - qa_i) = 0 (leg i stretched or folded).
    """
    _, la, lb, _, _ = _geom(g)
    qa, qb = _split(g, q)
    s = np.sin(qb - qa)
    Wa = _u(qb) / (la * s)[:, None]  # eq. 7, active rows
    Wb = -_u(qa) / (lb * s)[:, None]  # eq. 7, passive rows
    return np.vstack([Wa, Wb])


def S(g: Any, q: np.ndarray) -> np.ndarray:
    """Active-joint velocity map qd_a = S xed, eq. 8: first n rows of W.

    Returns
    -------
    S : ndarray, shape (n, 2), rad/m
    """
    _, _, _, _, n = _geom(g)
    return W(g, q)[:n]


def Wdot(g: Any, q: np.ndarray, xed: np.ndarray) -> np.ndarray:
    """Time derivative of W along the motion qd = W(q) xed (used in eq. 9).

    Parameters
    ----------
    g : Geometry-like
    q : array_like, shape (2n,)
        Closed-chain joint angles, rad.
    xed : array_like, shape (2,)
        Tip velocity, m/s.

    Returns
    -------
    Wdot : ndarray, shape (2n, 2), rad/(m s)

    Notes
    -----
    With s = sin(qb-qa), c = cos(qb-qa), d/dt s = c (qdb - qda):
    d/dt [u(qb)/(la s)]  = u'(qb) qdb/(la s) - u(qb) c (qdb-qda)/(la s^2),
    d/dt [-u(qa)/(lb s)] = -u'(qa) qda/(lb s) + u(qa) c (qdb-qda)/(lb s^2).
    """
    _, la, lb, _, n = _geom(g)
    qa, qb = _split(g, q)
    xed = np.asarray(xed, dtype=float).reshape(2)
    qd = W(g, q) @ xed
    qda, qdb = qd[:n], qd[n:]
    s = np.sin(qb - qa)
    c = np.cos(qb - qa)
    sd = c * (qdb - qda)  # d/dt sin(qb - qa)
    Wda = (_up(qb) * (qdb / (la * s))[:, None]
           - _u(qb) * (sd / (la * s**2))[:, None])
    Wdb = (-_up(qa) * (qda / (lb * s))[:, None]
           + _u(qa) * (sd / (lb * s**2))[:, None])
    return np.vstack([Wda, Wdb])


# --------------------------------------------------------------------------
# Dynamics
# --------------------------------------------------------------------------


def M(g: Any, q: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """Open-chain inertia matrix, eqs. 1 and 3.

    Parameters
    ----------
    g : Geometry-like
    q : array_like, shape (2n,)
    theta : array_like, shape (5n,)
        (alpha, beta, gamma, fv, fc), each n entries.

    Returns
    -------
    M : ndarray, shape (2n, 2n), kg m^2
        alpha_i at (i,i), gamma_i at (n+i,n+i), beta_i cos(qa_i-qb_i) at
        (i,n+i) and (n+i,i).
    """
    _, _, _, _, n = _geom(g)
    qa, qb = _split(g, q)
    alpha, beta, gamma, _, _ = _theta(g, theta)
    i = np.arange(n)
    out = np.zeros((2 * n, 2 * n))
    # eq. 1: M_i = [[alpha_i, beta_i c_i], [beta_i c_i, gamma_i]]
    out[i, i] = alpha
    out[n + i, n + i] = gamma
    out[i, n + i] = out[n + i, i] = beta * np.cos(qa - qb)
    return out


def C(g: Any, q: np.ndarray, qd: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """Open-chain Coriolis/centrifugal matrix, eqs. 1 and 3.

    Parameters
    ----------
    g : Geometry-like
    q, qd : array_like, shape (2n,)
        Joint angles (rad) and velocities (rad/s).
    theta : array_like, shape (5n,)

    Returns
    -------
    C : ndarray, shape (2n, 2n), kg m^2/s
        beta_i s_i qd_bi at (i,n+i), -beta_i s_i qd_ai at (n+i,i),
        s_i = sin(qa_i - qb_i).
    """
    _, _, _, _, n = _geom(g)
    qa, qb = _split(g, q)
    qda, qdb = _split(g, qd)
    _, beta, _, _, _ = _theta(g, theta)
    i = np.arange(n)
    s = np.sin(qa - qb)
    out = np.zeros((2 * n, 2 * n))
    # eq. 1: C_i = [[0, beta_i s_i qd_bi], [-beta_i s_i qd_ai, 0]]
    out[i, n + i] = beta * s * qdb
    out[n + i, i] = -beta * s * qda
    return out


def friction(g: Any, qd_a: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """Actuated-joint friction torques, eq. 2.

    Parameters
    ----------
    g : Geometry-like
    qd_a : array_like, shape (n,)
        Active joint velocities, rad/s.
    theta : array_like, shape (5n,)

    Returns
    -------
    f_a : ndarray, shape (n,), N m
        sign(qd_ai) fc_i + fv_i qd_ai, with sign(0) = 0.
    """
    _, _, _, fv, fc = _theta(g, theta)
    qd_a = np.asarray(qd_a, dtype=float)
    sgn = np.sign(qd_a)
    return sgn * fc + fv * qd_a  # eq. 2


def Me(g: Any, q: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """Task-space inertia M_e = W^T M W, eq. 12.

    Returns
    -------
    Me : ndarray, shape (2, 2), kg
    """
    Wq = W(g, q)
    return Wq.T @ M(g, q, theta) @ Wq  # eq. 12


def Ce(g: Any, q: np.ndarray, xed: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """Task-space Coriolis matrix C_e = W^T (M Wdot + C W), eq. 12.

    Parameters
    ----------
    g : Geometry-like
    q : array_like, shape (2n,)
    xed : array_like, shape (2,)
        Tip velocity, m/s; the joint velocities are qd = W xed.
    theta : array_like, shape (5n,)

    Returns
    -------
    Ce : ndarray, shape (2, 2), kg/s
    """
    Wq = W(g, q)
    qd = Wq @ np.asarray(xed, dtype=float).reshape(2)
    return Wq.T @ (M(g, q, theta) @ Wdot(g, q, xed) + C(g, q, qd, theta) @ Wq)  # eq. 12


def task_friction(g: Any, q: np.ndarray, xed: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """Friction mapped to task space, S^T f_a(S xed) (eq. 12).

    Returns
    -------
    f_e : ndarray, shape (2,), N
    """
    Sq = S(g, q)
    return Sq.T @ friction(g, Sq @ np.asarray(xed, dtype=float).reshape(2), theta)


def _Y_expr(g, q, xed, xrd, xrdd, theta) -> np.ndarray:
    """Me xrdd + Ce(q, W xed) xrd + S^T f_a(S xed) (eq. 13's right side)."""
    return (Me(g, q, theta) @ xrdd + Ce(g, q, xed, theta) @ xrd
            + task_friction(g, q, xed, theta))


def Y(g: Any, q: np.ndarray, xed: np.ndarray, xrd: np.ndarray, xrdd: np.ndarray) -> np.ndarray:
    """Regressor of the linear parameterisation, eq. 13.

    Y theta = Me(q) xrdd + Ce(q, qd) xrd + S^T f_a(qd_a), with qd = W xed
    (measured velocity) and xrd, xrdd the reference velocity/acceleration.

    Parameters
    ----------
    g : Geometry-like
    q : array_like, shape (2n,)
    xed : array_like, shape (2,)
        Measured tip velocity, m/s.
    xrd : array_like, shape (2,)
        Reference tip velocity, m/s.
    xrdd : array_like, shape (2,)
        Reference tip acceleration, m/s^2.

    Returns
    -------
    Y : ndarray, shape (2, 5n)
        Columns ordered as theta = (alpha, beta, gamma, fv, fc).

    Notes
    -----
    The expression is linear in theta with no constant term, so column k is
    the expression evaluated at theta = e_k (no hand-typed element formulas).
    """
    _, _, _, _, n = _geom(g)
    xed = np.asarray(xed, dtype=float).reshape(2)
    xrd = np.asarray(xrd, dtype=float).reshape(2)
    xrdd = np.asarray(xrdd, dtype=float).reshape(2)
    eye = np.eye(5 * n)
    return np.column_stack([_Y_expr(g, q, xed, xrd, xrdd, eye[k]) for k in range(5 * n)])


def singularity_measures(g: Any, q: np.ndarray) -> np.ndarray:
    """[type I, type II] singularity measures, by a plain SVD (independent of the C's closed form).

    type I: min_i |sin(qb_i - qa_i)|. type II: the smallest singular value of S (eq. 8) after
    scaling each row to unit length, divided by sqrt(n/2) (its largest possible value, reached
    when the distal directions are isotropic).
    """
    qa, qb = _split(g, q)
    Sq = S(g, q)
    rows = Sq / np.linalg.norm(Sq, axis=1, keepdims=True)
    n = rows.shape[0]
    sv = np.linalg.svd(rows, compute_uv=False)
    return np.array([np.min(np.abs(np.sin(qb - qa))), sv[-1] / np.sqrt(n / 2)])


def forward_dynamics(g: Any, xe: np.ndarray, xed: np.ndarray, tau_a: np.ndarray,
                     theta: np.ndarray) -> np.ndarray:
    """Task-space forward dynamics, eqs. 10-12.

    Solves Me xedd = S^T tau_a - Ce xed - S^T f_a(S xed).

    Parameters
    ----------
    g : Geometry-like
    xe : array_like, shape (2,)
        Tip position, m (the joint angles are ik(g, xe)).
    xed : array_like, shape (2,)
        Tip velocity, m/s.
    tau_a : array_like, shape (n,)
        Actuator torques, N m.
    theta : array_like, shape (5n,)

    Returns
    -------
    xedd : ndarray, shape (2,), m/s^2
    """
    q = ik(g, xe)
    xed = np.asarray(xed, dtype=float).reshape(2)
    tau_a = np.asarray(tau_a, dtype=float)
    rhs = S(g, q).T @ tau_a - Ce(g, q, xed, theta) @ xed - task_friction(g, q, xed, theta)
    return np.linalg.solve(Me(g, q, theta), rhs)  # eq. 12


def forward_dynamics_joint(g: Any, xe: np.ndarray, xed: np.ndarray, tau_a: np.ndarray,
                           theta: np.ndarray) -> np.ndarray:
    """Joint-space forward dynamics with Lagrange multipliers, eq. 4.

    Solves the KKT system
    [[M, -A^T], [A, 0]] [qdd; lambda] = [tau - f - C qd; -Adot qd]
    with tau = [tau_a; 0], f = [f_a(qd_a); 0], qd = W xed, and returns the
    acceleration of leg 1's tip
    la_1 u'(qa_1) qdd_a1 + lb_1 u'(qb_1) qdd_b1
    - la_1 u(qa_1) qd_a1^2 - lb_1 u(qb_1) qd_b1^2.

    Parameters
    ----------
    g : Geometry-like
    xe : array_like, shape (2,)
        Tip position, m.
    xed : array_like, shape (2,)
        Tip velocity, m/s.
    tau_a : array_like, shape (n,)
        Actuator torques, N m.
    theta : array_like, shape (5n,)

    Returns
    -------
    xedd : ndarray, shape (2,), m/s^2

    Notes
    -----
    Independent of W-dot / M_e: uses only eqs. 1-6 and the constraint
    acceleration A qdd + Adot qd = 0 (second derivative of eq. 5).
    """
    _, la, lb, _, n = _geom(g)
    q = ik(g, xe)
    xed = np.asarray(xed, dtype=float).reshape(2)
    qd = W(g, q) @ xed
    tau = np.concatenate([np.asarray(tau_a, dtype=float).reshape(n), np.zeros(n)])
    f = np.concatenate([friction(g, qd[:n], theta), np.zeros(n)])
    Mq = M(g, q, theta)
    Aq = A(g, q)
    m = Aq.shape[0]
    K = np.block([[Mq, -Aq.T], [Aq, np.zeros((m, m))]])
    rhs = np.concatenate([tau - f - C(g, q, qd, theta) @ qd, -_Adot_qd(g, q, qd)])  # eq. 4
    # K is (4n-2) x (4n-2): 2n joints, 2(n-1) independent constraints away
    # from singular poses.
    sol = np.linalg.solve(K, rhs)
    qdd = sol[: 2 * n]
    qa, qb = q[0], q[n]
    return (la[0] * _up(qa) * qdd[0] + lb[0] * _up(qb) * qdd[n]
            - la[0] * _u(qa) * qd[0] ** 2 - lb[0] * _u(qb) * qd[n] ** 2)
