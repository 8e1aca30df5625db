# pm2dof: generated-C model and controllers of the Shang & Cong (2010) planar parallel manipulator.
"""pm2dof: derive, generate and run the model and controllers of a planar RR parallel manipulator.

>>> import pm2dof
>>> m = pm2dof.load_model()
"""
from .errors import ModelFileError, SingularityError, StaleGeneratedCodeError, WorkspaceError
from .model import Model, load_model

__all__ = ["load_model", "Model", "ModelFileError", "SingularityError",
           "StaleGeneratedCodeError", "WorkspaceError"]
