# The Pareto front of evaluated designs and its hypervolume.
"""The non-dominated designs and the hypervolume they dominate.

Objectives are compared as minimised (a maximised objective negated), as the optimisers see
them (:mod:`.optimize`). Only feasible designs (every constraint ``G <= 0``) enter a front.

**The hypervolume's reference point.** The hypervolume of a front is the area (volume, for
more than two objectives) of the objective space that it dominates and that is bounded by a
reference point ``r`` worse than every point counted. It is only comparable between fronts
measured against the same ``r``. :func:`reference_point` gives the one this package uses: per
objective, the worst (largest minimised) value over the fronts compared, plus 10 % of that
objective's range over them (``nadir + 0.1 (nadir - ideal)``; an objective with no range gets
``+ 0.1 max(1, |nadir|)``), so that the extreme points of every front add volume.
"""
from dataclasses import dataclass

import numpy as np

__all__ = ["front_indices", "hypervolume", "reference_point", "MARGIN", "DesignFront",
           "read_front", "format_front"]

#: the reference point's margin beyond the nadir, as a fraction of each objective's range
MARGIN = 0.1


def front_indices(F, feasible=None, X=None):
    """Indices of the non-dominated rows of ``F`` (pymoo's NonDominatedSorting, first front).

    Parameters
    ----------
    F : array_like, (N, n_obj)
        Objectives, minimised.
    feasible : array_like of bool, (N,), optional
        Rows that may enter the front (default: all).
    X : array_like, (N, k), optional
        The designs: a design evaluated more than once enters once (its first row).

    Returns
    -------
    ndarray of int
        Row indices into ``F``, sorted by the first objective (then the others).
    """
    from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting
    F = np.asarray(F, dtype=float)
    F = F.reshape(len(F), -1)
    keep = np.arange(len(F)) if feasible is None else np.flatnonzero(np.asarray(feasible))
    if X is not None and len(keep):
        _, first = np.unique(np.asarray(X, dtype=float)[keep], axis=0, return_index=True)
        keep = keep[np.sort(first)]
    if not len(keep):
        return np.zeros(0, dtype=int)
    nd = keep[NonDominatedSorting().do(F[keep], only_non_dominated_front=True)]
    order = np.lexsort(F[nd].T[::-1])
    return nd[order]


def reference_point(*fronts, margin=MARGIN):
    """The hypervolume reference point for comparing ``fronts`` (each (n_i, n_obj),
    minimised): the nadir over all of them plus ``margin`` times their range (module
    docstring).

    Parameters
    ----------
    *fronts : array_like
        The fronts to be compared, at least one non-empty.
    margin : float
        Fraction of the range added beyond the nadir.

    Returns
    -------
    ndarray, (n_obj,)
    """
    F = np.vstack([np.asarray(f, dtype=float).reshape(len(f), -1) for f in fronts if len(f)])
    lo, hi = F.min(axis=0), F.max(axis=0)
    span = np.where(hi > lo, hi - lo, np.maximum(1.0, np.abs(hi)))
    return hi + margin * span


def hypervolume(F, ref):
    """The hypervolume of the points ``F`` (minimised) against ``ref`` (pymoo's
    ``pymoo.indicators.hv.HV``); points not better than ``ref`` in every objective add nothing.

    Parameters
    ----------
    F : array_like, (N, n_obj)
        Objectives, minimised (a front, or any set of points).
    ref : array_like, (n_obj,)
        The reference point (:func:`reference_point`).

    Returns
    -------
    float
        In the product of the objectives' units.
    """
    from pymoo.indicators.hv import HV
    ref = np.asarray(ref, dtype=float)
    F = np.asarray(F, dtype=float).reshape(-1, len(ref))
    F = F[np.all(F < ref, axis=1)]
    if not len(F):
        return 0.0
    return float(HV(ref_point=ref)(F))


@dataclass(frozen=True)
class DesignFront:
    """The front of a design run's folder (:func:`read_front`).

    Attributes
    ----------
    info : dict
        ``DIR/design.json``: the study, its objectives (name, sense), constraints, provenance.
    columns : dict
        {column: ndarray (N,)} of every evaluated design (:func:`.store.read_designs`).
    index : ndarray of int
        The rows of ``columns`` on the front, in the order listed (``INDEX`` of ``design
        pick`` is a position in it, from 0).
    """
    info: dict
    columns: dict
    index: np.ndarray

    @property
    def variables(self):
        """The design variables' names, in the study's order."""
        return list(self.info["variables"])

    @property
    def objectives(self):
        """[{"name", "sense"}] of the objectives, in order."""
        return [dict(o) for o in self.info["objectives"]]

    def design(self, i):
        """{variable: value} of the front's design ``i`` (from 0)."""
        r = self.index[i]
        return {v: float(self.columns[v][r]) for v in self.variables}

    def payload(self):
        """The front as the JSON of ``design run --json`` and ``design show --json``:
        ``{"objectives": [{"name", "sense"}], "front": [{"design": {name: value},
        "objectives": {name: value}}]}`` (each objective in its own sense)."""
        names = [o["name"] for o in self.objectives]
        return {"objectives": self.objectives,
                "front": [{"design": self.design(i),
                           "objectives": {n: float(self.columns[n][r]) for n in names}}
                          for i, r in enumerate(self.index)]}


def read_front(out):
    """The :class:`DesignFront` of a design run's folder ``out``: the non-dominated feasible
    designs among all it evaluated (every generation, not only the last), sorted by the first
    objective as minimised.

    Parameters
    ----------
    out : path
        The ``--out`` of ``pm2dof design run``.
    """
    from .store import read_designs
    info, cols = read_designs(out)
    signs = [-1.0 if o["sense"] == "max" else 1.0 for o in info["objectives"]]
    F = np.column_stack([s * cols[o["name"]] for s, o in zip(signs, info["objectives"])])
    X = np.column_stack([cols[v] for v in info["variables"]])
    return DesignFront(info, cols, front_indices(F, cols["feasible"], X))


def format_front(fr):
    """The front as a text table: ``#`` (design pick's INDEX), each design variable (m), each
    objective with its unit and sense; then how many designs were evaluated."""
    info, cols = fr.info, fr.columns
    units = info.get("units") or {}
    names = [o["name"] for o in info["objectives"]]
    heads = (["#"] + [f"{v} (m)" for v in fr.variables]
             + [f"{n}{f' ({units[n]})' if units.get(n) else ''} {o['sense']}"
                for n, o in zip(names, info["objectives"])])
    rows = [[str(i)] + [f"{cols[v][r]:.6g}" for v in fr.variables]
            + [f"{cols[n][r]:.6g}" for n in names] for i, r in enumerate(fr.index)]
    widths = [max(len(h), *(len(r[j]) for r in rows)) if rows else len(h)
              for j, h in enumerate(heads)]
    line = (lambda cells: "  ".join(c.rjust(w) for c, w in zip(cells, widths)))
    feas = int(np.sum(cols["feasible"]))
    out = [f"design study {info.get('name')!r}: {len(fr.index)} designs on the front, of "
           f"{len(cols['feasible'])} evaluated ({feas} feasible)"
           + ("" if info.get("complete") else "; the run has not finished"), line(heads)]
    out += [line(r) for r in rows]
    if not rows:
        out.append("  (no feasible design: every evaluated design breaks a constraint)")
    return "\n".join(out)
