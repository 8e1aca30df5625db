# Layer 3, analyses: the paper's experiment, the model report, splits, maps.
"""Analyses on top of :mod:`pm2dof.control`: each returns numbers (dicts, arrays) and text.

* :mod:`.experiment` -- Table 3 in simulation, the Gamma = 0 ablation, repeated runs,
  sensitivity (``pm2dof table3``);
* identification (``pm2dof identify``) has its own sub-package beside this one:
  :mod:`pm2dof.identification`;
* :mod:`.report` -- what the compiled model says over the workspace (``pm2dof report``);
* result files with provenance and progress bars are below the layers, in
  :mod:`pm2dof.infra`.

May import :mod:`pm2dof.core`, :mod:`pm2dof.control`, :mod:`pm2dof.infra`,
:mod:`pm2dof.linear` and NumPy. Never matplotlib: figures live in :mod:`pm2dof.figures`.
"""
