# What a controller step did with one sample: the one definition of the status codes.
"""Status codes of the generated controller steps and closed loops.

The derivation writes these codes into the generated C and its manifest
(``manifest["status_codes"]``); :class:`pm2dof.Model` checks, when it loads, that the manifest's
codes are these. Compare with the names, never with bare integers: ``status == Status.SINGULAR``.
"""
from enum import IntEnum

__all__ = ["Status", "STATUS_NAMES"]


class Status(IntEnum):
    """What a controller step did with one 2 ms sample (``status`` output of the C step)."""

    #: the law's torque, within the limits
    OK = 0
    #: the pose is closer to a singularity (type I or II) than its threshold: zero torque,
    #: theta_hat not updated
    SINGULAR = 1
    #: some |tau_i| exceeded tau_max before clipping; the clipped torque was applied
    SATURATED = 2
    #: a non-finite intermediate result: zero torque, the whole state kept
    NON_FINITE = 3
    #: the preload split could not keep every preload within the limits: the largest
    #: worst-case preload instead
    PRELOAD_INFEASIBLE = 4
    #: the encoders do not close the loops (closure residual beyond [sensing]
    #: closure_tolerance): zero torque, the whole state kept
    INCONSISTENT_ENCODERS = 5

    @property
    def label(self):
        """The lower-case name used in the manifest, messages and result tables ("singular")."""
        return self.name.lower()

    @classmethod
    def codes(cls):
        """{label: code}: what the manifest's ``status_codes`` must equal."""
        return {s.label: int(s) for s in cls}


#: code -> label, e.g. STATUS_NAMES[1] == "singular"
STATUS_NAMES = {int(s): s.label for s in Status}
