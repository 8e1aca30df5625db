# The platforms beside the paper's robot in one run: NA step, forward dynamics, rollout, plan.
"""The 3-RRR and the 4-RRR platforms beside the paper's robot, in one run.

For each model of :data:`BENCH_MODELS` (the paper's robot first), in interleaved rounds (every
round times each call of every model once, so the ratios of a round are paired under the same
machine load):

* the NA step in a C loop (``time_calls``) and ``NAController.step(..., out=buf)`` from Python;
* the forward dynamics in a C loop and ``Model.forward_dynamics(..., out=buf)`` from Python;
  the binding's overhead per call is Python time minus C time;
* the closed-loop rollout (``accumulate`` on the model's high-speed move back and forth);
* ``plan_time_optimal`` (min-max split, 1,000 grid points) on the model's own first move (a
  platform's path carries phi: :func:`pm2dof.planning.pathfile.model_move_path`).

The ratios to the paper's robot are paired per round, then the median taken; the binding's
overhead, a difference of two noisy times, is compared as the ratio of its medians. The peers
(Pinocchio, MuJoCo) are not run here: they model RR legs meeting at a point.
"""
import time

import numpy as np

from ..control.controllers import NAController
from ..control.trajectory import line_moves, model_move
from ..core.model import load_model
from ..planning import plan_time_optimal
from ..planning.pathfile import model_move_path
from .baselines import operating_point
from .derivatives import dynamics_state
from .rollout import rollout_call
from .timing import stats, time_interleaved

__all__ = ["BENCH_MODELS", "PAPER_MODEL", "models_bench"]

#: the paper's robot (the reference of the ratios) and the platforms timed beside it
PAPER_MODEL = "shang2010"
BENCH_MODELS = (PAPER_MODEL, "rrr3_platform", "rrr4_platform")
PLAN_GRID = 1000


def _calls(model, c_calls):
    """{kind: run(k)} of one model: the NA step and the forward dynamics, from Python and in a
    C loop (``c_calls`` C calls per Python call of a batch), at the NA operating point of the
    model's high-speed move (the bench's, :func:`pm2dof.bench.run.setup`)."""
    n = model.n_legs
    na = NAController(model)
    moves = line_moves(model)
    traj = model_move(model, "high" if "high" in moves else moves[0])
    k = len(traj.t) // 2
    state0, qa, xd, xd_dot, xd_ddot = operating_point(model, na, traj, k)
    qa_prev = model.ik(traj.xd[k - 1])[:n].copy()
    xe, xed, tau, th = dynamics_state(model, traj, k)
    fd, f_fd = model.forward_dynamics, model.function("forward_dynamics")
    buf, fd_outs = np.empty(model.dof), [np.empty(s) for s in f_fd.sizes_out]
    f_na = model.function("na_step")
    na_outs = [np.empty(s) for s in f_na.sizes_out]
    step, tau_buf, params = na.step, np.empty(n), na.params

    def na_py(k):
        na.reset(qa_prev)             # once per batch, not timed per step
        for _ in range(k):
            step(qa, xd, xd_dot, xd_ddot, out=tau_buf)

    def na_c(k):
        f_na.time_calls(c_calls * k, 1, state0, qa, xd, xd_dot, xd_ddot, params, *na_outs)

    na.reset(qa_prev)
    step(qa, xd, xd_dot, xd_ddot, out=tau_buf)
    state_py = na.state_layout.pack(**na.state)      # the state the Python calls run at

    def na_c_py(k):
        f_na.time_calls(c_calls * k, 1, state_py, qa, xd, xd_dot, xd_ddot, params, *na_outs)

    def fd_py(k):
        for _ in range(k):
            fd(xe, xed, tau, th, out=buf)

    def fd_c(k):
        f_fd.time_calls(c_calls * k, 1, xe, xed, tau, th, *fd_outs)

    return na, {"na_py": na_py, "na_c": na_c, "na_c_py": na_c_py, "fd_py": fd_py, "fd_c": fd_c}


def _overhead(t, name, call):
    """The binding's overhead per call of each round, ns: the Python call's time minus its C
    loop's at the same state (the NA step's: the state the Python calls run at)."""
    c = t[name, "na_c_py" if call == "na" else "fd_c"]
    return [p - q for p, q in zip(t[name, f"{call}_py"], c, strict=True)]


def _paired(a, b):
    """The median of the per-round ratios a / b."""
    return stats([x / y for x, y in zip(a, b, strict=True)])["median"]


def models_bench(repeats, batch_s, c_inner, n_roll, say=None, names=BENCH_MODELS):
    """The measurements of the module docstring. ``repeats`` rounds, Python batches of about
    ``batch_s`` s, ``c_inner`` calls per C-loop batch, ``n_roll`` rollout samples.

    Returns a JSON-able dict: ``model_rows`` {name: {n_legs, dof, na_step_c_ns,
    na_step_python_ns, na_step_binding_overhead_ns, forward_dynamics_c_ns,
    forward_dynamics_python_ns, forward_dynamics_binding_overhead_ns, rollout_steps_per_s,
    plan_time_optimal_ms, plan_path} and, for each model but the paper's, the paired ratios
    to the paper's robot ``*_over_paper``}; the targets' values ``rrr4_na_step_c_over_paper``
    and ``platform_binding_overhead_over_paper_max`` (the worst of the platforms' two calls'
    overhead ratios); ``models_elapsed_s``."""
    say = say or (lambda msg: None)
    t_start = time.perf_counter()
    models = {name: load_model(name) for name in names}
    paper = names[0]
    c_calls = max(1, c_inner // 10)
    runs, ctrls = {}, {}
    for name, model in models.items():
        ctrls[name], calls = _calls(model, c_calls)
        runs.update({(name, k): run for k, run in calls.items()})
    say(f"models: NA step and forward dynamics, C and Python, interleaved over {', '.join(names)}")
    t = time_interleaved(runs, repeats, batch_s)
    for key in runs:
        if key[1] in ("na_c", "na_c_py", "fd_c"):
            t[key] = [x / c_calls for x in t[key]]        # one C call per Python call
    rows = {}
    for name, model in models.items():
        r = rows[name] = {"n_legs": model.n_legs, "dof": model.dof}
        for call, label in (("na", "na_step"), ("fd", "forward_dynamics")):
            py, c = t[name, f"{call}_py"], t[name, f"{call}_c"]
            r[f"{label}_c_ns"] = stats(c)["median"]
            r[f"{label}_python_ns"] = stats(py)["median"]
            r[f"{label}_binding_overhead_ns"] = stats(_overhead(t, name, call))["median"]

    say(f"models: rollouts ({n_roll} samples), interleaved")
    rolls = {name: rollout_call(model, ctrls[name], n_roll)[0] for name, model in models.items()}
    for run in rolls.values():
        run(1)
    tr = time_interleaved(rolls, repeats, batch_s)
    for name in names:
        rows[name]["rollout_steps_per_s"] = n_roll * 1e9 / stats(tr[name])["median"]

    say(f"models: plan_time_optimal, min_max split, {PLAN_GRID} grid points, each model's first "
        f"move, interleaved")
    paths = {}
    for name, model in models.items():
        first = line_moves(model)[0]
        paths[name] = model_move_path(model, first).path
        rows[name]["plan_path"] = f"the {first} move as a line" + (
            " (x, y, phi)" if model.dof == 3 else "")
        plan_time_optimal(model, paths[name], grid=PLAN_GRID)       # warm up
    tp = {name: [] for name in names}
    for _ in range(repeats):
        for name, model in models.items():
            t0 = time.perf_counter()
            plan_time_optimal(model, paths[name], grid=PLAN_GRID)
            tp[name].append((time.perf_counter() - t0) * 1e3)
    for name in names:
        rows[name]["plan_time_optimal_ms"] = stats(tp[name])["median"]

    # the ratios to the paper's robot, paired per round
    for name in names[1:]:
        r = rows[name]
        for call, label in (("na", "na_step"), ("fd", "forward_dynamics")):
            py, c = t[name, f"{call}_py"], t[name, f"{call}_c"]
            py0, c0 = t[paper, f"{call}_py"], t[paper, f"{call}_c"]
            r[f"{label}_c_over_paper"] = _paired(c, c0)
            r[f"{label}_python_over_paper"] = _paired(py, py0)
            # a ratio of differences is too noisy per round: the ratio of their medians
            r[f"{label}_binding_overhead_over_paper"] = (
                r[f"{label}_binding_overhead_ns"] / rows[paper][f"{label}_binding_overhead_ns"])
        r["rollout_time_over_paper"] = _paired(tr[name], tr[paper])
        r["plan_time_optimal_over_paper"] = _paired(tp[name], tp[paper])
    res = {"model_rows": rows, "models_paper": paper}
    res["rrr4_na_step_c_over_paper"] = (rows["rrr4_platform"]["na_step_c_over_paper"]
                                        if "rrr4_platform" in rows else None)
    over = [rows[nm][f"{lb}_binding_overhead_over_paper"] for nm in names[1:]
            for lb in ("na_step", "forward_dynamics")]
    res["platform_binding_overhead_over_paper_max"] = max(over) if over else None
    res["models_elapsed_s"] = time.perf_counter() - t_start
    return res
