# What a study's rows say: RMSE per controller, NA over APD on the same plants, gain maps, runs.
"""Summaries of a study's results (``pm2dof study report``, run by :func:`.jobs.run_report`).

Every statistic is over the rows of the Parquet dataset; medians and 5th/95th percentiles
because RMSE distributions are skewed. The RPE of a controller over APD (100 (APD - X) / APD,
the paper's measure) is paired: the two rollouts of one pair met the same plant (same draw),
move and repetition.
"""
import numpy as np

__all__ = ["summarise", "format_report", "columns_of"]

_METRIC_KEYS = {"rollout", "controller", "law", "move", "draw", "run", "rmse", "max_error",
                "peak_tau", "n_saturated", "n_singular", "n_non_finite", "diverged",
                "theta_error"}


def columns_of(table):
    """{column: ndarray} of a pyarrow table (nulls as NaN in float columns)."""
    return {k: table.column(k).to_numpy(zero_copy_only=False) for k in table.column_names}


def _q(x):
    x = x[np.isfinite(x)]
    if not len(x):
        return {"median": None, "p05": None, "p95": None}
    p05, med, p95 = np.percentile(x, [5, 50, 95])
    return {"median": float(med), "p05": float(p05), "p95": float(p95)}


def _groups(cols, *keys):
    """{tuple of key values: boolean mask} in order of first appearance."""
    out = {}
    for vals in zip(*[cols[k] for k in keys]):
        out.setdefault(vals, None)
    return {g: np.logical_and.reduce([cols[k] == v for k, v in zip(keys, g)]) for g in out}


def _spearman(a, b):
    """Spearman's rank correlation (no ties expected in continuous draws; ties ranked by order)."""
    ra, rb = np.argsort(np.argsort(a)), np.argsort(np.argsort(b))
    return float(np.corrcoef(ra, rb)[0, 1])


def _bins(v, y):
    """Median of y by value of v (up to 5 distinct values) or by terciles of v."""
    vals = np.unique(v)
    if len(vals) <= 5:
        edges = [(x, x) for x in vals]
    else:
        e = np.percentile(v, [0, 100 / 3, 200 / 3, 100])
        edges = list(zip(e[:-1], e[1:]))
    out = []
    for i, (lo, hi) in enumerate(edges):
        m = (v >= lo) & ((v <= hi) if (i == len(edges) - 1 or lo == hi) else (v < hi))
        if not m.any():
            continue
        out.append({"lo": float(lo), "hi": float(hi), "rpe_median": _q(y[m])["median"],
                    "pairs": int(m.sum())})
    return out


def _reference(cols, grid_keys):
    """Name of the APD controller to compare with: law apd and no grid."""
    names = [c for c in dict.fromkeys(cols["controller"][cols["law"] == "apd"])]
    plain = [c for c in names
             if all(np.isnan(cols[k][cols["controller"] == c]).all() for k in grid_keys)]
    return "apd" if "apd" in plain else (plain[0] if plain else None)


def summarise(cols, info):
    """The report's numbers as a JSON-able dict (see :func:`format_report`)."""
    grid_keys = [k for k in info.get("grid_keys", []) if k in cols]
    unc = [k for k in cols if k not in _METRIC_KEYS and k not in grid_keys]
    out = {"study": info["name"], "rows": int(len(cols["rollout"])),
           "complete": bool(info.get("complete")), "rollouts_expected": info.get("rollouts"),
           "rmse": [], "rpe": [], "rpe_vs_uncertainty": [], "grids": [], "runs": []}
    for (c, mv), sel in _groups(cols, "controller", "move").items():
        n = int(sel.sum())
        out["rmse"].append({
            "controller": c, "move": mv, "rollouts": n, **_q(cols["rmse"][sel]),
            "max_error_median": _q(cols["max_error"][sel])["median"],
            "peak_tau_median": _q(cols["peak_tau"][sel])["median"],
            "saturated_share": float(np.mean(cols["n_saturated"][sel] > 0)),
            "singular_rollouts": int(np.sum(cols["n_singular"][sel] > 0)),
            "diverged": int(np.sum(cols["diverged"][sel]))})
    ref = _reference(cols, grid_keys)
    if ref is not None:
        for (c, mv), sel in _groups(cols, "controller", "move").items():
            if c == ref:
                continue
            rsel = (cols["controller"] == ref) & (cols["move"] == mv)
            a = {(d, r): e for d, r, e in zip(cols["draw"][rsel], cols["run"][rsel],
                                             cols["rmse"][rsel])}
            pairs = [(a[(d, r)], e, i) for d, r, e, i in zip(
                cols["draw"][sel], cols["run"][sel], cols["rmse"][sel], np.flatnonzero(sel))
                if (d, r) in a]
            if not pairs:
                continue
            apd, x, idx = (np.array(v) for v in zip(*pairs))
            rpe = 100 * (apd - x) / apd
            out["rpe"].append({"controller": c, "reference": ref, "move": mv,
                               "pairs": len(rpe), **_q(rpe),
                               "share_better": float(np.mean(rpe > 0))})
            for k in unc:
                v = cols[k][idx].astype(float)
                if len(np.unique(v)) < 2:
                    continue
                out["rpe_vs_uncertainty"].append({"controller": c, "move": mv, "key": k,
                                                  "spearman": _spearman(v, rpe),
                                                  "bins": _bins(v, rpe)})
    for (c, mv), sel in _groups(cols, "controller", "move").items():
        keys = [k for k in grid_keys if not np.isnan(cols[k][sel]).all()]
        if not keys or len(keys) > 2:
            continue
        axes = [sorted(np.unique(cols[k][sel]).tolist()) for k in keys]
        med = np.full([len(a) for a in axes], np.nan)
        for idx in np.ndindex(med.shape):
            m = sel.copy()
            for k, a, i in zip(keys, axes, idx):
                m &= cols[k] == a[i]
            med[idx] = _q(cols["rmse"][m])["median"] or np.nan
        best = np.unravel_index(np.nanargmin(med), med.shape)
        out["grids"].append({
            "controller": c, "move": mv, "keys": keys, "values": axes,
            "rmse_median": med.tolist(),
            "best": {**{k: a[i] for k, a, i in zip(keys, axes, best)}, "rmse": float(med[best])},
            "within_10_percent_share": float(np.mean(med <= 1.1 * med[best]))})
    if cols["run"].max(initial=0) > 0:
        for (c, mv, r), sel in _groups(cols, "controller", "move", "run").items():
            out["runs"].append({"controller": c, "move": mv, "run": int(r),
                                "rmse_median": _q(cols["rmse"][sel])["median"],
                                "theta_error_median": _q(cols["theta_error"][sel])["median"]})
    return out


def _f(x, fmt=".3e"):
    return "-" if x is None else format(x, fmt)


def format_report(s):
    """Text tables of :func:`summarise`'s dict."""
    lines = [f"study {s['study']!r}: {s['rows']} rows"
             + ("" if s["complete"] else f" (INCOMPLETE: {s['rollouts_expected']} expected; "
                "rerun `pm2dof study run` with the same --out)"),
             "", "RMSE of the end-effector position (eq. 41), m: median [5th, 95th percentile]",
             f"{'controller':24s} {'move':6s} {'rollouts':>8s} {'median':>10s} {'p05':>10s} "
             f"{'p95':>10s} {'max|e| med':>10s} {'peak tau':>8s} {'sat.':>5s} {'div.':>4s}"]
    for r in s["rmse"]:
        lines.append(f"{r['controller']:24s} {r['move']:6s} {r['rollouts']:8d} "
                     f"{_f(r['median']):>10s} {_f(r['p05']):>10s} {_f(r['p95']):>10s} "
                     f"{_f(r['max_error_median']):>10s} {_f(r['peak_tau_median'], '.2f'):>8s} "
                     f"{100 * r['saturated_share']:4.0f}% {r['diverged']:4d}")
    if s["rpe"]:
        lines += ["", "RPE over APD on the same plants, %: 100 (APD - X) / APD per pair "
                  "(positive: X tracks better)",
                  f"{'controller':24s} {'move':6s} {'pairs':>6s} {'median':>7s} {'p05':>7s} "
                  f"{'p95':>7s} {'X better':>8s}"]
        for r in s["rpe"]:
            lines.append(f"{r['controller']:24s} {r['move']:6s} {r['pairs']:6d} "
                         f"{_f(r['median'], '.1f'):>7s} {_f(r['p05'], '.1f'):>7s} "
                         f"{_f(r['p95'], '.1f'):>7s} {100 * r['share_better']:7.0f}%")
    if s["rpe_vs_uncertainty"]:
        lines += ["", "What the RPE depends on: the 3 sampled quantities of largest |Spearman rho| "
                  "with it, and the median RPE by their terciles (or values)"]
        by = {}
        for r in s["rpe_vs_uncertainty"]:
            by.setdefault((r["controller"], r["move"]), []).append(r)
        for (c, mv), rs in by.items():
            for r in sorted(rs, key=lambda r: -abs(r["spearman"]))[:3]:
                cells = " | ".join((f"{b['lo']:.3g}" if b["lo"] == b["hi"] else
                                    f"{b['lo']:.3g}..{b['hi']:.3g}")
                                   + f": {_f(b['rpe_median'], '.1f')}" for b in r["bins"])
                lines.append(f"  {c:18s} {mv:5s} {r['key']:30s} rho {r['spearman']:+.2f}  {cells}")
    for g in s["grids"]:
        lines += ["", f"Gain grid of {g['controller']} on {g['move']}: median RMSE, m "
                  f"(rows {g['keys'][0]}" + (f", columns {g['keys'][1]})" if len(g["keys"]) > 1
                                              else ")")]
        med = np.atleast_2d(np.array(g["rmse_median"], dtype=float))
        if len(g["keys"]) == 1:
            med = med.T
        if len(g["keys"]) > 1:
            lines.append(" " * 12 + "".join(f"{v:>10.4g}" for v in g["values"][1]))
        for v, row in zip(g["values"][0], med):
            lines.append(f"{v:>10.4g}  " + "".join(f"{x:10.3e}" for x in row))
        best = ", ".join(f"{k} = {g['best'][k]:.4g}" for k in g["keys"])
        lines.append(f"best: {best}, RMSE {g['best']['rmse']:.3e} m; "
                     f"{100 * g['within_10_percent_share']:.0f}% of the grid within 10 % of it")
    if s["runs"]:
        by, one_move = {}, len({r["move"] for r in s["runs"]}) == 1
        for r in s["runs"]:
            label = r["controller"] if one_move else f"{r['controller']}/{r['move']}"
            by.setdefault(label, {})[r["run"]] = r
        names = list(by)
        runs = sorted({r["run"] for r in s["runs"]})
        w = max(12, *(len(n) + 1 for n in names))
        for key, title, fmt in (("rmse_median", "median RMSE (m)", ".3e"),
                                ("theta_error_median", "median theta error (relative, "
                                 "identifiable directions; NA only)", ".4f")):
            cols = [n for n in names if any(by[n][r][key] is not None for r in by[n])]
            if not cols:
                continue
            lines += ["", f"Repeated runs carrying theta_hat: {title} by run",
                      f"{'run':>4s}" + "".join(f"{n:>{w}s}" for n in cols)]
            for r in runs:
                lines.append(f"{r:4d}" + "".join(
                    f"{_f(by[n][r][key] if r in by[n] else None, fmt):>{w}s}" for n in cols))
    return "\n".join(lines)
