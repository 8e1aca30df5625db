# Design studies' speed: designs per second per objective class, kinematic objectives against the
# generated-C calls they make, and Dask's overhead on one worker (pm2dof bench).
"""The speed of a design study (:mod:`pm2dof.synthesis`) on the two shipped models with a
``[design]`` table, the paper's robot (``shang2010_design``, la and lb tied across its legs) and
the 4-RRR platform (``rrr4_platform_design``, la and lb), each with its shipped study's
variables and bounds (``paper_legs``, ``rrr4_platform_legs``):

* **Designs per second per objective class**, every design a fresh ``Model.at_design`` and its
  objectives (``objectives.evaluate_batch`` in this process, random designs in the middle half
  of the bounds, the same ones in every round): *kinematic* (clear_area, dexterity_min,
  dexterity_mean and margin over a 50 x 50 region grid, a platform at its home orientation),
  *capability* (force and accel, min-max split, the same region), *planning* (the high-speed
  move's time-optimal duration, min-max split, 1,000 grid points) and *closed loop* (NA's RMSE
  on the high-speed move against the model file's plant). Each beside structdimsynth's
  published cost, 0.5 s per design for kinematic objectives and 1.8 s with dynamics (the other
  three classes), as the speed-up ``structdimsynth seconds * designs per second``.
* **Kinematic objectives against their generated-C calls**: per design, ``at_design`` and the
  kinematic class's four objectives against the same ``Function.map`` calls alone (``ik`` over
  the grid, ``singularity_measures`` over its reachable points, on a model already at the
  design, into arrays already allocated), in interleaved rounds; the ratio paired per round,
  its median; the worst model's is the target's value (<= 1.5).
* **Dask's overhead on one worker**: a batch of designs (the shipped ``paper_legs`` study with
  the ``grid`` optimiser, :data:`DASK_GRID` points a side) through
  :func:`pm2dof.synthesis.runner.run_design` on an embedded ``LocalCluster`` of one worker
  process (started once, before the rounds; each round a fresh output folder). The overhead is
  the run's wall time over the time its worker spent evaluating the designs
  (:func:`timed_evaluate_batch`, summed over the run's tasks), minus 1: everything Dask and the
  run add (scheduling, transfer, the Parquet chunks, the run's folder), measured in the same
  run, so the machine's speed from one moment to the next cancels (target <= 10 %). Beside it,
  the run against ``evaluate_batch`` of the same designs in this process, in interleaved rounds
  whose order alternates (the paired ratio's median): whether the worker evaluates as fast as
  this process. On this shared 2-core machine one pair varies by +-20 %, so that ratio is
  reported, not a target.
"""
import dataclasses
import tempfile
import time

import numpy as np

from .timing import stats

__all__ = ["SYNTH_MODELS", "OBJECTIVE_CLASSES", "STRUCTDIMSYNTH_S", "synthesis_bench",
           "class_study"]

#: the models timed, with the shipped study whose variables and bounds they use
SYNTH_MODELS = {"shang2010_design": "paper_legs", "rrr4_platform_design": "rrr4_platform_legs"}
#: structdimsynth's published seconds per design: kinematic objectives, and with dynamics
STRUCTDIMSYNTH_S = {"kinematic": 0.5, "dynamic": 1.8}
#: objective class -> ((name, measure, sense, options), ...)
OBJECTIVE_CLASSES = {
    "kinematic": (("clear_area", "clear_area", "max", {}),
                  ("dexterity_min", "dexterity_min", "max", {}),
                  ("dexterity_mean", "dexterity_mean", "max", {}),
                  ("margin", "margin", "max", {})),
    "capability": (("force", "force", "max", {"split": "min_max"}),
                   ("accel", "accel", "max", {"split": "min_max"})),
    "planning": (("duration", "duration", "min", {"path": "high", "split": "min_max"}),),
    "closed_loop": (("rmse", "rmse", "min", {"law": "na", "path": "high"}),),
}
#: the regions (50 x 50 points in a full run): the shipped studies' boxes, a platform at home
_REGION_N = 50
#: the Dask batch of a full run: a DASK_GRID x DASK_GRID grid of paper_legs designs (256, a
#: fifth of the shipped study's 40 x 30; about 2 s on one worker)
DASK_GRID = 16


def class_study(model_name, objective_class, n=_REGION_N):
    """The shipped study of ``model_name`` (:data:`SYNTH_MODELS`) with the objectives of
    ``objective_class`` (:data:`OBJECTIVE_CLASSES`), no constraint, its region's box at ``n``
    x ``n`` points (a platform at its home orientation).

    Returns
    -------
    pm2dof.synthesis.spec.DesignStudy
    """
    from ..synthesis.spec import FrozenMapping, Objective, find_design_study, read_design_study
    st = read_design_study(find_design_study(SYNTH_MODELS[model_name]))
    region = FrozenMapping({"x": tuple(st.region["x"]), "y": tuple(st.region["y"]), "n": int(n),
                            "phi": None, "n_phi": 1})
    objs = tuple(Objective(name, measure, sense, FrozenMapping(opts))
                 for name, measure, sense, opts in OBJECTIVE_CLASSES[objective_class])
    return dataclasses.replace(st, region=region, objectives=objs, constraints=())


def _designs(study, count, seed=38):
    """``count`` random designs in the middle half of the study's bounds, (count, k)."""
    b = np.asarray(study.bounds, dtype=float)
    lo, span = b[:, 0] + 0.25 * (b[:, 1] - b[:, 0]), 0.5 * (b[:, 1] - b[:, 0])
    return lo + span * np.random.default_rng(seed).random((count, len(b)))


def _rates(models, repeats, quick, say):
    """Designs per second of each (model, class), evaluate_batch on the same designs each
    round; and the share of designs whose every measure was computed ("ok")."""
    from ..synthesis.objectives import evaluate_batch
    count = {"kinematic": 20, "capability": 10, "planning": 4, "closed_loop": 4}
    jobs = {}
    for name in models:
        for cls in OBJECTIVE_CLASSES:
            st = class_study(name, cls, 8 if quick else _REGION_N)
            X = _designs(st, 2 if quick else count[cls])
            _, _, rows = evaluate_batch(st, X)                     # warm: the model, caches
            jobs[name, cls] = (st, X, sum(r["status"] == "ok" for r in rows) / len(rows))
    say(f"synthesis: designs per second, {len(jobs)} (model, objective class) batches x "
        f"{repeats} rounds")
    per = {k: [] for k in jobs}
    for _ in range(repeats):
        for key, (st, X, _) in jobs.items():
            t0 = time.perf_counter()
            evaluate_batch(st, X)
            per[key].append(len(X) / (time.perf_counter() - t0))
    out = {}
    for (name, cls), rates in per.items():
        rate = stats(rates)["median"]
        ref = STRUCTDIMSYNTH_S["kinematic" if cls == "kinematic" else "dynamic"]
        out.setdefault(name, {})[cls] = {
            "designs_per_s": rate, "designs": len(jobs[name, cls][1]),
            "ok_fraction": jobs[name, cls][2], "structdimsynth_s": ref,
            "speedup_vs_structdimsynth": ref * rate}
    return out


def _kinematic_over_c(name, repeats, quick):
    """Per round: at_design and the kinematic objectives of each design, then the same
    ``Function.map`` calls alone; (median paired ratio, median s per design of each)."""
    from ..core.model import load_model
    from ..synthesis.objectives import evaluate_with_status
    from ..synthesis.region import grid_points
    st = class_study(name, "kinematic", 8 if quick else _REGION_N)
    base = load_model(st.model_path)
    X = _designs(st, 2 if quick else 10, seed=5)
    designs = [dict(zip(st.variables, map(float, x))) for x in X]
    calls = []
    for d in designs:                 # each design's calls, on a model already at it
        m = base.at_design(d)
        pts, _, _ = grid_points(st.region, m)
        ik, sm = m.function("ik"), m.function("singularity_measures")
        q = np.empty((len(pts), 2 * m.n_legs))
        ik.map(len(pts), pts, q)
        qr = np.ascontiguousarray(q[np.isfinite(q).all(axis=1)])
        calls.append((ik, sm, pts, q, qr, np.empty((len(qr), 2))))

    def objectives():
        for d in designs:
            evaluate_with_status(base.at_design(d), st)

    def c_calls():
        for ik, sm, pts, q, qr, s in calls:
            ik.map(len(pts), pts, q)
            sm.map(len(qr), qr, s)

    objectives()
    c_calls()
    t_obj, t_c = [], []
    for _ in range(max(repeats, 3)):
        for run, into in ((objectives, t_obj), (c_calls, t_c)):
            t0 = time.perf_counter()
            run()
            into.append((time.perf_counter() - t0) / len(designs))
    ratio = stats([a / b for a, b in zip(t_obj, t_c)])["median"]
    return ratio, stats(t_obj)["median"], stats(t_c)["median"], len(pts)


_EVAL_S = []


def timed_evaluate_batch(study, X):
    """``objectives.evaluate_batch``, its wall time kept in this process (a worker's) for
    :func:`take_eval_s`: the ``evaluate`` a measurement passes to ``run_design``."""
    from ..synthesis.objectives import evaluate_batch
    t0 = time.perf_counter()
    out = evaluate_batch(study, X)
    _EVAL_S.append(time.perf_counter() - t0)
    return out


def take_eval_s(dask_worker=None):
    """The seconds :func:`timed_evaluate_batch` spent in this process since the last call
    (``client.run`` calls it on each worker)."""
    total = sum(_EVAL_S)
    _EVAL_S.clear()
    return total


def _dask_overhead(repeats, quick, say, grid=None, timeout=60.0):
    """The same designs (a ``grid`` x ``grid`` grid; default 3 quick, else :data:`DASK_GRID`)
    through run_design on one worker, and through evaluate_batch in this process, in
    interleaved rounds (each pair's order alternating).

    Returns (median over rounds of the run's wall time / the worker's time evaluating designs,
    median paired ratio of the run's wall time / this process's, median s of the run, of the
    worker's evaluation and of this process's, designs)."""
    from ..studies.runner import connect, disconnect
    from ..synthesis.objectives import evaluate_batch
    from ..synthesis.optimize import grid_designs
    from ..synthesis.runner import run_design
    from ..synthesis.spec import find_design_study, read_design_study, with_overrides
    from ..synthesis.store import read_designs
    grid = grid or (3 if quick else DASK_GRID)
    rounds = max(repeats, 3)
    st = read_design_study(find_design_study("paper_legs"))
    if quick:
        st = with_overrides(st, quick=True)
    st = with_overrides(st, optimizer="grid", grid=grid)
    X = grid_designs(st.bounds, grid)
    say(f"synthesis: Dask overhead, {len(X)} designs of {st.name} on a LocalCluster of 1 "
        f"worker, against its time evaluating them and against this process, {rounds} "
        f"interleaved rounds")
    client = connect(1, None, timeout)
    t_dask, t_worker, t_here = [], [], []
    try:
        with tempfile.TemporaryDirectory(prefix="pm2dof-bench-design-") as tmp:
            def on_dask(r):
                client.run(take_eval_s)
                t0 = time.perf_counter()
                res = run_design(st, f"{tmp}/r{r}", client=client, progress=False,
                                 command_line=["pm2dof", "bench"], file_design=False,
                                 evaluate=timed_evaluate_batch)
                td = time.perf_counter() - t0
                if res["evaluated"] != len(X):
                    raise RuntimeError(f"run_design evaluated {res['evaluated']} of {len(X)}")
                return td, sum(client.run(take_eval_s).values())

            def here():
                t0 = time.perf_counter()
                F, _, _ = evaluate_batch(st, X)
                return time.perf_counter() - t0, F

            for r in range(rounds + 1):                     # round 0 warms both (not kept)
                if r % 2:
                    td, tw = on_dask(r)
                    th, F = here()
                else:
                    th, F = here()
                    td, tw = on_dask(r)
                if r:
                    t_dask.append(td)
                    t_worker.append(tw)
                    t_here.append(th)
            _, cols = read_designs(f"{tmp}/r{r}")       # the same designs, the same values
            got = np.column_stack([cols[v] for v in st.variables])
            sign = [-1.0 if o.sense == "max" else 1.0 for o in st.objectives]
            Fd = np.column_stack([s * cols[o.name] for s, o in zip(sign, st.objectives)])
            if not (np.array_equal(got, X) and np.array_equal(Fd, F)):
                raise RuntimeError("the designs evaluated on Dask differ from this process's")
    finally:
        disconnect(client)
    over_worker = stats([a / b for a, b in zip(t_dask, t_worker)])["median"]
    over_here = stats([a / b for a, b in zip(t_dask, t_here)])["median"]
    return (over_worker, over_here, stats(t_dask)["median"], stats(t_worker)["median"],
            stats(t_here)["median"], len(X))


def synthesis_bench(repeats, quick=False, say=None, models=tuple(SYNTH_MODELS), dask=True,
                    dask_grid=None):
    """The measurements of the module docstring, ``repeats`` rounds each (``quick``: 8 x 8
    regions, 2 designs per batch, a 3 x 3 grid through Dask; numbers that are noise).
    ``dask_grid``: the Dask batch's grid points per variable (default :data:`DASK_GRID`, 3
    quick).

    Returns a JSON-able dict: ``synthesis_rows`` {model: {class: {designs_per_s, designs,
    ok_fraction, structdimsynth_s, speedup_vs_structdimsynth}, "kinematic_over_c": ratio,
    "kinematic_objectives_ms", "kinematic_c_ms" (per design), "region_points"}};
    ``synthesis_kinematic_over_c_max`` (the worst model's ratio, a target);
    ``synthesis_speedup_vs_structdimsynth_kinematic_min`` and ``..._dynamic_min`` (the least
    speed-up over the models, and over the dynamic classes); ``synthesis_dask_over_worker``
    (the run's wall time / its worker's evaluation, the median over rounds, a target) and
    ``synthesis_dask_overhead`` (it minus 1), ``synthesis_dask_over_inprocess`` (the median
    paired ratio to this process), ``synthesis_dask_s``, ``synthesis_worker_s``,
    ``synthesis_inprocess_s`` (s per batch), ``synthesis_dask_designs`` (None without
    ``dask``); ``synthesis_elapsed_s``."""
    say = say or (lambda msg: None)
    t_start = time.perf_counter()
    rows = _rates(models, repeats, quick, say)
    say("synthesis: kinematic objectives against their generated-C calls, interleaved")
    for name in models:
        ratio, t_obj, t_c, pts = _kinematic_over_c(name, repeats, quick)
        rows[name].update({"kinematic_over_c": ratio, "kinematic_objectives_ms": t_obj * 1e3,
                           "kinematic_c_ms": t_c * 1e3, "region_points": pts})
    res = {"synthesis_rows": rows,
           "synthesis_kinematic_over_c_max": max(r["kinematic_over_c"] for r in rows.values()),
           "synthesis_speedup_vs_structdimsynth_kinematic_min": min(
               r["kinematic"]["speedup_vs_structdimsynth"] for r in rows.values()),
           "synthesis_speedup_vs_structdimsynth_dynamic_min": min(
               r[c]["speedup_vs_structdimsynth"] for r in rows.values()
               for c in OBJECTIVE_CLASSES if c != "kinematic")}
    keys = ("synthesis_dask_over_worker", "synthesis_dask_overhead",
            "synthesis_dask_over_inprocess", "synthesis_dask_s", "synthesis_worker_s",
            "synthesis_inprocess_s", "synthesis_dask_designs")
    if dask:
        over_worker, over_here, td, tw, th, n = _dask_overhead(repeats, quick, say, dask_grid)
        res.update(zip(keys, (over_worker, over_worker - 1.0, over_here, td, tw, th, n)))
    else:
        res.update(dict.fromkeys(keys))
    res["synthesis_elapsed_s"] = time.perf_counter() - t_start
    return res
