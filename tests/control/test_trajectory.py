# Tests of pm2dof.trajectory: S-curve against ruckig, structure, the paper's moves, errors.
import math

import numpy as np
import pytest

from pm2dof.control.trajectory import (
    PAPER_MOVES,
    SCurve,
    Trajectory,
    TrajectoryError,
    line,
    line_profile,
    paper_move,
)

ruckig = pytest.importorskip("ruckig")  # test-only reference implementation

# ---------------------------------------------------------------------------
# Cases. The shape is derived here from first principles, independently of the
# module: a_max is reached on the way to v_max iff v j > a^2; the shortest move
# reaching v_max is L_v = v (t_j + v/a) (a reached) or 2 v sqrt(v/j) (not);
# without cruise, a_max is reached iff L >= 2 a^3 / j^2.
# ---------------------------------------------------------------------------


def expected_shape(L, v, a, j):
    """(constant-acceleration segment present, cruise present)."""
    if v * j > a * a:
        L_v = v * (a / j + v / a)
        return (True, L > L_v) if L > L_v else (L > 2 * a**3 / j**2, False)
    return False, L > 2 * v * math.sqrt(v / j)


def random_cases(n_per_shape=12, seed=20100101):
    """Limits log-uniform over wide ranges; rejection-sample n cases of each of 4 shapes."""
    rng = np.random.default_rng(seed)
    buckets = {shape: [] for shape in [(True, True), (True, False), (False, True), (False, False)]}
    while any(len(b) < n_per_shape for b in buckets.values()):
        L, v, a, j = 10.0 ** rng.uniform([-4, -2, -1, 0], [0.5, 1, 2, 4])
        b = buckets[expected_shape(L, v, a, j)]
        if len(b) < n_per_shape:
            b.append((L, v, a, j))
    return [c for b in buckets.values() for c in b]


PAPER = [(0.05 * math.sqrt(2), m["v_max"], m["a_max"], m["j_max"]) for m in PAPER_MOVES.values()]
EDGE = [
    (0.2 * (5 / 200 + 0.2 / 5), 0.2, 5.0, 200.0),  # L exactly L_v: v_max reached, t_v = 0
    (0.05, 0.125, 5.0, 200.0),  # v j == a^2 exactly: t_a = 0 at v_max
    (2 * 5.0**3 / 200.0**2, 0.2, 5.0, 200.0),  # L exactly 2 a^3/j^2: a_max just reached
    (1e-9, 0.2, 5.0, 200.0),  # very short moves
    (1e-12, 0.5, 10.0, 400.0),
    (1e-6, 10.0, 0.1, 1e4),
    # Just either side of each shape boundary (branch selection).
    (1.001 * 0.013, 0.2, 5.0, 200.0), (0.999 * 0.013, 0.2, 5.0, 200.0),
    (1.001 * 2 * 5.0**3 / 200.0**2, 0.2, 5.0, 200.0),
    (0.999 * 2 * 5.0**3 / 200.0**2, 0.2, 5.0, 200.0),
    (0.05, 0.125 * 1.001, 5.0, 200.0), (0.05, 0.125 * 0.999, 5.0, 200.0),
]
CASES = PAPER + random_cases() + EDGE


def test_random_cases_cover_every_shape():
    shapes = [expected_shape(*c) for c in CASES]
    for shape in [(True, True), (True, False), (False, True), (False, False)]:
        assert shapes.count(shape) >= 10, f"shape {shape} only {shapes.count(shape)} times"


@pytest.mark.parametrize("case", CASES, ids=lambda c: "L=%.3g,v=%.3g,a=%.3g,j=%.3g" % c)
def test_profile_shape_matches_first_principles(case):
    p = SCurve.plan(*case)
    has_a, has_v = expected_shape(*case)
    if has_a:
        assert p.t_a > 0 and p.a_peak == pytest.approx(case[2], rel=1e-14), (case, p)
    else:
        assert p.t_a == 0 and p.a_peak <= case[2] * (1 + 1e-14), (case, p)
    if has_v:
        assert p.t_v > 0 and p.v_peak == pytest.approx(case[1], rel=1e-14), (case, p)
    else:
        assert p.t_v == 0 or p.t_v < 1e-12 * p.duration, (case, p)
        assert p.v_peak <= case[1] * (1 + 1e-14), (case, p)


# ---------------------------------------------------------------------------
# Against ruckig (Berscheid & Kroeger 2021), an independent time-optimal solver.
#
# Duration: ruckig documents no precision for the duration itself; its segment
# times are closed-form roots polished by Newton steps, and over 20 000 random
# cases the discrepancy with this module was <= 1.5e-13 s (relative 8e-16).
# We require 1e-9 relative (and 1e-9 s absolute for T < 1 s): four orders of
# margin over what was observed, yet far below any non-optimal alternative
# profile (those differ by >> 1e-9 relative).
#
# Samples: ruckig documents final position/velocity exact to 1e-8 and final
# acceleration to 1e-10 (absolute; https://docs.ruckig.com/background.html).
# Inside the move the two profiles may also have their switching times offset
# by up to DT; since |sd'| <= a, |s'| <= v and |sdd'| <= j, this adds v*DT, a*DT
# and j*DT respectively.
# ---------------------------------------------------------------------------


def ruckig_trajectory(L, v, a, j):
    otg, inp, traj = ruckig.Ruckig(1), ruckig.InputParameter(1), ruckig.Trajectory(1)
    inp.current_position, inp.target_position = [0.0], [L]
    inp.max_velocity, inp.max_acceleration, inp.max_jerk = [v], [a], [j]
    result = otg.calculate(inp, traj)
    assert result in (ruckig.Result.Working, ruckig.Result.Finished), (L, v, a, j, result)
    return traj


@pytest.mark.parametrize("case", CASES, ids=lambda c: "L=%.3g,v=%.3g,a=%.3g,j=%.3g" % c)
def test_against_ruckig(case):
    L, v, a, j = case
    p, ref = SCurve.plan(*case), ruckig_trajectory(*case)
    DT = 1e-9 * max(1.0, ref.duration)
    assert abs(p.duration - ref.duration) <= DT, (case, p.duration, ref.duration)
    t = np.concatenate([np.linspace(0.0, p.duration, 201),
                        np.random.default_rng(7).uniform(0.0, p.duration, 100)])
    s, sd, sdd, _ = p.evaluate(t)
    r = np.array([[q[0] for q in ref.at_time(float(tk))[:3]] for tk in t])
    for name, mine, theirs, tol in [("s", s, r[:, 0], 1e-8 + v * DT),
                                    ("sd", sd, r[:, 1], 1e-8 + a * DT),
                                    ("sdd", sdd, r[:, 2], 1e-10 + j * DT)]:
        k = np.argmax(abs(mine - theirs))
        assert abs(mine[k] - theirs[k]) <= tol, (case, name, t[k], mine[k], theirs[k], tol)


# ---------------------------------------------------------------------------
# Structure of the profile.
# ---------------------------------------------------------------------------


def boundaries(p):
    return np.cumsum([0.0, p.t_j, p.t_a, p.t_j, p.t_v, p.t_j, p.t_a, p.t_j])


@pytest.mark.parametrize("case", CASES, ids=lambda c: "L=%.3g,v=%.3g,a=%.3g,j=%.3g" % c)
def test_structure(case):
    L, v, a, j = case
    p = SCurve.plan(*case)
    assert p.duration == pytest.approx(boundaries(p)[-1], rel=1e-15), case
    s, sd, sdd, _ = p.evaluate([0.0, p.duration])
    assert s[0] == 0.0 and s[1] == L, (case, s)
    assert np.all(sd == 0.0) and np.all(sdd == 0.0), (case, sd, sdd)
    t = np.linspace(0.0, p.duration, 4001)
    s, sd, sdd, sddd = p.evaluate(t)
    assert np.all(sd >= 0.0), (case, t[np.argmin(sd)], sd.min())
    assert np.all(np.diff(s) >= 0.0), (case, "s not monotone")
    assert np.all(sd <= v + 1e-12), (case, sd.max())
    assert np.all(abs(sdd) <= a + 1e-12), (case, abs(sdd).max())
    assert np.all(abs(sddd) <= j + 1e-12), (case, abs(sddd).max())
    # Jerk pattern +j, 0, -j, 0, -j, 0, +j at the middle of each non-empty segment.
    b = boundaries(p)
    mid, width = 0.5 * (b[1:] + b[:-1]), np.diff(b)
    jerk = p.evaluate(mid)[3][width > 0]
    assert np.array_equal(jerk, (j * np.array([1, 0, -1, 0, -1, 0, 1]))[width > 0]), (case, jerk)
    # Outside [0, T]: at rest at the ends.
    out = p.evaluate([-1.0, -1e-9, p.duration + 1e-9, p.duration + 5.0])
    assert np.array_equal(np.stack(out), [[0, 0, L, L], [0] * 4, [0] * 4, [0] * 4]), (case, out)


@pytest.mark.parametrize("case", CASES, ids=lambda c: "L=%.3g,v=%.3g,a=%.3g,j=%.3g" % c)
def test_continuity_at_segment_boundaries(case):
    # Over a gap g = 2e, s, sd, sdd may change by at most g times the bound on
    # their derivative (v, a, j), plus rounding of a few ulps of L, v and a. The
    # gap itself is known to ~ulp(b) ~ 1e-16 T << 1e-6 g, hence g (1 + 1e-6).
    L, v, a, j = case
    p = SCurve.plan(*case)
    e = 1e-9 * p.duration
    b = boundaries(p)[1:-1]
    lo, hi = p.evaluate(b - e), p.evaluate(b + e)
    g = 2 * e * (1 + 1e-6)
    for name, k, bound in [("s", 0, v * g + 8e-16 * L), ("sd", 1, a * g + 8e-16 * v),
                           ("sdd", 2, j * g + 8e-16 * a)]:
        jump = abs(hi[k] - lo[k])
        assert np.all(jump <= bound), (case, name, b[np.argmax(jump)], jump.max(), bound)


@pytest.mark.parametrize("case", CASES, ids=lambda c: "L=%.3g,v=%.3g,a=%.3g,j=%.3g" % c)
def test_derivatives_match_finite_differences(case):
    # Central differences with step h: since |s'''| <= j (piecewise), Taylor gives
    # |D_h s - sd| <= j h^2 / 6 and, sdd being j-Lipschitz, |D_h sd - sdd| <= j h / 2;
    # rounding adds ~ eps |s| / h and eps |sd| / h (factor 4 of slack).
    L, v, a, j = case
    p = SCurve.plan(*case)
    h = 1e-4 * p.duration
    t = np.random.default_rng(3).uniform(-0.05, 1.05, 500) * p.duration
    s, sd, sdd, _ = p.evaluate(t)
    sp, sdp, _, _ = p.evaluate(t + h)
    sm, sdm, _, _ = p.evaluate(t - h)
    eps = np.finfo(float).eps
    err_v = abs((sp - sm) / (2 * h) - sd)
    err_a = abs((sdp - sdm) / (2 * h) - sdd)
    assert err_v.max() <= j * h * h / 6 + 4 * eps * L / h, (case, t[np.argmax(err_v)], err_v.max())
    assert err_a.max() <= j * h / 2 + 4 * eps * v / h, (case, t[np.argmax(err_a)], err_a.max())


def test_evaluate_is_vectorized_and_exact_closed_form():
    p = SCurve.plan(1.0, 1.0, 1.0, 1.0)  # t_j = 1, t_a = 0, L_v = 2 > 1: no cruise
    assert (p.t_j, p.t_a, p.t_v) == pytest.approx((0.5 ** (1 / 3), 0.0, 0.0), rel=1e-15)
    t = np.linspace(-1, 5, 12).reshape(3, 4)
    assert all(x.shape == (3, 4) for x in p.evaluate(t))
    s, sd, sdd, sddd = p.evaluate(0.5)  # first jerk segment: s = j t^3 / 6
    assert (float(s), float(sd), float(sdd), float(sddd)) == pytest.approx(
        (0.5**3 / 6, 0.125, 0.5, 1.0), rel=1e-15)
    # Full profile by hand: v=0.2, a=5, j=200, L=0.1: t_j = a/j = 0.025,
    # t_a = v/a - t_j = 0.015, L_v = v (2 t_j + t_a) = 0.013, t_v = (L - L_v)/v = 0.435.
    q = SCurve.plan(0.1, 0.2, 5.0, 200.0)
    assert (q.t_j, q.t_a, q.t_v, q.duration) == pytest.approx((0.025, 0.015, 0.435, 0.565),
                                                              rel=1e-13)
    assert q.evaluate(0.2825)[:3] == pytest.approx((0.05, 0.2, 0.0), rel=1e-14)  # mid-cruise
    assert float(q.evaluate(0.04)[1]) == pytest.approx(0.0625 + 5 * 0.015, rel=1e-14)  # end of t_a


# ---------------------------------------------------------------------------
# The paper's moves.
# ---------------------------------------------------------------------------


@pytest.mark.parametrize("speed, T_hand", [
    # T = 4 t_j + 2 t_a + t_v with t_j = a/j, t_a = v/a - a/j, t_v = L/v - v/a - a/j.
    ("low", 4 * 0.025 + 2 * 0.015 + (0.05 * math.sqrt(2) - 0.013) / 0.2),
    ("high", 4 * 0.025 + 2 * 0.025 + (0.05 * math.sqrt(2) - 0.0375) / 0.5),
])
def test_paper_moves(speed, T_hand):
    tr = paper_move(speed)
    m = PAPER_MOVES[speed]
    prof = line_profile(**m)                  # the move's kinematic plan
    start, end = np.array(m["start"]), np.array(m["end"])
    assert prof.L == pytest.approx(0.05 * math.sqrt(2), rel=1e-15), prof.L
    assert round(prof.L, 4) == 0.0707
    assert prof.duration == pytest.approx(T_hand, rel=1e-14), (speed, prof.duration, T_hand)
    N = math.ceil(T_hand / 0.002) + 1
    assert tr.t.shape == (N,) and tr.xd.shape == (N, 2), (speed, tr.t.shape, N)
    assert np.array_equal(tr.t, np.arange(N) * 0.002), speed
    assert np.allclose(np.diff(tr.t), 0.002, rtol=0, atol=1e-15), speed
    assert tr.t[-2] < prof.duration <= tr.t[-1], (speed, tr.t[-2:], prof.duration)
    assert tr.duration == tr.t[-1] == (N - 1) * 0.002, (speed, tr.duration)
    assert np.array_equal(tr.xd[0], start), (speed, tr.xd[0])
    assert np.array_equal(tr.xd[-1], end), (speed, tr.xd[-1])
    assert np.all(tr.xd_dot[[0, -1]] == 0) and np.all(tr.xd_ddot[[0, -1]] == 0), speed
    # On the segment: zero cross product with the direction, projection in [0, L].
    u = (end - start) / np.linalg.norm(end - start)
    rel = tr.xd - start
    cross = rel[:, 0] * u[1] - rel[:, 1] * u[0]
    assert abs(cross).max() <= 1e-16, (speed, abs(cross).max())
    proj = rel @ u
    assert np.all(np.diff(proj) >= -1e-16) and proj.min() >= -1e-16, speed
    assert proj.max() <= prof.L + 1e-16, speed
    # Velocity and acceleration along u with magnitude sd, |sdd| within the limits.
    speed_n = np.linalg.norm(tr.xd_dot, axis=1)
    assert speed_n.max() <= m["v_max"] + 1e-12, (speed, speed_n.max())
    assert np.linalg.norm(tr.xd_ddot, axis=1).max() <= m["a_max"] + 1e-12, speed
    assert abs(tr.xd_dot[:, 0] * u[1] - tr.xd_dot[:, 1] * u[0]).max() <= 1e-16, speed
    _, sd, sdd, _ = prof.evaluate(tr.t)
    assert np.allclose(tr.xd_dot, sd[:, None] * u, rtol=0, atol=1e-15), speed
    assert np.allclose(tr.xd_ddot, sdd[:, None] * u, rtol=0, atol=1e-13), speed


def test_paper_durations_and_sample_counts():
    low, high = paper_move("low"), paper_move("high")
    d_low, d_high = (line_profile(**PAPER_MOVES[k]).duration for k in ("low", "high"))
    assert d_low == pytest.approx(0.41855339059327373, rel=1e-14) and len(low.t) == 211
    assert d_high == pytest.approx(0.2164213562373095, rel=1e-14) and len(high.t) == 110
    assert low.duration == pytest.approx(0.42, rel=1e-14) and high.duration == pytest.approx(0.218)
    assert PAPER_MOVES["low"]["start"] == (0.22, 0.29), PAPER_MOVES["low"]
    assert PAPER_MOVES["high"]["end"] == (0.27, 0.24), PAPER_MOVES["high"]
    with pytest.raises(TypeError):
        PAPER_MOVES["low"]["v_max"] = 1.0  # read-only


def test_arrays_read_only_float64_c_contiguous():
    tr = paper_move("high")
    for name in ("t", "xd", "xd_dot", "xd_ddot"):
        x = getattr(tr, name)
        assert x.dtype == np.float64 and x.flags.c_contiguous and not x.flags.writeable, name
        with pytest.raises(ValueError):
            x[0] = 1.0


def test_extended_appends_rest_samples():
    tr = paper_move("low")
    ext = tr.extended(0.1)
    n = len(tr.t)
    assert isinstance(ext, Trajectory) and len(ext.t) == n + 50, len(ext.t)
    assert np.array_equal(ext.t, np.arange(n + 50) * 0.002)
    assert np.array_equal(ext.xd[:n], tr.xd) and np.array_equal(ext.xd_dot[:n], tr.xd_dot)
    assert np.all(ext.xd[n:] == PAPER_MOVES["low"]["end"]), ext.xd[n:]
    assert np.all(ext.xd_dot[n:] == 0) and np.all(ext.xd_ddot[n:] == 0)
    assert ext.duration == tr.duration + 0.1 and not ext.xd.flags.writeable
    assert len(tr.extended(0.0).t) == n and len(tr.extended(0.0011).t) == n + 1


def test_other_period_and_generic_line():
    tr = line((0.0, 0.0), (0.3, -0.4), 0.5, 10.0, 400.0, period=0.001)
    prof = line_profile((0.0, 0.0), (0.3, -0.4), 0.5, 10.0, 400.0)
    assert tr.period == 0.001 and prof.L == pytest.approx(0.5, rel=1e-15)
    assert np.array_equal(tr.xd[-1], (0.3, -0.4)) and tr.t[-1] >= prof.duration
    assert tr.xd_dot[len(tr.t) // 2] == pytest.approx((0.3, -0.4), rel=1e-12), "mid-cruise velocity"
    # 0.7 + (0.1 - 0.7) != 0.1 in floating point: the end must still be hit exactly.
    tr = line((0.7, 0.22), (0.1, 0.05), 0.2, 5.0, 200.0)
    assert tr.xd[-1].tolist() == [0.1, 0.05] and tr.xd[0].tolist() == [0.7, 0.22], tr.xd[[0, -1]]


# ---------------------------------------------------------------------------
# Errors.
# ---------------------------------------------------------------------------

GOOD = dict(start=(0.22, 0.29), end=(0.27, 0.24), v_max=0.2, a_max=5.0, j_max=200.0)


@pytest.mark.parametrize("kwargs, words", [
    (dict(v_max=0.0), ["v_max", "0.0", "> 0"]),
    (dict(v_max=-1.0), ["v_max", "-1.0", "> 0"]),
    (dict(a_max=math.inf), ["a_max", "inf", "finite"]),
    (dict(j_max=math.nan), ["j_max", "nan", "finite"]),
    (dict(j_max="fast"), ["j_max", "fast"]),
    (dict(period=0.0), ["period", "0.0", "> 0"]),
    (dict(period=-0.002), ["period", "-0.002"]),
    (dict(end=(0.22, 0.29)), ["zero path length", "0.22"]),
    (dict(start=(0.22, math.nan)), ["start", "nan", "finite"]),
    (dict(end=(0.27, 0.24, 0.0)), ["end", "shape (2,)"]),
    (dict(start=[[0.22, 0.29]]), ["start", "shape (2,)"]),
    (dict(end="here"), ["end", "here"]),
])
def test_line_errors(kwargs, words):
    with pytest.raises(TrajectoryError) as info:
        line(**{**GOOD, **kwargs})
    assert isinstance(info.value, ValueError)
    for w in words:
        assert w in str(info.value), (kwargs, w, str(info.value))


@pytest.mark.parametrize("args, words", [
    ((0.0, 1, 1, 1), ["L", "0.0", "> 0"]),
    ((1, 1, 1, -2.5), ["j_max", "-2.5"]),
    ((math.inf, 1, 1, 1), ["L", "inf"]),
])
def test_plan_errors(args, words):
    with pytest.raises(TrajectoryError) as info:
        SCurve.plan(*args)
    for w in words:
        assert w in str(info.value), (args, w, str(info.value))


def test_trajectory_constructor_checks_shapes():
    tr = paper_move("low")
    with pytest.raises(TrajectoryError, match=r"xd_dot must have shape \(211, 2\), got \(211, 3\)"):
        Trajectory(tr.t, tr.xd, np.zeros((211, 3)), tr.xd_ddot, tr.period)


def test_paper_move_and_extended_errors():
    with pytest.raises(TrajectoryError, match=r"'medium'.*\['high', 'low'\]"):
        paper_move("medium")
    with pytest.raises(TrajectoryError, match="period"):
        paper_move("low", period=-1.0)
    for bad in (-0.1, math.nan, math.inf, "x"):
        with pytest.raises(TrajectoryError, match="settle_time"):
            paper_move("low").extended(bad)


def test_the_paper_moves_have_one_home_the_model_file():
    """PAPER_MOVES is read from the shipped model file: the same trajectory either
    way, and an edit of the file's move is what paper_move would follow."""
    import pm2dof
    from pm2dof.control.trajectory import model_move
    m = pm2dof.load_model()
    for name, t in m.spec.trajectories.items():
        assert PAPER_MOVES[name]["start"] == tuple(t["start"]) and \
            PAPER_MOVES[name]["v_max"] == t["v_max"], name
        a, b = model_move(m, name), pm2dof.paper_move(name)
        assert np.array_equal(a.xd, b.xd) and np.array_equal(a.xd_ddot, b.xd_ddot), name
    with pytest.raises(TrajectoryError, match=r"no move 'far' in \[trajectories\] of .*; have "
                                              r"\['high', 'low'\]"):
        model_move(m, "far")
