# The generated path dynamics against independent formulations: Model's Me/Ce/S/StF, convex hulls,
# the generated min-max split, and a brute-force maximum-velocity curve.
import numpy as np
import pytest
from scipy.spatial import ConvexHull

import pm2dof
from pm2dof.analysis.maps import zonotope_inradius
from pm2dof.core.task import orientation_length
from pm2dof.planning import TaskPath
from pm2dof.planning.problem import PlanProblem
from pm2dof.planning.stages import V_TOP, params, stages
from pm2dof.planning.torques import path_torques

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

PAPER_LINE = ([0.22, 0.29], [0.27, 0.24])


def _coefficients(model, xe, dp, ddp, theta, w):
    """The generated path_coefficients at one point: dict by output name (a, b, g with
    gravity, S, v1, N_min_norm, h_min_norm, N_min_max, h_min_max, sing)."""
    f = model.function("path_coefficients")
    outs = [np.empty(k) for k in f.sizes_out]
    f(np.asarray(xe, float), dp, ddp, theta, w, *outs)
    return dict(zip(f.names_out, outs))


def _facets(n, m):
    """Facet pairs of a generic zonotope of n generators in R^m: n for m = 2, n (n - 1) / 2
    for m = 3 (one per pair of generators); the generated polytopes pad min-norm's n slabs
    (and a 3-RRR's 3) to the larger count."""
    return n if m == 2 else max(n, n * (n - 1) // 2)


def test_coefficients_match_the_model_functions(model, sample_xe, random_theta):
    """a = Me p', b = Me p'' + Ce(q, p') p', g = Ge (eq. 10, present exactly when the model has
    gravity), S, v1 = S p' (eqs. 8, 12) at random poses, directions (m = model.dof: a
    platform's p' has a phi row), curvatures and parameters."""
    rng = np.random.default_rng(20)
    n, m = model.n_legs, model.dof
    gravity = model.spec.has_gravity
    for xe in sample_xe(model, 21, 5):
        th = random_theta(model, rng)
        dp = rng.normal(size=m)
        dp /= np.linalg.norm(dp)
        ddp = rng.normal(0, 20, m)
        w = rng.uniform(1, 30, n)
        c = _coefficients(model, xe, dp, ddp, th, w)
        q = model.ik(xe)
        Me, Ce, S = model.Me(q, th), model.Ce(q, dp, th), model.S(q)
        assert np.allclose(c["a"], Me @ dp, rtol=1e-12, atol=1e-12 * np.abs(Me).max())
        assert np.allclose(c["b"], Me @ ddp + Ce @ dp, rtol=1e-11,
                           atol=1e-11 * (np.abs(Me).max() * 20 + np.abs(Ce).max()))
        assert ("g" in c) == gravity
        if gravity:
            G = model.Ge(q, th)
            assert np.abs(G).max() > 0.1, G          # the check can fail: gravity is there
            assert np.allclose(c["g"], G, rtol=1e-12, atol=1e-12 * np.abs(G).max())
        assert np.allclose(c["S"].reshape(n, m), S, rtol=1e-13, atol=1e-13)
        assert np.allclose(c["v1"], S @ dp, rtol=1e-12, atol=1e-12 * np.abs(S).max())
        assert np.allclose(c["sing"], model.singularity_measures(q), atol=1e-13)


def test_force_polygons_are_the_splits_feasible_sets(coulomb_viscous_model, sample_xe):
    """min-norm: |N_j u| <= h_j is |(S (S^T S)^-1 u)_j| <= w_j; min-max: the facets of the convex
    hull of the 2^n vertices sum_i +-w_i s_i (scipy's Qhull; a polygon for m = 2, a 3-D
    zonotope for a platform), every hull facet one of ours and each of ours a face of the hull
    (at least m vertices on it), and the least h is the inradius of pm2dof.analysis.maps."""
    model = coulomb_viscous_model
    rng = np.random.default_rng(3)
    n, m = model.n_legs, model.dof
    F = _facets(n, m)
    for xe in sample_xe(model, 5, 4):
        w = rng.uniform(2, 30, n)
        c = _coefficients(model, xe, np.eye(m)[0], np.zeros(m), model.theta_nominal, w)
        S = model.S(model.ik(xe))
        P = S @ np.linalg.inv(S.T @ S)
        N, h = c["N_min_norm"].reshape(F, m), c["h_min_norm"]
        assert np.allclose(N[:n] * (w / h[:n])[:, None], P, rtol=1e-12,
                           atol=1e-12 * np.abs(P).max())
        assert np.array_equal(N[n:], np.repeat(N[:1], F - n, axis=0))     # padding: slab 1
        assert np.array_equal(h[n:], np.repeat(h[:1], F - n))
        N, h = c["N_min_max"].reshape(F, m), c["h_min_max"]
        assert np.allclose(np.linalg.norm(N, axis=1), 1.0, atol=1e-14)
        G = S * w[:, None]
        signs = np.array(np.meshgrid(*[[-1, 1]] * n)).reshape(n, -1).T
        vertices = signs @ G
        hull = ConvexHull(vertices)
        for eq in hull.equations:              # each hull facet is one of ours (up to sign)
            normal, off = eq[:m], -eq[m]
            match = [j for j in range(F) if abs(abs(N[j] @ normal) - 1) < 1e-9]
            assert match and any(abs(h[j] - off) < 1e-9 * off for j in match), (eq, N, h)
        for j in range(F):                     # ... and each of ours is a face of the hull
            assert np.abs(vertices @ N[j]).max() == pytest.approx(h[j], rel=1e-12)
            assert np.sum(np.abs(vertices @ N[j] - h[j]) < 1e-9 * h[j]) >= m, (j, N[j])
        assert h.min() == pytest.approx(zonotope_inradius(G), rel=1e-12)


def test_min_max_polygon_agrees_with_the_generated_split(coulomb_viscous_model, sample_xe):
    """u (m,) is inside the min-max polytope exactly when the generated min-max split needs no
    more than tau_max (its ratio <= 1). u = sum_i t_i w_i s_i, t_i in [-1.5, 1.5]: both sides of
    the boundary in every direction, whatever the units of the task rows (N, N m for phi)."""
    model = coulomb_viscous_model
    rng = np.random.default_rng(4)
    n, m = model.n_legs, model.dof
    F = _facets(n, m)
    for xe in sample_xe(model, 6, 3):
        w = np.full(n, 10.0)
        c = _coefficients(model, xe, np.eye(m)[1], np.zeros(m), model.theta_nominal, w)
        N, h = c["N_min_max"].reshape(F, m), c["h_min_max"]
        q = model.ik(xe)
        G = model.S(q) * w[:, None]
        inside_seen = outside_seen = 0
        for _ in range(40):
            u = G.T @ rng.uniform(-1.5, 1.5, n)
            inside = np.all(np.abs(N @ u) <= h)
            ratio = model.torque_splits(q, u, tau_max=w)["min_max_ratio"]
            margin = np.min((h - np.abs(N @ u)) / h)
            if abs(margin) > 1e-9:
                assert inside == (ratio <= 1), (u, ratio, margin)
                inside_seen += inside
                outside_seen += not inside
        assert inside_seen and outside_seen      # both sides of the boundary were tested


def _model_arc(model):
    """An arc around the middle of the model file's first move, radius 0.3 of its planar
    length; a platform's phi turns linearly from the move's start to its end along it."""
    mv = next(iter(model.spec.trajectories.values()))
    start, end = np.asarray(mv["start"], float), np.asarray(mv["end"], float)
    c = (start + end) / 2
    r = 0.3 * np.hypot(*(end - start)[:2])
    if model.dof == 2:
        return TaskPath.arc(c, r, 0.1, 2.0)
    return TaskPath.arc(c[:2], r, 0.1, 2.0, phi=(start[2], end[2]),
                        orientation_length=orientation_length(model))


def test_torques_along_a_path_match_inverse_dynamics(model, random_theta):
    """path_torques (planner's C) = Me (p' s_dd + p'' s_d^2) + Ce s_d p' s_d + StF (+ Ge with
    gravity), then each split (torque_splits): pm2dof.planning.torques against the generated
    path_torques, u (K, m) in the model's task space."""
    rng = np.random.default_rng(8)
    path = _model_arc(model)
    assert path.dim == model.dof
    th = random_theta(model, rng)
    w = np.full(model.n_legs, 20.0)
    s = np.linspace(0, path.length, 30)
    prm, th = params(model, th)
    stage, coef = stages(PlanProblem(model, path, w, th, "min_max", prm), s)
    assert coef["S"].shape == (30, model.n_legs, model.dof)
    sd, sdd = rng.uniform(0.01, 1.0, 30), rng.normal(0, 10, 30)
    K, n = len(s), model.n_legs
    outs = (np.empty((K, model.dof)), np.empty((K, n)), np.empty((K, n)), np.empty(K))
    model.function("path_torques").map(K, stage, sd, sdd, prm, w, *outs)
    ref = path_torques(model, path, s, sd, sdd, th, w)
    scale = np.abs(ref["u"]).max()
    assert np.abs(outs[0] - ref["u"]).max() < 1e-10 * scale
    assert np.abs(outs[1] - ref["min_norm"]).max() < 1e-10 * np.abs(ref["min_norm"]).max()
    assert np.abs(outs[2] - ref["min_max"]).max() < 1e-9 * np.abs(ref["min_max"]).max()


def _feasible_at(model, q, a, b, dp, y, w, split, theta):
    """Is some s_dd feasible at speed y? By inverse dynamics and the generated split: the
    torque of the min-max split (a norm of u) is convex in s_dd, so a golden-section search
    finds its least value; min-norm's actuator intervals are intersected exactly."""
    F = model.StF(q, dp * max(y, 1e-12), theta)
    u0 = b * y * y + F
    if model.spec.has_gravity:
        u0 = u0 + model.Ge(q, theta)                    # eq. 10's gravity term
    if split == "min_norm":
        S = model.S(q)
        P = S @ np.linalg.inv(S.T @ S)
        pa, pu = P @ a, P @ u0
        lo, hi = -np.inf, np.inf
        for i in range(len(w)):
            if abs(pa[i]) < 1e-14:
                if abs(pu[i]) > w[i]:
                    return False
                continue
            r = sorted(((-w[i] - pu[i]) / pa[i], (w[i] - pu[i]) / pa[i]))
            lo, hi = max(lo, r[0]), min(hi, r[1])
        return lo <= hi
    ratio = lambda sdd: model.torque_splits(q, a * sdd + u0, tau_max=w)["min_max_ratio"]  # noqa
    lo, hi = -1e4, 1e4
    g = (np.sqrt(5) - 1) / 2
    for _ in range(90):
        m1, m2 = hi - g * (hi - lo), lo + g * (hi - lo)
        if ratio(m1) < ratio(m2):
            hi = m2
        else:
            lo = m1
    return ratio(0.5 * (lo + hi)) <= 1


@pytest.mark.parametrize("split", ["min_norm", "min_max"])
@pytest.mark.parametrize("name", ["shang2010", "shang2010_vertical", "rrr4_platform"])
def test_maximum_velocity_curve_by_brute_force(name, split):
    """The generated maximum-velocity curve against a search over s_d with the model's own
    inverse dynamics (gravity included: the paper's robot upright) and split (friction
    included; a platform's 3-D zonotope), at a few points of an arc."""
    m = pm2dof.load_model(name)
    if m.dof == 2:
        path = TaskPath.arc([0.245, 0.265], 0.03, 0.0, 3.0)
    else:
        path = _model_arc(m)
    w = np.full(m.n_legs, 8.0)
    s = np.linspace(0, path.length, 7)[1:-1]
    prm, th = params(m, None)
    stage, coef = stages(PlanProblem(m, path, w, th, split, prm), s)
    stage[:, m.layout("path_stage").slices["rho"]] = 0.0    # each joint's own Coulomb sign
    x = np.empty(len(s))
    m.function("path_mvc").map(len(s), stage, prm, x)
    for k in range(len(s)):
        q = m.ik(coef["p"][k])
        args = (m, q, coef["a"][k], coef["b"][k], coef["dp"][k])
        lo, hi = 0.0, 2 * np.sqrt(x[k])
        assert _feasible_at(*args, lo, w, split, th) and not _feasible_at(*args, hi, w, split, th)
        for _ in range(40):
            mid = 0.5 * (lo + hi)
            if _feasible_at(*args, mid, w, split, th):
                lo = mid
            else:
                hi = mid
        # closed form for the affine laws (all three models: Coulomb + viscous): exact to the
        # search's resolution; the bisection it replaced was within v_top 2^-20 below
        assert np.sqrt(x[k]) == pytest.approx(lo, abs=1e-9), (k, split)


@pytest.mark.parametrize("split", ["min_norm", "min_max"])
@pytest.mark.parametrize("name", ["shang2010", "shang2010_vertical", "rrr4_platform"])
def test_friction_free_maximum_velocity_curve_is_a_linear_program(name, split):
    """Without friction the stage set is a polygon in (s_dd, x = s_d^2): |N_j . (a s_dd + b x
    (+ g))| <= h_j; the largest x is a linear program (SciPy's HiGHS), which the generated
    closed-form curve matches, at points of an arc and of the bench's spline and shipped
    paths."""
    from scipy.optimize import linprog

    from pm2dof.bench.planning import bench_paths, friction_free
    m = pm2dof.load_model(name)
    if m.dof == 2:
        paths = list(bench_paths(m, TaskPath.arc([0.245, 0.265], 0.03, 0.0, 3.0)).values())
    else:
        paths = [_model_arc(m)]
    w = np.full(m.n_legs, 8.0)
    prm, th = params(m, friction_free(m))
    checked = 0
    for path in paths:
        s = np.linspace(0, path.length, 23)[1:-1]
        stage, coef = stages(PlanProblem(m, path, w, th, split, prm), s)
        x = np.empty(len(s))
        m.function("path_mvc").map(len(s), stage, prm, x)
        for k in range(len(s)):
            N, h = coef["N"][k], coef["h"][k]
            g = coef["g"][k] if "g" in coef else np.zeros(m.dof)
            A = np.column_stack([N @ coef["a"][k], N @ coef["b"][k]])   # (F, 2): s_dd, x
            res = linprog([0.0, -1.0], A_ub=np.vstack([A, -A]),
                          b_ub=np.concatenate([h - N @ g, h + N @ g]),
                          bounds=[(None, None), (0.0, V_TOP ** 2)], method="highs")
            assert res.status == 0, res.message
            assert np.sqrt(x[k]) == pytest.approx(np.sqrt(res.x[1]), rel=1e-8), (k, split)
            checked += 1
    assert checked >= 21


def test_reversing_joint_is_flagged_and_costs_both_signs():
    """A path along which an active joint reverses: its grid interval carries rho = 1, and the
    maximum-velocity curve there is at most the one with either Coulomb sign alone."""
    m = pm2dof.load_model()
    path = TaskPath.arc([0.245, 0.265], 0.04, 0.0, 2 * np.pi - 0.1)
    s = np.linspace(0, path.length, 400)
    prm, th = params(m, None)
    w = np.full(3, 10.0)
    stage, coef = stages(PlanProblem(m, path, w, th, "min_max", prm), s)
    rho = stage[:, m.layout("path_stage").slices["rho"]]
    flips = np.diff(np.sign(coef["v1"]), axis=0) != 0
    assert flips.any(), "no joint reverses on this path"
    assert np.array_equal(rho[:-1].astype(bool), flips)
    k = int(np.argmax(rho.any(axis=1)))
    x = np.empty(3)
    sl = m.layout("path_stage").slices
    one = np.repeat(stage[k:k + 1], 3, axis=0)
    one[1:, sl["rho"]] = 0.0
    v1 = one[2, sl["v1"]]
    v1[rho[k] > 0] *= -1           # the reversing joint's other sign, same magnitude
    m.function("path_mvc").map(3, one, prm, x)
    assert x[0] <= min(x[1], x[2]) + 1e-12
