# `pm2dof export MODEL --out DIR`: the controllers as standalone C99 (--embedded: on a Cortex-M).
import argparse
import sys

from ..options import progress, wrap


def add_parser(sub, common):
    p = sub.add_parser(
        "export", parents=[common], help="the controllers as a standalone C99 library (CMake)",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description=wrap(
            "Write a self-contained C99 project for MODEL's controllers into --out: its "
            "generated C (copied, not re-derived; pruned to what the API calls), the API header "
            "include/<name>_pm2dof.h (fixed-size structs; init, reset and one step per controller taking the encoder angles and "
            "the reference and returning the torques and a status, the codes of pm2dof.Status; "
            "fk, ik, the torque splits; the parameters' layout with the model file's values as "
            "defaults), a CMakeLists.txt building a static library with a package config "
            "(find_package(<name>_pm2dof)), a closed-loop example against the generated plant, a "
            "ctest comparing the C closed loop with pm2dof.simulate, and embedded/ (Cortex-M4F and "
            "M7 under QEMU). No heap, no global state, only the standard math functions; no Python "
            "on the target."),
        epilog="examples:\n"
               "  pm2dof export shang2010 --out robot_c\n"
               "  cmake -S robot_c -B robot_c/build && cmake --build robot_c/build && "
               "ctest --test-dir robot_c/build\n"
               "  pm2dof export ~/robots/myrobot.toml --out myrobot_c --precision single "
               "--controllers na,apd\n"
               "  pm2dof export --embedded --out build/embedded     # what make embedded runs\n"
               "docs/deploying.md: the API, the sizes and times, a 2 ms interrupt")
    p.add_argument("path", nargs="?", metavar="MODEL", help="a shipped model's name or your "
                   "model file (the same as --model; default shang2010)")
    p.add_argument("--out", required=True, metavar="DIR", help="the project folder (new or "
                   "empty, unless --force)")
    p.add_argument("--precision", metavar="double|single",
                   help="double (default; equals pm2dof to the bit) or single: the same code "
                   "with float, refused with the reason where float is not enough")
    p.add_argument("--controllers", metavar="LIST",
                   help="comma-separated subset of na,apd,ctc,lqr (default all four; LQR's "
                   "gains are inputs of its step)")
    p.add_argument("--force", action="store_true", help="write into a non-empty --out (a "
                   "previous export's files are replaced)")
    p.add_argument("--move", metavar="NAME", help="the model file's move the example and the "
                   "ctest run (default high)")
    p.add_argument("--no-stack", action="store_true", help="do not measure each function's "
                   "worst-case stack (by default measured for a Cortex-M4F when "
                   "arm-none-eabi-gcc is on the PATH, and written into the README)")
    p.add_argument("--embedded", action="store_true",
                   help="instead: export MODEL in double and in single precision into "
                   "--out/double and --out/single, cross-compile each for a Cortex-M4F and a "
                   "Cortex-M7 (arm-none-eabi-gcc, newlib), run them under QEMU beside the host "
                   "build, print the table of docs/deploying.md and write --out/results.json; "
                   "exit status 1 when the torques differ from the host's beyond the bound "
                   "(what make embedded runs)")
    return p


def run(args):
    from ...core.errors import ArgumentError
    if args.path and args.model and args.path != args.model:
        raise ArgumentError(f"give the model once: positional {args.path!r} or --model "
                            f"{args.model!r}, not both")
    if args.embedded:
        return _embedded(args)
    from ...export import export_project
    out = export_project(args.path or args.model, args.out, precision=args.precision or "double",
                         controllers=args.controllers or "na,apd,ctc,lqr", force=args.force,
                         generated=args.generated, move=args.move,
                         measure_stack=not args.no_stack, progress=progress(args))
    print(f"wrote {out}: build and test it with\n  cmake -S {out} -B {out}/build && cmake "
          f"--build {out}/build && ctest --test-dir {out}/build\n(docs/deploying.md: the API, "
          f"a 2 ms interrupt, make -C {out}/embedded run for a Cortex-M under QEMU)")
    return 0


def _embedded(args):
    """``pm2dof export --embedded``: :func:`pm2dof.export.embedded.run_embedded`, its table,
    ``--out/results.json``; status 1 beyond the bound."""
    import shutil
    from pathlib import Path

    from ...core.build import BuildError
    from ...core.errors import ArgumentError
    from ...export.embedded import (
        INSTALL,
        TOOLS,
        format_results,
        format_stacks,
        run_embedded,
    )
    from ...infra.results import write_json
    from ..options import progress
    given = [flag for flag, value in (("--precision", args.precision),
                                      ("--controllers", args.controllers),
                                      ("--move", args.move), ("--force", args.force),
                                      ("--generated", args.generated)) if value]
    if given:
        raise ArgumentError(f"--embedded exports both precisions with every controller into "
                            f"--out (replacing a previous run's) from the model's own folder: "
                            f"{', '.join(given)} cannot be given with it")
    missing = [t for t in TOOLS if shutil.which(t) is None]
    if missing:
        raise BuildError(f"pm2dof export --embedded needs {', '.join(missing)}: {INSTALL} "
                         f"(Debian)")
    res = run_embedded(args.out, args.path or args.model or "shang2010",
                       progress=progress(args))
    print("QEMU counts instructions, not cycles: the cycles are an estimate, a range of "
          "cycles per instruction (M4F 1.0-2.0, M7 0.7-1.5) at a stated clock.")
    for precision, why in res["refused"].items():
        print(f"{precision} precision: not exported: {why}")
    print(format_results(res))
    print(format_stacks(res))
    print(f"wrote {write_json(Path(args.out) / 'results.json', res)}")
    bad = [k for k, r in res["runs"].items() if "samples" in r and (
        not r["statuses_equal"] or r["max_abs_diff"] > res["bound"][r["precision"]])]
    if bad:
        print(f"pm2dof export --embedded: the efforts of {', '.join(bad)} differ from the "
              f"host's beyond the bound ({res['bound']} {res['effort_unit']})", file=sys.stderr)
        return 1
    return 0
