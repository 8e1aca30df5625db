# pm2dof study bench: rollouts per second on the high-speed move, every path measured in one run.
"""Throughput of the study machinery (``pm2dof study bench``).

One study of NA on the paper's high-speed move over random plants (:func:`bench_uncertainty`:
the gains study's uncertainty, with the robustness study's encoder resolutions) is run four
ways, in one process run so the ratios are fair on a noisy machine; each rate is the median of
``repeats`` passes:

* ``plain_loop``: :func:`pm2dof.simulate` in a Python loop (the plants drawn beforehand);
* ``batch``: :func:`pm2dof.studies.run_chunk` chunk after chunk in this process;
* ``dask_1_worker`` / ``dask_2_workers``: the same chunks as tasks on a LocalCluster of one or
  two single-threaded worker processes, started and warmed up before the clock, each pass
  interleaved with a batch pass; the ratios are medians of the ratios of interleaved passes;
* ``study_run_2_workers``: :func:`pm2dof.studies.run_study` end to end (Parquet writes,
  progress, resume bookkeeping; the cluster already up), at 1/10 and all of the rollouts, with
  the client's peak traced memory, which stays flat in the number of rollouts.
"""
import dataclasses
import os
import statistics
import tempfile
import time
import tracemalloc

from ..control.simulate import simulate
from . import resolve_study
from .evaluate import rollout_setup, run_chunk
from .runner import connect, disconnect, run_study
from .spec import UNCERTAINTY, read_study

__all__ = ["study_bench", "format_study_bench", "bench_study", "bench_uncertainty"]

def bench_study(rollouts, chunk=1000):
    """The benchmark's study: NA on the paper's high-speed move over ``rollouts`` random
    plants, drawn from :func:`bench_uncertainty`."""
    s = read_study(resolve_study("robustness"))
    na = [v for v in s.variants if v.name == "na"]
    return dataclasses.replace(s, name="bench", variants=tuple(na),
                               moves=tuple(m for m in s.moves if m[0] == "high"),
                               draws=rollouts, runs=1, chunk=chunk,
                               uncertainty=bench_uncertainty())


def bench_uncertainty():
    """The plants of the benchmark: the gains study's uncertainty (payload 0-0.6 kg, friction
    x0.85-1.15, Stribeck x0.5-1.5, inertias normal with sd 5 %) and the robustness study's
    encoder resolutions, as (key, Distribution) in the order of
    :data:`pm2dof.studies.spec.UNCERTAINTY`.

    A rollout's work does not depend on its plant's values, only on which quantities are drawn
    (an encoder resolution quantises the measurement), so any plants the paper's robot can
    simulate measure the same throughput. The robustness study's own uncertainty is wider:
    drawn 10,000 times (five times that study's draws), its draw 6116 (Coulomb x1.25,
    Stribeck x1.99, alpha_1 -24.6 %) has a friction at rest too stiff for the robot's three
    RK4 substeps: h lambda = 2.5001, above the accepted 2.5
    (:data:`pm2dof.control.plant_step.RK4_STABLE_Z`), and the study is refused before any
    rollout. The stiffest of these 10,000 plants has h lambda = 1.86."""
    gains = dict(read_study(resolve_study("gains")).uncertainty)
    robust = dict(read_study(resolve_study("robustness")).uncertainty)
    chosen = {**gains, "encoder_counts_per_rev": robust["encoder_counts_per_rev"]}
    return tuple((k, chosen[k]) for k in UNCERTAINTY if k in chosen)


def _dask_pass(client, study):
    from distributed import as_completed
    t0 = time.perf_counter()
    n = 0
    for fut in as_completed(client.map(run_chunk, [study] * study.n_chunks,
                                       range(study.n_chunks), pure=False)):
        n += len(fut.result()["rollout"])
        fut.release()
    return n / (time.perf_counter() - t0)


def _batch_pass(study):
    t0 = time.perf_counter()
    for i in range(study.n_chunks):
        run_chunk(study, i)
    return study.n_rollouts / (time.perf_counter() - t0)


def _median(f, repeats):
    return statistics.median([f() for _ in range(repeats)])


def study_bench(quick=False, progress=None):
    """Rollouts per second of each path (module docstring); JSON-able dict."""
    say = progress or (lambda msg: None)
    n = 1000 if quick else 10000
    repeats = 1 if quick else 3
    study = bench_study(n, chunk=n // 10)   # 10 tasks: 5 per worker with two
    res = {"rollouts": n, "chunk": study.chunk, "move": "high", "controller": "na",
           "cores": os.cpu_count(), "repeats": repeats}
    # plain loop: today's simulate(), one call per rollout
    n_plain = n // 10
    setups = [rollout_setup(study, 0, 0, d, 0) for d in range(n_plain)]
    say(f"plain loop: simulate() x {n_plain}, {repeats} time(s)")

    def plain():
        t0 = time.perf_counter()
        for model, ctrl, traj, truth, counts, _th0, _ in setups:
            simulate(model, ctrl, traj, truth=truth, encoder_counts_per_rev=counts)
        return n_plain / (time.perf_counter() - t0)
    res["rollouts_per_s_plain_loop"] = _median(plain, repeats)
    say(f"batch: run_chunk x {study.n_chunks} chunks of {study.chunk}")
    run_chunk(study, 0)
    batch, ratio = [], {}
    for k, key in ((1, "rollouts_per_s_dask_1_worker"), (2, "rollouts_per_s_dask_2_workers")):
        say(f"Dask: LocalCluster of {k} worker process(es), interleaved with the batch "
            f"{repeats} time(s)")
        client = connect(workers=k)
        try:
            client.gather(client.map(run_chunk, [study] * k, range(k), pure=False))  # warm
            rates, ratio[k] = [], []
            for _ in range(repeats):       # interleaved: drift of a shared machine cancels
                b = _batch_pass(study)
                d = _dask_pass(client, study)
                batch.append(b)
                rates.append(d)
                ratio[k].append(d / b)
            res[key] = statistics.median(rates)
            if k == 2:
                for size in (n // 10, n):
                    say(f"run_study end to end, {size} rollouts, 2 workers")
                    s = bench_study(size, chunk=max(1, size // 10))
                    with tempfile.TemporaryDirectory() as tmp:
                        tracemalloc.start()
                        r = run_study(s, tmp, client=client, progress=False)
                        peak = tracemalloc.get_traced_memory()[1]
                        tracemalloc.stop()
                    res[f"rollouts_per_s_study_run_2_workers_{size}"] = r["rollouts_per_s"]
                    res[f"client_peak_traced_mb_{size}"] = peak / 2 ** 20
        finally:
            disconnect(client)
    res["rollouts_per_s_batch"] = statistics.median(batch)
    # ratios: medians of the ratios of interleaved passes
    r1, r2 = statistics.median(ratio[1]), statistics.median(ratio[2])
    res["dask_2_over_1_workers"] = r2 / r1
    res["dask_1_worker_overhead_vs_batch"] = 1 - r1
    res["batch_over_plain_loop"] = res["rollouts_per_s_batch"] / res["rollouts_per_s_plain_loop"]
    res["targets"] = {
        "batch >= 4000 rollouts/s": res["rollouts_per_s_batch"] >= 4000,
        "2 workers >= 1.7x 1 worker": res["dask_2_over_1_workers"] >= 1.7,
        "Dask overhead <= 10 % (1 worker vs batch)": res["dask_1_worker_overhead_vs_batch"] <= 0.10,
    }
    return res


def format_study_bench(r):
    m = (r["rollouts"] // 10, r["rollouts"])
    lines = [f"Study throughput: NA on the high-speed move over random plants, {r['rollouts']} "
             f"rollouts in chunks of {r['chunk']}, {r['cores']} cores; medians of {r['repeats']} "
             f"passes, all in one run (on a shared machine the ratios are what counts)",
             f"  simulate() in a Python loop       {r['rollouts_per_s_plain_loop']:9,.0f} rollouts/s",
             f"  batch, one process (run_chunk)    {r['rollouts_per_s_batch']:9,.0f} rollouts/s "
             f"({r['batch_over_plain_loop']:.2f}x the loop)",
             f"  Dask, 1 worker process            {r['rollouts_per_s_dask_1_worker']:9,.0f} rollouts/s "
             f"(overhead {100 * r['dask_1_worker_overhead_vs_batch']:+.1f} % vs the interleaved batch passes)",
             f"  Dask, 2 worker processes          {r['rollouts_per_s_dask_2_workers']:9,.0f} rollouts/s "
             f"({r['dask_2_over_1_workers']:.2f}x 1 worker)"]
    for size in m:
        lines.append(f"  run_study, 2 workers, {size:6d} rows {r[f'rollouts_per_s_study_run_2_workers_{size}']:7,.0f} "
                     f"rollouts/s, client peak {r[f'client_peak_traced_mb_{size}']:.1f} MB traced")
    lines.append("targets: " + "; ".join(f"{k}: {'met' if v else 'NOT MET'}"
                                         for k, v in r["targets"].items()))
    return "\n".join(lines)
