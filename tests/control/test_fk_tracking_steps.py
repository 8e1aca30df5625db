# The controllers' platform fk: FK_TRACKING_STEPS Gauss-Newton steps from the previous pose suffice.
"""The generated controller steps run FK_TRACKING_STEPS Gauss-Newton steps of a platform's fk
from the previous sample's pose (Model.fk keeps FK_NEWTON_STEPS from its seed). A step whose
update is at most FK_NEWTON_TOL is not taken, and none after it is, so the pose equals
FK_NEWTON_STEPS' whenever at most FK_TRACKING_STEPS updates exceed the tolerance. Along every
shipped platform's moves (the NA loop, quantised encoders, both speeds) that count, from the
SymPy step lambdified on its own, must leave two steps of margin."""
import warnings

import numpy as np
import pytest

import pm2dof
from pm2dof.control.controllers import NAController
from pm2dof.control.plant import plant_vector
from pm2dof.control.simulate import simulate
from pm2dof.control.trajectory import line_moves, model_move
from pm2dof.core.model_file import read_model_file
from pm2dof.core.paths import SHIPPED_MODELS
from pm2dof.derive.kinematics import FK_NEWTON_STEPS, FK_NEWTON_TOL, FK_TRACKING_STEPS, Kinematics
from pm2dof.derive.symbols import Symbols
from tests import derivations

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

PLATFORMS = sorted(s.name for s in (read_model_file(p) for p in SHIPPED_MODELS.glob("*.toml"))
                   if s.end_effector == "platform")
MARGIN = 2          # steps left over at the worst sample


def _taken_steps(newton, seed, qa):
    """(updates larger than FK_NEWTON_TOL before the first that is not, the pose)."""
    x = np.asarray(seed, float)
    for taken in range(4 * FK_NEWTON_STEPS):
        x_next = np.array(newton(x, qa), dtype=float).ravel()
        if not np.max(np.abs(x_next - x)) > FK_NEWTON_TOL:
            return taken, x
        x = x_next
    raise AssertionError(f"no convergence from {seed} in {4 * FK_NEWTON_STEPS} steps")


def test_tracking_steps_fewer_than_newton_steps():
    assert FK_TRACKING_STEPS <= FK_NEWTON_STEPS


@pytest.mark.parametrize("name", PLATFORMS)
def test_fk_tracking_steps_suffice_along_the_moves(name):
    assert PLATFORMS, "no shipped platform model"
    model = pm2dof.load_model(name)
    sym = Symbols(model.n_legs, model.param_names, model.spec.task_names)
    kin = Kinematics(model.spec, sym)
    # cse: the same SymPy step with its repeated subtrees evaluated once (12 against 730 us a
    # call on rrr4_platform; the same step counts at every sample of the four platforms)
    newton = derivations.plain_lambdify([list(sym.xe), list(sym.qa)], kin.fk_newton_step(),
                                        "numpy", cse=True)
    measure, pv = model.function("measure"), plant_vector(model)
    qa = np.empty(model.n_legs)
    worst, checked = 0, 0
    for move in line_moves(model):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            res = simulate(model, NAController(model), model_move(model, move), settle_time=0.1)
        assert res.outcome == "completed", f"{name} {move}: {res.outcome}"
        measure(np.ascontiguousarray(res.xe[0]), pv, qa)
        est = model.fk(qa)
        for xe in res.xe[1:]:
            measure(np.ascontiguousarray(xe), pv, qa)
            taken, est = _taken_steps(newton, est, qa)
            worst = max(worst, taken)
            checked += 1
        # the tracked pose is Model.fk's (FK_NEWTON_STEPS from [platform] home) at the last qa
        np.testing.assert_allclose(est, model.fk(qa), rtol=0, atol=1e-12)
    assert checked > 100
    assert worst + MARGIN <= FK_TRACKING_STEPS, \
        f"{name}: {worst} Gauss-Newton updates above {FK_NEWTON_TOL} at some sample"
