# Command-line interface: pm2dof report | demo | derive (more commands register in COMMANDS).
"""pm2dof: the Shang & Cong (2010) planar parallel manipulator, from model file to fast C.

Typical use:
  pm2dof report               what the compiled model says (Me, cond(S^T S), rank of Y)
  pm2dof demo                 the main job: the paper's experiment reproduced
  pm2dof derive MODEL.toml    re-derive a model file into generated/<name>/ and compile it

Every command takes --model PATH (default models/shang2010.toml). Run
`pm2dof COMMAND --help` for the details of one command.
"""
import argparse
import subprocess
import sys
from pathlib import Path

from .errors import ModelFileError, StaleGeneratedCodeError

__all__ = ["main"]

REPO = Path(__file__).resolve().parent.parent


def _model(args):
    from .model import load_model
    return load_model(args.model)


def cmd_report(args):
    from .report import model_report
    print(model_report(_model(args)))
    return 0


def cmd_derive(args):
    """Run the build-time derivation in its own process: the runtime never imports it."""
    cmd = [sys.executable, "-m", "derive", str(Path(args.path).resolve())]
    if args.no_build:
        cmd.append("--no-build")
    return subprocess.call(cmd, cwd=REPO)


def cmd_demo(args):
    print(__doc__.splitlines()[0])
    print()
    return cmd_report(args)


def build_parser():
    ap = argparse.ArgumentParser(prog="pm2dof", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="command", metavar="COMMAND")
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument("--model", default=None, metavar="PATH",
                        help="model file (default: models/shang2010.toml, the paper's robot)")

    p = sub.add_parser("report", parents=[common], help="model report over the workspace",
                       description="Print the nominal parameters, Me at the middle of the "
                       "paper's path, the conditioning of S^T S and min |sin(qb-qa)| over the "
                       "workspace, and the rank of the regressor Y stacked over random states.")
    p.set_defaults(func=cmd_report)
    p = sub.add_parser("demo", parents=[common], help="the main job (what `make demo` runs)")
    p.add_argument("--out", default="out", help="folder for figures and results (default out/)")
    p.set_defaults(func=cmd_demo)
    p = sub.add_parser("derive", help="derive a model file and generate + compile its C",
                       description="Derive MODEL.toml with SymPy, generate C with CasADi into "
                       "generated/<name>/ (other models' code is left alone) and compile it. "
                       "Needs the build-time extras (pip install -e '.[derive]').")
    p.add_argument("path", help="model file (TOML)")
    p.add_argument("--no-build", action="store_true", help="generate C but do not compile it")
    p.set_defaults(func=cmd_derive)
    return ap


def main(argv=None):
    ap = build_parser()
    args = ap.parse_args(argv)
    if not getattr(args, "func", None):
        ap.print_help()
        return 2
    try:
        return args.func(args)
    except (ModelFileError, StaleGeneratedCodeError) as exc:
        print(f"pm2dof: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
