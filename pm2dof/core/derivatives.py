# Model methods of the generated derivatives: Jacobians, the sampled step, inverse dynamics,
# linearisation.
"""Derivatives of the dynamics, bound from the generated C (``derive/derivatives.py``).

:class:`DerivativeMethods` is a base of :class:`pm2dof.Model`; every method is one call into
the generated C, takes ``out=`` to write into arrays you own, and refuses bad input like the
model functions: :class:`~pm2dof.SingularityError` at a pose closer to a singularity of either
kind than its threshold (a pose out of reach: :class:`~pm2dof.WorkspaceError` naming the leg),
:class:`~pm2dof.ArgumentError` for a NaN or a wrong length, :class:`~pm2dof.NonFiniteError`
for a non-finite result from finite inputs.

Friction's sign(v) (eq. 2) is piecewise constant; its derivative is taken as 0. Every
Jacobian here is that of the smooth part of the dynamics: exact wherever no actuated joint's
velocity S xed is zero, and one-sided nowhere (a central difference across v = 0 sees the
jump 2 fc, the Jacobian does not).
"""
from typing import NamedTuple

import numpy as np

from .contract import DERIVATIVE_FUNCTIONS  # the generated functions bound here
from .errors import ArgumentError
from .fastmethod import fast_method

try:
    from . import _cbind
except ImportError:  # a source tree never built: importing pm2dof.core.model says what to do
    _cbind = None

__all__ = ["DerivativeMethods", "ForwardDynamicsJacobians", "SampledStepJacobians",
           "InverseDynamicsJacobians", "DERIVATIVE_FUNCTIONS", "continuous_AB"]



def continuous_AB(d_xe, d_xed, d_tau_a):
    """(A, B) of d/dt [xe, xed] = [xed, xedd]: A = [[0, I], [d_xe, d_xed]], B = [[0], [d_tau_a]].
    Works on one point ((m, m), (m, m), (m, n)) or a batch ((K, m, m), ...); m from d_xe."""
    d_xe, d_xed, d_tau_a = (np.asarray(a, dtype=float) for a in (d_xe, d_xed, d_tau_a))
    lead, m = d_xe.shape[:-2], d_xe.shape[-1]
    A = np.zeros(lead + (2 * m, 2 * m))
    A[..., :m, m:] = np.eye(m)
    A[..., m:, :m], A[..., m:, m:] = d_xe, d_xed
    B = np.zeros(lead + (2 * m, d_tau_a.shape[-1]))
    B[..., m:, :] = d_tau_a
    return A, B

class ForwardDynamicsJacobians(NamedTuple):
    """Jacobians of xedd (eqs. 10-12) at one state: d_xe (m, m) 1/s^2, d_xed (m, m) 1/s,
    d_tau_a (m, n) m/(s^2 N m), d_theta (m, p) in theta's units (m = ``Model.dof``)."""
    d_xe: np.ndarray
    d_xed: np.ndarray
    d_tau_a: np.ndarray
    d_theta: np.ndarray


class SampledStepJacobians(NamedTuple):
    """Jacobians of one sampled step x_next(x, tau_a): d_x (2m, 2m), d_tau_a (2m, n)."""
    d_x: np.ndarray
    d_tau_a: np.ndarray


class InverseDynamicsJacobians(NamedTuple):
    """Jacobians of the task force u (eqs. 10-12): d_xe (m, m) N/m, d_xed (m, m) N s/m."""
    d_xe: np.ndarray
    d_xed: np.ndarray


class DerivativeMethods:
    """The derivative methods of :class:`pm2dof.Model` (see the module docstring)."""

    __slots__ = ()

    def _outs(self, kind, shapes, out):
        """The output arrays: new ones, or ``out`` checked (a tuple of float64 C-contiguous
        arrays of ``shapes``, e.g. a previous result)."""
        if out is None:
            return kind(*[np.empty(s) for s in shapes])
        if not isinstance(out, tuple) or len(out) != len(shapes) or not all(
                type(a) is np.ndarray and a.shape == s and a.dtype == np.float64
                and a.flags.c_contiguous for a, s in zip(out, shapes)):
            raise ArgumentError(
                f"out must be a tuple of {len(shapes)} C-contiguous float64 arrays of shapes "
                f"{list(shapes)} ({', '.join(kind._fields)}), e.g. an earlier result, got "
                f"{[getattr(a, 'shape', type(a).__name__) for a in out] if isinstance(out, tuple) else type(out).__name__}")
        return out if type(out) is kind else kind(*out)

    def _eval_jacobians(self, short, kind, shapes, out, args):
        """The checked path of a derivative method (its fast path, ``self._fast[short]``,
        refused the call): ``<name>_<short>`` with its first output (the value) skipped, the
        Jacobians written into ``out`` (:meth:`_outs`), its last output the singularity
        measures; converts the arguments if need be and raises the typed error
        (:meth:`Model._checked_call`)."""
        res = self._outs(kind, shapes, out)
        self._checked_call(short, self._f[short], args, (None, *res, self._sing), self._sing)
        return res

    @fast_method
    def forward_dynamics_jacobians(self, xe, xed, tau_a, theta, out=None):
        """Jacobians of the task-space acceleration xedd (eqs. 10-12, eq. 2 friction).

        xedd = Me^-1 (S^T tau_a - Ce xed - S^T f_a) at the pose ``xe`` (m,) m, velocity ``xed``
        (m,) m/s (rad, rad/s for phi), torques ``tau_a`` (n,) N*m and parameters ``theta`` (p,) (as
        :meth:`forward_dynamics`), in the generated C: Me^-1 times the Jacobian of
        S^T tau_a - Ce xed - S^T f_a - Me a at a = xedd held, by CasADi's reverse-mode AD. Friction's sign(v) contributes 0 (the Jacobian of the smooth part).

        Parameters
        ----------
        xe : array_like (m,)
            The pose, m.
        xed : array_like (m,)
            The velocity, m/s.
        tau_a : array_like (n,)
            The actuator torques, N*m.
        theta : array_like (p,)
            The dynamic parameters (:attr:`param_names` order).
        out : tuple of 4 ndarrays, optional
            Arrays of shapes (m, m), (m, m), (m, n), (m, p) to write into (e.g. an earlier
            result): no allocation.

        Returns
        -------
        ForwardDynamicsJacobians
            ``d_xe`` (m, m) 1/s^2, ``d_xed`` (m, m) 1/s, ``d_tau_a`` (m, n) = Me^-1 S^T,
            ``d_theta`` (m, p) (columns in :attr:`param_names` order).

        Examples
        --------
        >>> import numpy as np, pm2dof
        >>> m = pm2dof.load_model()
        >>> J = m.forward_dynamics_jacobians([0.245, 0.265], [0.1, -0.2], np.zeros(3),
        ...                                  m.theta_nominal)
        >>> q = m.ik([0.245, 0.265])
        >>> bool(np.allclose(J.d_tau_a, np.linalg.solve(m.Me(q, m.theta_nominal), m.S(q).T)))
        True
        """
        try:
            return self._fast["forward_dynamics_jacobians"](xe, xed, tau_a, theta, out)
        except _cbind.Refused:
            n, p, m = self.n_legs, len(self.param_names), self._m
            return self._eval_jacobians("forward_dynamics_jacobians", ForwardDynamicsJacobians,
                                        ((m, m), (m, m), (m, n), (m, p)), out,
                                        (xe, xed, tau_a, theta))

    @fast_method
    def sampled_step(self, x, tau_a, theta, period=None, out=None):
        """One sample of the model's dynamics with ``theta`` under a zero-order hold.

        ``rk4_substeps`` (model file) classical RK4 steps of period / rk4_substeps of
        d/dt [xe, xed] = [xed, xedd(xe, xed, tau_a, theta)] (eqs. 10-12), ``tau_a`` (n,) N*m
        held constant; ``x`` = [xe, xed] (2m,) m, m/s; ``period`` s (default ``[sensing]
        sample_period``). The model's own dynamics (eq. 2 friction), not the plant's truth
        (``pm2dof.plant_truth``). Raises SingularityError when x's pose is singular; a
        stage that leaves the workspace gives NonFiniteError.

        Parameters
        ----------
        x : array_like (2m,)
            The state [xe, xed], m, m/s.
        tau_a : array_like (n,)
            The held actuator torques, N*m.
        theta : array_like (p,)
            The dynamic parameters (:attr:`param_names` order).
        period : float, optional
            The sample period, s (default ``[sensing] sample_period``).
        out : ndarray (2m,), optional
            Written into and returned (no allocation).

        Returns
        -------
        x_next : ndarray (2m,)
        """
        T = self.checked_period(period)
        try:
            return self._fast["sampled_step"](x, tau_a, theta, T, out)
        except _cbind.Refused:
            return self._eval("sampled_step", (2 * self._m,), out, x, tau_a, theta, T)

    @fast_method
    def sampled_step_jacobians(self, x, tau_a, theta, period=None, out=None):
        """Jacobians of :meth:`sampled_step` w.r.t. the state x = [xe, xed] and the held
        torque, by forward-mode AD of the RK4 stages (each stage's Jacobian from
        :meth:`forward_dynamics_jacobians`' generated code).

        Parameters
        ----------
        x, tau_a, theta, period :
            As :meth:`sampled_step`.
        out : tuple of 2 ndarrays, optional
            Arrays of shapes (2m, 2m), (2m, n) to write into (no allocation).

        Returns
        -------
        SampledStepJacobians
            ``d_x`` (2m, 2m), ``d_tau_a`` (2m, n) (the discrete-time A and B at x, tau_a).
        """
        T, k = self.checked_period(period), 2 * self._m
        try:
            return self._fast["sampled_step_jacobians"](x, tau_a, theta, T, out)
        except _cbind.Refused:
            return self._eval_jacobians("sampled_step_jacobians", SampledStepJacobians,
                                        ((k, k), (k, self.n_legs)), out, (x, tau_a, theta, T))

    @fast_method
    def inverse_dynamics(self, xe, xed, xedd, theta, out=None):
        """The task force u = Me xedd + Ce xed + S^T f_a (m,), N (N m for phi) (eqs. 10-12,
        eq. 2 friction) that gives the acceleration ``xedd`` (m,) m/s^2 at the pose ``xe`` and
        velocity ``xed``. Actuator torques: any tau_a with S^T tau_a = u
        (:meth:`torque_splits`).

        Parameters
        ----------
        xe, xed, theta :
            The state and the parameters, as :meth:`forward_dynamics_jacobians`.
        xedd : array_like (m,)
            The acceleration, m/s^2.
        out : ndarray (m,), optional
            Written into and returned (no allocation).
        """
        try:
            return self._fast["inverse_dynamics"](xe, xed, xedd, theta, out)
        except _cbind.Refused:
            return self._eval("inverse_dynamics", (self._m,), out, xe, xed, xedd, theta)

    @fast_method
    def inverse_dynamics_jacobians(self, xe, xed, xedd, theta, out=None):
        """Jacobians of :meth:`inverse_dynamics` w.r.t. the state (reverse-mode AD; friction's
        sign contributes 0). d u / d xedd is Me.

        Parameters
        ----------
        xe, xed, xedd, theta :
            As :meth:`inverse_dynamics`.
        out : tuple of 2 ndarrays, optional
            Arrays of shapes (m, m), (m, m) to write into (no allocation).

        Returns
        -------
        InverseDynamicsJacobians
            ``d_xe`` (m, m) N/m, ``d_xed`` (m, m) N s/m.
        """
        try:
            return self._fast["inverse_dynamics_jacobians"](xe, xed, xedd, theta, out)
        except _cbind.Refused:
            m = self._m
            return self._eval_jacobians("inverse_dynamics_jacobians", InverseDynamicsJacobians,
                                        ((m, m), (m, m)), out, (xe, xed, xedd, theta))

    def linearize(self, xe, xed, tau_a, theta=None, discrete=False, period=None):
        """The linearisation (A, B) of the dynamics at the state [xe, xed] and torque tau_a.

        Continuous (``discrete=False``): d/dt dx = A dx + B dtau with
        A = [[0, I], [d xedd/d xe, d xedd/d xed]] (2m, 2m), B = [[0], [d xedd/d tau_a]] (2m, n)
        (:meth:`forward_dynamics_jacobians`). Discrete (``discrete=True``): dx_{k+1} = A dx_k
        + B dtau_k for one sample of ``period`` s (default ``[sensing] sample_period``) under
        the zero-order hold (:meth:`sampled_step_jacobians`). State order [xe, xed] in
        :attr:`task_names` order ([x, y, xd, yd], m, m/s, for a point), input order
        tau_1..tau_n (N*m).

        Parameters
        ----------
        xe, xed, tau_a :
            The state and the torques, as :meth:`forward_dynamics_jacobians`.
        theta : array_like (p,), optional
            The dynamic parameters (default :attr:`theta_nominal`).
        discrete : bool
            The sampled (zero-order hold) linearisation instead of the continuous one.
        period : float, optional
            The sample period of the discrete one, s (default ``[sensing] sample_period``).

        Returns
        -------
        A : ndarray (2m, 2m)
        B : ndarray (2m, n)

        Examples
        --------
        >>> import numpy as np, pm2dof
        >>> m = pm2dof.load_model()
        >>> A, B = m.linearize([0.245, 0.265], [0.0, 0.0], np.zeros(3))
        >>> A.shape, B.shape
        ((4, 4), (4, 3))
        """
        theta = self.theta_nominal if theta is None else theta
        if discrete:
            x = np.concatenate([np.ravel(np.asarray(xe, dtype=float)),
                                np.ravel(np.asarray(xed, dtype=float))])
            if x.shape != (2 * self._m,):
                raise ArgumentError(f"linearize: xe and xed must have m = {self._m} entries each "
                                    f"({', '.join(self.task_names)}), got {np.shape(xe)} and "
                                    f"{np.shape(xed)}")
            J = self.sampled_step_jacobians(x, tau_a, theta, period)
            return J.d_x, J.d_tau_a
        J = self.forward_dynamics_jacobians(xe, xed, tau_a, theta)
        return continuous_AB(J.d_xe, J.d_xed, J.d_tau_a)
