# `pm2dof plan`: time-optimal motion along a path, with either torque split.
import pathlib
import sys

from ..options import POSITIVE, count, model, number, progress, tau_max


def add_parser(sub, common):
    p = sub.add_parser("plan", parents=[common], help="time-optimal motion along a path",
                       description="Time a path as fast as the motors allow: the "
                       "kinematic S-curve of the path's arc length beside the time-optimal "
                       "timing under the torque limits with the min-norm split (eq. 21) and the "
                       "min-max split (the whole redundancy), friction included. The paths are "
                       "the model file's moves (start to end as lines) or a path file (--path: "
                       "a shipped name such as pick_and_place, or your TOML file; its format: "
                       "docs/using-planning.md, Path files).",
                       epilog="examples: pm2dof plan --tau-max 6 --closed-loop; pm2dof plan "
                       "--path pick_and_place --out out/plan")
    p.add_argument("--path", metavar="NAME|FILE", help="a path file (default: the moves)")
    p.add_argument("--move", help="only this move of the model file (default: every move)")
    p.add_argument("--tau-max", type=POSITIVE, nargs="+", metavar="NM",
                   help="actuator limits, N m (N for a linear actuator): one value for all "
                   "or one per actuator (default: [limits].tau_max)")
    p.add_argument("--margin", type=number(0.0, 1.0), default=1.0,
                   help="plan with tau_max * margin (default 1.0)")
    p.add_argument("--grid", type=count(2, 100000), default=1000,
                   help="about this many grid points (default 1000): graded, finer near the "
                   "stops, at least 2 intervals between two stops and a point at every junction "
                   "of the path's pieces, then refined until the plan resolves the path; the "
                   "count used is in the output")
    p.add_argument("--split", choices=["both", "min_norm", "min_max"], default="both",
                   help="torque split(s) to plan with (default both)")
    for flag, what in (("--v-max", "m/s"), ("--a-max", "m/s^2"), ("--j-max", "m/s^3")):
        p.add_argument(flag, type=POSITIVE, help=f"kinematic S-curve limit, {what} (default: the "
                       "move's, the path file's [kinematic], else the model's last move's)")
    p.add_argument("--smooth", action="store_true", help="also the torque-rate-limited "
                   "near-time-optimal plan (CasADi + IPOPT; needs casadi)")
    p.add_argument("--tau-rate", type=POSITIVE, metavar="NM_PER_S",
                   help="--smooth: largest |dtau/dt|, N m/s (N/s for a linear actuator; "
                   "default tau_max / 20 ms)")
    p.add_argument("--closed-loop", action="store_true",
                   help="simulate NA and APD, with the same split, tracking the time-optimal "
                   "plan of the last split --split names (min-max for the default both, "
                   "min-norm with --split min_norm) at each of --margins")
    p.add_argument("--margins", type=number(0.0, 1.0), nargs="+", default=[1.0, 0.9],
                   help="--closed-loop: the margins to plan with (default 1.0 0.9)")
    p.add_argument("--out", metavar="DIR", help="write each plan's trajectory (CSV) and the "
                   "figures (phase plane, torques, path on the force map) here")
    p.add_argument("--json", action="store_true", help="print the numbers as JSON")
    return p


def run(args):
    from ...core.errors import ArgumentError
    from ...infra.results import dumps
    from ...planning.jobs import run_plan, write_plan_csvs
    from ...planning.report import format_report
    if args.tau_rate is not None and not args.smooth:
        raise ArgumentError("--tau-rate limits the smoothed plan's torque rate: add --smooth")
    m = model(args)
    said = progress(args)           # stage lines on stderr, with --json too (stdout stays JSON)
    r = run_plan(
        m, path=args.path, move=args.move, tau_max=tau_max(args, m), margin=args.margin,
        grid=args.grid, splits=("min_norm", "min_max") if args.split == "both" else (args.split,),
        kinematic={k: getattr(args, k) for k in ("v_max", "a_max", "j_max")},
        smooth=args.smooth, tau_rate=args.tau_rate,
        closed_loop_margins=args.margins if args.closed_loop else None, progress=said,
        command_line=args.command_line)
    print(dumps(r.summary) if args.json else format_report(r.summary))
    if args.out:
        from ...figures.planning import plan_figures
        written = write_plan_csvs(r, args.out)
        said("figures: the phase plane, the torques and the path on the force map")
        written += plan_figures(r.model, r.plans, pathlib.Path(args.out), r.provenance,
                                r.summary["tau_max"])
        for p in written:
            print(f"wrote {p}", file=sys.stderr if args.json else sys.stdout)
    return 0
