# The public API: every name in pm2dof.__all__, old import paths, and the README's code kept honest.
"""The contract with users.

* Every name in ``pm2dof.__all__`` imports from ``pm2dof`` (the lazy ones too) and is the
  object of its home module.
* The names the controllers issue promised exist exactly there (``pm2dof.NAController``...).
* Old module paths of pm2dof 0.1 fail with a ModuleNotFoundError naming the new place.
* The README's Python blocks run, in order, in one namespace (a fresh interpreter); every
  ``pm2dof ...`` command line in its shell blocks parses with the real CLI parser, and every
  ``make`` target it names exists. So the README cannot drift from the code.
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
from pm2dof._moved import MOVED

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
    from pm2dof import (STATUS_NAMES, APDController, NAController, SimResult, line,
                        paper_move, simulate)
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


@pytest.mark.parametrize("old", sorted(MOVED))
def test_old_module_paths_fail_naming_the_new_place(old):
    new, hint = MOVED[old][:2]
    with pytest.raises(ModuleNotFoundError) as info:
        importlib.import_module(old)
    msg = str(info.value)
    assert new in msg and hint in msg, msg
    importlib.import_module(new)  # the new place exists
    hinted = re.match(r"from (\S+) import (.+)$", hint)
    if hinted:  # and the hint is right: what it names imports
        mod = importlib.import_module(hinted.group(1))
        for name in hinted.group(2).split(", "):
            assert hasattr(mod, name.strip()), (hint, name)


def test_old_from_import_form_fails_the_same_way():
    with pytest.raises(ModuleNotFoundError, match=r"pm2dof\.control\.controllers"):
        exec("from pm2dof.controllers import NAController", {})  # noqa: S102
    with pytest.raises(ModuleNotFoundError, match=r"pm2dof\.control\.simulate"):
        exec("from pm2dof.simulate import simulate", {})  # noqa: S102
    assert callable(pm2dof.simulate)  # the failed import did not replace the function


def test_controller_step_refuses_a_wrong_shape():
    m = pm2dof.load_model()
    c = pm2dof.NAController(m)
    q = m.ik([0.245, 0.265])
    c.reset(q[:3])
    with pytest.raises(pm2dof.ArgumentError, match=r"input 'qa' must have shape \(3,\), got shape \(1, 3\)"):
        c.step(q[:3].reshape(1, 3).copy(), np.array([0.245, 0.265]), np.zeros(2), np.zeros(2))


# --------------------------------------------------------------------------------------
# the README
# --------------------------------------------------------------------------------------

def _blocks(lang):
    text = README.read_text()
    return [textwrap.dedent(m.group(1)) for m in re.finditer(rf"```{lang}\n(.*?)```", text, re.S)]


def test_readme_python_blocks_run():
    blocks = _blocks("python")
    assert len(blocks) >= 3, "the README has lost its Python examples"
    code = "\n".join(f"# --- README block {k + 1}\n{b}" for k, b in enumerate(blocks))
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO,
                       timeout=300, env={**os.environ, "MPLBACKEND": "Agg"})
    assert r.returncode == 0, f"a README block fails:\n{r.stderr[-3000:]}"


def test_readme_command_lines_parse():
    from pm2dof.cli import build_parser
    make_targets = set(re.findall(r"^([a-z][\w-]*):", (REPO / "Makefile").read_text(), re.M))
    seen_cli = seen_make = 0
    for block in _blocks("sh"):
        for line in block.splitlines():
            line = line.split("#")[0].strip()
            if line.startswith("pm2dof "):
                try:
                    build_parser().parse_args(shlex.split(line)[1:])
                except SystemExit as exc:
                    raise AssertionError(f"README command does not parse: {line}") from exc
                seen_cli += 1
            elif line.startswith("make "):
                target = shlex.split(line)[1]
                assert target in make_targets, f"README names a missing make target: {line}"
                seen_make += 1
    assert seen_cli >= 3 and seen_make >= 2, (seen_cli, seen_make)
