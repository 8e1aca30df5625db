# Numeric tables from CSV or Parquet files: named float columns, errors naming file, row and column.
"""Read a table of numbers (one column per name) from ``.csv`` or ``.parquet``.

CSV: optional ``#`` comment lines and blank lines, then a header row of column names, then
one row of numbers per line. Parquet: the columns of the file's table (pyarrow, the
``studies`` or ``ident`` extra, imported when a Parquet file is read). Every problem raises
the caller's error class with one line naming the file, the row (1-based, data rows; for CSV
also the line) and the column.
"""
import csv
import io
from pathlib import Path

import numpy as np

from ..core.validate import Problems

__all__ = ["read_columns", "decode_text", "TABLE_SUFFIXES"]

#: file suffix -> format
TABLE_SUFFIXES = {".csv": "csv", ".parquet": "parquet", ".pq": "parquet"}


def decode_text(path, raw, error, what="a table"):
    """The text of a CSV file's bytes ``raw``: UTF-8 (a BOM, Excel's "CSV UTF-8", dropped). A
    ``#`` comment line in another encoding (a logger's Latin-1 ``# operator = Müller``) is read
    as Latin-1; any other byte that is not UTF-8 (binary junk) raises ``error`` (an
    :class:`~pm2dof.core.errors.InputFileError` subclass) in one line naming the file, the
    line, the byte and its column, and saying that ``what`` ("a log", "a reference") is a UTF-8
    CSV or a Parquet file. The one reader of CSV text for logs and reference files."""
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        pass
    lines = raw.split(b"\n")
    for no, line in enumerate(lines):
        try:
            lines[no] = line.decode("utf-8-sig" if no == 0 else "utf-8")
        except UnicodeDecodeError as exc:
            if line.lstrip().startswith(b"#"):
                lines[no] = line.decode("latin-1")
                continue
            Problems(path, error).stop(
                None, f"line {no + 1} is not text (byte 0x{line[exc.start]:02x} at column "
                      f"{exc.start + 1} is not UTF-8): {what} is a UTF-8 CSV or a Parquet file")
    return "\n".join(lines)


def _csv_columns(path, error, what):
    try:
        raw = Path(path).read_bytes()
    except OSError as exc:
        raise error(f"{path}: cannot read the file: {exc.strerror or exc}") from None
    lines = decode_text(path, raw, error, what).splitlines()
    body = [(k + 1, line) for k, line in enumerate(lines)
            if line.strip() and not line.lstrip().startswith("#")]
    if not body:
        raise error(f"{path}: no header row (the column names)")
    rows = list(csv.reader(io.StringIO("\n".join(line for _, line in body))))
    header = [h.strip() for h in rows[0]]
    other = next((d for d in (";", "\t", "|") if len(header) == 1 and d in rows[0][0]), None)
    if other is not None:
        raise error(f"{path}: line {body[0][0]}: the header is one column, "
                    f"{rows[0][0].strip()!r}: columns must be separated by commas, not "
                    f"{'tabs' if other == chr(9) else repr(other)}")
    cols = {h: [] for h in header}
    for r, ((line_no, _), row) in enumerate(zip(body[1:], rows[1:], strict=False), start=1):
        if len(row) != len(header):
            raise error(f"{path}: row {r} (line {line_no}) has {len(row)} fields, the header "
                        f"{len(header)}")
        for h, cell in zip(header, row, strict=True):
            try:
                cols[h].append(float(cell))
            except ValueError:
                raise error(f"{path}: row {r} (line {line_no}), column {h}: {cell!r} is not a "
                            f"number") from None
    return header, {h: np.array(v, dtype=float) for h, v in cols.items()}, \
        [line_no for line_no, _ in body[1:]]


def _parquet_columns(path, error):
    try:
        import pyarrow.parquet as pq
    except ModuleNotFoundError:
        raise error(f"{path}: reading Parquet needs pyarrow: pip install 'pm2dof[studies]', "
                    f"or write the file as .csv") from None
    try:
        table = pq.read_table(path)
    except Exception as exc:     # pyarrow raises its own types for a corrupt file
        raise error(f"{path}: not a readable Parquet file ({exc})") from None
    cols = {}
    for name in table.column_names:
        col = table.column(name)
        if col.null_count:
            r = next(k for k, v in enumerate(col.to_pylist()) if v is None)
            raise error(f"{path}: row {r + 1}, column {name}: empty (null)")
        try:
            cols[name] = np.asarray(col.to_numpy(zero_copy_only=False), dtype=float)
        except (TypeError, ValueError) as exc:
            raise error(f"{path}: column {name} is not numeric ({col.type}: {exc})") from None
    return list(table.column_names), cols


def read_columns(path, error, what="a table"):
    """(column names in file order, {name: float64 array}) of the table at ``path``.

    Parameters
    ----------
    path : str or pathlib.Path
        A ``.csv`` or ``.parquet`` (``.pq``) file.
    error : type
        The exception class raised, with one line naming the file and, where it applies, the
        row and the column: a missing file, another suffix, a repeated or empty column name,
        ragged CSV rows, a cell that is not a number, NaN or infinity, no data rows, a CSV
        line that is not text (:func:`decode_text`).
    what : str
        What the file is, for the message about bytes that are not text ("a reference").
    """
    path = Path(path)
    kind = TABLE_SUFFIXES.get(path.suffix.lower())
    if kind is None:
        raise error(f"{path}: unknown table format {path.suffix!r} (use .csv or .parquet)")
    if not path.is_file():
        raise error(f"{path}: no such file")
    header, cols, lines = _csv_columns(path, error, what) if kind == "csv" else (
        *_parquet_columns(path, error), None)
    empty = [k + 1 for k, h in enumerate(header) if not h]
    if empty:
        raise error(f"{path}: column {empty[0]} of the header has no name")
    dup = sorted({h for h in header if header.count(h) > 1})
    if dup:
        raise error(f"{path}: column(s) {', '.join(dup)} appear more than once")
    if not header or len(cols[header[0]]) == 0:
        raise error(f"{path}: no data rows")
    for h in header:
        bad = np.flatnonzero(~np.isfinite(cols[h]))
        if bad.size:
            r = int(bad[0])
            where = f"row {r + 1}" + ("" if lines is None else f" (line {lines[r]})")
            raise error(f"{path}: {where}, column {h}: {float(cols[h][r])} is not a finite "
                        f"number")
    return header, cols
