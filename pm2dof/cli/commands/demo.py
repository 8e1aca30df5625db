# `pm2dof demo`: the main job, the paper's experiment with its figures and numbers.
from ..options import count, model, progress


def add_parser(sub, common):
    p = sub.add_parser("demo", parents=[common], help="the main job (what `make demo` runs)",
                       description="Simulate the paper's experiment (APD, NA and NA with "
                       "Gamma = 0 on the low- and high-speed moves), print Table 3 beside the "
                       "paper's measured numbers, repeat the high-speed move carrying theta_hat "
                       "over, and write figures and results.json into --out.")
    p.add_argument("--out", default="out", help="folder for figures and results (default out/)")
    p.add_argument("--runs", type=count(0, 100000), default=40,
                   help="repeated runs (default 40; 0: none)")
    return p


def run(args):
    from ...figures.demo import demo_header, format_demo, run_demo
    m = model(args)
    print(demo_header(m), flush=True)
    print(format_demo(run_demo(m, args.out, args.runs, progress=progress(args),
                                     command_line=args.command_line)))
    return 0
