# Excitation signals: the Fourier series of a designed excitation and its file, the default multi-sine.
"""What an excitation is: a signal in task space with a known band, sampled as a Trajectory.

* :class:`FourierExcitation` -- a periodic finite Fourier series per task axis j (x, y, and a
  platform's phi: m = ``Model.dof`` series)
  (Swevers, Ganseman, Bilgin, De Schutter & Van Brussel, 1997), w_l = 2 pi l f0, l = 1..L::

      x_j(t)   = c_j + sum_l ( a_jl / w_l sin(w_l t) - b_jl / w_l cos(w_l t) )
      xd_j(t)  = sum_l ( a_jl cos(w_l t) + b_jl sin(w_l t) )
      xdd_j(t) = sum_l w_l ( -a_jl sin(w_l t) + b_jl cos(w_l t) )

  with sum_l a_jl = 0 and sum_l w_l b_jl = 0, so the motion starts and ends (after whole
  periods) at rest. :mod:`.design` chooses a, b, c; :func:`write_excitation` and
  :func:`load_excitation` are its file (TOML), read through :class:`pm2dof.core.validate.Problems`
  like model and study files: a bad file is one :class:`ExcitationError` listing every problem.
* :class:`MultiSine` -- the default excitation (:func:`multisine`): a smooth multi-sine
  around the middle of the model's first move, starting at rest.

Each has ``evaluate(t)``, ``duration`` (s) and ``max_hz`` (its highest frequency, the band the
fit's low-pass follows), and :meth:`~Signal.trajectory` samples it as a :class:`pm2dof.Trajectory`
(:meth:`pm2dof.Trajectory.from_samples`): what :func:`pm2dof.simulate` runs.
"""
import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..control.trajectory import Trajectory
from ..core.errors import ArgumentError, InputFileError
from ..core.task import orientation_length
from ..core.validate import Problems, entry
from .base import region_center
from .model_ref import ENTRIES, incomplete, mismatch, model_entries

__all__ = ["ExcitationError", "Signal", "FourierExcitation", "MultiSine", "multisine",
           "trajectory_of", "load_excitation", "write_excitation", "DEFAULT_DURATION",
           "MAX_DURATION", "AXES"]

#: s: the default multi-sine's length (``--duration``)
DEFAULT_DURATION = 4.0

#: the longest excitation run, s (an hour: 1.8 million samples at 2 ms)
MAX_DURATION = 3600.0


class ExcitationError(InputFileError):
    """An excitation file that cannot be used: names the file and lists every problem, each
    with its key (``excitation.a_x (harmonic 3)``), as model and study files do
    (:class:`~pm2dof.core.errors.InputFileError`)."""


class Signal:
    """An excitation signal: :meth:`evaluate` at any time, ``duration`` (s), ``max_hz``
    (highest frequency, Hz)."""

    def evaluate(self, t):
        """Position, velocity, acceleration (N, m) at times t (N,)."""
        raise NotImplementedError

    def trajectory(self, period):
        """The signal sampled every ``period`` s over its ``duration``: a
        :class:`pm2dof.Trajectory` (:meth:`~pm2dof.Trajectory.from_samples`).

        Parameters
        ----------
        period : float
            Sampling period, s.
        """
        t = np.arange(int(round(self.duration / period)) + 1) * period
        return Trajectory.from_samples(*self.evaluate(t), period)


def trajectory_of(model, signal, period=None):
    """``signal`` (a :class:`Signal`) sampled at the controller period (default the model's
    ``[sensing].sample_period``): a :class:`pm2dof.Trajectory`."""
    return signal.trajectory(model.checked_period(period))


@dataclass(frozen=True)
class FourierExcitation(Signal):
    """A periodic finite Fourier series in task space (see the module docstring).

    Attributes
    ----------
    base_hz : float
        f0, Hz (the period is 1 / f0).
    periods : int
        Whole periods the run lasts.
    center : ndarray (m,)
        c, m (rad for phi); m = ``Model.dof``, the axes ``Model.task_names``.
    a, b : ndarray (m, L)
        Coefficients, m/s (rad/s for phi), per axis (x, y[, phi]) and harmonic.
    info : dict
        What the design reported (limits, objective, condition numbers), for the file.
    model : dict
        The model a file records (``model``, ``model_name``, ``formulation_sha256``:
        :mod:`.model_ref`) as read by :func:`load_excitation`; empty for a design in memory.
    """
    base_hz: float
    periods: int
    center: np.ndarray
    a: np.ndarray
    b: np.ndarray
    info: dict = field(default_factory=dict)
    model: dict = field(default_factory=dict)

    harmonics = property(lambda self: self.a.shape[1])
    max_hz = property(lambda self: self.base_hz * self.harmonics, doc="highest harmonic, Hz")
    duration = property(lambda self: self.periods / self.base_hz, doc="s")

    def evaluate(self, t):
        """Position (N, m) m, velocity (N, m) m/s, acceleration (N, m) m/s^2 at times t (N,)
        (phi in rad, rad/s, rad/s^2)."""
        t = np.asarray(t, dtype=float)[:, None]
        w = 2 * np.pi * self.base_hz * np.arange(1, self.harmonics + 1)
        s, c = np.sin(w * t), np.cos(w * t)
        x = self.center + (s / w) @ self.a.T - (c / w) @ self.b.T
        return x, c @ self.a.T + s @ self.b.T, (-s * w) @ self.a.T + (c * w) @ self.b.T


@dataclass(frozen=True)
class MultiSine(Signal):
    """x_j(t) = offset_j + sum_k amplitude_jk (1 - cos(omega_jk t)) per task axis j: at rest at
    t = 0 (:func:`multisine` chooses the numbers).

    Attributes
    ----------
    offset : ndarray (m,)
        x(0), m (rad for an orientation).
    amplitude : ndarray (m, K)
        Per axis and harmonic, m (rad).
    omega : ndarray (m, K)
        Angular frequencies, rad/s.
    duration : float
        s.
    max_hz : float
        The highest frequency, Hz.
    """
    offset: np.ndarray
    amplitude: np.ndarray
    omega: np.ndarray
    duration: float
    max_hz: float

    def evaluate(self, t):
        """Position, velocity, acceleration (N, m) at times t (N,)."""
        t = np.asarray(t, dtype=float)
        m, K = np.shape(self.amplitude)
        xd, xd_dot, xd_ddot = (np.zeros((len(t), m)) for _ in range(3))
        for axis in range(m):
            for k in range(K):
                w, a = self.omega[axis, k], self.amplitude[axis, k]
                xd[:, axis] += a * (1 - np.cos(w * t))
                xd_dot[:, axis] += a * w * np.sin(w * t)
                xd_ddot[:, axis] += a * w * w * np.cos(w * t)
        xd += self.offset
        return xd, xd_dot, xd_ddot


def multisine(model, duration=DEFAULT_DURATION, amplitude=0.02, seed=1, harmonics=4,
              base_hz=0.75):
    """The default excitation: a smooth multi-sine around the middle of the model's first move,
    starting at rest.

    x(t) = c + sum_k a_k (1 - cos(w_k t)) per task axis (each axis' frequencies 13 % higher
    than the previous one's); velocity is zero at t = 0. A platform's phi moves by amplitude /
    l rad (l its orientation length, :func:`pm2dof.core.task.orientation_length`).

    Returns
    -------
    MultiSine
        Of the model's task dimension m; :func:`trajectory_of` samples it at the model's period.
    """
    if not (isinstance(duration, (int, float)) and np.isfinite(duration)
            and 0 < duration <= MAX_DURATION):
        raise ArgumentError(f"duration must be a number of seconds in (0, {MAX_DURATION:g}], "
                            f"got {duration!r}")
    rng = np.random.default_rng(seed)
    m = model.dof
    scale = np.ones(m)                         # m per m of amplitude; phi: rad per m
    if m == 3:
        scale[2] = 1.0 / orientation_length(model)
    amp, omega = np.zeros((m, harmonics)), np.zeros((m, harmonics))
    for axis in range(m):
        for k in range(1, harmonics + 1):
            omega[axis, k - 1] = 2 * np.pi * base_hz * k * (1.0 + 0.13 * axis)
            amp[axis, k - 1] = (amplitude / harmonics * rng.uniform(0.5, 1.0)
                                * rng.choice([-1, 1]) * scale[axis])
    return MultiSine(offset=region_center(model) - amplitude / 2 * scale, amplitude=amp,
                     omega=omega, duration=float(duration),
                     max_hz=base_hz * harmonics * (1.0 + 0.13 * (m - 1)))    # Hz


# ---- the file of a Fourier excitation ----

def _toml_list(v):
    return "[" + ", ".join(format(float(x), ".17g") for x in np.ravel(v)) + "]"


def _toml_value(v):
    if isinstance(v, str):
        return json.dumps(v)            # a TOML basic string
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (list, tuple, np.ndarray)):
        return _toml_list(v)
    return repr(int(v)) if isinstance(v, (int, np.integer)) else repr(float(v))


def write_excitation(path, exc, model):
    """Write ``exc`` as TOML (``[excitation]``: the model, :mod:`.model_ref`, a model file by its
    path relative to ``path``'s folder, and the coefficients, ``a_<axis>`` and ``b_<axis>`` per
    task axis: x and y, and phi for a platform; ``[design]`` its ``info``, a dict value such as
    ``ipopt`` or ``provenance`` as the sub-table ``[design.<key>]``), atomically. The text is a
    function of ``exc``, the model and the file's folder only."""
    from ..infra.results import write_atomic
    entries = model_entries(model, Path(path).parent)
    axes = AXES[:len(exc.center)]
    phi = len(axes) == 3
    lines = ["# pm2dof excitation: periodic finite Fourier series in task space (Swevers et al. "
             "1997)",
             "# x_j(t) = center_j + sum_l a_jl/w_l sin(w_l t) - b_jl/w_l cos(w_l t), "
             f"w_l = 2 pi l base_hz; j = {', '.join(axes)}",
             "# run it: pm2dof identify excite --excitation THIS_FILE --out run.csv", "",
             "[excitation]", *(f"{k} = {_toml_value(v)}" for k, v in entries.items()),
             f"base_hz = {exc.base_hz!r}", f"periods = {int(exc.periods)}",
             f"center = {_toml_list(exc.center)}   # m{', m, rad' if phi else ''}"]
    for letter, coef in (("a", exc.a), ("b", exc.b)):
        lines += [f"{letter}_{axis} = {_toml_list(coef[j])}"
                  + {"x": "   # m/s", "y": "", "phi": "   # rad/s"}[axis]
                  for j, axis in enumerate(axes)]
    lines.append("")
    if exc.info:
        tables = {k: v for k, v in exc.info.items() if isinstance(v, dict)}
        lines.append("[design]")
        lines += [f"{k} = {_toml_value(v)}" for k, v in exc.info.items() if k not in tables]
        for name, table in tables.items():
            lines += ["", f"[design.{name}]"] + [f"{k} = {_toml_value(v)}"
                                                 for k, v in table.items()]
    write_atomic(path, ("\n".join(lines) + "\n").encode())
    return path


#: the task axes of an excitation file's series (``Model.task_names`` of a point and a platform)
AXES = ("x", "y", "phi")


def _coefficient_keys(m):
    """[excitation]'s coefficient keys of an m-axis file: a_x, a_y[, a_phi], b_x, b_y[, b_phi]."""
    return tuple(f"{letter}_{axis}" for letter in "ab" for axis in AXES[:m])


def _coefficients(pr, e, key):
    """[excitation].``key``: a non-empty list of finite numbers, one per harmonic (m/s)."""
    value, where = e[key], f"excitation.{key}"
    if not isinstance(value, list) or not value:
        return pr.add(where, f"must be a non-empty list of numbers, one per harmonic, got "
                             f"{type(value).__name__} {value!r}")
    out = [pr.number(entry(where, f"harmonic {l + 1}"), v) for l, v in enumerate(value)]
    return None if None in out else out


def load_excitation(path, model=None):
    """Read an excitation file (TOML, as :func:`write_excitation` writes it).

    Parameters
    ----------
    path : str or Path
    model : Model, optional
        Check that the file was made for this model (:func:`.model_ref.mismatch`: by name and
        formulation hash; a file that records no model is taken as this model's).

    Returns
    -------
    FourierExcitation
        Its ``model``: the model entries the file records.

    Raises
    ------
    ExcitationError
        Every problem of the file at once: unreadable or not TOML, a missing, unknown or
        malformed key (named), coefficients of different lengths or not starting at rest; or
        another model's file.
    """
    pr = Problems(path, ExcitationError)
    _, d = pr.read_toml("excitation file")
    pr.keys("", d, {"excitation", "design"})
    e = pr.table("excitation", d.get("excitation"))
    if e is None:
        pr.raise_if_any()
    # a platform's file has a phi series too (a_phi, b_phi); a point's, x and y only
    m = 3 if {"a_phi", "b_phi"} & set(e) else 2
    coefficient_keys = _coefficient_keys(m)
    pr.keys("excitation", e, {*ENTRIES, "design", "base_hz", "periods", "center",
                              *_coefficient_keys(3)},
            ("base_hz", "periods", "center", *coefficient_keys))
    entries = {k: pr.text(f"excitation.{k}", e[k], nonempty=True) for k in (*ENTRIES, "design")
               if k in e}
    old = incomplete(entries, "[excitation]")
    if old is not None:
        pr.add(None, old)
    f0 = pr.number("excitation.base_hz", e["base_hz"], low=0.0, low_ok=False) \
        if "base_hz" in e else None
    periods = pr.number("excitation.periods", e["periods"], integer=True, low=1) \
        if "periods" in e else None
    center = pr.vector("excitation.center", e["center"], AXES[:m],
                       meaning=", m" if m == 2 else " (x, y in m, phi in rad): a_phi and b_phi "
                       "make it a platform's") if "center" in e else None
    design = pr.table("design", d.get("design"), required=False) or {}
    coef = {k: _coefficients(pr, e, k) for k in coefficient_keys if k in e}
    lengths = {k: len(v) for k, v in coef.items() if v is not None}
    if len(set(lengths.values())) > 1:
        pr.add("excitation", f"{', '.join(coefficient_keys)} need one number per harmonic each, "
                             f"got lengths {lengths}")
    pr.raise_if_any()
    msg = None if model is None else mismatch(model, entries, Path(path).parent, str(path))
    if msg:
        raise ExcitationError(msg, path=path)
    if model is not None and model.dof != m:
        raise ExcitationError(f"{path} has series for ({', '.join(AXES[:m])}), but model "
                              f"{model.name!r} has task {model.task_names}", path=path)
    a = np.array([coef[f"a_{axis}"] for axis in AXES[:m]], dtype=float)
    b = np.array([coef[f"b_{axis}"] for axis in AXES[:m]], dtype=float)
    exc = FourierExcitation(f0, periods, np.array(center, dtype=float), a, b, dict(design),
                            entries)
    _, v, acc = exc.evaluate([0.0])
    if np.abs(np.concatenate([v[0], acc[0]])).max() > 1e-9 * (1 + np.abs(a).max() * f0):
        pr.stop(None, f"the motion does not start at rest (sum of "
                      f"{', '.join(coefficient_keys[:m])} and of "
                      f"{', '.join('w_l ' + k for k in coefficient_keys[m:])} must be 0)")
    return exc
