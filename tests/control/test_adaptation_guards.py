# NA's guards on theta_hat: the projection, the freeze while saturated, the pause.
"""The blocked robot: NA on a robot held at the start of its high-speed move (the encoders read
that pose for ever) while the reference moves on at 0.05 m/s along x for 10 s, on the paper's
robot and on the 4-RRR platform.

* The paper's law runs away (gamma3 of shang2010 from 0.0111 to 86, m_p of rrr4_platform from
  0.6 to 197) and on shang2010 leaves the physical set (beta1^2 > alpha1 gamma1).
* ``project=True`` keeps every estimate physical (checked here from the parameter names, not
  with the generated projection); it does not bound the inertias.
* ``freeze_when_saturated=True`` holds theta_hat on every saturated sample: only the few
  samples before the torque saturates move it (by 1.4e-3 and 0.011 at most).
* The freeze is a parameter of the generated step: the Python step and simulate's rollout (a
  C loop) give the same torques and estimates bit for bit.
* ``adapting = False`` pauses adaptation and keeps the state; True resumes it.
"""
import functools

import numpy as np
import pytest

import pm2dof
from pm2dof import NAController, simulate
from pm2dof.core.errors import ArgumentTypeError

MODELS = ("shang2010", "rrr4_platform")
SPEED = 0.05                # m/s along x
DURATION = 10.0             # s
FLOOR = 1e-6                # the projection's floor of alpha, gamma, kg m^2


@functools.lru_cache(maxsize=None)
def _model(name):
    return pm2dof.load_model(name)


@functools.lru_cache(maxsize=None)
def _blocked(name, project=False, freeze=False):
    """(theta_hat (N + 1, p): theta0 then after each sample, status labels (N,))."""
    m = _model(name)
    c = NAController(m, project=project, freeze_when_saturated=freeze, on_singular="zero")
    x0 = np.asarray(pm2dof.model_move(m, "high").xd[0])
    qa = m.ik(x0)[:m.n_legs].copy()
    c.reset(qa)
    n = int(round(DURATION / c.sample_period))
    v = np.zeros(m.dof)
    v[0] = SPEED
    zero = np.zeros(m.dof)
    th, status = [c.theta_hat], []
    for k in range(n):
        c.step(qa, x0 + v * (k * c.sample_period), v, zero)
        th.append(c.theta_hat)
        status.append(c.status)
    return np.array(th), np.array(status)


def _unphysical(model, theta):
    """Which rows of theta (K, p) break alpha_i, gamma_i >= FLOOR, beta_i^2 <= alpha_i gamma_i or
    friction >= 0: a (K,) bool, from the parameter names."""
    idx = {name: k for k, name in enumerate(model.param_names)}
    bad = np.zeros(len(theta), dtype=bool)
    for i in range(1, model.n_legs + 1):
        a, b, g = (theta[:, idx[f"{s}{i}"]] for s in ("alpha", "beta", "gamma"))
        bad |= (a < FLOOR * (1 - 1e-12)) | (g < FLOOR * (1 - 1e-12))
        bad |= b * b > a * g * (1 + 1e-12)
    for name, k in idx.items():
        if name.rstrip("0123456789") in ("fv", "fc", "fs"):
            bad |= theta[:, k] < 0
    return bad


@pytest.mark.parametrize("name, param, nominal, above", [("shang2010", "gamma3", 0.0111, 50.0),
                                                         ("rrr4_platform", "m_p", 0.6, 100.0)])
def test_the_papers_law_runs_away_on_a_blocked_robot(name, param, nominal, above):
    """What the guards are for: the estimate grows by orders of magnitude in 10 s, on samples
    that are nearly all saturated."""
    m = _model(name)
    th, status = _blocked(name)
    k = m.param_names.index(param)
    assert th[0, k] == pytest.approx(nominal, rel=1e-3)
    assert th[-1, k] > above, (param, th[-1, k])
    assert np.mean(status == "saturated") > 0.99, np.unique(status, return_counts=True)
    if name == "shang2010":          # and leaves the physical set
        assert _unphysical(m, th).any()


@pytest.mark.parametrize("name", MODELS)
def test_the_projection_keeps_every_estimate_physical(name):
    m = _model(name)
    th, _ = _blocked(name, project=True)
    bad = _unphysical(m, th)
    assert not bad.any(), (np.flatnonzero(bad)[:5], th[bad][:1])
    if name == "shang2010":          # it acted: the paper's law differs
        assert not np.array_equal(th, _blocked(name)[0])


@pytest.mark.parametrize("name", MODELS)
@pytest.mark.parametrize("project", [False, True])
def test_the_freeze_holds_theta_hat_on_every_saturated_sample(name, project):
    m = _model(name)
    th, status = _blocked(name, project=project, freeze=True)
    sat = np.flatnonzero(status == "saturated")
    assert len(sat) > 0.99 * len(status)
    for k in sat:                       # th[k + 1]: after sample k
        assert np.array_equal(th[k + 1], th[k]), (k, th[k + 1] - th[k])
    ok = np.flatnonzero(status == "ok")
    assert len(ok) and any(not np.array_equal(th[k + 1], th[k]) for k in ok)   # still adapts
    # bounded: the few unsaturated samples move it by 1.4e-3 (shang2010's gamma3) and 0.011
    # (rrr4_platform's m_p), against 86 and 196 for the paper's law
    paper = _blocked(name)[0]
    moved, runaway = np.abs(th - th[0]).max(), np.abs(paper - paper[0]).max()
    assert moved < 1e-4 * runaway, (moved, runaway)
    if project:
        assert not _unphysical(m, th).any()


@pytest.mark.parametrize("name", ["shang2010", "prr3_platform", "shang2010_vertical"])
def test_step_and_simulate_freeze_alike(name):
    """A limit at half the efforts' peak saturates part of the high-speed move. The rollout
    (simulate, a generated C loop) and the Python step, fed the same plant and encoders, give
    the same efforts and estimates, frozen on the saturated samples."""
    m = _model(name)
    move = pm2dof.model_move(m, "high")
    tau_max = 0.5 * simulate(m, NAController(m), move).peak_tau
    c = NAController(m, tau_max=tau_max, freeze_when_saturated=True)
    r = simulate(m, c, move)
    assert r.outcome == "completed", r.outcome_message
    sat = np.flatnonzero(r.status == pm2dof.Status.SATURATED)
    assert 0.05 * len(r.t) < len(sat) < len(r.t), len(sat)
    th = np.vstack([c.theta0, r.theta_hat])
    assert all(np.array_equal(th[k + 1], th[k]) for k in sat)
    paper = simulate(m, NAController(m, tau_max=tau_max), move)
    assert not np.array_equal(paper.theta_hat, r.theta_hat)
    # the Python step in a loop over the generated plant and encoders
    tau, theta = _python_loop(m, c, move)
    assert np.array_equal(tau, r.tau_a) and np.array_equal(theta, r.theta_hat)


def _python_loop(m, c, traj):
    """The closed loop of simulate, one Python step per sample: the generated measure and
    plant_step (rk4_substeps RK4 steps of the zero-order hold)."""
    n, d, sub = m.n_legs, m.dof, m.spec.rk4_substeps
    plant = pm2dof.control.plant.plant_vector(m)
    measure, step = m.function("measure"), m.function("plant_step")
    z, nxt, qa = np.concatenate([traj.xd[0], np.zeros(d)]), np.empty(2 * d), np.empty(n)
    h = np.array([c.sample_period / sub])
    measure(np.ascontiguousarray(traj.xd[0]), plant, qa)
    c.reset(qa.copy())
    tau_all, theta = np.empty((len(traj.t), n)), np.empty((len(traj.t), len(c.theta0)))
    for k in range(len(traj.t)):
        measure(np.ascontiguousarray(z[:d]), plant, qa)
        tau = c.step(qa.copy(), traj.xd[k], traj.xd_dot[k], traj.xd_ddot[k])
        tau_all[k], theta[k] = tau, c.theta_hat
        for _ in range(sub):
            step(z, tau, plant, h, nxt)
            z[:] = nxt
    return tau_all, theta


def test_adapting_false_pauses_and_keeps_the_state():
    """Paused: theta_hat held while the robot moves (the same samples adapt when running);
    the pose and velocity estimates carry on; resumed: it adapts again from where it was."""
    m = _model("shang2010")
    move = pm2dof.model_move(m, "high")
    q0 = m.ik(move.xd[0])[:3]
    a, b = NAController(m), NAController(m)
    for c in (a, b):
        c.reset(q0)
    b.adapting = False
    assert not b.adapting and np.all(b.params_layout.unpack(b.params)["Gamma"] == 0)
    for k in range(1, 20):       # the move accelerates: every sample adapts when running
        qa = m.ik(move.xd[k])[:3]
        for c in (a, b):
            c.step(qa, move.xd[k], move.xd_dot[k], move.xd_ddot[k])
        assert np.array_equal(b.theta_hat, b.theta0)
        np.testing.assert_array_equal(b.state["v"], a.state["v"])
    assert not np.array_equal(a.theta_hat, a.theta0)            # the same samples adapt
    b.adapting = True
    assert np.array_equal(b.params, a.params)
    before = b.theta_hat
    qa = m.ik(move.xd[20])[:3]
    b.step(qa, move.xd[20], move.xd_dot[20], move.xd_ddot[20])
    assert not np.array_equal(b.theta_hat, before)
    with pytest.raises(ArgumentTypeError, match="adapting must be True or False"):
        b.adapting = 0
    paused = NAController(m)
    paused.adapting = False
    r = simulate(m, paused, move)                   # the rollout reads the same parameters
    assert np.all(r.theta_hat == paused.theta0)


def test_freeze_when_saturated_is_a_bool():
    with pytest.raises(ArgumentTypeError, match="freeze_when_saturated must be True or False"):
        NAController(_model("shang2010"), freeze_when_saturated=1)
