# `pm2dof derive MODEL.toml`: derive a model file, generate and compile its C.
import argparse


def add_parser(sub, common):
    p = sub.add_parser("derive", parents=[common],
                       help="derive a model file and generate + compile its C",
                       description="Derive MODEL (a model file, TOML) with SymPy, generate C "
                       "with CasADi, and compile it: MODEL.c, MODEL.h, manifest.json and "
                       "libMODEL.so go into --out, by default generated/<stem>/ beside the model "
                       "file (~/robots/myrobot.toml -> ~/robots/generated/myrobot/), where "
                       "load_model and --model find them. A folder generated from another model "
                       "file is not overwritten without --force. When the folder is up to date "
                       "(the manifest matches the model file, the derivation's sources, SymPy "
                       "and CasADi, and the library its C), it says so and stops; --force "
                       "derives again. Needs the derivation extra: pip install 'pm2dof[derive]'.",
                       formatter_class=argparse.RawDescriptionHelpFormatter, epilog=(
                           "examples:\n"
                           "  pm2dof models --copy shang2010 ~/robots   # a model file to edit\n"
                           "  pm2dof derive ~/robots/shang2010.toml\n"
                           "  pm2dof table3 --model ~/robots/shang2010.toml"))
    p.add_argument("path", nargs="?", metavar="MODEL", help="model file (the same as --model)")
    p.add_argument("--out", metavar="DIR", help="folder for the generated code (default: "
                   "generated/<stem>/ beside the model file)")
    p.add_argument("--force", action="store_true",
                   help="derive even if the folder is up to date, and overwrite a folder that "
                        "holds code generated from another model file")
    p.add_argument("--no-build", action="store_true", help="generate C but do not compile it")
    return p


def run(args):
    from ...core.errors import ArgumentError, Pm2dofError
    if args.path and args.model and args.path != args.model:
        raise ArgumentError(f"give the model once: positional {args.path!r} or --model "
                            f"{args.model!r}, not both")
    if args.generated:                  # a common option: where the other commands read
        raise ArgumentError(f"pm2dof derive writes into --out DIR, not --generated "
                            f"({args.generated!r}): --generated tells the other commands where "
                            f"to read the generated C")
    if not (args.path or args.model):
        raise ArgumentError("pm2dof derive needs a model file: copy a shipped one with `pm2dof "
                            "models --copy shang2010 ~/robots`, edit it, then `pm2dof derive "
                            "~/robots/shang2010.toml` (`pm2dof models` lists them)")
    from ...core.generated import derive_is_current
    try:
        out, current, _ = derive_is_current(args.path or args.model, args.out,
                                            library=not args.no_build)
    except Pm2dofError:                 # a bad model file or folder: derive says what is wrong
        current = False
    if current and not args.force:     # no SymPy, no CasADi: well under a second
        print(f"{out} is up to date (its manifest matches the model file, the derivation and "
              f"its compiled library); --force derives again")
        return 0
    import json
    import time

    from ...core import build
    from ...derive.run import derive  # needs the [derive] extra (SymPy, CasADi); main() says so
    t0 = time.perf_counter()

    def say(msg):                      # derive()'s stage lines, on (almost) the same clock
        print(f"[derive {time.perf_counter() - t0:5.1f}s] {msg}", flush=True)
    # the compiler runs here, not inside derive(), so that a stage line (the C file's size, an
    # estimate) comes before the wait and the elapsed time after it
    out = derive(args.path or args.model, args.out, force=args.force, build=False,
                 progress=lambda msg: print(msg, flush=True))
    if not args.no_build:
        name = json.loads((out / "manifest.json").read_text())["model"]
        build.compile_library(out / f"{name}.c", out / f"lib{name}.so", progress=say)
    return 0
