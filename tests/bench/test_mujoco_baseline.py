"""The MuJoCo baseline of ``pm2dof bench`` models this robot: its forward dynamics are pm2dof's.

MuJoCo's equality constraints are soft (impedance d < 1), so its tip acceleration differs
from the exact one by O(1 - d). The test checks that the difference shrinks in proportion to
1 - d and that the limit d -> 1, extrapolated from two impedances, is pm2dof's
``forward_dynamics`` (friction-free theta: the baseline has no friction).
"""
import numpy as np
import pytest

from pm2dof import load_model
from pm2dof.bench.timing import rel_diff

mujoco = pytest.importorskip("mujoco")
from pm2dof.bench.mujoco_baseline import MAX_IMPEDANCE, MujocoRobot  # noqa: E402


@pytest.fixture(scope="module", params=["shang2010", "fivebar"])
def model(request):
    return load_model(request.param)


def _states(m, rng, count=3):
    """Poses around the middle of the model's first move, random velocities and torques."""
    from pm2dof.control.trajectory import line_moves, model_move
    traj = model_move(m, line_moves(m)[0])
    centre = traj.xd[len(traj.t) // 2]
    for _ in range(count):
        yield (centre + rng.uniform(-0.01, 0.01, 2), rng.uniform(-0.3, 0.3, 2),
               rng.uniform(-0.5, 0.5, m.n_legs))


def _tip(m, theta, d, xe, xed, tau):
    r = MujocoRobot(m, theta, d)
    r.set_state(xe, xed, tau)
    r.forward()
    return r.tip_acceleration()


def test_mujoco_forward_dynamics_converge_to_pm2dofs(model):
    th = np.array(model.theta_nominal)
    th[3 * model.n_legs:] = 0.0                    # the baseline has no friction
    rng = np.random.default_rng(25)
    d1, d2 = 0.999, MAX_IMPEDANCE
    for xe, xed, tau in _states(model, rng):
        ours = model.forward_dynamics(xe, xed, tau, th)
        a1, a2 = _tip(model, th, d1, xe, xed, tau), _tip(model, th, d2, xe, xed, tau)
        e1, e2 = rel_diff(a1, ours), rel_diff(a2, ours)
        # the whole difference is MuJoCo's softness: it scales with 1 - d ...
        assert 0 < e2 < 1e-3, (e1, e2)
        assert e1 / e2 == pytest.approx((1 - d1) / (1 - d2), rel=0.05), (e1, e2)
        # ... and vanishes in the limit d -> 1 (linear extrapolation in 1 - d)
        limit = a2 + (a2 - a1) * (1 - d2) / (d2 - d1)
        assert rel_diff(limit, ours) < 1e-3 * e2, (rel_diff(limit, ours), e2)


def test_the_model_text_has_the_legs_and_ties(model):
    r = MujocoRobot(model, model.theta_nominal)
    assert r.model.nq == 2 * model.n_legs          # two hinges per leg
    assert r.model.neq == model.n_legs - 1         # leg 1's tip tied to each other leg's
    assert r.model.ngeom == 0                      # nothing collides
