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

**The model file's own design** (evaluated once per run beside the optimiser's designs,
:mod:`.runner`) never enters the front; :meth:`DesignFront.file_design` says where it stands
against it: which designs of the front dominate it, and its :func:`distance_to_front`.
"""
from dataclasses import dataclass

import numpy as np

__all__ = ["front_indices", "hypervolume", "reference_point", "MARGIN", "DesignFront",
           "read_front", "format_front", "dominated_by", "distance_to_front",
           "format_file_design"]

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


def dominated_by(f, front):
    """Which points of ``front`` dominate ``f`` (no worse in every objective, better in one).

    Parameters
    ----------
    f : array_like, (n_obj,)
        A point, minimised.
    front : array_like, (n, n_obj)
        The front's points, minimised.

    Returns
    -------
    ndarray of int
        Row indices into ``front``, ascending.
    """
    f = np.asarray(f, dtype=float)
    P = np.asarray(front, dtype=float).reshape(-1, len(f))
    return np.flatnonzero(np.all(P <= f, axis=1) & np.any(P < f, axis=1))


def distance_to_front(f, front):
    """How far a point is behind a front, relative to the point's own values: the largest
    fraction ``t`` by which one point of the front beats ``f`` in every objective at once,
    ``max_j min_i (f_i - p_ji) / |f_i|`` over the points ``p_j`` that dominate ``f`` (all
    minimised; an objective whose value is 0 is counted in its own unit). 0 for a point no
    point of the front dominates.

    Equivalently, the least improvement, the same fraction of its own value in every
    objective, after which no point of the front dominates ``f``: it must leave each of their
    dominated orthants, and it leaves the orthant of ``p_j`` once it has gained ``f_i - p_ji``
    in one objective ``i``. A distance of 0.05: a design of the front is at least 5 % better in
    every objective.

    Parameters
    ----------
    f : array_like, (n_obj,)
        A point, minimised.
    front : array_like, (n, n_obj), n >= 1
        The front's points, minimised.

    Returns
    -------
    float
        A fraction (dimensionless, >= 0).
    """
    f = np.asarray(f, dtype=float)
    P = np.asarray(front, dtype=float).reshape(-1, len(f))
    dom = dominated_by(f, P)
    if not len(dom):
        return 0.0
    scale = np.where(np.abs(f) > 0, np.abs(f), 1.0)
    return float(np.max(np.min((f - P[dom]) / scale, axis=1)))


@dataclass(frozen=True)
class DesignFront:
    """The front of a design run's folder (:func:`read_front`).

    Attributes
    ----------
    info : dict
        ``DIR/design.json``: the study, its objectives (name, sense), constraints, provenance.
    columns : dict
        {column: ndarray (N,)} of every evaluated design (:func:`.store.read_designs`), the
        model file's own design among them (column ``file_design``).
    index : ndarray of int
        The rows of ``columns`` on the front, in the order listed (``INDEX`` of ``design
        pick`` is a position in it, from 0); never the model file's design's row.
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

    def _minimised(self, rows):
        """(len(rows), n_obj) objectives of ``rows``, as minimised."""
        return np.column_stack([(-1.0 if o["sense"] == "max" else 1.0)
                                * np.asarray(self.columns[o["name"]], dtype=float)[rows]
                                for o in self.objectives]).reshape(len(rows), -1)

    @property
    def file_row(self):
        """The row of ``columns`` of the model file's own design, or None (a run of an earlier
        pm2dof, or one interrupted before it was evaluated)."""
        rows = np.flatnonzero(self.columns.get("file_design", np.zeros(0, dtype=bool)))
        return int(rows[0]) if len(rows) else None

    @property
    def searched(self):
        """(N,) bool: the rows the optimiser asked for (every row but the file's design)."""
        return ~np.asarray(self.columns.get("file_design", np.zeros(len(self.columns[
            "feasible"]), dtype=bool)), dtype=bool)

    def file_design(self):
        """Where the model file's own design stands against the front, or None if the run
        holds none.

        Returns
        -------
        dict or None
            ``design`` ({variable: value}, m), ``objectives`` ({name: value}, each in its own
            sense), ``feasible`` (every constraint met), ``on_front`` (feasible, and no design
            of the front dominates it), ``dominated_by`` (the positions in the front, design
            pick's INDEX, of the designs that dominate it) and ``distance``
            (:func:`distance_to_front`: the largest fraction by which one design of the front
            beats it in every objective at once; 0 on the front; None when it breaks a
            constraint or the front is empty) and ``beaten_most_by`` (the position in the front
            of that design; None when no design of the front dominates it).
        """
        r = self.file_row
        if r is None:
            return None
        names = [o["name"] for o in self.objectives]
        feasible = bool(self.columns["feasible"][r])
        f = self._minimised([r])[0]
        P = self._minimised(self.index)
        dom = dominated_by(f, P) if len(P) else np.zeros(0, dtype=int)
        best = None
        if len(dom):
            scale = np.where(np.abs(f) > 0, np.abs(f), 1.0)
            best = int(dom[np.argmax(np.min((f - P[dom]) / scale, axis=1))])
        return {"design": {v: float(self.columns[v][r]) for v in self.variables},
                "objectives": {n: float(self.columns[n][r]) for n in names},
                "feasible": feasible,
                "on_front": feasible and not len(dom),
                "dominated_by": [int(i) for i in dom],
                "distance": (distance_to_front(f, P) if feasible and len(P) else None),
                "beaten_most_by": best}

    def payload(self):
        """The front as the JSON of ``design run --json`` and ``design show --json``:
        ``{"objectives": [{"name", "sense"}], "front": [{"design": {name: value},
        "objectives": {name: value}}], "file_design": {...} or null}`` (each objective in its
        own sense; ``file_design``: :meth:`file_design`)."""
        names = [o["name"] for o in self.objectives]
        return {"objectives": self.objectives,
                "front": [{"design": self.design(i),
                           "objectives": {n: float(self.columns[n][r]) for n in names}}
                          for i, r in enumerate(self.index)],
                "file_design": self.file_design()}


def read_front(out):
    """The :class:`DesignFront` of a design run's folder ``out``: the non-dominated feasible
    designs among all the optimiser evaluated (every generation, not only the last; the model
    file's own design aside), sorted by the first objective as minimised.

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
    feasible = np.asarray(cols["feasible"], dtype=bool) & ~np.asarray(cols["file_design"],
                                                                       dtype=bool)
    return DesignFront(info, cols, front_indices(F, feasible, X))


def format_front(fr):
    """The front as a text table: ``#`` (design pick's INDEX), each design variable (m), each
    objective with its unit and sense; how many designs were evaluated; then the model file's
    own design, and where it stands (:meth:`DesignFront.file_design`)."""
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
    searched = fr.searched
    feas = int(np.sum(np.asarray(cols["feasible"], dtype=bool) & searched))
    out = [f"design study {info.get('name')!r}: {len(fr.index)} designs on the front, of "
           f"{int(searched.sum())} evaluated ({feas} feasible)"
           + ("" if info.get("complete") else "; the run has not finished"), line(heads)]
    out += [line(r) for r in rows]
    if not rows:
        out.append("  (no feasible design: every evaluated design breaks a constraint)")
    fd = fr.file_design()
    if fd is not None:
        out.append(format_file_design(fd, units))
    return "\n".join(out)


def format_file_design(fd, units=None):
    """Lines on the model file's own design (:meth:`DesignFront.file_design`'s dict)."""
    units = units or {}
    var = ", ".join(f"{k} = {v:.6g} m" for k, v in fd["design"].items())
    obj = ", ".join(f"{k} {v:.6g}{f' {units[k]}' if units.get(k, '1') != '1' else ''}"
                    for k, v in fd["objectives"].items())
    if not fd["feasible"]:
        where = "it breaks a constraint of the study"
    elif fd["on_front"]:
        where = "on the front: no design of the front dominates it"
    else:
        dom = fd["dominated_by"]
        said = "#" + ", #".join(map(str, dom[:8])) + (f", ... ({len(dom)} designs)"
                                                         if len(dom) > 8 else "")
        where = (f"not on the front: dominated by {said}; the best of them, "
                 f"#{fd['beaten_most_by']}, is {100 * fd['distance']:.3g} % better (or more) in "
                 f"every objective")
    return f"the model file's design ({var}): {obj}\n  {where}"
