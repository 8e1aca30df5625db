# Step-time benchmark: the generated NA/APD steps in C, from Python, against casadi.Function,
# NumPy and SymPy-lambdify implementations of the same step; closed-loop rollout speed; op counts.
"""Benchmark of the generated controller step and closed-loop rollout.

:func:`run_bench` measures everything in one run and returns a JSON-able dict, assembled
from one function per measurement (``bench_c_steps``, ``bench_splits``, ...), each returning
its numbers; :func:`format_bench` renders it as a table with the project's targets. Used by
``pm2dof bench [--json] [--quick]``.
"""
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..control.controllers import APDController, NAController
from ..control.simulate import simulate
from ..control.trajectory import line_moves, model_move
from ..core.contract import SPLITS
from ..core.layout import Layout
from ..core.model import load_model
from ..core.status import Status
from ..reference import control as rc
from .baselines import (
    c_step,
    lambdify_problem,
    lambdify_step,
    operating_point,
    random_cases,
    reference_geometry,
    reference_problem,
)
from .derivatives import derivative_bench, dynamics_state
from .machine import machine
from .opcount import OPS_FUNCTIONS, count_ops
from .overheads import OVERHEAD_METHODS, UNTARGETED, overhead_bench
from .peers import peer_bench
from .rollout import rollout_call
from .timing import rel_diff, stats, time_batches

__all__ = ["run_bench", "TARGETS", "REQUIRED_KEYS"]

#: Keys every result holds (a number, or None where a note in ``notes`` says why).
REQUIRED_KEYS = ("na_step_c_ns", "apd_step_c_ns", "na_step_python_us",
                 "na_step_casadi_function_us", "na_step_numpy_us", "na_step_lambdify_us",
                 "rollout_steps_per_s")

#: (key, comparison, target, unit, what). Checked against the median; reported, never enforced.
TARGETS = (
    ("na_step_c_ns", "<=", 250.0, "ns", "NA step in C (C loop)"),
    ("na_step_python_us", "<=", 1.0, "us", "NA step from Python (NAController.step, out=)"),
    ("rollout_steps_per_s", ">=", 500000.0, "steps/s", "closed-loop rollout in C (accumulate)"),
    ("speedup_c_vs_numpy", ">=", 300.0, "x", "C step vs NumPy reference step"),
    ("speedup_binding_vs_casadi_function", ">=", 50.0, "x",
     "NAController.step vs casadi.Function call"),
    ("agreement_c_vs_numpy", "<=", 1e-10, "rel", "C step vs NumPy reference (max rel. diff.)"),
    ("na_min_max_over_min_norm", "<=", 1.3, "x", "NA step, min_max split / min_norm split"),
    ("plan_time_optimal_ms", "<=", 5.0, "ms", "plan_time_optimal, 1000 grid points"),
    ("speedup_vs_toppra", ">=", 10.0, "x", "plan_time_optimal vs toppra, friction-free"),
    # refined plans (bench/planning.py, bench_refinement), worst case over the paths
    ("plan_refined_over_unrefined_max", "<=", 1.3, "x",
     "refined plan / unrefined plan of its grid size, worst path"),
    ("speedup_vs_toppra_min", ">=", 12.0, "x", "plan_time_optimal vs toppra, worst path"),
    # derivatives and the model-based steps (bench/derivatives.py)
    ("fd_jacobians_over_fd_c", "<=", 3.0, "x", "forward-dynamics Jacobians / forward dynamics, C"),
    ("fd_jacobians_python_us", "<=", 1.5, "us",
     "forward-dynamics Jacobians from Python (Model.forward_dynamics_jacobians, out=)"),
    ("ctc_step_c_ns", "<=", 300.0, "ns", "CTC step in C (C loop)"),
    ("lqr_step_c_ns", "<=", 300.0, "ns", "LQR step in C (C loop)"),
    # the Python calls (bench/peers.py), ratios of interleaved rounds
    ("speedup_fd_vs_pinocchio", ">=", 4.0, "x",
     "Model.forward_dynamics vs Pinocchio constraintDynamics, from Python"),
    ("speedup_fd_vs_mujoco", ">=", 4.0, "x", "Model.forward_dynamics vs MuJoCo mj_forward, "
     "from Python"),
    ("fd_binding_overhead_over_c", "<=", 4.0, "x",
     "forward dynamics: binding overhead (Python - C) / C"),
    # every per-sample Model method (bench/overheads.py), ratios of interleaved rounds
    *((f"overhead_over_c_{name}", "<=", 1.5, "x",
       f"Model.{name}: binding overhead (Python - C) / C") for name, _ in OVERHEAD_METHODS
      if name not in UNTARGETED),
    # the 3-RRR and 4-RRR platforms beside the paper's robot (bench/models.py),
    # ratios of interleaved rounds; measured when the platform rows run (``models``)
    ("rrr4_na_step_c_over_paper", "<=", 3.0, "x", "NA step in C, 4-RRR / paper's robot"),
    ("platform_binding_overhead_over_paper_max", "<=", 1.25, "x",
     "binding overhead (Python - C), platform / paper's robot, worst call"),
    # the geometry as a run-time input (bench/design.py): a design model / the fixed one
    ("design_fd_ratio", "<=", 1.5, "x",
     "Model.forward_dynamics, [design] model / fixed-geometry model, from Python"),
    ("design_na_step_ratio", "<=", 1.5, "x",
     "NAController.step, [design] model / fixed-geometry model, from Python"),
    # design studies (bench/synthesis.py): at_design and a design's kinematic objectives on a
    # 50 x 50 region / the generated-C calls they make (worst model); a design run on one Dask
    # worker / the worker's time evaluating its designs
    ("synthesis_kinematic_over_c_max", "<=", 1.5, "x",
     "kinematic objectives, 50x50 region / their generated-C calls, worst model"),
    ("synthesis_dask_over_worker", "<=", 1.1, "x",
     "design run through Dask on 1 worker / its worker's time evaluating the designs"),
    # the build (bench/build_time.py): pm2dof derive of the 4-RRR platform / gcc -O3 on the
    # paper's C compiled whole, back to back in the same run
    ("derive_rrr4_over_gcc_paper", "<=", 1.5, "x",
     "pm2dof derive rrr4_platform / gcc -O3 on the paper robot's C (whole), wall"),
)
#: torque splits timed side by side (docs/benchmark.md, "The torque splits"); preload, N*m
#: for a revolute actuator, N for a linear one
BENCH_SPLITS = tuple(SPLITS)
BENCH_PRELOAD = 1.0


def run_bench(model=None, quick=False, progress=None, models=None, build=None):
    """Benchmark the generated C where users wait, all in one run: the controller steps and
    rollouts, the derivatives, the planner, a design model and design studies, and every
    per-sample Model method's binding, beside their peers.

    A development tool: besides the runtime package it imports CasADi (to call the compiled
    library through ``casadi.external``) and, for the SymPy baseline, the build-time
    ``derive`` package and SymPy. Where one of those is not importable the value is None
    and ``notes`` says why.

    Measured (median over repeated batches, also the min; Python timings use
    ``time.perf_counter_ns`` batches with gc off, C timings a loop inside C):

    - ``na_step_c_ns``, ``apd_step_c_ns``: the generated step in a C loop (time_calls), ns.
    - ``na_step_python_us``: ``NAController.step(..., out=buf)`` from Python (no allocation),
      us; ``na_step_python_alloc_us`` without ``out=``; ``na_step_binding_us`` the bare
      ``_cbind`` call with preallocated outputs.
    - ``na_step_casadi_function_us``: the same compiled function as a ``casadi.Function``
      (``casadi.external``) called with NumPy arguments, us.
    - ``na_step_numpy_us``: ``pm2dof.reference.control.na_step`` (plain NumPy), us.
    - ``na_step_lambdify_us``: the step composed in NumPy from the SymPy expressions
      (fk, passive unit vectors, S, Y) through ``sympy.lambdify(..., cse=True)``, us.
    - ``rollout_steps_per_s``: closed-loop rollout (encoder + NA step + the plant's RK4 substeps
      per 2 ms sample) in control steps per second, the ``accumulate`` call alone over
      ~20000 samples (the high-speed move back and forth); ``rollout_end_to_end_steps_per_s``
      through ``pm2dof.simulate``.
    - ``op_counts``: operations of each generated function, parsed from the generated C.
    - ratios ``speedup_c_vs_numpy`` (NumPy step / C step), ``speedup_c_vs_lambdify``,
      ``speedup_binding_vs_casadi_function`` (casadi.Function call / NAController.step);
      agreement ``agreement_c_vs_numpy`` (max relative difference ||a-b||/||b|| of tau_a and
      state_next over random states; ~1e-12) and ``agreement_c_vs_lambdify``.
    - ``design_rows`` and the ``design_*`` ratios: the paper's robot with a ``[design]`` table
      beside the fixed-geometry model (:func:`pm2dof.bench.design.design_bench`).
    - ``synthesis_rows`` and the ``synthesis_*`` keys: design studies' designs per second per
      objective class beside structdimsynth's published cost, a design's kinematic objectives
      against their generated-C calls, Dask's overhead on one worker
      (:func:`pm2dof.bench.synthesis.synthesis_bench`; it starts a one-worker LocalCluster).
    - ``targets``: pass/fail of each target (never enforced), ``machine``: CPU, cores,
      compiler and flags, Python.

    Parameters
    ----------
    model : Model, optional
        Default: the paper's robot (``load_model()``). Any kind: task vectors have the
        model's m = ``model.dof`` entries, theta is read by parameter name. The baselines of
        the paper's family only are None on other models, with a note naming the model and
        why: the NumPy reference (RR legs at a point, no gravity, eq. 2's sign friction:
        :func:`.baselines.reference_problem`), the SymPy-lambdify step (RR legs at a point:
        :func:`.baselines.lambdify_problem`), Pinocchio and MuJoCo (RR legs at a point in a
        horizontal plane: :func:`.baselines.peer_problem`).
    quick : bool
        3 short batches per measurement, a 2000-sample rollout and a smoothed plan of 15 grid
        points (for tests; the numbers are noise). The full run: 7 batches of ~50 ms, a
        20000-sample rollout, a smoothed plan of 200 points.
    progress : callable(str), optional
        Called with a short message before each stage.
    models : bool, optional
        Also time the 3-RRR and 4-RRR platforms beside the paper's robot
        (:func:`pm2dof.bench.models.models_bench`: ``model_rows`` and the two platform
        targets; about 9 s in a full run, under 1 s in a quick one). Default: in the full
        run, not in the quick one (then those targets are n/a).
    build : bool, optional
        Also time ``pm2dof derive`` of the 4-RRR platform beside gcc ``-O3`` on the paper
        robot's C compiled whole (:func:`pm2dof.bench.build_time.build_bench`: the
        ``derive_rrr4_*``, ``gcc_paper_*`` keys and their target; about a minute and a half on
        two idle processors, SymPy, CasADi and a C compiler needed). Default: in the full run,
        not in the quick one (then the target is n/a).

    Returns
    -------
    dict
        JSON-serialisable; see :data:`REQUIRED_KEYS` and :data:`TARGETS`.
    """
    t_start = time.perf_counter()
    say = progress or (lambda msg: None)
    b = setup(load_model() if model is None else model, quick, say)
    model, na = b.model, b.na
    res = {"model": model.name, "n_legs": model.n_legs, "quick": bool(quick),
           "repeats": b.repeats, "notes": {}}
    notes = res["notes"]
    res["operating_point"] = {"trajectory": b.speed, "sample": b.k_op}
    say(f"C loop: na_step and apd_step, {b.repeats} x {b.c_inner} calls")
    res.update(bench_c_steps(b))
    say(f"C loop: NA step per torque split {BENCH_SPLITS}, interleaved batches")
    res.update(bench_splits(b))
    say("Python: NAController.step (out= and allocating), bare binding call")
    res.update(bench_python_steps(b))
    say("casadi.Function: casadi.external on the compiled library")
    res.update(bench_casadi_function(b, notes))
    say("NumPy reference step (pm2dof.reference.control.na_step) and agreement")
    res.update(bench_numpy_reference(b, notes))
    say("SymPy: derive the expressions, lambdify fk, unit vectors, S, Y (numpy, cse)")
    res.update(bench_lambdify(b, notes))
    res.update(bench_rollout(b, say))

    # --- derivatives and the CTC, LQR steps (bench/derivatives.py) -----------------------
    say("derivatives: Jacobians, sampled step, inverse dynamics (C, Python, Pinocchio, finite "
        "differences); CTC and LQR steps")
    res.update(derivative_bench(model, b.traj, b.op, b.repeats, b.c_inner, b.batch_s, notes))

    # --- the binding's overhead and the peers (bench/peers.py) -----------------------------
    say("binding overhead (Python - C) of forward_dynamics and NAController.step; forward "
        "dynamics beside Pinocchio and MuJoCo, interleaved rounds")
    fd_state = dynamics_state(model, b.traj, len(b.traj.t) // 2)
    res.update(peer_bench(model, na, b.op, b.qa_prev, fd_state, b.repeats, b.batch_s,
                          b.c_inner, notes))

    # --- every per-sample Model method's overhead (bench/overheads.py) ---------------------
    say(f"binding overhead (Python - C) / C of {len(OVERHEAD_METHODS)} per-sample Model "
        f"methods, interleaved rounds")
    res.update(overhead_bench(model, b.traj, b.repeats, b.batch_s, b.c_inner))

    # --- motion planning: plan_time_optimal beside toppra ----------------------------------
    from .planning import bench_planning
    planning = bench_planning(model, quick, say)
    notes.update(planning.pop("notes"))
    res.update(planning)

    # --- the platforms beside the paper's robot: bench/models.py ---------------------------
    if (not quick) if models is None else models:
        from .models import models_bench
        res.update(models_bench(b.repeats, b.batch_s, b.c_inner, b.n_roll, say))
        notes["model_rows"] = ("the peers (Pinocchio, MuJoCo) are timed on the paper's robot "
                               "only: they model RR legs meeting at a point, not a platform")
    else:
        res["rrr4_na_step_c_over_paper"] = res["platform_binding_overhead_over_paper_max"] = None
        notes["model_rows"] = "the platforms were not timed (pm2dof bench --models adds them)"

    from .design import design_bench
    res.update(design_bench(b.repeats, b.batch_s, b.c_inner, say))

    # --- the build: derive the 4-RRR platform beside gcc on the paper's C (bench/build_time.py)
    if (not quick) if build is None else build:
        from .build_time import build_bench
        try:
            res.update(build_bench(1, say))
        except (ImportError, OSError, RuntimeError) as exc:
            res["derive_rrr4_over_gcc_paper"] = None
            notes["build"] = f"the derive and the compile could not run: {exc}"
    else:
        res["derive_rrr4_over_gcc_paper"] = None
        notes["build"] = "the build was not timed (pm2dof bench --build adds it)"

    # --- design studies: designs per second, kinematic objectives vs C, Dask's overhead ----
    from .synthesis import synthesis_bench
    res.update(synthesis_bench(b.repeats, quick, say))

    say("op counts from the generated C source")
    res.update(bench_op_counts(model, notes))
    res.update(ratios(res, na.sample_period))
    res["targets"] = targets = check_targets(res)
    res["all_targets_pass"] = all(t["pass"] for t in targets.values())
    res["machine"] = machine(model.library)
    res["elapsed_s"] = time.perf_counter() - t_start
    return res


@dataclass(frozen=True, eq=False)
class BenchSetup:
    """What the measurements share: the model, the sizes of the run, the NA and APD
    controllers, the move and the NA operating point on it (sample ``k_op`` of ``traj``,
    ``speed`` its name; ``qa_prev`` the active angles one sample before, rad), ``lays`` the
    manifest's layouts and ``cases`` the step inputs the references are compared on."""

    model: object
    quick: bool
    repeats: int          # batches per measurement
    batch_s: float        # s per Python batch
    c_inner: int          # calls per C-loop batch
    n_roll: int           # rollout samples
    lays: dict
    na: NAController
    apd: APDController
    speed: str
    traj: object
    k_op: int
    op: tuple             # (state, qa, xd, xd_dot, xd_ddot) of the NA step
    qa_prev: np.ndarray
    cases: list


def setup(model, quick, say):
    """The :class:`BenchSetup` of one run (``quick``: the short one of :func:`run_bench`)."""
    repeats = 3 if quick else 7
    n = model.n_legs
    na, apd = NAController(model), APDController(model)
    moves = line_moves(model)
    speed = "high" if "high" in moves else moves[0]
    traj = model_move(model, speed)
    k_op = len(traj.t) // 2
    say(f"operating point: the NA controller along the {speed}-speed move to sample {k_op}")
    op = operating_point(model, na, traj, k_op)
    rng = np.random.default_rng(20100101)
    cases = [op] + random_cases(model, na, rng, 3 if quick else 10, traj.xd[k_op])
    return BenchSetup(model, bool(quick), repeats, 0.004 if quick else 0.05,
                      2000 if quick else 20000, 2000 if quick else 20000,
                      {k: Layout(k, v) for k, v in model.manifest["layouts"].items()}, na, apd,
                      speed, traj, k_op, op, model.ik(traj.xd[k_op - 1])[:n].copy(), cases)


def _c_step_outs(model, f, op):
    """Preallocated outputs (tau, state_next, status, diagnostics) of a controller step."""
    n = model.n_legs
    return np.empty(n), np.empty(len(op[0])), np.empty(1), np.empty(f.sizes_out[3])


def bench_c_steps(b):
    """``na_step_c_ns``, ``apd_step_c_ns`` (and ``_min``): the generated steps in a C loop, ns."""
    res = {}
    for law, ctrl in (("na", b.na), ("apd", b.apd)):
        f = b.model.function(f"{law}_step")
        outs = _c_step_outs(b.model, f, b.op)
        f.time_calls(max(1, b.c_inner // 10), 1, *b.op, ctrl.params, *outs)  # warm up
        st = stats(f.time_calls(b.c_inner, b.repeats, *b.op, ctrl.params, *outs))
        res[f"{law}_step_c_ns"], res[f"{law}_step_c_ns_min"] = st["median"], st["min"]
    return res


def bench_splits(b):
    """The NA step of each torque split in a C loop, batches interleaved: ``na_<split>_step_c_ns``
    (and ``_min``), ns, and the paired ratios ``na_min_max_over_min_norm``,
    ``na_preload_over_min_norm``."""
    model, n = b.model, b.model.n_legs
    ctrls = {s: NAController(model, split=s, preload=np.full(n, BENCH_PRELOAD))
             for s in BENCH_SPLITS}
    per = {s: [] for s in BENCH_SPLITS}
    for _ in range(b.repeats):
        for s, c in ctrls.items():
            f = model.function(f"{c.function_name}_step")
            outs = _c_step_outs(model, f, b.op)
            per[s] += f.time_calls(b.c_inner, 1, *b.op, c.params, *outs)
    res = {}
    for s, times in per.items():
        st = stats(times)
        res[f"na_{s}_step_c_ns"], res[f"na_{s}_step_c_ns_min"] = st["median"], st["min"]
    # ratios of batches paired in the same round
    res["na_min_max_over_min_norm"] = stats([t / t0 for t, t0 in
                                             zip(per["min_max"], per["min_norm"])])["median"]
    res["na_preload_over_min_norm"] = stats([t / t0 for t, t0 in
                                             zip(per["preload"], per["min_norm"])])["median"]
    return res


def bench_python_steps(b):
    """``NAController.step`` from Python with ``out=`` (``na_step_python_us``), allocating
    (``na_step_python_alloc_us``) and the bare binding call (``na_step_binding_us``), us."""
    na, n = b.na, b.model.n_legs
    state0, qa, xd, xd_dot, xd_ddot = b.op
    buf = np.empty(n)
    step = na.step

    def run_out(k):
        for _ in range(k):
            step(qa, xd, xd_dot, xd_ddot, out=buf)

    def run_alloc(k):
        for _ in range(k):
            step(qa, xd, xd_dot, xd_ddot)

    fna = b.model.function("na_step")
    s1, tau, stat, dg = np.empty_like(state0), np.empty(n), np.empty(1), np.empty(fna.sizes_out[3])
    params = na.params

    def run_binding(k):
        for _ in range(k):
            fna(state0, qa, xd, xd_dot, xd_ddot, params, tau, s1, stat, dg)

    res = {}
    for key, run in (("na_step_python_us", run_out), ("na_step_python_alloc_us", run_alloc),
                     ("na_step_binding_us", run_binding)):
        na.reset(b.qa_prev)
        ns, _ = time_batches(run, b.repeats, b.batch_s)
        st = stats(ns)
        res[key], res[key + "_min"] = st["median"] / 1e3, st["min"] / 1e3
    return res


def bench_casadi_function(b, notes):
    """The same compiled NA step as a ``casadi.Function`` (``casadi.external``) called with
    NumPy arguments: ``na_step_casadi_function_us`` (None, with a note, without CasADi)."""
    res = {}
    try:
        import casadi
    except ImportError as exc:
        casadi = None
        notes["na_step_casadi_function_us"] = f"casadi is not importable ({exc})"
    res["na_step_casadi_function_us"] = res["na_step_casadi_function_us_min"] = None
    if casadi is None:
        return res
    model, params = b.model, b.na.params
    state0, qa, xd, xd_dot, xd_ddot = b.op
    cf = casadi.external(f"{model.name}_na_step", model.library)
    cargs = (state0, qa, xd, xd_dot, xd_ddot, params)
    tau_cf = np.asarray(cf(*cargs)[0]).ravel()
    res["agreement_casadi_function_vs_c"] = rel_diff(
        tau_cf, c_step(model.function("na_step"), params, b.op, model.n_legs)[0])

    def run_cf(k):
        for _ in range(k):
            cf(state0, qa, xd, xd_dot, xd_ddot, params)

    st = stats(time_batches(run_cf, b.repeats, b.batch_s * 2)[0])
    res["na_step_casadi_function_us"] = st["median"] / 1e3
    res["na_step_casadi_function_us_min"] = st["min"] / 1e3
    res["casadi_version"] = casadi.__version__
    return res


def bench_numpy_reference(b, notes):
    """``pm2dof.reference.control.na_step`` (plain NumPy): ``na_step_numpy_us`` and its
    agreement with the C step over ``b.cases`` (``agreement_c_vs_numpy``); None, with a note
    saying why, for a model that formulation does not cover (:func:`.baselines.reference_problem`:
    a platform, prismatic legs, gravity, another friction law)."""
    model, params, n = b.model, b.na.params, b.model.n_legs
    why = reference_problem(model)
    if why is not None:
        notes["na_step_numpy_us"] = notes["agreement_c_vs_numpy"] = why
        return {"na_step_numpy_us": None, "na_step_numpy_us_min": None,
                "agreement_c_vs_numpy": None, "agreement_cases": None}
    g = reference_geometry(model)
    ref_step = rc.na_step
    state0, qa, xd, xd_dot, xd_ddot = b.op

    def run_np(k):
        for _ in range(k):
            ref_step(g, state0, qa, xd, xd_dot, xd_ddot, params)

    res = {}
    st = stats(time_batches(run_np, b.repeats, b.batch_s * 2)[0])
    res["na_step_numpy_us"], res["na_step_numpy_us_min"] = st["median"] / 1e3, st["min"] / 1e3
    notes["na_step_numpy_us"] = (
        "the NumPy reference is written for clarity: it builds Y column by column "
        f"({len(model.param_names)} evaluations of eq. 13's right side), so it is far slower "
        "than straight NumPy; the lambdify row is the plain-NumPy baseline")
    fna = model.function("na_step")
    worst = 0.0
    for case in b.cases:
        tau_c, s_c, stat_c = c_step(fna, params, case, n)
        tau_r, s_r, stat_r, _ = ref_step(g, *case, params)
        worst = max(worst, rel_diff(tau_c, tau_r), rel_diff(s_c, s_r), float(stat_c != stat_r))
    res["agreement_c_vs_numpy"] = worst
    res["agreement_cases"] = len(b.cases)
    return res


def bench_lambdify(b, notes):
    """The step composed in NumPy from the SymPy expressions through ``sympy.lambdify``:
    ``na_step_lambdify_us`` and ``agreement_c_vs_lambdify`` (None, with a note, without
    SymPy or the derive package, or for a mechanism :func:`.baselines.lambdify_problem` names
    a reason for)."""
    res = {"na_step_lambdify_us": None, "na_step_lambdify_us_min": None,
           "agreement_c_vs_lambdify": None}
    why = lambdify_problem(b.model)
    if why is not None:
        notes["na_step_lambdify_us"] = notes["agreement_c_vs_lambdify"] = why
        return res
    try:
        lstep, build_s = lambdify_step(b.model, b.lays)
    except ImportError as exc:
        notes["na_step_lambdify_us"] = f"sympy or the derive package is not importable ({exc})"
        return res
    model, params, n = b.model, b.na.params, b.model.n_legs
    fna = model.function("na_step")
    res["lambdify_build_s"] = build_s
    worst = 0.0
    for case in b.cases:
        tau_c, s_c, stat_c = c_step(fna, params, case, n)
        tau_l, s_l, stat_l = lstep(*case, params)
        worst = max(worst, rel_diff(tau_c, tau_l), rel_diff(s_c, s_l), float(stat_c != stat_l))
    res["agreement_c_vs_lambdify"] = worst
    state0, qa, xd, xd_dot, xd_ddot = b.op

    def run_lam(k):
        for _ in range(k):
            lstep(state0, qa, xd, xd_dot, xd_ddot, params)

    st = stats(time_batches(run_lam, b.repeats, b.batch_s * 2)[0])
    res["na_step_lambdify_us"] = st["median"] / 1e3
    res["na_step_lambdify_us_min"] = st["min"] / 1e3
    return res


def bench_rollout(b, say):
    """The closed-loop rollout (encoder, NA step, the plant's RK4 substeps per sample) over
    ``b.n_roll`` samples: the ``accumulate`` call alone (``rollout_steps_per_s``) and through
    ``pm2dof.simulate`` (``rollout_end_to_end_steps_per_s``), control steps per second."""
    model, na, lays, n_roll = b.model, b.na, b.lays, b.n_roll
    run_acc, y, long, speed_l = rollout_call(model, na, n_roll)
    say(f"rollout: {n_roll} samples ({speed_l}-speed move back and forth), accumulate and "
        f"simulate()")
    res = {"rollout_samples": n_roll,
           "rk4_substeps": int(model.manifest.get("rk4_substeps", 0)) or None}
    run_acc(1)
    status = y[:, lays["cl_output"].slices["status"]].ravel()
    res["rollout_singular_samples"] = int(np.sum(status == Status.SINGULAR))
    err = long.xd - y[:, lays["cl_output"].slices["xe"]]        # (n_roll, m), task_names order
    ix, iy = (model.task_names.index(k) for k in ("x", "y"))
    res["rollout_max_error_m"] = float(np.max(np.hypot(err[:, ix], err[:, iy])))
    if "phi" in model.task_names:                                 # a platform's orientation
        res["rollout_max_error_phi_rad"] = float(np.max(np.abs(
            err[:, model.task_names.index("phi")])))
    acc = stats(time_batches(run_acc, b.repeats, 0.0 if b.quick else 0.05)[0])
    res["rollout_steps_per_s"] = n_roll * 1e9 / acc["median"]
    res["rollout_steps_per_s_best"] = n_roll * 1e9 / acc["min"]
    res["rollout_ns_per_step"] = acc["median"] / n_roll

    def run_sim(k):
        for _ in range(k):
            simulate(model, na, long)

    sim = stats(time_batches(run_sim, b.repeats, 0.0 if b.quick else 0.05)[0])
    res["rollout_end_to_end_steps_per_s"] = n_roll * 1e9 / sim["median"]
    res["rollout_end_to_end_steps_per_s_best"] = n_roll * 1e9 / sim["min"]
    res["rollout_python_overhead_us_per_step"] = (sim["median"] - acc["median"]) / n_roll / 1e3
    return res


def bench_op_counts(model, notes):
    """``op_counts``: operations of each generated function, parsed from the generated C
    (None, with a note, where it cannot be read), and ``generated_c`` its path."""
    c_path = Path(model.library).with_name(f"{model.name}.c")
    try:
        ops = count_ops(c_path.read_text(), [f"{model.name}_{s}" for s in OPS_FUNCTIONS])
        res = {"op_counts": {k[len(model.name) + 1:]: v for k, v in ops.items()}}
    except (OSError, KeyError, RecursionError) as exc:
        res = {"op_counts": None}
        notes["op_counts"] = f"cannot read {c_path}: {exc}"
    res["generated_c"] = str(c_path)
    return res


def ratios(res, sample_period):
    """The speed-ups and overheads derived from the measurements ``res`` (None where one is
    missing); ``sample_period`` s, the NA controller's."""
    def ratio(a, b):
        return a / b if (a is not None and b) else None

    def ns(us):
        return None if us is None else us * 1e3

    return {
        "speedup_c_vs_numpy": ratio(ns(res["na_step_numpy_us"]), res["na_step_c_ns"]),
        "speedup_c_vs_lambdify": ratio(ns(res["na_step_lambdify_us"]), res["na_step_c_ns"]),
        "speedup_binding_vs_casadi_function": ratio(res["na_step_casadi_function_us"],
                                                    res["na_step_python_us"]),
        "speedup_raw_binding_vs_casadi_function": ratio(res["na_step_casadi_function_us"],
                                                        res["na_step_binding_us"]),
        "python_overhead_us": res["na_step_python_us"] - res["na_step_c_ns"] / 1e3,
        "na_step_budget_fraction": res["na_step_c_ns"] * 1e-9 / sample_period,
    }


def check_targets(res):
    """Each of :data:`TARGETS` against its value in ``res``: pass, fail, or None (no value)."""
    targets = {}
    for key, cmp, target, unit, what in TARGETS:
        v = res.get(key)
        ok = None if v is None else (v <= target if cmp == "<=" else v >= target)
        targets[key] = {"value": v, "target": target, "op": cmp, "unit": unit, "what": what,
                        "pass": ok}
    return targets
