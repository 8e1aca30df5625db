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
* :data:`BEING_EDITED`: functions in files that other branches are editing, expected to fail
  (strict: one that passes must leave the list). The lead empties the list after merging.
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

EDITED = "being edited on another branch, lead fixes at merge"
#: qualified name -> why it may fail for now: in files other branches are editing (issue 29:
#: core/model.py, control/controllers.py, identification/, planning/, studies/spec.py). The
#: lead documents these after merging and empties the list.
BEING_EDITED = dict.fromkeys([
    # control/controllers.py (LQRController's reset and step inherit its docstrings)
    "pm2dof.control.controllers.APDController",
    "pm2dof.control.controllers._Controller.closed_loop_inputs",
    "pm2dof.control.controllers._Controller.reset", "pm2dof.control.controllers._Controller.step",
    "pm2dof.linear.lqr.LQRController.reset", "pm2dof.linear.lqr.LQRController.step",
    # core/model.py
    "pm2dof.core.model.Model", "pm2dof.core.model.Model.A", "pm2dof.core.model.Model.C",
    "pm2dof.core.model.Model.Ce", "pm2dof.core.model.Model.H", "pm2dof.core.model.Model.M",
    "pm2dof.core.model.Model.Me", "pm2dof.core.model.Model.S", "pm2dof.core.model.Model.StF",
    "pm2dof.core.model.Model.W", "pm2dof.core.model.Model.Wdot", "pm2dof.core.model.Model.Y",
    "pm2dof.core.model.Model.checked_theta", "pm2dof.core.model.Model.fk",
    "pm2dof.core.model.Model.forward_dynamics", "pm2dof.core.model.Model.function",
    "pm2dof.core.model.Model.ik", "pm2dof.core.model.Model.layout",
    "pm2dof.core.model.Model.singularity", "pm2dof.core.model.Model.singularity_measures",
    "pm2dof.core.model.Model.singularity_message", "pm2dof.core.model.Model.torque_splits",
    # identification/
    "pm2dof.identification.base.BaseParameters.fold",
    "pm2dof.identification.base.BaseParameters.unfold",
    "pm2dof.identification.base.base_parameters",
    "pm2dof.identification.design.design_excitation",
    "pm2dof.identification.fit.identify_log",
    "pm2dof.identification.log.write_log",
    # planning/
    "pm2dof.planning.pathfile.model_move_path",
    "pm2dof.planning.paths.TaskPath", "pm2dof.planning.paths.TaskPath.arc",
    "pm2dof.planning.paths.TaskPath.concat", "pm2dof.planning.paths.TaskPath.line",
    "pm2dof.planning.paths.TaskPath.polyline", "pm2dof.planning.paths.TaskPath.spline",
    "pm2dof.planning.plan.PathProfile", "pm2dof.planning.plan.PathProfile.evaluate",
    # studies/spec.py
    "pm2dof.studies.spec.read_study",
], EDITED)


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
    """The function of a class attribute (a method, class method or static method), else None."""
    func = raw.__func__ if isinstance(raw, (staticmethod, classmethod)) else raw
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


def _cases():
    for key in sorted(TARGETS):
        marks = [pytest.mark.xfail(reason=BEING_EDITED[key], strict=True)] \
            if key in BEING_EDITED else []
        yield pytest.param(key, id=key, marks=marks)


@pytest.mark.parametrize("key", list(_cases()))
def test_every_parameter_is_documented(key):
    func, docs, sections = TARGETS[key]
    missing = undocumented(func, docs, sections)
    assert not missing, (f"{key}: parameters missing from the docstring's "
                         f"{' or '.join(repr(s) for s in sections)} section: {missing}")


def test_the_allow_list_names_only_checked_functions():
    assert set(BEING_EDITED) <= set(TARGETS), sorted(set(BEING_EDITED) - set(TARGETS))
    assert all(why == EDITED for why in BEING_EDITED.values())


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
            "pm2dof.linear.lqr.LQRController.step", "pm2dof.core.errors.ModelFileError",
            "pm2dof.identification.base.identifiability"} <= set(TARGETS)
