# Input-file validation shared by model, study and path files: collect every problem, then raise.
"""Checks of a user's input file that collect problems instead of raising at the first one.

A :class:`Problems` collector belongs to one file. Its typed checks (:meth:`~Problems.number`,
:meth:`~Problems.vector`, :meth:`~Problems.point`, :meth:`~Problems.table`, :meth:`~Problems.keys`,
:meth:`~Problems.choice`, ...) return the checked value, or None after recording a
:class:`~pm2dof.core.errors.Problem`; callers skip the checks that depend on a None.
:meth:`~Problems.raise_if_any` then raises every problem at once, as one
:class:`~pm2dof.core.errors.InputFileError` (a ``ModelFileError``, a ``StudyFileError``)::

    /path/model.toml: 2 problems:
      [nominal.alpha] must be a list of 4 numbers, one per leg (the file has 4 [[legs]]), ...
      [limits.tau_max (leg 2)] must be > 0, got 0.0

Entries of arrays are numbered from 1, as the paper numbers legs: :func:`entry`.
"""
import math
import tomllib
from pathlib import Path

from .errors import InputFileError, Problem

__all__ = ["Problems", "entry", "format_problems", "RULES"]

#: named bounds for :meth:`Problems.number`: "pos" > 0, "nonneg" >= 0, "any" unbounded
RULES = {"pos": {"low": 0.0, "low_ok": False}, "nonneg": {"low": 0.0}, "any": {}}


def entry(key, label):
    """The key of one entry of an array: ``entry("nominal.alpha", "leg 2")`` is
    ``"nominal.alpha (leg 2)"`` (labels count from 1: ``leg 1`` is the first)."""
    return f"{key} ({label})"


def format_problems(path, problems):
    """``path: [key] reason`` for one problem; for several, a count and one line each."""
    lines = [p.reason if p.key is None else f"[{p.key}] {p.reason}" for p in problems]
    if len(lines) == 1:
        return f"{path}: {lines[0]}"
    return f"{path}: {len(lines)} problems:\n" + "\n".join(f"  {line}" for line in lines)


class Problems:
    """The problems found in one input file.

    Parameters
    ----------
    path : str or pathlib.Path
        The file, named by every message.
    error : type
        The :class:`~pm2dof.core.errors.InputFileError` subclass to raise.
    """

    def __init__(self, path, error=InputFileError):
        self.path, self.error, self.found = path, error, []

    def __len__(self):
        return len(self.found)

    def add(self, key, reason):
        """Record a problem at ``key`` (None: the whole file). Returns None."""
        self.found.append(Problem(key, reason))
        return None

    def stop(self, key, reason):
        """Record a problem that makes further checks meaningless, and raise all of them."""
        self.add(key, reason)
        self.raise_if_any()

    def raise_if_any(self):
        """Raise every problem recorded so far as one error; nothing when there is none."""
        if self.found:
            raise self.error(format_problems(self.path, self.found), problems=self.found,
                             path=self.path) from None

    def read_toml(self, kind):
        """(bytes, TOML document) of the file at ``path``: one reader for model, study and path
        files. Unreadable, binary (a NUL byte), non-UTF-8 or non-TOML content stops here, named;
        ``kind`` ("model file") is how messages call the file."""
        try:
            raw = Path(self.path).read_bytes()
        except OSError as exc:
            self.stop(None, f"cannot read the {kind}: {exc.strerror or exc}")
        nul = raw.find(b"\x00")
        if nul >= 0:
            self.stop(None, f"binary content (NUL byte at offset {nul}), not a TOML {kind}")
        try:
            return raw, tomllib.loads(raw.decode("utf-8"))
        except UnicodeDecodeError as exc:
            self.stop(None, f"not a text (UTF-8) file: {exc.reason} at byte {exc.start}")
        except tomllib.TOMLDecodeError as exc:
            self.stop(None, f"not valid TOML: {exc}")

    # ---- typed checks: each returns the checked value, or None after recording a problem ----

    def number(self, key, value, *, integer=False, low=None, low_ok=True):
        """A finite number (an integer when ``integer``), at least ``low`` (or above it when
        not ``low_ok``). Returns it as a float, or the int when ``integer``."""
        if (isinstance(value, bool) or not isinstance(value, (int, float))
                or (integer and not isinstance(value, int))):
            what = "an integer" if integer else "a number"
            return self.add(key, f"must be {what}, got {type(value).__name__} {value!r}")
        try:
            as_float = float(value)
        except OverflowError:
            return self.add(key, f"is too large for a float: {str(value)[:20]}...")
        if not math.isfinite(as_float):
            return self.add(key, f"must be finite, got {value}")
        if low is not None and (value < low or (value == low and not low_ok)):
            return self.add(key, f"must be {'>=' if low_ok else '>'} {low:g}, got {value}")
        return value if integer else as_float

    def vector(self, key, value, labels, *, meaning="", **bounds):
        """A list of ``len(labels)`` numbers, entry i named ``key (labels[i])`` in messages;
        ``meaning`` follows the length in the message (", one per leg ..."). ``bounds`` as
        :meth:`number`. Returns a tuple of floats."""
        size = len(labels)
        if not isinstance(value, list) or len(value) != size:
            got = (f"got {len(value)}: {value!r}" if isinstance(value, list)
                   else f"got {type(value).__name__} {value!r}")
            return self.add(key, f"must be a list of {size} numbers{meaning}, {got}")
        out = [self.number(entry(key, label), v, **bounds) for label, v in zip(labels, value)]
        return None if any(v is None for v in out) else tuple(out)

    def point(self, key, value):
        """A point [x, y] in m: two finite numbers. Returns a tuple of floats."""
        if not (isinstance(value, list) and len(value) == 2):
            return self.add(key, f"must be a point [x, y] in m, got {value!r}")
        xy = [self.number(key, v) for v in value]
        return None if None in xy else tuple(xy)

    def table(self, key, value, *, required=True):
        """``value`` (a ``doc.get(key)``) as a table. Absent: a problem when ``required``;
        None either way."""
        if value is None:
            return self.add(key, "missing (required)") if required else None
        if not isinstance(value, dict):
            return self.add(key, f"must be a table, got {type(value).__name__}")
        return value

    def keys(self, where, table, allowed, required=(), label=None):
        """One problem per unknown key and per missing required key of ``table`` (at
        ``where``, "" at the top level; ``label`` numbers an entry of an array of tables).
        Returns True when there is none."""
        def at(k):
            key = f"{where}.{k}" if where else str(k)
            return key if label is None else entry(key, label)
        n = len(self.found)
        for k in sorted(set(table) - set(allowed), key=str):
            self.add(at(k), f"unknown key; allowed here: {sorted(allowed)}")
        for k in sorted(set(required) - set(table)):
            self.add(at(k), "missing (required)")
        return len(self.found) == n

    def choice(self, key, value, choices):
        """A string that must be a key of ``choices`` (a dict): returns its mapped value."""
        if not isinstance(value, str) or value not in choices:
            return self.add(key, f"must be one of {sorted(choices)}, got {value!r}")
        return choices[value]

    def boolean(self, key, value):
        """true or false."""
        if not isinstance(value, bool):
            return self.add(key, f"must be true or false, got {value!r}")
        return value

    def text(self, key, value, *, nonempty=False):
        """A string (non-empty when ``nonempty``)."""
        if not isinstance(value, str) or (nonempty and not value):
            what = "a non-empty string" if nonempty else "a string"
            return self.add(key, f"must be {what}, got {type(value).__name__} {value!r}")
        return value
