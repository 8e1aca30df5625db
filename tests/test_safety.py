# Safe behaviour on bad samples: controllers, the generated step, projection, rollouts, trajectory checks.
"""The controllers and the generated step functions on bad samples.

* A singular pose: ``on_singular="zero"`` returns exactly zero torque with status "singular"
  and theta_hat unchanged; the default raises SingularityError (a ValueError) carrying the
  measure. The next good sample gives a finite torque.
* Non-finite measured angles or references raise ValueError and leave the whole controller
  state as it was.
* A huge but finite sample whose result overflows inside the generated step: status
  "non_finite", zero torque, state unchanged; the next good sample gives a finite torque.
  Over random sequences of good and bad samples (hypothesis) theta_hat never becomes
  non-finite and every good sample gives a finite torque within the limits.
* Projection of theta_hat (``project=True``): every estimate of a rollout with a large
  Gamma stays physical (alpha, gamma >= 1e-6, beta^2 <= alpha gamma, friction >= 0), while the
  same run without projection (the default, as in the paper) leaves that set; the generated
  projected step equals ``pm2dof.reference.control.na_step(..., project=True)``.
* Rollouts count their bad and saturated samples consistently with ``status``.
* ``check_trajectory`` names the first offending sample and its time; ``line`` refuses
  non-positive limits.
"""
from __future__ import annotations

import math
import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import pm2dof
from pm2dof import (
    APDController,
    NAController,
    SingularityError,
    WorkspaceError,
    check_trajectory,
    simulate,
)
from pm2dof.control.trajectory import Trajectory, TrajectoryError, line, paper_move
from pm2dof.core.layout import Layout
from pm2dof.reference import control as rc
from pm2dof.reference import model as ref

M = pm2dof.load_model()
N = M.n_legs
P = len(M.param_names)
THR = M.singularity_threshold
TAU_MAX = np.asarray(M.spec.limits["tau_max"])
G = ref.Geometry.paper()
XE = np.array([0.245, 0.265])
QA = M.ik(XE)[:N].copy()
Z2 = np.zeros(2)
STATUS = dict(M.manifest["status_codes"])
MEASURE_RE = re.compile(r"min_i \|sin\(qb_i - qa_i\)\| = ([-+0-9.eE]+)")


def measure_at(xe):
    q = M.ik(xe)
    return float(np.min(np.abs(np.sin(q[N:] - q[:N]))))


def _find_singular_xe(lo, hi, seed=1):
    """A reachable xe with lo < min_i |sin(qb_i - qa_i)| < hi (fixed seed)."""
    rng = np.random.default_rng(seed)
    for _ in range(200000):
        xe = rng.uniform([0.0, 0.0], [0.45, 0.5])
        try:
            mu = measure_at(xe)
        except WorkspaceError:
            continue
        if lo < mu < hi:
            return xe, mu
    raise AssertionError(f"no reachable pose with {lo} < measure < {hi}")


XS, MU_S = _find_singular_xe(0.01, 0.8 * THR)
QA_S = M.ik(XS)[:N].copy()


def ready(cls=NAController, **kw):
    c = cls(M, **kw)
    c.reset(QA)
    c.step(QA, XE, Z2, Z2)
    return c


def same_state(a, b):
    return all(np.array_equal(a[k], b[k]) for k in a) and a.keys() == b.keys()


def test_status_codes():
    assert STATUS == {"ok": 0, "singular": 1, "saturated": 2, "non_finite": 3,
                      "preload_infeasible": 4, "inconsistent_encoders": 5}
    assert issubclass(SingularityError, ValueError)


# --------------------------------------------------------------------------------------
# 1. Singular pose
# --------------------------------------------------------------------------------------

@pytest.mark.parametrize("cls", [NAController, APDController])
def test_singular_pose_zero_torque_theta_unchanged_then_recovers(cls):
    c = ready(cls, on_singular="zero")
    before = c.state
    out = np.full(N, 7.0)
    tau = c.step(QA_S, XS, Z2, Z2, out=out)
    info = f"{cls.__name__} at xe={XS.tolist()} (measure {MU_S})"
    assert tau is out
    assert np.array_equal(tau, np.zeros(N)), f"not the safe torque zero: {tau}; {info}"
    assert c.status == "singular", info
    assert c.diag["sing"] == pytest.approx(MU_S, rel=1e-9), (c.diag["sing"], info)
    assert np.array_equal(c.state["theta_hat"], before["theta_hat"]), info
    # many singular samples in a row: still zero, theta_hat still unchanged
    for _ in range(5):
        assert not np.any(c.step(QA_S, XS, Z2, Z2)), info
        assert c.status == "singular"
    assert np.array_equal(c.state["theta_hat"], before["theta_hat"]), info
    # the next good sample: a finite torque within the limits, theta_hat finite
    tau = c.step(QA, XE, Z2, Z2)
    assert np.isfinite(tau).all() and np.all(np.abs(tau) <= TAU_MAX), f"{tau}; {info}"
    assert c.status in ("ok", "saturated"), c.status
    assert np.isfinite(c.state["theta_hat"]).all()
    # and a few more: back to an unsaturated torque once the velocity estimate settles
    for _ in range(3):
        tau = c.step(QA, XE, Z2, Z2)
    assert c.status == "ok" and np.isfinite(tau).all(), (c.status, tau, info)


@pytest.mark.parametrize("cls", [NAController, APDController])
def test_singular_pose_raises_by_default(cls):
    c = ready(cls)
    assert c.on_singular == "raise"
    before = c.state
    with pytest.raises(SingularityError) as info:
        c.step(QA_S, XS, Z2, Z2)
    assert isinstance(info.value, ValueError)
    msg = str(info.value)
    found = MEASURE_RE.search(msg)
    assert found and float(found.group(1)) == pytest.approx(MU_S, rel=1e-3), (msg, MU_S)
    assert str(THR) in msg, msg
    assert c.status == "singular"
    assert np.array_equal(c.state["theta_hat"], before["theta_hat"])
    tau = c.step(QA, XE, Z2, Z2)  # the next good sample
    assert np.isfinite(tau).all() and np.all(np.abs(tau) <= TAU_MAX), tau


def test_on_singular_is_validated():
    with pytest.raises(ValueError, match="on_singular"):
        NAController(M, on_singular="ignore")


def test_singular_threshold_boundary_is_respected_by_the_step():
    """The step's singular decision agrees with Model.W's at the sampled near-singular pose:
    both refuse it, and both accept the regular pose."""
    with pytest.raises(SingularityError):
        M.W(M.ik(XS))
    assert np.isfinite(M.W(M.ik(XE))).all()
    assert measure_at(XS) < THR <= measure_at(XE)


# --------------------------------------------------------------------------------------
# 2. Non-finite inputs: ValueError, state unchanged
# --------------------------------------------------------------------------------------

@pytest.mark.parametrize("cls", [NAController, APDController])
@pytest.mark.parametrize("arg", range(4), ids=["qa", "xd", "xd_dot", "xd_ddot"])
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf], ids=["nan", "inf", "-inf"])
def test_non_finite_inputs_raise_and_leave_the_state(cls, arg, bad):
    c = ready(cls, on_singular="zero")
    c.step(QA, XE + [1e-3, 0], Z2, Z2)  # a non-trivial state (v != 0, theta_hat moved)
    before = c.state
    status_before = c.status
    args = [QA.copy(), XE.copy(), np.array([0.1, 0.0]), np.array([0.0, 1.0])]
    args[arg][-1] = bad
    names = ["qa", "xd", "xd_dot", "xd_ddot"]
    with pytest.raises(ValueError) as info:
        c.step(*args)
    assert names[arg] in str(info.value), str(info.value)
    assert same_state(c.state, before), f"state changed by a refused sample: {c.state} {before}"
    assert c.status == status_before
    tau = c.step(QA, XE, Z2, Z2)
    assert np.isfinite(tau).all(), tau


def test_step_argument_errors_are_clear():
    c = ready(on_singular="zero")
    before = c.state
    for args, name in [((QA[:2], XE, Z2, Z2), "qa"), ((QA, XE[:1], Z2, Z2), "xd"),
                       ((QA, XE, "ab", Z2), "xd_dot"), ((QA, XE, Z2, None), "xd_ddot"),
                       ((QA, XE, Z2, [0.0, 1j]), "xd_ddot")]:   # float32, lists: converted
        with pytest.raises((ValueError, TypeError)) as info:
            c.step(*args)
        assert name in str(info.value), (name, str(info.value))
        assert same_state(c.state, before)
    with pytest.raises((ValueError, TypeError)) as info:
        c.step(QA, XE, Z2, Z2, out=np.empty(N + 1))
    assert "tau_a" in str(info.value) or "out" in str(info.value), str(info.value)
    assert same_state(c.state, before)
    with pytest.raises(pm2dof.NotResetError, match="reset") as info:   # a RuntimeError too
        NAController(M).step(QA, XE, Z2, Z2)
    assert isinstance(info.value, RuntimeError)


# --------------------------------------------------------------------------------------
# 3. Non-finite intermediate inside the generated step
# --------------------------------------------------------------------------------------

HUGE_CASES = {
    "xd_ddot=1e308": (dict(), (QA, XE, Z2, np.array([1e308, 1e308]))),
    "xd_dot=1e308": (dict(), (QA, XE, np.array([1e308, -1e308]), Z2)),
    "xd=1e308": (dict(), (QA, np.array([1e308, 1e308]), Z2, Z2)),
    "Q=1e308": (dict(Q=[1e308, 1e308]), (QA, XE + [1e-3, -1e-3], Z2, Z2)),
    "Kd=1e308": (dict(Kd=[1e308, 1e308]), (QA, XE, np.array([0.2, 0.1]), Z2)),
}


@pytest.mark.parametrize("case", sorted(HUGE_CASES))
def test_overflow_inside_the_step_gives_non_finite_status(case):
    kw, args = HUGE_CASES[case]
    c = ready(on_singular="zero", **kw)
    before = c.state
    tau = c.step(*args)
    assert c.status == "non_finite", f"{case}: status {c.status}, tau {tau}"
    assert np.array_equal(tau, np.zeros(N)), f"{case}: not the safe torque: {tau}"
    assert same_state(c.state, before), f"{case}: state changed: {c.state} vs {before}"
    assert np.isfinite(c.state["theta_hat"]).all()
    if not kw:  # with the gains themselves huge every moving sample overflows; else recover
        tau = c.step(QA, XE, Z2, Z2)
        assert np.isfinite(tau).all() and c.status in ("ok", "saturated"), (case, tau, c.status)


def test_apd_overflow_gives_non_finite_status():
    c = ready(APDController, on_singular="zero")
    before = c.state
    tau = c.step(QA, XE, Z2, np.array([1e308, -1e308]))
    assert c.status == "non_finite" and not np.any(tau), (c.status, tau)
    assert same_state(c.state, before)
    assert np.isfinite(c.step(QA, XE, Z2, Z2)).all()


SAMPLE_KINDS = ["good", "good_moving", "singular", "nan_qa", "inf_xd", "nan_xd_dot",
                "inf_xd_ddot", "huge_xd_ddot", "huge_xd_dot", "huge_xd", "big_xd_ddot"]


def _sample(kind, k):
    wiggle = np.array([1e-4 * math.sin(k), 1e-4 * math.cos(k)])
    qa, xd, xdd, xddd = QA.copy(), XE.copy(), Z2.copy(), Z2.copy()
    if kind == "good_moving":
        xd, xdd, xddd = XE + wiggle, np.array([0.2, -0.1]), np.array([2.0, 1.0])
    elif kind == "singular":
        qa, xd = QA_S.copy(), XS.copy()
    elif kind == "nan_qa":
        qa[k % N] = np.nan
    elif kind == "inf_xd":
        xd[k % 2] = np.inf
    elif kind == "nan_xd_dot":
        xdd[k % 2] = np.nan
    elif kind == "inf_xd_ddot":
        xddd[k % 2] = -np.inf
    elif kind == "huge_xd_ddot":
        xddd[:] = 1e308
    elif kind == "huge_xd_dot":
        xdd[:] = [1e308, -1e308]
    elif kind == "huge_xd":
        xd[:] = -1e308
    elif kind == "big_xd_ddot":  # finite, does not overflow: saturates, theta_hat moves far
        xddd[:] = [1e250, 0.0]
    return qa, xd, xdd, xddd


@settings(derandomize=True, max_examples=120, deadline=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(seq=st.lists(st.sampled_from(SAMPLE_KINDS), min_size=1, max_size=25),
       law=st.sampled_from(["na", "apd", "na_proj"]))
def test_random_bad_sample_sequences_are_safe(seq, law):
    """Each bad sample: ValueError (state unchanged) or the safe torque zero (status singular
    / non_finite, theta_hat unchanged) or a finite, clipped torque; theta_hat always finite;
    every good sample gives a finite torque within tau_max."""
    c = (APDController(M, on_singular="zero") if law == "apd" else
         NAController(M, on_singular="zero", project=(law == "na_proj")))
    c.reset(QA)
    for k, kind in enumerate(seq + ["good"]):
        before = c.state
        args = _sample(kind, k)
        info = f"{law} sample {k} ({kind}) of {seq}"
        try:
            tau = c.step(*args)
        except ValueError as exc:
            assert kind.startswith(("nan", "inf")), f"{info}: unexpected {exc}"
            assert not isinstance(exc, SingularityError), info
            assert same_state(c.state, before), f"{info}: refused sample changed the state"
            continue
        assert not kind.startswith(("nan", "inf")), f"{info}: non-finite input accepted: {tau}"
        assert np.isfinite(c.state["theta_hat"]).all(), f"{info}: theta_hat {c.state}"
        assert np.isfinite(tau).all() and np.all(np.abs(tau) <= TAU_MAX), f"{info}: {tau}"
        if c.status in ("singular", "non_finite"):
            assert np.array_equal(tau, np.zeros(N)), f"{info}: {c.status} but tau {tau}"
            assert np.array_equal(c.state["theta_hat"], before["theta_hat"]), info
        if c.status == "non_finite":
            assert same_state(c.state, before), info
        if kind == "singular":
            assert c.status == "singular", f"{info}: status {c.status}"
        if kind.startswith("huge"):
            assert c.status == "non_finite", f"{info}: status {c.status}"
        if kind.startswith("good"):
            assert c.status in ("ok", "saturated"), f"{info}: status {c.status}"


# --------------------------------------------------------------------------------------
# 4. Projection of theta_hat
# --------------------------------------------------------------------------------------

def physical_violations(th, n=N):
    th = np.atleast_2d(th)
    a, b, g, f = th[:, :n], th[:, n:2 * n], th[:, 2 * n:3 * n], th[:, 3 * n:]
    return {"alpha < 1e-6": int(np.sum(a < 1e-6)), "gamma < 1e-6": int(np.sum(g < 1e-6)),
            "beta^2 > alpha gamma": int(np.sum(b * b > a * g * (1 + 1e-12))),
            "friction < 0": int(np.sum(f < 0))}


GAMMA = np.asarray(M.spec.gains["na"]["Gamma"])


@pytest.mark.parametrize("mult", [1e3, 1e4])
def test_projection_keeps_theta_hat_physical_in_a_rollout(mult):
    traj = paper_move("high")
    runs = {proj: simulate(M, NAController(M, Gamma=GAMMA * mult, project=proj), traj,
                           quantise=False, settle_time=0.2) for proj in (False, True)}
    free, proj = physical_violations(runs[False].theta_hat), physical_violations(runs[True].theta_hat)
    assert sum(free.values()) > 0, f"Gamma x {mult:g}: the unprojected run never left the " \
                                   f"physical set ({free}): the test shows nothing"
    assert sum(proj.values()) == 0, f"Gamma x {mult:g}: projected run violates {proj}"
    for r in runs.values():
        assert np.isfinite(r.theta_hat).all() and np.isfinite(r.xe).all()
    th = runs[True].theta_hat  # the bounds themselves, explicitly
    a, b, g, f = th[:, :N], th[:, N:2 * N], th[:, 2 * N:3 * N], th[:, 3 * N:]
    assert a.min() >= 1e-6 and g.min() >= 1e-6 and f.min() >= 0.0
    assert np.all(b * b <= a * g * (1 + 1e-12)), np.max(b * b - a * g)


def test_projection_is_off_by_default():
    c = NAController(M)
    assert c.project is False
    assert c.function_name == "na"


def test_projection_is_the_identity_inside_the_physical_set():
    """With the paper's gains the estimates stay physical: projected and unprojected rollouts
    are bit for bit the same."""
    traj = paper_move("low")
    a = simulate(M, NAController(M), traj, quantise=False)
    b = simulate(M, NAController(M, project=True), traj, quantise=False)
    assert sum(physical_violations(a.theta_hat).values()) == 0
    assert np.array_equal(a.theta_hat, b.theta_hat) and np.array_equal(a.tau_a, b.tau_a)


def _c_step(name, state, qa, xd, xd_dot, xd_ddot, params):
    tau, sn, st, dg = np.empty(N), np.empty(len(state)), np.empty(1), np.empty(10)
    M.function(f"{name}_step")(*(np.ascontiguousarray(a, dtype=float) for a in
                                 (state, qa, xd, xd_dot, xd_ddot, params)), tau, sn, st, dg)
    return tau, sn, int(st[0]), dg


def _projection_case(rng):
    """A step whose update leaves the physical set: some estimates start outside it."""
    lays = {k: Layout(k, v) for k, v in M.manifest["layouts"].items()}
    theta = np.array(M.theta_nominal) * rng.uniform(0.5, 1.5, P)
    theta[N + rng.integers(N)] = 0.3            # beta_i^2 >> alpha_i gamma_i
    theta[3 * N + rng.integers(2 * N)] = -0.2   # a negative friction parameter
    theta[rng.integers(N)] = -0.01              # a negative alpha_i
    theta[2 * N + rng.integers(N)] = 1e-9       # gamma_i below the floor
    xe_prev = XE + rng.normal(0, 1e-3, 2)
    state = lays["ctrl_state"].pack(xe_prev=xe_prev, v=rng.normal(0, 0.2, 2), theta_hat=theta)
    params = lays["na_params"].pack(Kd=[195.0, 195.0], Q=[280.0, 280.0],
                                    Gamma=rng.uniform(0, 0.02, P), freeze_saturated=0.0,
                                    T=0.002, vel_alpha=1.0,
                                    sing_threshold=THR, parallel_sing_threshold=THR,
                                    tau_max=np.full(N, 1e3), preload_sign=np.ones(N),
                                    preload=np.zeros(N), closure_tol=M.closure_tolerance)
    qa = rc.measure(G, XE, 0.0)
    xd = XE + rng.normal(0, 2e-3, 2)
    return state, qa, xd, rng.normal(0, 0.3, 2), rng.normal(0, 5, 2), params


def test_generated_projected_step_equals_the_reference():
    rng = np.random.default_rng(7)
    for i in range(20):
        args = _projection_case(rng)
        tau_c, sn_c, st_c, _ = _c_step("na_proj", *args)
        tau_r, sn_r, st_r, _ = rc.na_step(G, *args, project=True)
        info = f"case {i}: state={args[0].tolist()} qa={args[1].tolist()} xd={args[2].tolist()}"
        assert st_c == st_r == STATUS["ok"], (st_c, st_r, info)
        th_c, th_r = sn_c[4:], sn_r[4:]
        assert sum(physical_violations(th_c).values()) == 0, (th_c, info)
        assert sum(physical_violations(args[0][4:]).values()) > 0  # it started outside
        err = np.max(np.abs(th_c - th_r))
        assert err <= 1e-12 * np.max(np.abs(th_r)), f"theta_hat: C {th_c} ref {th_r} ({err:.3e}); {info}"
        err = np.max(np.abs(tau_c - tau_r))
        assert err <= 1e-12 * (1 + np.max(np.abs(tau_r))), f"tau: C {tau_c} ref {tau_r}; {info}"
        err = np.max(np.abs(sn_c[:4] - sn_r[:4]))
        assert err <= 1e-12 * (1 + np.max(np.abs(sn_r[:4]))), f"xe_prev, v: {sn_c[:4]} {sn_r[:4]}"
        # the projected step = the plain step followed by the projection, both in C
        tau_p, sn_p, st_p, _ = _c_step("na", *args)
        assert np.array_equal(tau_p, tau_c), "projection changed this sample's torque"
        proj = rc.project_theta(sn_p[4:], N)
        assert np.max(np.abs(proj - th_c)) <= 1e-15 * np.max(np.abs(proj)), (proj, th_c)
        assert not np.array_equal(sn_p[4:], th_c), f"projection did nothing in {info}"


def test_reference_projection_rules():
    th = np.array(M.theta_nominal, dtype=float)
    th[0], th[N], th[2 * N] = -1.0, 0.5, 0.04       # alpha1 < 0, beta1 large, gamma1 ok
    th[N + 1] = -0.5                                 # beta2 very negative
    th[3 * N] = -3.0                                 # fv1 < 0
    p = rc.project_theta(th, N)
    assert p[0] == rc.PROJECTION_FLOOR == 1e-6
    assert p[N] == pytest.approx(math.sqrt(1e-6 * 0.04), rel=1e-15)
    assert p[N + 1] == pytest.approx(-math.sqrt(th[1] * th[2 * N + 1]), rel=1e-15)
    assert p[3 * N] == 0.0
    keep = [k for k in range(P) if k not in (0, N, N + 1, 3 * N)]
    assert np.array_equal(p[keep], th[keep])


# --------------------------------------------------------------------------------------
# 5. Rollouts: counts consistent with status
# --------------------------------------------------------------------------------------

def _check_counts(r, info):
    st_ = r.status
    assert set(np.unique(st_)) <= {0, 1, 2, 3}, (np.unique(st_), info)
    counts = np.bincount(st_, minlength=4)
    assert (r.n_singular, r.n_saturated, r.n_non_finite) == (counts[1], counts[2], counts[3]), info
    assert counts.sum() == len(r.t)


@pytest.mark.parametrize("cls", [NAController, APDController])
def test_small_tau_max_saturates_and_is_counted(cls):
    tmax = np.full(N, 1.0)
    r = simulate(M, cls(M, tau_max=tmax), paper_move("low"), quantise=False)
    info = cls.__name__
    _check_counts(r, info)
    assert r.n_saturated > 0, info
    assert np.all(np.abs(r.tau_a) <= tmax), info
    sat = r.status == 2
    assert np.all(np.max(np.abs(r.tau_a[sat]), axis=1) == 1.0), "saturated sample off the limit"
    assert r.n_singular == 0 and r.n_non_finite == 0, info
    r0 = simulate(M, cls(M), paper_move("low"), quantise=False)  # default limits: no saturation
    _check_counts(r0, info)
    assert r0.n_saturated == 0 and r0.n_singular == 0 and r0.n_non_finite == 0, info
    assert np.all(r0.status == 0)


def test_non_finite_samples_in_a_rollout_are_counted_and_safe():
    r = simulate(M, NAController(M, Q=[1e308, 1e308]), paper_move("low"), quantise=False)
    _check_counts(r, "Q = 1e308")
    assert r.n_non_finite > 0
    bad = np.flatnonzero(r.status == 3)
    assert not np.any(r.tau_a[bad]), "non-finite samples must output zero torque"
    for k in bad:
        prev = r.theta_hat[k - 1] if k > 0 else np.asarray(M.theta_nominal)
        assert np.array_equal(r.theta_hat[k], prev), f"theta_hat changed at bad sample {k}"
    assert np.isfinite(r.theta_hat).all() and np.isfinite(r.xe).all()


# --------------------------------------------------------------------------------------
# 6. Trajectories are checked before they run
# --------------------------------------------------------------------------------------

START = (0.22, 0.29)


def _first_bad(traj):
    """(k, kind, detail) of the first sample that is unreachable or singular (independent of
    check_trajectory: Model.ik and the measure)."""
    for k, x in enumerate(traj.xd):
        try:
            mu = measure_at(x)
        except WorkspaceError as exc:
            return k, "workspace", str(exc)
        if mu < THR:
            return k, "singular", mu
    return None


def _singular_line():
    """A straight line from the paper's start whose first bad sample is singular, not out of
    reach (a deterministic search)."""
    for ang in np.linspace(0, 2 * np.pi, 73)[:-1]:
        for dist in (0.1, 0.15, 0.2, 0.25):
            end = np.array(START) + dist * np.array([np.cos(ang), np.sin(ang)])
            traj = line(START, end, v_max=0.5, a_max=10.0, j_max=400.0)
            bad = _first_bad(traj)
            if bad and bad[1] == "singular" and bad[0] > 0:
                return traj, bad
    raise AssertionError("no line from the start into a singular region found")


def test_line_into_a_singular_region_is_refused_before_it_runs():
    traj, (k, _, mu) = _singular_line()
    with pytest.raises(SingularityError) as info:
        check_trajectory(M, traj)
    msg = str(info.value)
    assert f"sample {k} " in msg, f"expected sample {k} in {msg}"
    assert f"t = {traj.t[k]:.4f} s" in msg, msg
    found = MEASURE_RE.search(msg)
    assert found and float(found.group(1)) == pytest.approx(mu, rel=1e-3), (msg, mu)
    with pytest.raises(SingularityError):  # simulate checks it too, before any step
        simulate(M, NAController(M), traj)


def _unreachable_legs(x):
    return [i + 1 for i, leg in enumerate(M.spec.legs)
            if not abs(leg.la - leg.lb) <= np.hypot(*(np.asarray(x) - leg.base)) <= leg.la + leg.lb]


@pytest.mark.parametrize("start, end, k", [
    ((0.9, 0.29), START, 0),          # a line that starts out of reach: sample 0
])
def test_line_out_of_reach_is_refused_naming_the_leg(start, end, k):
    traj = line(start, end, v_max=0.5, a_max=10.0, j_max=400.0)
    with pytest.raises(WorkspaceError) as info:
        check_trajectory(M, traj)
    msg = str(info.value)
    legs = _unreachable_legs(traj.xd[k])
    assert legs, traj.xd[k]
    assert f"sample {k} " in msg and f"t = {traj.t[k]:.4f} s" in msg, msg
    assert re.search(rf"leg {legs[0]}\b", msg), f"expected leg {legs[0]} in {msg}"
    assert "distance" in msg, msg
    with pytest.raises(WorkspaceError):  # simulate checks it before any step
        simulate(M, NAController(M), traj)


def test_sample_jumping_out_of_reach_is_refused_naming_the_leg():
    """A sampled trajectory whose second sample is far out of reach (no singular sample in
    between to be caught first)."""
    far = (1.5, 0.29)
    traj = Trajectory(t=[0.0, 0.002], xd=[START, far], xd_dot=np.zeros((2, 2)),
                      xd_ddot=np.zeros((2, 2)), period=0.002)
    with pytest.raises(WorkspaceError) as info:
        check_trajectory(M, traj)
    msg = str(info.value)
    legs = _unreachable_legs(far)
    assert "sample 1 " in msg and "t = 0.0020 s" in msg, msg
    assert re.search(rf"leg {legs[0]}\b", msg) and "distance" in msg, msg


def test_non_finite_trajectory_is_refused():
    good = paper_move("low")
    xd = np.array(good.xd)
    xd[5, 1] = np.nan
    bad = Trajectory(good.t, xd, good.xd_dot, good.xd_ddot, good.period)
    with pytest.raises(ValueError, match="sample 5"):
        check_trajectory(M, bad)


def test_paper_moves_pass_the_check():
    for speed in ("low", "high"):
        check_trajectory(M, paper_move(speed))  # no exception


@pytest.mark.parametrize("kw", [dict(v_max=0.0), dict(v_max=-0.2), dict(a_max=0.0),
                                dict(a_max=-5.0), dict(j_max=0.0), dict(j_max=-1.0),
                                dict(v_max=math.nan), dict(a_max=math.inf), dict(period=0.0),
                                dict(period=-0.002), dict(v_max="fast")])
def test_line_refuses_non_positive_limits(kw):
    args = dict(start=START, end=(0.27, 0.24), v_max=0.2, a_max=5.0, j_max=200.0)
    args.update(kw)
    with pytest.raises(TrajectoryError) as info:
        line(**args)
    name = next(iter(kw))
    assert name in str(info.value), str(info.value)
    assert isinstance(info.value, ValueError)
