# Where models and their generated code live: shipped names, user folders, the derive guards.
"""Model references and generated-code folders, and the derive guards.

The full install (wheel and sdist in fresh virtual environments, used from an empty folder) is
``tests/install/smoke.sh`` (``make check-install``, run by CI); these are the in-process parts.
"""
import contextlib
import hashlib
import io
import json
import re
import shutil
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof.core import paths
from pm2dof.core.model_file import read_model_file
from pm2dof.core.paths import SHIPPED_GENERATED, SHIPPED_MODELS
from tests import derivations

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

PAPER = SHIPPED_MODELS / "shang2010.toml"
PM2DOF = [sys.executable, "-m", "pm2dof"]


def _derive(*args, build=False):
    """``pm2dof derive ARGS --no-build`` in-process (``cli.main``; a subprocess would import
    SymPy and CasADi again and derive with a cold SymPy cache, ~2 s more per call); returns
    (exit code, stdout + stderr). The CLI's entry point as a program is checked by the
    subprocess tests below (``models``, ``--version``, ``report``, ``table3``).

    The SymPy derivation of a model file's content is built once per process
    (tests/derivations.py): this module derives the same files (:func:`_robot`'s) several
    times, ~1.3 s each; the rest of ``pm2dof derive`` (checks, CasADi, C, manifest) runs every
    time."""
    from pm2dof import cli
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out), \
            derivations.shared_in_derive():
        rc = cli.main(["derive", *map(str, args), *([] if build else ["--no-build"])])
    return rc, out.getvalue()


@pytest.fixture(scope="module")
def libraries(tmp_path_factory):
    """Compiled libraries kept across this module's tests, by the SHA-256 of their C: the user
    model of :func:`_robot` is the same C in every test, compiled once (the first load, in
    ``test_derive_into_the_default_folder...``) instead of once per test (~8 s of gcc -O3 each).
    ``reuse(gen)`` copies a library built from ``gen``'s C, with its build record, into ``gen``:
    ``load_model`` then finds it fresh by its own check (the record's source hash against the C
    file, :func:`pm2dof.core.build.library_is_fresh`), or compiles if the C differs."""
    from pm2dof.core.build import stamp_path
    store = tmp_path_factory.mktemp("libraries")

    class Libraries:
        def _key(self, gen):
            name = json.loads((gen / "manifest.json").read_text())["model"]
            c = gen / f"{name}.c"
            return name, hashlib.sha256(c.read_bytes()).hexdigest()

        def keep(self, gen):
            name, sha = self._key(gen)
            lib = gen / f"lib{name}.so"
            assert lib.is_file(), f"{lib} was not compiled"
            (store / sha).mkdir(exist_ok=True)
            for f in (lib, stamp_path(lib)):
                shutil.copy2(f, store / sha / f.name)

        def kept(self, gen):
            """The library kept from ``gen``'s C, or None."""
            name, sha = self._key(gen)
            lib = store / sha / f"lib{name}.so"
            return lib if lib.is_file() else None

        def reuse(self, gen):
            name, sha = self._key(gen)
            for f in (store / sha).glob("*") if (store / sha).is_dir() else ():
                shutil.copy2(f, gen / f.name)

    return Libraries()


def _robot(folder, name="myrobot", la="0.246", stem=None):
    """A model file of our own: the paper's with another name and leg 1's active link."""
    text = PAPER.read_text()
    text = text.replace('name = "shang2010"', f'name = "{name}"').replace("la = 0.244", f"la = {la}", 1)
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"{stem or name}.toml"
    path.write_text(text)
    return path


# --- references -----------------------------------------------------------------------------

def test_shipped_models_by_name():
    names = set(paths.shipped_models())
    assert names == {p.stem for p in SHIPPED_MODELS.glob("*.toml")} and "fivebar" in names
    assert pm2dof.load_model().name == "shang2010"
    five = pm2dof.load_model("fivebar")
    assert five.n_legs == 2 and Path(five.generated) == SHIPPED_GENERATED / "fivebar"
    assert paths.resolve_model("fivebar") == SHIPPED_MODELS / "fivebar.toml"


def test_unknown_name_lists_the_shipped_models():
    with pytest.raises(pm2dof.ModelFileError) as info:
        pm2dof.load_model("fivebars")
    msg = str(info.value)
    assert "'fivebars' is neither a shipped model" in msg and "fivebar, fourleg" in msg, msg
    for empty in ("", "  "):        # not the working directory ("Is a directory")
        with pytest.raises(pm2dof.ModelFileError, match="the model is an empty string") as info:
            pm2dof.load_model(empty)
        assert "fivebar, fourleg" in str(info.value)


def test_paths_expand_home_and_are_taken_relative_to_a_given_folder(tmp_path, monkeypatch):
    monkeypatch.setenv("HOME", str(tmp_path))
    assert paths.resolve_model("~/robots/r.toml") == tmp_path / "robots" / "r.toml"
    assert paths.resolve_model("../r.toml", relative_to=tmp_path / "s") == tmp_path / "s" / ".." / "r.toml"
    assert paths.default_generated_dir(tmp_path / "robots" / "r.toml") == \
        tmp_path / "robots" / "generated" / "r"
    assert paths.default_generated_dir(PAPER) == SHIPPED_GENERATED / "shang2010"


def test_cli_models_lists_every_shipped_model_with_its_description():
    r = subprocess.run([*PM2DOF, "models"], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    for name, (path, desc) in paths.shipped_models().items():
        line = next(l for l in r.stdout.splitlines() if l.startswith(name + " "))
        assert desc and desc in line and f"{read_model_file(path).n_legs} legs" in line, line


def test_cli_version_is_the_package_metadata():
    from importlib.metadata import version
    r = subprocess.run([*PM2DOF, "--version"], capture_output=True, text=True, timeout=60)
    assert r.stdout.strip() == f"pm2dof {version('pm2dof')}" == f"pm2dof {pm2dof.__version__}"


# --- your robot, your folder ------------------------------------------------------------------

@pytest.mark.slow      # derives and compiles a model (20 s): make test-slow (CI)
def test_derive_into_the_default_folder_compile_on_first_use_and_load_by_path(tmp_path, capfd,
                                                                               libraries):
    model = _robot(tmp_path / "robots")
    rc, out = _derive(model)
    gen = tmp_path / "robots" / "generated" / "myrobot"
    assert rc == 0 and (gen / "manifest.json").is_file() and (gen / "myrobot.c").is_file(), out
    assert json.loads((gen / "manifest.json").read_text())["model_file"] == "../../myrobot.toml"
    assert not (gen / "libmyrobot.so").exists()          # --no-build: compiled on first use
    with pytest.warns(pm2dof.CompileWarning) as said:
        m = pm2dof.load_model(model)
    assert (gen / "libmyrobot.so").is_file()
    # a warning with the C file's size and an estimate, then one with the time it took; a
    # Python caller filters them (the CLI prints them: the next test), nothing is printed
    lines = [str(w.message) for w in said if w.category is pm2dof.CompileWarning]
    assert len(lines) == 2, lines
    # cut into units compiled side by side (core/csplit.py): the estimate is processor time
    assert re.fullmatch(r"compiling myrobot\.c \(\d\.\d MB of C\) with \S+ -O3 in \d+ units "
                        r"\([^)]*\), \d+ at a time: about \d+ s of processor time, \d+ s on \d+ "
                        rf"idle processors? .* \(first use of the generated code in "
                        rf"{re.escape(str(gen))}\)", lines[0]), lines
    assert re.fullmatch(rf"compiled {re.escape(str(gen))}/libmyrobot\.so in \d+\.\d s",
                        lines[1]), lines
    assert "compil" not in capfd.readouterr().err
    libraries.keep(gen)
    assert Path(m.generated) == gen and m.spec.legs[0].la == 0.246
    q = m.ik([0.25, 0.26])
    assert abs(m.fk(q[:3]) - [0.25, 0.26]).max() < 1e-12
    with warnings.catch_warnings():
        warnings.simplefilter("error", pm2dof.CompileWarning)
        pm2dof.load_model(str(model))                    # a second load compiles nothing
    # the folder moves with its model file: the manifest names it relatively
    shutil.move(tmp_path / "robots", tmp_path / "moved")
    assert pm2dof.load_model(tmp_path / "moved" / "myrobot.toml").name == "myrobot"


@pytest.mark.slow      # derives and compiles a model (15 s): make test-slow (CI)
def test_the_cli_prints_the_compile_on_first_use_as_stage_lines(tmp_path, capfd, monkeypatch,
                                                                libraries):
    """``pm2dof`` turns each CompileWarning into the line it printed before the warnings: the
    C file's size and the estimate, then the time it took. The compiler is a stand-in (CC):
    it copies the library the test above compiled from the same C, or else builds at -O0."""
    from pm2dof import cli
    model = _robot(tmp_path / "robots")
    assert _derive(model)[0] == 0
    gen = tmp_path / "robots" / "generated" / "myrobot"
    kept = libraries.kept(gen)
    cc = tmp_path / "cc.sh"
    cc.write_text('#!/bin/sh\nwhile [ "$1" != "-o" ]; do shift; done\n'
                  f'cp {kept} "$2"\n' if kept else '#!/bin/sh\nexec cc "$@" -O0\n')
    cc.chmod(0o755)
    monkeypatch.setenv("CC", str(cc))
    capfd.readouterr()
    assert cli.main(["report", "--model", str(model)]) == 0
    out, err = capfd.readouterr()
    lines = err.splitlines()
    assert len(lines) == 2 and "myrobot" in out, err
    assert re.fullmatch(rf"pm2dof: compiling myrobot\.c \(\d\.\d MB of C\) with "
                        rf"{re.escape(str(cc))} -O3 in \d+ units \([^)]*\), \d+ at a time: about "
                        rf"\d+ s of processor time, \d+ s on \d+ idle processors? \(16 s per "
                        rf"MB\), longer while other programs use it \(first use of the generated "
                        rf"code in {re.escape(str(gen))}\)", lines[0]), lines
    assert re.fullmatch(rf"pm2dof: compiled {re.escape(str(gen))}/libmyrobot\.so in \d+\.\d s",
                        lines[1]), lines


@pytest.mark.slow      # derives and compiles a model (15 s): make test-slow (CI)
def test_generated_elsewhere_is_named_by_generated(tmp_path, libraries):
    model = _robot(tmp_path)
    rc, out = _derive("--model", model, "--out", tmp_path / "build" / "c")   # --model, as every command
    assert rc == 0, out
    libraries.reuse(tmp_path / "build" / "c")
    with pytest.raises(pm2dof.StaleGeneratedCodeError) as info:
        pm2dof.load_model(model)
    assert f"Run `pm2dof derive {model}`" in str(info.value)
    assert pm2dof.load_model(model, generated=tmp_path / "build" / "c").name == "myrobot"
    r = subprocess.run([*PM2DOF, "report", "--model", str(model), "--generated",
                        str(tmp_path / "build" / "c")], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and "myrobot" in r.stdout, r.stderr


@pytest.mark.slow      # derives and compiles a model (9 s in make test): make test-slow (CI)
def test_derive_says_when_the_compiler_starts_and_how_long_it_took(tmp_path, monkeypatch):
    """The compile of a generated file takes 10 s to minutes (gcc -O3: 16 s per MB on an idle
    processor, more on a busy one), and derive printed nothing between "wrote" and "compiled".
    A stand-in compiler (CC) that writes an empty library and sleeps 1 s: the stage line with
    the file's size and the estimate comes before it, the elapsed time after it."""
    cc = tmp_path / "cc.sh"
    cc.write_text('#!/bin/sh\nwhile [ "$1" != "-o" ]; do shift; done\n: > "$2"\nsleep 1\n')
    cc.chmod(0o755)
    monkeypatch.setenv("CC", str(cc))
    model = _robot(tmp_path / "robots")
    rc, out = _derive(model, build=True)
    assert rc == 0, out
    lines = out.splitlines()
    c_file = tmp_path / "robots" / "generated" / "myrobot" / "myrobot.c"
    size = c_file.stat().st_size
    wrote = next(i for i, line in enumerate(lines) if "] wrote myrobot.c" in line)
    stage = lines[wrote + 1]
    assert re.fullmatch(rf"\[derive +\d+\.\ds\] compiling myrobot\.c \({size / 1e6:.1f} MB of "
                        rf"C\) with {re.escape(str(cc))} -O3 in \d+ units \(\d+ at -O\d(, \d+ at "
                        rf"-O\d)*\), \d+ at a time: about {size * 16e-6:.0f} s of processor time, "
                        rf"\d+ s on \d+ idle processors? \(16 s per MB\), longer while other "
                        rf"programs use it", stage), stage
    done = re.fullmatch(r"\[derive +(\S+)s\] compiled (\S+) in (\S+) s", lines[wrote + 2])
    assert done and done.group(2) == str(c_file.parent / "libmyrobot.so"), lines[wrote + 2]
    assert 1.0 <= float(done.group(3)) <= float(done.group(1)), lines[wrote + 2]


@pytest.mark.slow      # derives a model into a user's folder (3 s): make test-slow (CI)
def test_edited_geometry_names_the_exact_derive_command(tmp_path):
    model = _robot(tmp_path)
    assert _derive(model)[0] == 0
    model.write_text(model.read_text().replace("la = 0.246", "la = 0.2465", 1))
    r = subprocess.run([*PM2DOF, "table3", "--model", str(model)], capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 2 and f"Run `pm2dof derive {model}`" in r.stderr, r.stderr


@pytest.mark.slow      # derives two models four times (4 s): make test-slow (CI)
def test_derive_refuses_a_folder_generated_from_another_model_file(tmp_path):
    """A copied model file that keeps an existing name, derived into that name's
    folder, used to overwrite it silently. Now refused naming both files; --force overrides."""
    pkg = tmp_path / "pkg"                       # the package's layout: models/, generated/<name>/
    original = _robot(pkg / "models", name="shang2010", la="0.244")
    assert _derive(original)[0] == 0
    gen = pkg / "models" / "generated" / "shang2010"
    before = (gen / "shang2010.c").read_bytes()
    copy = _robot(pkg / "models", name="shang2010", la="0.25", stem="copy")
    rc, out = _derive(copy, "--out", gen)
    assert rc == 2 and f"{gen} holds code generated from another model file ({original})" in out \
        and f"not from {copy}" in out and "--force" in out, out
    assert (gen / "shang2010.c").read_bytes() == before
    rc, out = _derive(copy)                      # its own default folder: no collision
    assert rc == 0 and (pkg / "models" / "generated" / "copy" / "shang2010.c").is_file(), out
    rc, out = _derive(copy, "--out", gen, "--force")
    assert rc == 0 and (gen / "shang2010.c").read_bytes() != before, out
    rc, out = _derive(copy, "--out", gen)        # now it is this file's folder: re-deriving is fine
    assert rc == 0, out


def test_derive_never_writes_into_an_installed_package(tmp_path, monkeypatch):
    from pm2dof.derive.run import DeriveError, derive
    monkeypatch.setattr(paths, "in_installed_package", lambda p: True)
    with pytest.raises(DeriveError, match="inside the installed pm2dof package"):
        derive(PAPER, build=False, progress=None)


def test_installed_package_with_a_stale_library_is_never_compiled_into(tmp_path, monkeypatch):
    gen = tmp_path / "shang2010"
    shutil.copytree(SHIPPED_GENERATED / "shang2010", gen,
                    ignore=shutil.ignore_patterns("*.so", "*.so.json"))
    monkeypatch.setattr(paths, "in_installed_package", lambda p: True)
    with pytest.raises(pm2dof.StaleGeneratedCodeError, match="reinstall pm2dof"):
        pm2dof.load_model(generated=gen)
    assert not (gen / "libshang2010.so").exists()


def test_a_missing_extra_is_named(tmp_path):
    code = ("import sys; sys.modules['casadi'] = None\n"   # as if casadi were not installed
            "from pm2dof.cli import main\n"
            f"sys.exit(main(['derive', {str(tmp_path / 'x.toml')!r}]))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert r.returncode == 2
    assert "needs casadi, which is not installed: pip install 'pm2dof[derive]'" in r.stderr, r.stderr


def test_provenance_records_version_model_file_and_generated_folder():
    from pm2dof.infra.results import provenance
    m = pm2dof.load_model("fivebar")
    p = provenance(m)
    assert p["pm2dof"] == pm2dof.__version__ and p["model_shipped"] is True
    assert p["model_file"] == str(SHIPPED_MODELS / "fivebar.toml")
    assert p["generated"] == str(SHIPPED_GENERATED / "fivebar") and p["library"].endswith(".so")


def test_shipped_studies_by_name_and_study_show():
    from pm2dof.studies import SHIPPED_STUDIES, read_study, resolve_study
    s = read_study(resolve_study("robustness"), quick=True)
    assert Path(s.model_path) == PAPER
    r = subprocess.run([*PM2DOF, "study", "show", "gains"], capture_output=True, text=True,
                       timeout=60)
    assert r.stdout == (SHIPPED_STUDIES / "gains.toml").read_text()


@pytest.mark.slow      # derives and compiles a model (15 s): make test-slow (CI)
def test_a_study_names_its_model_and_generated_folder_relative_to_itself(tmp_path, libraries):
    """A study folder holding the model file and its code in a non-default folder: the
    study's `model` and `generated` keys, relative to the study file, are all it needs; the
    whole folder can move."""
    from pm2dof.studies import SHIPPED_STUDIES, read_study, run_chunk
    model = _robot(tmp_path / "proj" / "robot")
    assert _derive(model, "--out", tmp_path / "proj" / "code")[0] == 0
    libraries.reuse(tmp_path / "proj" / "code")
    text = (SHIPPED_STUDIES / "robustness.toml").read_text().replace(
        'model = "shang2010"', 'model = "../robot/myrobot.toml"\ngenerated = "../code"', 1)
    (tmp_path / "proj" / "studies").mkdir()
    (tmp_path / "proj" / "studies" / "s.toml").write_text(text)
    shutil.move(tmp_path / "proj", tmp_path / "moved")
    s = read_study(tmp_path / "moved" / "studies" / "s.toml", quick=True)
    assert s.model_path == str(tmp_path / "moved" / "robot" / "myrobot.toml")
    assert s.generated_path == str(tmp_path / "moved" / "code")
    cols = run_chunk(s, 0)
    assert len(cols["rollout"]) > 0 and np.all(np.isfinite(cols["rmse"]))
    assert read_study("robustness").name == "robustness"       # a shipped study by name


def test_models_copy_creates_the_folder_and_refuses_what_it_cannot_write(tmp_path):
    r = subprocess.run([*PM2DOF, "models", "--copy", "shang2010", str(tmp_path / "robots")],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 0 and (tmp_path / "robots" / "shang2010.toml").is_file(), r.stderr
    (tmp_path / "afile").write_text("")
    r = subprocess.run([*PM2DOF, "models", "--copy", "fivebar", str(tmp_path / "afile" / "zz")],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and r.stderr.startswith("pm2dof: error: cannot write"), r.stderr
    rc, out = _derive("--model", "fivebar", "--out", tmp_path / "afile" / "g")
    assert rc == 2 and "cannot create the output folder" in out and "Traceback" not in out, out
