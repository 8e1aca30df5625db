# Capability maps under gravity: what tau_max leaves once the robot is held, against brute force.
import numpy as np
import pytest
from scipy.optimize import linprog

import pm2dof
from pm2dof.analysis.maps import capability, maps_summary, workspace_maps, zonotope_inradius

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

DIRS = np.linspace(0, 2 * np.pi, 3600, endpoint=False)        # 0.1 deg
COARSE = np.linspace(0, 2 * np.pi, 72, endpoint=False)        # 5 deg


def _gravity_force(m, xe, h=1e-6):
    """Ge at rest from the potential energy alone: dV/dxe by central differences (not the
    generated Ge)."""
    xe = np.asarray(xe, dtype=float)
    g = np.empty(len(xe))
    for k in range(len(xe)):
        e = np.zeros(len(xe))
        e[k] = h
        g[k] = (m.potential_energy(xe + e) - m.potential_energy(xe - e)) / (2 * h)
    return g


def _radial_lp(A, w, d, b):
    """LP (HiGHS): the largest t >= 0 with A tau = t d + b, |tau_i| <= w_i."""
    n = len(w)
    c = np.zeros(n + 1)
    c[-1] = -1.0
    res = linprog(c, A_eq=np.hstack([A, -np.reshape(d, (-1, 1))]), b_eq=b,
                  bounds=[(-wi, wi) for wi in w] + [(0, None)], method="highs")
    assert res.status == 0, res.message
    return res.x[-1]


def _least_radial(radial):
    """The least of ``radial(angle)`` over the circle: a 5 deg grid, then each of its local
    minima refined by bounded Brent within +-5 deg. Returns (least value, coarse least)."""
    from scipy.optimize import minimize_scalar
    v = np.array([radial(a) for a in COARSE])
    k = len(v)
    best = v.min()
    for i in range(k):
        if v[i] <= v[i - 1] and v[i] <= v[(i + 1) % k]:
            step = COARSE[1]
            r = minimize_scalar(radial, bounds=(COARSE[i] - step, COARSE[i] + step),
                                method="bounded", options={"xatol": 1e-7})
            best = min(best, r.fun)
    return best, v.min()


def _poses(m, k, seed):
    rng = np.random.default_rng(seed)
    c = np.mean([m.spec.trajectories[s]["start"] for s in m.spec.trajectories], axis=0)
    out = []
    while len(out) < k:
        x = c + rng.uniform(-0.08, 0.08, 2)
        try:
            q = m.ik(x)
            m.S(q)
        except ValueError:
            continue
        out.append((x, q))
    return out


@pytest.mark.parametrize("tau_max, seed", [(None, 7), ([9.0, 7.0, 8.0], 8)])
def test_vertical_robot_force_and_acceleration_leave_the_holding_torque(tau_max, seed):
    """shang2010_vertical: the largest force (and acceleration at rest) available in every
    direction is the least, over the directions, of what the actuators reach along that
    direction while holding the robot: min-max by LP (S^T tau = t d + Ge; a 5 deg grid, its
    local minima refined), min-norm by the minimum-norm torques P (t d + Ge) within the limits
    on a 0.1 deg grid, Ge from the potential energy. With the low limits of the second case
    the minimum-norm holding torque is up to 40 % of an actuator's limit."""
    m = pm2dof.load_model("shang2010_vertical")
    w = np.asarray(m.spec.limits["tau_max"] if tau_max is None else tau_max, dtype=float)
    D = np.stack([np.cos(DIRS), np.sin(DIRS)], axis=1)
    for k, (x, q) in enumerate(_poses(m, 3, seed)):
        S, Me = m.S(q), m.Me(q, m.theta_nominal)
        Ge = _gravity_force(m, x)
        assert np.linalg.norm(Ge) > 5.0                       # gravity matters here (N)
        c = capability(m, q, tau_max=w)
        if k == 0:                                            # the LP: one pose per case
            for key, A in (("force_min_max", np.eye(2)), ("accel_min_max", Me)):
                least, coarse = _least_radial(lambda a, A=A: _radial_lp(
                    S.T, w, A @ [np.cos(a), np.sin(a)], Ge))
                assert coarse >= c[key] * (1 - 1e-7), key     # the ball fits
                assert least == pytest.approx(c[key], rel=1e-7), key
        # min-norm: tau = P (t d + Ge), P = pinv(S^T); the largest t per direction, row by row
        P = np.linalg.pinv(S.T)
        for key, F in (("force_min_norm", D.T), ("accel_min_norm", Me @ D.T)):
            rate, hold = P @ F, P @ Ge                        # (n, K), (n,)
            with np.errstate(divide="ignore"):
                t = np.where(rate > 0, (w[:, None] - hold[:, None]) / rate,
                             np.where(rate < 0, (-w[:, None] - hold[:, None]) / rate, np.inf))
            assert t.min(axis=0).min() == pytest.approx(c[key], rel=1e-5), key
        # and gravity costs something: the same pose without it (the shipped horizontal robot)
        h = capability(pm2dof.load_model("shang2010"), q, tau_max=w)
        assert c["force_min_max"] < h["force_min_max"]
        assert c["force_min_norm"] < h["force_min_norm"]


def test_a_horizontal_robot_is_computed_as_before():
    """No gravity: the maps are the zonotope's inradius about the origin, exactly."""
    m = pm2dof.load_model("shang2010")
    w = np.asarray(m.spec.limits["tau_max"], dtype=float)
    for _x, q in _poses(m, 3, 8):
        S = m.S(q)
        c = capability(m, q)
        assert c["force_min_max"] == zonotope_inradius(S * w[:, None])
        assert c["force_min_norm"] == float(np.min(w / np.linalg.norm(
            S @ np.linalg.inv(S.T @ S), axis=1)))


def test_holding_takes_every_actuator_past_its_limit_gives_zero_not_a_negative_force():
    m = pm2dof.load_model("shang2010_vertical")
    _x, q = _poses(m, 1, 9)[0]
    c = capability(m, q, tau_max=[0.5, 0.5, 0.5])     # N m: below the holding torques
    assert c["force_min_max"] == 0.0 and c["force_min_norm"] == 0.0
    assert np.isnan(c["force_ratio"])


def test_shifted_inradius_in_three_dimensions_by_lp():
    """A platform's task space (m = 3): the ball about a centre inside the zonotope, against
    the LP's radial function over the facet normals and a dense Fibonacci sphere."""
    rng = np.random.default_rng(3)
    G = rng.normal(size=(4, 3))
    centre = 0.3 * rng.normal(size=3)
    r = zonotope_inradius(G, centre)
    assert r > 0
    k = np.arange(4000) + 0.5
    z, a = 1 - 2 * k / len(k), np.pi * (1 + 5 ** 0.5) * k
    D = np.stack([np.sqrt(1 - z * z) * np.cos(a), np.sqrt(1 - z * z) * np.sin(a), z], axis=1)
    i, j = np.triu_indices(len(G), 1)
    N = np.cross(G[i], G[j])
    N /= np.linalg.norm(N, axis=1)[:, None]
    at_normals = min(_radial_lp(G.T, np.ones(len(G)), s * n, centre) for n in N for s in (1, -1))
    assert at_normals == pytest.approx(r, rel=1e-7)
    dense = min(_radial_lp(G.T, np.ones(len(G)), d, centre) for d in D[::16])
    assert dense >= r * (1 - 1e-7)
    assert zonotope_inradius(G, 100 * G.sum(axis=0)) == 0.0        # a centre outside


def test_the_summary_and_its_moves_under_gravity():
    """maps_summary's worst force along the low move is the least capability of its poses,
    gravity included (was: the figure without gravity)."""
    m = pm2dof.load_model("shang2010_vertical")
    s = maps_summary(m, workspace_maps(m, 9))
    worst = s["moves"]["low"]["worst_on_path"]
    h = pm2dof.load_model("shang2010")
    sh = maps_summary(h, workspace_maps(h, 9))["moves"]["low"]["worst_on_path"]
    assert worst["force_min_max"] < sh["force_min_max"]
    assert s["gravity"] == [0.0, -9.81]


def test_the_vertical_numbers_of_the_redundancy_page():
    """docs/results-redundancy.md's worst forces along shang2010_vertical's low move, beside
    the flat robot's (its table)."""
    from pathlib import Path
    page = " ".join((Path(__file__).resolve().parents[2] / "docs" / "results-redundancy.md")
                    .read_text().split())
    worst = {}
    for name in ("shang2010_vertical", "shang2010"):
        m = pm2dof.load_model(name)
        worst[name] = maps_summary(m, workspace_maps(m, 5))["moves"]["low"]["worst_on_path"]
    v, h = worst["shang2010_vertical"], worst["shang2010"]
    mm, mn = v["force_min_max"], v["force_min_norm"]
    assert (f"is {mm:.1f} N (min-max) and {mn:.1f} N (min-norm), "
            f"{100 * (1 - mm / h['force_min_max']):.1f} % and "
            f"{100 * (1 - mn / h['force_min_norm']):.1f} % below the same robot lying flat "
            f"({h['force_min_max']:.1f} and {h['force_min_norm']:.1f} N)") in page
