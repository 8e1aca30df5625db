"""The derivation of every mechanism kind against an independent formulation.

The SymPy derivation (pm2dof.derive: Kinematics, Dynamics) is evaluated with lambdify and
compared with tests/mechanisms/independent.py: every body from its own mass, centre of mass and
inertia in z = [qa, qb, xe], loop closures by Lagrange multipliers, NumPy only. The links'
values are random; theta comes from them by the rule of docs/model-file.md, written again in
independent.lumped_theta. Structural checks: W against finite differences of ik, fk(ik(x)),
Me positive definite, Medot - 2 Ce skew-symmetric, energy conserved along the model's own
forward dynamics with torque and friction zero.
"""
import dataclasses
import functools

import casadi as ca
import numpy as np
import pytest
import sympy as sp

from pm2dof.core.mechanism import theta_groups
from pm2dof.core.model_file import Leg, read_model_file
from pm2dof.derive.dynamics import Dynamics
from pm2dof.derive.kinematics import FK_NEWTON_STEPS, Kinematics
from pm2dof.derive.symbols import Symbols
from pm2dof.derive.to_casadi import Converter
from tests import derivations
from tests.mechanisms.independent import Mechanism, lumped_theta, random_links
from tests.mechanisms.models import model_path

pytestmark = pytest.mark.slow     # every mechanism against the Lagrange-multiplier formulation (30 s): make test-slow (CI)

G = (0.0, -9.81)
_lambdify = derivations.plain_lambdify       # sympy.lambdify, the same functions, built faster


def _lambdify_cse(args, expr, modules):
    """:data:`_lambdify` with SymPy's common-subexpression elimination: the same function,
    each repeated subtree evaluated once (a platform's fk Newton step: 12 instead of 730 us a
    call, 0.1 instead of 0.6 s to build)."""
    return _lambdify(args, expr, modules, cse=derivations.cse)


def _with(spec, **changes):
    """``spec`` with other legs or gravity, and theta's names that go with them."""
    spec = dataclasses.replace(spec, **changes)
    groups = theta_groups(spec.legs, spec.end_effector, spec.gravity, spec.friction)
    names = tuple(k if idx is None else f"{k}{i + 1}" for k, idx in groups
                  for i in (idx if idx is not None else [0]))
    return dataclasses.replace(spec, param_names=names)


def _rpr_point(spec):
    legs = (Leg((0.0, 0.0), None, None, None, kind="RPR", stroke=(0.1, 0.6)),
            Leg((0.5, 0.0), None, None, None, kind="RPR", stroke=(0.1, 0.6)),
            Leg((0.25, 0.5), None, None, None, kind="RPR", stroke=(0.1, 0.6)))
    return _with(spec, legs=legs, gravity=G)


def _mixed_platform(spec):
    """One leg of each kind on a platform, with gravity."""
    rrr = read_model_file(model_path("rrr3_platform")).legs[0]
    prr = read_model_file(model_path("prr3_platform")).legs[1]
    rpr = read_model_file(model_path("rpr3_platform")).legs[2]
    return _with(spec, legs=(rrr, prr, rpr), gravity=G)


# name -> (shipped model, change); every kind at a point and on a platform, with and
# without gravity (the derivation of each takes 5-20 s: a case more is a minute more)
CASES = {
    "shang2010": ("shang2010", None),
    "shang2010_vertical": ("shang2010_vertical", None),
    "rrr3_platform": ("rrr3_platform", None),
    "rrr4_platform": ("rrr4_platform", None),
    "prr3_platform_gravity": ("prr3_platform", lambda s: _with(s, gravity=G)),
    "prr_point": ("prr_point", None),
    "prr_point_gravity": ("prr_point", lambda s: _with(s, gravity=(3.0, -9.81))),
    "rpr3_platform_gravity": ("rpr3_platform", lambda s: _with(s, gravity=(2.0, -9.81))),
    "rpr_point_gravity": ("shang2010", _rpr_point),
    "mixed_platform_gravity": ("rrr3_platform", _mixed_platform),
}


def _sgn(v):
    return np.where(np.asarray(v) >= 0, 1.0, -1.0)


class Lambdified:
    """The derivation of one spec, as NumPy functions of (q, xe, xed, xrd, xrdd, tau, theta)."""

    def __init__(self, spec, derivation=None):
        """``derivation``: the model file's Derivation (its sym, kin, dyn), when it is a
        shipped file as read; else Symbols, Kinematics and Dynamics of ``spec`` are built here
        (the same three classes, as Derivation builds them)."""
        self.spec = spec
        if derivation is not None:
            sym, kin, dyn = derivation.sym, derivation.kin, derivation.dyn
            self.sym, self.kin, self.dyn = sym, kin, dyn
        else:
            sym = self.sym = Symbols(spec.n_legs, spec.param_names, spec.task_names)
            self.kin = kin = Kinematics(spec, sym)
            self.dyn = dyn = Dynamics(spec, sym, kin)
        self.n, self.m, self.p = spec.n_legs, sym.m, len(spec.param_names)
        self.args = [list(sym.q), list(sym.xe), list(sym.xed), list(sym.xrd), list(sym.xrdd),
                     list(sym.tau_a), list(sym.theta)]
        f = self._f
        self.ik = _lambdify_cse([list(sym.xe)], kin.ik(), "numpy")
        self.pose = _lambdify_cse([list(sym.q)], kin.pose_from_q(), "numpy")
        self.W = f(kin.W)
        self.Me, self.Ce, self.Ge, self.StF = f(dyn.Me), f(dyn.Ce), f(dyn.Ge), f(dyn.StF)
        self.xedd, self.Y = f(dyn.xedd), f(dyn.Y)
        self.T, self.V = f(sp.Matrix([dyn.kinetic_energy])), f(sp.Matrix([dyn.potential_energy]))
        qa = list(sym.qa)
        if kin.platform:
            self.newton = _lambdify_cse([list(sym.xe), qa], kin.fk_newton_step(), "numpy")
            self.residual = _lambdify_cse([list(sym.xe), qa], kin.closure_residuals(sym.xe),
                                          "numpy")
        else:
            self.fk_point = _lambdify_cse([qa], kin.fk(), "numpy")
            self.residual = _lambdify_cse([list(sym.xe), qa], kin.closure_residuals(sym.xe),
                                          "numpy")

    def _f(self, expr):
        fn = derivations.lambdify(self.args, expr, [{"sgn": _sgn}, "numpy"])
        zeros = {k: np.zeros(v) for k, v in (("m", self.m), ("n", self.n))}

        def call(q, xe, xed=None, xrd=None, xrdd=None, tau=None, theta=None):
            z_m, z_n = zeros["m"], zeros["n"]
            out = fn(q, xe, z_m if xed is None else xed, z_m if xrd is None else xrd,
                     z_m if xrdd is None else xrdd, z_n if tau is None else tau,
                     np.zeros(self.p) if theta is None else theta)
            return np.array(out, dtype=float)
        return call

    def q(self, xe):
        return np.array(self.ik(xe), dtype=float).ravel()

    def fk(self, qa, seed):
        if not self.kin.platform:
            return np.array(self.fk_point(qa), dtype=float).ravel()
        x = np.asarray(seed, float)
        for _ in range(FK_NEWTON_STEPS):
            x = np.array(self.newton(x, qa), dtype=float).ravel()
        return x


@functools.lru_cache(maxsize=None)
def _case(name):
    model, change = CASES[name]
    spec = read_model_file(model_path(model))
    if change is None:     # a shipped file as it is: its derivation, shared (tests/derivations.py)
        return Lambdified(spec, derivations.derivation(spec))
    return Lambdified(change(spec))


def _legs(spec):
    out = []
    for leg in spec.legs:
        d = dict(kind=leg.kind, base=leg.base, la=leg.la, lb=leg.lb, attach=leg.attach)
        if leg.kind == "PRR":
            d["rail_end"] = leg.rail_end
        out.append(d)
    return out


def _home(spec):
    if spec.home is not None:
        return np.array(spec.home)
    t = next(iter(spec.trajectories.values()))
    return np.asarray(t["start"], float)


class Setup:
    """A case with random links, their theta and the independent mechanism."""

    def __init__(self, name, seed=0):
        self.lam = lam = _case(name)
        spec = lam.spec
        self.rng = np.random.default_rng(seed)
        legs = _legs(spec)
        links, plat = random_links(self.rng, legs, lam.kin.platform)
        self.mech = Mechanism(legs, links, plat, spec.gravity)
        th = lumped_theta(legs, links, plat, spec.has_gravity)
        fric = {name: self.rng.uniform(0.1, 1.0) for name in spec.param_names if name not in th}
        self.theta = np.array([th.get(k, fric.get(k)) for k in spec.param_names])
        self.fric = fric

    def state(self, radius=0.02, speed=0.2):
        """A random reachable pose near home, its q, and a task velocity."""
        lam = self.lam
        for _ in range(1000):
            xe = _home(lam.spec) + self.rng.uniform(-radius, radius, lam.m) * (
                [1, 1, 5] if lam.m == 3 else 1)
            with np.errstate(invalid="ignore"):
                q = lam.q(xe)
            if np.all(np.isfinite(q)):
                return xe, q, self.rng.normal(0, speed, lam.m)
        raise AssertionError("no reachable pose near home")

    def friction(self, qd_a):
        n = self.lam.n
        fv = np.array([self.fric[f"fv{i + 1}"] for i in range(n)])
        fc = np.array([self.fric[f"fc{i + 1}"] for i in range(n)])
        law = self.lam.spec.friction
        if law == "smooth_sign":            # sign(v) -> v / sqrt(v^2 + eps^2) (docs/model-file.md)
            eps = self.lam.spec.friction_constants["sign_smoothing_velocity"]
            return fc * qd_a / np.sqrt(qd_a**2 + eps**2) + fv * qd_a
        assert law == "coulomb_viscous", law
        return fc * _sgn(qd_a) + fv * qd_a


CASE_NAMES = list(CASES)


@pytest.mark.parametrize("name", CASE_NAMES)
def test_ik_closes_the_loops_and_W_is_its_derivative(name):
    s = Setup(name, seed=1)
    lam = s.lam
    for _ in range(5):
        xe, q, _ = s.state()
        z = np.concatenate([q, xe])
        assert np.abs(s.mech.closure(z)).max() < 1e-12
        np.testing.assert_allclose(np.array(lam.pose(q), float).ravel(), xe, rtol=0, atol=1e-13)
        W = lam.W(q, xe)
        N = s.mech.null_space(z)
        np.testing.assert_allclose(W, N[:2 * lam.n], rtol=1e-10, atol=1e-10 * np.abs(W).max())
        h = 1e-6   # central differences of ik, O(h^2) ~ 1e-12 relative
        fd = np.column_stack([(lam.q(xe + h * e) - lam.q(xe - h * e)) / (2 * h)
                              for e in np.eye(lam.m)])
        np.testing.assert_allclose(W, fd, rtol=1e-6, atol=1e-6 * np.abs(W).max())


@pytest.mark.parametrize("name", CASE_NAMES)
def test_fk_of_ik_round_trips(name):
    s = Setup(name, seed=2)
    lam = s.lam
    for _ in range(5):
        xe, q, _ = s.state()
        qa = q[:lam.n]
        seed = xe + (s.rng.uniform(-0.01, 0.01, lam.m) * ([1, 1, 5] if lam.m == 3 else 1))
        x = lam.fk(qa, seed)
        np.testing.assert_allclose(x, xe, rtol=0, atol=1e-12)
        assert np.abs(np.array(lam.residual(x, qa), dtype=float)).max() < 1e-12


@pytest.mark.parametrize("name", CASE_NAMES)
def test_task_dynamics_match_the_lagrange_multiplier_formulation(name):
    """Me, Ce xed, the gravity term, the forward dynamics and Y theta, at random states."""
    s = Setup(name, seed=3)
    lam, mech, th = s.lam, s.mech, s.theta
    for _ in range(5):
        xe, q, xed = s.state()
        z = np.concatenate([q, xe])
        Me_i, Cx_i, Ge_i, N = mech.task_terms(z, xed)
        Me = lam.Me(q, xe, theta=th)
        scale = np.abs(Me_i).max()
        np.testing.assert_allclose(Me, Me_i, rtol=1e-10, atol=1e-11 * scale)
        Cx = lam.Ce(q, xe, xed, theta=th) @ xed
        np.testing.assert_allclose(Cx, Cx_i, rtol=1e-9, atol=1e-10 * np.abs(Cx_i).max())
        Ge = lam.Ge(q, xe, theta=th).ravel()
        np.testing.assert_allclose(Ge, Ge_i, rtol=1e-10, atol=1e-11 * max(np.abs(Ge_i).max(), 1))
        if not lam.spec.has_gravity:
            assert np.all(Ge == 0)
        # forward dynamics: the KKT system with torques and friction at the actuated joints
        tau = s.rng.normal(0, 2.0, lam.n)
        zd = N @ xed
        fa = s.friction(zd[:lam.n])
        zdd = mech.forward_dynamics(z, zd, tau - fa)
        xedd = lam.xedd(q, xe, xed, tau=tau, theta=th).ravel()
        np.testing.assert_allclose(xedd, zdd[2 * lam.n:], rtol=1e-9,
                                   atol=1e-10 * np.abs(zdd[2 * lam.n:]).max())
        # Y theta = the inverse dynamics Me a + Ce xed + Ge + S^T f at any reference
        a = s.rng.normal(0, 3.0, lam.m)
        S = N[:lam.n]
        u_ind = Me_i @ a + Cx_i + Ge_i + S.T @ fa
        Y = lam.Y(q, xe, xed, xed, a)
        np.testing.assert_allclose(Y @ th, u_ind, rtol=1e-9, atol=1e-10 * np.abs(u_ind).max())


@pytest.mark.parametrize("name", CASE_NAMES)
def test_energies_match_the_bodies(name):
    s = Setup(name, seed=4)
    lam, mech, th = s.lam, s.mech, s.theta
    offsets = []
    for _ in range(5):
        xe, q, xed = s.state()
        z = np.concatenate([q, xe])
        T_i, V_i = mech.energy(z, mech.null_space(z) @ xed)
        T = float(lam.T(q, xe, xed, theta=th).ravel()[0])
        np.testing.assert_allclose(T, T_i, rtol=1e-11)
        offsets.append(float(lam.V(q, xe, theta=th).ravel()[0]) - V_i)
    # V is defined up to a constant: the same at every pose
    assert np.ptp(offsets) < 1e-11 * max(1.0, abs(offsets[0]))


@pytest.mark.parametrize("name", CASE_NAMES)
def test_Me_positive_definite_and_Medot_minus_2Ce_skew(name):
    s = Setup(name, seed=5)
    lam, th = s.lam, s.theta
    for _ in range(5):
        xe, q, xed = s.state()
        Me = lam.Me(q, xe, theta=th)
        assert np.all(np.linalg.eigvalsh((Me + Me.T) / 2) > 0)
        np.testing.assert_allclose(Me, Me.T, rtol=0, atol=1e-13 * np.abs(Me).max())
        # Medot along xe + t xed by 4th-order central differences (error ~ h^4, 1e-12 rel.)
        h = 1e-4

        def Me_at(t):
            x = xe + t * xed
            return lam.Me(lam.q(x), x, theta=th)
        Medot = (8 * (Me_at(h) - Me_at(-h)) - (Me_at(2 * h) - Me_at(-2 * h))) / (12 * h)
        K = Medot - 2 * lam.Ce(q, xe, xed, theta=th)
        scale = np.abs(Medot).max() + 1e-300
        np.testing.assert_allclose(K + K.T, 0, atol=1e-8 * scale)


ENERGY_CASES = ["shang2010_vertical", "rrr3_platform", "rrr4_platform", "prr_point_gravity",
                "rpr3_platform_gravity", "mixed_platform_gravity"]


@pytest.mark.parametrize("name", ENERGY_CASES)
def test_energy_conserved_along_the_forward_dynamics(name):
    """T + V constant along xedd(xe, xed, tau = 0) with friction zero (DOP853, rtol 1e-12)."""
    from scipy.integrate import solve_ivp
    s = Setup(name, seed=6)
    lam, th = s.lam, s.theta.copy()
    th[[k for k, nm in enumerate(lam.spec.param_names) if nm.startswith(("fv", "fc"))]] = 0.0
    xe0, _, xed0 = s.state(radius=0.005, speed=0.05)
    m = lam.m

    def rhs(_, y):
        xe, xed = y[:m], y[m:]
        return np.concatenate([xed, lam.xedd(lam.q(xe), xe, xed, theta=th).ravel()])

    def energy(y):
        xe, xed = y[:m], y[m:]
        q = lam.q(xe)
        return float(lam.T(q, xe, xed, theta=th).ravel()[0] + lam.V(q, xe, theta=th).ravel()[0])
    sol = solve_ivp(rhs, (0.0, 0.05), np.concatenate([xe0, xed0]), method="DOP853", rtol=1e-12,
                    atol=1e-14, dense_output=False)
    assert sol.success
    E = np.array([energy(y) for y in sol.y.T])
    moved = np.abs(sol.y[:m, -1] - xe0).max()
    assert moved > 1e-4                               # the robot did move
    T0 = max(abs(E[0]), float(lam.T(lam.q(xe0), xe0, xed0, theta=th).ravel()[0]))
    assert np.abs(E - E[0]).max() < 1e-9 * max(T0, 1e-3)


PLATFORMS = ["rrr3_platform", "rrr4_platform", "prr3_platform_gravity", "rpr3_platform_gravity"]


@pytest.mark.parametrize("name", PLATFORMS)
def test_platform_fk_converges_from_a_seed_within_5cm_and_0p2rad(name):
    """FK_NEWTON_STEPS Gauss-Newton steps reach rounding from seeds 0.05 m and 0.2 rad away
    (the previous sample is ~1e-3 m away); a seed too far off leaves a closure residual."""
    s = Setup(name, seed=7)
    lam = s.lam
    for _ in range(20):
        xe, q, _ = s.state()
        d = s.rng.normal(size=2)
        seed = xe + np.r_[0.05 * d / np.linalg.norm(d), 0.2 * s.rng.choice([-1, 1])]
        x = lam.fk(q[:lam.n], seed)
        np.testing.assert_allclose(x, xe, rtol=0, atol=1e-12)
    # non-convergence is reported: from far off the residual is far from zero
    xe, q, _ = s.state()
    x = lam.fk(q[:lam.n], xe + np.array([0.3, -0.3, 2.0]))
    with np.errstate(invalid="ignore"):
        res = np.array(lam.residual(x, q[:lam.n]), dtype=float)
    if np.allclose(x, xe, atol=1e-9):
        pytest.skip("the far seed happened to converge")
    assert not np.all(np.abs(res) < 1e-6)


@pytest.mark.parametrize("name", ["shang2010_vertical", "prr_point_gravity", "rpr_point_gravity"])
def test_payload_booked_to_a_leg_is_a_point_mass_at_its_tip(name):
    """payload_increments: theta + the increments is the mechanism with a point mass at the tip
    (Me, Ce xed and the gravity term of the independent formulation)."""
    from pm2dof.core.mechanism import payload_increments
    s = Setup(name, seed=8)
    lam, spec = s.lam, s.lam.spec
    legs = _legs(spec)
    links, _ = random_links(s.rng, legs, False)
    j, mass = 1, 0.7
    mech = Mechanism(legs, links, None, spec.gravity, payload=(j, mass))
    th = lumped_theta(legs, links, None, spec.has_gravity)
    for key, inc in payload_increments(spec.legs[j], spec.end_effector, mass).items():
        if f"{key}{j + 1}" in th:
            th[f"{key}{j + 1}"] += inc
    theta = np.array([th.get(k, 0.0) for k in spec.param_names])
    xe, q, xed = s.state()
    z = np.concatenate([q, xe])
    Me_i, Cx_i, Ge_i, _ = mech.task_terms(z, xed)
    np.testing.assert_allclose(lam.Me(q, xe, theta=theta), Me_i, rtol=1e-10)
    np.testing.assert_allclose(lam.Ce(q, xe, xed, theta=theta) @ xed, Cx_i, rtol=1e-9,
                               atol=1e-12)
    np.testing.assert_allclose(lam.Ge(q, xe, theta=theta).ravel(), Ge_i, rtol=1e-10)


class _DuckModel:
    """What pm2dof.identification.base.identifiability asks of a Model, from the derivation."""

    def __init__(self, lam):
        from pm2dof.core.errors import WorkspaceError
        self.lam, self.spec, self.param_names = lam, lam.spec, lam.spec.param_names
        self._error = WorkspaceError

    def ik(self, xe):
        with np.errstate(invalid="ignore"):
            q = self.lam.q(xe)
        if not np.all(np.isfinite(q)):
            raise self._error("out of reach")
        return q

    def _xe(self, q):
        return np.array(self.lam.pose(q), float).ravel()

    def W(self, q):
        return self.lam.W(q, self._xe(q))

    def Y(self, q, v, vr, ar):
        return self.lam.Y(q, self._xe(q), v, vr, ar)


@pytest.mark.parametrize("name", ["shang2010_vertical", "prr_point_gravity", "rrr3_platform",
                                  "rpr3_platform_gravity"])
def test_base_parameters_identifiable_from_a_simulated_excitation(name):
    """pm2dof.identification.base on the new theta: the base parameters pi = P theta of random
    states' stacked Y are recovered exactly by least squares from the torques Y theta, and
    they reproduce every torque; the null space changes none."""
    from pm2dof.identification.base import _random_states, identifiability, region_center
    s = Setup(name, seed=9)
    model = _DuckModel(s.lam)
    ident = identifiability(model, samples=60, seed=1, radius=0.01)
    base = ident.base
    assert ident.rank == base.r < len(model.param_names)
    # a fresh excitation: torques from the true theta, fit on the independent columns
    states = _random_states(model, 80, np.random.default_rng(2), region_center(model), 0.01)
    Phi = np.vstack([model.Y(*st) for st in states])
    u = Phi @ s.theta
    pi, *_ = np.linalg.lstsq(Phi[:, list(base.independent)], u, rcond=None)
    np.testing.assert_allclose(pi, base.fold(s.theta), rtol=1e-7, atol=1e-9)
    np.testing.assert_allclose(Phi[:, list(base.independent)] @ base.fold(s.theta), u,
                               rtol=1e-9, atol=1e-9 * np.abs(u).max())
    np.testing.assert_allclose(Phi @ ident.null_space, 0, atol=1e-8 * np.abs(Phi).max())
    assert base.inertial.sum() == sum(not n.startswith(("fv", "fc")) for n in base.independent_names)


@pytest.mark.parametrize("name", ["rrr3_platform", "rrr4_platform", "prr3_platform_gravity",
                                  "rpr3_platform_gravity"])
def test_platform_parallel_measure(name):
    """Type II of a platform: (det U^T U)^(1/3) / (n/3) of S's rows (the independent null
    space's), moments over L, rows normalised; in (0, 1] away from singularities."""
    s = Setup(name, seed=11)
    lam, kin = s.lam, s.lam.kin
    f = _lambdify([list(lam.sym.q), list(lam.sym.xe)], kin.parallel_measure(), "numpy",
              cse=derivations.cse)
    L = float(kin.moment_length())
    for _ in range(3):
        xe, q, _ = s.state()
        S = s.mech.null_space(np.concatenate([q, xe]))[:lam.n]
        U = S * np.array([1, 1, 1 / L])          # rows of S, moments over L
        U /= np.linalg.norm(U, axis=1, keepdims=True)
        want = np.linalg.det(U.T @ U) ** (1 / 3) / (lam.n / 3)
        assert 0 < want <= 1
        np.testing.assert_allclose(float(f(q, xe)), want, rtol=1e-10)


def test_platform_parallel_measure_is_zero_where_the_lines_meet():
    """A 3-RPR whose legs all point at the platform's origin (attachments on the bases' rays):
    the three lines meet there, S loses rank, the measure is 0."""
    lam = _case("rpr3_platform_gravity")
    spec = lam.spec
    legs = tuple(dataclasses.replace(leg, attach=(0.05 * leg.base[0] / np.hypot(*leg.base),
                                                  0.05 * leg.base[1] / np.hypot(*leg.base)))
                 for leg in spec.legs)
    radial = _with(spec, legs=legs)
    # its kinematics only (the measure and ik): Lambdified would derive its dynamics too (~6 s)
    sym = Symbols(radial.n_legs, radial.param_names, radial.task_names)
    kin = Kinematics(radial, sym)
    f = _lambdify([list(sym.q), list(sym.xe)], kin.parallel_measure(), "numpy",
              cse=derivations.cse)
    ik = _lambdify([list(sym.xe)], kin.ik(), "numpy")

    def q_of(xe):
        return np.array(ik(xe), dtype=float).ravel()      # as Lambdified.q
    xe = np.zeros(3)
    q = q_of(xe)
    assert abs(float(f(q, xe))) < 1e-5
    assert float(f(q_of(xe + [0, 0, 0.3]), xe + [0, 0, 0.3])) > 0.05


# --- CasADi conversion (in this module: it reuses the cached derivations of _case) ----------
# Every expression the generic derivation hands to CasADi converts (Converter), and
# gives the lambdified value: q's trig from the angular coordinates only (kin.angular), the
# prismatic coordinates as values; the platform's fk step; the energies.


CONVERSION_CASES = ["shang2010_vertical", "prr_point_gravity", "rpr_point_gravity", "rrr3_platform",
         "mixed_platform_gravity"]


@pytest.mark.parametrize("name", CONVERSION_CASES)
def test_expressions_convert_and_agree(name):
    s = Setup(name, seed=10)
    lam, kin, dyn, sym = s.lam, s.lam.kin, s.lam.dyn, s.lam.sym
    xe, q, xed = s.state()
    xrd, xrdd = s.rng.normal(size=lam.m), s.rng.normal(size=lam.m)
    tau = s.rng.normal(size=lam.n)
    values = {**dict(zip(sym.q, q)), **dict(zip(sym.xe, xe)), **dict(zip(sym.xed, xed)),
              **dict(zip(sym.xrd, xrd)), **dict(zip(sym.xrdd, xrdd)),
              **dict(zip(sym.tau_a, tau)), **dict(zip(sym.theta, s.theta)),
              **dict(zip(sym.qd, lam.W(q, xe) @ xed))}
    symbols = {k: ca.SX(float(v)) for k, v in values.items()}
    trig = {sym.q[k]: (ca.SX(np.cos(q[k])), ca.SX(np.sin(q[k])))
            for k in range(2 * lam.n) if kin.angular[k]}
    assert kin.angular == [k == "RRR" for k in kin.kinds] + [True] * lam.n
    conv = Converter(symbols, trig)
    exprs = {"W": kin.W, "Wdot": kin.Wdot, "Me": dyn.Me, "Ce": dyn.Ce, "Ge": dyn.Ge,
             "StF": dyn.StF, "Y": dyn.Y, "xedd": dyn.xedd, "ik": kin.ik(),
             "T": sp.Matrix([dyn.kinetic_energy]), "V": sp.Matrix([dyn.potential_energy]),
             "measures": sp.Matrix([kin.leg_measure(i) for i in range(lam.n)]),
             "lines": kin.wrench_lines(), "pose": kin.pose_from_q(),
             "residual": kin.fk_residual()}
    if kin.platform:
        exprs["newton"] = kin.fk_newton_step()
        exprs["parallel_measure"] = sp.Matrix([kin.parallel_measure()])
    else:
        exprs["fk"] = kin.fk()
    for what, e in exprs.items():
        got = np.array(ca.evalf(conv(e)), dtype=float).ravel()
        want = np.array(_lambdify([], e.xreplace(values), "numpy")(), dtype=float).ravel() \
            if what not in ("StF", "Y", "xedd") else None
        if want is None:   # sgn(): evaluate by lambdify with the same mapping as the tests
            fn = {"StF": lam.StF, "Y": lam.Y, "xedd": lam.xedd}[what]
            want = np.asarray(fn(q, xe, xed, xrd, xrdd, tau, s.theta), float).ravel()
        np.testing.assert_allclose(got, want, rtol=1e-10, atol=1e-12 * max(1, np.abs(want).max()),
                                   err_msg=what)
        # no cos/sin of a prismatic coordinate anywhere
        for f in e.atoms(sp.cos, sp.sin):
            for k in range(2 * lam.n):
                if not kin.angular[k]:
                    assert sym.q[k] not in f.free_symbols, (what, f)
