# A Plan's s, sdot, sddot, t and duration are its profile's: one home, read-only views.
"""pm2dof.planning.Plan keeps its timing in ``profile`` alone; ``s``, ``sdot``, ``sddot``, ``t``
and ``duration`` (documented attributes) are read-only properties of it, not copies kept
beside it. Checked on a platform (rrr3_platform), linear actuators (prr_point) and gravity
(shang2010_vertical), with the time-optimal, smooth and kinematic planners; the kinematic
plan's arrays against its S-curve evaluated here at the trajectory's samples."""
import dataclasses

import numpy as np
import pytest

import pm2dof
from pm2dof.planning import (
    PathProfile,
    Plan,
    model_move_path,
    plan_kinematic,
    plan_smooth,
    plan_time_optimal,
)

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

GRID = ("s", "sdot", "sddot", "t")


def test_the_timing_is_not_a_field_beside_the_profile():
    fields = {f.name for f in dataclasses.fields(Plan)}
    assert "profile" in fields and not fields & {*GRID, "duration"}, fields


def _read_only(plan):
    for name in GRID:
        a = getattr(plan, name)
        assert not a.flags.writeable, name
        with pytest.raises(ValueError):
            a[0] = 1.0
        with pytest.raises(dataclasses.FrozenInstanceError):
            setattr(plan, name, a)


@pytest.mark.parametrize("name", ["rrr3_platform", "prr_point", "shang2010_vertical"])
def test_a_grid_plan_reads_its_path_profile(name):
    m = pm2dof.load_model(name)
    path = model_move_path(m, next(iter(m.spec.trajectories))).path
    plans = [plan_time_optimal(m, path, grid=100)]
    if name == "prr_point":                                  # IPOPT: once is enough
        plans.append(plan_smooth(m, path, grid=40))
    for plan in plans:
        prof = plan.profile
        assert isinstance(prof, PathProfile)
        for key in GRID:
            assert getattr(plan, key) is getattr(prof, key), (plan.method, key)
        assert plan.duration == prof.duration == float(prof.t[-1])
        assert plan.t[0] == 0.0 and np.all(np.diff(plan.s) > 0) and np.all(plan.sdot >= 0)
        _read_only(plan)


def test_the_kinematic_plan_reads_its_s_curve_at_the_samples():
    m = pm2dof.load_model("rrr3_platform")
    path = model_move_path(m, next(iter(m.spec.trajectories))).path
    plan = plan_kinematic(path, 0.2, 2.0, 50.0)
    t = plan.trajectory.t
    s, sd, sdd = plan.profile.evaluate(t)[:3]
    assert np.array_equal(plan.t, t) and np.array_equal(plan.s, s)
    assert np.array_equal(plan.sdot, sd) and np.array_equal(plan.sddot, sdd)
    assert plan.duration == plan.profile.duration and plan.s[-1] == pytest.approx(path.length)
    _read_only(plan)
