# Command-line interface: parses `pm2dof COMMAND ...` and runs the command's module.
"""pm2dof: the Shang & Cong (2010) planar parallel manipulator, from model file to fast C.

Typical use:
  pm2dof demo                 the main job: Table 3 simulated, figures, repeated runs
  pm2dof table3 [--json]      the paper's Table 3: APD vs NA (and NA with Gamma = 0)
  pm2dof simulate --reference F   controllers tracking a reference file (CSV or Parquet)
  pm2dof figures --out DIR    error, torque, theta_hat and repeated-run figures (PNG)
  pm2dof report               what the compiled model says (Me, cond(S^T S), rank of Y)
  pm2dof identify report      identifiable parameters (base parameters, null space)
  pm2dof identify fit [LOG]   least squares for theta from a log (without one: a simulated run)
  pm2dof splits [--tau-max X] torque splits (min-norm, min-max, preload) in closed loop
  pm2dof maps --out DIR       singularities, conditioning, force/acceleration capability maps
  pm2dof animate --out F.gif  the move as an animation: legs to scale, error magnified
  pm2dof study run S.toml --out DIR   many rollouts on Dask (robustness, gains, adaptation,
                              model_based)
  pm2dof study report DIR     summary tables and figures of a study's results
  pm2dof design run S.toml --out DIR   search a model's geometry (NSGA-II, GA, a grid)
  pm2dof design pick DIR I --out F     a plain model file at a design of the front
  pm2dof plan [--path P]      time-optimal motion along a path, with either torque split
  pm2dof bench [--json]       controller step time: C, Python binding, CasADi, NumPy, SymPy
  pm2dof models               the shipped models, with their descriptions
  pm2dof derive MYROBOT.toml  derive your own model file: C into generated/MYROBOT/ beside it
  pm2dof export MODEL --out DIR   the controllers as a standalone C99 library (CMake)

The model: every command that uses one takes --model NAME|PATH, a shipped model's name
(`pm2dof models` lists them) or your model file (default: shang2010, the paper's robot), and
--generated DIR when its generated C is not in the default folder (generated/<stem>/ beside
the model file). Where a file names its model (a study file; a log or an excitation file, for
pm2dof identify), that model is the default: --model overrides a study's, and must match a
log's or an excitation file's. Run `pm2dof COMMAND --help` for the details of one command.
"""
import argparse
import importlib
import sys

from .commands import COMMANDS

__all__ = ["main", "build_parser"]


def build_parser(command=None):
    """The parser of ``pm2dof``: every command's, each from its module
    (:data:`~pm2dof.cli.commands.COMMANDS`), or with ``command`` only that command's (its
    module alone is imported; the others stay choices without options)."""
    ap = argparse.ArgumentParser(prog="pm2dof", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="command", metavar="COMMAND")
    from ..core.version import __version__
    ap.add_argument("--version", action="version", version=f"pm2dof {__version__}")
    from .options import common_options
    common = common_options()
    for name, module in COMMANDS.items():
        if command in (None, name):
            mod = importlib.import_module(module)
            mod.add_parser(sub, common).set_defaults(func=mod.run)
        else:
            sub.add_parser(name)
    return ap


def _deepest(parser, args):
    """The (sub)command's parser that ``args`` reached (``pm2dof study run`` -> run's)."""
    while True:
        sub = next((a for a in parser._actions if isinstance(a, argparse._SubParsersAction)),
                   None)
        name = getattr(args, sub.dest, None) if sub is not None else None
        if name not in getattr(sub, "choices", {}):
            return parser
        parser = sub.choices[name]


def main(argv=None):
    """``pm2dof ARGS`` (default: the command line's); returns the exit status.

    The command runs with ``args.command_line = ["pm2dof", *ARGS]``, which it passes to
    whatever records a provenance (:func:`pm2dof.infra.results.provenance`): a file written
    by ``main(argv)`` called from Python names that argv, not the caller's ``sys.argv``."""
    from .errors import run
    given = sys.argv[1:] if argv is None else list(argv)
    ap = build_parser(given[0] if given and given[0] in COMMANDS else None)
    args, extra = ap.parse_known_args(given)
    if extra:               # the command's own usage line and error, not the top level's
        _deepest(ap, args).error(f"unrecognized arguments: {' '.join(extra)}")
    args.command_line = ["pm2dof", *given]
    if not getattr(args, "func", None):
        ap.print_help()
        return 2
    return run(args)
