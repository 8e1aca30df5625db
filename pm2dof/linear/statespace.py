# python-control state space of the linearised robot, named states and inputs.
"""``statespace(model, xe, xed, tau_a)``: a ``control.StateSpace`` of the linearisation.

python-control is an optional dependency (the ``control`` extra), imported when called.
"""
import numpy as np

from ..core.model import require_model

__all__ = ["statespace", "STATE_NAMES", "state_names"]

#: the state of a point end effector's linearisation: [xe, xed] (m, m/s)
STATE_NAMES = ("x", "y", "xd", "yd")


def state_names(model):
    """The linearisation's state [xe, xed] named from ``model.task_names``: ("x", "y", "xd",
    "yd") (:data:`STATE_NAMES`) for a point, ("x", "y", "phi", "xd", "yd", "phid") for a
    platform."""
    return tuple(model.task_names) + tuple(f"{c}d" for c in model.task_names)


def _control():
    try:
        import control
    except ModuleNotFoundError as exc:
        raise ModuleNotFoundError(
            f"pm2dof.statespace needs python-control, which is not installed: "
            f"pip install 'pm2dof[control]' ({exc})", name="control") from None
    return control


def statespace(model, xe, xed, tau_a, theta=None, *, discrete=False, period=None):
    """The linearisation of the robot at [xe, xed], tau_a as a python-control ``StateSpace``.

    States [xe, xed] (:func:`state_names`: ``x, y, xd, yd``, m and m/s, for a point;
    ``x, y, phi, xd, yd, phid`` for a platform), inputs ``tau1..taun`` (N*m), outputs the
    states (C = I, D = 0). (A, B) are :meth:`pm2dof.Model.linearize`'s.

    Parameters
    ----------
    model : Model
    xe, xed : array_like (m,)
        The operating state, m and m/s (phi in rad, rad/s).
    tau_a : array_like (n,)
        The operating torques, N*m (e.g. from :meth:`Model.inverse_dynamics` and
        :meth:`Model.torque_splits`).
    theta : array_like (p,), optional
        Default Tables 1-2.
    discrete : bool
        False (default): continuous. True: the sampled step over ``period``, a discrete-time
        system with ``dt = period``.
    period : float, optional
        The sample period, s (default ``[sensing] sample_period``).

    Returns
    -------
    control.StateSpace

    Examples
    --------
    >>> import numpy as np, pm2dof
    >>> m = pm2dof.load_model()
    >>> sys = pm2dof.statespace(m, [0.245, 0.265], [0.0, 0.0], np.zeros(3), discrete=True)
    >>> sys.dt, sys.input_labels
    (0.002, ['tau1', 'tau2', 'tau3'])
    """
    require_model(model)
    control = _control()
    T = model.checked_period(period)
    A, B = model.linearize(xe, xed, tau_a, theta, discrete=discrete, period=T)
    n, names = model.n_legs, list(state_names(model))
    return control.ss(A, B, np.eye(len(names)), np.zeros((len(names), n)),
                      dt=float(T) if discrete else 0, states=names,
                      inputs=[f"tau{i + 1}" for i in range(n)], outputs=names,
                      name=f"{model.name}_linearised")
