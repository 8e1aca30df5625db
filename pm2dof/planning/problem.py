# What one time-optimal plan is computed for: the model, the path, the limits, theta, the split.
"""A :class:`PlanProblem`: the bundle every stage of the time-optimal planner takes (the
coefficients, the passes, the checks between the grid points), built once in
:func:`pm2dof.plan_time_optimal` and :func:`pm2dof.plan_smooth`. The grid is not part of it:
it changes as the planner refines it."""
from dataclasses import dataclass, field

import numpy as np

from .stages import limits, params

__all__ = ["PlanProblem"]


@dataclass(frozen=True, eq=False)
class PlanProblem:
    """The path, the robot and its limits of one plan.

    Attributes
    ----------
    model : Model
    path : TaskPath
    tau_max : ndarray (n,)
        The torque limits the plan respects, N m (the margin applied).
    theta : ndarray (5n,)
        Dynamic parameters, checked physical.
    split : {"min_norm", "min_max"}
    params : ndarray
        ``theta`` packed as the generated passes' ``path_params`` vector.
    """

    model: object = field(repr=False)
    path: object = field(repr=False)
    tau_max: np.ndarray
    theta: np.ndarray = field(repr=False)
    split: str
    params: np.ndarray = field(repr=False)

    @classmethod
    def create(cls, model, path, tau_max=None, split="min_max", theta=None, margin=1.0):
        """The problem with ``tau_max`` * ``margin`` (:func:`pm2dof.planning.stages.limits`)
        and theta checked (:func:`pm2dof.planning.stages.params`), in that order."""
        tau_lim = limits(model, tau_max, margin)
        prm, th = params(model, theta)
        return cls(model, path, tau_lim, th, split, prm)
