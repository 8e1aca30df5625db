# Figures of a study's results: RMSE distributions, RPE across the uncertainty, gain maps, runs.
from pathlib import Path

import numpy as np

from ..analysis.results import save_figure
from .experiment import _plt

__all__ = ["study_figures"]


def _color(i):
    return f"C{i % 10}"


_DASHES = ("-", "--", ":", "-.")


def _rmse_ecdf(plt, cols, moves, names):
    fig, axes = plt.subplots(1, len(moves), figsize=(5.2 * len(moves), 4), squeeze=False)
    for ax, mv in zip(axes[0], moves):
        for i, c in enumerate(names):
            x = np.sort(cols["rmse"][(cols["controller"] == c) & (cols["move"] == mv)])
            x = x[np.isfinite(x)]
            if len(x):
                ax.step(x * 1e3, np.arange(1, len(x) + 1) / len(x), where="post",
                        color=_color(i), ls=_DASHES[i % 4], label=c)
        ax.set_xscale("log")
        ax.xaxis.set_minor_formatter(plt.NullFormatter())
        ax.set_xlabel("RMSE, eq. 41 (mm)")
        ax.set_title(f"{mv} move")
        ax.grid(alpha=0.3, which="both")
    axes[0][0].set_ylabel("share of rollouts with RMSE <= x")
    axes[0][0].legend(fontsize=8)
    fig.tight_layout()
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
    fig, axes = plt.subplots(1, len(keys), figsize=(4.2 * len(keys), 3.8), squeeze=False,
                             sharey=True)
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
                ax.scatter(x, y, s=4, alpha=0.35, color=_color(i), label=f"{c}, {mv}")
        ax.axhline(0, color="k", lw=0.8)
        ax.set_xlabel(k)
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel(f"RPE over {ref}, % (positive: better)")
    axes[0][0].legend(fontsize=7, markerscale=3)
    fig.tight_layout()
    return fig


def _grid(plt, g):
    fig, ax = plt.subplots(figsize=(5.6, 4.4))
    med = np.array(g["rmse_median"], dtype=float)
    if len(g["keys"]) == 1:
        ax.semilogy(g["values"][0], med * 1e3, "o-")
        ax.set_xlabel(g["keys"][0])
        ax.set_ylabel("median RMSE (mm)")
    else:
        im = ax.imshow(np.log10(med * 1e3).T, origin="lower", aspect="auto", cmap="viridis")
        ax.set_xticks(range(len(g["values"][0])), [f"{v:.3g}" for v in g["values"][0]],
                      rotation=45)
        ax.set_yticks(range(len(g["values"][1])), [f"{v:.3g}" for v in g["values"][1]])
        ax.set_xlabel(g["keys"][0])
        ax.set_ylabel(g["keys"][1])
        b = [g["values"][i].index(g["best"][k]) for i, k in enumerate(g["keys"])]
        ax.plot(*b, "r*", ms=12, label="best")
        for (i, j), v in np.ndenumerate(med):
            if v <= 1.1 * g["best"]["rmse"]:
                ax.plot(i, j, "w.", ms=4)
        fig.colorbar(im, ax=ax, label="log10 median RMSE (mm)")
        ax.legend(fontsize=8, loc="upper right")
    ax.set_title(f"{g['controller']}, {g['move']} move (dots: within 10 % of best)", fontsize=9)
    fig.tight_layout()
    return fig


def _runs(plt, s, payload_change):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4))
    if payload_change:
        after, mass = payload_change
        for ax in (a1, a2):
            ax.axvline(after - 0.5, color="0.5", ls="--", lw=1)
        a2.annotate(f" payload {mass:g} kg from run {after}", (after - 0.5, 0.02), xycoords=(
            "data", "axes fraction"), va="bottom", fontsize=8, color="0.3")
    by = {}
    for r in s["runs"]:
        by.setdefault((r["controller"], r["move"]), []).append(r)
    for i, ((c, mv), rs) in enumerate(by.items()):
        runs = [r["run"] for r in rs]
        a1.semilogy(runs, [r["rmse_median"] * 1e3 for r in rs], "o-", ms=3, color=_color(i),
                    label=f"{c}, {mv}")
        th = [r["theta_error_median"] for r in rs]
        if any(t is not None for t in th):
            a2.plot(runs, [np.nan if t is None else t for t in th], "o-", ms=3, color=_color(i),
                    label=f"{c}, {mv}")
    a1.set_ylabel("median RMSE (mm)")
    a2.set_ylabel("median theta error (identifiable directions)")
    for ax in (a1, a2):
        ax.set_xlabel("run (theta_hat carried from the run before)")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    fig.tight_layout()
    return fig


def study_figures(cols, summary, out_dir, prov, payload_change=None):
    """Write the figures of a study's rows into ``out_dir``; returns the paths.

    ``rmse_ecdf.png`` always; ``rpe.png`` when there are paired RPEs over a sampled
    uncertainty; ``grid_<controller>_<move>.png`` per gain grid; ``runs.png`` for repeated runs
    (``payload_change``: the study's (after_run, kg), drawn as a line).
    """
    plt = _plt()
    out_dir = Path(out_dir)
    moves = list(dict.fromkeys(cols["move"]))
    names = list(dict.fromkeys(cols["controller"]))
    figs = [("rmse_ecdf.png", lambda: _rmse_ecdf(plt, cols, moves, names))]
    if summary["rpe"] and summary["rpe_vs_uncertainty"]:
        figs.append(("rpe.png", lambda: _rpe(plt, cols, summary)))
    for g in summary["grids"]:
        figs.append((f"grid_{g['controller']}_{g['move']}.png", lambda g=g: _grid(plt, g)))
    if summary["runs"]:
        figs.append(("runs.png", lambda: _runs(plt, summary, payload_change)))
    paths = []
    for name, make in figs:
        fig = make()
        paths.append(save_figure(fig, out_dir / name, prov))
        plt.close(fig)
    return paths
