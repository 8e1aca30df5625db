# Figures of the experiment: errors (like the paper's Figs. 4-5), torques, theta_hat, repeated runs.
import numpy as np
from matplotlib.ticker import MaxNLocator

from ..control.trajectory import line_moves
from ..core.task import effort_unit
from ..infra.results import save_figure
from .style import kind_of, legend_outside, param_styles, place_legend, tex_name

__all__ = ["write_figures", "experiment_figures"]

COLORS = {"apd": "tab:blue", "na": "tab:red", "na_no_adaptation": "tab:gray"}
LABELS = {"apd": "APD (eq. 40)", "na": "NA (eqs. 28-29)", "na_no_adaptation": "NA, Gamma = 0"}
THETA_HAT = r"$\hat\theta$"


def sci(x, digits=3):
    """``x`` in scientific notation without padding: 1.23e-4."""
    m, e = f"{x:.{digits - 1}e}".split("e")
    return f"{m}e{int(e)}"


def _plt():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def _errors(plt, results, speed, task_names=("x", "y")):
    """One panel per task coordinate (a platform's phi in mrad, positions in mm)."""
    fig, axes = plt.subplots(len(task_names), 1, figsize=(7, 0.5 + 2.5 * len(task_names)),
                             sharex=True, layout="constrained")
    for name in ("apd", "na"):
        r = results[speed][name]
        n = r.n_move
        for k, ax in enumerate(axes):
            ax.plot(r.t[:n], 1e3 * r.e[:n, k], color=COLORS[name],
                    label=f"{LABELS[name]}, RMSE (eq. 41) {sci(r.rmse)} m")
    for k, ax in enumerate(axes):
        c = task_names[k]
        ax.set_ylabel(f"{c}d - {c}e ({'mrad' if c == 'phi' else 'mm'})")
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel("time (s)")
    fig.suptitle(f"Tracking errors, {speed}-speed move (simulated; cf. the paper's Figs. 4-5)",
                 fontsize=10)
    legend_outside(fig, axes[:1], "lower", ncol=1)
    return fig


def _torques(plt, results, unit="N m"):
    speeds = list(results)
    fig, axes = plt.subplots(len(speeds), 2, figsize=(9, 0.4 + 3 * len(speeds)), squeeze=False,
                             sharex="row", sharey="row", layout="constrained")
    for i, speed in enumerate(speeds):
        for j, name in enumerate(("apd", "na")):
            r, ax = results[speed][name], axes[i][j]
            for leg in range(r.tau_a.shape[1]):
                ax.plot(r.t, r.tau_a[:, leg], color=f"C{leg}", lw=1,
                        label=rf"$\tau_{{a{leg + 1}}}$, actuator {leg + 1}")
            ax.axvline(r.t[r.n_move - 1], color="0.5", ls=":", lw=1)
            ax.set_title(f"{LABELS[name]}, {speed} speed", fontsize=9)
            ax.set_xlabel("time (s)")
            ax.grid(alpha=0.3)
        axes[i][0].set_ylabel(f"{'force' if unit == 'N' else 'torque'} ({unit})")
    fig.suptitle("Actuator torques (simulated; dotted: the end of the move)", fontsize=10)
    legend_outside(fig, axes[0][:1], "lower")
    return fig


def _theta(plt, results, names):
    speeds = list(results)
    styles = param_styles(names)
    fig, axes = plt.subplots(1, len(speeds), figsize=(5 * len(speeds), 4.6), squeeze=False,
                             layout="constrained")
    for ax, speed in zip(axes[0], speeds):
        r = results[speed]["na"]
        start = r.theta_hat[0]
        shown = [k for k in range(len(names)) if start[k] != 0]   # a 0 has no relative change
        for k in shown:
            change = 100.0 * (r.theta_hat[:, k] / start[k] - 1.0)
            ax.plot(r.t, change, lw=1, label=tex_name(names[k]), **styles[names[k]])
        left = [names[k] for k in range(len(names)) if k not in shown]
        ax.set_title(f"NA's estimate during the {speed}-speed move"
                     + (f"\n({', '.join(left)} start at 0: no relative change, not shown)"
                        if left else ""),
                     fontsize=9)
        ax.set_xlabel("time (s)")
        ax.set_ylabel(THETA_HAT + r"$_k\,/\,$" + THETA_HAT + r"$_k(0) - 1$ (%)")
        ax.grid(alpha=0.3)
    legend_outside(fig, axes[0][:1], "lower", ncol=len({kind_of(n)[0] for n in names}),
                   fontsize=8)
    return fig


def _repeated(plt, rep, names, speed):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.8), layout="constrained")
    runs = np.arange(1, len(rep["rmse"]) + 1)
    a1.plot(runs, 1e3 * np.asarray(rep["rmse"]), "o-", color=COLORS["na"], ms=3,
            label="NA, " + THETA_HAT + " carried over")
    if "apd_rmse" in rep:
        a1.axhline(1e3 * rep["apd_rmse"], color=COLORS["apd"], ls="--",
                   label="APD (no memory)")
    a1.set_xlabel("run")
    a1.set_ylabel("RMSE, eq. 41 (mm)")
    a1.set_title(f"The same {speed}-speed move repeated", fontsize=9)
    a1.grid(alpha=0.3)
    a1.xaxis.set_major_locator(MaxNLocator(integer=True))
    theta = np.vstack([rep["theta0"], rep["theta_hat_end"]])
    truth = np.asarray(rep["theta_truth"], dtype=float)
    rel = theta / np.where(truth != 0, truth, 1.0)
    styles = param_styles(names)
    for k, name in enumerate(names):
        if truth[k] == 0:            # no ratio to a zero truth (a platform's centred mx_p, my_p)
            continue
        a2.plot(np.arange(len(theta)), rel[:, k], lw=1, label=tex_name(name), **styles[name])
    a2.axhline(1.0, color="k", lw=0.8)
    a2.set_xlabel("run (0: Tables 1-2)")
    a2.set_ylabel(THETA_HAT + " / truth at the end of the run")
    zero = [name for k, name in enumerate(names) if truth[k] == 0]
    a2.set_title("Where " + THETA_HAT + r" goes (truth: inertias with the payload, $f_v$, $f_c$)"
                 + (f"\n({', '.join(zero)}: truth 0, no ratio, not shown)" if zero else ""),
                 fontsize=9)
    a2.grid(alpha=0.3)
    a2.xaxis.set_major_locator(MaxNLocator(integer=True))
    place_legend(a1, fontsize=8)
    legend_outside(fig, [a2], "right", fontsize=8)
    return fig


def write_figures(model, results, repeated, out_dir, prov):
    """Write every figure as PNG into ``out_dir``; returns the list of paths."""
    from pathlib import Path
    plt = _plt()
    out_dir = Path(out_dir)
    written = []
    names = list(model.param_names)
    figs = [(f"errors_{speed}.png", _errors(plt, results, speed, model.task_names))
            for speed in results]
    figs.append(("torques.png", _torques(plt, results, effort_unit(model))))
    figs.append(("theta_hat.png", _theta(plt, results, names)))
    if repeated is not None:
        figs.append(("repeated_runs.png", _repeated(plt, repeated, names, repeated["speed"])))
    for name, fig in figs:
        written.append(save_figure(fig, out_dir / name, prov))
        plt.close(fig)
    return written


def experiment_figures(model, out, runs=40, progress=None, command_line=None):
    """Run the experiment (Table 3 and ``runs`` repeated runs) and write its figures to ``out``,
    each with its provenance (``command_line``: the command it records, None: ``sys.argv``).

    Returns (table3 results, repeated-runs dict or None, list of PNG paths).
    """
    from ..analysis.experiment import repeated_runs, table3
    from ..infra.results import provenance
    results = table3(model, progress=progress)
    rep = None
    if runs > 0:
        moves = line_moves(model)
        speed = "high" if "high" in moves else moves[0]
        rep = repeated_runs(model, speed, runs, progress=progress)
        rep["speed"] = speed
        rep["apd_rmse"] = results[speed]["apd"].rmse
    paths = write_figures(model, results, rep, out, provenance(model, command_line))
    return results, rep, paths
