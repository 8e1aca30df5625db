# `pm2dof splits`: the torque splits compared in closed loop.
import sys

from ..options import NONNEGATIVE, POSITIVE, model, progress


def add_parser(sub, common):
    p = sub.add_parser("splits", parents=[common], help="torque splits compared in closed loop",
                       description="Simulate APD and NA with each torque split (min_norm: eq. "
                       "21; min_max: least max_i |tau_i|/tau_max,i; preload: every actuator "
                       "keeps its sign and |tau_i| >= preload_i, least 2-norm) on the model's "
                       "moves, and print RMSE (eq. 41), largest error, saturated samples and "
                       "peak torque. All splits give the same task force S^T tau; they differ "
                       "once an actuator reaches its limit, so lower --tau-max to see them "
                       "differ (the paper's robot, high-speed move: NA peaks at 7.41 N m with "
                       "min-norm and 7.56 N m with min-max, APD at 7.11 and 6.90 N m; "
                       "docs/results-redundancy.md). With --out, also sweep the limit "
                       "and plot RMSE and clipped samples against it (splits_high.png).",
                       epilog="example: pm2dof splits --tau-max 6.0 --preload 1.0 --out out")
    p.add_argument("--tau-max", type=POSITIVE, metavar="NM",
                   help="limit of every actuator, N m (N for a linear actuator; default: "
                   "[limits].tau_max)")
    p.add_argument("--preload", type=NONNEGATIVE, metavar="NM",
                   help="least |tau_i| of the preload split, N m (N for a linear actuator; "
                   "default: [control].preload)")
    p.add_argument("--preload-sign", type=float, nargs="+", metavar="S",
                   help="sign (+1/-1) each actuator keeps under the preload split "
                   "(default: [control].preload_sign)")
    p.add_argument("--json", action="store_true", help="print the numbers as JSON")
    p.add_argument("--out", metavar="DIR", help="also write the sweep figure splits_high.png here")
    return p


def run(args):
    from ...analysis.splits import format_splits, run_splits
    from ...infra.results import dumps
    res = run_splits(model(args), args.tau_max, args.preload, args.preload_sign,
                     progress=None if args.json else progress(args))
    print(dumps(res) if args.json else format_splits(res))
    if args.out:
        from ...figures.splits import splits_figure
        path, _ = splits_figure(model(args), args.out, preload=args.preload,
                                preload_sign=args.preload_sign, progress=progress(args),
                                command_line=args.command_line)
        print(f"wrote {path}", file=sys.stderr if args.json else sys.stdout)
    return 0
