"""TaskPath.evaluate in C (pm2dof/planning/_pathc.c) against each piece's own NumPy evaluation
(paths.py, spline.py), bit for bit: every kind of piece, both sides of a junction, the ends,
the junctions and their neighbouring floats, rounding beyond the ends."""
import pickle

import numpy as np
import pytest

from pm2dof import TaskPath
from pm2dof.planning import _pathc
from pm2dof.planning.pathfile import read_path_file

L = 0.1     # orientation length, m


def _bits(a):
    """The float64 entries' bits (signed zeros told apart)."""
    return np.ascontiguousarray(a).view(np.int64)


def _numpy(path, s, side):
    """The path evaluated piece by piece with the pieces' NumPy code (the reference)."""
    s = np.clip(np.asarray(s, dtype=float), 0.0, path.length)
    ends, pieces = path.breakpoints, path._pieces
    idx = np.clip(np.searchsorted(ends, s, side=side) - 1, 0, len(pieces) - 1)
    lengths = np.array([pc.length for pc in pieces])
    local = np.clip(s - ends[idx], 0.0, lengths[idx])
    out = [np.full((len(s), path.dim), np.nan) for _ in range(3)]
    for i, pc in enumerate(pieces):
        sel = idx == i
        if sel.any():
            for o, v in zip(out, pc.evaluate(local[sel])):
                o[sel] = v
    return out


SPLINE = [[0.18, 0.20], [0.22, 0.13], [0.27, 0.21], [0.31, 0.15]]
PATHS = {
    "line": lambda: TaskPath.line([0.22, 0.29], [0.27, 0.24]),
    "arc_ccw": lambda: TaskPath.arc([0.245, 0.265], 0.03, 0.0, np.pi),
    "arc_cw": lambda: TaskPath.arc([0.245, 0.265], 0.03, 1.0, -0.5),
    "spline": lambda: TaskPath.spline(SPLINE),
    "blended_polyline": lambda: TaskPath.polyline([[0, 0], [0.1, 0], [0.1, 0.1], [0.3, 0.2]],
                                                  blend_radius=0.02),
    "sharp_polyline": lambda: TaskPath.polyline([[0, 0], [0.1, 0], [0.1, 0.1]]),
    "spline_then_line": lambda: TaskPath.concat(TaskPath.spline(SPLINE),
                                                TaskPath.line(SPLINE[-1], [0.35, 0.2])),
    "line_with_phi": lambda: TaskPath.line([0, 0, 0], [0.1, 0.05, 0.3], orientation_length=L),
    "rotation": lambda: TaskPath.line([0.1, 0.1, 0], [0.1, 0.1, -0.3], orientation_length=L),
    "arc_with_phi": lambda: TaskPath.arc([0, 0], 0.1, 0, 1, phi=[0, 0.4], orientation_length=L),
    "platform_chain": lambda: TaskPath.concat(
        TaskPath.line([0, 0, 0], [0.1, 0.05, 0.3], orientation_length=L),
        TaskPath.line([0.1, 0.05, 0.3], [0.1, 0.05, 0.5], orientation_length=L),
        TaskPath.arc([0.0, 0.05], 0.1, 0, 1, phi=[0.5, 0.2], orientation_length=L)),
    "pick_and_place": lambda: read_path_file("pick_and_place").path,
    "curve": lambda: read_path_file("curve").path,
}


@pytest.mark.parametrize("name", sorted(PATHS))
@pytest.mark.parametrize("side", ["right", "left"])
def test_c_evaluation_equals_the_pieces_numpy_bit_for_bit(name, side):
    path = PATHS[name]()
    bp = path.breakpoints
    s = np.concatenate([np.random.default_rng(7).uniform(0.0, path.length, 4000), bp,
                        np.nextafter(bp, np.inf), np.nextafter(bp, -np.inf),
                        [0.0, -0.0, -1e-13, path.length * (1 + 1e-12)]])
    got, want = path.evaluate(s, side), _numpy(path, s, side)
    for g, w, what in zip(got, want, ("p", "dp", "ddp")):
        assert g.shape == (len(s), path.dim)
        assert np.isfinite(w).all()
        same = _bits(g) == _bits(w)
        assert same.all(), f"{what} differs at s = {s[~same.all(axis=1)][:3]}"


def test_the_left_side_takes_the_preceding_piece_at_a_junction():
    path = PATHS["sharp_polyline"]()
    j = path.breakpoints[1:2]
    (_, right, _), (_, left, _) = path.evaluate(j, "right"), path.evaluate(j, "left")
    assert right[0].tolist() == [0.0, 1.0] and left[0].tolist() == [1.0, 0.0]


def test_the_c_evaluator_refuses_wrong_buffers():
    path = PATHS["line"]()
    s = np.array([0.0, 0.01])
    good = [np.empty((2, 2)) for _ in range(3)]
    with pytest.raises(TypeError, match="s must be a contiguous float64 array"):
        _pathc.evaluate(path._table, s.astype(np.float32), True, *good)
    with pytest.raises(ValueError, match="ddp must hold 2 x 2 entries"):
        _pathc.evaluate(path._table, s, True, *good[:2], np.empty((3, 2)))
    with pytest.raises(ValueError, match="table"):
        _pathc.evaluate(np.zeros(1), s, True, *good)
    with pytest.raises(ValueError, match="read-only"):
        _pathc.evaluate(path._table, s, True, *good[:2], path._table[:4])   # read-only


@pytest.mark.parametrize("name", ["spline_then_line", "platform_chain", "pick_and_place"])
def test_a_path_survives_pickling(name):
    """A TaskPath sent to another process (Dask, multiprocessing) is rebuilt from its pieces:
    the same stops and the same points, bit for bit (it could not be unpickled before: its
    immutability refused the attributes pickle sets)."""
    path = PATHS[name]()
    back = pickle.loads(pickle.dumps(path))
    assert np.array_equal(back.stops, path.stops) and back.kinds == path.kinds
    s = np.linspace(0.0, path.length, 501)
    for a, b in zip(back.evaluate(s), path.evaluate(s)):
        assert np.array_equal(_bits(a), _bits(b))
