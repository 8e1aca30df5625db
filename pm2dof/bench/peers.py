# The Python calls beside their C and beside the peers: binding overhead, Pinocchio, MuJoCo.
"""What a call from Python costs beyond its C, and the forward dynamics beside the peers.

In interleaved rounds (every round times each of these once, so the ratios of a round are
paired under the same machine load):

* ``Model.forward_dynamics(..., out=buf)`` and its generated function in a C loop
  (``time_calls``): the binding's overhead per call is the difference;
* ``NAController.step(..., out=buf)`` and its step in a C loop: the same for the controller;
* Pinocchio's ``constraintDynamics`` (the constrained forward dynamics, :mod:`.pinocchio_baseline`)
  and MuJoCo's ``mj_forward`` (:mod:`.mujoco_baseline`) on this robot, each one call from
  Python on a state already set, as the forward dynamics is.

Each peer models the robot's legs as chains closed by constraints with the same inertias, no
friction (pm2dof's theta with zero friction); the agreement of each with pm2dof's
acceleration is reported. A peer that is not installed (``pip install pin mujoco``, the
``bench`` extra) gives None and a note.
"""
import numpy as np

from .baselines import friction_free, peer_problem
from .timing import rel_diff, stats, time_interleaved

__all__ = ["peer_bench"]


def peer_bench(model, na, op, qa_prev, state, repeats, batch_s, c_inner, notes):
    """The measurements of the module docstring. ``na``: an NAController, ``op`` its operating
    point (state, qa, xd, xd_dot, xd_ddot), ``qa_prev`` the angles it is reset to before each
    batch; ``state`` = (xe, xed, tau_a, theta) of the forward dynamics. Returns a dict (None where a peer is missing; ``notes`` says why)."""
    res = {}
    xe, xed, tau, th = state
    n = model.n_legs
    fd, f_fd = model.forward_dynamics, model.function("forward_dynamics")
    buf, fd_outs = np.empty(model.dof), [np.empty(s) for s in f_fd.sizes_out]
    state0, qa, xd, xd_dot, xd_ddot = op
    f_na = model.function("na_step")
    na_outs = [np.empty(s) for s in f_na.sizes_out]
    step, tau_buf = na.step, np.empty(n)
    c_calls = max(1, c_inner // 10)

    def run_fd(k):
        for _ in range(k):
            fd(xe, xed, tau, th, out=buf)

    def run_fd_c(k):
        f_fd.time_calls(c_calls * k, 1, xe, xed, tau, th, *fd_outs)

    def run_na(k):
        na.reset(qa_prev)             # not timed per step: once per batch
        for _ in range(k):
            step(qa, xd, xd_dot, xd_ddot, out=tau_buf)

    def run_na_c(k):
        f_na.time_calls(c_calls * k, 1, state0, qa, xd, xd_dot, xd_ddot, na.params, *na_outs)

    runs = {"fd": run_fd, "fd_c": run_fd_c, "na": run_na, "na_c": run_na_c}
    th0 = friction_free(model, th)                       # the peers have no friction
    ours0 = model.forward_dynamics(xe, xed, tau, th0)
    pin = mj = None
    why = peer_problem(model)
    if why is not None:
        notes["pinocchio_forward_dynamics_python_us"] = notes["mujoco_forward_python_us"] = why
    else:
        try:
            from .pinocchio_baseline import PinocchioRobot
            pin = PinocchioRobot(model, th0)
        except ImportError as exc:
            notes["pinocchio_forward_dynamics_python_us"] = (
                f"pinocchio is not importable ({exc}); `pip install pin` adds the baseline")
        try:
            from .mujoco_baseline import MujocoRobot
            mj = MujocoRobot(model, th0)
        except ImportError as exc:
            notes["mujoco_forward_python_us"] = (
                f"mujoco is not importable ({exc}); `pip install mujoco` adds the baseline")
    if pin is not None:
        q, v, tq = pin.state(xe, xed, tau)
        res["agreement_pinocchio_forward_dynamics"] = rel_diff(pin.tip_acceleration(q, v, tq),
                                                               ours0)
        pin_fd = pin.forward_dynamics

        def run_pin(k):
            for _ in range(k):
                pin_fd(q, v, tq)
        runs["pinocchio"] = run_pin
    if mj is not None:
        mj.set_state(xe, xed, tau)
        mj.forward()
        res["agreement_mujoco_forward_dynamics"] = rel_diff(mj.tip_acceleration(), ours0)
        mj_forward, mjm, mjd = mj.mujoco.mj_forward, mj.model, mj.data

        def run_mj(k):
            for _ in range(k):
                mj_forward(mjm, mjd)
        runs["mujoco"] = run_mj

    t = time_interleaved(runs, repeats, batch_s)
    t["fd_c"] = [x / c_calls for x in t["fd_c"]]         # one C-loop call per Python call
    t["na_c"] = [x / c_calls for x in t["na_c"]]

    def med(values):
        return stats(values)["median"]

    for key, run in (("fd_python_interleaved_ns", "fd"), ("fd_c_interleaved_ns", "fd_c"),
                     ("na_step_python_interleaved_ns", "na"),
                     ("na_step_c_interleaved_ns", "na_c")):
        res[key], res[key + "_min"] = med(t[run]), min(t[run])
    # the binding's overhead per call: Python time minus C time, over the C time (paired)
    res["fd_binding_overhead_ns"] = med([p - c for p, c in zip(t["fd"], t["fd_c"], strict=True)])
    res["fd_binding_overhead_over_c"] = med([(p - c) / c for p, c in zip(t["fd"], t["fd_c"], strict=True)])
    res["na_step_binding_overhead_ns"] = med([p - c for p, c in zip(t["na"], t["na_c"], strict=True)])
    res["na_step_binding_overhead_over_c"] = med([(p - c) / c for p, c in
                                                  zip(t["na"], t["na_c"], strict=True)])
    res["na_step_binding_overhead_over_fd_c"] = med([(p - c) / f for p, c, f in
                                                     zip(t["na"], t["na_c"], t["fd_c"], strict=True)])
    for peer, key, ratio in (("pinocchio", "pinocchio_forward_dynamics_python_us",
                              "speedup_fd_vs_pinocchio"),
                             ("mujoco", "mujoco_forward_python_us", "speedup_fd_vs_mujoco")):
        res[key] = res[ratio] = None
        if peer in t:
            res[key], res[key + "_min"] = med(t[peer]) / 1e3, min(t[peer]) / 1e3
            res[ratio] = med([p / f for p, f in zip(t[peer], t["fd"], strict=True)])
    return res
