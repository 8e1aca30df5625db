# Layer 3, linear: linearisation along trajectories, python-control state space, LQR design.
"""Linear models of the robot and the controllers designed on them, on :mod:`pm2dof.core`.

* :mod:`.trajectory` -- :func:`linearize_trajectory`: time-varying (A_k, B_k) along a desired
  motion, the torque along it from the inverse dynamics and the model's split (each quantity
  one :meth:`Function.map` call into the generated C);
* :mod:`.statespace` -- :func:`statespace`: a ``control.StateSpace`` (python-control, the
  ``control`` extra, imported on use) with named states and inputs;
* :mod:`.lqr` -- :func:`lqr_gains` (time-varying LQR by a backward Riccati recursion, SciPy's
  DARE for its end) and :class:`LQRController` (its generated C step).

Above the runtime (core, control): SciPy and python-control are imported here only.
"""
from .lqr import LQRController, lqr_gains
from .statespace import STATE_NAMES, statespace
from .trajectory import LinearTrajectory, linearize_trajectory

__all__ = ["linearize_trajectory", "LinearTrajectory", "statespace", "STATE_NAMES",
           "lqr_gains", "LQRController"]
