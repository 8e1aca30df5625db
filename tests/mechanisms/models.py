"""The model files of the other kinds: in pm2dof/models/ once derived, in pm2dof/models/pending/ until the
generic derivation (the task dimension m) can derive them."""
from pm2dof.core import paths

PENDING = paths.SHIPPED_MODELS / "pending"


def model_path(name):
    """The model file of ``name``: shipped, or still pending."""
    shipped = paths.SHIPPED_MODELS / f"{name}.toml"
    return shipped if shipped.is_file() else PENDING / f"{name}.toml"
