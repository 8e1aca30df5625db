# `pm2dof figures --out DIR`: the experiment's figures as PNG.
from ..options import count, model, progress


def add_parser(sub, common):
    p = sub.add_parser("figures", parents=[common], help="write the figures as PNG",
                       description="Write errors_<speed>.png (x and y error against time, APD "
                       "and NA, like the paper's Figs. 4-5), torques.png, theta_hat.png and "
                       "repeated_runs.png into --out. Each PNG carries its provenance in its "
                       "text chunks.")
    p.add_argument("--out", required=True, help="output folder")
    p.add_argument("--runs", type=count(0, 100000), default=40,
                   help="repeated runs for repeated_runs.png")
    return p


def run(args):
    from ...figures.experiment import experiment_figures
    _, _, paths = experiment_figures(model(args), args.out, args.runs, progress(args),
                                     command_line=args.command_line)
    for p in paths:
        print(f"wrote {p}")
    return 0
