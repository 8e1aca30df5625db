# TaskPath: arc-length parameterisation, derivatives by finite differences, corners, stops, errors.
import math

import numpy as np
import pytest

import pm2dof
from pm2dof import PlanError, TaskPath

PATHS = {
    "line": lambda: TaskPath.line([0.22, 0.29], [0.27, 0.24]),
    "arc_ccw": lambda: TaskPath.arc([0.25, 0.26], 0.04, -0.3, 2.2),
    "arc_cw": lambda: TaskPath.arc([0.25, 0.26], 0.03, 1.0, -1.5),
    "polyline": lambda: TaskPath.polyline([[0.2, 0.22], [0.3, 0.22], [0.28, 0.32], [0.2, 0.3]],
                                          0.02),
    "spline": lambda: TaskPath.spline([[0.2, 0.2], [0.25, 0.26], [0.3, 0.22], [0.32, 0.3]]),
    "concat": lambda: TaskPath.concat(TaskPath.line([0.2, 0.25], [0.3, 0.25]),
                                      TaskPath.arc([0.3, 0.27], 0.02, -math.pi / 2, 0.0)),
}


@pytest.fixture(params=sorted(PATHS))
def path(request):
    return PATHS[request.param]()


def test_unit_tangent_and_arc_length(path):
    s = np.linspace(0, path.length, 20001)
    p, dp, ddp = path.evaluate(s)
    assert np.abs(np.hypot(*dp.T) - 1).max() < 1e-12
    assert np.abs(np.sum(dp * ddp, axis=1)).max() < 1e-9 * max(1.0, np.abs(ddp).max())
    chord = np.hypot(*np.diff(p, axis=0).T).sum()          # polygon length -> arc length
    assert abs(chord - path.length) < 1e-7 * path.length, (chord, path.length)


def test_derivatives_by_finite_differences(path):
    """p' and p'' against central differences (step 1e-6 m), away from the breakpoints (where
    p'' may jump)."""
    h = 1e-6
    s = np.linspace(0, path.length, 997)[1:-1]
    bp = path.breakpoints
    s = s[np.min(np.abs(s[:, None] - bp[None, :]), axis=1) > 10 * h]
    p, dp, ddp = path.evaluate(s)
    pp, dpp, _ = path.evaluate(s + h)
    pm, dpm, _ = path.evaluate(s - h)
    err1 = np.abs((pp - pm) / (2 * h) - dp).max()
    err2 = np.abs((dpp - dpm) / (2 * h) - ddp).max() / max(1.0, np.abs(ddp).max())
    assert err1 < 1e-7 and err2 < 1e-4, (err1, err2)


def test_ends_and_continuity(path):
    s = np.linspace(0, path.length, 5001)
    p, dp, _ = path.evaluate(s)
    assert np.allclose(p[0], path.start) and np.allclose(p[-1], path.end)
    step = np.hypot(*np.diff(p, axis=0).T)
    assert step.max() < 1.01 * path.length / 5000          # no jump in position
    turn = np.hypot(*np.diff(dp, axis=0).T)
    assert turn.max() < 0.1                                # no corner: these paths are G1
    assert path.stops.tolist() == [0.0, path.length]


def test_shapes():
    arc = TaskPath.arc([0.1, 0.2], 0.05, 0.0, math.pi)
    assert arc.length == pytest.approx(0.05 * math.pi, rel=1e-15)
    p, dp, ddp = arc.evaluate(np.array([0.0, arc.length / 2, arc.length]))
    assert np.allclose(p, [[0.15, 0.2], [0.1, 0.25], [0.05, 0.2]], atol=1e-15)
    assert np.allclose(dp[1], [-1, 0], atol=1e-15) and np.allclose(ddp[1], [0, -20], atol=1e-12)
    sp = TaskPath.spline([[0.2, 0.2], [0.25, 0.26], [0.3, 0.22]])
    s = np.linspace(0, sp.length, 2001)                  # passes through the middle waypoint
    k = np.argmin(np.hypot(*(sp.evaluate(s)[0] - [0.25, 0.26]).T))
    fine = np.linspace(s[k - 1], s[k + 1], 2001)
    assert np.hypot(*(sp.evaluate(fine)[0] - [0.25, 0.26]).T).min() < 1e-6
    assert np.allclose(sp.evaluate(np.array([sp.length]))[0], [[0.3, 0.22]], atol=1e-12)
    # natural spline: no curvature at either end
    assert np.abs(sp.evaluate(np.array([0.0, sp.length]))[2]).max() < 1e-9


def test_polyline_blend_is_tangent_and_has_the_radius():
    r = 0.02
    pl = TaskPath.polyline([[0.2, 0.22], [0.3, 0.22], [0.3, 0.32]], r)
    assert pl.kinds == ("line", "arc", "line")
    assert pl.length == pytest.approx(0.1 - r + r * math.pi / 2 + 0.1 - r, rel=1e-14)
    b = pl.breakpoints
    for s in b[1:-1]:
        _, t1, _ = pl.evaluate(np.array([s - 1e-12]))
        _, t2, _ = pl.evaluate(np.array([s]))
        assert np.allclose(t1, t2, atol=1e-9)
    mid = pl.evaluate(np.array([(b[1] + b[2]) / 2]))
    assert np.hypot(*mid[2][0]) == pytest.approx(1 / r, rel=1e-12)


def test_sharp_corners_and_reversals_are_stops():
    sharp = TaskPath.polyline([[0.2, 0.22], [0.3, 0.22], [0.3, 0.32]])
    assert sharp.stops.tolist() == pytest.approx([0.0, 0.1, 0.2])
    there = TaskPath.line([0.2, 0.25], [0.3, 0.25])
    back = TaskPath.line([0.3, 0.25], [0.2, 0.25])
    cycle = TaskPath.concat(there, back, there)
    assert cycle.stops.tolist() == pytest.approx([0.0, 0.1, 0.2, 0.3])
    smooth = TaskPath.concat(TaskPath.line([0.2, 0.25], [0.3, 0.25]),
                             TaskPath.line([0.3, 0.25], [0.4, 0.25]))
    assert smooth.stops.tolist() == pytest.approx([0.0, 0.2])


@pytest.mark.parametrize("make, match", [
    (lambda: TaskPath.line([0.2, 0.2], [0.2, 0.2]), "zero length"),
    (lambda: TaskPath.line([0.2, float("nan")], [0.3, 0.2]), "p0 must be a finite point"),
    (lambda: TaskPath.line([0.2], [0.3, 0.2]), "p0 must be a finite point"),
    (lambda: TaskPath.arc([0, 0], -1.0, 0, 1), "radius"),
    (lambda: TaskPath.arc([0, 0], 1.0, 1, 1), "zero length"),
    (lambda: TaskPath.polyline([[0.2, 0.2]], 0.01), "m >= 2"),
    (lambda: TaskPath.polyline([[0.2, 0.2], [0.2, 0.2], [0.3, 0.3]], 0.01), r"points 1 and 2 coincide at \(0.2, 0.2\) m \(points numbered from 1\)"),
    (lambda: TaskPath.polyline([[0.2, 0.2], [0.3, 0.2], [0.3, 0.21]], 0.05),
     r"does not fit on line 2 \(points 2 -> 3, \(0.3, 0.2\) m -> \(0.3, 0.21\) m"),
    (lambda: TaskPath.polyline([[0.2, 0.2], [0.3, 0.2], [0.2, 0.2]], 0.01), r"corner 1 \(point 2, \(0.3, 0.2\) m; .*\) turns back"),
    (lambda: TaskPath.polyline([[0.2, 0.2], [0.3, 0.2]], -0.01), "blend_radius"),
    (lambda: TaskPath.spline([[0.2, 0.2], [0.2, 0.2]]), r"waypoints 1 and 2 coincide"),
    (lambda: TaskPath.concat(TaskPath.line([0, 0], [1, 0]), TaskPath.line([1, 1e-6], [2, 0])),
     r"path 2 starts at \(1, 1e-06\) m, 1e-06 m from where path 1 ends \(\(1, 0\) m\) "
     r"\(paths numbered from 1\)"),
    (lambda: TaskPath.concat(), "one or more TaskPath"),
])
def test_bad_geometry_is_a_plan_error(make, match):
    with pytest.raises(PlanError, match=match):
        make()


def test_evaluate_refuses_outside_the_path():
    line = PATHS["line"]()
    with pytest.raises(PlanError, match="outside the path"):
        line.evaluate([line.length * 1.01])
    with pytest.raises(PlanError, match="finite"):
        line.evaluate([float("nan")])
    p, _, _ = line.evaluate([line.length * (1 + 1e-12)])     # rounding is clipped
    assert np.allclose(p[0], [0.27, 0.24])


def test_immutable():
    with pytest.raises(AttributeError):
        PATHS["line"]().foo = 1
    assert isinstance(pm2dof.TaskPath.line([0, 0], [1, 0]), TaskPath)
