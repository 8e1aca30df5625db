# Figures of a design run: the Pareto front among every evaluated design, and robots to scale.
"""The figures of ``pm2dof design show``.

* ``front.png`` -- every evaluated design in the plane of two objectives (each in its own
  sense, with its unit): feasible designs grey, infeasible ones light crosses, the front
  coloured and numbered as ``design show`` lists it (the ``INDEX`` of ``design pick``), and
  the model file's own design as a star; one panel per pair of objectives (up to six), a
  single objective against the first design variable; a two-variable study adds the plane of
  its variables (where the front's designs lie).
* ``designs.png`` -- the chosen designs of the front (its ends and evenly spaced ones between,
  up to four) drawn to scale with the same axes, each at the study's pose (the region's centre,
  a platform's home), with the file's default design dashed in each panel for comparison.
"""
from pathlib import Path

import numpy as np

from ..infra.results import save_figure
from .experiment import _plt
from .robot import draw_fixed, fixed_key, fixed_points, leg_points, platform_polygon
from .style import legend_outside, wrap

__all__ = ["design_figures", "front_figure", "designs_figure", "chosen", "axis_label"]


def axis_label(info, name):
    """``name (unit)`` of an objective (its unit as design.json records it) or a variable (m),
    with "max" or "min" said."""
    for o in info["objectives"]:
        if o["name"] == name:
            unit = (info.get("units") or {}).get(name)
            return f"{name}{f' ({unit})' if unit else ''}, {o['sense']}imised"
    return f"{name} (m)" if name in info["variables"] else name


def chosen(n, k=4):
    """Up to ``k`` positions of a front of ``n``: both ends and evenly spaced ones between."""
    return sorted({int(round(v)) for v in np.linspace(0, n - 1, min(k, n))}) if n else []


def _panels(info):
    """The (x, y) column pairs of the front figure: every pair of objectives (up to six: four
    objectives give all six), a single objective against the first design variable; and the
    plane of the two design variables of a two-variable study."""
    names = [o["name"] for o in info["objectives"]]
    pairs = ([(a, b) for i, a in enumerate(names) for b in names[i + 1:]][:6]
             if len(names) > 1 else [(info["variables"][0], names[0])])
    if len(info["variables"]) == 2:
        pairs.append(tuple(info["variables"]))
    return pairs


def _limits(v):
    """Axis limits holding the values ``v`` with a 5 % margin (None when there are none)."""
    v = np.asarray(v, float)
    v = v[np.isfinite(v)]
    if not len(v):
        return None
    lo, hi = float(v.min()), float(v.max())
    pad = 0.05 * (hi - lo) if hi > lo else 0.05 * max(abs(hi), 1e-12)
    return lo - pad, hi + pad


def front_figure(plt, fr):
    """The front among every evaluated design (:class:`pm2dof.synthesis.front.DesignFront`):
    one panel per pair of objectives (:func:`_panels`), and the design plane of a two-variable
    study. With two objectives the front is a line; with more, a cloud of points (its
    projection). The axes hold the feasible designs: an infeasible design whose measure failed
    (its worst value, ±1e9) lies outside them."""
    info, cols = fr.info, fr.columns
    n_obj = len(info["objectives"])
    panels = _panels(info)
    ncol = min(len(panels), 4 if len(panels) > 6 else 3)
    nrow = -(-len(panels) // ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.6 * ncol, 4.0 * nrow + 0.6),
                             layout="constrained", squeeze=False)
    searched = fr.searched
    feas = np.asarray(cols["feasible"], dtype=bool) & searched
    bad = ~np.asarray(cols["feasible"], dtype=bool) & searched
    fd, r0 = fr.file_design(), fr.file_row
    shown = chosen(len(fr.index), 12 if n_obj <= 2 else 6)
    used = []
    for ax, (a, b) in zip(axes.ravel(), panels):
        used.append(ax)
        x, y = np.asarray(cols[a], float), np.asarray(cols[b], float)
        ax.plot(x[feas], y[feas], ".", color="0.7", ms=3, label="feasible designs")
        if bad.any():
            ax.plot(x[bad], y[bad], "x", color="0.85", ms=3,
                    label="infeasible (a constraint not met)")
        fx, fy = x[fr.index], y[fr.index]
        if n_obj <= 2 and a not in info["variables"]:
            order = np.argsort(fx)
            ax.plot(fx[order], fy[order], "-o", color="tab:red", ms=4, lw=1, label="the front")
        else:
            ax.plot(fx, fy, "o", color="tab:red", ms=2.5, alpha=0.6, label="the front")
        for i in shown:
            ax.annotate(str(i), (fx[i], fy[i]), xytext=(4, 4), textcoords="offset points",
                        fontsize=7, color="tab:red")
        keep = feas.copy()
        if fd is not None:
            where = ("on the front" if fd["on_front"] else "breaks a constraint"
                     if not fd["feasible"] else "dominated")
            ax.plot([x[r0]], [y[r0]], "*", color="black", ms=11, mfc="gold", zorder=5,
                    label=f"the model file's design ({where})")
            keep[r0] = True
        for lim, setter in ((_limits(x[keep]), ax.set_xlim), (_limits(y[keep]), ax.set_ylim)):
            if lim is not None:
                setter(*lim)
        ax.set_xlabel(axis_label(info, a))
        ax.set_ylabel(axis_label(info, b))
        if a in info["variables"] and b in info["variables"]:
            ax.set_title("the designs searched", fontsize=8)
        ax.grid(alpha=0.3)
    for ax in axes.ravel()[len(panels):]:
        ax.set_visible(False)
    fig.suptitle(wrap(fig, f"design study {info.get('name')!r}: {len(fr.index)} designs on "
                      f"the front, of {int(searched.sum())} evaluated ({int(feas.sum())} "
                      f"feasible); numbers: design pick's INDEX", 9), fontsize=9)
    legend_outside(fig, axes=used, where="lower", ncol=4)
    return fig


def _pose(model, info):
    region = (info.get("inputs") or {}).get("region") or {}
    if model.spec.home is not None:
        return np.asarray(model.spec.home, dtype=float)
    if region.get("x") and region.get("y"):
        return np.array([np.mean(region["x"]), np.mean(region["y"])])
    first = next(iter(model.spec.trajectories.values()))
    return np.asarray(first.get("start"), dtype=float)


def _draw(ax, m, pose, color, ls="-", label=None):
    try:
        q = m.ik(pose)
    except Exception:                       # not assembled at this pose: the bases only
        return False
    if not np.all(np.isfinite(q)):
        return False
    for k, pts in enumerate(leg_points(m, q)):
        ax.plot(pts[:, 0], pts[:, 1], ls, marker="o", color=color, lw=2 if ls == "-" else 1,
                ms=3, label=label if k == 0 else None)
    body = platform_polygon(m, pose)
    if body is not None:
        from matplotlib.patches import Polygon
        ax.add_patch(Polygon(body, closed=True, fc="0.85" if ls == "-" else "none", ec=color,
                             lw=1.2, ls=ls))
    return True


def designs_figure(plt, model, fr, picks=None):
    """The front's chosen designs (``picks``: positions in the front, default
    :func:`chosen`) drawn to scale with ``model.at_design``, one panel each, equal axes."""
    info = fr.info
    picks = chosen(len(fr.index)) if picks is None else list(picks)
    pose = _pose(model, info)
    fig, axes = plt.subplots(1, max(1, len(picks)), figsize=(3.6 * max(1, len(picks)), 4.0),
                             layout="constrained", squeeze=False, sharex=True, sharey=True)
    names = [o["name"] for o in info["objectives"]]
    pts = [fixed_points(model)]
    for ax, i in zip(axes[0], picks):
        values = fr.design(i)
        m2 = model.at_design(values)
        draw_fixed(ax, m2, ms=6, fontsize=7, offset=6.0, label=fixed_key(m2, marks=False))
        _draw(ax, model, pose, "0.6", "--", "the model file's design")
        ok = _draw(ax, m2, pose, "tab:red", "-", "this design")
        pts.append(fixed_points(m2))
        r = fr.index[i]
        obj = (", " if len(names) <= 2 else "\n").join(
            f"{n} {float(fr.columns[n][r]):.4g}" for n in names)
        var = ", ".join(f"{k} {v:.4g}" for k, v in values.items())
        ax.set_title(f"#{i}: {var}\n{obj}" + ("" if ok else "\n(not assembled at the pose)"),
                     fontsize=7)
        ax.set_aspect("equal")
        ax.set_xlabel("x (m)")
        ax.grid(alpha=0.2)
    axes[0][0].set_ylabel("y (m)")
    p = np.vstack(pts)
    span = float(np.max(p.max(axis=0) - p.min(axis=0)))
    pad = 0.35 * span
    axes[0][0].set_xlim(p[:, 0].min() - pad, p[:, 0].max() + pad)
    axes[0][0].set_ylim(p[:, 1].min() - pad, p[:, 1].max() + pad)
    fig.suptitle(wrap(fig, f"designs of the front of {info.get('name')!r}, to scale, at the "
                      f"pose {np.round(pose, 4).tolist()}", 9), fontsize=9)
    legend_outside(fig, axes=list(axes[0]), where="lower", ncol=3)
    return fig


def design_figures(fr, model, out_dir, prov=None, picks=None):
    """Write ``front.png`` and ``designs.png`` of the run's front ``fr`` into ``out_dir``
    (``model``: the run's model, whose ``at_design`` draws each design); returns the paths.

    Parameters
    ----------
    fr : DesignFront
        :func:`pm2dof.synthesis.front.read_front` of the run.
    model : Model
        The study's model (with its ``[design]``).
    out_dir : path
        Folder of the figures.
    prov : dict, optional
        Provenance stored in the PNGs.
    picks : sequence of int, optional
        Front positions drawn (default: :func:`chosen`).
    """
    plt = _plt()
    out_dir = Path(out_dir)
    paths = []
    for name, make in (("front.png", lambda: front_figure(plt, fr)),
                       ("designs.png", lambda: designs_figure(plt, model, fr, picks))):
        if name == "designs.png" and not len(fr.index):
            continue
        fig = make()
        paths.append(save_figure(fig, out_dir / name, prov or {}))
        plt.close(fig)
    return paths
