# `pm2dof identify SUBCOMMAND`: identification of theta (report, excite, fit, design, ...).
import argparse

from ...core.errors import ArgumentError
from ..options import NONNEGATIVE, POSITIVE, count, model, number, progress, wrap


def add_parser(sub, common):
    p = sub.add_parser("identify", help="identification of theta: report, excite, fit, design, "
                       "monte-carlo",
                       description=wrap("Identify the dynamic parameters theta (eq. 13: S^T "
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
    isub = p.add_subparsers(dest="identify_command", metavar="SUBCOMMAND")

    def excitation_options(r, what):
        r.add_argument("--excitation", metavar="FILE", help=f"excitation file to {what} "
                       "(written by `pm2dof identify design`); its model is the default")
        r.add_argument("--duration", type=number(0.0, 3600.0), metavar="S",
                       help="without --excitation: length of the default multi-sine, s "
                       "(default 4)")

    def simulated_options(r, when=""):
        r.add_argument("--exact-encoders", action="store_true",
                       help=f"{when}no encoder quantisation (a noise-free log)")
        r.add_argument("--controller", choices=["apd", "na"],
                       help=f"{when}controller tracking the excitation, with Tables 1-2 "
                       "(default apd)")

    def sub_command(name, help, description, examples):
        return isub.add_parser(name, parents=[common], help=help, description=wrap(description),
                               formatter_class=argparse.RawDescriptionHelpFormatter,
                               epilog="examples:\n" + "\n".join(f"  {e}" for e in examples))

    sub_command("report", "identifiable parameters: base parameters, null space",
                "Stack the regressor Y over random states around the middle of the model's "
                "first move and print its rank, the identifiable base parameters (each "
                "independent column of Y with the dependent ones folded in) and the directions "
                "of theta no motion can show (the null space of Y).",
                ["pm2dof identify report --model fivebar"])

    r = sub_command("excite", "run an excitation on the simulated robot and write its log",
                    "Run an excitation on the simulated plant (its truth: [plant] of the model "
                    "file; quantised encoders; a controller with Tables 1-2 tracking) and write "
                    "what a real set-up logs, encoder angles and commanded torques, to --out "
                    "(CSV or Parquet by the suffix; the format: docs/log-format.md). The log "
                    "records its model relative to itself.",
                    ["pm2dof identify excite --excitation exc.toml --out run.csv",
                     "pm2dof identify excite --duration 10 --out run.parquet"])
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
                     "pm2dof identify fit --json       # the default 4 s multi-sine, simulated"])
    r.add_argument("log", nargs="?", metavar="LOG", help="log file (.csv or .parquet); without "
                   "it, a simulated excitation run")
    r.add_argument("--save", metavar="FILE", help="write the estimate, a full theta0 and the "
                   "provenance as JSON")
    r.add_argument("--json", action="store_true", help="print the results as JSON")
    r.add_argument("--seed-na", action="store_true",
                   help="also Table 3 with APD and NA using the identified theta")
    r.add_argument("--cutoff", type=POSITIVE, metavar="HZ",
                   help="low-pass cutoff (default 10 x the excitation band)")
    r.add_argument("--time-tolerance", type=number(0.0, 1.0, low_inclusive=True,
                   high_inclusive=False), default=1e-3, metavar="FRACTION",
                   help="largest allowed |t_k+1 - t_k - T| / T of LOG (default 1e-3)")
    r.add_argument("--min-joint-speed", type=NONNEGATIVE, metavar="RAD_S",
                   help="leave out samples with a slower active joint (default 0.1; 0 keeps all); "
                   "a linear actuator's threshold is 0.1 x this, m/s")
    excitation_options(r, "simulate without LOG")
    simulated_options(r, "without LOG: ")

    r = sub_command("design", "design a D-optimal excitation (20 s to about a minute)",
                    "Design a periodic excitation (a finite Fourier series in task space, "
                    "Swevers et al. 1997) that maximises log det of the base regressor's "
                    "information matrix, with CasADi + IPOPT (20 s for the paper's robot, about a "
                    "minute for a platform: the time per kind of robot is in "
                    "docs/results-identification.md), within speed, "
                    "acceleration, torque, singularity and region limits checked every 1 ms, and "
                    "write it as TOML to --out (the model recorded relative to the file). A "
                    "platform's excitation moves phi too, within its own limits (--phi-*). If "
                    "IPOPT does not converge, the file is written all the same, marked "
                    "converged = false, and the command exits 1 (unless --accept-unconverged).",
                    ["pm2dof identify design --out exc.toml",
                     "pm2dof identify design --model rrr3_platform --phi-range 0.1 --out exc.toml"])
    r.add_argument("--out", required=True, metavar="FILE", help="excitation file to write (TOML)")
    for flag, kind, default, text in (
            ("--base-hz", POSITIVE, 0.2, "base frequency f0, Hz (default 0.2: 5 s period)"),
            ("--harmonics", count(1, 1000), 10, "harmonics of f0 (default 10: up to 2 Hz)"),
            ("--periods", count(1, 1000), 2, "periods per run (default 2: 10 s)"),
            ("--v-max", POSITIVE, 0.5, "speed limit of (x, y), m/s (default 0.5)"),
            ("--a-max", POSITIVE, 10.0, "acceleration limit of (x, y), m/s^2 (default 10)"),
            ("--tau-fraction", number(0.0, 1.0), 0.5, "torque limit / tau_max, in (0, 1] "
             "(default 0.5)"),
            ("--seed", int, 0, "seed of IPOPT's random start (default 0)"),
            ("--max-iter", count(1, 100000), 500, "IPOPT's iteration limit (default 500)")):
        r.add_argument(flag, type=kind, default=default, help=text)
    r.add_argument("--accept-unconverged", action="store_true",
                   help="exit 0 when IPOPT did not converge (the file says converged = false)")
    # a platform's orientation: its own limits (pm2dof.identification.design.phi_limits)
    for flag, metavar, text in (
            ("--phi-v-max", "RAD_S", "a platform's phi speed limit, rad/s (default: v-max / l, "
             "l the platform's radius)"),
            ("--phi-a-max", "RAD_S2", "a platform's phi acceleration limit, rad/s^2 (default: "
             "a-max / l)"),
            ("--phi-range", "RAD", "a platform's |phi - phi_c0| limit about the centre's phi, "
             "rad (default: the largest phi excursion of the model's moves)")):
        r.add_argument(flag, type=POSITIVE, metavar=metavar, help=text)

    r = sub_command("monte-carlo", "the identification targets measured over N seeds",
                    "Measure the identification targets over N seeds: each draws a plant truth "
                    "around [plant] (inertia and friction x (1 + 0.1 N(0, 1)), payload 0-0.5 kg) "
                    "and encoder noise, runs the excitation on it, identifies from the log alone "
                    "and compares with the truth.",
                    ["pm2dof identify monte-carlo 50 --excitation exc.toml"])
    r.add_argument("seeds", type=count(1, 100000), metavar="N", help="number of seeds")
    r.add_argument("--json", action="store_true", help="print the results as JSON")
    excitation_options(r, "run")
    return p


def run(args):
    """The sub-command (each takes --model and --generated after its name)."""
    if args.identify_command is None:
        raise ArgumentError("pm2dof identify needs a sub-command: report, excite, fit, design "
                            "or monte-carlo (plain `pm2dof identify` was replaced by: pm2dof "
                            "identify report, and pm2dof identify fit)")
    return _SUBCOMMANDS[args.identify_command](args)


def _progress(args):
    """Stage lines and bars on stderr (--quiet aside); none with --json."""
    return None if getattr(args, "json", False) else progress(args)


def _report(args):
    from ...identification.base import format_identifiability, identifiability
    print(format_identifiability(identifiability(model(args))))
    return 0


def _excite(args):
    from ...core.task import effort_unit
    from ...identification.excitation import format_excite, model_of_excitation, run_excite
    log = run_excite(args.out, model=args.model, generated=args.generated,
                     excitation_file=args.excitation, duration=args.duration,
                     quantise=not args.exact_encoders, controller=args.controller,
                     progress=_progress(args))
    m = model_of_excitation(args.excitation, args.duration, model=args.model,
                            generated=args.generated)
    print(format_excite(args.out, log, effort_unit(m)))
    return 0


def _fit(args):
    from ...identification.jobs import run_fit, save_fit, with_table3
    from ...identification.report import format_fit
    from ...infra.results import dumps
    said = _progress(args)
    r = run_fit(args.log, model=args.model, generated=args.generated,
                excitation_file=args.excitation, duration=args.duration,
                quantise=not args.exact_encoders, controller=args.controller,
                cutoff_hz=args.cutoff, min_joint_speed=args.min_joint_speed,
                time_tolerance=args.time_tolerance, progress=said)
    if args.seed_na:          # the paper's experiment with the identified theta
        from ...analysis.experiment import seeded_table3
        if said:
            said("Table 3 with Tables 1-2 and with the identified theta")
        r = with_table3(r, seeded_table3(r.model, r.result.theta0))
    if args.save:
        save_fit(r, args.save, args.command_line)
    print(dumps(r.summary) if args.json else format_fit(r))
    if args.save and not args.json:
        print(f"saved {args.save} (theta0: use it with NAController(model, theta0=...))")
    return 0


def _design(args):
    import sys

    from ...identification.design import (
        LimitOptions,
        SeriesOptions,
        SolverOptions,
        format_design,
        run_design,
    )
    r = run_design(
        model(args), args.out,
        SeriesOptions(base_hz=args.base_hz, harmonics=args.harmonics, periods=args.periods),
        LimitOptions(v_max=args.v_max, a_max=args.a_max, tau_fraction=args.tau_fraction,
                     phi_v_max=args.phi_v_max, phi_a_max=args.phi_a_max,
                     phi_range=args.phi_range),
        SolverOptions(seed=args.seed, max_iter=args.max_iter), progress=_progress(args))
    print(format_design(r))
    if r.converged or args.accept_unconverged:
        return 0
    info = r.excitation.info
    print(f"pm2dof identify design: IPOPT did not converge ({info['ipopt_status']} after "
          f"{info['ipopt_iterations']} iterations); {args.out} is marked converged = false "
          f"(--accept-unconverged to exit 0 with it)", file=sys.stderr)
    return 1


def _monte_carlo(args):
    from ...identification.monte_carlo import format_monte_carlo, monte_carlo_json, run_monte_carlo
    from ...infra.results import dumps
    mc = run_monte_carlo(args.seeds, model=args.model, generated=args.generated,
                         excitation_file=args.excitation, duration=args.duration,
                         progress=_progress(args))
    print(dumps(monte_carlo_json(mc)) if args.json else format_monte_carlo(mc))
    return 0


_SUBCOMMANDS = {"report": _report, "excite": _excite, "fit": _fit, "design": _design,
                "monte-carlo": _monte_carlo}
