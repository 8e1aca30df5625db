# Layer 3, analyses: the paper's experiment, identification, the model report, result files.
"""Analyses on top of :mod:`pm2dof.control`: each returns numbers (dicts, arrays) and text.

* :mod:`.experiment` -- Table 3 in simulation, the Gamma = 0 ablation, repeated runs,
  sensitivity (``pm2dof table3``);
* :mod:`.identify` -- identifiability and least squares (``pm2dof identify``);
* :mod:`.report` -- what the compiled model says over the workspace (``pm2dof report``);
* :mod:`.results` -- atomic result files with provenance.

May import :mod:`pm2dof.core`, :mod:`pm2dof.control`, NumPy and the analysis libraries
(SciPy, CasADi). Never matplotlib: figures live in :mod:`pm2dof.figures`.
"""
