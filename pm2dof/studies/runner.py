# Running a study on Dask: an embedded LocalCluster, or an existing cluster by its address.
"""``pm2dof study run``: every chunk of a study as a Dask task, rows written as chunks finish.

The client keeps a bounded window of tasks in flight and writes each finished chunk to
Parquet at once (:mod:`pm2dof.studies.store`), so memory does not grow with the number of
rollouts and an interruption loses at most the chunks in flight. Dask reruns the tasks of a
lost worker (``retries`` on top of its own rescheduling). Rows do not depend on the worker
count, the cluster or the order in which chunks finish.
"""
import contextlib
import importlib.util
import logging
import os
import signal
import threading
import time

from ..core.errors import ArgumentError, Pm2dofError
from ..core.model import load_model
from ..infra.progress import Progress
from ..infra.progress import bar as progress_bar
from .evaluate import run_chunk
from .spec import check_study
from .store import finish_out, prepare_out, write_chunk

__all__ = ["StudyRunError", "run_study", "format_notice", "format_run", "connect", "disconnect",
           "dashboard_link", "Progress"]


#: Dask settings of the embedded cluster, throughput over introspection. Each of the worker's
#: periodic callbacks (the statistical profiler every 10 ms, the event-loop tick every 20 ms,
#: the system and memory monitors) takes the GIL from the thread running the study between its
#: C calls; with the defaults a worker ran chunks 5-10 % slower than the client process, with
#: these as fast (`pm2dof study bench`). Malloc trimming slows NumPy's allocations.
QUIET_WORKERS = {
    "distributed.worker.profile.enabled": False,
    "distributed.admin.tick.interval": "1s",
    "distributed.admin.system-monitor.interval": "2s",
    "distributed.worker.memory.monitor-interval": "1s",
    "distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None,
}


class StudyRunError(Pm2dofError, RuntimeError):
    """The study could not run: no scheduler at the address, no workers, a failing chunk."""


@contextlib.contextmanager
def _workers_ignore_sigint():
    """SIGINT ignored while the LocalCluster starts its worker processes, which inherit that
    (an ignored signal stays ignored across exec, and Python then installs no handler): a
    terminal's Ctrl-C, sent to the whole process group, reaches only this process, which
    stops the run and closes the cluster, instead of each worker printing its traceback."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


def connect(workers=None, scheduler=None, timeout=10.0):
    """A ``distributed.Client``: to ``scheduler`` (an address such as ``tcp://10.0.0.5:8786``),
    else to a new ``LocalCluster`` of ``workers`` single-threaded worker processes (default: one
    per core). Raises StudyRunError within ``timeout`` s when the scheduler cannot be reached or
    has no worker. The caller closes the client (and its cluster)."""
    from distributed import Client, LocalCluster
    if scheduler:
        try:
            client = Client(scheduler, timeout=timeout)
        except (OSError, TimeoutError) as exc:
            raise StudyRunError(f"cannot reach the Dask scheduler at {scheduler} within "
                                f"{timeout:g} s ({type(exc).__name__}: {exc}). Is `dask "
                                f"scheduler` running there, and the port open?") from None
        try:
            client.wait_for_workers(1, timeout=timeout)
        except (OSError, TimeoutError):
            client.close()
            raise StudyRunError(f"the Dask scheduler at {scheduler} has no worker after "
                                f"{timeout:g} s; start some with `dask worker {scheduler}`") \
                from None
        return client
    n = (os.cpu_count() or 1) if workers is None else workers
    if n < 1:
        raise ArgumentError(f"--workers must be >= 1, got {n}")
    import dask
    with dask.config.set(QUIET_WORKERS), _workers_ignore_sigint():
        # CRITICAL: a worker's heartbeat that meets the closing scheduler logs a traceback at
        # ERROR level (CommClosedError) on a loaded machine; a task's own failure reaches the
        # client as its exception, and a lost worker is retried, so nothing is hidden
        cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                               dashboard_address=":0", silence_logs=logging.CRITICAL)
    client = Client(cluster, timeout=timeout)
    client._pm2dof_owns_cluster = cluster
    return client


def disconnect(client):
    """Close a client of :func:`connect`, and its embedded cluster if it started one."""
    cluster = getattr(client, "_pm2dof_owns_cluster", None)
    client.close()
    if cluster is not None:
        cluster.close()


def run_study(study, out, *, workers=None, scheduler=None, client=None, timeout=10.0,
              progress=True, notify=None, command_line=None):
    """Run every rollout of ``study`` (a :class:`~pm2dof.studies.spec.Study`) into ``out``.

    Parameters
    ----------
    study : Study
        The study (:func:`~pm2dof.studies.spec.read_study`).
    out : path
        Output folder (created); a rerun with the same study skips its finished chunks.
    workers : int, optional
        Worker processes of the embedded LocalCluster (default: one per core).
    scheduler : str, optional
        Address of an existing Dask scheduler; its workers need pm2dof installed with the same
        generated code, and the model file at the same path.
    client : distributed.Client, optional
        Use this client (not closed here) instead of ``workers`` / ``scheduler``.
    timeout : float
        Seconds to wait for the scheduler and its first worker (StudyRunError after that).
    progress : bool or pm2dof.infra.progress.Progress
        True: a bar on stderr when it is a terminal (rollouts done, the rate since the first
        task, ETA), nothing otherwise; a Progress: its bar; False: none.
    notify : callable(dict), optional
        Told what runs, as it starts (:func:`format_notice` words it): once the folder is
        ready, ``{"study", "rollouts", "chunks", "skipped", "out"}`` (``skipped``: chunks
        already there); then, once the cluster is up, ``{"where", "dashboard"}``
        (``dashboard``: its link, or None).
    command_line : list of str, optional
        The command ``out/study.json``'s provenance records (None: ``sys.argv``).

    Returns
    -------
    dict
        ``rows`` (in the folder), ``chunks``, ``skipped`` (already there), and the times of
        this session, whose rollouts are the ``rows`` minus those already there:

        * ``seconds``: wall time from starting (or connecting to) the cluster to stopping it
          (or disconnecting), s; ``rollouts_per_s``: rollouts over ``seconds``;
        * ``run_seconds``: from submitting the first task to writing the last chunk, s;
          ``run_rollouts_per_s``: rollouts over ``run_seconds``, the progress line's rate;
        * ``cluster_seconds``: ``seconds - run_seconds``, mostly starting and stopping the
          embedded cluster (about a second), s.
    """
    from distributed import as_completed
    if client is None and not scheduler and workers is not None and workers < 1:
        raise ArgumentError(f"--workers must be >= 1, got {workers}")
    model = load_model(study.model_path, study.generated_path)
    check_study(study, model)
    done = prepare_out(out, study, model, command_line)
    todo = [i for i in range(study.n_chunks) if i not in done]
    rows_done = sum(len(study.chunk_units(i)) for i in done) * study.runs
    notify = notify or (lambda notice: None)
    notify({"study": study.name, "rollouts": study.n_rollouts, "chunks": study.n_chunks,
            "skipped": len(done), "out": out})
    t0 = time.perf_counter()
    if not todo:
        return {"rows": finish_out(out, study), "chunks": study.n_chunks, "skipped": len(done),
                "seconds": 0.0, "rollouts_per_s": 0.0, "run_seconds": 0.0,
                "run_rollouts_per_s": 0.0, "cluster_seconds": 0.0}
    own = client is None
    if own:
        client = connect(workers, scheduler, timeout)
    t_run = time.perf_counter()                  # the cluster is up: the rollouts start now
    reporter = Progress() if progress is True else progress
    bar = progress_bar(reporter, study.n_rollouts, f"study {study.name}", unit="rollout",
                       initial=rows_done, smoothing=0)      # the mean rate since the first task
    try:
        nthreads = sum(client.nthreads().values()) or 1
        where = scheduler or f"a local cluster of {nthreads} worker process(es)"
        notify({"where": where,
                "dashboard": dashboard_link(client)})
        pending = iter(todo)
        ac, index = as_completed(), {}

        def submit():
            i = next(pending, None)
            if i is not None:
                fut = client.submit(run_chunk, study, i, pure=False, retries=2,
                                    key=f"pm2dof-{study.identity[:12]}-chunk-{i}")
                index[fut.key] = i
                ac.add(fut)

        for _ in range(2 * nthreads + 2):
            submit()
        for fut in ac:
            i = index.pop(fut.key)
            try:
                cols = fut.result()
            except Exception as exc:
                raise StudyRunError(f"chunk {i} (rollouts {study.chunk_units(i)[0] * study.runs}"
                                    f"..) failed: {type(exc).__name__}: {exc}") from exc
            write_chunk(out, i, cols, study)
            fut.release()
            bar.update(len(cols["rollout"]))
            submit()
        run_dt = time.perf_counter() - t_run
    finally:
        bar.close()
        if own:
            disconnect(client)
    dt = time.perf_counter() - t0
    n = study.n_rollouts - rows_done
    return {"rows": finish_out(out, study), "chunks": study.n_chunks, "skipped": len(done),
            "seconds": dt, "rollouts_per_s": n / dt, "run_seconds": run_dt,
            "run_rollouts_per_s": n / run_dt, "cluster_seconds": dt - run_dt}


def format_notice(notice):
    """A line of what :func:`run_study` says it runs (its ``notify``'s argument)."""
    if "where" in notice:
        return f"running on {notice['where']}" + (f"; dashboard {notice['dashboard']}"
                                                   if notice["dashboard"] else "")
    return (f"study {notice['study']!r}: {notice['rollouts']} rollouts in {notice['chunks']} "
            f"chunks" + (f"; {notice['skipped']} chunk(s) already in {notice['out']}, skipped"
                         if notice["skipped"] else ""))


def format_run(res, out):
    """What ``pm2dof study run`` prints of :func:`run_study`'s result ``res`` into ``out``."""
    if res["skipped"] == res["chunks"]:
        return (f"{res['rows']} rows in {out}/results: all {res['chunks']} chunks were already "
                f"there, nothing to run. Next: pm2dof study report {out}")
    return (f"{res['rows']} rows in {out}/results ({res['skipped']} of {res['chunks']} chunks "
            f"were already there). Wall time {res['seconds']:.1f} s, "
            f"{res['rollouts_per_s']:,.0f} rollouts/s, including {res['cluster_seconds']:.1f} s "
            f"to set up and close the cluster; running the rollouts {res['run_seconds']:.1f} s, "
            f"{res['run_rollouts_per_s']:,.0f} rollouts/s (the rate the progress bar shows on a "
            f"terminal). Next: pm2dof study report {out}")


def dashboard_link(client):
    """The link of the cluster's dashboard, or None when it has none (no bokeh installed)."""
    try:
        if client.dashboard_link and importlib.util.find_spec("bokeh") is not None:
            return client.dashboard_link
    except (KeyError, AttributeError):
        pass
    return None
