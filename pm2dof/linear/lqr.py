# Time-varying LQR tracking along a trajectory: gains at planning time, a generated C step.
"""Time-varying LQR tracking of a desired motion.

Planning (once, in Python): the discrete linearisation (A_k, B_k) along the trajectory
(:func:`pm2dof.linearize_trajectory`, the model's theta, the model's split), the terminal cost
P_N from SciPy's discrete algebraic Riccati solver at the last sample (the robot at rest at the
end point), then the backward Riccati recursion

    K_k = (R + B_k^T P_{k+1} B_k)^-1 B_k^T P_{k+1} A_k,
    P_k = Q + A_k^T P_{k+1} (A_k - B_k K_k),

which minimises sum_k dx_k^T Q dx_k + dtau_k^T R dtau_k for the linearised error dynamics.
Run time (per sample, in the generated C ``<name>_lqr<split>_step``): the Fig. 2 signal
processing, tau = tau_ff,k - K_k [xe - xd, v - xd_dot], its task force S^T tau at the measured
pose shared by the model's split, clipping, the statuses of NA and APD. K_k and tau_ff,k (the
inverse dynamics' torque) enter the C as per-sample inputs; nothing is solved per step.
"""
import numpy as np

from ..control.controllers import _Controller, diagonal_gain
from ..control.trajectory import require_trajectory
from ..core import _cbind
from ..core.errors import ArgumentError
from .trajectory import linearize_trajectory

__all__ = ["lqr_gains", "LQRController", "LQR_DEFAULT_WEIGHTS"]

#: LQRController's weights when the model file has no [gains.lqr] (Bryson's rule: one over
#: the square of what is acceptable): 0.1 mm of position error, 10 mm/s of velocity error,
#: 2 N m of torque correction per actuator
LQR_DEFAULT_WEIGHTS = {"Q_position": [1e8, 1e8], "Q_velocity": [1e4, 1e4], "R": 0.25}
#: a platform's orientation phi, by the same rule: 1 mrad of error, 0.1 rad/s of rate error
LQR_DEFAULT_PHI_WEIGHTS = {"Q_position": 1e6, "Q_velocity": 1e2}


def _default_weights(model):
    """LQR_DEFAULT_WEIGHTS in the model's task coordinates (phi's appended for a platform)."""
    extra = [c for c in model.task_names if c not in ("x", "y")]
    return {k: (list(v) + [LQR_DEFAULT_PHI_WEIGHTS[k]] * len(extra)
                if k in LQR_DEFAULT_PHI_WEIGHTS else v) for k, v in LQR_DEFAULT_WEIGHTS.items()}


def lqr_gains(A, B, Q, R):
    """Time-varying LQR gains of x_{k+1} = A_k x_k + B_k u_k, k = 0..K-1.

    Parameters
    ----------
    A : array_like (K, nx, nx)
    B : array_like (K, nx, nu)
    Q : array_like (nx, nx)
        State weight, positive definite.
    R : array_like (nu, nu)
        Input weight, positive definite.

    Returns
    -------
    K : ndarray (K, nu, nx)
        u_k = -K_k x_k. The terminal cost is the stationary one of the last sample
        (SciPy's ``solve_discrete_are`` on (A_{K-1}, B_{K-1})), so K_{K-1} is that sample's
        infinite-horizon gain: the loop can stay at the end point with it.
    P : ndarray (K + 1, nx, nx)
        The cost-to-go matrices, P[K] the terminal one.
    """
    from scipy.linalg import solve_discrete_are
    A, B = np.asarray(A, dtype=float), np.asarray(B, dtype=float)
    Q, R = np.asarray(Q, dtype=float), np.asarray(R, dtype=float)
    N = len(A)
    P = np.empty((N + 1,) + Q.shape)
    # an overflow is reported below as a typed error, not as NumPy's warnings on the way
    try:
        with np.errstate(all="ignore"):
            P[N] = solve_discrete_are(A[-1], B[-1], Q, R)
            K = np.empty((N, B.shape[2], A.shape[1]))
            for k in range(N - 1, -1, -1):
                BtP = B[k].T @ P[k + 1]
                K[k] = np.linalg.solve(R + BtP @ B[k], BtP @ A[k])
                P[k] = Q + A[k].T @ P[k + 1] @ (A[k] - B[k] @ K[k])
                P[k] = (P[k] + P[k].T) / 2          # keep it symmetric against rounding
    except (np.linalg.LinAlgError, ValueError) as exc:   # SciPy's LinAlgError is NumPy's
        raise ArgumentError(f"lqr_gains: no stabilising solution for these weights ({exc}); "
                            f"Q and R must be positive definite and of moderate scale") from None
    if not (np.isfinite(K).all() and np.isfinite(P).all()):
        raise ArgumentError("lqr_gains: the Riccati recursion overflowed for these weights "
                            "(Q or R too large or too small)")
    return K, P


class LQRController(_Controller):
    """Time-varying LQR tracking along ``trajectory`` (module docstring), one C call per sample.

    Parameters
    ----------
    model : Model
    trajectory : pm2dof.Trajectory
        The motion the gains are planned for; :func:`pm2dof.simulate` accepts it and its
        ``extended(settle_time)`` copies (the last sample's gain holds the end point).
    Q_position, Q_velocity : float or array_like (m,), optional
        Diagonal state weights on the position error (1/m^2) and the velocity error
        (s^2/m^2), each > 0 (default ``[gains.lqr]`` of the model file, else
        :data:`LQR_DEFAULT_WEIGHTS`).
    R : float or array_like (n,), optional
        Diagonal torque weight, 1/(N m)^2, each > 0. Weights outside these conditions raise
        :class:`pm2dof.GainError`.
    theta0 : array_like (5n,), optional
        The model linearised and inverted (default Tables 1-2).
    sample_period, velocity_filter_hz, tau_max, on_singular, split, preload, preload_sign
        As for :class:`pm2dof.NAController`. ``step`` counts samples from ``reset``: sample k
        uses K_k and tau_ff,k (after the plan, its last ones).

    Attributes
    ----------
    K : ndarray (N, n, 2m)
        The gains, N*m per [xe, xed] ([m, m, m/s, m/s] for a point).
    tau_ff : ndarray (N, n)
        The feedforward torques, N*m.
    linearization : LinearTrajectory
    """
    _law = "lqr"

    def __init__(self, model, trajectory, *, Q_position=None, Q_velocity=None, R=None,
                 theta0=None, sample_period=None, velocity_filter_hz=None, tau_max=None,
                 on_singular="raise", split=None, preload=None, preload_sign=None):
        require_trajectory(trajectory)
        super().__init__(model, "lqr", {}, theta0, sample_period, velocity_filter_hz, tau_max,
                         on_singular, split, preload, preload_sign)
        if abs(trajectory.period - self.sample_period) > 1e-12 * self.sample_period:
            raise ArgumentError(f"trajectory period {trajectory.period} s differs from the "
                                f"controller's sample period {self.sample_period} s")
        g = model.spec.gains.get("lqr") or _default_weights(model)
        name, n = type(self).__name__, model.n_legs
        qp = diagonal_gain(name, "Q_position", g["Q_position"] if Q_position is None
                           else Q_position, model.task_names)
        qv = diagonal_gain(name, "Q_velocity", g["Q_velocity"] if Q_velocity is None
                           else Q_velocity, tuple(f"{c}d" for c in model.task_names))
        r = diagonal_gain(name, "R", g["R"] if R is None else R,
                          tuple(f"tau{i + 1}" for i in range(n)))
        self.weights = {"Q": np.diag(np.concatenate([qp, qv])), "R": np.diag(r)}
        self.trajectory = trajectory
        self.linearization = lin = linearize_trajectory(model, trajectory, self.theta0,
                                                        discrete=True, split=self.split,
                                                        period=self.sample_period)
        K, _ = lqr_gains(lin.A, lin.B, self.weights["Q"], self.weights["R"])
        self.K, self.tau_ff = K, lin.tau_a
        # the C's per-sample inputs: K_k row-major (n x 2m), tau_ff_k
        self._rows = np.ascontiguousarray(np.hstack([K.reshape(len(K), -1), lin.tau_a]))
        for a in (self.K, self._rows):
            a.setflags(write=False)
        self._k = 0

    def _row(self, k):
        r = self._rows[min(k, len(self._rows) - 1)]
        nk = 2 * self.model.dof * self.model.n_legs
        return r[:nk], r[nk:]

    def reset(self, qa0, theta_hat=None):
        super().reset(qa0, theta_hat)
        self._k = 0

    def step(self, qa_meas, xd, xd_dot, xd_ddot, out=None):
        """As :meth:`pm2dof.NAController.step`, at the next sample of the plan (its K_k,
        tau_ff,k; the last ones after the plan's end)."""
        self._extra = K_k, tau_ff_k = self._row(self._k)
        try:
            tau = self._run(qa_meas, xd, xd_dot, xd_ddot, K_k, tau_ff_k, out)
        except _cbind.Refused as exc:
            tau = self._refused(exc, (qa_meas, xd, xd_dot, xd_ddot), out)
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
