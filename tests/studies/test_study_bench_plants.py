"""The plants of ``pm2dof study bench``: every one is a plant the paper's robot can simulate.

The bench runs NA over 10,000 random plants. Drawn from the robustness study's uncertainty
(five times that study's own 2,000 draws), its draw 6116 has a friction at rest too stiff for
the paper robot's three RK4 substeps within the accepted margin, h lambda = 2.5001 > 2.5, and
``check_study`` refused the whole bench before any rollout. The bench now draws from the gains
study's narrower uncertainty. The full check of all 10,000 draws (and the bench itself) runs
in tests/studies/test_studies_full.py (slow). h lambda is recomputed here from the model's Me
and S and the plant's friction slope at rest, not read from the check's message.
"""
import dataclasses

import pytest

from pm2dof import load_model, plant_truth
from pm2dof.control.plant_step import RK4_STABLE_Z, check_plant_step
from pm2dof.core.errors import ArgumentError
from pm2dof.studies import read_study, resolve_study
from pm2dof.studies.bench import bench_study, bench_uncertainty
from pm2dof.studies.draws import plant_of, sample_draw
from pm2dof.studies.evaluate import make_trajectory
from pm2dof.studies.spec import UNCERTAINTY
from tests.studies.stiffness import h_lambda

DRAW = 6116


@pytest.fixture(scope="module")
def setup():
    bench = bench_study(10000)
    model = load_model(bench.model_path)
    T = model.spec.sensing["sample_period"]
    (move,) = bench.moves
    return bench, model, make_trajectory(model, move, T).xd


def test_the_robustness_uncertainty_drawn_10000_times_gives_a_plant_too_stiff(setup):
    bench, model, xd = setup
    robust = dataclasses.replace(
        bench, uncertainty=read_study(resolve_study("robustness")).uncertainty)
    truth = plant_of(model, robust, sample_draw(robust, DRAW, model.n_legs), 0)[0]
    z = h_lambda(model, xd, truth)
    assert RK4_STABLE_Z < z < 2.5002 and model.spec.rk4_substeps == 3
    with pytest.raises(ArgumentError, match=r"h lambda = 2\.5 > 2\.5 .*rk4_substeps >= 4"):
        check_plant_step(model, xd, truth)


def test_the_bench_draws_plants_the_robot_can_simulate(setup):
    bench, model, xd = setup
    keys = [k for k, _ in bench.uncertainty]
    for d in (DRAW, 0, 9999):
        values = sample_draw(bench, d, model.n_legs)
        assert set(values) == set(keys)
        truth = plant_of(model, bench, values, 0)[0]
        check_plant_step(model, xd, truth)                          # accepted
        assert h_lambda(model, xd, truth) < 1.87
    # the nominal plant, for scale: the bench's plants are near it
    assert h_lambda(model, xd, plant_truth(model)) < 1.5
    # physical: the gains study's uncertainty, and the robustness study's encoders
    assert keys == [k for k in UNCERTAINTY if k in keys]          # the draws' fixed order
    assert bench.uncertainty == bench_uncertainty()
    gains = dict(read_study(resolve_study("gains")).uncertainty)
    robust = dict(read_study(resolve_study("robustness")).uncertainty)
    for k, dist in bench.uncertainty:
        assert dist == (robust[k] if k == "encoder_counts_per_rev" else gains[k]), k
