# Wrong arguments to simulate, the controllers, Trajectory and load_model are typed errors that
# name the argument (review findings: these were AttributeError, TypeError, IndexError or a C
# error with a flattened index, and some were silently accepted).
import dataclasses

import numpy as np
import pytest

import pm2dof
from pm2dof import (
    APDController,
    ArgumentError,
    ArgumentTypeError,
    CTCController,
    LQRController,
    NAController,
    TrajectoryError,
    simulate,
)


@pytest.fixture(scope="module")
def m():
    return pm2dof.load_model()


@pytest.fixture(scope="module")
def traj():
    return pm2dof.paper_move("high")


def test_truth_must_be_a_plant_dict(m, traj):
    with pytest.raises(ArgumentTypeError, match=r"truth must be a dict like pm2dof.plant_truth"):
        simulate(m, NAController(m), traj, truth=m.theta_nominal)
    with pytest.raises(ArgumentError, match=r"truth: plant: .*missing \['beta'"):
        simulate(m, NAController(m), traj, truth={"alpha": [0.1, 0.1, 0.1]})


@pytest.mark.parametrize("name, what", [("xd_dot", "velocity"), ("xd_ddot", "acceleration")])
def test_every_desired_signal_is_checked_finite_with_its_sample(m, traj, name, what):
    """The guide says every sample of the desired trajectory is checked finite: before, only
    xd was, and an inf in xd_dot reached the C, which named a flattened index."""
    v = getattr(traj, name).copy()
    v[50, 0] = np.inf
    bad = dataclasses.replace(traj, **{name: v})
    with pytest.raises(ArgumentError, match=rf"desired {what} \({name}\) at sample 50 "
                                            rf"\(t = 0.1000 s\) is not finite: \[inf"):
        simulate(m, NAController(m), bad)


@pytest.mark.parametrize("settle_time", [-1.0, np.nan, np.inf, "x"])
def test_settle_time_is_checked(m, traj, settle_time):
    with pytest.raises(TrajectoryError, match="settle_time"):
        simulate(m, NAController(m), traj, settle_time=settle_time)


def test_a_trajectory_has_samples_at_its_period(traj):
    with pytest.raises(TrajectoryError, match="at least one sample"):
        dataclasses.replace(traj, t=traj.t[:0], xd=traj.xd[:0], xd_dot=traj.xd_dot[:0],
                            xd_ddot=traj.xd_ddot[:0])
    t = traj.t.copy()
    t[10] += 1e-4
    with pytest.raises(TrajectoryError, match=r"t must be sampled every period = 0.002 s; "
                                              r"t\[10\] - t\[9\] = 0.0021"):
        dataclasses.replace(traj, t=t)
    with pytest.raises(TrajectoryError, match="period"):
        dataclasses.replace(traj, period=0.0)


@pytest.mark.parametrize("make", [
    lambda m, tr: simulate(m, NAController(m), "high"),
    lambda m, tr: LQRController(m, None),
    lambda m, tr: pm2dof.linearize_trajectory(m, tr.xd),
])
def test_a_trajectory_argument_must_be_a_trajectory(m, traj, make):
    with pytest.raises(ArgumentTypeError, match="trajectory must be a pm2dof.Trajectory"):
        make(m, traj)


@pytest.mark.parametrize("cls", [NAController, APDController, CTCController])
def test_a_controller_needs_a_model(cls):
    with pytest.raises(ArgumentTypeError, match=r"model must be a pm2dof.Model .*got str"):
        cls("shang2010")


def test_load_model_needs_a_name_or_a_path():
    with pytest.raises(ArgumentTypeError, match="model must be a name or a path"):
        pm2dof.load_model(5)
    with pytest.raises(ArgumentTypeError, match="generated must be a name or a path"):
        pm2dof.load_model("shang2010", generated=3.0)


@pytest.mark.parametrize("project", ["no", 1, None])
def test_project_is_a_bool(m, project):
    with pytest.raises(ArgumentTypeError, match="project must be True or False"):
        NAController(m, project=project)


def test_tau_max_one_value_for_every_actuator(m):
    """One limit for every actuator, as plan_time_optimal and the CLI take it; zero or negative
    is refused naming the condition (the message used to say '3 finite numbers' for 0.01)."""
    assert NAController(m, tau_max=6.0).params_layout.unpack(
        NAController(m, tau_max=6.0).params)["tau_max"].tolist() == [6.0, 6.0, 6.0]
    for bad in (0.0, -1.0, -5.0):
        with pytest.raises(ArgumentError, match=r"tau_max\[0\] \(leg 1\) = -?\d.* N m must be in "
                                                r"\(0, 1e\+06\]") as info:
            NAController(m, tau_max=bad)
        assert "preload" not in str(info.value)     # none was set (the message spoke of one)
    with pytest.raises(ArgumentError, match=r"tau_max must be one finite number or 3 \(one per "
                                            r"actuator\), got \[1.0, 2.0\]"):
        NAController(m, tau_max=[1.0, 2.0])


def test_model_inputs_name_what_was_passed(m):
    with pytest.raises(ArgumentTypeError, match=r"input 'xe' must be an array of 2 real numbers"
                                                r", got NoneType"):
        m.ik(None)
    with pytest.raises(ArgumentError, match=r"input 'xe' must have shape \(2,\), got shape \(\)"):
        m.ik(0.3)
