# The runtime Model: a frozen model file plus its compiled generated C, bound through pm2dof.core._cbind.
"""The runtime model of an n-leg planar RR parallel manipulator.

:func:`load_model` reads a model file, checks that ``generated/<name>/`` was derived from it
(``manifest.json``) and binds the compiled functions. Every method is one call into the
generated C. Inputs are float arrays of the documented length (lists and other dtypes are
converted, on a slower path); outputs are new arrays unless ``out=`` is given, in which case
the result is written there (no allocation) and returned.
"""
import array
import json
import sys
import types
from pathlib import Path

import numpy as np

from . import build, paths
from .errors import ClosureError, SingularityError, StaleGeneratedCodeError, WorkspaceError
from .layout import Layout
from .model_file import read_model_file

try:
    from . import _cbind
except ImportError:  # a source tree whose C extension was never built
    raise ImportError(
        f"pm2dof is not built: its C extension pm2dof.core._cbind is missing from "
        f"{Path(__file__).parent}; build it with `pip install -e .` (or `make install`) in the "
        f"source tree") from None

__all__ = ["Model", "load_model"]


# controller steps and closed loops: <law><split>_step, <law><split>_closed_loop
_SPLIT_SUFFIXES = ("", "_minmax", "_preload")                   # min_norm, min_max, preload
_LOOPS = tuple(f"{law}{sfx}_{kind}" for law in ("na", "na_proj", "apd")
               for sfx in _SPLIT_SUFFIXES for kind in ("step", "closed_loop"))
_STEPPING = ("plant_xedd", "plant_step", "measure") + _LOOPS
# motion planning (pm2dof.planning): per-grid-point path dynamics; they report, never raise
_PATH = ("path_coefficients", "path_mvc", "path_backward", "path_forward", "path_torques")
_FUNCTIONS = ("ik", "fk", "H", "A", "singularity", "singularity_measures", "W", "S", "Wdot",
              "M", "C", "Me", "Ce", "StF", "Y", "torque_splits", "forward_dynamics") + _STEPPING \
    + _PATH


def _freeze(obj):
    """Read-only view of JSON data: dicts -> mappingproxy, lists -> tuples."""
    if isinstance(obj, dict):
        return types.MappingProxyType({k: _freeze(v) for k, v in obj.items()})
    if isinstance(obj, list):
        return tuple(_freeze(v) for v in obj)
    return obj


def _stale(spec, gen_dir, msg):
    if paths.in_installed_package(gen_dir):
        raise StaleGeneratedCodeError(
            f"{msg}. This is the installed pm2dof's own generated code for a shipped model: "
            f"reinstall pm2dof (`pip install --force-reinstall pm2dof`)")
    raise StaleGeneratedCodeError(
        f"{msg}. Run `{paths.derive_command(spec.path, gen_dir)}`")


def _check_generated(spec, gen_dir):
    """Refuse generated code that is missing or was derived from another formulation; compile
    the C on first use when its library is missing or older than it (never inside an installed
    package)."""
    manifest_path = gen_dir / "manifest.json"
    if not manifest_path.is_file():
        _stale(spec, gen_dir, f"no generated code for model file {spec.path} in {gen_dir} "
                              f"({manifest_path.name} is missing)")
    manifest = json.loads(manifest_path.read_text())
    if manifest.get("formulation_sha256") != spec.formulation_sha256:
        _stale(spec, gen_dir,
               f"{gen_dir} was generated from a different formulation than {spec.path} (hash "
               f"{str(manifest.get('formulation_sha256', '?'))[:12]} != "
               f"{spec.formulation_sha256[:12]}): the legs, geometry or friction model changed")
    name = manifest.get("model", spec.name)
    c_file = gen_dir / f"{name}.c"
    lib = gen_dir / f"lib{name}.so"
    if not c_file.is_file():
        _stale(spec, gen_dir, f"{c_file} is missing")
    if not build.library_is_fresh(c_file, lib, manifest.get("files", {}).get(c_file.name)):
        if paths.in_installed_package(gen_dir):
            _stale(spec, gen_dir, f"the compiled library {lib} is missing or older than {c_file}")
        print(f"pm2dof: compiling {c_file} (first use of this generated code; a few seconds)",
              file=sys.stderr, flush=True)
        build.compile_library(c_file, lib)
    return manifest, lib


class Model:
    """A planar RR parallel manipulator with its compiled model functions. Immutable.

    Build with :func:`load_model`. Attributes: ``name``, ``spec`` (the validated model file),
    ``n_legs``, ``bases`` (n, 2) m, ``param_names`` (5n,), ``theta_nominal`` (5n,) (Tables
    1-2), ``singularity_threshold`` (type I), ``parallel_singularity_threshold`` (type II),
    ``manifest``, ``generated`` (the folder of the generated C), ``library`` (path of the
    compiled C).
    Angles in rad, lengths in m; q = [qa_1..qa_n, qb_1..qb_n].

    Two kinds of singularity are guarded (:meth:`singularity_measures`): type I, a leg
    stretched or folded (min_i |sin(qb_i - qa_i)| -> 0, W unbounded), and type II, the
    actuation losing a direction (all distal links parallel, S^T rank-deficient). Functions
    of the pose raise :class:`SingularityError` naming the kind when either measure is below
    its threshold in ``[limits]``.

    A Model holds one small scratch buffer, so one Model must not be called from two threads
    at once; load one Model per thread.
    """

    __slots__ = ("spec", "manifest", "library", "generated", "_lib", "_f", "_layouts", "_sing_thr",
                 "_sing", "_residual", "__weakref__")

    #: names of the two singularity measures, in the order of :meth:`singularity_measures`
    SINGULARITY_KINDS = ("type I (a leg's links aligned)",
                         "type II (parallel: all distal links aligned, the actuators lose a "
                         "task direction)")

    def __init__(self, spec, gen_dir=None):
        gen_dir = (Path(gen_dir).expanduser().absolute() if gen_dir is not None
                   else paths.default_generated_dir(spec.path))
        manifest, lib_path = _check_generated(spec, gen_dir)
        lib = _cbind.Library(str(lib_path))
        funcs = {}
        for short in _FUNCTIONS:
            f = _cbind.Function(lib, f"{spec.name}_{short}")
            want = manifest["functions"].get(f.name)
            have = {"inputs": [[a, k] for a, k in zip(f.names_in, f.sizes_in)],
                    "outputs": [[a, k] for a, k in zip(f.names_out, f.sizes_out)]}
            if want != have:
                _stale(spec, gen_dir, f"{lib_path}: {f.name} has signature {have}, manifest "
                                      f"says {want}")
            # model functions never hand back NaN/inf silently; ik and fk turn NaN into a
            # WorkspaceError themselves; controller steps and the plant report by status
            f.check_outputs = short not in _STEPPING + _PATH and short not in ("ik", "fk")
            funcs[short] = f
        for k, v in (("spec", spec), ("manifest", _freeze(manifest)), ("library", str(lib_path)),
                     ("generated", str(gen_dir)),
                     ("_lib", lib), ("_f", types.MappingProxyType(funcs)),
                     ("_layouts", types.MappingProxyType(
                         {name: Layout(name, fl) for name, fl in manifest["layouts"].items()})),
                     ("_sing_thr", (spec.limits["singularity_threshold"],
                                    spec.limits["parallel_singularity_threshold"])),
                     ("_sing", array.array("d", [0.0, 0.0])),   # array: [0] ~3x faster than numpy
                     ("_residual", np.zeros(spec.n_legs))):
            object.__setattr__(self, k, v)

    def __setattr__(self, key, value):
        raise AttributeError(f"Model is immutable (tried to set {key!r})")

    def __delattr__(self, key):
        raise AttributeError(f"Model is immutable (tried to delete {key!r})")

    def __repr__(self):
        return (f"<Model {self.name!r}: {self.n_legs} legs, {len(self.param_names)} parameters, "
                f"friction {self.spec.friction!r}>")

    # --- description ---------------------------------------------------------------------
    name = property(lambda self: self.spec.name)
    n_legs = property(lambda self: self.spec.n_legs, doc="number of legs (= actuators)")
    param_names = property(lambda self: self.spec.param_names, doc="names of theta, in order")
    theta_nominal = property(lambda self: self.spec.theta_nominal, doc="(5n,) Tables 1-2")
    singularity_threshold = property(lambda self: self._sing_thr[0],
                                     doc="type I: smallest allowed min_i |sin(qb_i - qa_i)|")
    parallel_singularity_threshold = property(
        lambda self: self._sing_thr[1],
        doc="type II: smallest allowed normalised sigma_min of the distal directions")

    @property
    def bases(self):
        """(n, 2) base positions A_i, m."""
        b = self.spec.bases
        b.setflags(write=False)
        return b

    def function(self, short_name):
        """The bound generated function ``<name>_<short_name>`` (for benchmarks and tools)."""
        return self._f[short_name]

    def layout(self, name):
        """The :class:`~pm2dof.core.layout.Layout` ``name`` of the manifest (e.g. "plant",
        "cl_state"), built once."""
        return self._layouts[name]

    # --- argument handling ---------------------------------------------------------------
    # Fast path: the arguments go straight to the C binding, which checks the dtype (float64),
    # contiguity, element count and finiteness of every one. Only if it rejects an argument
    # are the arguments converted (lists, ints, float32 ...) and the call retried.
    def _coerce(self, f, args):
        out = []
        for name, size, x in zip(f.names_in, f.sizes_in, args):
            try:
                if np.iscomplexobj(x):
                    raise TypeError("complex values are not allowed")
                a = np.ascontiguousarray(x, dtype=np.float64)
            except (TypeError, ValueError) as exc:
                raise TypeError(f"{name} must be an array of {size} real numbers, got "
                                f"{type(x).__name__}: {exc}") from None
            if a.shape != (size,) and not (size == 1 and a.ndim == 0):
                raise ValueError(f"{f.name}: input '{name}' must have shape ({size},), got shape "
                                 f"{a.shape}")
            out.append(a)
        return out

    def _eval(self, short, shape, out, *args):
        """Evaluate ``<name>_<short>(*args) -> out [, sing]``; raise on a singular pose."""
        if out is None:
            out = np.empty(shape)
        elif type(out) is not np.ndarray or out.shape != shape:
            raise ValueError(f"out must be a C-contiguous float64 array of shape {shape}, got "
                             f"{type(out).__name__} {getattr(out, 'shape', '')}")
        f = self._f[short]
        sing = self._sing if f.n_out == 2 else None
        outs = (out, sing) if sing is not None else (out,)
        nonfinite = None  # a NaN/inf result from finite inputs: a singular pose explains it
        try:
            f(*args, *outs)
        except _cbind.NonFiniteOutputError as exc:
            nonfinite = exc
        except (TypeError, ValueError):  # not float64 arrays: convert (clear errors) and retry
            args = self._coerce(f, args)
            try:
                f(*args, *outs)
            except _cbind.NonFiniteOutputError as exc:
                nonfinite = exc
        if sing is not None and not (sing[0] >= self._sing_thr[0] and
                                     sing[1] >= self._sing_thr[1]):
            if sing[0] != sing[0] and short == "forward_dynamics":
                self.ik(args[0])  # NaN measure: some leg cannot reach xe; ik names it
            raise SingularityError(f"{short}: {self.singularity_message(sing)}")
        if nonfinite is not None:
            raise nonfinite
        return out

    def singularity_message(self, sing):
        """Which kind of singularity the measures ``sing`` = [type I, type II] hit, with the
        measure, its threshold and the model-file key (for error messages)."""
        kind = 0 if not sing[0] >= self._sing_thr[0] else 1
        what = ("min_i |sin(qb_i - qa_i)|", "sigma_min(S with unit rows) / sqrt(n/2)")[kind]
        key = ("singularity_threshold", "parallel_singularity_threshold")[kind]
        return (f"the pose is too close to a {self.SINGULARITY_KINDS[kind]} singularity: "
                f"{what} = {sing[kind]:.4g} < threshold {self._sing_thr[kind]} (limits.{key})")

    # --- kinematics ----------------------------------------------------------------------
    def ik(self, xe, out=None):
        """Inverse kinematics for the configured assembly modes.

        Parameters
        ----------
        xe : array_like (2,)
            End-effector position [x, y], m.

        Returns
        -------
        q : ndarray (2n,)
            [qa_1..qa_n, qb_1..qb_n], absolute angles, rad.

        Raises
        ------
        WorkspaceError
            If a leg cannot reach ``xe`` (names the leg and its distance), or, for two legs,
            if the pose at ``xe`` is not in the model's assembly mode (``fk_branch``): ``fk``
            could not return to it. So ``fk(ik(xe)[:n]) == xe`` wherever ``ik`` answers.
        """
        out = self._eval("ik", (2 * self.n_legs,), out, xe)
        if not np.isfinite(out).all():
            xe = np.asarray(xe, dtype=float).ravel()
            for i, leg in enumerate(self.spec.legs):
                dist = float(np.hypot(*(xe - leg.base)))
                lo, hi = abs(leg.la - leg.lb), leg.la + leg.lb
                if not lo <= dist <= hi:
                    raise WorkspaceError(
                        f"xe = {xe.tolist()} is out of reach of leg {i + 1}: distance from its "
                        f"base {dist:.6g} m is outside [{lo:.6g}, {hi:.6g}] m")
            if self.n_legs == 2:
                side = {1: "left", -1: "right"}[self.spec.fk_branch]
                raise WorkspaceError(
                    f"xe = {xe.tolist()} is reachable by both legs, but not in the model's "
                    f"assembly mode: with these elbows the tip lies on the other side of the "
                    f"line B1 -> B2 than model.fk_branch = {side!r}, so fk could not return to "
                    f"it (the parallel singularity, distal links aligned, separates the modes)")
            raise WorkspaceError(f"inverse kinematics failed at xe = {xe.tolist()}")
        return out

    closure_tolerance = property(
        lambda self: self.spec.sensing["closure_tolerance"],
        doc="largest |O - B_i| - lb_i, m, that fk and the controllers accept from the encoders")

    def fk(self, qa, out=None):
        """Forward kinematics from the measured active angles.

        Parameters
        ----------
        qa : array_like (n,)
            Active (encoder) angles, rad, absolute from +x.

        Returns
        -------
        xe : ndarray (2,)
            End-effector position O, m: for n >= 3 legs the least-squares point of the n
            elbow circles (B_i = A_i + la_i u(qa_i), radius lb_i), for two legs their
            intersection on the ``fk_branch`` side.

        Raises
        ------
        WorkspaceError
            No assembly exists (a five-bar's circles do not meet), or (:class:`ClosureError`, a
            WorkspaceError) the angles do not close the loops: some leg's closure residual | |O - B_i| - lb_i | exceeds
            :attr:`closure_tolerance` (``[sensing] closure_tolerance``, by default a few
            encoder steps at the active link's length). With three encoders for two degrees of
            freedom, the extra legs are a check of the measurement; the message names the leg
            and its residual in m.
        """
        if out is None:
            out = np.empty(2)
        elif type(out) is not np.ndarray or out.shape != (2,):
            raise ValueError(f"out must be a C-contiguous float64 array of shape (2,), got "
                             f"{type(out).__name__} {getattr(out, 'shape', '')}")
        f, r = self._f["fk"], self._residual
        try:
            f(qa, out, r)
        except (TypeError, ValueError):
            qa = self._coerce(f, (qa,))[0]
            f(qa, out, r)
        tol = self.spec.sensing["closure_tolerance"]
        if not (np.isfinite(out).all() and np.isfinite(r).all()):
            raise WorkspaceError(f"no assembly of the legs has active angles qa = "
                                 f"{np.asarray(qa).tolist()} rad")
        worst = int(np.argmax(np.abs(r)))
        if not abs(r[worst]) <= tol:
            raise ClosureError(
                f"the active angles qa = {np.asarray(qa).tolist()} rad do not close the loops: "
                f"leg {worst + 1}'s tip misses the common point by {r[worst]:+.3g} m (closure "
                f"residual |O - B_i| - lb_i; tolerance {tol:.3g} m, [sensing] "
                f"closure_tolerance): inconsistent encoders, or angles of another robot")
        return out

    def H(self, q, out=None):
        """Loop-closure constraints H(q) (2(n-1),), m (eq. 5)."""
        return self._eval("H", (2 * (self.n_legs - 1),), out, q)

    def A(self, q, out=None):
        """Constraint Jacobian A = dH/dq (2(n-1), 2n) (eq. 6)."""
        n = self.n_legs
        return self._eval("A", (2 * (n - 1), 2 * n), out, q)

    def singularity(self, q, out=None):
        """Per-leg singularity measure sin(qb_i - qa_i) (n,); W is singular where one is 0."""
        return self._eval("singularity", (self.n_legs,), out, q)

    def singularity_measures(self, q, out=None):
        """The two singularity measures at the pose q (2n,), each in [0, 1], 0 when singular.

        ``[0]`` type I (a leg): min_i |sin(qb_i - qa_i)|, compared with
        ``limits.singularity_threshold``; ``[1]`` type II (parallel, the actuation): the smallest
        singular value of S with its rows normalised (the distal links' directions), over its
        largest possible value sqrt(n/2), i.e. sqrt(1 - |sum_i exp(2 i qb_i)| / n); 0 when all
        distal links are parallel; compared with ``limits.parallel_singularity_threshold``.
        Never raises on a singular pose: it is the measure.
        """
        return self._eval("singularity_measures", (2,), out, q)

    def W(self, q, out=None):
        """W (2n, 2) with qd = W xed (eq. 7). Raises SingularityError near singular poses."""
        return self._eval("W", (2 * self.n_legs, 2), out, q)

    def S(self, q, out=None):
        """S (n, 2), the actuated rows of W: qd_a = S xed (eq. 8)."""
        return self._eval("S", (self.n_legs, 2), out, q)

    def Wdot(self, q, xed, out=None):
        """dW/dt (2n, 2) along qd = W xed, with xed (2,) in m/s (eq. 9), 1/s per m."""
        return self._eval("Wdot", (2 * self.n_legs, 2), out, q, xed)

    # --- dynamics ------------------------------------------------------------------------
    def M(self, q, theta, out=None):
        """Open-chain joint-space inertia M (2n, 2n), kg*m^2 (eq. 3)."""
        n = self.n_legs
        return self._eval("M", (2 * n, 2 * n), out, q, theta)

    def C(self, q, qd, theta, out=None):
        """Open-chain Coriolis/centrifugal matrix C (2n, 2n) at joint velocity qd (eq. 3)."""
        n = self.n_legs
        return self._eval("C", (2 * n, 2 * n), out, q, qd, theta)

    def Me(self, q, theta, out=None):
        """Task-space inertia Me = W^T M W (2, 2), kg (eq. 12)."""
        return self._eval("Me", (2, 2), out, q, theta)

    def Ce(self, q, xed, theta, out=None):
        """Task-space Coriolis matrix Ce = W^T (M Wdot + C W) (2, 2), kg/s (eq. 12)."""
        return self._eval("Ce", (2, 2), out, q, xed, theta)

    def StF(self, q, xed, theta, out=None):
        """Friction in task space S^T f_a(S xed) (2,), N (eqs. 2, 10)."""
        return self._eval("StF", (2,), out, q, xed, theta)

    def Y(self, q, xed, xrd, xrdd, out=None):
        """Regressor Y (2, 5n): Y theta = Me xrdd + Ce(q, W xed) xrd + S^T f_a(S xed) (eq. 13).

        Columns follow :attr:`param_names`; friction uses sign(0) = +1.
        """
        return self._eval("Y", (2, len(self.param_names)), out, q, xed, xrd, xrdd)

    def torque_splits(self, q, u, tau_max=None, preload=None, preload_sign=None):
        """The actuator torques of every split for the task force ``u`` (2,), N, at pose q (2n,).

        All satisfy S^T tau = u (eqs. 10, 21) to rounding; ``tau_max`` (n,) N*m defaults to
        ``[limits]``, ``preload`` (n,) N*m and ``preload_sign`` (n,) +-1 to ``[control]``. No
        clipping is applied here (the controller steps clip). Raises SingularityError at a pose
        too close to a singularity of either kind.

        Returns
        -------
        dict
            ``min_norm`` (n,) eq. 21; ``min_max`` (n,) and ``min_max_ratio`` = max_i |tau_i| /
            tau_max,i at that optimum (> 1: u is beyond the actuators); ``preload`` (n,) and
            ``preload_mode`` (0 the preload holds, 1 only the largest worst-case preload margin
            fits the limits, 2 not even the limits: min-max torques).
        """
        n, ctl = self.n_legs, self.spec.control
        w = self.spec.limits["tau_max"] if tau_max is None else tau_max
        pre = ctl["preload"] if preload is None else preload
        sgn = ctl["preload_sign"] if preload_sign is None else preload_sign
        args = [np.ascontiguousarray(a, dtype=float) for a in (q, u, w, sgn, pre)]
        f = self._f["torque_splits"]
        outs = (np.empty(n), np.empty(n), np.empty(1), np.empty(n), np.empty(1), np.empty(2))
        try:
            f(*args, *outs)
        except (TypeError, ValueError):
            f(*self._coerce(f, args), *outs)
        sing = outs[5]
        if not (sing[0] >= self._sing_thr[0] and sing[1] >= self._sing_thr[1]):
            raise SingularityError(f"torque_splits: {self.singularity_message(sing)}")
        return {"min_norm": outs[0], "min_max": outs[1], "min_max_ratio": float(outs[2][0]),
                "preload": outs[3], "preload_mode": int(outs[4][0])}

    def forward_dynamics(self, xe, xed, tau_a, theta, out=None):
        """Task-space acceleration xedd (2,), m/s^2, from eq. 12 with eq. 2 friction.

        Solves Me xedd = S^T tau_a - Ce xed - S^T f_a at the pose ``xe`` (2,) m, velocity
        ``xed`` (2,) m/s, actuator torques ``tau_a`` (n,) N*m and parameters ``theta``.
        """
        return self._eval("forward_dynamics", (2,), out, xe, xed, tau_a, theta)


def load_model(model=None, generated=None):
    """Load a model file and bind its generated, compiled C.

    Parameters
    ----------
    model : str or pathlib.Path, optional
        A shipped model's name (``"fivebar"``; ``pm2dof models`` lists them) or the path of a
        model file (``"~/robots/myrobot.toml"``). Default: ``"shang2010"``, the paper's robot.
    generated : str or pathlib.Path, optional
        The folder of the model's generated C. Default: the one ``pm2dof derive`` writes,
        ``generated/<stem>/`` beside the model file (a shipped model's code comes with pm2dof).

    Returns
    -------
    Model

    Raises
    ------
    ModelFileError
        The model file is unreadable or invalid, or the name is not a shipped model.
    StaleGeneratedCodeError
        The generated code is missing or was derived from another formulation of the model
        (the message names the ``pm2dof derive ...`` command to run).
    pm2dof.core.build.BuildError
        The library had to be compiled (first use, or the C is newer) and that failed, or
        there is no C compiler (the message says what to install).

    Examples
    --------
    >>> import pm2dof
    >>> m = pm2dof.load_model()
    >>> m.n_legs, m.param_names[:3]
    (3, ('alpha1', 'alpha2', 'alpha3'))
    >>> q = m.ik([0.25, 0.26])
    >>> bool(abs(m.fk(q[:3]) - [0.25, 0.26]).max() < 1e-12)
    True
    >>> pm2dof.load_model("fivebar").n_legs
    2
    """
    return Model(read_model_file(paths.resolve_model(model)), generated)
