# Design study files (TOML): the model, the task, the objectives and the optimiser, all checked at once.
"""Read and validate a design study file (docs/design-study-file.md).

A design study names a model file with a ``[design]`` table, the design variables it
searches (default: all of them) and their bounds (default: the model file's, which it may
narrow), the required task (a region of the task plane, with a phi range for a platform,
and/or path files), the objectives and constraints (:data:`pm2dof.synthesis.objectives.MEASURES`)
and the optimiser. Every problem of the file is reported at once, naming the key, as the
study files' and model files' readers do (:class:`pm2dof.core.validate.Problems`); entries of
``[[objectives]]`` and ``[[constraints]]`` are numbered from 1. The shipped studies
(``pm2dof/synthesis/shipped/*.toml``) are commented examples.
"""
import dataclasses
import hashlib
from dataclasses import dataclass
from pathlib import Path
from typing import Mapping

from ..core.errors import InputFileError, ModelFileError, PlanError
from ..core.validate import Problems, entry

__all__ = ["DesignStudyError", "Objective", "DesignStudy", "read_design_study",
           "find_design_study", "with_overrides", "shipped_design_studies",
           "SHIPPED_DESIGN_STUDIES", "OPTIMIZERS"]

#: the design studies that come with pm2dof, by name
SHIPPED_DESIGN_STUDIES = Path(__file__).resolve().parent / "shipped"
#: optimiser kinds: "nsga2" (any number of objectives), "ga" and "cmaes" (one), "grid"
#: (every design of a grid, one or two variables)
OPTIMIZERS = ("nsga2", "ga", "cmaes", "grid")
_TOP = {"study", "task", "objectives", "constraints", "optimizer", "quick"}
_STUDY = {"name", "description", "model", "variables", "bounds"}
_REGION = {"x", "y", "n", "phi", "n_phi"}
_OPTIMIZER = {"kind", "population", "generations", "grid", "seed"}
_QUICK = {"population", "generations", "grid", "n", "n_phi"}
_OPT_DEFAULTS = {"population": 40, "generations": 30, "grid": 11, "seed": 0}
_REGION_N = 21
_GRID_MAX = 100000


class DesignStudyError(InputFileError):
    """A design study file that cannot be run: every problem of the file, one per line, each
    naming the key (``objectives.path (entry 2)``: ``path`` of the second ``[[objectives]]``
    table) and the reason; also as ``exc.problems``."""


@dataclass(frozen=True)
class Objective:
    """One objective or constraint of a design study.

    ``name``: its column in the results (unique); ``measure``: a key of
    :data:`pm2dof.synthesis.objectives.MEASURES`; ``sense``: "min" or "max" for an objective,
    "" for a constraint; ``options``: the measure's options (read-only); ``limit`` and ``op``
    (constraints): feasible when value >= limit (``op`` "ge") or value <= limit ("le")."""
    name: str
    measure: str
    sense: str
    options: Mapping
    limit: float = None
    op: str = ""


@dataclass(frozen=True)
class DesignStudy:
    """A validated design study file. Immutable; sent as is to every worker.

    ``variables`` the design variables searched, ``bounds`` ((lo, hi), ...) per variable, m;
    ``region`` None or {"x": (lo, hi), "y": (lo, hi), "phi": (lo, hi) or None, "n": points
    per axis, "n_phi": orientations}; ``paths`` the path files (absolute); ``objectives`` and
    ``constraints`` :class:`Objective` tuples; ``optimizer`` {"kind", "population",
    "generations", "grid", "seed"}; ``quick`` the ``[quick]`` overrides (applied by
    :func:`with_overrides`); ``file_sha256`` of the file's bytes.
    """
    name: str
    path: str
    model_path: str
    variables: tuple
    bounds: tuple
    region: object
    paths: tuple
    objectives: tuple
    constraints: tuple
    optimizer: Mapping
    quick: Mapping
    file_sha256: str
    description: str = ""


class FrozenMapping(dict):
    """A read-only dict: the mappings of a :class:`DesignStudy` (picklable for the workers,
    unlike ``types.MappingProxyType``; hashable by its items)."""

    def _read_only(self, *args, **kwargs):
        raise TypeError(f"{type(self).__name__} is read-only")

    __setitem__ = __delitem__ = __ior__ = clear = pop = popitem = setdefault = update = \
        _read_only

    def __reduce__(self):
        return type(self), (dict(self),)

    def __hash__(self):
        return hash(tuple(sorted(self.items())))


def _frozen(d):
    return FrozenMapping(d)


def shipped_design_studies():
    """{name: path} of the shipped design studies."""
    return {p.stem: p for p in sorted(SHIPPED_DESIGN_STUDIES.glob("*.toml"))}


def find_design_study(name_or_path):
    """The file of a design study: a shipped study's name (``"paper_legs"``), else a path
    (``~`` expanded), as a string.

    Parameters
    ----------
    name_or_path : str or os.PathLike
        A shipped study's name, or a file's path.
    """
    s = str(name_or_path)
    if "/" not in s and not s.endswith(".toml"):
        shipped = shipped_design_studies()
        if s in shipped:
            return str(shipped[s])
    return str(Path(s).expanduser())


def read_design_study(path, *, model=None, check_design=True):
    """Read and validate a design study file, or a shipped study by name.

    Parameters
    ----------
    path : str or os.PathLike
        The study file, or a shipped study's name (:func:`find_design_study`).
    model : str or os.PathLike, optional
        A model file or shipped model's name replacing ``study.model`` (relative paths from the
        working directory).
    check_design : bool
        Require the model file's ``[design]`` table (what an optimiser searches). False
        accepts a model without one: its fixed geometry is then the only design (no
        variables), as when the study's objectives are evaluated on a conventionally derived
        model (:func:`pm2dof.synthesis.objectives.evaluate_design`).

    Returns
    -------
    DesignStudy

    Raises
    ------
    DesignStudyError
        Listing every problem of the file at once, each naming the key and the reason.
    """
    from .objectives import MEASURES
    path = Path(find_design_study(path))
    pr = Problems(path, DesignStudyError)
    raw, doc = pr.read_toml("design study file")
    pr.keys("", doc, _TOP, ("study", "objectives"))
    st = pr.table("study", doc.get("study")) or {}
    pr.keys("study", st, _STUDY, ("name", "model"))
    name = pr.text("study.name", st.get("name"), nonempty=True) if "name" in st else None
    description = pr.text("study.description", st.get("description", ""))
    model_path = spec = None
    ref, key, folder = (model, "model", Path.cwd()) if model is not None else \
        (st.get("model"), "study.model", path.parent)
    if ref is not None:
        model_path, spec = _model(pr, key, ref, folder)
    variables, bounds = _variables(pr, st, spec, check_design)
    task = pr.table("task", doc.get("task"), required=False) or {}
    pr.keys("task", task, {"region", "paths"})
    region = _region(pr, task.get("region"), spec)
    paths, path_names = _paths(pr, task.get("paths", []), path.parent, spec)
    names = set()
    objectives = _entries(pr, "objectives", doc.get("objectives"), spec, region, path_names,
                          names, MEASURES)
    constraints = _entries(pr, "constraints", doc.get("constraints", []), spec, region,
                           path_names, names, MEASURES)
    if isinstance(doc.get("objectives"), list) and not doc["objectives"]:
        pr.add("objectives", "need at least one [[objectives]] table")
    optimizer = _optimizer(pr, doc.get("optimizer"), len(objectives or ()), len(variables or ()))
    quick = _quick(pr, doc.get("quick"))
    pr.raise_if_any()
    return DesignStudy(name=name, path=str(path.resolve()), model_path=model_path,
                       variables=tuple(variables), bounds=tuple(bounds), region=region,
                       paths=tuple(paths), objectives=tuple(objectives),
                       constraints=tuple(constraints), optimizer=_frozen(optimizer),
                       quick=_frozen(quick), file_sha256=hashlib.sha256(raw).hexdigest(),
                       description=description or "")


def _model(pr, key, ref, folder):
    """(absolute model path, ModelSpec) of study.model; (None, None) after a problem."""
    from ..core.model_file import read_model_file
    from ..core.paths import resolve_model
    if pr.text(key, ref, nonempty=True) is None:
        return None, None
    try:
        model_path = resolve_model(ref, relative_to=folder).resolve()
    except ModelFileError as exc:
        return pr.add(key, str(exc)), None
    if not model_path.is_file():
        return pr.add(key, f"no model file at {model_path} (a shipped model's name, or a path "
                           f"relative to the study file's folder)"), None
    try:
        return str(model_path), read_model_file(model_path)
    except ModelFileError as exc:
        return pr.add(key, f"the model file cannot be used: {exc}"), None


def _variables(pr, st, spec, check_design):
    """(variables, bounds) from study.variables and study.bounds and the model's [design]."""
    design = spec.design if spec is not None else None
    if spec is None:
        return (), ()
    if design is None:
        if check_design:      # else: the fixed geometry is the one design; variables unused
            pr.add("study.model", f"model file {spec.path} has no [design] table: nothing to "
                                  f"search (docs/model-file.md, [design])")
        return (), ()
    known = dict(zip(design.names, design.bounds))
    variables = st.get("variables", list(design.names))
    if (not isinstance(variables, list) or not variables
            or not all(isinstance(v, str) for v in variables)):
        pr.add("study.variables", f"must be a non-empty list of design variable names, got "
                                  f"{variables!r}")
        return (), ()
    for v in variables:
        if v not in known:
            pr.add("study.variables", f"{v!r} is not a design variable of {spec.path}; its "
                                      f"[design] has {list(design.names)}")
    if len(set(variables)) != len(variables):
        pr.add("study.variables", f"names a variable twice: {variables}")
    variables = [v for v in dict.fromkeys(variables) if v in known]
    given = pr.table("study.bounds", st.get("bounds"), required=False) or {}
    for k in sorted(set(given) - set(variables)):
        pr.add(f"study.bounds.{k}", f"not a searched variable; variables: {variables}")
    bounds = []
    for v in variables:
        lo, hi = known[v]
        if v in given:
            b = given[v]
            at = f"study.bounds.{v}"
            if not (isinstance(b, list) and len(b) == 2):
                pr.add(at, f"must be [lo, hi], got {b!r}")
            else:
                lo2, hi2 = (pr.number(at, x) for x in b)
                if lo2 is not None and hi2 is not None:
                    if not lo2 < hi2:
                        pr.add(at, f"empty range [{lo2}, {hi2}]: need hi > lo")
                    elif lo2 < lo or hi2 > hi:
                        pr.add(at, f"[{lo2}, {hi2}] is outside the model file's bounds "
                                   f"[{lo}, {hi}] ([design] {v}); a study may only narrow them")
                    else:
                        lo, hi = lo2, hi2
        bounds.append((float(lo), float(hi)))
    return variables, bounds


def _range(pr, key, v):
    """(lo, hi) with lo <= hi; None after a problem."""
    if not (isinstance(v, list) and len(v) == 2):
        return pr.add(key, f"must be [lo, hi], got {v!r}")
    lo, hi = (pr.number(key, x) for x in v)
    if lo is None or hi is None:
        return None
    if hi < lo:
        return pr.add(key, f"empty range [{lo}, {hi}]: need hi >= lo")
    return float(lo), float(hi)


def _region(pr, reg, spec):
    """task.region as a read-only mapping; None when absent or after a problem."""
    reg = pr.table("task.region", reg, required=False)
    if reg is None:
        return None
    pr.keys("task.region", reg, _REGION, ("x", "y"))
    out = {}
    for k in ("x", "y"):
        if k in reg:
            out[k] = _range(pr, f"task.region.{k}", reg[k])
            if out[k] is not None and out[k][0] == out[k][1]:
                pr.add(f"task.region.{k}", f"empty range [{out[k][0]}, {out[k][1]}]: need hi > lo")
    out["n"] = pr.number("task.region.n", reg.get("n", _REGION_N), integer=True, low=2)
    platform = spec is not None and spec.end_effector == "platform"
    if "phi" in reg and spec is not None and not platform:
        pr.add("task.region.phi", f"model file {spec.path} has a point end effector: no "
                                  f"orientation")
    out["phi"] = _range(pr, "task.region.phi", reg["phi"]) if "phi" in reg else None
    n_phi = reg.get("n_phi", 5 if out["phi"] is not None and out["phi"][0] < out["phi"][1] else 1)
    out["n_phi"] = pr.number("task.region.n_phi", n_phi, integer=True, low=1)
    if "n_phi" in reg and out["phi"] is None:
        pr.add("task.region.n_phi", "needs a phi range")
    if any(v is None for k, v in out.items() if k != "phi") or ("phi" in reg and out["phi"] is None):
        return None
    return _frozen(out)


def _paths(pr, refs, folder, spec):
    """(absolute path files, their paths' names) of task.paths."""
    from ..planning.pathfile import read_path_file, resolve_path_file
    if not isinstance(refs, list) or not all(isinstance(r, str) and r for r in refs):
        pr.add("task.paths", f"must be a list of path files (a shipped path's name, or a file "
                             f"relative to the study file), got {refs!r}")
        return [], set()
    files, names = [], set()
    ell = None
    if spec is not None and spec.end_effector == "platform":
        from ..core.task import orientation_length
        ell = orientation_length(_SpecOnly(spec))
    for i, ref in enumerate(refs):
        at = entry("task.paths", f"entry {i + 1}")
        try:
            f = Path(resolve_path_file(ref, relative_to=folder)).resolve()
            named = read_path_file(f, orientation_length=ell)
        except (PlanError, InputFileError) as exc:
            pr.add(at, str(exc))
            continue
        if named.name in names:
            pr.add(at, f"a second path named {named.name!r}")
        if spec is not None and named.name in spec.trajectories:
            pr.add(at, f"path {named.name!r} has the name of a move of the model file's "
                       f"[trajectories]: rename it ([path] name)")
        names.add(named.name)
        files.append(str(f))
    return files, names


class _SpecOnly:
    """A stand-in for a Model where only its spec is read (orientation_length)."""

    def __init__(self, spec):
        self.spec = spec


def _entries(pr, section, tables, spec, region, path_names, names, measures):
    """[[objectives]] or [[constraints]] as Objective tuples."""
    constraint = section == "constraints"
    if tables is None:                     # [[objectives]] missing: reported by the keys' check
        return ()
    if not isinstance(tables, list) or not all(isinstance(t, dict) for t in tables):
        return pr.add(section, f"must be [[{section}]] tables") or ()
    out = []
    for i, t in enumerate(tables):
        label = f"entry {i + 1}"

        def at(k, label=label):
            return entry(f"{section}.{k}", label)
        measure = pr.choice(at("measure"), t.get("measure"), {k: k for k in measures})
        name = t.get("name", measure)
        if not isinstance(name, str) or not name.isidentifier():
            pr.add(at("name"), f"must be a name like dexterity_min, got {name!r}")
            name = None
        elif name in names:
            pr.add(at("name"), f"{name!r} is used twice (objective and constraint names are "
                               f"the results' columns)")
        else:
            names.add(name)
        if measure is None:
            continue
        sense_default, kinds, _, needs = measures[measure]
        fixed = {"name", "measure"} | ({"ge", "le"} if constraint else {"sense"})
        if measure == "rmse" and isinstance(t.get("law"), str):
            from ..studies.spec import LAWS
            allowed = {"law", "path", "quantise", *LAWS.get(t["law"], ())}
            if t["law"] == "na":
                allowed.add("Gamma_scale")
        else:
            allowed = set(kinds)
        pr.keys(section, t, fixed | allowed, label=label)
        sense, op, limit = "", "", None
        if constraint:
            given = [k for k in ("ge", "le") if k in t]
            if len(given) != 1:
                pr.add(entry(section, label), f"give exactly one of ge = <limit> (feasible when "
                                              f"the value >= limit) or le = <limit>, got {given}")
            else:
                op = given[0]
                limit = pr.number(at(op), t[op])
        else:
            sense = pr.choice(at("sense"), t.get("sense", sense_default), {"min": "min",
                                                                          "max": "max"})
        options = {}
        for k in sorted(allowed & set(t)):
            v = _option(pr, at(k), kinds.get(k), t[k], spec, path_names)
            if v is not None:
                options[k] = v
        _needs(pr, section, label, measure, needs, options, region, path_names, spec)
        if name is not None and (not constraint or limit is not None) and (constraint or sense):
            out.append(Objective(name, measure, sense, _frozen(options), limit, op))
    return tuple(out)


def _needs(pr, section, label, measure, needs, options, region, path_names, spec):
    """What a measure needs: the region, a path option, a law; body masses."""
    if needs == "region" and region is None:
        pr.add(entry(section, label), f"measure {measure!r} is taken over the region: give "
                                      f"[task] region")
    if needs == "path" and "path" not in options:
        pr.add(entry(f"{section}.path", label), f"missing (required by {measure!r}): a path of "
                                                f"[task] paths or a move of the model file")
    if measure == "rmse" and "law" not in options:
        pr.add(entry(f"{section}.law", label), "missing (required by 'rmse'): na, apd, ctc or lqr")
    if measure == "margin" and not options.get("region", True) and not path_names \
            and not options.get("paths"):
        pr.add(entry(section, label), "margin with region = false needs paths")
    if measure == "moving_mass" and spec is not None and \
            (spec.links or {}).get("nominal") is None:
        pr.add(entry(f"{section}.measure", label),
               f"moving_mass needs the legs' bodies: model file {spec.path} gives lumped "
               f"inertia only (give [[nominal.links]])")


def _option(pr, key, kind, v, spec, path_names):
    """One measure option, checked by its kind; None after a problem."""
    from ..core.contract import SPLITS
    from .objectives import LAWS
    n = spec.n_legs if spec is not None else None
    if isinstance(kind, tuple):
        return pr.choice(key, v, {k: k for k in kind})
    if kind in ("name", "names"):
        vals = v if kind == "names" else [v]
        if not isinstance(vals, list) or not all(isinstance(x, str) and x for x in vals):
            return pr.add(key, f"must be {'a list of path names' if kind == 'names' else 'a name'}"
                               f" (a path of [task] paths or a move of the model file), got {v!r}")
        moves = set(spec.trajectories) if spec is not None else set()
        for x in vals:
            if spec is not None and x not in path_names and x not in moves:
                pr.add(key, f"{x!r} is neither a path of [task] paths ({sorted(path_names)}) nor a "
                            f"move of the model file ({sorted(moves)})")
        return tuple(vals) if kind == "names" else v
    if kind == "law":
        return pr.choice(key, v, {k: k for k in LAWS})
    if kind == "split":
        return pr.choice(key, v, {k: k for k in SPLITS})
    if kind == "bool":
        return pr.boolean(key, v)
    if kind == "nonneg":
        return pr.number(key, v, low=0.0)
    if kind == "fraction":
        x = pr.number(key, v, low=0.0, low_ok=False)
        if x is not None and x > 1:
            return pr.add(key, f"must be in (0, 1], got {v}")
        return x
    if kind == "grid":
        x = pr.number(key, v, integer=True, low=2)
        if x is not None and x > _GRID_MAX:
            return pr.add(key, f"must be <= {_GRID_MAX}, got {v}")
        return x
    if kind == "signs":
        vals = v if isinstance(v, list) else [v]
        if not all(x in (1, -1) and not isinstance(x, bool) for x in vals) or \
                (isinstance(v, list) and n is not None and len(v) != n):
            return pr.add(key, f"must be +1 or -1, or one per leg ({n}), got {v!r}")
        return tuple(float(x) for x in vals) if isinstance(v, list) else float(v)
    low_ok = kind == "efforts_nonneg"           # efforts, gains: > 0; preloads: >= 0
    if isinstance(v, list):
        if kind.startswith("efforts") and n is not None and len(v) != n:
            return pr.add(key, f"must be a number or one per leg ({n}), got {v!r}")
        vals = [pr.number(key, x, low=0.0, low_ok=low_ok) for x in v]
        return None if None in vals or not vals else tuple(vals)
    return pr.number(key, v, low=0.0, low_ok=low_ok)


def _optimizer(pr, t, n_obj, n_var):
    """[optimizer] with its defaults."""
    t = pr.table("optimizer", t, required=False) or {}
    pr.keys("optimizer", t, _OPTIMIZER)
    kind = pr.choice("optimizer.kind", t.get("kind", "nsga2" if n_obj != 1 else "ga"),
                     {k: k for k in OPTIMIZERS})
    out = {"kind": kind}
    lows = {"population": 2, "generations": 1, "grid": 2, "seed": 0}
    for k, d in _OPT_DEFAULTS.items():
        out[k] = pr.number(f"optimizer.{k}", t.get(k, d), integer=True, low=lows[k])
    if kind in ("ga", "cmaes") and n_obj > 1:
        pr.add("optimizer.kind", f"{kind!r} optimises one objective; the study has {n_obj} "
                                 f"(use nsga2)")
    if kind == "grid" and n_var > 2:
        pr.add("optimizer.kind", f"a grid is for one or two variables; the study searches "
                                 f"{n_var}")
    return out


def _quick(pr, t):
    """[quick]: the overrides of --quick."""
    t = pr.table("quick", t, required=False) or {}
    pr.keys("quick", t, _QUICK)
    lows = {"population": 2, "generations": 1, "grid": 2, "n": 2, "n_phi": 1}
    out = {k: pr.number(f"quick.{k}", t[k], integer=True, low=lows[k]) for k in _QUICK if k in t}
    return {k: v for k, v in out.items() if v is not None}


def with_overrides(study, quick=False, optimizer=None, grid=None):
    """``study`` with the command line's overrides: ``quick`` applies its ``[quick]`` table
    (population, generations, grid, and the region's n and n_phi), then ``optimizer`` replaces
    the kind and ``grid`` the grid's points per variable (``--optimizer grid --grid N``).

    Parameters
    ----------
    study : DesignStudy
    quick : bool
        Apply ``study.quick``.
    optimizer : str, optional
        One of :data:`OPTIMIZERS`.
    grid : int, optional
        Grid points per variable (>= 2).

    Raises
    ------
    DesignStudyError
        An unknown optimiser, a bad grid, a grid over more than two variables, or a
        single-objective optimiser for several objectives.
    """
    opt = dict(study.optimizer)
    region = None if study.region is None else dict(study.region)
    if quick:
        opt.update({k: v for k, v in study.quick.items() if k in opt})
        if region is not None:
            region.update({k: v for k, v in study.quick.items() if k in ("n", "n_phi")})
            if region["phi"] is None or region["phi"][0] == region["phi"][1]:
                region["n_phi"] = 1
    pr = Problems(study.path, DesignStudyError)
    if optimizer is not None:
        opt["kind"] = pr.choice("--optimizer", optimizer, {k: k for k in OPTIMIZERS})
    if grid is not None:
        opt["grid"] = pr.number("--grid", grid, integer=True, low=2)
    if opt["kind"] == "grid" and len(study.variables) > 2:
        pr.add("--optimizer", f"a grid is for one or two variables; the study searches "
                              f"{len(study.variables)}")
    if opt["kind"] in ("ga", "cmaes") and len(study.objectives) > 1:
        pr.add("--optimizer", f"{opt['kind']!r} optimises one objective; the study has "
                              f"{len(study.objectives)} (use nsga2)")
    pr.raise_if_any()
    return dataclasses.replace(study, optimizer=_frozen(opt),
                               region=None if region is None else _frozen(region))
