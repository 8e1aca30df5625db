# Bad input to the derivative methods: the same typed errors as the model functions.
"""Singular poses, poses out of reach, NaN and wrong shapes give, for every derivative method,
the error :meth:`pm2dof.Model.forward_dynamics` gives for the same pose or argument (type and
message), or an error naming the argument."""
import numpy as np
import pytest

import pm2dof

MODELS = ("shang2010", "fivebar")


@pytest.fixture(scope="module", params=MODELS)
def m(request):
    return pm2dof.load_model(request.param)


def calls(m, xe, xed=(0.1, -0.2)):
    """Every derivative method at the pose xe, as (name, call)."""
    xe, xed = np.asarray(xe, float), np.asarray(xed, float)
    tau, th = np.linspace(-1, 1, m.n_legs), np.array(m.theta_nominal)
    x = np.concatenate([xe, xed])
    return {
        "forward_dynamics": lambda: m.forward_dynamics(xe, xed, tau, th),
        "forward_dynamics_jacobians": lambda: m.forward_dynamics_jacobians(xe, xed, tau, th),
        "inverse_dynamics": lambda: m.inverse_dynamics(xe, xed, np.ones(2), th),
        "inverse_dynamics_jacobians": lambda: m.inverse_dynamics_jacobians(xe, xed, np.ones(2),
                                                                           th),
        "sampled_step": lambda: m.sampled_step(x, tau, th),
        "sampled_step_jacobians": lambda: m.sampled_step_jacobians(x, tau, th),
        "linearize": lambda: m.linearize(xe, xed, tau),
        "linearize discrete": lambda: m.linearize(xe, xed, tau, discrete=True),
    }


def _error(call):
    try:
        call()
    except Exception as exc:   # noqa: BLE001 (the type is what is compared)
        return type(exc), str(exc).split(": ", 1)[-1]
    return None, None


def _singular_xe(m, seed=0):
    """A reachable pose whose type I measure is below the threshold (but not zero)."""
    rng = np.random.default_rng(seed)
    lo = m.spec.legs
    for _ in range(100000):
        xe = rng.uniform([-0.1, -0.1], [0.6, 0.6])
        try:
            q = m.ik(xe)
        except pm2dof.WorkspaceError:
            continue
        s = m.singularity_measures(q)
        if 0.01 < s[0] < 0.9 * m.singularity_threshold:
            return xe
    raise AssertionError(f"{m.name}: no singular reachable pose found ({len(lo)} legs)")


@pytest.mark.parametrize("where", ["singular", "out_of_reach"])
def test_poses_give_the_model_functions_errors(m, where):
    xe = _singular_xe(m) if where == "singular" else np.array([5.0, 5.0])
    want_type, want_msg = _error(calls(m, xe)["forward_dynamics"])
    assert want_type is (pm2dof.SingularityError if where == "singular" else
                         pm2dof.WorkspaceError), (want_type, want_msg)
    for name, call in calls(m, xe).items():
        got_type, got_msg = _error(call)
        assert got_type is want_type, f"{m.name} {name} at {where} xe={xe.tolist()}: " \
                                      f"{got_type} ({got_msg}), want {want_type}"
        assert got_msg == want_msg, f"{name}: {got_msg!r} != {want_msg!r}"


@pytest.mark.parametrize("arg", [0, 1, 2, 3])
def test_nan_and_wrong_shape_name_the_argument(m, arg, first_point):
    n, th = m.n_legs, np.array(m.theta_nominal)
    good = [np.array([0.245, 0.265]) if m.n_legs > 2 else first_point(m),
        np.array([0.1, -0.2]), np.linspace(-1, 1, n), th]
    names = ("xe", "xed", "tau_a", "theta")
    for bad, what in ((np.full_like(good[arg], np.nan), "non-finite"),
                      (np.zeros(len(good[arg]) + 1), "shape")):
        args = list(good)
        args[arg] = bad
        for meth in (m.forward_dynamics, m.forward_dynamics_jacobians):
            with pytest.raises(pm2dof.ArgumentError) as info:
                meth(*args)
            msg = str(info.value)
            assert f"'{names[arg]}'" in msg and (what in msg or "shape" in msg), msg
    x = np.concatenate(good[:2])
    with pytest.raises(pm2dof.ArgumentError, match="'x'"):
        m.sampled_step_jacobians(np.r_[x[:3], np.nan], good[2], th)
    with pytest.raises(pm2dof.ArgumentError, match="'tau_a'"):
        m.sampled_step(x, np.zeros(n + 1), th)
    with pytest.raises(pm2dof.ArgumentError, match="period"):
        m.sampled_step(x, good[2], th, period=-1.0)
    with pytest.raises(pm2dof.ArgumentError, match="'xedd'"):
        m.inverse_dynamics_jacobians(good[0], good[1], [np.nan, 0.0], th)


def test_linear_layer_refuses_bad_arguments_typed():
    """Review findings: wrong types and hopeless weights give Pm2dofErrors, and a non-finite
    result from finite inputs is a NonFiniteError (as from the Model's own methods)."""
    m = pm2dof.load_model()
    traj = pm2dof.paper_move("high")
    with pytest.raises(pm2dof.ArgumentTypeError, match="model must be a pm2dof.Model"):
        pm2dof.statespace("shang2010", [0.245, 0.265], [0.0, 0.0], np.zeros(3))
    with pytest.raises(pm2dof.ArgumentTypeError, match="trajectory must be a pm2dof.Trajectory"):
        pm2dof.linearize_trajectory(m, [1, 2, 3])
    with pytest.raises(pm2dof.NonFiniteError, match="not finite"):
        pm2dof.linearize_trajectory(m, traj, period=1e6)
    with pytest.raises(pm2dof.ArgumentError, match="lqr_gains"):
        pm2dof.LQRController(m, traj, Q_position=1e300)
    with pytest.raises(pm2dof.ArgumentError, match=r"theta must be 15 finite numbers \(alpha1"):
        pm2dof.linearize_trajectory(m, traj, theta=[1.0, 2.0])
