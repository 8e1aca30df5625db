# `pm2dof maps --out DIR`: singularity, conditioning and capability maps.
import sys

from ..options import POSITIVE, model, progress, tau_max


def add_parser(sub, common):
    p = sub.add_parser("maps", parents=[common], help="capability maps over the workspace (PNG)",
                       description="Map over the workspace, in the model's assembly mode: the "
                       "type I and type II singularity measures with their thresholds (and, for "
                       "two legs, the parallel-singular curve), cond(S^T S), the largest task "
                       "force available in every direction within tau_max for the min-norm split "
                       "(eq. 21) and for the min-max split (the circle inside the zonotope "
                       "{S^T tau : |tau_i| <= tau_max_i}) and their ratio, and the same for "
                       "acceleration at rest through Me (Tables 1-2); under gravity, what "
                       "tau_max leaves once the robot is held at rest at each pose. The model's "
                       "moves are drawn on every map. Writes maps_*.png and maps.json into --out.",
                       epilog="example: pm2dof maps --model fivebar --out out/maps")
    p.add_argument("--out", required=True, metavar="DIR", help="folder for the PNGs and maps.json")
    p.add_argument("--resolution", type=int, default=121, metavar="N",
                   help="grid points per axis, 5 to 1001 (default 121; about 1 s per 10^4 "
                   "points)")
    p.add_argument("--tau-max", type=POSITIVE, nargs="+", metavar="NM",
                   help="actuator limits, N m (N for a linear actuator): one value for all "
                   "or one per actuator (default: [limits].tau_max)")
    p.add_argument("--json", action="store_true", help="print the summary as JSON")
    return p


def run(args):
    from ...analysis.maps import format_maps_summary
    from ...figures.maps import maps_figures
    from ...infra.results import dumps
    m = model(args)
    summary, paths = maps_figures(m, args.out, args.resolution, tau_max=tau_max(args, m),
                                  progress=progress(args), command_line=args.command_line)
    print(dumps(summary) if args.json else format_maps_summary(summary))
    for p in paths:
        print(f"wrote {p}", file=sys.stderr if args.json else sys.stdout)
    return 0
