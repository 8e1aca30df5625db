# Rollouts of Python-level controllers: one Python step per sample against the generated plant.
"""Closed loops whose controller is Python (e.g. the nonlinear MPC example), for
:func:`pm2dof.simulate`.

Each sample k, as in the generated closed loops: the encoder reads the true pose (generated
``measure``), the controller's :meth:`PythonController.step` computes the torque, clipped to
``tau_max``, and the plant takes ``rk4_substeps`` generated RK4 steps (``plant_step``) under
it. The rows are the ``cl_output`` layout of the C closed loops, so :func:`pm2dof.simulate`
turns them into the same :class:`pm2dof.SimResult`.
"""
import numpy as np

from ..core.status import Status

__all__ = ["PythonController", "python_rollout"]


class PythonController:
    """Base of a controller written in Python, run by :func:`pm2dof.simulate` sample by sample.

    A subclass sets ``model`` and ``sample_period`` and implements :meth:`reset` and
    :meth:`step`; ``theta0`` (the model's theta it uses, default Tables 1-2) is reported as
    ``SimResult.theta_hat``. ``status`` after a step is a :class:`pm2dof.Status`.
    """

    _law = "python"

    def __init__(self, model, sample_period=None, theta0=None):
        self.model = model
        self.sample_period = model.checked_period(sample_period)
        self.theta0 = np.array(model.theta_nominal if theta0 is None else theta0, dtype=float)
        self.status = Status.OK

    def reset(self, qa0, trajectory):
        """Start at rest at the measured active coordinates ``qa0`` (n,) (rad for a revolute
        actuator, m for a linear one), to follow ``trajectory`` (a :class:`pm2dof.Trajectory`)."""
        raise NotImplementedError

    def step(self, k, qa, xd, xd_dot, xd_ddot):
        """Sample ``k``: measured active coordinates (n,) (rad or m by kind) and the desired
        motion -> efforts (n,) (N*m for a revolute actuator, N for a linear one; clipped to
        ``tau_max`` by the rollout; a clip sets status SATURATED)."""
        raise NotImplementedError


def python_rollout(model, controller, traj, plant, theta_hat0=None):
    """One rollout of a :class:`PythonController`: (None: no closed-loop state to report, y
    (N, ny) rows of ``cl_output``, its Layout). A sample whose plant state stops being finite
    ends the run (later rows NaN, as the C closed loops leave them)."""
    n, m, substeps = model.n_legs, model.dof, model.spec.rk4_substeps
    T = controller.sample_period
    ylay = model.layout("cl_output")
    measure, step = model.function("measure"), model.function("plant_step")
    tau_max = np.asarray(model.spec.limits["tau_max"], dtype=float)
    theta = controller.theta0 if theta_hat0 is None else np.asarray(theta_hat0, dtype=float)
    y = np.full((len(traj.t), ylay.size), np.nan)
    Y = ylay.unpack(y)
    z, nxt, qa = np.concatenate([traj.xd[0], np.zeros(m)]), np.empty(2 * m), np.empty(n)
    h = np.array([T / substeps])
    measure(np.ascontiguousarray(traj.xd[0]), plant, qa)
    controller.reset(qa.copy(), traj)
    for k in range(len(traj.t)):
        measure(z[:m].copy(), plant, qa)
        tau = np.asarray(controller.step(k, qa.copy(), traj.xd[k], traj.xd_dot[k],
                                         traj.xd_ddot[k]), dtype=float)
        status = controller.status
        if np.any(np.abs(tau) > tau_max) and status == Status.OK:
            status = Status.SATURATED
        tau = np.clip(tau, -tau_max, tau_max)
        Y["xe"][k], Y["xed"][k], Y["tau_a"][k] = z[:m], z[m:], tau
        Y["status"][k], Y["theta_hat"][k] = int(status), theta
        for _ in range(substeps):
            step(z, tau, plant, h, nxt)
            z[:] = nxt
        if not np.isfinite(z).all():
            break
    return None, y, ylay
