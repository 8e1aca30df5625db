# Figure of the torque splits: tracking and saturation against the actuator limit.
from pathlib import Path

import numpy as np

from ..analysis.splits import split_comparison, tau_max_sweep
from ..core.task import effort_unit
from ..infra.results import provenance, save_figure
from .experiment import COLORS, LABELS, _plt
from .style import legend_outside, log_ticks

__all__ = ["splits_figure", "sweep_figure", "sweep_levels"]

SPLIT_STYLE = {"min_norm": "-", "min_max": "--", "preload": ":"}


def sweep_levels(model, speed="high", k=41):
    """Uniform limits (k,) N*m (N for linear actuators) from 0.7x the min-max split's peak |tau| to 1.1x min-norm's,
    on the move ``speed`` at the model's limits: the range where the splits differ."""
    r = split_comparison(model, speeds=[speed], splits=("min_norm", "min_max"))[speed]
    lo = min(r[c]["min_max"]["peak_tau"] for c in r)
    hi = max(r[c]["min_norm"]["peak_tau"] for c in r)
    return np.linspace(0.7 * lo, 1.1 * hi, k)


def sweep_figure(plt, model, sw, speed, preload=None):
    """The figure of a :func:`tau_max_sweep` result ``sw``: RMSE (eq. 41) and clipped samples
    of every controller and split against the uniform limit."""
    levels = np.asarray(sw["tau_max"], dtype=float)
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.8), sharex=True, layout="constrained")
    for name in ("apd", "na"):
        for split, res in sw[name].items():
            kw = dict(color=COLORS[name], ls=SPLIT_STYLE[split], lw=1.3,
                      label=f"{LABELS[name]}, {split} split")
            a1.semilogy(levels, 1e3 * np.asarray(res["rmse"]), **kw)
            a2.plot(levels, res["n_saturated"], **kw)
    a1.set_ylabel("RMSE, eq. 41 (mm)")
    a2.set_ylabel("samples with a clipped torque")
    for ax in (a1, a2):
        ax.set_xlabel(rf"$\tau_{{max}}$, every actuator ({effort_unit(model)})")
        ax.grid(alpha=0.3, which="both")
    log_ticks(a1.yaxis)
    pre = model.spec.control["preload"] if preload is None else np.broadcast_to(
        np.asarray(preload, dtype=float), (model.n_legs,))
    fig.suptitle(f"{model.name}, {speed}-speed move: tracking and clipping against the torque "
                 f"limit", fontsize=10)
    a1.set_title("tracking", fontsize=9)
    a2.set_title(r"clipped samples; preload split: $|\tau_i| \geq$ "
                 + ", ".join(f"{v:g}" for v in pre) + f" {effort_unit(model)}", fontsize=9)
    legend_outside(fig, [a1], "lower", ncol=2)
    return fig


def splits_figure(model, out_dir, speed="high", preload=None, preload_sign=None, levels=None,
                  progress=None, command_line=None):
    """Write ``splits_<speed>.png``: RMSE (eq. 41) and saturated samples of APD and NA with each
    split against a uniform torque limit, with its provenance (``command_line``: the command it
    records, None: ``sys.argv``). Returns (path, sweep dict of :func:`tau_max_sweep`)."""
    plt = _plt()
    levels = sweep_levels(model, speed) if levels is None else np.asarray(levels, dtype=float)
    sw = tau_max_sweep(model, levels, speed, preload, preload_sign, progress=progress)
    fig = sweep_figure(plt, model, sw, speed, preload)
    path = save_figure(fig, Path(out_dir) / f"splits_{speed}.png", provenance(model, command_line))
    plt.close(fig)
    return path, sw
