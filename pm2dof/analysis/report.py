# Model report: what the compiled model says about the robot over its workspace (pm2dof report).
import numpy as np

from ..control.trajectory import line_moves
from ..core.errors import SingularityError, WorkspaceError

__all__ = ["model_report", "report_pose"]


def _pose(m, x, y):
    """The task pose at (x, y): a platform at its home orientation ``[platform] home``."""
    return np.array([x, y] if m.dof == 2 else [x, y, m.spec.home[2]], dtype=float)


def _grid(m, n=41):
    """Task positions on a grid over the bases' bounding box where every function is defined
    (a platform at its home orientation)."""
    lo, hi = m.bases.min(axis=0), m.bases.max(axis=0)
    pts = []
    for x in np.linspace(lo[0], hi[0], n):
        for y in np.linspace(lo[1], hi[1], n):
            try:
                q = m.ik(_pose(m, x, y))
                m.W(q)
            except (WorkspaceError, SingularityError):
                continue
            pts.append((x, y, q))
    return pts


def report_pose(m, pts=None):
    """(xe (m,), what) where the report evaluates Me: the midpoint of the model's first line
    move, or without one (or outside the workspace) the grid point of :func:`_grid` farthest
    from both singularities."""
    for name in line_moves(m):
        t = m.spec.trajectories[name]
        xe = (np.asarray(t["start"], float) + np.asarray(t["end"], float)) / 2
        try:
            m.W(m.ik(xe))
            return xe, f"midpoint of the model's move {name!r}"
        except (WorkspaceError, SingularityError):
            break
    pts = _grid(m) if pts is None else pts
    if not pts:
        raise WorkspaceError(f"model {m.name!r}: no grid point between its bases is inside "
                             f"its workspace and clear of both singularities")
    best = max(pts, key=lambda p: (np.asarray(m.singularity_measures(p[2])) /
                                   [m.singularity_threshold,
                                    m.parallel_singularity_threshold]).min())
    return _pose(m, *best[:2]), "the grid point farthest from both singularities"


def model_report(m, seed=0, samples=200):
    """A text report: parameters, Me at the model's own pose (:func:`report_pose`),
    cond(S^T S) and rank of Y.

    Parameters
    ----------
    m : Model
        The robot.
    seed : int
        Seed of the random states over which Y is stacked.
    samples : int
        How many grid points (at most) Y is stacked at, one random state each.

    Returns
    -------
    str
    """
    rng = np.random.default_rng(seed)
    lines = [f"model {m.name!r}: {m.n_legs} legs, {len(m.param_names)} parameters "
             f"({m.spec.friction} friction)", f"  generated C: {m.library}"]
    lines.append("  theta_nominal ([nominal]; Tables 1-2 for the paper's robot):")
    for name, value in zip(m.param_names, m.theta_nominal):
        lines.append(f"    {name:8s} {value:9.4f}")
    pts = _grid(m)
    xe, what = report_pose(m, pts)
    q = m.ik(xe)
    Me = m.Me(q, m.theta_nominal)
    units = "m" if m.dof == 2 else "m, m, rad"
    lines.append(f"  at xe = {np.round(xe, 6).tolist()} {units} ({what}):")
    linear = any(leg.kind != "RRR" for leg in m.spec.legs)
    lines.append(f"    q  = {np.round(q, 4).tolist()} "
                 + ("rad (qa of a linear actuator in m)" if linear else "rad"))
    rows = ", ".join("[" + ", ".join(f"{v:.4f}" for v in row) + "]" for row in Me)
    lines.append(f"    Me = [{rows}] kg" + ("" if m.dof == 2 else " (kg m, kg m^2 in phi)")
                 + f", eigenvalues {np.round(np.linalg.eigvalsh(Me), 4).tolist()}")
    conds, sings = [], []
    Ys = []
    for _x, _y, qq in pts:
        S = m.S(qq)
        conds.append(np.linalg.cond(S.T @ S))
        sings.append(m.singularity_measures(qq))
    sings = np.array(sings)
    for k in rng.choice(len(pts), size=min(samples, len(pts)), replace=False):
        v = rng.normal(size=(3, m.dof)) * [[0.3], [0.3], [5.0]]
        Ys.append(m.Y(pts[k][2], v[0], v[0], v[2]))  # reference = measured velocity
    Y = np.vstack(Ys)
    sv = np.linalg.svd(Y, compute_uv=False)
    rank = int(np.sum(sv > sv[0] * 1e-10))
    lines.append(f"  over {len(pts)} grid points of the workspace in the model's assembly mode "
                 f"and clear of both singularities:")
    lines.append(f"    cond(S^T S): min {min(conds):.3g}, median {np.median(conds):.3g}, "
                 f"max {max(conds):.3g}")
    lines.append(f"    type I  (RRR |sin(qb_i - qa_i)|, PRR |d . u(qb)|, RPR 1): min "
                 f"{sings[:, 0].min():.3g}, max "
                 f"{sings[:, 0].max():.3g} (threshold {m.singularity_threshold})")
    lines.append(f"    type II ({'sigma_min(S, unit rows)/sqrt(n/2)' if m.dof == 2 else 'the legs lines, docs/model-file.md'}): "
                 f"min {sings[:, 1].min():.3g}, max "
                 f"{sings[:, 1].max():.3g} (threshold {m.parallel_singularity_threshold})")
    lines.append(f"    regressor Y stacked over {len(Ys)} random states: rank {rank} of "
                 f"{Y.shape[1]} (singular values {sv[-1]:.3g} .. {sv[0]:.3g})")
    return "\n".join(lines)
