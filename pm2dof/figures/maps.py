# Figures of the capability maps: singularities, conditioning, force and acceleration (issue 11).
from pathlib import Path

import numpy as np

from ..analysis.experiment import trajectory
from ..analysis.maps import FIELDS, maps_summary, workspace_maps
from ..analysis.results import provenance, save_figure, write_json
from .experiment import _plt

__all__ = ["maps_figures", "draw_robot_frame"]

FIGURES = {  # file -> the maps it shows, side by side
    "maps_singularity.png": ("type1", "type2"),
    "maps_conditioning.png": ("cond_StS",),
    "maps_force.png": ("force_min_norm", "force_min_max", "force_ratio"),
    "maps_acceleration.png": ("accel_min_norm", "accel_min_max", "accel_ratio"),
}


def draw_robot_frame(ax, model, maps):
    """Bases, the reachable set's boundary, for two legs the parallel-singular curve, and the
    model's moves, on an axis in metres."""
    X, Y = np.meshgrid(maps["x"], maps["y"])
    ax.contour(X, Y, maps["reachable"].astype(float), levels=[0.5], colors="k", linewidths=0.8)
    if model.n_legs == 2:
        side = np.where(np.isfinite(maps["side"]), maps["side"], np.nan)
        ax.contour(X, Y, side, levels=[0.0], colors="m", linewidths=1.2, linestyles="-")
    b = model.bases
    ax.plot(b[:, 0], b[:, 1], "k^", ms=7)
    for speed in model.spec.trajectories:
        xd = trajectory(model, speed).xd
        ax.plot(xd[:, 0], xd[:, 1], "-", color="w", lw=3.5)
        ax.plot(xd[:, 0], xd[:, 1], "-", color="tab:red", lw=1.5)
        ax.plot(*xd[0], "o", color="tab:red", ms=4)
        ax.plot(*xd[-1], "s", color="tab:red", ms=4)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")


def _panel(plt, fig, ax, model, maps, key):
    from matplotlib.colors import LogNorm
    X, Y = np.meshgrid(maps["x"], maps["y"])
    Z = np.ma.masked_invalid(maps[key])
    if key == "cond_StS":
        kw = {"norm": LogNorm(vmin=max(1.0, float(Z.min())), vmax=float(Z.max()))}
    elif key.startswith(("force_min", "accel_min")):  # huge beside the edges: colour the bulk
        kw = {"vmax": float(np.percentile(Z.compressed(), 95)), "vmin": float(Z.min())}
    else:
        kw = {}
    pc = ax.pcolormesh(X, Y, Z, shading="auto", cmap="viridis", **kw)
    fig.colorbar(pc, ax=ax, shrink=0.8, label=FIELDS[key][0])
    thr = {"type1": model.singularity_threshold, "type2": model.parallel_singularity_threshold}
    if key in thr:
        ax.contour(X, Y, maps[key], levels=[thr[key]], colors="tab:orange", linewidths=1.2,
                   linestyles="--")
    draw_robot_frame(ax, model, maps)
    ax.set_title(FIELDS[key][1], fontsize=8)


def maps_figures(model, out_dir, resolution=121, theta=None, tau_max=None, progress=None):
    """Compute :func:`workspace_maps`, write the PNGs of :data:`FIGURES` and ``maps.json`` (the
    summary of :func:`maps_summary` and the provenance) into ``out_dir``.

    Returns (summary dict, list of written paths).
    """
    plt = _plt()
    maps = workspace_maps(model, resolution, theta, tau_max, progress)
    summary = maps_summary(model, maps, theta, tau_max)
    prov = provenance(model)
    out_dir = Path(out_dir)
    w = model.spec.limits["tau_max"] if tau_max is None else np.asarray(tau_max, dtype=float)
    note = (f"model {model.name!r}; tau_max = {np.round(w, 3).tolist()} N m; Me from Tables 1-2. "
            f"95th percentile and above share the top colour.\nBlack: reachable set in the assembly mode; orange dashed: singularity threshold; "
            + ("magenta: parallel-singular curve; " if model.n_legs == 2 else "")
            + "red: the moves (o start, square end); triangles: bases")
    paths = []
    for name, keys in FIGURES.items():
        fig, axes = plt.subplots(1, len(keys), figsize=(5.2 * len(keys), 4.6), squeeze=False)
        for ax, key in zip(axes[0], keys):
            _panel(plt, fig, ax, model, maps, key)
        fig.suptitle(note, fontsize=7)
        fig.tight_layout()
        paths.append(save_figure(fig, out_dir / name, prov))
        plt.close(fig)
    paths.append(write_json(out_dir / "maps.json", {"summary": summary, "provenance": prov}))
    return summary, paths
