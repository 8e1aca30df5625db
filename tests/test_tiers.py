# The test tiers: make test-quick, make test, make test-slow, by markers and not by timings.
"""The tiers of docs/developing.md ("The tests"): ``slow`` and ``long`` are registered
markers; a module marked long (``pytestmark = pytest.mark.long`` at its top) is left out of
``make test-quick`` without being imported, kept in ``make test``, and handed out first to the
workers of ``make test``; the schedule keeps no hand-timed list. Checked on the real suite with
``pytest --collect-only`` in a subprocess (tests/core: one long module, test_model.py, beside
quick ones) and on the ordering rule."""
import ast
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

ROOT = Path(__file__).resolve().parent.parent
MODULES = sorted((ROOT / "tests").rglob("test_*.py"))


def _conftest(config):
    """tests/conftest.py, the plugin (not ``import conftest``: tests/derivatives has its
    own)."""
    return next(p for p in config.pluginmanager.get_plugins()
                if getattr(p, "__file__", None) == str(ROOT / "tests" / "conftest.py"))


def _declares_long(path):
    """What the module says, by its syntax tree: a top-level ``pytestmark`` holding
    ``pytest.mark.long``."""
    for node in ast.parse(path.read_text()).body:
        if isinstance(node, ast.Assign) and any(getattr(t, "id", "") == "pytestmark"
                                                for t in node.targets):
            return "pytest.mark.long" in ast.unparse(node.value)
    return False


def test_the_markers_are_registered_and_strict():
    ini = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["pytest"]["ini_options"]
    assert "--strict-markers" in ini["addopts"] and "-m 'not slow'" in ini["addopts"]
    assert {m.split(":")[0] for m in ini["markers"]} == {"slow", "long"}
    make = (ROOT / "Makefile").read_text()
    assert re.search(r"^test-quick: .*\n\t.*-m 'not slow and not long'", make, re.MULTILINE)


def test_no_hand_timed_schedule(request):
    conftest = _conftest(request.config)
    assert not [name for name in vars(conftest) if "LONGEST" in name.upper()]
    text = (ROOT / "tests" / "conftest.py").read_text()
    assert not re.search(r"#\s*\(\d+(\.\d+)?\)", text), "a timing in brackets is back"


def test_the_text_rule_agrees_with_the_syntax_tree(request):
    """conftest reads a module's mark as text (without importing it): the same answer as
    its syntax tree, for every test module; and some modules are long, some not."""
    marked = _conftest(request.config)._marked_long
    answers = {p: marked(p) for p in MODULES}
    assert answers == {p: _declares_long(p) for p in MODULES}
    assert 0 < sum(answers.values()) < len(MODULES)


def _collected(*args):
    r = subprocess.run([sys.executable, "-m", "pytest", "--collect-only", "-q", "-p",
                        "no:xdist", "-p", "no:cacheprovider", *args, "tests/core"],
                       capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    return {line.split("::")[0] for line in r.stdout.splitlines() if "::" in line}, r.stdout


@pytest.mark.slow      # collects the suite three times in subprocesses (5 s): make test-slow (CI)
def test_quick_leaves_out_the_long_modules_without_importing_them():
    everything, _ = _collected()
    quick, out = _collected("-m", "not slow and not long")
    long_only, _ = _collected("-m", "long")
    assert "tests/core/test_model.py" in everything and "tests/core/test_cbind.py" in quick
    assert quick == {m for m in everything if not _declares_long(ROOT / m)}
    assert long_only == {m for m in everything if _declares_long(ROOT / m)}
    # ignored (never imported), not deselected: only the slow tests count as deselected
    _, slow_out = _collected("-m", "slow")
    n_slow = sum(1 for line in slow_out.splitlines()       # the slow tests of modules it imports
                 if "::" in line and not _declares_long(ROOT / line.split("::")[0]))
    last = out.splitlines()[-1]
    deselected = re.search(r"(\d+) deselected", last)
    assert (int(deselected[1]) if deselected else 0) == n_slow, (last, n_slow)


def test_make_test_hands_out_the_long_units_first(request):
    conftest = _conftest(request.config)
    units = ["tests/core/test_cbind.py", "tests/core/test_model.py", "derivations",
             "tests/test_errors_status.py", "tests/test_api.py"]
    assert conftest.long_first(units, ROOT) == [
        "tests/core/test_model.py", "derivations", "tests/test_api.py",
        "tests/core/test_cbind.py", "tests/test_errors_status.py"]
