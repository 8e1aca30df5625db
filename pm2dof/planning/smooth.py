# A torque-rate-limited, near-time-optimal timing by direct collocation (CasADi + IPOPT).
"""``plan_smooth``: the time-optimal problem of :mod:`.topp` on the same kind of grid, plus a
limit on how fast each actuator torque may change, |d tau_i / dt| <= tau_rate,i. A bang-bang
torque profile (the strict optimum) jumps between its limits and excites the structure; this
one ramps. Solved by IPOPT (shipped in the casadi wheel), warm-started from the strict optimum.

Variables: the path speeds y_k at the grid points and, for the min-max split, the torques at
both ends of every interval (n each; min-norm: tau = S (S^T S)^-1 u). With
u_k = (y_k+1^2 - y_k^2) / (2 delta_k), on the same two-ended discretisation as
:func:`plan_time_optimal`:

    min sum_k 2 delta_k / (y_k + y_k+1)
    S^T tau = a u_k + b y^2 + g(y) leaving s_k (y_k) and arriving at s_k+1 (y_k+1),
    |tau_i| <= tau_max,i at both,   |tau_k+1,i - tau_k,i| (y_k + y_k+1) <= 2 delta_k tau_rate,i
    (tau_k the torque leaving s_k, the last one arriving),   y = 0 at the stops,

g(y) = S^T f_a(S p' y) (+ gravity) the friction force, a CasADi expression of y with exact
derivatives for every friction law (:func:`.path_friction.path_friction`: from the generated
``path_torques`` where it is affine in y, by the law otherwise; before, a law not affine in the
speed went through the generated C with finite differences, minutes per plan).
"""
import numbers
import time

import numpy as np

from ..core.errors import PlanError
from ..core.task import per_actuator
from ..infra.interrupt import noticing_ctrl_c
from .check import require
from .path_friction import AFFINE, BY_LAW, path_friction
from .plan import PathProfile, Plan, grid_times, sample
from .problem import PlanProblem
from .stages import limits, params, stages
from .topp import plan_time_optimal
from .watch import iteration_watch

__all__ = ["plan_smooth", "RISE_TIME", "MAX_ITER"]

RISE_TIME = 0.02   # s: the default tau_rate lets each torque swing 0 -> tau_max in 20 ms
MAX_ITER = 100_000  # the most IPOPT iterations max_iter may ask for


def _rate_unit(model):
    """The unit of the actuators' effort rates, for messages: N m/s, N/s (linear actuators)."""
    return per_actuator(model.spec.actuators, "N m/s", "N/s", "N m/s or N/s")


def plan_smooth(model, path, tau_max=None, split="min_max", theta=None, margin=1.0, grid=200,
                tau_rate=None, max_iter=1000, progress=None):
    """A near-time-optimal traversal of ``path`` whose torques change at a limited rate.

    Parameters
    ----------
    model, path, tau_max, split, theta, margin, grid
        As :func:`plan_time_optimal` (grid: fewer points, IPOPT's cost grows with it).
    tau_rate : float or array_like (n,), optional
        Largest |d tau_i / dt|, N m/s (N/s for a linear actuator), > 0 (default tau_max *
        margin / RISE_TIME: a full swing in 20 ms).
    max_iter : int
        IPOPT's iteration limit, 1 to MAX_ITER = 100000.
    progress : callable, optional
        Takes one-line messages (:class:`pm2dof.infra.progress.Progress` or any callable):
        the problem's size before IPOPT starts, IPOPT's iterations while it runs (a bar on a
        terminal, else a line every :data:`pm2dof.planning.watch.LINE_EVERY` s with the
        iteration and the elapsed time) and its status, iterations and time when it ends.
        None: silent.

    Returns
    -------
    Plan
        ``method`` "smooth"; ``info`` holds ``strict_duration`` (the time-optimal plan on the
        same grid), ``ipopt_status``, ``iterations``, ``solve_time_s``, ``tau_rate``,
        ``friction`` (how the friction force entered: "affine, exact" from the generated C,
        "exact, CasADi" by the law: :func:`.path_friction.path_friction`).

    Raises
    ------
    PlanError
        Bad arguments (as :func:`plan_time_optimal`; a max_iter or tau_rate out of range,
        checked before IPOPT runs), or IPOPT finds no solution.
    KeyboardInterrupt
        Ctrl-C while IPOPT runs: IPOPT is stopped at its next iteration (it would otherwise
        report the interrupt as ``NonIpopt_Exception_Thrown``, a failure of the solver) and no
        plan is returned; the message says after how many iterations.
    """
    t0 = time.perf_counter()
    require(model, path)
    if isinstance(max_iter, bool) or not isinstance(max_iter, numbers.Integral) or \
            not 1 <= max_iter <= MAX_ITER:
        raise PlanError(f"max_iter must be a whole number of IPOPT iterations from 1 to "
                        f"{MAX_ITER}, got {max_iter!r}")
    tau_lim = limits(model, tau_max, margin)
    n, m = model.n_legs, model.dof
    try:
        rate = (tau_lim / RISE_TIME if tau_rate is None
                else np.array(tau_rate, dtype=float).ravel() * np.ones(n))
    except (TypeError, ValueError):
        rate = np.full(n, np.nan)
    if rate.shape != (n,) or not (np.isfinite(rate).all() and (rate > 0).all()):
        raise PlanError(f"tau_rate must be one value or {n} finite rates > 0 "
                        f"{_rate_unit(model)}, got {tau_rate!r}")
    import casadi as ca
    strict = plan_time_optimal(model, path, tau_max, split, theta, margin, grid)
    s = strict.s
    prm, th = params(model, strict.info["theta"])
    problem = PlanProblem(model, path, tau_lim, th, split, prm)
    stops = np.searchsorted(s, path.stops)
    stage, coef = stages(problem, s, stops)
    K = len(s)
    delta = np.diff(s)
    lay = model.layout("path_stage")
    ends = (stage[:-1], coef["arrive"][1:])          # the facets leaving s_k, arriving s_k+1
    opti = ca.Opti()
    y = opti.variable(K)
    x = y * y
    u = (x[1:] - x[:-1]) / (2 * delta)
    taus, how = [], set()
    for rows, yk in zip(ends, (y[:-1], y[1:])):
        R = lay.unpack(rows)
        a, b, S = R["a"], R["b"], R["S"].reshape(K - 1, n, m)
        fr, formed = path_friction(problem, rows, yk)
        how.add(formed)
        force = [ca.DM(a[:, i]) * u + ca.DM(b[:, i]) * yk * yk + fr[i] for i in range(m)]
        if split == "min_max":
            tau = opti.variable(K - 1, n)
            for i in range(m):
                opti.subject_to(sum(ca.DM(S[:, j, i]) * tau[:, j] for j in range(n)) == force[i])
        else:
            P = np.einsum("kij,kjl->kil", S, np.linalg.inv(np.einsum("kji,kjl->kil", S, S)))
            tau = ca.horzcat(*[sum((ca.DM(P[:, j, i]) * force[i] for i in range(1, m)),
                                   ca.DM(P[:, j, 0]) * force[0]) for j in range(n)])
        for j in range(n):
            opti.subject_to(opti.bounded(-tau_lim[j], tau[:, j], tau_lim[j]))
        taus.append(tau)
    if split == "min_max":
        opti.set_initial(taus[0], strict.tau[:-1])
        opti.set_initial(taus[1], strict.tau[1:])
    tau = ca.vertcat(taus[0], taus[1][-1, :])        # at the grid points (the end: arriving)
    for j in range(n):
        d = (tau[1:, j] - tau[:-1, j]) * (y[1:] + y[:-1])
        opti.subject_to(opti.bounded(-2 * delta * rate[j], d, 2 * delta * rate[j]))
    opti.subject_to(y >= 0)
    for k in stops:
        opti.subject_to(y[int(k)] == 0)
    opti.minimize(ca.sum1(2 * delta / (y[1:] + y[:-1] + 1e-12)))
    opti.set_initial(y, 0.9 * strict.sdot)
    friction = AFFINE if how == {AFFINE} else BY_LAW
    what = f"smoothing ({split})"
    if progress is not None:
        progress(f"{what}: IPOPT on {K} grid points, {opti.nx} variables, {opti.ng} "
                 f"constraints (friction {friction})")
    t1 = time.perf_counter()
    with noticing_ctrl_c() as ctrl_c:
        watch = iteration_watch(opti.nx, opti.ng, progress, ctrl_c, what, max_iter)
        opti.solver("ipopt", {"print_time": False, "iteration_callback": watch},
                    {"print_level": 0, "max_iter": int(max_iter), "tol": 1e-8, "sb": "yes"})
        try:
            sol = opti.solve()
            status = "Solve_Succeeded"
        except RuntimeError:
            sol, status = opti.debug, opti.stats().get("return_status", "failed")
        finally:
            watch.close()
    solve_s = time.perf_counter() - t1
    iterations = int(opti.stats().get("iter_count", -1))
    if ctrl_c or status == "User_Requested_Stop":
        raise KeyboardInterrupt(f"IPOPT stopped after {iterations} iterations, {solve_s:.1f} s; "
                                f"no smoothed plan")
    if progress is not None:
        progress(f"{what}: IPOPT {status} after {iterations} iterations, {solve_s:.1f} s")
    if not str(status).startswith(("Solve_Succeeded", "Solved_To_Acceptable")):
        raise PlanError(f"plan_smooth: IPOPT did not converge ({status}) on {K} grid points "
                        f"with tau_rate {rate.tolist()} {_rate_unit(model)}")
    sdot = np.maximum(np.asarray(sol.value(y), dtype=float).ravel(), 0.0)
    sdot[stops] = 0.0
    x = sdot ** 2
    sdd = np.diff(x) / (2 * delta)
    sdd = np.concatenate([sdd, sdd[-1:]])
    t = grid_times(s, sdot)
    tau_v = np.asarray(sol.value(tau), dtype=float).reshape(K, n)
    profile = PathProfile(s, sdot, sdd, t)
    traj = sample(path, profile, model.spec.sensing["sample_period"])
    return Plan(path=path, method="smooth", split=split, max_velocity=strict.max_velocity,
                tau=tau_v, tau_peak=np.abs(tau_v).max(axis=0), tau_max=tau_lim, margin=float(margin),
                trajectory=traj, profile=profile, compute_time_s=time.perf_counter() - t0,
                info={"grid": K, "theta": th.tolist(), "strict_duration": strict.duration,
                      "tau_max_actuators": strict.info["tau_max_actuators"],
                      "ipopt_status": str(status), "iterations": iterations,
                      "solve_time_s": solve_s, "tau_rate": rate.tolist(),
                      "friction": friction})
