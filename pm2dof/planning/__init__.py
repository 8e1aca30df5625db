# Layer 3, motion planning: task-plane paths timed as fast as the motors allow, using the redundancy.
"""Motion planning along paths in the task plane.

* :mod:`.paths` -- :class:`TaskPath` (line, arc, blended polyline, C2 spline, concat), by arc
  length (:mod:`.spline` the spline piece);
* :mod:`.check` -- :func:`check_path`: workspace and singularities along a path;
* :mod:`.kinematic` -- :func:`plan_kinematic`: the S-curve of pm2dof.control along a path;
* :mod:`.stages`, :mod:`.grid`, :mod:`.topp` -- :func:`plan_time_optimal`: time-optimal under
  torque limits, friction included, in generated C (:mod:`.grid`: the grid refined in place);
* :mod:`.smooth` -- :func:`plan_smooth`: torque-rate-limited near-time-optimal (CasADi/IPOPT;
  :mod:`.watch` its progress while IPOPT runs, and Ctrl-C);
* :mod:`.plan` -- :class:`Plan`, the sampled :class:`pm2dof.Trajectory`;
* :mod:`.torques` -- inverse dynamics along a timed path (Me, Ce, StF, then the split);
* :mod:`.pathfile` -- path files (TOML) for ``pm2dof plan``, and :func:`model_move_path`: a model
  file's move (a line, or ``path = ...``) as a path;
* :mod:`.jobs` -- what ``pm2dof plan`` runs (:func:`.jobs.run_plan`), :mod:`.report` what it
  prints and its CSV format.

Imports :mod:`pm2dof.core`, :mod:`pm2dof.control` and NumPy; CasADi only inside
:func:`plan_smooth`.
"""
from .check import check_path
from .kinematic import plan_kinematic
from .pathfile import model_move_path
from .paths import TaskPath
from .plan import PathProfile, Plan
from .smooth import plan_smooth
from .topp import plan_time_optimal

__all__ = ["TaskPath", "check_path", "plan_kinematic", "plan_time_optimal", "plan_smooth",
           "Plan", "PathProfile", "model_move_path"]
