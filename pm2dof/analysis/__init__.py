# Layer 3, analyses: the paper's experiment, the model report, splits, maps, result files.
"""Analyses on top of :mod:`pm2dof.control`: each returns numbers (dicts, arrays) and text.

* :mod:`.experiment` -- Table 3 in simulation, the Gamma = 0 ablation, repeated runs,
  sensitivity (``pm2dof table3``);
* identification (``pm2dof identify``) has its own sub-package beside this one:
  :mod:`pm2dof.identification`;
* :mod:`.report` -- what the compiled model says over the workspace (``pm2dof report``);
* :mod:`.results` -- atomic result files with provenance.

May import :mod:`pm2dof.core`, :mod:`pm2dof.control` and NumPy. Never matplotlib: figures live
in :mod:`pm2dof.figures`.
"""
