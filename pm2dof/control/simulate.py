# Closed-loop simulation: controller + plant over a trajectory, the whole rollout one call into C.
"""Closed-loop rollouts in generated C.

Each control sample k: the encoder reads the true active angles (quantised), the controller
step computes tau_k from them and the desired motion at t_k, and the plant integrates its
truth dynamics over [t_k, t_k + T] with ``rk4_substeps`` RK4 steps under that torque held
constant (zero-order hold). The loop over samples runs in C
(``pm2dof.core.binding.Function.accumulate``).
"""
import math
import warnings
from dataclasses import dataclass, field

import numpy as np

from ..core.errors import (
    ArgumentError,
    ArgumentTypeError,
    MovingStartWarning,
    OutcomeWarning,
    SingularityError,
    WorkspaceError,
)
from ..core.status import Status
from ..core.task import is_rr_point
from .controllers import _Controller, check_same_model
from .outcome import OUTCOMES, classify_failure
from .plant import plant_vector
from .plant_step import check_plant_step
from .trajectory import _positive, require_trajectory

__all__ = ["simulate", "SimResult", "OUTCOMES", "completed_samples", "rmse",
           "check_trajectory", "moving_start", "REST_VELOCITY_FLOOR", "rollout_inputs",
           "batch_inputs"]

#: m/s (rad/s for phi): a start velocity at or below it is rest, whatever the acceleration
REST_VELOCITY_FLOOR = 1e-9


def rmse(xd, xe):
    """Eq. 41: sqrt(1/N sum_i [(xd_i - xe_i)^2 + (yd_i - ye_i)^2]) over N samples, m.

    Parameters
    ----------
    xd, xe : array_like (N, 2)
        Desired and actual positions, m. Only the position (x, y) enters eq. 41: for a
        platform (N, 3) the orientation phi (rad, another unit) is left out; its error is
        ``SimResult.e[:, 2]``.
    """
    xd, xe = np.asarray(xd, dtype=float)[..., :2], np.asarray(xe, dtype=float)[..., :2]
    d = np.asarray(xd, dtype=float) - np.asarray(xe, dtype=float)
    return float(np.sqrt(np.mean(np.sum(d * d, axis=-1))))


@dataclass(frozen=True)
class SimResult:
    """One rollout. Arrays have one row per control sample k (t_k = k T). No field is ever
    NaN.

    Attributes
    ----------
    controller : str
        The controller's law ("na", "apd", ...).
    t : ndarray (N,)
        The sample times t_k, s.
    xd, xd_dot : ndarray (N, m)
        Desired pose and velocity (m = ``model.dof``, columns ``model.task_names``: x, y in
        m, m/s; a platform's phi in rad, rad/s).
    xe, xed : ndarray (N, m)
        True pose and velocity at t_k.
    tau_a : ndarray (N, n)
        Torques applied over [t_k, t_k+T], N*m.
    status : ndarray (N,) int
        0 ok, 1 singular, 2 saturated, 3 non-finite, 4 preload infeasible, 5 inconsistent
        encoders.
    theta_hat : ndarray (N, p)
        The estimate after the update at t_k.
    n_move : int
        The number of samples of the desired trajectory proper (eq. 41's N) in the arrays;
        later rows are settling.
    final_state : ndarray
        The closed loop's state after the last sample (``cl_state`` layout).
    outcome : str
        How the run ended (:data:`pm2dof.control.outcome.OUTCOMES`): "completed", or
        "left_workspace" / "diverged" when the true pose left the workspace or the state
        stopped being finite during sample ``failed_sample`` (over [t_k, t_k + T]).
    failed_sample : int or None
        That sample; None for a completed run.
    failed_time : float or None
        When it happened, s; None for a completed run.
    outcome_reason : str
        Where and why.

    Notes
    -----
    A run that did not complete ends there: its arrays hold samples 0..failed_sample (each
    one finite and in the workspace), ``n_move`` is clipped to that length, ``final_state``
    (the closed loop's state after the last sample, ``cl_state`` layout) is None, and
    :attr:`rmse` is ``inf``: no finite tracking error describes the run, and a sum or mean
    over runs that includes it cannot pass for a good result (medians and counts still work).
    The status counts and ``peak_tau`` cover the samples held.
    """
    controller: str
    t: np.ndarray
    xd: np.ndarray
    xd_dot: np.ndarray
    xe: np.ndarray
    xed: np.ndarray
    tau_a: np.ndarray
    status: np.ndarray
    theta_hat: np.ndarray
    n_move: int
    final_state: np.ndarray = field(repr=False)
    outcome: str = "completed"
    failed_sample: int = None
    failed_time: float = None
    outcome_reason: str = ""

    @property
    def e(self):
        """Pose error xd - xe (N, m), m (rad for phi)."""
        return self.xd - self.xe

    @property
    def rmse(self):
        """Eq. 41 over the samples of the desired trajectory, m; ``inf`` if the run did not
        complete (see ``outcome``)."""
        if self.outcome != "completed":
            return math.inf
        return rmse(self.xd[:self.n_move], self.xe[:self.n_move])

    @property
    def outcome_message(self):
        """One line: the outcome, and for a run that did not complete, its sample, time and
        reason."""
        if self.outcome == "completed":
            return f"completed ({len(self.t)} samples)"
        return (f"{self.outcome} during sample {self.failed_sample} (t = "
                f"{self.t[self.failed_sample]:.4f} s), at t = {self.failed_time:.5f} s: "
                f"{self.outcome_reason}")

    def count(self, status):
        """Samples of the run with the given status.

        Parameters
        ----------
        status : pm2dof.Status, int or str
            A :class:`~pm2dof.Status`, its code or its label ("singular", ...).
        """
        code = Status[status.upper()] if isinstance(status, str) else Status(status)
        return int(np.sum(self.status == code))

    n_singular = property(lambda self: self.count(Status.SINGULAR),
                          doc="samples at a singular pose (zero torque, theta_hat frozen)")
    n_saturated = property(lambda self: self.count(Status.SATURATED),
                           doc="samples whose torque was clipped to tau_max")
    n_non_finite = property(lambda self: self.count(Status.NON_FINITE),
                            doc="samples with a non-finite intermediate (zero torque)")
    n_preload_infeasible = property(
        lambda self: self.count(Status.PRELOAD_INFEASIBLE),
        doc="samples where the preload split could not keep every preload within the limits")
    n_inconsistent_encoders = property(
        lambda self: self.count(Status.INCONSISTENT_ENCODERS),
        doc="samples whose encoders did not close the loops (zero torque, state kept)")

    @property
    def peak_tau(self):
        """Largest |tau_a| applied over the rollout, N*m."""
        return float(np.max(np.abs(self.tau_a)))


def check_trajectory(model, trajectory):
    """Check every sample of a desired trajectory before a run.

    Every sample must be reachable by every leg in the model's assembly mode (WorkspaceError
    otherwise) and keep both singularity measures at or above their thresholds,
    ``limits.singularity_threshold`` (type I, legs) and
    ``limits.parallel_singularity_threshold`` (type II, actuation) (SingularityError naming
    the kind), and every sample of xd, xd_dot and xd_ddot must be finite (ArgumentError) with
    the model's task dimension m columns (ArgumentError naming m). The error names the sample,
    its time and position.

    Parameters
    ----------
    model : Model
        The robot.
    trajectory : Trajectory
        The desired trajectory (``t``, ``xd``, ``xd_dot``, ``xd_ddot``).
    """
    m = model.dof
    for name in ("xd", "xd_dot", "xd_ddot"):
        shape = np.shape(getattr(trajectory, name))
        if len(shape) != 2 or shape[1] != m:
            raise ArgumentError(
                f"trajectory {name} has shape {shape}: model {model.name!r} has task dimension "
                f"m = {m} ({', '.join(model.task_names)}), so it must be (N, {m})")
    for name, what in (("xd", "position"), ("xd_dot", "velocity"), ("xd_ddot", "acceleration")):
        v = np.asarray(getattr(trajectory, name), dtype=float)
        if not np.isfinite(v).all():
            k = int(np.argwhere(~np.isfinite(v))[0, 0])
            raise ArgumentError(f"desired {what} ({name}) at sample {k} (t = "
                                f"{trajectory.t[k]:.4f} s) is not finite: {v[k].tolist()}")
    xd = np.asarray(trajectory.xd, dtype=float)
    thr1, thr2 = model.singularity_threshold, model.parallel_singularity_threshold
    type1, type2, side = model.pose_measures(xd)
    # the first offending sample is re-checked with the generated ik for its message
    ok = model.poses_clear(type1, type2, side)
    for k in np.flatnonzero(~ok)[:1]:
        x = xd[k]
        where = f"trajectory sample {k} (t = {trajectory.t[k]:.4f} s) at xe = {x.tolist()}"
        try:
            q = model.ik(x)
        except WorkspaceError as exc:
            raise WorkspaceError(f"{where}: {exc}") from None
        sing = model.singularity_measures(q)
        if not (sing[0] >= thr1 and sing[1] >= thr2):
            raise SingularityError(f"{where}: {model.singularity_message(sing)}")


def moving_start(trajectory, names=("x", "y", "phi")):
    """Whether a desired trajectory does not start at rest, and by how much.

    The simulated robot starts at rest at the first sample. A coordinate c moves at the start
    when |xd_dot[0, c]| > T max_k |xd_ddot[k, c]| + :data:`REST_VELOCITY_FLOOR`: more than
    one sample (T) of the trajectory's own largest acceleration gives. A trajectory sampled
    from a motion that starts at rest passes, also with its rates differentiated from its
    positions (an S-curve's one-sided difference at t = 0 is j T^2 / 3, far below T a_max).

    Parameters
    ----------
    trajectory : Trajectory
        ``xd_dot``, ``xd_ddot`` (N, m) and ``period`` T, s.
    names : sequence of str
        The task coordinates' names (default x, y, phi; ``Model.task_names``).

    Returns
    -------
    str or None
        None at rest; else one phrase naming the desired velocity at t = 0 (m/s, rad/s for
        phi) and the bound it exceeds.
    """
    v0 = np.asarray(trajectory.xd_dot[0], dtype=float)
    acc = np.max(np.abs(np.asarray(trajectory.xd_ddot, dtype=float)), axis=0)
    bound = trajectory.period * acc
    if not np.any(np.abs(v0) > bound + REST_VELOCITY_FLOOR):
        return None
    names = list(names)[:len(v0)]
    unit = ", ".join(sorted({"rad/s" if c == "phi" else "m/s" for c in names},
                            key=["m/s", "rad/s"].index))
    cols = ", ".join(f"{c}_dot" for c in names)
    return (f"the desired velocity at t = 0 is ({cols}) = ({', '.join(f'{v:.4g}' for v in v0)}) "
            f"{unit}, not rest: more than one sample of its own largest acceleration gives "
            f"(T max|xd_ddot| = ({', '.join(f'{b:.3g}' for b in bound)}) {unit}); the simulated "
            f"robot starts at rest, so its first samples answer a velocity step")


def _reachable(model, xe):
    """(K,) bool: the poses ``xe`` (K, m) every leg reaches (RR legs at a point: |la - lb| <=
    |xe - A_i| <= la + lb; other mechanisms: the generated ik has a solution)."""
    if not is_rr_point(model.spec):
        q, ok = np.empty(2 * model.n_legs), np.zeros(len(xe), dtype=bool)
        for k, x in enumerate(xe):
            try:
                model.ik(x, out=q)
                ok[k] = True
            except (WorkspaceError, ArgumentError):     # out of reach, or not finite
                pass
        return ok
    reach = np.ones(len(xe), dtype=bool)
    for leg in model.spec.legs:
        d = np.hypot(xe[:, 0] - leg.base[0], xe[:, 1] - leg.base[1])
        reach &= (abs(leg.la - leg.lb) <= d) & (d <= leg.la + leg.lb)
    return reach


def completed_samples(model, y, ylay):
    """How many leading samples of rollouts exist: (...,) int, from their outputs ``y``
    (..., N, ny) in the Layout ``ylay`` (``cl_output``).

    A sample exists when its whole row is finite and its true pose xe is in reach of every
    leg (RR legs: |la - lb| <= |xe - A_i| <= la + lb). The plant's dynamics go through the inverse
    kinematics, so a pose out of reach makes every later row non-finite: only the last finite
    row can hold one, and only it is checked. ``N`` for a run that completed; else the first
    sample that does not exist.
    """
    N, ny = y.shape[-2:]
    if y.ndim == 2 and np.isfinite(y).all() and is_rr_point(model.spec):
        x, z = y[-1, ylay.slices["xe"]].tolist()   # one finite rollout (simulate): its last pose
        return N - (not all(abs(g.la - g.lb) <= math.hypot(x - g.base[0], z - g.base[1])
                            <= g.la + g.lb for g in model.spec.legs))
    yy = y.reshape(-1, N, ny)
    bad = ~np.isfinite(yy).all(axis=-1)
    n = np.where(bad.any(axis=-1), bad.argmax(axis=-1), N)
    last = yy[np.arange(len(yy)), np.maximum(n - 1, 0), ylay.slices["xe"]]     # (K, m)
    reach = (n > 0) & _reachable(model, last)
    return np.where((n > 0) & ~reach, n - 1, n).reshape(y.shape[:-2])


def rollout_inputs(model, controller, traj, plant, theta_hat0=None):
    """What one rollout's C call takes: (closed-loop function, initial state x (nx,), inputs u
    (N, 3m), parameters p (np,), output Layout). The robot starts at rest at traj's first point,
    the controller's estimate of xe from the first (quantised) measurement, theta_hat(0) =
    ``theta_hat0`` or the controller's theta0. ``plant`` is a :func:`plant_vector`."""
    f, X, u, P, ylay = batch_inputs(model, controller, traj, np.asarray(plant)[None],
                                    None if theta_hat0 is None else [theta_hat0])
    return f, X[0], u, P[0], ylay


def batch_inputs(model, controller, traj, plants, theta_hat0=None):
    """:func:`rollout_inputs` for K rollouts at once, for ``Function.accumulate_batch``:
    ``plants`` (K, n_plant) rows of :func:`plant_vector`, ``theta_hat0`` None or K rows (a row
    None: the controller's theta0). Returns (f, X (K, nx), u (N, 3m), P (K, np), output Layout).
    """
    check_same_model(model, controller)
    plants = np.asarray(plants, dtype=float)
    K = len(plants)
    f = model.function(f"{controller.function_name}_closed_loop")
    P = np.empty((K, len(controller.params) + plants.shape[1]))
    P[:, :len(controller.params)] = controller.params
    P[:, len(controller.params):] = plants
    xs, cs = model.layout("cl_state"), model.layout("ctrl_state")
    X = np.zeros((K, xs.size))
    S = xs.unpack(X)
    S["xe"][:] = traj.xd[0]
    C = cs.unpack(S["ctrl_state"])
    qa0 = np.empty(model.n_legs)
    measure, x0 = model.function("measure"), np.ascontiguousarray(traj.xd[0])
    for k in range(K):   # the first (quantised) measurement depends on each plant's encoder
        measure(x0, plants[k], qa0)
        C["xe_prev"][k] = model.fk(qa0)
    C["theta_hat"][:] = controller.theta0
    if theta_hat0 is not None:
        for k, th in enumerate(theta_hat0):
            if th is not None:
                C["theta_hat"][k] = model.checked_theta(th, "theta_hat0")
    u = controller.closed_loop_inputs(traj)
    return f, X, u, P, model.layout("cl_output")


def simulate(model, controller, trajectory, *, truth=None, quantise=True, theta_hat0=None,
             settle_time=0.0, encoder_counts_per_rev=None):
    """Run ``controller`` against the plant's truth along ``trajectory``: one call into C.

    Parameters
    ----------
    model : Model
    controller : NAController, APDController, CTCController or LQRController
        Supplies the law, its gains, sample period and theta0 (its internal state is not used
        or changed: the rollout keeps its own state in C). A Python-level controller
        (:class:`pm2dof.control.python_loop.PythonController`, e.g. the NMPC example) runs
        one Python step per sample against the same generated plant.
    trajectory : pm2dof.Trajectory
        Desired motion sampled at the controller's period; the robot starts at rest at its
        first point.
    truth : dict, optional
        Plant truth (default :func:`plant_truth`); must not be the controller's parameters.
    quantise : bool
        Quantise the encoders to ``[sensing].encoder_counts_per_rev`` (False: exact angles).
    encoder_counts_per_rev : int, optional
        Replaces the model file's encoder resolution (0: exact angles).
    theta_hat0 : array_like (p,), optional
        Initial estimate (default: the controller's ``theta0``).
    settle_time : float
        Seconds of rest at the end point simulated after the move (not in the RMSE).

    Returns
    -------
    SimResult
        Its ``outcome`` says whether the run completed; one that left the workspace or
        diverged ends at the failed sample (see :class:`SimResult`), and ``simulate`` warns
        (:class:`pm2dof.OutcomeWarning`) naming the sample, the time and the reason.

    Warns
    -----
    MovingStartWarning
        The trajectory does not start at rest (:func:`moving_start`): the robot starts at rest,
        so the first samples answer a velocity step. The run goes on (a reference file is
        refused instead, ``pm2dof simulate --reference``).

    Raises
    ------
    ModelMismatchError
        If ``controller`` was built for another model.
    """
    from .python_loop import PythonController, python_rollout
    if not isinstance(controller, (_Controller, PythonController)):
        raise ArgumentTypeError(f"controller must be an NAController, APDController, "
                                f"CTCController, LQRController or a PythonController, got "
                                f"{type(controller).__name__}")
    require_trajectory(trajectory)
    ts = _positive("settle_time (s)", settle_time, zero_ok=True)
    T = controller.sample_period
    if abs(trajectory.period - T) > 1e-12 * T:
        raise ArgumentError(f"trajectory period {trajectory.period} s differs from the "
                         f"controller's sample period {T} s")
    check_same_model(model, controller)
    check_trajectory(model, trajectory)
    moving = moving_start(trajectory, model.task_names)
    if moving is not None:
        warnings.warn(f"simulate ({controller._law}, model {model.name!r}): {moving}",
                      MovingStartWarning, stacklevel=2)
    n_move = len(trajectory.t)
    traj = trajectory.extended(ts) if ts > 0 else trajectory
    plant = plant_vector(model, truth, quantise, encoder_counts_per_rev)
    check_plant_step(model, traj.xd, truth)
    if isinstance(controller, PythonController):   # one Python step per sample
        x, y, ylay = python_rollout(model, controller, traj, plant, theta_hat0)
    else:
        f, x, u, p, ylay = rollout_inputs(model, controller, traj, plant, theta_hat0)
        y = np.empty((len(traj.t), ylay.size))
        f.accumulate(x, u, p, y)
    N = int(completed_samples(model, y, ylay))
    end = {}
    if N < len(y):              # the state at sample N does not exist: the run ends at N - 1
        y, k = y[:N], N - 1
        Y = ylay.unpack(y)
        outcome, when, reason = classify_failure(
            model, Y["xe"][k], Y["xed"][k], Y["tau_a"][k], plant, T, model.spec.rk4_substeps,
            traj.t[k])
        end = {"outcome": outcome, "failed_sample": k, "failed_time": float(when),
               "outcome_reason": reason}
        n_move, x = min(n_move, N), None
    Y = ylay.unpack(y)
    r = SimResult(controller=controller._law, t=traj.t[:N], xd=traj.xd[:N],
                  xd_dot=traj.xd_dot[:N], xe=Y["xe"], xed=Y["xed"], tau_a=Y["tau_a"],
                  status=Y["status"][:, 0].astype(int), theta_hat=Y["theta_hat"], n_move=n_move,
                  final_state=x, **end)
    if end:
        warnings.warn(f"simulate ({controller._law}, model {model.name!r}): "
                      f"{r.outcome_message}", OutcomeWarning, stacklevel=2)
    return r
