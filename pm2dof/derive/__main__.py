# `python -m pm2dof.derive MODEL`: the same as `pm2dof derive MODEL` (kept for make and tests).
"""Derive a model file and generate its C code.

Usage: python -m pm2dof.derive [MODEL] [--out DIR] [--force] [--no-build]

MODEL is a model file or a shipped model's name (default shang2010). Writes DIR/<name>.c,
DIR/<name>.h and DIR/manifest.json (DIR defaults to generated/<stem>/ beside the model file),
then compiles DIR/lib<name>.so unless --no-build.
"""
import argparse
import sys

from pm2dof.core.errors import ModelFileError

from .run import derive


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m pm2dof.derive",
                                 description=__doc__.split("\n\n")[0])
    ap.add_argument("model", nargs="?", default=None)
    ap.add_argument("--out", help="output folder (default generated/<stem>/ beside the model file)")
    ap.add_argument("--force", action="store_true",
                    help="overwrite a folder generated from another model file")
    ap.add_argument("--no-build", action="store_true", help="do not compile the shared library")
    args = ap.parse_args(argv)
    try:
        derive(args.model, args.out, force=args.force, build=not args.no_build,
               progress=lambda msg: print(msg, flush=True))
    except ModelFileError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
