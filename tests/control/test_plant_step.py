# The simulated plant's RK4 substep against the stiffness of its smoothed friction at rest.
"""pm2dof.control.plant_step on every shipped model.

* Every shipped model's plant is stable near rest along each of its moves (h lambda <= 2.5).
  Before their plants took more RK4 substeps, prr_point, prr3_platform and rpr3_platform had
  3.9, 3.9 and 10.2.
* The rate is the true one: the generated ``plant_step`` (RK4, zero torque) applied to a small
  velocity at rest along the slowest-stable eigenvector shrinks it by |R(-h lambda)| per step,
  R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24 (RK4's stability polynomial; the law is linear in v
  for |v| << eps), whatever h: growth above h lambda = 2.785, decay below.
* The check refuses a plant whose step is unstable, naming the key to change.
"""
import numpy as np
import pytest

import pm2dof
from pm2dof.control.plant import plant_truth, plant_vector, theta_truth
from pm2dof.control.plant_step import RK4_STABLE_Z, check_plant_step, rest_decay_rate


def test_every_shipped_plant_is_stable_along_its_moves(model):
    T = model.spec.sensing["sample_period"]
    for name in model.spec.trajectories:
        xd = pm2dof.model_move(model, name).xd
        check_plant_step(model, xd)                       # raises if not
        z = max(rest_decay_rate(model, x) for x in xd[::10]) * T / model.spec.rk4_substeps
        assert 0 < z <= RK4_STABLE_Z, (model.name, name, z)


def _rk4_factor(z):
    return 1 - z + z**2 / 2 - z**3 / 6 + z**4 / 24        # R(-z)


@pytest.mark.parametrize("name", ["shang2010", "prr_point"])
def test_the_rate_is_what_the_generated_step_does(name):
    model = pm2dof.load_model(name)
    xe = pm2dof.model_move(model, next(iter(model.spec.trajectories))).xd[0]
    truth = plant_truth(model)
    lam = rest_decay_rate(model, xe, truth)
    q = model.ik(xe)
    S = model.S(q)
    d = (truth["fc"] + truth["fs"]) / truth["coulomb_smoothing_velocity"] + truth["fv"]
    w, V = np.linalg.eig(np.linalg.solve(model.Me(q, theta_truth(model, truth)),
                                         S.T @ (d[:, None] * S)))
    v = np.real(V[:, np.argmax(w.real)])
    step = model.function("plant_step")
    m, plant = model.dof, plant_vector(model, truth, quantise=False)
    eps = float(truth["coulomb_smoothing_velocity"])
    for z in (1.0, 2.6, 2.9, 3.5):                     # h lambda below and above 2.785
        h = z / lam
        x, out = np.concatenate([xe, 1e-6 * eps * v]), np.empty(2 * m)
        step(x, np.zeros(model.n_legs), plant, np.array([h]), out)
        # the whole velocity is R(-z) times the eigenvector (no other mode appears): the law
        # departs from linear by (v / eps)^2 / 2 = 5e-13 and Ce xed is O(|v|^2), amplified by
        # at most R's z^4 / 24 < 7 in the RK4 stages; measured <= 2.5e-9 of |v| at z = 3.5
        gain = out[m:] / (x[m:] @ v)
        np.testing.assert_allclose(gain, _rk4_factor(z) * v, rtol=0, atol=1e-7,
                                   err_msg=f"{name}, h lambda = {z}")
        ratio = gain @ v
        assert (abs(ratio) > 1) == (z > 2.785), (name, z, ratio)


def test_an_unstable_plant_is_refused_with_the_key_to_change():
    model = pm2dof.load_model("shang2010")
    truth = plant_truth(model, coulomb_smoothing_velocity=2e-4)   # 25x stiffer than the file
    xd = pm2dof.model_move(model, "low").xd
    with pytest.raises(pm2dof.ArgumentError, match=r"rk4_substeps >= \d+.*coulomb_smoothing"):
        check_plant_step(model, xd, truth)
    with pytest.raises(pm2dof.ArgumentError, match="numerically unstable"):
        pm2dof.simulate(model, pm2dof.NAController(model), pm2dof.model_move(model, "low"),
                        truth=truth)
