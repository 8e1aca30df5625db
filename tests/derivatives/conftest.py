# Fixtures of the derivative tests.
import numpy as np
import pytest

import pm2dof


def _first_point(m):
    """The start of the model file's first move, m (pm2dof.model_move reads the moves)."""
    return np.array(pm2dof.model_move(m, next(iter(m.spec.trajectories))).xd[0])


@pytest.fixture(scope="session")
def first_point():
    return _first_point


def _rk4_numpy(model, x, tau, theta, T):
    """The sampled step written out in NumPy over model.forward_dynamics (independent of the
    generated RK4): rk4_substeps classical RK4 steps of T / rk4_substeps, x = [xe, xed] (2m,)."""
    s, m = model.spec.rk4_substeps, model.dof
    h = T / s

    def f(z):
        return np.concatenate([z[m:], model.forward_dynamics(z[:m], z[m:], tau, theta)])
    for _ in range(s):
        k1 = f(x)
        k2 = f(x + h / 2 * k1)
        k3 = f(x + h / 2 * k2)
        k4 = f(x + h * k3)
        x = x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return x


@pytest.fixture(scope="session")
def rk4_numpy():
    return _rk4_numpy
