# Beside the layers: independent plain-NumPy formulations, for the tests and the bench only.
"""Independent, hand-derived NumPy formulations that check the generated C.

* :mod:`.model` -- kinematics and dynamics (eqs. 1-13), n legs;
* :mod:`.control` -- the controller steps, truth plant, encoder and rollout.

Never used at run time: clarity over speed (a reference step is ~10^4 times slower than
the C). Imports NumPy, :mod:`pm2dof.core.layout` and :mod:`pm2dof.core.task` only. RR legs
meeting at a point only: :meth:`.model.Geometry.of_model` refuses other mechanisms
(UnsupportedMechanismError).
"""
from . import control
from .model import (
                    A,
                    C,
                    Ce,
                    Geometry,
                    H,
                    M,
                    Me,
                    S,
                    W,
                    Wdot,
                    Y,
                    fk,
                    forward_dynamics,
                    forward_dynamics_joint,
                    friction,
                    ik,
                    task_friction,
)

__all__ = ["control", "Geometry", "ik", "fk", "H", "A", "W", "S", "Wdot", "M", "C", "friction",
           "Me", "Ce", "task_friction", "Y", "forward_dynamics", "forward_dynamics_joint"]
