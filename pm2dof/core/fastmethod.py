# The per-sample Model methods as one C call from Python: a decorator making a method a _cbind.FastMethod.
"""The fast path of a per-sample :class:`pm2dof.Model` method, from the call site into C.

A Model method (``fk``, ``forward_dynamics_jacobians``, ...) is one :class:`_cbind.Method`
(:func:`pm2dof.core.model._methods`): one C call that binds the arguments, evaluates and
checks the result. Called from a Python method body, the call still paid for the Python
frame of the method (about as much as the whole C call). :func:`fast_method` makes the
method a ``_cbind.FastMethod`` instead, a method descriptor written in C: ``model.fk(qa,
out=buf)`` maps the arguments onto ``model._fast["fk"]`` and calls it, with no Python frame.

The decorated function stays the method's documented body and its checked path: whatever
the Method refuses (a list, another dtype, a NaN, a singular pose, a wrong ``out``, ...) and
every call the descriptor does not map (an unknown keyword, a missing argument) is passed to
it with the arguments as given, so the results and the typed errors are the body's. Its
signature, docstring and name are the function's (``functools.update_wrapper``; ``inspect``
follows ``__wrapped__``).
"""
import functools
import inspect

try:
    from . import _cbind
except ImportError:  # a source tree never built: importing pm2dof.core.model says what to do
    _cbind = None

__all__ = ["fast_method"]


def fast_method(func=None, *, key=None, unless=None):
    """Decorate a Model method whose fast path is the instance's ``_fast[key]``.

    Parameters
    ----------
    func : function, optional
        The method, ``def name(self, <inputs>, [optional inputs=None], out=None)``: every
        parameter after ``self`` but ``out`` is an input of the Method, in its order.
    key : str, optional
        The Method's key in ``self._fast`` (default: the function's name).
    unless : str, optional
        An attribute of the instance: the fast path is taken only while it is None (e.g. a
        platform's fk, whose working modes the body checks in Python).

    Returns
    -------
    _cbind.FastMethod or function
        The descriptor (the function itself when the C extension is not built).
    """
    def wrap(f):
        if _cbind is None:
            return f
        params = list(inspect.signature(f).parameters.values())[1:]
        if any(p.kind is not p.POSITIONAL_OR_KEYWORD for p in params):
            raise TypeError(f"fast_method: {f.__qualname__} may have positional-or-keyword "
                            f"parameters only")
        required = sum(p.default is p.empty for p in params)
        if any(p.default is p.empty for p in params[required:]):
            raise TypeError(f"fast_method: {f.__qualname__}'s required parameters come first")
        d = _cbind.FastMethod(f, key or f.__name__, tuple(p.name for p in params), required,
                              unless=unless)
        return functools.update_wrapper(d, f)
    return wrap if func is None else wrap(func)
