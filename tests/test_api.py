# The public API: every name in pm2dof.__all__, and the README's code kept honest.
"""The contract with users.

* Every name in ``pm2dof.__all__`` imports from ``pm2dof`` (the lazy ones too) and is the
  object of its home module.
* The names the controllers issue promised exist exactly there (``pm2dof.NAController``...).
* The README's Python blocks run, in order, in one namespace (a fresh interpreter), and so do
  those of each page of the documentation site (docs/*.md, one interpreter per page); every
  ``pm2dof ...`` command line in their shell blocks parses with the real CLI parser, and every
  ``make`` target they name exists. So neither the README nor the docs can drift from the code.
* The README's links into docs/ exist, the home page (docs/index.md) links every page, and
  the API reference page (docs/api.md) documents exactly the names of ``pm2dof.__all__``,
  each from the module that holds it.
"""
import importlib
import os
import re
import shlex
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

import pm2dof

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

REPO = Path(__file__).resolve().parent.parent
README = REPO / "README.md"


def test_every_name_in_all_imports():
    assert len(pm2dof.__all__) == len(set(pm2dof.__all__)), "duplicates in __all__"
    ns = {}
    exec(f"from pm2dof import {', '.join(pm2dof.__all__)}", ns)  # noqa: S102 - the test itself
    for name in pm2dof.__all__:
        assert ns[name] is getattr(pm2dof, name), name
    assert set(pm2dof.__all__) <= set(dir(pm2dof))


def test_star_import_gives_exactly_all():
    ns = {}
    exec("from pm2dof import *", ns)  # noqa: S102
    assert set(ns) - {"__builtins__"} == set(pm2dof.__all__)


def test_promised_names_are_at_the_top_level():
    """The controllers issue's API block: pm2dof.NAController(m), pm2dof.APDController(m)."""
    from pm2dof import (
        STATUS_NAMES,
        APDController,
        NAController,
        SimResult,
        line,
        paper_move,
        simulate,
    )
    m = pm2dof.load_model()
    na, apd = NAController(m), APDController(m)
    assert na.theta_hat.shape == (len(m.param_names),)
    r = simulate(m, apd, paper_move("low"))
    assert isinstance(r, SimResult) and r.rmse < 1e-3
    assert set(STATUS_NAMES.values()) == {"ok", "singular", "saturated", "non_finite",
                                          "preload_infeasible", "inconsistent_encoders"}
    assert STATUS_NAMES == {int(v): k for k, v in m.manifest["status_codes"].items()}
    assert len(line((0.22, 0.29), (0.27, 0.24), 0.2, 5.0, 200.0).t) == len(paper_move("low").t)


def test_lazy_names_resolve_to_their_home_objects():
    from pm2dof.analysis.experiment import table3
    from pm2dof.bench import run_bench
    assert pm2dof.table3 is table3 and pm2dof.run_bench is run_bench
    with pytest.raises(AttributeError, match="no attribute 'no_such_name'"):
        pm2dof.no_such_name  # noqa: B018


def test_controller_step_refuses_a_wrong_shape():
    m = pm2dof.load_model()
    c = pm2dof.NAController(m)
    q = m.ik([0.245, 0.265])
    c.reset(q[:3])
    with pytest.raises(pm2dof.ArgumentError, match=r"input 'qa' must have shape \(3,\), got shape \(1, 3\)"):
        c.step(q[:3].reshape(1, 3).copy(), np.array([0.245, 0.265]), np.zeros(2), np.zeros(2))


# --------------------------------------------------------------------------------------
# the README and the documentation site (docs/*.md)
# --------------------------------------------------------------------------------------

DOCS = REPO / "docs"
DOC_PAGES = sorted(DOCS.glob("*.md"))


def _blocks(lang, path=README):
    """The fenced ```lang blocks of a Markdown file, dedented (blocks inside list items too)."""
    text = path.read_text()
    return [textwrap.dedent(m.group(1)) for m in re.finditer(rf"```{lang}\n(.*?)```", text, re.S)]


def _run_python_blocks(path):
    """Run a Markdown file's Python blocks in order, in one fresh interpreter; the error."""
    blocks = _blocks("python", path)
    code = "\n".join(f"# --- {path.name} block {k + 1}\n{b}" for k, b in enumerate(blocks))
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO,
                       timeout=300, env={**os.environ, "MPLBACKEND": "Agg"})
    assert r.returncode == 0, f"a Python block of {path.name} fails:\n{r.stderr[-3000:]}"


def test_readme_python_blocks_run():
    assert len(_blocks("python")) >= 1, "the README has lost its Python example"
    _run_python_blocks(README)


@pytest.mark.parametrize("page", [p for p in DOC_PAGES if _blocks("python", p)],
                         ids=lambda p: p.name)
def test_docs_python_blocks_run(page):
    _run_python_blocks(page)


def test_docs_keep_their_examples():
    """The pages' Python examples are not lost silently (the test above runs what it finds)."""
    pages = {p.name: len(_blocks("python", p)) for p in DOC_PAGES}
    for name in ("guide.md", "results-redundancy.md", "study-file.md", "log-format.md",
                 "model-file.md"):
        assert pages.get(name, 0) >= 1, f"docs/{name} has lost its Python example: {pages}"


_PM2DOF_LINE = re.compile(r"^(?:\S*/)?pm2dof\s")   # pm2dof ..., venv/bin/pm2dof ...


def _check_command_lines(path):
    """Every pm2dof command line of a file's sh blocks parses, every make target exists;
    returns the numbers of each seen."""
    from pm2dof.cli import build_parser
    make_targets = set(re.findall(r"^([a-z][\w-]*):", (REPO / "Makefile").read_text(), re.M))
    seen_cli = seen_make = 0
    for block in _blocks("sh", path):
        for line in block.splitlines():
            line = line.split("#")[0].strip()
            if _PM2DOF_LINE.match(line):
                try:
                    build_parser().parse_args(shlex.split(line)[1:])
                except SystemExit as exc:
                    raise AssertionError(f"{path.name}: command does not parse: {line}") from exc
                seen_cli += 1
            elif line.startswith("make "):
                target = shlex.split(line)[1]
                assert target in make_targets, f"{path.name} names a missing make target: {line}"
                seen_make += 1
    return seen_cli, seen_make


def test_readme_command_lines_parse():
    seen_cli, seen_make = _check_command_lines(README)
    assert seen_cli >= 3 and seen_make >= 2, (seen_cli, seen_make)


def test_docs_command_lines_parse():
    seen = {p.name: _check_command_lines(p) for p in DOC_PAGES}
    assert sum(c for c, _ in seen.values()) >= 30, seen
    assert seen["commands.md"][0] >= 10 and seen["commands.md"][1] >= 3, seen["commands.md"]


def test_readme_links_into_the_docs_exist():
    text = README.read_text()
    links = re.findall(r"\]\((docs/[^)#\s]+)", text) + re.findall(r'src="(docs/[^"]+)"', text)
    assert len(links) >= 5, links
    missing = [link for link in links if not (REPO / link).is_file()]
    assert not missing, f"README links to missing files: {missing}"


def test_the_home_page_links_every_page():
    """docs/index.md links every other page of the site (every results page among them)."""
    links = set(re.findall(r"\]\(([\w-]+\.md)", (DOCS / "index.md").read_text()))
    pages = {p.name for p in DOC_PAGES} - {"index.md"}
    assert pages <= links, f"not linked from docs/index.md: {sorted(pages - links)}"
    assert {p for p in pages if p.startswith("results-")} and links <= pages | {"index.md"}


def test_api_page_documents_exactly_all():
    """docs/api.md has one ``::: module.NAME`` per name of pm2dof.__all__ (but __version__),
    and each is the very object pm2dof.NAME."""
    paths = re.findall(r"^::: ([\w.]+)$", (DOCS / "api.md").read_text(), re.M)
    names = [p.rsplit(".", 1)[1] for p in paths]
    assert len(names) == len(set(names)), f"documented twice: {names}"
    assert set(names) == set(pm2dof.__all__) - {"__version__"}, (
        f"missing: {sorted(set(pm2dof.__all__) - set(names) - {'__version__'})}, "
        f"not in __all__: {sorted(set(names) - set(pm2dof.__all__))}")
    for path in paths:
        module, name = path.rsplit(".", 1)
        assert getattr(importlib.import_module(module), name) is getattr(pm2dof, name), path
