# Figures of the experiment: errors (like the paper's Figs. 4-5), torques, theta_hat, repeated runs.
import numpy as np

from ..analysis.results import save_figure

__all__ = ["write_figures", "experiment_figures"]

COLORS = {"apd": "tab:blue", "na": "tab:red", "na_no_adaptation": "tab:gray"}
LABELS = {"apd": "APD (eq. 40)", "na": "NA (eqs. 28-29)", "na_no_adaptation": "NA, Gamma = 0"}


def _style(name):
    """Line style by parameter group: inertial solid, viscous dashed, Coulomb dotted."""
    return {"alpha": "-", "beta": "-", "gamma": "-", "fv": "--", "fc": ":", "fs": "-."}[
        name.rstrip("0123456789")]


def _plt():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def _errors(plt, results, speed):
    fig, axes = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
    for name in ("apd", "na"):
        r = results[speed][name]
        n = r.n_move
        for k, ax in enumerate(axes):
            ax.plot(r.t[:n], 1e3 * r.e[:n, k], color=COLORS[name],
                    label=f"{LABELS[name]}, RMSE {r.rmse:.3g} m")
    for k, ax in enumerate(axes):
        ax.set_ylabel(f"{'xy'[k]} error (mm)")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    axes[1].set_xlabel("time (s)")
    fig.suptitle(f"Position errors, {speed}-speed move (simulated; cf. the paper's Figs. 4-5)")
    fig.tight_layout()
    return fig


def _torques(plt, results):
    speeds = list(results)
    fig, axes = plt.subplots(len(speeds), 2, figsize=(9, 3 * len(speeds)), squeeze=False,
                             sharex="row")
    for i, speed in enumerate(speeds):
        for j, name in enumerate(("apd", "na")):
            r, ax = results[speed][name], axes[i][j]
            for leg in range(r.tau_a.shape[1]):
                ax.plot(r.t, r.tau_a[:, leg], label=f"tau_a{leg + 1}")
            ax.set_title(f"{LABELS[name]}, {speed} speed", fontsize=9)
            ax.set_ylabel("torque (N m)")
            ax.grid(alpha=0.3)
        axes[i][0].legend(fontsize=8)
    for ax in axes[-1]:
        ax.set_xlabel("time (s)")
    fig.tight_layout()
    return fig


def _theta(plt, results, names):
    speeds = list(results)
    fig, axes = plt.subplots(1, len(speeds), figsize=(5 * len(speeds), 4), squeeze=False)
    for ax, speed in zip(axes[0], speeds):
        r = results[speed]["na"]
        ratio = r.theta_hat / r.theta_hat[0]
        for k, name in enumerate(names):
            ax.plot(r.t, ratio[:, k], _style(name), label=name, lw=1)
        ax.set_title(f"NA estimate theta_hat / theta_hat(0), {speed} speed", fontsize=9)
        ax.set_xlabel("time (s)")
        ax.grid(alpha=0.3)
    axes[0][-1].legend(fontsize=7, ncol=3)
    fig.tight_layout()
    return fig


def _repeated(plt, rep, names, speed):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4))
    runs = np.arange(1, len(rep["rmse"]) + 1)
    a1.plot(runs, rep["rmse"], "o-", color=COLORS["na"], ms=3, label="NA, theta_hat carried over")
    if "apd_rmse" in rep:
        a1.axhline(rep["apd_rmse"], color=COLORS["apd"], ls="--", label="APD (no memory)")
    a1.set_xlabel("run")
    a1.set_ylabel("RMSE (m)")
    a1.set_title(f"Same {speed}-speed move repeated", fontsize=9)
    a1.grid(alpha=0.3)
    a1.legend(fontsize=8)
    theta = np.vstack([rep["theta0"], rep["theta_hat_end"]])
    rel = theta / rep["theta_truth"]
    for k, name in enumerate(names):
        a2.plot(np.arange(len(theta)), rel[:, k], _style(name), lw=1, label=name)
    a2.axhline(1.0, color="k", lw=0.8)
    a2.set_xlabel("run (0: Tables 1-2)")
    a2.set_ylabel("theta_hat / truth")
    a2.set_title("Where theta_hat goes (truth: payload-augmented inertias, fv, fc)", fontsize=9)
    a2.grid(alpha=0.3)
    a2.legend(fontsize=7, ncol=3)
    fig.tight_layout()
    return fig


def write_figures(model, results, repeated, out_dir, prov):
    """Write every figure as PNG into ``out_dir``; returns the list of paths."""
    from pathlib import Path
    plt = _plt()
    out_dir = Path(out_dir)
    written = []
    names = list(model.param_names)
    figs = [(f"errors_{speed}.png", _errors(plt, results, speed)) for speed in results]
    figs.append(("torques.png", _torques(plt, results)))
    figs.append(("theta_hat.png", _theta(plt, results, names)))
    if repeated is not None:
        figs.append(("repeated_runs.png", _repeated(plt, repeated, names, repeated["speed"])))
    for name, fig in figs:
        written.append(save_figure(fig, out_dir / name, prov))
        plt.close(fig)
    return written


def experiment_figures(model, out, runs=40, progress=None):
    """Run the experiment (Table 3 and ``runs`` repeated runs) and write its figures to ``out``.

    Returns (table3 results, repeated-runs dict or None, list of PNG paths).
    """
    from ..analysis.experiment import repeated_runs, table3
    from ..analysis.results import provenance
    results = table3(model, progress=progress)
    rep = None
    if runs > 0:
        moves = model.spec.trajectories
        speed = "high" if "high" in moves else next(iter(moves))
        rep = repeated_runs(model, speed, runs, progress=progress)
        rep["speed"] = speed
        rep["apd_rmse"] = results[speed]["apd"].rmse
    paths = write_figures(model, results, rep, out, provenance(model))
    return results, rep, paths
