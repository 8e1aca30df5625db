# The design's limits: layout, the kinematic limits' samples, per-sample violations, multipliers.
import numpy as np
import pytest

import pm2dof
from pm2dof.identification.base import base_parameters, region_center
from pm2dof.identification.design import phi_limits, random_start, sample_function
from pm2dof.identification.design_limits import (
    Limits,
    carry_multipliers,
    kinematic_constraints,
    kinematic_samples,
    model_constraints,
    sample_slack,
    sample_violations,
)
from pm2dof.identification.fit import MIN_JOINT_SPEED
from pm2dof.identification.signals import FourierExcitation

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

ca = pytest.importorskip("casadi")


def _setup(name, L=3, f0=0.5):
    model = pm2dof.load_model(name)
    I = list(base_parameters(model).independent)
    per_sample = sample_function(model, I, smooth_sign=MIN_JOINT_SPEED)
    phi = phi_limits(model)
    c0 = region_center(model)
    # tight enough that the random start breaks some (it moves at 30 % of the defaults)
    lim = Limits(0.02, 0.5, 0.001, np.full(model.n_legs, 0.2), np.array([0.2, 0.3]), c0, phi)
    start = random_start(model, base_hz=f0, harmonics=L, periods=1, v_max=0.5, a_max=10.0,
                         radius=0.06, seed=1)
    z0 = np.concatenate([start.a.ravel(), start.b.ravel(), start.center])
    return model, per_sample, lim, z0, start


@pytest.mark.parametrize("name", ["shang2010", "rrr3_platform"])
def test_limits_at_samples_are_the_motion_and_the_model(name):
    """kinematic_constraints and model_constraints at a subset of times: each row is the
    quantity it names, computed here from the series (FourierExcitation.evaluate), the Model's
    singularity measures and the per-sample torque; sample_violations is the worst model row
    per sample, by brute force over the rows."""
    model, per_sample, lim, z0, start = _setup(name)
    L, m, n, f0 = 3, model.dof, model.n_legs, 0.5
    t = np.array([0.0, 0.13, 0.5, 1.31, 1.9])
    z = ca.MX.sym("z", z0.size)
    gk, lbk, ubk = kinematic_constraints(z, lim, base_hz=f0, L=L, m=m, t=t)
    g, lbg, ubg = model_constraints(z, per_sample, lim, base_hz=f0, L=L, m=m, t=t)
    kin = np.array(ca.Function("g", [z], [gk])(z0)).ravel()
    values = np.array(ca.Function("g", [z], [g])(z0)).ravel()
    x, v, a = start.evaluate(t)
    N = len(t)
    want = [np.sum(v[:, :2] ** 2, axis=1), np.sum(a[:, :2] ** 2, axis=1),
            np.sum((x[:, :2] - lim.center[:2]) ** 2, axis=1)]
    if m == 3:
        want += [v[:, 2], a[:, 2], x[:, 2] - lim.center[2]]
    np.testing.assert_allclose(kin, np.concatenate(want), rtol=1e-12, atol=1e-12)
    assert len(kin) == (6 if m == 3 else 3) * N == len(lbk) == len(ubk)
    taus, sings = [], []
    for xk, vk, ak in zip(x, v, a):
        # the torque rows: the per-sample function's min-norm torque (its Coulomb columns
        # smoothed as in the objective; test_identification_design checks it against the C)
        taus.append(np.array(per_sample(xk, vk, ak)[1]).ravel())
        sings.append(model.singularity_measures(model.ik(xk)))
    np.testing.assert_allclose(values, np.concatenate([np.concatenate(taus),
                                                       np.concatenate(sings)]),
                               rtol=1e-12, atol=1e-12)
    rows = [n, 2]
    assert len(values) == sum(rows) * N == len(lbg) == len(ubg)
    np.testing.assert_array_equal(lbg[n * N:], np.tile(lim.sing_min, N))
    # brute force: the worst violation per sample over its rows, wherever they are
    worst, start_row = np.zeros(N), 0
    for r in rows:
        for k in range(N):
            for i in range(r):
                j = start_row + k * r + i
                worst[k] = max(worst[k], lbg[j] - values[j], values[j] - ubg[j], 0.0)
        start_row += r * N
    np.testing.assert_array_equal(sample_violations(values, lbg, ubg, n), worst)
    assert worst.max() > 0                       # the tight test limits are broken somewhere


@pytest.mark.parametrize("L,safety", [(10, 0.98), (4, 0.98),
                                     pytest.param(10, 0.995, marks=pytest.mark.slow),
                                     pytest.param(25, 0.9, marks=pytest.mark.slow)])
def test_kinematic_samples_bound_the_limits_between_samples(L, safety):
    """kinematic_samples: the fewest M with cos(2 pi L / M) >= safety^2, and M samples per
    period bound a squared limit (degree 2 L) within safety^2 of its bound everywhere: random
    series (speed^2 of (x, y)), checked on a grid 50 times finer. M = K without a margin
    (safety 1) or when K samples are too few."""
    K = 1000
    M = kinematic_samples(K, L, safety)
    assert M <= K
    w = 2 * np.pi * np.arange(1, L + 1)                   # period 1 s
    t = np.arange(M) / M
    fine = np.arange(50 * M) / (50 * M)
    # the fewest with the bound's factor within the margin (degree 2 L)
    assert np.cos(2 * np.pi * L / M) >= safety ** 2 > np.cos(2 * np.pi * L / (M - 1))
    rng = np.random.default_rng(3)
    for _ in range(200):
        a, b = rng.normal(size=(2, 2, L)) / np.arange(1, L + 1) ** rng.uniform(0, 2)

        def speed2(tt, a=a, b=b):
            vx, vy = (np.cos(np.outer(tt, w)) @ a[j] + np.sin(np.outer(tt, w)) @ b[j]
                      for j in range(2))
            return vx ** 2 + vy ** 2
        assert speed2(fine).max() <= speed2(t).max() / safety ** 2
    assert kinematic_samples(K, L, 1.0) == K
    # a margin too small for K samples: all K (the limits at the constraint samples, as before)
    assert kinematic_samples(K, 400, 0.98) == K


def test_carried_multipliers_keep_their_samples():
    """carry_multipliers puts each multiplier at its own sample in the new layout (per block,
    sample after sample), zero at the added samples, and drops those of dropped samples."""
    n = 3
    rows = [n, 2]
    seen, now = np.array([0, 4, 8]), np.array([0, 3, 4, 5])
    lam = np.arange(1, sum(rows) * len(seen) + 1, dtype=float)
    out = carry_multipliers(lam, seen, now, n)
    assert len(out) == sum(rows) * len(now)
    old_start, new_start = 0, 0
    for r in rows:
        old = lam[old_start:old_start + r * len(seen)].reshape(len(seen), r)
        new = out[new_start:new_start + r * len(now)].reshape(len(now), r)
        for k, sample in enumerate(now):
            if sample in seen:
                np.testing.assert_array_equal(new[k], old[list(seen).index(sample)])
            else:
                assert not new[k].any()
        old_start += r * len(seen)
        new_start += r * len(now)
    # sample 8's multipliers are gone: the total is that of samples 0 and 4
    kept = sum(lam[s0:s0 + r * 3].reshape(3, r)[:2].sum() for s0, r in
               zip(np.cumsum([0] + [r * 3 for r in rows[:-1]]), rows))
    assert out.sum() == kept


def test_slack_is_the_nearest_bound_over_the_width():
    """sample_slack: per sample the smallest (distance to the nearer bound) / (bound width,
    or |lower bound| without an upper one), negative when broken."""
    n = 1
    # one sample: torque, sing (2); bounds as the design's
    lbg = np.array([-2.0, 0.5, 0.5])
    ubg = np.array([2.0, np.inf, np.inf])
    values = np.array([1.8, 0.6, 3.0])
    want = min(0.2 / 4, 0.1 / 0.5, 2.5 / 0.5)
    assert sample_slack(values, lbg, ubg, n) == pytest.approx([want], rel=1e-15)
    values[1] = 0.4                                     # a singularity measure below its bound
    assert sample_slack(values, lbg, ubg, n) == pytest.approx([-0.2], rel=1e-15)


def test_series_excitation_is_the_design_layout():
    """The layout z = [a (axis after axis), b, c] of the limits is FourierExcitation's a, b, c
    (the design builds its result from z that way)."""
    model, per_sample, lim, z0, start = _setup("shang2010")
    L, m = 3, 2
    exc = FourierExcitation(0.5, 1, z0[2 * m * L:], z0[:m * L].reshape(m, L),
                            z0[m * L:2 * m * L].reshape(m, L))
    t = np.array([0.2, 0.7])
    for got, want in zip(exc.evaluate(t), start.evaluate(t)):
        np.testing.assert_array_equal(got, want)


@pytest.mark.slow      # a whole excitation design (4 s): make test-slow (CI)
def test_design_solves_the_problem_on_every_constraint_sample():
    """A small design whose first solve (every CONSTRAINT_STRIDE-th sample) breaks the torque
    or singularity limits between its samples: IPOPT solves again with the broken samples
    added, and the result keeps those limits at all constraint samples (to IPOPT's constraint
    tolerance; the rest conditions are projected afterwards, which moves the rows by rounding
    only), and the speed, acceleration and region limits (at kinematic_samples) everywhere, on
    a grid 20 times finer than the constraint samples."""
    from pm2dof.identification.design import (
        CONSTRAINT_STRIDE,
        LimitOptions,
        SeriesOptions,
        SolverOptions,
        design_excitation,
    )
    model = pm2dof.load_model("shang2010")
    f0, L, K = 0.5, 4, 200
    lines = []
    exc = design_excitation(model, SeriesOptions(base_hz=f0, harmonics=L, periods=1),
                            LimitOptions(v_max=0.4, a_max=6.0, tau_fraction=0.2),
                            SolverOptions(samples=80, constraint_samples=K),
                            progress=lines.append)
    info = exc.info
    assert info["converged"] and info["constraint_stride"] == CONSTRAINT_STRIDE
    assert info["ipopt_solves"] >= 2, info        # else this test does not test the rounds
    # the last solve saw a subset: the first solve's samples and some of the others
    assert K // CONSTRAINT_STRIDE < info["limit_samples_seen"] < K
    assert sum("break the limits" in ln for ln in lines) == info["ipopt_solves"] - 1, lines
    I = list(base_parameters(model).independent)
    per_sample = sample_function(model, I, smooth_sign=MIN_JOINT_SPEED)
    lim = Limits(0.98 * 0.4, 0.98 * 6.0, 0.98 * 0.06,
                 0.98 * 0.2 * np.asarray(model.spec.limits["tau_max"], float),
                 (np.array([model.singularity_threshold, model.parallel_singularity_threshold])
                  + 0.1) / 0.98, region_center(model), {})
    z = ca.MX.sym("z", 2 * 2 * L + 2)
    g, lbg, ubg = model_constraints(z, per_sample, lim, base_hz=f0, L=L, m=2,
                                    t=np.arange(K) / (K * f0))
    z1 = np.concatenate([exc.a.ravel(), exc.b.ravel(), exc.center])
    worst = sample_violations(np.array(ca.Function("g", [z], [g])(z1)), lbg, ubg,
                              model.n_legs)
    assert worst.max() <= 1e-8, worst.max()
    x, v, a = exc.evaluate(np.arange(20 * K) / (20 * K * f0))
    assert np.hypot(*v.T).max() <= 0.4 and np.hypot(*a.T).max() <= 6.0
    assert np.hypot(*(x - region_center(model)).T).max() <= 0.06
