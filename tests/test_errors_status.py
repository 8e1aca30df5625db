# One error base (Pm2dofError) and one definition of the status codes.
"""* Every typed error of pm2dof derives from :class:`pm2dof.Pm2dofError` and keeps its builtin
  base; the CLI prints a Pm2dofError as one line (exit 2) and lets any other exception show its
  traceback (a bug must look like a bug).
* :class:`pm2dof.Status` is the only definition of the status codes: the derivation, the NumPy
  reference and the manifests use it, and a manifest with other codes is refused at load.
"""
import importlib
import inspect
import json
import shutil
import subprocess
import sys

import pytest

import pm2dof
from pm2dof.core.paths import SHIPPED_GENERATED

BUILTIN = (ValueError, TypeError, RuntimeError, OSError, ImportError)
MODULES = ["pm2dof.core.errors", "pm2dof.core.build", "pm2dof.control.trajectory",
           "pm2dof.studies.spec", "pm2dof.studies.store", "pm2dof.studies.runner",
           "pm2dof.identification.log", "pm2dof.identification.signals", "pm2dof.derive.run",
           "pm2dof.planning.pathfile", "pm2dof.analysis.reference_file",
           "pm2dof.synthesis.spec", "pm2dof.synthesis.runner", "pm2dof.synthesis.store"]


def _error_classes():
    for name in MODULES:
        mod = importlib.import_module(name)
        for obj in vars(mod).values():
            if (inspect.isclass(obj) and issubclass(obj, Exception) and obj.__module__ == name
                    and not issubclass(obj, Warning)):
                yield obj


def test_every_typed_error_is_a_pm2dof_error_with_a_builtin_base():
    classes = list(_error_classes())
    assert len(classes) >= 20, [c.__name__ for c in classes]
    bad = [c.__name__ for c in classes
           if not (issubclass(c, pm2dof.Pm2dofError) and issubclass(c, BUILTIN))
           and c is not pm2dof.Pm2dofError]
    assert not bad, f"not a Pm2dofError with a builtin base: {bad}"


def test_every_error_of_a_users_input_file_is_an_input_file_error():
    """One family: each lists the file's problems (``.problems``, ``.path``). A
    TrajectoryError is not in it: it refuses a request (a limit, a period, a move's name), and
    only its ReferenceFileError, raised for a file, is."""
    from pm2dof.analysis.reference_file import ReferenceFileError
    from pm2dof.identification.log import LogError
    from pm2dof.identification.signals import ExcitationError
    from pm2dof.planning.pathfile import PathFileError
    from pm2dof.studies import StudyFileError
    for cls in (pm2dof.ModelFileError, StudyFileError, PathFileError, LogError, ExcitationError,
                ReferenceFileError):
        assert issubclass(cls, pm2dof.InputFileError), cls.__name__
    assert not issubclass(pm2dof.TrajectoryError, pm2dof.InputFileError)
    assert issubclass(ReferenceFileError, pm2dof.TrajectoryError)


def test_public_errors_are_exported():
    for name in pm2dof.__all__:
        obj = getattr(pm2dof, name)
        if inspect.isclass(obj) and issubclass(obj, Exception) and not issubclass(obj, Warning):
            assert issubclass(obj, pm2dof.Pm2dofError), name


def _cli(*code):
    return subprocess.run([sys.executable, "-c", "\n".join(code)], capture_output=True,
                          text=True, timeout=120)


def test_cli_prints_a_typed_error_as_one_line():
    r = subprocess.run([sys.executable, "-m", "pm2dof", "table3", "--model", "nosuchmodel"],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 2 and r.stdout == ""
    assert r.stderr.count("\n") == 1 and r.stderr.startswith("pm2dof: error: 'nosuchmodel'")


def test_cli_shows_the_traceback_of_a_bug():
    """A ValueError that is not a Pm2dofError (here: planted in the report) is a bug: the CLI
    must not pass it off as a user error."""
    r = _cli("import sys, pm2dof.analysis.report as rep",
             "def boom(m): raise ValueError('planted bug')",
             "rep.model_report = boom",
             "from pm2dof.cli import main",
             "sys.exit(main(['report']))")
    assert r.returncode == 1, r.stderr
    assert "Traceback (most recent call last)" in r.stderr and "ValueError: planted bug" in r.stderr


def test_binding_refusals_reach_the_user_typed():
    m = pm2dof.load_model()
    with pytest.raises(pm2dof.ArgumentError, match=r"input 'q' \(#0\) has a non-finite value"):
        m.W([0.1, float("nan"), 0, 0, 0, 0])
    with pytest.raises(pm2dof.ArgumentTypeError, match="input 'xe' must be an array of 2 real"):
        m.ik(["a", "b"])
    with pytest.raises(pm2dof.NonFiniteError, match="not finite"):
        m.Me(m.ik([0.245, 0.265]), [1e308] * 15)


def test_status_is_the_one_definition():
    from pm2dof.derive.controllers import STATUS as derived
    from pm2dof.reference.control import STATUS as reference
    assert derived == reference == pm2dof.Status.codes()
    assert pm2dof.STATUS_NAMES == {int(s): s.label for s in pm2dof.Status}
    for name in ("shang2010", "fivebar", "fourleg"):
        m = pm2dof.load_model(name)
        assert dict(m.manifest["status_codes"]) == pm2dof.Status.codes()


def test_a_manifest_with_other_status_codes_is_refused(tmp_path):
    gen = tmp_path / "g"
    shutil.copytree(SHIPPED_GENERATED / "shang2010", gen)
    man = json.loads((gen / "manifest.json").read_text())
    man["status_codes"]["singular"], man["status_codes"]["saturated"] = 2, 1
    (gen / "manifest.json").write_text(json.dumps(man))
    with pytest.raises(pm2dof.StaleGeneratedCodeError, match="status codes"):
        pm2dof.load_model(generated=gen)


def test_simresult_counts_by_status_name():
    m = pm2dof.load_model()
    r = pm2dof.simulate(m, pm2dof.NAController(m, tau_max=[6.0] * 3), pm2dof.paper_move("high"))
    assert r.n_saturated == r.count(pm2dof.Status.SATURATED) == r.count("saturated") > 0
    assert r.n_inconsistent_encoders == 0 and r.n_singular == 0
    total = sum(r.count(s) for s in pm2dof.Status)
    assert total == len(r.status)
