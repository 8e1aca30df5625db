# At rest on its reference, with zero error, no controller pushes the robot (sign(0) = 0).
"""Controllers at rest (eq. 2 with sign(0) = 0).

* Every controller (NA, NA with projection, APD, CTC, LQR), with each torque split, at rest on
  its reference with zero error (xd = fk(qa), zero desired velocity and acceleration, zero
  measured velocity) commands zero torque on every model: the friction feedforward of eq. 2
  has no Coulomb term at zero velocity. (With sign(0) = +1 the paper's robot got
  tau = (0.080, 0.131, -0.164) N m.) The preload split with a preload commands only the
  internal preload, the model's preload split of the zero task force.
* ``simulate`` of :meth:`pm2dof.Trajectory.hold` with the model's quantised encoders keeps
  every actuated joint within one encoder count (2 pi / [sensing] encoder_counts_per_rev rad,
  measured at the joints: the true qa = ik(xe) against its start) for NA and APD. With
  sign(0) = +1 the paper's robot drifted up to 1.7 (NA) and 4.0 (APD) counts.
"""
import numpy as np
import pytest

import pm2dof
from pm2dof.linear.lqr import LQRController

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

SPLITS = ("min_norm", "min_max", "preload")
HOLD_S = 0.6          # s: long enough for the old bias to settle at its offset (~0.1 s)


def _controllers(model, xd, split, **kw):
    """Every controller of the package for this model and split, by name."""
    T = model.spec.sensing["sample_period"]
    return {"NA": pm2dof.NAController(model, split=split, **kw),
            "NA projected": pm2dof.NAController(model, project=True, split=split, **kw),
            "APD": pm2dof.APDController(model, split=split, **kw),
            "CTC": pm2dof.CTCController(model, split=split, **kw),
            "LQR": LQRController(model, pm2dof.Trajectory.hold(xd, 0.02, T), split=split,
                                 **kw)}


def _at_rest(model, sample_xe):
    for xe in sample_xe(model, 25, 3):
        qa = model.ik(xe)[:model.n_legs].copy()
        yield qa, model.fk(qa)          # xd = fk(qa): the controller's own e is exactly zero


def _holding(model, q, split, **kw):
    """The torque that holds the robot at rest: the model's ``split`` of its gravity term
    Ge(q, theta0) (eq. 10 at rest), zero in a horizontal plane."""
    if not model.spec.has_gravity:
        return np.zeros(model.n_legs)
    return model.torque_splits(q, model.Ge(q, model.theta_nominal), **kw)[split]


@pytest.mark.parametrize("split", SPLITS)
def test_controllers_at_rest_command_zero_torque(model, sample_xe, split):
    """... or, under gravity, exactly the torque that holds the robot (the gravity term once:
    the generated controllers once added it twice, tau = 2 x the holding torque)."""
    zero = np.zeros(model.dof)
    tol = 1e-9 * np.max(model.spec.limits["tau_max"])   # old convention: ~0.1 N m
    for qa, xd in _at_rest(model, sample_xe):
        hold = _holding(model, model.ik(xd), split)
        for name, c in _controllers(model, xd, split).items():
            c.reset(qa)
            for k in range(3):          # the first sample and two more, still at rest
                tau = c.step(qa, xd, zero, zero)
                assert np.abs(tau - hold).max() <= tol, \
                    f"{model.name} {name} {split} sample {k} at {xd.tolist()}: tau = {tau}, " \
                    f"holding torque {hold}"
                assert c.status == "ok", (model.name, name, split, c.status)


def test_preload_split_at_rest_commands_only_the_preload(model, sample_xe):
    """With a preload the split's torque is an internal force: the model's preload split of
    u = 0 (S^T tau = 0; zero for two legs, which have none), nothing for friction."""
    n, zero = model.n_legs, np.zeros(model.dof)
    preload = 0.1 * np.asarray(model.spec.limits["tau_max"], dtype=float) * np.ones(n)
    sign = np.where(np.arange(n) % 2 == 0, 1.0, -1.0)
    for qa, xd in _at_rest(model, sample_xe):
        q = model.ik(xd)
        expected = _holding(model, q, "preload", preload=preload, preload_sign=sign)
        if not model.spec.has_gravity:
            expected = model.torque_splits(q, zero, preload=preload,
                                           preload_sign=sign)["preload"]
            assert np.abs(model.S(q).T @ expected).max() <= 1e-12 * preload.max()  # internal
        for name, c in _controllers(model, xd, "preload", preload=preload,
                                    preload_sign=sign).items():
            c.reset(qa)
            tau = c.step(qa, xd, zero, zero)
            np.testing.assert_allclose(tau, expected, rtol=0, atol=1e-9 * preload.max(),
                                       err_msg=f"{model.name} {name} at {xd.tolist()}")




@pytest.mark.parametrize("law", ["NA", "APD"])
def test_simulated_hold_stays_within_one_encoder_count(model, law):
    counts = model.spec.sensing["encoder_counts_per_rev"]
    assert counts > 0, f"{model.name}: the hold test needs quantised encoders"
    kinds = [leg.kind for leg in model.spec.legs]
    count = np.array([2 * np.pi / counts if k == "RRR"         # rad at a revolute actuator
                      else model.spec.sensing["linear_encoder_resolution"]   # m at a linear one
                      for k in kinds])
    T = model.spec.sensing["sample_period"]
    x0 = pm2dof.model_move(model, next(iter(model.spec.trajectories))).xd[0]
    ctl = {"NA": pm2dof.NAController, "APD": pm2dof.APDController}[law](model)
    res = pm2dof.simulate(model, ctl, pm2dof.Trajectory.hold(x0, HOLD_S, T))
    assert res.outcome == "completed", res.outcome_reason
    assert len(res.t) == len(pm2dof.Trajectory.hold(x0, HOLD_S, T).t) >= HOLD_S / T
    qa0 = model.ik(x0)[:model.n_legs]
    qa = np.array([model.ik(x)[:model.n_legs] for x in res.xe])
    drift = np.abs(qa - qa0).max(axis=0) / count
    assert np.all(drift <= 1.0), f"{model.name} {law}: joints drift {drift} encoder counts"
