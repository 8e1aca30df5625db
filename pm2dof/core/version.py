# The version of the installed pm2dof, read from its metadata (written once, in pyproject.toml).
from importlib.metadata import PackageNotFoundError, version

__all__ = ["__version__"]

try:
    __version__ = version("pm2dof")
except PackageNotFoundError:               # a source tree that was never installed
    __version__ = "unknown (not installed)"
