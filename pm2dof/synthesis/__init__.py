# Design studies: search a model file's [design] for the geometry that serves a task best.
"""Design studies (docs/design-study-file.md).

* :mod:`.spec` -- the design study file: :func:`read_design_study`, :class:`DesignStudy`,
  :class:`Objective`, :func:`with_overrides` (``--quick``, ``--optimizer``, ``--grid``);
* :mod:`.region` -- the task region as a grid of poses and its measures, one batched call into
  the generated C per function;
* :mod:`.objectives` -- the measures (:data:`MEASURES`), :func:`evaluate_design` at one
  design and :func:`evaluate_batch` for an optimiser.

Imports core, control, analysis, planning, linear and studies; pymoo only in the optimiser.
"""
from .objectives import MEASURES, evaluate_batch, evaluate_design, evaluate_with_status
from .spec import (
                   DesignStudy,
                   DesignStudyError,
                   Objective,
                   find_design_study,
                   read_design_study,
                   shipped_design_studies,
                   with_overrides,
)

__all__ = ["MEASURES", "evaluate_batch", "evaluate_design", "evaluate_with_status",
           "DesignStudy", "DesignStudyError", "Objective", "find_design_study",
           "read_design_study", "shipped_design_studies", "with_overrides"]
