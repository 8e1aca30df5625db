# The plant's stiffness at rest against its RK4 substep, computed here from Me, S and friction.
"""``h_lambda(model, poses, truth)``: the largest h lambda of the simulated plant at rest.

Computed from the model's Me and S and the plant truth's friction slope at zero velocity,
independently of :mod:`pm2dof.control.plant_step` (whose check it is compared with).
"""
import numpy as np

from pm2dof import theta_truth


def h_lambda(model, poses, truth):
    """The largest h lambda over ``poses``: lambda = max eig(Me^-1 S^T diag(d) S) with d the
    slope of the plant's smoothed friction at zero velocity, h = T / rk4_substeps."""
    d = ((np.asarray(truth["fc"]) + np.asarray(truth["fs"]))
         / truth["coulomb_smoothing_velocity"] + np.asarray(truth["fv"]))
    th = theta_truth(model, truth)
    h = model.spec.sensing["sample_period"] / model.spec.rk4_substeps
    lam = 0.0
    for x in poses:
        q = model.ik(x)
        S = model.S(q)
        lam = max(lam, float(np.max(np.linalg.eigvals(
            np.linalg.solve(model.Me(q, th), S.T @ (d[:, None] * S))).real)))
    return h * lam
