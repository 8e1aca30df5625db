# The torque splits compared in closed loop: where the redundancy delays saturation.
"""APD and NA with each torque split on the model file's moves, at a chosen torque limit.

With the paper's limits nothing saturates and every split tracks alike (they all give the same
S^T tau, eq. 10). Lower ``tau_max`` until the minimum-norm split (eq. 21) clips on the
high-speed move, and the min-max split, which uses the redundancy to keep every actuator below
its limit for as long as the task force allows, tracks where min-norm cannot. The preload split
pays for its backlash protection in torque.

The preload split keeps every actuator's sign sigma_i (``preload_sign``) and |tau_i| >= p_i
(``preload``); a preload of 0 still keeps the signs (no torque reversal: no backlash crossing).
Where no torques within tau_max do that, the split takes the torques with the largest
worst-case margin min_i (sigma_i tau_i - p_i) (status "preload_infeasible"), which can put an
actuator exactly at tau_max without clipping it. The rows say so: ``n_preload_infeasible``
counts those samples and ``preload_margin`` is the least margin over the move (< 0: some
actuator reversed its sign or fell short of its preload, by that much).
"""
import numpy as np

from ..control.controllers import APDController, NAController
from ..control.settings import actuator_limits, per_actuator
from ..control.simulate import simulate
from ..control.trajectory import line_moves, model_move
from ..core.contract import SPLITS
from ..core.task import effort_unit
from ..infra.progress import bar

__all__ = ["split_comparison", "format_split_comparison", "tau_max_sweep", "run_splits",
           "format_splits", "preload_settings", "splits_units", "redundancy_note"]

CONTROLLERS = {"apd": APDController, "na": NAController}


def _row(r, preload=None, preload_sign=None):
    """The numbers of one run; with ``preload`` and ``preload_sign`` (n,) also
    ``preload_margin`` = min over the move's samples and actuators of sigma_i tau_i - p_i, N*m
    (N for a linear actuator)."""
    e = r.e[:r.n_move]
    row = {"rmse": r.rmse, "max_error": float(np.max(np.hypot(e[:, 0], e[:, 1]))),   # (x, y)
           "n_saturated": r.n_saturated, "n_preload_infeasible": r.n_preload_infeasible,
           "n_singular": r.n_singular, "peak_tau": r.peak_tau,
           "rms_tau": float(np.sqrt(np.mean(r.tau_a[:r.n_move] ** 2)))}
    if preload is not None:
        row["preload_margin"] = float(np.min(r.tau_a[:r.n_move] * preload_sign - preload))
    return row


def preload_settings(model, preload=None, preload_sign=None):
    """(preload, preload_sign), each (n,): the arguments, a scalar broadcast to every actuator,
    else ``[control]`` of the model file (the controllers' defaults)."""
    n, ctl = model.n_legs, model.spec.control
    pre = ctl["preload"] if preload is None else preload
    sgn = ctl["preload_sign"] if preload_sign is None else preload_sign
    return per_actuator("preload", pre, n), per_actuator("preload_sign", sgn, n)


def splits_units(model):
    """The unit of every number of :func:`run_splits`: efforts (tau_max, preload, peak and rms
    torque, the preload margin) by the actuators' kind, "N m" (revolute), "N" (linear) or
    "N m or N" (both), errors in m, counts 1."""
    u = effort_unit(model)
    return {"tau_max": u, "preload": u, "preload_sign": "1", "rmse": "m", "max_error": "m",
            "n_saturated": "1", "n_preload_infeasible": "1", "n_singular": "1", "peak_tau": u,
            "rms_tau": u, "preload_margin": u}


def redundancy_note(model):
    """One line saying why the splits cannot differ on a robot without actuation redundancy
    (as many actuators as task coordinates); None for a redundant one."""
    n, m = model.n_legs, model.dof
    if n > m:
        return None
    return (f"model {model.name!r} has no redundant actuator ({n} actuators for {m} task "
            f"coordinates): S^T tau = u has one solution, so every split commands the same "
            f"torques, and the preload split cannot choose signs (its 'preload unmet' samples "
            f"are where that solution reverses a sign or falls short of the preload).")


def split_comparison(model, tau_max=None, preload=None, preload_sign=None, speeds=None,
                     splits=SPLITS, controllers=("apd", "na"), quantise=True, progress=None):
    """Simulate every controller x split on each move at the torque limit ``tau_max``.

    Parameters
    ----------
    model : Model
    tau_max : float or array_like (n,), optional
        Actuator limits, N*m (N for a linear actuator), for the controllers (default
        ``[limits].tau_max``). A scalar applies to every actuator. The plant applies what the
        controller commands.
    preload, preload_sign : array_like (n,), optional
        The preload split's least |tau_i| (N*m; N for a linear actuator) and signs (default
        ``[control]``). A preload of 0 still keeps the signs.
    speeds : list of str, optional
        Moves of ``[trajectories]`` (default: all).
    splits : sequence of str
        The torque splits to compare (default: all, ``pm2dof.control.settings.SPLITS``).
    controllers : sequence of str
        "apd", "na" or both.
    quantise : bool
        Encoder quantisation in the rollouts.
    progress : callable(str) or pm2dof.infra.progress.Progress, optional
        Stage lines; a ``Progress`` also draws a bar over the rollouts.

    Returns
    -------
    dict
        ``{speed: {controller: {split: {rmse (m), max_error (m), n_saturated,
        n_preload_infeasible, n_singular, peak_tau, rms_tau (N*m; N for linear actuators)}}}}``;
        the preload split's rows also have ``preload_margin`` (the same unit, see the module
        docstring).
    """
    n = model.n_legs
    if tau_max is not None:
        tau_max = np.broadcast_to(np.asarray(tau_max, dtype=float), (n,)).copy()
    preload, preload_sign = preload_settings(model, preload, preload_sign)
    out = {}
    speeds = list(line_moves(model)) if speeds is None else speeds
    b = bar(progress, len(speeds) * len(controllers) * len(splits), "splits", unit="rollout")
    for speed in speeds:
        traj = model_move(model, speed)
        out[speed] = {}
        for name in controllers:
            out[speed][name] = {}
            for split in splits:
                b.set_postfix_str(f"{speed} speed, {name}, {split}")
                b.update()
                pre = {"preload": preload, "preload_sign": preload_sign} if split == "preload" \
                    else {"preload": np.zeros(n)}   # the preload only binds its own split
                ctrl = CONTROLLERS[name](model, tau_max=tau_max, split=split, **pre)
                r = simulate(model, ctrl, traj, quantise=quantise)
                out[speed][name][split] = (_row(r, preload, preload_sign) if split == "preload"
                                           else _row(r))
    b.close()
    return out


def tau_max_sweep(model, levels, speed="high", preload=None, preload_sign=None,
                  controllers=("apd", "na"), splits=SPLITS, progress=None):
    """RMSE and saturated samples of every controller x split against a uniform limit.

    ``levels`` (k,) N*m (N for linear actuators). Returns ``{"tau_max": levels, controller: {split: {"rmse": (k,),
    "n_saturated": (k,), "peak_tau": (k,)}}}``. A split whose preload does not fit under a
    level (preload >= level) has NaN there.
    """
    levels = np.asarray(levels, dtype=float)
    res = {"tau_max": levels}
    keys = ("rmse", "n_saturated", "peak_tau")
    for name in controllers:
        res[name] = {s: {k: np.full(len(levels), np.nan) for k in keys} for s in splits}
    pre, _ = preload_settings(model, preload, preload_sign)
    b = bar(progress, len(levels), "tau_max sweep", unit="level")
    for i, level in enumerate(levels):
        b.set_postfix_str(f"tau_max = {level:.3g} N m")
        b.update()
        for split in splits:
            if split == "preload" and np.any(pre >= level):
                continue
            r = split_comparison(model, level, preload, preload_sign, [speed], (split,),
                                 controllers)[speed]
            for name in controllers:
                for k in keys:
                    res[name][split][k][i] = r[name][split][k]
    b.close()
    return res


def _signs(sign):
    return "(" + ", ".join("+" if v > 0 else "-" for v in sign) + ")"


def format_split_comparison(numbers, tau_max, preload, preload_sign, unit="N m", note=None):
    """A text table of :func:`split_comparison` at ``tau_max``, ``preload`` and
    ``preload_sign`` (n,), with a legend of its columns; ``unit`` the efforts' unit
    (:func:`pm2dof.core.task.effort_unit`), ``note`` a line printed first (e.g.
    :func:`redundancy_note`)."""
    zero = "; a preload of 0 still keeps the signs" if not np.any(preload) else ""
    lines = ([] if note is None else [note]) + [
             f"Torque splits in closed loop: tau_max = {np.round(tau_max, 4).tolist()} {unit} "
             f"(plant: the model file's truth)",
             f"preload split: every tau_i keeps the sign {_signs(preload_sign)} with |tau_i| >= "
             f"{np.round(preload, 4).tolist()} {unit}{zero}",
             f"{'move':5s} {'ctrl':4s} {'split':9s} {'RMSE, m':>10s} {'max |e|, m':>10s} "
             f"{'saturated':>9s} {'preload unmet':>13s} {'margin':>7s} {'peak |tau|':>10s} "
             f"{'rms tau':>8s}"]
    for speed, by_ctrl in numbers.items():
        for name, by_split in by_ctrl.items():
            for split, r in by_split.items():
                margin = f"{r['preload_margin']:7.3f}" if "preload_margin" in r else f"{'-':>7s}"
                lines.append(f"{speed:5s} {name:4s} {split:9s} {r['rmse']:10.4e} "
                             f"{r['max_error']:10.4e} {r['n_saturated']:9d} "
                             f"{r['n_preload_infeasible']:13d} {margin} {r['peak_tau']:10.3f} "
                             f"{r['rms_tau']:8.3f}")
    lines += ["saturated: samples where some actuator was clipped at tau_max.",
              "preload unmet: samples where no torques within tau_max keep every sign and "
              "preload; there the preload split",
              "  takes the largest worst-case margin min_i (sign_i tau_i - preload_i), which can "
              "put an actuator at tau_max",
              "  without clipping it (peak |tau| = tau_max with 0 saturated).",
              f"margin: the least of that margin over the move, {unit} (< 0: an actuator "
              f"reversed its sign or fell short of its preload).",
              f"peak |tau|, rms tau: {unit}."]
    return "\n".join(lines)


def run_splits(model, tau_max=None, preload=None, preload_sign=None, progress=None):
    """The ``pm2dof splits`` command's numbers at one limit: ``{"tau_max", "preload",
    "preload_sign", "results", "units"}`` (:func:`splits_units`), and ``"note"``
    (:func:`redundancy_note`) on a robot without a redundant actuator (its ``--json``; the
    text: :func:`format_splits`)."""
    w = actuator_limits(model.spec, tau_max, "splits")
    pre, sgn = preload_settings(model, preload, preload_sign)
    numbers = split_comparison(model, w, pre, sgn, progress=progress)
    out = {"tau_max": w, "preload": pre, "preload_sign": sgn, "results": numbers,
           "units": splits_units(model)}
    note = redundancy_note(model)
    if note is not None:
        out["note"] = note
    return out


def format_splits(res):
    """:func:`run_splits`'s result as the table ``pm2dof splits`` prints."""
    return format_split_comparison(res["results"], res["tau_max"], res["preload"],
                                   res["preload_sign"], res["units"]["tau_max"],
                                   res.get("note"))
