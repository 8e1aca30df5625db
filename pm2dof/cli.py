# Command-line interface: parses `pm2dof COMMAND ...` and dispatches to the command's layer.
"""pm2dof: the Shang & Cong (2010) planar parallel manipulator, from model file to fast C.

Typical use:
  pm2dof demo                 the main job: Table 3 simulated, figures, repeated runs
  pm2dof table3 [--json]      the paper's Table 3: APD vs NA (and NA with Gamma = 0)
  pm2dof figures --out DIR    error, torque, theta_hat and repeated-run figures (PNG)
  pm2dof report               what the compiled model says (Me, cond(S^T S), rank of Y)
  pm2dof identify [--report]  identifiable parameters; least-squares estimate of theta
  pm2dof bench [--json]       controller step time: C, Python binding, CasADi, NumPy, SymPy
  pm2dof derive MODEL.toml    re-derive a model file into generated/<name>/ and compile it

Every command takes --model PATH (default models/shang2010.toml). Run
`pm2dof COMMAND --help` for the details of one command.
"""
import argparse
import sys

from .core.errors import ModelFileError, StaleGeneratedCodeError

__all__ = ["main", "build_parser"]


def _progress(msg):
    print(f"  .. {msg}", file=sys.stderr, flush=True)


def _model(args):
    from .core.model import load_model
    return load_model(args.model)


# one dispatcher per command: load what it needs, call its layer, print
def cmd_report(args):
    from .analysis.report import model_report
    print(model_report(_model(args)))
    return 0


def cmd_derive(args):
    from .core.build import derive
    return derive(args.path, build=not args.no_build)


def cmd_table3(args):
    from .analysis.experiment import run_table3
    run_table3(_model(args), as_json=args.json, exact_encoders=args.exact_encoders,
               save=args.save, progress=_progress)
    return 0


def cmd_figures(args):
    from .figures.experiment import experiment_figures
    _, _, paths = experiment_figures(_model(args), args.out, args.runs, _progress)
    for p in paths:
        print(f"wrote {p}")
    return 0


def cmd_demo(args):
    from .figures.demo import run_demo
    run_demo(_model(args), args.out, args.runs, progress=_progress)
    return 0


def cmd_identify(args):
    from .analysis.identify import run_identify
    run_identify(_model(args), report_only=args.report, duration=args.duration, save=args.save,
                 seed=args.seed_na, progress=_progress)
    return 0


def cmd_bench(args):
    from .analysis.results import dumps
    from .bench import format_bench, run_bench
    res = run_bench(_model(args), quick=args.quick, progress=None if args.json else _progress)
    print(dumps(res) if args.json else format_bench(res))
    return 0


def build_parser():
    ap = argparse.ArgumentParser(prog="pm2dof", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="command", metavar="COMMAND")
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument("--model", default=None, metavar="PATH",
                        help="model file (default: models/shang2010.toml, the paper's robot)")

    p = sub.add_parser("report", parents=[common], help="model report over the workspace",
                       description="Print the nominal parameters, Me at the middle of the "
                       "paper's path, the conditioning of S^T S and min |sin(qb-qa)| over the "
                       "workspace, and the rank of the regressor Y stacked over random states.")
    p.set_defaults(func=cmd_report)
    p = sub.add_parser("demo", parents=[common], help="the main job (what `make demo` runs)",
                       description="Simulate the paper's experiment (APD, NA and NA with "
                       "Gamma = 0 on the low- and high-speed moves), print Table 3 beside the "
                       "paper's measured numbers, repeat the high-speed move carrying theta_hat "
                       "over, and write figures and results.json into --out.")
    p.add_argument("--out", default="out", help="folder for figures and results (default out/)")
    p.add_argument("--runs", type=int, default=40, help="repeated runs (default 40; 0: none)")
    p.set_defaults(func=cmd_demo)
    p = sub.add_parser("table3", parents=[common], help="Table 3: RMSE of APD and NA, simulated",
                       description="Simulate APD, NA and NA with Gamma = 0 (same gains, no "
                       "adaptation) on each move of the model file and print the RMSE of eq. 41 "
                       "(m) and the RPE (percent reduction from APD to NA) beside the paper's "
                       "measured Table 3. The plant uses the model file's [plant] truth, not the "
                       "controllers' nominal parameters.")
    p.add_argument("--json", action="store_true", help="print JSON: {speed: {apd_rmse, na_rmse, "
                   "na_no_adaptation_rmse, rpe_percent, trajectory_duration_s, ...}}")
    p.add_argument("--exact-encoders", action="store_true",
                   help="no encoder quantisation (default: [sensing].encoder_counts_per_rev)")
    p.add_argument("--save", metavar="FILE", help="also write the numbers and provenance as JSON")
    p.set_defaults(func=cmd_table3)
    p = sub.add_parser("figures", parents=[common], help="write the figures as PNG",
                       description="Write errors_<speed>.png (x and y error against time, APD "
                       "and NA, like the paper's Figs. 4-5), torques.png, theta_hat.png and "
                       "repeated_runs.png into --out. Each PNG carries its provenance in its "
                       "text chunks.")
    p.add_argument("--out", required=True, help="output folder")
    p.add_argument("--runs", type=int, default=40, help="repeated runs for repeated_runs.png")
    p.set_defaults(func=cmd_figures)
    p = sub.add_parser("identify", parents=[common], help="identifiability and least squares",
                       description="Stack the regressor Y over random states and report its "
                       "rank, the identifiable base parameters and the invisible directions of "
                       "theta. Then (without --report) simulate an excitation run on the plant "
                       "(its truth, encoder quantisation, APD tracking) and estimate the base "
                       "parameters by least squares from the measured angles and commanded "
                       "torques, with the truth beside the estimate.")
    p.add_argument("--report", action="store_true", help="identifiability only, no estimation")
    p.add_argument("--duration", type=float, default=4.0, help="excitation length, s (default 4)")
    p.add_argument("--save", metavar="FILE", help="write the estimate and a full theta0 as JSON")
    p.add_argument("--seed-na", action="store_true",
                   help="rerun the moves with NA seeded by the identified theta")
    p.set_defaults(func=cmd_identify)
    from .bench.run import run_bench
    p = sub.add_parser("bench", parents=[common], help="controller step-time benchmark",
                       description=(run_bench.__doc__ or "").split("\n\n")[0] + " Targets: NA "
                       "step in C <= 250 ns, from Python <= 1 us, rollout >= 500k steps/s, C >= "
                       "300x NumPy, binding >= 50x casadi.Function. Quote medians from one run: "
                       "this machine is shared and noisy.")
    p.add_argument("--json", action="store_true", help="print the results as JSON")
    p.add_argument("--quick", action="store_true", help="few repeats (a few seconds; for tests)")
    p.set_defaults(func=cmd_bench)
    p = sub.add_parser("derive", help="derive a model file and generate + compile its C",
                       description="Derive MODEL.toml with SymPy, generate C with CasADi into "
                       "generated/<name>/ (other models' code is left alone) and compile it. "
                       "Needs the build-time extras (pip install -e '.[derive]').")
    p.add_argument("path", help="model file (TOML)")
    p.add_argument("--no-build", action="store_true", help="generate C but do not compile it")
    p.set_defaults(func=cmd_derive)
    return ap


def main(argv=None):
    from .analysis import results
    ap = build_parser()
    args = ap.parse_args(argv)
    results.COMMAND_LINE = ["pm2dof", *(sys.argv[1:] if argv is None else argv)]
    if not getattr(args, "func", None):
        ap.print_help()
        return 2
    try:
        return args.func(args)
    except (ModelFileError, StaleGeneratedCodeError) as exc:
        print(f"pm2dof: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # output piped into `head` and the like
        sys.stderr.close()
        return 0


if __name__ == "__main__":
    sys.exit(main())
