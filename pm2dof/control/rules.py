# The controllers' parameter rules: one table, read by the Python constructors and the exported C.
"""What every entry of a controller's parameter vector must be.

The table :data:`RULES` is keyed by law ("na", "apd", "ctc", "lqr") and by the field names of
the generated parameter layouts (``<law>_params`` of the manifest, derive/controllers.py; the
LQR's weights ``Q_position``, ``Q_velocity``, ``R`` are not in its layout but checked here as
well). It has two readers:

* the Python side: :meth:`pm2dof.ControlSettings.from_spec` checks the settings every law
  shares (:data:`COMMON`), the controllers (:class:`pm2dof.NAController` and the others) their
  gains (:func:`check_entries`), and :func:`pm2dof.control.controllers.law_params` the whole
  vector they pack (:func:`check_params`), each with a typed error naming the field, the
  entry, the value and the rule;
* ``pm2dof export`` writes the same rules into ``<name>_pm2dof_<law>_init`` as C comparisons
  (pm2dof/export/checks.py), which refuse a parameter vector with BAD_PARAMS and name the
  offset of the first entry that breaks one.

Every entry must also be finite. The bounds, and why:

* gains: K_d, Q > 0 and Gamma >= 0 (the Lyapunov argument of Sect. 4); APD's and CTC's Kp,
  Kv > 0;
* ``T``, the sample period: within [:data:`T_MIN`, :data:`T_MAX`] s. Below a microsecond the
  backward difference (x_k - x_{k-1}) / T of an encoder count overflows any sensible
  velocity; above a second the loop does not control these robots;
* ``vel_alpha``, the velocity low-pass gain: (0, 1];
* the singularity thresholds: (0, 1), as the model file's: both measures lie in [0, 1], so a
  threshold <= 0 never trips and one >= 1 always does;
* ``tau_max``: (0, :data:`TAU_MAX_LIMIT`] N m or N. A drive beyond a million newton (metres)
  is a unit error; 1e30 leaves the clipping switched off;
* ``preload_sign``: +1 or -1; ``preload``: >= 0 and below ``tau_max`` (entry by entry);
* ``closure_tol``: (0, :data:`CLOSURE_TOL_MAX`] m. A tolerance <= 0 refuses every reading,
  one of metres lets any encoder fault through;
* NA's ``freeze_saturated``: 0 (adapt on every good sample, the paper's law) or 1 (hold
  theta_hat on a saturated sample).
"""
import math
from dataclasses import dataclass

import numpy as np

from ..core.errors import ArgumentError, GainError

__all__ = ["Rule", "RULES", "COMMON", "LAW_OF_CLASS", "T_MIN", "T_MAX", "TAU_MAX_LIMIT",
           "CLOSURE_TOL_MAX", "rule", "violations", "check_entries", "check_params"]

#: the sample period's bounds, s
T_MIN, T_MAX = 1e-6, 1.0
#: the largest tau_max, N m (revolute actuators) or N (linear ones)
TAU_MAX_LIMIT = 1e6
#: the largest closure tolerance, m
CLOSURE_TOL_MAX = 0.1


@dataclass(frozen=True)
class Rule:
    """What each entry of one parameter field must be, besides finite.

    Attributes
    ----------
    lo, hi : float
        Bounds (-inf, inf: none).
    lo_open, hi_open : bool
        True when the bound itself is excluded (> lo, < hi).
    values : tuple of float
        When not empty, the only values allowed (the bounds are then not used).
    below : str
        When set, each entry must also be below the same entry of this field.
    name : str
        What the user sets (the constructor's argument or the model file's key), when it is
        not the field's name.
    why : str
        The reason, for messages.
    gain : bool
        A gain of the law: its errors are :class:`pm2dof.GainError` (else ArgumentError).
    """

    lo: float = -math.inf
    hi: float = math.inf
    lo_open: bool = False
    hi_open: bool = False
    values: tuple = ()
    below: str = ""
    name: str = ""
    why: str = ""
    gain: bool = False

    @property
    def condition(self):
        """The rule as text: "> 0", "in [1e-06, 1]", "-1 or +1", ">= 0 and < tau_max"."""
        if self.values:
            return " or ".join(f"{v:+g}" if min(self.values) < 0 else f"{v:g}"
                               for v in self.values)
        lo = f"{'>' if self.lo_open else '>='} {self.lo:g}" if self.lo > -math.inf else ""
        hi = f"{'<' if self.hi_open else '<='} {self.hi:g}" if self.hi < math.inf else ""
        if lo and hi:
            text = (f"in {'(' if self.lo_open else '['}{self.lo:g}, {self.hi:g}"
                    f"{')' if self.hi_open else ']'}")
        else:
            text = lo or hi or "finite"
        return f"{text} and < {self.below}" if self.below else text

    def holds(self, x, bound=None):
        """(k,) bool: which entries of ``x`` keep the rule (``bound``: the entries of the field
        ``below`` names). NaN and inf never do."""
        x = np.asarray(x, dtype=float)
        with np.errstate(invalid="ignore"):
            ok = np.isfinite(x)
            if self.values:
                return ok & np.isin(x, self.values)
            ok &= (x > self.lo) if self.lo_open else (x >= self.lo)
            ok &= (x < self.hi) if self.hi_open else (x <= self.hi)
            if self.below:
                ok &= x < np.asarray(bound, dtype=float)
        return ok


_POSITIVE = dict(lo=0.0, lo_open=True, gain=True)
_LYAPUNOV = "(the Lyapunov argument of Sect. 4)"
_CTC = "computed torque needs {} positive definite (the error dynamics are then stable)"
#: field -> Rule of the fields every law's parameters share after its gains (the settings of
#: pm2dof.control.settings.ControlSettings)
COMMON = {
    "T": Rule(lo=T_MIN, hi=T_MAX, name="sample_period",
              why="the controller's sample period, s"),
    "vel_alpha": Rule(lo=0.0, lo_open=True, hi=1.0, name="velocity filter gain",
                      why="the velocity low-pass gain a (1: none; from velocity_filter_hz)"),
    "sing_threshold": Rule(lo=0.0, lo_open=True, hi=1.0, hi_open=True,
                           name="limits.singularity_threshold",
                           why="the type I measure lies in [0, 1]: a threshold <= 0 never "
                               "trips"),
    "parallel_sing_threshold": Rule(lo=0.0, lo_open=True, hi=1.0, hi_open=True,
                                    name="limits.parallel_singularity_threshold",
                                    why="the type II measure lies in [0, 1]: a threshold <= 0 "
                                        "never trips"),
    "tau_max": Rule(lo=0.0, lo_open=True, hi=TAU_MAX_LIMIT, name="tau_max",
                    why="the actuators' limit (beyond 1e6 the clipping is off: a unit error)"),
    "preload_sign": Rule(values=(-1.0, 1.0), name="preload_sign",
                         why="the preload split's sign per actuator"),
    "preload": Rule(lo=0.0, below="tau_max", name="preload",
                    why="the preload split's least effort per actuator"),
    "closure_tol": Rule(lo=0.0, lo_open=True, hi=CLOSURE_TOL_MAX,
                        name="sensing.closure_tolerance",
                        why="the largest closure residual of the encoders, m (<= 0 refuses "
                            "every reading, a large one lets an encoder fault through)"),
}
#: law -> field -> Rule: every field of the law's parameter layout (and the LQR's weights)
RULES = {
    "na": {"Kd": Rule(**_POSITIVE, why=f"K_d must be positive definite {_LYAPUNOV}"),
           "Q": Rule(**_POSITIVE, why=f"Q must be positive definite {_LYAPUNOV}"),
           "Gamma": Rule(lo=0.0, gain=True,
                         why="Gamma must be positive semi-definite (Sect. 4; a zero entry "
                             "switches adaptation of that parameter off)"),
           "freeze_saturated": Rule(values=(0.0, 1.0), name="freeze_when_saturated",
                                    why="1 holds theta_hat on a saturated sample, 0 adapts"),
           **COMMON},
    "apd": {"Kp": Rule(**_POSITIVE, why="APD (eq. 40) needs Kp positive definite"),
            "Kv": Rule(**_POSITIVE, why="APD (eq. 40) needs Kv positive definite"),
            **COMMON},
    "ctc": {"Kp": Rule(**_POSITIVE, why=_CTC.format("Kp")),
            "Kv": Rule(**_POSITIVE, why=_CTC.format("Kv")), **COMMON},
    "lqr": {"Q_position": Rule(**_POSITIVE, why="the LQR needs positive state weights Q"),
            "Q_velocity": Rule(**_POSITIVE, why="the LQR needs positive state weights Q"),
            "R": Rule(**_POSITIVE, why="the LQR needs positive definite torque weights R"),
            **COMMON},
}
#: controller class name -> law
LAW_OF_CLASS = {"NAController": "na", "APDController": "apd", "CTCController": "ctc",
                "LQRController": "lqr"}


def rule(law, field):
    """The :class:`Rule` of ``field`` in ``law`` (a law or a controller class name; None: a
    field every law shares, :data:`COMMON`)."""
    law = LAW_OF_CLASS.get(law, law)
    try:
        return COMMON[field] if law is None else RULES[law][field]
    except KeyError:
        raise ArgumentError(f"no parameter rule for {law!r} field {field!r}") from None


def violations(law, layout, params):
    """[(field, entry, value)] of every entry of the parameter vector ``params`` (a
    :class:`pm2dof.core.layout.Layout` ``layout``) that breaks its rule, in layout order."""
    p = np.asarray(params, dtype=float)
    out = []
    for field, _ in layout.fields:
        r = rule(law, field)
        x = p[layout.slices[field]]
        bound = p[layout.slices[r.below]] if r.below else None
        out += [(field, int(i), float(x[i])) for i in np.flatnonzero(~r.holds(x, bound))]
    return out


def check_entries(who, law, field, x, labels, bound=None, unit=""):
    """Raise :class:`pm2dof.GainError` (a gain) or :class:`pm2dof.ArgumentError` (another
    field) naming ``who`` (e.g. "NAController"), the field, the first entry of ``x`` that breaks
    its rule, its label in ``labels``, the value and the rule; ``bound``: the entries of the
    field the rule's ``below`` names. ``unit`` follows the value in the message."""
    r = rule(law, field)
    x = np.atleast_1d(np.asarray(x, dtype=float))
    bad = np.flatnonzero(~r.holds(x, bound))
    if not len(bad):
        return
    i = int(bad[0])
    more = f" (and {len(bad) - 1} more entries)" if len(bad) > 1 else ""
    name = r.name or field
    entry = f"{name}[{i}] ({labels[i]})" if len(x) > 1 or labels else name
    cond = r.condition if math.isfinite(x[i]) else "finite"
    if r.below and math.isfinite(x[i]):
        cond += f" = {float(np.asarray(bound, dtype=float)[i]):g}{unit}"
    what = f"{who}: {entry} = {float(x[i])!r}{unit} must be {cond}{more}: {r.why}"
    raise (GainError if r.gain else ArgumentError)(what)


def check_params(who, law, layout, params, labels=None):
    """:func:`check_entries` for every field of the packed vector ``params`` (``layout``);
    ``labels``: {field: entry labels} (default the entry numbers)."""
    p = np.asarray(params, dtype=float)
    for field, size in layout.fields:
        r = rule(law, field)
        lab = (labels or {}).get(field) or ([str(i + 1) for i in range(size)] if size > 1
                                            else [])
        check_entries(who, law, field, p[layout.slices[field]], lab,
                      p[layout.slices[r.below]] if r.below else None)
