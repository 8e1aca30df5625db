# Is the plant's RK4 substep stable? The smoothed Coulomb law is stiff near rest.
"""The stability of the simulated plant's integration (a problem found on linear actuators).

The plant integrates eq. 10 with its truth's friction, whose Coulomb term is smoothed over
``coulomb_smoothing_velocity`` = eps. Near rest that law is a steep viscous one: its slope at
v = 0 is d_i = (fc_i + fs_i) / eps + fv_i per actuator, so a small task velocity decays at the
rates lambda = eig(Me^-1 S^T diag(d) S) (real and positive: Me is symmetric positive definite).
Classical RK4 is stable on the negative real axis for h lambda <= 2.785; beyond, the state
at rest grows by |R(-h lambda)| > 1 per substep from rounding (a 3-PRR with 1 mm/s smoothing
and 3 substeps of 0.67 ms had h lambda = 3.9: a rest of 1e-15 m/s grew x77 per sample).
:func:`check_plant_step` refuses such a plant before it is simulated.
"""
import math

import numpy as np

from ..core.errors import ArgumentError
from .plant import plant_truth, theta_truth

__all__ = ["RK4_STABLE_Z", "rest_decay_rate", "check_plant_step", "rest_poses"]

#: the largest h * lambda accepted: RK4's real stability bound 2.785, with 10 % margin
RK4_STABLE_Z = 2.5


def rest_decay_rate(model, xe, truth=None):
    """The fastest decay rate of a task velocity at rest under the plant's friction, 1/s.

    Parameters
    ----------
    model : Model
    xe : array_like (m,)
        The pose (m = ``model.dof``).
    truth : dict, optional
        The plant truth (default :func:`pm2dof.plant_truth`).

    Returns
    -------
    float
        max eig(Me^-1 S^T diag(d) S), d_i = (fc_i + fs_i) / eps + fv_i (the slope at v = 0 of
        the plant's smoothed Coulomb + Stribeck + viscous law).
    """
    (x, q, S), = rest_poses(model, [xe])
    return _rates(model, truth, [(x, q, S)])[0][0]


def _rates(model, truth, kin):
    """[(rate, xe)] at each (xe, q, S) of ``kin`` under the plant ``truth``."""
    t = plant_truth(model) if truth is None else truth
    d = (np.asarray(t["fc"], float) + np.asarray(t["fs"], float)) \
        / float(t["coulomb_smoothing_velocity"]) + np.asarray(t["fv"], float)
    theta = theta_truth(model, t)
    return [(float(np.linalg.eigvals(np.linalg.solve(model.Me(q, theta),
                                                     S.T @ (d[:, None] * S))).real.max()), x)
            for x, q, S in kin]


def rest_poses(model, poses):
    """The poses :func:`check_plant_step` checks of ``poses`` (K, m): nine of them, the first
    and the last included (the rate varies smoothly along a move), as [(xe, q, S)]: to check
    many plant truths on the same move, compute them once."""
    poses = np.atleast_2d(np.asarray(poses, dtype=float))
    poses = poses[np.unique(np.linspace(0, len(poses) - 1, min(len(poses), 9)).astype(int))]
    out = []
    for x in poses:
        q = model.ik(x)
        out.append((x, q, model.S(q)))
    return out


def check_plant_step(model, poses, truth=None):
    """Raise if the plant's RK4 substep is unstable at rest at any of ``poses``.

    Parameters
    ----------
    model : Model
    poses : array_like (K, m), or list
        Poses, e.g. a trajectory's samples: nine of them are checked, the first and the last
        included (the rate varies smoothly along a move); or what :func:`rest_poses` returns.
    truth : dict, optional
        The plant truth (default :func:`pm2dof.plant_truth`).

    Raises
    ------
    ArgumentError
        If h lambda > :data:`RK4_STABLE_Z` (h = sample_period / rk4_substeps), naming the
        pose, the rate and the fewest ``[model] rk4_substeps`` that would do.
    """
    T = float(model.spec.sensing["sample_period"])
    substeps = int(model.spec.rk4_substeps)
    if not isinstance(poses, list):
        poses = rest_poses(model, poses)
    lam, at = max(_rates(model, truth, poses), key=lambda pair: pair[0])
    z = lam * T / substeps
    if z > RK4_STABLE_Z:
        need = math.ceil(lam * T / RK4_STABLE_Z)
        raise ArgumentError(
            f"model {model.name!r}: the simulated plant is numerically unstable near rest at "
            f"xe = {np.round(at, 6).tolist()}: its friction's slope at zero velocity "
            f"((fc + fs) / coulomb_smoothing_velocity + fv, through Me) damps at {lam:.4g} 1/s, "
            f"and RK4 with h = sample_period / rk4_substeps = {T / substeps:.4g} s gives "
            f"h lambda = {z:.3g} > {RK4_STABLE_Z} (stable to 2.785). Set [model] rk4_substeps "
            f">= {need} in {model.spec.path}, or widen [plant] coulomb_smoothing_velocity")
