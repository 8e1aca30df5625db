# Optimal excitation: a periodic finite Fourier series in task space (Swevers et al. 1997), IPOPT.
"""Excitation trajectories for identification, designed by optimisation.

The motion is a periodic finite Fourier series per task axis j (x, y) (Swevers, Ganseman,
Bilgin, De Schutter & Van Brussel, 1997), w_l = 2 pi l f0, l = 1..L:

    x_j(t)   = c_j + sum_l ( a_jl / w_l sin(w_l t) - b_jl / w_l cos(w_l t) )
    xd_j(t)  = sum_l ( a_jl cos(w_l t) + b_jl sin(w_l t) )
    xdd_j(t) = sum_l w_l ( -a_jl sin(w_l t) + b_jl cos(w_l t) )

with sum_l a_jl = 0 and sum_l w_l b_jl = 0, so the motion starts and ends (after whole
periods) at rest. :func:`design_excitation` chooses a, b, c with CasADi and IPOPT to
maximise log det(Phi^T Phi), Phi the base regressor stacked over one period (D-optimality),
subject to the workspace and a singularity margin, speed, acceleration and torque limits at
dense samples.

Why log det and not the condition number: log det is smooth (IPOPT needs derivatives; the
condition number is a ratio of extreme singular values, non-smooth where they cross), it is
invariant to the parameters' units (scaling a column adds a constant), it is the volume of
the confidence ellipsoid of the estimate, and it rewards signal over noise, which the
condition number ignores (doubling the motion leaves cond unchanged but halves the errors).
The condition number of the column-scaled regressor is reported before and after.

The model's Y, S, ik and singularity measures enter the optimisation as its generated C
(``casadi.external`` on the compiled library, derivatives by finite differences): nothing is
re-derived. In the objective, the Coulomb columns use tanh(qd / 0.1 rad/s) for sign(qd): it
keeps log det differentiable, and samples slower than 0.1 rad/s are left out by
``identify --data`` anyway.
"""
import math
import time
from dataclasses import dataclass, field
from types import SimpleNamespace

import numpy as np

from ..core.errors import Pm2dofError
from .ident_data import MIN_JOINT_SPEED

__all__ = ["ExcitationError", "FourierExcitation", "design_excitation", "load_excitation",
           "write_excitation", "trajectory_of", "regressor_condition", "check_excitation",
           "sample_function", "excitation_trajectory", "run_design"]


class ExcitationError(Pm2dofError, ValueError):
    """An excitation file or design request that cannot be used (names the key and value)."""


@dataclass(frozen=True)
class FourierExcitation:
    """A periodic finite Fourier series in task space (see the module docstring).

    Attributes
    ----------
    base_hz : float
        f0, Hz (the period is 1 / f0).
    periods : int
        Whole periods the run lasts.
    center : ndarray (2,)
        c, m.
    a, b : ndarray (2, L)
        Coefficients, m/s, per axis (x, y) and harmonic.
    info : dict
        What the design reported (limits, objective, condition numbers), for the file.
    """
    base_hz: float
    periods: int
    center: np.ndarray
    a: np.ndarray
    b: np.ndarray
    info: dict = field(default_factory=dict)

    harmonics = property(lambda self: self.a.shape[1])
    max_hz = property(lambda self: self.base_hz * self.harmonics, doc="highest harmonic, Hz")
    duration = property(lambda self: self.periods / self.base_hz, doc="s")

    def evaluate(self, t):
        """Position (N, 2) m, velocity (N, 2) m/s, acceleration (N, 2) m/s^2 at times t (N,)."""
        t = np.asarray(t, dtype=float)[:, None]
        w = 2 * np.pi * self.base_hz * np.arange(1, self.harmonics + 1)
        s, c = np.sin(w * t), np.cos(w * t)
        x = self.center + (s / w) @ self.a.T - (c / w) @ self.b.T
        return x, c @ self.a.T + s @ self.b.T, (-s * w) @ self.a.T + (c * w) @ self.b.T


def trajectory_of(model, exc, period=None):
    """The excitation sampled at the controller period (default ``[sensing].sample_period``):
    an object with t, xd, xd_dot, xd_ddot (N, 2), period and max_hz, for ``simulate`` and
    :func:`pm2dof.analysis.excite.excite`."""
    T = model.spec.sensing["sample_period"] if period is None else float(period)
    t = np.arange(int(round(exc.duration / T)) + 1) * T
    x, v, a = exc.evaluate(t)
    return SimpleNamespace(t=t, xd=x, xd_dot=v, xd_ddot=a, period=T, max_hz=exc.max_hz)


def _basis(f0, L, t):
    """(pos_a, pos_b, vel_a, vel_b, acc_a, acc_b), each (N, L): x = pos_a @ a + pos_b @ b + c."""
    w = 2 * np.pi * f0 * np.arange(1, L + 1)
    t = np.asarray(t, dtype=float)[:, None]
    s, c = np.sin(w * t), np.cos(w * t)
    return s / w, -c / w, c, s, -s * w, c * w


def regressor_condition(model, ident, traj, every=5):
    """Condition number of the column-scaled base regressor stacked over ``traj`` (every
    ``every``-th sample; desired motion, exact derivatives), and log det(Phi^T Phi / K) of the
    unscaled one. NumPy on the model's C functions (independent of the CasADi design graph).

    Returns
    -------
    cond, logdet : float
    """
    I = ident["independent"]
    rows = [model.Y(model.ik(x), v, v, a)[:, I] for x, v, a in
            zip(traj.xd[::every], traj.xd_dot[::every], traj.xd_ddot[::every])]
    Phi = np.vstack(rows)
    sv = np.linalg.svd(Phi / np.linalg.norm(Phi, axis=0), compute_uv=False)
    _, logdet = np.linalg.slogdet(Phi.T @ Phi / len(rows))
    return float(sv[0] / sv[-1]), float(logdet)


def check_excitation(model, exc, *, v_max, a_max, tau_limit, sing_min, radius, step=1e-3):
    """The excitation's worst values at samples every ``step`` s over one period, against the
    design's limits (``radius`` around the middle of the model's first move).

    Returns
    -------
    dict
        ``speed`` (max |xd|, m/s), ``acceleration`` (max |xdd|, m/s^2), ``torque`` (max |tau_i|
        of the min-norm split with Tables 1-2, N m), ``sing`` (min of both singularity measures),
        ``radius`` (max |x - center|, m), ``rest`` (|xd|, |xdd| at t = 0), each with ``ok``.
    """
    t = np.arange(int(round(1.0 / (exc.base_hz * step))) + 1) * step
    x, v, a = exc.evaluate(t)
    th = model.theta_nominal
    tau, sing = 0.0, np.inf
    for xk, vk, ak in zip(x, v, a):
        q = model.ik(xk)
        sing = min(sing, float(np.min(model.singularity_measures(q))))
        S = model.S(q)
        u = model.Y(q, vk, vk, ak) @ th
        tau = max(tau, float(np.abs(S @ np.linalg.solve(S.T @ S, u)).max()))
    out = {"speed": float(np.max(np.hypot(*v.T))), "acceleration": float(np.max(np.hypot(*a.T))),
           "torque": tau, "sing": sing,
           "radius": float(np.max(np.hypot(*(x - _center(model)).T))),
           "rest": float(np.abs(np.concatenate([v[0], a[0]])).max())}
    out["ok"] = (out["speed"] <= v_max and out["acceleration"] <= a_max and tau <= tau_limit
                 and sing >= sing_min and out["radius"] <= radius and out["rest"] < 1e-9)
    return out


def sample_function(model, independent, smooth_sign=None):
    """CasADi function (x (2), xd (2), xdd (2)) -> (vec of Y[:, independent] (2r, column-major),
    tau (n) of the min-norm split with Tables 1-2 (eq. 21), both singularity measures (2)),
    built on the model's generated C (``casadi.external``, finite-difference derivatives).

    ``smooth_sign`` (rad/s): replace sign(qd_i) in the Coulomb (and Stribeck) columns by
    tanh(qd_i / smooth_sign), so that the design's objective is differentiable (a sign
    flipping at one sample would make it jump); None keeps the model's Y exactly.
    """
    import casadi as ca
    n, p = model.n_legs, len(model.param_names)
    ext = {k: ca.external(f"{model.name}_{k}", model.library, {"enable_fd": True})
           for k in ("ik", "Y", "S", "singularity_measures")}
    x, v, acc = ca.MX.sym("x", 2), ca.MX.sym("v", 2), ca.MX.sym("a", 2)
    q = ext["ik"](x)
    Yfull = ca.reshape(ext["Y"](q, v, v, acc)[0], p, 2).T       # the C writes Y row-major
    S = ca.reshape(ext["S"](q)[0], 2, n).T
    if smooth_sign and model.spec.friction in ("coulomb_viscous", "coulomb_viscous_stribeck"):
        qd = ca.mtimes(S, v)                                    # eq. 8
        names = list(model.param_names)
        cols = [Yfull[:, j] for j in range(p)]
        for i in range(n):
            sgn = ca.tanh(qd[i] / smooth_sign)
            cols[names.index(f"fc{i + 1}")] = S[i, :].T * sgn   # S^T e_i sign(qd_i), eq. 2
            if f"fs{i + 1}" in names:
                vs = model.spec.friction_constants["stribeck_velocity"]
                cols[names.index(f"fs{i + 1}")] = S[i, :].T * sgn / (1 + (qd[i] / vs) ** 2)
        Yfull = ca.horzcat(*cols)
    u = ca.mtimes(Yfull, ca.DM(model.theta_nominal))
    tau = ca.mtimes(S, ca.solve(ca.mtimes(S.T, S), u))          # eq. 21, Tables 1-2
    return ca.Function("sample", [x, v, acc],
                       [ca.vec(Yfull[:, list(independent)]), tau,
                        ext["singularity_measures"](q)])


def excitation_trajectory(model, excitation_file=None, duration=10.0):
    """(trajectory, description): the file's excitation (:func:`load_excitation`) sampled at
    the model's period, or without a file the default multi-sine of
    :func:`pm2dof.analysis.identify.excitation` lasting ``duration`` s."""
    if excitation_file is None:
        from .identify import excitation
        return excitation(model, duration=duration), f"the default {duration:g} s multi-sine"
    return trajectory_of(model, load_excitation(excitation_file, model)), str(excitation_file)


def _center(model):
    t = next(iter(model.spec.trajectories.values()))
    return (np.asarray(t["start"], float) + np.asarray(t["end"], float)) / 2


def design_excitation(model, *, base_hz=0.2, harmonics=10, periods=2, v_max=0.5, a_max=10.0,
                      tau_fraction=0.5, singularity_margin=0.1, radius=0.06, samples=250,
                      constraint_samples=1000, safety=0.98, seed=0, max_iter=500,
                      progress=None):
    """Design a D-optimal excitation (CasADi + IPOPT).

    Parameters
    ----------
    model : Model
    base_hz : float
        f0, Hz; the period is 1 / f0 (default 0.2 Hz: 5 s).
    harmonics : int
        L (default 10: up to 2 Hz).
    periods : int
        Whole periods of the run (default 2: 10 s).
    v_max, a_max : float
        Task-space speed (m/s) and acceleration (m/s^2) limits; defaults are those of the
        paper's high-speed move (0.5 m/s, 10 m/s^2): the robot is known to do them.
    tau_fraction : float
        |tau_i| <= tau_fraction * tau_max_i with the nominal model and the min-norm split
        (default 0.5: the rest is left to feedback and model error).
    singularity_margin : float
        Both singularity measures >= their threshold + this (default 0.1).
    radius : float
        |x - c0| <= radius, m, c0 the middle of the model's first move (the region the
        model is meant for).
    samples, constraint_samples : int
        Samples per period of the objective and of the constraints. The constraints are
        imposed with the limits times ``safety`` (0.98), so that they hold between the
        samples too (:func:`check_excitation` checks every 1 ms).
    seed : int
        Random start (IPOPT finds a local optimum; log det is not concave here).

    Returns
    -------
    FourierExcitation
        Its ``info`` has the limits, the objective, cond and log det before (the start)
        and after, IPOPT's status, iterations and wall time.
    """
    import casadi as ca
    from .identify import identifiability
    if not (base_hz > 0 and harmonics >= 1 and periods >= 1 and v_max > 0 and a_max > 0
            and 0 < tau_fraction <= 1 and radius > 0):
        raise ExcitationError("need base_hz > 0, harmonics >= 1, periods >= 1, v_max > 0, "
                              "a_max > 0, 0 < tau_fraction <= 1, radius > 0")
    t_start = time.perf_counter()
    ident = identifiability(model)
    I, L = ident["independent"], int(harmonics)
    r = len(I)
    tau_lim = safety * tau_fraction * np.asarray(model.spec.limits["tau_max"], float)
    sing_min = (np.array([model.singularity_threshold, model.parallel_singularity_threshold])
                + singularity_margin)
    c0 = _center(model)
    per_sample = sample_function(model, I, smooth_sign=MIN_JOINT_SPEED)
    z = ca.MX.sym("z", 4 * L + 2)
    A = ca.reshape(z[:2 * L], L, 2)
    B = ca.reshape(z[2 * L:4 * L], L, 2)
    c = z[4 * L:]

    def motion(K):
        Pa, Pb, Va, Vb, Aa, Ab = (ca.DM(M) for M in _basis(base_hz, L, np.arange(K) / (K * base_hz)))
        X = ca.mtimes(Pa, A) + ca.mtimes(Pb, B) + ca.repmat(c.T, K, 1)
        return X, ca.mtimes(Va, A) + ca.mtimes(Vb, B), ca.mtimes(Aa, A) + ca.mtimes(Ab, B)

    X, V, Acc = motion(samples)
    Yv, _, _ = per_sample.map(samples)(X.T, V.T, Acc.T)
    Phi = ca.vertcat(*[ca.reshape(Yv[:, k], 2, r) for k in range(samples)])

    # random start: small coefficients with the rest conditions, inside every limit
    rng = np.random.default_rng(seed)
    w = 2 * np.pi * base_hz * np.arange(1, L + 1)
    a0 = rng.normal(size=(2, L)) / np.arange(1, L + 1)
    b0 = rng.normal(size=(2, L)) / np.arange(1, L + 1) ** 2
    a0 -= a0.mean(axis=1, keepdims=True)
    b0 -= np.outer(b0 @ w, w) / (w @ w)
    start = FourierExcitation(base_hz, periods, c0.copy(), a0, b0)
    _, v_, a_ = start.evaluate(np.arange(2000) / (2000 * base_hz))
    x_ = start.evaluate(np.arange(2000) / (2000 * base_hz))[0]
    k = min(0.3 * v_max / np.max(np.hypot(*v_.T)), 0.3 * a_max / np.max(np.hypot(*a_.T)),
            0.3 * radius / np.max(np.hypot(*(x_ - c0).T)))
    start = FourierExcitation(base_hz, periods, c0.copy(), k * a0, k * b0)
    z0 = np.concatenate([start.a.ravel(), start.b.ravel(), c0])   # z = [a_x, a_y, b_x, b_y, c]
    # column scaling: log det is invariant to it up to a constant; it keeps det() in range
    Phi0 = ca.Function("Phi0", [z], [Phi])(z0).full()
    D = ca.DM(np.diag(1.0 / np.linalg.norm(Phi0, axis=0)))
    M = ca.mtimes([D, Phi.T, Phi, D])
    objective = -ca.log(ca.det(M))

    Xc, Vc, Ac = motion(constraint_samples)
    _, Tc, Sc = per_sample.map(constraint_samples)(Xc.T, Vc.T, Ac.T)
    g = [ca.vec(ca.sum1(A)), ca.mtimes(B.T, ca.DM(w)),                               # rest: 4
         ca.sum2(Vc ** 2), ca.sum2(Ac ** 2),                                  # speed, accel
         ca.sum2((Xc - ca.repmat(ca.DM(c0).T, constraint_samples, 1)) ** 2),  # radius
         ca.vec(Tc), ca.vec(Sc)]
    K = constraint_samples
    lbg = np.concatenate([np.zeros(4), np.zeros(K), np.zeros(K), np.zeros(K),
                          -np.tile(tau_lim, K), np.tile(sing_min, K)])
    ubg = np.concatenate([np.zeros(4), np.full(K, (safety * v_max) ** 2),
                          np.full(K, (safety * a_max) ** 2), np.full(K, (safety * radius) ** 2),
                          np.tile(tau_lim, K), np.full(2 * K, np.inf)])
    if progress:
        progress(f"IPOPT: {4 * L + 2} coefficients, log det over {samples} samples, "
                 f"{len(lbg)} constraints at {constraint_samples} samples per period")
    opts = {}
    if progress:    # IPOPT's iterations reported as they happen (about a minute in all)
        watch = _IterationProgress(z.numel(), len(lbg), progress, t_start)
        opts["iteration_callback"] = watch
    solver = ca.nlpsol("excitation", "ipopt", {"x": z, "f": objective, "g": ca.vertcat(*g)},
                       {**opts, "ipopt.print_level": 0, "print_time": False, "ipopt.sb": "yes",
                        "ipopt.hessian_approximation": "limited-memory",
                        "ipopt.max_iter": int(max_iter), "ipopt.tol": 1e-6,
                        "ipopt.acceptable_tol": 1e-4, "ipopt.acceptable_iter": 10,
                        "ipopt.acceptable_obj_change_tol": 1e-7})
    sol = solver(x0=z0, lbg=lbg, ubg=ubg)
    zs = np.array(sol["x"]).ravel()
    stats = solver.stats()
    exc = FourierExcitation(base_hz, periods, zs[4 * L:], zs[:2 * L].reshape(2, L),
                            zs[2 * L:4 * L].reshape(2, L))
    exc = _with_rest(exc)
    before = regressor_condition(model, ident, trajectory_of(model, start))
    after = regressor_condition(model, ident, trajectory_of(model, exc))
    info = {"objective": "log det of the base regressor's information matrix (D-optimal)",
            "v_max": v_max, "a_max": a_max, "tau_fraction": tau_fraction,
            "singularity_margin": singularity_margin, "radius": radius,
            "region_center": c0.tolist(), "seed": seed,
            "cond_before": before[0], "cond_after": after[0], "logdet_before": before[1],
            "logdet_after": after[1], "ipopt_status": stats["return_status"],
            "ipopt_iterations": stats["iter_count"],
            "design_seconds": round(time.perf_counter() - t_start, 2)}
    return FourierExcitation(exc.base_hz, exc.periods, exc.center, exc.a, exc.b, info)


def _iteration_progress_class():
    import casadi as ca

    class IterationProgress(ca.Callback):
        """CasADi iteration callback: a progress line every ``every`` IPOPT iterations."""

        def __init__(self, nx, ng, progress, t_start, every=25):
            ca.Callback.__init__(self)
            self.nx, self.ng, self.progress, self.t_start = nx, ng, progress, t_start
            self.every, self.iteration = every, 0
            self.construct("excitation_progress", {})

        def get_n_in(self):
            return ca.nlpsol_n_out()

        def get_n_out(self):
            return 1

        def get_name_in(self, i):
            return ca.nlpsol_out(i)

        def get_name_out(self, i):
            return "ret"

        def get_sparsity_in(self, i):
            name = ca.nlpsol_out(i)
            if name == "f":
                return ca.Sparsity.scalar()
            if name in ("x", "lam_x"):
                return ca.Sparsity.dense(self.nx)
            if name in ("g", "lam_g"):
                return ca.Sparsity.dense(self.ng)
            return ca.Sparsity(0, 0)

        def eval(self, arg):
            self.iteration += 1
            if self.iteration % self.every == 0:
                self.progress(f"IPOPT iteration {self.iteration}: log det {-float(arg[1]):.3f}, "
                              f"{time.perf_counter() - self.t_start:.0f} s")
            return [0]

    return IterationProgress


def _IterationProgress(*args):
    return _iteration_progress_class()(*args)


def _with_rest(exc):
    """Project a, b onto the rest conditions exactly (IPOPT meets them to its tolerance)."""
    w = 2 * np.pi * exc.base_hz * np.arange(1, exc.harmonics + 1)
    a = exc.a - exc.a.mean(axis=1, keepdims=True)
    b = exc.b - np.outer(exc.b @ w, w) / (w @ w)
    return FourierExcitation(exc.base_hz, exc.periods, np.asarray(exc.center, float), a, b,
                             exc.info)


def _toml_list(v):
    return "[" + ", ".join(format(float(x), ".17g") for x in np.ravel(v)) + "]"


def write_excitation(path, exc, model):
    """Write ``exc`` as TOML (``[excitation]`` coefficients, ``[design]`` what the design
    reported), atomically."""
    from .results import write_atomic
    lines = ["# pm2dof excitation: periodic finite Fourier series in task space (Swevers et al. "
             "1997)",
             "# x_j(t) = center_j + sum_l a_jl/w_l sin(w_l t) - b_jl/w_l cos(w_l t), "
             "w_l = 2 pi l base_hz; j = x, y",
             "# run it: pm2dof identify --excite --excitation THIS_FILE --out run.csv", "",
             "[excitation]", f'model = "{model.name}"', f"base_hz = {exc.base_hz!r}",
             f"periods = {int(exc.periods)}", f"center = {_toml_list(exc.center)}   # m",
             f"a_x = {_toml_list(exc.a[0])}   # m/s", f"a_y = {_toml_list(exc.a[1])}",
             f"b_x = {_toml_list(exc.b[0])}   # m/s", f"b_y = {_toml_list(exc.b[1])}", ""]
    if exc.info:
        lines.append("[design]")
        for k, v in exc.info.items():
            if isinstance(v, str):
                lines.append(f'{k} = "{v}"')
            elif isinstance(v, (list, tuple, np.ndarray)):
                lines.append(f"{k} = {_toml_list(v)}")
            else:
                lines.append(f"{k} = {v!r}")
    write_atomic(path, ("\n".join(lines) + "\n").encode())
    return path


def load_excitation(path, model=None):
    """Read an excitation file (TOML, as :func:`write_excitation` writes it).

    Raises
    ------
    ExcitationError
        Unreadable file, a missing or malformed key (named), another model's file, or
        coefficients that do not start at rest.
    """
    import tomllib
    try:
        with open(path, "rb") as fh:
            d = tomllib.load(fh)
    except (OSError, tomllib.TOMLDecodeError) as exc:
        raise ExcitationError(f"{path}: cannot read the excitation file ({exc})") from None
    e = d.get("excitation")
    if not isinstance(e, dict):
        raise ExcitationError(f"{path}: no [excitation] table")
    try:
        f0, periods = float(e["base_hz"]), int(e["periods"])
        center = np.array(e["center"], dtype=float)
        a = np.array([e["a_x"], e["a_y"]], dtype=float)
        b = np.array([e["b_x"], e["b_y"]], dtype=float)
    except KeyError as exc:
        raise ExcitationError(f"{path}: [excitation] misses key {exc.args[0]!r}") from None
    except (TypeError, ValueError) as exc:
        raise ExcitationError(f"{path}: [excitation] has a malformed value ({exc})") from None
    if model is not None and e.get("model", model.name) != model.name:
        raise ExcitationError(f"{path}: designed for model {e['model']!r}, not {model.name!r}")
    if not (f0 > 0 and periods >= 1 and center.shape == (2,) and a.shape == b.shape
            and a.shape[1] >= 1 and np.isfinite(a).all() and np.isfinite(b).all()
            and np.isfinite(center).all()):
        raise ExcitationError(f"{path}: need base_hz > 0, periods >= 1, center of 2 numbers and "
                              f"a_x, a_y, b_x, b_y of one finite number per harmonic")
    exc = FourierExcitation(f0, periods, center, a, b, dict(d.get("design", {})))
    _, v, acc = exc.evaluate([0.0])
    if np.abs(np.concatenate([v[0], acc[0]])).max() > 1e-9 * (1 + np.abs(a).max() * f0):
        raise ExcitationError(f"{path}: the motion does not start at rest (sum of a_x, a_y and "
                              f"of w_l b_x, w_l b_y must be 0)")
    return exc


def run_design(model, out, *, base_hz=0.2, harmonics=10, periods=2, v_max=0.5, a_max=10.0,
               tau_fraction=0.5, seed=0, echo=print, progress=None):
    """``pm2dof identify --design-excitation --out FILE``: design, check at 1 ms, write."""
    from .identify import excitation, identifiability
    exc = design_excitation(model, base_hz=base_hz, harmonics=harmonics, periods=periods,
                            v_max=v_max, a_max=a_max, tau_fraction=tau_fraction, seed=seed,
                            progress=progress)
    i = exc.info
    chk = check_excitation(model, exc, v_max=v_max, a_max=a_max,
                           tau_limit=tau_fraction * np.max(model.spec.limits["tau_max"]),
                           sing_min=max(model.singularity_threshold,
                                        model.parallel_singularity_threshold) + 0.1,
                           radius=i["radius"])
    ident = identifiability(model)
    default = regressor_condition(model, ident, excitation(model, duration=exc.duration))
    write_excitation(out, exc, model)
    echo(f"wrote {out}: {exc.harmonics} harmonics of {exc.base_hz:g} Hz (up to {exc.max_hz:g} "
         f"Hz), {exc.periods} periods = {exc.duration:g} s; IPOPT {i['ipopt_status']} after "
         f"{i['ipopt_iterations']} iterations, {i['design_seconds']:g} s")
    echo(f"objective: {i['objective']}")
    echo(f"condition number of the column-scaled base regressor: {i['cond_before']:.4g} at the "
         f"start -> {i['cond_after']:.4g} optimised (the default multi-sine of --excite: "
         f"{default[0]:.4g}); log det {i['logdet_before']:.2f} -> {i['logdet_after']:.2f}")
    echo(f"checked every 1 ms: speed {chk['speed']:.3f} <= {v_max:g} m/s, acceleration "
         f"{chk['acceleration']:.2f} <= {a_max:g} m/s^2, torque (Tables 1-2, min-norm) "
         f"{chk['torque']:.2f} N m, singularity measures >= {chk['sing']:.3f}, "
         f"|x - c0| <= {chk['radius'] * 1e3:.1f} mm, starts and ends at rest: "
         f"{'all met' if chk['ok'] else 'NOT MET'}")
    return exc, chk
