# What every controller step shares besides its gains: the model file's defaults, checked once.
"""The settings of a controller's step that do not depend on its law.

Every controller (NA, APD, computed torque, LQR) packs the same fields after its gains into
its generated parameter vector (``<law>_params``, derive/controllers.py): the sample period
``T``, the velocity low-pass gain ``vel_alpha``, the two singularity thresholds, the effort
limits ``tau_max``, the preload split's ``preload_sign`` and ``preload``, and the encoders'
closure tolerance ``closure_tol``; and each runs one torque split. :class:`ControlSettings`
holds them: :meth:`ControlSettings.from_spec` is where they default to the model file
(``[sensing]``, ``[limits]``, ``[control]``) and where each is checked against its rule in
:data:`pm2dof.control.rules.RULES` (the table the exported C's ``init`` applies too). The
controllers take one (their ``settings`` argument) or build one from their keywords;
``pm2dof export`` reads the default parameter vectors from it.
"""
import math
from dataclasses import dataclass

import numpy as np

from ..core import task
from ..core.contract import SPLITS
from ..core.errors import ArgumentError, ArgumentTypeError
from . import rules

__all__ = ["ControlSettings", "actuator_limits", "checked_split", "per_actuator",
           "velocity_filter_alpha"]


def velocity_filter_alpha(sample_period, cutoff_hz):
    """Gain a of v_k = v_{k-1} + a ((x_k - x_{k-1})/T - v_{k-1}); cutoff 0: no filter (a = 1)."""
    if cutoff_hz == 0:
        return 1.0
    return sample_period / (sample_period + 1.0 / (2.0 * math.pi * cutoff_hz))


def per_actuator(name, value, n):
    """``value`` as (n,) floats: n finite numbers, or one for every actuator (as the planner
    and the CLI take it); ArgumentError naming ``name`` otherwise."""
    try:
        v = np.array(value, dtype=float)
    except (TypeError, ValueError):
        v = None
    if v is not None and v.ndim == 0:
        v = np.full(n, float(v))
    if v is None or v.shape != (n,) or not np.isfinite(v).all():
        raise ArgumentError(f"{name} must be one finite number or {n} (one per actuator), got "
                            f"{value!r}")
    return v


def actuator_limits(spec, tau_max=None, who="tau_max"):
    """The effort limits (n,): ``tau_max`` (one for every actuator or one each), or the model
    file's ``[limits] tau_max`` for None; N*m per revolute actuator, N per linear one.

    Raises ArgumentError naming ``who``, the leg, the value and the rule unless each limit is
    finite and in (0, 1e6] (:data:`pm2dof.control.rules.COMMON`'s ``tau_max``).

    Parameters
    ----------
    spec : pm2dof.core.model_file.ModelSpec
        The model file (``Model.spec``).
    tau_max : float or array_like (n,), optional
        The limits; the model file's when None.
    who : str
        What the messages name (a controller's class name, a command).
    """
    tau = per_actuator("tau_max", spec.limits["tau_max"] if tau_max is None else tau_max,
                       spec.n_legs)
    rules.check_entries(who, None, "tau_max", tau, _legs(spec), unit=_unit(spec))
    return tau


def _number(who, name, value):
    """``value`` as a float; ArgumentTypeError naming ``who`` and ``name`` for what is not a
    real number."""
    try:
        if isinstance(value, (str, bytes, bool)) or np.iscomplexobj(value):
            raise TypeError
        return float(value)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"{who}: {name} must be a real number, got {value!r}") from None


def _legs(spec):
    return [f"leg {i + 1}" for i in range(spec.n_legs)]


def _unit(spec):
    """The efforts' unit by the actuators' kinds after a space, for messages (" N m")."""
    return " " + task.per_actuator(spec.actuators, "N m", "N", "N m or N")


def checked_split(spec, split=None):
    """The torque split ``split``, or the model file's ``[control] split`` for None;
    ArgumentError unless it is one of :data:`SPLITS`."""
    out = spec.control["split"] if split is None else split
    if out not in SPLITS:
        raise ArgumentError(f"split must be one of {list(SPLITS)}, got {split!r}")
    return out


def _frozen(a):
    a = np.array(a, dtype=float)
    a.setflags(write=False)
    return a


@dataclass(frozen=True, eq=False)
class ControlSettings:
    """A controller step's settings besides its gains, checked (build with :meth:`from_spec`).

    Attributes
    ----------
    sample_period : float
        T, s: the step's sample period, in [1e-6, 1].
    velocity_filter_hz : float
        Cutoff of the velocity low-pass, Hz, >= 0 (0: the raw backward difference).
    tau_max : ndarray (n,)
        The effort limits, N*m per revolute actuator, N per linear one, in (0, 1e6].
    preload : ndarray (n,)
        The "preload" split's least |tau_i| (N*m or N by kind), >= 0 and below ``tau_max``.
    preload_sign : ndarray (n,)
        The "preload" split's signs, +-1.
    split : str
        The torque split: "min_norm" (eq. 21), "min_max" or "preload" (:data:`SPLITS`).
    singularity_threshold, parallel_singularity_threshold : float
        The type I and type II thresholds (``[limits]``), in (0, 1).
    closure_tolerance : float
        The largest closure residual of the encoders, m (``[sensing] closure_tolerance``), in
        (0, 0.1].
    """

    sample_period: float
    velocity_filter_hz: float
    tau_max: np.ndarray
    preload: np.ndarray
    preload_sign: np.ndarray
    split: str
    singularity_threshold: float
    parallel_singularity_threshold: float
    closure_tolerance: float

    @classmethod
    def from_spec(cls, spec, *, sample_period=None, velocity_filter_hz=None, tau_max=None,
                  split=None, preload=None, preload_sign=None, who="ControlSettings"):
        """The settings of the model file ``spec``, with the arguments given in their place.

        Each is checked against its rule (:data:`pm2dof.control.rules.RULES`): an
        :class:`~pm2dof.ArgumentError` naming ``who``, the setting, the entry (its leg), the
        value, the rule and why.

        Parameters
        ----------
        spec : pm2dof.core.model_file.ModelSpec
            The model file (``Model.spec``).
        sample_period : float, optional
            s (default ``[sensing] sample_period``).
        velocity_filter_hz : float, optional
            Hz; 0 for the raw backward difference (default ``[sensing] velocity_filter_hz``).
        tau_max : float or array_like (n,), optional
            Effort limits, one for every actuator or one each (default ``[limits] tau_max``).
        split : {"min_norm", "min_max", "preload"}, optional
            The torque split (default ``[control] split``).
        preload, preload_sign : float or array_like (n,), optional
            The "preload" split's least |tau_i| and signs (default ``[control]``).
        who : str
            What the messages name (a controller's class name).

        Returns
        -------
        ControlSettings
        """
        ctl, n = spec.control, spec.n_legs
        split = checked_split(spec, split)
        T = spec.sensing["sample_period"] if sample_period is None else _number(
            who, "sample_period", sample_period)
        fc = (spec.sensing["velocity_filter_hz"] if velocity_filter_hz is None
              else _number(who, "velocity_filter_hz", velocity_filter_hz))
        rules.check_entries(who, None, "T", T, (), unit=" s")
        if not (math.isfinite(fc) and fc >= 0):
            raise ArgumentError(f"velocity_filter_hz must be >= 0 (0: no filter), got {fc}")
        tau_max = actuator_limits(spec, tau_max, who)
        preload = per_actuator("preload", ctl["preload"] if preload is None else preload, n)
        preload_sign = per_actuator("preload_sign", ctl["preload_sign"] if preload_sign is None
                                    else preload_sign, n)
        rules.check_entries(who, None, "preload", preload, _legs(spec), tau_max,
                            unit=_unit(spec))
        rules.check_entries(who, None, "preload_sign", preload_sign, _legs(spec))
        out = cls(sample_period=T, velocity_filter_hz=fc, tau_max=_frozen(tau_max),
                  preload=_frozen(preload), preload_sign=_frozen(preload_sign), split=split,
                  singularity_threshold=spec.limits["singularity_threshold"],
                  parallel_singularity_threshold=spec.limits["parallel_singularity_threshold"],
                  closure_tolerance=spec.sensing["closure_tolerance"])
        # the model file's thresholds and closure tolerance, and the velocity gain
        for field in ("vel_alpha", "sing_threshold", "parallel_sing_threshold", "closure_tol"):
            rules.check_entries(who, None, field, out.params()[field], ())
        return out

    @classmethod
    def resolve(cls, spec, settings=None, *, who="ControlSettings", **overrides):
        """``settings`` as given, else :meth:`from_spec` of ``spec`` with ``overrides``: what a
        controller's ``settings`` argument and its keywords mean together.

        Raises :class:`~pm2dof.ArgumentTypeError` for a ``settings`` that is not a
        ControlSettings, and :class:`~pm2dof.ArgumentError` for one given together with a
        keyword (an override that is not None) or sized for another number of actuators.

        Parameters
        ----------
        spec : pm2dof.core.model_file.ModelSpec
            The model file (``Model.spec``).
        settings : ControlSettings, optional
            The settings to use as they are.
        who : str
            What the messages name (a controller's class name).
        **overrides
            The keywords of :meth:`from_spec` (None: the model file's).
        """
        if settings is None:
            return cls.from_spec(spec, who=who, **overrides)
        if not isinstance(settings, cls):
            raise ArgumentTypeError(f"{who}: settings must be a pm2dof.control.settings."
                                    f"ControlSettings, got {type(settings).__name__}")
        named = [k for k, v in overrides.items() if v is not None]
        if named:
            raise ArgumentError(f"{who}: give settings or {', '.join(named)}, not both (build "
                                f"the settings with ControlSettings.from_spec(model.spec, "
                                f"...))")
        checked_split(spec, settings.split)
        if len(settings.tau_max) != spec.n_legs:
            raise ArgumentError(f"{who}: the settings are for {len(settings.tau_max)} "
                                f"actuators, model {spec.name!r} has {spec.n_legs}")
        return settings

    @property
    def vel_alpha(self):
        """The velocity low-pass gain a in (0, 1] of the step (1: no filter), from
        ``sample_period`` and ``velocity_filter_hz``."""
        return velocity_filter_alpha(self.sample_period, self.velocity_filter_hz)

    def params(self):
        """{field: value} of the parameter fields every law's layout holds after its gains
        (``T``, ``vel_alpha``, ``sing_threshold``, ``parallel_sing_threshold``, ``tau_max``,
        ``preload_sign``, ``preload``, ``closure_tol``): what
        :meth:`pm2dof.core.layout.Layout.pack` takes."""
        return {"T": self.sample_period, "vel_alpha": self.vel_alpha,
                "sing_threshold": self.singularity_threshold,
                "parallel_sing_threshold": self.parallel_singularity_threshold,
                "tau_max": self.tau_max, "preload_sign": self.preload_sign,
                "preload": self.preload, "closure_tol": self.closure_tolerance}
