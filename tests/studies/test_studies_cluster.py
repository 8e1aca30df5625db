# Studies on real Dask components, started here as separate processes on 127.0.0.1 with free
# ports: the embedded LocalCluster through the CLI, an interrupted and a killed run resumed,
# `dask scheduler` + two `dask worker` processes with one worker killed mid-run, an
# unreachable scheduler. Every process started here is stopped here; every wait is bounded.
#
# The reference for every dataset is the same study evaluated chunk by chunk in this process
# (run_chunk, which tests/test_studies.py checks against simulate() bit for bit): rows must be
# present exactly once and equal to it, whatever the workers, interruptions or lost workers.
import os
import re
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from pm2dof.studies import (
    SHIPPED_STUDIES,
    StudyRunError,
    read_results,
    read_study,
    run_chunk,
    run_study,
)
from pm2dof.studies.report import columns_of
from tests.processes import from_a_terminal

pytestmark = pytest.mark.slow     # long runs (builds, full benches, Dask clusters): make test-slow (CI)

ROOT = Path(__file__).resolve().parents[2]
BIN = Path(sys.executable).parent
PM2DOF = [sys.executable, "-m", "pm2dof"]
DEADLINE = 120.0    # s: no step of these tests may wait longer


def _study_file(tmp_path, draws=300, chunk=30):
    """The robustness study's quick variant, larger: enough chunks to interrupt in the middle."""
    text = (SHIPPED_STUDIES / "robustness.toml").read_text()
    text = text.replace("draws = 40\nchunk = 40", f"draws = {draws}\nchunk = {chunk}")
    p = tmp_path / "study.toml"
    p.write_text(text)
    return p


_REFERENCES = {}


def _reference(study):
    """Every chunk of ``study`` in this process, once per study identity (three tests run the
    same study file, each from its own folder)."""
    key = study.identity                 # "equal identities give identical rows"
    if key not in _REFERENCES:
        parts = [run_chunk(study, i) for i in range(study.n_chunks)]
        _REFERENCES[key] = {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}
    return _REFERENCES[key]


def _assert_same(out, ref):
    info, table = read_results(out)
    cols = columns_of(table)
    assert info["complete"] and info["rows"] == len(ref["rollout"])
    np.testing.assert_array_equal(cols["rollout"], np.arange(len(ref["rollout"])))  # once each
    for k, v in ref.items():
        got = cols[k]
        if v.dtype == object:
            assert got.tolist() == v.tolist(), k
        else:
            np.testing.assert_array_equal(got, v, err_msg=k)


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _wait(pred, what, timeout=DEADLINE, procs=()):
    t0 = time.monotonic()
    while not pred():
        for p in procs:
            if p.poll() is not None:
                raise AssertionError(f"{what}: process {p.args} exited with {p.returncode}: "
                                     f"{p.stderr.read() if p.stderr else ''}")
        if time.monotonic() - t0 > timeout:
            raise AssertionError(f"timed out after {timeout} s waiting for {what}")
        time.sleep(0.05)


def _chunks(out):
    return len(list((Path(out) / "results").glob("chunk-*.parquet")))


def _stop(procs):
    for p in procs:
        if p.poll() is None:
            try:
                os.killpg(p.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
    for p in procs:
        try:
            p.wait(timeout=30)
        except subprocess.TimeoutExpired:
            pass


def _start(args, **kw):
    return subprocess.Popen(from_a_terminal(args), stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, cwd=ROOT, start_new_session=True,
                            **kw)


@pytest.fixture
def study_file(tmp_path):
    return _study_file(tmp_path)


@pytest.mark.parametrize("how", [signal.SIGINT, signal.SIGKILL])
def test_interrupted_or_killed_run_resumes_to_the_same_dataset(tmp_path, study_file, how):
    out = tmp_path / "out"
    cmd = [*PM2DOF, "study", "run", str(study_file), "--quick", "--out", str(out), "--workers", "1"]
    procs = [_start(cmd)]
    try:
        _wait(lambda: _chunks(out) >= 2, "the first chunks", procs=procs)
        if how == signal.SIGINT:
            # Ctrl-C, as a terminal sends it: to the whole process group, the workers too.
            # The CLI shuts its cluster down; the workers ignore it (they printed ~70 lines of
            # tracebacks before), so the user reads the one line that says what to do.
            os.killpg(procs[0].pid, signal.SIGINT)
            rc = procs[0].wait(timeout=DEADLINE)
            err = procs[0].stderr.read()
            assert rc == 130, err
            assert "interrupted" in err and "Run the same command again" in err
            assert "Traceback" not in err and len(err.strip().splitlines()) == 1, err
        else:
            os.killpg(procs[0].pid, signal.SIGKILL)  # a crash: client and workers gone at once
            procs[0].wait(timeout=DEADLINE)
        n_before = _chunks(out)
        study = read_study(study_file, quick=True)
        assert 2 <= n_before < study.n_chunks, "the run ended before it could be interrupted"
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=DEADLINE, cwd=ROOT)
        assert r.returncode == 0, r.stderr
        assert f"{n_before} chunk(s) already in" in r.stdout
        again = subprocess.run(cmd, capture_output=True, text=True, timeout=DEADLINE, cwd=ROOT)
        assert again.returncode == 0, again.stderr       # finished: no cluster, no 0 rollouts/s
        assert (f"all {study.n_chunks} chunks were already there, nothing to run"
                in again.stdout and "rollouts/s" not in again.stdout), again.stdout
    finally:
        _stop(procs)
    _assert_same(out, _reference(study))


def test_real_scheduler_two_workers_one_killed_mid_run(tmp_path, study_file):
    port = _free_port()
    addr = f"tcp://127.0.0.1:{port}"
    procs = []
    try:
        procs.append(_start([str(BIN / "dask"), "scheduler", "--host", "127.0.0.1", "--port",
                             str(port), "--dashboard-address", f"127.0.0.1:{_free_port()}"]))
        for _ in range(2):
            procs.append(_start([str(BIN / "dask"), "worker", addr, "--nworkers", "1",
                                 "--nthreads", "1", "--host", "127.0.0.1",
                                 "--dashboard-address", f"127.0.0.1:{_free_port()}"]))
        out = tmp_path / "out"
        run = _start([*PM2DOF, "study", "run", str(study_file), "--quick", "--out", str(out),
                      "--scheduler", addr, "--timeout", "60"])
        procs.append(run)
        _wait(lambda: _chunks(out) >= 1, "the first chunk", procs=procs)
        os.killpg(procs[1].pid, signal.SIGKILL)        # lose a worker in the middle
        study = read_study(study_file, quick=True)
        assert _chunks(out) < study.n_chunks, "the run ended before a worker could be killed"
        rc = run.wait(timeout=DEADLINE)
        stdout, stderr = run.stdout.read(), run.stderr.read()
        assert rc == 0, stderr
        assert f"running on {addr}" in stdout
    finally:
        _stop(procs)
    _assert_same(out, _reference(study))


def test_embedded_cluster_equals_in_process_rows_and_report_runs(tmp_path, study_file):
    import io

    from pm2dof.infra.progress import Progress
    study = read_study(SHIPPED_STUDIES / "adaptation.toml", quick=True)
    out = tmp_path / "a"
    stream = io.StringIO()                 # a bar drawn as on a terminal, into a buffer
    res = run_study(study, out, workers=2, progress=Progress(stream, bars=True))
    assert res["rows"] == study.n_rollouts and res["skipped"] == 0
    # the two rates: the progress bar's is the summary's run rate, the
    # wall-time rate also counts the cluster's start and stop
    last = [seg for seg in stream.getvalue().split("\r") if "rollout/s" in seg][-1]  # final state
    assert f"{study.n_rollouts}/{study.n_rollouts}" in last, last
    shown = float(re.search(r"([\d.]+)rollout/s", last)[1])
    assert abs(shown - res["run_rollouts_per_s"]) <= 0.05 * shown + 1, (last, res)
    assert res["seconds"] == pytest.approx(res["run_seconds"] + res["cluster_seconds"])
    assert 0 < res["run_seconds"] < res["seconds"], res
    assert res["rollouts_per_s"] == pytest.approx(study.n_rollouts / res["seconds"])
    _assert_same(out, _reference(study))
    again = run_study(study, out, workers=2, progress=False)
    assert again["skipped"] == study.n_chunks and again["rows"] == study.n_rollouts
    r = subprocess.run([*PM2DOF, "study", "report", str(out), "--json"], capture_output=True,
                       text=True, timeout=DEADLINE, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    import json
    s = json.loads(r.stdout)
    assert s["rows"] == study.n_rollouts and s["complete"]
    assert {x["run"] for x in s["runs"]} == set(range(study.runs))
    assert (out / "figures" / "runs.png").stat().st_size > 10_000


def test_unreachable_scheduler_fails_clearly_within_the_timeout(tmp_path):
    study = read_study(SHIPPED_STUDIES / "robustness.toml", quick=True)
    addr = f"tcp://127.0.0.1:{_free_port()}"           # nothing listens there
    t0 = time.monotonic()
    with pytest.raises(StudyRunError, match=rf"cannot reach the Dask scheduler at {addr} "
                       r"within 0\.25 s"):
        run_study(study, tmp_path / "out", scheduler=addr, timeout=0.25, progress=False)
    assert time.monotonic() - t0 < 20
    r = subprocess.run([*PM2DOF, "study", "run", str(SHIPPED_STUDIES / "robustness.toml"),
                        "--quick", "--out", str(tmp_path / "o2"), "--scheduler", addr,
                        "--timeout", "0.25"], capture_output=True, text=True, timeout=DEADLINE,
                       cwd=ROOT)
    assert r.returncode == 2 and "pm2dof: error: cannot reach the Dask scheduler" in r.stderr


def test_readme_command_on_a_shipped_study_and_the_bench_keys(tmp_path):
    """`pm2dof study run robustness --quick --out DIR` (the issue's "done when"),
    and the bench's JSON contract (its speed targets live in the bench, not here)."""
    out = tmp_path / "rob"
    r = subprocess.run([*PM2DOF, "study", "run", "robustness", "--quick", "--out",
                        str(out), "--workers", "2"], capture_output=True, text=True,
                       timeout=DEADLINE, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    study = read_study(SHIPPED_STUDIES / "robustness.toml", quick=True)
    info, table = read_results(out)
    assert table.num_rows == info["rows"] == study.n_rollouts == 240 and info["complete"]
    assert info["provenance"]["model_file_sha256"] and info["study_text"] == \
        (SHIPPED_STUDIES / "robustness.toml").read_text()
    from pm2dof.studies.bench import study_bench
    res = study_bench(quick=True)
    for k in ("rollouts_per_s_plain_loop", "rollouts_per_s_batch",
              "rollouts_per_s_dask_1_worker", "rollouts_per_s_dask_2_workers"):
        assert res[k] > 0, k
    assert set(res["targets"]) == {"batch >= 4000 rollouts/s", "2 workers >= 1.7x 1 worker",
                                   "Dask overhead <= 10 % (1 worker vs batch)"}
