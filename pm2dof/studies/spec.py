# Study files (TOML): read and validate everything a many-rollout study needs, before any rollout.
"""Read and validate a study file.

A study file names the model, the moves, the controllers (with gain overrides and gain
grids), the plant's uncertainty as distributions, the number of random draws, a seed,
repeated runs that carry theta_hat from run to run, and optionally a payload change.
``studies/*.toml`` are commented examples; README "Studies at scale" lists every key.

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
import math
import tomllib
from dataclasses import dataclass
from pathlib import Path

from ..core.errors import ModelFileError
from ..core.paths import resolve_model

__all__ = ["StudyFileError", "Study", "Variant", "Distribution", "read_study", "UNCERTAINTY",
           "LAWS"]


class StudyFileError(ValueError):
    """A study file that cannot be run: names the file, the key and the reason."""


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
}
GRID_KEYS = ("Kp", "Kv", "Kd", "Q", "Gamma_scale", "velocity_filter_hz")
_STUDY_KEYS = {"name", "description", "model", "moves", "seed", "draws", "runs", "chunk",
               "settle_time", "quantise"}
_QUICK_KEYS = {"moves", "draws", "runs", "chunk", "grid_points"}
_TOP_KEYS = {"study", "quick", "controllers", "uncertainty", "payload_change"}
_MOVE_KEYS = {"name", "start", "end", "v_max", "a_max", "j_max"}


def _fail(path, key, reason):
    raise StudyFileError(f"{path}: {key}: {reason}")


def _number(path, key, v, *, integer=False, low=None, low_ok=True):
    if isinstance(v, bool) or not isinstance(v, (int, float)) or (integer and not isinstance(v, int)):
        _fail(path, key, f"must be {'an integer' if integer else 'a number'}, got {v!r}")
    if not math.isfinite(v):
        _fail(path, key, f"must be finite, got {v!r}")
    if low is not None and (v < low or (v == low and not low_ok)):
        _fail(path, key, f"must be {'>=' if low_ok else '>'} {low:g}, got {v!r}")
    return v


def _unknown(path, where, table, allowed):
    extra = sorted(set(table) - set(allowed))
    if extra:
        _fail(path, f"{where}{extra[0]}", f"unknown key; allowed here: {sorted(allowed)}")


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


def _distribution(path, key, v, integer=False):
    if not isinstance(v, dict):
        v = {"value": v}
    if len(v) != 1:
        _fail(path, key, f"give exactly one of value / uniform / normal / choice, got {sorted(v)}")
    (kind, a), = v.items()
    if kind == "value":
        return Distribution("value", (_number(path, f"{key}.value", a, integer=integer),))
    if kind not in ("uniform", "normal", "choice"):
        _fail(path, key, f"unknown distribution {kind!r}; use value, uniform, normal or choice")
    if integer and kind != "choice":
        _fail(path, key, "takes whole numbers: use value or choice")
    if not isinstance(a, list) or not a:
        _fail(path, f"{key}.{kind}", f"must be a non-empty list, got {a!r}")
    a = tuple(_number(path, f"{key}.{kind}", x, integer=integer) for x in a)
    if kind == "uniform":
        if len(a) != 2:
            _fail(path, f"{key}.uniform", f"must be [lo, hi], got {list(a)}")
        if not a[1] > a[0]:
            _fail(path, f"{key}.uniform", f"empty or negative range [{a[0]}, {a[1]}]: need hi > "
                  f"lo (a single value is {{value = {a[0]}}})")
    if kind == "normal":
        if len(a) != 2:
            _fail(path, f"{key}.normal", f"must be [mean, sd], got {list(a)}")
        if not a[1] > 0:
            _fail(path, f"{key}.normal", f"sd must be > 0, got {a[1]}")
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


def _controller_value(path, key, name, v):
    if name in ("Kp", "Kv", "Kd", "Q", "tau_max"):
        vals = v if isinstance(v, list) else [v]
        for x in vals:
            _number(path, key, x, low=0.0, low_ok=False)
        return float(v) if not isinstance(v, list) else tuple(float(x) for x in v)
    if name in ("Gamma_scale", "velocity_filter_hz"):
        return float(_number(path, key, v, low=0.0))
    if name == "project":
        if not isinstance(v, bool):
            _fail(path, key, f"must be true or false, got {v!r}")
        return v
    if not isinstance(v, str):   # split
        _fail(path, key, f"must be a string, got {v!r}")
    return v


def _variants(path, entries, grid_points):
    if not isinstance(entries, list) or not entries:
        _fail(path, "controllers", "need at least one [[controllers]] entry")
    out, names = [], set()
    for i, e in enumerate(entries):
        where = f"controllers[{i}]"
        if not isinstance(e, dict):
            _fail(path, where, "must be a table")
        law = e.get("law")
        if law not in LAWS:
            _fail(path, f"{where}.law", f"must be one of {sorted(LAWS)}, got {law!r}")
        name = e.get("name", law)
        if not isinstance(name, str) or not name.isidentifier():
            _fail(path, f"{where}.name", f"must be a name like na_no_adaptation, got {name!r}")
        if name in names:
            _fail(path, f"{where}.name", f"{name!r} is used twice")
        names.add(name)
        _unknown(path, f"{where}.", e, {"name", "law", *LAWS[law]})
        fixed, grids = {}, []
        for k in LAWS[law]:
            if k not in e:
                continue
            v = e[k]
            if isinstance(v, dict):
                if set(v) != {"grid"}:
                    _fail(path, f"{where}.{k}", f"a table here must be {{grid = [...]}}, got {sorted(v)}")
                if k not in GRID_KEYS:
                    _fail(path, f"{where}.{k}", f"cannot be a grid; grids: {list(GRID_KEYS)}")
                g = v["grid"]
                if not isinstance(g, list) or not g:
                    _fail(path, f"{where}.{k}.grid", "must be a non-empty list of numbers")
                if grid_points:   # --quick: the grid's ends and middle
                    g = sorted(set([g[0], g[len(g) // 2], g[-1]]), key=g.index)[:grid_points]
                vals = [_controller_value(path, f"{where}.{k}.grid", k, x) for x in g]
                if any(isinstance(x, tuple) for x in vals) or len(set(vals)) != len(vals):
                    _fail(path, f"{where}.{k}.grid", f"must hold distinct scalars, got {g}")
                grids.append((k, vals))
            else:
                fixed[k] = _controller_value(path, f"{where}.{k}", k, v)
        for point in itertools.product(*[vals for _, vals in grids]):
            grid = tuple(zip([k for k, _ in grids], point))
            out.append(Variant(name, law, tuple(sorted({**fixed, **dict(grid)}.items())), grid))
    return tuple(out)


def _moves(path, moves):
    if not isinstance(moves, list) or not moves:
        _fail(path, "study.moves", "must be a non-empty list of move names or {name, start, "
              "end, v_max, a_max, j_max} tables")
    out = []
    for i, mv in enumerate(moves):
        key = f"study.moves[{i}]"
        if isinstance(mv, str):
            out.append((mv, None))
            continue
        if not isinstance(mv, dict):
            _fail(path, key, f"must be a move name or a table, got {mv!r}")
        _unknown(path, f"{key}.", mv, _MOVE_KEYS)
        missing = sorted(_MOVE_KEYS - set(mv))
        if missing:
            _fail(path, key, f"missing {missing}")
        line = {}
        for k in ("start", "end"):
            p = mv[k]
            if not (isinstance(p, list) and len(p) == 2):
                _fail(path, f"{key}.{k}", f"must be a point [x, y] in m, got {p!r}")
            line[k] = tuple(float(_number(path, f"{key}.{k}", x)) for x in p)
        for k in ("v_max", "a_max", "j_max"):
            line[k] = float(_number(path, f"{key}.{k}", mv[k], low=0.0, low_ok=False))
        out.append((mv["name"], tuple(sorted(line.items()))))
    names = [n for n, _ in out]
    if len(set(names)) != len(names):
        _fail(path, "study.moves", f"move names must be distinct, got {names}")
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
        return {"name": self.name, "model_sha256": _sha(Path(self.model_path)),
                "moves": self.moves, "seed": self.seed, "draws": self.draws, "runs": self.runs,
                "chunk": self.chunk, "settle_time": self.settle_time, "quantise": self.quantise,
                "variants": [(v.name, v.law, v.options) for v in self.variants],
                "uncertainty": [(k, d.kind, d.args) for k, d in self.uncertainty],
                "payload_change": self.payload_change, "quick": self.quick}

    @property
    def identity(self):
        """sha256 of :meth:`canonical`: equal identities give identical rows."""
        return hashlib.sha256(json.dumps(self.canonical(), sort_keys=True).encode()).hexdigest()


def _sha(p):
    return hashlib.sha256(p.read_bytes()).hexdigest()


def read_study(path, quick=False):
    """Read and validate a study file (TOML). ``quick``: apply its ``[quick]`` table.

    Paths in the file (``study.model``) are relative to the study file's folder. Raises
    :class:`StudyFileError` naming the file, the key and the reason. Checks that need the
    model (moves reachable and clear of singularities, gains accepted by the controllers) are
    made by :func:`pm2dof.studies.check_study`.
    """
    path = Path(path)
    try:
        text = path.read_text()
    except OSError as exc:
        raise StudyFileError(f"{path}: cannot read the study file: {exc.strerror}") from None
    try:
        doc = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise StudyFileError(f"{path}: not valid TOML: {exc}") from None
    _unknown(path, "", doc, _TOP_KEYS)
    st = doc.get("study")
    if not isinstance(st, dict):
        _fail(path, "study", "missing [study] table")
    _unknown(path, "study.", st, _STUDY_KEYS)
    q = doc.get("quick", {})
    if not isinstance(q, dict):
        _fail(path, "quick", "must be a table")
    _unknown(path, "quick.", q, _QUICK_KEYS)
    if quick:
        st = {**st, **{k: v for k, v in q.items() if k != "grid_points"}}
    for k in ("name", "model", "moves", "seed", "draws"):
        if k not in st:
            _fail(path, f"study.{k}", "missing")
    name = st["name"]
    if not isinstance(name, str) or not name:
        _fail(path, "study.name", f"must be a non-empty string, got {name!r}")
    try:
        model_path = resolve_model(str(st["model"]), relative_to=path.parent).resolve()
    except ModelFileError as exc:
        _fail(path, "study.model", str(exc))
    if not model_path.is_file():
        _fail(path, "study.model", f"no model file at {model_path} (a shipped model's name, or "
              f"a path relative to the study file's folder)")
    grid_points = q.get("grid_points") if quick else None
    if grid_points is not None:
        _number(path, "quick.grid_points", grid_points, integer=True, low=1)
    unc = doc.get("uncertainty", {})
    if not isinstance(unc, dict):
        _fail(path, "uncertainty", "must be a table")
    _unknown(path, "uncertainty.", unc, UNCERTAINTY)
    dists = []
    for k in UNCERTAINTY:   # canonical order: the draws do not depend on the file's order
        if k in unc:
            d = _distribution(path, f"uncertainty.{k}", unc[k],
                              integer=(k == "encoder_counts_per_rev"))
            lo, low_ok = UNCERTAINTY[k][1], UNCERTAINTY[k][2]
            if d.support[0] < lo or (d.support[0] == lo and not low_ok):
                _fail(path, f"uncertainty.{k}", f"can draw {d.support[0]:g}, below the allowed "
                      f"{'>=' if low_ok else '>'} {lo:g} ({UNCERTAINTY[k][0]})")
            dists.append((k, d))
    pc = doc.get("payload_change")
    if pc is not None:
        if not isinstance(pc, dict):
            _fail(path, "payload_change", "must be a table {after_run, payload_mass}")
        _unknown(path, "payload_change.", pc, {"after_run", "payload_mass"})
        if set(pc) != {"after_run", "payload_mass"}:
            _fail(path, "payload_change", "needs after_run and payload_mass")
        after = _number(path, "payload_change.after_run", pc["after_run"], integer=True, low=1)
        if quick and "runs" in q:
            after = min(after, max(1, q["runs"] // 2))
        pc = (after, float(_number(path, "payload_change.payload_mass", pc["payload_mass"],
                                   low=0.0)))
    runs = _number(path, "study.runs", st.get("runs", 1), integer=True, low=1)
    if pc is not None and pc[0] >= runs:
        _fail(path, "payload_change.after_run", f"must be < study.runs = {runs}, got {pc[0]}")
    quantise = st.get("quantise", True)
    if not isinstance(quantise, bool):
        _fail(path, "study.quantise", f"must be true or false, got {quantise!r}")
    description = st.get("description", "")
    if not isinstance(description, str):
        _fail(path, "study.description", "must be a string")
    return Study(
        path=str(path.resolve()), text=text, name=name, description=description,
        model_path=str(model_path), moves=_moves(path, st["moves"]),
        seed=_number(path, "study.seed", st["seed"], integer=True, low=0),
        draws=_number(path, "study.draws", st["draws"], integer=True, low=1, low_ok=True),
        runs=runs, chunk=_number(path, "study.chunk", st.get("chunk", 256), integer=True, low=1),
        settle_time=float(_number(path, "study.settle_time", st.get("settle_time", 0.0), low=0.0)),
        quantise=quantise, variants=_variants(path, doc.get("controllers"), grid_points),
        uncertainty=tuple(dists), payload_change=pc, quick=bool(quick))
