# `pm2dof bench`: the controller step-time benchmark.
import argparse
import sys

from ..options import model, progress


def add_parser(sub, common):
    from ...bench.run import run_bench
    p = sub.add_parser("bench", parents=[common], help="controller step-time benchmark",
                       formatter_class=argparse.RawDescriptionHelpFormatter,
                       description=_wrap(" ".join((run_bench.__doc__ or "").split("\n\n")[0]
                                                  .split())) + "\n\n" + _targets_text()
                       + "\n\n" + _wrap("Each target is checked against the median of its "
                                        "rounds, and ratios are taken within one run: quote "
                                        "them from one run, as this machine is shared and "
                                        "noisy. docs/benchmark.md explains every row."))
    p.add_argument("--json", action="store_true", help="print the results as JSON")
    p.add_argument("--quick", action="store_true", help="few repeats (a few seconds; for tests)")
    p.add_argument("--models", action=argparse.BooleanOptionalAction, default=None,
                   help="time the 3-RRR and 4-RRR platforms beside the paper's robot (NA step, "
                   "forward dynamics, rollout, plan; targets: 4-RRR NA step <= 3x the paper "
                   "robot's, binding overhead <= 1.25x); on by default in the full run (about "
                   "9 s more), off with --quick")
    p.add_argument("--build", action=argparse.BooleanOptionalAction, default=None,
                   help="time pm2dof derive of the 4-RRR platform beside gcc -O3 on the paper "
                   "robot's C, back to back (target: derive <= 1.5x gcc); on by default in the "
                   "full run (about 1.5 min more on 2 idle cores), off with --quick")
    p.add_argument("--strict", action="store_true", help="exit 1 when a target is missed (for "
                   "CI); a target that could not be measured (n/a: a baseline not installed, "
                   "the note says which) does not count")
    return p


def _wrap(text, indent=""):
    import textwrap
    return textwrap.fill(text, width=78, initial_indent=indent, subsequent_indent=indent + "  ")


def _targets_text():
    """The targets of ``pm2dof bench`` (bench.run.TARGETS), one line each; the per-method
    binding overheads as one line."""
    from ...bench.run import TARGETS
    lines, methods = [], []
    for key, op, value, unit, what in TARGETS:
        if key.startswith("overhead_over_c_"):
            methods.append(key[len("overhead_over_c_"):])
            bound = f"{op} {value:g} {unit}"
            continue
        lines.append(f"  {what}: {op} {value:g} {unit}")
    if methods:
        lines.append(_wrap(f"every per-sample Model method ({', '.join(methods)}): binding "
                           f"overhead (Python - C) / C {bound}", indent="  "))
    return "Targets:\n" + "\n".join(lines)


def run(args):
    from ...bench import format_bench, run_bench
    from ...infra.results import dumps
    res = run_bench(model(args), quick=args.quick, progress=None if args.json else progress(args),
                    models=args.models, build=args.build)
    print(dumps(res) if args.json else format_bench(res))
    missed = [k for k, t in res["targets"].items() if t["pass"] is False]
    if args.strict and missed:
        print(f"pm2dof bench --strict: {len(missed)} target(s) missed: {', '.join(missed)}",
              file=sys.stderr)
        return 1
    return 0
