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
