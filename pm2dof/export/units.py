# The units an export's C header documents: the model's task coordinates and its actuators' kinds.
"""Unit strings for ``<name>_pm2dof.h``.

A task vector has m = ``Model.dof`` entries named ``Model.task_names``: x, y in m, and for a
platform phi in rad. An actuator's joint coordinate qa_i is an angle in rad (RRR legs) or a
length in m (PRR, RPR: a linear actuator), and its effort is a torque in N m or a force in N
(docs/model-file.md). For the paper's robot every string is the one the header always had.
"""
from ..core.task import per_actuator

__all__ = ["ExportUnits", "export_units"]


class ExportUnits:
    """The unit phrases of one model (attributes are strings for C comments)."""

    def __init__(self, task_names, actuators):
        self.task_names = tuple(task_names)
        self.actuators = tuple(actuators)       # "revolute" or "prismatic", one per leg
        angular = [nm == "phi" for nm in self.task_names]
        self.has_phi = any(angular)
        self.task = ", ".join(self.task_names)

        def task(linear, phi):      # e.g. "m" or "m (x, y), rad (phi)"
            if not self.has_phi:
                return linear
            lin = ", ".join(nm for nm, a in zip(self.task_names, angular) if not a)
            return f"{linear} ({lin}), {phi} (phi)"

        self.pos = task("m", "rad")
        self.vel = task("m/s", "rad/s")
        self.acc = task("m/s^2", "rad/s^2")
        self.force = task("N", "N m")                  # the task force u
        self.kd = task("N s/m", "N m s/rad")           # K_d of eq. 29, APD's Kv
        self.kp = task("N/m", "N m/rad")               # APD's Kp
        self.qa = self._per_actuator("rad", "m")
        self.effort = self._per_actuator("N m", "N")
        self.joint = self._per_actuator("angle", "length")
        self.efforts = self._per_actuator("torques", "forces")

    def _per_actuator(self, revolute, prismatic):
        return per_actuator(self.actuators, revolute, prismatic)


def export_units(model):
    """:class:`ExportUnits` of ``model`` (a :class:`pm2dof.Model`)."""
    return ExportUnits(model.task_names, model.spec.actuators)
