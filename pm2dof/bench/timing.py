# The timing harness: calibrated batches of calls with gc off; medians, minima, relative differences.
import gc
import statistics
import time

import numpy as np

__all__ = ["stats", "time_batches", "time_interleaved", "rel_diff", "warm_then_time"]


def stats(per_call):
    """{"median", "min", "samples"} of per-call times (one per batch)."""
    return {"median": float(statistics.median(per_call)), "min": float(min(per_call)),
            "samples": [float(x) for x in per_call]}


def time_batches(run, repeats, batch_s):
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


def warm_then_time(run):
    """(result, seconds) of ``run()`` timed right after an untimed ``run()``: the timed call
    never pays for what ran before it (a plan right after toppra's ~40 ms of Python paid
    0.8-1 ms of refilled caches, 2.8 -> 3.7 ms on the paper's line)."""
    run()
    t0 = time.perf_counter()
    out = run()
    return out, time.perf_counter() - t0


def rel_diff(a, b):
    """||a - b||_inf / ||b||_inf (0 if both are zero)."""
    a, b = np.ravel(np.asarray(a, dtype=float)), np.ravel(np.asarray(b, dtype=float))
    d = float(np.max(np.abs(a - b)))
    s = float(np.max(np.abs(b)))
    return d / s if s > 0 else d


def time_interleaved(runs, repeats, batch_s):
    """Per-call ns of each ``runs[name](n)`` in ``repeats`` rounds, the runs' batches
    interleaved in every round (the same machine state for each: ratios of one round are
    paired). Each batch size is calibrated once to about ``batch_s`` seconds; gc is off.
    Returns {name: [ns per call, one per round]}."""
    sizes = {k: time_batches(run, 1, batch_s)[1] for k, run in runs.items()}
    out = {k: [] for k in runs}
    enabled = gc.isenabled()
    gc.disable()
    try:
        for _ in range(repeats):
            for k, run in runs.items():
                t0 = time.perf_counter_ns()
                run(sizes[k])
                out[k].append((time.perf_counter_ns() - t0) / sizes[k])
    finally:
        if enabled:
            gc.enable()
    return out
