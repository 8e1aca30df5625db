# Closed loop of every model file: the paper's experiment (Table 3) runs and tracks for each variant.
"""Every ``models/*.toml`` (the ``model`` fixture of ``conftest.py``) through the closed loop.

* ``pm2dof.table3(model)`` runs APD, NA and NA with Gamma = 0 on each of the model
  file's moves: every run is finite, has no singular and no non-finite sample, and tracks
  with an RMSE (eq. 41) below 1e-3 m. The bound: the paper's moves are 0.0707 m long and the
  paper's worst measured RMSE is 4.7e-4 m (APD, high speed, Table 3); a wrongly wired
  controller (wrong S, a sign error, a broken redundancy resolution) or an unstable loop
  leaves errors of the order of the path length, 1e-2 m and more. The simulated RMSEs are
  ~2e-5..1.3e-4 m, so 1e-3 m separates the two cases by an order of magnitude each way.
* One controller step from rest resolves the task-space demand u into actuator torques
  with the minimum-norm rule of eq. 21, tau_a = S (S^T S)^-1 u: S^T tau_a = u and tau_a is
  in the range of S. For the non-redundant five-bar S is 2 x 2 and the rule reduces to
  tau_a = S^-T u (checked to work, not to degenerate). At rest (xe_prev = fk(qa), xd_dot =
  xd_ddot = 0) the demand is known in closed form: APD (eq. 40) u = S^T f_a(0) + Kp e; NA
  with Gamma = 0 (eq. 29) u = Y theta_hat + Kd s = S^T f_a(0) + Kd Q e (Me xrdd = 0, Ce = 0
  at zero velocity), with S^T f_a(0) = model.StF(q, 0, theta_nominal) (the model's own law).
  Tolerance 1e-12 * cond(S)^2 relative to |u|: a 2 x 2 normal-equations solve loses
  cond(S^T S) = cond(S)^2 digits, on top of ~100 flops of O(eps) rounding.
"""
from __future__ import annotations

import numpy as np
import pytest

from pm2dof import APDController, NAController
from pm2dof.analysis.experiment import table3
from pm2dof.control.trajectory import model_move

RMSE_MAX = 1e-3          # m, see the module docstring
CONTROLLERS = ("apd", "na", "na_no_adaptation")


_OBSERVED: dict[str, float] = {}
_RMSE: dict[str, float] = {}


@pytest.fixture(scope="module", autouse=True)
def _report_observed():
    yield
    if _OBSERVED:
        print("\n[test_models_closed_loop] observed relative residuals of one step:")
        for k in sorted(_OBSERVED):
            print(f"  {k:<60s} {_OBSERVED[k]:.3e}")
    if _RMSE:
        print("[test_models_closed_loop] RMSE (eq. 41), m:")
        for k in sorted(_RMSE):
            print(f"  {k:<60s} {_RMSE[k]:.3e}")


@pytest.fixture(scope="module")
def results(model):
    return table3(model)


def test_table3_runs_and_tracks_on_every_move(model, results):
    n = model.n_legs
    assert set(results) == set(model.spec.trajectories) and results, results.keys()
    tau_max = np.asarray(model.spec.limits["tau_max"])
    for speed, runs in results.items():
        traj = model_move(model, speed)
        assert set(runs) == set(CONTROLLERS), runs.keys()
        for name, r in runs.items():
            where = f"{model.name}, {speed} speed, {name}"
            assert r.n_move == len(traj.t) > 10, where
            assert r.tau_a.shape == (len(r.t), n) and r.xe.shape == (len(r.t), 2), where
            assert np.isfinite(r.xe).all() and np.isfinite(r.tau_a).all(), f"{where}: non-finite"
            assert r.n_singular == 0, f"{where}: {r.n_singular} singular samples"
            assert r.n_non_finite == 0, f"{where}: {r.n_non_finite} non-finite samples"
            assert np.isfinite(r.rmse) and 0.0 < r.rmse < RMSE_MAX, f"{where}: RMSE {r.rmse:.3e} m"
            _RMSE[where] = r.rmse
            # the actuators work and stay within their limits (clipping is status 2)
            assert np.max(np.abs(r.tau_a)) > 0.0, f"{where}: zero torque throughout"
            assert np.all(np.abs(r.tau_a) <= tau_max * (1 + 1e-12)), f"{where}: |tau| > tau_max"
            # it really moved along the path: start and end within RMSE_MAX of the desired
            np.testing.assert_allclose(r.xe[0], traj.xd[0], rtol=0, atol=RMSE_MAX, err_msg=where)
            np.testing.assert_allclose(r.xe[r.n_move - 1], traj.xd[-1], rtol=0, atol=RMSE_MAX,
                                       err_msg=where)


def test_na_adapts_on_every_model(model, results):
    """NA's theta_hat moves (Gamma > 0); with Gamma = 0 it stays at theta_nominal exactly."""
    for speed, runs in results.items():
        th0 = np.asarray(model.theta_nominal)
        assert np.max(np.abs(runs["na"].theta_hat[-1] - th0)) > 0, f"{model.name}, {speed}"
        np.testing.assert_array_equal(runs["na_no_adaptation"].theta_hat[-1], th0,
                                      err_msg=f"{model.name}, {speed}")


@pytest.mark.parametrize("law", ["apd", "na_gamma0"])
def test_one_step_torque_is_the_minimum_norm_resolution(model, law):
    n, m = model.n_legs, model.dof
    traj = model_move(model, next(iter(model.spec.trajectories)))
    theta0 = np.array(model.theta_nominal)
    qa0 = model.ik(traj.xd[0])[:n]
    q = model.ik(model.fk(qa0))
    S = model.S(q)
    assert S.shape == (n, m)
    cond = np.linalg.cond(S)
    assert cond < 1e3, f"{model.name}: S badly conditioned at the start ({cond:.3g})"
    xe = model.fk(qa0)
    # a position error of ~0.1 mm (and 1 mrad of a platform's phi), at rest
    xd = xe + np.array([1e-4, -5e-5, 1e-3][:m])
    e = xd - xe                         # the same rounding as the controller's e = xd - fk(qa)
    fa0 = model.StF(q, np.zeros(m), theta0)  # S^T f_a(0), the model's own friction law
    # the gravity term at the pose, from the model function (eq. 10); 0 in a horizontal plane
    g0 = model.Ge(q, theta0) if model.spec.has_gravity else np.zeros(m)
    if law == "apd":
        ctrl = APDController(model)
        u = fa0 + g0 + model.spec.gains["apd"]["Kp"] * e
    else:
        ctrl = NAController(model, Gamma=np.zeros(len(theta0)))
        g = model.spec.gains["na"]
        u = fa0 + g0 + g["Kd"] * (g["Q"] * e)
    ctrl.reset(qa0)
    tau = ctrl.step(qa0, xd, np.zeros(m), np.zeros(m))
    where = f"{model.name}, {law}: tau={tau.tolist()}, u={u.tolist()}, S={S.tolist()}"
    assert ctrl.status == "ok", where
    np.testing.assert_allclose(ctrl.diag["e"], e, rtol=0, atol=1e-15, err_msg=where)
    rel = 1e-12 * cond ** 2
    err = np.max(np.abs(S.T @ tau - u)) / np.max(np.abs(u))
    _OBSERVED[f"{model.name} {law}: |S^T tau - u| / |u|"] = err
    assert err <= rel, f"S^T tau != u (relative {err:.3e} > {rel:.1e}): {where}"
    # minimum norm: tau = S z for some z (the component of tau outside range(S) vanishes;
    # for n = m range(S) is the whole task space and this holds trivially)
    z = np.linalg.lstsq(S, tau, rcond=None)[0]
    err = np.max(np.abs(S @ z - tau)) / np.max(np.abs(tau))
    _OBSERVED[f"{model.name} {law}: |tau outside range(S)| / |tau|"] = err
    assert err <= rel, f"tau is not in range(S) (relative {err:.3e} > {rel:.1e}): {where}"
    if n == m:  # non-redundant (the five-bar, the 3-leg platforms): S square, tau = S^-T u
        want = np.linalg.solve(S.T, u)
        err = np.max(np.abs(tau - want)) / np.max(np.abs(want))
        _OBSERVED[f"{model.name} {law}: |tau - S^-T u| / |S^-T u|"] = err
        assert err <= rel, f"tau != S^-T u (relative {err:.3e} > {rel:.1e}): {where}"

