# `pm2dof table3`: the paper's Table 3, APD against NA, simulated.
from ..options import model, progress


def add_parser(sub, common):
    p = sub.add_parser("table3", parents=[common], help="Table 3: RMSE of APD and NA, simulated",
                       description="Simulate APD, NA and NA with Gamma = 0 (same gains, no "
                       "adaptation) on each move of the model file and print the RMSE of eq. 41 "
                       "(m) and the RPE (percent reduction from APD to NA) beside the paper's "
                       "measured Table 3; a platform's orientation phi has an RMSE of its own (rad). "
                       "The plant uses the model file's [plant] truth, not the "
                       "controllers' nominal parameters.")
    p.add_argument("--json", action="store_true", help="print JSON: {speed: {apd_rmse, na_rmse, "
                   "na_no_adaptation_rmse (m), rpe_percent, trajectory_duration (s), a "
                   "platform's apd_phi_rmse, ... (rad), units, ...}}")
    p.add_argument("--exact-encoders", action="store_true",
                   help="no encoder quantisation (default: [sensing].encoder_counts_per_rev)")
    p.add_argument("--save", metavar="FILE", help="also write the numbers and provenance as JSON")
    p.add_argument("--include", nargs="+", choices=["ctc", "lqr"], default=[], metavar="LAW",
                   help="also run these model-based controllers with Tables 1-2: ctc (computed "
                   "torque), lqr (time-varying LQR along each move; needs the control extra)")
    return p


def run(args):
    from ...analysis.experiment import format_table3, is_paper_robot, run_table3
    from ...infra.results import dumps
    m = model(args)
    numbers = run_table3(m, exact_encoders=args.exact_encoders, save=args.save,
                         progress=None if args.json else progress(args),
                         include=tuple(args.include), command_line=args.command_line)
    print(dumps(numbers) if args.json else format_table3(numbers, is_paper_robot(m)))
    if args.save and not args.json:
        print(f"saved {args.save}")
    return 0
