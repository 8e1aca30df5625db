# An independent formulation of a planar parallel manipulator's dynamics, for the tests only:
# every body (link, slider, cylinder, rod, platform) from its own mass, centre of mass and
# inertia, in the coordinates z = [qa (n), qb (n), xe (m)], closed by Lagrange multipliers.
"""NumPy only: nothing here imports pm2dof.derive.

Each body's centre of mass is a constant plus a sum of terms c(z) u(a(z)), with c and a affine
in z (u(a) = (cos a, sin a)); its angle is affine in z. Then, with zdd = 0, the term's
acceleration is 2 cd ad u'(a) - c ad^2 u(a): the velocity-product acceleration of the body,
from which the Coriolis/centrifugal force follows without differentiating anything
numerically. The loop closures Phi(z) = tip_i(q) - P_i(xe) = 0 use the same terms.

    Mz zdd + h(z, zd) + dV/dz = B (tau - f) + Phi_z^T lam,   Phi_z zdd = -Phi_vp(z, zd)
"""
import numpy as np

__all__ = ["Mechanism", "random_links", "lumped_theta"]


def _u(a):
    return np.array([np.cos(a), np.sin(a)])


def _up(a):
    return np.array([-np.sin(a), np.cos(a)])


class _Term:
    """c(z) u(a(z)) with c = c0 + gc . z and a = a0 + ga . z."""

    def __init__(self, nz, c0=0.0, gc=None, a0=0.0, ga=None):
        self.c0, self.a0 = c0, a0
        self.gc = np.zeros(nz) if gc is None else gc
        self.ga = np.zeros(nz) if ga is None else ga

    def value(self, z):
        return (self.c0 + self.gc @ z) * _u(self.a0 + self.ga @ z)

    def jacobian(self, z):
        c, a = self.c0 + self.gc @ z, self.a0 + self.ga @ z
        return np.outer(_u(a), self.gc) + c * np.outer(_up(a), self.ga)

    def velocity_product(self, z, zd):
        c, a = self.c0 + self.gc @ z, self.a0 + self.ga @ z
        cd, ad = self.gc @ zd, self.ga @ zd
        return 2 * cd * ad * _up(a) - c * ad ** 2 * _u(a)


class _Point:
    """A constant plus a sum of terms: a body's centre of mass, a tip, an attachment point."""

    def __init__(self, const, terms):
        self.const, self.terms = np.asarray(const, float), terms

    def value(self, z):
        return self.const + sum(t.value(z) for t in self.terms)

    def jacobian(self, z):
        return sum(t.jacobian(z) for t in self.terms)

    def velocity_product(self, z, zd):
        return sum(t.velocity_product(z, zd) for t in self.terms)


class Mechanism:
    """A mechanism built from leg descriptions and link values.

    Parameters
    ----------
    legs : list of dict
        ``kind`` ("RRR", "PRR", "RPR"), ``base`` (2,), and per kind: RRR ``la``, ``lb``;
        PRR ``rail_end`` (2,), ``lb``; RPR nothing more. ``attach`` (2,) on a platform.
    links : list of dict
        Per leg, the bodies' values: RRR ``ma, ca, Ia, mb, cb, Ib`` (com distances from the
        body's joint along the link, inertias about the com); PRR ``ms, mb, cb, Ib``; RPR
        ``ma, ca, Ia`` (cylinder, com from the base pivot), ``mb, cb, Ib`` (rod, com cb back
        from the platform's joint).
    platform : dict or None
        ``m, c (2,), I`` (mass, com in the platform frame, inertia about the com).
    gravity : (2,)
    payload : (int, float) or None
        A point mass (kg) at the tip of leg j (0-based).
    """

    def __init__(self, legs, links, platform=None, gravity=(0.0, 0.0), payload=None):
        n = len(legs)
        self.n, self.m = n, 3 if platform is not None else 2
        self.nz = nz = 2 * n + self.m
        self.g = np.asarray(gravity, float)
        e = np.eye(nz)
        ia, ib = [e[i] for i in range(n)], [e[n + i] for i in range(n)]
        ex, ey = e[2 * n], e[2 * n + 1]
        ephi = e[2 * n + 2] if platform is not None else None
        self.bodies = []   # (mass, inertia about com, com _Point, angle gradient)
        self.tips, self.attach = [], []
        for i, (leg, lk) in enumerate(zip(legs, links)):
            A = np.asarray(leg["base"], float)
            if leg["kind"] == "RRR":
                la, lb = leg["la"], leg["lb"]
                self.bodies.append((lk["ma"], lk["Ia"], _Point(A, [_Term(nz, lk["ca"], ga=ia[i])]), ia[i]))
                self.bodies.append((lk["mb"], lk["Ib"], _Point(A, [_Term(nz, la, ga=ia[i]),
                                                                  _Term(nz, lk["cb"], ga=ib[i])]), ib[i]))
                self.tips.append(_Point(A, [_Term(nz, la, ga=ia[i]), _Term(nz, lb, ga=ib[i])]))
            elif leg["kind"] == "PRR":
                d = np.asarray(leg["rail_end"], float) - A
                delta = np.arctan2(d[1], d[0])
                slide = _Term(nz, gc=ia[i], a0=delta)                  # qa d
                self.bodies.append((lk["ms"], 0.0, _Point(A, [slide]), np.zeros(nz)))
                self.bodies.append((lk["mb"], lk["Ib"], _Point(A, [slide, _Term(nz, lk["cb"], ga=ib[i])]),
                                    ib[i]))
                self.tips.append(_Point(A, [slide, _Term(nz, leg["lb"], ga=ib[i])]))
            else:  # RPR: cylinder about the base pivot, rod sliding in it, both at angle qb
                self.bodies.append((lk["ma"], lk["Ia"], _Point(A, [_Term(nz, lk["ca"], ga=ib[i])]), ib[i]))
                self.bodies.append((lk["mb"], lk["Ib"], _Point(A, [_Term(nz, -lk["cb"], gc=ia[i], ga=ib[i])]),
                                    ib[i]))
                self.tips.append(_Point(A, [_Term(nz, gc=ia[i], ga=ib[i])]))
            origin = [_Term(nz, gc=ex), _Term(nz, gc=ey, a0=np.pi / 2)]
            if platform is None:
                self.attach.append(_Point([0.0, 0.0], origin))
            else:
                a = np.asarray(leg["attach"], float)
                self.attach.append(_Point([0.0, 0.0], origin + [
                    _Term(nz, np.hypot(*a), a0=np.arctan2(a[1], a[0]), ga=ephi)]))
        if payload is not None:   # (leg j, mass): a point mass at leg j's tip
            j, mass = payload
            self.bodies.append((mass, 0.0, self.tips[j], np.zeros(nz)))
        if platform is not None:
            c = np.asarray(platform["c"], float)
            com = _Point([0.0, 0.0], [_Term(nz, gc=ex), _Term(nz, gc=ey, a0=np.pi / 2),
                                      _Term(nz, np.hypot(*c), a0=np.arctan2(c[1], c[0]), ga=ephi)])
            self.bodies.append((platform["m"], platform["I"], com, ephi))

    # ---- unconstrained dynamics in z ----

    def mass(self, z):
        Mz = np.zeros((self.nz, self.nz))
        for m, inertia, com, ga in self.bodies:
            J = com.jacobian(z)
            Mz += m * J.T @ J + inertia * np.outer(ga, ga)
        return Mz

    def velocity_forces(self, z, zd):
        """h(z, zd): the Coriolis and centrifugal forces, sum of m J^T (velocity product)."""
        return sum(m * com.jacobian(z).T @ com.velocity_product(z, zd)
                   for m, _, com, _ in self.bodies)

    def gravity_forces(self, z):
        """dV/dz, V = -sum m g . com."""
        return -sum(m * com.jacobian(z).T @ self.g for m, _, com, _ in self.bodies)

    def energy(self, z, zd):
        """(kinetic, potential) energy."""
        T = 0.5 * zd @ self.mass(z) @ zd
        V = -sum(m * self.g @ com.value(z) for m, _, com, _ in self.bodies)
        return T, V

    # ---- loop closures ----

    def closure(self, z):
        return np.concatenate([t.value(z) - p.value(z) for t, p in zip(self.tips, self.attach)])

    def closure_jacobian(self, z):
        return np.vstack([t.jacobian(z) - p.jacobian(z) for t, p in zip(self.tips, self.attach)])

    def closure_velocity_product(self, z, zd):
        return np.concatenate([t.velocity_product(z, zd) - p.velocity_product(z, zd)
                               for t, p in zip(self.tips, self.attach)])

    def null_space(self, z):
        """N (nz, m) with zd = N xed on the constraint: qd = -Phi_q^-1 Phi_x xed."""
        Pz = self.closure_jacobian(z)
        nq = 2 * self.n
        Wq = -np.linalg.solve(Pz[:, :nq], Pz[:, nq:])
        return np.vstack([Wq, np.eye(self.m)])

    def task_terms(self, z, xed):
        """(Me, Ce xed, Ge, N) of the constrained system in the task coordinates."""
        N = self.null_space(z)
        zd = N @ xed
        Pz = self.closure_jacobian(z)
        nq = 2 * self.n
        Ndot_xed = np.concatenate([-np.linalg.solve(Pz[:, :nq],
                                                    self.closure_velocity_product(z, zd)),
                                   np.zeros(self.m)])
        Mz = self.mass(z)
        Me = N.T @ Mz @ N
        Ce_xed = N.T @ (Mz @ Ndot_xed + self.velocity_forces(z, zd))
        Ge = N.T @ self.gravity_forces(z)
        return Me, Ce_xed, Ge, N

    def forward_dynamics(self, z, zd, Q_a):
        """zdd from the KKT system, with generalised forces Q_a on the actuated coordinates."""
        nz, nc = self.nz, 2 * self.n
        Pz = self.closure_jacobian(z)
        K = np.zeros((nz + nc, nz + nc))
        K[:nz, :nz], K[:nz, nz:], K[nz:, :nz] = self.mass(z), -Pz.T, Pz
        Q = np.zeros(nz)
        Q[:self.n] = Q_a
        rhs = np.concatenate([Q - self.velocity_forces(z, zd) - self.gravity_forces(z),
                              -self.closure_velocity_product(z, zd)])
        return np.linalg.solve(K, rhs)[:nz]


def random_links(rng, legs, platform):
    """Random physical values for every body of ``legs`` (and a platform when ``platform``)."""
    out = []
    for leg in legs:
        if leg["kind"] == "RRR":
            out.append(dict(ma=rng.uniform(0.3, 2), ca=rng.uniform(0.2, 0.8) * leg["la"],
                            Ia=rng.uniform(1e-3, 1e-2), mb=rng.uniform(0.2, 1.5),
                            cb=rng.uniform(0.2, 0.8) * leg["lb"], Ib=rng.uniform(1e-3, 1e-2)))
        elif leg["kind"] == "PRR":
            out.append(dict(ms=rng.uniform(0.5, 2), mb=rng.uniform(0.2, 1),
                            cb=rng.uniform(0.2, 0.8) * leg["lb"], Ib=rng.uniform(1e-3, 1e-2)))
        else:
            out.append(dict(ma=rng.uniform(0.5, 2), ca=rng.uniform(0.05, 0.15),
                            Ia=rng.uniform(1e-3, 1e-2), mb=rng.uniform(0.2, 1),
                            cb=rng.uniform(0.05, 0.15), Ib=rng.uniform(1e-4, 1e-3)))
    plat = None
    if platform:
        plat = dict(m=rng.uniform(0.3, 2), c=rng.uniform(-0.02, 0.02, 2), I=rng.uniform(1e-4, 1e-3))
    return out, plat


def lumped_theta(legs, links, platform, gravity_on):
    """theta's inertial entries {name: value} by the rule of docs/model-file.md, written here
    from the links for the tests (not pm2dof's code)."""
    th = {}
    for i, (leg, lk) in enumerate(zip(legs, links), start=1):
        if leg["kind"] == "RRR":
            la = leg["la"]
            th[f"alpha{i}"] = lk["Ia"] + lk["ma"] * lk["ca"] ** 2 + lk["mb"] * la ** 2
            th[f"beta{i}"] = lk["mb"] * la * lk["cb"]
            th[f"gamma{i}"] = lk["Ib"] + lk["mb"] * lk["cb"] ** 2
            if gravity_on:
                th[f"kappa{i}"] = lk["ma"] * lk["ca"] + lk["mb"] * la
        elif leg["kind"] == "PRR":
            th[f"alpha{i}"] = lk["ms"] + lk["mb"]
            th[f"beta{i}"] = lk["mb"] * lk["cb"]
            th[f"gamma{i}"] = lk["Ib"] + lk["mb"] * lk["cb"] ** 2
        else:
            th[f"alpha{i}"] = lk["mb"]
            th[f"beta{i}"] = lk["mb"] * lk["cb"]
            th[f"gamma{i}"] = lk["Ia"] + lk["ma"] * lk["ca"] ** 2 + lk["Ib"] + lk["mb"] * lk["cb"] ** 2
            if gravity_on:
                th[f"kappa{i}"] = lk["ma"] * lk["ca"]
    if platform is not None:
        m, c = platform["m"], platform["c"]
        th.update(m_p=m, mx_p=m * c[0], my_p=m * c[1], I_p=platform["I"] + m * (c @ c))
    return th
