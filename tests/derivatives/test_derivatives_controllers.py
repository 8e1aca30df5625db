# CTC and LQR: the generated steps against the NumPy reference, gains, planning, rollouts.
"""The computed-torque and time-varying LQR controllers.

* the generated ``ctc_step`` and ``lqr_step`` against :mod:`pm2dof.reference.control` (plain
  NumPy, its own kinematics and dynamics) at random states: tau_a and the state to 1e-10;
* the LQR planner's gains against python-control's ``dlqr`` on a time-invariant system (an
  independent Riccati solver), and the recursion's P_k against its defining equation;
* gains outside the conditions raise GainError; both run in simulate and track.
"""
import numpy as np
import pytest

import pm2dof
from pm2dof.bench.baselines import random_cases, reference_geometry
from pm2dof.linear import LQRController, lqr_gains
from pm2dof.reference import control as rc

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

MODELS = ("shang2010", "fourleg", "fivebar")


@pytest.fixture(scope="module", params=MODELS)
def m(request):
    return pm2dof.load_model(request.param)


def _rel(a, b):
    return float(np.linalg.norm(np.asarray(a) - b) / max(np.linalg.norm(b), 1e-300))


def _c(f, args, n, nstate):
    tau, s1, st, dg = np.empty(n), np.empty(nstate), np.empty(1), np.empty(f.sizes_out[3])
    f(*args, tau, s1, st, dg)
    return tau, s1, int(st[0])


@pytest.mark.parametrize("split", ["min_norm", "min_max", "preload"])
def test_ctc_and_lqr_steps_match_the_numpy_reference(m, split, first_point):
    n = m.n_legs
    rng = np.random.default_rng(2101)
    g = reference_geometry(m)
    ctc = pm2dof.CTCController(m, split=split)
    centre = first_point(m)
    cases = random_cases(m, ctc, rng, 6, centre)
    assert len(cases) == 6
    f_ctc = m.function(f"{ctc.function_name}_step")
    f_lqr = m.function(f"lqr{ctc.function_name[3:]}_step")
    lqr_params = m.layout("lqr_params").pack(**{k: v for k, v in m.layout(
        "ctc_params").unpack(ctc.params).items() if k not in ("Kp", "Kv")})
    for case in cases:
        info = f"{m.name}, {split}: case={[np.round(c, 6).tolist() for c in case]}"
        tau_c, s_c, st_c = _c(f_ctc, (*case, ctc.params), n, len(case[0]))
        if split == "min_norm":     # the reference implements eq. 21's split
            tau_r, s_r, st_r, _ = rc.ctc_step(g, *case, ctc.params)
            assert st_c == st_r and _rel(tau_c, tau_r) < 1e-10 and _rel(s_c, s_r) < 1e-12, info
        # gains of the planned LQR's size on the state errors of these cases: torques below
        # tau_max, so no split clips and S^T tau compares
        K, tff = rng.normal(0, 3e2, (n, 4)), rng.uniform(-2, 2, n)
        tau_l, s_l, st_l = _c(f_lqr, (*case, lqr_params, K.ravel(), tff), n, len(case[0]))
        tau_r, s_r, st_r, d = rc.lqr_step(g, *case, lqr_params, K, tff)
        # every split gives the same task force S^T tau (to rounding): compare S^T tau
        S = m.S(d["q"])
        assert st_r == pm2dof.Status.OK and st_l in (pm2dof.Status.OK,
                                                     pm2dof.Status.PRELOAD_INFEASIBLE), info
        assert _rel(S.T @ tau_l, S.T @ tau_r) < 1e-10, info
        if split == "min_norm":
            assert _rel(tau_l, tau_r) < 1e-10, info
        assert _rel(s_l, s_r) < 1e-12, info


def test_lqr_gains_match_python_control_on_a_time_invariant_system(m, first_point):
    """Long horizon, constant (A, B): K_0 is the infinite-horizon gain of dlqr."""
    control = pytest.importorskip("control")
    xe = first_point(m)
    A, B = m.linearize(xe, [0.1, -0.1], np.zeros(m.n_legs), discrete=True)
    Q, R = np.diag([1e8, 1e8, 1e4, 1e4]), 0.25 * np.eye(m.n_legs)
    N = 4000
    K, P = lqr_gains(np.broadcast_to(A, (N, 4, 4)), np.broadcast_to(B, (N,) + B.shape), Q, R)
    K_ref, P_ref, _ = control.dlqr(A, B, Q, R)
    assert _rel(K[0], K_ref) < 1e-8 and _rel(P[0], P_ref) < 1e-8, (K[0], K_ref)
    # the recursion's defining equation at a middle sample
    k = N // 2
    BtP = B.T @ P[k + 1]
    np.testing.assert_allclose(K[k], np.linalg.solve(R + BtP @ B, BtP @ A), rtol=1e-10)


@pytest.mark.parametrize("bad", [0.0, -1.0, [1.0, np.nan], [[1.0, 2.0], [0.0, 1.0]]])
def test_gains_outside_the_conditions_are_refused(bad):
    m = pm2dof.load_model()
    for kw in ({"Kp": bad}, {"Kv": bad}):
        with pytest.raises(pm2dof.GainError, match="CTCController: K"):
            pm2dof.CTCController(m, **kw)
    traj = pm2dof.model_move(m, "low")
    for kw in ({"Q_position": bad}, {"Q_velocity": bad}, {"R": bad}):
        with pytest.raises(pm2dof.GainError, match="LQRController"):
            LQRController(m, traj, **kw)


def test_ctc_and_lqr_track_in_simulate_and_lqr_refuses_another_trajectory():
    m = pm2dof.load_model()
    for speed in ("low", "high"):
        traj = pm2dof.model_move(m, speed)
        for ctrl in (pm2dof.CTCController(m), LQRController(m, traj)):
            r = pm2dof.simulate(m, ctrl, traj, settle_time=0.05)
            assert r.outcome == "completed" and r.rmse < 2e-4, (speed, ctrl._law, r.rmse)
            assert np.abs(r.e[-1]).max() < 1e-4, (speed, ctrl._law, r.e[-1])
    lqr = LQRController(m, pm2dof.model_move(m, "low"))
    with pytest.raises(pm2dof.ArgumentError, match="planned for another trajectory"):
        pm2dof.simulate(m, lqr, pm2dof.model_move(m, "high"))


def test_python_steps_equal_the_closed_loop_in_c():
    """CTCController.step / LQRController.step sample by sample, fed the measurements of the
    C rollout, reproduce its torques exactly (the same generated step)."""
    m = pm2dof.load_model()
    traj = pm2dof.model_move(m, "low")
    for ctrl in (pm2dof.CTCController(m), LQRController(m, traj)):
        r = pm2dof.simulate(m, ctrl, traj, quantise=False)
        ctrl.reset(m.ik(traj.xd[0])[:m.n_legs])
        for k in range(len(traj.t)):
            tau = ctrl.step(m.ik(r.xe[k])[:m.n_legs], traj.xd[k], traj.xd_dot[k],
                            traj.xd_ddot[k])
            np.testing.assert_allclose(tau, r.tau_a[k], rtol=1e-9, atol=1e-9,
                                       err_msg=f"{ctrl._law} sample {k}")


def test_model_file_gains_of_ctc_and_lqr(tmp_path):
    """[gains.ctc] and [gains.lqr] are optional; when present they are the defaults, and bad
    values are listed by the model file's reader."""
    from pm2dof.core.paths import SHIPPED_GENERATED, SHIPPED_MODELS
    text = (SHIPPED_MODELS / "shang2010.toml").read_text()
    extra = ("\n[gains.ctc]\nKp = [10000.0, 12000.0]\nKv = [200.0, 220.0]\n"
             "\n[gains.lqr]\nQ_position = [2e8, 3e8]\nQ_velocity = [1e4, 2e4]\n"
             "R = [0.5, 0.5, 0.5]\n")
    p = tmp_path / "shang2010.toml"
    p.write_text(text.replace("\n[gains.apd]", extra + "\n[gains.apd]", 1))
    m = pm2dof.load_model(p, generated=SHIPPED_GENERATED / "shang2010")
    ctc = pm2dof.CTCController(m)
    np.testing.assert_array_equal(m.layout("ctc_params").unpack(ctc.params)["Kp"], [1e4, 1.2e4])
    lqr = LQRController(m, pm2dof.model_move(m, "low"))
    np.testing.assert_array_equal(np.diag(lqr.weights["Q"]), [2e8, 3e8, 1e4, 2e4])
    np.testing.assert_array_equal(np.diag(lqr.weights["R"]), [0.5, 0.5, 0.5])
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace("\n[gains.apd]", "\n[gains.ctc]\nKp = [-1.0, 1.0]\nKv = 3\n"
                                "\n[gains.lqr]\nR = [1.0]\n\n[gains.apd]", 1))
    with pytest.raises(pm2dof.ModelFileError) as exc:
        pm2dof.load_model(bad, generated=SHIPPED_GENERATED / "shang2010")
    keys = [pr.key for pr in exc.value.problems]
    assert any(k and k.startswith("gains.ctc.Kp") for k in keys), keys
    assert any(k and k.startswith("gains.lqr") for k in keys), keys
