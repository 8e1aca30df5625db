# Layer 2, control: the paper's controllers, desired trajectories and closed-loop rollouts.
"""Controllers, trajectories and rollouts, on top of :mod:`pm2dof.core`.

* :mod:`.controllers` -- :class:`NAController` (eqs. 14-29), :class:`APDController` (eq. 40),
  ``CTCController``: one call into generated C per sample;
* :mod:`.lqr` -- the time-varying LQR's step on a planned gain schedule (the gains are
  planned by :mod:`pm2dof.linear.lqr`);
* :mod:`.settings` -- :class:`ControlSettings`: what every controller's step shares besides
  its gains (sample period, limits, split, thresholds), defaulted and checked in one place;
* :mod:`.rules` -- what each entry of a controller's parameters must be: one table, read by
  the settings, the constructors and written into the exported C's init;
* :mod:`.trajectory` -- jerk-limited straight-line moves (:func:`line`, :func:`paper_move`);
* :mod:`.plant` -- the simulated robot's truth (:func:`plant_truth`, :func:`theta_truth`);
* :mod:`.simulate` -- :func:`simulate`: a whole closed-loop rollout in one call into C.

Imports :mod:`pm2dof.core`, the standard library and NumPy only.
"""
from .controllers import STATUS_NAMES, APDController, NAController
from .plant import plant_truth, theta_truth
from .settings import ControlSettings
from .simulate import SimResult, check_trajectory, rmse, simulate
from .trajectory import SCurve, Trajectory, TrajectoryError, line, paper_move

__all__ = ["NAController", "APDController", "ControlSettings", "STATUS_NAMES", "simulate",
           "SimResult",
           "check_trajectory", "plant_truth", "theta_truth", "rmse", "line", "paper_move",
           "Trajectory", "SCurve", "TrajectoryError"]
