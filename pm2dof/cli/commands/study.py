# `pm2dof study SUBCOMMAND`: many-rollout studies on Dask (run, show, report, bench).
import argparse
import pathlib
import sys

from ...core.errors import ArgumentError
from ..options import POSITIVE, progress


def add_parser(sub, common):
    p = sub.add_parser("study", help="many-rollout studies on Dask (run, show, report, bench)",
                       description="Studies run thousands to millions of closed-loop rollouts "
                       "(controller x move x random plant x repetition) described by a study "
                       "file (TOML), on Dask: an embedded LocalCluster by "
                       "default, or an existing cluster with --scheduler. Rows (one per "
                       "rollout) go to Parquet in DIR/results/.",
                       formatter_class=argparse.RawDescriptionHelpFormatter, epilog=(
                           "examples:\n"
                           "  pm2dof study run robustness --quick --out out/rob\n"
                           "  pm2dof study report out/rob\n"
                           "  dask scheduler --port 8786 &  dask worker tcp://HOST:8786 &\n"
                           "  pm2dof study run gains --scheduler tcp://HOST:8786 "
                           "--out out/gains"))
    ssub = p.add_subparsers(dest="study_command", metavar="SUBCOMMAND", required=True)
    r = ssub.add_parser("run", help="run every rollout of a study file",
                        description="Run every rollout of STUDY into DIR/results/ (Parquet, one "
                        "row per rollout, written chunk by chunk as they finish). Interrupted? "
                        "Run the same command again: finished chunks are skipped. A different "
                        "study on a non-empty DIR is refused. Rows depend only on the study file "
                        "(seed, draw), not on the workers or the cluster. Every key of a study "
                        "file is listed in docs/study-file.md; the shipped studies "
                        "(robustness, gains, adaptation, model_based) are commented examples: "
                        "see them with `pm2dof study show NAME`.")
    r.add_argument("study", help="study file (TOML), or a shipped study's name: robustness, "
                   "gains, adaptation, model_based")
    r.add_argument("--model", metavar="NAME|PATH", help="run the study on this model instead of "
                   "the one its file names")
    r.add_argument("--generated", metavar="DIR", help="the model's generated C, when not in "
                   "the default folder (overrides the study file's generated key)")
    r.add_argument("--out", required=True, metavar="DIR", help="output folder")
    r.add_argument("--workers", type=int, metavar="N",
                   help="worker processes of the embedded cluster (default: one per core)")
    r.add_argument("--scheduler", metavar="ADDRESS",
                   help="use an existing Dask cluster, e.g. tcp://10.0.0.5:8786 (its workers need "
                   "pm2dof installed, with the model file at the same path)")
    r.add_argument("--quick", action="store_true",
                   help="the study file's [quick] size: seconds, for a first look and the tests")
    r.add_argument("--timeout", type=POSITIVE, default=10.0, metavar="S",
                   help="seconds to wait for the scheduler and its workers (default 10)")
    r.add_argument("--quiet", "--no-progress", action="store_true", dest="quiet",
                   help="no progress output (bars are drawn only on a terminal anyway)")
    r = ssub.add_parser("show", help="print a shipped study file (a commented example)",
                        description="Print a shipped study file, or list them without NAME. "
                        "Start your own: pm2dof study show robustness > my_study.toml, edit its "
                        "model key (a shipped model's name or a path relative to the study file)")
    r.add_argument("name", nargs="?", metavar="NAME", help="robustness, gains, adaptation or "
                   "model_based")
    r = ssub.add_parser("report", help="summary tables and figures of a study's results",
                        description="Read DIR/results and print: RMSE (eq. 41) per controller "
                        "and move; the RPE of every NA variant over APD on the same plants; the "
                        "best point and flatness of every gain grid; RMSE and theta error "
                        "against the repetition index. Writes PNG figures into DIR/figures.")
    r.add_argument("dir", metavar="DIR", help="the --out of `pm2dof study run`")
    r.add_argument("--json", action="store_true", help="print the summary as JSON")
    r.add_argument("--no-figures", action="store_true", help="tables only")
    r = ssub.add_parser("bench", help="rollouts per second: plain loop, batch, Dask 1 and 2 "
                        "workers", description="High-speed-move rollouts per second, measured "
                        "in one run: simulate() in a Python loop, the batch path in one process "
                        "(run_chunk), and the same chunks on a LocalCluster of 1 and of 2 "
                        "worker processes (started before the clock). Targets: batch >= 4000/s "
                        "on one core; 2 workers >= 1.7x one; Dask (1 worker) within 10 % of "
                        "the in-process batch at 10^4 rollouts.")
    r.add_argument("--json", action="store_true", help="print the results as JSON")
    r.add_argument("--quick", action="store_true", help="10x fewer rollouts (for tests)")
    r.add_argument("--quiet", action="store_true", help="no progress output on stderr")
    return p


def run(args):
    return _SUBCOMMANDS[args.study_command](args)


def _run(args):
    from ...studies import read_study, resolve_study, run_study
    from ...studies.runner import format_notice, format_run
    if args.workers is not None and args.scheduler:
        raise ArgumentError("give --workers (an embedded cluster) or --scheduler (an existing "
                            "one), not both: an existing cluster's workers are started with it")
    study = read_study(resolve_study(args.study), quick=args.quick, model=args.model,
                       generated=args.generated)       # --model, --generated: the file's replaced
    try:
        res = run_study(study, args.out, workers=args.workers, scheduler=args.scheduler,
                        timeout=args.timeout, progress=progress(args),
                        notify=lambda notice: print(format_notice(notice)),
                        command_line=args.command_line)
    except KeyboardInterrupt:
        print(f"\npm2dof: interrupted; the finished chunks are in {args.out}/results. Run the "
              f"same command again to continue where it stopped.", file=sys.stderr)
        return 130
    print(format_run(res, args.out))
    return 0


def _show(args):
    from ...studies import SHIPPED_STUDIES, resolve_study
    if args.name is None:
        for f in sorted(SHIPPED_STUDIES.glob("*.toml")):
            print(f.stem)
        return 0
    path = resolve_study(args.name)
    if not path.is_file():
        raise ArgumentError(f"no study file {path} (shipped: "
                            f"{', '.join(f.stem for f in sorted(SHIPPED_STUDIES.glob('*.toml')))})")
    sys.stdout.write(path.read_text())
    return 0


def _report(args):
    from ...infra.results import dumps
    from ...studies.jobs import run_report
    from ...studies.report import format_report
    r = run_report(args.dir)
    print(dumps(r.summary) if args.json else format_report(r.summary))
    if not args.no_figures:
        from ...figures.studies import study_figures
        for p in study_figures(r.columns, r.summary, pathlib.Path(args.dir) / "figures",
                               r.provenance, r.info.get("payload_change")):
            print(f"wrote {p}", file=sys.stderr if args.json else sys.stdout)
    return 0


def _bench(args):
    from ...infra.results import dumps
    from ...studies.bench import format_study_bench, study_bench
    res = study_bench(quick=args.quick, progress=None if args.json else progress(args))
    print(dumps(res) if args.json else format_study_bench(res))
    return 0


_SUBCOMMANDS = {"run": _run, "show": _show, "report": _report, "bench": _bench}
