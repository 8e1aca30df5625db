# Typed errors of pm2dof: each subclasses a builtin and names the value, the place and the limit.
__all__ = ["ModelFileError", "StaleGeneratedCodeError", "WorkspaceError", "ClosureError",
           "SingularityError"]


class ModelFileError(ValueError):
    """A model file is unreadable, incomplete or non-physical (names the file, key and reason)."""


class StaleGeneratedCodeError(RuntimeError):
    """Generated code is missing, or does not match its model file: run ``make derive``."""


class WorkspaceError(ValueError):
    """A task-space position no leg (or not every leg) can reach."""


class ClosureError(WorkspaceError):
    """Active (encoder) angles that do not close the loops: some leg's closure residual exceeds
    ``[sensing] closure_tolerance`` (names the leg and the residual in m)."""


class SingularityError(ValueError):
    """A pose too close to a singularity (singularity measure below the model's threshold)."""
