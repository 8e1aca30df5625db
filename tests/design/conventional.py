# A design model file turned into the conventional file of one design: its numbers written in.
"""The conventional model file of a design (the reference of the design-equivalence checks).

:func:`conventional_file` reads a model file with a ``[design]`` table with :mod:`tomllib`,
writes each design variable's value into the ``[[legs]]`` keys it sets (``repr`` of the float,
so the value is exact), drops ``[design]`` and writes the rest unchanged with :func:`dumps`, a
small TOML writer independent of pm2dof (none is installed). Deriving that file conventionally
(every geometric number folded in) is what ``Model.at_design`` must equal.

Design keys are ``legs.<i>.<key>`` with i from 1: ``la``, ``lb``, ``base.x``/``base.y``,
``attach.x``/``attach.y``, and a PRR rail's ends ``rail.start.x``, ``rail.end.y`` (also
accepted as ``rail.1.x``, ``rail.2.y``); a rail is written ``rail = [[x0, y0], [x1, y1]]``.
"""
from __future__ import annotations

import math
import re
import tomllib
from pathlib import Path

__all__ = ["conventional_file", "conventional_doc", "set_key", "dumps"]

_COMPONENT = {"x": 0, "y": 1}
_RAIL_END = {"start": 0, "1": 0, "end": 1, "2": 1}


def set_key(doc, label, value):
    """Write ``value`` (float) into the parsed model file ``doc`` at the design key ``label``
    ("legs.2.base.x"), in place. KeyError for a key this writer does not know."""
    parts = label.split(".")
    if parts[0] != "legs" or len(parts) < 3 or not parts[1].isdigit():
        raise KeyError(f"not a [[legs]] key: {label!r}")
    leg = doc["legs"][int(parts[1]) - 1]
    rest = parts[2:]
    if rest in (["la"], ["lb"]):
        leg[rest[0]] = float(value)
    elif len(rest) == 2 and rest[0] in ("base", "attach") and rest[1] in _COMPONENT:
        leg[rest[0]][_COMPONENT[rest[1]]] = float(value)
    elif len(rest) == 3 and rest[0] == "rail" and rest[1] in _RAIL_END and rest[2] in _COMPONENT:
        leg["rail"][_RAIL_END[rest[1]]][_COMPONENT[rest[2]]] = float(value)
    else:
        raise KeyError(f"unknown design key {label!r}")


def conventional_doc(doc, values):
    """The parsed file ``doc`` (not modified) with ``values`` {variable: float} written into
    its ``[design]`` keys and ``[design]`` dropped: a new dict."""
    import copy
    out = copy.deepcopy(doc)
    design = out.pop("design")
    unknown = sorted(set(values) - set(design))
    if unknown:
        raise KeyError(f"unknown design variable(s) {unknown}; the file has {sorted(design)}")
    for name, value in values.items():
        for label in design[name]["keys"]:
            set_key(out, label, value)
    return out


def conventional_file(design_file, values, out_path):
    """Write the conventional model file of ``design_file`` at the design ``values``.

    Parameters
    ----------
    design_file : str or Path
        A model file with a ``[design]`` table.
    values : mapping or sequence of float
        {variable: value, m}, or the values in the file's ``[design]`` order; variables not
        given keep the file's numbers.
    out_path : str or Path
        Where the conventional file is written (UTF-8).

    Returns
    -------
    pathlib.Path
        ``out_path``.
    """
    with open(design_file, "rb") as fh:
        doc = tomllib.load(fh)
    if not isinstance(values, dict):
        values = dict(zip(doc["design"], (float(v) for v in values), strict=True))
    out_path = Path(out_path)
    out_path.write_text(dumps(conventional_doc(doc, values)), encoding="utf-8")
    return out_path


# --- a small TOML writer ------------------------------------------------------------------

_BARE = re.compile(r"[A-Za-z0-9_-]+\Z")
_ESC = {'"': '\\"', "\\": "\\\\", "\b": "\\b", "\t": "\\t", "\n": "\\n", "\f": "\\f",
        "\r": "\\r"}


def _key(k):
    return k if _BARE.match(k) else _string(k)


def _string(s):
    return '"' + "".join(_ESC.get(c) or (f"\\u{ord(c):04x}" if ord(c) < 32 or ord(c) == 127
                                          else c) for c in s) + '"'


def _value(v):
    """One TOML value, inline (tables inside values become inline tables)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return ("nan" if math.isnan(v) else ("inf" if v > 0 else "-inf")) if not math.isfinite(v) \
            else repr(v)
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(f"cannot write {type(v).__name__} as TOML: {v!r}")


def _is_aot(v):
    return isinstance(v, list) and v != [] and all(isinstance(x, dict) for x in v)


def _table(lines, path, table, header, inline_dicts):
    """Append ``table``'s lines under ``header`` (None at the root): its plain keys first,
    then its sub-tables ([a.b]) and arrays of tables ([[a.b]]). ``inline_dicts``: write
    dict values inline (inside an array-of-tables element, as the shipped files do)."""
    plain = {k: v for k, v in table.items()
             if not (_is_aot(v) or (isinstance(v, dict) and not inline_dicts))}
    if header is not None and (plain or not table or header.startswith("[[")):
        lines += ["", header]
    lines += [f"{_key(k)} = {_value(v)}" for k, v in plain.items()]
    for k, v in table.items():
        if k in plain:
            continue
        sub = path + [k]
        name = ".".join(_key(x) for x in sub)
        if isinstance(v, dict):
            _table(lines, sub, v, f"[{name}]", False)
        else:
            for element in v:
                _table(lines, sub, element, f"[[{name}]]", True)


def dumps(doc):
    """The TOML text of ``doc`` (a dict as :func:`tomllib.loads` returns it): nested tables,
    arrays of tables, inline tables, strings, floats (``repr``, so exact), ints, bools and
    arrays. ``tomllib.loads(dumps(doc)) == doc``."""
    lines = []
    _table(lines, [], doc, None, False)
    return "\n".join(lines).lstrip("\n") + "\n"
