# pm2dof identify's outputs, byte for byte as committed (files move, outputs stay).
"""The expected files in ``expected/`` were written by the code before a refactoring moved the
excitation signals into one module (``identification/signals.py``) and made ``identify_log``
return a dataclass; these tests hold every later change to the same bytes. Floating point may
round differently on another machine or install (BLAS, libm): regenerate them there from a
commit known to be right, never from the code under test.

Added since, and checked apart: the log's metadata lines ``actuators``, ``plant_theta`` and
``plant_sha256`` (each leg's actuator, the plant that wrote the log), and the fit JSON's keys
:data:`NEW_FIT_KEYS` (unit-free twins of keys that name a unit, ``units``, where the truth
comes from). Everything else is the committed bytes and values."""
import hashlib
import json
from pathlib import Path

import pm2dof
from pm2dof import cli
from pm2dof.control.plant import theta_truth
from pm2dof.identification.excitation import plant_sha256

HERE = Path(__file__).resolve().parent
EXPECTED = HERE / "expected"
EXAMPLE = HERE.parents[1] / "examples" / "excitation_shang2010.toml"

#: sha256 of the logs `identify excite` wrote before that refactoring (the example's: of the
#: excitation designed again with the monotone barrier)
LOG_SHA256 = {"multisine_2s": "262ca41ad099df55ac9c4821a8c52de40132677ea6337bac24dc8802c6933693",
              "example": "b7c85d43a1fdb861af24ffa513ee11745c0f52a548243327137611bd2443eb43"}


#: fit JSON keys added after the committed file was written
NEW_FIT_KEYS = {"joint_speed_floor", "task_axes", "residual_rms", "units", "truth_from",
                "plant_changed_since_log"}
#: log metadata lines added after the committed logs were written
NEW_META = (b"# actuators = ", b"# plant_theta = ", b"# plant_sha256 = ")


def test_fit_json_of_the_simulated_default_multisine_is_as_committed(capsys):
    assert cli.main(["identify", "fit", "--duration", "2", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert set(out) - NEW_FIT_KEYS == set(json.loads((EXPECTED / "fit_multisine_2s.json")
                                                     .read_text()))
    old = {k: v for k, v in out.items() if k not in NEW_FIT_KEYS}
    assert json.dumps(old, indent=1) + "\n" == (EXPECTED / "fit_multisine_2s.json").read_text()
    assert out["residual_rms"] == out["residual_rms_N"] and out["task_axes"] == ["x", "y"]
    assert out["plant_changed_since_log"] is False


def test_identify_report_is_as_committed(capsys):
    assert cli.main(["identify", "report"]) == 0
    assert capsys.readouterr().out == (EXPECTED / "identify_report.txt").read_text()


def _excite(args, out, capsys):
    """The printed line and the sha256 of the log without the NEW_META lines, which are
    checked here: once each, the leg kinds and the model file's [plant] of the paper's robot."""
    assert cli.main(["identify", "excite", *args, "--out", str(out), "--quiet"]) == 0
    lines = out.read_bytes().splitlines(keepends=True)
    new = [ln for ln in lines if ln.startswith(NEW_META)]
    m = pm2dof.load_model()
    assert [ln.split(b" = ")[0] for ln in new] == [k.rstrip(b" = ") for k in NEW_META]
    assert new[0] == b"# actuators = revolute, revolute, revolute\n"
    assert new[1].decode() == "# plant_theta = " + " ".join(
        f"{n}={float(v)!r}" for n, v in zip(m.param_names, theta_truth(m))) + "\n"
    assert new[2].decode() == f"# plant_sha256 = {plant_sha256(pm2dof.plant_truth(m))}\n"
    old = b"".join(ln for ln in lines if not ln.startswith(NEW_META))
    return capsys.readouterr().out, hashlib.sha256(old).hexdigest()


def test_excite_writes_the_committed_log_of_the_default_multisine(tmp_path, capsys):
    out, sha = _excite(["--duration", "2"], tmp_path / "ms.csv", capsys)
    text = (EXPECTED / "excite_multisine_2s.txt").read_text()
    assert out == text.format(out=tmp_path / "ms.csv") and sha == LOG_SHA256["multisine_2s"]


def test_excite_writes_the_committed_log_of_the_example_excitation(tmp_path, capsys):
    out, sha = _excite(["--excitation", str(EXAMPLE)], tmp_path / "fourier.csv", capsys)
    text = (EXPECTED / "excite_example.txt").read_text()
    assert out == text.format(out=tmp_path / "fourier.csv") and sha == LOG_SHA256["example"]
