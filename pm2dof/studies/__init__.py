# Studies at scale (layer 3): many closed-loop rollouts from a study file, on Dask, into Parquet.
"""Many-rollout studies: robustness to model error, gain maps, when adaptation pays.

``read_study`` (spec) -> ``run_study`` (runner: Dask tasks of ``run_chunk`` in evaluate, rows
into Parquet by store) -> ``study_report`` (report). ``pm2dof study run|report|bench`` are the
commands. Nothing here is imported by ``import pm2dof`` until used.
"""
from pathlib import Path

from .spec import Study, StudyFileError, read_study
from .evaluate import check_study, rollout_setup, run_chunk
from .store import StudyOutError, read_results
from .runner import StudyRunError, run_study

__all__ = ["Study", "StudyFileError", "StudyOutError", "StudyRunError", "read_study",
           "check_study", "run_study", "run_chunk", "rollout_setup", "read_results",
           "SHIPPED_STUDIES", "resolve_study"]

#: the study files that come with pm2dof (robustness, gains, adaptation)
SHIPPED_STUDIES = Path(__file__).resolve().parent / "shipped"


def resolve_study(ref):
    """A shipped study's name (``"robustness"``) -> its file; anything else is a path."""
    s = str(ref)
    if "/" not in s and not s.endswith(".toml") and (SHIPPED_STUDIES / f"{s}.toml").is_file():
        return SHIPPED_STUDIES / f"{s}.toml"
    return Path(s).expanduser()
