# The product speaks of the project, not of its work items: no issue numbers in code, docs, tests.
"""Comments, docstrings, help texts, the documentation pages and the tests' messages say what a
change was for ("the platforms", "sign(0) = 0"), never which work item it came from ("issue
26"): a reader of the package has no tracker. Every text file of the package, the docs, the
tests, the examples, the README and the Makefile is read (the compiled libraries aside, and
CasADi's generated C: its headers, written from the derivation's text, are read).

:data:`NOT_YET` would list, each exactly, a line left for later; it is empty, and an entry
that no longer matches fails too, so that the list only shrinks."""
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PATTERN = re.compile(r"\b[Ii]ssues? ?#?\d+|\b[Ii]ssue-\d+")
PLACES = ["pm2dof", "docs", "tests", "examples", "README.md", "Makefile"]
BINARY = {".so", ".png", ".gif", ".parquet", ".pyc", ".npz", ".ico", ".woff", ".woff2"}

#: (path, the whole line, stripped): lines with an issue number left to their owner
NOT_YET: set = set()


def _files():
    for place in PLACES:
        path = ROOT / place
        for f in sorted(path.rglob("*")) if path.is_dir() else [path]:
            generated_c = f.suffix == ".c" and f.parent.parent.name == "generated"
            if f.is_file() and f.suffix not in BINARY and "__pycache__" not in f.parts \
                    and not generated_c and f != Path(__file__).resolve():
                yield f


def _found():
    out = set()
    for f in _files():
        try:
            text = f.read_text()
        except UnicodeDecodeError:
            continue
        for line in text.splitlines():
            if PATTERN.search(line):
                out.add((str(f.relative_to(ROOT)), line.strip()))
    return out


def test_no_issue_numbers_in_the_product():
    found = _found()
    new = sorted(found - NOT_YET)
    assert not new, "issue numbers (say what the change was for instead):\n" + "\n".join(
        f"  {path}: {line}" for path, line in new)
    gone = sorted(NOT_YET - found)
    assert not gone, "reworded: remove from NOT_YET:\n" + "\n".join(
        f"  {path}: {line}" for path, line in gone)


def test_the_pattern_finds_the_forms_used():
    for text in ("(issue 27)", "Issue 26: the", "issue-28 spline", "issue 22 #14", "issues 25"):
        assert PATTERN.search(text), text
    for text in ("It issues two instructions", "tissue 3", "the issue's targets"):
        assert not PATTERN.search(text), text
