# The LQR's run-time step (pm2dof.control.lqr): a planned gain schedule, no SciPy, one C call.
"""``pm2dof.control.lqr.LQRController`` runs gains planned elsewhere: built from the K and
tau_ff that :mod:`pm2dof.linear.lqr` plans (SciPy's Riccati solver), it steps and rolls out
exactly as the planning constructor ``pm2dof.LQRController`` (the same generated step, the same
per-sample inputs). Importing and running it loads no SciPy; arrays of the wrong shape or not
finite are refused, naming them."""
import subprocess
import sys

import numpy as np
import pytest

import pm2dof
from pm2dof.control.lqr import LQRController
from pm2dof.control.settings import ControlSettings
from pm2dof.control.trajectory import line_moves
from pm2dof.core.errors import ArgumentError

#: a platform, linear actuators and gravity
KINDS = ["rrr4_platform", "prr3_platform", "shang2010_vertical"]


@pytest.fixture(scope="module", params=KINDS)
def planned(request):
    model = pm2dof.load_model(request.param)
    traj = pm2dof.model_move(model, line_moves(model)[0])
    return model, traj, pm2dof.LQRController(model, traj)


def test_the_planning_constructor_builds_the_run_time_controller(planned):
    model, traj, lqr = planned
    assert isinstance(lqr, LQRController)
    assert type(lqr).__module__ == "pm2dof.linear.lqr"
    assert lqr.K.shape == (len(traj.t), model.n_legs, 2 * model.dof)
    assert lqr.tau_ff.shape == (len(traj.t), model.n_legs)
    assert not lqr.K.flags.writeable and not lqr.tau_ff.flags.writeable


def test_a_plan_run_from_its_arrays_steps_as_planned(planned):
    model, traj, lqr = planned
    run = LQRController(model, traj, lqr.K, lqr.tau_ff, settings=lqr.settings)
    assert np.array_equal(run.params, lqr.params) and run.function_name == lqr.function_name
    assert np.array_equal(run.closed_loop_inputs(traj), lqr.closed_loop_inputs(traj))
    a = pm2dof.simulate(model, lqr, traj, settle_time=0.02)
    b = pm2dof.simulate(model, run, traj, settle_time=0.02)
    assert a.outcome == b.outcome == "completed"
    np.testing.assert_array_equal(a.tau_a, b.tau_a)
    np.testing.assert_array_equal(a.xe, b.xe)
    # and sample by sample in Python, fed the rollout's exact measurements
    for c in (lqr, run):
        c.reset(model.ik(traj.xd[0])[:model.n_legs])
    for k in range(0, len(traj.t), 7):
        qa = model.ik(a.xe[k])[:model.n_legs]
        for c in (lqr, run):
            c._k = k
        np.testing.assert_array_equal(lqr.step(qa, traj.xd[k], traj.xd_dot[k], traj.xd_ddot[k]),
                                      run.step(qa, traj.xd[k], traj.xd_dot[k],
                                               traj.xd_ddot[k]))


def test_bad_schedules_are_named(planned):
    model, traj, lqr = planned
    N, n, m = len(traj.t), model.n_legs, model.dof
    with pytest.raises(ArgumentError, match=rf"LQRController: K must be \({N}, {n}, {2 * m}\) "
                                            rf"finite numbers .*got shape \({N - 1}, "):
        LQRController(model, traj, lqr.K[1:], lqr.tau_ff)
    bad = np.array(lqr.tau_ff)
    bad[3, 0] = np.nan
    with pytest.raises(ArgumentError, match=r"tau_ff must be .* got non-finite entries"):
        LQRController(model, traj, lqr.K, bad)
    with pytest.raises(ArgumentError, match=r"give settings or tau_max, not both"):
        LQRController(model, traj, lqr.K, lqr.tau_ff, settings=lqr.settings, tau_max=5.0)
    fast = ControlSettings.from_spec(model.spec, sample_period=0.001)
    with pytest.raises(ArgumentError, match=r"trajectory period 0.002 s differs from the "
                                            r"controller's sample period 0.001 s"):
        LQRController(model, traj, lqr.K, lqr.tau_ff, settings=fast)


def test_the_run_time_lqr_loads_no_scipy():
    code = ("import sys, numpy as np, pm2dof\n"
            "from pm2dof.control.lqr import LQRController\n"
            "m = pm2dof.load_model('prr3_platform')\n"
            "t = pm2dof.model_move(m, pm2dof.control.trajectory.line_moves(m)[0])\n"
            "N, n = len(t.t), m.n_legs\n"
            "c = LQRController(m, t, np.zeros((N, n, 2 * m.dof)), np.zeros((N, n)))\n"
            "c.reset(m.ik(t.xd[0])[:n]); c.step(m.ik(t.xd[0])[:n], t.xd[0], t.xd_dot[0], "
            "t.xd_ddot[0])\n"
            "r = pm2dof.simulate(m, c, t)\n"
            "assert 'scipy' not in sys.modules, sorted(k for k in sys.modules if 'scipy' in k)\n")
    subprocess.run([sys.executable, "-c", code], check=True)
