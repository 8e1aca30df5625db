# The sampled references of every kind of robot: Trajectory.from_samples and Trajectory.hold.
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
    assert not any(hasattr(tr, k) for k in ("start", "end", "profile"))    # plain samples
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


def test_line_is_plain_samples():
    tr = pm2dof.paper_move("low")
    assert not any(hasattr(tr, k) for k in ("start", "end", "profile"))
    assert tr.duration == (len(tr.t) - 1) * tr.period
    ext = tr.extended(0.01)
    end = pm2dof.PAPER_MOVES["low"]["end"]
    np.testing.assert_array_equal(ext.xd[len(tr.t) - 1:], np.broadcast_to(end, (6, 2)))


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


def test_an_object_with_a_trajectorys_fields_is_not_a_trajectory():
    """The duck-typing branch went with identification's pseudo-trajectories: an
    object with t, xd, xd_dot, xd_ddot and period is refused, naming what to build instead."""
    from types import SimpleNamespace

    import pm2dof
    from pm2dof.control.trajectory import require_trajectory
    real = Trajectory.hold([0.25, 0.26], 0.01, 0.002)
    duck = SimpleNamespace(**{k: getattr(real, k) for k in ("t", "xd", "xd_dot", "xd_ddot",
                                                            "period")})
    assert require_trajectory(real) is real
    with pytest.raises(pm2dof.ArgumentTypeError, match=r"trajectory must be a pm2dof.Trajectory "
                       r"\(.*Trajectory.from_samples.*\), got SimpleNamespace"):
        require_trajectory(duck)
    m = pm2dof.load_model()
    with pytest.raises(pm2dof.ArgumentTypeError, match="got SimpleNamespace"):
        pm2dof.simulate(m, pm2dof.APDController(m), duck)
