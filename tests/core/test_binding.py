# The public binding (pm2dof.core.binding) and Model.sample_period: what the layers above core use.
"""The C extension ``_cbind`` is private to core: the controllers and the linear design call
the generated C through :mod:`pm2dof.core.binding`, and read the sample period from
``Model.sample_period`` / ``Model.checked_period``, never through a Model's private members.
The expected periods are read from the model files themselves (tomllib)."""
import ast
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof.core import binding
from pm2dof.core.errors import ArgumentError, ArgumentTypeError
from tests.test_layers import MODULES, PKG, _imports

#: a platform, linear actuators and gravity
KINDS = ["rrr4_platform", "prr3_platform", "shang2010_vertical"]
#: the Model's private members the layers above core used to call
PRIVATE = {"_call", "_coerce", "_period"}


def _outside_core():
    return [p for p in MODULES if p.relative_to(PKG).parts[0] != "core"]


def _cbind_imports(path):
    """Lines of ``path`` that import the C extension: ``from ..core import _cbind``,
    ``from pm2dof.core._cbind import X``, ``import pm2dof.core._cbind``."""
    out = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            names = [a.name for a in node.names] + [getattr(node, "module", None) or ""]
            if any(n == "_cbind" or n.endswith("._cbind") for n in names):
                out.append(node.lineno)
    return out


def test_cbind_is_imported_in_core_only():
    found = [f"{p.relative_to(PKG)}:{line}" for p in _outside_core()
             for line in _cbind_imports(p)]
    assert not found, found
    assert _cbind_imports(PKG / "core" / "binding.py")
    assert any(mod == "pm2dof.core._cbind" for line, mod in _imports(PKG / "core" / "binding.py"))


def test_no_layer_reaches_into_a_models_private_binding():
    found = [f"{p.relative_to(PKG)}:{node.lineno} .{node.attr}" for p in _outside_core()
             for node in ast.walk(ast.parse(p.read_text()))
             if isinstance(node, ast.Attribute) and node.attr in PRIVATE]
    assert not found, found


@pytest.mark.parametrize("name", KINDS)
def test_sample_period_is_the_model_files(name):
    model = pm2dof.load_model(name)
    with open(Path(pm2dof.__file__).parent / "models" / f"{name}.toml", "rb") as fh:
        T = tomllib.load(fh)["sensing"]["sample_period"]
    assert type(model.sample_period) is float and model.sample_period == T
    assert model.checked_period() == T and model.checked_period(0.001) == 0.001
    assert model.checked_period(np.float32(0.5)) == 0.5
    for bad in (0.0, -0.002, math.inf, math.nan, "0.002", [0.002]):
        with pytest.raises(ArgumentError, match=r"period must be a finite number of seconds "
                                                r"> 0, got "):
            model.checked_period(bad)


@pytest.mark.parametrize("name", KINDS)
def test_call_converts_what_the_fast_path_refuses_and_names_the_rest(name):
    model = pm2dof.load_model(name)
    f = model.function("fk")
    qa = model.ik(np.asarray(model.spec.trajectories[
        next(k for k, t in model.spec.trajectories.items() if "start" in t)]["start"],
        dtype=float))[:model.n_legs]
    want = model.fk(qa)
    out, res = np.empty(model.dof), np.empty(model.n_legs)
    args, nonfinite = binding.call(f, (qa.tolist(),), (out, res))    # a list: converted
    assert nonfinite is None and isinstance(args[0], np.ndarray)
    np.testing.assert_array_equal(out, want)
    with pytest.raises(ArgumentError, match=r"input 'qa' must have shape"):
        binding.call(f, (qa[:-1],), (out, res))
    with pytest.raises(ArgumentTypeError, match=r"input 'qa' must be an array of "):
        binding.call(f, ("no",), (out, res))
    with pytest.raises(ArgumentError):
        binding.call(f, (np.full(model.n_legs, np.nan),), (out, res))
