# pm2dof.bench.synthesis in quick mode: every number is there and means what it says.
"""One quick run of the design-study bench (:func:`pm2dof.bench.synthesis.synthesis_bench`):
a row per model and objective class with its designs per second and the speed-up over
structdimsynth's published seconds per design (0.5 s kinematic, 1.8 s with dynamics) derived
from it; the kinematic class's objectives against their generated-C calls; Dask's run of a
batch (which the bench itself checks equal, design by design, to the same batch in this
process); the targets and the report's lines. No timing thresholds: a quick run's numbers are
noise, and the targets are reported by the bench, never enforced.

Besides, what the bench times is checked to be what it names: the kinematic class's study has
the four kinematic measures on an n x n region at the home orientation and no constraint, and
its objectives' values equal NumPy over the same two ``map`` calls the bench times them
against.
"""
import json
import math

import numpy as np
import pytest

from pm2dof.bench import synthesis as sb
from pm2dof.bench.report import format_bench
from pm2dof.bench.run import TARGETS, check_targets
from pm2dof.core.model import load_model
from pm2dof.synthesis.objectives import evaluate_with_status
from pm2dof.synthesis.region import grid_points

pytestmark = pytest.mark.slow     # starts a Dask cluster: make test-slow (CI)


@pytest.fixture(scope="module")
def results():
    said = []
    r = sb.synthesis_bench(1, quick=True, say=said.append)
    r["_said"] = said
    return r


def _positive(v):
    return isinstance(v, float) and math.isfinite(v) and v > 0


def test_a_row_per_model_and_class(results):
    rows = results["synthesis_rows"]
    assert set(rows) == set(sb.SYNTH_MODELS)
    for name, row in rows.items():
        for cls in sb.OBJECTIVE_CLASSES:
            c = row[cls]
            assert _positive(c["designs_per_s"]) and c["designs"] == 2, (name, cls)
            assert c["ok_fraction"] == 1.0, (name, cls)      # every measure computed
            ref = 0.5 if cls == "kinematic" else 1.8
            assert c["structdimsynth_s"] == ref
            assert c["speedup_vs_structdimsynth"] == pytest.approx(ref * c["designs_per_s"],
                                                                   rel=1e-15)
        assert _positive(row["kinematic_over_c"]) and row["region_points"] == 64
        assert _positive(row["kinematic_objectives_ms"]) and _positive(row["kinematic_c_ms"])
    assert results["synthesis_kinematic_over_c_max"] == max(
        r["kinematic_over_c"] for r in rows.values())
    assert results["synthesis_speedup_vs_structdimsynth_kinematic_min"] == min(
        r["kinematic"]["speedup_vs_structdimsynth"] for r in rows.values())


def test_the_dask_batch_and_the_targets(results):
    assert results["synthesis_dask_designs"] == 9                 # a 3 x 3 grid
    for key in ("synthesis_dask_s", "synthesis_worker_s", "synthesis_inprocess_s",
                "synthesis_dask_over_inprocess"):
        assert _positive(results[key]), key
    assert results["synthesis_dask_overhead"] == results["synthesis_dask_over_worker"] - 1.0
    # the run's wall time includes its worker's evaluation: the ratio is at least 1
    assert results["synthesis_dask_over_worker"] >= 1.0
    assert results["synthesis_worker_s"] <= results["synthesis_dask_s"]
    keys = {k for k, *_ in TARGETS}
    assert {"synthesis_kinematic_over_c_max", "synthesis_dask_over_worker"} <= keys
    tg = check_targets(results)
    for key in ("synthesis_kinematic_over_c_max", "synthesis_dask_over_worker"):
        assert tg[key]["pass"] in (True, False) and tg[key]["value"] == results[key]
    json.dumps({k: v for k, v in results.items() if k != "_said"})
    text = format_bench({**results, "targets": tg})
    assert "design studies: designs per second per objective class" in text
    assert "kinematic objectives / their C calls, worst model" in text
    assert any("Dask overhead" in s for s in results["_said"])


@pytest.mark.parametrize("name", sorted(sb.SYNTH_MODELS))
def test_the_kinematic_class_is_the_four_measures_over_the_two_map_calls(name):
    st = sb.class_study(name, "kinematic", n=12)
    assert [o.measure for o in st.objectives] == ["clear_area", "dexterity_min",
                                                  "dexterity_mean", "margin"]
    assert st.constraints == () and st.region["n"] == 12 and st.region["phi"] is None
    base = load_model(st.model_path)
    X = sb._designs(st, 3)
    b = np.asarray(st.bounds)
    assert np.all(X >= b[:, 0] + 0.25 * (b[:, 1] - b[:, 0]) - 1e-15)
    assert np.all(X <= b[:, 0] + 0.75 * (b[:, 1] - b[:, 0]) + 1e-15)
    for x in X:
        m = base.at_design(dict(zip(st.variables, x)))
        values, status = evaluate_with_status(m, st)
        assert status == "ok"
        pts, cell, _ = grid_points(st.region, m)
        assert pts.shape == (144, m.dof)
        if m.dof == 3:
            assert np.all(pts[:, 2] == m.spec.home[2])
        q = np.empty((len(pts), 2 * m.n_legs))
        m.function("ik").map(len(pts), pts, q)
        reach = np.isfinite(q).all(axis=1)
        s = np.empty((int(reach.sum()), 2))
        m.function("singularity_measures").map(len(s), np.ascontiguousarray(q[reach]), s)
        t1, t2 = m.singularity_threshold, m.parallel_singularity_threshold
        clear = (s[:, 0] >= t1) & (s[:, 1] >= t2)
        type2 = np.zeros(len(pts))
        type2[reach] = s[:, 1]
        margin = np.full(len(pts), -1.0)
        margin[reach] = np.minimum(s[:, 0] - t1, s[:, 1] - t2)
        assert values["clear_area"] == pytest.approx(clear.sum() * cell, rel=1e-12)
        assert values["dexterity_min"] == type2.min()
        assert values["dexterity_mean"] == pytest.approx(type2.mean(), rel=1e-12)
        assert values["margin"] == margin.min()
