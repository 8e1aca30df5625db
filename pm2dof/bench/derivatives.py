# Benchmark of the generated derivatives and the model-based controller steps.
"""Timings of the forward-dynamics Jacobians, the sampled step, the inverse dynamics and the
CTC and LQR steps, beside the forward dynamics and NA, in one run of ``pm2dof bench``.

Baselines of the Jacobians from Python: Pinocchio's constrained forward dynamics with its
derivatives (``constraintDynamics`` + ``computeConstraintDynamicsDerivatives``) on the same
robot (:mod:`.pinocchio_baseline`), when ``pinocchio`` (``pip install pin``) is importable, and
always central finite differences of ``Model.forward_dynamics`` (2 (4 + n + p) calls).
"""
import numpy as np

from ..control.controllers import CTCController
from ..linear.lqr import LQRController
from .baselines import friction_free, peer_problem
from .timing import rel_diff, stats, time_batches

__all__ = ["derivative_bench", "dynamics_state"]


def _interleaved_c(fns, repeats, c_inner):
    """{name: C-loop ns per call} of several bound functions, batches interleaved (the same
    machine state for each), and the per-batch lists (for paired ratios)."""
    per = {k: [] for k in fns}
    for _ in range(repeats):
        for k, (f, args) in fns.items():
            per[k] += f.time_calls(c_inner, 1, *args)
    return {k: stats(v) for k, v in per.items()}, per


def dynamics_state(model, traj, k):
    """The desired state of sample k and its model torque (inverse dynamics, the split)."""
    th = np.array(model.theta_nominal)
    xe, xed, xedd = (np.ascontiguousarray(a[k]) for a in (traj.xd, traj.xd_dot, traj.xd_ddot))
    u = model.inverse_dynamics(xe, xed, xedd, th)
    tau = model.torque_splits(model.ik(xe), u)["min_norm"]
    return xe, xed, tau, th


def derivative_bench(model, traj, op, repeats, c_inner, batch_s, notes):
    """The measurements of the module docstring, at sample len(traj) // 2 of ``traj``
    (``op``: the NA operating point (state, qa, xd, xd_dot, xd_ddot) of the bench). Returns
    a dict of ``*_c_ns``, ``*_python_us``, ratios and agreements (None where a baseline is
    missing; ``notes`` says why)."""
    res = {}
    xe, xed, tau, th = dynamics_state(model, traj, len(traj.t) // 2)
    n = model.n_legs
    x = np.concatenate([xe, xed])
    T = float(model.spec.sensing["sample_period"])
    outs = {k: [np.empty(s) for s in model.function(k).sizes_out] for k in
            ("forward_dynamics", "forward_dynamics_jacobians", "sampled_step",
             "sampled_step_jacobians", "inverse_dynamics_jacobians")}
    xedd = model.forward_dynamics(xe, xed, tau, th)
    fns = {"forward_dynamics": (xe, xed, tau, th), "forward_dynamics_jacobians": (xe, xed, tau, th),
           "sampled_step": (x, tau, th, T), "sampled_step_jacobians": (x, tau, th, T),
           "inverse_dynamics_jacobians": (xe, xed, xedd, th)}
    st, per = _interleaved_c({k: (model.function(k), (*a, *outs[k])) for k, a in fns.items()},
                             repeats, c_inner)
    for k, s in st.items():
        res[f"{k}_c_ns"], res[f"{k}_c_ns_min"] = s["median"], s["min"]
    res["fd_jacobians_over_fd_c"] = stats([a / b for a, b in zip(
        per["forward_dynamics_jacobians"], per["forward_dynamics"])])["median"]

    # --- from Python ----------------------------------------------------------------------
    J = model.forward_dynamics_jacobians(xe, xed, tau, th)
    m = model.dof
    buf = np.empty(m)
    fd, fdj = model.forward_dynamics, model.forward_dynamics_jacobians

    def run_fd(k):
        for _ in range(k):
            fd(xe, xed, tau, th, out=buf)

    def run_jac(k):
        for _ in range(k):
            fdj(xe, xed, tau, th, out=J)

    z = np.concatenate([xe, xed, tau, th])
    h = 1e-6 * np.maximum(np.abs(z), 1e-3)
    zp, zm = z.copy(), z.copy()

    def args(zz):      # z = [xe (m), xed (m), tau_a (n), theta (p)] split into the arguments
        return zz[:m], zz[m:2 * m], zz[2 * m:2 * m + n], zz[2 * m + n:]

    def fd_jacobian():
        out = np.empty((m, len(z)))
        for i in range(len(z)):
            zp[i] += h[i]
            zm[i] -= h[i]
            out[:, i] = (fd(*args(zp)) - fd(*args(zm))) / (2 * h[i])
            zp[i] = zm[i] = z[i]
        return out

    def run_fdiff(k):
        for _ in range(k):
            fd_jacobian()

    for key, run in (("forward_dynamics_python_us", run_fd),
                     ("fd_jacobians_python_us", run_jac),
                     ("fd_jacobians_finite_differences_python_us", run_fdiff)):
        s = stats(time_batches(run, repeats, batch_s)[0])
        res[key], res[key + "_min"] = s["median"] / 1e3, s["min"] / 1e3
    res["speedup_fd_jacobians_vs_finite_differences"] = (
        res["fd_jacobians_finite_differences_python_us"] / res["fd_jacobians_python_us"])
    ad = np.hstack(list(J))
    res["agreement_fd_jacobians_vs_finite_differences"] = rel_diff(ad, fd_jacobian())

    # --- Pinocchio ----------------------------------------------------------------------
    key = "pinocchio_constraint_derivatives_python_us"
    res[key] = res["speedup_fd_jacobians_vs_pinocchio"] = None
    why = peer_problem(model)               # None: the peer can model this robot
    if why is None:
        try:
            import pinocchio

            from .pinocchio_baseline import PinocchioRobot
        except ImportError as exc:
            why = f"pinocchio is not importable ({exc}); `pip install pin` adds the baseline"
    if why is not None:
        notes[key] = why
    else:
        th0 = friction_free(model, th)          # Pinocchio's robot has no friction
        robot = PinocchioRobot(model, th0)
        q, v, tq = robot.state(xe, xed, tau)
        res["agreement_pinocchio_tip_acceleration"] = rel_diff(
            robot.tip_acceleration(q, v, tq), model.forward_dynamics(xe, xed, tau, th0))
        step = robot.forward_dynamics_with_derivatives

        def run_pin(k):
            for _ in range(k):
                step(q, v, tq)

        s = stats(time_batches(run_pin, repeats, batch_s)[0])
        res["pinocchio_constraint_derivatives_python_us"] = s["median"] / 1e3
        res["pinocchio_constraint_derivatives_python_us_min"] = s["min"] / 1e3
        res["speedup_fd_jacobians_vs_pinocchio"] = s["median"] / 1e3 / res[
            "fd_jacobians_python_us"]
        res["pinocchio_version"] = pinocchio.__version__

    # --- CTC and LQR steps in C ------------------------------------------------------------
    laws = [("ctc", CTCController(model), ())]
    try:
        lqr = LQRController(model, traj)              # plans with SciPy (the control extra)
        laws.append(("lqr", lqr, lqr._row(len(traj.t) // 2)))
    except ImportError as exc:
        notes["lqr_step_c_ns"] = f"the LQR plans with SciPy, which is not importable ({exc})"
        res["lqr_step_c_ns"] = res["lqr_step_c_ns_min"] = None
    steps = {}
    for name, ctrl, extra in laws:
        f = model.function(f"{ctrl.function_name}_step")
        o = (np.empty(n), np.empty(len(op[0])), np.empty(1), np.empty(f.sizes_out[3]))
        steps[f"{name}_step"] = (f, (*op, ctrl.params, *extra, *o))
    fna = model.function("na_step")
    from ..control.controllers import NAController
    steps["na_step"] = (fna, (*op, NAController(model).params, np.empty(n), np.empty(len(op[0])),
                              np.empty(1), np.empty(fna.sizes_out[3])))
    st, _ = _interleaved_c(steps, repeats, c_inner)
    for key in (f"{name}_step" for name, _, _ in laws):
        res[f"{key}_c_ns"], res[f"{key}_c_ns_min"] = st[key]["median"], st[key]["min"]
    res["na_step_interleaved_c_ns"] = st["na_step"]["median"]
    return res
