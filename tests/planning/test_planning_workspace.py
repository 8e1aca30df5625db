# The passes' scratch buffers are reused across rounds and plans: the plans stay bit for bit the same.
"""A refined plan paid ~15 % for fresh ~1 MB blocks every round (the passes'
inputs); they now live in a per-thread :class:`pm2dof.planning.workspace.Workspace`. Whatever a
workspace holds from before, the plan is the one computed with fresh buffers."""
import threading

import numpy as np
import pytest

import pm2dof
from pm2dof.bench.planning import friction_free
from pm2dof.planning.pathfile import read_path_file
from pm2dof.planning.workspace import KEEP_MAX, Workspace, workspace

KEYS = ("s", "sdot", "sddot", "t", "max_velocity", "tau")


def test_take_reuses_and_grows_its_buffers():
    ws = Workspace()
    a = ws.take("x", (10, 3))
    assert a.shape == (10, 3) and a.dtype == np.float64
    b = ws.take("x", (4, 5))                   # smaller: the same memory
    assert b.shape == (4, 5) and np.shares_memory(a, b)
    c = ws.take("x", (31,))                    # larger: a new buffer, 1.5x the old at least
    assert c.shape == (31,) and not np.shares_memory(a, c)
    assert np.shares_memory(c, ws.take("x", (45,)))        # 1.5 * 30 = 45 fits
    assert not np.shares_memory(c, ws.take("y", (31,)))    # names are separate
    big = ws.take("z", (KEEP_MAX + 1,))        # beyond KEEP_MAX: not kept
    assert not np.shares_memory(big, ws.take("z", (KEEP_MAX + 1,)))


def test_each_thread_has_its_own():
    seen = []
    t = threading.Thread(target=lambda: seen.append(workspace()))
    t.start()
    t.join()
    assert seen[0] is not workspace() and workspace() is workspace()


@pytest.mark.parametrize("split", ["min_max", "min_norm"])
def test_a_poisoned_workspace_gives_the_same_plan(split):
    """A plan computed after the thread's workspace was filled with NaN (and grown beyond what
    the plan needs) equals, bit for bit, the plan of a fresh thread (a fresh workspace): every
    entry the passes read is written first. pick_and_place without friction (two solves, the
    second from the first's memo) and with."""
    m = pm2dof.load_model()
    path = read_path_file("pick_and_place").path
    for theta in (friction_free(m), None):
        fresh = []
        t = threading.Thread(target=lambda: fresh.append(
            pm2dof.plan_time_optimal(m, path, split=split, theta=theta)))
        t.start()
        t.join()
        ws = workspace()
        for name in ("forward", "backward", "back"):
            ws.take(name, (200_000,))[:] = np.nan
        plan = pm2dof.plan_time_optimal(m, path, split=split, theta=theta)
        assert plan.info["refinements"] > 0 or theta is None
        for key in KEYS:
            assert np.array_equal(getattr(plan, key), getattr(fresh[0], key)), key
