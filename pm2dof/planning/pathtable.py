# A TaskPath packed into one float64 array for the C evaluator (pm2dof/planning/_pathc.c).
"""``pack(pieces, ends, dim)``: the table ``_pathc.evaluate`` reads, built once per
:class:`pm2dof.TaskPath`.

Layout (float64)::

    n, dim, ends (n + 1), offsets (n), lengths (n), then each piece at its offset:
    line      0, length, p0 (2), p1 (2), u (2)
    arc       1, center (2), radius, angle0, direction (+1 / -1)
    spline    2, m, N, u (m), P (m, 2), k1, k2, k3 (m - 1, 2), nodes, s_nodes, du_ds (N each)
    oriented  3, has_planar, point (2), phi0, dphi, length, c, the planar piece (as above)
"""
import numpy as np

__all__ = ["pack"]

_KIND = {"line": 0, "arc": 1, "spline": 2}


def _planar(pc):
    kind = _KIND[pc.kind]
    if kind == 0:
        return [0.0, pc.length, *pc.p0, *pc.p1, *pc.u]
    if kind == 1:
        return [1.0, *pc.c, pc.r, pc.a0, pc.d]
    return [2.0, len(pc.u), len(pc.nodes), *pc.u, *pc.P.ravel(), *pc.k1.ravel(),
            *pc.k2.ravel(), *pc.k3.ravel(), *pc.nodes, *pc.s_nodes, *pc.du_ds]


def _piece(pc, dim):
    if dim == 2:
        return _planar(pc)
    point = pc.point if pc.point is not None else (0.0, 0.0)   # an arc's: unused
    head = [3.0, float(pc.planar is not None), *point, pc.phi0, pc.dphi, pc.length, pc.c]
    return head + (_planar(pc.planar) if pc.planar is not None else [])


def pack(pieces, ends, dim):
    """The table of ``pieces`` (a TaskPath's, in order) with junction arc lengths ``ends``
    (n + 1,) m and task dimension ``dim``: a read-only float64 array."""
    n = len(pieces)
    body = [_piece(pc, dim) for pc in pieces]
    start = 2 + 3 * n + 1
    offsets = np.cumsum([start] + [len(b) for b in body[:-1]])
    table = np.concatenate([[n, dim], ends, offsets, [pc.length for pc in pieces],
                            *[np.asarray(b, dtype=float) for b in body]]).astype(float)
    table.setflags(write=False)
    return table
