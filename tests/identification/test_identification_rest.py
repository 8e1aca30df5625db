# A sample at zero velocity has no Coulomb friction column (eq. 2, sign(0) = 0).
"""The regressor the fit stacks (:func:`pm2dof.identification.fit.stack_regressor`, eq. 13
with xrd = xed, xrdd = xedd) at samples where the robot is at rest: the fc (and fs) columns
are exactly zero on every model with a Coulomb law (sign(0) = +1 gave them S^T e_i). In a
horizontal plane so is the whole row (Me 0 + Ce 0 + S^T f_a(0) = 0); under gravity the row is
the gravity term's (eq. 10 at rest: Y theta = Ge = dV/dxe), column by column. The log is one held pose, stacked with every sample kept
(``min_joint_speed=0``: by default slow samples are left out). Task arrays have m = model.dof."""
import numpy as np
import pytest

from pm2dof.identification.base import base_parameters
from pm2dof.identification.fit import stack_regressor

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not


def _kind(name):
    return name.rstrip("0123456789")


def test_rest_samples_have_no_friction_columns(model, random_theta):
    n, m, N = model.n_legs, model.dof, 400
    T = model.spec.sensing["sample_period"]
    x0 = np.asarray(next(iter(model.spec.trajectories.values()))["start"], dtype=float)
    assert x0.shape == (m,)
    base = base_parameters(model)
    names = [model.param_names[j] for j in base.independent]
    friction = [k for k, name in enumerate(names) if _kind(name) in ("fc", "fs")]
    assert friction, f"{model.name}: no Coulomb column among the base parameters {names}"
    st = stack_regressor(model, base, np.arange(N) * T, np.tile(x0, (N, 1)), np.zeros((N, n)),
                         10.0, decimate=1, min_joint_speed=0.0)
    assert len(st["Phi"]) == st["n_candidates"] > 0 and not st["xed"].any() and not st["xedd"].any()
    assert np.all(st["Phi"][:, :, friction] == 0.0), \
        f"{model.name}: friction columns at rest {np.abs(st['Phi'][:, :, friction]).max()}"
    # the regressor itself at one rest sample
    q = model.ik(x0)
    Y = model.Y(q, np.zeros(m), np.zeros(m), np.zeros(m))
    if not model.spec.has_gravity:
        assert np.all(st["Phi"] == 0.0)
        assert np.all(Y == 0.0), f"{model.name}: Y at rest {Y}"
        return
    # gravity: column j is the gradient of the potential energy of theta = e_j (V is linear in
    # theta; central differences of the generated V, an independent route to Y's gravity part):
    # zero for the second moments and the friction, the gravity term for the first moments
    h, P = 1e-6, len(model.param_names)
    dV = np.array([[(model.potential_energy(x0 + h * e, ej) - model.potential_energy(x0 - h * e, ej))
                    / (2 * h) for ej in np.eye(P)] for e in np.eye(m)])
    assert np.any(dV != 0.0) and np.any(np.all(dV == 0.0, axis=0))
    np.testing.assert_allclose(Y, dV, rtol=1e-7, atol=1e-8 * np.abs(dV).max())
    assert np.all(Y[:, np.all(dV == 0.0, axis=0)] == 0.0)
    # ... the stacked rows are that regressor at every sample (a constant log, filtered) ...
    np.testing.assert_allclose(st["Phi"], np.broadcast_to(Y[:, base.independent], st["Phi"].shape),
                               rtol=1e-12, atol=1e-12 * np.abs(Y).max())
    # ... and Y theta is the generated gravity term Ge (eq. 10 at rest)
    theta = random_theta(model, np.random.default_rng(7))
    g = Y @ theta
    np.testing.assert_allclose(g, model.Ge(q, theta), rtol=1e-12, atol=1e-12 * np.abs(g).max())



def test_slow_threshold_is_in_each_actuators_unit(model):
    """A short log from the model's start pose at a constant velocity that moves every linear
    actuator at about 0.04 m/s, their speeds |S xed| (computed here from the generated S) all
    between 0.02 and 0.1: above
    their default threshold 0.1 x SPEED_LEVER = 0.01 m/s, so no sample is left out (the
    revolute 0.1 taken as m/s left out some). Revolute actuators keep 0.1 rad/s (the 2-DOF
    identification outputs pinned in tests/identification)."""
    from pm2dof.identification.fit import MIN_JOINT_SPEED, SPEED_LEVER
    linear = [i for i, leg in enumerate(model.spec.legs) if leg.actuator == "prismatic"]
    if len(linear) < model.n_legs:
        pytest.skip(f"{model.name}: revolute actuators (their threshold is unchanged)")
    n, N = model.n_legs, 100
    T = model.spec.sensing["sample_period"]
    x0 = np.asarray(next(iter(model.spec.trajectories.values()))["start"], dtype=float)
    t = np.arange(N) * T
    xed = np.linalg.pinv(model.S(model.ik(x0))) @ np.full(n, 0.04)   # every actuator ~0.04
    xe = x0 + np.outer(t, xed)
    qd = np.array([np.abs(model.S(model.ik(x)) @ xed) for x in xe])
    assert 0.02 < qd.min() and qd.min() < MIN_JOINT_SPEED, qd.min()
    st = stack_regressor(model, base_parameters(model), t, xe,
                         np.zeros((N, n)), 50.0, decimate=1)
    assert qd.min() > MIN_JOINT_SPEED * SPEED_LEVER and st["n_slow"] == 0, st["n_slow"]
    assert len(st["Phi"]) == st["n_candidates"] > 0
    old = stack_regressor(model, base_parameters(model), t, xe,
                          np.zeros((N, n)), 50.0, decimate=1,
                          min_joint_speed=MIN_JOINT_SPEED / SPEED_LEVER)   # 0.1 m/s
    assert old["n_slow"] > 0, (old["n_slow"], old["n_candidates"], qd.min(), qd.max())
