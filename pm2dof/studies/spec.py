# Study files (TOML): read and validate everything a many-rollout study needs, before any rollout.
"""Read and validate a study file.

A study file names the model, the moves, the controllers (with gain overrides and gain
grids), the plant's uncertainty as distributions, the number of random draws, a seed,
repeated runs that carry theta_hat from run to run, and optionally a payload change.
The shipped studies (``pm2dof/studies/shipped/*.toml``, ``pm2dof study show NAME``) are
commented examples; docs/study-file.md lists every key.

Rollouts are enumerated as (draw d, variant c, move m, run r), run innermost::

    rollout = ((d * C + c) * M + m) * R + r

Draw d's plant depends only on (seed, d): every controller and move meets the same plants
(common random numbers, a paired comparison). A chunk is a contiguous range of
(d, c, m) units, each with its R runs: its plants are drawn once and shared by every
controller and move, and the draws of one controller and move run as one batch in C.
"""
import hashlib
import itertools
import json
import tomllib
from dataclasses import dataclass
from pathlib import Path

from ..core.errors import InputFileError, ModelFileError
from ..core.paths import resolve_model
from ..core.validate import Problems, entry

__all__ = ["StudyFileError", "check_study", "Study", "Variant", "Distribution", "read_study",
           "UNCERTAINTY", "LAWS"]


class StudyFileError(InputFileError):
    """A study file that cannot be run.

    Lists every problem of the file (also as ``exc.problems``), each naming the key and the
    reason. Entries of ``[[controllers]]`` and of ``study.moves`` are numbered from 1:
    ``controllers.Kp (entry 2)`` is ``Kp`` of the second ``[[controllers]]`` table.
    """


#: uncertainty key -> (meaning, lowest allowed value, whether the lowest value is allowed)
UNCERTAINTY = {
    "payload_mass": ("kg at the end-effector, booked to [plant].payload_leg", 0.0, True),
    "fv_scale": ("factor on the plant's viscous friction fv (every leg)", 0.0, True),
    "fc_scale": ("factor on the plant's Coulomb friction fc (every leg)", 0.0, True),
    "stribeck_scale": ("factor on the plant's Stribeck excess fs (every leg)", 0.0, True),
    "inertia_error_percent": ("relative error of each plant inertia alpha_i, beta_i, gamma_i, "
                              "%, drawn independently per parameter", -100.0, False),
    "encoder_counts_per_rev": ("encoder resolution, counts per revolution (0: exact)", 0.0, True),
}
#: law -> the controller keys a study may set (scalars apply to both task axes)
LAWS = {
    "apd": ("Kp", "Kv", "velocity_filter_hz", "split", "tau_max"),
    "na": ("Kd", "Q", "Gamma_scale", "project", "velocity_filter_hz", "split", "tau_max"),
    # computed torque (Kp 1/s^2, Kv 1/s) and time-varying LQR (weights, planned per move)
    "ctc": ("Kp", "Kv", "velocity_filter_hz", "split", "tau_max"),
    "lqr": ("Q_position", "Q_velocity", "R", "velocity_filter_hz", "split", "tau_max"),
}
GRID_KEYS = ("Kp", "Kv", "Kd", "Q", "Gamma_scale", "velocity_filter_hz")
_STUDY_KEYS = {"name", "description", "model", "generated", "moves", "seed", "draws", "runs",
               "chunk", "settle_time", "quantise"}
#: the study files that come with pm2dof (robustness, gains, adaptation, model_based): by name
SHIPPED_STUDIES = Path(__file__).resolve().parent / "shipped"
_QUICK_KEYS = {"moves", "draws", "runs", "chunk", "grid_points"}
_TOP_KEYS = {"study", "quick", "controllers", "uncertainty", "payload_change"}
_MOVE_KEYS = {"name", "start", "end", "v_max", "a_max", "j_max"}


@dataclass(frozen=True)
class Distribution:
    """One uncertain quantity: ``value``, ``uniform`` [lo, hi], ``normal`` [mean, sd] or
    ``choice`` [v1, v2, ...] (equally likely)."""
    kind: str
    args: tuple

    def sample(self, rng, size=None):
        if self.kind == "value":
            return self.args[0] if size is None else [self.args[0]] * size
        if self.kind == "uniform":
            return rng.uniform(*self.args, size)
        if self.kind == "normal":
            return rng.normal(*self.args, size)
        i = rng.integers(len(self.args), size=size)
        return self.args[i] if size is None else [self.args[k] for k in i]

    @property
    def support(self):
        """(lo, hi); a normal's is taken as mean -+ 6 sd (probability ~2e-9 outside)."""
        if self.kind == "normal":
            return self.args[0] - 6 * self.args[1], self.args[0] + 6 * self.args[1]
        return min(self.args), max(self.args)


def _distribution(pr, key, v, integer=False):
    """A Distribution from ``{kind = args}`` or a bare value; None after a problem."""
    if not isinstance(v, dict):
        v = {"value": v}
    if len(v) != 1:
        return pr.add(key, f"give exactly one of value / uniform / normal / choice, got "
                           f"{sorted(v)}")
    (kind, a), = v.items()
    if kind == "value":
        return None if pr.number(f"{key}.value", a, integer=integer) is None else \
            Distribution("value", (a,))
    if kind not in ("uniform", "normal", "choice"):
        return pr.add(key, f"unknown distribution {kind!r}; use value, uniform, normal or choice")
    if integer and kind != "choice":
        return pr.add(key, "takes whole numbers: use value or choice")
    if not isinstance(a, list) or not a:
        return pr.add(f"{key}.{kind}", f"must be a non-empty list, got {a!r}")
    if None in [pr.number(entry(f"{key}.{kind}", f"entry {i + 1}"), x, integer=integer)
                for i, x in enumerate(a)]:
        return None
    a = tuple(a)
    if kind == "uniform":
        if len(a) != 2:
            return pr.add(f"{key}.uniform", f"must be [lo, hi], got {list(a)}")
        if not a[1] > a[0]:
            return pr.add(f"{key}.uniform", f"empty or negative range [{a[0]}, {a[1]}]: need hi > "
                          f"lo (a single value is {{value = {a[0]}}})")
    if kind == "normal":
        if len(a) != 2:
            return pr.add(f"{key}.normal", f"must be [mean, sd], got {list(a)}")
        if not a[1] > 0:
            return pr.add(f"{key}.normal", f"sd must be > 0, got {a[1]}")
    return Distribution(kind, a)


@dataclass(frozen=True)
class Variant:
    """One controller configuration: a ``[[controllers]]`` entry at one point of its grid.

    ``options`` are sorted (key, value) pairs of the study's controller keys, ``grid`` the
    (key, value) pairs of this grid point (its columns in the results)."""
    name: str
    law: str
    options: tuple
    grid: tuple


def _controller_value(pr, key, name, v):
    """One controller key's value (gains as floats or tuples); None after a problem."""
    if name in ("Kp", "Kv", "Kd", "Q", "tau_max", "Q_position", "Q_velocity", "R"):
        vals = [pr.number(key, x, low=0.0, low_ok=False)
                for x in (v if isinstance(v, list) else [v])]
        return None if None in vals else (tuple(vals) if isinstance(v, list) else vals[0])
    if name in ("Gamma_scale", "velocity_filter_hz"):
        return pr.number(key, v, low=0.0)
    if name == "project":
        return pr.boolean(key, v)
    return pr.text(key, v)   # split


def _grid(pr, name, label, v, grid_points):
    """The values of ``{grid = [...]}`` of controller key ``name`` in entry ``label`` (its ends
    and middle under --quick); None after a problem."""
    key, gkey = entry(f"controllers.{name}", label), entry(f"controllers.{name}.grid", label)
    if set(v) != {"grid"}:
        return pr.add(key, f"a table here must be {{grid = [...]}}, got {sorted(v)}")
    if name not in GRID_KEYS:
        return pr.add(key, f"cannot be a grid; grids: {list(GRID_KEYS)}")
    g = v["grid"]
    if not isinstance(g, list) or not g:
        return pr.add(gkey, "must be a non-empty list of numbers")
    vals = [_controller_value(pr, gkey, name, x) for x in g]
    if None in vals:
        return None
    if any(isinstance(x, tuple) for x in vals) or len(set(vals)) != len(vals):
        return pr.add(gkey, f"must hold distinct scalars, got {g}")
    if grid_points:   # --quick: the grid's ends and middle
        vals = sorted({vals[0], vals[len(vals) // 2], vals[-1]}, key=vals.index)[:grid_points]
    return vals


def _variants(pr, entries, grid_points):
    """Every [[controllers]] entry at every point of its grid."""
    if not isinstance(entries, list) or not entries:
        return pr.add("controllers", "need at least one [[controllers]] entry")
    out, names = [], set()
    for i, e in enumerate(entries):
        label = f"entry {i + 1}"
        if not isinstance(e, dict):
            pr.add(entry("controllers", label), f"must be a table, got {type(e).__name__}")
            continue
        law = pr.choice(entry("controllers.law", label), e.get("law"), {k: k for k in LAWS})
        if law is None:
            continue
        name = e.get("name", law)
        if not isinstance(name, str) or not name.isidentifier():
            pr.add(entry("controllers.name", label), f"must be a name like na_no_adaptation, "
                   f"got {name!r}")
        elif name in names:
            pr.add(entry("controllers.name", label), f"{name!r} is used twice")
        else:
            names.add(name)
        pr.keys("controllers", e, {"name", "law", *LAWS[law]}, label=label)
        fixed, grids = {}, []
        for k in LAWS[law]:
            if k not in e:
                continue
            if isinstance(e[k], dict):
                grids.append((k, _grid(pr, k, label, e[k], grid_points)))
            else:
                fixed[k] = _controller_value(pr, entry(f"controllers.{k}", label), k, e[k])
        if None in fixed.values() or any(vals is None for _, vals in grids):
            continue
        for point in itertools.product(*[vals for _, vals in grids]):
            grid = tuple(zip([k for k, _ in grids], point))
            out.append(Variant(name, law, tuple(sorted({**fixed, **dict(grid)}.items())), grid))
    return tuple(out)


def _moves(pr, moves):
    """study.moves: (name, None) for a model file's move, (name, sorted line items) for a line."""
    if not isinstance(moves, list) or not moves:
        return pr.add("study.moves", "must be a non-empty list of move names or {name, start, "
                      "end, v_max, a_max, j_max} tables")
    out = []
    for i, mv in enumerate(moves):
        label = f"entry {i + 1}"
        if isinstance(mv, str):
            out.append((mv, None))
            continue
        if not isinstance(mv, dict):
            pr.add(entry("study.moves", label), f"must be a move name or a table, got {mv!r}")
            continue
        ok = pr.keys("study.moves", mv, _MOVE_KEYS, _MOVE_KEYS, label=label)
        at = {k: entry(f"study.moves.{k}", label) for k in _MOVE_KEYS}
        line = {k: pr.point(at[k], mv[k]) for k in ("start", "end") if k in mv}
        line.update({k: pr.number(at[k], mv[k], low=0.0, low_ok=False)
                     for k in ("v_max", "a_max", "j_max") if k in mv})
        name = pr.text(at["name"], mv["name"], nonempty=True) if "name" in mv else None
        if ok and name is not None and None not in line.values():
            out.append((name, tuple(sorted(line.items()))))
    names = [n for n, _ in out]
    if len(set(names)) != len(names):
        pr.add("study.moves", f"move names must be distinct, got {names}")
    return tuple(out)


@dataclass(frozen=True)
class Study:
    """A validated study file. Immutable; sent as is to every worker.

    ``moves``: (name, None | sorted line items); ``uncertainty``: (key, Distribution);
    ``payload_change``: None or (after_run, payload_mass kg); ``chunk``: rollouts per task.
    """
    path: str
    text: str
    name: str
    description: str
    model_path: str
    moves: tuple
    seed: int
    draws: int
    runs: int
    chunk: int
    settle_time: float
    quantise: bool
    variants: tuple
    uncertainty: tuple
    payload_change: object
    quick: bool
    generated_path: object = None   # the model's generated C, when not beside the model file

    # the enumeration (module docstring)
    @property
    def n_units(self):
        return len(self.variants) * len(self.moves) * self.draws

    @property
    def n_rollouts(self):
        return self.n_units * self.runs

    @property
    def units_per_chunk(self):
        return max(1, self.chunk // self.runs)

    @property
    def n_chunks(self):
        return -(-self.n_units // self.units_per_chunk)

    def chunk_units(self, i):
        """range of unit indices u = (d * C + c) * M + m in chunk ``i``."""
        if not 0 <= i < self.n_chunks:
            raise IndexError(f"chunk {i} out of range [0, {self.n_chunks})")
        k = self.units_per_chunk
        return range(i * k, min((i + 1) * k, self.n_units))

    def unit(self, u):
        """(variant c, move m, draw d) of unit ``u``."""
        dc, m = divmod(u, len(self.moves))
        d, c = divmod(dc, len(self.variants))
        return c, m, d

    def rollout(self, c, m, d, r):
        return ((d * len(self.variants) + c) * len(self.moves) + m) * self.runs + r

    @property
    def grid_keys(self):
        return tuple(dict.fromkeys(k for v in self.variants for k, _ in v.grid))

    def canonical(self):
        """What defines the rows (not the file's comments or layout): JSON-able dict."""
        return {"name": self.name, "model_values": model_values(self.model_path),
                "moves": self.moves, "seed": self.seed, "draws": self.draws, "runs": self.runs,
                "chunk": self.chunk, "settle_time": self.settle_time, "quantise": self.quantise,
                "variants": [(v.name, v.law, v.options) for v in self.variants],
                "uncertainty": [(k, d.kind, d.args) for k, d in self.uncertainty],
                "payload_change": self.payload_change, "quick": self.quick}

    @property
    def identity(self):
        """sha256 of :meth:`canonical`: equal identities give identical rows."""
        return hashlib.sha256(json.dumps(self.canonical(), sort_keys=True).encode()).hexdigest()


def model_values(path):
    """{table: sha256} of a model file's values, per top-level table (``[plant]``, ``[[legs]]``,
    ...): what enters a study's rows. Comments, layout and the order of keys do not count."""
    d = tomllib.loads(Path(path).read_text(encoding="utf-8"))
    return {k: hashlib.sha256(json.dumps(v, sort_keys=True, default=str).encode()).hexdigest()
            for k, v in sorted(d.items())}


def resolve_study(ref):
    """A shipped study's name (``"robustness"``) -> its file; anything else is a path."""
    s = str(ref)
    if "/" not in s and not s.endswith(".toml") and (SHIPPED_STUDIES / f"{s}.toml").is_file():
        return SHIPPED_STUDIES / f"{s}.toml"
    return Path(s).expanduser()


def read_study(path, quick=False, *, model=None, generated=None, check=True):
    """Read and validate a study file (TOML), or a shipped study by name (``"robustness"``).
    ``quick``: apply its ``[quick]`` table.

    Paths in the file (``study.model``, ``study.generated``) are relative to the study file's
    folder; ``model`` and ``generated`` (``--model``, ``--generated``) replace them. Raises
    :class:`StudyFileError` listing every problem of the file, each naming the key and the
    reason, in one pass: with ``check``, also those that need the model (moves reachable and
    clear of singularities, gains accepted by the controllers:
    :func:`pm2dof.studies.evaluate.model_problems`) once the model loads.

    Parameters
    ----------
    path : str or pathlib.Path
        The study file, or a shipped study's name (``pm2dof study list``).
    quick : bool
        Apply the file's ``[quick]`` table (fewer runs, a coarser grid).
    model : str or pathlib.Path, optional
        A model file or shipped model's name replacing ``study.model`` (``--model``).
    generated : str or pathlib.Path, optional
        The folder of the model's generated C, replacing ``study.generated``
        (``--generated``).
    check : bool
        Also check what needs the model (moves, gains) once it loads.
    """
    path = resolve_study(path)
    pr = Problems(path, StudyFileError)
    raw, doc = pr.read_toml("study file")
    text = raw.decode("utf-8")
    pr.keys("", doc, _TOP_KEYS)
    q = pr.table("quick", doc.get("quick"), required=False) or {}
    pr.keys("quick", q, _QUICK_KEYS)
    grid_points = q.get("grid_points") if quick else None
    if grid_points is not None:
        grid_points = pr.number("quick.grid_points", grid_points, integer=True, low=1)
    fields = _study_table(pr, path, pr.table("study", doc.get("study")), q if quick else None)
    uncertainty = _uncertainty(pr, doc.get("uncertainty"))
    variants = _variants(pr, doc.get("controllers"), grid_points)
    payload_change = _payload_change(pr, doc.get("payload_change"), fields.get("runs"),
                                     quick and "runs" in q)
    if model is not None:
        fields["model_path"] = _model_path(pr, Path.cwd(), str(model), "--model")
    if generated is not None:
        fields["generated_path"] = str(Path(generated).expanduser().resolve())
    if check:
        _check_with_model(pr, fields, variants)
    pr.raise_if_any()
    return Study(path=str(path.resolve()), text=text, **fields, variants=variants,
                 uncertainty=uncertainty, payload_change=payload_change, quick=bool(quick))


def _study_table(pr, path, st, q):
    """[study] (with ``q``, the [quick] table, applied): the fields of Study it holds."""
    if st is None:
        return {}
    pr.keys("study", st, _STUDY_KEYS, ("name", "model", "moves", "seed", "draws"))
    quick = {k: v for k, v in (q or {}).items() if k in _QUICK_KEYS - {"grid_points"}}
    st = {**st, **quick}

    def at(key):       # where a value came from, for its message: [quick] overrides [study]
        return f"{'quick' if key in quick else 'study'}.{key}"

    out = {"description": pr.text(at("description"), st.get("description", "")),
           "runs": pr.number(at("runs"), st.get("runs", 1), integer=True, low=1),
           "chunk": pr.number(at("chunk"), st.get("chunk", 256), integer=True, low=1),
           "settle_time": pr.number(at("settle_time"), st.get("settle_time", 0.0), low=0.0),
           "quantise": pr.boolean(at("quantise"), st.get("quantise", True))}
    if "name" in st:
        out["name"] = pr.text(at("name"), st["name"], nonempty=True)
    if "model" in st:
        out["model_path"] = _model_path(pr, path.parent, st["model"])
    if "generated" in st and pr.text(at("generated"), st["generated"], nonempty=True):
        out["generated_path"] = str((path.parent / Path(st["generated"]).expanduser()).resolve())
    if "moves" in st:
        out["moves"] = _moves(pr, st["moves"])
    if "seed" in st:
        out["seed"] = pr.number(at("seed"), st["seed"], integer=True, low=0)
    if "draws" in st:
        out["draws"] = pr.number(at("draws"), st["draws"], integer=True, low=1)
    return out


def _model_path(pr, folder, ref, key="study.model"):
    """study.model: a shipped model's name or a path relative to the study file's ``folder``
    (``--model``: to the working directory)."""
    if pr.text(key, ref, nonempty=True) is None:
        return None
    try:
        model_path = resolve_model(ref, relative_to=folder).resolve()
    except ModelFileError as exc:
        return pr.add(key, str(exc))
    if not model_path.is_file():
        return pr.add(key, f"no model file at {model_path} (a shipped model's name, "
                      f"or a path relative to the study file's folder)")
    return str(model_path)


def check_study(study, model):
    """Everything that needs the model, before any rollout: each controller variant is accepted
    by its controller, each move is reachable and clear of both singularity kinds, and every
    draw's plant can be integrated stably at rest (:func:`pm2dof.studies.evaluate.plant_problems`:
    the first draw that cannot, under ``uncertainty``). Raises :class:`StudyFileError`
    listing every refused variant and move (``[[controllers]]`` and ``study.moves`` entries
    numbered from 1). :func:`pm2dof.studies.read_study` makes the first two checks too, in the
    same pass as the file's own."""
    from .evaluate import model_problems, plant_problems
    pr = Problems(study.path, StudyFileError)
    model_problems(pr, model, study.variants, study.moves)
    if not pr.found:
        plant_problems(pr, model, study)
    pr.raise_if_any()


def _check_with_model(pr, fields, variants):
    """The checks that need the model, into the same collector: moves (unless study.moves
    had problems of its own) and controller variants (unless [[controllers]] had)."""
    keys = [str(p.key) for p in pr.found]
    if not fields.get("model_path") or not fields.get("moves") or any(
            k.startswith("study.moves") for k in keys):
        return
    from ..core.errors import Pm2dofError
    from ..core.model import load_model
    from .evaluate import model_problems
    try:
        model = load_model(fields["model_path"], fields.get("generated_path"))
    except Pm2dofError as exc:
        return pr.add("study.model", str(exc))
    ok = variants is not None and not any(k.startswith("controllers") for k in keys)
    model_problems(pr, model, variants if ok else None, fields["moves"])


def _uncertainty(pr, unc):
    """[uncertainty]: (key, Distribution) in UNCERTAINTY's order (the draws do not depend on
    the file's order)."""
    unc = pr.table("uncertainty", unc, required=False) or {}
    pr.keys("uncertainty", unc, UNCERTAINTY)
    dists = []
    for k in UNCERTAINTY:
        if k not in unc:
            continue
        d = _distribution(pr, f"uncertainty.{k}", unc[k], integer=(k == "encoder_counts_per_rev"))
        if d is None:
            continue
        lo, low_ok = UNCERTAINTY[k][1], UNCERTAINTY[k][2]
        if d.support[0] < lo or (d.support[0] == lo and not low_ok):
            pr.add(f"uncertainty.{k}", f"can draw {d.support[0]:g}, below the allowed "
                   f"{'>=' if low_ok else '>'} {lo:g} ({UNCERTAINTY[k][0]})")
        dists.append((k, d))
    return tuple(dists)


def _payload_change(pr, pc, runs, quick_runs):
    """[payload_change]: None or (after_run, payload_mass kg); under --quick with [quick]
    runs, after_run moves to at most half the runs."""
    pc = pr.table("payload_change", pc, required=False)
    if pc is None:
        return None
    keys = ("after_run", "payload_mass")
    pr.keys("payload_change", pc, keys, keys)
    after = (pr.number("payload_change.after_run", pc["after_run"], integer=True, low=1)
             if "after_run" in pc else None)
    mass = (pr.number("payload_change.payload_mass", pc["payload_mass"], low=0.0)
            if "payload_mass" in pc else None)
    if after is None or mass is None:
        return None
    if quick_runs and runs is not None:
        after = min(after, max(1, runs // 2))
    if runs is not None and after >= runs:
        pr.add("payload_change.after_run", f"must be < study.runs = {runs}, got {after}")
    return after, mass
