# Torque splits: exact against independent LP/QP solvers; S^T tau unchanged.
"""The three torque distributions of the generated C, checked independently.

* ``Model.torque_splits`` (the same generated code as the controller steps' splits) against
  SciPy: min-max against the LP solved by HiGHS; the preload QP against SLSQP (ours must be
  feasible and at least as good: SLSQP reaches these convex QPs to ~1e-12 relative, measured
  8e-13); the preload fallback against the max-margin LP (HiGHS); the fallback modes against
  the LPs' (in)feasibility. 3- and 4-leg models, random poses, forces, limits and preloads.
* S^T tau = u for every split to 1e-12 (relative to |S| |tau| + |u|).
* The controller steps: every split gives the same S^T tau_a as min_norm at the same state.
* Two legs: no redundancy, every split is the min-norm torque.
* Bad split names, preload settings and model-file [control] entries are refused by name.
"""
import numpy as np
import pytest
from scipy.optimize import linprog, lsq_linear, minimize

import pm2dof
from pm2dof.core.paths import SHIPPED_GENERATED, SHIPPED_MODELS

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

MODELS = ("shang2010", "unequal", "fourleg")
HIGHS = dict(primal_feasibility_tolerance=1e-10, dual_feasibility_tolerance=1e-10)


@pytest.fixture(scope="module", params=MODELS)
def redundant(request):
    return pm2dof.load_model(SHIPPED_MODELS / f"{request.param}.toml")


def _cases(m, count, seed):
    """(q, S, u, tau_max, preload, sign): random poses near the paper's path, task forces from
    well inside to far beyond the actuators, random limits and preloads; signs of a null vector
    of S^T (the pattern that can hold a preload at rest) or random."""
    rng = np.random.default_rng(seed)
    n, out = m.n_legs, []
    while len(out) < count:
        x = np.array([0.245, 0.265]) + rng.uniform(-0.04, 0.04, 2)
        try:
            q = m.ik(x)
            S = m.S(q)
        except (pm2dof.WorkspaceError, pm2dof.SingularityError):
            continue
        null = np.linalg.svd(S.T)[2][-1]
        sign = np.sign(null) if rng.random() < 0.7 else rng.choice([-1.0, 1.0], n)
        w = rng.uniform(5.0, 30.0, n)
        out.append((q, S, rng.normal(0, 1, 2) * rng.choice([5.0, 30.0, 100.0]), w,
                    rng.uniform(0, 0.3, n) * w, sign))
    return out


def _lp_min_max(S, u, w):
    n = len(w)
    A = np.zeros((2 * n, n + 1))
    for i in range(n):
        A[2 * i, [i, n]] = 1.0, -w[i]
        A[2 * i + 1, [i, n]] = -1.0, -w[i]
    r = linprog(np.r_[np.zeros(n), 1.0], A_ub=A, b_ub=np.zeros(2 * n),
                A_eq=np.c_[S.T, np.zeros(2)], b_eq=u, bounds=[(None, None)] * (n + 1),
                method="highs", options=HIGHS)
    assert r.status == 0, r.message
    return r.fun


def _lp_max_margin(S, u, w, pre, sign):
    """max m s.t. S^T tau = u, sign_i tau_i - pre_i >= m, |tau_i| <= w_i (None: limits infeasible)."""
    n = len(w)
    r = linprog(np.r_[np.zeros(n), -1.0], A_ub=np.c_[-np.diag(sign), np.ones(n)], b_ub=-pre,
                A_eq=np.c_[S.T, np.zeros(2)], b_eq=u, bounds=[(-a, a) for a in w] + [(None, None)],
                method="highs", options=HIGHS)
    return -r.fun if r.status == 0 else None


def _qp_preload(S, u, lo, hi, x0):
    """SLSQP's optimum of min |tau|^2 s.t. S^T tau = u, lo <= tau <= hi (it may stop at its
    precision limit, status 8: its point is then checked for feasibility, not trusted blindly)."""
    r = minimize(lambda t: t @ t, x0, jac=lambda t: 2 * t, bounds=list(zip(lo, hi)),
                 constraints=[dict(type="eq", fun=lambda t: S.T @ t - u, jac=lambda t: S.T)],
                 method="SLSQP", options=dict(ftol=1e-15, maxiter=500))
    assert r.status in (0, 8), r.message
    assert np.abs(S.T @ r.x - u).max() <= 1e-8 * (1 + np.abs(u).max()), r
    return r.fun


def _kkt_residual(S, tau, lo, hi, w):
    """Optimality certificate of tau for min |tau|^2 s.t. S^T tau = u, lo <= tau <= hi: the
    smallest |2 tau - S nu - sum_lower l_i e_i + sum_upper l_i e_i| over free nu and l >= 0
    (bounded least squares). Zero (to rounding) exactly when tau satisfies the KKT conditions,
    which for this convex QP means tau is the optimum. Relative to |2 tau|, absolute at tau = 0
    (u = 0 with no preload, e.g. at rest: sign(0) = 0 leaves no friction to resist)."""
    n = len(tau)
    at_lo = tau <= lo + 1e-9 * w
    at_hi = tau >= hi - 1e-9 * w
    E = np.eye(n)
    A = np.c_[S, E[:, at_lo], -E[:, at_hi]]
    bounds = ([-np.inf] * 2 + [0.0] * int(at_lo.sum() + at_hi.sum()),
              [np.inf] * (2 + int(at_lo.sum() + at_hi.sum())))
    r = lsq_linear(A, 2 * tau, bounds=bounds, method="bvls", tol=1e-14)
    return np.abs(A @ r.x - 2 * tau).max() / (2 * np.abs(tau).max() or 1.0)


def test_splits_are_exact_against_independent_solvers(redundant):
    m, n = redundant, redundant.n_legs
    modes, modes_checked = [0, 0, 0], []
    for q, S, u, w, pre, sign in _cases(m, 60, seed=n):
        r = m.torque_splits(q, u, w, pre, sign)
        info = f"{m.name} q={q.tolist()} u={u.tolist()} w={w.tolist()} pre={pre.tolist()} sign={sign}"
        for key in ("min_norm", "min_max", "preload"):
            tau = r[key]
            scale = np.abs(S).max() * np.abs(tau).max() + np.abs(u).max()
            assert np.abs(S.T @ tau - u).max() <= 1e-12 * scale, (key, info)
        # min-max: the LP optimum (HiGHS), and the ratio is what the torques show
        t_lp = _lp_min_max(S, u, w)
        assert abs(r["min_max_ratio"] - t_lp) <= 1e-9 * t_lp, (r["min_max_ratio"], t_lp, info)
        assert np.max(np.abs(r["min_max"]) / w) == pytest.approx(r["min_max_ratio"], rel=1e-12)
        assert np.max(np.abs(r["min_max"]) / w) <= np.max(np.abs(r["min_norm"]) / w) * (1 + 1e-12)
        # preload
        lo, hi = np.where(sign > 0, pre, -w), np.where(sign > 0, w, -pre)
        tau, mode = r["preload"], r["preload_mode"]
        modes[mode] += 1
        margin = _lp_max_margin(S, u, w, pre, sign)
        if mode == 0:
            assert margin is not None and margin >= -1e-9 * w.max(), (margin, info)
            assert np.all(tau >= lo - 1e-10 * w) and np.all(tau <= hi + 1e-10 * w), info
            assert _kkt_residual(S, tau, lo, hi, w) <= 1e-9, info
            worse = tau + 0.05 * np.linalg.svd(S.T)[2][-1] * w.min()  # feasible, not optimal
            if np.all(worse > lo + 1e-6) and np.all(worse < hi - 1e-6):
                assert _kkt_residual(S, worse, lo, hi, w) > 1e-4, "the certificate is vacuous"
                modes_checked.append(1)
            best = _qp_preload(S, u, lo, hi, r["min_max"])
            assert tau @ tau <= best * (1 + 1e-9), (tau @ tau, best, info)
        elif mode == 1:   # the preload cannot be held: the largest worst-case margin instead
            assert margin is not None and margin < 1e-9 * w.max(), (margin, info)
            assert np.all(np.abs(tau) <= w * (1 + 1e-10)), info
            assert np.min(sign * tau - pre) == pytest.approx(margin, abs=1e-8 * w.max()), info
        else:             # not even the limits: the min-max torques
            assert margin is None and t_lp > 1, info
            np.testing.assert_array_equal(tau, r["min_max"])
    assert min(modes) >= 3, f"every preload mode must be exercised: {modes}"
    assert modes_checked, "no case showed that a non-optimal torque fails the KKT check"


def test_zero_preload_still_keeps_the_signs_as_the_lp_says():
    """A preload of 0 (the model file's default) is not "no preload": every tau_i keeps its sign
    where some torques within the limits can (mode 0, least norm), and where none can (mode 1)
    the torques are HiGHS's largest worst-case margin, which is < 0 there. Along the low-speed
    move's inverse dynamics at 6 N m both happen: keeping (+, +, +) needs
    more torque than min-norm, so `splits --tau-max 6.0` counts preload-infeasible samples."""
    from pm2dof.control.trajectory import model_move
    m = pm2dof.load_model()
    n, traj = m.n_legs, model_move(m, "low")
    w, pre, sign = np.full(n, 6.0), np.zeros(n), np.ones(n)
    modes = set()
    for x, v, a in zip(traj.xd, traj.xd_dot, traj.xd_ddot):
        q = m.ik(x)
        S, u = m.S(q), m.Y(q, v, v, a) @ m.theta_nominal
        r = m.torque_splits(q, u, w, pre, sign)
        tau, mode, best = r["preload"], r["preload_mode"], _lp_max_margin(S, u, w, pre, sign)
        info = f"x={x.tolist()} u={u.tolist()} mode={mode} lp={best}"
        assert best is not None, info                      # the limits alone are never exceeded
        if mode == 0:
            assert best >= -1e-9 * w.max() and np.all(tau >= -1e-10 * w), info
            assert _kkt_residual(S, tau, pre, w, w) <= 1e-9, info
        else:
            assert mode == 1 and best < 0, info
            assert np.min(sign * tau - pre) == pytest.approx(best, abs=1e-8 * w.max()), info
        modes.add(mode)
    assert modes == {0, 1}


def test_every_split_gives_the_min_norm_task_force_in_the_steps(redundant):
    """The generated steps at one state: S^T tau_a of every split equals min_norm's (no clipping
    here: the torques stay inside tau_max)."""
    m, n = redundant, redundant.n_legs
    rng = np.random.default_rng(7)
    seen = set()
    for law in (pm2dof.NAController, pm2dof.APDController):
        ctrls = {s: law(m, split=s, preload=np.full(n, 1.0), on_singular="zero")
                 for s in ("min_norm", "min_max", "preload")}
        for _ in range(20):
            x = np.array([0.245, 0.265]) + rng.uniform(-0.02, 0.02, 2)
            qa = m.ik(x)[:n].copy()
            S = m.S(m.ik(m.fk(qa)))
            xd, v, a = x + rng.normal(0, 1e-4, 2), rng.normal(0, 0.1, 2), rng.normal(0, 2, 2)
            taus, status = {}, {}
            for s, c in ctrls.items():
                c.reset(qa)
                taus[s] = c.step(qa, xd, v, a).copy()
                status[s] = c.status
            assert status["min_norm"] == status["min_max"] == "ok", status
            assert status["preload"] in ("ok", "preload_infeasible"), status
            u = S.T @ taus["min_norm"]
            for s in ("min_max", "preload"):
                scale = np.abs(S).max() * np.abs(taus[s]).max()
                assert np.abs(S.T @ taus[s] - u).max() <= 1e-12 * scale, (law.__name__, s)
            if status["preload"] == "ok":
                assert np.all(taus["preload"] >= 1.0 - 1e-9), taus["preload"]
            seen.add(status["preload"])
    assert "ok" in seen, seen


def test_two_legs_have_nothing_to_distribute():
    m = pm2dof.load_model(SHIPPED_MODELS / "fivebar.toml")
    q = m.ik([0.35, 0.45])
    for u in ([3.0, -2.0], [100.0, 50.0]):
        r = m.torque_splits(q, u, [30.0, 30.0], [0.5, 0.5], [1.0, 1.0])
        np.testing.assert_array_equal(r["min_max"], r["min_norm"])
        np.testing.assert_allclose(r["preload"], r["min_norm"], rtol=1e-12)
    traj = pm2dof.paper_move("low")
    a = pm2dof.simulate(m, pm2dof.NAController(m), traj)
    b = pm2dof.simulate(m, pm2dof.NAController(m, split="min_max"), traj)
    np.testing.assert_array_equal(a.tau_a, b.tau_a)


def test_saturated_min_max_reports_saturation_not_preload():
    m = pm2dof.load_model()
    q = m.ik([0.245, 0.265])
    S = m.S(q)
    u = S.T @ np.array([50.0, -50.0, 50.0])   # far beyond tau_max = 30 N*m in any split
    r = m.torque_splits(q, u)
    assert r["min_max_ratio"] > 1 and r["preload_mode"] == 2


@pytest.mark.parametrize("kwargs,match", [
    (dict(split="minmax"), "split must be one of"),
    (dict(split="preload", preload=[1.0, 1.0]),
     r"preload must be one finite number or 3 \(one per actuator\)"),
    (dict(split="preload", preload=[40.0, 1.0, 1.0]),
     r"preload\[0\] \(leg 1\) = 40.0 N m must be >= 0 and < tau_max = 30 N m"),
    (dict(split="preload", preload_sign=[1.0, 0.0, 1.0]),
     r"preload_sign\[1\] \(leg 2\) = 0.0 must be -1 or \+1"),
    (dict(tau_max=[30.0, -1.0, 30.0]), r"tau_max\[1\] \(leg 2\) = -1.0 N m must be in \(0, 1e\+06\]"),
])
def test_bad_split_settings_are_refused(kwargs, match):
    m = pm2dof.load_model()
    for law in (pm2dof.NAController, pm2dof.APDController):
        with pytest.raises(ValueError, match=match):
            law(m, **kwargs)


@pytest.mark.parametrize("control,key", [
    ('split = "fastest"', "control.split"),
    ("preload = [1.0, 1.0]", "control.preload"),
    ("preload = [1.0, -1.0, 1.0]", r"control\.preload \(leg 2\)"),   # legs count from 1
    ("preload = [1.0, 1.0, 31.0]", "control.preload"),
    ("preload_sign = [1, 2, 1]", "control.preload_sign"),
    ("mode = 3", "control"),
])
def test_model_file_control_section_is_validated(tmp_path, control, key):
    from pm2dof.core.model_file import read_model_file
    path = tmp_path / "m.toml"
    path.write_text((SHIPPED_MODELS / "shang2010.toml").read_text() + f"\n[control]\n{control}\n")
    with pytest.raises(pm2dof.ModelFileError, match=key):
        read_model_file(path)


def test_model_file_split_is_the_controllers_default(tmp_path):
    from pm2dof.core.model_file import read_model_file
    path = tmp_path / "m.toml"
    path.write_text((SHIPPED_MODELS / "shang2010.toml").read_text()
                    + '\n[control]\nsplit = "min_max"\npreload = [0.5, 0.5, 0.5]\n')
    spec = read_model_file(path)
    assert spec.control["split"] == "min_max" and spec.formulation_sha256 == \
        read_model_file(SHIPPED_MODELS / "shang2010.toml").formulation_sha256
    m = pm2dof.core.model.Model(spec, SHIPPED_GENERATED / "shang2010")
    assert pm2dof.NAController(m).split == "min_max"
    assert pm2dof.APDController(m, split="min_norm").function_name == "apd"


@pytest.mark.parametrize("n", [3, 4])
def test_min_max_with_parallel_legs_is_exact(n):
    """Degenerate poses the random cases never hit: two rows of S parallel (same or opposite
    direction), so two torques are free at the dual optimum. The derivation's min_max, as a
    CasADi function, against HiGHS; equal S^T tau and max |tau_i|/w_i = t* to rounding."""
    import casadi as ca

    from pm2dof.derive.splits import min_max
    Ssym, usym, wsym = ca.SX.sym("S", n, 2), ca.SX.sym("u", 2), ca.SX.sym("w", n)
    f = ca.Function("mm", [Ssym, usym, wsym], list(min_max(Ssym, usym, wsym)))
    rng = np.random.default_rng(7)
    hits = 0
    for k in range(200):
        S = rng.normal(size=(n, 2))
        S[1] = S[0] * rng.choice([-1.0, 1.0]) * rng.uniform(0.5, 2.0)   # parallel rows 0, 1
        w = rng.uniform(5.0, 30.0, n)
        u = S[0] * rng.normal() * 20 + rng.normal(size=2) * rng.choice([0.0, 1.0, 30.0])
        tau, t = (np.asarray(v, dtype=float).ravel() for v in f(S, u, w))
        t_lp = _lp_min_max(S, u, w)
        assert float(t[0]) == pytest.approx(t_lp, rel=1e-9, abs=1e-12), (S, u, w)
        assert np.abs(S.T @ tau - u).max() <= 1e-12 * (np.abs(S).max() * np.abs(tau).max()
                                                       + np.abs(u).max())
        assert np.max(np.abs(tau) / w) <= t_lp * (1 + 1e-9) + 1e-12
        both_free = abs(tau[0]) < w[0] * t_lp * (1 - 1e-6)
        hits += bool(both_free)
    assert hits >= 10, f"the degenerate branch (a free pair) was exercised only {hits} times"
