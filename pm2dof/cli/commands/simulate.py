# `pm2dof simulate --reference FILE`: controllers tracking a reference file.
from ..options import NONNEGATIVE, model


def add_parser(sub, common):
    p = sub.add_parser("simulate", parents=[common], help="run controllers on a reference file",
                       description="Simulate controllers (default NA and APD, gains of the model "
                       "file) tracking a reference trajectory read from a CSV or Parquet file "
                       "(columns t, x, y[, phi] and optionally their _dot and _ddot: "
                       "docs/reference-format.md), and print RMSE (eq. 41), largest error, "
                       "peak torque and saturated samples.",
                       epilog="example: pm2dof simulate --reference ref.csv --controller na ctc")
    p.add_argument("--reference", required=True, metavar="FILE",
                   help="the reference, .csv or .parquet, sampled at the model's period")
    p.add_argument("--controller", nargs="+", default=["na", "apd"],
                   choices=["na", "apd", "ctc", "lqr"], metavar="LAW",
                   help="na, apd, ctc, lqr (default: na apd)")
    p.add_argument("--split", choices=["min_norm", "min_max", "preload"],
                   help="torque split (default: [control].split)")
    p.add_argument("--settle", type=NONNEGATIVE, default=0.0, metavar="S",
                   help="seconds of rest at the last sample after the reference (default 0)")
    p.add_argument("--json", action="store_true", help="print the numbers as JSON")
    return p


def run(args):
    from ...analysis.reference_file import (
        format_reference_summary,
        reference_summary,
        simulate_reference,
    )
    from ...infra.results import dumps
    m = model(args)
    res = reference_summary(simulate_reference(m, args.reference, args.controller,
                                               split=args.split, settle_time=args.settle), m)
    print(dumps(res) if args.json else format_reference_summary(res))
    return 0
