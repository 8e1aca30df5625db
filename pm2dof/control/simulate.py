# Closed-loop simulation: controller + plant over a trajectory, the whole rollout one call into C.
"""Closed-loop rollouts in generated C.

Each control sample k: the encoder reads the true active angles (quantised), the controller
step computes tau_k from them and the desired motion at t_k, and the plant integrates its
truth dynamics over [t_k, t_k + T] with ``rk4_substeps`` RK4 steps under that torque held
constant (zero-order hold). The loop over samples runs in C (``_cbind.Function.accumulate``).
"""
import functools
import math
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from ..core.errors import (
    ArgumentError,
    ArgumentTypeError,
    OutcomeWarning,
    SingularityError,
    WorkspaceError,
)
from ..core.model_file import payload_increments
from ..core.status import Status
from ..core.task import is_rr_point
from .controllers import _Controller, check_same_model
from .outcome import OUTCOMES, classify_failure
from .trajectory import _positive, require_trajectory

__all__ = ["simulate", "SimResult", "OUTCOMES", "completed_samples", "plant_truth",
           "plant_vector", "rmse", "theta_truth", "check_trajectory", "pose_measures",
           "poses_clear", "rollout_inputs", "batch_inputs"]


def plant_truth(model, **overrides):
    """The plant's truth as a dict: the model file's ``[plant]`` with the payload booked in.

    The payload's mass m is booked by ``pm2dof.core.model_file.payload_increments``: a
    platform carries it at its origin (m_p += m); a point end effector books it to the tip of
    leg j's distal link (j = ``payload_leg``, counted from 1 as in the paper): an RRR leg's
    alpha_j, beta_j, gamma_j, kappa_j gain m la^2, m la lb, m lb^2, m la (its kinetic energy
    1/2 m |tip velocity|^2 in the leg's angles, its potential energy), a PRR leg's m, m lb,
    m lb^2, an RPR leg's alpha_j m.

    Parameters
    ----------
    model : Model
        The robot; its model file's ``[plant]`` is the truth.
    **overrides
        Replace fields of ``[plant]`` (e.g. ``payload_mass=0``); a ``payload_leg`` outside
        1..n raises ArgumentError.
    """
    p = dict(model.spec.plant)
    unknown = sorted(set(overrides) - set(p))
    if unknown:
        raise ArgumentTypeError(f"unknown plant field(s) {unknown}; fields are {sorted(p)}")
    p.update(overrides)
    platform = getattr(model.spec, "end_effector", "point") == "platform"
    leg_no = 1 if platform else p["payload_leg"]
    if not (isinstance(leg_no, (int, float, np.number)) and not isinstance(leg_no, bool)
            and leg_no == int(leg_no) and 1 <= leg_no <= model.n_legs):
        raise ArgumentError(f"payload_leg must be a leg number 1..{model.n_legs} (legs count from 1, "
                         f"as in the paper), got {leg_no!r}")
    j = int(leg_no) - 1
    inertial = [f for f, _ in model.layout("plant").fields if f in p and f not in
                ("fv", "fc", "fs", "stribeck_velocity", "coulomb_smoothing_velocity")]
    truth = {k: np.array(p[k], dtype=float) for k in inertial}
    for name, inc in payload_increments(model.spec.legs[j], "platform" if platform else "point",
                                        float(p["payload_mass"])).items():
        if name in truth:                      # e.g. no kappa without gravity
            if truth[name].ndim:
                truth[name][j] += inc
            else:
                truth[name] = truth[name] + inc
    return {**truth, **{k: np.array(p[k], dtype=float) for k in ("fv", "fc", "fs")},
            "stribeck_velocity": float(p["stribeck_velocity"]),
            "coulomb_smoothing_velocity": float(p["coulomb_smoothing_velocity"])}


def plant_vector(model, truth=None, quantise=True, encoder_counts_per_rev=None):
    """The generated plant's parameter vector (manifest layout ``plant``): the truth (default
    :func:`plant_truth`) and the encoder step 2 pi / encoder_counts_per_rev (0 when
    ``quantise`` is false or the resolution is 0), and for linear actuators (PRR, RPR legs)
    ``[sensing] linear_encoder_resolution``, m (0 when ``quantise`` is false). ``encoder_counts_per_rev`` replaces the model
    file's ``[sensing]`` value."""
    counts = (model.spec.sensing["encoder_counts_per_rev"] if encoder_counts_per_rev is None
              else encoder_counts_per_rev)
    if not (isinstance(counts, (int, float, np.integer, np.floating)) and counts >= 0
            and float(counts).is_integer()):
        raise ArgumentError(f"encoder_counts_per_rev must be a whole number >= 0, got {counts!r}")
    truth = plant_truth(model) if truth is None else truth
    if not isinstance(truth, Mapping):
        raise ArgumentTypeError(f"truth must be a dict like pm2dof.plant_truth(model) (fields "
                                f"{sorted(plant_truth(model))}), got {type(truth).__name__}; "
                                f"plant_truth(model, alpha=..., fv=...) makes one")
    lay = model.layout("plant")
    steps = {"encoder_step": (2 * math.pi / counts) if (quantise and counts > 0) else 0.0}
    if "linear_encoder_step" in lay.slices:      # PRR, RPR legs: m per count
        steps["linear_encoder_step"] = (
            float(model.spec.sensing["linear_encoder_resolution"]) if quantise else 0.0)
    try:
        vec = lay.pack(**truth, **steps)
    except (TypeError, ValueError) as exc:
        raise ArgumentError(f"truth: {exc}") from None
    return vec


def theta_truth(model, truth=None):
    """The truth in theta's coordinates (``model.param_names`` order): inertias with payload,
    fv, fc, and fs when the model's friction has a Stribeck term.

    The paper's model (eq. 2) has no coordinate for the Stribeck excess; it is left out.
    Smooth-sign or Stribeck shapes of the controller's model differ from the plant's, so
    only the coefficients are compared.

    Parameters
    ----------
    model : Model
        The robot.
    truth : dict, optional
        A plant truth (:func:`plant_truth`'s dict); default the model file's ``[plant]``.
    """
    t = plant_truth(model) if truth is None else truth
    return np.array([np.ravel(t[base])[i] for base, i in _param_index(model.param_names)])


@functools.lru_cache(maxsize=16)
def _param_index(names):
    """(field, leg index) of each parameter name, e.g. 'gamma3' -> ('gamma', 2), 'm_p' ->
    ('m_p', 0) (the platform's parameters carry no leg number)."""
    out = []
    for name in names:
        base = name.rstrip("0123456789")
        out.append((base, int(name[len(base):]) - 1 if len(base) < len(name) else 0))
    return tuple(out)


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


def _generated_measures(model, xd):
    """:func:`pose_measures` by the generated ik and singularity_measures, sample by sample:
    any mechanism (NaN where ik has no solution)."""
    type1, type2 = np.full(len(xd), np.nan), np.full(len(xd), np.nan)
    q, sing = np.empty(2 * model.n_legs), np.empty(2)
    for k, x in enumerate(xd):
        try:
            model.ik(x, out=q)
        except WorkspaceError:
            continue
        model.singularity_measures(q, out=sing)
        type1[k], type2[k] = sing
    return type1, type2, np.ones(len(xd))


def pose_measures(model, xd):
    """Both singularity measures and, for two legs, the assembly side of every pose.

    For RR legs meeting at a point: vectorised NumPy geometry of ``ik`` (law of cosines per
    leg, the model's elbows), used to check a whole trajectory at once; the generated ``ik``
    and ``singularity_measures`` remain the reference and word the errors. Other mechanisms
    (prismatic legs, a platform): the generated functions at every pose.

    Parameters
    ----------
    xd : array_like (N, m)
        Task poses (m = ``model.dof``), m (phi in rad).

    Returns
    -------
    type1, type2, side : ndarray (N,)
        min_i |sin(qb_i - qa_i)|, the type II measure (see ``Model.singularity_measures``), NaN
        where some leg cannot reach; ``side`` = fk_branch * cross(B2 - B1, O - B1) for two legs
        (> 0 in the model's assembly mode), +1 for more legs.
    """
    xd = np.asarray(xd, dtype=float).reshape(-1, model.dof)
    if not is_rr_point(model.spec):
        return _generated_measures(model, xd)
    legs = model.spec.legs
    type1 = np.full(len(xd), np.inf)
    z = np.zeros(len(xd), dtype=complex)
    elbows = []
    with np.errstate(invalid="ignore", divide="ignore"):
        for leg in legs:
            d = xd - np.asarray(leg.base)
            dist = np.hypot(d[:, 0], d[:, 1])
            c = (leg.la ** 2 + dist ** 2 - leg.lb ** 2) / (2 * leg.la * dist)
            c[~(np.abs(c) <= 1)] = np.nan                       # out of reach: NaN
            s = leg.elbow * np.sqrt(1 - c * c)
            dh = d / dist[:, None]
            ua = c[:, None] * dh + s[:, None] * np.stack([-dh[:, 1], dh[:, 0]], axis=1)
            ub = (d - leg.la * ua) / leg.lb
            type1 = np.minimum(type1, np.abs(ua[:, 0] * ub[:, 1] - ua[:, 1] * ub[:, 0]))
            z += (ub[:, 0] + 1j * ub[:, 1]) ** 2                # e^(2 i qb)
            elbows.append(np.asarray(leg.base) + leg.la * ua)
        type2 = np.sqrt(np.maximum(1 - np.abs(z) / len(legs), 0)) + 0 * type1  # NaN stays
        side = np.ones(len(xd))
        if len(legs) == 2:
            dB, e = elbows[1] - elbows[0], xd - elbows[0]
            side = model.spec.fk_branch * (dB[:, 0] * e[:, 1] - dB[:, 1] * e[:, 0])
    return type1, type2, side


def poses_clear(model, type1, type2, side=1.0):
    """(N,) bool: the poses a desired motion may use, from their measures (``pose_measures``
    or the generated ``singularity_measures``, each (N,)): both at or above their thresholds
    (``[limits]``; a relative slack of 1e-12 for rounding) and, for two legs, in the model's
    assembly mode (``side`` > 0). NaN (out of reach) is not clear."""
    thr1, thr2 = model.singularity_threshold, model.parallel_singularity_threshold
    return (np.asarray(type1) >= thr1 * (1 - 1e-12)) & \
        (np.asarray(type2) >= thr2 * (1 - 1e-12)) & (np.asarray(side) > 0)


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
    type1, type2, side = pose_measures(model, xd)
    # the first offending sample is re-checked with the generated ik for its message
    ok = poses_clear(model, type1, type2, side)
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
    n_move = len(trajectory.t)
    traj = trajectory.extended(ts) if ts > 0 else trajectory
    plant = plant_vector(model, truth, quantise, encoder_counts_per_rev)
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
