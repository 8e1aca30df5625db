# Animation of a closed-loop move: the robot to scale, the paths, the error magnified.
from pathlib import Path

import numpy as np

from ..control.controllers import APDController, NAController
from ..control.simulate import simulate
from ..control.trajectory import model_move
from ..core.errors import ArgumentError, OutputError
from ..infra.results import output_path, provenance, save_figure
from .experiment import COLORS, LABELS, _plt, sci
from .robot import barrels, draw_fixed, fixed_key, fixed_points, leg_points, platform_polygon
from .style import legend_outside

__all__ = ["animate_move", "animation_figure", "render_frames"]

DPI = 80    # of the GIF: about 960 x 380 px

CONTROLLERS = {"na": NAController, "apd": APDController}


def animate_move(model, out, speed="high", controller="na", split=None, magnify=None,
                 fps=20, every=2, settle_time=0.1, progress=None, command_line=None):
    """Simulate one move and write it as an animated GIF (matplotlib animation, Pillow), or
    as one PNG frame at the middle of the move when ``out`` ends in .png.

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
    command_line : list of str, optional
        The command a PNG frame's provenance records (None: ``sys.argv``).

    Returns
    -------
    (Path, SimResult)
    """
    if controller not in CONTROLLERS:
        raise ArgumentError(f"controller must be one of {sorted(CONTROLLERS)}, got {controller!r}")
    if not (isinstance(every, int) and every >= 1 and isinstance(fps, int) and fps >= 1):
        raise ArgumentError(f"every and fps must be integers >= 1, got {every}, {fps}")
    still = Path(out).suffix.lower() == ".png"
    if Path(out).suffix.lower() != ".gif" and not still:
        raise ArgumentError(f"out must name a .gif file (the animation) or a .png file (one "
                            f"frame, at the middle of the move), got {out}")
    out = output_path(out)                  # before any work: a folder, a file in the way
    plt = _plt()
    traj = model_move(model, speed)
    r = simulate(model, CONTROLLERS[controller](model, split=split), traj,
                 settle_time=settle_time)
    e = r.xe - r.xd
    emax = float(np.max(np.hypot(e[:, 0], e[:, 1])))
    length = float(np.linalg.norm((traj.xd[-1] - traj.xd[0])[:2]))   # of the position (x, y)
    if magnify is None:
        magnify = 10.0 ** np.floor(np.log10(0.3 * length / max(emax, 1e-12)))
    if not (np.isfinite(magnify) and magnify > 0):
        raise ArgumentError(f"magnify must be > 0, got {magnify}")
    fig, draw, n_frames = animation_figure(plt, model, r, speed, controller, magnify,
                                           fps=fps, every=every, gif=not still)
    if still:                                    # one frame: the middle of the move
        draw(min(n_frames - 1, (r.n_move // 2) // every))
        save_figure(fig, out, provenance(model, command_line))
        plt.close(fig)
        return out, r
    if progress:
        progress(f"{n_frames} frames of {speed}-speed {controller}, error x{magnify:g}")
    frames = render_frames(fig, draw, n_frames)
    plt.close(fig)
    tmp = out.with_name(f".{out.name}.tmp.gif")
    try:
        _save_gif(frames, tmp, fps)
        tmp.replace(out)                         # atomic: never a half-written GIF
    except OSError as exc:
        tmp.unlink(missing_ok=True)
        raise OutputError(f"cannot write {out}: {exc.strerror or exc}") from None
    return out, r


def render_frames(fig, draw, n_frames):
    """The frames as RGB images: the figure drawn once without the artists ``draw`` moves
    (marked animated), then per frame that background restored and only those artists drawn
    on it (blitting). A full redraw per frame (matplotlib's FuncAnimation.save: 244 redraws for
    80 frames) re-rendered every axis, tick and legend each time for the same pixels."""
    from PIL import Image
    moving = draw(0)
    for a in moving:
        a.set_animated(True)
    canvas = fig.canvas
    canvas.draw()
    background = canvas.copy_from_bbox(fig.bbox)
    out = []
    for j in range(n_frames):
        canvas.restore_region(background)
        for a in draw(j):
            fig.draw_artist(a)
        out.append(Image.frombuffer("RGBA", canvas.get_width_height(), canvas.buffer_rgba(),
                                    "raw", "RGBA", 0, 1).convert("RGB"))
    return out


def _save_gif(frames, path, fps):
    """An animated GIF with one palette for every frame, taken from the first, and no
    dithering: frames then differ only where something moved, and Pillow stores only that
    (a third of the size of independently dithered frames)."""
    from PIL import Image
    first = frames[0].quantize(colors=128, method=Image.Quantize.MEDIANCUT,
                               dither=Image.Dither.NONE)
    rest = [f.quantize(palette=first, dither=Image.Dither.NONE) for f in frames[1:]]
    first.save(path, format="GIF", save_all=True, append_images=rest,
               duration=int(1000 / fps), loop=0)


def animation_figure(plt, model, r, speed, controller, magnify, fps=20, every=2, gif=True):
    """The animation's figure for the rollout ``r`` (a :class:`SimResult`), and its frames
    (``gif``: the title says how much slower than real time the GIF runs; False for a still).

    Returns (fig, draw, n_frames): ``draw(j)`` sets the figure to frame j (sample ``j * every``
    of ``r``) and returns the artists it changed (the same objects every frame: their data
    is updated, nothing is created). The layout is fixed at frame 0, so that nothing moves
    between frames.
    """
    e = r.xe - r.xd
    shown = r.xd + magnify * e
    qs = np.array([model.ik(x) for x in r.xe])
    frames = np.arange(0, len(r.t), every)
    period = float(r.t[1] - r.t[0])
    fig, (ax, az, ae) = plt.subplots(1, 3, figsize=(12, 4.8), layout="constrained",
                                     gridspec_kw={"width_ratios": [1.1, 1, 1]})
    color = COLORS[controller]
    links = [leg_points(model, qs[k]) for k in frames]     # per frame, per leg (k, 2)
    cyls = [barrels(model, qs[k]) for k in frames]         # RPR legs' cylinders
    bodies = [platform_polygon(model, r.xe[k]) for k in frames]   # a platform's outline
    pts = np.vstack([fixed_points(model)] + [p for f in links for p in f])
    lo, hi = pts.min(axis=0) - 0.07, pts.max(axis=0) + 0.07    # room for the labels
    draw_fixed(ax, model, ms=8, fontsize=9, offset=9.0, label=fixed_key(model, marks=False))
    ax.plot(r.xd[:, 0], r.xd[:, 1], "-", color="0.6", lw=3, label="desired path")
    trace_true, = ax.plot([], [], "-", color=color, lw=1, label="actual path, true scale")
    body = None
    if bodies[0] is not None:                      # the platform as a body, under the legs
        from matplotlib.patches import Polygon
        body = ax.add_patch(Polygon(bodies[0], closed=True, fc="0.85", ec="0.25", lw=1.5,
                                    zorder=1.9, label="platform"))
    legs = [ax.plot([], [], "-o", color="0.25", lw=2, ms=3)[0] for _ in range(model.n_legs)]
    barrel = {i: ax.plot([], [], "-", color="tab:brown", lw=6, solid_capstyle="butt")[0]
              for i in cyls[0]}                    # RPR: the cylinder, the rod slides out
    slider = {i: ax.plot([], [], "s", color="0.1", ms=6)[0]
              for i, leg in enumerate(model.spec.legs) if leg.kind == "PRR"}
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title("the legs to scale", fontsize=9)
    # the move's neighbourhood, the error magnified
    az.plot(r.xd[:, 0], r.xd[:, 1], "-", color="0.6", lw=3)
    trace, = az.plot([], [], "-", color=color, lw=1.2,
                     label=f"xd + {magnify:g} (xe - xd)")
    tip, = az.plot([], [], "o", color=color, ms=5)
    ref, = az.plot([], [], "o", mfc="none", mec="k", ms=7, label="desired point now")
    c_lo, c_hi = np.minimum(shown.min(axis=0), r.xd.min(axis=0)), np.maximum(
        shown.max(axis=0), r.xd.max(axis=0))
    pad = 0.15 * float(np.max(c_hi - c_lo))
    az.set_xlim(c_lo[0] - pad, c_hi[0] + pad)
    az.set_ylim(c_lo[1] - pad, c_hi[1] + pad)
    bar = 1e-4 * magnify                           # 0.1 mm of error on the figure's scale
    x0, y0 = c_lo[0] - 0.6 * pad, c_lo[1] - 0.6 * pad
    az.plot([x0, x0 + bar], [y0, y0], "k-", lw=2.5)
    az.annotate(f"0.1 mm of error (x{magnify:g})", (x0, y0), xytext=(0, 4),
                textcoords="offset points", fontsize=8, va="bottom")
    az.set_aspect("equal")
    az.set_xlabel("x (m)")
    az.set_ylabel("y (m)")
    az.set_title(f"the move, error magnified x{magnify:g}", fontsize=9)
    err_mm = 1e3 * np.hypot(e[:, 0], e[:, 1])
    ae.plot(r.t, err_mm, color=color, lw=1)
    ae.axvline(r.t[r.n_move - 1], color="0.5", ls=":", lw=1)
    cursor = ae.axvline(0.0, color="k", lw=1)
    ae.set_xlabel("time (s); dotted: end of the move")
    ae.set_ylabel("|xd - xe| (mm)" if model.dof == 2 else "|xd - xe| of (x, y) (mm)")
    ae.grid(alpha=0.3)
    slow = 1.0 / (fps * every * period)            # real seconds per GIF second
    fig.suptitle(f"{model.name}: {LABELS[controller]}, {speed}-speed move, RMSE (eq. 41) "
                 f"{sci(r.rmse)} m"
                 + (f"; the GIF runs {slow:.3g}x slower than real time" if gif else ""),
                 fontsize=10)
    legend_outside(fig, [ax, az], "lower", ncol=5, fontsize=9)

    def draw(j):
        k = frames[j]
        for line, seg in zip(legs, links[j]):
            line.set_data(seg[:, 0], seg[:, 1])
        for i, line in barrel.items():
            line.set_data(cyls[j][i][:, 0], cyls[j][i][:, 1])
        for i, mark in slider.items():
            mark.set_data(links[j][i][:1, 0], links[j][i][:1, 1])
        if body is not None:
            body.set_xy(bodies[j])
        trace_true.set_data(r.xe[:k + 1, 0], r.xe[:k + 1, 1])
        trace.set_data(shown[:k + 1, 0], shown[:k + 1, 1])
        tip.set_data([shown[k, 0]], [shown[k, 1]])
        ref.set_data([r.xd[k, 0]], [r.xd[k, 1]])
        cursor.set_xdata([r.t[k], r.t[k]])
        ae.set_title(f"t = {r.t[k]:.3f} s, |xd - xe| = {err_mm[k]:.4f} mm", fontsize=9)
        return [*([body] if body is not None else []), trace_true, *legs, *barrel.values(),
                *slider.values(), trace, tip, ref, cursor, ae.title]                      # as drawn: in order

    draw(0)
    fig.set_dpi(DPI)
    fig.canvas.draw()
    fig.set_layout_engine("none")                  # frozen: the panels stay put
    return fig, draw, len(frames)
