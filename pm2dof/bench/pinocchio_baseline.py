# The same robot in Pinocchio: legs as a kinematic tree closed by point constraints.
"""The paper's robot (any n-leg model) in Pinocchio, for the derivative benchmark.

Each leg is two revolute joints about z (the active one at its base A_i, the passive one at
the elbow, angle qb_i - qa_i relative to it); the legs' tips are tied to leg 1's by 3-D point
constraints (``RigidConstraintModel``, CONTACT_3D; the z rows are redundant in the plane, so
the proximal solver handles the rank deficiency). The lumped parameters of eq. 1 become
bodies: the distal link a point mass m_b = beta / (la r_b) with its centre at r_b = lb / 2
and inertia gamma - m_b r_b^2 about it, the active link the inertia alpha - m_b la^2 about
its joint (T = 1/2 alpha qa'^2 + beta cos(qa - qb) qa' qb' + 1/2 gamma qb'^2, as eq. 1). No
friction, no gravity (planar). :meth:`PinocchioRobot.tip_acceleration` turns Pinocchio's
constrained forward dynamics into the tip's acceleration, to compare with pm2dof's xedd.
"""
import numpy as np

from .baselines import theta_by_name

__all__ = ["PinocchioRobot", "leg_bodies", "chain_state"]


def leg_bodies(model, theta):
    """Per leg (m_b, r_b, I_a, I_b): the two bodies whose kinetic energy is eq. 1's with
    ``theta``'s alpha, beta, gamma (read by name; the distal link a mass m_b = beta / (la r_b) at r_b = lb / 2
    with inertia I_b = gamma - m_b r_b^2 about it, the active link I_a = alpha - m_b la^2 about
    its joint). ValueError where no such bodies exist."""
    alpha, beta, gamma = theta_by_name(model, theta, "alpha", "beta", "gamma")
    out = []
    for i, leg in enumerate(model.spec.legs):
        rb = leg.lb / 2
        mb = beta[i] / (leg.la * rb)
        Ib, Ia = gamma[i] - mb * rb ** 2, alpha[i] - mb * leg.la ** 2
        if not (mb > 0 and Ib > 0 and Ia > 0):
            raise ValueError(f"leg {i + 1}: alpha, beta, gamma are not those of two links "
                             f"with a distal centre at lb/2 (m_b {mb}, I_a {Ia}, I_b {Ib})")
        out.append((mb, rb, Ia, Ib))
    return out


def chain_state(model, xe, xed, tau_a):
    """The legs as open chains: (q, v, tau) (2n,) ordered leg by leg [qa_i, qb_i - qa_i] (the
    distal joint relative to the active link) at the pose xe, velocity xed, torques tau_a."""
    n = model.n_legs
    qq = model.ik(xe)
    qd = model.W(qq) @ np.asarray(xed, dtype=float)
    q, v, tau = np.empty(2 * n), np.empty(2 * n), np.zeros(2 * n)
    q[0::2], q[1::2] = qq[:n], qq[n:] - qq[:n]
    v[0::2], v[1::2] = qd[:n], qd[n:] - qd[:n]
    tau[0::2] = tau_a
    return q, v, tau


class PinocchioRobot:
    """``model``'s robot with parameters ``theta`` (friction ignored) in Pinocchio."""

    def __init__(self, model, theta):
        import pinocchio as pin
        self.pin, self.m = pin, model
        pm = pin.Model()
        self.tips = []
        bodies = leg_bodies(model, theta)
        for i, (leg, (mb, rb, Ia, Ib)) in enumerate(zip(model.spec.legs, bodies, strict=True)):
            ja = pm.addJoint(0, pin.JointModelRZ(),
                             pin.SE3(np.eye(3), np.array([*leg.base, 0.0])), f"qa{i + 1}")
            pm.appendBodyToJoint(ja, pin.Inertia(1e-9, np.zeros(3), np.diag([1e-6, 1e-6, Ia])),
                                 pin.SE3.Identity())
            jb = pm.addJoint(ja, pin.JointModelRZ(),
                             pin.SE3(np.eye(3), np.array([leg.la, 0.0, 0.0])), f"qb{i + 1}")
            pm.appendBodyToJoint(jb, pin.Inertia(mb, np.array([rb, 0.0, 0.0]),
                                                 np.diag([1e-6, 1e-6, Ib])), pin.SE3.Identity())
            self.tips.append((jb, pin.SE3(np.eye(3), np.array([leg.lb, 0.0, 0.0]))))
        pm.gravity = pin.Motion.Zero()
        self.model, self.data = pm, pm.createData()
        self.cms = pin.StdVec_RigidConstraintModel()
        self.cds = pin.StdVec_RigidConstraintData()
        for jb, tip in self.tips[1:]:
            c = pin.RigidConstraintModel(pin.ContactType.CONTACT_3D, pm, self.tips[0][0],
                                         self.tips[0][1], jb, tip, pin.ReferenceFrame.LOCAL)
            self.cms.append(c)
            self.cds.append(c.createData())
        pin.initConstraintDynamics(pm, self.data, self.cms, self.cds)
        self.prox = pin.ProximalSettings(1e-12, 1e-8, 20)

    def state(self, xe, xed, tau_a):
        """Pinocchio's (q, v, tau) of the pose xe, velocity xed and actuator torques tau_a."""
        return chain_state(self.m, xe, xed, tau_a)

    def forward_dynamics_with_derivatives(self, q, v, tau):
        """constraintDynamics then computeConstraintDynamicsDerivatives (what one gets the
        derivatives of the constrained dynamics with): ddq and data.ddq_dq, ddq_dv, ddq_dtau."""
        pin = self.pin
        ddq = pin.constraintDynamics(self.model, self.data, q, v, tau, self.cms, self.cds,
                                     self.prox)
        pin.computeConstraintDynamicsDerivatives(self.model, self.data, self.cms, self.cds,
                                                 self.prox)
        return ddq

    def forward_dynamics(self, q, v, tau):
        """Pinocchio's constrained forward dynamics alone (``constraintDynamics``): ddq."""
        return self.pin.constraintDynamics(self.model, self.data, q, v, tau, self.cms, self.cds,
                                           self.prox)

    def tip_acceleration(self, q, v, tau):
        """The tip's acceleration (2,) m/s^2 from Pinocchio's constrained ddq."""
        pin = self.pin
        ddq = pin.constraintDynamics(self.model, self.data, q, v, tau, self.cms, self.cds,
                                     self.prox)
        pin.forwardKinematics(self.model, self.data, q, v, ddq)
        jb, tip = self.tips[0]
        a, w_v = self.data.a[jb], self.data.v[jb]
        p = tip.translation
        w = w_v.angular
        acc = a.linear + np.cross(a.angular, p) + np.cross(w, w_v.linear + np.cross(w, p))
        return (self.data.oMi[jb].rotation @ acc)[:2]
