# How the CLI ends: a typed error is one line and status 2, a bug shows its traceback.
"""The mapping of errors to the exit status of ``pm2dof COMMAND``: a
:class:`~pm2dof.core.errors.Pm2dofError` is one line ``pm2dof: error: ...`` and status 2; a
missing optional dependency names the extra to install (status 2); Ctrl-C is status 130; a
closed pipe (``| head``) is status 0; anything else is a bug and shows its traceback. A rollout
that did not complete (an :class:`~pm2dof.core.errors.OutcomeWarning`) and a trajectory that does
not start at rest (a :class:`~pm2dof.core.errors.MovingStartWarning`) are one line on stderr,
as is each stage of a model's first-use compile (a
:class:`~pm2dof.core.errors.CompileWarning`)."""
import sys
import warnings

from ..core.errors import CompileWarning, MovingStartWarning, OutcomeWarning, Pm2dofError
from .options import check_outputs

__all__ = ["run", "EXTRAS", "COMMAND_EXTRAS"]

#: optional dependencies -> the extra that installs them (pyproject.toml)
EXTRAS = {"sympy": "derive", "casadi": "derive", "dask": "studies", "distributed": "studies",
          "pyarrow": "studies", "scipy": "ident", "control": "control", "pymoo": "design"}
COMMAND_EXTRAS = {"derive": "derive", "identify": "ident", "study": "studies", "design": "design",
                  "table3": "control",     # table3 --include lqr: SciPy's Riccati solver
                  "simulate": "control"}   # simulate --controller lqr: the same


def _show_warning(message, category, filename, lineno, file=None, line=None,
                  _default=warnings.showwarning):
    if issubclass(category, (OutcomeWarning, MovingStartWarning)):
        print(f"pm2dof: warning: {message}", file=sys.stderr, flush=True)
    elif issubclass(category, CompileWarning):      # a stage line, not a warning
        print(f"pm2dof: {message}", file=sys.stderr, flush=True)
    else:
        _default(message, category, filename, lineno, file, line)


def run(args):
    """Run the parsed command ``args.func(args)``; returns its exit status."""
    try:
        check_outputs(args)
        with warnings.catch_warnings():   # each rollout that did not complete: one line
            warnings.simplefilter("always", OutcomeWarning)
            warnings.simplefilter("always", CompileWarning)
            warnings.showwarning = _show_warning
            return args.func(args)
    except Pm2dofError as exc:  # a typed error: the input is refused, not a bug
        print(f"pm2dof: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as exc:
        print(f"\npm2dof: interrupted{f' ({exc})' if str(exc) else ''}", file=sys.stderr)
        return 130
    except ModuleNotFoundError as exc:
        module = (exc.name or "").split(".")[0]
        if module not in EXTRAS:
            raise
        extra = COMMAND_EXTRAS.get(args.command, EXTRAS[module])
        print(f"pm2dof: error: `pm2dof {args.command}` needs {exc.name}, which is not "
              f"installed: pip install 'pm2dof[{extra}]'", file=sys.stderr)
        return 2
    except BrokenPipeError:  # output piped into `head` and the like
        sys.stderr.close()
        return 0
