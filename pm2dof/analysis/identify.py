# Identification: which parameter combinations the regressor can see, and least squares from data.
"""Identifiability and least-squares identification of theta (eq. 13: S^T tau_a = Y theta).

* :func:`identifiability` stacks Y over random states and finds the base parameters: a set of
  independent columns of Y and, for every other column, the combination it folds into.
* :func:`excitation` builds a smooth multi-sine motion that starts at rest.
* :func:`estimate` simulates that motion on the plant (its truth, encoder quantisation),
  estimates velocities and accelerations offline (zero-phase filter, central differences of
  fk of the measured angles), and solves the least-squares problem for the base parameters,
  as the paper did for friction (Table 2).
"""
from types import SimpleNamespace

import numpy as np

from ..control.controllers import APDController
from ..core.errors import SingularityError, WorkspaceError
from ..control.simulate import plant_vector, simulate, theta_truth

__all__ = ["identifiability", "excitation", "estimate", "format_identifiability",
           "format_estimate", "full_theta", "seed_na", "run_identify"]


def _random_states(model, n, rng, center, radius):
    out = []
    while len(out) < n:
        xe = center + rng.uniform(-radius, radius, 2)
        try:
            q = model.ik(xe)
            model.W(q)
        except (WorkspaceError, SingularityError):
            continue
        v = rng.normal(0, 0.3, 2)
        out.append((q, v, rng.normal(0, 0.3, 2), rng.normal(0, 5.0, 2)))
    return out


def _center(model):
    t = next(iter(model.spec.trajectories.values()))
    return (np.asarray(t["start"]) + np.asarray(t["end"])) / 2


def identifiability(model, samples=400, seed=0, radius=0.04, rtol=1e-9):
    """Rank of the stacked regressor and the base parameters.

    Parameters
    ----------
    model : Model
    samples : int
        Random states over which Y is stacked.
    seed : int
        Seed of the random states.
    radius : float
        m: the states' positions are drawn uniformly within +-radius in x and y of the middle
        of the model file's first move; velocities N(0, 0.3) m/s, accelerations N(0, 5) m/s^2.
    rtol : float
        Singular values of the column-scaled stacked Y below ``rtol`` times the largest count
        as zero.

    Returns
    -------
    dict
        ``rank``, ``n_params`` (p), ``singular_values`` (of the column-scaled stack),
        ``independent`` (indices of base columns, in order), ``dependent`` (indices), ``beta``
        (len(independent), len(dependent)): column d of Y equals sum_i beta[i, d] * column i,
        so base parameter i is theta_i + sum_d beta[i, d] theta_d, ``null_space`` (p, p - rank)
        orthonormal, and ``param_names``.
    """
    rng = np.random.default_rng(seed)
    Phi_raw = np.vstack([model.Y(q, v, vr, ar) for q, v, vr, ar
                         in _random_states(model, samples, rng, _center(model), radius)])
    Phi = Phi_raw / np.linalg.norm(Phi_raw, axis=0)  # scale columns: units differ
    sv = np.linalg.svd(Phi, compute_uv=False)
    rank = int(np.sum(sv > sv[0] * rtol))
    independent = []
    for j in range(Phi.shape[1]):  # greedy: keep a column if it raises the rank
        cols = Phi[:, independent + [j]]
        s = np.linalg.svd(cols, compute_uv=False)
        if s[-1] > sv[0] * rtol:
            independent.append(j)
    dependent = [j for j in range(Phi.shape[1]) if j not in independent]
    beta, *_ = np.linalg.lstsq(Phi_raw[:, independent], Phi_raw[:, dependent], rcond=None)
    beta[np.abs(beta) < 1e-9 * max(1.0, np.abs(beta).max(initial=0))] = 0.0
    _, _, Vt = np.linalg.svd(Phi_raw)
    return {"rank": rank, "n_params": Phi.shape[1], "singular_values": sv,
            "independent": independent, "dependent": dependent, "beta": beta,
            "null_space": Vt[rank:].T, "param_names": list(model.param_names)}


def base_names(ident):
    """Readable base parameters, e.g. 'gamma1 + 1.000 gamma3 ...'."""
    names, out = ident["param_names"], []
    for i, j in enumerate(ident["independent"]):
        terms = [names[j]]
        for k, d in enumerate(ident["dependent"]):
            b = ident["beta"][i, k]
            if b != 0.0:
                terms.append(f"{'+' if b > 0 else '-'} {abs(b):.4g} {names[d]}")
        out.append(" ".join(terms))
    return out


def format_identifiability(ident):
    names = ident["param_names"]
    lines = [f"regressor Y stacked over random states: rank {ident['rank']} of "
             f"{ident['n_params']} (column-scaled singular values "
             f"{ident['singular_values'][-1]:.2e} .. {ident['singular_values'][0]:.2e})"]
    if ident["dependent"]:
        lines.append(f"not identifiable on their own: {', '.join(names[d] for d in ident['dependent'])}")
    lines.append("identifiable base parameters (each column folds in the dependent ones):")
    lines += [f"  {s}" for s in base_names(ident)]
    if ident["null_space"].shape[1]:
        lines.append("invisible directions of theta (null space of Y; moving theta along them "
                     "changes no torque):")
        for k in range(ident["null_space"].shape[1]):
            v = ident["null_space"][:, k]
            v = v / v[np.argmax(np.abs(v))]
            terms = [f"{c:+.3f} {n}" for c, n in zip(v, names) if abs(c) > 1e-6]
            lines.append("  " + " ".join(terms))
    return "\n".join(lines)


def excitation(model, duration=4.0, amplitude=0.02, seed=1, harmonics=4, base_hz=0.75):
    """A smooth multi-sine motion around the middle of the model's first move, starting at rest.

    x(t) = c + sum_k a_k (1 - cos(w_k t + 0)) rotated per axis; velocity is zero at t = 0.
    Returns an object with t, xd, xd_dot, xd_ddot (N, 2), period and max_hz (the highest
    harmonic, Hz), like a Trajectory.
    """
    rng = np.random.default_rng(seed)
    T = model.spec.sensing["sample_period"]
    t = np.arange(int(round(duration / T)) + 1) * T
    c = _center(model)
    xd, xd_dot, xd_ddot = (np.zeros((len(t), 2)) for _ in range(3))
    for axis in range(2):
        for k in range(1, harmonics + 1):
            w = 2 * np.pi * base_hz * k * (1.0 + 0.13 * axis)
            a = amplitude / harmonics * rng.uniform(0.5, 1.0) * rng.choice([-1, 1])
            xd[:, axis] += a * (1 - np.cos(w * t))
            xd_dot[:, axis] += a * w * np.sin(w * t)
            xd_ddot[:, axis] += a * w * w * np.cos(w * t)
    xd += c - amplitude / 2
    return SimpleNamespace(t=t, xd=xd, xd_dot=xd_dot, xd_ddot=xd_ddot, period=T,
                           max_hz=base_hz * harmonics * 1.13)  # highest harmonic, Hz


def _filtfilt(x, alpha):
    """Zero-phase first-order low-pass along axis 0 (forward then backward)."""
    y = x.copy()
    for rng in (range(1, len(y)), range(len(y) - 2, -1, -1)):
        step = 1 if rng.step == 1 else -1
        for k in rng:
            y[k] = y[k - step] + alpha * (y[k] - y[k - step])
    return y


def estimate(model, duration=4.0, seed=1, quantise=True, filter_alpha=0.3, ident=None):
    """Least-squares identification from a simulated excitation run.

    The plant runs with its truth and encoder quantisation, tracked by APD with the nominal
    model. Only what a real set-up has is used: the measured active angles and the commanded
    torques. Positions are fk of the measured angles, smoothed by a zero-phase low-pass;
    velocities and accelerations are central differences. Each sample gives
    Y(q, v, v, a) theta = S^T (tau_{k-1} + tau_k) / 2 (the torque held around t_k).

    Returns
    -------
    dict with the base-parameter ``estimate``, ``std`` (1 sigma from the residual, assuming
    independent errors — optimistic, since the errors are filtered), ``truth`` (the plant
    truth folded into the same base parameters; the Stribeck excess has no coordinate),
    ``names`` of the base parameters, ``theta0`` (a full theta: dependent parameters at their
    nominal values, for NAController(theta0=...)), ``rms_residual`` and ``samples``.
    """
    ident = identifiability(model) if ident is None else ident
    traj = excitation(model, duration=duration, seed=seed)
    r = simulate(model, APDController(model), traj, quantise=quantise)
    plant = plant_vector(model, quantise=quantise)
    measure = model.function("measure")
    qa = np.empty(model.n_legs)
    xm = np.empty_like(r.xe)
    for k, xe in enumerate(r.xe):
        measure(xe, plant, qa)
        xm[k] = model.fk(qa)
    T = traj.period
    xf = _filtfilt(xm, filter_alpha)
    v = (xf[2:] - xf[:-2]) / (2 * T)
    a = (xf[2:] - 2 * xf[1:-1] + xf[:-2]) / (T * T)
    rows, rhs = [], []
    for k in range(1, len(xf) - 1):
        q = model.ik(xf[k])
        rows.append(model.Y(q, v[k - 1], v[k - 1], a[k - 1]))
        S = model.S(q)
        rhs.append(S.T @ (0.5 * (r.tau_a[k - 1] + r.tau_a[k])))
    Phi, b = np.vstack(rows), np.concatenate(rhs)
    I, D = ident["independent"], ident["dependent"]
    PhiI = Phi[:, I]
    est, *_ = np.linalg.lstsq(PhiI, b, rcond=None)
    res = b - PhiI @ est
    dof = max(len(b) - len(I), 1)
    sigma2 = res @ res / dof
    std = np.sqrt(np.diag(sigma2 * np.linalg.inv(PhiI.T @ PhiI)))
    truth = theta_truth(model)
    truth_base = truth[I] + ident["beta"] @ truth[D]
    nominal = model.theta_nominal
    theta0 = nominal.copy()
    theta0[I] = est - ident["beta"] @ nominal[D]
    return {"names": base_names(ident), "estimate": est, "std": std, "truth": truth_base,
            "nominal": nominal[I] + ident["beta"] @ nominal[D], "theta0": theta0,
            "rms_residual": float(np.sqrt(sigma2)), "samples": len(rows), "duration_s": duration}


def format_estimate(e):
    lines = [f"least squares over {e['samples']} samples of a {e['duration_s']:g} s excitation "
             f"(APD tracking, encoder quantisation), residual rms {e['rms_residual']:.3g} N",
             f"{'base parameter':46s} {'estimate':>10s} {'+-2 sigma':>10s} {'truth':>10s} "
             f"{'nominal':>10s}"]
    for n, est, s, t, nom in zip(e["names"], e["estimate"], e["std"], e["truth"], e["nominal"]):
        flag = "" if abs(est - t) <= 2 * s else "  (truth outside +-2 sigma)"
        lines.append(f"{n[:46]:46s} {est:10.4f} {2 * s:10.4f} {t:10.4f} {nom:10.4f}{flag}")
    lines.append("sigma assumes independent residuals; filtering and unmodelled Stribeck friction "
                 "make it optimistic.")
    return "\n".join(lines)


def full_theta(e):
    """The full theta (5n,) to seed NAController(theta0=...) with."""
    return e["theta0"].copy()


def seed_na(model, theta0):
    """RMSE of NA on each move of the model file with Tables 1-2 and with ``theta0``.

    Returns {speed: (rmse_nominal, rmse_theta0)}, m.
    """
    from ..control.controllers import NAController
    from ..control.trajectory import model_move
    out = {}
    for speed in model.spec.trajectories:
        traj = model_move(model, speed)
        out[speed] = (simulate(model, NAController(model), traj).rmse,
                      simulate(model, NAController(model, theta0=theta0), traj).rmse)
    return out


def run_identify(model, *, report_only=False, duration=4.0, save=None, seed=False, echo=print,
                 progress=None):
    """``pm2dof identify``: identifiability, then (unless ``report_only``) least squares from
    a simulated excitation run; ``save`` writes a full theta0 (JSON), ``seed`` reruns the
    moves with NA seeded by it."""
    ident = identifiability(model)
    echo(format_identifiability(ident))
    if report_only:
        return ident
    echo("")
    if progress:
        progress(f"simulating a {duration:g} s excitation run and solving least squares")
    e = estimate(model, duration=duration, ident=ident)
    echo(format_estimate(e))
    if save:
        from .results import provenance, write_json
        write_json(save, {"param_names": model.param_names, "theta0": full_theta(e),
                          "base_parameters": e["names"], "estimate": e["estimate"],
                          "std": e["std"], "truth": e["truth"], "provenance": provenance(model)})
        echo(f"saved {save} (theta0: use it with NAController(model, theta0=...))")
    if seed:
        echo("\nNA seeded with the identified theta (dependent parameters at nominal):")
        for speed, (a, b) in seed_na(model, full_theta(e)).items():
            echo(f"  {speed:5s}: RMSE {a:.4e} m with Tables 1-2 -> {b:.4e} m identified "
                 f"({100 * (a - b) / a:+.1f} %)")
    return e
