# Step-time benchmark: the generated NA/APD steps in C, from Python, against casadi.Function,
# NumPy and SymPy-lambdify implementations of the same step; closed-loop rollout speed; op counts.
"""Benchmark of the generated controller step and closed-loop rollout.

:func:`run_bench` measures everything in one run and returns a JSON-able dict;
:func:`format_bench` renders it as a table with the project's targets. Used by
``pm2dof bench [--json] [--quick]``.
"""
import time
from pathlib import Path

import numpy as np

from ..control.controllers import APDController, NAController
from ..control.simulate import plant_vector, simulate
from ..control.trajectory import line_moves, model_move
from ..core.layout import Layout
from ..core.model import load_model
from ..core.status import Status
from ..reference import control as rc
from .baselines import (
    c_step,
    lambdify_step,
    long_trajectory,
    operating_point,
    random_cases,
    reference_geometry,
)
from .derivatives import derivative_bench, dynamics_state
from .machine import machine
from .opcount import OPS_FUNCTIONS, count_ops
from .peers import peer_bench
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
    # issue 25: refined plans (bench/planning.py, bench_refinement), worst case over the paths
    ("plan_refined_over_unrefined_max", "<=", 1.3, "x",
     "refined plan / unrefined plan of its grid size, worst path"),
    ("speedup_vs_toppra_min", ">=", 12.0, "x", "plan_time_optimal vs toppra, worst path"),
    # issue 21: derivatives and the model-based steps (bench/derivatives.py)
    ("fd_jacobians_over_fd_c", "<=", 3.0, "x", "forward-dynamics Jacobians / forward dynamics, C"),
    ("fd_jacobians_python_us", "<=", 1.5, "us",
     "forward-dynamics Jacobians from Python (Model.forward_dynamics_jacobians, out=)"),
    ("ctc_step_c_ns", "<=", 300.0, "ns", "CTC step in C (C loop)"),
    ("lqr_step_c_ns", "<=", 300.0, "ns", "LQR step in C (C loop)"),
    # issue 25: the Python calls (bench/peers.py), ratios of interleaved rounds
    ("speedup_fd_vs_pinocchio", ">=", 4.0, "x",
     "Model.forward_dynamics vs Pinocchio constraintDynamics, from Python"),
    ("speedup_fd_vs_mujoco", ">=", 4.0, "x", "Model.forward_dynamics vs MuJoCo mj_forward, "
     "from Python"),
    ("fd_binding_overhead_over_c", "<=", 4.0, "x",
     "forward dynamics: binding overhead (Python - C) / C"),
)
#: torque splits timed side by side (docs/benchmark.md, "The torque splits"); preload, N*m
BENCH_SPLITS = ("min_norm", "min_max", "preload")
BENCH_PRELOAD = 1.0


def run_bench(model=None, quick=False, progress=None):
    """Benchmark the generated NA step and closed-loop rollout, all in one run.

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
    - ``targets``: pass/fail of each target (never enforced), ``machine``: CPU, cores,
      compiler and flags, Python.

    Parameters
    ----------
    model : Model, optional
        Default: the paper's robot (``load_model()``).
    quick : bool
        3 short batches per measurement and a 2000-sample rollout: about 3 s in all (for
        tests; the numbers are noisier). The full run (7 batches of ~50 ms, 20000-sample
        rollout) takes about 10 s, most of it the SymPy derivation and the NumPy reference.
    progress : callable(str), optional
        Called with a short message before each stage.

    Returns
    -------
    dict
        JSON-serialisable; see :data:`REQUIRED_KEYS` and :data:`TARGETS`.
    """
    t_start = time.perf_counter()
    say = progress or (lambda msg: None)
    model = load_model() if model is None else model
    repeats = 3 if quick else 7
    batch_s = 0.004 if quick else 0.05       # Python batches
    c_inner = 2000 if quick else 20000       # C-loop batches (calls per batch)
    n_roll = 2000 if quick else 20000        # rollout samples
    n_agree = 3 if quick else 10

    res = {"model": model.name, "n_legs": model.n_legs, "quick": bool(quick),
           "repeats": repeats, "notes": {}}
    notes = res["notes"]
    lays = {k: Layout(k, v) for k, v in model.manifest["layouts"].items()}
    n = model.n_legs
    na, apd = NAController(model), APDController(model)
    moves = line_moves(model)
    speed = "high" if "high" in moves else moves[0]
    traj = model_move(model, speed)
    k_op = len(traj.t) // 2
    say(f"operating point: the NA controller along the {speed}-speed move to sample {k_op}")
    op = operating_point(model, na, traj, k_op)
    res["operating_point"] = {"trajectory": speed, "sample": k_op}

    # --- C loop ----------------------------------------------------------------------
    say(f"C loop: na_step and apd_step, {repeats} x {c_inner} calls")
    for law, ctrl in (("na", na), ("apd", apd)):
        f = model.function(f"{law}_step")
        outs = (np.empty(n), np.empty(len(op[0])), np.empty(1), np.empty(f.sizes_out[3]))
        f.time_calls(max(1, c_inner // 10), 1, *op, ctrl.params, *outs)  # warm up
        st = stats(f.time_calls(c_inner, repeats, *op, ctrl.params, *outs))
        res[f"{law}_step_c_ns"], res[f"{law}_step_c_ns_min"] = st["median"], st["min"]

    # --- C loop: the NA step of each torque split, batches interleaved -------------------
    say(f"C loop: NA step per torque split {BENCH_SPLITS}, interleaved batches")
    ctrls = {s: NAController(model, split=s, preload=np.full(n, BENCH_PRELOAD))
             for s in BENCH_SPLITS}
    per = {s: [] for s in BENCH_SPLITS}
    for _ in range(repeats):
        for s, c in ctrls.items():
            f = model.function(f"{c.function_name}_step")
            outs = (np.empty(n), np.empty(len(op[0])), np.empty(1), np.empty(f.sizes_out[3]))
            per[s] += f.time_calls(c_inner, 1, *op, c.params, *outs)
    for s, times in per.items():
        st = stats(times)
        res[f"na_{s}_step_c_ns"], res[f"na_{s}_step_c_ns_min"] = st["median"], st["min"]
    ratios = [a / b for a, b in zip(per["min_max"], per["min_norm"])]  # paired, same round
    res["na_min_max_over_min_norm"] = stats(ratios)["median"]
    res["na_preload_over_min_norm"] = stats([a / b for a, b in
                                             zip(per["preload"], per["min_norm"])])["median"]

    # --- Python: NAController.step, with and without out=, and the bare binding ------
    say("Python: NAController.step (out= and allocating), bare binding call")
    state0, qa, xd, xd_dot, xd_ddot = op
    qa_prev = model.ik(traj.xd[k_op - 1])[:n].copy()
    buf = np.empty(n)
    step = na.step

    def run_out(k):
        for _ in range(k):
            step(qa, xd, xd_dot, xd_ddot, out=buf)

    def run_alloc(k):
        for _ in range(k):
            step(qa, xd, xd_dot, xd_ddot)

    fna = model.function("na_step")
    s1, tau, stat, dg = np.empty_like(state0), np.empty(n), np.empty(1), np.empty(fna.sizes_out[3])
    params = na.params

    def run_binding(k):
        for _ in range(k):
            fna(state0, qa, xd, xd_dot, xd_ddot, params, tau, s1, stat, dg)

    for key, run in (("na_step_python_us", run_out), ("na_step_python_alloc_us", run_alloc),
                     ("na_step_binding_us", run_binding)):
        na.reset(qa_prev)
        ns, _ = time_batches(run, repeats, batch_s)
        st = stats(ns)
        res[key], res[key + "_min"] = st["median"] / 1e3, st["min"] / 1e3

    # --- casadi.Function (casadi.external on the compiled library) --------------------
    say("casadi.Function: casadi.external on the compiled library")
    try:
        import casadi
    except ImportError as exc:
        casadi = None
        notes["na_step_casadi_function_us"] = f"casadi is not importable ({exc})"
    res["na_step_casadi_function_us"] = res["na_step_casadi_function_us_min"] = None
    if casadi is not None:
        cf = casadi.external(f"{model.name}_na_step", model.library)
        cargs = (state0, qa, xd, xd_dot, xd_ddot, params)
        tau_cf = np.asarray(cf(*cargs)[0]).ravel()
        res["agreement_casadi_function_vs_c"] = rel_diff(tau_cf, c_step(fna, params, op, n)[0])

        def run_cf(k):
            for _ in range(k):
                cf(state0, qa, xd, xd_dot, xd_ddot, params)

        st = stats(time_batches(run_cf, repeats, batch_s * 2)[0])
        res["na_step_casadi_function_us"] = st["median"] / 1e3
        res["na_step_casadi_function_us_min"] = st["min"] / 1e3
        res["casadi_version"] = casadi.__version__

    # --- NumPy reference --------------------------------------------------------------
    say("NumPy reference step (pm2dof.reference.control.na_step) and agreement")
    g = reference_geometry(model)
    ref_step = rc.na_step

    def run_np(k):
        for _ in range(k):
            ref_step(g, state0, qa, xd, xd_dot, xd_ddot, params)

    st = stats(time_batches(run_np, repeats, batch_s * 2)[0])
    res["na_step_numpy_us"], res["na_step_numpy_us_min"] = st["median"] / 1e3, st["min"] / 1e3
    notes["na_step_numpy_us"] = (
        "the NumPy reference is written for clarity: it builds Y column by column "
        f"({len(model.param_names)} evaluations of eq. 13's right side), so it is far slower "
        "than straight NumPy; the lambdify row is the plain-NumPy baseline")
    rng = np.random.default_rng(20100101)
    cases = [op] + random_cases(model, na, rng, n_agree, traj.xd[k_op])
    worst = 0.0
    for case in cases:
        tau_c, s_c, stat_c = c_step(fna, params, case, n)
        tau_r, s_r, stat_r, _ = ref_step(g, *case, params)
        worst = max(worst, rel_diff(tau_c, tau_r), rel_diff(s_c, s_r), float(stat_c != stat_r))
    res["agreement_c_vs_numpy"] = worst
    res["agreement_cases"] = len(cases)

    # --- SymPy lambdify ---------------------------------------------------------------
    say("SymPy: derive the expressions, lambdify fk, unit vectors, S, Y (numpy, cse)")
    res["na_step_lambdify_us"] = res["na_step_lambdify_us_min"] = None
    try:
        lstep, build_s = lambdify_step(model, lays)
    except ImportError as exc:
        lstep = None
        notes["na_step_lambdify_us"] = f"sympy or the derive package is not importable ({exc})"
    if lstep is not None:
        res["lambdify_build_s"] = build_s
        worst = 0.0
        for case in cases:
            tau_c, s_c, stat_c = c_step(fna, params, case, n)
            tau_l, s_l, stat_l = lstep(*case, params)
            worst = max(worst, rel_diff(tau_c, tau_l), rel_diff(s_c, s_l), float(stat_c != stat_l))
        res["agreement_c_vs_lambdify"] = worst

        def run_lam(k):
            for _ in range(k):
                lstep(state0, qa, xd, xd_dot, xd_ddot, params)

        st = stats(time_batches(run_lam, repeats, batch_s * 2)[0])
        res["na_step_lambdify_us"] = st["median"] / 1e3
        res["na_step_lambdify_us_min"] = st["min"] / 1e3

    # --- closed-loop rollout ----------------------------------------------------------
    long, speed_l = long_trajectory(model, n_roll)
    say(f"rollout: {n_roll} samples ({speed_l}-speed move back and forth), accumulate and "
        f"simulate()")
    res["rollout_samples"] = n_roll
    res["rk4_substeps"] = int(model.manifest.get("rk4_substeps", 0)) or None
    f_cl = model.function("na_closed_loop")
    plant = plant_vector(model)
    p = np.concatenate([na.params, plant])
    x0 = np.zeros(lays["cl_state"].size)
    X = lays["cl_state"].unpack(x0)
    X["xe"][:] = long.xd[0]
    qa0 = np.empty(n)
    model.function("measure")(long.xd[0], plant, qa0)
    C0 = lays["ctrl_state"].unpack(X["ctrl_state"])
    C0["xe_prev"][:] = model.fk(qa0)
    C0["theta_hat"][:] = na.theta0
    u = np.ascontiguousarray(np.hstack([long.xd, long.xd_dot, long.xd_ddot]))
    y = np.empty((n_roll, lays["cl_output"].size))
    x = x0.copy()

    def run_acc(k):
        for _ in range(k):
            x[:] = x0
            f_cl.accumulate(x, u, p, y)

    run_acc(1)
    status = y[:, lays["cl_output"].slices["status"]].ravel()
    res["rollout_singular_samples"] = int(np.sum(status == Status.SINGULAR))
    res["rollout_max_error_m"] = float(np.max(np.hypot(*(long.xd - y[:, 0:2]).T)))
    acc = stats(time_batches(run_acc, repeats, 0.0 if quick else 0.05)[0])
    res["rollout_steps_per_s"] = n_roll * 1e9 / acc["median"]
    res["rollout_steps_per_s_best"] = n_roll * 1e9 / acc["min"]
    res["rollout_ns_per_step"] = acc["median"] / n_roll

    def run_sim(k):
        for _ in range(k):
            simulate(model, na, long)

    sim = stats(time_batches(run_sim, repeats, 0.0 if quick else 0.05)[0])
    res["rollout_end_to_end_steps_per_s"] = n_roll * 1e9 / sim["median"]
    res["rollout_end_to_end_steps_per_s_best"] = n_roll * 1e9 / sim["min"]
    res["rollout_python_overhead_us_per_step"] = (sim["median"] - acc["median"]) / n_roll / 1e3

    # --- derivatives and the CTC, LQR steps (bench/derivatives.py) -----------------------
    say("derivatives: Jacobians, sampled step, inverse dynamics (C, Python, Pinocchio, finite "
        "differences); CTC and LQR steps")
    res.update(derivative_bench(model, traj, op, repeats, c_inner, batch_s, notes))

    # --- the binding's overhead and the peers (bench/peers.py) -----------------------------
    say("binding overhead (Python - C) of forward_dynamics and NAController.step; forward "
        "dynamics beside Pinocchio and MuJoCo, interleaved rounds")
    fd_state = dynamics_state(model, traj, len(traj.t) // 2)
    res.update(peer_bench(model, na, op, qa_prev, fd_state, repeats, batch_s, c_inner, notes))

    # --- motion planning (issue 20): plan_time_optimal beside toppra ----------------------
    from .planning import bench_planning
    planning = bench_planning(model, quick, say)
    notes.update(planning.pop("notes"))
    res.update(planning)

    # --- op counts --------------------------------------------------------------------
    say("op counts from the generated C source")
    c_path = Path(model.library).with_name(f"{model.name}.c")
    try:
        ops = count_ops(c_path.read_text(), [f"{model.name}_{s}" for s in OPS_FUNCTIONS])
        res["op_counts"] = {k[len(model.name) + 1:]: v for k, v in ops.items()}
    except (OSError, KeyError, RecursionError) as exc:
        res["op_counts"] = None
        notes["op_counts"] = f"cannot read {c_path}: {exc}"
    res["generated_c"] = str(c_path)

    # --- ratios, targets, machine -----------------------------------------------------
    def ratio(a, b):
        return a / b if (a is not None and b) else None

    res["speedup_c_vs_numpy"] = ratio(res["na_step_numpy_us"] * 1e3, res["na_step_c_ns"])
    res["speedup_c_vs_lambdify"] = ratio(
        None if res["na_step_lambdify_us"] is None else res["na_step_lambdify_us"] * 1e3,
        res["na_step_c_ns"])
    res["speedup_binding_vs_casadi_function"] = ratio(res["na_step_casadi_function_us"],
                                                      res["na_step_python_us"])
    res["speedup_raw_binding_vs_casadi_function"] = ratio(res["na_step_casadi_function_us"],
                                                          res["na_step_binding_us"])
    res["python_overhead_us"] = res["na_step_python_us"] - res["na_step_c_ns"] / 1e3
    res["na_step_budget_fraction"] = res["na_step_c_ns"] * 1e-9 / na.sample_period
    targets = {}
    for key, cmp, target, unit, what in TARGETS:
        v = res.get(key)
        ok = None if v is None else (v <= target if cmp == "<=" else v >= target)
        targets[key] = {"value": v, "target": target, "op": cmp, "unit": unit, "what": what,
                        "pass": ok}
    res["targets"] = targets
    res["all_targets_pass"] = all(t["pass"] for t in targets.values())
    res["machine"] = machine(model.library)
    res["elapsed_s"] = time.perf_counter() - t_start
    return res
