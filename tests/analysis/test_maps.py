# Capability maps against an independent LP and direct geometry.
import json

import numpy as np
import pytest
from scipy.optimize import linprog

import pm2dof
from pm2dof.analysis.maps import (
    FIELDS,
    capability,
    maps_summary,
    min_norm_radius,
    workspace_maps,
    zonotope_inradius,
)
from pm2dof.cli import main

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not


def _radial(S, w, d):
    """LP (HiGHS): the largest t with t d = S^T tau, |tau_i| <= w_i -- the zonotope's radial
    function in the unit direction d, computed without any knowledge of zonotopes."""
    n = len(w)
    c = np.zeros(n + 1)
    c[-1] = -1.0                                       # maximise t
    A_eq = np.hstack([S.T, -np.asarray(d).reshape(2, 1)])
    res = linprog(c, A_eq=A_eq, b_eq=np.zeros(2),
                  bounds=[(-wi, wi) for wi in w] + [(0, None)], method="highs")
    assert res.status == 0
    return res.x[-1]


def _random_poses(m, k, seed):
    rng = np.random.default_rng(seed)
    c = m.bases.mean(axis=0)
    out = []
    while len(out) < k:
        x = c + rng.uniform(-0.12, 0.12, 2)
        try:
            q = m.ik(x)
            m.S(q)                      # clear of both singularity thresholds
        except ValueError:
            continue
        out.append(q)
    return out


@pytest.mark.parametrize("name", ["shang2010", "fourleg", "unequal"])
def test_min_max_force_radius_is_the_lp_inradius(name):
    """The closed form (least support over edge normals) equals the least LP radial value:
    at the edge normals (where the minimum is attained) to solver precision, and no dense
    direction has a smaller one (the circle fits)."""
    m = pm2dof.load_model(name)
    w = np.array([30.0, 22.0, 27.0, 25.0][:m.n_legs])
    dirs = np.linspace(0, np.pi, 90, endpoint=False)     # radial(-d) = radial(d): symmetric
    for q in _random_poses(m, 3, 1):
        S = m.S(q)
        r = zonotope_inradius(S * w[:, None])
        normals = [np.array([-s[1], s[0]]) / np.hypot(*s) for s in S]
        at_normals = min(_radial(S, w, d) for d in normals)
        assert at_normals == pytest.approx(r, rel=1e-7)
        dense = min(_radial(S, w, (np.cos(a), np.sin(a))) for a in dirs)
        assert dense >= r * (1 - 1e-7)


def test_min_norm_force_radius_by_dense_directions():
    """min_i w_i / |P_i| against the largest |f| along dense directions that keeps the
    minimum-norm torques (numpy lstsq, not the formula) within the limits."""
    m = pm2dof.load_model()
    w = np.array([30.0, 25.0, 20.0])
    a = np.linspace(0, 2 * np.pi, 20001)
    D = np.stack([np.cos(a), np.sin(a)])
    for q in _random_poses(m, 4, 2):
        S = m.S(q)
        tau_unit = np.linalg.lstsq(S.T, D, rcond=None)[0]  # min-norm tau for each unit force
        along = np.min(w[:, None] / np.abs(tau_unit), axis=0)
        r = min_norm_radius(S @ np.linalg.inv(S.T @ S), w)
        assert along.min() == pytest.approx(r, rel=1e-6)   # 2e-4 rad grid: 1 - cos ~ 1e-8


def test_capability_ordering_and_the_five_bar():
    """min-max >= min-norm everywhere (it is the optimum); with two legs there is no choice."""
    for name, equal in (("shang2010", False), ("fivebar", True)):
        m = pm2dof.load_model(name)
        for q in _random_poses(m, 10, 3):
            c = capability(m, q)
            assert c["force_min_max"] >= c["force_min_norm"] * (1 - 1e-12)
            assert c["accel_min_max"] >= c["accel_min_norm"] * (1 - 1e-12)
            if equal:
                assert c["force_ratio"] == pytest.approx(1.0, abs=1e-12)


def test_acceleration_capability_is_force_through_Me():
    """The acceleration zonotope is Me^-1 Z: its LP radial function in direction a equals the
    force LP with the constraint S^T tau = t Me a."""
    m = pm2dof.load_model()
    w = np.asarray(m.spec.limits["tau_max"])
    q = _random_poses(m, 1, 4)[0]
    S, Me = m.S(q), m.Me(q, m.theta_nominal)
    c = capability(m, q)
    dirs = np.linspace(0, np.pi, 361, endpoint=False)
    radial = []
    for ang in dirs:
        a = np.array([np.cos(ang), np.sin(ang)])
        f = Me @ a                                       # force per unit acceleration
        radial.append(_radial(S, w, f / np.linalg.norm(f)) / np.linalg.norm(f))
    assert min(radial) >= c["accel_min_max"] * (1 - 1e-7)
    assert min(radial) == pytest.approx(c["accel_min_max"], rel=2e-3)  # 0.5 deg grid


def test_workspace_maps_shapes_and_reachable_round_trip():
    m = pm2dof.load_model("fivebar")
    mp = workspace_maps(m, 25)
    assert mp["reachable"].shape == (25, 25) and mp["reachable"].any()
    X, Y = np.meshgrid(mp["x"], mp["y"])
    for x, y in zip(X[mp["reachable"]], Y[mp["reachable"]]):
        q = m.ik([x, y])                                  # reachable means ik answers ...
        np.testing.assert_allclose(m.fk(q[:2]), [x, y], atol=1e-9)   # ... in the mode
    for key in FIELDS:
        assert np.all(np.isnan(mp[key][~mp["reachable"]]))
    s = maps_summary(m, mp)
    assert set(s["moves"]) == set(m.spec.trajectories)
    assert s["clear_area_m2"] <= s["reachable_area_m2"]
    with pytest.raises(ValueError, match="resolution"):
        workspace_maps(m, 2)
    for bad in (100_000, True, 21.0):     # too many poses (74 GB at 10^5), a bool, a float
        with pytest.raises(pm2dof.ArgumentError, match="from 5 to 1001"):
            workspace_maps(m, bad)


def test_maps_command_writes_figures_and_json(tmp_path, capsys):
    assert main(["maps", "--out", str(tmp_path), "--resolution", "21", "--json"]) == 0
    cap = capsys.readouterr()
    summary = json.loads(cap.out)
    assert "capability maps: 21 x 21 poses" in cap.err                   # stage lines
    assert summary["over_clear_workspace"]["force_ratio"]["min"] >= 1 - 1e-12
    for f in ("maps_singularity.png", "maps_conditioning.png", "maps_force.png",
              "maps_acceleration.png", "maps.json"):
        assert (tmp_path / f).stat().st_size > 0
    assert main(["maps", "--out", str(tmp_path), "--tau-max", "1", "2"]) == 2
    assert "--tau-max" in capsys.readouterr().err
    assert main(["maps", "--out", str(tmp_path), "--resolution", "100000"]) == 2
    assert "from 5 to 1001" in capsys.readouterr().err
