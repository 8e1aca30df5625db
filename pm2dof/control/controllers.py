# NA (eqs. 14-29), APD (eq. 40) and computed-torque (CTC) controllers: one C call per sample.
"""Task-space controllers of the paper, each step one call into the generated C.

A step runs the whole chain of Fig. 2: end-effector position by fk from the measured active
angles, velocity by a first-order low-pass on the backward difference, the passive joints
from geometry, the control law, the minimum-norm torque split (eq. 21) and, for NA, the
parameter update (eq. 28, explicit Euler over the sample period). Torques are clipped to
``limits.tau_max``; at a pose closer to a singularity of either kind than its threshold
(``limits.singularity_threshold``: type I, a leg; ``limits.parallel_singularity_threshold``:
type II, the actuation) the step outputs the safe torque zero and leaves theta_hat unchanged
(see ``status``).

What every controller shares besides its gains (the sample period, the velocity filter, the
limits, the split, the model file's thresholds) is one
:class:`~pm2dof.control.settings.ControlSettings`, given as ``settings`` or built from the
same keywords; :func:`law_params` packs a law's parameter vector from its gains and the
settings. The time-varying LQR's step is :mod:`pm2dof.control.lqr`.
"""
import math

import numpy as np

from ..core import binding
from ..core.contract import SPLITS
from ..core.errors import (
    ArgumentError,
    ArgumentTypeError,
    GainError,
    ModelMismatchError,
    NotResetError,
    SingularityError,
)
from ..core.model import require_model
from ..core.status import STATUS_NAMES, Status
from . import rules
from .settings import ControlSettings

__all__ = ["NAController", "APDController", "CTCController", "STATUS_NAMES", "Status",
           "check_same_model", "CTC_DEFAULT_GAINS", "default_gains", "law_params"]

_SINGULAR = float(Status.SINGULAR)   # the hot path compares a float (an Enum lookup: ~60 ns)
#: law -> its controller's class name (the name its messages give)
_CLASS_OF_LAW = {law: name for name, law in rules.LAW_OF_CLASS.items()}
#: law -> its parameter fields beyond the gains and the settings, at their defaults (NA's
#: freeze_saturated: 0, adapt on every good sample, the paper's law)
_OPTIONS = {"na": {"freeze_saturated": 0.0}}


def _checked_on_singular(value):
    if value not in ("raise", "zero"):
        raise ArgumentError(f"on_singular must be 'raise' or 'zero', got {value!r}")
    return value


#: CTCController's gains when the model file has no [gains.ctc]: on every task axis a
#: critically damped pair at omega = 2 pi 20 Hz (Kp = omega^2 1/s^2, Kv = 2 omega 1/s), a tenth
#: of the 2 ms sample rate, like APD's Kp, Kv over the paper robot's Me (about 1 kg); scalars,
#: so they apply to any task dimension m
CTC_DEFAULT_GAINS = {"Kp": (2 * math.pi * 20) ** 2, "Kv": 2 * (2 * math.pi * 20)}


def diagonal_gain(law, name, value, labels):
    """The diagonal of a gain matrix of the control law, checked against its rule.

    The gains of eqs. 14-29 and 40 are diagonal matrices, applied entry by entry in the
    generated C. ``value`` may be a scalar (every entry alike), the k diagonal entries, or a
    diagonal k x k matrix (k = len(labels)). Raises :class:`GainError` naming the gain, the
    entry and the condition: a wrong shape, an off-diagonal entry, a non-finite entry, or an
    entry outside its rule in :data:`pm2dof.control.rules.RULES` (<= 0; Gamma: < 0). ``law``:
    the controller's class name ("NAController"). Returns the (k,) float64 diagonal.
    """
    k = len(labels)
    where = f"{law}: {name}"
    try:
        if np.iscomplexobj(value):
            raise ArgumentTypeError("complex values are not allowed")
        a = np.array(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise GainError(f"{where} must be real numbers, got {value!r} ({exc})") from None
    if a.ndim == 2 and a.shape == (k, k):
        off = np.argwhere((a != 0) & ~np.eye(k, dtype=bool))
        if len(off):
            i, j = off[0]
            raise GainError(f"{where} must be diagonal (the law applies it entry by entry); "
                            f"entry [{i}, {j}] = {float(a[i, j])!r}")
        a = np.diag(a).copy()
    elif a.ndim == 0:
        a = np.full(k, float(a))
    if a.shape != (k,):
        raise GainError(f"{where} must be a scalar, {k} diagonal entries ({', '.join(labels)}) "
                        f"or a diagonal {k} x {k} matrix, got shape {a.shape}")
    rules.check_entries(law, law, name, a, labels)
    return a


def check_same_model(model, controller):
    """Raise :class:`ModelMismatchError` unless ``controller`` was built for ``model``: the same
    Model, or one with the same name, formulation hash (the same generated code) and design
    (:meth:`Model.at_design`: the controller's steps are bound to its model's geometry)."""
    cm = controller.model
    if cm is model or ((cm.name, cm.spec.formulation_sha256) == (model.name,
                                                                 model.spec.formulation_sha256)
                       and np.array_equal(cm.design, model.design)):
        return

    def who(m):
        design = f", design {m.spec.design.describe()}" if m.spec.design is not None else ""
        return (f"{m.name!r} ({m.n_legs} legs, {m.spec.path}, formulation "
                f"{m.spec.formulation_sha256[:12]}{design})")
    raise ModelMismatchError(
        f"the {type(controller).__name__} was built for model {who(cm)}, not for model "
        f"{who(model)}; build the controller with the model it runs on")


def default_gains(spec, law):
    """{gain: value} of ``law`` in the model file ``spec``: ``[gains.<law>]`` (computed torque
    without one: :data:`CTC_DEFAULT_GAINS`). The LQR's parameter vector holds no gains (its
    K_k are inputs of each step): {}.

    Parameters
    ----------
    spec : pm2dof.core.model_file.ModelSpec
        The model file (``Model.spec``).
    law : {"na", "apd", "ctc", "lqr"}
        The control law.
    """
    if law == "ctc":
        return dict(spec.gains.get("ctc") or CTC_DEFAULT_GAINS)
    return dict(spec.gains[law]) if law in ("na", "apd") else {}


def law_params(model, law, gains=None, settings=None, options=None, who=None):
    """The parameter vector of ``law``'s generated step (layout ``<law>_params``), checked.

    The gains (each given or the model file's, :func:`default_gains`; checked by
    :func:`diagonal_gain`), then the settings' fields (:meth:`ControlSettings.params`) and the
    law's options (NA's ``freeze_saturated``, default 0), packed and checked entry by entry
    against :data:`pm2dof.control.rules.RULES`, the rules the exported C's init applies.
    What a controller of ``law`` built with the same arguments steps with (its ``params``);
    ``pm2dof export`` writes it as the law's defaults.

    Parameters
    ----------
    model : Model
    law : {"na", "apd", "ctc", "lqr"}
        The control law.
    gains : dict, optional
        {gain: value or None (the model file's)}, in the order they are checked; default the
        model file's gains of ``law``.
    settings : ControlSettings, optional
        Default :meth:`ControlSettings.from_spec` of the model file.
    options : dict, optional
        The law's options by field (NA: ``freeze_saturated``, 0 or 1).
    who : str, optional
        What the messages name (default the law's controller class, "NAController").

    Returns
    -------
    ndarray (k,)
        Read-only, in the layout's order.
    """
    who = who or _CLASS_OF_LAW[law]
    if settings is None:
        settings = ControlSettings.from_spec(model.spec, who=who)
    defaults = default_gains(model.spec, law)
    gains = defaults if gains is None else {k: defaults[k] if v is None else v
                                            for k, v in gains.items()}
    labels = {"Gamma": model.param_names}
    gains = {k: diagonal_gain(who, k, v, labels.get(k, model.task_names))
             for k, v in gains.items()}
    layout = model.layout(f"{law}_params")
    params = layout.pack(**gains, **settings.params(), **{**_OPTIONS.get(law, {}),
                                                          **(options or {})})
    # every entry against pm2dof.control.rules, the rules the exported C's init applies
    # (the model's thresholds and closure tolerance, the velocity gain, the options)
    legs = [f"leg {i + 1}" for i in range(model.n_legs)]
    rules.check_params(who, law, layout, params,
                       {"Gamma": model.param_names, "tau_max": legs, "preload": legs,
                        "preload_sign": legs, **{k: model.task_names for k in gains}})
    params.setflags(write=False)
    return params


class _Controller:
    """What every controller shares: its settings, its parameter vector, the step's fast path
    (one C call) and its checked path. ``gains``: {gain: value or None}; ``options``: the law's
    options (:func:`law_params`)."""
    _law = ""

    def __init__(self, model, base, gains, theta0, settings, on_singular, options=None):
        self._on_singular = _checked_on_singular(on_singular)
        self.model = model
        self.settings = settings
        self.split = settings.split
        self.function_name = base + SPLITS[self.split]   # generated <name>_<function_name>_step
        self.state_layout = model.layout("ctrl_state")
        self.params_layout = model.layout(f"{self._law}_params")
        self.sample_period = settings.sample_period
        self.theta0 = model.checked_theta(theta0, "theta0")
        n = model.n_legs
        self.params = law_params(model, self._law, gains, settings, options, type(self).__name__)
        self._f = f = model.function(f"{self.function_name}_step")
        self._state, self._state_next = (np.zeros(self.state_layout.size),
                                         np.zeros(self.state_layout.size))
        self._n = n
        self._status = np.zeros(1)
        self._diag = np.zeros(model.layout("diag").size)  # the step's diag (the manifest's)
        # the step's fast path, one C call: state and params bound here (checked once, now),
        # state <- state_next after the evaluation, a singular status reported (GuardTripped)
        # when on_singular is "raise"; what it refuses takes _refused's checked path
        self._method = binding.Method(
            f, (self._state, None, None, None, None, self.params) + (None,) * (f.n_in - 6),
            ((n,), self._state_next, self._status, self._diag), empty=np.empty,
            guard=(2, "not_equal", _SINGULAR), feedback=(1, 0))
        self._method.guard_on = on_singular == "raise"
        self._run = self._not_reset

    def closed_loop_inputs(self, trajectory):
        """The closed loop's per-sample inputs along ``trajectory``: (N, 3m) rows [xd, xd_dot,
        xd_ddot] (a law with per-sample gains appends them, ``<law>_cl_input`` layout).

        Parameters
        ----------
        trajectory : Trajectory
            The desired motion, N samples of ``xd``, ``xd_dot``, ``xd_ddot`` (N, m) each.
        """
        return np.ascontiguousarray(np.hstack([trajectory.xd, trajectory.xd_dot,
                                               trajectory.xd_ddot]))

    def reset(self, qa0, theta_hat=None):
        """Start at rest at the measured active angles ``qa0`` (n,), rad.

        ``theta_hat`` (p,) replaces the initial estimate (default: ``theta0``, Tables 1-2).

        Parameters
        ----------
        qa0 : array_like (n,)
            Measured active angles, rad, closing every loop (``model.fk`` accepts them).
        theta_hat : array_like (p,), optional
            Initial parameter estimate, in ``model.param_names`` order; ``theta0`` when None.
        """
        th = self.theta0 if theta_hat is None else np.array(theta_hat, dtype=float)
        if th.shape != self.theta0.shape or not np.isfinite(th).all():
            raise ArgumentError(f"theta_hat must be {len(th)} finite numbers "
                             f"({', '.join(self.model.param_names)}), got {th.tolist()}")
        xe = self.model.fk(qa0)
        s = self.state_layout.unpack(self._state)
        s["xe_prev"][:] = xe
        s["v"][:] = 0.0
        s["theta_hat"][:] = th
        self._run = self._method

    @staticmethod
    def _not_reset(*args):
        raise NotResetError("call reset(qa0) with the measured active angles before the first "
                            "step: it sets the starting pose and theta_hat")

    @property
    def on_singular(self):
        """What ``step`` does at a singular pose: "raise" SingularityError, or "zero" (return
        the safe torque zero)."""
        return self._on_singular

    @on_singular.setter
    def on_singular(self, value):
        self._on_singular = _checked_on_singular(value)
        self._method.guard_on = value == "raise"

    def step(self, qa_meas, xd, xd_dot, xd_ddot, out=None):
        """One control sample: measured active angles (n,) rad and the desired pose (m,) m,
        velocity (m,) m/s and acceleration (m,) m/s^2 (m = ``model.dof``, in
        ``model.task_names`` order; phi in rad) -> actuator torques tau_a (n,) N*m.

        Returns a new array, or writes into ``out`` (n,) and returns it (no allocation).
        Non-finite inputs raise ArgumentError (a ValueError) and leave the controller unchanged. At a pose
        closer to a singularity of either kind than its threshold the step raises
        SingularityError (a ValueError), or with ``on_singular="zero"`` returns the safe
        torque zero; either way theta_hat is not updated (``status == "singular"``). A
        non-finite intermediate result gives zero torque and leaves the whole state as it
        was (``status == "non_finite"``). Encoder angles that do not close the loops give
        zero torque and leave the state as it was (``status == "inconsistent_encoders"``). The
        next good sample gives a finite torque. Before :meth:`reset` it raises NotResetError
        (a RuntimeError).

        Inputs may be any array-likes of real numbers (lists, float32, ...): they are converted
        once, and a wrong length raises ArgumentError (a ValueError) naming the input. C-contiguous float64
        arrays go straight to the C (the fast path, no conversion).

        Parameters
        ----------
        qa_meas : array_like (n,)
            Measured active (encoder) angles, rad.
        xd : array_like (m,)
            Desired pose, m (rad for phi).
        xd_dot : array_like (m,)
            Desired velocity, m/s (rad/s for phi).
        xd_ddot : array_like (m,)
            Desired acceleration, m/s^2 (rad/s^2 for phi).
        out : ndarray (n,), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._run(qa_meas, xd, xd_dot, xd_ddot, out)
        except binding.Refused as exc:
            return self._refused(exc, (qa_meas, xd, xd_dot, xd_ddot), out)

    def _refused(self, exc, given, out, extra=()):
        """After the fast path refused a step: at a singular pose (GuardTripped: the step ran,
        theta_hat kept) raise SingularityError; otherwise nothing ran, so take the checked
        path: the inputs ``given`` converted once and the step run, what the binding refuses
        raised as ArgumentError. ``extra``: the inputs after the parameters (a law's
        per-sample inputs: the LQR's K_k, tau_ff_k)."""
        if isinstance(exc, binding.GuardTripped):
            raise self._singular_error() from None
        tau = np.empty(self._n) if out is None else out  # the C checks out's dtype and size
        binding.call(self._f, (self._state, *given, self.params, *extra),
                     (tau, self._state_next, self._status, self._diag))
        self._state[:] = self._state_next
        if self._status[0] == _SINGULAR and self._on_singular == "raise":
            raise self._singular_error()
        return tau

    def _singular_error(self):
        return SingularityError(
            f"controller step: {self.model.singularity_message(self._diag[-2:])}; "
            f"theta_hat was not updated and the safe torque is zero (on_singular='zero' "
            f"returns it instead of raising)")

    @property
    def status(self):
        """What the last step did: "ok", "singular" (zero torque), "saturated" (clipped),
        "non_finite" (zero torque, state kept), "preload_infeasible" (the preload split could
        not keep every preload within the limits: the largest worst-case preload instead) or
        "inconsistent_encoders" (the encoders do not close the loops within ``[sensing]
        closure_tolerance``: zero torque, state kept). :class:`pm2dof.Status` names them."""
        return STATUS_NAMES[int(self._status[0])]

    @property
    def state(self):
        """Copy of the controller state: dict of xe_prev (m,), v (m,), theta_hat (p,)."""
        return {k: v.copy() for k, v in self.state_layout.unpack(self._state).items()}

    @property
    def diag(self):
        """Last step's signal processing: dict of xe (m,) m, v (m,) m/s, e (m,) m, edot (m,) m/s,
        sing (type I measure min_i |sin(qb_i - qa_i)|) and sing_parallel (type II measure, see
        :meth:`pm2dof.Model.singularity_measures`)."""
        d = self.model.layout("diag").unpack(self._diag.copy())
        sing = d.pop("sing")
        return {**d, "sing": float(sing[0]), "sing_parallel": float(sing[1])}


class NAController(_Controller):
    """The nonlinear adaptive controller (eqs. 14-29), gains of Sect. 5 by default.

    Parameters
    ----------
    model : Model
    Kd, Q : float or array_like (m,) or (m, m), optional
        Diagonal gains K_d (N*s/m) and Q (1/s), each entry > 0 (positive definite, as the
        Lyapunov argument of Sect. 4 needs): a scalar, the diagonal in ``model.task_names``
        order ([x, y] for a point) or a diagonal matrix (default: ``[gains.na]`` of the model file).
    Gamma : float or array_like (p,) or (p, p), optional
        Diagonal adaptation gain in ``model.param_names`` order, each entry >= 0 (positive
        semi-definite); zeros switch adaptation off. Gains outside these conditions, non-finite
        or of the wrong shape raise :class:`pm2dof.GainError` naming the gain and the entry.
    theta0 : array_like (p,), optional
        Initial estimate theta_hat (default: Tables 1-2, ``model.theta_nominal``).
    sample_period : float, optional
        s (default ``[sensing].sample_period``, 0.002).
    velocity_filter_hz : float, optional
        Cutoff of the velocity low-pass, Hz; 0 for the raw backward difference.
    tau_max : float or array_like (n,), optional
        Torque limits, N*m, one for every actuator or one each (default ``[limits].tau_max``).
    project : bool
        Project theta_hat after each update onto physical values: alpha_i, gamma_i >= 1e-6
        kg m^2, beta_i^2 <= alpha_i gamma_i (each RR leg's inertia block positive
        semi-definite), friction parameters >= 0; the platform's parameters and first moments
        are left as they are. Its own generated step (``<name>_na_proj_step``), so the default
        pays nothing for it. Off by default, as in the paper.
    freeze_when_saturated : bool
        Hold theta_hat on a sample whose torque was clipped (status "saturated"): the
        actuators did not apply the law's u, and eq. 28 would go on integrating an error they
        cannot act on (a robot held at its start while the reference moves on drives
        theta_hat without bound). A parameter of the generated step (``freeze_saturated``), so
        the step, :func:`pm2dof.simulate` and the exported C do the same. Off by default, as in
        the paper.
    on_singular : {"raise", "zero"}
        What ``step`` does at a singular pose: raise SingularityError, or return zeros.
    split : {"min_norm", "min_max", "preload"}, optional
        How S^T tau_a = u is shared among the n actuators (default ``[control] split``,
        "min_norm"): "min_norm" is eq. 21; "min_max" minimises max_i |tau_i| / tau_max,i (delays
        saturation); "preload" keeps sign preload_sign_i and |tau_i| >= preload_i with the
        least 2-norm (against backlash), else the largest worst-case preload the limits allow
        (status "preload_infeasible"). Every split gives the same S^T tau_a to rounding. Each
        is an exact optimum, generated as its own C step (docs/results-redundancy.md).
    preload, preload_sign : float or array_like (n,), optional
        The "preload" split's least |tau_i|, N*m, and signs +-1 (default ``[control]``).
    settings : pm2dof.control.settings.ControlSettings, optional
        All of ``sample_period``, ``velocity_filter_hz``, ``tau_max``, ``split``, ``preload``
        and ``preload_sign`` at once, checked
        (:meth:`~pm2dof.control.settings.ControlSettings.from_spec`); not with any of them.

    Notes
    -----
    To pause adaptation without losing the state, set :attr:`adapting` to False: Gamma is
    zero in the step's parameters until it is set back to True, so eq. 28 adds nothing and
    theta_hat, the pose and the velocity estimate carry on (a new controller with
    ``Gamma=0`` would start again from ``reset``). The exported C does the same with
    ``<name>_pm2dof_na_set_params`` (docs/deploying.md).
    """
    _law = "na"

    def __init__(self, model, *, Kd=None, Q=None, Gamma=None, theta0=None, sample_period=None,
                 velocity_filter_hz=None, tau_max=None, project=False,
                 freeze_when_saturated=False, on_singular="raise", split=None, preload=None,
                 preload_sign=None, settings=None):
        require_model(model)
        for name, value in (("project", project),
                            ("freeze_when_saturated", freeze_when_saturated)):
            if not isinstance(value, (bool, np.bool_)):
                raise ArgumentTypeError(f"{name} must be True or False, got {value!r}")
        self.project = bool(project)
        self.freeze_when_saturated = bool(freeze_when_saturated)
        settings = ControlSettings.resolve(
            model.spec, settings, who="NAController", sample_period=sample_period,
            velocity_filter_hz=velocity_filter_hz, tau_max=tau_max, split=split, preload=preload,
            preload_sign=preload_sign)
        super().__init__(model, "na_proj" if self.project else "na",
                         {"Kd": Kd, "Q": Q, "Gamma": Gamma}, theta0, settings, on_singular,
                         {"freeze_saturated": float(self.freeze_when_saturated)})
        self._gamma = self.params[self.params_layout.slices["Gamma"]].copy()
        self._adapting = True

    @property
    def theta_hat(self):
        """Current estimate theta_hat (p,), in ``model.param_names`` order (a copy)."""
        return self.state["theta_hat"]

    @property
    def adapting(self):
        """Whether the step updates theta_hat (eq. 28); set False to pause adaptation and
        True to resume it, keeping the whole state (theta_hat, the pose, the velocity
        estimate). While paused, ``params``' Gamma is zero (:func:`pm2dof.simulate` of this
        controller runs without adaptation too)."""
        return self._adapting

    @adapting.setter
    def adapting(self, value):
        if not isinstance(value, (bool, np.bool_)):
            raise ArgumentTypeError(f"adapting must be True or False, got {value!r}")
        self.params.setflags(write=True)      # in place: the bound C call reads this array
        try:
            self.params[self.params_layout.slices["Gamma"]] = self._gamma if value else 0.0
        finally:
            self.params.setflags(write=False)
        self._adapting = bool(value)


class APDController(_Controller):
    """The augmented PD controller of eq. 40 with the nominal model (Tables 1-2).

    Parameters are those of :class:`NAController` with ``Kp`` (N/m), ``Kv`` (N*s/m) in place
    of the NA gains (diagonal, each entry > 0, else :class:`pm2dof.GainError`); ``theta0`` is
    the fixed model inside the feedforward; ``split``, ``preload`` and ``preload_sign`` as for
    NA.

    Parameters
    ----------
    model : Model
    Kp : float or array_like (m,) or (m, m), optional
        Diagonal stiffness, N/m (N m/rad for phi), each entry > 0 (default ``[gains.apd]``
        of the model file).
    Kv : float or array_like (m,) or (m, m), optional
        Diagonal damping, N*s/m (N m s/rad for phi), each entry > 0. Gains outside these
        conditions raise :class:`pm2dof.GainError` naming the gain and the entry.
    theta0 : array_like (p,), optional
        The model inside the feedforward (default Tables 1-2); never updated.
    sample_period, velocity_filter_hz, tau_max, on_singular, split, preload, preload_sign, settings
        As for :class:`NAController`.
    """
    _law = "apd"

    def __init__(self, model, *, Kp=None, Kv=None, theta0=None, sample_period=None,
                 velocity_filter_hz=None, tau_max=None, on_singular="raise", split=None,
                 preload=None, preload_sign=None, settings=None):
        require_model(model)
        settings = ControlSettings.resolve(
            model.spec, settings, who="APDController", sample_period=sample_period,
            velocity_filter_hz=velocity_filter_hz, tau_max=tau_max, split=split, preload=preload,
            preload_sign=preload_sign)
        super().__init__(model, "apd", {"Kp": Kp, "Kv": Kv}, theta0, settings, on_singular)


class CTCController(_Controller):
    """Computed torque with the model's theta: the standard model-based baseline.

    u = S^T tau_a = Me (xd_ddot + Kv edot + Kp e) + Ce xed + S^T f_a (eqs. 10-12 with the
    measured pose and velocity of Fig. 2), i.e. Y(q, v, v, a) theta with a = xd_ddot + Kv edot
    + Kp e (eq. 13). One C call per sample (``<name>_ctc<split>_step``), the signal
    processing, statuses and splits of :class:`NAController`.

    With an exact model the error does not obey the continuous edd + Kv edot + Kp e = 0 (its
    limit as T -> 0) but its sampled version: the torque of sample k is held over [t_k, t_k +
    T] and the velocity is the backward difference v_k = (x_k - x_{k-1}) / T (the low-pass
    with ``velocity_filter_hz=0``), so on each axis x_{k+1} = x_k + T xd_k + T^2 a_k / 2 and
    xd_{k+1} = xd_k + T a_k with a_k = xd_ddot + Kv (xd_dot - v_k) + Kp e_k. On the paper's
    robot with the default gains (omega = 2 pi 20 Hz, omega T = 0.25) and its model as the
    plant (friction-free: the plant's smoothed Coulomb term is not the controller's sign), a
    step error e0 of 1.1 mm departs from the continuous solution by 9.4 % of |e0|
    and follows the recursion to 6e-8 m (the pose's own nonlinearity within a sample);
    tests/control/test_ctc_sampled.py measures both.

    Parameters
    ----------
    model : Model
    Kp : float or array_like (m,) or (m, m), optional
        Diagonal stiffness of the error dynamics, 1/s^2, each entry > 0 (default
        ``[gains.ctc]`` of the model file, else :data:`CTC_DEFAULT_GAINS`).
    Kv : float or array_like (m,) or (m, m), optional
        Diagonal damping, 1/s, each entry > 0. Gains outside these conditions raise
        :class:`pm2dof.GainError` naming the gain and the entry.
    theta0 : array_like (p,), optional
        The model inside the law (default Tables 1-2); never updated.
    sample_period, velocity_filter_hz, tau_max, on_singular, split, preload, preload_sign, settings
        As for :class:`NAController`.
    """
    _law = "ctc"

    def __init__(self, model, *, Kp=None, Kv=None, theta0=None, sample_period=None,
                 velocity_filter_hz=None, tau_max=None, on_singular="raise", split=None,
                 preload=None, preload_sign=None, settings=None):
        require_model(model)
        settings = ControlSettings.resolve(
            model.spec, settings, who="CTCController", sample_period=sample_period,
            velocity_filter_hz=velocity_filter_hz, tau_max=tau_max, split=split, preload=preload,
            preload_sign=preload_sign)
        super().__init__(model, "ctc", {"Kp": Kp, "Kv": Kv}, theta0, settings, on_singular)
