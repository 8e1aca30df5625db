# A design study's region grid and its measures, each a batched call into the generated C.
"""The region of a design study as a grid of task poses, and what the robot can do there.

The grid is (x, y) as :func:`pm2dof.analysis.workspace_maps` lays it out (rows y, columns x,
``numpy.meshgrid``), ``n`` points per axis over the region's box; a platform's grid repeats it
at ``n_phi`` orientations from the region's phi range (the home orientation when the study
gives none). Every measure is computed for the whole grid at once: one ``Function.map`` call
per generated function (ik, singularity_measures, S, Me and, under gravity, Ge), then NumPy
over the stack. The force and acceleration capability is
:func:`pm2dof.analysis.maps.capability`'s, vectorised.

A pose is *reachable* where the generated ``ik`` answers: every leg reaches it in the model
file's working modes (two legs: the assembly mode; NaN rows otherwise).
"""
import functools

import numpy as np

from ..control.settings import actuator_limits
from ..core.binding import NonFiniteOutputError
from ..core.errors import WorkspaceError

__all__ = ["grid_points", "pose_batch", "capability_batch", "zonotope_inradius_batch",
           "min_norm_radius_batch", "NEAR_SINGULAR"]

#: poses whose type I or type II measure is at most this have no capability (0), as the maps
#: leave them out
NEAR_SINGULAR = 1e-6


def grid_points(region, model):
    """The poses of a region grid and the area each (x, y) point stands for.

    Parameters
    ----------
    region : Mapping
        ``x``, ``y``: (lo, hi) m; ``n``: points per axis (>= 2); ``phi``: (lo, hi) rad or None;
        ``n_phi``: orientations (a platform).
    model : Model
        The robot (its task dimension; a platform's home orientation when ``phi`` is None).

    Returns
    -------
    pts : ndarray (n_phi * n * n, m)
        The poses, phi outermost, then y, then x (m, m, rad).
    cell : float
        dx * dy, m^2: a grid point's share of the area, as the maps count it.
    shape : tuple
        (n_phi, n, n) for a platform, (n, n) for a point.

    The arrays are cached (read-only): the grid of a study is the same at every design, but for
    a platform's home orientation when the region gives no phi range.
    """
    phi = region.get("phi")
    home = float(model.spec.home[2]) if model.dof == 3 and phi is None else None
    return _grid(tuple(region["x"]), tuple(region["y"]), int(region["n"]),
                 None if phi is None else tuple(phi), int(region.get("n_phi", 1)), model.dof,
                 home)


@functools.lru_cache(maxsize=32)
def _grid(xr, yr, n, phi, n_phi, dof, home):
    """:func:`grid_points` of plain values (hashable: the cache's key)."""
    x = np.linspace(*xr, n)
    y = np.linspace(*yr, n)
    X, Y = np.meshgrid(x, y)
    xy = np.stack([X.ravel(), Y.ravel()], axis=1)
    cell = float((x[1] - x[0]) * (y[1] - y[0]))
    if dof == 2:
        xy.setflags(write=False)
        return xy, cell, (n, n)
    phis = np.array([home]) if phi is None else np.linspace(phi[0], phi[1], n_phi)
    pts = np.concatenate([np.column_stack([xy, np.full(len(xy), p)]) for p in phis])
    pts.setflags(write=False)
    return pts, cell, (len(phis), n, n)


def pose_batch(model, pts):
    """Joint coordinates and both singularity measures of every pose, two ``map`` calls.

    Parameters
    ----------
    model : Model
    pts : array_like (K, m)
        Task poses (m, rad for phi).

    Returns
    -------
    q : ndarray (K, 2n)
        ``ik``'s joint coordinates, NaN rows where a pose is out of reach.
    reach : ndarray (K,) bool
        Every leg reaches the pose in the model's working modes.
    sing : ndarray (K, 2)
        [type I, type II] measures (``singularity_measures``), NaN where not reachable.
    """
    pts = np.ascontiguousarray(pts, dtype=float).reshape(-1, model.dof)
    K = len(pts)
    q = np.empty((K, 2 * model.n_legs))
    model.function("ik").map(K, pts, q)
    reach = np.isfinite(q @ np.ones(q.shape[1]))    # a NaN in a row: out of reach (a matrix-
    # vector product propagates it, and takes a tenth of the time of q.sum(axis=1))
    n_reach = int(np.count_nonzero(reach))
    if n_reach == K:                    # every pose reached (the usual case): no copies
        sing = np.empty((K, 2))
        model.function("singularity_measures").map(K, q, sing)
        return q, reach, sing
    sing = np.full((K, 2), np.nan)
    if n_reach:
        s = np.empty((n_reach, 2))
        model.function("singularity_measures").map(n_reach, np.ascontiguousarray(q[reach]), s)
        sing[reach] = s
    return q, reach, sing


def zonotope_inradius_batch(G, centre=None):
    """:func:`pm2dof.analysis.maps.zonotope_inradius` of K zonotopes at once.

    Parameters
    ----------
    G : ndarray (K, k, m)
        Generators as rows, m = 2 or 3 (zero rows are left out).
    centre : ndarray (K, m), optional
        The ball's centres (default the origin).

    Returns
    -------
    ndarray (K,)
        The radius, 0 where the centre is outside or the zonotope is flat.
    """
    G = np.asarray(G, dtype=float)
    K, k, m = G.shape
    size = np.linalg.norm(G, axis=2)                                     # (K, k)
    with np.errstate(invalid="ignore", divide="ignore"):
        if m == 2:
            N = np.stack([-G[..., 1], G[..., 0]], axis=2) / np.hypot(G[..., 0], G[..., 1])[..., None]
            keep = size > 0
        else:
            i, j = np.triu_indices(k, 1)
            N = np.cross(G[:, i], G[:, j])
            s = np.linalg.norm(N, axis=2)
            keep = s > 1e-12 * size[:, i] * size[:, j]
            N = N / s[..., None]
        support = np.abs(np.einsum("kim,kjm->kij", G, np.where(keep[..., None], N, 0.0))
                         ).sum(axis=1)                                   # (K, facets)
        if centre is not None:
            support = support - np.abs(np.einsum("kjm,km->kj", np.where(keep[..., None], N, 0.0),
                                                 np.asarray(centre, dtype=float)))
    support = np.where(keep, support, np.inf)
    r = support.min(axis=1)
    flat = (~keep.any(axis=1)) | ((size > 0).sum(axis=1) < m)
    return np.where(flat, 0.0, np.maximum(r, 0.0))


def min_norm_radius_batch(P, tau_max, tau_hold=None):
    """:func:`pm2dof.analysis.maps.min_norm_radius` of K poses at once.

    Parameters
    ----------
    P : ndarray (K, n, m)
        The min-norm split's matrices (rows P_i).
    tau_max : ndarray (n,)
        Actuator limits (N m or N by the actuator's kind).
    tau_hold : ndarray (K, n), optional
        Efforts already spent (holding the robot against gravity).

    Returns
    -------
    ndarray (K,)
    """
    P = np.asarray(P, dtype=float)
    norms = np.hypot(P[..., 0], P[..., 1]) if P.shape[2] == 2 else np.linalg.norm(P, axis=2)
    room = np.broadcast_to(np.asarray(tau_max, dtype=float), norms.shape)
    if tau_hold is not None:
        room = room - np.abs(tau_hold)
    return np.maximum(np.min(room / norms, axis=1), 0.0)


def _map(model, short, K, outs, *args):
    """``short``'s map over K points into ``outs[0]`` (its singularity output, if any, not
    written)."""
    f = model.function(short)
    f.map(K, *args, outs, *([None] if f.n_out == 2 else []))


def capability_batch(model, q, theta=None, tau_max=None):
    """:func:`pm2dof.analysis.maps.capability` at K poses, one ``map`` call per function.

    Parameters
    ----------
    model : Model
    q : ndarray (K, 2n)
        Poses (every joint coordinate), each reachable and clear of both singularities by
        more than :data:`NEAR_SINGULAR`.
    theta : array_like (p,), optional
        Parameters of Me and Ge (default the model's nominal theta).
    tau_max : array_like (n,), optional
        Actuator limits (default ``[limits] tau_max``).

    Returns
    -------
    dict
        ``force_min_norm``, ``force_min_max`` (N; N m for phi), ``accel_min_norm``,
        ``accel_min_max`` (m/s^2; rad/s^2 for phi), each (K,): what the limits leave in every
        direction (under gravity, once the robot is held at rest).
    """
    theta = np.ascontiguousarray(model.theta_nominal if theta is None else theta, dtype=float)
    w = actuator_limits(model.spec, tau_max, "capability")
    n, m = model.n_legs, model.dof
    q = np.ascontiguousarray(q, dtype=float)
    K = len(q)
    if K == 0:
        return {k: np.zeros(0) for k in ("force_min_norm", "force_min_max", "accel_min_norm",
                                          "accel_min_max")}
    S, Me = np.empty((K, n * m)), np.empty((K, m * m))
    try:
        _map(model, "S", K, S, q)
        _map(model, "Me", K, Me, q, theta)
        S, Me = S.reshape(K, n, m), Me.reshape(K, m, m)
        P = S @ np.linalg.inv(np.swapaxes(S, 1, 2) @ S)    # eq. 21: tau = S (S^T S)^-1 f
        Mi = np.linalg.inv(Me)
    except (NonFiniteOutputError, np.linalg.LinAlgError):  # an exactly singular pose: one by one
        return _capability_each(model, q, theta, w)
    Ge = hold = Ge_a = None
    if model.spec.has_gravity:                     # at rest: S^T tau = f + Ge (eq. 10)
        Ge = np.empty((K, m))
        _map(model, "Ge", K, Ge, q, theta)
        hold, Ge_a = np.einsum("kij,kj->ki", P, Ge), np.einsum("kij,kj->ki", Mi, Ge)
    return {"force_min_norm": min_norm_radius_batch(P, w, hold),
            "force_min_max": zonotope_inradius_batch(S * w[:, None], Ge),
            "accel_min_norm": min_norm_radius_batch(P @ Me, w, hold),
            "accel_min_max": zonotope_inradius_batch((S @ Mi) * w[:, None], Ge_a)}


def _capability_each(model, q, theta, w):
    """:func:`capability_batch` pose by pose, for a batch holding an exactly singular pose
    (no capability there: 0)."""
    from ..analysis.maps import capability
    keys = ("force_min_norm", "force_min_max", "accel_min_norm", "accel_min_max")
    out = {k: np.zeros(len(q)) for k in keys}
    for j, qj in enumerate(q):
        try:
            c = capability(model, qj, theta, w)
        except (ValueError, WorkspaceError, np.linalg.LinAlgError):
            continue
        for k in keys:
            out[k][j] = c[k]
    return out
