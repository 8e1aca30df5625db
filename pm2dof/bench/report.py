# Rendering of a benchmark result: timings, targets, ratios and op counts as a text table.
__all__ = ["format_bench"]


def _fmt(v, unit=""):
    if v is None:
        return "n/a"
    if unit == "rel":
        return f"{v:.2e}"
    if abs(v) >= 1e5:
        return f"{v:,.0f}"
    if abs(v) >= 100:
        return f"{v:.1f}"
    if abs(v) >= 1:
        return f"{v:.2f}"
    return f"{v:.3g}"


def _target_cells(t):
    """(target, result) of a target entry, or blanks."""
    if not t:
        return "", ""
    res = "n/a" if t["pass"] is None else ("PASS" if t["pass"] else "FAIL")
    return f"{t['op']} {_fmt(t['target'], t['unit'])}", res


def _model_rows(r, tg):
    """The platforms beside the paper's robot (``model_rows``): one line per model, then the
    paired ratios to the paper's robot and the two targets."""
    rows = r.get("model_rows")
    if not rows:
        return []
    paper = r.get("models_paper")
    out = ["", f"the platforms beside the paper's robot ({paper}), interleaved rounds, medians; "
           "ns unless named", f"  {'model':15s} {'legs':>4s} {'m':>2s} {'NA C':>8s} {'NA Py':>8s} "
           f"{'NA ovh':>8s} {'FD C':>8s} {'FD Py':>8s} {'FD ovh':>8s} {'rollout/s':>11s} "
           f"{'plan ms':>8s}"]
    for name, x in rows.items():
        out.append(f"  {name:15s} {x['n_legs']:4d} {x['dof']:2d} "
                   + " ".join(f"{_fmt(x[k]):>8s}" for k in (
                       "na_step_c_ns", "na_step_python_ns", "na_step_binding_overhead_ns",
                       "forward_dynamics_c_ns", "forward_dynamics_python_ns",
                       "forward_dynamics_binding_overhead_ns"))
                   + f" {_fmt(x['rollout_steps_per_s']):>11s} {_fmt(x['plan_time_optimal_ms']):>8s}")
    out.append("  (NA/FD: the NA step and the forward dynamics; ovh: the binding's overhead, "
               "Python - C; plan: plan_time_optimal, min_max, 1000 points, the model's first "
               "move, a platform's carrying phi)")
    out.append(f"  ratios to {paper} (paired per round; ovh: of the medians): NA C, NA Py, NA ovh, "
               "FD C, FD Py, FD ovh, rollout time, plan time")
    for name, x in rows.items():
        if name == paper:
            continue
        out.append(f"  {name:15s} " + " ".join(f"{_fmt(x[k]):>6s}" for k in (
            "na_step_c_over_paper", "na_step_python_over_paper",
            "na_step_binding_overhead_over_paper", "forward_dynamics_c_over_paper",
            "forward_dynamics_python_over_paper", "forward_dynamics_binding_overhead_over_paper",
            "rollout_time_over_paper", "plan_time_optimal_over_paper")))
    for key, label in (("rrr4_na_step_c_over_paper", "NA step in C, 4-RRR / paper's robot"),
                       ("platform_binding_overhead_over_paper_max",
                        "binding overhead, platforms / paper's, worst call")):
        tgt, res = _target_cells(tg.get(key))
        out.append(f"  {label:52s} {_fmt(r.get(key), 'x'):>8s} x {tgt:>10s}  {res}")
    out.append("  the peers (Pinocchio, MuJoCo) stay on the paper's robot: they model RR legs "
               "meeting at a point")
    return out


def _build_rows(r, tg):
    """``pm2dof derive`` of the 4-RRR platform beside gcc on the paper's C (bench/build_time.py):
    wall and processor times, the target."""
    if r.get("derive_rrr4_s") is None:
        return []
    return ["", f"the build: pm2dof derive rrr4_platform (SymPy, CasADi, the C compiled on "
            f"{r.get('build_jobs')} processors) beside gcc -O3 on the paper robot's C (whole), "
            f"back to back",
            f"  derive {_fmt(r['derive_rrr4_s'])} s wall ({_fmt(r['derive_rrr4_cpu_s'])} s of "
            f"processor time); gcc {_fmt(r['gcc_paper_s'])} s wall "
            f"({_fmt(r['gcc_paper_cpu_s'])} s); processor times "
            f"{_fmt(r.get('derive_rrr4_cpu_over_gcc_paper_cpu'))}x",
            _target_line(r, tg, "derive_rrr4_over_gcc_paper", "derive / gcc, wall")]


def _target_line(r, tg, key, label, unit="x"):
    tgt, res = _target_cells(tg.get(key))
    return f"  {label:60s} {_fmt(r.get(key), unit):>8s} {unit:2s} {tgt:>10s}  {res}"


def _design_rows(r, tg):
    """The geometry as a run-time input (``design_rows``: the [design] model beside the fixed
    one) and the design studies (``synthesis_rows``: designs per second per objective class,
    the kinematic objectives against their C calls, Dask's overhead)."""
    out = []
    rows = r.get("design_rows")
    if rows:
        out += ["", "the geometry as a run-time input: a [design] model beside the fixed one "
                "(interleaved rounds, medians, ns)",
                f"  {'model':18s} {'FD C':>8s} {'FD Py':>8s} {'NA C':>8s} {'NA Py':>8s} "
                f"{'FD flops':>9s} {'NA flops':>9s}"]
        for name, x in rows.items():
            ops = x.get("ops") or {}
            out.append(f"  {name:18s} " + " ".join(f"{_fmt(x.get(k)):>8s}" for k in (
                "forward_dynamics_c_ns", "forward_dynamics_python_ns", "na_step_c_ns",
                "na_step_python_ns"))
                + f" {(ops.get('forward_dynamics') or {}).get('flops', 'n/a'):>9}"
                + f" {(ops.get('na_step') or {}).get('flops', 'n/a'):>9}")
        out.append(_target_line(r, tg, "design_fd_ratio",
                                "forward dynamics, design / fixed, Python (paired)"))
        out.append(_target_line(r, tg, "design_na_step_ratio",
                                "NA step, design / fixed, Python (paired)"))
    srows = r.get("synthesis_rows")
    if not srows:
        return out
    out += ["", "design studies: designs per second per objective class (evaluate_batch, "
            "at_design included), and the speed-up on structdimsynth's published s per design "
            "(0.5 s kinematic, 1.8 s with dynamics)"]
    classes = list(next(iter(srows.values())))
    classes = [c for c in classes if isinstance(srows[next(iter(srows))][c], dict)]
    out.append(f"  {'model':22s}" + "".join(f"{c:>22s}" for c in classes))
    for name, x in srows.items():
        out.append(f"  {name:22s}" + "".join(
            f"{_fmt(x[c]['designs_per_s']):>10s}/s ({_fmt(x[c]['speedup_vs_structdimsynth'])}x)"
            .rjust(22) for c in classes))
    reg = next(iter(srows.values())).get("region_points")
    for name, x in srows.items():
        out.append(f"  {name:22s} kinematic objectives {_fmt(x.get('kinematic_objectives_ms'))} "
                   f"ms per design against its C calls {_fmt(x.get('kinematic_c_ms'))} ms "
                   f"({reg} region points): {_fmt(x.get('kinematic_over_c'))}x")
    out.append(_target_line(r, tg, "synthesis_kinematic_over_c_max",
                            "kinematic objectives / their C calls, worst model"))
    if r.get("synthesis_dask_s") is not None:
        out.append(f"  Dask, 1 worker: {r.get('synthesis_dask_designs')} designs in "
                   f"{_fmt(r['synthesis_dask_s'])} s, of which the worker evaluated for "
                   f"{_fmt(r['synthesis_worker_s'])} s (overhead "
                   f"{100 * r['synthesis_dask_overhead']:.1f} %); in this process "
                   f"{_fmt(r['synthesis_inprocess_s'])} s (paired ratio "
                   f"{_fmt(r['synthesis_dask_over_inprocess'])}x, not a target: this machine's "
                   f"noise)")
    out.append(_target_line(r, tg, "synthesis_dask_over_worker",
                            "design run, Dask 1 worker / the worker's evaluation"))
    return out


def _overhead_rows(r, tg):
    """Every per-sample Model method's binding overhead (``overhead_over_c_<method>``,
    bench/overheads.py): its Python and C times and the ratio, with its target."""
    keys = [k[len("overhead_over_c_"):] for k in r if k.startswith("overhead_over_c_")
            and k not in ("overhead_over_c_max", "overhead_over_c_worst")]
    if not keys:
        return []
    out = ["", "the binding's overhead of each per-sample Model method (Python with out= - C "
           "loop) / C, paired rounds, medians",
           f"  {'method':28s} {'Python ns':>10s} {'C ns':>10s} {'(Py - C) / C':>13s} "
           f"{'target':>10s}  result"]
    for name in keys:
        tgt, res = _target_cells(tg.get(f"overhead_over_c_{name}"))
        out.append(f"  {name:28s} {_fmt(r.get(f'overhead_python_ns_{name}')):>10s} "
                   f"{_fmt(r.get(f'overhead_c_ns_{name}')):>10s} "
                   f"{_fmt(r.get(f'overhead_over_c_{name}'), 'x'):>13s} {tgt:>10s}  {res}")
    out.append(f"  worst: {r.get('overhead_over_c_worst')} "
               f"{_fmt(r.get('overhead_over_c_max'), 'x')} x; the energies return a float (no "
               f"out=) and have no target: their C takes a few ns")
    return out


def format_bench(results):
    """A readable report of :func:`run_bench`'s dict: timings, targets, ratios, op counts."""
    r = results
    tg = r.get("targets", {})
    lines = [f"pm2dof bench: model {r.get('model')!r} ({r.get('n_legs')} legs), "
             f"{'quick' if r.get('quick') else 'full'} run, median (min) of "
             f"{r.get('repeats')} batches",
             ""]
    head = f"{'measurement':44s} {'median':>12s} {'min':>12s} {'unit':8s} {'target':>10s}  result"
    lines += [head, "-" * len(head)]

    def row(label, key, unit, scale=1.0, min_key=None):
        v = r.get(key)
        vm = r.get(min_key or key + "_min")
        v = None if v is None else v * scale
        vm = None if vm is None else vm * scale
        t = tg.get(key)
        tgt = res_s = ""
        if t:
            tgt = f"{t['op']} {_fmt(t['target'], t['unit'])}"
            res_s = "n/a" if t["pass"] is None else ("PASS" if t["pass"] else "FAIL")
        vm_s = _fmt(vm, unit) if vm is not None else ""
        lines.append(f"{label:44s} {_fmt(v, unit):>12s} {vm_s:>12s} {unit:8s} {tgt:>10s}  "
                     f"{res_s}")

    row("NA step, C loop (time_calls)", "na_step_c_ns", "ns")
    row("APD step, C loop (time_calls)", "apd_step_c_ns", "ns")
    for split in ("min_norm", "min_max", "preload"):
        row(f"NA step, {split} split, C loop (interleaved)", f"na_{split}_step_c_ns", "ns")
    row("NA step, bare _cbind call from Python", "na_step_binding_us", "us")
    row("NA step, NAController.step(out=buf)", "na_step_python_us", "us")
    row("NA step, NAController.step (allocating)", "na_step_python_alloc_us", "us")
    row("NA step, casadi.Function (casadi.external)", "na_step_casadi_function_us", "us")
    row("NA step, NumPy reference", "na_step_numpy_us", "us")
    row("NA step, SymPy lambdify (numpy, cse)", "na_step_lambdify_us", "us")
    row("CTC step, C loop (interleaved with NA)", "ctc_step_c_ns", "ns")
    row("LQR step, C loop (interleaved with NA)", "lqr_step_c_ns", "ns")
    row("forward dynamics, C loop", "forward_dynamics_c_ns", "ns")
    row("forward-dynamics Jacobians, C loop", "forward_dynamics_jacobians_c_ns", "ns")
    row("sampled step (RK4 under ZOH), C loop", "sampled_step_c_ns", "ns")
    row("sampled step + Jacobians, C loop", "sampled_step_jacobians_c_ns", "ns")
    row("inverse dynamics + Jacobians, C loop", "inverse_dynamics_jacobians_c_ns", "ns")
    row("forward dynamics, Model method (out=)", "forward_dynamics_python_us", "us")
    row("FD Jacobians, Model method (out=)", "fd_jacobians_python_us", "us")
    row("FD Jacobians by central differences, Python", "fd_jacobians_finite_differences_python_us",
        "us")
    row("Pinocchio constraintDynamics + derivatives", "pinocchio_constraint_derivatives_python_us",
        "us")
    row("forward dynamics, Model method (interleaved)", "fd_python_interleaved_ns", "ns")
    row("forward dynamics, C loop (interleaved)", "fd_c_interleaved_ns", "ns")
    row("NA step, NAController.step (interleaved)", "na_step_python_interleaved_ns", "ns")
    row("NA step, C loop (interleaved)", "na_step_c_interleaved_ns", "ns")
    row("Pinocchio constraintDynamics, Python", "pinocchio_forward_dynamics_python_us", "us")
    row("MuJoCo mj_forward, Python", "mujoco_forward_python_us", "us")
    row(f"rollout, accumulate ({r.get('rollout_samples')} samples)", "rollout_steps_per_s",
        "steps/s", min_key="rollout_steps_per_s_best")
    row("rollout, end to end (simulate())", "rollout_end_to_end_steps_per_s", "steps/s",
        min_key="rollout_end_to_end_steps_per_s_best")
    lines.append("(for the rollout rows the second column is the best batch)")
    if r.get("rollout_ns_per_step") is not None:
        lines.append(f"rollout: {_fmt(r['rollout_ns_per_step'])} ns per control step in C "
                     f"(NA step, encoder, {r.get('rk4_substeps')} RK4 plant steps); simulate() "
                     f"adds {_fmt(r.get('rollout_python_overhead_us_per_step'))} us per step "
                     f"in Python")
    if r.get("plan_time_optimal_ms") is not None:
        lines.append("")
        lines.append(f"motion planning: {r.get('plan_path')}, {r.get('plan_grid')} grid points "
                     f"(median and min)")
        row("plan_time_optimal, min_max split", "plan_time_optimal_ms", "ms")
        row("plan_time_optimal, min_norm split", "plan_time_optimal_min_norm_ms", "ms")
        row("  the same, friction-free theta", "plan_friction_free_ms", "ms")
        row("toppra, end to end (Me, Ce per point in C)", "toppra_ms", "ms")
        row("toppra, solver alone (coefficients given)", "toppra_solve_ms", "ms")
        if r.get("toppra_duration_s") is not None:
            lines.append(f"  durations found: pm2dof {r['plan_duration_friction_free_s']:.7f} s, "
                         f"toppra {r['toppra_duration_s']:.7f} s (rel. diff. "
                         f"{r['plan_vs_toppra_rel_diff']:.1e})")
        paths = r.get("plan_paths") or {}
        if paths:
            lines.append("  refined plans (1000 points asked; ms, medians): path, case, grid "
                         "(rounds): refined / unrefined of that grid = ratio; toppra (x)")
            for name, cases in paths.items():
                for case, c in cases.items():
                    tp = (f"; toppra {_fmt(c['toppra_ms'])} ms ({c['speedup_vs_toppra']:.1f}x)"
                          if c.get("toppra_ms") is not None else "")
                    lines.append(f"    {name:15s} {case:23s} {c['grid']:5d} ({c['refinements']})"
                                 f" {_fmt(c['refined_ms']):>7s} / {_fmt(c['unrefined_ms']):>7s}"
                                 f" = {c['refined_over_unrefined']:.2f}{tp}")
        if r.get("plan_smooth_solve_s") is not None:
            lines.append(f"  smoothed plan (IPOPT, {r.get('plan_smooth_grid', 200)} points): "
                         f"{r['plan_smooth_solve_s']:.3f} s "
                         f"solve, {r['plan_smooth_iterations']} iterations; "
                         f"{r['plan_smooth_duration_s']:.4f} s vs strict "
                         f"{r['plan_smooth_strict_duration_s']:.4f} s")
    lines += _model_rows(r, tg)
    lines += _build_rows(r, tg)
    lines += _design_rows(r, tg)
    lines += _overhead_rows(r, tg)
    lines.append("")
    lines.append("ratios and agreement")
    for label, key, unit in (
            ("NA step: min_max / min_norm split", "na_min_max_over_min_norm", "x"),
            ("NA step: preload / min_norm split", "na_preload_over_min_norm", "x"),
            ("plan_time_optimal vs toppra, end to end", "speedup_vs_toppra", "x"),
            ("plan_time_optimal vs toppra's solver alone", "speedup_vs_toppra_solve", "x"),
            ("refined / unrefined plan, worst path", "plan_refined_over_unrefined_max", "x"),
            ("plan_time_optimal vs toppra, worst path", "speedup_vs_toppra_min", "x"),
            ("C step vs NumPy reference", "speedup_c_vs_numpy", "x"),
            ("C step vs SymPy lambdify", "speedup_c_vs_lambdify", "x"),
            ("NAController.step vs casadi.Function", "speedup_binding_vs_casadi_function", "x"),
            ("bare binding vs casadi.Function", "speedup_raw_binding_vs_casadi_function", "x"),
            ("C vs NumPy, max rel. diff." + (f" ({r['agreement_cases']} states)"
                                             if r.get("agreement_cases") else ""),
             "agreement_c_vs_numpy", "rel"),
            ("C vs lambdify, max rel. diff.", "agreement_c_vs_lambdify", "rel"),
            ("casadi.Function vs binding (tau_a)", "agreement_casadi_function_vs_c", "rel"),
            ("FD Jacobians / forward dynamics, C", "fd_jacobians_over_fd_c", "x"),
            ("Pinocchio derivatives / FD Jacobians, Python", "speedup_fd_jacobians_vs_pinocchio",
             "x"),
            ("central differences / FD Jacobians, Python",
             "speedup_fd_jacobians_vs_finite_differences", "x"),
            ("FD Jacobians vs central differences", "agreement_fd_jacobians_vs_finite_differences",
             "rel"),
            ("Pinocchio vs pm2dof tip acceleration", "agreement_pinocchio_tip_acceleration",
             "rel"),
            ("forward dynamics vs Pinocchio, Python", "speedup_fd_vs_pinocchio", "x"),
            ("forward dynamics vs MuJoCo, Python", "speedup_fd_vs_mujoco", "x"),
            ("forward dynamics: (Python - C) / C", "fd_binding_overhead_over_c", "x"),
            ("NA step: (Python - C) / C", "na_step_binding_overhead_over_c", "x"),
            ("NA step: (Python - C) / forward dynamics C",
             "na_step_binding_overhead_over_fd_c", "x"),
            ("MuJoCo vs pm2dof tip acceleration (soft)", "agreement_mujoco_forward_dynamics",
             "rel")):
        t = tg.get(key)
        tgt = f"{t['op']} {_fmt(t['target'], t['unit'])}" if t else ""
        res_s = ("n/a" if t["pass"] is None else ("PASS" if t["pass"] else "FAIL")) if t else ""
        lines.append(f"  {label:42s} {_fmt(r.get(key), unit):>12s} {'':12s} {unit:8s} "
                     f"{tgt:>10s}  {res_s}")
    if r.get("na_step_budget_fraction") is not None:
        lines.append(f"  the NA step in C takes {100 * r['na_step_budget_fraction']:.4f} % of "
                     f"the sample period; NAController.step adds "
                     f"{_fmt(r.get('python_overhead_us'))} us of Python")
    if r.get("fd_binding_overhead_ns") is not None:
        lines.append(f"  the binding's overhead per call (Python - C, paired rounds): "
                     f"forward_dynamics {_fmt(r['fd_binding_overhead_ns'])} ns, "
                     f"NAController.step {_fmt(r.get('na_step_binding_overhead_ns'))} ns")
    ops = r.get("op_counts")
    if ops:
        lines.append("")
        lines.append("operations in the generated C (static count, callees included)")
        cols = ("mul", "sq", "add", "sub", "div", "neg", "sin", "cos", "sqrt", "atan2", "exp",
                "tanh", "floor", "fmin", "fmax", "fabs", "cmp", "select", "flops")
        lines.append(f"  {'function':18s}" + "".join(f"{c:>7s}" for c in cols))
        for name, c in ops.items():
            lines.append(f"  {name:18s}" + "".join(f"{c.get(k, 0):7d}" for k in cols))
    notes = r.get("notes") or {}
    if notes:
        lines.append("")
        lines += [f"note: {k}: {v}" for k, v in notes.items()]
    m = r.get("machine") or {}
    if m:
        lines.append("")
        lines.append(f"machine: {m.get('cpu')}, {m.get('cores')} cores "
                     f"({m.get('cores_available')} available), {m.get('platform')}")
        lines.append(f"compiler: {m.get('compiler_version') or m.get('compiler')}; flags: "
                     f"{m.get('compiler_flags')} ({m.get('compiler_flags_source')})")
        lines.append(f"python {m.get('python')}, numpy {m.get('numpy')}"
                     + (f", casadi {r['casadi_version']}" if r.get("casadi_version") else ""))
    if "elapsed_s" in r:
        n_pass = sum(1 for t in tg.values() if t["pass"])
        lines.append(f"targets met: {n_pass}/{len(tg)}; bench took {r['elapsed_s']:.1f} s")
    return "\n".join(lines)
