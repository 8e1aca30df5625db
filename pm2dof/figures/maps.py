# Figures of the capability maps: singularities, conditioning, force and acceleration.
from pathlib import Path

import numpy as np

from ..analysis.maps import maps_summary, workspace_maps
from ..control.settings import actuator_limits
from ..control.trajectory import line_moves, model_move
from ..core.task import per_actuator
from ..infra.results import provenance, save_figure, write_json
from .experiment import _plt
from .robot import draw_fixed, fixed_key, fixed_points
from .style import log_ticks, wrap

__all__ = ["maps_figures", "maps_figure", "maps_note", "draw_robot_frame"]

FIGURES = {  # file -> the maps it shows, side by side
    "maps_singularity.png": ("type1", "type2"),
    "maps_conditioning.png": ("cond_StS",),
    "maps_force.png": ("force_min_norm", "force_min_max", "force_ratio"),
    "maps_acceleration.png": ("accel_min_norm", "accel_min_max", "accel_ratio"),
}


def _extent(model, maps):
    """(lo, hi) (2,) m of a map's axes: the reachable set and the bases, with room for the
    bases' labels."""
    X, Y = np.meshgrid(maps["x"], maps["y"])
    reach = np.column_stack([X[maps["reachable"]], Y[maps["reachable"]]])
    if not len(reach):                                 # nothing reachable: the whole grid
        reach = np.array([[maps["x"][0], maps["y"][0]], [maps["x"][-1], maps["y"][-1]]])
    b = fixed_points(model)
    lo = np.minimum(b.min(axis=0), reach.min(axis=0))
    hi = np.maximum(b.max(axis=0), reach.max(axis=0))
    pad = 0.1 * float(np.max(hi - lo))
    return lo - pad, hi + pad


def draw_robot_frame(ax, model, maps):
    """Bases (and rails), the reachable set's boundary, for two legs the parallel-singular
    curve, and the model's moves (a platform's: the path of its frame's origin), on an axis
    in metres."""
    X, Y = np.meshgrid(maps["x"], maps["y"])
    ax.contour(X, Y, maps["reachable"].astype(float), levels=[0.5], colors="k", linewidths=0.8)
    if model.n_legs == 2:
        side = np.where(np.isfinite(maps["side"]), maps["side"], np.nan)
        ax.contour(X, Y, side, levels=[0.0], colors="m", linewidths=1.2, linestyles="-")
    draw_fixed(ax, model)
    for speed in line_moves(model):
        xd = model_move(model, speed).xd
        ax.plot(xd[:, 0], xd[:, 1], "-", color="w", lw=3.5)
        ax.plot(xd[:, 0], xd[:, 1], "-", color="tab:red", lw=1.5)
        ax.plot(*xd[0, :2], "o", color="tab:red", ms=4)    # (x, y): a platform's xd has phi
        ax.plot(*xd[-1, :2], "s", color="tab:red", ms=4)
    lo, hi = _extent(model, maps)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")


#: colour bar label and panel title of each map (FIELDS gives the units)
CBAR = {
    "type1": ("type I measure (dimensionless; 0: singular)",
              r"type I measure $\min_i |\sin(q_{bi} - q_{ai})|$"),
    "type2": ("type II measure (dimensionless; 0: singular)",
              r"type II measure $\sigma_{min}$(S, unit rows) / $\sqrt{n/2}$"),
    "cond_StS": (r"cond($S^TS$) (dimensionless)", r"condition number of $S^TS$"),
    "force_min_norm": ("force (N)", "task force available in every direction,\n"
                                    "min-norm split (eq. 21)"),
    "force_min_max": ("force (N)", "task force available in every direction,\n"
                                   "min-max split"),
    "force_ratio": ("min-max / min-norm (ratio)", "force ratio, min-max / min-norm split"),
    "accel_min_norm": (r"acceleration (m/s$^2$)", "acceleration at rest in every direction,\n"
                                                   "min-norm split"),
    "accel_min_max": (r"acceleration (m/s$^2$)", "acceleration at rest in every direction,\n"
                                                  "min-max split"),
    "accel_ratio": ("min-max / min-norm (ratio)", "acceleration ratio, min-max / min-norm"),
}


def _panel(plt, fig, ax, model, maps, key):
    from matplotlib.colors import LogNorm
    from matplotlib.ticker import ScalarFormatter
    X, Y = np.meshgrid(maps["x"], maps["y"])
    Z = np.ma.masked_invalid(maps[key])
    extend = "neither"
    if key == "cond_StS":
        kw = {"norm": LogNorm(vmin=max(1.0, float(Z.min())), vmax=float(Z.max()))}
    elif key.startswith(("force_min", "accel_min")):  # huge beside the edges: colour the bulk
        kw = {"vmax": float(np.percentile(Z.compressed(), 95)), "vmin": float(Z.min())}
        extend = "max"
    elif key.endswith("_ratio"):                      # >= 1; a constant 1 (five-bar) stays 1
        kw = {"vmin": 1.0, "vmax": max(float(Z.max()), 1.01)}
    else:
        kw = {}
    pc = ax.pcolormesh(X, Y, Z, shading="auto", cmap="viridis", **kw)
    cb = fig.colorbar(pc, ax=ax, shrink=0.85, extend=extend, label=CBAR[key][0])
    if key == "cond_StS":
        log_ticks(cb.ax.yaxis)
    else:
        cb.formatter = ScalarFormatter(useOffset=False)
        cb.update_ticks()
    thr = {"type1": model.singularity_threshold, "type2": model.parallel_singularity_threshold}
    if key in thr:
        ax.contour(X, Y, maps[key], levels=[thr[key]], colors="tab:orange", linewidths=1.2,
                   linestyles="--")
    draw_robot_frame(ax, model, maps)
    ax.set_title(_title(model, key), fontsize=9)


def maps_figure(plt, model, maps, keys, note):
    """One figure of the maps ``keys`` side by side, ``note`` wrapped above them."""
    lo, hi = _extent(model, maps)
    aspect = float(np.clip((hi[1] - lo[1]) / (hi[0] - lo[0]), 0.5, 2.0))
    fig, axes = plt.subplots(1, len(keys), figsize=(0.6 + 5.0 * len(keys), 1.6 + 3.4 * aspect),
                             squeeze=False, layout="constrained")
    text = wrap(fig, note, 8)
    # the height above leaves room for a note of 3 lines (5 beside one narrow panel); a longer
    # one (a platform's says its orientation) gets 0.25 in per line more
    extra = text.count("\n") + 1 - (5 if len(keys) == 1 else 3)
    if extra > 0:
        fig.set_figheight(fig.get_figheight() + 0.25 * extra)
    for ax, key in zip(axes[0], keys):
        _panel(plt, fig, ax, model, maps, key)
    fig.suptitle(text, fontsize=8)
    return fig


def _title(model, key):
    """A panel's title: the singularity measures written out for RRR legs at a point, else
    named with where each kind's is defined."""
    if key == "type1" and any(leg.kind != "RRR" for leg in model.spec.legs):
        return "type I measure, min over the legs\n(each kind's: docs/model-file.md)"
    if key == "type2" and model.dof == 3:
        return "type II measure of the legs' lines\n(a platform's: docs/model-file.md)"
    return CBAR[key][1]


def maps_note(model, tau_max=None, phi=None):
    """The key to the maps' figures: model, limits, a platform's orientation ``phi`` (rad; the
    maps' ``phi``), and what each line and marker is."""
    w = actuator_limits(model.spec, tau_max, "maps")
    units = per_actuator(model.spec.actuators, "N m", "N", "N m (revolute) or N (linear)")
    pose = ("" if phi is None else
            f"The platform at phi = {phi:g} rad (its home orientation unless given) over the "
            f"whole map; force: the largest ball of (fx, fy, moment), N and N m alike; "
            f"acceleration: m/s^2 and rad/s^2 alike; the moves drawn by their (x, y).\n")
    hold = (f"Gravity {', '.join(f'{g:g}' for g in model.spec.gravity)} m/s^2: force and "
            f"acceleration are what tau_max leaves once the actuators hold the robot at rest at "
            f"each pose (0 where they cannot). "
            if model.spec.has_gravity else "")
    return (f"Model {model.name!r}; tau_max = {', '.join(f'{v:g}' for v in w)} {units}; Me from "
            f"Tables 1-2. {hold}{pose}Force and acceleration maps: the 95th percentile and above "
            f"share the top colour.\nBlack: the reachable set in the assembly mode; orange dashed: the "
            f"singularity threshold; "
            + ("magenta: the parallel-singular curve; " if model.n_legs == 2 else "")
            + f"red: the moves (o start, square end); {fixed_key(model)}")


def maps_figures(model, out_dir, resolution=121, theta=None, tau_max=None, progress=None,
                 phi=None, command_line=None):
    """Compute :func:`workspace_maps` (a platform at the orientation ``phi``, default its home
    one), write the PNGs of :data:`FIGURES` and ``maps.json`` (the
    summary of :func:`maps_summary` and the provenance, ``command_line`` the command it records,
    None: ``sys.argv``) into ``out_dir``.

    Returns (summary dict, list of written paths).
    """
    plt = _plt()
    maps = workspace_maps(model, resolution, theta, tau_max, progress, phi)
    summary = maps_summary(model, maps, theta, tau_max)
    prov = provenance(model, command_line)
    out_dir = Path(out_dir)
    note = maps_note(model, tau_max, maps["phi"])
    paths = []
    if progress is not None:
        progress(f"capability maps: drawing {len(FIGURES)} figures into {out_dir}")
    for name, keys in FIGURES.items():
        fig = maps_figure(plt, model, maps, keys, note)
        paths.append(save_figure(fig, out_dir / name, prov))
        plt.close(fig)
    paths.append(write_json(out_dir / "maps.json", {"summary": summary, "provenance": prov}))
    return summary, paths
