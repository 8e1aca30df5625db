# The same robot in MuJoCo: the legs as kinematic chains, their tips tied by equality constraints.
"""The paper's robot (any n-leg model) in MuJoCo, for the forward-dynamics benchmark.

Each leg is a chain of two hinges about z, the active one at its base A_i and the distal one
at the elbow (angle qb_i - qa_i relative to the active link), with the bodies of
:func:`.pinocchio_baseline.leg_bodies` (the inertias of eq. 1's alpha, beta, gamma). Leg 1's
tip is tied to every other leg's tip by a ``connect`` equality between sites. No friction, no
gravity (planar), no geoms (nothing to collide).

MuJoCo's constraints are soft: at impedance d the constraint force is that of a hard
constraint regularised by R = (1 - d) / d times (an approximation of) the constraint-space
inertia, so its accelerations differ from the exact ones by O(1 - d) relative. ``impedance``
defaults to MuJoCo's largest, 0.9999 (``mjMAXIMP``); the benchmark's test checks that the
difference from pm2dof's forward dynamics shrinks in proportion to 1 - d.
"""
import numpy as np

from .pinocchio_baseline import chain_state, leg_bodies

__all__ = ["MujocoRobot", "MAX_IMPEDANCE"]

#: MuJoCo's largest constraint impedance (mjMAXIMP)
MAX_IMPEDANCE = 0.9999


def _mjcf(model, theta, impedance):
    legs = []
    for i, (leg, body) in enumerate(zip(model.spec.legs, leg_bodies(model, theta), strict=True)):
        mb, rb, Ia, Ib = (float(v) for v in body)
        # rotations about x, y are impossible for a hinge about z: those inertias are
        # irrelevant, and set equal to the z one (MuJoCo asks A + B >= C)
        legs.append(f"""
    <body name="a{i + 1}" pos="{float(leg.base[0])!r} {float(leg.base[1])!r} 0">
      <joint name="qa{i + 1}" type="hinge" axis="0 0 1"/>
      <inertial pos="0 0 0" mass="1e-9" diaginertia="{Ia!r} {Ia!r} {Ia!r}"/>
      <body name="b{i + 1}" pos="{float(leg.la)!r} 0 0">
        <joint name="qb{i + 1}" type="hinge" axis="0 0 1"/>
        <inertial pos="{rb!r} 0 0" mass="{mb!r}" diaginertia="{Ib!r} {Ib!r} {Ib!r}"/>
        <site name="tip{i + 1}" pos="{float(leg.lb)!r} 0 0"/>
      </body>
    </body>""")
    imp = f"{float(impedance)!r} {float(impedance)!r} 0.001 0.5 2"
    ties = "".join(f'\n    <connect site1="tip1" site2="tip{i + 1}" solimp="{imp}"/>'
                   for i in range(1, model.n_legs))
    return (f'<mujoco model="{model.name}">\n  <option gravity="0 0 0"/>\n  <worldbody>'
            f'{"".join(legs)}\n  </worldbody>\n  <equality>{ties}\n  </equality>\n</mujoco>\n')


class MujocoRobot:
    """``model``'s robot with parameters ``theta`` (friction ignored) in MuJoCo; ``mjcf`` is
    its model text."""

    def __init__(self, model, theta, impedance=MAX_IMPEDANCE):
        import mujoco
        self.mujoco, self.m = mujoco, model
        self.mjcf = _mjcf(model, theta, impedance)
        self.model = mujoco.MjModel.from_xml_string(self.mjcf)
        self.data = mujoco.MjData(self.model)

    def set_state(self, xe, xed, tau_a):
        """Put the pose xe, velocity xed and actuator torques tau_a into ``data`` (qpos, qvel,
        qfrc_applied: MuJoCo's tree order is pm2dof's chain order)."""
        q, v, tau = chain_state(self.m, xe, xed, tau_a)
        self.data.qpos[:], self.data.qvel[:], self.data.qfrc_applied[:] = q, v, tau

    def forward(self):
        """``mj_forward`` on the state in ``data``: qacc."""
        self.mujoco.mj_forward(self.model, self.data)
        return self.data.qacc

    def tip_acceleration(self):
        """Leg 1's tip acceleration (2,) m/s^2 from qpos, qvel and the qacc of :meth:`forward`
        (the tip is A_1 + la u(qa) + lb u(qa + q_rel), u(a) = (cos a, sin a))."""
        la, lb = self.m.spec.legs[0].la, self.m.spec.legs[0].lb
        qa, qr = self.data.qpos[:2]
        wa, wr = self.data.qvel[:2]
        aa, ar = self.data.qacc[:2]
        qb, wb, ab = qa + qr, wa + wr, aa + ar

        def acc(length, q, w, a):     # d2/dt2 of length * u(q)
            return length * (a * np.array([-np.sin(q), np.cos(q)])
                             - w * w * np.array([np.cos(q), np.sin(q)]))
        return acc(la, qa, wa, aa) + acc(lb, qb, wb, ab)
