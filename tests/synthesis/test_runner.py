# The design runner on Dask: results equal the in-process optimiser's, chunks in Parquet, resume.
"""``run_design`` against the same optimiser run in this process (``optimize`` calling the
stand-in ``evaluate_batch`` directly): every design, objective and constraint equal, whatever
the chunking, the cluster or an interruption. The stand-in is the analytic problem of
tests/synthesis/analytic.py, so the machinery is checked independently of the real objectives.

Quick tests use an in-process cluster (threads, no processes); the ones marked slow start
worker processes on 127.0.0.1 (the embedded LocalCluster, and a killed worker), each wait
bounded, every process started here stopped here."""
import functools
import os
import signal
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from pm2dof.synthesis.front import read_front
from pm2dof.synthesis.optimize import optimize
from pm2dof.synthesis.runner import DesignRunError, chunk_size
from pm2dof.synthesis.runner import run_design as _run_design
from pm2dof.synthesis.store import DesignOutError, read_designs
from tests.synthesis import analytic

#: the machinery on small batches: chunks of 4 designs (MIN_CHUNK is 16), so that a
#: generation of 20 makes several tasks
run_design = functools.partial(_run_design, min_chunk=4)

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

DEADLINE = 120.0     # s: no wait of these tests may be longer


@pytest.fixture(autouse=True)
def _no_units(monkeypatch):
    """The stand-in's measure ("analytic") has no unit in the real objectives' table."""
    from pm2dof.synthesis import store
    monkeypatch.setattr(store, "units", lambda study, model: {})


def _reference(study):
    opt = study.optimizer
    return optimize(lambda X: analytic.evaluate_batch(study, X)[:2], study.bounds,
                    len(study.objectives), len(study.constraints), kind=opt["kind"],
                    population=opt["population"], generations=opt["generations"],
                    grid=opt["grid"], seed=opt["seed"])


def _assert_same(out, study):
    ref = _reference(study)
    info, all_cols = read_designs(out)
    # the model file's own design (la = lb = 0.244 m), first and flagged; the optimiser's after
    assert all_cols["file_design"][0] and not all_cols["file_design"][1:].any()
    assert all_cols["generation"][0] == -1
    assert (all_cols["la"][0], all_cols["lb"][0]) == (0.244, 0.244)
    want = analytic.evaluate_batch(study, [[0.244, 0.244]])[2][0]
    assert (all_cols["f1"][0], all_cols["score"][0]) == (want["f1"], want["score"])
    cols = {k: v[1:] for k, v in all_cols.items()}
    assert info["complete"] and info["designs"] == len(ref.X)
    np.testing.assert_array_equal(cols["generation"], ref.generation)
    np.testing.assert_array_equal(np.column_stack([cols[v] for v in study.variables]), ref.X)
    np.testing.assert_array_equal(cols["f1"], ref.F[:, 0])
    np.testing.assert_array_equal(cols["score"], -ref.F[:, 1])      # a max objective: as is
    if study.constraints:
        np.testing.assert_array_equal(cols["g.reach"], ref.G[:, 0])
        np.testing.assert_array_equal(cols["reach"], ref.X.sum(axis=1))
    np.testing.assert_array_equal(cols["feasible"], ref.feasible)
    assert set(cols["status"]) == {"ok"}


@pytest.fixture(scope="module")
def client():
    from distributed import Client, LocalCluster
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                           dashboard_address=":0")
    c = Client(cluster)
    yield c
    c.close()
    cluster.close()


def _chunks(out):
    return sorted(p.name for p in (Path(out) / "batches").glob("g*.parquet"))


@pytest.mark.parametrize("constrained", [False, True])
def test_run_equals_the_in_process_optimiser_and_resumes(tmp_path, client, constrained):
    study = analytic.study(constrained=constrained)
    out = tmp_path / "out"
    res = run_design(study, out, client=client, progress=False,
                     evaluate=analytic.evaluate_batch)
    assert res["evaluated"] == res["designs"] and res["reused"] == 0
    assert res["generations"] == 6
    _assert_same(out, study)
    files = _chunks(out)
    assert len(files) == 6 * 5            # 20 designs a generation in chunks of 4
    # a second run evaluates nothing, and needs no cluster
    again = run_design(study, out, client=None, progress=False, evaluate=_refuse)
    assert again["evaluated"] == 0 and again["reused"] == again["designs"] == res["designs"]
    assert _chunks(out) == files
    _assert_same(out, study)


def _refuse(study, X):
    raise AssertionError("a resumed run evaluated a design")


def test_an_interrupted_run_resumes_from_its_chunks(tmp_path, client):
    study = analytic.study(optimizer={"generations": 5})
    out = tmp_path / "out"
    calls = []

    class Stop(Exception):
        pass

    def notify(notice):
        calls.append(notice)

    from pm2dof.infra.progress import Progress

    class StopAfter(Progress):        # the bar is told of each chunk: stop after 9 chunks
        def bar(self, total, desc, unit="step", **kw):
            outer = self

            class B:
                n = 0

                def update(self, k):
                    B.n += 1
                    if B.n == 9:
                        raise Stop

                def close(self):
                    outer.closed = True
            return B()

    with pytest.raises(Stop):
        run_design(study, out, client=client, progress=StopAfter(quiet=True), notify=notify,
                   evaluate=analytic.evaluate_batch)
    assert len(_chunks(out)) == 9 and not read_designs(out)[0]["complete"]
    res = run_design(study, out, client=client, progress=False,
                     evaluate=analytic.evaluate_batch)
    assert res["reused"] == 9 * 4 and res["evaluated"] == res["designs"] - 36
    _assert_same(out, study)


def test_grid_run_front_and_payload(tmp_path, client):
    study = analytic.study(optimizer={"kind": "grid", "grid": 30})
    out = tmp_path / "g"
    res = run_design(study, out, client=client, progress=False,
                     evaluate=analytic.evaluate_batch, min_chunk=4)
    assert res["designs"] == 900 and res["generations"] == 1
    assert len(_chunks(out)) == 900 // chunk_size(900, 4) + (900 % chunk_size(900, 4) > 0)
    _assert_same(out, study)
    fr = read_front(out)
    p = fr.payload()
    assert p["objectives"] == [{"name": "f1", "sense": "min"}, {"name": "score", "sense": "max"}]
    # the grid's front: x2 = 0, f1 = x1 in 30 steps, score = -(1 - sqrt(f1))
    assert len(p["front"]) == 30
    for e in p["front"]:
        assert e["design"]["lb"] == 0.0 and set(e) == {"design", "objectives"}
        assert e["objectives"]["score"] == pytest.approx(-(1 - np.sqrt(e["design"]["la"])),
                                                         abs=1e-15)


def test_another_study_on_a_used_folder_is_refused(tmp_path, client):
    out = tmp_path / "out"
    run_design(analytic.study(optimizer={"generations": 2}), out, client=client,
               progress=False, evaluate=analytic.evaluate_batch)
    with pytest.raises(DesignOutError, match="another design run"):
        run_design(analytic.study(optimizer={"generations": 2, "seed": 8}), out,
                   client=client, progress=False, evaluate=analytic.evaluate_batch)
    with pytest.raises(DesignOutError, match="no design.json"):
        read_front(tmp_path)


def _fails_on_chunks(study, X):
    if len(X) == 1:                  # the model file's design: one row (chunks hold 4)
        return analytic.evaluate_batch(study, X)
    raise ValueError("a measure broke")


def _fails_on_the_file_design(study, X):
    if len(X) == 1:
        raise ValueError("a measure broke")
    return analytic.evaluate_batch(study, X)


def test_a_failing_chunk_names_itself(tmp_path, client):
    with pytest.raises(DesignRunError, match=r"generation 0, chunk \d+ .*ValueError: a measure "
                       r"broke"):
        run_design(analytic.study(), tmp_path / "o", client=client, progress=False,
                   evaluate=_fails_on_chunks)
    with pytest.raises(DesignRunError, match=r"the model file's design failed: ValueError: a "
                       r"measure broke"):
        run_design(analytic.study(optimizer={"seed": 8}), tmp_path / "p", client=client,
                   progress=False, evaluate=_fails_on_the_file_design)


def test_the_file_design_against_the_front(tmp_path, client):
    """The model file's design (la = lb = 0.244 m) on the grid run of ZDT1 over bounds that
    put it at u = (0.44, 0.44): f1 = 0.44, f2 = g (1 - sqrt(f1 / g)) with g = 1 + 9 * 0.44.
    The grid's front is x2 = 0 (lb at its bound): the front's designs with f1 <= 0.44 and
    f2 <= its f2 dominate it. It stays out of the front, is read back on a rerun, and an
    older run's folder (no file design) still reads."""
    bounds = ((0.0, 0.5545454545454546), (0.0, 0.5545454545454546))   # 0.244 = 0.44 * hi
    study = analytic.study(optimizer={"kind": "grid", "grid": 12}, bounds=bounds)
    out = tmp_path / "g"
    res = run_design(study, out, client=client, progress=False,
                     evaluate=analytic.evaluate_batch)
    assert res["file_design"] == "evaluated" and res["designs"] == 144
    fr = read_front(out)
    assert fr.file_row == 0 and 0 not in fr.index and len(fr.index) == 12
    fd = fr.payload()["file_design"]
    assert set(fd) == {"design", "objectives", "feasible", "on_front", "dominated_by",
                       "distance", "beaten_most_by"}
    assert fd["design"] == {"la": 0.244, "lb": 0.244} and fd["feasible"]
    u = 0.244 / bounds[0][1]
    g = 1 + 9 * u
    f2 = g * (1 - np.sqrt(u / g))
    assert fd["objectives"]["f1"] == pytest.approx(u, abs=1e-15)
    assert fd["objectives"]["score"] == pytest.approx(-f2, abs=1e-14)
    # independently: the grid's front points x2 = 0, f1 = k / 11, f2 = 1 - sqrt(f1)
    f1s = np.arange(12) / 11
    f2s = 1 - np.sqrt(f1s)
    dom = [k for k in range(12) if f1s[k] <= u and f2s[k] <= f2]
    assert fd["dominated_by"] == dom and not fd["on_front"]
    gain = {k: min((u - f1s[k]) / u, (f2 - f2s[k]) / f2) for k in dom}
    best = max(gain, key=gain.get)
    assert fd["distance"] == pytest.approx(gain[best], rel=1e-12)
    assert fd["beaten_most_by"] == best
    again = run_design(study, out, client=None, progress=False, evaluate=_refuse)
    assert again["file_design"] == "reused" and again["evaluated"] == 0
    assert read_front(out).payload() == fr.payload()
    for p in (out / "batches").glob("file-design-*.parquet"):        # a run without it
        p.unlink()
    old = read_front(out)
    assert old.file_row is None and old.payload()["file_design"] is None
    np.testing.assert_array_equal(old.index, fr.index - 1)
    none = run_design(study, tmp_path / "n", client=client, progress=False,
                      evaluate=analytic.evaluate_batch, file_design=False)
    assert none["file_design"] is None and none["designs"] == 144
    assert not list((tmp_path / "n" / "batches").glob("file-design-*"))
    np.testing.assert_array_equal(read_front(tmp_path / "n").index, old.index)


# ---- real worker processes (slow): the embedded cluster, a worker killed mid-run ----

@pytest.mark.slow
def test_embedded_cluster_on_processes_and_a_killed_worker(tmp_path, monkeypatch):
    """Two worker processes of the embedded LocalCluster (connect(), on 127.0.0.1); one is
    killed (SIGKILL) once the first chunks are in: Dask reruns its tasks on the other (or on
    the nanny's restart), and the designs are those of the in-process run."""
    from pm2dof.studies.runner import connect, disconnect
    monkeypatch.setenv(analytic.DELAY_ENV, "0.02")        # 0.08 s a chunk: time to kill one
    client = connect(workers=2, timeout=60)
    try:
        pids = list(client.run(os.getpid).values())
        assert len(pids) == 2 and os.getpid() not in pids
        study = analytic.study(optimizer={"generations": 8}, constrained=True)
        out = tmp_path / "out"
        killed = []

        def killer():
            t0 = time.monotonic()
            while len(_chunks(out)) < 6 and time.monotonic() - t0 < DEADLINE:
                time.sleep(0.01)
            os.kill(pids[0], signal.SIGKILL)
            killed.append(len(_chunks(out)))

        th = threading.Thread(target=killer, daemon=True)
        th.start()
        res = run_design(study, out, client=client, progress=False,
                         evaluate=analytic.evaluate_batch)
        th.join(DEADLINE)
        assert killed and killed[0] < 8 * 5, "the run ended before a worker could be killed"
        assert res["evaluated"] == res["designs"]
        _assert_same(out, study)
    finally:
        disconnect(client)
