# The paper's experiment (Sect. 5): Table 3 in simulation, the Gamma = 0 ablation, repeated runs.
import math

import numpy as np

from ..control.controllers import APDController, CTCController, NAController
from ..control.plant import theta_truth
from ..control.simulate import simulate
from ..control.trajectory import line_moves, model_move
from ..core.errors import ArgumentError
from ..infra.progress import bar

__all__ = ["PAPER_TABLE3", "is_paper_robot", "table3", "table3_json", "phi_rmse", "seeded_table3",
           "format_table3",
           "run_table3", "repeated_runs", "sensitivity", "sensitivity_variants",
           "nominal_truth", "format_sensitivity"]

# Table 3 of the paper: RMSE measured on the real robot, m; RPE in percent
PAPER_TABLE3 = {"low": {"apd_rmse": 1.3738e-4, "na_rmse": 8.4625e-5, "rpe_percent": 38.40},
                "high": {"apd_rmse": 4.7136e-4, "na_rmse": 2.8299e-4, "rpe_percent": 39.96}}
"""Table 3 of the paper, measured on the real robot: {move: {"apd_rmse", "na_rmse" (eq. 41, m),
"rpe_percent" (100 (APD - NA) / APD)}} for the moves "low" and "high"."""


def is_paper_robot(model):
    """Whether ``model`` has the geometry of the paper's robot (the shipped shang2010's legs:
    bases, link lengths, elbows); only then is Table 3's measured column a comparison."""
    from ..core.model_file import read_model_file
    from ..core.paths import SHIPPED_MODELS
    paper = read_model_file(SHIPPED_MODELS / "shang2010.toml").legs
    return [(tuple(l.base), l.la, l.lb, l.elbow) for l in model.spec.legs] == \
        [(tuple(l.base), l.la, l.lb, l.elbow) for l in paper]


def rpe(apd_rmse, na_rmse):
    """Relative performance: percentage reduction of the RMSE from APD to NA; None when a run
    did not complete (its RMSE is inf: no percentage means anything then)."""
    if not (np.isfinite(apd_rmse) and np.isfinite(na_rmse)):
        return None
    return 100.0 * (apd_rmse - na_rmse) / apd_rmse


#: the model-based controllers ``table3(include=...)`` can add, with Tables 1-2
EXTRA_CONTROLLERS = ("ctc", "lqr")
#: each controller's column heading in the text table
LABELS = {"apd": "APD", "na": "NA", "na_no_adaptation": "NA G=0"}


def _extra_controller(model, name, traj, kw):
    if name == "ctc":
        return CTCController(model, **kw)
    from ..linear.lqr import LQRController  # SciPy (the control extra)
    return LQRController(model, traj, **kw)


def table3(model, speeds=None, quantise=True, progress=None, truth=None, include=(),
           **controller_options):
    """Run APD, NA and NA with Gamma = 0 on each move. Returns {speed: {name: SimResult}}.

    Parameters
    ----------
    model : Model
        The robot; its line moves are the moves, its ``[plant]`` the simulated plant.
    speeds : list of str, optional
        The moves to run (default: every line move of the model, the paper's "low", "high").
    quantise : bool
        Encoder quantisation in the rollouts (``pm2dof table3 --exact-encoders``: False).
    progress : callable(str) or pm2dof.infra.progress.Progress, optional
        Stage lines; a ``Progress`` also draws a bar over the rollouts.
    truth : dict, optional
        Replaces the plant truth (see :func:`pm2dof.plant_truth`).
    include : sequence of str
        Model-based controllers of :data:`EXTRA_CONTROLLERS` to add ("ctc": computed torque,
        "lqr": time-varying LQR along each move), each with the nominal model (Tables 1-2).
    **controller_options
        Go to all the controllers alike (e.g. ``velocity_filter_hz``).
    """
    speeds = list(line_moves(model)) if speeds is None else speeds
    unknown = sorted(set(include) - set(EXTRA_CONTROLLERS))
    if unknown:
        raise ArgumentError(f"include: unknown controller(s) {unknown}; choose from "
                            f"{list(EXTRA_CONTROLLERS)}")
    out = {}
    p = len(model.param_names)
    kw = controller_options
    with bar(progress, (3 + len(include)) * len(speeds), "Table 3", unit="rollout") as b:
        for speed in speeds:
            traj = model_move(model, speed)
            runs = {}
            for name, ctrl in (("apd", APDController(model, **kw)),
                               ("na", NAController(model, **kw)),
                               ("na_no_adaptation", NAController(model, Gamma=np.zeros(p), **kw)),
                               *((x, _extra_controller(model, x, traj, kw)) for x in include)):
                b.set_postfix_str(f"{speed} speed, {name}")
                runs[name] = simulate(model, ctrl, traj, quantise=quantise, truth=truth)
                b.update()
            out[speed] = runs
    return out


def phi_rmse(r):
    """RMSE of a platform's orientation phi over the samples of the move, rad:
    sqrt(1/N sum_k (phi_d,k - phi_k)^2), the angle beside eq. 41's position (which leaves it
    out, another unit); None for a point end effector, ``inf`` for a run that did not
    complete (as :attr:`SimResult.rmse`)."""
    if r.xd.shape[1] < 3:
        return None
    if r.outcome != "completed":
        return math.inf
    e = r.e[:r.n_move, 2]
    return float(np.sqrt(np.mean(e * e)))


def table3_json(results):
    """The numbers of :func:`table3`: RMSE in m, RPE in percent, duration in s; for a platform
    also each controller's ``<name>_phi_rmse`` (:func:`phi_rmse`, rad). Each move's ``units``
    names the unit of every number (``trajectory_duration`` is ``trajectory_duration_s``
    without the unit in its name; both are kept)."""
    out = {}
    for speed, runs in results.items():
        r = runs["na"]
        names = ["apd", "na", "na_no_adaptation", *(x for x in EXTRA_CONTROLLERS if x in runs)]
        duration = float(r.t[r.n_move - 1])
        out[speed] = {
            "apd_rmse": runs["apd"].rmse,
            "na_rmse": r.rmse,
            "na_no_adaptation_rmse": runs["na_no_adaptation"].rmse,
            "rpe_percent": rpe(runs["apd"].rmse, r.rmse),
            **{f"{x}_rmse": runs[x].rmse for x in EXTRA_CONTROLLERS if x in runs},
            "trajectory_duration_s": duration,
            "samples": r.n_move,
            "saturated_samples": {k: v.n_saturated for k, v in runs.items()},
            "singular_samples": {k: v.n_singular for k, v in runs.items()},
        }
        platform = r.xd.shape[1] == 3
        if platform:
            out[speed].update({f"{x}_phi_rmse": phi_rmse(runs[x]) for x in names})
        failed = {k: v.outcome_message for k, v in runs.items() if v.outcome != "completed"}
        if failed:  # a run that left the workspace or diverged: its RMSE is inf (JSON: null)
            out[speed]["outcomes"] = failed
        out[speed]["trajectory_duration"] = duration
        out[speed]["units"] = {**{f"{x}_rmse": "m" for x in names}, "rpe_percent": "%",
                               **({f"{x}_phi_rmse": "rad" for x in names} if platform else {}),
                               "trajectory_duration": "s", "trajectory_duration_s": "s",
                               "samples": "1", "saturated_samples": "1",
                               "singular_samples": "1"}
    return out


def seeded_table3(model, theta):
    """Table 3 with the controllers' model = Tables 1-2 and = ``theta`` (identified).

    ``pm2dof identify fit --seed-na`` hands its numbers to
    :func:`pm2dof.identification.jobs.with_table3` (identification does not import the paper's
    experiment).

    Parameters
    ----------
    model : Model
        The robot; its ``[plant]`` is the simulated plant.
    theta : array_like, shape (p,)
        The controllers' model of theta, e.g. an identified ``theta0``.

    Returns
    -------
    dict
        {speed: {"nominal": table3 numbers, "identified": table3 numbers}} (RMSE in m,
        RPE in percent; see :func:`table3_json`).
    """
    nominal = table3_json(table3(model))
    identified = table3_json(table3(model, theta0=np.asarray(theta, dtype=float)))
    return {s: {"nominal": nominal[s], "identified": identified[s]} for s in nominal}


def format_table3(numbers, paper=True):
    """A text table like the paper's Table 3, simulated beside measured (``paper``: the model
    is the paper's robot, :func:`is_paper_robot`; for another robot the measured columns are
    left out, they are not its numbers)."""
    extra = [x for x in EXTRA_CONTROLLERS if all(f"{x}_rmse" in r for r in numbers.values())]
    lines = ["RMSE of the end-effector position (eq. 41), m. Simulated here | measured in the "
             "paper (Table 3)." if paper else
             "RMSE of the end-effector position (eq. 41), m, simulated (the paper's measured "
             "Table 3 is of its own robot, not this one: not shown).",
             f"{'speed':6s} {'APD sim':>11s} {'NA sim':>11s} {'NA G=0 sim':>11s} {'RPE sim':>8s}"
             + (f" | {'APD paper':>11s} {'NA paper':>11s} {'RPE paper':>9s}" if paper else "")
             + "".join(f" | {x.upper() + ' sim':>11s}" for x in extra)]
    def cell(x, width, spec, none="-"):   # None: no paper number, or a run that failed
        return f"{x:{width}{spec}}" if x is not None and np.isfinite(x) else f"{none:>{width}s}"

    failed = []
    for speed, r in numbers.items():
        measured = PAPER_TABLE3.get(speed, {})
        lines.append(f"{speed:6s} {cell(r['apd_rmse'], 11, '.4e', 'failed')} "
                     f"{cell(r['na_rmse'], 11, '.4e', 'failed')} "
                     f"{cell(r['na_no_adaptation_rmse'], 11, '.4e', 'failed')} "
                     f"{cell(r['rpe_percent'], 7, '.2f', 'n/a')}%"
                     + (f" | {cell(measured.get('apd_rmse'), 11, '.4e')} "
                        f"{cell(measured.get('na_rmse'), 11, '.4e')} "
                        f"{cell(measured.get('rpe_percent'), 8, '.2f')}%" if paper else "")
                     + "".join(f" | {cell(r[f'{x}_rmse'], 11, '.4e', 'failed')}" for x in extra))
        failed += [f"  {speed} {k}: {msg}" for k, msg in r.get("outcomes", {}).items()]
    phi = [x for x in ("apd", "na", "na_no_adaptation", *extra)
           if all(f"{x}_phi_rmse" in r for r in numbers.values())]
    if phi:             # a platform: its orientation, beside eq. 41's position
        lines.append(f"RMSE of the platform's orientation phi, rad, simulated:\n{'speed':6s} "
                     + " ".join(f"{LABELS.get(x, x.upper()) + ' sim':>11s}" for x in phi))
        for speed, r in numbers.items():
            lines.append(f"{speed:6s} " + " ".join(cell(r[f"{x}_phi_rmse"], 11, ".4e", "failed")
                                                  for x in phi))
    lines.append("RPE = 100 (APD - NA) / APD: positive when NA tracks better.")
    if extra:
        lines.append("CTC: computed torque, LQR: time-varying LQR along the move; both with "
                     "Tables 1-2 (pm2dof table3 --include).")
    if failed:
        lines += ["Runs that did not complete (their RMSE is infinite):"] + failed
    return "\n".join(lines)


def run_table3(model, *, exact_encoders=False, save=None, progress=None, include=(),
               command_line=None):
    """``pm2dof table3``: run :func:`table3`, optionally save it; returns the numbers
    (:func:`table3_json`; the text: :func:`format_table3`).

    ``save`` is a path for the numbers and their provenance (JSON; ``command_line`` the command
    it records, None: ``sys.argv``); ``include`` adds controllers (:data:`EXTRA_CONTROLLERS`).
    """
    from ..infra.results import provenance, write_json
    numbers = table3_json(table3(model, quantise=not exact_encoders, progress=progress,
                                 include=include))
    if save:
        write_json(save, {**numbers, "provenance": provenance(model, command_line)})
    return numbers


def repeated_runs(model, speed="high", runs=20, quantise=True, progress=None):
    """Run the same move ``runs`` times with NA, carrying theta_hat from one run to the next.

    Each run starts at rest at the start point (the return move is not simulated).

    Parameters
    ----------
    model : Model
    speed : str
        A move of the model file's ``[trajectories]`` (default "high").
    runs : int
        Number of runs.
    quantise : bool
        Quantise the encoder angles (``[sensing] encoder_counts_per_rev``).
    progress : callable, optional
        Called with a one-line message every 5 runs.

    Returns
    -------
    dict
        ``rmse`` (runs,) m, eq. 41 of each run; ``theta_hat_end`` (runs, 5n), theta_hat at the
        end of each run; ``theta_truth`` (5n,), the plant's; ``theta0`` (5n,), theta_hat of
        the first run (Tables 1-2).
    """
    traj = model_move(model, speed)
    ctrl = NAController(model)
    theta = ctrl.theta0.copy()
    rmses, thetas = [], []
    with bar(progress, runs, f"repeated {speed}-speed runs", unit="run") as b:
        for _k in range(runs):
            r = simulate(model, ctrl, traj, quantise=quantise, theta_hat0=theta)
            theta = r.theta_hat[-1].copy()
            rmses.append(r.rmse)
            thetas.append(theta)
            b.set_postfix_str(f"RMSE {r.rmse:.3e} m")
            b.update()
    return {"rmse": np.array(rmses), "theta_hat_end": np.array(thetas),
            "theta_truth": theta_truth(model), "theta0": ctrl.theta0.copy()}


def nominal_truth(model):
    """A plant whose truth is the controllers' nominal model: every parameter of
    ``model.theta_nominal`` set by its name (``model.param_names``: alpha_i, beta_i, gamma_i,
    kappa_i under gravity, a platform's m_p, mx_p, my_p, I_p, fv_i, fc_i, fs_i), no payload and
    no Stribeck excess beyond the nominal model's; the rest of ``[plant]`` (the Stribeck
    velocity, the Coulomb smoothing of the plant's sign) as the model file gives it.

    Returns
    -------
    dict
        A plant truth as :func:`pm2dof.plant_truth` returns it (``simulate(..., truth=...)``).
    """
    from ..control.plant import _param_index, plant_truth
    truth = {k: np.array(v, dtype=float) for k, v in plant_truth(model, payload_mass=0.0).items()}
    truth["fs"] = np.zeros(model.n_legs)
    for (field, i), value in zip(_param_index(model.param_names), model.theta_nominal):
        if field not in truth:
            raise ArgumentError(f"model {model.name!r}: parameter {field!r} of theta has no "
                                f"field in the plant's truth (fields {sorted(truth)})")
        if truth[field].ndim:
            truth[field][i] = value
        else:
            truth[field] = np.array(value, dtype=float)
    return truth


def sensitivity_variants(model):
    """The variants of :func:`sensitivity`: a list of (label, keyword arguments of
    :func:`table3`)."""
    fc = model.spec.sensing["velocity_filter_hz"]
    return [(f"model file (velocity filter {fc:g} Hz)", {}),
            ("velocity filter 100 Hz", {"velocity_filter_hz": 100.0}),
            ("velocity filter 300 Hz", {"velocity_filter_hz": 300.0}),
            ("exact encoders", {"quantise": False}),
            ("plant truth = nominal model", {"truth": nominal_truth(model)})]


def sensitivity(model):
    """Table 3 under other assumptions of the simulation (what the ranking depends on): the
    variants of :func:`sensitivity_variants`.

    Returns a list of (label, table3_json numbers).
    """
    return [(label, table3_json(table3(model, **kw)))
            for label, kw in sensitivity_variants(model)]


def format_sensitivity(rows):
    speeds = list(rows[0][1])
    head = f"{'variant':38s}" + "".join(f" | {s + ': APD, NA, NA G=0, RPE':>42s}" for s in speeds)
    lines = [head]
    for label, numbers in rows:
        cells = "".join(f" | {r['apd_rmse']:.3e} {r['na_rmse']:.3e} {r['na_no_adaptation_rmse']:.3e}"
                        f" {r['rpe_percent']:6.1f}%" for r in numbers.values())
        lines.append(f"{label:38s}{cells}")
    return "\n".join(lines)
