# Model methods that test task poses against the singularity thresholds, a whole array at once.
"""The pose checks of a desired motion: both singularity measures of every pose, and which
poses a motion may use.

:class:`PoseMethods` is a base of :class:`pm2dof.Model`. Controllers' rollouts
(``check_trajectory``), the path planner's checks and the singularity maps all use these, so
that the thresholds and their slack have one home.
"""
import numpy as np

from .errors import WorkspaceError
from .task import is_rr_point

__all__ = ["PoseMethods"]


class PoseMethods:
    """The pose checks of :class:`pm2dof.Model` (see the module docstring)."""

    __slots__ = ()

    def pose_measures(self, xd):
        """Both singularity measures and, for two legs, the assembly side of every pose.

        For RR legs meeting at a point: vectorised NumPy geometry of ``ik`` (law of cosines per
        leg, the model's elbows), used to check a whole trajectory at once; the generated ``ik``
        and ``singularity_measures`` remain the reference and word the errors. Other mechanisms
        (prismatic legs, a platform): the generated functions at every pose.

        Parameters
        ----------
        xd : array_like (N, m)
            Task poses (m = ``model.dof``), m (phi in rad).

        Returns
        -------
        type1, type2, side : ndarray (N,)
            min_i |sin(qb_i - qa_i)|, the type II measure (see ``Model.singularity_measures``), NaN
            where some leg cannot reach; ``side`` = fk_branch * cross(B2 - B1, O - B1) for two legs
            (> 0 in the model's assembly mode), +1 for more legs.
        """
        xd = np.asarray(xd, dtype=float).reshape(-1, self.dof)
        if not is_rr_point(self.spec):
            return self._generated_measures(xd)
        legs = self.spec.legs
        type1 = np.full(len(xd), np.inf)
        z = np.zeros(len(xd), dtype=complex)
        elbows = []
        with np.errstate(invalid="ignore", divide="ignore"):
            for leg in legs:
                d = xd - np.asarray(leg.base)
                dist = np.hypot(d[:, 0], d[:, 1])
                c = (leg.la ** 2 + dist ** 2 - leg.lb ** 2) / (2 * leg.la * dist)
                c[~(np.abs(c) <= 1)] = np.nan                       # out of reach: NaN
                s = leg.elbow * np.sqrt(1 - c * c)
                dh = d / dist[:, None]
                ua = c[:, None] * dh + s[:, None] * np.stack([-dh[:, 1], dh[:, 0]], axis=1)
                ub = (d - leg.la * ua) / leg.lb
                type1 = np.minimum(type1, np.abs(ua[:, 0] * ub[:, 1] - ua[:, 1] * ub[:, 0]))
                z += (ub[:, 0] + 1j * ub[:, 1]) ** 2                # e^(2 i qb)
                elbows.append(np.asarray(leg.base) + leg.la * ua)
            type2 = np.sqrt(np.maximum(1 - np.abs(z) / len(legs), 0)) + 0 * type1  # NaN stays
            side = np.ones(len(xd))
            if len(legs) == 2:
                dB, e = elbows[1] - elbows[0], xd - elbows[0]
                side = self.spec.fk_branch * (dB[:, 0] * e[:, 1] - dB[:, 1] * e[:, 0])
        return type1, type2, side

    def _generated_measures(self, xd):
        """:meth:`pose_measures` by the generated ik and singularity_measures, sample by sample:
        any mechanism (NaN where ik has no solution)."""
        type1, type2 = np.full(len(xd), np.nan), np.full(len(xd), np.nan)
        q, sing = np.empty(2 * self.n_legs), np.empty(2)
        for k, x in enumerate(xd):
            try:
                self.ik(x, out=q)
            except WorkspaceError:
                continue
            self.singularity_measures(q, out=sing)
            type1[k], type2[k] = sing
        return type1, type2, np.ones(len(xd))

    def poses_clear(self, type1, type2, side=1.0):
        """(N,) bool: the poses a desired motion may use, from their measures.

        Both measures at or above their thresholds (``[limits]``; a relative slack of 1e-12
        for rounding) and, for two legs, in the model's assembly mode (``side`` > 0). NaN (out
        of reach) is not clear.

        Parameters
        ----------
        type1, type2 : array_like (N,)
            The type I and type II singularity measures of the poses (:meth:`pose_measures`,
            or the generated ``singularity_measures``), each in [0, 1], NaN out of reach.
        side : float or array_like (N,)
            The assembly side of :meth:`pose_measures` (> 0 in the model's assembly mode);
            the default 1.0 takes every pose as on the right side.
        """
        thr1, thr2 = self.singularity_threshold, self.parallel_singularity_threshold
        return (np.asarray(type1) >= thr1 * (1 - 1e-12)) & \
            (np.asarray(type2) >= thr2 * (1 - 1e-12)) & (np.asarray(side) > 0)
