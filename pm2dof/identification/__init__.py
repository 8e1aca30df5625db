# Layer 3, identification: which parameters the regressor sees, logs, excitations, the fit.
"""Identification of theta (eq. 13: S^T tau_a = Y theta) from logs of encoder angles and torques.

One module per job (``pm2dof identify SUBCOMMAND`` in brackets):

* :mod:`.base` -- identifiability: the base parameters and the null space (``report``);
* :mod:`.log` -- the log format: read, write, check against a model (:class:`.log.LogError`);
* :mod:`.signals` -- what an excitation is: the default multi-sine, the Fourier series and
  its file, each sampled as a :class:`pm2dof.Trajectory`;
* :mod:`.excitation` -- an excitation run on the simulated robot, recorded as a log
  (``excite``);
* :mod:`.design` -- the D-optimal Fourier excitation, CasADi + IPOPT (``design``);
* :mod:`.fit` -- the least-squares pipeline: filter, regressor, weighted least squares (``fit``);
* :mod:`.consistent` -- the physically consistent theta (CasADi + IPOPT);
* :mod:`.jobs` -- what ``fit`` runs: a log read or simulated, the fit, Table 3 with its theta
  handed in, ``--save``;
* :mod:`.report` -- the printed and JSON report of a fit;
* :mod:`.monte_carlo` -- the accuracy targets over random plants and encoder noise
  (``monte-carlo``).

May import :mod:`pm2dof.core`, :mod:`pm2dof.control`, :mod:`pm2dof.infra`, NumPy and, inside
the functions that need them, SciPy, CasADi and pyarrow (the ``ident`` extra): importing a
module of this package loads none of them.
"""
