# Generated derivatives (CasADi AD): forward-dynamics Jacobians, the sampled step and its
# Jacobians, the inverse dynamics (eqs. 10-12) and its Jacobians.
"""Derivatives of the model's dynamics by CasADi's algorithmic differentiation.

Every function here differentiates expressions the derivation already builds (the factored
Me, Ce xed and S of :func:`pm2dof.derive.factored.task_inertia_coriolis`, the friction f_a of
eq. 2 from :class:`pm2dof.derive.dynamics.Dynamics`); nothing is differentiated by hand.
Matrices are flattened ROW-MAJOR, as every other output of the generated code.

Friction's sign(v) is piecewise constant: its derivative is taken as 0 (CasADi's sign has
none), so each Jacobian is that of the smooth part of the dynamics, exact wherever no actuated
joint's velocity is zero. ``sing`` is [type I, type II] at the pose (the model functions' rule).

Functions (``<prefix>_`` + name):

Sizes below for the task dimension m (2: a point, 3: a platform):

* ``forward_dynamics_jacobians(xe, xed, tau_a, theta) -> (xedd, d_xe, d_xed, d_tau_a,
  d_theta, sing)``: xedd (m,) of eqs. 10-12 and d xedd / d xe (m, m), / d xed (m, m),
  / d tau_a (m, n), / d theta (m, p): Me^-1 times the Jacobian of S^T tau_a - Ce xed -
  S^T f_a (- Ge) - Me a at a = xedd held fixed, by reverse-mode AD (m sweeps, one per row);
* ``sampled_step(x, tau_a, theta, T) -> (x_next, sing)``: x = [xe, xed] (2m,) after one sample
  period T of the model's dynamics with theta, ``rk4_substeps`` classical RK4 steps under the
  torque tau_a held constant (zero-order hold); sing at x;
* ``sampled_step_jacobians(x, tau_a, theta, T) -> (x_next, d_x, d_tau_a, sing)``: the same
  step and its Jacobians d x_next / d x (2m, 2m) and / d tau_a (2m, n): forward-mode AD of the RK4
  stages (the variational equations), each stage one call of ``forward_dynamics_jacobians``;
* ``inverse_dynamics(xe, xed, xedd, theta) -> (u, sing)``: the task force u = Me xedd +
  Ce xed + S^T f_a (+ Ge with gravity) (eqs. 10-12), N, whose actuator torques are any tau_a
  with S^T tau_a = u;
* ``inverse_dynamics_jacobians(xe, xed, xedd, theta) -> (u, d_xe, d_xed, sing)``: u and
  d u / d xe (m, m), / d xed (m, m) (d u / d xedd is Me).
"""
import casadi as ca

from .factored import inverse_small, solve_small, task_gravity, task_inertia_coriolis

__all__ = ["derivative_functions", "DERIVATIVE_FUNCTIONS"]

#: the generated functions of this module, without the model prefix
DERIVATIVE_FUNCTIONS = ("forward_dynamics_jacobians", "sampled_step", "sampled_step_jacobians",
                        "inverse_dynamics", "inverse_dynamics_jacobians")


def _row_major(J):
    """A matrix as its entries row by row (the layout of every generated output)."""
    return ca.vec(J.T)


def _rows(v, nrow, ncol):
    """The matrix (nrow, ncol) of a row-major flat vector."""
    return ca.reshape(v, ncol, nrow).T


class _TrigForm:
    """The task-space dynamics (eqs. 2, 10-12) as functions of the joint angles' (cos, sin),
    taken as free symbols c, s (one each per angle), of the prismatic coordinates r (as
    values), and of xed, theta.

    AD then differentiates w.r.t. c, s and r, and the pose enters by the chain rule through
    q(xe): d c_k / d xe = -s_k W[k, :], d s_k / d xe = c_k W[k, :], d r_k / d xe = W[k, :],
    since d q / d xe = W (eq. 7). This skips differentiating the inverse kinematics' geometry
    (square roots, divisions), about 15 % cheaper than AD through it. Where the matrices also
    name the pose itself (a platform's own inertia, in phi), it is a variable ``pose`` whose
    partial derivative adds to the chain rule's. :meth:`at_pose` binds c, s, r and the pose
    to their values at xe (unit vectors from geometry, as the model functions).
    """

    def __init__(self, d, xed, theta):
        sym = d.sym
        self.d = d
        N = len(sym.q)
        self.angles = [k for k in range(N) if d.angular[k]]
        self.lengths = [k for k in range(N) if not d.angular[k]]
        na = len(self.angles)
        self.c, self.s = ca.SX.sym("c", na), ca.SX.sym("s", na)
        self.r = ca.SX.sym("r", len(self.lengths))
        self.pose = ca.SX.sym("pose", d.m)
        values = {sym.q[k]: self.r[j] for j, k in enumerate(self.lengths)}
        values.update(zip(sym.xe, ca.vertsplit(self.pose)))
        conv = d.converter(values,
                           {sym.q[k]: (self.c[j], self.s[j]) for j, k in enumerate(self.angles)})
        self.Me, self.Ce_v, self.S, self.W = task_inertia_coriolis(d, conv, xed,
                                                                   [(sym.theta, theta)])
        f_a = conv.extended([(sym.qd, self.W @ xed), (sym.theta, theta)])(d.dyn.f_a)  # eq. 2
        self.StF = self.S.T @ f_a
        self.Ge = task_gravity(d, conv, [(sym.theta, theta)])          # None: no gravity

    def jacobian(self, y, others):
        """(d y / d xe, d y / d others) by reverse-mode AD, one sweep per entry of y."""
        cs = ca.vertcat(self.c, self.s)
        if self.lengths:
            cs = ca.vertcat(cs, self.r)
        direct = ca.depends_on(y, self.pose)          # the pose named outside q (a platform)
        if direct:
            cs = ca.vertcat(cs, self.pose)
        J = ca.jtimes(y, ca.vertcat(cs, others), ca.SX.eye(y.numel()), True).T
        k = self.c.numel()
        Wa = self.W if not self.lengths else self.W[self.angles, :]
        d_xe = (J[:, :k] @ (-ca.diag(self.s) @ Wa) + J[:, k:2 * k] @ (ca.diag(self.c) @ Wa))
        nr = len(self.lengths)
        if nr:
            d_xe = d_xe + J[:, 2 * k:2 * k + nr] @ self.W[self.lengths, :]
        if direct:
            d_xe = d_xe + J[:, 2 * k + nr:2 * k + nr + self.pose.numel()]
        return d_xe, J[:, cs.numel():]

    def at_pose(self, exprs, xe):
        """``exprs`` with c, s, r bound to their values at the pose xe, and the singularity
        measures there."""
        sym = self.d.sym
        conv = self.d.converter_xe(xe)
        c = ca.vertcat(*[conv.trig[sym.q[k]][0] for k in self.angles])
        s = ca.vertcat(*[conv.trig[sym.q[k]][1] for k in self.angles])
        old, new = [self.c, self.s], [c, s]
        if self.lengths:
            old.append(self.r)
            new.append(ca.vertcat(*[conv.symbols[sym.q[k]] for k in self.lengths]))
        if any(ca.depends_on(e, self.pose) for e in exprs):
            old.append(self.pose)
            new.append(xe)
        return ca.substitute(exprs, old, new), self.d.singularity_measures(conv)


def derivative_functions(d, prefix, substeps, finalize):
    """The functions of the module docstring, named ``<prefix>_<name>``, with named inputs and
    outputs (SX for the pointwise ones, MX for the sampled step, whose RK4 stages call the
    factored xedd and ``forward_dynamics_jacobians``).

    Parameters
    ----------
    d : pm2dof.derive.model_functions.Derivation
    prefix : str
        The model's name.
    substeps : int
        RK4 steps per sample (the model file's ``rk4_substeps``).
    finalize : callable(casadi.Function) -> casadi.Function
        Dense outputs and merged subexpressions (``derive.run``); applied to the SX functions
        before the MX steps call them, so each is generated once.
    """
    n, p, m = d.spec.n_legs, len(d.spec.param_names), d.m
    xe, xed, xedd_in = ca.SX.sym("xe", m), ca.SX.sym("xed", m), ca.SX.sym("xedd", m)
    tau, theta = ca.SX.sym("tau_a", n), ca.SX.sym("theta", p)
    tf = _TrigForm(d, xed, theta)
    out = []

    def add(name, ins, outs, export=True):
        """A named function of ``ins``; ``outs`` (name, expression in c, s) are bound to the
        pose xe and the singularity measures ``sing`` appended."""
        exprs, sing = tf.at_pose([v for _, v in outs], xe)
        f = finalize(d.function(f"{prefix}_{name}", [v for _, v in ins], exprs + [sing],
                                [k for k, _ in ins], [k for k, _ in outs] + ["sing"]))
        if export:
            out.append(f)
        return f

    # forward dynamics (eqs. 10-12): Me xedd = S^T tau_a - Ce xed - S^T f_a (- Ge)
    rhs = tf.S.T @ tau - tf.Ce_v - tf.StF
    if tf.Ge is not None:
        rhs = rhs - tf.Ge
    xedd = solve_small(tf.Me, rhs)
    # d xedd = Me^-1 (d rhs - (d Me) xedd): AD of phi = rhs - Me a with a held, then a = xedd
    # (no AD through the solve: 11 % fewer operations for the paper's robot, 20 % for rrr4)
    held = ca.SX.sym("xedd_held", m)
    dphi_xe, dphi = tf.jacobian(rhs - tf.Me @ held, ca.vertcat(xed, tau, theta))
    Me_inv = inverse_small(tf.Me)
    d_xe, J = (ca.substitute(Me_inv @ D, held, xedd) for D in (dphi_xe, dphi))
    fd_ins = [("xe", xe), ("xed", xed), ("tau_a", tau), ("theta", theta)]
    fd_jac = add("forward_dynamics_jacobians", fd_ins,
                 [("xedd", xedd), ("d_xe", _row_major(d_xe)), ("d_xed", _row_major(J[:, 0:m])),
                  ("d_tau_a", _row_major(J[:, m:m + n])), ("d_theta", _row_major(J[:, m + n:]))])
    # the same xedd alone, for the RK4 stages of sampled_step (called there, not exported)
    fd_value = add("sampled_step_xedd", fd_ins, [("xedd", xedd)], export=False)

    # inverse dynamics (eqs. 10-12): u = Me xedd + Ce xed + S^T f_a (+ Ge)
    u = tf.Me @ xedd_in + tf.Ce_v + tf.StF
    if tf.Ge is not None:
        u = u + tf.Ge
    du_dxe, du_dxed = tf.jacobian(u, xed)
    ins = [("xe", xe), ("xed", xed), ("xedd", xedd_in), ("theta", theta)]
    add("inverse_dynamics", ins, [("u", u)])
    add("inverse_dynamics_jacobians", ins, [("u", u), ("d_xe", _row_major(du_dxe)),
                                            ("d_xed", _row_major(du_dxed))])
    out += _sampled_step(prefix, n, p, m, substeps, fd_value, fd_jac)
    return out


def _sampled_step(prefix, n, p, m, substeps, fd_value, fd_jac):
    """``sampled_step`` and ``sampled_step_jacobians`` (MX): ``substeps`` classical RK4 steps
    of h = T / substeps of z' = [xed, xedd(z, tau_a, theta)] with tau_a held."""
    x, tau = ca.MX.sym("x", 2 * m), ca.MX.sym("tau_a", n)
    theta, T = ca.MX.sym("theta", p), ca.MX.sym("T")
    h = T / substeps
    names_in = ["x", "tau_a", "theta", "T"]
    ins = [x, tau, theta, T]
    design = []          # the [design] input, passed on to the forward dynamics that take it
    if fd_value.name_in(fd_value.n_in() - 1) == "design":
        design = [ca.MX.sym("design", fd_value.size1_in(fd_value.n_in() - 1))]
        names_in, ins = names_in + ["design"], ins + design

    def rhs(z):
        xedd, sing = fd_value(z[0:m], z[m:2 * m], tau, theta, *design)
        return ca.vertcat(z[m:2 * m], xedd), sing

    z, sing0 = x, None
    for _ in range(substeps):
        k1, s = rhs(z)
        sing0 = s if sing0 is None else sing0
        k2, _ = rhs(z + h / 2 * k1)
        k3, _ = rhs(z + h / 2 * k2)
        k4, _ = rhs(z + h * k3)
        z = z + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    step = ca.Function(f"{prefix}_sampled_step", ins, [z, sing0], names_in,
                       ["x_next", "sing"])

    # forward-mode AD over the same stages (the variational equations of RK4):
    # D = d z / d [x, tau_a] (2m, 2m + n), propagated stage by stage with each stage's Jacobian

    def rhs_jac(z, Dz):
        """k = f(z) and d k / d [x, tau_a] = d f / d z Dz + [0, d f / d tau_a]."""
        xedd, d_xe, d_xed, d_tau, _, sing = fd_jac(z[0:m], z[m:2 * m], tau, theta, *design)
        Ja_z = ca.horzcat(_rows(d_xe, m, m), _rows(d_xed, m, m))           # (m, 2m)
        dk = ca.vertcat(Dz[m:2 * m, :],
                        Ja_z @ Dz + ca.horzcat(ca.MX.zeros(m, 2 * m), _rows(d_tau, m, n)))
        return ca.vertcat(z[m:2 * m], xedd), dk, sing

    z, D, sing0 = x, ca.horzcat(ca.MX.eye(2 * m), ca.MX.zeros(2 * m, n)), None
    for _ in range(substeps):
        k1, D1, s = rhs_jac(z, D)
        sing0 = s if sing0 is None else sing0
        k2, D2, _ = rhs_jac(z + h / 2 * k1, D + h / 2 * D1)
        k3, D3, _ = rhs_jac(z + h / 2 * k2, D + h / 2 * D2)
        k4, D4, _ = rhs_jac(z + h * k3, D + h * D3)
        z = z + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        D = D + h / 6 * (D1 + 2 * D2 + 2 * D3 + D4)
    step_jac = ca.Function(f"{prefix}_sampled_step_jacobians", ins,
                           [z, _row_major(D[:, 0:2 * m]), _row_major(D[:, 2 * m:]), sing0], names_in,
                           ["x_next", "d_x", "d_tau_a", "sing"])
    return [step, step_jac]
