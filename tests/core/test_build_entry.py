# `make libs`: the Makefile's rule compiles each library through core/build.py run as a file.
"""``make libs`` runs ``python pm2dof/core/build.py SOURCE.c OUT.so`` for every library older
than its C file (the Makefile's LIB_RULE); ``pm2dof`` is the only user's entry point. That file
entry is a few lines without argparse: it compiles, or, for a library built from the same C
(a touched file), only renews the library's time so that make is satisfied."""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BUILD = ROOT / "pm2dof" / "core" / "build.py"


def _entry(*args):
    """``python pm2dof/core/build.py ARGS`` from the checkout, as make runs it."""
    return subprocess.run([sys.executable, str(BUILD), *map(str, args)], capture_output=True,
                          text=True, timeout=120, cwd=ROOT)


def test_the_file_entry_compiles_then_renews_a_fresh_library(tmp_path):
    c = tmp_path / "a.c"
    c.write_text("double twice(double x) { return 2 * x; }\n")
    lib = tmp_path / "liba.so"
    r = _entry(c, lib)
    assert r.returncode == 0 and lib.is_file(), r.stderr
    lines = r.stdout.splitlines()
    assert lines[0].startswith("compiling a.c (0.0 MB of C) with ") and \
        re.fullmatch(rf"compiled {re.escape(str(lib))} in \d+\.\d s", lines[1]), lines
    os.utime(lib, (1, 1))                        # older than its C, as after a checkout
    inode = lib.stat().st_ino
    r = _entry(c, lib)
    assert r.returncode == 0 and r.stdout == f"{lib} is up to date with {c}\n", r.stdout
    assert lib.stat().st_ino == inode and lib.stat().st_mtime > c.stat().st_mtime - 1


def test_the_file_entry_refuses_bad_use(tmp_path):
    r = _entry(tmp_path / "a.c")
    assert r.returncode == 2 and r.stderr == "usage: python pm2dof/core/build.py SOURCE.c OUT.so\n"
    r = _entry(tmp_path / "none.c", tmp_path / "libnone.so")
    assert r.returncode == 1 and r.stderr == f"error: C source not found: {tmp_path / 'none.c'}\n"
    assert "Traceback" not in r.stderr


@pytest.mark.skipif(shutil.which("make") is None, reason="make is not installed")
def test_make_libs_runs_the_file_entry_for_a_library_older_than_its_c():
    """The recipe make libs runs for a shipped model's library whose C is newer (make -n -W: as
    if the C had just changed), run as make would: its library is up to date."""
    c = "pm2dof/generated/fivebar/fivebar.c"
    lib = "pm2dof/generated/fivebar/libfivebar.so"
    r = subprocess.run(["make", "-n", "-W", c, "libs", f"PY={sys.executable}",
                        "STAMP=Makefile"], capture_output=True, text=True, timeout=60, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    recipe = [ln for ln in r.stdout.splitlines() if c in ln]
    # one compiler per library: make -j runs the libraries side by side
    assert recipe == [f"PM2DOF_BUILD_JOBS=1 {sys.executable} pm2dof/core/build.py {c} {lib}"], \
        r.stdout
    env_set, *cmd = recipe[0].split()
    ran = subprocess.run(cmd, capture_output=True, text=True, timeout=60, cwd=ROOT,
                         env={**os.environ, **dict([env_set.split("=")])})
    assert ran.returncode == 0 and ran.stdout == f"{lib} is up to date with {c}\n", ran.stderr


def test_setup_py_loads_the_module_as_a_file_without_running_the_entry(capsys):
    """setup.py loads core/build.py by its path, outside the package (its own Pm2dofError
    stand-in): the module imports, prints nothing and gives what setup.py calls."""
    import importlib.util
    spec = importlib.util.spec_from_file_location("_pm2dof_build", BUILD)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    assert callable(mod.compile_library) and callable(mod.library_is_fresh)
    assert mod.Pm2dofError.__module__ == "_pm2dof_build"          # the stand-in
    assert capsys.readouterr() == ("", "")
