# Animation of a closed-loop move: the robot to scale, the paths, the error magnified (issue 11).
from pathlib import Path

import numpy as np

from ..analysis.experiment import trajectory
from ..control.controllers import APDController, NAController
from ..control.simulate import simulate
from .experiment import COLORS, LABELS, _plt

__all__ = ["animate_move"]

CONTROLLERS = {"na": NAController, "apd": APDController}


def _links(model, q):
    """(n, 3, 2) points base -> elbow -> tip of each leg at the pose q (2n,)."""
    n, legs = model.n_legs, model.spec.legs
    out = np.empty((n, 3, 2))
    for i, leg in enumerate(legs):
        a = np.asarray(leg.base)
        b = a + leg.la * np.array([np.cos(q[i]), np.sin(q[i])])
        out[i] = (a, b, b + leg.lb * np.array([np.cos(q[n + i]), np.sin(q[n + i])]))
    return out


def animate_move(model, out, speed="high", controller="na", split=None, magnify=None,
                 fps=20, every=2, settle_time=0.1, progress=None):
    """Simulate one move and write it as an animated GIF (matplotlib animation, Pillow).

    The legs are drawn to scale at the true pose of every ``every``-th 2 ms sample. The tip's
    error e = xe - xd is invisible at that scale, so the actual path is drawn as
    xd + magnify * e, with the factor and a scale bar on the figure; a second panel shows |e|
    in mm against time.

    Parameters
    ----------
    speed : str
        A move of ``[trajectories]`` ("low", "high").
    controller : {"na", "apd"}
    split : str, optional
        Torque split (default ``[control] split``).
    magnify : float, optional
        Error magnification (default: the largest power of ten that keeps the largest error
        below 0.3 of the move's length).
    fps, every : int
        Frames per second of the GIF, and samples per frame (2: 4 ms of motion per frame).
    settle_time : float
        Seconds at rest after the move, s.

    Returns
    -------
    (Path, SimResult)
    """
    from matplotlib import animation
    if controller not in CONTROLLERS:
        raise ValueError(f"controller must be one of {sorted(CONTROLLERS)}, got {controller!r}")
    if not (isinstance(every, int) and every >= 1 and isinstance(fps, int) and fps >= 1):
        raise ValueError(f"every and fps must be integers >= 1, got {every}, {fps}")
    plt = _plt()
    traj = trajectory(model, speed)
    r = simulate(model, CONTROLLERS[controller](model, split=split), traj,
                 settle_time=settle_time)
    e = r.xe - r.xd
    emax = float(np.max(np.hypot(e[:, 0], e[:, 1])))
    length = float(np.hypot(*(traj.xd[-1] - traj.xd[0])))
    if magnify is None:
        magnify = 10.0 ** np.floor(np.log10(0.3 * length / max(emax, 1e-12)))
    if not (np.isfinite(magnify) and magnify > 0):
        raise ValueError(f"magnify must be > 0, got {magnify}")
    shown = r.xd + magnify * e
    qs = np.array([model.ik(x) for x in r.xe])
    frames = np.arange(0, len(r.t), every)
    if progress:
        progress(f"{len(frames)} frames of {speed}-speed {controller}, error x{magnify:g}")

    fig, (ax, az, ae) = plt.subplots(1, 3, figsize=(12, 4.2),
                                     gridspec_kw={"width_ratios": [1.1, 1, 1]})
    color = COLORS[controller]
    b = model.bases
    links = np.array([_links(model, qs[k]) for k in frames])          # (frames, n, 3, 2)
    pts = np.vstack([b, links.reshape(-1, 2)])
    lo, hi = pts.min(axis=0) - 0.03, pts.max(axis=0) + 0.03
    ax.plot(b[:, 0], b[:, 1], "k^", ms=8)
    ax.plot(r.xd[:, 0], r.xd[:, 1], "-", color="0.6", lw=3, label="desired path")
    trace_true, = ax.plot([], [], "-", color=color, lw=1, label="actual path (true scale)")
    legs = [ax.plot([], [], "-o", color="0.25", lw=2, ms=3)[0] for _ in range(model.n_legs)]
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.legend(fontsize=7, loc="lower right")
    ax.set_title(f"{model.name}: {LABELS[controller]}, {speed} speed; links to scale",
                 fontsize=8)
    # the move's neighbourhood, the error magnified
    az.plot(r.xd[:, 0], r.xd[:, 1], "-", color="0.6", lw=3, label="desired path")
    trace, = az.plot([], [], "-", color=color, lw=1.2, label=f"xd + {magnify:g} (xe - xd)")
    tip, = az.plot([], [], "o", color=color, ms=5)
    ref, = az.plot([], [], "o", mfc="none", mec="k", ms=7)
    c_lo, c_hi = np.minimum(shown.min(axis=0), r.xd.min(axis=0)), np.maximum(
        shown.max(axis=0), r.xd.max(axis=0))
    pad = 0.15 * float(np.max(c_hi - c_lo))
    az.set_xlim(c_lo[0] - pad, c_hi[0] + pad)
    az.set_ylim(c_lo[1] - pad, c_hi[1] + pad)
    bar = 1e-4 * magnify                           # 0.1 mm of error on the figure's scale
    x0, y0 = c_lo[0] - 0.6 * pad, c_lo[1] - 0.6 * pad
    az.plot([x0, x0 + bar], [y0, y0], "k-", lw=2.5)
    az.text(x0, y0 + 0.15 * pad, f"0.1 mm of error (x{magnify:g})", fontsize=7)
    az.set_aspect("equal")
    az.set_xlabel("x (m)")
    az.legend(fontsize=7, loc="upper right")
    slow = fps * every * traj.period                # seconds of GIF per second of motion
    az.set_title(f"the move, error magnified (o: desired point now); {1 / slow:.3g}x slower "
                 f"than real time", fontsize=8)
    err_mm = 1e3 * np.hypot(e[:, 0], e[:, 1])
    ae.plot(r.t, err_mm, color=color, lw=1)
    ae.axvline(r.t[r.n_move - 1], color="0.5", ls=":", lw=1)
    cursor = ae.axvline(0.0, color="k", lw=1)
    ae.set_xlabel("time (s)")
    ae.set_ylabel("|xd - xe| (mm)")
    ae.set_title(f"RMSE (eq. 41) {r.rmse:.3g} m; dotted: end of the move", fontsize=8)
    ae.grid(alpha=0.3)
    clock = ae.text(0.02, 0.95, "", transform=ae.transAxes, fontsize=8, va="top")
    fig.tight_layout()

    def draw(j):
        k = frames[j]
        for line, seg in zip(legs, links[j]):
            line.set_data(seg[:, 0], seg[:, 1])
        trace_true.set_data(r.xe[:k + 1, 0], r.xe[:k + 1, 1])
        trace.set_data(shown[:k + 1, 0], shown[:k + 1, 1])
        tip.set_data([shown[k, 0]], [shown[k, 1]])
        ref.set_data([r.xd[k, 0]], [r.xd[k, 1]])
        cursor.set_xdata([r.t[k], r.t[k]])
        clock.set_text(f"t = {r.t[k]:.3f} s   |e| = {err_mm[k]:.4f} mm")
        return [*legs, trace_true, trace, tip, ref, cursor, clock]

    anim = animation.FuncAnimation(fig, draw, frames=len(frames), blit=False)
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = out.with_name(f".{out.name}.tmp.gif")
    anim.save(tmp, writer=animation.PillowWriter(fps=fps), dpi=72)
    tmp.replace(out)                             # atomic: never a half-written GIF
    plt.close(fig)
    return out, r
