# `pm2dof design pick`: a plain model file (no [design]) at one design of a run's front.
"""A model file at a chosen design, written as text so that the file stays the user's.

The model file of the run is copied line by line; only two things change:

* in each ``[[legs]]`` entry, the value of every key a searched design variable sets
  (``la = 0.244`` becomes ``la = 0.22``; ``base = [0.433, 0.0]`` keeps its other
  coordinate), the rest of the line (its comment) kept;
* the ``[design]`` table is removed (its header, its keys and the comments among them; the
  comments above it, and those directly above the next table, are kept).

A line at the top says where the design came from. The result is checked before it is
returned: parsed as TOML it equals the original with those values set and without
``[design]``; read as a model file (:func:`pm2dof.core.model_file.read_model_file`) its legs
carry the design's values exactly, and equal those of
:func:`pm2dof.core.design.spec_at_design` on the original (what ``Model.at_design`` uses). ``pm2dof derive`` then derives it as any fixed model.
"""
import copy
import re
import tomllib
from pathlib import Path

from ..core.errors import ArgumentError, DesignError
from ..infra.results import write_atomic

__all__ = ["pick_design", "text_at_design"]

_HEADER = re.compile(r"^\s*\[\[?\s*([A-Za-z_][\w.\-]*)\s*\]\]?\s*(#.*)?$")
_COORD = {"x": 0, "y": 1}


def _toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    return str(v)


def _where(label, legs):
    """(leg index from 0, TOML key, index path inside its value) of a design key label."""
    m = re.fullmatch(r"legs\.(\d+)\.(.+)", label)
    if m is None or not 1 <= int(m[1]) <= len(legs):
        raise DesignError(f"design key {label!r}: not legs.<i>.<key> with i in 1..{len(legs)}")
    i, key = int(m[1]) - 1, m[2]
    parts = key.split(".")
    if key in ("la", "lb"):
        return i, key, ()
    if parts[0] in ("base", "attach") and len(parts) == 2 and parts[1] in _COORD:
        return i, parts[0], (_COORD[parts[1]],)
    if parts[0] == "rail" and len(parts) == 3 and parts[1] in ("start", "end") \
            and parts[2] in _COORD:
        return i, "rail", (0 if parts[1] == "start" else 1, _COORD[parts[2]])
    raise DesignError(f"design key {label!r}: {key!r} is not a designable key")


def _value_end(lines, row, col):
    """(row, col) just past the TOML value starting at lines[row][col] (arrays may span
    lines; a comment after the value is not part of it)."""
    depth, quote = 0, None
    r, c = row, col
    started = False
    while r < len(lines):
        line = lines[r]
        while c < len(line):
            ch = line[c]
            if quote:
                if ch == "\\" and quote == '"':
                    c += 2
                    continue
                if ch == quote:
                    quote = None
            elif ch in "\"'":
                quote, started = ch, True
            elif ch == "[":
                depth, started = depth + 1, True
            elif ch == "]":
                depth -= 1
                if depth == 0:
                    return r, c + 1
            elif ch == "#" or (ch.isspace() and started and depth == 0):
                if depth == 0:
                    return r, c
                if ch == "#":             # a comment inside a multi-line array
                    break
            elif not ch.isspace():
                started = True
            c += 1
        if depth == 0 and started:
            return r, len(line.rstrip("\n"))
        r, c = r + 1, 0
    raise DesignError("unterminated value in the model file")


def _sections(lines):
    """[(name, is_array, first line, end line)] of the file's tables."""
    heads = [(i, m[1], lines[i].lstrip().startswith("[["))
             for i, line in enumerate(lines) if (m := _HEADER.match(line))]
    return [(name, arr, i, heads[k + 1][0] if k + 1 < len(heads) else len(lines))
            for k, (i, name, arr) in enumerate(heads)]


def text_at_design(text, values):
    """The model file ``text`` with the ``[design]`` variables ``values`` set in its
    ``[[legs]]`` and its ``[design]`` table removed.

    Parameters
    ----------
    text : str
        A model file with a ``[design]`` table.
    values : mapping
        {variable: value}, m; variables not given keep the file's values.

    Returns
    -------
    (str, dict)
        The new text, and what it must parse to (TOML) for the edit to be right.
    """
    raw = tomllib.loads(text)
    table = raw.get("design")
    if not isinstance(table, dict):
        raise DesignError("the model file has no [design] table: nothing to pick")
    unknown = sorted(set(values) - set(table))
    if unknown:
        raise DesignError(f"design variable(s) {unknown} are not in the model file's [design] "
                          f"({', '.join(table)})")
    legs = raw.get("legs", [])
    expected = copy.deepcopy({k: v for k, v in raw.items() if k != "design"})
    edits = {}                                   # (leg, toml key) -> new value
    for name, value in values.items():
        for label in table[name].get("keys", []):
            i, key, path = _where(label, legs)
            new = edits.get((i, key), copy.deepcopy(legs[i].get(key)))
            if new is None:
                raise DesignError(f"design key {label!r}: legs {i + 1} has no {key!r}")
            if path:
                target = new
                for p in path[:-1]:
                    target = target[p]
                target[path[-1]] = float(value)
            else:
                new = float(value)
            edits[(i, key)] = new
            expected["legs"][i][key] = new
    lines = text.splitlines(keepends=True)
    secs = _sections(lines)
    legs_secs = [s for s in secs if s[0] == "legs" and s[1]]
    for (i, key), new in edits.items():
        _, _, start, end = legs_secs[i]
        for r in range(start + 1, end):
            m = re.match(rf"^(\s*{re.escape(key)}\s*=\s*)", lines[r])
            if m:
                r2, c2 = _value_end(lines, r, m.end())
                tail, value = lines[r2][c2:], _toml_value(new)
                rest = tail.lstrip(" \t")
                if r2 == r and rest.startswith("#"):   # keep the comment's column
                    width = c2 - m.end() + len(tail) - len(rest)
                    tail = " " * max(1, width - len(value)) + rest
                lines[r] = m[1] + value + tail
                for k in range(r + 1, r2 + 1):
                    lines[k] = ""
                break
        else:
            raise DesignError(f"legs {i + 1}: no line '{key} = ...' in its [[legs]] entry")
    drop = set()
    for name, _, start, end in secs:
        if name == "design" or name.startswith("design."):
            # the comments directly above the next table are that table's: kept
            while end - 1 > start and (lines[end - 1].lstrip().startswith("#")
                                       or not lines[end - 1].strip()):
                end -= 1
            drop.update(range(start, end))
    out = "".join(line for r, line in enumerate(lines) if r not in drop)
    out = re.sub(r"\n{3,}", "\n\n", out)
    return out, expected


def pick_design(out, index, path, command_line=None):
    """Write a plain model file at the design ``index`` of the front of the run ``out``.

    Parameters
    ----------
    out : path
        The ``--out`` of ``pm2dof design run``.
    index : int
        The design's position in the front (``design show``'s ``#``, from 0).
    path : path
        The model file to write.
    command_line : list of str, optional
        The command recorded in the file's first line (None: not recorded).

    Returns
    -------
    (Path, dict)
        The file written and the design ({variable: value}).
    """
    from ..core.model_file import read_model_file
    from .front import read_front
    fr = read_front(out)
    n = len(fr.index)
    if not n:
        raise ArgumentError(f"{out}: the front is empty (no feasible design); nothing to pick")
    if not 0 <= index < n:
        raise ArgumentError(f"INDEX must be in 0..{n - 1} (the front of {out} has {n} "
                            f"designs; `pm2dof design show {out}` lists them), got {index}")
    values = fr.design(index)
    model_file = Path(fr.info["model_file"])
    text, expected = text_at_design(model_file.read_text(), values)
    said = ", ".join(f"{k} = {v!r}" for k, v in values.items())
    head = (f"# Picked by `pm2dof design pick`: design {index} of the front of {out} (study "
            f"{fr.info.get('name')!r}, model file {model_file}): {said}.\n# Its [design] table "
            f"is removed: a plain model file (`pm2dof derive` derives it).\n")
    if command_line:
        head += f"# Command: {' '.join(map(str, command_line))}\n"
    text = head + text
    if tomllib.loads(text) != expected:
        raise DesignError(f"the picked file does not parse to the model file at the design "
                          f"(a bug; {model_file} has a layout the text edit missed)")
    dest = write_atomic(Path(path), text.encode())
    spec = read_model_file(dest)
    raw = tomllib.loads(model_file.read_text())
    for name, value in values.items():
        for label in raw["design"][name]["keys"]:
            i, key, sub = _where(label, raw["legs"])
            got = _spec_value(spec.legs[i], key, sub)
            if got != float(value):
                raise DesignError(f"{dest}: {label} reads back as {got!r}, not {value!r}")
    from ..core.design import spec_at_design
    want = spec_at_design(read_model_file(model_file), values)   # the model API's route
    if spec.legs != want.legs:
        raise DesignError(f"{dest}: its legs differ from the model file's at the design "
                          f"(Model.at_design's): {spec.legs} != {want.legs}")
    return dest, values


def _spec_value(leg, key, sub):
    """The value of a design key in a read Leg (``rail`` is ``base`` -> ``rail_end``)."""
    if key == "rail":
        return float((leg.base if sub[0] == 0 else leg.rail_end)[sub[1]])
    v = getattr(leg, key)
    return float(v[sub[0]] if sub else v)
