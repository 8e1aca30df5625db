# pm2dof: generated-C model and controllers of the Shang & Cong (2010) planar parallel manipulator.
"""pm2dof: derive, generate and run the model and controllers of a planar RR parallel manipulator.

Everything a user touches is importable from here::

    >>> import pm2dof
    >>> m = pm2dof.load_model()
    >>> ctrl = pm2dof.NAController(m)
    >>> r = pm2dof.simulate(m, ctrl, pm2dof.paper_move("high"))
    >>> bool(r.rmse < 1e-3)
    True

The package is layered; imports only point down (tests/test_layers.py checks it):

=================  ==========================================================================
``core/``          1. the thin runtime: model file, ``Model``, the C binding. NumPy only.
``control/``       2. controllers, trajectories, closed-loop rollouts (one call into C each).
``infra/``         result files with their provenance, progress bars (below the analyses).
``linear/``        3. linearisation along a trajectory, python-control state spaces, LQR.
``analysis/``      3. the paper's experiment, reports, splits, maps.
``identification/`` 3. logs, excitations, the least-squares fit of theta (``pm2dof identify``).
``bench/``         3. the step-time benchmark.
``studies/``       3. many-rollout studies on Dask, results in Parquet.
``planning/``      3. paths in the task plane, time-optimal and kinematic timing.
``figures/``       4. matplotlib figures and the demo.
``cli/``          4. ``pm2dof COMMAND``: one module per command, each parses and prints.
``reference/``     beside the layers: independent NumPy formulations for tests and the bench.
=================  ==========================================================================

``import pm2dof`` loads layers 1-2 only; the names of the analyses (e.g. :func:`table3`)
are imported on first use, so a real-time process never pays for them.
"""
import importlib

from .control.controllers import STATUS_NAMES, APDController, CTCController, NAController, Status
from .control.plant import plant_truth, theta_truth
from .control.settings import ControlSettings
from .control.simulate import SimResult, check_trajectory, rmse, simulate
from .control.trajectory import (
    PAPER_MOVES,
    Trajectory,
    TrajectoryError,
    line,
    model_move,
    paper_move,
)
from .core.build import BuildError
from .core.errors import (
    ArgumentError,
    ArgumentTypeError,
    ClosureError,
    CompileWarning,
    DesignError,
    GainError,
    InputFileError,
    ModelFileError,
    ModelMismatchError,
    MovingStartWarning,
    NonFiniteError,
    NotResetError,
    OutcomeWarning,
    OutputError,
    PlanError,
    Pm2dofError,
    SingularityError,
    StaleGeneratedCodeError,
    UnsupportedMechanismError,
    WorkspaceError,
)
from .core.model import Model, load_model
from .core.version import __version__

# analyses (layer 3): resolved on first access by __getattr__ below. name -> module
_LAZY = {
    "table3": "pm2dof.analysis.experiment",
    "PAPER_TABLE3": "pm2dof.analysis.experiment",
    "repeated_runs": "pm2dof.analysis.experiment",
    "identifiability": "pm2dof.identification.base",
    "model_report": "pm2dof.analysis.report",
    "run_bench": "pm2dof.bench",
    "split_comparison": "pm2dof.analysis.splits",
    "workspace_maps": "pm2dof.analysis.maps",
    "capability": "pm2dof.analysis.maps",
    "read_study": "pm2dof.studies",
    "run_study": "pm2dof.studies",
    "StudyFileError": "pm2dof.studies",
    # identification from logs (pm2dof.identification)
    "IdentLog": "pm2dof.identification.log",
    "LogError": "pm2dof.identification.log",
    "read_log": "pm2dof.identification.log",
    "write_log": "pm2dof.identification.log",
    "excite": "pm2dof.identification.excitation",
    "identify_log": "pm2dof.identification.fit",
    "design_excitation": "pm2dof.identification.design",
    "load_excitation": "pm2dof.identification.signals",
    # a reference trajectory sampled elsewhere
    "read_trajectory": "pm2dof.analysis.reference_file",
    "ReferenceFileError": "pm2dof.analysis.reference_file",
    # motion planning
    "TaskPath": "pm2dof.planning",
    "check_path": "pm2dof.planning",
    "plan_kinematic": "pm2dof.planning",
    "plan_time_optimal": "pm2dof.planning",
    "plan_smooth": "pm2dof.planning",
    "Plan": "pm2dof.planning",
    # derivatives and linear design
    "linearize_trajectory": "pm2dof.linear",
    "statespace": "pm2dof.linear",
    "LQRController": "pm2dof.linear",
}

__all__ = [
    "__version__",
    # layer 1: the model
    "load_model", "Model",
    # layer 2: control
    "NAController", "APDController", "CTCController", "Status", "STATUS_NAMES", "simulate", "SimResult",
    "check_trajectory", "ControlSettings",
    "plant_truth", "theta_truth", "rmse", "line", "model_move", "paper_move", "PAPER_MOVES",
    "Trajectory",
    # errors
    "Pm2dofError", "ArgumentError", "ArgumentTypeError", "NonFiniteError", "OutputError",
    "InputFileError",
    "ModelFileError", "SingularityError", "StaleGeneratedCodeError", "WorkspaceError",
    "ClosureError", "TrajectoryError", "GainError", "ModelMismatchError", "BuildError",
    "OutcomeWarning", "MovingStartWarning", "CompileWarning", "PlanError", "UnsupportedMechanismError", "NotResetError",
    "DesignError",
    # layer 3 (imported on first use)
    *_LAZY,
]


def __getattr__(name):
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'pm2dof' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(__all__))

