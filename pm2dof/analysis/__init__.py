# Layer 3, analyses: the paper's experiment, identification, the model report, result files.
"""Analyses on top of :mod:`pm2dof.control`: each returns numbers (dicts, arrays) and text.

* :mod:`.experiment` -- Table 3 in simulation, the Gamma = 0 ablation, repeated runs,
  sensitivity (``pm2dof table3``);
* :mod:`.identify` -- identifiability and least squares (``pm2dof identify``);
* identification from logs (``pm2dof identify --data / --excite / --design-excitation``):
  :mod:`.ident_log` (the log format, LogError), :mod:`.excite` (simulated robot -> log),
  :mod:`.ident_data` (filter, regressor, weighted LS), :mod:`.ident_consistent` (physical
  theta, IPOPT), :mod:`.excitation_design` (D-optimal Fourier excitation, IPOPT),
  :mod:`.ident_report` (printing, --save), :mod:`.ident_study` (the targets over seeds);
* :mod:`.report` -- what the compiled model says over the workspace (``pm2dof report``);
* :mod:`.results` -- atomic result files with provenance.

May import :mod:`pm2dof.core`, :mod:`pm2dof.control`, NumPy and the analysis libraries
(SciPy, CasADi). Never matplotlib: figures live in :mod:`pm2dof.figures`.
"""
