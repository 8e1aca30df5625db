# Identifiability: the combinations of theta the regressor sees (base parameters), its null space.
"""The base parameters of eq. 13 (S^T tau_a = Y theta).

:func:`identifiability` stacks Y over random states and finds a set of independent columns of
Y and, for every other column, the combination of independent ones it equals. The result's
:class:`BaseParameters` is what every step of the identification passes along: the fit solves
for the base parameters pi = theta[I] + beta theta[D] (:meth:`BaseParameters.fold`), the
physically consistent solution maps them back to a full theta, the reports name them.
"""
from dataclasses import dataclass

import numpy as np

from ..control.trajectory import line_moves
from ..core.errors import ArgumentError, SingularityError, WorkspaceError
from ..core.mechanism import FRICTION_MODELS

__all__ = ["BaseParameters", "Identifiability", "identifiability", "base_parameters",
           "format_identifiability", "inertial_mask", "region_center", "parameter_units"]

#: name prefixes of the friction coefficients of every friction model (eq. 2 and its
#: extensions: fv, fc, fs); every other parameter (a leg's alpha, beta, gamma, kappa, the
#: platform's m_p, mx_p, my_p, I_p) is inertial
FRICTION = tuple(dict.fromkeys(key for keys in FRICTION_MODELS.values() for key in keys))


def inertial_mask(names):
    """Boolean array: which of ``names`` (parameters or base parameters) are inertial (not
    friction)."""
    return np.array([not str(n).startswith(FRICTION) for n in names], dtype=bool)


#: units of theta's entries by key: (a revolute leg's, a linear leg's) where they differ
#: (docs/model-file.md, [nominal]); the platform's keys have no leg
_UNITS = {"alpha": ("kg m^2", "kg"), "beta": ("kg m^2", "kg m"), "gamma": ("kg m^2", "kg m^2"),
          "kappa": ("kg m", "kg m"), "fv": ("N m s/rad", "N s/m"), "fc": ("N m", "N"),
          "fs": ("N m", "N"), "m_p": "kg", "mx_p": "kg m", "my_p": "kg m", "I_p": "kg m^2"}


def parameter_units(model, names=None):
    """The unit of each named entry of theta, by its leg's kind (docs/model-file.md).

    An RRR leg's alpha, beta, gamma are kg m^2, a PRR or RPR leg's alpha kg and beta kg m; a
    revolute actuator's fv is N m s/rad and fc, fs N m, a linear one's N s/m and N. A base
    parameter has the unit of the independent entry it is named after (the folded entries
    come with coefficients in the matching units).

    Parameters
    ----------
    model : Model
    names : sequence of str, optional
        Entries of ``model.param_names`` (default all of them).

    Returns
    -------
    list of str
        One unit per name, e.g. "kg m^2", "N s/m".
    """
    legs = model.spec.legs
    out = []
    for name in model.param_names if names is None else names:
        key = str(name).rstrip("0123456789")
        unit = _UNITS.get(key)
        if unit is None:
            raise ArgumentError(f"{name!r} is not a parameter of theta (known: "
                                f"{', '.join(_UNITS)} with a leg number)")
        if isinstance(unit, tuple):
            idx = str(name)[len(key):]
            if not idx or not 1 <= int(idx) <= len(legs):
                raise ArgumentError(f"{name!r}: {key} needs a leg number 1..{len(legs)}")
            unit = unit[0] if legs[int(idx) - 1].actuator == "revolute" else unit[1]
        out.append(unit)
    return out


def region_center(model):
    """The middle of the model's first move (m, (2,)): where identification excites the robot."""
    t = model.spec.trajectories[line_moves(model)[0]]
    return (np.asarray(t["start"], float) + np.asarray(t["end"], float)) / 2


@dataclass(frozen=True)
class BaseParameters:
    """The identifiable combinations of theta: pi = theta[I] + beta @ theta[D].

    Column d of Y equals sum_i beta[i, d] times independent column i, so the data determine
    r = len(independent) combinations of the p parameters and nothing of the rest.

    Attributes
    ----------
    independent : tuple of int (r,)
        Indices I of theta whose columns of Y are kept, in order.
    dependent : tuple of int (p - r,)
        Indices D folded into them.
    beta : ndarray (r, p - r), read-only
        The folding.
    names : tuple of str (p,)
        The model's parameter names (``Model.param_names``).
    """
    independent: tuple
    dependent: tuple
    beta: np.ndarray
    names: tuple

    def __post_init__(self):
        ind = tuple(int(i) for i in self.independent)
        dep = tuple(int(i) for i in self.dependent)
        names = tuple(str(n) for n in self.names)
        beta = np.array(self.beta, dtype=float).reshape(len(ind), len(dep))
        if sorted(ind + dep) != list(range(len(names))):
            raise ArgumentError(f"independent {ind} and dependent {dep} must split the "
                                f"{len(names)} parameter indices 0..{len(names) - 1}")
        beta.setflags(write=False)
        for k, v in (("independent", ind), ("dependent", dep), ("beta", beta), ("names", names)):
            object.__setattr__(self, k, v)

    def __eq__(self, other):
        return (isinstance(other, BaseParameters) and self.names == other.names
                and (self.independent, self.dependent) == (other.independent, other.dependent)
                and np.array_equal(self.beta, other.beta))

    __hash__ = None

    r = property(lambda self: len(self.independent), doc="number of base parameters")
    independent_names = property(lambda self: [self.names[i] for i in self.independent],
                                 doc="names of the independent columns (one per base parameter)")
    inertial = property(lambda self: inertial_mask(self.independent_names),
                        doc="(r,) bool: which base parameters are inertial (else friction)")

    def fold(self, theta):
        """Base parameters pi (r,) of a full theta (p,): theta[I] + beta @ theta[D].

        Parameters
        ----------
        theta : array_like (p,)
            Full parameters, in ``names`` order (Tables 1-2 units).
        """
        th = np.asarray(theta, dtype=float)
        if th.shape != (len(self.names),):
            raise ArgumentError(f"theta must have shape ({len(self.names)},), got {th.shape}")
        return th[list(self.independent)] + self.beta @ th[list(self.dependent)]

    def unfold(self, base, theta):
        """A full theta (p,) whose base parameters are ``base`` (r,) and whose dependent
        entries are those of ``theta`` (e.g. Tables 1-2): fold(unfold(base, theta)) = base.

        Parameters
        ----------
        base : array_like (r,)
            Base parameters, in ``independent_names`` order.
        theta : array_like (p,)
            Full parameters giving the dependent entries, in ``names`` order.
        """
        out = np.array(theta, dtype=float)
        out[list(self.independent)] = base - self.beta @ out[list(self.dependent)]
        return out

    def matrix(self):
        """P (r, p) with pi = P theta: the identity on the independent columns, beta on the
        dependent ones."""
        P = np.zeros((self.r, len(self.names)))
        P[np.arange(self.r), list(self.independent)] = 1.0
        P[:, list(self.dependent)] = self.beta
        return P

    def labels(self):
        """Readable base parameters, e.g. 'alpha1 + 1 gamma2 + 1 gamma3'."""
        out = []
        for i, j in enumerate(self.independent):
            terms = [self.names[j]]
            for k, d in enumerate(self.dependent):
                b = self.beta[i, k]
                if b != 0.0:
                    terms.append(f"{'+' if b > 0 else '-'} {abs(b):.4g} {self.names[d]}")
            out.append(" ".join(terms))
        return out


@dataclass(frozen=True)
class Identifiability:
    """What the stacked regressor shows: :func:`identifiability`'s result.

    Attributes
    ----------
    base : BaseParameters
    rank : int
        Numerical rank of the column-scaled stacked regressor.
    singular_values : ndarray (p,)
        Of the column-scaled stacked regressor, largest first.
    null_space : ndarray (p, p - rank)
        Orthonormal directions of theta that change no torque (of the unscaled regressor).
    """
    base: BaseParameters
    rank: int
    singular_values: np.ndarray
    null_space: np.ndarray

    n_params = property(lambda self: len(self.base.names), doc="p")


def _random_states(model, n, rng, center, radius):
    out, m = [], len(center)   # the task dimension (2, or 3 for a platform: x, y, phi)
    while len(out) < n:
        xe = center + rng.uniform(-radius, radius, m)
        try:
            q = model.ik(xe)
            model.W(q)
        except (WorkspaceError, SingularityError):
            continue
        v = rng.normal(0, 0.3, m)
        out.append((q, v, rng.normal(0, 0.3, m), rng.normal(0, 5.0, m)))
    return out


def identifiability(model, samples=400, seed=0, radius=0.04, rtol=1e-9):
    """Rank of the regressor Y stacked over random states, and the base parameters.

    Parameters
    ----------
    model : Model
    samples : int
        Random states over which Y is stacked.
    seed : int
        Seed of the random states.
    radius : float
        m: the states' positions are drawn uniformly within +-radius in x and y of
        :func:`region_center` (the middle of the model file's first move); velocities
        N(0, 0.3) m/s, accelerations N(0, 5) m/s^2.
    rtol : float
        Singular values of the column-scaled stacked Y below ``rtol`` times the largest count
        as zero.

    Returns
    -------
    Identifiability
        Its ``base`` (:class:`BaseParameters`): a greedy choice of independent columns (a column
        is kept if it raises the rank) and the least-squares folding of the others; ``rank``,
        ``singular_values`` and ``null_space``.
    """
    rng = np.random.default_rng(seed)
    Phi_raw = np.vstack([model.Y(q, v, vr, ar) for q, v, vr, ar
                         in _random_states(model, samples, rng, region_center(model), radius)])
    Phi = Phi_raw / np.linalg.norm(Phi_raw, axis=0)  # scale columns: units differ
    sv = np.linalg.svd(Phi, compute_uv=False)
    rank = int(np.sum(sv > sv[0] * rtol))
    independent = []
    for j in range(Phi.shape[1]):  # greedy: keep a column if it raises the rank
        cols = Phi[:, independent + [j]]
        s = np.linalg.svd(cols, compute_uv=False)
        if s[-1] > sv[0] * rtol:
            independent.append(j)
    dependent = [j for j in range(Phi.shape[1]) if j not in independent]
    beta, *_ = np.linalg.lstsq(Phi_raw[:, independent], Phi_raw[:, dependent], rcond=None)
    beta[np.abs(beta) < 1e-9 * max(1.0, np.abs(beta).max(initial=0))] = 0.0
    _, _, Vt = np.linalg.svd(Phi_raw)
    return Identifiability(BaseParameters(independent, dependent, beta, model.param_names),
                           rank, sv, Vt[rank:].T)


def base_parameters(model):
    """The model's :class:`BaseParameters` (:func:`identifiability` with its defaults).

    Parameters
    ----------
    model : Model
    """
    return identifiability(model).base


def format_identifiability(ident):
    """The printed report of ``pm2dof identify report`` (an :class:`Identifiability`)."""
    base, names = ident.base, ident.base.names
    lines = [f"regressor Y stacked over random states: rank {ident.rank} of "
             f"{ident.n_params} (column-scaled singular values "
             f"{ident.singular_values[-1]:.2e} .. {ident.singular_values[0]:.2e})"]
    if base.dependent:
        lines.append("not identifiable on their own: "
                     + ", ".join(names[d] for d in base.dependent))
    lines.append("identifiable base parameters (each column folds in the dependent ones):")
    lines += [f"  {s}" for s in base.labels()]
    if ident.null_space.shape[1]:
        lines.append("invisible directions of theta (null space of Y; moving theta along them "
                     "changes no torque):")
        for k in range(ident.null_space.shape[1]):
            v = ident.null_space[:, k]
            v = v / v[np.argmax(np.abs(v))]
            terms = [f"{c:+.3f} {n}" for c, n in zip(v, names) if abs(c) > 1e-6]
            lines.append("  " + " ".join(terms))
    return "\n".join(lines)
