# The sampled references of issue 26's contract: Trajectory.from_samples and Trajectory.hold.
import numpy as np
import pytest

import pm2dof
from pm2dof import Trajectory, TrajectoryError


@pytest.mark.parametrize("m", [1, 2, 3])
def test_from_samples_any_task_dimension(m):
    rng = np.random.default_rng(m)
    N, T = 7, 0.004
    xd, v, a = (rng.normal(size=(N, m)) for _ in range(3))
    tr = Trajectory.from_samples(xd, v, a, T)
    assert tr.t.tolist() == [k * T for k in range(N)]
    for got, want in ((tr.xd, xd), (tr.xd_dot, v), (tr.xd_ddot, a)):
        assert got.shape == (N, m) and got.dtype == np.float64 and got.flags.c_contiguous
        assert not got.flags.writeable
        np.testing.assert_array_equal(got, want)
    assert tr.start is None and tr.end is None and tr.profile is None
    assert tr.duration == (N - 1) * T
    ext = tr.extended(3 * T)                      # rest at the last sample
    assert ext.xd.shape == (N + 3, m) and ext.duration == (N + 2) * T
    np.testing.assert_array_equal(ext.xd[N:], np.broadcast_to(xd[-1], (3, m)))
    assert not ext.xd_dot[N:].any() and not ext.xd_ddot[N:].any()
    np.testing.assert_array_equal(ext.xd[:N], xd)


def test_hold():
    x = [0.245, 0.265]
    tr = Trajectory.hold(x, 0.01, 0.002)
    assert len(tr.t) == 6 and tr.duration == pytest.approx(0.01, abs=1e-15)
    np.testing.assert_array_equal(tr.xd, np.tile(x, (6, 1)))
    assert not tr.xd_dot.any() and not tr.xd_ddot.any()
    assert len(Trajectory.hold(x, 0.0, 0.002).t) == 1
    assert len(Trajectory.hold(x, 0.0101, 0.002).t) == 7         # at least the duration
    assert Trajectory.hold([1.0, 2.0, 3.0], 0.004, 0.002).xd.shape == (3, 3)


def test_line_unchanged_by_the_optional_fields():
    tr = pm2dof.paper_move("low")
    assert tr.profile is not None and tr.duration == tr.profile.duration
    ext = tr.extended(0.01)
    np.testing.assert_array_equal(ext.xd[len(tr.t):], np.broadcast_to(tr.end, (5, 2)))
    assert ext.start == tr.start and ext.end == tr.end and ext.profile is tr.profile


@pytest.mark.parametrize("call, words", [
    (lambda: Trajectory.from_samples(np.zeros((3, 2)), np.zeros((3, 3)), np.zeros((3, 2)), 0.002),
     "xd_dot must have shape (3, 2)"),
    (lambda: Trajectory.from_samples(np.zeros(3), np.zeros(3), np.zeros(3), 0.002),
     "xd must have shape (N, m)"),
    (lambda: Trajectory.from_samples(np.zeros((0, 2)), np.zeros((0, 2)), np.zeros((0, 2)), 0.002),
     "at least one sample"),
    (lambda: Trajectory.from_samples([[0.0, np.nan]], [[0.0, 0.0]], [[0.0, 0.0]], 0.002),
     "xd must be finite; sample 0"),
    (lambda: Trajectory.from_samples([[0.0, 0.0]], [[0.0, 0.0]], [[0.0, 0.0]], 0.0), "period"),
    (lambda: Trajectory.from_samples("ab", [[0.0]], [[0.0]], 0.002), "xd must be"),
    (lambda: Trajectory.hold([0.2, np.inf], 0.1, 0.002), "x must be a finite point"),
    (lambda: Trajectory.hold([[0.2, 0.2]], 0.1, 0.002), "x must be a finite point"),
    (lambda: Trajectory.hold([0.2, 0.2], -1.0, 0.002), "duration"),
    (lambda: Trajectory.hold([0.2, 0.2], 0.1, -0.002), "period"),
])
def test_bad_samples_name_what_is_wrong(call, words):
    with pytest.raises(TrajectoryError) as exc:
        call()
    assert words in str(exc.value)
