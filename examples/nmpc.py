# Example: nonlinear MPC on the generated dynamics and its Jacobians, run in pm2dof.simulate.
"""Nonlinear model-predictive control of the paper's robot.

The prediction model is the model's own sampled step (``<name>_sampled_step``: the model
file's RK4 sub-steps under the zero-order hold, Tables 1-2), loaded from the compiled library
with ``casadi.external``; its derivatives are the generated ``sampled_step_jacobians`` (CasADi
AD in C), given to CasADi as the step's custom Jacobian, so IPOPT never differentiates by
finite differences. Multiple shooting over N samples:

    min  sum_k |xe_k - xd_k|^2_Qp + |v_k - vd_k|^2_Qv + |tau_k - tau_ff,k|^2_R
         + |x_N - x_d,N|^2_P                 (P: the time-varying LQR's cost-to-go there)
    s.t. x_0 = [fk(qa), backward-difference velocity],  x_{k+1} = F(x_k, tau_k),
         |tau_k| <= tau_max,

with the feedforward tau_ff from the inverse dynamics (``pm2dof.linearize_trajectory``),
IPOPT (from the casadi wheel, limited-memory Hessian: F has no second derivatives here),
warm-started from the previous solution shifted by one sample. It runs in
``pm2dof.simulate`` as a Python-level controller (one Python step per 2 ms sample against the
generated plant).

    python examples/nmpc.py [--move high] [--horizon 10]

prints the RMSE beside NA's and LQR's on the same move and the solve time per sample against
the 2 ms budget.
"""
import argparse
import time

import casadi as ca
import numpy as np

import pm2dof
from pm2dof.control.python_loop import PythonController
import pm2dof.linear
from pm2dof.core.status import Status


def prediction_model(model, theta, period):
    """F(x (4), tau (n)) -> x_next as a CasADi Function on the generated C, with the
    generated Jacobians as its custom Jacobian."""
    n, lib = model.n_legs, model.library
    step = ca.external(f"{model.name}_sampled_step", lib)
    jac = ca.external(f"{model.name}_sampled_step_jacobians", lib)
    x, tau = ca.MX.sym("x", 4), ca.MX.sym("tau", n)
    out = ca.MX.sym("out_x_next", 4)
    _, d_x, d_tau, _ = jac(x, tau, theta, period)
    J = ca.Function(f"jac_{model.name}_F", [x, tau, out],
                    [ca.reshape(d_x, 4, 4).T, ca.reshape(d_tau, n, 4).T],
                    ["x", "tau", "out_x_next"], ["jac_x_next_x", "jac_x_next_tau"])
    return ca.Function(f"{model.name}_F", [x, tau], [step(x, tau, theta, period)[0]],
                       ["x", "tau"], ["x_next"],
                       {"custom_jacobian": J, "jac_penalty": 0, "never_inline": True})


class NMPCController(PythonController):
    """Nonlinear MPC (module docstring). ``solve_times`` holds the wall time of each solve, s.

    Parameters
    ----------
    model : Model
    trajectory : pm2dof.Trajectory
        The motion to follow (its feedforward is planned once).
    horizon : int
        Prediction samples N.
    Qp, Qv, R : float
        Weights on position error (1/m^2), velocity error (s^2/m^2), torque deviation
        (1/(N m)^2): the LQR's defaults (Bryson's rule).
    """

    _law = "nmpc"

    def __init__(self, model, trajectory, horizon=10, Qp=1e8, Qv=1e4, R=0.25):
        super().__init__(model)
        n, N, T = model.n_legs, horizon, self.sample_period
        self.N, self.n = N, n
        self.lin = pm2dof.linearize_trajectory(model, trajectory)
        _, self.P_lqr = pm2dof.linear.lqr_gains(self.lin.A, self.lin.B, np.diag([Qp, Qp, Qv, Qv]),
                                                R * np.eye(n))
        F = prediction_model(model, self.theta0, T)
        X, U = ca.MX.sym("X", 4, N + 1), ca.MX.sym("U", n, N)
        # parameters: x0, reference states, feedforward, terminal cost (4 x 4)
        P = ca.MX.sym("P", 4 + 4 * N + n * N + 16)
        ref = ca.reshape(P[4:4 + 4 * N], 4, N)
        uff = ca.reshape(P[4 + 4 * N:4 + 4 * N + n * N], n, N)
        PN = ca.reshape(P[4 + 4 * N + n * N:], 4, 4)
        J, g = 0, [X[:, 0] - P[0:4]]
        for k in range(N):
            g.append(X[:, k + 1] - F(X[:, k], U[:, k]))
            e = X[:, k + 1] - ref[:, k]
            J += Qp * ca.sumsqr(e[0:2]) + Qv * ca.sumsqr(e[2:4]) + R * ca.sumsqr(U[:, k] - uff[:, k])
        eN = X[:, N] - ref[:, N - 1]
        J += ca.bilin(PN, eN, eN)
        J = J * (1e10 / Qp)   # scaled: 1 = a position error of 10 um (IPOPT's tolerances)
        w = ca.vertcat(ca.vec(X), ca.vec(U))
        opts = {"ipopt.print_level": 0, "print_time": False, "ipopt.sb": "yes",
                "ipopt.hessian_approximation": "limited-memory", "ipopt.tol": 1e-6,
                "ipopt.acceptable_tol": 1e-4, "ipopt.max_iter": 50, "ipopt.mu_init": 1e-3,
                "ipopt.warm_start_init_point": "yes"}
        self.solver = ca.nlpsol("nmpc", "ipopt", {"x": w, "f": J, "g": ca.vertcat(*g), "p": P},
                                opts)
        tmax = np.asarray(model.spec.limits["tau_max"], dtype=float)
        self.lbw = np.concatenate([np.full(4 * (N + 1), -np.inf), np.tile(-tmax, N)])
        self.ubw = -self.lbw.copy()
        self.ubw[:4 * (N + 1)] = np.inf
        self.ng = 4 * (N + 1)
        self.solve_times = []
        self.unconverged = 0

    def reset(self, qa0, trajectory):
        self.xe_prev = self.model.fk(qa0)
        self.w0 = None
        self.lam_g = None
        self.solve_times = []
        self.unconverged = 0

    def _plan(self, k):
        """Reference states and feedforward of samples k+1 .. k+N (the last held)."""
        K = len(self.lin.x)
        idx = np.minimum(np.arange(k + 1, k + 1 + self.N), K - 1)
        ff = np.minimum(np.arange(k, k + self.N), K - 1)
        return self.lin.x[idx].T.ravel(order="F"), self.lin.tau_a[ff].T.ravel(order="F")

    def step(self, k, qa, xd, xd_dot, xd_ddot):
        xe = self.model.fk(qa)                                  # Fig. 2: fk, backward difference
        v = (xe - self.xe_prev) / self.sample_period if k > 0 else np.zeros(2)
        self.xe_prev = xe
        x0 = np.concatenate([xe, v])
        ref, uff = self._plan(k)
        PN = self.P_lqr[min(k + self.N, len(self.P_lqr) - 1)]
        p = np.concatenate([x0, ref, uff, PN.ravel()])
        if self.w0 is None:   # cold start: the reference and its feedforward
            X0 = np.concatenate([x0, ref])
            self.w0 = np.concatenate([X0, uff])
        args = {"x0": self.w0, "p": p, "lbx": self.lbw, "ubx": self.ubw, "lbg": 0, "ubg": 0}
        if self.lam_g is not None:
            args["lam_g0"] = self.lam_g
        t0 = time.perf_counter()
        sol = self.solver(**args)
        self.solve_times.append(time.perf_counter() - t0)
        w = np.asarray(sol["x"]).ravel()
        # IPOPT's last iterate is applied either way (finite, within tau_max by its bounds)
        self.unconverged += not self.solver.stats()["success"]
        self.status = Status.OK
        nX = 4 * (self.N + 1)
        X, U = w[:nX].reshape(self.N + 1, 4), w[nX:].reshape(self.N, self.n)
        # warm start: shift by one sample
        self.w0 = np.concatenate([np.vstack([X[1:], X[-1:]]).ravel(),
                                  np.vstack([U[1:], U[-1:]]).ravel()])
        self.lam_g = np.asarray(sol["lam_g"]).ravel()
        return U[0].copy()


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--move", default="high")
    ap.add_argument("--horizon", type=int, default=10)
    args = ap.parse_args(argv)
    m = pm2dof.load_model()
    traj = pm2dof.model_move(m, args.move)
    mpc = NMPCController(m, traj, horizon=args.horizon)
    r = pm2dof.simulate(m, mpc, traj)
    ts = np.array(mpc.solve_times) * 1e3
    budget = 1e3 * mpc.sample_period
    lqr = pm2dof.simulate(m, pm2dof.LQRController(m, traj), traj)
    na = pm2dof.simulate(m, pm2dof.NAController(m), traj)
    print(f"{args.move}-speed move, {len(ts)} samples, horizon {args.horizon} "
          f"({args.horizon * budget:.0f} ms)")
    print(f"RMSE: NMPC {r.rmse:.3e} m, LQR {lqr.rmse:.3e} m, NA {na.rmse:.3e} m; IPOPT did "
          f"not converge in {mpc.unconverged} of {len(ts)} samples (its last iterate applied)")
    print(f"solve time per sample: median {np.median(ts):.2f} ms, p95 "
          f"{np.percentile(ts, 95):.2f} ms, max {ts.max():.2f} ms; budget {budget:.1f} ms: "
          f"{np.mean(ts <= budget) * 100:.0f} % of the samples within it")
    return r, ts


if __name__ == "__main__":
    main()
