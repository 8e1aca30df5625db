# Command-line interface: parses `pm2dof COMMAND ...` and dispatches to the command's layer.
"""pm2dof: the Shang & Cong (2010) planar parallel manipulator, from model file to fast C.

Typical use:
  pm2dof demo                 the main job: Table 3 simulated, figures, repeated runs
  pm2dof table3 [--json]      the paper's Table 3: APD vs NA (and NA with Gamma = 0)
  pm2dof simulate --reference F   controllers tracking a reference file (CSV or Parquet)
  pm2dof figures --out DIR    error, torque, theta_hat and repeated-run figures (PNG)
  pm2dof report               what the compiled model says (Me, cond(S^T S), rank of Y)
  pm2dof identify report      identifiable parameters (base parameters, null space)
  pm2dof identify fit [LOG]   least squares for theta from a log (without one: a simulated run)
  pm2dof splits [--tau-max X] torque splits (min-norm, min-max, preload) in closed loop
  pm2dof maps --out DIR       singularities, conditioning, force/acceleration capability maps
  pm2dof animate --out F.gif  the move as an animation: legs to scale, error magnified
  pm2dof study run S.toml --out DIR   many rollouts on Dask (robustness, gains, adaptation)
  pm2dof study report DIR     summary tables and figures of a study's results
  pm2dof plan [--path P]      time-optimal motion along a path, with either torque split
  pm2dof bench [--json]       controller step time: C, Python binding, CasADi, NumPy, SymPy
  pm2dof models               the shipped models, with their descriptions
  pm2dof derive MYROBOT.toml  derive your own model file: C into generated/MYROBOT/ beside it
  pm2dof export MODEL --out DIR   the controllers as a standalone C99 library (CMake)

The model: every command that uses one takes --model NAME|PATH, a shipped model's name
(`pm2dof models` lists them) or your model file (default: shang2010, the paper's robot), and
--generated DIR when its generated C is not in the default folder (generated/<stem>/ beside
the model file). Where a file names its model (a study file; a log or an excitation file, for
pm2dof identify), that model is the default: --model overrides a study's, and must match a
log's or an excitation file's. Run `pm2dof COMMAND --help` for the details of one command.
"""
import argparse
import sys
import warnings
from pathlib import Path

from .core.errors import ArgumentError, OutcomeWarning, Pm2dofError
from .infra.progress import Progress

__all__ = ["main", "build_parser"]


def _number(low=None, high=None, *, low_inclusive=False, high_inclusive=True):
    """An argparse type: a finite float within (low, high] (bounds as given), else a usage
    error naming the range (argparse prints it with the option's name, exit 2)."""
    import math

    def convert(text):
        try:
            x = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
        below = low is not None and (x < low if low_inclusive else x <= low)
        above = high is not None and (x > high if high_inclusive else x >= high)
        if not math.isfinite(x) or below or above:
            lo = "" if low is None else f"{'>=' if low_inclusive else '>'} {low:g}"
            hi = "" if high is None else f"{'<=' if high_inclusive else '<'} {high:g}"
            raise argparse.ArgumentTypeError(
                f"must be a finite number {' and '.join(b for b in (lo, hi) if b)}, got {text}")
        return x
    return convert


def _count(low, high):
    """An argparse type: a whole number in [low, high]."""
    def convert(text):
        try:
            k = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
        if not low <= k <= high:
            raise argparse.ArgumentTypeError(f"must be in [{low}, {high}], got {k}")
        return k
    return convert


_POSITIVE = _number(0.0)
_NONNEGATIVE = _number(0.0, low_inclusive=True)


#: where long jobs report (stage lines; bars on a terminal); main() makes it quiet on --quiet
_progress = Progress()


def _model(args):
    from .core.model import load_model
    return load_model(args.model, args.generated)


def cmd_models(args):
    from .core.model_file import read_model_file
    from .core.paths import shipped_models
    rows = []
    for name, (path, desc) in shipped_models().items():
        spec = read_model_file(path)
        rows.append((name, f"{spec.n_legs} legs", desc))
    w = max(len(r[0]) for r in rows)
    for name, legs, desc in rows:
        print(f"{name:{w}s}  {legs}  {desc}")
    print("\nLoad one with --model NAME or pm2dof.load_model(NAME). To start your own robot, "
          "copy one (pm2dof models --copy NAME DIR) and run pm2dof derive DIR/NAME.toml.")
    return 0


def cmd_models_copy(args):
    import shutil
    from .core.paths import resolve_model
    from .core.errors import OutputError
    src = resolve_model(args.copy[0])
    dest = Path(args.copy[1]).expanduser()
    if dest.suffix != ".toml":      # a folder (created if need be), as in `--copy NAME ~/robots`
        dest = dest / src.name
    if dest.exists():
        raise ArgumentError(f"{dest} exists; not overwritten (choose another folder or remove it)")
    try:
        dest.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(src, dest)
    except OSError as exc:
        raise OutputError(f"cannot write {dest}: {exc.strerror or exc}") from None
    print(f"wrote {dest}. Edit it (keep or change [model].name), then: pm2dof derive {dest}")
    return 0


# one dispatcher per command: load what it needs, call its layer, print
def cmd_report(args):
    from .analysis.report import model_report
    print(model_report(_model(args)))
    return 0


def cmd_derive(args):
    if args.path and args.model and args.path != args.model:
        raise ArgumentError(f"give the model once: positional {args.path!r} or --model "
                         f"{args.model!r}, not both")
    if not (args.path or args.model):
        raise ArgumentError("pm2dof derive needs a model file: copy a shipped one with `pm2dof "
                            "models --copy shang2010 ~/robots`, edit it, then `pm2dof derive "
                            "~/robots/shang2010.toml` (`pm2dof models` lists them)")
    from .core.generated import derive_is_current
    try:
        out, current, _ = derive_is_current(args.path or args.model, args.out,
                                            library=not args.no_build)
    except Pm2dofError:                 # a bad model file or folder: derive says what is wrong
        current = False
    if current and not args.force:     # no SymPy, no CasADi: well under a second
        print(f"{out} is up to date (its manifest matches the model file, the derivation and "
              f"its compiled library); --force derives again")
        return 0
    from .derive.run import derive  # needs the [derive] extra (SymPy, CasADi); main() says so
    derive(args.path or args.model, args.out, force=args.force, build=not args.no_build,
           progress=lambda msg: print(msg, flush=True))
    return 0


def cmd_table3(args):
    from .analysis.experiment import run_table3
    run_table3(_model(args), as_json=args.json, exact_encoders=args.exact_encoders,
               save=args.save, progress=_progress, include=tuple(args.include))
    return 0


def cmd_simulate(args):
    import json

    from .analysis.reference_file import reference_summary, simulate_reference
    res = reference_summary(simulate_reference(_model(args), args.reference, args.controller,
                                               split=args.split, settle_time=args.settle))
    if args.json:
        print(json.dumps(res, indent=1))
        return 0
    print(f"{'law':5s} {'RMSE m':>11s} {'max err m':>11s} {'peak tau':>9s} {'saturated':>9s}  "
          f"outcome")
    for law, r in res.items():
        print(f"{law:5s} {r['rmse_m']:11.4e} {r['max_error_m']:11.4e} {r['peak_tau']:9.4g} "
              f"{r['n_saturated']:9d}  {r['outcome_message']}")
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


def _identify(cmd):
    """``cmd`` with --model/--generated given before the sub-command taken as given after it."""
    def run(args):
        for key in ("model", "generated"):
            before = getattr(args, f"identify_{key}", None)
            if before is not None:
                if getattr(args, key) not in (None, before):
                    raise ArgumentError(f"--{key} given twice ({before!r} before the "
                                        f"sub-command, {getattr(args, key)!r} after it)")
                setattr(args, key, before)
        return cmd(args)
    return run


def _ident_progress(args):
    """Stage lines and bars on stderr (main()'s, --quiet aside); none with --json."""
    return None if getattr(args, "json", False) else _progress


def cmd_identify_report(args):
    from .identification.base import format_identifiability, identifiability
    print(format_identifiability(identifiability(_model(args))))
    return 0


def cmd_identify_excite(args):
    from .identification.excitation import run_excite
    run_excite(args.out, model=args.model, generated=args.generated,
               excitation_file=args.excitation, duration=args.duration,
               quantise=not args.exact_encoders, controller=args.controller,
               progress=_ident_progress(args))
    return 0


def cmd_identify_fit(args):
    from .analysis.experiment import seeded_table3
    from .identification.report import run_fit
    run_fit(args.log, model=args.model, generated=args.generated,
            excitation_file=args.excitation, duration=args.duration,
            quantise=not args.exact_encoders, controller=args.controller, save=args.save,
            as_json=args.json, cutoff_hz=args.cutoff, min_joint_speed=args.min_joint_speed,
            time_tolerance=args.time_tolerance,
            seed=seeded_table3 if args.seed_na else None,
            progress=_ident_progress(args))
    return 0


def cmd_identify_design(args):
    from .identification.design import run_design
    run_design(_model(args), args.out, base_hz=args.base_hz, harmonics=args.harmonics,
               periods=args.periods, v_max=args.v_max, a_max=args.a_max,
               tau_fraction=args.tau_fraction, seed=args.seed, progress=_ident_progress(args))
    return 0


def cmd_identify_monte_carlo(args):
    from .identification.monte_carlo import run_monte_carlo
    run_monte_carlo(args.seeds, model=args.model, generated=args.generated,
                    excitation_file=args.excitation, duration=args.duration, as_json=args.json,
                    progress=_ident_progress(args))
    return 0


def cmd_identify_without_subcommand(args):
    raise ArgumentError("pm2dof identify needs a sub-command: report, excite, fit, design or "
                        "monte-carlo (plain `pm2dof identify` was replaced by: pm2dof identify "
                        "report, and pm2dof identify fit)")


def _wrap(text):
    """A description wrapped for a parser whose epilog keeps its line breaks."""
    import textwrap
    return textwrap.fill(text, 79)


def _identify_parser(sub, common):
    p = sub.add_parser("identify", help="identification of theta: report, excite, fit, design, "
                       "monte-carlo",
                       description=_wrap("Identify the dynamic parameters theta (eq. 13: S^T "
                       "tau_a = Y theta) from logs of encoder angles and commanded torques: which "
                       "combinations of theta the data can determine (report), an excitation "
                       "to run (design), a run of it on the simulated robot written as a log "
                       "(excite), and least squares from a log or a simulated run (fit). Logs "
                       "and excitation files record their model (a shipped model's name or the "
                       "model file's path relative to themselves): that model is the default "
                       "of fit, excite and monte-carlo, and --model must match it. The results: "
                       "docs/results-identification.md."),
                       formatter_class=argparse.RawDescriptionHelpFormatter, epilog=(
                           "examples:\n"
                           "  pm2dof identify report\n"
                           "  pm2dof identify design --out exc.toml\n"
                           "  pm2dof identify excite --excitation exc.toml --out run.csv\n"
                           "  pm2dof identify fit run.csv --save theta.json --seed-na\n"
                           "  pm2dof identify monte-carlo 50 --excitation exc.toml"))
    for flag in ("--model", "--generated"):   # before the sub-command: as after it
        p.add_argument(flag, dest=f"identify_{flag[2:]}", help=argparse.SUPPRESS)
    p.set_defaults(func=cmd_identify_without_subcommand)
    isub = p.add_subparsers(dest="identify_command", metavar="SUBCOMMAND")

    def excitation_options(r, what):
        r.add_argument("--excitation", metavar="FILE", help=f"excitation file to {what} "
                       "(written by `pm2dof identify design`); its model is the default")
        r.add_argument("--duration", type=_number(0.0, 3600.0), metavar="S", help="without --excitation: "
                       "length of the default multi-sine, s (default 4)")

    def simulated_options(r, when=""):
        r.add_argument("--exact-encoders", action="store_true",
                       help=f"{when}no encoder quantisation (a noise-free log)")
        r.add_argument("--controller", choices=["apd", "na"],
                       help=f"{when}controller tracking the excitation, with Tables 1-2 "
                       "(default apd)")

    def sub_command(name, help, description, examples, func):
        r = isub.add_parser(name, parents=[common], help=help, description=_wrap(description),
                            formatter_class=argparse.RawDescriptionHelpFormatter,
                            epilog="examples:\n" + "\n".join(f"  {e}" for e in examples))
        r.set_defaults(func=_identify(func))
        return r

    sub_command("report", "identifiable parameters: base parameters, null space",
                "Stack the regressor Y over random states around the middle of the model's "
                "first move and print its rank, the identifiable base parameters (each "
                "independent column of Y with the dependent ones folded in) and the directions "
                "of theta no motion can show (the null space of Y).",
                ["pm2dof identify report --model fivebar"], cmd_identify_report)

    r = sub_command("excite", "run an excitation on the simulated robot and write its log",
                    "Run an excitation on the simulated plant (its truth: [plant] of the model "
                    "file; quantised encoders; a controller with Tables 1-2 tracking) and write "
                    "what a real set-up logs, encoder angles and commanded torques, to --out "
                    "(CSV or Parquet by the suffix; the format: docs/log-format.md). The log "
                    "records its model relative to itself.",
                    ["pm2dof identify excite --excitation exc.toml --out run.csv",
                     "pm2dof identify excite --duration 10 --out run.parquet"],
                    cmd_identify_excite)
    r.add_argument("--out", required=True, metavar="LOG", help="log to write (.csv or .parquet)")
    excitation_options(r, "run")
    simulated_options(r)

    r = sub_command("fit", "least squares for theta from a log (or a simulated run)",
                    "Identify the base parameters from LOG (t, qa1..qan, tau1..taun, optional "
                    "qb1..qbn; the format: docs/log-format.md): fk of the encoder angles, a "
                    "zero-phase Butterworth low-pass, central differences, the same filter on "
                    "the regressor and on S^T tau, weighted least squares with a Newey-West "
                    "covariance (+-2 sigma), then a physically consistent full theta (CasADi + "
                    "IPOPT). The model is the one the log records unless --model is given. "
                    "Without LOG, an excitation first runs on the simulated plant (as "
                    "`identify excite` does) and its log goes through the same pipeline and "
                    "the same report, with the plant's truth beside the estimate.",
                    ["pm2dof identify fit run.csv --save theta.json --seed-na",
                     "pm2dof identify fit --json       # the default 4 s multi-sine, simulated"],
                    cmd_identify_fit)
    r.add_argument("log", nargs="?", metavar="LOG", help="log file (.csv or .parquet); without "
                   "it, a simulated excitation run")
    r.add_argument("--save", metavar="FILE", help="write the estimate, a full theta0 and the "
                   "provenance as JSON")
    r.add_argument("--json", action="store_true", help="print the results as JSON")
    r.add_argument("--seed-na", action="store_true",
                   help="also Table 3 with APD and NA using the identified theta")
    r.add_argument("--cutoff", type=_POSITIVE, metavar="HZ",
                   help="low-pass cutoff (default 10 x the excitation band)")
    r.add_argument("--time-tolerance", type=_number(0.0, 1.0, low_inclusive=True,
                   high_inclusive=False), default=1e-3, metavar="FRACTION",
                   help="largest allowed |t_k+1 - t_k - T| / T of LOG (default 1e-3)")
    r.add_argument("--min-joint-speed", type=_NONNEGATIVE, metavar="RAD_S",
                   help="leave out samples with a slower active joint (default 0.1; 0 keeps all)")
    excitation_options(r, "simulate without LOG")
    simulated_options(r, "without LOG: ")

    r = sub_command("design", "design a D-optimal excitation (1-2 minutes)",
                    "Design a periodic excitation (a finite Fourier series in task space, "
                    "Swevers et al. 1997) that maximises log det of the base regressor's "
                    "information matrix, with CasADi + IPOPT (1-2 minutes), within speed, "
                    "acceleration, torque, singularity and region limits checked every 1 ms, and "
                    "write it as TOML to --out (the model recorded relative to the file).",
                    ["pm2dof identify design --out exc.toml"], cmd_identify_design)
    r.add_argument("--out", required=True, metavar="FILE", help="excitation file to write (TOML)")
    for flag, kind, default, text in (
            ("--base-hz", float, 0.2, "base frequency f0, Hz (default 0.2: 5 s period)"),
            ("--harmonics", int, 10, "harmonics of f0 (default 10: up to 2 Hz)"),
            ("--periods", int, 2, "periods per run (default 2: 10 s)"),
            ("--v-max", float, 0.5, "task speed limit, m/s (default 0.5)"),
            ("--a-max", float, 10.0, "task acceleration limit, m/s^2 (default 10)"),
            ("--tau-fraction", float, 0.5, "torque limit / tau_max (default 0.5)"),
            ("--seed", int, 0, "seed of IPOPT's random start (default 0)")):
        r.add_argument(flag, type=kind, default=default, help=text)

    r = sub_command("monte-carlo", "the identification targets measured over N seeds",
                    "Measure the identification targets over N seeds: each draws a plant truth "
                    "around [plant] (inertia and friction x (1 + 0.1 N(0, 1)), payload 0-0.5 kg) "
                    "and encoder noise, runs the excitation on it, identifies from the log alone "
                    "and compares with the truth.",
                    ["pm2dof identify monte-carlo 50 --excitation exc.toml"],
                    cmd_identify_monte_carlo)
    r.add_argument("seeds", type=_count(1, 100000), metavar="N", help="number of seeds")
    r.add_argument("--json", action="store_true", help="print the results as JSON")
    excitation_options(r, "run")


def cmd_splits(args):
    from .analysis.splits import run_splits
    run_splits(_model(args), args.tau_max, args.preload, args.preload_sign, as_json=args.json,
               progress=None if args.json else _progress)
    if args.out:
        from .figures.splits import splits_figure
        path, _ = splits_figure(_model(args), args.out, preload=args.preload,
                                preload_sign=args.preload_sign, progress=_progress)
        print(f"wrote {path}", file=sys.stderr if args.json else sys.stdout)
    return 0


def _per_actuator(values, n, flag):
    if len(values) not in (1, n):
        raise ArgumentError(f"{flag}: give one value or {n} (one per actuator), got {len(values)}")
    if not all(v > 0 for v in values):
        raise ArgumentError(f"{flag}: every value must be > 0, got {values}")
    return [values[0]] * n if len(values) == 1 else list(values)


def cmd_maps(args):
    from .figures.maps import maps_figures
    from .infra.results import dumps
    m = _model(args)
    tau_max = None if args.tau_max is None else _per_actuator(args.tau_max, m.n_legs, "--tau-max")
    summary, paths = maps_figures(m, args.out, args.resolution, tau_max=tau_max,
                                  progress=_progress)
    if args.json:
        print(dumps(summary))
    else:
        from .analysis.maps import format_maps_summary
        print(format_maps_summary(summary))
    for p in paths:
        print(f"wrote {p}", file=sys.stderr if args.json else sys.stdout)
    return 0


def cmd_animate(args):
    from .figures.animate import animate_move
    path, r = animate_move(_model(args), args.out, args.move, args.controller, args.split,
                           args.magnify, args.fps, args.every, progress=_progress)
    print(f"wrote {path} ({r.controller}, {r.outcome_message}, RMSE {r.rmse:.4g} m, "
          f"{r.n_saturated} saturated samples)")
    return 0


def cmd_study_run(args):
    from .studies import read_study, resolve_study, run_study
    if args.workers is not None and args.scheduler:
        raise ArgumentError("give --workers (an embedded cluster) or --scheduler (an existing "
                         "one), not both: an existing cluster's workers are started with it")
    study = read_study(resolve_study(args.study), quick=args.quick, model=args.model,
                       generated=args.generated)       # --model, --generated: the file's replaced
    try:
        res = run_study(study, args.out, workers=args.workers, scheduler=args.scheduler,
                        timeout=args.timeout, progress=_progress)
    except KeyboardInterrupt:
        print(f"\npm2dof: interrupted; the finished chunks are in {args.out}/results. Run the "
              f"same command again to continue where it stopped.", file=sys.stderr)
        return 130
    if res["skipped"] == res["chunks"]:
        print(f"{res['rows']} rows in {args.out}/results: all {res['chunks']} chunks were already "
              f"there, nothing to run. Next: pm2dof study report {args.out}")
        return 0
    print(f"{res['rows']} rows in {args.out}/results ({res['skipped']} of {res['chunks']} chunks "
          f"were already there). Wall time {res['seconds']:.1f} s, {res['rollouts_per_s']:,.0f} "
          f"rollouts/s, including {res['cluster_seconds']:.1f} s to set up and close the cluster; "
          f"running the rollouts {res['run_seconds']:.1f} s, {res['run_rollouts_per_s']:,.0f} "
          f"rollouts/s (the rate the progress bar shows on a terminal). Next: pm2dof study "
          f"report {args.out}")
    return 0


def cmd_study_show(args):
    from .studies import SHIPPED_STUDIES, resolve_study
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


def cmd_study_report(args):
    from .studies.report import run_report
    s, cols, info = run_report(args.dir, as_json=args.json)
    if not args.no_figures:
        from .figures.studies import study_figures
        for p in study_figures(cols, s, Path(args.dir) / "figures", info.get("provenance", {}),
                               info.get("payload_change")):
            print(f"wrote {p}", file=sys.stderr if args.json else sys.stdout)
    return 0


def cmd_study_bench(args):
    from .infra.results import dumps
    from .studies.bench import format_study_bench, study_bench
    res = study_bench(quick=args.quick, progress=None if args.json else _progress)
    print(dumps(res) if args.json else format_study_bench(res))
    return 0


def _study_parser(sub):
    p = sub.add_parser("study", help="many-rollout studies on Dask (run, report, bench)",
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
                        "(robustness, gains, adaptation) are commented examples: see them with "
                        "`pm2dof study show NAME`.")
    r.add_argument("study", help="study file (TOML), or a shipped study's name: robustness, "
                   "gains, adaptation")
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
    r.add_argument("--timeout", type=_POSITIVE, default=10.0, metavar="S",
                   help="seconds to wait for the scheduler and its workers (default 10)")
    r.add_argument("--quiet", "--no-progress", action="store_true", dest="quiet",
                   help="no progress output (bars are drawn only on a terminal anyway)")
    r.set_defaults(func=cmd_study_run)
    r = ssub.add_parser("show", help="print a shipped study file (a commented example)",
                        description="Print a shipped study file, or list them without NAME. "
                        "Start your own: pm2dof study show robustness > my_study.toml, edit its "
                        "model key (a shipped model's name or a path relative to the study file)")
    r.add_argument("name", nargs="?", metavar="NAME", help="robustness, gains or adaptation")
    r.set_defaults(func=cmd_study_show)
    r = ssub.add_parser("report", help="summary tables and figures of a study's results",
                        description="Read DIR/results and print: RMSE (eq. 41) per controller "
                        "and move; the RPE of every NA variant over APD on the same plants; the "
                        "best point and flatness of every gain grid; RMSE and theta error "
                        "against the repetition index. Writes PNG figures into DIR/figures.")
    r.add_argument("dir", metavar="DIR", help="the --out of `pm2dof study run`")
    r.add_argument("--json", action="store_true", help="print the summary as JSON")
    r.add_argument("--no-figures", action="store_true", help="tables only")
    r.set_defaults(func=cmd_study_report)
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
    r.set_defaults(func=cmd_study_bench)


def cmd_plan(args):
    from .infra.results import dumps, provenance, write_atomic
    from .planning.report import closed_loop, csv_text, format_report, model_moves, plan_paths
    if args.tau_rate is not None and not args.smooth:
        raise ArgumentError("--tau-rate limits the smoothed plan's torque rate: add --smooth")
    m = _model(args)
    tau_max = None if args.tau_max is None else _per_actuator(args.tau_max, m.n_legs, "--tau-max")
    if args.path:
        from .planning.pathfile import read_path_file
        items = [read_path_file(args.path)]
    else:
        items = [mv for mv in model_moves(m) if args.move in (None, mv.name)]
        if not items:
            raise ArgumentError(f"--move {args.move!r}: the model file's moves are "
                                f"{sorted(m.spec.trajectories)}")
    kin = {k: getattr(args, k) for k in ("v_max", "a_max", "j_max")}
    if any(v is not None for v in kin.values()):     # the options override the item's limits
        from dataclasses import replace

        def given(it):
            base = it.kinematic or model_moves(m)[-1].kinematic
            return replace(it, kinematic={k: (base[k] if v is None else v)
                                          for k, v in kin.items()})
        items = [given(it) for it in items]
    splits = ("min_norm", "min_max") if args.split == "both" else (args.split,)
    res, plans = plan_paths(m, items, tau_max, args.margin, args.grid, splits,
                            smooth=args.smooth, tau_rate=args.tau_rate)
    loops = {}
    if args.closed_loop:
        for it in items:
            loops[it.name] = closed_loop(m, it.path, tau_max, splits[-1], args.margins,
                                            args.grid)
        res["closed_loop"] = loops
    print(dumps(res) if args.json else format_report(res, loops))
    if args.out:
        from pathlib import Path
        from .figures.planning import plan_figures
        out, prov = Path(args.out), provenance(m)
        written = []
        for (name, key), p in plans.items():
            written.append(write_atomic(out / f"plan_{name}_{key}.csv",
                                        csv_text(m, p).encode()))
        written += plan_figures(m, plans, out, prov, res["tau_max"])
        for p in written:
            print(f"wrote {p}", file=sys.stderr if args.json else sys.stdout)
    return 0


def cmd_bench(args):
    from .bench import format_bench, run_bench
    from .infra.results import dumps
    res = run_bench(_model(args), quick=args.quick, progress=None if args.json else _progress)
    print(dumps(res) if args.json else format_bench(res))
    return 0


def cmd_export(args):
    from .export import export_project
    if args.path and args.model and args.path != args.model:
        raise ArgumentError(f"give the model once: positional {args.path!r} or --model "
                            f"{args.model!r}, not both")
    out = export_project(args.path or args.model, args.out, precision=args.precision,
                         controllers=args.controllers, force=args.force,
                         generated=args.generated, move=args.move)
    print(f"wrote {out}: build and test it with\n  cmake -S {out} -B {out}/build && cmake "
          f"--build {out}/build && ctest --test-dir {out}/build\n(docs/deploying.md: the API, "
          f"a 2 ms interrupt, make -C {out}/embedded run for a Cortex-M under QEMU)")
    return 0


def build_parser():
    ap = argparse.ArgumentParser(prog="pm2dof", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="command", metavar="COMMAND")
    from .core.version import __version__
    ap.add_argument("--version", action="version", version=f"pm2dof {__version__}")
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument("--model", default=None, metavar="NAME|PATH",
                        help="a shipped model's name (pm2dof models) or your model file "
                        "(default: shang2010, the paper's robot)")
    common.add_argument("--generated", default=None, metavar="DIR",
                        help="folder of the model's generated C (default: generated/<stem>/ "
                        "beside the model file; shipped models: inside pm2dof)")
    common.add_argument("--quiet", action="store_true",
                        help="no progress output on stderr (progress bars are drawn only when "
                        "stderr is a terminal; stage lines always, unless --quiet)")
    p = sub.add_parser("models", help="list the shipped models",
                       description="List the models that come with pm2dof: their name (for "
                       "--model NAME and load_model(NAME)), leg count and description. With "
                       "--copy NAME DIR, copy one into a folder of yours as a starting point "
                       "for your own robot.")
    p.add_argument("--copy", nargs=2, metavar=("NAME", "DIR"),
                   help="copy shipped model NAME's file into the folder DIR (created if need be; "
                   "or to DIR if it ends in .toml), then edit and `pm2dof derive` it")
    p.set_defaults(func=lambda a: cmd_models_copy(a) if a.copy else cmd_models(a))

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
    p.add_argument("--runs", type=_count(0, 100000), default=40,
                   help="repeated runs (default 40; 0: none)")
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
    p.add_argument("--include", nargs="+", choices=["ctc", "lqr"], default=[], metavar="LAW",
                   help="also run these model-based controllers with Tables 1-2: ctc (computed "
                   "torque), lqr (time-varying LQR along each move; needs the control extra)")
    p.set_defaults(func=cmd_table3)
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
    p.add_argument("--settle", type=_NONNEGATIVE, default=0.0, metavar="S",
                   help="seconds of rest at the last sample after the reference (default 0)")
    p.add_argument("--json", action="store_true", help="print the numbers as JSON")
    p.set_defaults(func=cmd_simulate)
    p = sub.add_parser("figures", parents=[common], help="write the figures as PNG",
                       description="Write errors_<speed>.png (x and y error against time, APD "
                       "and NA, like the paper's Figs. 4-5), torques.png, theta_hat.png and "
                       "repeated_runs.png into --out. Each PNG carries its provenance in its "
                       "text chunks.")
    p.add_argument("--out", required=True, help="output folder")
    p.add_argument("--runs", type=_count(0, 100000), default=40,
                   help="repeated runs for repeated_runs.png")
    p.set_defaults(func=cmd_figures)
    _identify_parser(sub, common)
    p = sub.add_parser("splits", parents=[common], help="torque splits compared in closed loop",
                       description="Simulate APD and NA with each torque split (min_norm: eq. "
                       "21; min_max: least max_i |tau_i|/tau_max,i; preload: every actuator "
                       "keeps its sign and |tau_i| >= preload_i, least 2-norm) on the model's "
                       "moves, and print RMSE (eq. 41), largest error, saturated samples and "
                       "peak torque. All splits give the same task force S^T tau; they differ "
                       "once an actuator reaches its limit, so lower --tau-max to see them "
                       "differ (the paper's robot: min-norm first clips near 7.4 N m on the "
                       "high-speed move, min-max near 7.1 N m). With --out, also sweep the limit "
                       "and plot RMSE and clipped samples against it (splits_high.png).",
                       epilog="example: pm2dof splits --tau-max 6.0 --preload 1.0 --out out")
    p.add_argument("--tau-max", type=_POSITIVE, metavar="NM",
                   help="torque limit of every actuator, N m (default: [limits].tau_max)")
    p.add_argument("--preload", type=_NONNEGATIVE, metavar="NM",
                   help="least |tau_i| of the preload split, N m (default: [control].preload)")
    p.add_argument("--preload-sign", type=float, nargs="+", metavar="S",
                   help="sign (+1/-1) each actuator keeps under the preload split "
                   "(default: [control].preload_sign)")
    p.add_argument("--json", action="store_true", help="print the numbers as JSON")
    p.add_argument("--out", metavar="DIR", help="also write the sweep figure splits_high.png here")
    p.set_defaults(func=cmd_splits)
    p = sub.add_parser("maps", parents=[common], help="capability maps over the workspace (PNG)",
                       description="Map over the workspace, in the model's assembly mode: the "
                       "type I and type II singularity measures with their thresholds (and, for "
                       "two legs, the parallel-singular curve), cond(S^T S), the largest task "
                       "force available in every direction within tau_max for the min-norm split "
                       "(eq. 21) and for the min-max split (the circle inside the zonotope "
                       "{S^T tau : |tau_i| <= tau_max_i}) and their ratio, and the same for "
                       "acceleration at rest through Me (Tables 1-2). The model's moves are "
                       "drawn on every map. Writes maps_*.png and maps.json into --out.",
                       epilog="example: pm2dof maps --model fivebar --out out/maps")
    p.add_argument("--out", required=True, metavar="DIR", help="folder for the PNGs and maps.json")
    p.add_argument("--resolution", type=int, default=121, metavar="N",
                   help="grid points per axis (default 121; about 1 s per 10^4 points)")
    p.add_argument("--tau-max", type=_POSITIVE, nargs="+", metavar="NM",
                   help="actuator limits, N m: one value for all or one per actuator "
                   "(default: [limits].tau_max)")
    p.add_argument("--json", action="store_true", help="print the summary as JSON")
    p.set_defaults(func=cmd_maps)
    p = sub.add_parser("animate", parents=[common], help="animated GIF of a closed-loop move",
                       description="Simulate one move of the model file with one controller and "
                       "write an animated GIF: the legs and links to scale at the true pose, the "
                       "desired and actual paths, the same move zoomed with the error magnified "
                       "(its factor and a 0.1 mm scale bar shown), and |xd - xe| against time. "
                       "Uses matplotlib's animation with Pillow.",
                       epilog="example: pm2dof animate --move high --controller apd --out apd.gif")
    p.add_argument("--move", default="high", help="move of [trajectories] (default high)")
    p.add_argument("--controller", default="na", choices=["na", "apd"],
                   help="NA (eqs. 28-29, default) or APD (eq. 40)")
    p.add_argument("--split", choices=["min_norm", "min_max", "preload"],
                   help="torque split (default: [control].split)")
    p.add_argument("--out", default="move.gif", help="GIF to write (default move.gif)")
    p.add_argument("--magnify", type=_POSITIVE, help="error magnification (default: a power of ten "
                   "that keeps the error below 0.3 of the move's length)")
    p.add_argument("--fps", type=int, default=20, help="GIF frames per second (default 20)")
    p.add_argument("--every", type=int, default=2,
                   help="2 ms samples per frame (default 2: the GIF is 12.5x slower than life)")
    p.set_defaults(func=cmd_animate)
    p = sub.add_parser("plan", parents=[common], help="time-optimal motion along a path",
                       description="Time a path as fast as the motors allow (issue 20): the "
                       "kinematic S-curve of the path's arc length beside the time-optimal "
                       "timing under the torque limits with the min-norm split (eq. 21) and the "
                       "min-max split (the whole redundancy), friction included. The paths are "
                       "the model file's moves (start to end as lines) or a path file (--path: "
                       "a shipped name such as pick_and_place, or your TOML file).",
                       epilog="examples: pm2dof plan --tau-max 6 --closed-loop; pm2dof plan "
                       "--path pick_and_place --out out/plan")
    p.add_argument("--path", metavar="NAME|FILE", help="a path file (default: the moves)")
    p.add_argument("--move", help="only this move of the model file (default: every move)")
    p.add_argument("--tau-max", type=_POSITIVE, nargs="+", metavar="NM",
                   help="actuator limits, N m: one value for all or one per actuator "
                   "(default: [limits].tau_max)")
    p.add_argument("--margin", type=_number(0.0, 1.0), default=1.0,
                   help="plan with tau_max * margin (default 1.0)")
    p.add_argument("--grid", type=_count(2, 100000), default=1000, help="grid points (default 1000)")
    p.add_argument("--split", choices=["both", "min_norm", "min_max"], default="both",
                   help="torque split(s) to plan with (default both)")
    for flag, what in (("--v-max", "m/s"), ("--a-max", "m/s^2"), ("--j-max", "m/s^3")):
        p.add_argument(flag, type=_POSITIVE, help=f"kinematic S-curve limit, {what} (default: the "
                       "move's, the path file's [kinematic], else the model's last move's)")
    p.add_argument("--smooth", action="store_true", help="also the torque-rate-limited "
                   "near-time-optimal plan (CasADi + IPOPT; needs casadi)")
    p.add_argument("--tau-rate", type=_POSITIVE, metavar="NM_PER_S",
                   help="--smooth: largest |dtau/dt| (default tau_max / 20 ms)")
    p.add_argument("--closed-loop", action="store_true",
                   help="simulate NA and APD, with the same split, tracking the time-optimal "
                   "plan of the last split --split names (min-max for the default both, "
                   "min-norm with --split min_norm) at each of --margins")
    p.add_argument("--margins", type=_number(0.0, 1.0), nargs="+", default=[1.0, 0.9],
                   help="--closed-loop: the margins to plan with (default 1.0 0.9)")
    p.add_argument("--out", metavar="DIR", help="write each plan's trajectory (CSV) and the "
                   "figures (phase plane, torques, path on the force map) here")
    p.add_argument("--json", action="store_true", help="print the numbers as JSON")
    p.set_defaults(func=cmd_plan)
    _study_parser(sub)
    from .bench.run import run_bench
    p = sub.add_parser("bench", parents=[common], help="controller step-time benchmark",
                       description=(run_bench.__doc__ or "").split("\n\n")[0] + " Targets: NA "
                       "step in C <= 250 ns, from Python <= 1 us, rollout >= 500k steps/s, C >= "
                       "300x NumPy, binding >= 50x casadi.Function. Quote medians from one run: "
                       "this machine is shared and noisy.")
    p.add_argument("--json", action="store_true", help="print the results as JSON")
    p.add_argument("--quick", action="store_true", help="few repeats (a few seconds; for tests)")
    p.set_defaults(func=cmd_bench)
    p = sub.add_parser("derive", parents=[common],
                       help="derive a model file and generate + compile its C",
                       description="Derive MODEL (a model file, TOML) with SymPy, generate C "
                       "with CasADi, and compile it: MODEL.c, MODEL.h, manifest.json and "
                       "libMODEL.so go into --out, by default generated/<stem>/ beside the model "
                       "file (~/robots/myrobot.toml -> ~/robots/generated/myrobot/), where "
                       "load_model and --model find them. A folder generated from another model "
                       "file is not overwritten without --force. When the folder is up to date "
                       "(the manifest matches the model file, the derivation's sources, SymPy "
                       "and CasADi, and the library its C), it says so and stops; --force "
                       "derives again. Needs the derivation extra: pip install 'pm2dof[derive]'.",
                       formatter_class=argparse.RawDescriptionHelpFormatter, epilog=(
                           "examples:\n"
                           "  pm2dof models --copy shang2010 ~/robots   # a model file to edit\n"
                           "  pm2dof derive ~/robots/shang2010.toml\n"
                           "  pm2dof table3 --model ~/robots/shang2010.toml"))
    p.add_argument("path", nargs="?", metavar="MODEL", help="model file (the same as --model)")
    p.add_argument("--out", metavar="DIR", help="folder for the generated code (default: "
                   "generated/<stem>/ beside the model file)")
    p.add_argument("--force", action="store_true",
                   help="derive even if the folder is up to date, and overwrite a folder that "
                        "holds code generated from another model file")
    p.add_argument("--no-build", action="store_true", help="generate C but do not compile it")
    p.set_defaults(func=cmd_derive)
    p = sub.add_parser(
        "export", parents=[common], help="the controllers as a standalone C99 library (CMake)",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description=_wrap(
            "Write a self-contained C99 project for MODEL's controllers into --out: its "
            "generated C (copied, not re-derived), the API header include/<name>_pm2dof.h (fixed-"
            "size structs; init, reset and one step per controller taking the encoder angles and "
            "the reference and returning the torques and a status, the codes of pm2dof.Status; "
            "fk, ik, the torque splits; the parameters' layout with the model file's values as "
            "defaults), a CMakeLists.txt building a static library with a package config "
            "(find_package(<name>_pm2dof)), a closed-loop example against the generated plant, a "
            "ctest comparing the C closed loop with pm2dof.simulate, and embedded/ (Cortex-M4F and "
            "M7 under QEMU). No heap, no global state, only the standard math functions; no Python "
            "on the target."),
        epilog="examples:\n"
               "  pm2dof export shang2010 --out robot_c\n"
               "  cmake -S robot_c -B robot_c/build && cmake --build robot_c/build && "
               "ctest --test-dir robot_c/build\n"
               "  pm2dof export ~/robots/myrobot.toml --out myrobot_c --precision single "
               "--controllers na,apd\n"
               "docs/deploying.md: the API, the sizes and times, a 2 ms interrupt")
    p.add_argument("path", nargs="?", metavar="MODEL", help="a shipped model's name or your "
                   "model file (the same as --model; default shang2010)")
    p.add_argument("--out", required=True, metavar="DIR", help="the project folder (new or "
                   "empty, unless --force)")
    p.add_argument("--precision", default="double", metavar="double|single",
                   help="double (default; equals pm2dof to the bit) or single: the same code "
                   "with float, refused with the reason where float is not enough")
    p.add_argument("--controllers", default="na,apd,ctc,lqr", metavar="LIST",
                   help="comma-separated subset of na,apd,ctc,lqr (default all four; LQR's "
                   "gains are inputs of its step)")
    p.add_argument("--force", action="store_true", help="write into a non-empty --out (a "
                   "previous export's files are replaced)")
    p.add_argument("--move", metavar="NAME", help="the model file's move the example and the "
                   "ctest run (default high)")
    p.set_defaults(func=cmd_export)
    return ap


def _show_warning(message, category, filename, lineno, file=None, line=None,
                  _default=warnings.showwarning):
    if issubclass(category, OutcomeWarning):
        print(f"pm2dof: warning: {message}", file=sys.stderr, flush=True)
    else:
        _default(message, category, filename, lineno, file, line)


#: optional dependencies -> the extra that installs them (pyproject.toml)
_EXTRAS = {"sympy": "derive", "casadi": "derive", "dask": "studies", "distributed": "studies",
           "pyarrow": "studies", "scipy": "ident", "control": "control"}
_COMMAND_EXTRAS = {"derive": "derive", "identify": "ident", "study": "studies",
                   "table3": "control",     # table3 --include lqr: SciPy's Riccati solver
                   "simulate": "control"}   # simulate --controller lqr: the same


#: commands whose --out names a folder (the others' --out, and every --save, name a file)
_OUT_FOLDERS = {"demo", "figures", "splits", "maps", "plan", "study", "export"}


def _check_outputs(args):
    """Refuse an output that cannot be written before any work: a --save or file --out that is
    a folder or lies under a file, a folder --out that is a file (OutputError)."""
    from .infra.results import output_folder, output_path
    if getattr(args, "save", None):
        output_path(args.save)
    out = getattr(args, "out", None)
    if out and args.command != "derive":          # derive checks its own --out
        (output_folder if args.command in _OUT_FOLDERS else output_path)(out)


def main(argv=None):
    from .infra import results
    ap = build_parser()
    args = ap.parse_args(argv)
    results.COMMAND_LINE = ["pm2dof", *(sys.argv[1:] if argv is None else argv)]
    global _progress
    _progress = Progress(quiet=getattr(args, "quiet", False))
    if not getattr(args, "func", None):
        ap.print_help()
        return 2
    try:
        _check_outputs(args)
        with warnings.catch_warnings():   # each rollout that did not complete: one line
            warnings.simplefilter("always", OutcomeWarning)
            warnings.showwarning = _show_warning
            return args.func(args)
    except Pm2dofError as exc:  # a typed error: the input is refused, not a bug
        print(f"pm2dof: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as exc:
        print(f"\npm2dof: interrupted{f' ({exc})' if str(exc) else ''}", file=sys.stderr)
        return 130
    except ModuleNotFoundError as exc:
        module = (exc.name or "").split(".")[0]
        if module not in _EXTRAS:
            raise
        extra = _COMMAND_EXTRAS.get(args.command, _EXTRAS[module])
        print(f"pm2dof: error: `pm2dof {args.command}` needs {exc.name}, which is not "
              f"installed: pip install 'pm2dof[{extra}]'", file=sys.stderr)
        return 2
    except BrokenPipeError:  # output piped into `head` and the like
        sys.stderr.close()
        return 0


if __name__ == "__main__":
    sys.exit(main())
