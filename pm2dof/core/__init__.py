# Layer 1, the thin runtime: a model file bound to its compiled generated C. NumPy only.
"""The runtime core: what a real-time loop links against.

* :mod:`.model_file` -- read and validate a model file (TOML) into a frozen ``ModelSpec``;
* :mod:`.mechanism` -- the mechanism's rules (leg kinds, theta's layout, lumped parameters,
  payload, reach) that the model file is checked against;
* :mod:`.model` -- :class:`Model`: the spec plus its compiled C, each method one call into C;
* :mod:`._cbind` -- the C extension binding CasADi's C API (``dlopen``, no allocation per call);
* :mod:`.layout` -- flat state/parameter vectors packed by field name (from the manifest);
* :mod:`.errors` -- the typed errors;
* :mod:`.validate` -- the checks of input files (model and study files), collecting every
  problem of a file into one error;
* :mod:`.build` -- compile generated C into a shared library (used by ``make``).

Imports the standard library and NumPy only: never SymPy, CasADi, matplotlib, Dask or
pyarrow (tests/test_layers.py checks it).
"""
from .errors import (
                     ClosureError,
                     ModelFileError,
                     SingularityError,
                     StaleGeneratedCodeError,
                     WorkspaceError,
)
from .layout import Layout
from .model import Model, load_model
from .model_file import ModelSpec, read_model_file

__all__ = ["Model", "load_model", "ModelSpec", "read_model_file", "Layout", "ModelFileError",
           "SingularityError", "StaleGeneratedCodeError", "WorkspaceError", "ClosureError"]
