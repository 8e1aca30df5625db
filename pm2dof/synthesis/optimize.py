# The optimisers of a design study: pymoo's NSGA-II, GA and CMA-ES, and an exhaustive grid.
"""The search of a design study, independent of what a design's objectives are.

Every optimiser takes a batch callable ``evaluate(X) -> (F, G)``: ``X`` (N, k) designs in the
study's variable order, ``F`` (N, n_obj) the objectives to *minimise* (a maximised objective
negated), ``G`` (N, n_con) the constraints in pymoo's convention (a design is feasible when
every ``G <= 0``). The callable sees one batch per generation (a pymoo problem with
``elementwise=False``), so it may spread the batch over a cluster. Constraints reach pymoo as
constraints (its constrained domination and tournament), never as penalties on ``F``.

* ``"nsga2"``: NSGA-II, for one or more objectives;
* ``"ga"``: a genetic algorithm, one objective;
* ``"cmaes"``: CMA-ES (pymoo's, through the ``cma`` package pymoo installs), one objective;
* ``"grid"``: every design of an N-point (one variable) or N x N (two variables) grid over the
  bounds, bounds included, in one batch.

The same ``seed`` gives the same designs in the same order (the callable's answers being the
same), which is what lets a run resume from its stored batches.
"""
from dataclasses import dataclass

import numpy as np

from ..core.errors import ArgumentError

__all__ = ["KINDS", "OptimizeResult", "optimize", "grid_designs", "batch_problem"]

#: the optimisers, by the name a study file gives
KINDS = ("nsga2", "ga", "cmaes", "grid")


@dataclass(frozen=True)
class OptimizeResult:
    """Every design an optimiser evaluated, in the order it asked for them.

    Attributes
    ----------
    X : ndarray, (N, k)
        The designs, in the study's variable order.
    F : ndarray, (N, n_obj)
        Their objectives, as minimised (maximised objectives negated).
    G : ndarray, (N, n_con)
        Their constraints, feasible when ``<= 0``.
    generation : ndarray of int, (N,)
        The batch (0 = the first) each design was evaluated in.
    """
    X: np.ndarray
    F: np.ndarray
    G: np.ndarray
    generation: np.ndarray

    @property
    def feasible(self):
        """(N,) bool: every constraint met (``G <= 0``)."""
        return np.all(self.G <= 0.0, axis=1)


def grid_designs(bounds, n):
    """Every design of the grid: ``n`` points per variable, evenly spaced, bounds included.

    Parameters
    ----------
    bounds : sequence of (low, high)
        One or two variables' bounds.
    n : int
        Points per variable (>= 2).

    Returns
    -------
    ndarray, (n, 1) or (n * n, 2)
        For two variables, the first varies slowest (row-major, as ``np.meshgrid(...,
        indexing="ij")``).
    """
    bounds = np.asarray(bounds, dtype=float).reshape(-1, 2)
    if len(bounds) not in (1, 2):
        raise ArgumentError(f"the grid optimiser searches one or two design variables, this "
                            f"study has {len(bounds)}; use nsga2, ga or cmaes")
    if int(n) < 2:
        raise ArgumentError(f"--grid must be >= 2 points per variable, got {n}")
    axes = [np.linspace(lo, hi, int(n)) for lo, hi in bounds]
    mesh = np.meshgrid(*axes, indexing="ij")
    return np.column_stack([m.ravel() for m in mesh])


def batch_problem(evaluate, bounds, n_obj, n_con):
    """A pymoo ``Problem`` (``elementwise=False``) whose batches go to ``evaluate(X) -> (F,
    G)``.

    Parameters
    ----------
    evaluate : callable
        ``(N, k) -> ((N, n_obj), (N, n_con))``.
    bounds : sequence of (low, high)
        Per variable.
    n_obj, n_con : int
        Objectives and constraints.
    """
    from pymoo.core.problem import Problem
    bounds = np.asarray(bounds, dtype=float).reshape(-1, 2)

    class _Batch(Problem):
        def __init__(self):
            super().__init__(n_var=len(bounds), n_obj=n_obj, n_ieq_constr=n_con,
                             xl=bounds[:, 0], xu=bounds[:, 1], elementwise=False)

        def _evaluate(self, X, out, *args, **kwargs):
            F, G = evaluate(X)
            out["F"] = F
            if n_con:
                out["G"] = G

    return _Batch()


def _algorithm(kind, n_obj, population, seed):
    if kind == "nsga2":
        from pymoo.algorithms.moo.nsga2 import NSGA2
        return NSGA2(pop_size=population)
    if n_obj != 1:
        raise ArgumentError(f"the {kind} optimiser minimises one objective, the study has "
                            f"{n_obj}: use nsga2 (or grid)")
    if kind == "ga":
        from pymoo.algorithms.soo.nonconvex.ga import GA
        return GA(pop_size=population)
    if kind == "cmaes":
        from pymoo.algorithms.soo.nonconvex.cmaes import CMAES
        return CMAES(popsize=population, seed=seed)
    raise ArgumentError(f"unknown optimizer {kind!r}; one of {', '.join(KINDS)}")


def optimize(evaluate, bounds, n_obj, n_con=0, *, kind="nsga2", population=40, generations=30,
             grid=20, seed=1):
    """Search the designs within ``bounds`` with the optimiser ``kind``.

    Parameters
    ----------
    evaluate : callable
        ``evaluate(X) -> (F, G)``, X (N, k), F (N, n_obj) minimised, G (N, n_con) feasible
        when <= 0; called once per generation (once in all for ``"grid"``).
    bounds : sequence of (low, high)
        Per design variable, m (or the variable's unit).
    n_obj : int
        Number of objectives (1 for ``"ga"`` and ``"cmaes"``).
    n_con : int
        Number of constraints.
    kind : str
        One of :data:`KINDS`.
    population : int
        Designs per generation (NSGA-II, GA: the population; CMA-ES: its ``popsize``).
    generations : int
        Generations, the first (random) population included.
    grid : int
        Points per variable of the ``"grid"`` optimiser.
    seed : int
        The random seed: the same seed, the same designs.

    Returns
    -------
    OptimizeResult
        Every evaluated design, in order.
    """
    if kind not in KINDS:
        raise ArgumentError(f"unknown optimizer {kind!r}; one of {', '.join(KINDS)}")
    seen = {"X": [], "F": [], "G": []}

    def recorded(X):
        X = np.array(X, dtype=float, copy=True)
        F, G = evaluate(X)
        F = np.asarray(F, dtype=float).reshape(len(X), n_obj)
        G = np.asarray(G, dtype=float).reshape(len(X), n_con)
        if not (np.isfinite(F).all() and np.isfinite(G).all()):
            raise ArgumentError("the objectives and constraints must be finite (a design "
                                "where a measure fails gets its worst documented value)")
        for k, v in (("X", X), ("F", F), ("G", G)):
            seen[k].append(v)
        return F, G

    if kind == "grid":
        recorded(grid_designs(bounds, grid))
    else:
        if int(population) < 2 or int(generations) < 1:
            raise ArgumentError(f"population must be >= 2 and generations >= 1, got "
                                f"{population} and {generations}")
        from pymoo.optimize import minimize
        problem = batch_problem(recorded, bounds, n_obj, n_con)
        minimize(problem, _algorithm(kind, n_obj, int(population), int(seed)),
                 ("n_gen", int(generations)), seed=int(seed), verbose=False,
                 save_history=False)
    k = len(np.asarray(bounds).reshape(-1, 2))
    gen = np.concatenate([np.full(len(x), i) for i, x in enumerate(seen["X"])]) \
        if seen["X"] else np.zeros(0, dtype=int)
    stack = (lambda key, w: np.vstack(seen[key]) if seen[key] else np.zeros((0, w)))
    return OptimizeResult(stack("X", k), stack("F", n_obj), stack("G", n_con), gen)
