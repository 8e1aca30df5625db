# What the commands share: the options every command takes, the argument types, the progress.
"""The options every command shares (``--model NAME|PATH``, ``--generated DIR``, ``--quiet``),
the argument types (finite numbers in a range, whole numbers in a range), the model and the
progress of a command's arguments, and the check of its outputs before any work."""
import argparse
import math
import textwrap

__all__ = ["number", "count", "POSITIVE", "NONNEGATIVE", "wrap", "common_options", "model",
           "progress", "tau_max", "check_outputs", "OUT_FOLDERS"]


def number(low=None, high=None, *, low_inclusive=False, high_inclusive=True):
    """An argparse type: a finite float within (low, high] (bounds as given), else a usage
    error naming the range (argparse prints it with the option's name, exit 2)."""
    def convert(text):
        try:
            x = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
        below = low is not None and (x < low if low_inclusive else x <= low)
        above = high is not None and (x > high if high_inclusive else x >= high)
        if not math.isfinite(x) or below or above:
            lo = "" if low is None else f"{'>=' if low_inclusive else '>'} {low:g}"
            hi = "" if high is None else f"{'<=' if high_inclusive else '<'} {high:g}"
            raise argparse.ArgumentTypeError(
                f"must be a finite number {' and '.join(b for b in (lo, hi) if b)}, got {text}")
        return x
    return convert


def count(low, high):
    """An argparse type: a whole number in [low, high]."""
    def convert(text):
        try:
            k = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
        if not low <= k <= high:
            raise argparse.ArgumentTypeError(f"must be in [{low}, {high}], got {k}")
        return k
    return convert


POSITIVE = number(0.0)
NONNEGATIVE = number(0.0, low_inclusive=True)


def wrap(text):
    """A description wrapped for a parser whose epilog keeps its line breaks."""
    return textwrap.fill(text, 79)


def common_options():
    """The parent parser of the options every command that uses a model takes."""
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument("--model", default=None, metavar="NAME|PATH",
                        help="a shipped model's name (pm2dof models) or your model file "
                        "(default: shang2010, the paper's robot)")
    common.add_argument("--generated", default=None, metavar="DIR",
                        help="folder of the model's generated C (default: generated/<stem>/ "
                        "beside the model file; shipped models: inside pm2dof)")
    common.add_argument("--quiet", action="store_true",
                        help="no progress output on stderr (progress bars are drawn only when "
                        "stderr is a terminal; stage lines always, unless --quiet)")
    return common


def model(args):
    """The model of ``--model`` and ``--generated``."""
    from ..core.model import load_model
    return load_model(args.model, args.generated)


def progress(args):
    """Where a long job reports: stage lines (and bars on a terminal) on stderr; silent with
    ``--quiet``."""
    from ..infra.progress import Progress
    return Progress(quiet=getattr(args, "quiet", False))


def tau_max(args, m):
    """``--tau-max`` (one value for every actuator or one per actuator) as (n,), or None."""
    if args.tau_max is None:
        return None
    from ..control.settings import per_actuator
    values = args.tau_max
    return per_actuator("--tau-max", values[0] if len(values) == 1 else values, m.n_legs)


#: commands whose --out names a folder (the others' --out, and every --save, name a file)
OUT_FOLDERS = {"demo", "figures", "splits", "maps", "plan", "study", "export"}


def check_outputs(args):
    """Refuse an output that cannot be written before any work: a --save or file --out that is
    a folder or lies under a file, a folder --out that is a file (OutputError)."""
    from ..infra.results import output_folder, output_path
    if getattr(args, "save", None):
        output_path(args.save)
    out = getattr(args, "out", None)
    if out and args.command != "derive":          # derive checks its own --out
        (output_folder if args.command in OUT_FOLDERS else output_path)(out)
