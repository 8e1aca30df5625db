# The closed-loop rollout the bench times: one `accumulate` call over a long move, set up once.
import numpy as np

from ..control.plant import plant_vector
from ..core.layout import Layout
from .baselines import long_trajectory

__all__ = ["rollout_call"]


def rollout_call(model, na, n_roll):
    """The closed-loop rollout (encoder, NA step, the plant's RK4 substeps per sample) of
    ``na`` on ``model`` over ``n_roll`` samples of the high-speed move back and forth.

    Returns (run, y, long, speed): ``run(k)`` runs the ``na_closed_loop`` ``accumulate`` call
    k times from the same initial state, writing the outputs (``cl_output`` layout) into
    ``y`` (n_roll, size); ``long`` the reference, ``speed`` its move's name."""
    lays = {k: Layout(k, v) for k, v in model.manifest["layouts"].items()}
    n = model.n_legs
    long, speed = long_trajectory(model, n_roll)
    f_cl = model.function("na_closed_loop")
    plant = plant_vector(model)
    p = np.concatenate([na.params, plant])
    x0 = np.zeros(lays["cl_state"].size)
    X = lays["cl_state"].unpack(x0)
    X["xe"][:] = long.xd[0]
    qa0 = np.empty(n)
    model.function("measure")(long.xd[0], plant, qa0)
    C0 = lays["ctrl_state"].unpack(X["ctrl_state"])
    C0["xe_prev"][:] = model.fk(qa0)
    C0["theta_hat"][:] = na.theta0
    lay_u = lays["cl_input"]                     # the reference, one row per sample
    u = np.empty((n_roll, lay_u.size))
    for field, rows in (("xd", long.xd), ("xd_dot", long.xd_dot), ("xd_ddot", long.xd_ddot)):
        u[:, lay_u.slices[field]] = rows
    y = np.empty((n_roll, lays["cl_output"].size))
    x = x0.copy()

    def run(k):
        for _ in range(k):
            x[:] = x0
            f_cl.accumulate(x, u, p, y)

    return run, y, long, speed
