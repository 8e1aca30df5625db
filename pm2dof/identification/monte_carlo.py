# How good is identification from logs? Monte Carlo over plant truths and encoder noise, against the targets.
"""``pm2dof identify monte-carlo N --excitation FILE``: the identification's accuracy targets
(:data:`TARGETS`), measured.

Each seed draws a plant truth around the model file's ``[plant]`` (every bare-link inertia,
viscous, Coulomb and Stribeck coefficient scaled by 1 + 0.1 N(0, 1), the payload mass
uniform in [0, 0.5] kg) and encoder noise (Gaussian, ``noise_counts`` counts rms, added to the
logged joints on top of the quantisation the controller sees: counts of the 17-bit rotary
encoders, or of a linear actuator's encoder, :func:`encoder_steps`), runs the excitation on
that plant (APD with Tables 1-2 tracking), identifies from the log alone, and compares with
the truth:

* the inertial base parameters as a vector (relative 2-norm of the error), and each one
  larger than 10 % of the largest (relative error);
* friction (fv, fc): largest relative error;
* the actuator effort the identified (physical) theta predicts over random states, against
  the plant's own (its friction with Coulomb smoothing and the Stribeck excess): relative
  2-norm over the states;
* whether each base parameter's truth lies within its printed interval, ±(2 sigma + model
  error) (:func:`pm2dof.identification.fit.model_error`); where that coverage is below 90 %,
  the table says so and why (:func:`untrusted`).
"""
import math

import numpy as np

from ..control.plant import plant_truth, theta_truth
from ..core.errors import ArgumentError, SingularityError, WorkspaceError
from ..core.task import per_actuator
from ..infra.progress import bar
from .base import base_parameters, inertial_mask, region_center
from .excitation import excite
from .fit import identify_log

__all__ = ["random_truth", "plant_task_force", "torque_error", "monte_carlo",
           "format_monte_carlo", "substep_sensitivity", "format_seeded_table3",
           "run_monte_carlo", "monte_carlo_json", "untrusted", "check_before_fits",
           "encoder_steps", "TARGETS"]

#: the identification's accuracy targets: inertial vector, each large inertial parameter, friction, torque, coverage
TARGETS = {"inertial_vector": 0.05, "inertial_each": 0.05, "friction": 0.03, "torque": 0.05,
           "coverage": 0.90}


def random_truth(model, rng, spread=0.1, payload=(0.0, 0.5)):
    """A plant truth (dict as :func:`pm2dof.plant_truth`) around ``[plant]``: each bare-link
    inertia and friction coefficient times 1 + spread N(0, 1) (clipped to [0.5, 1.5]), payload
    mass uniform in ``payload`` kg."""
    p = model.spec.plant
    over = {k: list(np.asarray(p[k], float) * np.clip(1 + spread * rng.normal(size=model.n_legs),
                                                      0.5, 1.5))
            for k in ("alpha", "beta", "gamma", "fv", "fc", "fs")}
    return plant_truth(model, payload_mass=float(rng.uniform(*payload)), **over)


def plant_task_force(model, truth, q, xed, xedd):
    """The plant's task force S^T tau (2,), N, at pose q, velocity xed, acceleration xedd:
    truth inertia (eq. 12 via Y with the truth's inertial and zero friction parameters) plus
    the plant's friction f_i = (fc_i + fs_i / (1 + (v/vs)^2)) v / sqrt(v^2 + eps^2) + fv_i v
    (derive/plant.py), v = qd_a,i."""
    th = theta_truth(model, truth).copy()
    th[~inertial_mask(model.param_names)] = 0.0
    S = model.S(q)
    v = S @ xed
    eps, vs = truth["coulomb_smoothing_velocity"], truth["stribeck_velocity"]
    f = ((truth["fc"] + truth["fs"] / (1 + (v / vs) ** 2)) * v / np.sqrt(v * v + eps * eps)
         + truth["fv"] * v)
    return model.Y(q, xed, xed, xedd) @ th + S.T @ f


def torque_error(model, theta, truth, n=400, seed=0, radius=0.05, speed=0.3, accel=5.0):
    """Relative 2-norm of the min-norm actuator torque predicted by ``theta`` minus the plant's,
    over ``n`` random states: positions uniform in a disc of ``radius`` m around the middle of
    the model's first move, velocities N(0, speed) m/s, accelerations N(0, accel) m/s^2 per
    axis. A platform's phi is uniform within the design's ``phi_range`` of the middle's phi
    (:func:`pm2dof.identification.design.phi_limits`), its rate N(0, speed / l) rad/s and
    acceleration N(0, accel / l) rad/s^2, l the platform's radius (the rotation alone moves
    the attachment points as fast as the (x, y) draws). A state outside the workspace or
    too close to a singularity is drawn again.

    Parameters
    ----------
    model : Model
    theta : ndarray (p,)
        The identified theta.
    truth : dict
        The plant truth (:func:`pm2dof.plant_truth`'s dict).
    n : int
        Number of states.
    seed, radius, speed, accel :
        The states' draw, as above.
    """
    from ..core.task import orientation_length
    from .design import phi_limits
    rng = np.random.default_rng(seed)
    c = np.asarray(region_center(model), dtype=float)
    platform = model.dof == 3
    if platform:
        l, turn = orientation_length(model), phi_limits(model)["phi_range"]
    num = den = 0.0
    tries, budget = 0, 100 * (n + 1)
    while n > 0:
        tries += 1
        if tries > budget:
            raise ArgumentError(f"torque_error: {tries - 1} random states around {c.tolist()} "
                                f"fell outside the workspace of {model.name!r} or too close to "
                                f"a singularity")
        r, ang = radius * math.sqrt(rng.uniform()), rng.uniform(0, 2 * math.pi)
        x = c.copy()
        x[:2] += r * np.array([math.cos(ang), math.sin(ang)])
        if platform:
            x[2] += rng.uniform(-turn, turn)
        v, a = rng.normal(0, speed, 2), rng.normal(0, accel, 2)
        if platform:
            v, a = np.append(v, rng.normal(0, speed / l)), np.append(a, rng.normal(0, accel / l))
        try:
            q = model.ik(x)
            S = model.S(q)
        except (WorkspaceError, SingularityError):
            continue
        split = S @ np.linalg.inv(S.T @ S)                     # eq. 21
        tp = split @ plant_task_force(model, truth, q, v, a)
        ti = split @ (model.Y(q, v, v, a) @ theta)
        num += float(np.sum((ti - tp) ** 2))
        den += float(np.sum(tp ** 2))
        n -= 1
    return math.sqrt(num / den)


def _metrics(model, base, truth, estimate, interval, theta0, torque_states=400):
    """The per-seed numbers of :func:`monte_carlo` from one identification's ``estimate`` and
    ``interval`` (r,) and ``theta0`` (p,)."""
    pi = base.fold(theta_truth(model, truth))
    inert = base.inertial
    err = estimate - pi
    large = inert & (np.abs(pi) > 0.1 * np.abs(pi[inert]).max())
    return {"estimate": estimate, "truth": pi, "interval": interval,
            "inertial_vector": float(np.linalg.norm(err[inert]) / np.linalg.norm(pi[inert])),
            "inertial_each": float(np.max(np.abs(err[large] / pi[large]))),
            "friction": float(np.max(np.abs(err[~inert] / pi[~inert]))),
            "torque": torque_error(model, theta0, truth, n=torque_states),
            "covered": np.abs(err) <= interval, "theta0": theta0, "large": large}


def check_before_fits(model, base):
    """Everything :func:`monte_carlo` computes after each fit, run once on the nominal theta
    and the model file's [plant] (two torque states) before any excitation runs, so that a
    shape that does not fit the model (a platform's phi, a gravity model's kappa) fails in
    the first second instead of after every fit.

    Parameters
    ----------
    model : Model
    base : BaseParameters
    """
    nominal = np.asarray(model.theta_nominal, dtype=float)
    _metrics(model, base, plant_truth(model), base.fold(nominal), np.zeros(base.r), nominal,
             torque_states=2)


def encoder_steps(model):
    """(n,) one encoder count of each actuator: 2 pi / ``[sensing] encoder_counts_per_rev``
    rad for a revolute one, ``[sensing] linear_encoder_resolution`` m for a linear one (0 for
    exact encoders).

    Parameters
    ----------
    model : Model
    """
    sensing = model.spec.sensing
    counts = sensing["encoder_counts_per_rev"]
    return np.array([(2 * math.pi / counts if counts > 0 else 0.0) if leg.actuator == "revolute"
                     else float(sensing.get("linear_encoder_resolution", 0.0))
                     for leg in model.spec.legs])


def _encoders(model):
    """The encoders in words: "17-bit encoders", "1e-06 m linear encoders", or both."""
    sensing = model.spec.sensing
    counts = sensing["encoder_counts_per_rev"]
    bits = math.log2(counts) if counts > 0 else 0
    rev = (f"{bits:.0f}-bit encoders" if bits.is_integer() else f"{counts:g} counts/rev encoders")
    lin = f"{float(sensing.get('linear_encoder_resolution', 0)):g} m linear encoders"
    return per_actuator(model.spec.actuators, rev, lin, f"{rev} and {lin}")


def _one(model, base, traj, truth, rng, noise_counts, identify_kw):
    log = excite(model, traj, truth=truth)
    if noise_counts > 0:
        step = encoder_steps(model)
        log = type(log)(t=log.t, qa=log.qa + noise_counts * step * rng.normal(size=log.qa.shape),
                        tau=log.tau, meta=log.meta)
    res = identify_log(model, log, base=base, **identify_kw)
    return {**_metrics(model, base, truth, res.estimate, res.interval, res.theta0),
            "std": res.std}


def monte_carlo(model, traj, seeds=20, *, noise_counts=0.5, truth="random", identify_kw=None,
                progress=None):
    """Identify from ``seeds`` simulated logs of ``traj`` and measure the targets.

    Parameters
    ----------
    traj : Signal or Trajectory
        The excitation, as :func:`pm2dof.identification.excitation.excite` takes it (a
        :mod:`~pm2dof.identification.signals` signal records its band in the logs).
    truth : "random" or "model"
        A fresh :func:`random_truth` per seed, or the model file's [plant] every time (then
        only the encoder noise differs).
    noise_counts : float
        Encoder noise added to the logged angles, counts rms (0: quantisation only).
    progress : callable(str) or pm2dof.infra.progress.Progress, optional
        A :class:`~pm2dof.infra.progress.Progress` draws a bar over the seeds.

    Returns
    -------
    dict
        Per-seed arrays of every metric, the names, the coverage per base parameter, and
        the medians and 90th percentiles.
    """
    base = base_parameters(model)
    check_before_fits(model, base)
    runs = []
    with bar(progress, seeds, "Monte Carlo", unit="seed") as done:
        for s in range(seeds):
            rng = np.random.default_rng(1000 + s)
            tr = random_truth(model, rng) if truth == "random" else plant_truth(model)
            runs.append(_one(model, base, traj, tr, rng, noise_counts, identify_kw or {}))
            done.set_postfix_str(f"inertial error {100 * runs[-1]['inertial_vector']:.2f} %",
                                 refresh=False)
            done.update(1)
    out = {"seeds": seeds, "noise_counts": noise_counts, "truth": truth,
           "encoders": _encoders(model),
           "effort": per_actuator(model.spec.actuators, "torque", "force", "torque and force"),
           "names": base.labels(),
           "coverage": np.mean([r["covered"] for r in runs], axis=0),
           "large_inertial": runs[0]["large"]}
    for k in ("inertial_vector", "inertial_each", "friction", "torque"):
        v = np.array([r[k] for r in runs])
        out[k] = {"median": float(np.median(v)), "p90": float(np.percentile(v, 90)),
                  "max": float(v.max()), "met_fraction": float(np.mean(v <= TARGETS[k]))}
    out["relative_error"] = np.array([(r["estimate"] - r["truth"]) / np.abs(r["truth"])
                                      for r in runs])
    err = np.array([r["estimate"] - r["truth"] for r in runs])
    out["untrusted"] = untrusted(out["names"], out["coverage"], err,
                                 np.array([r["interval"] for r in runs]), base.inertial)
    return out


def untrusted(names, coverage, err, interval, inertial):
    """{name: why} for every base parameter whose interval covered the truth in fewer than
    90 % of the seeds.

    ``err`` and ``interval`` are (seeds, r). An error of one sign in >= 80 % of the seeds is a
    bias the interval does not reach (the residuals cannot reveal it); otherwise the scatter
    is wider than the interval claims.
    """
    out = {}
    for k, n in enumerate(names):
        if coverage[k] >= TARGETS["coverage"]:
            continue
        same = int(max(np.sum(err[:, k] > 0), np.sum(err[:, k] < 0)))
        ratio = float(np.median(np.abs(err[:, k]) / interval[:, k]))
        if same >= 0.8 * len(err):
            cause = ("discretisation (the filter on a nonlinear regressor)" if inertial[k] else
                     "friction outside eq. 2 (the plant's Stribeck excess, largest on a slow "
                     "excitation)")
            out[n] = (f"a bias: the error has one sign in {same} of {len(err)} seeds, median "
                      f"{ratio:.2g} x the interval; likely {cause}. Do not trust this interval")
        else:
            out[n] = (f"scatter wider than the interval (median error {ratio:.2g} x the "
                      f"interval). Do not trust this interval")
    return out


def format_monte_carlo(mc):
    """The target table of a :func:`monte_carlo` run."""
    lines = [f"Monte Carlo over {mc['seeds']} seeds ({'random plant truths' if mc['truth'] == 'random' else 'the model file [plant]'}, "
             f"{mc.get('encoders', '17-bit encoders')} + {mc['noise_counts']:g} count rms "
             f"noise in the log)",
             f"{'target':52s} {'median':>9s} {'90 %':>9s} {'max':>9s} {'met in':>7s}"]
    what = {"inertial_vector": "inertial base parameters, vector, within 5 %",
            "inertial_each": "each inertial base parameter > 10 % of max, within 5 %",
            "friction": "friction (fv, fc) within 3 %",
            "torque": f"{mc.get('effort', 'torque')} predicted over random states within 5 %"}
    for k, text in what.items():
        d = mc[k]
        lines.append(f"{text:52s} {100 * d['median']:8.2f}% {100 * d['p90']:8.2f}% "
                     f"{100 * d['max']:8.2f}% {100 * d['met_fraction']:6.0f}%")
    lines.append("truth within the printed interval +-(2 sigma + model error) (target >= 90 % of "
                 "seeds), per base parameter:")
    wn = max(44, *(len(n) for n in mc["names"]))
    for n, c in zip(mc["names"], mc["coverage"]):
        lines.append(f"  {n:{wn}s} {100 * c:5.0f} %"
                     f"{'' if c >= TARGETS['coverage'] else '  (below 90 %)'}")
    for n, why in mc["untrusted"].items():
        lines.append(f"untrusted interval: {n}: {why}")
    return "\n".join(lines)


def substep_sensitivity(model, other, traj, seeds=10, *, noise_counts=0.5, identify_kw=None):
    """How much the estimates move when only the plant's integration changes.

    ``other`` is the same robot derived with another ``rk4_substeps`` (same parameter names).
    For each seed the same random truth and the same encoder noise run on both plants; the
    relative change of each base parameter between the two identifications is returned.

    Returns
    -------
    dict
        ``names``, ``change`` (seeds, r) relative changes, ``max_large`` (largest over the
        inertial base parameters > 10 % of the largest and the friction ones, per seed).
    """
    if list(other.param_names) != list(model.param_names):
        raise ArgumentError("the two models must have the same parameters")
    base = base_parameters(model)
    changes, worst = [], []
    for s in range(seeds):
        est = []
        for mdl in (model, other):
            rng = np.random.default_rng(1000 + s)
            tr = random_truth(model, rng)
            est.append(_one(mdl, base, traj, tr, rng, noise_counts, identify_kw or {}))
        d = (est[1]["estimate"] - est[0]["estimate"]) / np.abs(est[0]["estimate"])
        changes.append(d)
        worst.append(float(np.max(np.abs(d[est[0]["large"] | ~base.inertial]))))
    return {"names": base.labels(), "change": np.array(changes), "max_large": np.array(worst)}


def format_seeded_table3(tab):
    lines = ["Table 3 (RMSE, eq. 41, m) with the controllers' model from Tables 1-2 and from the "
             "identified theta:",
             f"{'speed':6s} {'APD T1-2':>11s} {'APD ident':>11s} {'NA T1-2':>11s} "
             f"{'NA ident':>11s} {'RPE vs APD ident':>17s}"]
    for s, d in tab.items():
        a0, a1 = d["nominal"]["apd_rmse"], d["identified"]["apd_rmse"]
        n0, n1 = d["nominal"]["na_rmse"], d["identified"]["na_rmse"]
        lines.append(f"{s:6s} {a0:11.4e} {a1:11.4e} {n0:11.4e} {n1:11.4e} "
                     f"{d['identified']['rpe_percent']:16.1f}%")
    return "\n".join(lines)


def run_monte_carlo(seeds, *, model=None, generated=None, excitation_file=None,
                    duration=None, progress=None):
    """``pm2dof identify monte-carlo N [--excitation FILE]``: :func:`monte_carlo`'s result
    (its text: :func:`format_monte_carlo`; its ``--json``: :func:`monte_carlo_json`). The model
    is the one the excitation file records unless ``model`` is given (then it must be that
    one); without a file the default multi-sine of ``duration`` s runs on ``model``."""
    from .excitation import excitation_signal, model_of_excitation
    from .signals import DEFAULT_DURATION
    if seeds < 1:
        raise ArgumentError(f"monte-carlo needs N >= 1 seeds, got {seeds}")
    model = model_of_excitation(excitation_file, duration, model=model, generated=generated)
    traj, what = excitation_signal(model, excitation_file,
                                   DEFAULT_DURATION if duration is None else duration)
    if progress:
        progress(f"{seeds} seeds of {what}: random plant truth and encoder noise, excite, "
                 f"identify")
    return monte_carlo(model, traj, seeds, progress=progress)


def monte_carlo_json(mc):
    """What ``pm2dof identify monte-carlo --json`` prints of :func:`monte_carlo`'s result."""
    return {k: v for k, v in mc.items() if k != "large_inertial"}
