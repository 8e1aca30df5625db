# `pm2dof bench`: the controller step-time benchmark.
import argparse
import sys

from ..options import model, progress


def add_parser(sub, common):
    from ...bench.run import run_bench
    p = sub.add_parser("bench", parents=[common], help="controller step-time benchmark",
                       description=(run_bench.__doc__ or "").split("\n\n")[0] + " Targets: NA "
                       "step in C <= 250 ns, from Python <= 1 us, rollout >= 500k steps/s, C >= "
                       "300x NumPy, binding >= 50x casadi.Function, forward dynamics from Python "
                       ">= 4x Pinocchio's and MuJoCo's, binding overhead <= 4x the C. Quote "
                       "medians from one run: this machine is shared and noisy.")
    p.add_argument("--json", action="store_true", help="print the results as JSON")
    p.add_argument("--quick", action="store_true", help="few repeats (a few seconds; for tests)")
    p.add_argument("--models", action=argparse.BooleanOptionalAction, default=None,
                   help="time the 3-RRR and 4-RRR platforms beside the paper's robot (NA step, "
                   "forward dynamics, rollout, plan; targets: 4-RRR NA step <= 3x the paper "
                   "robot's, binding overhead <= 1.25x); on by default in the full run (about "
                   "9 s more), off with --quick")
    p.add_argument("--strict", action="store_true", help="exit 1 when a target is missed (for "
                   "CI); a target that could not be measured (n/a: a baseline not installed, "
                   "the note says which) does not count")
    return p


def run(args):
    from ...bench import format_bench, run_bench
    from ...infra.results import dumps
    res = run_bench(model(args), quick=args.quick, progress=None if args.json else progress(args),
                    models=args.models)
    print(dumps(res) if args.json else format_bench(res))
    missed = [k for k, t in res["targets"].items() if t["pass"] is False]
    if args.strict and missed:
        print(f"pm2dof bench --strict: {len(missed)} target(s) missed: {', '.join(missed)}",
              file=sys.stderr)
        return 1
    return 0
