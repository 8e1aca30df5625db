# Typed errors of pm2dof: each subclasses a builtin and names the value, the place and the limit.
from typing import NamedTuple

__all__ = ["Pm2dofError", "ArgumentError", "ArgumentTypeError", "NonFiniteError", "OutputError",
           "Problem",
           "InputFileError", "ModelFileError", "StaleGeneratedCodeError", "WorkspaceError",
           "ClosureError", "SingularityError", "GainError", "ModelMismatchError", "OutcomeWarning",
           "MovingStartWarning", "CompileWarning", "PlanError", "UnsupportedMechanismError",
           "NotResetError", "DesignError"]


class Pm2dofError(Exception):
    """Base of every typed error of pm2dof: a user's input, file or environment that pm2dof
    refuses, with a message naming the value, the place and the rule. Each subclass also keeps
    a builtin base (ValueError, TypeError, RuntimeError), so ``except ValueError`` still works.
    ``pm2dof`` (the CLI) prints these as one line and exits 2; any other exception is a bug
    and shows its traceback."""


class ArgumentError(Pm2dofError, ValueError):
    """An argument outside what a function accepts: names the argument, the value and the
    rule (a length, a range, a non-finite entry)."""


class ArgumentTypeError(Pm2dofError, TypeError):
    """An argument of the wrong type (names the argument and the type expected)."""


class OutputError(Pm2dofError, OSError):
    """A results file or folder that cannot be written (names the path and the reason)."""


class NonFiniteError(Pm2dofError, ValueError):
    """A model function whose result is not finite although every input is (inputs too large,
    or a degenerate pose or parameter set); names the output and the largest input."""


class Problem(NamedTuple):
    """One problem of an input file.

    ``key`` is the dotted key, with entries of arrays numbered from 1 after it in parentheses
    (``nominal.alpha (leg 2)``, ``gains.na.Gamma (entry 4, beta1)``), or None when the problem
    concerns the file as a whole (unreadable, not TOML). ``reason`` says what is wrong: the
    value, the rule and the limit.
    """
    key: object
    reason: str


class InputFileError(Pm2dofError, ValueError):
    """A user's input file (a model file or a study file) that cannot be used.

    The message names the file and lists every problem found, one per line; the same problems
    are in :attr:`problems`, a tuple of :class:`Problem`, in the order of the file's sections.
    Problems that make further checks meaningless (an unreadable file, not TOML, too few legs,
    an unknown friction model) stop the checks early, so those files report what was found up
    to there.
    """

    def __init__(self, message, problems=None, path=None):
        """
        Parameters
        ----------
        message : str
            The whole message: the file and every problem, one per line.
        problems : iterable of Problem, optional
            The problems (default: one, the message).
        path : str or Path, optional
            The file.
        """
        super().__init__(message)
        self.path = None if path is None else str(path)
        self.problems = (tuple(problems) if problems is not None
                         else (Problem(None, str(message)),))

    def __reduce__(self):  # keep problems and path across pickling (Dask workers)
        return type(self), (str(self), self.problems, self.path)


class ModelFileError(InputFileError):
    """A model file is unreadable, incomplete or non-physical.

    Lists every problem of the file (see :class:`InputFileError`), each naming the key and
    the reason. Legs are numbered from 1, as in the paper: the key ``legs.la (leg 2)`` is
    ``la`` of the second ``[[legs]]`` table, ``nominal.alpha (leg 2)`` the second entry of
    ``nominal.alpha`` (alpha_2); entries of per-parameter arrays name the parameter
    (``gains.na.Gamma (entry 4, beta1)``) and those of task-space pairs the axis
    (``gains.na.Kd (y)``).
    """


class StaleGeneratedCodeError(Pm2dofError, RuntimeError):
    """Generated code is missing, or does not match its model file: the message names the
    ``pm2dof derive ...`` command to run."""


class NotResetError(Pm2dofError, RuntimeError):
    """A controller stepped before ``reset(qa0)`` gave it its starting pose and estimate."""


class WorkspaceError(Pm2dofError, ValueError):
    """A task-space position no leg (or not every leg) can reach."""


class ClosureError(WorkspaceError):
    """Active (encoder) angles that do not close the loops: some leg's closure residual exceeds
    ``[sensing] closure_tolerance`` (names the leg and the residual in m)."""


class SingularityError(Pm2dofError, ValueError):
    """A pose too close to a singularity (singularity measure below the model's threshold)."""


class GainError(Pm2dofError, ValueError):
    """A controller gain outside what the stability argument allows (names the gain, the entry
    and the condition): K_d, Q > 0 and Gamma >= 0 (Sect. 4), Kp, Kv > 0 (eq. 40)."""


class ModelMismatchError(Pm2dofError, ValueError):
    """A controller built for one model used with another (names both models)."""


class OutcomeWarning(RuntimeWarning):
    """A rollout that did not complete: it left the workspace or diverged (``SimResult.outcome``
    names which, the sample and the time)."""


class CompileWarning(UserWarning):
    """pm2dof is compiling a model's generated C on its first use (a library missing, older
    than its C file or compiled with other flags; tens of seconds to minutes): one warning
    before the compiler starts (the C file's size and an estimate of the time) and one when it
    is done (the time it took).
    ``pm2dof`` prints each as a line on stderr; from Python, silence them with
    ``warnings.simplefilter("ignore", pm2dof.CompileWarning)``."""


class MovingStartWarning(RuntimeWarning):
    """A trajectory given to ``simulate`` that does not start at rest: its desired velocity at
    t = 0 exceeds what one sample of its own largest acceleration gives. The simulated robot
    starts at rest, so the first samples answer a velocity step (names the velocity)."""


class PlanError(Pm2dofError, ValueError):
    """A path or a motion plan that cannot be built (names what and where: the argument and its
    value, or the arc length and point of the path): bad path geometry, a non-positive grid or
    margin, torque limits too low to follow the path at any speed."""


class UnsupportedMechanismError(Pm2dofError, ValueError):
    """A capability that cannot apply to this model's mechanism (its leg kinds, its end effector
    or its task dimension m): names the capability, the mechanism and why, e.g. the Python
    reference formulation, which covers RR legs meeting at a point only."""


class DesignError(Pm2dofError, ValueError):
    """A design (values of a model file's ``[design]`` variables) that cannot be used: a value
    outside its bounds, an unknown variable, or a geometry where the file's home or moves cannot
    be reached. Names the variable, or the move and the leg."""
