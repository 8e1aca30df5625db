# tests/test_reference.py
#
# Tests of pm2dof.reference, the plain-NumPy reference kinematics/dynamics of
# the Shang & Cong (2010) manipulator generalised to n legs.
#
# Every random quantity comes from a numpy Generator with a fixed seed.  Poses
# are sampled in the paper's workspace (x in [0.17, 0.32], y in [0.18, 0.34] m)
# and kept only if min_i |sin(qb_i - qa_i)| > 0.2 (away from leg singularities,
# so |W| <~ 1/(0.2 * 0.2 m) = 25 rad/m and every derivative is well scaled).
#
# Tolerance rationale (used below):
# * Closed-form kinematics (ik, fk, H): a handful of flops on O(0.5 m)
#   numbers -> errors ~ 1e-16..1e-15 m; 1e-12 m leaves a 1000x margin.
# * Central finite differences with step h = 1e-6 (m or s): truncation
#   ~ h^2 |f'''| / 6 and round-off ~ eps |f| / h ~ 1e-10 |f|; for the
#   well-conditioned poses used here the observed relative error is ~1e-9 or
#   smaller, so FD comparisons use rtol = 1e-6 relative to the matrix norm.
# * Algebraic identities evaluated in floating point (A W = 0, skew-symmetry,
#   Y theta = expression, two forward-dynamics solvers): O(10) flops on
#   numbers bounded by ~1e3 -> ~1e-12 relative; asserted at 1e-9 relative.

from __future__ import annotations

import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

try:
    from pm2dof.reference import model as ref
except ImportError:  # running pytest without the project root on sys.path
    sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
    from pm2dof.reference import model as ref

# --------------------------------------------------------------------------
# Fixtures: geometries, poses, parameters
# --------------------------------------------------------------------------

PAPER = ref.Geometry.paper()
UNEQUAL = ref.Geometry(
    bases=[[0.0, 0.25], [0.433, 0.0], [0.433, 0.5]],
    la=[0.20, 0.26, 0.23],
    lb=[0.29, 0.25, 0.27],
    elbow=[-1, 1, -1],
)
FOUR_LEG = ref.Geometry(
    bases=[[0.0, 0.25], [0.433, 0.0], [0.433, 0.5], [0.2, 0.6]],
    la=[0.244, 0.244, 0.244, 0.26],
    lb=[0.244, 0.244, 0.244, 0.23],
    elbow=[-1, -1, -1, 1],
)
# Legs 1 and 2 of the paper robot: a non-redundant five-bar.  Over the sampled
# workspace the tip lies left of B_1 -> B_2 (checked in test_fk_branch_side).
FIVE_BAR = ref.Geometry(
    bases=[[0.0, 0.25], [0.433, 0.0]],
    la=[0.244, 0.244],
    lb=[0.244, 0.244],
    elbow=[-1, -1],
    fk_branch=1,
)

GEOMS = {"paper": PAPER, "unequal": UNEQUAL, "four_leg": FOUR_LEG, "five_bar": FIVE_BAR}
geoms = pytest.mark.parametrize("g", list(GEOMS.values()), ids=list(GEOMS))

N_POSES = 12
H_FD = 1e-6  # central finite-difference step (m for positions, s for time)
FD_RTOL = 1e-6  # see header: FD error ~1e-9 relative, 1000x margin
ALG_RTOL = 1e-9  # see header: algebraic identities, ~1e-12 expected


def _cross(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def sample_poses(g, seed, k=N_POSES):
    """k reachable tip positions with min |sin(qb - qa)| > 0.2."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(50 * k):
        xe = np.array([rng.uniform(0.17, 0.32), rng.uniform(0.18, 0.34)])
        try:
            q = ref.ik(g, xe)
        except ValueError:
            continue
        n = len(g.la)
        if np.min(np.abs(np.sin(q[n:] - q[:n]))) > 0.2:
            out.append(xe)
        if len(out) == k:
            return out
    raise AssertionError(f"only {len(out)} admissible poses found for {g}")


def random_theta(rng, n):
    """Physically valid parameters: each leg's 2x2 inertia block is SPD."""
    alpha = rng.uniform(0.01, 0.1, n)
    gamma = rng.uniform(0.005, 0.05, n)
    beta = rng.uniform(-0.9, 0.9, n) * np.sqrt(alpha * gamma)
    fv = rng.uniform(0.0, 3.0, n)
    fc = rng.uniform(0.0, 0.5, n)
    return np.concatenate([alpha, beta, gamma, fv, fc])


def cases(g, seed):
    """(xe, xed, xrd, xrdd, theta, tau_a) tuples for dynamics tests."""
    rng = np.random.default_rng(seed + 1000)
    n = len(g.la)
    for xe in sample_poses(g, seed):
        yield (
            xe,
            rng.uniform(-0.5, 0.5, 2),
            rng.uniform(-0.5, 0.5, 2),
            rng.uniform(-5.0, 5.0, 2),
            random_theta(rng, n),
            rng.uniform(-5.0, 5.0, n),
        )


def wrap(a):
    return np.angle(np.exp(1j * np.asarray(a)))


def assert_close(actual, desired, rtol, what, info):
    """|actual - desired| <= rtol * max(1, |desired|) (max-norm)."""
    actual, desired = np.asarray(actual), np.asarray(desired)
    err = np.max(np.abs(actual - desired))
    scale = max(1.0, np.max(np.abs(desired)))
    assert err <= rtol * scale, (
        f"{what}: max error {err:.3e} > {rtol:.1e} * {scale:.3e} for {info}\n"
        f"actual=\n{actual}\ndesired=\n{desired}"
    )


# --------------------------------------------------------------------------
# Geometry
# --------------------------------------------------------------------------


def test_paper_geometry_values():
    g = ref.Geometry.paper()
    np.testing.assert_array_equal(g.bases, [[0.0, 0.25], [0.433, 0.0], [0.433, 0.5]])
    np.testing.assert_array_equal(g.la, [0.244] * 3)
    np.testing.assert_array_equal(g.lb, [0.244] * 3)
    np.testing.assert_array_equal(g.elbow, [-1, -1, -1])
    assert g.fk_branch == 1 and g.n == 3


def test_geometry_is_immutable_and_hashable():
    g = ref.Geometry.paper()
    import dataclasses
    with pytest.raises(dataclasses.FrozenInstanceError):
        g.la = np.ones(3)  # frozen dataclass
    with pytest.raises(ValueError):
        g.la[0] = 1.0  # read-only array
    assert g == ref.Geometry.paper() and hash(g) == hash(ref.Geometry.paper())
    assert g != UNEQUAL


@pytest.mark.parametrize(
    "kwargs",
    [
        dict(bases=[[0, 0], [1, 0]], la=[1, 1, 1], lb=[1, 1], elbow=[1, 1]),
        dict(bases=[[0, 0], [1, 0]], la=[1, -1], lb=[1, 1], elbow=[1, 1]),
        dict(bases=[[0, 0], [1, 0]], la=[1, 1], lb=[1, 1], elbow=[1, 0]),
        dict(bases=[[0, 0], [1, 0]], la=[1, 1], lb=[1, 1], elbow=[1, 1], fk_branch=0),
    ],
)
def test_geometry_validation(kwargs):
    with pytest.raises(ValueError):
        ref.Geometry(**kwargs)


def test_duck_typed_geometry():
    """Any object with the right attributes (lists here) works like Geometry."""
    duck = SimpleNamespace(
        bases=[[0.0, 0.25], [0.433, 0.0], [0.433, 0.5]],
        la=[0.244] * 3,
        lb=[0.244] * 3,
        elbow=[-1, -1, -1],
        fk_branch=1,
    )
    xe = np.array([0.25, 0.26])
    np.testing.assert_array_equal(ref.ik(duck, xe), ref.ik(PAPER, xe))
    np.testing.assert_array_equal(ref.W(duck, ref.ik(duck, xe)), ref.W(PAPER, ref.ik(PAPER, xe)))


# --------------------------------------------------------------------------
# Kinematics
# --------------------------------------------------------------------------


@geoms
def test_ik_closes_loop_and_reaches_tip(g):
    n = len(g.la)
    for xe in sample_poses(g, 1):
        q = ref.ik(g, xe)
        assert q.shape == (2 * n,)
        h = ref.H(g, q)
        assert h.shape == (2 * (n - 1),)
        assert np.max(np.abs(h)) < 1e-12, f"H(ik({xe})) = {h}"
        tips = ref._tips(g, q)
        assert np.max(np.abs(tips - xe)) < 1e-12, f"tips {tips} != {xe}"


@geoms
def test_ik_elbow_side(g):
    """elbow=+1 puts B_i left of A_i -> O, -1 right (sign of the 2-D cross)."""
    n = len(g.la)
    for xe in sample_poses(g, 2):
        q = ref.ik(g, xe)
        B = g.bases + g.la[:, None] * np.stack([np.cos(q[:n]), np.sin(q[:n])], axis=1)
        side = np.sign(_cross(xe - g.bases, B - g.bases))
        np.testing.assert_array_equal(side, g.elbow, err_msg=f"xe={xe}, q={q}")


@geoms
def test_fk_inverts_ik(g):
    n = len(g.la)
    for xe in sample_poses(g, 3):
        q = ref.ik(g, xe)
        x2 = ref.fk(g, q[:n])
        assert x2.shape == (2,)
        assert np.max(np.abs(x2 - xe)) < 1e-12, f"fk(ik({xe})) = {x2}"


def test_fk_branch_side():
    """Five-bar: the sampled workspace is on branch +1, and branch -1 is the
    other (distinct) circle intersection."""
    g = FIVE_BAR
    other = ref.Geometry(g.bases, g.la, g.lb, g.elbow, fk_branch=-1)
    for xe in sample_poses(g, 4):
        qa = ref.ik(g, xe)[:2]
        B = g.bases + g.la[:, None] * np.stack([np.cos(qa), np.sin(qa)], axis=1)
        assert _cross(B[1] - B[0], xe - B[0]) > 0, f"tip right of B1->B2 at {xe}"
        x_other = ref.fk(other, qa)
        np.testing.assert_allclose(np.linalg.norm(x_other - B, axis=1), g.lb, atol=1e-12)
        assert _cross(B[1] - B[0], x_other - B[0]) < 0
        assert np.linalg.norm(x_other - xe) > 1e-3, f"branches coincide at {xe}"


def test_ik_unreachable_raises():
    with pytest.raises(ValueError, match=r"leg 1 .*distance"):
        ref.ik(PAPER, np.array([0.6, 0.25]))  # 0.6 m from A_1, reach 0.488 m
    with pytest.raises(ValueError, match=r"leg 2 "):
        ref.ik(PAPER, np.array([0.3, 0.55]))  # legs 1, 3 reach; 0.566 m from A_2


def test_fk_degenerate_raises():
    # n == 2: elbows 3 m apart, radii 1 m -> no intersection
    g2 = ref.Geometry(bases=[[0, 0], [3, 0]], la=[0.5, 0.5], lb=[1, 1], elbow=[1, 1])
    with pytest.raises(ValueError, match="do not intersect"):
        ref.fk(g2, np.array([np.pi, 0.0]))  # elbows 4 m apart
    # n == 3: collinear elbows -> tip undetermined
    g3 = ref.Geometry(bases=[[0, 0], [1, 0], [2, 0]], la=[1, 1, 1], lb=[1, 1, 1], elbow=[1, 1, 1])
    with pytest.raises(ValueError, match="collinear"):
        ref.fk(g3, np.full(3, np.pi / 2))


@geoms
def test_A_matches_fd_of_H(g):
    """Analytic eq. 6 vs central FD of eq. 5 at arbitrary (not closed) q."""
    rng = np.random.default_rng(5)
    n = len(g.la)
    for _ in range(N_POSES):
        q = rng.uniform(-np.pi, np.pi, 2 * n)
        Aq = ref.A(g, q)
        assert Aq.shape == (2 * (n - 1), 2 * n)
        fd = np.column_stack([
            (ref.H(g, q + H_FD * e) - ref.H(g, q - H_FD * e)) / (2 * H_FD) for e in np.eye(2 * n)
        ])
        assert_close(Aq, fd, FD_RTOL, "A vs FD", f"q={q}")


@geoms
def test_W_matches_fd_of_ik(g):
    for xe in sample_poses(g, 6):
        q = ref.ik(g, xe)
        Wq = ref.W(g, q)
        fd = np.column_stack([
            wrap(ref.ik(g, xe + H_FD * e) - ref.ik(g, xe - H_FD * e)) / (2 * H_FD)
            for e in np.eye(2)
        ])
        assert_close(Wq, fd, FD_RTOL, "W vs FD of ik", f"xe={xe}")
        np.testing.assert_array_equal(ref.S(g, q), Wq[: len(g.la)])


@geoms
def test_W_reproduces_tip_velocity_and_AW_zero(g):
    """Derivation check of eq. 7: with qd = W xed every leg's tip moves with
    xed, and the constraint velocity A W xed vanishes."""
    rng = np.random.default_rng(7)
    n = len(g.la)
    for xe in sample_poses(g, 7):
        q = ref.ik(g, xe)
        xed = rng.uniform(-1, 1, 2)
        qd = ref.W(g, q) @ xed
        qa, qb = q[:n], q[n:]
        tipvel = (g.la[:, None] * np.stack([-np.sin(qa), np.cos(qa)], 1) * qd[:n, None]
                  + g.lb[:, None] * np.stack([-np.sin(qb), np.cos(qb)], 1) * qd[n:, None])
        assert_close(tipvel, np.broadcast_to(xed, (n, 2)), ALG_RTOL, "tip velocity", f"xe={xe}")
        AW = ref.A(g, q) @ ref.W(g, q)
        assert np.max(np.abs(AW)) < 1e-12 * max(1.0, np.max(np.abs(ref.W(g, q)))), (
            f"A W != 0 at xe={xe}: {AW}")


@geoms
def test_Wdot_matches_fd_along_motion(g):
    rng = np.random.default_rng(8)
    for xe in sample_poses(g, 8):
        xed = rng.uniform(-0.5, 0.5, 2)
        Wd = ref.Wdot(g, ref.ik(g, xe), xed)
        fd = (ref.W(g, ref.ik(g, xe + H_FD * xed)) - ref.W(g, ref.ik(g, xe - H_FD * xed))) / (2 * H_FD)
        assert_close(Wd, fd, FD_RTOL, "Wdot vs FD", f"xe={xe}, xed={xed}")


@geoms
def test_Adot_qd_matches_fd(g):
    """Helper used by forward_dynamics_joint: (d/dt A) qd along q + t qd."""
    rng = np.random.default_rng(9)
    n = len(g.la)
    for _ in range(N_POSES):
        q = rng.uniform(-np.pi, np.pi, 2 * n)
        qd = rng.uniform(-3, 3, 2 * n)
        fd = (ref.A(g, q + H_FD * qd) - ref.A(g, q - H_FD * qd)) @ qd / (2 * H_FD)
        assert_close(ref._Adot_qd(g, q, qd), fd, FD_RTOL, "Adot qd vs FD", f"q={q}, qd={qd}")


# --------------------------------------------------------------------------
# Dynamics
# --------------------------------------------------------------------------


def test_M_C_layout_paper():
    """Eq. 1/3 block placement for the paper robot with Table 1 values."""
    g = PAPER
    theta = np.array([0.0932, 0.0427, 0.0427, 0.0381, 0.0085, 0.0085,
                      0.0426, 0.0111, 0.0111, 2.9936, 2.7617, 2.8771,
                      0.4976, 0.4570, 0.3006])
    q = ref.ik(g, np.array([0.22, 0.29]))
    qd = np.arange(1.0, 7.0)
    Mq, Cq = ref.M(g, q, theta), ref.C(g, q, qd, theta)
    for i in range(3):
        c, s = np.cos(q[i] - q[3 + i]), np.sin(q[i] - q[3 + i])
        blk_M = Mq[np.ix_([i, 3 + i], [i, 3 + i])]
        blk_C = Cq[np.ix_([i, 3 + i], [i, 3 + i])]
        np.testing.assert_allclose(blk_M, [[theta[i], theta[3 + i] * c], [theta[3 + i] * c, theta[6 + i]]], rtol=1e-15)
        np.testing.assert_allclose(blk_C, [[0, theta[3 + i] * s * qd[3 + i]], [-theta[3 + i] * s * qd[i], 0]], rtol=1e-15)
    # nothing outside the leg blocks (legs are dynamically decoupled in eq. 3)
    mask = np.ones((6, 6), bool)
    for i in range(3):
        mask[np.ix_([i, 3 + i], [i, 3 + i])] = False
    assert not np.any(Mq[mask]) and not np.any(Cq[mask])


@geoms
def test_joint_space_Mdot_minus_2C_skew(g):
    rng = np.random.default_rng(10)
    n = len(g.la)
    for _ in range(N_POSES):
        q = rng.uniform(-np.pi, np.pi, 2 * n)
        qd = rng.uniform(-3, 3, 2 * n)
        th = random_theta(rng, n)
        Md = (ref.M(g, q + H_FD * qd, th) - ref.M(g, q - H_FD * qd, th)) / (2 * H_FD)
        N = Md - 2 * ref.C(g, q, qd, th)
        assert np.max(np.abs(N + N.T)) < FD_RTOL * max(1.0, np.max(np.abs(N))), f"q={q}, qd={qd}"


def test_friction_eq2():
    n = 3
    theta = np.concatenate([np.zeros(9), [1.0, 2.0, 3.0], [0.5, 0.25, 0.125]])
    f = ref.friction(PAPER, np.array([2.0, -1.0, 0.0]), theta)
    # sign(0) = 0 -> third entry has no Coulomb term
    np.testing.assert_allclose(f, [0.5 + 2.0, -0.25 - 2.0, 0.0], rtol=0, atol=1e-15)
    assert f.shape == (n,)


@geoms
def test_Me_symmetric_positive_definite(g):
    rng = np.random.default_rng(11)
    for xe in sample_poses(g, 11):
        th = random_theta(rng, len(g.la))
        Mq = ref.Me(g, ref.ik(g, xe), th)
        assert Mq.shape == (2, 2)
        assert abs(Mq[0, 1] - Mq[1, 0]) <= ALG_RTOL * np.max(np.abs(Mq)), f"xe={xe}: {Mq}"
        ev = np.linalg.eigvalsh(Mq)
        assert ev.min() > 0, f"Me not PD at xe={xe}, theta={th}: eig {ev}"


@geoms
def test_Medot_minus_2Ce_skew(g):
    for xe, xed, _, _, th, _ in cases(g, 12):
        q = ref.ik(g, xe)
        Med = (ref.Me(g, ref.ik(g, xe + H_FD * xed), th)
               - ref.Me(g, ref.ik(g, xe - H_FD * xed), th)) / (2 * H_FD)
        Nm = Med - 2 * ref.Ce(g, q, xed, th)
        scale = max(1.0, np.max(np.abs(Med)), np.max(np.abs(ref.Ce(g, q, xed, th))))
        assert np.max(np.abs(Nm + Nm.T)) < FD_RTOL * scale, f"xe={xe}, xed={xed}: N={Nm}"
        # and it is not trivially zero (the check has teeth)
        assert np.max(np.abs(Nm)) > 0


@geoms
def test_Y_times_theta_equals_expression(g):
    n = len(g.la)
    for xe, xed, xrd, xrdd, th, _ in cases(g, 13):
        q = ref.ik(g, xe)
        Yq = ref.Y(g, q, xed, xrd, xrdd)
        assert Yq.shape == (2, 5 * n)
        expected = (ref.Me(g, q, th) @ xrdd + ref.Ce(g, q, xed, th) @ xrd
                    + ref.S(g, q).T @ ref.friction(g, ref.S(g, q) @ xed, th))
        assert_close(Yq @ th, expected, ALG_RTOL, "Y theta", f"xe={xe}, xed={xed}, theta={th}")
        # task_friction is the same friction term
        assert_close(ref.task_friction(g, q, xed, th),
                     ref.S(g, q).T @ ref.friction(g, ref.S(g, q) @ xed, th),
                     ALG_RTOL, "task_friction", f"xe={xe}")


def test_Y_friction_columns_paper():
    """The fc columns of Y are S^T sign(S xed) e_i (sign(0) = 0) and the fv
    columns S^T (S xed)_i e_i; independent of the reference signals."""
    g = PAPER
    q = ref.ik(g, np.array([0.25, 0.25]))
    Sq = ref.S(g, q)
    xed = np.array([0.1, -0.2])
    Yq = ref.Y(g, q, xed, np.array([1.0, 2.0]), np.array([3.0, 4.0]))
    qda = Sq @ xed
    np.testing.assert_allclose(Yq[:, 9:12], Sq.T * qda, rtol=1e-12)
    np.testing.assert_allclose(Yq[:, 12:15], Sq.T * np.sign(qda), rtol=1e-12)
    assert np.all(qda != 0.0)
    # at rest no fc column (sign(0) = 0): the whole row is zero with zero reference signals
    Y0 = ref.Y(g, q, np.zeros(2), np.zeros(2), np.zeros(2))
    assert not np.any(Y0)


@geoms
def test_forward_dynamics_task_equals_joint(g):
    for xe, xed, _, _, th, tau in cases(g, 14):
        a_task = ref.forward_dynamics(g, xe, xed, tau, th)
        a_joint = ref.forward_dynamics_joint(g, xe, xed, tau, th)
        assert a_task.shape == (2,) and a_joint.shape == (2,)
        assert_close(a_task, a_joint, ALG_RTOL, "task vs joint forward dynamics",
                     f"xe={xe}, xed={xed}, tau={tau}, theta={th}")


@geoms
def test_forward_dynamics_inverts_regressor(g):
    """With xrd = xed and xrdd = xedd, Y theta must equal S^T tau_a (eq. 12/13)."""
    for xe, xed, _, _, th, tau in cases(g, 15):
        q = ref.ik(g, xe)
        xedd = ref.forward_dynamics(g, xe, xed, tau, th)
        lhs = ref.Y(g, q, xed, xed, xedd) @ th
        assert_close(lhs, ref.S(g, q).T @ tau, ALG_RTOL, "Y theta vs S^T tau",
                     f"xe={xe}, xed={xed}, tau={tau}")


def test_forward_dynamics_joint_torque_balance_paper():
    """Joint-space solution satisfies eq. 4 leg by leg: the passive joints get
    only constraint forces, and the accelerations are consistent with every
    leg's tip (not just leg 1)."""
    g = PAPER
    n = 3
    rng = np.random.default_rng(16)
    for xe in sample_poses(g, 16, k=5):
        xed = rng.uniform(-0.5, 0.5, 2)
        th = random_theta(rng, n)
        tau = rng.uniform(-5, 5, n)
        xedd = ref.forward_dynamics_joint(g, xe, xed, tau, th)
        # reconstruct qdd from the task solution (eq. 9) and check each tip
        q = ref.ik(g, xe)
        qd = ref.W(g, q) @ xed
        qdd = ref.Wdot(g, q, xed) @ xed + ref.W(g, q) @ xedd
        qa, qb = q[:n], q[n:]
        acc = (g.la[:, None] * (np.stack([-np.sin(qa), np.cos(qa)], 1) * qdd[:n, None]
                                - np.stack([np.cos(qa), np.sin(qa)], 1) * qd[:n, None] ** 2)
               + g.lb[:, None] * (np.stack([-np.sin(qb), np.cos(qb)], 1) * qdd[n:, None]
                                  - np.stack([np.cos(qb), np.sin(qb)], 1) * qd[n:, None] ** 2))
        assert_close(acc, np.broadcast_to(xedd, (n, 2)), ALG_RTOL, "tip accelerations", f"xe={xe}")
