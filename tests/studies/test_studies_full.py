# Every shipped study and `pm2dof study bench` at full size, as a user runs them: slow (minutes
# on 2 cores), so `make test` leaves them out and `make test-slow` (CI, .ci/run) runs them.
#
# Each command runs as its own process group (its embedded Dask LocalCluster: scheduler and
# worker processes on 127.0.0.1), waited for at most DEADLINE, and killed with its workers
# whatever happens. What is checked: the command succeeds; every rollout is in the results
# once, with finite metrics and no singular, non-finite or diverged sample; the plants of
# every draw pass the integration check (the study would be refused otherwise); and rows
# spread over the study equal pm2dof.simulate() to the last bit (an independent path: one
# rollout at a time, no batch, no Dask).
import json
import math
import os
import signal
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof.studies import SHIPPED_STUDIES, read_results, read_study, resolve_study
from pm2dof.studies.bench import bench_study
from pm2dof.studies.evaluate import rollout_setup
from pm2dof.studies.report import columns_of
from pm2dof.studies.spec import check_study
from tests.studies.stiffness import h_lambda

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
PM2DOF = [sys.executable, "-m", "pm2dof"]
DEADLINE = 900.0           # s for one command, on a loaded 2-core machine
SHIPPED = sorted(p.stem for p in SHIPPED_STUDIES.glob("*.toml"))
COUNTS = ("n_singular", "n_non_finite")


def _run(args):
    """``pm2dof ARGS`` in its own process group, at most DEADLINE s; (rc, stdout, stderr).
    The group (the CLI and its cluster's processes) is killed on the way out."""
    p = subprocess.Popen([*PM2DOF, *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True, cwd=ROOT, start_new_session=True)
    try:
        out, err = p.communicate(timeout=DEADLINE)
        return p.returncode, out, err
    finally:
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        p.wait(timeout=30)


def _simulate(study, c, m, d):
    """[(rmse, max_error, peak_tau, n_saturated)] of unit (c, m, d) by simulate(), one per
    run, theta_hat carried from run to run as the study does."""
    rows, theta = [], None
    for r in range(study.runs):
        model, ctrl, traj, truth, counts, _, _ = rollout_setup(study, c, m, d, r)
        res = pm2dof.simulate(model, ctrl, traj, truth=truth, encoder_counts_per_rev=counts,
                              theta_hat0=theta, quantise=study.quantise)
        theta = res.theta_hat[-1].copy()
        e = res.e[:res.n_move]
        rows.append((res.rmse, math.sqrt(float(np.max(np.sum(e * e, axis=1)))), res.peak_tau,
                     res.n_saturated))
    return rows


@pytest.mark.parametrize("name", SHIPPED)
def test_shipped_study_runs_at_full_size(tmp_path, name):
    study = read_study(resolve_study(name))
    assert not study.quick and study.n_rollouts >= 3600
    out = tmp_path / name
    rc, stdout, err = _run(["study", "run", name, "--out", str(out), "--workers", "2"])
    assert rc == 0, err[-3000:]
    assert f"{study.n_rollouts} rows in {out}/results" in stdout, stdout
    info, table = read_results(out)
    cols = columns_of(table)
    assert info["complete"] and info["rows"] == study.n_rollouts
    np.testing.assert_array_equal(np.sort(cols["rollout"]), np.arange(study.n_rollouts))
    for k in ("rmse", "max_error", "peak_tau"):
        assert np.isfinite(cols[k]).all() and (cols[k] > 0).all(), k
    for k in COUNTS:
        assert not cols[k].any(), (k, np.flatnonzero(cols[k])[:10])
    assert not cols["diverged"].any()
    # rows spread over the study against simulate(), one rollout at a time
    order = np.argsort(cols["rollout"])
    for u in np.linspace(0, study.n_units - 1, 6).astype(int):
        c, m, d = study.unit(int(u))
        for r, ref in enumerate(_simulate(study, c, m, d)):
            i = order[study.rollout(c, m, d, r)]
            got = (cols["rmse"][i], cols["max_error"][i], cols["peak_tau"][i],
                   cols["n_saturated"][i])
            assert got == ref, (name, int(u), r, got, ref)


def test_study_bench_runs_at_full_size():
    """``pm2dof study bench`` (10,000 rollouts, Dask with 1 and 2 workers, run_study end to
    end): it runs; its 10,000 plants pass the integration check. Its speed targets are
    reported, never enforced."""
    study = bench_study(10000)
    check_study(study, pm2dof.load_model(study.model_path))    # raises StudyFileError if not
    rc, stdout, err = _run(["study", "bench", "--json"])
    assert rc == 0, err[-3000:]
    r = json.loads(stdout)
    assert r["rollouts"] == 10000 and r["chunk"] == 1000 and r["controller"] == "na"
    for key in ("rollouts_per_s_plain_loop", "rollouts_per_s_batch",
                "rollouts_per_s_dask_1_worker", "rollouts_per_s_dask_2_workers",
                "rollouts_per_s_study_run_2_workers_1000",
                "rollouts_per_s_study_run_2_workers_10000"):
        assert r[key] > 0 and math.isfinite(r[key]), key
    assert set(r["targets"]) and all(v in (True, False) for v in r["targets"].values())


def _stiffest(study):
    """(largest h lambda, its draw) over every draw of ``study`` in its first run, at nine
    poses of each move (both ends: the stiffest pose of a line move)."""
    from pm2dof.studies.draws import plant_of, sample_draw
    from pm2dof.studies.evaluate import make_trajectory
    model = pm2dof.load_model(study.model_path)
    T = model.spec.sensing["sample_period"]
    poses = []
    for mv in study.moves:
        xd = make_trajectory(model, mv, T).xd
        poses.append(xd[np.unique(np.linspace(0, len(xd) - 1, 9).astype(int))])
    best = (0.0, None)
    for d in range(study.draws):
        truth = plant_of(model, study, sample_draw(study, d, model.n_legs), 0)[0]
        z = max(h_lambda(model, p, truth) for p in poses)
        best = max(best, (z, d))
    return best


def test_the_integration_margins_the_study_file_page_quotes():
    """docs/study-file.md, "Checks": on the paper's robot the robustness study's 2,000 draws
    reach h lambda = 2.40 (draw 1387); the bench's 10,000 plants 1.86 (draw 6116), both below
    the 2.5 accepted."""
    z, d = _stiffest(read_study(resolve_study("robustness")))
    assert (round(z, 2), d) == (2.40, 1387)
    z, d = _stiffest(bench_study(10000))
    assert (round(z, 2), d) == (1.86, 6116)
    page = (ROOT / "docs" / "study-file.md").read_text()
    assert "reach hλ = 2.40 (draw 1387" in page and "hλ = 1.86" in (
        ROOT / "docs" / "benchmark.md").read_text()
