# The public binding of the generated C: what the layers above core call it through.
"""Calling a model's generated functions from the layers above core.

The C extension ``pm2dof.core._cbind`` binds CasADi's C API (``dlopen``, shapes and work sizes
checked at load time, no allocation per call). It is private to :mod:`pm2dof.core`; the
controllers (:mod:`pm2dof.control`) and the linear design (:mod:`pm2dof.linear`) reach it
through this module only:

* :class:`Function` -- one generated function ``<name>_<short>``, as
  :meth:`pm2dof.Model.function` returns it: ``f(*inputs, *outputs)`` evaluates once,
  ``f.map(K, ...)`` over K points, ``f.accumulate(...)`` a closed loop over samples;
  ``Function(library, name, fixed=values)`` binds its last input ``design`` once for all
  (every call then runs at that design, with one input fewer and no cost per call);
* :func:`function` -- that constructor with its refusals as typed errors;
* :class:`Method` -- a function with some inputs and outputs bound once (the controllers'
  state and parameters), called with the rest: one C call that checks every argument, and
  refuses (:class:`Refused`) what it does not accept instead of converting it;
* :class:`Refused`, :class:`GuardTripped` -- a :class:`Method`'s refusal, and the one of a
  step that ran but whose guard output tripped (a singular pose);
* :class:`NonFiniteOutputError` -- a non-finite result from finite inputs (a ValueError);
* :func:`call` -- the checked path: evaluate, and where the binding refuses the arguments
  convert them (lists, ints, float32) and evaluate again, its refusals as typed errors.
"""
import numpy as np

from . import _cbind
from .errors import ArgumentError, ArgumentTypeError

__all__ = ["Library", "Function", "Method", "Refused", "GuardTripped", "NonFiniteOutputError",
           "call", "coerce", "function"]

Library = _cbind.Library
Function = _cbind.Function
Method = _cbind.Method
Refused = _cbind.Refused
GuardTripped = _cbind.GuardTripped
NonFiniteOutputError = _cbind.NonFiniteOutputError


def function(library, name, *, fixed=None):
    """The generated function ``name`` of ``library``, its last input bound to ``fixed``.

    ``Function(library, name, fixed=fixed)``, whose refusals become typed errors: values that
    are not real numbers are an :class:`~pm2dof.ArgumentTypeError`; a function whose last
    input is not a vector named ``design``, a wrong number of values or a non-finite one are
    an :class:`~pm2dof.ArgumentError`, each naming the function. A name the library does not
    hold stays a LookupError.

    Parameters
    ----------
    library : Library
        The loaded shared library.
    name : str
        The generated function, e.g. ``"paper_robot_ik"``.
    fixed : array_like, optional
        The design, shape (k,): one value per element of the function's last input
        ``design``, copied once. None (the default): every input stays an argument.

    Returns
    -------
    Function
        With ``fixed``, its inputs are the function's inputs but the last
        (``names_in``, ``sizes_in`` and ``signature`` say so) and ``f.fixed`` holds the
        values; without, the plain function.
    """
    try:
        return Function(library, name, fixed=fixed)
    except TypeError as exc:
        raise ArgumentTypeError(str(exc)) from None
    except ValueError as exc:
        raise ArgumentError(str(exc)) from None


def coerce(f, args):
    """The inputs ``args`` of the :class:`Function` ``f`` as C-contiguous float64 arrays of
    its input sizes (a scalar for a size-1 input).

    Raises :class:`~pm2dof.ArgumentTypeError` for what is not real numbers (None, complex,
    text) and :class:`~pm2dof.ArgumentError` for a wrong shape, each naming ``f`` and the
    input.

    Parameters
    ----------
    f : Function
        The generated function whose inputs ``args`` are.
    args : sequence of array_like
        One value per input of ``f``, in its order (``f.names_in``).
    """
    out = []
    for name, size, x in zip(f.names_in, f.sizes_in, args):
        try:
            if x is None:
                raise TypeError("None is not a number")
            if np.iscomplexobj(x):
                raise TypeError("complex values are not allowed")
            a = np.asarray(x, dtype=np.float64)
        except (TypeError, ValueError) as exc:
            raise ArgumentTypeError(f"{f.name}: input '{name}' must be an array of {size} "
                                    f"real numbers, got {type(x).__name__}: {exc}") from None
        if a.shape != (size,) and not (size == 1 and a.ndim == 0):
            raise ArgumentError(f"{f.name}: input '{name}' must have shape ({size},), got "
                                f"shape {a.shape}")
        out.append(np.ascontiguousarray(a).reshape(size))
    return out


def call(f, args, outs):
    """``f(*args, *outs)`` on the checked path.

    The arguments go to the C as given; where the binding refuses them (not float64 arrays of
    the right size) they are converted (:func:`coerce`, which names what is wrong) and the call
    is retried. What the binding then refuses is raised as :class:`~pm2dof.ArgumentTypeError`
    or :class:`~pm2dof.ArgumentError` (e.g. a NaN input, named). A non-finite result from
    finite inputs is returned, not raised: the caller knows whether a status or a singular
    pose explains it.

    Parameters
    ----------
    f : Function
        The generated function.
    args : sequence of array_like
        Its inputs, in its order.
    outs : sequence of ndarray
        Its outputs, C-contiguous float64 arrays of its output sizes (None: not computed),
        written in place.

    Returns
    -------
    args : sequence of ndarray
        The inputs as called (converted where they had to be).
    nonfinite : NonFiniteOutputError or None
        The binding's report of a non-finite result from finite inputs, else None.
    """
    try:
        f(*args, *outs)
        return args, None
    except NonFiniteOutputError as exc:
        return args, exc
    except (TypeError, ValueError):  # not float64 arrays: convert (clear errors) and retry
        args = coerce(f, args)
    try:
        f(*args, *outs)
    except NonFiniteOutputError as exc:
        return args, exc
    except TypeError as exc:
        raise ArgumentTypeError(str(exc)) from None
    except ValueError as exc:        # e.g. a NaN input, named by the binding
        raise ArgumentError(str(exc)) from None
    return args, None
