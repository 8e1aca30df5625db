# How a closed-loop rollout ended: completed, or where and why the plant's state stopped existing.
"""The outcome of a rollout (:attr:`pm2dof.SimResult.outcome`).

The plant's dynamics (eq. 10) are written in task space through the inverse kinematics, so
they exist only at poses every leg can reach. A run whose true pose is driven out of that set
(e.g. an unstable gain choice, or torque limits far above the actuators') cannot be integrated
further: the generated RK4 returns NaN and every later sample is undefined. The rollout in C
runs to the end regardless; afterwards :func:`pm2dof.control.simulate.completed_samples`
finds where the run ended, and :func:`classify_failure` replays the failed sample's RK4
substeps with the same generated plant functions to say where the state left the workspace or
stopped being finite, and why.
"""
import numpy as np

from ..core.errors import WorkspaceError

__all__ = ["OUTCOMES", "classify_failure"]

#: outcome -> what it means
OUTCOMES = {
    "completed": "every sample of the run has a finite state",
    "left_workspace": "the true pose left the workspace (some leg cannot reach it) during a "
                      "sample; the plant cannot be integrated beyond",
    "diverged": "the plant's state became non-finite at a pose every leg reaches (unbounded "
                "acceleration, e.g. at a singularity of the true robot, or an overflow)",
}


def _at_pose(model, xe):
    """(outcome, reason) at the pose ``xe`` (m,): "left_workspace" if some leg cannot reach
    it, else "diverged" (the reason says what the pose is like)."""
    if not np.isfinite(xe).all():
        return "diverged", f"the state overflowed (xe = {xe.tolist()} m)"
    try:
        q = model.ik(xe)
    except WorkspaceError as exc:
        return "left_workspace", str(exc)
    s = model.singularity_measures(q)
    return "diverged", (f"the plant's acceleration is not finite at xe = {xe.tolist()} m, which "
                        f"every leg reaches (singularity measures: type I {s[0]:.3g}, type II "
                        f"{s[1]:.3g})")


def classify_failure(model, xe, xed, tau_a, plant, period, substeps, t0):
    """Why the plant failed over one sample: replay its RK4 substeps under the held torque.

    Parameters
    ----------
    model : Model
    xe, xed : ndarray (m,)
        The true pose (m; phi in rad) and velocity (m/s; rad/s) at the start of the sample, finite.
    tau_a : ndarray (n,)
        The torque held over the sample, N*m.
    plant : ndarray
        The plant vector (:func:`pm2dof.control.plant.plant_vector`).
    period : float
        Sample period T, s; the sample has ``substeps`` RK4 steps of T / substeps.
    t0 : float
        Time of the sample, s.

    Returns
    -------
    outcome : str
        "left_workspace" or "diverged" (:data:`OUTCOMES`).
    time : float
        When the plant was first evaluated at a state it could not handle (the RK4 stage's
        time), s.
    reason : str
        What happened there (for a pose out of reach, :meth:`Model.ik`'s message naming the
        leg).
    """
    step, accel = model.function("plant_step"), model.function("plant_xedd")
    h = period / substeps
    hv = np.array([h])
    m = model.dof
    z, nxt, a = np.concatenate([xe, xed]), np.empty(2 * m), np.empty(m)
    tau_a, plant = np.ascontiguousarray(tau_a, dtype=float), np.ascontiguousarray(plant)
    for j in range(substeps):
        step(z, tau_a, plant, hv, nxt)
        if not np.isfinite(nxt).all():
            break
        outcome, reason = _at_pose(model, nxt[:m])
        if outcome == "left_workspace":      # a finite step that lands out of reach
            return outcome, t0 + (j + 1) * h, reason
        z = nxt.copy()
    else:
        return "diverged", t0 + period, ("the rollout's next state is not finite, but a replay "
                                         "of this sample stays finite and in reach")
    # the four RK4 stages of substep j (pm2dof/derive/plant.py), in order: the first that fails
    s = z
    for c, w in ((0.0, 0.5), (0.5, 0.5), (0.5, 1.0), (1.0, None)):
        if np.isfinite(s).all():
            accel(np.ascontiguousarray(s[:m]), np.ascontiguousarray(s[m:]), tau_a, plant, a)
        if not (np.isfinite(s).all() and np.isfinite(a).all()):
            outcome, reason = _at_pose(model, s[:m])
            return outcome, t0 + (j + c) * h, reason
        acc = np.concatenate([s[m:], a])
        if w is not None:
            s = z + w * h * acc
    return "diverged", t0 + (j + 1) * h, "the RK4 step overflowed"
