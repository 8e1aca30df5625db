# The runtime Model: a frozen model file plus its compiled generated C, bound through pm2dof.core._cbind.
"""The runtime model of an n-leg planar parallel manipulator with task dimension m.

:func:`load_model` reads a model file, checks that ``generated/<name>/`` was derived from it
(``manifest.json``) and binds the compiled functions. Every method is one call into the
generated C. Inputs are float arrays of the documented length (lists and other dtypes are
converted, on a slower path); outputs are new arrays unless ``out=`` is given, in which case
the result is written there (no allocation) and returned.
"""
import math
import types
import warnings
from pathlib import Path

import numpy as np

from . import build, contract, paths
from .derivatives import (
    DerivativeMethods,
    ForwardDynamicsJacobians,
    InverseDynamicsJacobians,
    SampledStepJacobians,
)
from .errors import (
    ArgumentError,
    ArgumentTypeError,
    ClosureError,
    CompileWarning,
    DesignError,
    NonFiniteError,
    SingularityError,
    StaleGeneratedCodeError,
    WorkspaceError,
)
from .fastmethod import fast_method
from .layout import Layout
from .manifest import Manifest
from .measures import singularity_words
from .mechanism import (
    INERTIAL,
    LEG_KINDS,
    PLATFORM_PARAMS,
    inertia_problem,
    is_friction_param,
    platform_inertia_problem,
)
from .model_file import read_model_file
from .poses import PoseMethods
from .status import Status
from .task import active_coordinates, is_rr_point

try:
    from . import _cbind
except ImportError:  # a source tree whose C extension was never built
    raise ImportError(
        f"pm2dof is not built: its C extension pm2dof.core._cbind is missing from "
        f"{Path(__file__).parent}; build it with `pip install -e .` (or `make install`) in the "
        f"source tree") from None
from .binding import call  # noqa: E402  (after the check above: it needs the C extension)

__all__ = ["Model", "load_model", "require_model"]



def _freeze(obj):
    """Read-only view of JSON data: dicts -> mappingproxy, lists -> tuples."""
    if isinstance(obj, dict):
        return types.MappingProxyType({k: _freeze(v) for k, v in obj.items()})
    if isinstance(obj, list):
        return tuple(_freeze(v) for v in obj)
    return obj


def _design_values(spec):
    """(k,) float64 of spec's design (None without [design]): the bound input ``design``."""
    design = spec.design
    return None if design is None else np.array(design.values, dtype=float)


def _design_text(spec):
    """", at design la = 0.25, ..." for a model with a [design] table, else ""."""
    design = spec.design
    if design is None:
        return ""
    return " at design " + design.describe()


def _check_design(spec, gen_dir, manifest):
    """The generated code's design input must be the model file's [design] variables."""
    have = (manifest.get("design") or {}).get("names")
    design = spec.design
    want = list(design.names) if design is not None else None
    if (list(have) if have is not None else None) != want:
        _stale(spec, gen_dir, f"{gen_dir} was generated with design variables {have}, the "
                              f"model file has {want}")


def _stale(spec, gen_dir, msg):
    if paths.in_installed_package(gen_dir):
        raise StaleGeneratedCodeError(
            f"{msg}. This is the installed pm2dof's own generated code for a shipped model: "
            f"reinstall pm2dof (`pip install --force-reinstall pm2dof`)")
    raise StaleGeneratedCodeError(
        f"{msg}. Run `{paths.derive_command(spec.path, gen_dir)}`")


def _check_generated(spec, gen_dir):
    """Refuse generated code that is missing or was derived from another formulation; compile
    the C on first use when its library is missing, older than it or compiled with other flags
    (never inside an installed package), saying so by a :class:`CompileWarning` before and
    after the compiler runs.
    Returns the folder's :class:`~pm2dof.core.manifest.Manifest`."""
    manifest = Manifest.read(gen_dir)
    if manifest is None:
        missing = not (gen_dir / "manifest.json").is_file()
        _stale(spec, gen_dir, f"no generated code for model file {spec.path} in {gen_dir} "
                              f"(manifest.json is {'missing' if missing else 'unreadable'}; if "
                              f"it was derived into another folder, pass --generated DIR, or "
                              f"load_model(..., generated=DIR))")
    if manifest.get("formulation_sha256") != spec.formulation_sha256:
        msg = (f"{gen_dir} was generated from a different formulation than {spec.path} (hash "
               f"{str(manifest.get('formulation_sha256', '?'))[:12]} != "
               f"{spec.formulation_sha256[:12]})")
        source = manifest.model_file()
        if source is not None and spec.path is not None and \
                not manifest.owned_by(spec.path) and not paths.in_installed_package(gen_dir):
            # another model file's folder: derive refuses to overwrite it without --force
            shipped = Path(gen_dir).resolve().parent == paths.SHIPPED_GENERATED.resolve()
            raise StaleGeneratedCodeError(
                f"{msg}: it holds the code of another model file, {source}. Derive this one "
                f"into its own folder, `{paths.derive_command(spec.path, None)}` (generated/"
                f"<stem>/ beside it, found without --generated)" + (
                    "" if shipped else f", or overwrite that folder: "
                    f"`{paths.derive_command(spec.path, gen_dir)} --force`"))
        _stale(spec, gen_dir, f"{msg}: the legs, geometry or friction model changed")
    if manifest.get("status_codes") != Status.codes():
        _stale(spec, gen_dir, f"{gen_dir}'s status codes {manifest.get('status_codes')} are not "
                              f"this pm2dof's {Status.codes()}: the code was generated by another "
                              f"version")
    if manifest.name is None:
        manifest.name = spec.name
    c_file, lib = manifest.c_file, manifest.library
    if not c_file.is_file():
        _stale(spec, gen_dir, f"{c_file} is missing")
    if not manifest.library_is_fresh():
        if paths.in_installed_package(gen_dir):
            _stale(spec, gen_dir, f"the compiled library {lib} is missing, older than {c_file} "
                                  f"or compiled with other flags")
        build.compile_library(c_file, lib, progress=lambda msg: warnings.warn(
            msg + (f" (first use of the generated code in {gen_dir})"
                   if msg.startswith("compiling") else ""), CompileWarning, stacklevel=2))
    missing = [f for f in contract.function_names() if f not in manifest.function_names()]
    if missing:
        _stale(spec, gen_dir, f"{manifest.path} lists no {', '.join(missing[:3])}"
                              f"{' ...' if len(missing) > 3 else ''}: the code was generated by "
                              f"another version")
    diag = manifest.get("layouts", {}).get("diag")
    if diag is None or [list(f) for f in diag] != [list(f) for f in contract.diag_layout(
            len(spec.task_names))]:
        _stale(spec, gen_dir, f"{manifest.path}'s diag layout {diag} is not "
                              f"{contract.diag_layout(len(spec.task_names))}")
    return manifest, lib


def _mode_geometry(spec):
    """A platform's legs for :meth:`Model._fk_same_mode`, one tuple each: (kind, its index in
    LEG_KINDS: 0 RRR, 1 PRR, 2 RPR (one working mode: not checked), base x, y, attachment a_x,
    a_y, la (RRR), the rail's unit direction d_x, d_y (PRR))."""
    legs = []
    for lg in spec.legs:
        kind = LEG_KINDS.index(lg.kind)
        d = ((lg.rail_end[0] - lg.base[0]) / lg.rail_length,
             (lg.rail_end[1] - lg.base[1]) / lg.rail_length) if kind == 1 else (0.0, 0.0)
        legs.append((kind, float(lg.base[0]), float(lg.base[1]), float(lg.attach[0]),
                     float(lg.attach[1]), float(lg.la or 0.0), *d))
    return tuple(legs)


def _mode_sides(legs, qa, xe):
    """Each leg's working mode at active coordinates qa (n,) and platform pose xe (3,), as a
    signed number (0.0 for an RPR leg): an RRR leg's u(qa) x (P_i - B_i), the side of its
    elbow B_i; a PRR leg's (P_i - B_i) . d, its slider B_i behind or ahead of the foot of the
    perpendicular from P_i on the rail d. P_i = p + R(phi) a_i, its attachment point. Plain
    floats: this runs on every platform fk from Python (a few legs)."""
    qa = qa.tolist() if isinstance(qa, np.ndarray) else [float(v) for v in qa]
    x, y, phi = xe.tolist()
    c, s = math.cos(phi), math.sin(phi)
    out = []
    for i, (kind, bx, by, ax, ay, la, dx, dy) in enumerate(legs):
        px, py = x + c * ax - s * ay, y + s * ax + c * ay
        if kind == 0:
            ux, uy = math.cos(qa[i]), math.sin(qa[i])
            out.append(ux * (py - by - la * uy) - uy * (px - bx - la * ux))
        elif kind == 1:
            out.append((px - bx - qa[i] * dx) * dx + (py - by - qa[i] * dy) * dy)
        else:
            out.append(0.0)
    return out


def _shapes(n, m, p, h):
    """The returned shape(s) of each Model method bound by :func:`_methods` (n legs, task
    dimension m, p parameters); a tuple of shapes for the derivative methods (their
    NamedTuple's fields); (1,) for the energies (returned as a float). H (eq. 5) has h rows:
    2 (n - 1) for legs meeting at a point (tip_1 = tip_i), 2 n for a platform (tip_i =
    P_i(xe), xe from q)."""
    return {"ik": (2 * n,), "fk": (m,), "H": (h,), "A": (h, 2 * n),
            "singularity": (n,), "singularity_measures": (2,), "W": (2 * n, m), "S": (n, m),
            "Wdot": (2 * n, m), "M": (2 * n, 2 * n), "C": (2 * n, 2 * n), "Me": (m, m),
            "Ce": (m, m), "StF": (m,), "Y": (m, p), "Ge": (m,), "forward_dynamics": (m,),
            "sampled_step": (2 * m,), "inverse_dynamics": (m,),
            "forward_dynamics_jacobians": ((m, m), (m, m), (m, n), (m, p)),
            "sampled_step_jacobians": ((2 * m, 2 * m), (2 * m, n)),
            "inverse_dynamics_jacobians": ((m, m), (m, m)),
            "kinetic_energy": (1,), "potential_energy": (1,)}


_KINDS = {"forward_dynamics_jacobians": ForwardDynamicsJacobians,
          "sampled_step_jacobians": SampledStepJacobians,
          "inverse_dynamics_jacobians": InverseDynamicsJacobians}


def _method(short, f, shape, sing, sing_thr, residual, closure_tol):
    """The fast path of the Model method ``short``: one :class:`_cbind.Method` (one C call that
    binds, evaluates and checks) of its bound function ``f``, returning ``shape``. It refuses
    (``_cbind.Refused``) what it does not accept: a bad argument, a non-finite result, a
    singular pose, fk's loops not closing, a sample period that is not a float > 0 (the
    sampled step's), a theta of None (the energies'); the method then takes its checked path,
    which names the problem in a typed error. The methods decorated with
    :func:`~pm2dof.core.fastmethod.fast_method` call it from C; the energies' returns a
    float."""
    kind = _KINDS.get(short)
    outs = list((None, *shape) if kind else (shape,))   # the Jacobians skip the value
    guard = None
    if len(outs) < f.n_out and f.names_out[-1] == "sing":   # the pose's measures, checked
        outs.append(sing)
        guard = (f.n_out - 1, "at_least", sing_thr)
    elif short == "fk":                                     # the closure residuals
        outs.append(residual)
        guard = (1, "abs_at_most", closure_tol)
    positive = (f.n_in - 1,) if short.startswith("sampled_step") else None   # the period
    return _cbind.Method(f, (None,) * f.n_in, tuple(outs), empty=np.empty, kind=kind,
                         finite=True, guard=guard, positive=positive,
                         scalar=short.endswith("_energy"))


def _methods(funcs, shapes, sing, sing_thr, residual, closure_tol):
    """{short: :func:`_method`} for every entry of ``shapes``."""
    return {short: _method(short, funcs[short], shape, sing, sing_thr, residual, closure_tol)
            for short, shape in shapes.items()}


class _Functions(dict):
    """The bound functions {short: Function} of a model at a design (:meth:`Model.at_design`),
    each cloned from the loaded model's (``root``) at ``design`` on first use: a design whose
    objectives call two functions pays for two. A name bound already is a plain dict lookup;
    iterating, ``len``, ``in``, ``keys``, ``items``, ``values`` and ``copy`` see every function (and
    bind the rest), in ``root``'s order. Read through a ``MappingProxyType``."""

    __slots__ = ("_root", "_design")

    def __init__(self, root, design):
        super().__init__()
        self._root, self._design = root, design

    def __missing__(self, short):
        f = self._root[short]                                 # KeyError for an unknown name
        g = f.clone(fixed=self._design if f.fixed is not None else None)
        dict.__setitem__(self, short, g)
        return g

    def _all(self):
        if dict.__len__(self) < len(self._root):
            bound = [(short, self[short]) for short in self._root]
            dict.clear(self)
            dict.update(self, bound)
        return self

    def __iter__(self):
        return dict.__iter__(self._all())

    def __len__(self):
        return len(self._root)

    def __contains__(self, short):
        return short in self._root

    def keys(self):
        return dict.keys(self._all())

    def items(self):
        return dict.items(self._all())

    def values(self):
        return dict.values(self._all())

    def get(self, short, default=None):
        return self[short] if short in self._root else default

    def copy(self):
        return dict(self.items())


class _Pending(dict):
    """The fast paths {short: :class:`_cbind.Method`} of a model at a design, each built on its
    first use (:func:`_method`, ``__missing__``) and kept: a design pays for the methods it
    calls. A Method built already is a plain dict lookup, as on a loaded model (the FastMethod
    descriptors find it there; a name not built yet takes their Python path once, which builds
    it). Holds the model's bound functions and scratch buffers, not the model (no cycle)."""

    __slots__ = ("_funcs", "_shapes", "_args")

    def __init__(self, funcs, shapes, sing, sing_thr, residual, closure_tol):
        super().__init__()
        self._funcs, self._shapes = funcs, shapes
        self._args = (sing, sing_thr, residual, closure_tol)

    def __missing__(self, short):
        meth = _method(short, self._funcs[short], self._shapes[short], *self._args)
        dict.__setitem__(self, short, meth)
        return meth


class Model(DerivativeMethods, PoseMethods):
    """A planar parallel manipulator with its compiled model functions. Immutable.

    Build with :func:`load_model`. Attributes: ``name``, ``spec`` (the validated model file),
    ``n_legs``, ``dof`` (m, the task dimension: 2 for a point end effector, 3 for a platform),
    ``task_names`` (``("x", "y")`` or ``("x", "y", "phi")``), ``bases`` (n, 2) m,
    ``param_names`` (p,), ``theta_nominal`` (p,) (Tables 1-2; p = 5n for the paper's
    family), ``singularity_threshold`` (type I), ``parallel_singularity_threshold`` (type II),
    ``manifest``, ``generated`` (the folder of the generated C), ``library`` (path of the
    compiled C).
    Angles in rad, lengths in m; q = [qa_1..qa_n, qb_1..qb_n]. Task-space arrays have m
    entries in the order of ``task_names`` (x, y in m; phi, the platform's orientation, in
    rad). The functions of q take it as given: q must close every loop (eq. 5), as
    :meth:`ik` returns it; :meth:`H` gives the closure residual, and :meth:`fk` refuses active
    angles that do not close (:class:`ClosureError`).

    Two kinds of singularity are guarded (:meth:`singularity_measures`): type I, a leg's
    Jacobian singular (an RRR leg stretched or folded, min_i |sin(qb_i - qa_i)| -> 0; a PRR
    leg's link across its rail; W unbounded), and type II, the actuation losing a direction
    (S^T rank-deficient: a point's distal links all parallel, a platform's lines of action
    concurrent or all parallel). Functions of the pose raise :class:`SingularityError` naming
    the kind and its measure when either measure is below its threshold in ``[limits]``.

    A Model holds one small scratch buffer, so one Model must not be called from two threads
    at once; load one Model per thread.

    Parameters
    ----------
    spec : pm2dof.core.model_file.ModelSpec
        The validated model file (``pm2dof.core.model_file.read_model_file``).
    gen_dir : str or Path, optional
        Folder of the generated C and its manifest; the model's default folder
        (``pm2dof/generated/<name>/``) when None.
    """

    __slots__ = ("spec", "manifest", "library", "generated", "_lib", "_f", "_fast", "_layouts",
                 "_sing_thr", "_sing", "_residual", "_m", "_task_names", "_modes", "_words",
                 "_design", "_manifest_obj", "_root", "__weakref__")

    def __init__(self, spec, gen_dir=None):
        gen_dir = (Path(gen_dir).expanduser().absolute() if gen_dir is not None
                   else paths.default_generated_dir(spec.path))
        manifest, lib_path = _check_generated(spec, gen_dir)
        _check_design(spec, gen_dir, manifest)
        self._bind(spec, gen_dir, manifest, lib_path, _cbind.Library(str(lib_path)))

    def _bind(self, spec, gen_dir, manifest, lib_path, lib):
        """Resolve and check every generated function of ``lib`` for ``spec`` (at its design,
        if any), then :meth:`_assemble`."""
        design = _design_values(spec)
        funcs = {}
        for short in manifest.function_names():        # every function the derivation wrote
            want = manifest.signature(short)
            takes_design = bool(want["inputs"]) and want["inputs"][-1][0] == "design"
            if takes_design:   # the design is bound once: callers see the other inputs only
                f = _cbind.Function(lib, f"{manifest.name}_{short}", fixed=design)
                want = {"inputs": want["inputs"][:-1], "outputs": want["outputs"]}
            else:
                f = _cbind.Function(lib, f"{manifest.name}_{short}")
            have = {"inputs": [[a, k] for a, k in zip(f.names_in, f.sizes_in)],
                    "outputs": [[a, k] for a, k in zip(f.names_out, f.sizes_out)]}
            if want != have:
                _stale(spec, gen_dir, f"{lib_path}: {f.name} has signature {have}, manifest "
                                      f"says {want}")
            # model functions never hand back NaN/inf silently; ik and fk turn NaN into a
            # WorkspaceError themselves; controller steps and the plant report by status
            # (and the energies check theirs: a pose out of reach is a WorkspaceError)
            f.check_outputs = not contract.reports_by_status(short)
            funcs[short] = f
        self._assemble(spec, gen_dir, manifest, lib_path, lib, funcs, _freeze(manifest.data),
                       types.MappingProxyType({name: Layout(name, fl) for name, fl in
                                               manifest.get("layouts", {}).items()}))

    def _assemble(self, spec, gen_dir, manifest, lib_path, lib, funcs, frozen, layouts,
                  root=None, words=None):
        """Set every attribute from the bound functions ``funcs`` {short: Function}: the fast
        paths, the scratch buffers, a platform's working modes read at home. ``frozen``: the
        manifest's read-only data; ``layouts``: {name: Layout} (read-only). ``root``: the
        loaded model's functions when ``funcs`` is a :class:`_Functions` of a model at a
        design (its fast paths are then built on first use, :class:`_Pending`); ``words``:
        the loaded model's (the legs' kinds do not change with the design)."""
        design = _design_values(spec)
        sizes = funcs if root is None else root
        m = sizes["ik"].sizes_in[0]          # the task dimension of the generated code
        task_names = spec.task_names
        if len(task_names) != m:
            _stale(spec, gen_dir, f"{lib_path} has task dimension {m}, the model file "
                                  f"{len(task_names)} ({', '.join(task_names)})")
        sing_thr = (spec.limits["singularity_threshold"],
                    spec.limits["parallel_singularity_threshold"])
        sing, residual = np.zeros(2), np.zeros(spec.n_legs)
        h = sizes["H"].sizes_out[0]          # constraints: 2 (n - 1) at a point, 2 n a platform
        shapes = _shapes(spec.n_legs, m, len(spec.param_names), h)
        if root is None:
            fast = _methods(funcs, shapes, sing, sing_thr, residual,
                            spec.sensing["closure_tolerance"])
        else:
            fast = _Pending(funcs, shapes, sing, sing_thr, residual,
                            spec.sensing["closure_tolerance"])
        f = types.MappingProxyType(funcs)
        for k, v in (("spec", spec),
                     ("manifest", frozen),
                     ("library", str(lib_path)),
                     ("generated", str(gen_dir)),
                     ("_lib", lib), ("_f", f), ("_fast", fast),
                     ("_root", f if root is None else root),
                     ("_layouts", layouts),
                     ("_sing_thr", sing_thr), ("_sing", sing), ("_residual", residual),
                     ("_m", m), ("_task_names", task_names), ("_modes", None),
                     ("_words", words if words is not None else
                      singularity_words(spec.legs, spec.end_effector)),
                     ("_design", design), ("_manifest_obj", manifest)):
            object.__setattr__(self, k, v)
        if spec.home is not None:       # a platform: its legs' working modes, read at home
            legs = _mode_geometry(spec)
            home = np.array(spec.home, dtype=float)
            qa = fast["ik"](home, None)[:spec.n_legs]
            if not np.all(np.isfinite(qa)):
                raise DesignError(f"model {spec.name!r}: [platform] home {tuple(spec.home)} "
                                  f"cannot be reached" + _design_text(spec))
            modes = tuple(_mode_sides(legs, qa, home))
            object.__setattr__(self, "_modes", (legs, modes))

    # --- the design: the model file's [design] variables ----------------------------------
    @property
    def design_names(self):
        """The model file's [design] variables, in the order of :attr:`design` (``()``
        without a [design] table)."""
        return tuple(self.spec.design.names) if self.spec.design is not None else ()

    @property
    def design(self):
        """(k,) the current values of the design variables, m (empty without [design])."""
        out = np.array(self._design if self._design is not None else (), dtype=float)
        out.setflags(write=False)
        return out

    @property
    def design_bounds(self):
        """(k, 2) each design variable's (low, high) bounds, m."""
        d = self.spec.design
        return np.array(d.bounds if d is not None else np.zeros((0, 2)), dtype=float)

    def at_design(self, values):
        """This robot at another design: a new Model whose every function (kinematics,
        dynamics, controllers, plant, planner) is that design's. No derivation and no compile:
        the generated C takes the design as an input. Each function of the loaded model is
        cloned at the new design when the new model first uses it (``Function.clone``: no
        symbol lookup, the signatures already checked), so a design pays for the functions it
        calls; the models are independent.

        Parameters
        ----------
        values : mapping or sequence of float
            {name: value} for some or all of :attr:`design_names` (the others keep this
            model's values), or k values in the order of :attr:`design_names`; m.

        Returns
        -------
        Model

        Raises
        ------
        DesignError
            The model file has no [design] table; an unknown name; a value not finite or
            outside its bounds (naming the variable); a design where the file's home or
            moves cannot be reached (naming the move and the leg).
        """
        from .design import spec_at_design
        if self.spec.design is None:
            raise DesignError(f"model {self.name!r} has no [design] table: its geometry is fixed "
                              f"(add a [design] table to {self.spec.path} and derive it)")
        spec = spec_at_design(self.spec, values)
        out = Model.__new__(Model)
        out._assemble(spec, Path(self.generated), self._manifest_obj, self.library, self._lib,
                      _Functions(self._root, _design_values(spec)), self.manifest,
                      self._layouts, root=self._root, words=self._words)
        return out

    def __setattr__(self, key, value):
        raise AttributeError(f"Model is immutable (tried to set {key!r})")

    def __delattr__(self, key):
        raise AttributeError(f"Model is immutable (tried to delete {key!r})")

    def __repr__(self):
        return (f"<Model {self.name!r}: {self.n_legs} legs, {len(self.param_names)} parameters, "
                f"friction {self.spec.friction!r}{_design_text(self.spec)}>")

    # --- description ---------------------------------------------------------------------
    name = property(lambda self: self.spec.name)
    n_legs = property(lambda self: self.spec.n_legs, doc="number of legs (= actuators)")
    dof = property(lambda self: self._m,
                   doc="m, the task dimension: 2 (x, y) for a point end effector, 3 (x, y, phi) "
                       "for a platform; every task-space array has m entries")
    task_names = property(lambda self: self._task_names,
                          doc='names of the task coordinates, ("x", "y") or ("x", "y", "phi")')
    param_names = property(lambda self: self.spec.param_names, doc="names of theta, in order")
    theta_nominal = property(lambda self: self.spec.theta_nominal, doc="(5n,) Tables 1-2")
    singularity_threshold = property(
        lambda self: self._sing_thr[0],
        doc="type I: smallest allowed leg measure (RRR |sin(qb_i - qa_i)|, PRR |d_i . u(qb_i)|)")
    parallel_singularity_threshold = property(
        lambda self: self._sing_thr[1],
        doc="type II: smallest allowed measure of the legs' lines of action "
            "(:meth:`singularity_measures`)")

    @property
    def bases(self):
        """(n, 2) base positions A_i, m."""
        b = self.spec.bases
        b.setflags(write=False)
        return b

    def checked_theta(self, theta=None, name="theta", physical=False):
        """A parameter vector as a new float64 array (p,): ``theta``, or Tables 1-2 for None.

        Raises ArgumentError naming ``name``, the expected order (:attr:`param_names`) and the
        value, for a wrong length or a non-finite entry. With ``physical=True`` also unless
        theta is physical by the model file's rule for ``[nominal]``: every leg's M_i (eq. 1)
        positive definite (so Me = W^T M W, eq. 12, is at every non-singular pose) and every
        friction coefficient >= 0.

        Parameters
        ----------
        theta : array_like (p,), optional
            Parameters in :attr:`param_names` order (Tables 1-2 units); the nominal ones when
            None.
        name : str
            What the caller calls the vector, for the error message.
        physical : bool
            Also require physical parameters (RR legs only).
        """
        p = len(self.param_names)
        try:
            th = np.array(self.theta_nominal if theta is None else theta, dtype=float)
        except (TypeError, ValueError):
            th = None
        if th is None or th.shape != (p,) or not np.isfinite(th).all():
            raise ArgumentError(f"{name} must be {p} finite numbers ({', '.join(self.param_names)})"
                                f", got {theta!r}")
        if physical:       # the model file's rule for [nominal], by parameter name
            index = {name: j for j, name in enumerate(self.param_names)}
            for i in range(self.n_legs):
                why = inertia_problem(*(th[index[f"{k}{i + 1}"]] for k in INERTIAL))
                if why is not None:
                    raise ArgumentError(f"{name} is not physical: leg {i + 1} {why}")
            if all(k in index for k in PLATFORM_PARAMS):
                why = platform_inertia_problem(*(th[index[k]] for k in PLATFORM_PARAMS))
                if why is not None:
                    raise ArgumentError(f"{name} is not physical: the platform's {why}")
            for j, pname in enumerate(self.param_names):
                if is_friction_param(pname, self.spec.friction) and th[j] < 0:
                    raise ArgumentError(f"{name} is not physical: {pname} = {th[j]:.6g} < 0 "
                                        f"(friction must dissipate)")
        return th

    def function(self, short_name):
        """The bound generated function ``<name>_<short_name>`` (for benchmarks and tools).

        Parameters
        ----------
        short_name : str
            The function's name without the model's prefix, e.g. "ik", "Me", "na_step".
        """
        return self._f[short_name]

    def layout(self, name):
        """The :class:`~pm2dof.core.layout.Layout` ``name`` of the manifest (e.g. "plant",
        "cl_state"), built once.

        Parameters
        ----------
        name : str
            A layout of the manifest's ``layouts``.
        """
        return self._layouts[name]

    # --- argument handling ---------------------------------------------------------------
    # Fast path: each method is one call of its _cbind.Method (self._fast, built by _methods):
    # in C it checks every argument's dtype (float64), contiguity, element count and
    # finiteness and out's type and shape, evaluates, and checks the result (finite, the
    # pose not singular, fk's loops closed). Whatever it refuses takes the checked path
    # (pm2dof.core.binding.call): the arguments converted (lists, ints, float32 ...), the call
    # retried and every problem named in a typed error.
    def _out(self, out, shape):
        if out is None:
            return np.empty(shape)
        if type(out) is not np.ndarray or out.shape != shape:
            raise ArgumentError(f"out must be a C-contiguous float64 array of shape {shape}, "
                                f"got {type(out).__name__} {getattr(out, 'shape', '')}")
        return out

    def _eval(self, short, shape, out, *args):
        """Evaluate ``<name>_<short>(*args) -> out [, sing]``; raise on a singular pose."""
        out = self._out(out, shape)
        f = self._f[short]
        sing = self._sing if f.n_out == 2 else None
        outs = (out, sing) if sing is not None else (out,)
        self._checked_call(short, f, args, outs, sing)
        return out

    def _checked_call(self, short, f, args, outs, sing):
        """``f(*args, *outs)``; raise on a singular pose (``sing``, the measures output, or
        None) and on a non-finite result from finite inputs."""
        # a NaN/inf result from finite inputs: a singular pose explains it, else NonFiniteError
        args, nonfinite = call(f, args, outs)
        if sing is not None and not (sing[0] >= self._sing_thr[0] and
                                     sing[1] >= self._sing_thr[1]):
            if sing[0] != sing[0] and f.names_in[0] in ("xe", "x"):
                self.ik(args[0][:self._m])  # NaN measure: some leg cannot reach xe; ik names it
            raise SingularityError(f"{short}: {self.singularity_message(sing)}")
        if nonfinite is not None:
            raise NonFiniteError(str(nonfinite)) from None

    def singularity_message(self, sing):
        """Which kind of singularity the measures ``sing`` = [type I, type II] hit, with the
        measure, its threshold and the model-file key (for error messages).

        Parameters
        ----------
        sing : array_like (2,)
            The measures [type I, type II] of :meth:`singularity_measures`, one of them
            below its threshold.
        """
        kind = 0 if not sing[0] >= self._sing_thr[0] else 1
        name, what = self._words[kind]       # by the legs' kinds and the end effector
        key = ("singularity_threshold", "parallel_singularity_threshold")[kind]
        return (f"the pose is too close to a {name} singularity: "
                f"{what} = {sing[kind]:.4g} < threshold {self._sing_thr[kind]} (limits.{key})")

    @property
    def singularity_kinds(self):
        """((type I name, its measure), (type II name, its measure)): how messages name the
        two singularities of this mechanism, by its legs' kinds and its end effector (an RRR
        leg's |sin(qb_i - qa_i)|, a PRR leg's |d_i . u(qb_i)|; a point's or a platform's type
        II measure, :meth:`singularity_measures`)."""
        return self._words

    # --- kinematics ----------------------------------------------------------------------
    @fast_method
    def ik(self, xe, out=None):
        """Inverse kinematics for the configured assembly modes.

        Parameters
        ----------
        xe : array_like (m,)
            End-effector pose in :attr:`task_names` order: [x, y] m (a platform: [x, y, phi],
            phi in rad).
        out : ndarray (2n,), optional
            Written into and returned (no allocation); a new array when None.

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
        try:
            return self._fast["ik"](xe, out)      # refuses a non-finite q: named below
        except _cbind.Refused:
            pass
        out = self._eval("ik", (2 * self.n_legs,), out, xe)
        if not np.isfinite(out).all():
            xe = np.asarray(xe, dtype=float).ravel()
            if not is_rr_point(self.spec):   # the per-leg reach below is an RR leg's annulus
                raise WorkspaceError(f"xe = {xe.tolist()} is out of reach of some leg: inverse "
                                     f"kinematics has no real solution there")
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
                    f"line B1 -> B2 than the model file's fk_branch = {side!r}, so fk could not "
                    f"return to it (the parallel singularity, distal links aligned, separates "
                    f"the modes)")
            raise WorkspaceError(f"inverse kinematics failed at xe = {xe.tolist()}")
        return out

    closure_tolerance = property(
        lambda self: self.spec.sensing["closure_tolerance"],
        doc="largest |O - B_i| - lb_i, m, that fk and the controllers accept from the encoders")
    sample_period = property(
        lambda self: float(self.spec.sensing["sample_period"]),
        doc="the controllers' sample period, s (``[sensing] sample_period``): the default of "
            "every ``period`` and ``sample_period`` argument")

    def checked_period(self, period=None):
        """A sample period as a float, s: ``period``, or :attr:`sample_period` for None.

        Raises ArgumentError unless it is a finite number of seconds > 0.

        Parameters
        ----------
        period : float, optional
            The sample period, s; the model file's (:attr:`sample_period`) when None.
        """
        T = self.sample_period if period is None else period
        if not (isinstance(T, (int, float, np.floating, np.integer)) and 0 < T < np.inf):
            raise ArgumentError(f"period must be a finite number of seconds > 0, got {period!r}")
        return float(T)

    @fast_method(unless="_modes")   # a platform checks its working modes in Python
    def fk(self, qa, out=None):
        """Forward kinematics from the measured active coordinates.

        Parameters
        ----------
        qa : array_like (n,)
            Active (encoder) coordinates, each in its actuator's unit: an RRR leg's angle in
            rad, absolute from +x; a PRR slider's position along its rail or an RPR leg's
            length, in m. Messages print each kind's unit.
        out : ndarray (m,), optional
            Written into and returned (no allocation); a new array when None.

        Returns
        -------
        xe : ndarray (m,)
            End-effector pose (a point: position O, m): for n >= 3 legs the least-squares point of the n
            elbow circles (B_i = A_i + la_i u(qa_i), radius lb_i), for two legs their
            intersection on the ``fk_branch`` side. A platform's pose (x, y, phi): Gauss-Newton
            from ``[platform] home``, an assembly with every leg in its working mode; reliable
            within about 0.05 m and 0.2 rad of home (docs/model-file.md), farther off possibly
            another assembly of the same modes, or phi shifted by a multiple of 2 pi. About
            2.5 us from Python (its working modes are checked in Python), 0.4 us for a point.

        Raises
        ------
        WorkspaceError
            No assembly exists (a five-bar's circles do not meet; a platform: the Gauss-Newton
            from home found none), or (:class:`ClosureError`, a WorkspaceError) the
            coordinates do not close the loops: some leg's closure residual | |P_i - B_i| -
            r_i | (P_i the point it must reach, B_i and r_i its circle's centre and radius) exceeds
            :attr:`closure_tolerance` (``[sensing] closure_tolerance``, by default a few
            encoder steps at the active link's length). With three encoders for two degrees of
            freedom, the extra legs are a check of the measurement; the message names the leg
            and its residual in m. A platform: WorkspaceError where Gauss-Newton from home
            ended with a leg in the other working mode (elbow or branch) than the model
            file's.
        """
        try:
            xe = self._fast["fk"](qa, out)      # refuses a residual beyond tol: named below
        except _cbind.Refused:
            xe = self._fk_checked(qa, out)
        if self._modes is not None:           # a platform: Gauss-Newton from [platform] home
            self._fk_same_mode(qa, xe)
        return xe

    def _fk_checked(self, qa, out):
        out = self._out(out, (self._m,))
        (qa,), _ = call(self._f["fk"], (qa,), (out, self._residual))
        r = self._residual
        tol = self.spec.sensing["closure_tolerance"]
        qa_text = active_coordinates(self.spec.actuators, qa)
        if not (np.isfinite(out).all() and np.isfinite(r).all()):
            if self.spec.home is not None:      # a platform: Gauss-Newton from home
                raise WorkspaceError(
                    f"fk of qa = {qa_text}: the Gauss-Newton from [platform] home = "
                    f"{list(self.spec.home)} found no pose (a step was not finite): no assembly "
                    f"of the legs has these active coordinates, or none near home (fk is "
                    f"reliable within about 0.05 m and 0.2 rad of it, docs/model-file.md)")
            raise WorkspaceError(f"no assembly of the legs has the active coordinates qa = "
                                 f"{qa_text}")
        worst = int(np.argmax(np.abs(r)))
        if not abs(r[worst]) <= tol:
            platform = self.spec.home is not None
            seeded = (f"; or a pose too far from [platform] home = {list(self.spec.home)} "
                      f"for fk's Gauss-Newton from it (reliable within about 0.05 m and "
                      f"0.2 rad, docs/model-file.md)" if platform else "")
            where, p = (f"its attachment point P_{worst + 1}", "P_i") if platform else \
                ("the common point", "O")
            raise ClosureError(
                f"the active coordinates qa = {qa_text} do not close the loops: leg "
                f"{worst + 1}'s tip misses {where} by {r[worst]:+.3g} m (closure residual "
                f"|{p} - B_i| - r_i, B_i and r_i the centre and radius of the circle its "
                f"actuator puts {p} on; tolerance {tol:.3g} m, [sensing] closure_tolerance): "
                f"inconsistent encoders, or coordinates of another robot{seeded}")
        return out

    def _fk_same_mode(self, qa, xe):
        """WorkspaceError unless ``xe`` (a platform's fk of ``qa``) has every leg in its model
        file's working mode: an RRR leg's elbow on its side of the proximal link, a PRR slider
        ahead of or behind the foot of the perpendicular from its attachment point (RPR legs
        have one). Gauss-Newton from [platform] home may end in another working mode of the
        same qa: a pose that closes the loops, but not one the robot can be in."""
        legs, modes = self._modes        # the model file's modes: the signs at home (ik's)
        wrong = [i for i, (side, mode) in enumerate(zip(_mode_sides(legs, qa, xe), modes))
                 if side * mode < 0]
        if wrong:
            legs = ", ".join(str(i + 1) for i in wrong)
            raise WorkspaceError(
                f"fk of qa = {active_coordinates(self.spec.actuators, qa)}: the Gauss-Newton from "
                f"[platform] home = "
                f"{list(self.spec.home)} ended at the pose {np.round(xe, 6).tolist()}, which "
                f"closes the loops with leg(s) {legs} in the other working mode (elbow or "
                f"branch) than the model file's, another assembly of the same active "
                f"coordinates. A platform's fk from home is reliable within about 0.05 m and "
                f"0.2 rad of it (docs/model-file.md); the controllers track from the previous "
                f"pose")

    @fast_method
    def H(self, q, out=None):
        """Loop-closure constraints H(q), m (eq. 5): (2(n-1),) for legs meeting at a point,
        (2n,) for a platform (tip_i(q) - P_i(xe), its pose xe from q).

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa_1..qa_n, qb_1..qb_n], rad, closing every loop (as :meth:`ik`
            returns them).
        out : ndarray (rows of H,), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._fast["H"](q, out)
        except _cbind.Refused:
            return self._eval("H", (self._f["H"].sizes_out[0],), out, q)

    @fast_method
    def A(self, q, out=None):
        """Constraint Jacobian A = dH/dq (rows of H, 2n) (eq. 6).

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa_1..qa_n, qb_1..qb_n], rad, closing every loop (as :meth:`ik`
            returns them).
        out : ndarray (rows of H, 2n), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._fast["A"](q, out)
        except _cbind.Refused:
            n = self.n_legs
            return self._eval("A", (self._f["H"].sizes_out[0], 2 * n), out, q)

    @fast_method
    def singularity(self, q, out=None):
        """sin(qb_i - qa_i) of every leg (n,): an RRR leg's singularity measure (its links
        aligned at 0, W unbounded). Not a PRR or RPR leg's measure (qa_i is a length there):
        :meth:`singularity_measures` gives every kind's.

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa_1..qa_n, qb_1..qb_n], rad, closing every loop (as :meth:`ik`
            returns them).
        out : ndarray (n,), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._fast["singularity"](q, out)
        except _cbind.Refused:
            return self._eval("singularity", (self.n_legs,), out, q)

    @fast_method
    def singularity_measures(self, q, out=None):
        """The two singularity measures at the pose q (2n,), each in [0, 1], 0 when singular.

        ``[0]`` type I (a leg): the minimum over the legs of an RRR leg's |sin(qb_i - qa_i)|,
        a PRR leg's |d_i . u(qb_i)| (the cosine between its rail d_i and its link) and an RPR
        leg's 1, compared with ``limits.singularity_threshold``; ``[1]`` type II (parallel,
        the actuation), compared with ``limits.parallel_singularity_threshold``. For legs
        meeting at a point: the smallest singular value of S with its rows normalised (the
        distal links' directions), over its largest possible value sqrt(n/2), i.e.
        sqrt(1 - |sum_i exp(2 i qb_i)| / n); 0 when all distal links are parallel. For a
        platform: (det U^T U)^(1/3) / (n/3), U the legs' lines of action with their moments
        about the platform's origin over L (the RMS distance of the attachment points), each
        row of unit length; 0 when the lines are concurrent or all parallel
        (docs/model-file.md, "Singularities"). Never raises on a singular pose: it is the
        measure.

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa_1..qa_n, qb_1..qb_n], rad, closing every loop (as :meth:`ik`
            returns them).
        out : ndarray (2,), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._fast["singularity_measures"](q, out)
        except _cbind.Refused:
            return self._eval("singularity_measures", (2,), out, q)

    @fast_method
    def W(self, q, out=None):
        """W (2n, m) with qd = W xed (eq. 7). Raises SingularityError near singular poses.

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa_1..qa_n, qb_1..qb_n], rad, closing every loop (as :meth:`ik`
            returns them).
        out : ndarray (2n, m), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._fast["W"](q, out)
        except _cbind.Refused:
            return self._eval("W", (2 * self.n_legs, self._m), out, q)

    @fast_method
    def S(self, q, out=None):
        """S (n, m), the actuated rows of W: qd_a = S xed (eq. 8).

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa_1..qa_n, qb_1..qb_n], rad, closing every loop (as :meth:`ik`
            returns them).
        out : ndarray (n, m), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._fast["S"](q, out)
        except _cbind.Refused:
            return self._eval("S", (self.n_legs, self._m), out, q)

    @fast_method
    def Wdot(self, q, xed, out=None):
        """dW/dt (2n, m) along qd = W xed, with xed (m,) in m/s (rad/s for phi) (eq. 9).

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa_1..qa_n, qb_1..qb_n], rad, closing every loop (as :meth:`ik`
            returns them).
        xed : array_like (m,)
            Task-space velocity, m/s (rad/s for phi).
        out : ndarray (2n, m), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._fast["Wdot"](q, xed, out)
        except _cbind.Refused:
            return self._eval("Wdot", (2 * self.n_legs, self._m), out, q, xed)

    # --- dynamics ------------------------------------------------------------------------
    @fast_method
    def M(self, q, theta, out=None):
        """Open-chain joint-space inertia M (2n, 2n), kg*m^2 (eq. 3).

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa_1..qa_n, qb_1..qb_n], rad, closing every loop (as :meth:`ik`
            returns them).
        theta : array_like (p,)
            Parameters, in :attr:`param_names` order (Tables 1-2 units).
        out : ndarray (2n, 2n), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._fast["M"](q, theta, out)
        except _cbind.Refused:
            n = self.n_legs
            return self._eval("M", (2 * n, 2 * n), out, q, theta)

    @fast_method
    def C(self, q, qd, theta, out=None):
        """Open-chain Coriolis/centrifugal matrix C (2n, 2n) at joint velocity qd (eq. 3).

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa_1..qa_n, qb_1..qb_n], rad, closing every loop (as :meth:`ik`
            returns them).
        qd : array_like (2n,)
            Joint velocities [qad, qbd], rad/s.
        theta : array_like (p,)
            Parameters, in :attr:`param_names` order (Tables 1-2 units).
        out : ndarray (2n, 2n), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._fast["C"](q, qd, theta, out)
        except _cbind.Refused:
            n = self.n_legs
            return self._eval("C", (2 * n, 2 * n), out, q, qd, theta)

    @fast_method
    def Me(self, q, theta, out=None):
        """Task-space inertia Me = W^T M W (m, m), kg (kg m, kg m^2 in phi's row and column)
        (eq. 12).

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa_1..qa_n, qb_1..qb_n], rad, closing every loop (as :meth:`ik`
            returns them).
        theta : array_like (p,)
            Parameters, in :attr:`param_names` order (Tables 1-2 units).
        out : ndarray (m, m), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._fast["Me"](q, theta, out)
        except _cbind.Refused:
            return self._eval("Me", (self._m, self._m), out, q, theta)

    @fast_method
    def Ce(self, q, xed, theta, out=None):
        """Task-space Coriolis matrix Ce = W^T (M Wdot + C W) (m, m), kg/s (eq. 12).

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa_1..qa_n, qb_1..qb_n], rad, closing every loop (as :meth:`ik`
            returns them).
        xed : array_like (m,)
            Task-space velocity, m/s (rad/s for phi).
        theta : array_like (p,)
            Parameters, in :attr:`param_names` order (Tables 1-2 units).
        out : ndarray (m, m), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._fast["Ce"](q, xed, theta, out)
        except _cbind.Refused:
            return self._eval("Ce", (self._m, self._m), out, q, xed, theta)

    @fast_method
    def StF(self, q, xed, theta, out=None):
        """Friction in task space S^T f_a(S xed) (m,), N (N m for phi) (eqs. 2, 10).

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa_1..qa_n, qb_1..qb_n], rad, closing every loop (as :meth:`ik`
            returns them).
        xed : array_like (m,)
            Task-space velocity, m/s (rad/s for phi).
        theta : array_like (p,)
            Parameters, in :attr:`param_names` order (Tables 1-2 units).
        out : ndarray (m,), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._fast["StF"](q, xed, theta, out)
        except _cbind.Refused:
            return self._eval("StF", (self._m,), out, q, xed, theta)

    @fast_method
    def Y(self, q, xed, xrd, xrdd, out=None):
        """Regressor Y (m, p): Y theta = Me xrdd + Ce(q, W xed) xrd + S^T f_a(S xed) (eq. 13).

        Columns follow :attr:`param_names`; friction uses sign(0) = 0 (an actuated joint at
        rest contributes no Coulomb column).

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa_1..qa_n, qb_1..qb_n], rad, closing every loop (as :meth:`ik`
            returns them).
        xed : array_like (m,)
            Task-space velocity, m/s (rad/s for phi).
        xrd : array_like (m,)
            Reference velocity xr_dot, m/s (rad/s for phi).
        xrdd : array_like (m,)
            Reference acceleration xr_ddot, m/s^2 (rad/s^2 for phi).
        out : ndarray (m, p), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._fast["Y"](q, xed, xrd, xrdd, out)
        except _cbind.Refused:
            return self._eval("Y", (self._m, len(self.param_names)), out, q, xed, xrd, xrdd)

    def torque_splits(self, q, u, tau_max=None, preload=None, preload_sign=None):
        """The actuator torques of every split for the task force ``u`` (m,), N (N m for phi),
        at pose q (2n,).

        All satisfy S^T tau = u (eqs. 10, 21) to rounding; ``tau_max`` (n,) (N*m per revolute
        actuator, N per linear one, as every effort below) defaults to ``[limits]``,
        ``preload`` (n,) and ``preload_sign`` (n,) +-1 to ``[control]``. No
        clipping is applied here (the controller steps clip). Raises SingularityError at a pose
        too close to a singularity of either kind.

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa_1..qa_n, qb_1..qb_n] (rad; a linear actuator's qa_i in m),
            closing every loop (as :meth:`ik` returns them).
        u : array_like (m,)
            Task-space force, N (N m for phi).
        tau_max : array_like (n,), optional
            Actuator limits, N*m (revolute) or N (linear); ``[limits] tau_max`` when None.
        preload : array_like (n,), optional
            Preload magnitudes, N*m or N by kind; ``[control] preload`` when None.
        preload_sign : array_like (n,), optional
            Preload directions, +-1 per actuator; ``[control] preload_sign`` when None.

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
        outs = (np.empty(n), np.empty(n), np.empty(1), np.empty(n), np.empty(1), np.empty(2))
        call(self._f["torque_splits"], (q, u, w, sgn, pre), outs)
        sing = outs[5]
        if not (sing[0] >= self._sing_thr[0] and sing[1] >= self._sing_thr[1]):
            raise SingularityError(f"torque_splits: {self.singularity_message(sing)}")
        return {"min_norm": outs[0], "min_max": outs[1], "min_max_ratio": float(outs[2][0]),
                "preload": outs[3], "preload_mode": int(outs[4][0])}

    @fast_method
    def forward_dynamics(self, xe, xed, tau_a, theta, out=None):
        """Task-space acceleration xedd (m,), m/s^2 (rad/s^2 for phi), from eq. 12 with eq. 2
        friction.

        Solves Me xedd = S^T tau_a - Ce xed - S^T f_a at the pose ``xe`` (m,), velocity
        ``xed`` (m,), actuator forces/torques ``tau_a`` (n,) and parameters ``theta``.

        Friction is the model file's law with sign(0) = 0 (docs/model-file.md): a joint at
        exact rest has no Coulomb force, so with tau_a = 0 and xed = 0 the result is zero
        (every pose at rest is an equilibrium of this planar model; :meth:`linearize` is
        taken at one). The simulated plant of :func:`pm2dof.simulate` has its own friction, the Coulomb
        term smoothed over ``[plant] coulomb_smoothing_velocity`` and zero at rest; neither
        models stiction.

        Parameters
        ----------
        xe : array_like (m,)
            End-effector pose, m (rad for phi), in :attr:`task_names` order.
        xed : array_like (m,)
            Task-space velocity, m/s (rad/s for phi).
        tau_a : array_like (n,)
            Actuator efforts, N*m (revolute) or N (linear).
        theta : array_like (p,)
            Parameters, in :attr:`param_names` order (Tables 1-2 units). Checked for length
            and finiteness only: this is a per-sample call, so it does not check that theta
            is physical (Me positive definite, friction >= 0). Check once with
            ``checked_theta(theta, physical=True)``; an unphysical theta gives the
            acceleration of that unphysical model.
        out : ndarray (m,), optional
            Written into and returned (no allocation); a new array when None.
        """
        try:
            return self._fast["forward_dynamics"](xe, xed, tau_a, theta, out)
        except _cbind.Refused:
            return self._eval("forward_dynamics", (self._m,), out, xe, xed, tau_a, theta)

    @fast_method
    def Ge(self, q, theta, out=None):
        """Gravity term Ge (m,) of eq. 10, N (N m for phi): Me xedd + Ce xed + Ge + S^T f_a =
        S^T tau_a, Ge = W^T dV/dq (+ the platform's own). Zero in a horizontal plane.

        Parameters
        ----------
        q : array_like (2n,)
            Joint coordinates [qa, qb] closing every loop (as :meth:`ik` returns them).
        theta : array_like (p,)
            Parameters, in :attr:`param_names` order.
        out : ndarray (m,), optional
            Written into and returned (no allocation).
        """
        try:
            return self._fast["Ge"](q, theta, out)
        except _cbind.Refused:
            return self._eval("Ge", (self._m,), out, q, theta)

    # --- energy --------------------------------------------------------------------------
    @fast_method
    def kinetic_energy(self, xe, xed, theta=None):
        """Kinetic energy T = 1/2 xed^T Me(xe) xed of the whole mechanism, J.

        Generated from the same derivation as Me (``<name>_kinetic_energy``).

        Parameters
        ----------
        xe : array_like (m,)
            The pose in :attr:`task_names` order, m (phi in rad).
        xed : array_like (m,)
            Its rate, m/s (phi: rad/s).
        theta : array_like (p,), optional
            Parameters (default :attr:`theta_nominal`).

        Returns
        -------
        float

        Raises
        ------
        WorkspaceError
            A pose some leg cannot reach.
        """
        return self._energy("kinetic_energy", xe, xed, theta)

    @fast_method
    def potential_energy(self, xe, theta=None):
        """Potential energy V(xe) of the links and the payload in the model's gravity, J.

        Zero in a horizontal plane (the model file's default); V = 0 at the height of the
        base frame's origin. Generated (``<name>_potential_energy``); T + V is conserved along
        the model's forward dynamics with zero torque and zero friction.

        Parameters
        ----------
        xe : array_like (m,)
            The pose in :attr:`task_names` order, m (phi in rad).
        theta : array_like (p,), optional
            Parameters (default :attr:`theta_nominal`).

        Returns
        -------
        float

        Raises
        ------
        WorkspaceError
            A pose some leg cannot reach.
        """
        return self._energy("potential_energy", xe, theta)

    def _energy(self, short, *args):
        *pose, theta = args
        out = self._eval(short, (1,), None, *pose, self.checked_theta(theta))
        if not np.isfinite(out[0]):        # a pose some leg cannot reach: ik names the leg
            self.ik(pose[0])
            raise NonFiniteError(f"{short}: not finite at xe = {np.ravel(pose[0]).tolist()}, "
                                 f"xed = {np.ravel(pose[1:2]).tolist()}")
        return float(out[0])


def require_model(model, name="model"):
    """``model``, or ArgumentTypeError unless it is a :class:`Model` (the one check of every
    function and controller that takes one)."""
    if not isinstance(model, Model):
        raise ArgumentTypeError(f"{name} must be a pm2dof.Model (pm2dof.load_model(...)), got "
                                f"{type(model).__name__}")
    return model


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
    for name, value in (("model", model), ("generated", generated)):
        if value is not None and not isinstance(value, (str, Path)):
            raise ArgumentTypeError(f"load_model: {name} must be a name or a path (str or "
                                    f"pathlib.Path), got {type(value).__name__}")
    return Model(read_model_file(paths.resolve_model(model)), generated)
