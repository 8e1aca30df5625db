# Every parameter of the public API is documented in its numpydoc "Parameters" section.
"""Undocumented parameters of the public API fail here (the approach of python-control's
``control/tests/docstrings_test.py``: a function's signature against its docstring).

* The API checked: the names of ``pm2dof.__all__`` and the public sub-package APIs that are
  stable: ``pm2dof.planning.__all__``, ``pm2dof.linear.__all__`` and identification's
  :data:`IDENTIFICATION` (the identification names of ``pm2dof.__all__`` and the base
  parameters). A function is checked against its docstring; a class's constructor against the
  class docstring (and ``__init__``'s, where it has one), a dataclass's generated constructor
  against its "Parameters" or "Attributes"; every public method, class method and static
  method a pm2dof class defines or inherits from a pm2dof base, against its own docstring.
* Documented means named in a "Parameters" or "Other Parameters" section: a line at the
  section's indent ``name : type`` or ``name1, name2 : type`` (``*args`` and ``**kwargs`` by
  that name). ``self`` and ``cls`` are not parameters.
"""
import dataclasses
import importlib
import inspect
import re

import pytest

import pm2dof

#: identification's stable public names (module -> names), beyond those in pm2dof.__all__
IDENTIFICATION = {"pm2dof.identification.base": ["identifiability", "BaseParameters",
                                                 "Identifiability", "base_parameters"]}

def _api():
    """Every checked public function and class, once each."""
    out = {}
    homes = {"pm2dof": pm2dof.__all__,
             "pm2dof.planning": importlib.import_module("pm2dof.planning").__all__,
             "pm2dof.linear": importlib.import_module("pm2dof.linear").__all__, **IDENTIFICATION}
    for module, names in homes.items():
        mod = importlib.import_module(module)
        for name in names:
            obj = getattr(mod, name)
            if inspect.isfunction(obj) or inspect.isclass(obj):
                out.setdefault(id(obj), obj)
    return list(out.values())


def _ours(obj):
    return (getattr(obj, "__module__", None) or "").startswith("pm2dof")


def _generated(func):
    """A constructor written by ``dataclasses`` (no source file of its own)."""
    return func.__code__.co_filename.startswith("<")


def targets():
    """qualified name -> (function, docstrings whose sections document it, section names)."""
    out = {}
    for obj in _api():
        if inspect.isfunction(obj):
            out[f"{obj.__module__}.{obj.__qualname__}"] = (obj, [obj.__doc__], PARAMETERS)
            continue
        init = obj.__init__
        if inspect.isfunction(init) and _ours(init):
            sections = PARAMETERS + (("Attributes",) if dataclasses.is_dataclass(obj)
                                     and _generated(init) else ())
            docs = [obj.__doc__] + ([] if _generated(init) else [init.__doc__])
            out[f"{obj.__module__}.{obj.__qualname__}"] = (init, docs, sections)
        ours = [k for k in obj.__mro__ if _ours(k)]
        for i, klass in enumerate(ours):
            for attr, raw in vars(klass).items():
                func = _function(raw)
                if attr.startswith("_") or func is None:
                    continue
                # an override is documented by its own docstring and those it overrides
                docs = [func.__doc__] + [_function(vars(base).get(attr)).__doc__
                                         for base in ours[i + 1:]
                                         if _function(vars(base).get(attr)) is not None]
                out.setdefault(f"{func.__module__}.{func.__qualname__}", (func, docs, PARAMETERS))
    return out


def _function(raw):
    """The function of a class attribute (a method, class method or static method, or a
    method written in C that wraps one: ``__wrapped__``, as a Model's per-sample methods),
    else None."""
    func = raw.__func__ if isinstance(raw, (staticmethod, classmethod)) else raw
    func = getattr(func, "__wrapped__", func)
    return func if inspect.isfunction(func) else None


PARAMETERS = ("Parameters", "Other Parameters")
_RULE = re.compile(r"-{3,}")


def documented(doc, sections=PARAMETERS):
    """The parameter names a numpydoc docstring documents in the given sections."""
    lines = inspect.cleandoc(doc or "").splitlines()
    names, inside, indent = set(), False, 0
    for i, line in enumerate(lines):
        if _RULE.fullmatch(line.strip()):
            continue
        if i + 1 < len(lines) and _RULE.fullmatch(lines[i + 1].strip()):   # a section heading
            inside, indent = line.strip() in sections, len(line) - len(line.lstrip())
            continue
        if inside and line.strip() and len(line) - len(line.lstrip()) == indent:
            names |= {n.strip().lstrip("*") for n in line.split(":")[0].split(",")}
    return names


def undocumented(func, docs, sections=PARAMETERS):
    """The parameters of ``func`` that none of ``docs`` documents."""
    have = set().union(*(documented(d, sections) for d in docs))
    params = list(inspect.signature(func).parameters)
    if params and params[0] in ("self", "cls"):
        params = params[1:]
    return [p for p in params if p not in have and not p.startswith("_")]


TARGETS = targets()


@pytest.mark.parametrize("key", sorted(TARGETS))
def test_every_parameter_is_documented(key):
    func, docs, sections = TARGETS[key]
    missing = undocumented(func, docs, sections)
    assert not missing, (f"{key}: parameters missing from the docstring's "
                         f"{' or '.join(repr(s) for s in sections)} section: {missing}")


def test_the_checker_finds_an_undocumented_parameter():
    """Not vacuous: a missing name, a name only in the prose, a grouped line, *args/**kwargs."""
    def f(model, path, s=None, *args, limits=None, **kwargs):
        """One line.

        Parameters
        ----------
        model : Model
            The robot; the path is what ``path`` says.
        s, limits : array_like
        *args
            Passed on.

        Returns
        -------
        kwargs : dict
        """
    assert undocumented(f, [f.__doc__]) == ["path", "kwargs"]
    assert documented(f.__doc__) == {"model", "s", "limits", "args"}
    assert undocumented(f, [None]) == ["model", "path", "s", "args", "limits", "kwargs"]
    assert len(TARGETS) > 90, len(TARGETS)   # the API was found
    assert {"pm2dof.core.model.Model.ik", "pm2dof.core.derivatives.DerivativeMethods.linearize",
            "pm2dof.control.simulate.simulate", "pm2dof.control.simulate.SimResult",
            "pm2dof.control.lqr.LQRController.step", "pm2dof.core.errors.ModelFileError",
            "pm2dof.identification.base.identifiability"} <= set(TARGETS)
