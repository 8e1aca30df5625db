# The planner's solve on one grid in one C call (pm2dof/planning/_passes.c), beside grid.passes.
"""``solve_c``: :func:`pm2dof.planning.stages.link` then :func:`pm2dof.planning.grid.passes` in one
call into C (``_passes.solve``): the generated path_mvc, path_backward and path_forward called
row by row with the rows built in C, the same inputs as the NumPy builds, so the same results
bit for bit (tests/planning/test_planning_passes_c.py); given the previous solve, it takes from
it what the added points cannot change. Where the passes would raise, it returns None and the
caller runs the NumPy passes for their message."""
import numpy as np

from . import _passes
from .stages import V_TOP, _fill

__all__ = ["Linking", "solve_c"]


def _offsets(model):
    st, pair = model.layout("path_stage"), model.layout("path_pair")
    bi, fi = model.layout("path_backward_input"), model.layout("path_forward_input")
    fo = model.layout("path_forward_output")
    s, p, b, f, y = st.slices, pair.slices, bi.slices, fi.slices, fo.slices
    return np.array([st.size, s["rho"].start, s["rho"].stop - s["rho"].start, s["delta"].start,
                     s["x_cap"].start, s["h"].start, s["h"].stop - s["h"].start,
                     pair.size, p["stage"].start, p["next"].start, p["next_cap"].start,
                     bi.size, b["pair"].start, fi.size, f["pair"].start, f["x_next_max"].start,
                     fo.size, y["x"].start, y["sdd"].start, y["L"].start, y["U"].start,
                     y["Z"].start, y["arrival_ok"].start], dtype=np.int64)


class Linking:
    """What the C solve needs of ``problem`` (:class:`.problem.PlanProblem`) beyond the grid:
    the layouts' offsets, the functions, and the preceding piece's rows at the path's interior
    breakpoints (``left``: :func:`pm2dof.planning.stages.junction_left`, packed as
    path_stage rows)."""

    def __init__(self, problem, left):
        model = problem.model
        self.problem = problem
        self.offsets = _offsets(model)
        self.y_size = model.layout("path_forward_output").size    # path_forward's y
        self.fns = tuple(model.function(k) for k in ("path_mvc", "path_backward",
                                                     "path_forward"))
        self.junctions = np.ascontiguousarray(problem.path.breakpoints[1:-1], dtype=float)
        self.left = np.zeros((len(self.junctions), model.layout("path_stage").size))
        if left is not None and len(self.junctions):
            _fill(model, self.left, left, problem.split)


def solve_c(linking, s, base, v1, stops, prev=None):
    """The passes on the grid ``s`` (K,) with its points' rows ``base`` (K, S) and v1 (K, n),
    at rest at the grid indices ``stops``: (stage (K, S), x (K,), sdd (K,), x_mvc (K,),
    relaxed, memo), as ``link`` then ``passes`` give them; None where those raise. ``prev``:
    the ``memo`` of a solve on a grid of which ``s`` is a refinement (its points among ``s``),
    whose steps the C takes where they cannot have changed (the result is the same, bit for
    bit), or None."""
    K = len(s)
    x_cap = np.full(K, V_TOP ** 2)
    x_cap[list(stops)] = 0.0
    stage = np.empty((K, linking.left.shape[1]))
    x, sdd, x_mvc, ok = np.empty(K), np.empty(K), np.empty(K), np.empty(K - 1)
    cap, hi, x_raw = np.empty(K), np.empty(K), np.empty(K)
    y = np.empty((K - 1, linking.y_size))
    status = _passes.solve(*linking.fns, linking.problem.params, s, base, v1, x_cap,
                           linking.left, linking.junctions, linking.offsets, stage, x, sdd,
                           x_mvc, ok, cap, hi, y, x_raw, prev)
    if status:
        return None
    memo = (s, stage, x_mvc, cap, hi, y, x_raw)
    return stage, x, sdd, x_mvc, np.flatnonzero(ok == 0), memo
