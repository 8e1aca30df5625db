# Old import paths of pm2dof 0.1 (flat modules): importing one fails with a message naming the new place.
"""pm2dof 0.2 moved its flat modules into layers (``core``, ``control``, ``analysis``, ...).

An old path such as ``pm2dof.controllers`` or ``pm2dof.simulate`` (the module) does not load
silently from somewhere else: the import fails with a :class:`ModuleNotFoundError` that names
the new place. One rule for every old path, because some old module names are now public
functions (``pm2dof.simulate`` is the function :func:`pm2dof.simulate`), and an alias could not
be both.
"""
import sys

__all__ = ["MOVED", "install"]

#: old module -> (its new module, what users imported from it and where to get it now)
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
    "pm2dof.identify": ("pm2dof.analysis.identify",
                        "from pm2dof.analysis.identify import identifiability, estimate"),
    "pm2dof.report": ("pm2dof.analysis.report", "from pm2dof import model_report"),
    "pm2dof.results": ("pm2dof.analysis.results",
                       "from pm2dof.analysis.results import write_json, provenance"),
    "pm2dof.reference_control": ("pm2dof.reference.control",
                                 "from pm2dof.reference import control"),
}


class _MovedFinder:
    """A meta-path finder that answers only for the old module names, with an error."""

    def find_spec(self, name, path=None, target=None):
        if name not in MOVED:
            return None
        new, hint = MOVED[name]
        raise ModuleNotFoundError(
            f"{name} was moved in pm2dof 0.2 to {new}: use `{hint}` "
            f"(docs/layout.md, 'Old import paths').", name=name)

    def __repr__(self):
        return "<pm2dof: old module paths, see pm2dof._moved>"


def install():
    """Put the finder first on ``sys.meta_path`` (once)."""
    if not any(isinstance(f, _MovedFinder) for f in sys.meta_path):
        sys.meta_path.insert(0, _MovedFinder())
