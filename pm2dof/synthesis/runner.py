# Running a design study: the optimiser in this process, each generation's designs on Dask.
"""``pm2dof design run``: the optimiser asks for a batch of designs per generation; the batch
is split into chunks, each chunk evaluated as a Dask task (``objectives.evaluate_batch`` on a
worker), the results gathered in order and handed back to the optimiser.

The Dask side is the studies' (:mod:`pm2dof.studies.runner`): an embedded LocalCluster of
single-threaded worker processes with the quiet settings (:func:`~pm2dof.studies.runner.connect`),
or an existing cluster by ``scheduler``; a bounded window of tasks in flight; ``retries`` on top
of Dask's own rescheduling, so a lost worker changes nothing. Each finished chunk is written to
Parquet at once (:mod:`.store`), keyed by its generation, its index and the hash of its designs;
a rerun with the same ``out`` asks for the same designs (same seed) and reads those chunks
back instead of evaluating them, so an interrupted run resumes and a finished one costs no
evaluation (and starts no cluster).

**The model file's own design.** Beside the optimiser's designs, every run evaluates the
design the model file gives (its ``[[legs]]`` values of the searched variables,
:func:`model_file_design`) once, as one more task of the first batch that needs a cluster,
and stores it flagged (``DIR/batches/file-design-*.parquet``, :mod:`.store`). The optimiser does not see
it: the search, its seed and its designs are those of a run without it. ``design show`` says
where it stands against the front (:meth:`.front.DesignFront.file_design`).
"""
import math
import time

import numpy as np

from ..core.errors import Pm2dofError
from ..infra.progress import Progress
from ..infra.progress import bar as progress_bar
from ..studies.runner import connect, dashboard_link, disconnect
from .objectives import base_model
from .optimize import optimize
from .store import (
    chunk_hash,
    file_design_path,
    find_chunk,
    finish_out,
    identity,
    prepare_out,
    read_chunk,
    write_chunk,
)

__all__ = ["DesignRunError", "run_design", "evaluate_chunk", "chunk_size", "MIN_CHUNK",
           "MAX_CHUNKS", "expected_designs", "model_file_design", "format_notice", "format_run"]

#: designs per chunk (a Dask task) at least, and chunks per generation's batch at most: a
#: population of 40 is 3 tasks (16, 16, 8 designs); a 100 x 100 grid, 64 tasks of 157. A
#: design costs 5-25 ms, a Dask task a few ms of scheduling and transfer: 16 designs keep that
#: to a few per cent (4 designs per task cost about 30 % on one worker, pm2dof bench)
MIN_CHUNK = 16
MAX_CHUNKS = 64


class DesignRunError(Pm2dofError, RuntimeError):
    """A design run could not finish: a chunk's evaluation failed (after Dask's retries)."""


def chunk_size(n, min_chunk=MIN_CHUNK):
    """Designs per chunk for a batch of ``n``: at least ``min_chunk``, at most
    :data:`MAX_CHUNKS` chunks (a function of ``n`` only, so a rerun splits alike)."""
    return max(int(min_chunk), math.ceil(n / MAX_CHUNKS))


def expected_designs(study):
    """How many designs the study's optimiser asks for: N^k for a grid, else population x
    generations (NSGA-II and GA may ask for fewer, when offspring repeat designs)."""
    opt = study.optimizer
    if opt["kind"] == "grid":
        return int(opt["grid"]) ** len(study.variables)
    return int(opt["population"]) * int(opt["generations"])


def model_file_design(model, study):
    """The model file's own design in ``study.variables`` order: (1, k), m.

    Parameters
    ----------
    model : Model
        The study's model as loaded from its file (at the file's design).
    study : DesignStudy
    """
    values = dict(zip(model.design_names, map(float, model.design)))
    return np.array([[values[v] for v in study.variables]], dtype=float)


def evaluate_chunk(study, X, evaluate):
    """One Dask task: ``evaluate(study, X) -> (F, G, rows)``, checked and made plain.

    Parameters
    ----------
    study : DesignStudy
        The study.
    X : ndarray, (n, k)
        The chunk's designs, in ``study.variables`` order.
    evaluate : callable
        ``pm2dof.synthesis.objectives.evaluate_batch`` (or a stand-in with its contract).

    Returns
    -------
    (ndarray (n, n_obj), ndarray (n, n_con), list of dict)
    """
    F, G, rows = evaluate(study, X)
    n = len(X)
    F = np.asarray(F, dtype=float).reshape(n, len(study.objectives))
    G = np.asarray(G, dtype=float).reshape(n, len(study.constraints))
    return F, G, [dict(r) for r in rows]


def _default_evaluate():
    from .objectives import evaluate_batch
    return evaluate_batch


class _Batches:
    """The optimiser's ``evaluate(X)``: one generation's batch, chunk by chunk, read back from
    ``out`` or evaluated on Dask, in order."""

    def __init__(self, study, out, ident, have, evaluate, min_chunk, bar, connecter,
                 file_x=None):
        self.study, self.out, self.ident, self.have = study, out, ident, have
        self.evaluate, self.min_chunk, self.bar, self.connecter = (evaluate, min_chunk, bar,
                                                                   connecter)
        self.generation = self.evaluated = self.reused = 0
        self.file_x = file_x          # the model file's design, while it is not evaluated

    def __call__(self, X):
        gen = self.generation
        self.generation += 1
        size = chunk_size(len(X), self.min_chunk)
        starts = range(0, len(X), size)
        F = np.empty((len(X), len(self.study.objectives)))
        G = np.empty((len(X), len(self.study.constraints)))
        todo = []
        for c, s in enumerate(starts):
            Xc = X[s:s + size]
            p = find_chunk(self.have, self.out, gen, c, chunk_hash(Xc))
            if p is None:
                todo.append((gen, c, s, Xc))
                continue
            F[s:s + len(Xc)], G[s:s + len(Xc)], _ = read_chunk(p, self.study)
            self.reused += len(Xc)
            self.bar.update(len(Xc))
        if todo:
            self._run(todo, F, G)
        return F, G

    def finish(self):
        """Evaluate the model file's design if no batch has taken it along."""
        if self.file_x is not None:
            self._run([], None, None)

    def _run(self, todo, F, G):
        from distributed import as_completed
        client = self.connecter()
        if self.file_x is not None:              # the model file's design rides along
            todo = [(None, 0, 0, self.file_x)] + list(todo)
            self.file_x = None
        window = 2 * (sum(client.nthreads().values()) or 1) + 2
        pending, ac, index = iter(todo), as_completed(), {}

        def submit():
            item = next(pending, None)
            if item is not None:
                gen, c, s, Xc = item
                where = "file" if gen is None else f"g{gen}-c{c}"
                fut = client.submit(evaluate_chunk, self.study, Xc, self.evaluate, pure=False,
                                    retries=2, key=f"pm2dof-design-{self.ident[:12]}-{where}-"
                                    f"{chunk_hash(Xc)[:8]}")
                index[fut.key] = item
                ac.add(fut)

        for _ in range(window):
            submit()
        for fut in ac:
            gen, c, s, Xc = index.pop(fut.key)
            try:
                Fc, Gc, rows = fut.result()
            except Exception as exc:
                what = ("the model file's design" if gen is None else
                        f"generation {gen}, chunk {c} (designs {s}..{s + len(Xc) - 1} of its "
                        f"batch)")
                raise DesignRunError(f"{what} failed: {type(exc).__name__}: {exc}") from exc
            path = write_chunk(self.out, gen, c, Xc, Fc, Gc, rows, self.study, self.ident,
                               start=s, file_design=gen is None)
            self.have.add(path.name)
            fut.release()
            if gen is not None:
                F[s:s + len(Xc)], G[s:s + len(Xc)] = Fc, Gc
                self.evaluated += len(Xc)
                self.bar.update(len(Xc))
            submit()


def run_design(study, out, *, workers=None, scheduler=None, client=None, timeout=10.0,
               progress=True, notify=None, command_line=None, evaluate=None,
               min_chunk=MIN_CHUNK, file_design=True):
    """Run the optimiser of ``study`` with every design evaluated on Dask, into ``out``.

    Parameters
    ----------
    study : DesignStudy
        The study (``pm2dof.synthesis.spec.read_design_study``, with its overrides applied).
    out : path
        Output folder (created); a rerun of the same study reads the chunks already there.
    workers : int, optional
        Worker processes of the embedded LocalCluster (default: one per core).
    scheduler : str, optional
        Address of an existing Dask scheduler; its workers need pm2dof installed with the same
        generated code, and the model file at the same path.
    client : distributed.Client, optional
        Use this client (not closed here) instead of ``workers`` / ``scheduler``.
    timeout : float
        Seconds to wait for the scheduler and its first worker, s.
    progress : bool or pm2dof.infra.progress.Progress
        True: a bar on stderr when it is a terminal (designs done, of the number expected);
        a Progress: its bar; False: none.
    notify : callable(dict), optional
        Told what runs (:func:`format_notice` words it): ``{"study", "optimizer", "designs",
        "out"}`` once the folder is ready; ``{"where", "dashboard"}`` once a cluster is up
        (only when some design needs evaluating).
    command_line : list of str, optional
        The command the provenance in ``out/design.json`` records (None: ``sys.argv``).
    evaluate : callable, optional
        ``(study, X) -> (F, G, rows)`` run on the workers (default:
        ``pm2dof.synthesis.objectives.evaluate_batch``); it must be importable there.
    min_chunk : int
        Designs per Dask task at least (:func:`chunk_size`); part of the run's identity.
    file_design : bool
        Also evaluate the model file's own design (module docstring); False: only the
        optimiser's designs (what a measurement of the optimiser's cost wants).

    Returns
    -------
    dict
        ``designs`` (evaluated in all, this run's optimiser), ``evaluated`` (by this session),
        ``reused`` (read back from ``out``), ``generations``, ``seconds`` (wall time, s),
        ``file_design`` (``"evaluated"`` by this session, ``"reused"``, or ``None`` when not
        asked for: the model file's own design, evaluated once beside the optimiser's and not
        counted in the others).
    """
    evaluate = evaluate or _default_evaluate()
    notify = notify or (lambda notice: None)
    model = base_model(study)     # loaded once per process (and model file version)
    ident = identity(study, f"{model.spec.file_sha256} chunk>={int(min_chunk)}")
    have = prepare_out(out, study, ident, model, command_line)
    opt = study.optimizer
    notify({"study": study.name, "optimizer": opt["kind"], "designs": expected_designs(study),
            "out": out})
    t0 = time.perf_counter()
    reporter = Progress() if progress is True else progress
    bar = progress_bar(reporter, expected_designs(study), f"design {study.name}", unit="design",
                       smoothing=0)
    box = {"client": client, "own": False}

    def connecter():
        if box["client"] is None:
            box["client"], box["own"] = connect(workers, scheduler, timeout), True
            nthreads = sum(box["client"].nthreads().values()) or 1
            notify({"where": scheduler or f"a local cluster of {nthreads} worker process(es)",
                    "dashboard": dashboard_link(box["client"])})
        return box["client"]

    file_x = model_file_design(model, study)
    stored = file_design_path(out, chunk_hash(file_x)).name in have
    batches = _Batches(study, out, ident, have, evaluate, min_chunk, bar, connecter,
                       None if stored or not file_design else file_x)
    try:
        res = optimize(batches, study.bounds, len(study.objectives), len(study.constraints),
                       kind=opt["kind"], population=opt.get("population", 40),
                       generations=opt.get("generations", 30), grid=opt.get("grid", 20),
                       seed=opt.get("seed", 1))
        batches.finish()
    finally:
        bar.close()
        if box["own"]:
            disconnect(box["client"])
    finish_out(out, len(res.X))
    return {"designs": len(res.X), "evaluated": batches.evaluated, "reused": batches.reused,
            "generations": batches.generation, "seconds": time.perf_counter() - t0,
            "file_design": None if not file_design else "reused" if stored else "evaluated"}


def format_notice(notice):
    """A line of what :func:`run_design` says it runs (its ``notify``'s argument)."""
    if "where" in notice:
        return f"running on {notice['where']}" + (f"; dashboard {notice['dashboard']}"
                                                   if notice["dashboard"] else "")
    return (f"design study {notice['study']!r}: optimiser {notice['optimizer']}, about "
            f"{notice['designs']} designs, into {notice['out']}")


def format_run(res, out):
    """What ``pm2dof design run`` prints of :func:`run_design`'s result ``res``."""
    if not res["evaluated"]:
        return (f"{res['designs']} designs in {out}/batches: all were already evaluated, "
                f"nothing to run. Next: pm2dof design show {out}")
    return (f"{res['designs']} designs in {out}/batches over {res['generations']} "
            f"generation(s): {res['evaluated']} evaluated now, {res['reused']} read back from "
            f"an earlier run; wall time {res['seconds']:.1f} s. Next: pm2dof design show {out}")
