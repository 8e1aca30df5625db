# Optimal excitation: a periodic finite Fourier series in task space (Swevers et al. 1997), IPOPT.
"""Excitation trajectories for identification, designed by optimisation.

The motion is a periodic finite Fourier series per task axis: x and y, and a platform's phi
(m = ``Model.dof`` series; :class:`~pm2dof.identification.signals.FourierExcitation`, Swevers
et al. 1997), starting and ending at rest. :func:`design_excitation` chooses its coefficients a, b, c with CasADi and IPOPT
to maximise log det(Phi^T Phi), Phi the base regressor stacked over one period (D-optimality),
subject to the workspace and a singularity margin, speed, acceleration and torque limits at
dense samples. The speed, acceleration and radius limits are on (x, y); a platform's phi has its
own (:func:`phi_limits`: angular speed, angular acceleration and a range about the centre's phi).

Why log det and not the condition number: log det is smooth (IPOPT needs derivatives; the
condition number is a ratio of extreme singular values, non-smooth where they cross), it is
invariant to the parameters' units (scaling a column adds a constant), it is the volume of
the confidence ellipsoid of the estimate, and it rewards signal over noise, which the
condition number ignores (doubling the motion leaves cond unchanged but halves the errors).
The condition number of the column-scaled regressor is reported before and after.

The model's Y, S, ik and singularity measures enter the optimisation as its generated C, read
back as CasADi SX (:mod:`.c_graph`: the same operations, so the same values; CasADi
differentiates them exactly); nothing is re-derived. A model whose C cannot be read that way
falls back to ``casadi.external`` on the compiled library with finite differences. The torque
and singularity limits' Jacobian is the per-sample Jacobian times the Fourier basis
(:mod:`.sampled`). The speed, acceleration, region and phi limits are polynomials in the
series: imposed at enough samples, their ``safety`` margin bounds them between the samples
(:func:`.design_limits.kinematic_samples`). The torque and singularity limits are checked at
all ``constraint_samples``: IPOPT sees them at every :data:`CONSTRAINT_STRIDE`-th sample
first, then also at the samples its solution broke, until none is broken
(:mod:`.design_limits`). In the objective, the Coulomb columns use tanh(qd / 0.1 rad/s) for
sign(qd): it keeps log det differentiable, and samples slower than 0.1 rad/s are left out by
``identify fit`` anyway.

Every log det reported is one quantity, log det(Phi^T Phi / K): Phi the unscaled base regressor
stacked over K samples, so that it does not grow with K. It is reported on two sample sets,
each named where printed: the *objective* (what IPOPT maximises and its progress bar shows:
``samples`` per period, Coulomb columns smoothed; IPOPT itself works on column-scaled Phi, which
shifts log det by a constant) and the *run* (every 5th sample of the controller period over the
whole run, exact sign: :func:`regressor_condition`).

Determinism: the design is a long IPOPT run (hundreds of iterations) on a non-convex problem,
and its path, hence the local optimum it ends at, follows the last bits of the arithmetic. So
the design runs CasADi's bundled OpenBLAS (the BLAS of IPOPT and MUMPS) on one thread: with
its default of one thread per core the result depended on the core count (measured: 345 IPOPT
iterations with 2 threads, 341 with 4, 373 with 1, each with other coefficients). Whatever
else rounds differently from one machine to another (glibc's libm picks FMA variants by CPU;
measured 308 iterations with them switched off) still moves the result: a design is
reproducible bit for bit on the same machine and install, which the file records
(``[design.provenance]``).

The file (:func:`~pm2dof.identification.signals.write_excitation`) records its model relative
to itself (:mod:`.model_ref`), so that it can be moved together with the model file.
"""
import contextlib
import platform
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..control.trajectory import line_moves
from ..core.errors import ArgumentError, ArgumentTypeError
from ..core.task import effort_unit, orientation_length, per_actuator
from ..infra.interrupt import noticing_ctrl_c
from ..infra.progress import Progress, bar
from .base import base_parameters, region_center
from .c_graph import CGraphError, sx_function
from .design_limits import (
    Limits,
    carry_multipliers,
    kinematic_constraints,
    kinematic_samples,
    model_constraints,
    rest_constraints,
    sample_slack,
    sample_violations,
)
from .fit import MIN_JOINT_SPEED, joint_speed_floor
from .sampled import fourier_basis
from .signals import FourierExcitation, multisine, trajectory_of, write_excitation

__all__ = ["design_excitation", "SeriesOptions", "LimitOptions", "SolverOptions",
           "regressor_condition", "check_excitation",
           "sample_function", "run_design", "DesignReport", "format_design", "objective_logdet",
           "random_start", "IPOPT_OPTIONS", "design_provenance", "phi_limits", "CONVERGED",
           "STAGE_SECONDS", "CONSTRAINT_STRIDE", "WARM_START"]

#: IPOPT's options of the design (``max_iter``: :class:`SolverOptions`);
#: written to the file's ``[design.ipopt]``. ``mu_strategy`` monotone (Fiacco-McCormick):
#: with the adaptive barrier IPOPT ran without it (mu rising and falling in its log), the
#: 3-PRR platform's design stopped at 500 iterations; monotone converges
#: (docs/results-identification.md, by kind)
IPOPT_OPTIONS = {"hessian_approximation": "limited-memory", "mu_strategy": "monotone",
                 "tol": 1e-6, "acceptable_tol": 1e-4, "acceptable_iter": 10,
                 "acceptable_obj_change_tol": 1e-7}

#: IPOPT's options of a solve after samples were added (:mod:`.design_limits`): from the last
#: solution and its multipliers, the barrier parameter near where it ended (the 3-PRR
#: platform's two later solves: 170 iterations from mu 1e-5, 126 from 1e-6; from 1e-7 the
#: second did not converge in the rest of the 500)
WARM_START = {"warm_start_init_point": "yes", "mu_init": 1e-6}
#: samples on either side of a broken one that are added with it (:mod:`.design_limits`)
NEIGHBOURS = 2
#: relative slack (:func:`.design_limits.sample_slack`) below which an added sample is kept
#: when IPOPT solves again; added samples farther from every limit are dropped (and added back
#: if a later solution breaks a limit there). The first solve's samples are never dropped:
#: without the singularity limits at the objective's samples (the same instants by default),
#: log det grows without bound towards a singularity (measured: the 3-PRR point's second solve
#: ran off to log det 285 and 1e17 steps)
NEAR = 0.01
#: IPOPT first sees the torque and singularity limits at every CONSTRAINT_STRIDE-th constraint
#: sample (250 of the default 1000 per period); the samples where its solution does worse than
#: at those are added and it solves again from there, until none does (:mod:`.design_limits`).
#: The problem solved is the same: those limits at all ``constraint_samples``. (The speed,
#: acceleration and region limits are at :func:`.design_limits.kinematic_samples`, in every
#: solve.) Recorded in the file's ``[design]``.
CONSTRAINT_STRIDE = 4

#: IPOPT's return statuses of a converged design; any other (Maximum_Iterations_Exceeded,
#: Restoration_Failed, ...) is written with ``converged = false`` in ``[design]``
CONVERGED = ("Solve_Succeeded", "Solved_To_Acceptable_Level")
#: s between two stage lines of IPOPT's iterations when no bar is drawn (stderr not a terminal)
STAGE_SECONDS = 30.0


@dataclass(frozen=True)
class SeriesOptions:
    """The Fourier series a design optimises (:func:`design_excitation`).

    Parameters
    ----------
    base_hz : float
        f0, Hz, > 0; the period is 1 / f0 (default 0.2 Hz: 5 s).
    harmonics : int
        L, >= 1 (default 10: up to 2 Hz).
    periods : int
        Whole periods of the run, >= 1 (default 2: 10 s).
    """

    base_hz: float = 0.2
    harmonics: int = 10
    periods: int = 2


@dataclass(frozen=True)
class LimitOptions:
    """What a design's motion must keep within (:func:`design_excitation`).

    Parameters
    ----------
    v_max, a_max : float
        Speed (m/s) and acceleration (m/s^2) limits of (x, y), > 0; defaults are those of the
        paper's high-speed move (0.5 m/s, 10 m/s^2): the robot is known to do them.
    tau_fraction : float
        |tau_i| <= tau_fraction * tau_max_i with the nominal model and the min-norm split, in
        (0, 1] (default 0.5: the rest is left to feedback and model error).
    singularity_margin : float
        Both singularity measures >= their threshold + this (default 0.1).
    radius : float
        |(x, y) - c0| <= radius, m, > 0, c0 the middle of the model's first move (the region
        the model is meant for).
    phi_v_max, phi_a_max, phi_range : float, optional
        A platform's limits of phi: |phid| <= phi_v_max (rad/s), |phidd| <= phi_a_max
        (rad/s^2), |phi - phi_c0| <= phi_range (rad). Not given: from the model
        (:func:`phi_limits`: v_max / l, a_max / l with l the platform's radius, and the phi
        excursion of the model's moves). An ArgumentError for a point (no phi).
    safety : float
        The fraction of every limit imposed at the constraints' samples (default 0.98), in
        (0, 1], so that the limits hold between the samples too (:func:`check_excitation`
        checks every 1 ms): an upper limit times ``safety``, a lower one (the singularity
        measures') over it. The speed, acceleration and region limits are at enough samples
        that this margin bounds them at every instant
        (:func:`.design_limits.kinematic_samples`).
    """

    v_max: float = 0.5
    a_max: float = 10.0
    tau_fraction: float = 0.5
    singularity_margin: float = 0.1
    radius: float = 0.06
    phi_v_max: float = None
    phi_a_max: float = None
    phi_range: float = None
    safety: float = 0.98


@dataclass(frozen=True)
class SolverOptions:
    """How a design is solved (:func:`design_excitation`).

    Parameters
    ----------
    samples, constraint_samples : int
        Samples per period of the objective and of the constraints (default 250, 1000).
    seed : int
        Random start (:func:`random_start`; IPOPT finds a local optimum, log det is not
        concave here).
    max_iter : int
        IPOPT's iteration limit over all its solves (its other options: :data:`IPOPT_OPTIONS`;
        the limits at every :data:`CONSTRAINT_STRIDE`-th constraint sample first).
    """

    samples: int = 250
    constraint_samples: int = 1000
    seed: int = 0
    max_iter: int = 500


def _options(kind, value):
    """``value``, or ``kind()`` (the defaults) for None; ArgumentTypeError for another type."""
    if value is None:
        return kind()
    if not isinstance(value, kind):
        raise ArgumentTypeError(f"design_excitation: expected a {kind.__name__} "
                                f"(pm2dof.identification.design), got {type(value).__name__}")
    return value


def _refuse_phi(model, given):
    """ArgumentError when phi limits are given for a model without phi (a point end effector)."""
    named = [k for k, v in given.items() if v is not None]
    if model.dof != 3 and named:
        raise ArgumentError(f"{', '.join(named)} limit a platform's orientation phi; model "
                            f"{model.name!r} has task {model.task_names}, no phi")


def phi_limits(model, *, v_max=0.5, a_max=10.0, radius=0.06, phi_v_max=None, phi_a_max=None,
               phi_range=None):
    """A platform's phi limits of the design, each as given or from the model, with l its
    radius (:func:`~pm2dof.core.task.orientation_length`, the farthest attachment point):

    * ``phi_v_max`` = v_max / l, rad/s, and ``phi_a_max`` = a_max / l, rad/s^2: the rotation
      alone moves the attachment points at the (x, y) limits;
    * ``phi_range`` = the largest phi excursion |phi_end - phi_start| of the model's moves, rad
      (|phi - phi_c| <= phi_range about the centre's phi_c, so the excitation spans twice the
      model's own turn); radius / l if no move turns.

    Returns
    -------
    dict
        ``phi_v_max``, ``phi_a_max``, ``phi_range``; empty for a point end effector (then giving
        any of them is an ArgumentError: there is no phi).
    """
    given = {"phi_v_max": phi_v_max, "phi_a_max": phi_a_max, "phi_range": phi_range}
    _refuse_phi(model, given)
    if model.dof != 3:
        return {}
    l = orientation_length(model)
    moves = [model.spec.trajectories[k] for k in line_moves(model)]
    turn = max((abs(float(t["end"][2]) - float(t["start"][2])) for t in moves), default=0.0)
    out = {"phi_v_max": v_max / l, "phi_a_max": a_max / l,
           "phi_range": turn if turn > 0 else radius / l}
    out.update({k: float(v) for k, v in given.items() if v is not None})
    if not all(v > 0 for v in out.values()):
        raise ArgumentError(f"need phi_v_max > 0, phi_a_max > 0, phi_range > 0, got {out}")
    return out


def regressor_condition(model, base, traj, every=5):
    """Condition number of the column-scaled base regressor stacked over ``traj`` (every
    ``every``-th sample; desired motion, exact derivatives), and log det(Phi^T Phi / K) of the
    unscaled one. NumPy on the model's C functions (independent of the CasADi design graph).

    Returns
    -------
    cond, logdet : float
    """
    I = list(base.independent)
    rows = [model.Y(model.ik(x), v, v, a)[:, I] for x, v, a in
            zip(traj.xd[::every], traj.xd_dot[::every], traj.xd_ddot[::every])]
    Phi = np.vstack(rows)
    sv = np.linalg.svd(Phi / np.linalg.norm(Phi, axis=0), compute_uv=False)
    _, logdet = np.linalg.slogdet(Phi.T @ Phi / len(rows))
    return float(sv[0] / sv[-1]), float(logdet)


def check_excitation(model, exc, *, v_max, a_max, tau_limit, sing_min, radius, step=1e-3,
                     phi_v_max=None, phi_a_max=None, phi_range=None):
    """The excitation's worst values at samples every ``step`` s over one period, against the
    design's limits (``radius`` around the middle of the model's first move; a platform's
    ``phi_v_max``, ``phi_a_max`` and ``phi_range``, required for it, as :func:`phi_limits`).

    Returns
    -------
    dict
        ``speed`` (max |(xd, yd)|, m/s), ``acceleration`` (max |(xdd, ydd)|, m/s^2),
        ``torque`` (max |tau_i| of the min-norm split with Tables 1-2, N m or N), ``sing`` (min
        of both singularity measures), ``radius`` (max |(x, y) - center|, m), ``rest`` (|xd|,
        |xdd| at t = 0); for a platform also ``phi_speed`` (max |phid|, rad/s),
        ``phi_acceleration`` (max |phidd|, rad/s^2) and ``phi_range`` (max |phi - phi_c|, rad);
        ``failed`` the names of those beyond their limit, ``ok`` none.
    """
    phi = {"phi_v_max": phi_v_max, "phi_a_max": phi_a_max, "phi_range": phi_range}
    _refuse_phi(model, phi)
    if model.dof == 3 and None in phi.values():
        raise ArgumentError(f"model {model.name!r} has a phi: check_excitation needs "
                            f"phi_v_max, phi_a_max and phi_range, got {phi}")
    t = np.arange(int(round(1.0 / (exc.base_hz * step))) + 1) * step
    x, v, a = exc.evaluate(t)
    th = model.theta_nominal
    tau, sing = 0.0, np.inf
    for xk, vk, ak in zip(x, v, a):
        q = model.ik(xk)
        sing = min(sing, float(np.min(model.singularity_measures(q))))
        S = model.S(q)
        u = model.Y(q, vk, vk, ak) @ th
        tau = max(tau, float(np.abs(S @ np.linalg.solve(S.T @ S, u)).max()))
    c0 = region_center(model)
    out = {"speed": float(np.max(np.hypot(*v[:, :2].T))),
           "acceleration": float(np.max(np.hypot(*a[:, :2].T))),
           "torque": tau, "sing": sing,
           "radius": float(np.max(np.hypot(*(x[:, :2] - c0[:2]).T))),
           "rest": float(np.abs(np.concatenate([v[0], a[0]])).max())}
    limits = [("speed", out["speed"] <= v_max), ("acceleration", out["acceleration"] <= a_max),
              ("torque", tau <= tau_limit), ("sing", sing >= sing_min),
              ("radius", out["radius"] <= radius)]
    if model.dof == 3:
        out.update(phi_speed=float(np.max(np.abs(v[:, 2]))),
                   phi_acceleration=float(np.max(np.abs(a[:, 2]))),
                   phi_range=float(np.max(np.abs(x[:, 2] - c0[2]))))
        limits += [("phi_speed", out["phi_speed"] <= phi_v_max),
                   ("phi_acceleration", out["phi_acceleration"] <= phi_a_max),
                   ("phi_range", out["phi_range"] <= phi_range)]
    out["failed"] = [k for k, met in (*limits, ("rest", out["rest"] < 1e-9)) if not met]
    out["ok"] = not out["failed"]
    return out


def _external(model, short):
    """``model``'s generated function ``short`` as a CasADi Function (``casadi.external``,
    finite-difference derivatives), with a design input bound to ``model.design`` (a model
    with a [design] table: :meth:`pm2dof.Model.at_design`)."""
    import casadi as ca
    ext = ca.external(f"{model.name}_{short}", model.library, {"enable_fd": True})
    last = ext.n_in() - 1
    if last < 0 or ext.name_in(last) != "design":
        return ext
    ins = [ca.MX.sym(ext.name_in(k), ext.sparsity_in(k)) for k in range(last)]
    return ca.Function(short, ins, ext.call(ins + [ca.DM(model.design)]),
                       [ext.name_in(k) for k in range(last)],
                       [ext.name_out(k) for k in range(ext.n_out())])


def _model_functions(model, shorts):
    """({short: CasADi Function}, exact): ``model``'s generated functions ``shorts`` as SX
    read from their C (:func:`.c_graph.sx_function`: exact derivatives), exact True; or, if
    any of them cannot be read, all as ``casadi.external`` with finite differences
    (:func:`_external`), exact False."""
    try:
        return {k: sx_function(model, k) for k in shorts}, True
    except CGraphError:
        return {k: _external(model, k) for k in shorts}, False


def sample_function(model, independent, smooth_sign=None):
    """CasADi function (x (m), xd (m), xdd (m)) -> (vec of Y[:, independent] (m r,
    column-major), tau (n) of the min-norm split with Tables 1-2 (eq. 21), both singularity
    measures (2)), m = ``Model.dof``, built on the model's generated C: an SX function of it
    read back from the C (:func:`_model_functions`, exact derivatives), else MX on
    ``casadi.external`` (finite-difference derivatives).

    ``smooth_sign`` (rad/s): replace sign(qd_i) in the Coulomb (and Stribeck) columns by
    tanh(qd_i / s_i), s_i = smooth_sign for a revolute actuator and smooth_sign x
    ``SPEED_LEVER`` m/s for a linear one (:func:`~pm2dof.identification.fit.joint_speed_floor`),
    so that the design's objective is differentiable (a sign flipping at one sample would make
    it jump); None keeps the model's Y exactly.
    """
    import casadi as ca
    n, p, m = model.n_legs, len(model.param_names), model.dof
    ext, exact = _model_functions(model, ("ik", "Y", "S", "singularity_measures"))
    sym = ca.SX.sym if exact else ca.MX.sym
    x, v, acc = sym("x", m), sym("v", m), sym("a", m)
    q = ext["ik"](x)
    Yfull = ca.reshape(ext["Y"](q, v, v, acc)[0], p, m).T       # the C writes Y row-major
    S = ca.reshape(ext["S"](q)[0], m, n).T
    if smooth_sign and model.spec.friction in ("coulomb_viscous", "coulomb_viscous_stribeck"):
        qd = ca.mtimes(S, v)                                    # eq. 8
        names = list(model.param_names)
        cols = [Yfull[:, j] for j in range(p)]
        floor = joint_speed_floor(model, smooth_sign)
        for i in range(n):
            sgn = ca.tanh(qd[i] / floor[i])
            cols[names.index(f"fc{i + 1}")] = S[i, :].T * sgn   # S^T e_i sign(qd_i), eq. 2
            if f"fs{i + 1}" in names:
                vs = model.spec.friction_constants["stribeck_velocity"]
                cols[names.index(f"fs{i + 1}")] = S[i, :].T * sgn / (1 + (qd[i] / vs) ** 2)
        Yfull = ca.horzcat(*cols)
    u = ca.mtimes(Yfull, ca.DM(model.theta_nominal))
    tau = ca.mtimes(S, ca.solve(ca.mtimes(S.T, S), u))          # eq. 21, Tables 1-2
    return ca.Function("sample", [x, v, acc],
                       [ca.vec(Yfull[:, list(independent)]), tau,
                        ext["singularity_measures"](q)])


def random_start(model, *, base_hz, harmonics, periods, v_max, a_max, radius, seed,
                 phi_v_max=None, phi_a_max=None, phi_range=None):
    """IPOPT's start: random coefficients (``numpy.random.default_rng(seed)``) with the rest
    conditions, around the middle c0 of the model's first move, the (x, y) series scaled to
    30 % of the speed, acceleration and radius limits, a platform's phi series to 30 % of its
    own (:func:`phi_limits`). Returns a :class:`FourierExcitation`."""
    L, c0, m = int(harmonics), region_center(model), model.dof
    phi = phi_limits(model, v_max=v_max, a_max=a_max, radius=radius, phi_v_max=phi_v_max,
                     phi_a_max=phi_a_max, phi_range=phi_range)
    rng = np.random.default_rng(seed)
    w = 2 * np.pi * base_hz * np.arange(1, L + 1)
    a0 = rng.normal(size=(m, L)) / np.arange(1, L + 1)
    b0 = rng.normal(size=(m, L)) / np.arange(1, L + 1) ** 2
    a0 -= a0.mean(axis=1, keepdims=True)
    b0 -= np.outer(b0 @ w, w) / (w @ w)
    x_, v_, a_ = FourierExcitation(base_hz, periods, c0, a0, b0).evaluate(
        np.arange(2000) / (2000 * base_hz))
    k = np.full((m, 1), min(0.3 * v_max / np.max(np.hypot(*v_[:, :2].T)),
                            0.3 * a_max / np.max(np.hypot(*a_[:, :2].T)),
                            0.3 * radius / np.max(np.hypot(*(x_[:, :2] - c0[:2]).T))))
    if phi:
        k[2] = min(0.3 * phi["phi_v_max"] / np.max(np.abs(v_[:, 2])),
                   0.3 * phi["phi_a_max"] / np.max(np.abs(a_[:, 2])),
                   0.3 * phi["phi_range"] / np.max(np.abs(x_[:, 2] - c0[2])))
    return FourierExcitation(base_hz, periods, c0.copy(), k * a0, k * b0)


def objective_logdet(model, exc, samples=250, base=None):
    """The design's objective at ``exc``: log det(Phi^T Phi / K) of the unscaled base regressor
    at K = ``samples`` instants of one period, Coulomb columns smoothed as in the design
    (:func:`sample_function`, evaluated numerically); the quantity IPOPT's progress bar
    shows. Recomputes the file's ``objective_logdet_*`` from its coefficients."""
    I = list((base_parameters(model) if base is None else base).independent)
    t = np.arange(samples) / (samples * exc.base_hz)
    x, v, a = exc.evaluate(t)
    Yv = np.array(sample_function(model, I, smooth_sign=MIN_JOINT_SPEED).map(samples)(
        x.T, v.T, a.T)[0])
    Phi = np.vstack([Yv[:, k].reshape(len(I), model.dof).T for k in range(samples)])
    return float(np.linalg.slogdet(Phi.T @ Phi / samples)[1])


def _casadi_openblas():
    """ctypes handle of the OpenBLAS that CasADi's IPOPT and MUMPS use, or None.

    The wheel ships it three times (``libcasadi-tp-openblas.so``, ``.so.0``, ``.so.0.3``: wheels
    hold no symbolic links) and IPOPT loads the ``.so.0`` (its soname): loading another copy
    would set the threads of a library nobody calls. So: the copy this process has mapped, else
    the ``.so.0``, which the IPOPT plugin then finds by its soname."""
    import ctypes

    import casadi
    path = Path(casadi.__file__).parent / "libcasadi-tp-openblas.so.0"
    try:
        with open("/proc/self/maps") as fh:
            mapped = {ln.split()[-1] for ln in fh if "libcasadi-tp-openblas" in ln}
        if len(mapped) == 1:
            path = Path(mapped.pop())
    except OSError:
        pass
    try:
        lib = ctypes.CDLL(str(path))
        lib.openblas_get_num_threads, lib.openblas_set_num_threads  # noqa: B018
    except (OSError, AttributeError):
        return None
    return lib


@contextlib.contextmanager
def _single_thread_blas():
    """CasADi's OpenBLAS (:func:`_casadi_openblas`) on one thread for the block, then as
    before. Yields the thread count in force, or None for a CasADi without that library."""
    lib = _casadi_openblas()
    if lib is None:
        yield None
        return
    before = lib.openblas_get_num_threads()
    lib.openblas_set_num_threads(1)
    try:
        yield int(lib.openblas_get_num_threads())
    finally:
        lib.openblas_set_num_threads(before)


def design_provenance(model):
    """What a design's result depends on besides its arguments: versions, the model's hashes and
    the machine's arithmetic (CPU, C library). Deterministic for one machine and install."""
    from importlib.metadata import PackageNotFoundError, version

    import casadi
    try:
        pm2dof_version = version("pm2dof")
    except PackageNotFoundError:
        pm2dof_version = "unknown"
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as fh:
            cpu = next((ln.split(":", 1)[1].strip() for ln in fh if ln.startswith("model name")),
                       cpu)
    except OSError:
        pass
    return {"pm2dof": pm2dof_version, "casadi": casadi.__version__, "numpy": np.__version__,
            "model_file_sha256": model.spec.file_sha256,
            "formulation_sha256": model.spec.formulation_sha256,
            "machine": f"{platform.machine()}, {cpu}",
            "libc": " ".join(platform.libc_ver()).strip() or "unknown"}


def design_excitation(model, series=None, limits=None, solver=None, *, progress=None):
    """Design a D-optimal excitation (CasADi + IPOPT).

    Parameters
    ----------
    model : Model
    series : SeriesOptions, optional
        The Fourier series: f0, harmonics, periods (default ``SeriesOptions()``: 0.2 Hz, 10
        harmonics, 2 periods).
    limits : LimitOptions, optional
        Speed, acceleration, effort, singularity, region and a platform's phi limits, and the
        safety fraction imposed at the samples (default ``LimitOptions()``).
    solver : SolverOptions, optional
        Samples of the objective and of the constraints, the random start's seed, IPOPT's
        iteration limit (default ``SolverOptions()``).
    progress : callable(str) or pm2dof.infra.progress.Progress, optional
        Stage lines; a :class:`~pm2dof.infra.progress.Progress` also draws a bar of IPOPT's
        iterations with the objective's log det as its postfix.

    Returns
    -------
    FourierExcitation
        Of m = ``Model.dof`` series. Its ``info`` (the file's ``[design]``): every option
        above (the phi limits, as used, for a platform only), the IPOPT options, cond and log
        det before (the start) and after on the objective's and the run's samples (module
        docstring), IPOPT's status and iterations, and :func:`design_provenance`. The same
        options on the same machine and install give the same coefficients and ``info`` bit
        for bit (no wall time in it).

    Raises
    ------
    ArgumentError
        Naming every option outside its rule (base_hz, v_max, a_max, radius > 0; harmonics,
        periods >= 1; tau_fraction in (0, 1]) before IPOPT runs.
    """
    import casadi as ca
    series, limits = _options(SeriesOptions, series), _options(LimitOptions, limits)
    solver = _options(SolverOptions, solver)
    base_hz, harmonics, periods = series.base_hz, series.harmonics, series.periods
    v_max, a_max, tau_fraction = limits.v_max, limits.a_max, limits.tau_fraction
    singularity_margin, radius, safety = limits.singularity_margin, limits.radius, limits.safety
    samples, constraint_samples = solver.samples, solver.constraint_samples
    seed, max_iter = solver.seed, solver.max_iter
    rules = (("base_hz", base_hz, "> 0", base_hz > 0), ("harmonics", harmonics, ">= 1",
             harmonics >= 1), ("periods", periods, ">= 1", periods >= 1),
             ("v_max", v_max, "> 0", v_max > 0), ("a_max", a_max, "> 0", a_max > 0),
             ("tau_fraction", tau_fraction, "in (0, 1]", 0 < tau_fraction <= 1),
             ("radius", radius, "> 0", radius > 0))
    wrong = [f"{name} must be {rule}, got {value!r}" for name, value, rule, ok in rules if not ok]
    if wrong:
        raise ArgumentError("design_excitation: " + "; ".join(wrong))
    phi = phi_limits(model, v_max=v_max, a_max=a_max, radius=radius,
                     phi_v_max=limits.phi_v_max, phi_a_max=limits.phi_a_max,
                     phi_range=limits.phi_range)      # {} for a point
    args = {"base_hz": base_hz, "harmonics": int(harmonics), "periods": int(periods),
            "v_max": v_max, "a_max": a_max, "tau_fraction": tau_fraction,
            "singularity_margin": singularity_margin, "radius": radius, **phi,
            "samples": int(samples),
            "constraint_samples": int(constraint_samples), "safety": safety, "seed": int(seed),
            "max_iter": int(max_iter)}
    base = base_parameters(model)
    I, L, m = list(base.independent), int(harmonics), model.dof
    r = len(I)
    tau_lim = safety * tau_fraction * np.asarray(model.spec.limits["tau_max"], float)
    sing_min = (np.array([model.singularity_threshold, model.parallel_singularity_threshold])
                + singularity_margin)
    c0 = region_center(model)
    per_sample = sample_function(model, I, smooth_sign=MIN_JOINT_SPEED)
    z = ca.MX.sym("z", 2 * m * L + m)            # z = [a_x, a_y(, a_phi), b_x, ..., c]
    A = ca.reshape(z[:m * L], L, m)
    B = ca.reshape(z[m * L:2 * m * L], L, m)
    c = z[2 * m * L:]

    def motion(K):
        Pa, Pb, Va, Vb, Aa, Ab = (ca.DM(M) for M in fourier_basis(base_hz, L,
                                                              np.arange(K) / (K * base_hz)))
        X = ca.mtimes(Pa, A) + ca.mtimes(Pb, B) + ca.repmat(c.T, K, 1)
        return X, ca.mtimes(Va, A) + ca.mtimes(Vb, B), ca.mtimes(Aa, A) + ca.mtimes(Ab, B)

    X, V, Acc = motion(samples)
    Yv, _, _ = per_sample.map(samples)(X.T, V.T, Acc.T)
    Phi = ca.vertcat(*[ca.reshape(Yv[:, k], m, r) for k in range(samples)])

    start = random_start(model, base_hz=base_hz, harmonics=L, periods=periods, v_max=v_max,
                         a_max=a_max, radius=radius, seed=seed, **phi)
    z0 = np.concatenate([start.a.ravel(), start.b.ravel(), c0])
    # column scaling: log det is invariant to it up to a constant; it keeps det() in range
    Phi0 = ca.Function("Phi0", [z], [Phi])(z0).full()
    norms = np.linalg.norm(Phi0, axis=0)
    D = ca.DM(np.diag(1.0 / norms))
    M = ca.mtimes([D, Phi.T, Phi, D])
    objective = -ca.log(ca.det(M))
    # -objective + this = log det(Phi^T Phi / samples), the unscaled per-sample log det
    to_logdet = float(2 * np.sum(np.log(norms)) - r * np.log(samples))

    # a lower bound's margin is the same fraction as an upper bound's: sing_min / safety
    lim = Limits(safety * v_max, safety * a_max, safety * radius, tau_lim, sing_min / safety,
                 c0, {k: safety * v for k, v in phi.items()})
    K, n = int(constraint_samples), model.n_legs
    t_all = np.arange(K) / (K * base_hz)
    g_rest, lb_rest, ub_rest = rest_constraints(z, m, L, base_hz)
    # the kinematic limits at M samples that bound them everywhere; the model's at all K
    # samples, IPOPT first seeing every stride-th, then the ones that do worse (design_limits)
    M = kinematic_samples(K, L, safety)
    g_kin, lb_kin, ub_kin = kinematic_constraints(z, lim, base_hz=base_hz, L=L, m=m,
                                                  t=np.arange(M) / (M * base_hz))
    g_all, lb_all, ub_all = model_constraints(z, per_sample, lim, base_hz=base_hz, L=L, m=m,
                                              t=t_all)
    every_sample = ca.Function("limits", [z], [g_all])
    seen = first = np.arange(0, K, min(CONSTRAINT_STRIDE, K))
    if progress:
        progress(f"IPOPT: {z.numel()} coefficients, objective log det(Phi^T Phi / K) over "
                 f"{samples} samples per period, speed, acceleration and region limits at {M} "
                 f"samples per period, torque and singularity limits at {K} (IPOPT first sees "
                 f"{len(seen)} of them)")
    # where no bar is drawn (stderr not a terminal, or a plain callable), a stage line every
    # STAGE_SECONDS instead: a design takes minutes (docs/results-identification.md, per kind)
    lines = (progress if progress and not (isinstance(progress, Progress) and progress.bars)
             else None)
    used, rounds, zs, warm = 0, 0, z0, {}
    with bar(progress, int(max_iter), "IPOPT", unit="it") as iterations, \
            noticing_ctrl_c() as ctrl_c, _single_thread_blas() as blas_threads:
        while True:
            rounds += 1
            g, lbg, ubg = model_constraints(z, per_sample, lim, base_hz=base_hz, L=L, m=m,
                                            t=t_all[seen])
            # IPOPT's iterations shown as they happen; the callback also stops IPOPT at the
            # iteration after a Ctrl-C
            head = 2 * m + len(lb_kin)      # rows before the model's: rest, kinematic
            callback = _IterationProgress(z.numel(), head + len(lbg), iterations, to_logdet,
                                          ctrl_c, lines, int(max_iter), used)
            solver = ca.nlpsol("excitation", "ipopt",
                               {"x": z, "f": objective, "g": ca.vertcat(g_rest, g_kin, g)},
                               {"iteration_callback": callback, "ipopt.print_level": 0,
                                "print_time": False, "ipopt.sb": "yes",
                                # a trial point where a leg's ik has no solution (NaN rows) is
                                # IPOPT's evaluation error: it cuts the step back; not printed
                                "show_eval_warnings": False,
                                "ipopt.max_iter": int(max_iter) - used,
                                **{f"ipopt.{k}": v for k, v in IPOPT_OPTIONS.items()},
                                **({f"ipopt.{k}": v for k, v in WARM_START.items()}
                                   if warm else {})})
            sol = solver(x0=zs, lbg=np.concatenate([lb_rest, lb_kin, lbg]),
                         ubg=np.concatenate([ub_rest, ub_kin, ubg]), **warm)
            zs = np.array(sol["x"]).ravel()
            lam = np.array(sol["lam_g"]).ravel()
            stats = solver.stats()
            used += int(stats["iter_count"])
            if ctrl_c or stats["return_status"] == "User_Requested_Stop":
                raise KeyboardInterrupt(f"IPOPT stopped after {used} iterations")
            values = every_sample(zs)
            worst = sample_violations(values, lb_all, ub_all, n)
            worse = np.flatnonzero(worst > max(worst[seen].max(), 1e-9))
            if (not len(worse) or stats["return_status"] not in CONVERGED
                    or used >= int(max_iter)):
                break
            # again with the first solve's samples, the broken samples and their neighbours (a
            # peak between two samples IPOPT saw moves a little when it solves again) and the
            # added samples within NEAR of a limit; the others are dropped (checked again after
            # the solve)
            near = np.flatnonzero(sample_slack(values, lb_all, ub_all, n) < NEAR)
            now = np.union1d(np.union1d(first, np.intersect1d(seen, near)), (
                worse[:, None] + np.arange(-NEIGHBOURS, NEIGHBOURS + 1)).ravel() % K)
            if progress:
                progress(f"IPOPT {stats['return_status']} after {used} iterations; "
                         f"{len(worse)} of the other samples break the limits (by up to "
                         f"{worst.max():.3g}): solving again with {len(now)} samples")
            warm = {"lam_g0": np.concatenate([lam[:head], carry_multipliers(
                lam[head:], seen, now, n)]), "lam_x0": np.array(sol["lam_x"]).ravel()}
            seen = now
    exc = _with_rest(FourierExcitation(base_hz, periods, zs[2 * m * L:],
                                       zs[:m * L].reshape(m, L),
                                       zs[m * L:2 * m * L].reshape(m, L)))
    before = regressor_condition(model, base, trajectory_of(model, start))
    after = regressor_condition(model, base, trajectory_of(model, exc))
    info = {"objective": "log det(Phi^T Phi / K) of the base regressor (D-optimal)", **args,
            "region_center": c0.tolist(),
            "objective_logdet_before": objective_logdet(model, start, samples, base),
            "objective_logdet_after": objective_logdet(model, exc, samples, base),
            "cond_before": before[0], "cond_after": after[0],
            "logdet_before": before[1], "logdet_after": after[1],
            "ipopt_status": stats["return_status"], "ipopt_iterations": used,
            "constraint_stride": CONSTRAINT_STRIDE, "kinematic_samples": M,
            "ipopt_solves": rounds,
            "limit_samples_seen": int(len(seen)),
            "converged": stats["return_status"] in CONVERGED,
            "ipopt": dict(IPOPT_OPTIONS), "blas_threads": blas_threads or "default",
            "provenance": design_provenance(model)}
    return FourierExcitation(exc.base_hz, exc.periods, exc.center, exc.a, exc.b, info)


def _iteration_progress_class():
    import casadi as ca

    class IterationProgress(ca.Callback):
        """CasADi iteration callback: one step of the bar ``iterations`` per IPOPT iteration,
        its postfix log det(Phi^T Phi / K) = -f + ``to_logdet`` (f IPOPT's objective,
        column-scaled); with ``lines`` (a callable taking a stage line), one line every
        :data:`STAGE_SECONDS` s; stops IPOPT (User_Requested_Stop) once ``stop`` is not
        empty. ``done``: IPOPT iterations of the design's earlier solves (its lines count
        on from there)."""

        def __init__(self, nx, ng, iterations, to_logdet, stop=(), lines=None, max_iter=None,
                     done=0):
            ca.Callback.__init__(self)
            self.nx, self.ng, self.iterations, self.to_logdet = nx, ng, iterations, to_logdet
            self.stop, self.lines, self.max_iter = stop, lines, max_iter
            self.t0 = self.last = time.perf_counter()
            self.count = int(done)      # iterations of earlier solves of the same design
            # a later solve's iteration 0 is the earlier solve's last iterate: not a step
            self.repeat_first = self.count > 0
            self.construct("excitation_progress", {})

        def get_n_in(self):
            return ca.nlpsol_n_out()

        def get_n_out(self):
            return 1

        def get_name_in(self, i):
            return ca.nlpsol_out(i)

        def get_name_out(self, i):
            return "ret"

        def get_sparsity_in(self, i):
            name = ca.nlpsol_out(i)
            if name == "f":
                return ca.Sparsity.scalar()
            if name in ("x", "lam_x"):
                return ca.Sparsity.dense(self.nx)
            if name in ("g", "lam_g"):
                return ca.Sparsity.dense(self.ng)
            return ca.Sparsity(0, 0)

        def eval(self, arg):
            # IPOPT calls back at its iterations 0, 1, 2, ...: the bar counts 1, 2, ...
            logdet = -float(arg[1]) + self.to_logdet
            self.iterations.set_postfix_str(f"objective log det {logdet:.3f}", refresh=False)
            if self.repeat_first:
                self.repeat_first = False
                return [1 if self.stop else 0]
            self.iterations.update(1)
            self.count += 1
            now = time.perf_counter()
            if self.lines and now - self.last >= STAGE_SECONDS:
                self.last = now
                self.lines(f"IPOPT iteration {self.count - 1} of at most {self.max_iter}: "
                           f"objective log det {logdet:.3f}, {now - self.t0:.0f} s")
            return [1 if self.stop else 0]

    return IterationProgress


def _IterationProgress(*args):
    return _iteration_progress_class()(*args)


def _with_rest(exc):
    """Project a, b onto the rest conditions exactly (IPOPT meets them to its tolerance)."""
    w = 2 * np.pi * exc.base_hz * np.arange(1, exc.harmonics + 1)
    a = exc.a - exc.a.mean(axis=1, keepdims=True)
    b = exc.b - np.outer(exc.b @ w, w) / (w @ w)
    return FourierExcitation(exc.base_hz, exc.periods, np.asarray(exc.center, float), a, b,
                             exc.info)


@dataclass(frozen=True)
class DesignReport:
    """What ``pm2dof identify design`` did (:func:`run_design`; its text: :func:`format_design`).

    ``excitation`` is the design written to ``out``; ``check`` is :func:`check_excitation`'s
    result against the limits ``v_max``, ``a_max``, ``tau_limit`` and ``sing_min``;
    ``default_cond`` the base regressor's condition number on the default multi-sine of the
    same length; ``seconds`` the design's wall time; ``effort`` and ``unit`` name the
    actuators' effort by kind ("torque", N m; "force", N)."""
    out: object
    excitation: object
    check: dict
    seconds: float
    default_cond: float
    v_max: float
    a_max: float
    tau_limit: float
    sing_min: float
    effort: str = "torque"
    unit: str = "N m"

    @property
    def converged(self):
        """Whether IPOPT converged (its status in :data:`CONVERGED`); a design that did not is
        written all the same, marked ``converged = false`` in the file's ``[design]``."""
        return bool(self.excitation.info.get("converged", True))


def run_design(model, out, series=None, limits=None, solver=None, *, progress=None):
    """``pm2dof identify design --out FILE``: design, check at 1 ms, write; returns a
    :class:`DesignReport` (its ``converged``: whether IPOPT converged; the file is written
    either way, ``converged`` in its ``[design]``). The options: :func:`design_excitation`;
    the phi limits: a platform's (:func:`phi_limits`)."""
    limits = _options(LimitOptions, limits)
    t0 = time.perf_counter()
    try:
        exc = design_excitation(model, series, limits, solver, progress=progress)
    except KeyboardInterrupt as stop:          # an interrupted design is not written
        raise KeyboardInterrupt(f"{str(stop) + '; ' if str(stop) else ''}{out} not "
                                f"written") from None
    seconds = time.perf_counter() - t0
    if progress:
        progress(f"IPOPT {exc.info['ipopt_status']} after {exc.info['ipopt_iterations']} "
                 f"iterations, {seconds:.0f} s; checking the excitation every 1 ms, writing {out}")
    v_max, a_max = limits.v_max, limits.a_max
    sing_min = max(model.singularity_threshold, model.parallel_singularity_threshold) + 0.1
    tau_limit = limits.tau_fraction * np.max(model.spec.limits["tau_max"])
    chk = check_excitation(model, exc, v_max=v_max, a_max=a_max, tau_limit=tau_limit,
                           sing_min=sing_min, radius=exc.info["radius"],
                           **{k: exc.info[k] for k in ("phi_v_max", "phi_a_max", "phi_range")
                              if k in exc.info})
    default = regressor_condition(model, base_parameters(model),
                                  trajectory_of(model, multisine(model, duration=exc.duration)))
    write_excitation(out, exc, model)
    return DesignReport(out, exc, chk, seconds, default[0], v_max, a_max, tau_limit, sing_min,
                        per_actuator(model.spec.actuators, "torque", "force", "torque or force"),
                        effort_unit(model))


def format_design(r):
    """The lines ``pm2dof identify design`` prints of a :class:`DesignReport`."""
    exc, i, chk = r.excitation, r.excitation.info, r.check

    def met(key):
        return " NOT MET" if key in chk["failed"] else ""

    unconverged = ([] if r.converged else [
        f"NOT CONVERGED: IPOPT stopped at {i['ipopt_status']} after {i['ipopt_iterations']} "
        f"iterations; {r.out} holds its last iterate, marked converged = false in [design]"])
    return "\n".join(unconverged + [
        f"wrote {r.out}: {exc.harmonics} harmonics of {exc.base_hz:g} Hz (up to "
        f"{exc.max_hz:g} Hz), {exc.periods} periods = {exc.duration:g} s; IPOPT "
        f"{i['ipopt_status']} after {i['ipopt_iterations']} iterations, {r.seconds:.0f} s",
        f"objective: {i['objective']}",
        f"log det(Phi^T Phi / K) at the start -> optimised: {i['objective_logdet_before']:.2f} "
        f"-> {i['objective_logdet_after']:.2f} on the objective's samples ({i['samples']} per "
        f"period, Coulomb smoothed: the progress bar), {i['logdet_before']:.2f} -> "
        f"{i['logdet_after']:.2f} on the run's (every 5th sample, exact sign)",
        f"condition number of the column-scaled base regressor on the run's samples: "
        f"{i['cond_before']:.4g} at the start -> {i['cond_after']:.4g} optimised (the default "
        f"multi-sine of excite: {r.default_cond:.4g})",
        f"checked every 1 ms: speed {chk['speed']:.3f} <= {r.v_max:g} m/s{met('speed')}, "
        f"acceleration {chk['acceleration']:.2f} <= {r.a_max:g} m/s^2{met('acceleration')}, "
        f"{r.effort} (Tables 1-2, min-norm) {chk['torque']:.2f} <= {r.tau_limit:g} {r.unit}"
        f"{met('torque')}, singularity measures {chk['sing']:.3f} >= {r.sing_min:.3f}"
        f"{met('sing')}, |x - c0| {chk['radius'] * 1e3:.1f} <= {i['radius'] * 1e3:.1f} mm"
        f"{met('radius')}, "
        + ("" if "phi_speed" not in chk else
           f"phi speed {chk['phi_speed']:.3f} <= {i['phi_v_max']:.4g} rad/s{met('phi_speed')}, "
           f"phi acceleration {chk['phi_acceleration']:.2f} <= {i['phi_a_max']:.4g} rad/s^2"
           f"{met('phi_acceleration')}, |phi - phi_c0| {chk['phi_range']:.3f} <= "
           f"{i['phi_range']:.4g} rad{met('phi_range')}, ")
        + f"starts and ends at rest{met('rest')}: "
        f"{'all met' if chk['ok'] else 'NOT MET: ' + ', '.join(chk['failed'])}"])
