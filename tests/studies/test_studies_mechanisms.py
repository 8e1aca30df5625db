# A quick study on one model of each other kind: a platform, prismatic actuators, cylinders,
# gravity. The rows go through the study's own path (check_study, run_chunk, the results
# folder), in this process: the cluster is tested in test_studies_cluster.py.
import numpy as np
import pytest

import pm2dof
from pm2dof.studies import (
    SHIPPED_STUDIES,
    StudyFileError,
    check_study,
    read_results,
    read_study,
    run_chunk,
)
from pm2dof.studies.report import columns_of, summarise
from pm2dof.studies.store import finish_out, prepare_out, write_chunk

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

# one of each new kind: a 3-RRR platform (m = 3), PRR legs at a point, RPR legs, the vertical plane
MODELS = ("rrr3_platform", "prr_point", "rpr3_platform", "shang2010_vertical")

STUDY = """
[study]
name = "kinds"
model = "{model}"
moves = ["{move}"]
seed = 26
draws = 40
runs = 2

[quick]
draws = 2
runs = 2

[[controllers]]
name = "apd"
law = "apd"

[[controllers]]
name = "na"
law = "na"

[uncertainty]
payload_mass = {{uniform = [0.0, 0.5]}}
fv_scale = {{uniform = [0.8, 1.0]}}
inertia_error_percent = {{normal = [0.0, 5.0]}}
encoder_counts_per_rev = {{choice = [16384, 131072]}}
"""
METRIC_COLUMNS = ("rmse", "max_error", "peak_tau", "n_saturated", "n_singular", "n_non_finite",
                  "diverged", "theta_error")


@pytest.mark.parametrize("name", MODELS)
def test_quick_study_on_each_new_kind(tmp_path, name):
    model = pm2dof.load_model(name)
    move = next(iter(model.spec.trajectories))          # the model's own first move
    path = tmp_path / "kinds.toml"
    path.write_text(STUDY.format(model=name, move=move))
    s = read_study(path, quick=True)
    assert (s.draws, s.runs) == (2, 2)
    check_study(s, model)                                # what run_study checks first
    out = tmp_path / "out"
    prepare_out(out, s, model)
    for i in range(s.n_chunks):
        write_chunk(out, i, run_chunk(s, i), s)
    finish_out(out, s)
    info, table = read_results(out)
    n_rows = 2 * 2 * 2                                   # controllers x draws x runs, one move
    assert info["complete"] and s.n_rollouts == table.num_rows == n_rows
    assert table.column("rollout").to_pylist() == list(range(n_rows))
    names = table.column_names
    for col in ("controller", "law", "move", "draw", "run", "payload_mass", "fv_scale",
                "encoder_counts_per_rev", *METRIC_COLUMNS):
        assert col in names, col
    # one inertia-error column per leg and inertial parameter (alpha, beta, gamma per leg)
    inertia = [c for c in names if c.startswith("inertia_error_percent_")]
    assert len(inertia) == 3 * model.n_legs, inertia
    assert not any(c.startswith("fc_") or c == "stribeck_scale" for c in names)
    cols = columns_of(table)
    for key in ("rmse", "max_error", "peak_tau"):
        assert np.all(np.isfinite(cols[key])) and np.all(cols[key] > 0), (name, key)
    assert not cols["diverged"].any() and not cols["n_non_finite"].any()
    assert not cols["n_singular"].any()
    na = cols["law"] == "na"
    assert np.all(np.isfinite(cols["theta_error"][na]))   # NA's estimate against the truth
    assert np.all(np.isnan(cols["theta_error"][~na]))     # APD estimates nothing
    # tracking of the position within 5 mm on every rollout (the errors are metres)
    assert np.max(cols["max_error"]) < 5e-3, (name, np.max(cols["max_error"]))
    rep = summarise(cols, {**info, "grid_keys": []})
    assert sorted(r["controller"] for r in rep["rmse"]) == ["apd", "na"]
    assert all(r["rollouts"] == 4 and np.isfinite(r["median"]) for r in rep["rmse"])


@pytest.mark.parametrize("name", ["rrr3_platform", "prr_point"])
def test_a_draw_too_stiff_for_the_plants_substeps_is_refused_before_any_rollout(name, tmp_path):
    """The shipped robustness study with its Coulomb scale widened to 3x: some draw's plant is
    unstable at rest with the model's RK4 substeps (the models take enough substeps for the
    shipped studies' 1.3x). check_study (run_study's first step) names the draw and the
    remedy."""
    text = (SHIPPED_STUDIES / "robustness.toml").read_text()
    assert "fc_scale = {uniform = [0.7, 1.3]}" in text
    study = tmp_path / "stiff.toml"
    study.write_text(text.replace("fc_scale = {uniform = [0.7, 1.3]}",
                                  "fc_scale = {uniform = [2.9, 3.0]}"))
    check_study(read_study("robustness", quick=True, model=name), pm2dof.load_model(name))
    s = read_study(study, quick=True, model=name)
    with pytest.raises(StudyFileError, match=r"\[uncertainty \(draw \d+, run 0, move '\w+'\)\] "
                                             r"the draw's plant cannot be simulated.*"
                                             r"rk4_substeps >= \d+"):
        check_study(s, pm2dof.load_model(name))
