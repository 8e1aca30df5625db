# `pm2dof bench`: the controller step-time benchmark.
from ..options import model, progress


def add_parser(sub, common):
    from ...bench.run import run_bench
    p = sub.add_parser("bench", parents=[common], help="controller step-time benchmark",
                       description=(run_bench.__doc__ or "").split("\n\n")[0] + " Targets: NA "
                       "step in C <= 250 ns, from Python <= 1 us, rollout >= 500k steps/s, C >= "
                       "300x NumPy, binding >= 50x casadi.Function. Quote medians from one run: "
                       "this machine is shared and noisy.")
    p.add_argument("--json", action="store_true", help="print the results as JSON")
    p.add_argument("--quick", action="store_true", help="few repeats (a few seconds; for tests)")
    return p


def run(args):
    from ...bench import format_bench, run_bench
    from ...infra.results import dumps
    res = run_bench(model(args), quick=args.quick, progress=None if args.json else progress(args))
    print(dumps(res) if args.json else format_bench(res))
    return 0
