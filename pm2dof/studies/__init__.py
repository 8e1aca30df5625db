# Studies at scale (layer 3): many closed-loop rollouts from a study file, on Dask, into Parquet.
"""Many-rollout studies: robustness to model error, gain maps, when adaptation pays.

``read_study`` (spec) -> ``run_study`` (runner: Dask tasks of ``run_chunk`` in evaluate, rows
into Parquet by store) -> ``run_report`` (jobs: the summary of report, written beside the rows). ``pm2dof study run|report|bench`` are the
commands. Nothing here is imported by ``import pm2dof`` until used.
"""
from .evaluate import rollout_setup, run_chunk
from .runner import StudyRunError, run_study
from .spec import SHIPPED_STUDIES, Study, StudyFileError, check_study, read_study, resolve_study
from .store import StudyOutError, read_results

__all__ = ["Study", "StudyFileError", "StudyOutError", "StudyRunError", "read_study",
           "check_study", "run_study", "run_chunk", "rollout_setup", "read_results",
           "SHIPPED_STUDIES", "resolve_study"]
