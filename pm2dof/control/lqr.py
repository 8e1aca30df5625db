# Time-varying LQR tracking at run time: a planned gain schedule, one generated C call per step.
"""The time-varying LQR's step, given its plan.

Per sample (in the generated C ``<name>_lqr<split>_step``): the Fig. 2 signal processing,
tau = tau_ff,k - K_k [xe - xd, v - xd_dot], its task force S^T tau at the measured pose shared
by the split, clipping, the statuses of NA and APD. K_k and tau_ff,k enter the C as per-sample
inputs; nothing is solved per step.

The plan (K_k from the backward Riccati recursion along the linearised trajectory, tau_ff,k
from the inverse dynamics) is computed once, before the run, by :mod:`pm2dof.linear.lqr`
(SciPy): ``pm2dof.LQRController(model, trajectory)`` plans and builds this controller. Here it
only runs: :class:`LQRController` takes the planned arrays.
"""
import numpy as np

from ..core import binding
from ..core.errors import ArgumentError
from ..core.model import require_model
from .controllers import _Controller
from .settings import ControlSettings
from .trajectory import require_trajectory

__all__ = ["LQRController"]


def _schedule(name, value, shape, unit):
    """``value`` as a read-only float64 array of ``shape``, finite; ArgumentError naming it."""
    try:
        a = np.array(value, dtype=float)
    except (TypeError, ValueError):
        a = None
    if a is None or a.shape != shape or not np.isfinite(a).all():
        got = "not numbers" if a is None else f"shape {a.shape}" if a.shape != shape else \
            "non-finite entries"
        raise ArgumentError(f"LQRController: {name} must be {shape} finite numbers ({unit}), "
                            f"got {got}")
    return a


class LQRController(_Controller):
    """Time-varying LQR tracking along ``trajectory`` with the planned gains ``K`` and
    feedforward ``tau_ff`` (module docstring), one C call per sample.

    To plan them, build it with ``pm2dof.LQRController(model, trajectory, ...)``
    (:class:`pm2dof.linear.lqr.LQRController`: the LQR's weights, SciPy's Riccati solver);
    this class runs a plan computed elsewhere (e.g. gains stored with an exported project).

    Parameters
    ----------
    model : Model
    trajectory : pm2dof.Trajectory
        The motion the gains are planned for, N samples; :func:`pm2dof.simulate` accepts it
        and its ``extended(settle_time)`` copies (the last sample's gain holds the end point).
    K : array_like (N, n, 2m)
        The gains, N*m per [xe, xed] ([m, m, m/s, m/s] for a point): tau = tau_ff,k - K_k
        [xe - xd, v - xd_dot].
    tau_ff : array_like (N, n)
        The feedforward torques, N*m (N for a linear actuator).
    theta0 : array_like (p,), optional
        The model the plan was made with (default Tables 1-2); never updated.
    sample_period, velocity_filter_hz, tau_max, on_singular, split, preload, preload_sign, settings
        As for :class:`pm2dof.NAController`. ``step`` counts samples from ``reset``: sample k
        uses K_k and tau_ff,k (after the plan, its last ones).

    Attributes
    ----------
    K : ndarray (N, n, 2m)
        The gains (read-only).
    tau_ff : ndarray (N, n)
        The feedforward torques (read-only).
    trajectory : pm2dof.Trajectory
        The planned motion.
    """
    _law = "lqr"

    def __init__(self, model, trajectory, K, tau_ff, *, theta0=None, sample_period=None,
                 velocity_filter_hz=None, tau_max=None, on_singular="raise", split=None,
                 preload=None, preload_sign=None, settings=None):
        require_model(model)
        require_trajectory(trajectory)
        settings = ControlSettings.resolve(
            model.spec, settings, who="LQRController", sample_period=sample_period,
            velocity_filter_hz=velocity_filter_hz, tau_max=tau_max, split=split, preload=preload,
            preload_sign=preload_sign)
        super().__init__(model, "lqr", {}, theta0, settings, on_singular)
        if abs(trajectory.period - self.sample_period) > 1e-12 * self.sample_period:
            raise ArgumentError(f"trajectory period {trajectory.period} s differs from the "
                                f"controller's sample period {self.sample_period} s")
        N, n, m = len(trajectory.t), model.n_legs, model.dof
        K = _schedule("K", K, (N, n, 2 * m), "N*m per m and per m/s")
        tau_ff = _schedule("tau_ff", tau_ff, (N, n), "N*m or N")
        self.trajectory = trajectory
        self.K, self.tau_ff = K, tau_ff
        # the C's per-sample inputs: K_k row-major (n x 2m), tau_ff_k
        self._rows = np.ascontiguousarray(np.hstack([K.reshape(N, -1), tau_ff]))
        for a in (self.K, self.tau_ff, self._rows):
            a.setflags(write=False)
        self._k = 0

    def _row(self, k):
        r = self._rows[min(k, len(self._rows) - 1)]
        nk = 2 * self.model.dof * self.model.n_legs
        return r[:nk], r[nk:]

    def reset(self, qa0, theta_hat=None):
        """As :meth:`pm2dof.NAController.reset`; the next step is the plan's sample 0.

        Parameters
        ----------
        qa0 : array_like (n,)
            Measured active angles, rad, closing every loop.
        theta_hat : array_like (p,), optional
            Replaces ``theta0`` in the state (the LQR does not use it).
        """
        super().reset(qa0, theta_hat)
        self._k = 0

    def step(self, qa_meas, xd, xd_dot, xd_ddot, out=None):
        """As :meth:`pm2dof.NAController.step`, at the next sample of the plan (its K_k,
        tau_ff,k; the last ones after the plan's end)."""
        K_k, tau_ff_k = self._row(self._k)
        try:
            tau = self._run(qa_meas, xd, xd_dot, xd_ddot, K_k, tau_ff_k, out)
        except binding.Refused as exc:
            tau = self._refused(exc, (qa_meas, xd, xd_dot, xd_ddot), out, (K_k, tau_ff_k))
        self._k += 1
        return tau

    def closed_loop_inputs(self, trajectory):
        """[xd, xd_dot, xd_ddot, K_k, tau_ff,k] per sample (``lqr_cl_input``) along
        ``trajectory``.

        Parameters
        ----------
        trajectory : Trajectory
            The planned one, or it followed by rest at its end point (the last gain then
            holds the end). Another trajectory raises ArgumentError.
        """
        plan = self.trajectory
        N = len(plan.t)
        t = trajectory
        same = (len(t.t) >= N and all(np.array_equal(getattr(t, k)[:N], getattr(plan, k))
                                      for k in ("xd", "xd_dot", "xd_ddot")))
        rest = same and (np.all(t.xd[N:] == plan.xd[-1]) and not np.any(t.xd_dot[N:])
                         and not np.any(t.xd_ddot[N:]))
        if not rest:
            raise ArgumentError(
                f"this LQRController was planned for another trajectory ({N} samples from "
                f"{plan.xd[0].tolist()} to {plan.xd[-1].tolist()}); plan one for this "
                f"trajectory: LQRController(model, trajectory)")
        rows = self._rows[np.minimum(np.arange(len(t.t)), N - 1)]
        return np.ascontiguousarray(np.hstack([super().closed_loop_inputs(t), rows]))
