# Figures of `pm2dof plan`: the phase plane with the maximum-velocity curve, torques, the path on a map.
"""Three PNGs per planned path (``pm2dof plan --out DIR``):

* ``plan_<name>_phase.png``: the path speed s_d against the arc length s for each split's
  time-optimal plan (and the kinematic S-curve), with each split's maximum-velocity curve;
* ``plan_<name>_torques.png``: the actuator efforts against time of each time-optimal plan
  (inverse dynamics at the 2 ms samples, the generated C) with the limits; the axis in N m
  for revolute actuators, N for linear ones (both named for a model with both);
* ``plan_<name>_map.png``: the path over the min-max force-capability map of the workspace.

Each legend is outside the axes (:func:`pm2dof.figures.style.legend_outside`): the curves and
the map fill their axes; tests/figures/test_figures_layout.py checks the three.
"""
from pathlib import Path

import numpy as np

from ..analysis.maps import workspace_maps
from ..core.task import per_actuator
from ..infra.results import save_figure
from ..planning.torques import path_torques
from .experiment import _plt
from .maps import draw_robot_frame
from .style import legend_outside

__all__ = ["plan_figures"]

_COLORS = {"min_norm": "tab:blue", "min_max": "tab:red", "kinematic": "tab:gray"}


def _phase(plt, name, plans):
    fig, ax = plt.subplots(figsize=(7, 4.6), layout="constrained")
    for key, p in plans.items():
        c = _COLORS.get(key, "k")
        label = (f"kinematic S-curve ({p.duration:.3f} s)" if key == "kinematic" else
                 f"time-optimal, {key} ({p.duration:.3f} s)")
        ax.plot(p.s, p.sdot, "-", color=c, lw=1.4, label=label)
        if key != "kinematic":
            ax.plot(p.s, p.max_velocity, "--", color=c, lw=0.9,
                    label=f"maximum-velocity curve, {key}")
    top = max(float(p.sdot.max()) for p in plans.values())
    mvc = max(float(p.max_velocity.max()) for k, p in plans.items() if k != "kinematic")
    ax.set_ylim(0, min(1.1 * mvc, 6 * top))
    ax.set_xlabel("arc length s (m)")
    ax.set_ylabel("path speed ds/dt (m/s)")
    ax.set_title(f"{name}: phase plane", fontsize=9)
    legend_outside(fig, [ax], "lower", ncol=2, fontsize=7)
    return fig


def _torques(plt, model, name, plans, w):
    opt = {k: p for k, p in plans.items() if k != "kinematic"}
    fig, axes = plt.subplots(len(opt), 1, figsize=(7, 2.6 * len(opt) + 0.5), squeeze=False,
                             sharex=True, layout="constrained")
    for ax, (key, p) in zip(axes[:, 0], opt.items()):
        tr = p.trajectory
        s, sd, sdd = p.profile.evaluate(tr.t)
        tau = path_torques(model, p.path, s, sd, sdd, p.info.get("theta"), w)[key]
        for i in range(model.n_legs):
            ax.plot(tr.t, tau[:, i], lw=1.2, label=f"tau_{i + 1}")
        for i in range(model.n_legs):
            ax.axhline(w[i], color="k", lw=0.6, ls="--", label="+-tau_max" if i == 0 else None)
            ax.axhline(-w[i], color="k", lw=0.6, ls="--")
        ax.set_ylabel(per_actuator(model.spec.actuators, "torque (N m)", "force (N)",
                                   "torque (N m), force (N)"))
        ax.set_title(f"{name}, time-optimal with {key}: {p.duration:.3f} s", fontsize=9)
    axes[-1, 0].set_xlabel("time (s)")
    legend_outside(fig, axes[:1, 0], "lower", ncol=model.n_legs + 1, fontsize=7)
    return fig


def _map(plt, model, name, path, maps):
    fig, ax = plt.subplots(figsize=(5.6, 5.2), layout="constrained")
    X, Y = np.meshgrid(maps["x"], maps["y"])
    Z = np.ma.masked_invalid(maps["force_min_max"])
    pc = ax.pcolormesh(X, Y, Z, shading="auto", cmap="viridis",
                       vmax=float(np.percentile(Z.compressed(), 95)))
    fig.colorbar(pc, ax=ax, shrink=0.8, label="force (N)")
    draw_robot_frame(ax, model, maps)
    p = path.evaluate(np.linspace(0, path.length, 400))[0]
    ax.plot(p[:, 0], p[:, 1], "-", color="w", lw=3.5)
    ax.plot(p[:, 0], p[:, 1], "-", color="tab:orange", lw=1.6, label=f"path {name}")
    ax.set_title("force in every direction within tau_max, min-max split", fontsize=8)
    legend_outside(fig, [ax], "lower", fontsize=7)
    return fig


def plan_figures(model, plans, out_dir, prov, w, resolution=81):
    """Write the three figures of each path of ``plans`` ({(path name, key): Plan}, key a split
    or "kinematic") into ``out_dir``; ``w`` the actuators' limits (n,), N m (N for a linear
    actuator). Returns the files."""
    plt = _plt()
    out_dir = Path(out_dir)
    names = list(dict.fromkeys(name for name, _ in plans))
    maps = workspace_maps(model, resolution, tau_max=w)
    files = []
    for name in names:
        mine = {k: p for (nm, k), p in plans.items() if nm == name and not k.startswith("smooth")}
        for suffix, fig in (("phase", _phase(plt, name, mine)),
                            ("torques", _torques(plt, model, name, mine, w)),
                            ("map", _map(plt, model, name, next(iter(mine.values())).path,
                                         maps))):
            files.append(save_figure(fig, out_dir / f"plan_{name}_{suffix}.png", prov))
            plt.close(fig)
    return files
