# Gains the stability proof allows, rollouts that end (never NaN), controller vs model, step inputs.
"""Controller gains, rollout outcomes, the controller's model and the step's inputs.

* Gains outside Sect. 4's conditions (K_d, Q > 0, Gamma >= 0) or eq. 40's (Kp, Kv > 0), not
  finite, of the wrong shape or not diagonal raise :class:`pm2dof.GainError` naming the gain,
  the entry and the condition; the accepted forms (scalar, diagonal, diagonal matrix) pack the
  same parameters.
* A rollout whose true pose leaves the workspace ends there with ``outcome`` "left_workspace",
  the sample and the time, and no field of its SimResult is NaN. The truncation point and the
  stated pose are checked against the raw C rollout and plain geometry (distance to each base
  against la + lb), not against the code that decides them. Study rows agree with simulate().
* A controller built for another model raises ModelMismatchError naming both models.
* ``step`` accepts array-likes and gives the same torque as with float64 arrays.
"""
import dataclasses
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof import (
    APDController,
    GainError,
    ModelMismatchError,
    NAController,
    OutcomeWarning,
    paper_move,
    simulate,
)
from pm2dof.control.plant import plant_vector
from pm2dof.control.simulate import rollout_inputs

M = pm2dof.load_model()
N = M.n_legs
P = len(M.param_names)
MODELS = Path(M.spec.path).parent
TRAJ = paper_move("high")
GAMMA = np.asarray(M.spec.gains["na"]["Gamma"], dtype=float)


# --------------------------------------------------------------------------------------
# 1. gains: refused at construction, with the gain, the entry and the condition
# --------------------------------------------------------------------------------------

def _neg(k, v=-1.0):
    g = GAMMA.copy()
    g[k] = v
    return g


@pytest.mark.parametrize("cls, kw, text", [
    (NAController, {"Q": [-280.0, 280.0]}, r"Q\[0\] \(x\) = -280.0 must be > 0: Q must be positive definite"),
    (NAController, {"Q": [280.0, 0.0]}, r"Q\[1\] \(y\) = 0.0 must be > 0"),
    (NAController, {"Gamma": -np.ones(P)}, r"Gamma\[0\] \(alpha1\) = -1.0 must be >= 0 \(and 14 more"),
    (NAController, {"Gamma": _neg(9)}, r"Gamma\[9\] \(fv1\) = -1.0 must be >= 0: Gamma must be positive semi-definite"),
    (NAController, {"Gamma": _neg(3, math.inf)}, r"Gamma\[3\] \(beta1\) = inf must be finite"),
    (NAController, {"Kd": [-50.0, 50.0]}, r"Kd\[0\] \(x\) = -50.0 must be > 0: K_d must be positive definite"),
    (NAController, {"Kd": -195.0}, r"Kd\[0\] \(x\) = -195.0 must be > 0 \(and 1 more"),
    (NAController, {"Kd": [195.0, math.nan]}, r"Kd\[1\] \(y\) = nan must be finite"),
    (NAController, {"Kd": [[195.0, 1.0], [0.0, 195.0]]}, r"Kd must be diagonal .* entry \[0, 1\] = 1.0"),
    (NAController, {"Gamma": GAMMA[:-1]}, rf"Gamma must be a scalar, {P} diagonal entries \(alpha1, .*fc3\) .* got shape \({P - 1},\)"),
    (NAController, {"Q": np.ones((2, 2, 1))}, r"Q must be a scalar, 2 diagonal entries \(x, y\).*got shape \(2, 2, 1\)"),
    (NAController, {"Q": "fast"}, r"Q must be real numbers, got 'fast'"),
    (NAController, {"Q": [1j, 1.0]}, r"Q must be real numbers.*complex"),
    (APDController, {"Kp": 0.0}, r"APDController: Kp\[0\] \(x\) = 0.0 must be > 0 .*APD \(eq. 40\) needs Kp"),
    (APDController, {"Kv": [300.0, -1.0]}, r"APDController: Kv\[1\] \(y\) = -1.0 must be > 0"),
    (APDController, {"Kp": [35000.0, math.inf]}, r"Kp\[1\] \(y\) = inf must be finite"),
])
def test_gains_outside_the_stability_conditions_are_refused(cls, kw, text):
    with pytest.raises(GainError, match=text) as info:
        cls(M, **kw)
    assert isinstance(info.value, ValueError)


def test_accepted_gain_forms_pack_the_same_parameters():
    lay = NAController(M).params_layout
    ref = lay.unpack(NAController(M, Kd=[195.0, 195.0], Q=[280.0, 300.0], Gamma=GAMMA).params)
    for kw in ({"Kd": 195.0}, {"Kd": np.diag([195.0, 195.0])}, {"Kd": (195, 195)}):
        got = lay.unpack(NAController(M, Q=[280.0, 300.0], Gamma=GAMMA, **kw).params)
        assert np.array_equal(got["Kd"], ref["Kd"]), (kw, got["Kd"])
    got = lay.unpack(NAController(M, Q=np.diag([280.0, 300.0])).params)
    assert got["Q"].tolist() == [280.0, 300.0]
    # Gamma >= 0 is enough: zeros switch adaptation off (Table 3's "NA G=0" run)
    r = simulate(M, NAController(M, Gamma=np.zeros(P)), TRAJ)
    assert r.outcome == "completed" and np.array_equal(r.theta_hat[-1], M.theta_nominal)
    g = NAController(M, Gamma=np.diag(GAMMA)).params
    assert np.array_equal(lay.unpack(g)["Gamma"], GAMMA)


def test_non_finite_initial_estimates_are_refused():
    bad = np.array(M.theta_nominal, dtype=float)
    bad[4] = math.nan
    with pytest.raises(ValueError, match="theta0 must be 15 finite numbers"):
        NAController(M, theta0=bad)
    c = NAController(M)
    with pytest.raises(ValueError, match="theta_hat0 must be 15 finite numbers"):
        simulate(M, c, TRAJ, theta_hat0=bad)
    with pytest.raises(ValueError, match="theta_hat must be 15 finite numbers"):
        c.reset(M.ik(TRAJ.xd[0])[:N], theta_hat=bad)
    with pytest.raises(ValueError, match="theta_hat0 must be 15 finite numbers"):
        simulate(M, c, TRAJ, theta_hat0=bad[:-1])


# --------------------------------------------------------------------------------------
# 2. rollouts that leave the workspace: an explicit outcome, never a NaN
# --------------------------------------------------------------------------------------

# admissible gains (> 0) that the 2 ms sampling cannot hold once the torque limits are lifted:
# the loop goes unstable and throws the tip out of the workspace within a few samples
UNSTABLE = [("na", lambda: NAController(M, Kd=1e4, tau_max=np.full(N, 1e6))),
            ("apd", lambda: APDController(M, Kp=1e6, tau_max=np.full(N, 1e6)))]


def _no_nan_anywhere(r, info):
    for f in dataclasses.fields(r):
        v = getattr(r, f.name)
        if isinstance(v, np.ndarray):
            assert np.isfinite(v).all(), f"{info}: SimResult.{f.name} has non-finite values"
        elif isinstance(v, float):
            assert not math.isnan(v), f"{info}: SimResult.{f.name} is NaN"
    for name in ("rmse", "peak_tau", "e"):
        v = np.asarray(getattr(r, name))
        assert not np.isnan(v).any(), f"{info}: SimResult.{name} is NaN"


def _out_of_reach(xe):
    """Legs (1-based) whose base is farther from xe than la + lb or nearer than |la - lb|."""
    return [i + 1 for i, leg in enumerate(M.spec.legs)
            if not abs(leg.la - leg.lb) <= math.dist(xe, leg.base) <= leg.la + leg.lb]


@pytest.mark.parametrize("name, make", UNSTABLE, ids=[u[0] for u in UNSTABLE])
def test_a_run_that_leaves_the_workspace_ends_with_its_outcome(name, make):
    ctrl = make()
    with pytest.warns(OutcomeWarning, match="left_workspace during sample"):
        r = simulate(M, ctrl, TRAJ, settle_time=0.5)
    _no_nan_anywhere(r, name)
    assert r.outcome == "left_workspace", (name, r.outcome, r.outcome_reason)
    k = r.failed_sample
    assert k == len(r.t) - 1 == len(r.xe) - 1 == len(r.theta_hat) - 1 and k >= 1, (name, k)
    assert r.t[k] <= r.failed_time <= r.t[k] + ctrl.sample_period, (name, r.failed_time)
    assert r.rmse == math.inf and r.final_state is None and r.n_move <= len(r.t)
    # every pose held is in reach of every leg (plain geometry), the stated one is not
    assert all(not _out_of_reach(x) for x in r.xe), name
    stated = [float(v) for v in r.outcome_reason.split("xe = [")[1].split("]")[0].split(",")]
    legs = _out_of_reach(stated)
    assert legs and f"out of reach of leg {legs[0]}" in r.outcome_reason, (name, r.outcome_reason)
    assert f"sample {k} (t = {r.t[k]:.4f} s)" in r.outcome_message
    # against the raw C rollout: the rows held are its first rows, bit for bit, and the next
    # row is not a state (non-finite, or a pose out of reach)
    f, x, u, p, ylay = rollout_inputs(M, ctrl, TRAJ.extended(0.5), plant_vector(M))
    y = np.empty((len(u), ylay.size))
    f.accumulate(x, u, p, y)
    Y = ylay.unpack(y)
    assert np.array_equal(Y["xe"][:k + 1], r.xe) and np.array_equal(Y["tau_a"][:k + 1], r.tau_a)
    assert np.array_equal(Y["theta_hat"][:k + 1], r.theta_hat), name
    nxt = y[k + 1]
    assert not np.isfinite(nxt).all() or _out_of_reach(Y["xe"][k + 1]), (name, nxt)
    assert not np.isfinite(y).all(), f"{name}: the raw rollout was expected to go non-finite"


def test_a_state_that_overflows_at_a_reachable_pose_is_diverged():
    from pm2dof.control.outcome import classify_failure
    xe = np.array([0.245, 0.265])                       # well inside the workspace
    plant, T, sub = plant_vector(M), 0.002, M.spec.rk4_substeps
    # 1e200 m/s: the velocity-squared (Coriolis) terms overflow at the very first RK4 stage
    got = classify_failure(M, xe, np.array([1e200, 0.0]), np.zeros(N), plant, T, sub, 0.1)
    assert got[:2] == ("diverged", 0.1), got
    assert "every leg reaches" in got[2] and str(xe.tolist()) in got[2], got
    # at rest with a finite torque nothing fails: the replay says so instead of guessing
    got = classify_failure(M, xe, np.zeros(2), np.ones(N), plant, T, sub, 0.1)
    assert got[:2] == ("diverged", 0.1 + T) and "a replay of this sample stays finite" in got[2]


def test_completed_runs_are_unchanged_and_do_not_warn():
    with warnings.catch_warnings():
        warnings.simplefilter("error", OutcomeWarning)
        r = simulate(M, NAController(M), TRAJ, settle_time=0.02)
    assert (r.outcome, r.failed_sample, r.failed_time) == ("completed", None, None)
    assert len(r.t) == len(TRAJ.extended(0.02).t) and r.n_move == len(TRAJ.t)
    assert np.isfinite(r.final_state).all() and 0 < r.rmse < 1e-3
    _no_nan_anywhere(r, "paper's NA")


def test_study_rows_follow_the_outcome(tmp_path):
    from pm2dof.studies import read_study, rollout_setup, run_chunk
    p = tmp_path / "s.toml"
    p.write_text(f"""
[study]
name = "unstable"
model = "{M.spec.path}"
moves = ["high"]
seed = 3
draws = 2
runs = 2

[[controllers]]
name = "na_unstable"
law = "na"
Kd = 1e4
tau_max = 1e6

[[controllers]]
name = "apd"
law = "apd"

[uncertainty]
payload_mass = {{uniform = [0.0, 0.5]}}
""")
    s = read_study(p)
    rows = {k: np.concatenate([run_chunk(s, i)[k] for i in range(s.n_chunks)])
            for k in run_chunk(s, 0)}
    seen = set()
    for c, m, d in (s.unit(u) for u in range(s.n_units)):
        theta = None
        for run in range(s.runs):
            model, ctrl, traj, truth, counts, _, _ = rollout_setup(s, c, m, d, run)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", OutcomeWarning)
                r = simulate(model, ctrl, traj, truth=truth, encoder_counts_per_rev=counts,
                             theta_hat0=theta, quantise=s.quantise)
            theta = r.theta_hat[-1].copy()
            i = s.rollout(c, m, d, run)
            info = (s.variants[c].name, d, run, r.outcome)
            seen.add(r.outcome)
            assert rows["diverged"][i] == (r.outcome != "completed"), info
            assert rows["rmse"][i] == r.rmse, info
            got = [rows[k][i] for k in ("peak_tau", "n_saturated", "n_singular", "n_non_finite")]
            assert got == [r.peak_tau, r.n_saturated, r.n_singular, r.n_non_finite], (info, got)
            assert not np.isnan(rows["rmse"][i]) and not np.isnan(rows["max_error"][i]), info
    assert seen == {"completed", "left_workspace"}, seen


def test_cli_prints_the_outcome(tmp_path, capsys):
    from pm2dof import cli
    text = Path(M.spec.path).read_text()
    edited = text.replace("tau_max = [30.0, 30.0, 30.0]", "tau_max = [1e6, 1e6, 1e6]", 1) \
                 .replace("Kd = [195.0, 195.0]", "Kd = [1e4, 1e4]", 1)
    assert edited.count("1e6") == 3 and "1e4, 1e4" in edited, "model file layout changed"
    p = tmp_path / "unstable.toml"
    p.write_text(edited)
    gen = Path(M.library).parent      # the same formulation: gains and limits are run time
    assert cli.main(["table3", "--model", str(p), "--generated", str(gen)]) == 0
    out, err = capsys.readouterr()
    assert "nan" not in out.lower(), out
    assert "pm2dof: warning: simulate (na, model 'shang2010'): left_workspace during sample" \
        in err, err
    assert "out of reach of leg" in err


# --------------------------------------------------------------------------------------
# 3. a controller built for another model
# --------------------------------------------------------------------------------------

@pytest.mark.parametrize("other", ["fourleg", "shang2010_smooth"])
def test_a_controller_of_another_model_is_refused(other):
    m2 = pm2dof.load_model(MODELS / f"{other}.toml")
    ctrl = NAController(M)
    with pytest.raises(ModelMismatchError,
                       match=rf"NAController was built for model 'shang2010' \({N} legs, .*not "
                             rf"for model '{other}' \({m2.n_legs} legs") as info:
        simulate(m2, ctrl, TRAJ)
    assert isinstance(info.value, ValueError)
    with pytest.raises(ModelMismatchError):
        rollout_inputs(m2, ctrl, TRAJ, plant_vector(m2))
    # the same model file loaded twice is the same model
    r = simulate(pm2dof.load_model(M.spec.path), ctrl, TRAJ)
    assert r.outcome == "completed"


# --------------------------------------------------------------------------------------
# 4. step: array-likes in, the same torque out
# --------------------------------------------------------------------------------------

def _pair():
    q = M.ik(TRAJ.xd[0])[:N].copy()
    a, b = NAController(M), NAController(M)
    a.reset(q)
    b.reset(q)
    return q, a, b


def test_step_accepts_array_likes():
    q, a, b = _pair()
    for k in range(1, 6):
        args = (q, TRAJ.xd[k], TRAJ.xd_dot[k], TRAJ.xd_ddot[k])
        want = a.step(*[np.ascontiguousarray(v) for v in args])
        got = b.step(*[v.tolist() for v in args])
        assert np.array_equal(got, want), (k, got, want)
        assert a.status == b.status
    assert np.array_equal(a.theta_hat, b.theta_hat)
    x32 = TRAJ.xd[6].astype(np.float32)
    want = a.step(q, x32.astype(np.float64), TRAJ.xd_dot[6], TRAJ.xd_ddot[6])
    got = b.step(q, x32, tuple(TRAJ.xd_dot[6]), TRAJ.xd_ddot[6][::1].copy())
    assert np.array_equal(got, want)


@pytest.mark.parametrize("args, text", [
    (lambda q: (q.tolist()[:2], [0.2, 0.3], [0, 0], [0, 0]), r"'qa' must have shape \(3,\), got shape \(2,\)"),
    (lambda q: (q, [0.2, 0.3, 0.1], [0, 0], [0, 0]), r"'xd' must have shape \(2,\), got shape \(3,\)"),
    (lambda q: (q, [0.2, math.nan], [0, 0], [0, 0]), r"'xd' \(#2\) has a non-finite value at index 1"),
    (lambda q: (q, [0.2, 0.3], [0, "x"], [0, 0]), r"input 'xd_dot' must be an array of 2 real numbers"),
])
def test_step_refuses_bad_array_likes_and_keeps_its_state(args, text):
    q, a, _ = _pair()
    before = a.state
    with pytest.raises((ValueError, TypeError), match=text) as info:
        a.step(*args(q))
    assert isinstance(info.value, pm2dof.Pm2dofError), type(info.value)   # a typed error
    after = a.state
    assert all(np.array_equal(before[k], after[k]) for k in before)
