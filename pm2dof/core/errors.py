# Typed errors of pm2dof: each subclasses a builtin and names the value, the place and the limit.
__all__ = ["ModelFileError", "StaleGeneratedCodeError", "WorkspaceError", "ClosureError",
           "SingularityError", "GainError", "ModelMismatchError", "OutcomeWarning", "PlanError"]


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


class GainError(ValueError):
    """A controller gain outside what the stability argument allows (names the gain, the entry
    and the condition): K_d, Q > 0 and Gamma >= 0 (Sect. 4), Kp, Kv > 0 (eq. 40)."""


class ModelMismatchError(ValueError):
    """A controller built for one model used with another (names both models)."""


class OutcomeWarning(RuntimeWarning):
    """A rollout that did not complete: it left the workspace or diverged (``SimResult.outcome``
    names which, the sample and the time)."""


class PlanError(ValueError):
    """A path or a motion plan that cannot be built (names what and where: the argument and its
    value, or the arc length and point of the path): bad path geometry, a non-positive grid or
    margin, torque limits too low to follow the path at any speed."""
