# Old import paths (0.1's flat modules, 0.2's identification): each fails naming its new place.
"""pm2dof 0.2 moved its flat modules into layers (``core``, ``control``, ``analysis``, ...);
pm2dof 0.3 moved identification out of ``analysis`` into its own sub-package,
``identification``.

An old path such as ``pm2dof.controllers`` or ``pm2dof.simulate`` (the module) does not load
silently from somewhere else: the import fails with a :class:`ModuleNotFoundError` that names
the new place. One rule for every old path, because some old module names are now public
functions (``pm2dof.simulate`` is the function :func:`pm2dof.simulate`), and an alias could not
be both.
"""
import sys

__all__ = ["MOVED", "install"]

#: old module -> (its new module, what users imported from it and where to get it now[, the
#: version that moved it, default 0.2])
MOVED = {
    "pm2dof.controllers": ("pm2dof.control.controllers",
                           "from pm2dof import NAController, APDController, STATUS_NAMES"),
    "pm2dof.simulate": ("pm2dof.control.simulate",
                        "from pm2dof import simulate, SimResult, plant_truth, theta_truth, rmse"),
    "pm2dof.trajectory": ("pm2dof.control.trajectory",
                          "from pm2dof import line, paper_move, Trajectory, TrajectoryError"),
    "pm2dof.model": ("pm2dof.core.model", "from pm2dof import load_model, Model"),
    "pm2dof.model_file": ("pm2dof.core.model_file",
                          "from pm2dof.core.model_file import read_model_file"),
    "pm2dof.errors": ("pm2dof.core.errors",
                      "from pm2dof import WorkspaceError, SingularityError, ModelFileError"),
    "pm2dof.layout": ("pm2dof.core.layout", "from pm2dof.core.layout import Layout"),
    "pm2dof.build": ("pm2dof.core.build", "python -m pm2dof.core.build SOURCE.c OUT.so"),
    "pm2dof._cbind": ("pm2dof.core._cbind", "from pm2dof.core import _cbind"),
    "pm2dof.experiment": ("pm2dof.analysis.experiment", "from pm2dof import table3"),
    "pm2dof.identify": ("pm2dof.identification.base",
                        "from pm2dof.identification.base import identifiability, BaseParameters",
                        "0.2 (and again in 0.3)"),
    "pm2dof.report": ("pm2dof.analysis.report", "from pm2dof import model_report"),
    "pm2dof.results": ("pm2dof.analysis.results",
                       "from pm2dof.analysis.results import write_json, provenance"),
    "pm2dof.reference_control": ("pm2dof.reference.control",
                                 "from pm2dof.reference import control"),
    # 0.3: identification, from analysis/ into pm2dof.identification (one module per job)
    "pm2dof.analysis.identify": ("pm2dof.identification.base",
                                 "from pm2dof.identification.base import identifiability, "
                                 "BaseParameters", "0.3"),
    "pm2dof.analysis.ident_log": ("pm2dof.identification.log",
                                  "from pm2dof import read_log, write_log, IdentLog, LogError",
                                  "0.3"),
    "pm2dof.analysis.excite": ("pm2dof.identification.excitation",
                               "from pm2dof.identification.excitation import excite, multisine",
                               "0.3"),
    "pm2dof.analysis.ident_data": ("pm2dof.identification.fit",
                                   "from pm2dof.identification.fit import identify_log, "
                                   "weighted_ls", "0.3"),
    "pm2dof.analysis.ident_consistent": ("pm2dof.identification.consistent",
                                         "from pm2dof.identification.consistent import "
                                         "consistent_theta", "0.3"),
    "pm2dof.analysis.excitation_design": ("pm2dof.identification.design",
                                          "from pm2dof.identification.design import "
                                          "design_excitation, load_excitation", "0.3"),
    "pm2dof.analysis.ident_report": ("pm2dof.identification.report",
                                     "from pm2dof.identification.report import "
                                     "format_identification, load_theta", "0.3"),
    "pm2dof.analysis.ident_study": ("pm2dof.identification.monte_carlo",
                                    "from pm2dof.identification.monte_carlo import monte_carlo, "
                                    "TARGETS", "0.3"),
}


class _MovedFinder:
    """A meta-path finder that answers only for the old module names, with an error."""

    def find_spec(self, name, path=None, target=None):
        if name not in MOVED:
            return None
        new, hint, *since = MOVED[name]
        raise ModuleNotFoundError(
            f"{name} was moved in pm2dof {since[0] if since else '0.2'} to {new}: use `{hint}` "
            f"(docs/layout.md, 'Old import paths').", name=name)

    def __repr__(self):
        return "<pm2dof: old module paths, see pm2dof._moved>"


def install():
    """Put the finder first on ``sys.meta_path`` (once)."""
    if not any(isinstance(f, _MovedFinder) for f in sys.meta_path):
        sys.meta_path.insert(0, _MovedFinder())
