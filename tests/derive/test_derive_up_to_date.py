# `pm2dof derive` on an unchanged model: "up to date" without SymPy or CasADi; --force derives.
"""Re-running ``pm2dof derive`` on an unchanged model re-derived and recompiled
everything (17.8 s). The shipped shang2010's generated folder, copied beside a copy of its
model file, is what ``derive`` would write: the check says so, and names what changed when
something did."""
import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from pm2dof import cli
from pm2dof.core.generated import derive_is_current, derive_sources_sha256
from pm2dof.core.paths import SHIPPED_MODELS

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def copied(tmp_path):
    """tmp/shang2010.toml and tmp/generated/shang2010/ (the shipped code, its manifest naming
    the copy)."""
    model = tmp_path / "shang2010.toml"
    shutil.copy(SHIPPED_MODELS / "shang2010.toml", model)
    gen = tmp_path / "generated" / "shang2010"
    shutil.copytree(ROOT / "pm2dof" / "generated" / "shang2010", gen)
    m = json.loads((gen / "manifest.json").read_text())
    m["model_file"] = "../../shang2010.toml"
    (gen / "manifest.json").write_text(json.dumps(m))
    return model, gen


def test_the_check_hashes_the_derivation_as_the_manifest_does():
    """One hash of the derivation's sources: the one derive writes is the one the check uses."""
    from pm2dof.core import manifest
    from pm2dof.derive import export as written
    assert written.derive_sources_sha256 is manifest.derive_sources_sha256
    assert derive_sources_sha256 is manifest.derive_sources_sha256


def test_unchanged_model_is_up_to_date_without_sympy_or_casadi(copied):
    model, gen = copied
    assert derive_is_current(model) == (gen, True, "")
    code = ("import sys; from pm2dof import cli; assert cli.main(['derive', sys.argv[1]]) == 0; "
            "heavy = {'sympy', 'casadi'} & set(sys.modules); assert not heavy, heavy")
    r = subprocess.run([sys.executable, "-c", code, str(model)], capture_output=True, text=True,
                       env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"})
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == (f"{gen} is up to date (its manifest matches the model file, the "
                                f"derivation and its compiled library); --force derives again")


def test_what_changed_is_named(copied):
    model, gen = copied
    text = model.read_text()
    model.write_text(text + "\n# a comment\n")
    assert derive_is_current(model)[1:] == (False, "the model file changed")
    model.write_text(text)
    (gen / "shang2010.h").write_text((gen / "shang2010.h").read_text() + "\n")
    assert derive_is_current(model)[1:] == (False, "shang2010.h differs from its manifest")
    shutil.copy(ROOT / "pm2dof" / "generated" / "shang2010" / "shang2010.h", gen)
    (gen / "libshang2010.so.json").unlink()                  # the build record
    assert derive_is_current(model)[1:] == (False, "the compiled library is missing or not "
                                                   "built from the C")
    assert derive_is_current(model, library=False)[1:] == (True, "")   # --no-build


def test_force_derives_again(copied, monkeypatch):
    import pm2dof.derive.run as run
    model, gen = copied
    from pm2dof.core import build
    calls, compiled = [], []
    monkeypatch.setattr(run, "derive", lambda *a, **k: calls.append((a, k)) or gen)
    monkeypatch.setattr(build, "compile_library", lambda *a, **k: compiled.append((a, k)))
    assert cli.main(["derive", str(model)]) == 0 and calls == [] and compiled == []
    assert cli.main(["derive", str(model), "--force"]) == 0
    assert len(calls) == 1 and calls[0][1]["force"] is True
    # derive writes the C; the command compiles it, with its stage lines (progress)
    assert calls[0][1]["build"] is False and len(compiled) == 1, compiled
    assert compiled[0][0] == (gen / "shang2010.c", gen / "libshang2010.so")
    assert callable(compiled[0][1]["progress"])
