# Step-time benchmark: the generated NA/APD steps in C, from Python, against casadi.Function,
# NumPy and SymPy-lambdify implementations of the same step; closed-loop rollout speed; op counts.
"""Benchmark of the generated controller step and closed-loop rollout.

:func:`run_bench` measures everything in one run and returns a JSON-able dict;
:func:`format_bench` renders it as a table with the project's targets. Used by
``pm2dof bench [--json] [--quick]``.
"""
import gc
import math
import os
import platform
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

__all__ = ["run_bench", "format_bench", "TARGETS", "REQUIRED_KEYS", "count_ops"]

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
)

# Functions whose generated C body is measured, by short name.
OPS_FUNCTIONS = ("na_step", "apd_step", "na_closed_loop", "plant_step", "Y", "forward_dynamics")

# Math-library / CasADi helper calls counted in a body.
_CALLS = ("sin", "cos", "tan", "sqrt", "atan2", "exp", "log", "tanh", "acos", "asin", "atan",
          "floor", "pow", "fmin", "fmax", "fabs", "sq")


# --------------------------------------------------------------------------------------
# operation counts from the generated C source
# --------------------------------------------------------------------------------------

_BODY_START = re.compile(r"^static int (casadi_f\d+)\(const casadi_real\*\* arg", re.M)
_WRAPPER = re.compile(r"^CASADI_SYMBOL_EXPORT int (\w+)\(const casadi_real\*\* arg[^{]*\{\s*"
                      r"return (casadi_f\d+)\(arg, res, iw, w, mem\);", re.M)
_BINARY = re.compile(r"=\s*\(\s*[\w.]+\s*([-+*/])\s*[\w.]+\s*\)\s*;")
_COMPOUND = re.compile(r"^\s*[\w\[\]]+\s*([-+*/])=\s*[\w.]+\s*;")
_NEG = re.compile(r"=\s*\(\s*-\s*\w+\s*\)\s*;")
_CMP = re.compile(r"=\s*\(\s*\w+\s*(<=|>=|<|>|==|!=)\s*\w+\s*\)\s*;")
_SELECT = re.compile(r"=\s*\(\s*\w+\s*\?\s*\w+\s*:\s*[\w.]+\s*\)\s*;")
_CALL = re.compile(r"\b(?:casadi_)?(" + "|".join(_CALLS) + r")\s*\(")
_SUBCALL = re.compile(r"\b(casadi_f\d+)\s*\(arg1")


def _bodies(src):
    """{casadi_fN: body text} of the generated C."""
    out = {}
    for m in _BODY_START.finditer(src):
        end = src.find("\n}\n", m.end())
        out[m.group(1)] = src[m.end():end if end >= 0 else len(src)]
    return out


def _own_counts(body):
    c = {"mul": 0, "add": 0, "sub": 0, "div": 0, "neg": 0, "cmp": 0, "select": 0,
         **{k: 0 for k in _CALLS}}
    sym = {"*": "mul", "+": "add", "-": "sub", "/": "div"}
    for line in body.splitlines():
        m = _BINARY.search(line) or _COMPOUND.search(line)
        if m:
            c[sym[m.group(1)]] += 1
        elif _NEG.search(line):
            c["neg"] += 1
        elif _CMP.search(line):
            c["cmp"] += 1
        elif _SELECT.search(line):
            c["select"] += 1
        for name in _CALL.findall(line):
            c[name] += 1
    return c


def count_ops(c_source, public_names):
    """Static operation counts of generated functions, read from their C source.

    Parameters
    ----------
    c_source : str
        Text of ``generated/<name>/<name>.c``.
    public_names : iterable of str
        Exported names (``shang2010_na_step``, ...).

    Returns
    -------
    dict
        {public name: {"body": casadi_fN, "mul", "add", "sub", "div", "neg", "cmp", "select",
        one count per math call (sin, cos, sqrt, atan2, exp, tanh, fmin, fmax, fabs, sq, ...),
        "flops" (mul + add + sub + div + neg + sq), "transcendental" (sin + cos + ... + tanh),
        "calls" {callee body: times}}}. Counts are of statements in the straight-line code
        CasADi writes, inclusive of the functions a body calls (the closed loop calls the step,
        the encoder and 4 plant steps); ``sq`` is x*x, counted apart from ``mul``.
    """
    bodies = _bodies(c_source)
    wrappers = dict(_WRAPPER.findall(c_source))
    memo = {}

    def inclusive(fn, depth=0):
        if fn in memo:
            return memo[fn]
        if depth > 50:
            raise RecursionError(fn)
        body = bodies[fn]
        c = _own_counts(body)
        calls = {}
        for callee in _SUBCALL.findall(body):
            calls[callee] = calls.get(callee, 0) + 1
            sub = inclusive(callee, depth + 1)
            for k, v in sub.items():
                if k not in ("calls", "body"):
                    c[k] += v
        c["calls"] = calls
        memo[fn] = c
        return c

    out = {}
    for name in public_names:
        fn = wrappers.get(name)
        if fn is None or fn not in bodies:
            raise KeyError(f"no generated body for {name} in the C source")
        c = dict(inclusive(fn))
        c["flops"] = c["mul"] + c["add"] + c["sub"] + c["div"] + c["neg"] + c["sq"]
        c["transcendental"] = sum(c[k] for k in ("sin", "cos", "tan", "sqrt", "atan2", "exp",
                                                 "log", "tanh", "acos", "asin", "atan", "pow"))
        out[name] = {"body": fn, **c}
    return out


# --------------------------------------------------------------------------------------
# timing helpers
# --------------------------------------------------------------------------------------

def _stats(per_call):
    """{"median", "min", "samples"} of per-call times (one per batch)."""
    return {"median": float(statistics.median(per_call)), "min": float(min(per_call)),
            "samples": [float(x) for x in per_call]}


def _time_batches(run, repeats, batch_s):
    """Time ``run(n)`` (n calls in its own tight loop): per-call ns for each of ``repeats``
    batches of about ``batch_s`` seconds. The batch size is calibrated first; gc is off."""
    n = 1
    while True:  # calibrate: grow n until one batch takes >= batch_s / 4
        t0 = time.perf_counter_ns()
        run(n)
        dt = time.perf_counter_ns() - t0
        if dt >= batch_s * 0.25e9 or n >= 1 << 24:
            break
        n *= 4 if dt < batch_s * 0.025e9 else 2
    n = max(1, int(n * batch_s * 1e9 / max(dt, 1)))
    out = []
    enabled = gc.isenabled()
    gc.disable()
    try:
        for _ in range(repeats):
            t0 = time.perf_counter_ns()
            run(n)
            out.append((time.perf_counter_ns() - t0) / n)
    finally:
        if enabled:
            gc.enable()
    return out, n


def _rel(a, b):
    """||a - b||_inf / ||b||_inf (0 if both are zero)."""
    a, b = np.ravel(np.asarray(a, dtype=float)), np.ravel(np.asarray(b, dtype=float))
    d = float(np.max(np.abs(a - b)))
    s = float(np.max(np.abs(b)))
    return d / s if s > 0 else d


# --------------------------------------------------------------------------------------
# the pieces
# --------------------------------------------------------------------------------------

def _geometry(model):
    from .reference import Geometry
    legs = model.spec.legs
    return Geometry(bases=model.bases, la=[l.la for l in legs], lb=[l.lb for l in legs],
                    elbow=[l.elbow for l in legs], fk_branch=model.spec.fk_branch)


def _operating_point(model, ctrl, traj, k):
    """A representative NA state: the controller run along ``traj`` to sample k with qa from
    ik(xd) (perfect tracking), so v and theta_hat are those of a real move. Returns
    (state, qa, xd, xd_dot, xd_ddot) for sample k, state in the ``ctrl_state`` layout."""
    n = model.n_legs
    ctrl.reset(model.ik(traj.xd[0])[:n])
    for i in range(k):
        ctrl.step(model.ik(traj.xd[i])[:n], traj.xd[i], traj.xd_dot[i], traj.xd_ddot[i])
    state = ctrl.state_layout.pack(**ctrl.state)
    return (state, model.ik(traj.xd[k])[:n].copy(), traj.xd[k].copy(), traj.xd_dot[k].copy(),
            traj.xd_ddot[k].copy())


def _random_cases(model, ctrl, rng, count, center):
    """Random NA step inputs within 3 cm of ``center`` (m): pose, velocity, estimate, desired
    motion. Poses out of reach or near a singularity are drawn again."""
    n, T = model.n_legs, ctrl.sample_period
    cases = []
    for _ in range(200 * count):
        if len(cases) == count:
            break
        xe = np.asarray(center, dtype=float) + rng.uniform(-0.03, 0.03, 2)
        try:
            q = model.ik(xe)
        except Exception:  # noqa: BLE001 (out of reach: draw again)
            continue
        if np.min(np.abs(model.singularity(q))) < 2 * model.singularity_threshold:
            continue
        qa = q[:n].copy()
        # tracking errors of the size seen on the paper's moves, so that the torques stay
        # below tau_max (a clipped torque would hide differences)
        v = rng.uniform(-0.5, 0.5, 2)
        theta = np.asarray(model.theta_nominal) * rng.uniform(0.7, 1.3, len(model.param_names))
        state = np.concatenate([xe - T * v + rng.normal(0, 1e-6, 2), v, theta])
        xd = xe + rng.normal(0, 2e-4, 2)
        xd_dot = v + rng.normal(0, 0.02, 2)
        cases.append((state, qa, xd, xd_dot, rng.uniform(-10, 10, 2)))
    return cases


def _c_step(f, params, case, n):
    tau, s1, st, dg = np.empty(n), np.empty(len(case[0])), np.empty(1), np.empty(f.sizes_out[3])
    f(*case, params, tau, s1, st, dg)
    return tau, s1, int(st[0])


def _import_derive():
    """derive is build-time code at the repository root; import it (lazily) for the bench."""
    try:
        import derive.model_functions as dmf
    except ImportError:
        from .model import REPO
        if not (REPO / "derive" / "__init__.py").is_file():
            raise
        if str(REPO) not in sys.path:
            sys.path.insert(0, str(REPO))
        import derive.model_functions as dmf
    return dmf


_LAMBDIFY_CACHE = {}


def _lambdify_step(model, layouts):
    """One NA step composed in NumPy from SymPy expressions turned into functions by
    sympy.lambdify (numpy backend, cse=True): fk(qa), the passive unit vectors (qa, xe),
    S(q), Y(q, xed, xrd, xrdd), sin(qb - qa). Returns (step, build seconds)."""
    key = (model.name, model.spec.formulation_sha256)
    if key in _LAMBDIFY_CACHE:
        return _LAMBDIFY_CACHE[key], 0.0
    t0 = time.perf_counter()
    import sympy as sp
    dmf = _import_derive()
    d = dmf.Derivation(model.spec)
    sym, kin, dyn = d.sym, d.kin, d.dyn
    n = model.n_legs
    qa_s, q_s = list(sym.qa), list(sym.q)
    modules = [{"sgn": lambda v: 1.0 if v >= 0 else -1.0}, "numpy"]  # sgn(0) = +1, as the C

    def lam(args, expr):
        return sp.lambdify(args, expr, modules, cse=True)

    fk = lam([qa_s], kin.fk())
    uv = kin.unit_vectors_from_qa(sym.xe)
    ub = lam([qa_s, list(sym.xe)],
             sp.Matrix([[uv[sym.qb[i]][0] for i in range(n)],
                        [uv[sym.qb[i]][1] for i in range(n)]]))
    S = lam([q_s], kin.S)
    Y = lam([q_s, list(sym.xed), list(sym.xrd), list(sym.xrdd)], dyn.Y)
    sab = lam([q_s], sp.Matrix([kin.sin_ab(i) for i in range(n)]))
    st_lay, p_lay = layouts["ctrl_state"], layouts["na_params"]

    def step(state, qa, xd, xd_dot, xd_ddot, params):
        st, P = st_lay.unpack(state), p_lay.unpack(params)
        T, a = P["T"][0], P["vel_alpha"][0]
        xe = np.asarray(fk(qa), dtype=float).ravel()
        v = st["v"] + a * ((xe - st["xe_prev"]) / T - st["v"])
        e = xd - xe
        edot = xd_dot - v
        theta = st["theta_hat"]
        c, s = np.asarray(ub(qa, xe), dtype=float)
        q = np.concatenate([qa, np.arctan2(s, c)])
        xrd = xd_dot + P["Q"] * e
        xrdd = xd_ddot + P["Q"] * edot
        sv = xrd - v
        Yq = np.asarray(Y(q, v, xrd, xrdd), dtype=float)
        Sq = np.asarray(S(q), dtype=float)
        u = Yq @ theta + P["Kd"] * sv
        theta_next = theta + T * P["Gamma"] * (Yq.T @ sv)
        G = Sq.T @ Sq
        tau = Sq @ np.linalg.solve(G, u)
        tau_max = P["tau_max"]
        ok = float(np.min(np.abs(np.asarray(sab(q), dtype=float)))) >= P["sing_threshold"][0]
        if ok:
            status = 2 if np.max(np.abs(tau) - tau_max) > 0 else 0
            tau_out, theta_out = np.minimum(np.maximum(tau, -tau_max), tau_max), theta_next
        else:
            status, tau_out, theta_out = 1, np.zeros(n), theta
        return tau_out, np.concatenate([xe, v, theta_out]), status

    _LAMBDIFY_CACHE[key] = step
    return step, time.perf_counter() - t0


def _long_trajectory(model, n_samples):
    """The high-speed move forward and back (reversed in time), tiled to ``n_samples``."""
    from .experiment import trajectory
    from .trajectory import Trajectory
    speed = "high" if "high" in model.spec.trajectories else next(iter(model.spec.trajectories))
    tr = trajectory(model, speed)
    xd = np.vstack([tr.xd, tr.xd[::-1]])
    xdd = np.vstack([tr.xd_dot, -tr.xd_dot[::-1]]) + 0.0
    xddd = np.vstack([tr.xd_ddot, tr.xd_ddot[::-1]])
    reps = math.ceil(n_samples / len(xd))
    xd, xdd, xddd = (np.tile(a, (reps, 1))[:n_samples] for a in (xd, xdd, xddd))
    return Trajectory(np.arange(n_samples) * tr.period, xd, xdd, xddd, tr.period, tr.start,
                      tr.end, tr.profile), speed


def _machine():
    from .build import FLAGS, LIBS, _compiler
    cpu = None
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    cc = _compiler()
    try:
        cc_version = subprocess.run([*cc, "--version"], capture_output=True, text=True,
                                    timeout=10).stdout.splitlines()[0]
    except (OSError, IndexError, subprocess.SubprocessError):
        cc_version = None
    try:
        affinity = len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        affinity = None
    return {"cpu": cpu or platform.processor() or None, "cores": os.cpu_count(),
            "cores_available": affinity, "platform": platform.platform(),
            "python": sys.version.split()[0], "numpy": np.__version__,
            "compiler": " ".join(cc), "compiler_version": cc_version,
            "compiler_flags": " ".join((*FLAGS, *LIBS))}


# --------------------------------------------------------------------------------------
# the benchmark
# --------------------------------------------------------------------------------------

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
    - ``na_step_numpy_us``: ``pm2dof.reference_control.na_step`` (plain NumPy), us.
    - ``na_step_lambdify_us``: the step composed in NumPy from the SymPy expressions
      (fk, passive unit vectors, S, Y) through ``sympy.lambdify(..., cse=True)``, us.
    - ``rollout_steps_per_s``: closed-loop rollout (encoder + NA step + the plant's RK4 substeps
      per 2 ms sample) in control steps per second, the ``accumulate`` call alone over
      ~20000 samples (the high-speed move back and forth); ``rollout_end_to_end_steps_per_s``
      through ``pm2dof.simulate.simulate``.
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
    from . import reference_control as rc
    from .controllers import APDController, NAController
    from .experiment import trajectory
    from .layout import Layout
    from .model import load_model
    from .simulate import plant_vector, simulate

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
    speed = "high" if "high" in model.spec.trajectories else next(iter(model.spec.trajectories))
    traj = trajectory(model, speed)
    k_op = len(traj.t) // 2
    say(f"operating point: the NA controller along the {speed}-speed move to sample {k_op}")
    op = _operating_point(model, na, traj, k_op)
    res["operating_point"] = {"trajectory": speed, "sample": k_op}

    # --- C loop ----------------------------------------------------------------------
    say(f"C loop: na_step and apd_step, {repeats} x {c_inner} calls")
    for law, ctrl in (("na", na), ("apd", apd)):
        f = model.function(f"{law}_step")
        outs = (np.empty(n), np.empty(len(op[0])), np.empty(1), np.empty(f.sizes_out[3]))
        f.time_calls(max(1, c_inner // 10), 1, *op, ctrl.params, *outs)  # warm up
        st = _stats(f.time_calls(c_inner, repeats, *op, ctrl.params, *outs))
        res[f"{law}_step_c_ns"], res[f"{law}_step_c_ns_min"] = st["median"], st["min"]

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
        ns, _ = _time_batches(run, repeats, batch_s)
        st = _stats(ns)
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
        res["agreement_casadi_function_vs_c"] = _rel(tau_cf, _c_step(fna, params, op, n)[0])

        def run_cf(k):
            for _ in range(k):
                cf(state0, qa, xd, xd_dot, xd_ddot, params)

        st = _stats(_time_batches(run_cf, repeats, batch_s * 2)[0])
        res["na_step_casadi_function_us"] = st["median"] / 1e3
        res["na_step_casadi_function_us_min"] = st["min"] / 1e3
        res["casadi_version"] = casadi.__version__

    # --- NumPy reference --------------------------------------------------------------
    say("NumPy reference step (pm2dof.reference_control.na_step) and agreement")
    g = _geometry(model)
    ref_step = rc.na_step

    def run_np(k):
        for _ in range(k):
            ref_step(g, state0, qa, xd, xd_dot, xd_ddot, params)

    st = _stats(_time_batches(run_np, repeats, batch_s * 2)[0])
    res["na_step_numpy_us"], res["na_step_numpy_us_min"] = st["median"] / 1e3, st["min"] / 1e3
    notes["na_step_numpy_us"] = (
        "the NumPy reference is written for clarity: it builds Y column by column "
        f"({len(model.param_names)} evaluations of eq. 13's right side), so it is far slower "
        "than straight NumPy; the lambdify row is the plain-NumPy baseline")
    rng = np.random.default_rng(20100101)
    cases = [op] + _random_cases(model, na, rng, n_agree, traj.xd[k_op])
    worst = 0.0
    for case in cases:
        tau_c, s_c, stat_c = _c_step(fna, params, case, n)
        tau_r, s_r, stat_r, _ = ref_step(g, *case, params)
        worst = max(worst, _rel(tau_c, tau_r), _rel(s_c, s_r), float(stat_c != stat_r))
    res["agreement_c_vs_numpy"] = worst
    res["agreement_cases"] = len(cases)

    # --- SymPy lambdify ---------------------------------------------------------------
    say("SymPy: derive the expressions, lambdify fk, unit vectors, S, Y (numpy, cse)")
    res["na_step_lambdify_us"] = res["na_step_lambdify_us_min"] = None
    try:
        lstep, build_s = _lambdify_step(model, lays)
    except ImportError as exc:
        lstep = None
        notes["na_step_lambdify_us"] = f"sympy or the derive package is not importable ({exc})"
    if lstep is not None:
        res["lambdify_build_s"] = build_s
        worst = 0.0
        for case in cases:
            tau_c, s_c, stat_c = _c_step(fna, params, case, n)
            tau_l, s_l, stat_l = lstep(*case, params)
            worst = max(worst, _rel(tau_c, tau_l), _rel(s_c, s_l), float(stat_c != stat_l))
        res["agreement_c_vs_lambdify"] = worst

        def run_lam(k):
            for _ in range(k):
                lstep(state0, qa, xd, xd_dot, xd_ddot, params)

        st = _stats(_time_batches(run_lam, repeats, batch_s * 2)[0])
        res["na_step_lambdify_us"] = st["median"] / 1e3
        res["na_step_lambdify_us_min"] = st["min"] / 1e3

    # --- closed-loop rollout ----------------------------------------------------------
    long, speed_l = _long_trajectory(model, n_roll)
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
    res["rollout_singular_samples"] = int(np.sum(status == 1))
    res["rollout_max_error_m"] = float(np.max(np.hypot(*(long.xd - y[:, 0:2]).T)))
    acc = _stats(_time_batches(run_acc, repeats, 0.0 if quick else 0.05)[0])
    res["rollout_steps_per_s"] = n_roll * 1e9 / acc["median"]
    res["rollout_steps_per_s_best"] = n_roll * 1e9 / acc["min"]
    res["rollout_ns_per_step"] = acc["median"] / n_roll

    def run_sim(k):
        for _ in range(k):
            simulate(model, na, long)

    sim = _stats(_time_batches(run_sim, repeats, 0.0 if quick else 0.05)[0])
    res["rollout_end_to_end_steps_per_s"] = n_roll * 1e9 / sim["median"]
    res["rollout_end_to_end_steps_per_s_best"] = n_roll * 1e9 / sim["min"]
    res["rollout_python_overhead_us_per_step"] = (sim["median"] - acc["median"]) / n_roll / 1e3

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
    res["machine"] = _machine()
    res["elapsed_s"] = time.perf_counter() - t_start
    return res


# --------------------------------------------------------------------------------------
# rendering
# --------------------------------------------------------------------------------------

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
    row("NA step, bare _cbind call from Python", "na_step_binding_us", "us")
    row("NA step, NAController.step(out=buf)", "na_step_python_us", "us")
    row("NA step, NAController.step (allocating)", "na_step_python_alloc_us", "us")
    row("NA step, casadi.Function (casadi.external)", "na_step_casadi_function_us", "us")
    row("NA step, NumPy reference", "na_step_numpy_us", "us")
    row("NA step, SymPy lambdify (numpy, cse)", "na_step_lambdify_us", "us")
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
    lines.append("")
    lines.append("ratios and agreement")
    for label, key, unit in (
            ("C step vs NumPy reference", "speedup_c_vs_numpy", "x"),
            ("C step vs SymPy lambdify", "speedup_c_vs_lambdify", "x"),
            ("NAController.step vs casadi.Function", "speedup_binding_vs_casadi_function", "x"),
            ("bare binding vs casadi.Function", "speedup_raw_binding_vs_casadi_function", "x"),
            (f"C vs NumPy, max rel. diff. ({r.get('agreement_cases')} states)",
             "agreement_c_vs_numpy", "rel"),
            ("C vs lambdify, max rel. diff.", "agreement_c_vs_lambdify", "rel"),
            ("casadi.Function vs binding (tau_a)", "agreement_casadi_function_vs_c", "rel")):
        t = tg.get(key)
        tgt = f"{t['op']} {_fmt(t['target'], t['unit'])}" if t else ""
        res_s = ("n/a" if t["pass"] is None else ("PASS" if t["pass"] else "FAIL")) if t else ""
        lines.append(f"  {label:42s} {_fmt(r.get(key), unit):>12s} {'':12s} {unit:8s} "
                     f"{tgt:>10s}  {res_s}")
    if r.get("na_step_budget_fraction") is not None:
        lines.append(f"  the NA step in C takes {100 * r['na_step_budget_fraction']:.4f} % of "
                     f"the sample period; NAController.step adds "
                     f"{_fmt(r.get('python_overhead_us'))} us of Python")
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
                     f"{m.get('compiler_flags')}")
        lines.append(f"python {m.get('python')}, numpy {m.get('numpy')}"
                     + (f", casadi {r['casadi_version']}" if r.get("casadi_version") else ""))
    if "elapsed_s" in r:
        n_pass = sum(1 for t in tg.values() if t["pass"])
        lines.append(f"targets met: {n_pass}/{len(tg)}; bench took {r['elapsed_s']:.1f} s")
    return "\n".join(lines)
