# The figures' shared look: readable log ticks, legends outside the data, parameter styles.
"""Helpers that every figure module uses, so that each reader-facing rule lives in one place.

* :func:`log_ticks` -- a log axis with at least two labelled ticks in plain numbers;
* :func:`legend_outside` -- one legend for the whole figure, outside every axes;
* :func:`place_legend` -- an axes' legend where it covers none of the axes' data, else beside it;
* :func:`wrap` -- a long note wrapped to the figure's width;
* :func:`param_styles` -- one colour per kind of parameter of theta, one line style per leg;
* :data:`UNITS` -- units of the quantities a study samples or grids, for axis labels.

Figures use matplotlib's constrained layout, which keeps titles, labels, colour bars and
``legend_outside`` legends inside the canvas and apart.
"""
import re
import textwrap

import numpy as np

__all__ = ["log_ticks", "legend_outside", "place_legend", "wrap", "param_styles", "kind_of",
           "tex_name", "label_bases", "UNITS", "with_unit"]

#: units of the columns a study samples or grids (pm2dof/studies/spec.py); "" = a factor
UNITS = {"payload_mass": "kg", "fv_scale": "factor", "fc_scale": "factor",
         "stribeck_scale": "factor", "encoder_counts_per_rev": "counts/rev",
         "inertia_error_percent": "%", "Kp": "N/m", "Kv": "N s/m", "Kd": "N s/m", "Q": "1/s",
         "Gamma_scale": "factor on Gamma", "velocity_filter_hz": "Hz", "tau_max": "N m"}


def with_unit(key):
    """``key (unit)`` for a study column, e.g. ``inertia_error_percent_gamma3 (%)``."""
    unit = UNITS.get(key) or next((u for k, u in UNITS.items() if key.startswith(k + "_")),
                                  None)
    return f"{key} ({unit})" if unit else key


def _plain(v, _pos=None):
    """A tick value as a plain number: 0.02, 0.5, 3, 200, 1e+05 only beyond 1e5."""
    return f"{v:.6g}" if 1e-4 <= abs(v) < 1e5 else f"{v:.0e}"


def log_ticks(axis):
    """Label a log-scaled axis (an ``ax.xaxis``, ``ax.yaxis`` or a colour bar's long axis) with
    plain numbers at 1, 2, 5 x 10^k when its view spans less than two decades (so that at least
    two labels show), at 10^k otherwise; unlabelled minor ticks at every integer multiple."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter
    lo, hi = sorted(abs(v) for v in axis.get_view_interval())
    decades = np.log10(hi / lo) if lo > 0 else np.inf
    subs = (1.0, 2.0, 5.0) if decades < 2 else (1.0,)
    if decades < 0.5:                                   # a narrow view: more labels
        subs = tuple(float(s) for s in range(1, 10))
    axis.set_major_locator(LogLocator(base=10, subs=subs))
    axis.set_major_formatter(FuncFormatter(_plain))
    axis.set_minor_locator(LogLocator(base=10, subs=np.arange(1, 10)))
    axis.set_minor_formatter(NullFormatter())


def legend_outside(fig, axes=None, where="lower", ncol=None, handles=None, labels=None,
                   fontsize=8, **kwargs):
    """One legend for the figure, outside every axes (``where``: "lower" or "upper" centre,
    or "right"). Entries are the labelled artists of ``axes`` (default: all), each label once,
    unless ``handles`` and ``labels`` are given; ``kwargs`` go to ``fig.legend``. Needs a figure
    with constrained layout."""
    if handles is None:
        seen, handles, labels = set(), [], []
        for ax in fig.axes if axes is None else axes:
            for h, lab in zip(*ax.get_legend_handles_labels()):
                if lab not in seen:
                    seen.add(lab)
                    handles.append(h)
                    labels.append(lab)
    if not handles:
        return None
    loc = {"lower": "outside lower center", "upper": "outside upper center",
           "right": "outside right center"}[where]
    if ncol is None:
        ncol = 1 if where == "right" else min(len(handles), 4)
    return fig.legend(handles, labels, loc=loc, ncol=ncol, fontsize=fontsize, frameon=False,
                      **kwargs)


_LOCS = ("upper right", "upper left", "lower right", "lower left", "center right",
         "center left", "upper center", "lower center", "center")


def _data_px(ax):
    """(k, 2) display points of the axes' lines (every vertex and 8 points on every segment)
    and scatter points, inside the axes."""
    from matplotlib.collections import PathCollection
    pts = []
    for line in ax.get_lines():
        v = line.get_transform().transform(line.get_path().vertices)
        v = v[np.isfinite(v).all(axis=1)]
        pts.append(v)
        if len(v) > 1 and line.get_linestyle() not in ("None", "none", "", " "):
            f = np.linspace(0, 1, 9)[1:-1, None, None]
            pts.append((v[:-1] + f * (v[1:] - v[:-1])).reshape(-1, 2))
    for c in ax.collections:
        if isinstance(c, PathCollection) and len(c.get_offsets()):
            pts.append(c.get_offset_transform().transform(np.asarray(c.get_offsets())))
    box = ax.get_window_extent()
    p = np.vstack(pts) if pts else np.empty((0, 2))
    return p[(p[:, 0] >= box.x0) & (p[:, 0] <= box.x1) & (p[:, 1] >= box.y0) & (p[:, 1] <= box.y1)]


def place_legend(ax, **kwargs):
    """The axes' legend at the first of the usual places that covers none of its data and stays
    inside the axes; when every place covers some, to the right of the axes. Call it after the
    data and the limits are final (it draws the figure once to know the layout)."""
    lg = ax.legend(**kwargs)
    fig = ax.figure
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    pts, box = _data_px(ax), ax.get_window_extent(r)
    for loc in _LOCS:
        lg.set_loc(loc)
        b = lg.get_window_extent(r)
        clear = not ((pts[:, 0] > b.x0) & (pts[:, 0] < b.x1) & (pts[:, 1] > b.y0)
                     & (pts[:, 1] < b.y1)).any()
        if clear and b.x0 >= box.x0 and b.x1 <= box.x1 and b.y0 >= box.y0 and b.y1 <= box.y1:
            return lg
    lg.remove()
    return ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, **kwargs)


def label_bases(ax, bases, fontsize=8, offset=8.0):
    """Name the bases A1, A2, ... beside their markers, each label ``offset`` points away from
    the bases' centre (outwards, off the robot). ``bases`` (n, 2) m."""
    bases = np.asarray(bases, dtype=float)
    for i, d in enumerate(bases - bases.mean(axis=0)):
        d = d / (np.hypot(*d) or 1.0)
        ax.annotate(f"A{i + 1}", bases[i], xytext=offset * d, textcoords="offset points",
                    fontsize=fontsize,
                    ha="left" if d[0] > 0.3 else "right" if d[0] < -0.3 else "center",
                    va="bottom" if d[1] > 0.3 else "top" if d[1] < -0.3 else "center")


def wrap(fig, text, fontsize):
    """``text`` wrapped to lines that fit the figure's width at ``fontsize`` points (paragraphs
    split at newlines are wrapped each)."""
    width_pt = fig.get_figwidth() * 72.0
    chars = max(20, int(0.92 * width_pt / (0.55 * fontsize)))
    return "\n".join(textwrap.fill(p, chars) for p in text.split("\n"))


_KIND = re.compile(r"([A-Za-z_]+?)(\d+)$")
_KIND_COLORS = {"alpha": "tab:blue", "beta": "tab:orange", "gamma": "tab:green",
                "kappa": "tab:olive", "fv": "tab:red", "fc": "tab:purple", "fs": "tab:brown",
                "m_p": "tab:pink", "mx_p": "tab:cyan", "my_p": "tab:gray", "I_p": "k"}
#: the platform's parameters (no leg number) and their symbols
_PLATFORM_TEX = {"m_p": "$m_p$", "mx_p": "$m x_p$", "my_p": "$m y_p$", "I_p": "$I_p$"}
_LEG_STYLES = ("-", "--", ":", "-.")


def kind_of(name):
    """("fv", 2) for "fv2": the kind of a parameter of theta and its leg (1-based); a
    platform's parameter has no leg: ("m_p", 0)."""
    match = _KIND.fullmatch(name)
    if match is None:
        return name, 0
    kind, leg = match.groups()
    return kind, int(leg)


def tex_name(name):
    """The paper's symbol of a parameter of theta as mathtext: "alpha1" -> $\\alpha_{1}$,
    "fv2" -> $f_{v2}$."""
    kind, leg = kind_of(name)
    if name in _PLATFORM_TEX:
        return _PLATFORM_TEX[name]
    if kind in ("alpha", "beta", "gamma", "kappa"):
        return rf"$\{kind}_{{{leg}}}$"
    if len(kind) == 2 and kind[0] == "f":
        return rf"$f_{{{kind[1]}{leg}}}$"
    return name


def param_styles(names):
    """{name: dict(color=..., ls=...)} for theta's names: the colour tells the kind (alpha,
    beta, gamma, fv, fc, fs), the line style the leg (1 solid, 2 dashed, 3 dotted, 4 dash-dot)."""
    out = {}
    for name in names:
        kind, leg = kind_of(name)
        out[name] = {"color": _KIND_COLORS.get(kind, "k"),
                     "ls": _LEG_STYLES[max(leg - 1, 0) % len(_LEG_STYLES)]}
    return out
