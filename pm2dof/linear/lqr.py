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
inverse dynamics' torque) enter the C as per-sample inputs; nothing is solved per step. The
run-time controller is :class:`pm2dof.control.lqr.LQRController` (no SciPy); this module's
:class:`LQRController` plans its gains and builds it.
"""
import numpy as np

from ..control import lqr as control_lqr
from ..control.controllers import diagonal_gain
from ..control.settings import ControlSettings
from ..control.trajectory import require_trajectory
from ..core.errors import ArgumentError
from ..core.model import require_model
from .trajectory import linearize_trajectory

__all__ = ["lqr_gains", "lqr_weights", "LQRController", "LQR_DEFAULT_WEIGHTS"]

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


class LQRController(control_lqr.LQRController):
    """Time-varying LQR tracking along ``trajectory`` (module docstring), one C call per sample.

    Plans the gains (:func:`linearize_trajectory`, :func:`lqr_gains`) and builds the run-time
    controller :class:`pm2dof.control.lqr.LQRController` with them: its step, ``reset``,
    ``closed_loop_inputs``, and what :func:`pm2dof.simulate` runs.

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
    sample_period, velocity_filter_hz, tau_max, on_singular, split, preload, preload_sign, settings
        As for :class:`pm2dof.NAController`. ``step`` counts samples from ``reset``: sample k
        uses K_k and tau_ff,k (after the plan, its last ones).

    Attributes
    ----------
    K : ndarray (N, n, 2m)
        The gains, N*m per [xe, xed] ([m, m, m/s, m/s] for a point).
    tau_ff : ndarray (N, n)
        The feedforward torques, N*m.
    weights : dict
        ``Q`` (2m, 2m) and ``R`` (n, n), the weights planned with.
    linearization : LinearTrajectory
    """

    def __init__(self, model, trajectory, *, Q_position=None, Q_velocity=None, R=None,
                 theta0=None, sample_period=None, velocity_filter_hz=None, tau_max=None,
                 on_singular="raise", split=None, preload=None, preload_sign=None,
                 settings=None):
        require_model(model)
        require_trajectory(trajectory)
        settings = ControlSettings.resolve(
            model.spec, settings, who="LQRController", sample_period=sample_period,
            velocity_filter_hz=velocity_filter_hz, tau_max=tau_max, split=split, preload=preload,
            preload_sign=preload_sign)
        theta0 = model.checked_theta(theta0, "theta0")
        T = settings.sample_period
        if abs(trajectory.period - T) > 1e-12 * T:
            raise ArgumentError(f"trajectory period {trajectory.period} s differs from the "
                                f"controller's sample period {T} s")
        weights = lqr_weights(model, Q_position, Q_velocity, R)
        lin = linearize_trajectory(model, trajectory, theta0, discrete=True, split=settings.split,
                                   period=T)
        K, _ = lqr_gains(lin.A, lin.B, weights["Q"], weights["R"])
        super().__init__(model, trajectory, K, lin.tau_a, theta0=theta0, settings=settings,
                         on_singular=on_singular)
        self.weights, self.linearization = weights, lin


def lqr_weights(model, Q_position=None, Q_velocity=None, R=None):
    """The LQR's weights, checked: ``Q`` (2m, 2m) = diag(Q_position, Q_velocity) and ``R``
    (n, n), each argument given or the model file's ``[gains.lqr]`` (else
    :data:`LQR_DEFAULT_WEIGHTS`); an entry <= 0 raises :class:`pm2dof.GainError`.

    Parameters
    ----------
    model : Model
    Q_position, Q_velocity : float or array_like (m,), optional
        Diagonal weights on the position error (1/m^2) and the velocity error (s^2/m^2).
    R : float or array_like (n,), optional
        Diagonal torque weight, 1/(N m)^2.

    Returns
    -------
    dict
        ``Q`` and ``R``.
    """
    g = model.spec.gains.get("lqr") or _default_weights(model)
    name, n = "LQRController", model.n_legs
    qp = diagonal_gain(name, "Q_position", g["Q_position"] if Q_position is None
                       else Q_position, model.task_names)
    qv = diagonal_gain(name, "Q_velocity", g["Q_velocity"] if Q_velocity is None
                       else Q_velocity, tuple(f"{c}d" for c in model.task_names))
    r = diagonal_gain(name, "R", g["R"] if R is None else R,
                      tuple(f"tau{i + 1}" for i in range(n)))
    return {"Q": np.diag(np.concatenate([qp, qv])), "R": np.diag(r)}
