# Below the analysis layers: result files (provenance, atomic writing) and progress reporting.
"""Infrastructure the layers above :mod:`pm2dof.control` share, with no analysis in it.

* :mod:`.results` -- atomic result files (JSON, PNG) carrying their provenance;
* :mod:`.progress` -- stage lines and progress bars for long jobs.

Used by analysis, identification, planning, studies, the bench, figures and the CLI, so none
of them needs another layer-3 package for it. May import :mod:`pm2dof.core` (its errors, its
version, the shipped paths), the standard library, NumPy and tqdm. :mod:`pm2dof.core` and
:mod:`pm2dof.control` do not import it.
"""
