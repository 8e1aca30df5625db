# `pm2dof design SUBCOMMAND`: design studies (run, show, pick): choose the robot's geometry.
import argparse
import pathlib
import sys

from ...core.errors import ArgumentError
from ..options import POSITIVE, count, progress, wrap


def add_parser(sub, common):
    p = sub.add_parser("design", help="design studies: search a model's geometry (run, show, "
                       "pick)",
                       description=wrap("A design study searches the [design] variables of a model "
                       "file (link lengths, base and attachment points) for the best "
                       "objectives (dexterity, force capability, a path's time-optimal "
                       "duration, a controller's RMSE, ...) under constraints, with pymoo's "
                       "NSGA-II (several objectives), GA or CMA-ES (one), or an exhaustive "
                       "grid. Each generation's designs are evaluated on Dask; every design "
                       "goes to Parquet in DIR/batches/. The study file is described in "
                       "docs/design-study-file.md."),
                       formatter_class=argparse.RawDescriptionHelpFormatter, epilog=(
                           "examples:\n"
                           "  pm2dof design run paper_legs --quick --out out/legs\n"
                           "  pm2dof design show out/legs\n"
                           "  pm2dof design pick out/legs 3 --out my_robot.toml\n"
                           "  pm2dof derive my_robot.toml && pm2dof simulate --model "
                           "my_robot.toml\n"
                           "  pm2dof design run paper_legs --optimizer grid --grid 100 "
                           "--out out/grid\n"
                           "  pm2dof design run my_study.toml --scheduler tcp://HOST:8786 "
                           "--out out/mine"))
    ssub = p.add_subparsers(dest="design_command", metavar="SUBCOMMAND", required=True)
    r = ssub.add_parser("run", help="run a design study's optimiser",
                        description=wrap("Run the optimiser of STUDY; every evaluated design is "
                        "written to DIR/batches/ (Parquet) as its chunk finishes, and the "
                        "front is printed at the end. Interrupted? Run the same command "
                        "again: the optimiser asks for the same designs (same seed) and the "
                        "ones already evaluated are read back. A different study (or "
                        "--quick, --optimizer, --grid) on a non-empty DIR is refused."),
                        formatter_class=argparse.RawDescriptionHelpFormatter, epilog=(
                            "examples:\n"
                            "  pm2dof design run paper_legs --quick --out out/legs\n"
                            "  pm2dof design run paper_legs --optimizer grid --grid 50 "
                            "--out out/grid --json"))
    r.add_argument("study", help="design study file (TOML), or a shipped study's name "
                   "(paper_legs, ...)")
    r.add_argument("--out", required=True, metavar="DIR", dest="out_dir",
                   help="output folder")
    r.add_argument("--quick", action="store_true",
                   help="the study file's [quick] size: a smaller population, fewer "
                   "generations, a coarser grid and region")
    r.add_argument("--optimizer", choices=("nsga2", "ga", "cmaes", "grid"),
                   help="override the study file's optimiser")
    r.add_argument("--grid", type=count(2, 1000), metavar="N",
                   help="points per variable of the grid optimiser (an N x N grid for two "
                   "variables)")
    r.add_argument("--workers", type=count(1, 4096), metavar="N",
                   help="worker processes of the embedded cluster (default: one per core)")
    r.add_argument("--scheduler", metavar="ADDRESS",
                   help="use an existing Dask cluster, e.g. tcp://10.0.0.5:8786 (its workers "
                   "need pm2dof installed, with the model file at the same path)")
    r.add_argument("--timeout", type=POSITIVE, default=10.0, metavar="S",
                   help="seconds to wait for the scheduler and its workers (default 10)")
    r.add_argument("--json", action="store_true", help="print the front as JSON")
    r.add_argument("--quiet", "--no-progress", action="store_true", dest="quiet",
                   help="no progress output (bars are drawn only on a terminal anyway)")
    r = ssub.add_parser("show", help="the front of a run: table, figures, the designs drawn",
                        description=wrap("Print the front of the designs a run evaluated (the "
                        "non-dominated feasible ones, numbered: the INDEX of design pick) and "
                        "write DIR/figures/front.png (the front among every design, the model file's own design "
                        "starred) and designs.png (chosen designs of the front to scale); then "
                        "the model file's design: on the front, or which designs of the front "
                        "dominate it and by how much."),
                        formatter_class=argparse.RawDescriptionHelpFormatter, epilog=(
                            "examples:\n"
                            "  pm2dof design show out/legs\n"
                            "  pm2dof design show out/legs --draw 0 5 --json"))
    r.add_argument("dir", metavar="DIR", help="the --out of `pm2dof design run`")
    r.add_argument("--json", action="store_true", help="print the front as JSON")
    r.add_argument("--no-figures", action="store_true", help="the table only")
    r.add_argument("--draw", type=count(0, 10**9), nargs="+", metavar="INDEX",
                   help="the front's designs drawn in designs.png (default: both ends of the "
                   "front and two between)")
    r = ssub.add_parser("pick", help="a plain model file at one design of the front",
                        description=wrap("Write the run's model file at the design INDEX of its "
                        "front (design show's #, from 0): the designed [[legs]] values set, "
                        "the [design] table removed, the comments kept. pm2dof derive then "
                        "derives it as a fixed model, which every command uses."),
                        formatter_class=argparse.RawDescriptionHelpFormatter, epilog=(
                            "example:\n"
                            "  pm2dof design pick out/legs 3 --out my_robot.toml\n"
                            "  pm2dof derive my_robot.toml"))
    r.add_argument("dir", metavar="DIR", help="the --out of `pm2dof design run`")
    r.add_argument("index", type=count(0, 10**9), metavar="INDEX",
                   help="the design's number in the front (from 0)")
    r.add_argument("--out", required=True, metavar="FILE", help="the model file to write")
    return p


def run(args):
    return _SUBCOMMANDS[args.design_command](args)


def _study(args):
    from ...synthesis.spec import find_design_study, read_design_study, with_overrides
    if args.grid is not None and args.optimizer not in (None, "grid"):
        raise ArgumentError(f"--grid sets the grid optimiser's size; it does not go with "
                            f"--optimizer {args.optimizer}")
    study = read_design_study(find_design_study(args.study))
    optimizer = "grid" if args.grid is not None and args.optimizer is None else args.optimizer
    return with_overrides(study, quick=args.quick, optimizer=optimizer, grid=args.grid)


def _run(args):
    from ...infra.results import dumps, output_folder
    from ...synthesis.front import format_front, read_front
    from ...synthesis.runner import format_notice, format_run, run_design
    if args.workers is not None and args.scheduler:
        raise ArgumentError("give --workers (an embedded cluster) or --scheduler (an existing "
                            "one), not both: an existing cluster's workers are started with it")
    output_folder(args.out_dir)
    study = _study(args)
    say = (lambda notice: print(format_notice(notice), file=sys.stderr if args.json
                                else sys.stdout))
    try:
        res = run_design(study, args.out_dir, workers=args.workers, scheduler=args.scheduler,
                         timeout=args.timeout, progress=progress(args), notify=say,
                         command_line=args.command_line)
    except KeyboardInterrupt:
        print(f"\npm2dof: interrupted; the evaluated designs are in {args.out_dir}/batches. Run "
              f"the same command again to continue where it stopped.", file=sys.stderr)
        return 130
    fr = read_front(args.out_dir)
    if args.json:
        print(dumps(fr.payload()))
    else:
        print(format_run(res, args.out_dir))
        print(format_front(fr))
    return 0


def _show(args):
    from ...infra.results import dumps
    from ...synthesis.front import format_front, read_front
    fr = read_front(args.dir)
    if args.draw and max(args.draw) >= len(fr.index):
        raise ArgumentError(f"--draw: INDEX must be in 0..{len(fr.index) - 1} (the front's "
                            f"designs), got {max(args.draw)}")
    print(dumps(fr.payload()) if args.json else format_front(fr))
    if not args.no_figures:
        from ...core.model import load_model
        from ...figures.design import design_figures
        model = load_model(fr.info["model_file"])
        prov = fr.info.get("provenance") or {}
        for p in design_figures(fr, model, pathlib.Path(args.dir) / "figures", prov,
                                picks=args.draw):
            print(f"wrote {p}", file=sys.stderr if args.json else sys.stdout)
    return 0


def _pick(args):
    from ...synthesis.pick import pick_design
    path, values = pick_design(args.dir, args.index, args.out, args.command_line)
    said = ", ".join(f"{k} = {v:.6g} m" for k, v in values.items())
    print(f"wrote {path}: design {args.index} of {args.dir} ({said}), without [design]. "
          f"Next: pm2dof derive {path}")
    return 0


_SUBCOMMANDS = {"run": _run, "show": _show, "pick": _pick}
