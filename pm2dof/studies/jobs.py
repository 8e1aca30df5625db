# What `pm2dof study report DIR` does: read a study's rows, summarise them, write summary.json.
"""The job of ``pm2dof study report DIR``: :func:`run_report` reads the rows a study wrote
(:func:`.store.read_results`), summarises them (:func:`.report.summarise`) and writes
``DIR/summary.json``; it returns a :class:`StudyReport` (its text:
:func:`.report.format_report`; its figures: :func:`pm2dof.figures.studies.study_figures`)."""
from dataclasses import dataclass
from pathlib import Path

from ..infra.results import write_json
from .report import columns_of, summarise
from .spec import GRID_KEYS, StudyFileError
from .store import read_results

__all__ = ["run_report", "StudyReport"]


@dataclass(frozen=True)
class StudyReport:
    """What ``pm2dof study report`` found (:func:`run_report`).

    Attributes
    ----------
    summary : dict
        The command's ``--json`` (:func:`.report.summarise`).
    columns : dict
        {column: ndarray} of every row (:func:`.report.columns_of`), for the figures.
    info : dict
        ``DIR/study.json`` (the study, its provenance), with the ``grid_keys`` found.
    """
    summary: dict
    columns: dict
    info: dict

    @property
    def provenance(self):
        """The study's provenance (``study.json``; {} when it has none)."""
        return self.info.get("provenance", {})


def run_report(out):
    """``pm2dof study report DIR``: the summary of the rows in ``out``, also written to
    ``out/summary.json`` (with the study's provenance); returns a :class:`StudyReport`.

    Raises
    ------
    StudyFileError
        ``out`` holds no rows yet.
    """
    info, table = read_results(out)
    cols = columns_of(table)
    if not len(cols.get("rollout", [])):
        raise StudyFileError(f"{out}: no rows yet; run `pm2dof study run` with --out {out}")
    info = {**info, "grid_keys": [k for k in cols if k in GRID_KEYS]}
    s = summarise(cols, info)
    write_json(Path(out) / "summary.json", {**s, "provenance": info.get("provenance")})
    return StudyReport(s, cols, info)
