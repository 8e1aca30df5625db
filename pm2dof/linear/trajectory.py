# Time-varying linearisation along a desired motion: (A_k, B_k) and the feedforward torques.
"""(A_k, B_k) of the robot along a :class:`pm2dof.Trajectory`, each quantity one call into C.

At sample k the state is the desired one, x_k = [xd_k, xd_dot_k], and the torque the one that
produces the desired acceleration in the model: the task force of the inverse dynamics
u_k = Me xd_ddot + Ce xd_dot + S^T f_a (eqs. 10-12) split among the actuators by the model's
split (``[control] split``: min-norm, eq. 21, by default). Every quantity (ik, inverse
dynamics, split, Jacobians) is one :meth:`pm2dof.core.binding.Function.map` call over all K
samples.
"""
from dataclasses import dataclass

import numpy as np

from ..control.settings import checked_split
from ..control.simulate import check_trajectory
from ..control.trajectory import require_trajectory
from ..core import binding
from ..core.derivatives import continuous_AB
from ..core.errors import ArgumentError, NonFiniteError, SingularityError
from ..core.model import require_model

__all__ = ["linearize_trajectory", "LinearTrajectory"]


@dataclass(frozen=True, eq=False)
class LinearTrajectory:
    """The linearisation of the robot along a trajectory (K samples).

    Attributes
    ----------
    A : ndarray (K, 2m, 2m)
        d x_{k+1} / d x_k (discrete) or d xdot / d x (continuous) at sample k; state
        [xe, xed] (m = ``model.dof``; [x, y, xd, yd], m and m/s, for a point).
    B : ndarray (K, 2m, n)
        The same w.r.t. the torques tau_1..tau_n (N*m).
    x : ndarray (K, 2m)
        The operating states [xd_k, xd_dot_k].
    tau_a : ndarray (K, n)
        The operating torques: the inverse dynamics' task force split by ``split``, N*m.
    u : ndarray (K, m)
        The task force S^T tau_a of the inverse dynamics (eqs. 10-12), N.
    theta : ndarray (p,)
        The parameters of the model linearised.
    discrete : bool
        True: (A, B) of one sampled step of ``period`` s (zero-order hold, the model file's RK4
        sub-steps); False: of the continuous dynamics.
    period : float
        The sample period, s.
    split : str
        The torque split of ``tau_a``.
    """
    A: np.ndarray
    B: np.ndarray
    x: np.ndarray
    tau_a: np.ndarray
    u: np.ndarray
    theta: np.ndarray
    discrete: bool
    period: float
    split: str


def _map(model, short, K, inputs, sizes_out):
    """``<name>_<short>`` at K points in one C call; outputs (K, size) arrays."""
    f = model.function(short)
    outs = [np.empty((K, k)) for k in sizes_out]
    try:
        f.map(K, *inputs, *outs)
    except binding.NonFiniteOutputError as exc:   # finite inputs, a non-finite result
        raise NonFiniteError(f"linearize_trajectory: {exc}") from None
    except ValueError as exc:                    # an input the binding refuses, named
        raise ArgumentError(f"linearize_trajectory: {exc}") from None
    return outs


def _check_sing(model, sing, short):
    bad = ~((sing[:, 0] >= model.singularity_threshold)
            & (sing[:, 1] >= model.parallel_singularity_threshold))
    if bad.any():
        k = int(np.argmax(bad))
        raise SingularityError(f"linearize_trajectory ({short}) at sample {k}: "
                               f"{model.singularity_message(sing[k])}")


def linearize_trajectory(model, trajectory, theta=None, *, discrete=True, split=None,
                         period=None):
    """Time-varying linearisation (A_k, B_k) along ``trajectory``, one C call per quantity.

    Parameters
    ----------
    model : Model
    trajectory : pm2dof.Trajectory
        The desired motion (its samples are checked as :func:`pm2dof.simulate` checks them).
    theta : array_like (p,), optional
        The model's parameters (default Tables 1-2, ``model.theta_nominal``).
    discrete : bool
        True (default): (A_k, B_k) of the sampled step x_{k+1} = F(x_k, tau_k) over ``period``
        (:meth:`Model.sampled_step_jacobians`); False: of the continuous dynamics
        (:meth:`Model.linearize`).
    split : {"min_norm", "min_max", "preload"}, optional
        How the inverse dynamics' task force is shared among the actuators (default
        ``[control] split``).
    period : float, optional
        s; default the trajectory's period.

    Returns
    -------
    LinearTrajectory

    Examples
    --------
    >>> import pm2dof
    >>> m = pm2dof.load_model()
    >>> lin = pm2dof.linearize_trajectory(m, pm2dof.paper_move("high"))
    >>> lin.A.shape[1:], lin.B.shape[1:]
    ((4, 4), (4, 3))
    """
    require_model(model)
    require_trajectory(trajectory)
    ctl, n, m = model.spec.control, model.n_legs, model.dof
    split = checked_split(model.spec, split)
    theta = model.checked_theta(theta)
    T = model.checked_period(trajectory.period if period is None else period)
    check_trajectory(model, trajectory)
    xd, xd_dot, xd_ddot = trajectory.xd, trajectory.xd_dot, trajectory.xd_ddot
    K = len(xd)
    q, = _map(model, "ik", K, (xd,), (2 * n,))
    u, sing = _map(model, "inverse_dynamics", K, (xd, xd_dot, xd_ddot, theta), (m, 2))
    _check_sing(model, sing, "inverse_dynamics")
    lim = model.spec.limits
    t_mn, t_mm, _, t_pl, _, _ = _map(
        model, "torque_splits", K, (q, u, np.asarray(lim["tau_max"], float),
                                    np.asarray(ctl["preload_sign"], float),
                                    np.asarray(ctl["preload"], float)), (n, n, 1, n, 1, 2))
    tau = {"min_norm": t_mn, "min_max": t_mm, "preload": t_pl}[split]
    x = np.ascontiguousarray(np.hstack([xd, xd_dot]))
    A = np.zeros((K, 2 * m, 2 * m))
    B = np.zeros((K, 2 * m, n))
    if discrete:
        _, dx, dtau, sing = _map(model, "sampled_step_jacobians", K, (x, tau, theta, T),
                                 (2 * m, 4 * m * m, 2 * m * n, 2))
        A[:], B[:] = dx.reshape(K, 2 * m, 2 * m), dtau.reshape(K, 2 * m, n)
    else:
        _, dxe, dxed, dtau, _, sing = _map(model, "forward_dynamics_jacobians", K,
                                           (xd, xd_dot, tau, theta),
                                           (m, m * m, m * m, m * n, m * len(theta), 2))
        A[:], B[:] = continuous_AB(dxe.reshape(K, m, m), dxed.reshape(K, m, m),
                                   dtau.reshape(K, m, n))
    _check_sing(model, sing, "jacobians")
    for a in (A, B, x, tau, u, theta):
        a.setflags(write=False)
    return LinearTrajectory(A=A, B=B, x=x, tau_a=tau, u=u, theta=theta, discrete=discrete,
                            period=T, split=split)
