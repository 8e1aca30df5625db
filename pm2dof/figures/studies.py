# Figures of a study's results: RMSE distributions, RPE across the uncertainty, gain maps, runs.
from pathlib import Path

import numpy as np
from matplotlib.ticker import MaxNLocator

from ..infra.results import save_figure
from .experiment import _plt
from .style import legend_outside, log_ticks, with_unit

__all__ = ["study_figures", "study_figure_makers"]


def _color(i):
    return f"C{i % 10}"


_DASHES = ("-", "--", ":", "-.")


def _rmse_ecdf(plt, cols, moves, names):
    fig, axes = plt.subplots(1, len(moves), figsize=(0.4 + 5.2 * len(moves), 4.6), squeeze=False,
                             sharey=True, layout="constrained")
    for ax, mv in zip(axes[0], moves):
        n = []
        for i, c in enumerate(names):
            x = np.sort(cols["rmse"][(cols["controller"] == c) & (cols["move"] == mv)])
            x = x[np.isfinite(x)]
            n.append(len(x))
            if len(x):
                ax.step(x * 1e3, np.arange(1, len(x) + 1) / len(x), where="post",
                        color=_color(i), ls=_DASHES[i % 4], label=c)
        ax.set_xscale("log")
        log_ticks(ax.xaxis)
        ax.set_xlabel("RMSE, eq. 41 (mm)")
        ax.set_title(f"{mv} move, {max(n)} rollouts per controller", fontsize=9)
        ax.grid(alpha=0.3, which="both")
    axes[0][0].set_ylabel("share of rollouts with RMSE <= x")
    legend_outside(fig, axes[0][:1], "lower")
    return fig


def _rpe(plt, cols, s):
    """RPE over APD against each sampled quantity with the largest rank correlations."""
    entries = s["rpe_vs_uncertainty"]
    keys = []
    for r in sorted(entries, key=lambda r: -abs(r["spearman"])):
        if r["key"] not in keys:
            keys.append(r["key"])
    keys = keys[:4]
    pairs = [(r["controller"], r["move"]) for r in s["rpe"]]
    fig, axes = plt.subplots(1, len(keys), figsize=(0.4 + 4.2 * len(keys), 4.4), squeeze=False,
                             sharey=True, layout="constrained")
    ref = s["rpe"][0]["reference"]
    for ax, k in zip(axes[0], keys):
        for i, (c, mv) in enumerate(pairs):
            a = (cols["controller"] == ref) & (cols["move"] == mv)
            b = (cols["controller"] == c) & (cols["move"] == mv)
            ra = dict(zip(zip(cols["draw"][a], cols["run"][a]), cols["rmse"][a]))
            pts = [(cols[k][j], 100 * (ra[(d, r)] - cols["rmse"][j]) / ra[(d, r)])
                   for j, d, r in zip(np.flatnonzero(b), cols["draw"][b], cols["run"][b])
                   if (d, r) in ra]
            if pts:
                x, y = np.array(pts, dtype=float).T
                ax.scatter(x, y, s=4, alpha=0.35, color=_color(i), label=f"{c}, {mv} move")
        ax.axhline(0, color="k", lw=0.8)
        ax.set_xlabel(with_unit(k))
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel(f"RPE over {ref} (%); > 0: better than {ref}")
    lg = legend_outside(fig, axes[0][:1], "lower", markerscale=3)
    for h in lg.legend_handles if lg else ():
        h.set_alpha(1.0)                          # the key's colours at full strength
    return fig


def _tick(v):
    """A grid value as a short tick label: 54.6k for 54600, 0.5, 195."""
    return f"{v / 1000:.4g}k" if abs(v) >= 1000 else f"{v:.3g}"


def _grid(plt, g):
    from matplotlib.colors import LogNorm
    fig, ax = plt.subplots(figsize=(5.8, 4.8), layout="constrained")
    med = np.array(g["rmse_median"], dtype=float) * 1e3
    if len(g["keys"]) == 1:
        ax.semilogy(g["values"][0], med, "o-")
        ax.set_xlabel(with_unit(g["keys"][0]))
        ax.set_ylabel("median RMSE, eq. 41 (mm)")
        log_ticks(ax.yaxis)
        ax.grid(alpha=0.3, which="both")
        title = f"{g['controller']}, {g['move']} move"
    else:
        nx, ny = (len(v) for v in g["values"])
        im = ax.pcolormesh(np.arange(nx + 1) - 0.5, np.arange(ny + 1) - 0.5, med.T,
                           cmap="viridis", norm=LogNorm(vmin=np.nanmin(med), vmax=np.nanmax(med)))
        ax.set_xticks(range(nx), [_tick(v) for v in g["values"][0]])
        ax.set_yticks(range(ny), [_tick(v) for v in g["values"][1]])
        ax.set_xlabel(with_unit(g["keys"][0]))
        ax.set_ylabel(with_unit(g["keys"][1]))
        b = [g["values"][i].index(g["best"][k]) for i, k in enumerate(g["keys"])]
        ax.plot(*b, "r*", ms=12)
        for (i, j), v in np.ndenumerate(med):
            if v <= 1.1 * 1e3 * g["best"]["rmse"]:
                ax.plot(i, j, "w.", ms=4)
        cb = fig.colorbar(im, ax=ax, label="median RMSE, eq. 41 (mm)")
        log_ticks(cb.ax.yaxis)
        title = (f"{g['controller']}, {g['move']} move (star: best;\nwhite dots: within 10 % "
                 f"of the best)")
    ax.set_title(title, fontsize=9)
    return fig


def _runs(plt, s, payload_change):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.8), layout="constrained")
    if payload_change:
        after, mass = payload_change
        for ax in (a1, a2):
            ax.axvline(after - 0.5, color="0.5", ls="--", lw=1,
                       label=f"payload {mass:g} kg from run {after} on")
    by = {}
    for r in s["runs"]:
        by.setdefault((r["controller"], r["move"]), []).append(r)
    for i, ((c, mv), rs) in enumerate(by.items()):
        runs = [r["run"] for r in rs]
        a1.semilogy(runs, [r["rmse_median"] * 1e3 for r in rs], "o-", ms=3, color=_color(i),
                    label=f"{c}, {mv} move")
        th = [r["theta_error_median"] for r in rs]
        if any(t is not None for t in th):
            a2.plot(runs, [np.nan if t is None else t for t in th], "o-", ms=3, color=_color(i),
                    label=f"{c}, {mv} move")
    a1.set_ylabel("median RMSE, eq. 41 (mm)")
    log_ticks(a1.yaxis)
    a2.set_ylabel(r"median $\|P(\hat\theta - \theta)\| / \|P\theta\|$ (relative)")
    a2.set_title(r"$\hat\theta$'s error on the identifiable directions (P), NA only",
                 fontsize=9)
    a1.set_title("tracking", fontsize=9)
    for ax in (a1, a2):
        ax.set_xlabel("run (" + r"$\hat\theta$" + " carried from the run before)")
        ax.grid(alpha=0.3, which="both")
        ax.xaxis.set_major_locator(MaxNLocator(integer=True))
    legend_outside(fig, [a1], "lower", ncol=3)
    return fig


def study_figure_makers(cols, summary, payload_change=None):
    """[(file name, function returning the figure)] of a study's rows, in the order written."""
    plt = _plt()
    moves = list(dict.fromkeys(cols["move"]))
    names = list(dict.fromkeys(cols["controller"]))
    figs = [("rmse_ecdf.png", lambda: _rmse_ecdf(plt, cols, moves, names))]
    if summary["rpe"] and summary["rpe_vs_uncertainty"]:
        figs.append(("rpe.png", lambda: _rpe(plt, cols, summary)))
    for g in summary["grids"]:
        figs.append((f"grid_{g['controller']}_{g['move']}.png", lambda g=g: _grid(plt, g)))
    if summary["runs"]:
        figs.append(("runs.png", lambda: _runs(plt, summary, payload_change)))
    return figs


def study_figures(cols, summary, out_dir, prov, payload_change=None):
    """Write the figures of a study's rows into ``out_dir``; returns the paths.

    ``rmse_ecdf.png`` always; ``rpe.png`` when there are paired RPEs over a sampled
    uncertainty; ``grid_<controller>_<move>.png`` per gain grid; ``runs.png`` for repeated runs
    (``payload_change``: the study's (after_run, kg), drawn as a line).
    """
    plt = _plt()
    out_dir = Path(out_dir)
    figs = study_figure_makers(cols, summary, payload_change)
    paths = []
    for name, make in figs:
        fig = make()
        paths.append(save_figure(fig, out_dir / name, prov))
        plt.close(fig)
    return paths
