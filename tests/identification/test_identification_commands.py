# pm2dof identify's sub-commands: one pipeline, files naming their model by path.
"""The command line of identification and the model its files record.

* ``pm2dof identify`` without a sub-command fails with one line naming them (exit 2); each
  sub-command has its own help with an example.
* One pipeline: ``fit`` without a log is the fit of the same simulated log written to a file.
* A log (``excite``) and an excitation file record their model: a shipped model by name, a
  model file by its path relative to themselves. ``fit`` and ``excite`` use it when no
  --model is given, so a folder with the model file, the excitation file and the log can be
  moved; a --model that is not that model is refused naming both.
"""
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof import cli
from pm2dof.core.paths import SHIPPED_GENERATED, SHIPPED_MODELS
from pm2dof.identification.log import IdentLog, read_log, write_log
from pm2dof.identification.signals import load_excitation, write_excitation

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "excitation_shang2010.toml"

NO_SUBCOMMAND = ("pm2dof identify needs a sub-command: report, excite, fit, design or "
                 "monte-carlo (plain `pm2dof identify` was replaced by: pm2dof identify report, "
                 "and pm2dof identify fit)")


def test_identify_without_a_sub_command_names_them(capsys):
    assert cli.main(["identify"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err == f"pm2dof: error: {NO_SUBCOMMAND}\n"


@pytest.mark.parametrize("sub", ["report", "excite", "fit", "design", "monte-carlo"])
def test_every_sub_command_has_its_help_model_options_and_an_example(sub, capsys):
    with pytest.raises(SystemExit) as info:
        cli.main(["identify", sub, "--help"])
    assert info.value.code == 0
    text = capsys.readouterr().out
    assert text.startswith(f"usage: pm2dof identify {sub} ")
    assert "--model NAME|PATH" in text and "--generated DIR" in text
    epilog = text[text.rindex("\nexample"):]
    example = re.search(rf"pm2dof identify {sub}[^\n#]*", epilog)[0].split()
    args = cli.build_parser().parse_args(example[1:])        # the example parses
    assert args.identify_command == sub


def test_the_sub_commands_take_the_model_and_identify_itself_does_not(capsys):
    assert cli.main(["identify", "report", "--model", "fivebar"]) == 0
    assert "rank 9 of 10" in capsys.readouterr().out
    for flag, value in (("--model", "fivebar"), ("--generated", "gen")):
        with pytest.raises(SystemExit) as info:
            cli.main(["identify", flag, value, "report"])
        assert info.value.code == 2
        assert "invalid choice" in capsys.readouterr().err


def test_plain_fit_is_the_fit_of_the_same_log_written_to_a_file(tmp_path, capsys):
    """One pipeline: `fit` without a log (a simulated run) prints the numbers `fit LOG` prints
    for that run's log, bit for bit (JSON holds floats exactly)."""
    assert cli.main(["identify", "fit", "--duration", "3", "--json"]) == 0
    plain = json.loads(capsys.readouterr().out)
    log = tmp_path / "run.csv"
    assert cli.main(["identify", "excite", "--duration", "3", "--out", str(log)]) == 0
    capsys.readouterr()
    assert cli.main(["identify", "fit", str(log), "--json"]) == 0
    from_file = json.loads(capsys.readouterr().out)
    assert plain.pop("log") == "<simulated run of the default 3 s multi-sine>"
    assert from_file.pop("log") == str(log)
    assert plain == from_file
    assert "truth" in plain and len(plain["estimate"]) == 13


def test_fit_refuses_options_of_a_simulated_run_with_a_log(tmp_path, capsys):
    assert cli.main(["identify", "fit", str(tmp_path / "run.csv"), "--duration", "3",
                     "--controller", "apd"]) == 2
    assert capsys.readouterr().err == (f"pm2dof: error: --duration, --controller: options of a "
                                       f"simulated excitation run, which fit runs only without "
                                       f"a LOG (got LOG {tmp_path / 'run.csv'})\n")


# --- a folder of one's own: model file, excitation file, log ---------------------------------

@pytest.fixture
def project(tmp_path):
    """tmp/project/robots/myshang.toml (the paper's model file, copied, with its generated code
    in the default folder beside it) and an empty tmp/project/data/."""
    robots = tmp_path / "project" / "robots"
    (robots / "generated").mkdir(parents=True)
    shutil.copyfile(SHIPPED_MODELS / "shang2010.toml", robots / "myshang.toml")
    shutil.copytree(SHIPPED_GENERATED / "shang2010", robots / "generated" / "myshang")
    (tmp_path / "project" / "data").mkdir()
    return tmp_path / "project"


def _fit(log, capsys, *more):
    code = cli.main(["identify", "fit", str(log), "--json", *more])
    out, err = capsys.readouterr()
    return code, (json.loads(out) if code == 0 else err)


def test_round_trip_with_the_model_taken_from_the_files_then_moved(project, tmp_path, capsys):
    model = pm2dof.load_model(project / "robots" / "myshang.toml")
    exc_file = project / "data" / "exc.toml"
    write_excitation(exc_file, load_excitation(EXAMPLE), model)     # designed for our copy
    assert 'model = "../robots/myshang.toml"' in exc_file.read_text()
    assert load_excitation(exc_file).model["model"] == "../robots/myshang.toml"
    # excite: no --model, the excitation file's; the log records it relative to itself
    log = project / "data" / "run.parquet"
    assert cli.main(["identify", "excite", "--excitation", str(exc_file), "--out", str(log)]) == 0
    capsys.readouterr()
    meta = read_log(log).meta
    assert (meta["model"], meta["model_name"], meta["formulation_sha256"]) == (
        "../robots/myshang.toml", "shang2010", model.spec.formulation_sha256)
    code, first = _fit(log, capsys)
    assert code == 0, first
    # the whole folder moves: the log still finds its model
    shutil.move(project, tmp_path / "elsewhere")
    moved = tmp_path / "elsewhere" / "data" / "run.parquet"
    code, again = _fit(moved, capsys)
    assert code == 0, again
    assert again["estimate"] == first["estimate"] and again["log"] == str(moved)
    # a --model made for another robot is refused, naming both
    code, err = _fit(moved, capsys, "--model", "fivebar")
    assert code == 2 and err.count("\n") == 1, err
    assert ("was written for model 'shang2010' (model ../robots/myshang.toml, formulation "
            f"{model.spec.formulation_sha256[:12]}), not 'fivebar' (" in err), err
    # the same model by another path (here the shipped file, the same formulation) is fine
    assert _fit(moved, capsys, "--model", "shang2010")[0] == 0
    # without its model file the log says which file it needs
    shutil.rmtree(tmp_path / "elsewhere" / "robots")
    code, err = _fit(moved, capsys)
    assert code == 2 and "names its model file '../robots/myshang.toml'" in err, err
    assert str(tmp_path / "elsewhere" / "robots" / "myshang.toml") in err


def test_a_log_written_elsewhere_is_rebased(project, tmp_path, capsys):
    log = project / "data" / "run.csv"
    assert cli.main(["identify", "excite", "--model", str(project / "robots" / "myshang.toml"),
                     "--duration", "3", "--out", str(log)]) == 0
    capsys.readouterr()
    first = read_log(log)
    assert first.meta["model"] == "../robots/myshang.toml"
    copy = write_log(tmp_path / "copies" / "deep" / "run.csv", first)
    assert read_log(copy).meta["model"] == "../../project/robots/myshang.toml"
    assert _fit(copy, capsys)[0] == 0
    # an in-memory log names a model file by its absolute path
    mem = pm2dof.excite(pm2dof.load_model(project / "robots" / "myshang.toml"),
                        pm2dof.paper_move("low"))
    assert mem.meta["model"] == str(project / "robots" / "myshang.toml")


def test_logs_of_before_0_3_that_name_their_model_by_name_alone_are_refused(tmp_path, capsys):
    """Logs written before pm2dof 0.3 recorded `model` (a name) alone: refused with or without
    --model, naming what is missing and what to do (docs/log-format.md); the same log with no
    model entries is a log of the model --model names."""
    m = pm2dof.load_model()
    q = np.array([m.ik(x) for x in pm2dof.paper_move("low").xd])
    for name in ("myrobot", "shang2010"):
        log = IdentLog(t=np.arange(len(q)) * 0.002, qa=q[:, :3], tau=np.zeros((len(q), 3)),
                       meta={"model": name})
        path = write_log(tmp_path / "old.csv", log)
        for extra in ((), ("--model", "shang2010")):
            code, err = _fit(path, capsys, *extra)
            assert code == 2 and err == (
                f"pm2dof: error: {path} records its model by model without model_name, "
                f"formulation_sha256: a file of pm2dof before 0.3, whose format this version "
                f"does not read (it reads files that record all of model, model_name, "
                f"formulation_sha256, or none). Write it again with this pm2dof, or remove its "
                f"model and give --model\n"), (name, extra, err)


def test_a_log_naming_a_model_that_cannot_be_found_is_refused(tmp_path, capsys):
    m = pm2dof.load_model()
    q = np.array([m.ik(x) for x in pm2dof.paper_move("low").xd])
    meta = {"model": "myrobot", "model_name": "myrobot", "formulation_sha256": "ab" * 32}
    log = IdentLog(t=np.arange(len(q)) * 0.002, qa=q[:, :3], tau=np.zeros((len(q), 3)),
                   meta=meta)
    path = write_log(tmp_path / "lost.csv", log)
    code, err = _fit(path, capsys)
    assert code == 2 and err == (f"pm2dof: error: {path} names its model 'myrobot', which is "
                                 f"neither a shipped model nor a model file relative to it: "
                                 f"pass --model with its model file\n")
    code, err = _fit(path, capsys, "--model", "shang2010")
    assert code == 2 and ("was written for model 'myrobot' (model myrobot, formulation "
                          "abababababab), not 'shang2010'") in err


def test_importing_identification_loads_no_heavy_library():
    """SciPy, CasADi and pyarrow are imported inside the functions that need them."""
    code = ("import sys, pm2dof.cli\n"
            "import pm2dof.identification.base, pm2dof.identification.log, "
            "pm2dof.identification.excitation, pm2dof.identification.fit, "
            "pm2dof.identification.consistent, pm2dof.identification.design, "
            "pm2dof.identification.report, pm2dof.identification.jobs, "
            "pm2dof.identification.monte_carlo, "
            "pm2dof.identification.model_ref, pm2dof.identification.signals\n"
            "print(sorted({k.split('.')[0] for k in sys.modules} & {'scipy', 'casadi', "
            "'pyarrow'}))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and r.stdout.strip() == "[]", r.stdout + r.stderr


@pytest.mark.parametrize("args", [
    ["excite", "--out", "x.csv", "--duration", "-1"],
    ["excite", "--out", "x.csv", "--duration", "nan"],
    ["excite", "--out", "x.csv", "--duration", "0"],
    ["excite", "--out", "x.csv", "--duration", "1e9"],
    ["fit", "x.csv", "--time-tolerance", "-1"],
    ["monte-carlo", "0"],
])
def test_bad_numbers_are_usage_errors_naming_the_option(tmp_path, args):
    """A number outside its range is refused by the parser (exit 2, one line naming the option
    and the range), never a traceback or a NaN on screen."""
    r = subprocess.run([sys.executable, "-m", "pm2dof", "identify", *args], cwd=tmp_path,
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and "Traceback" not in r.stderr, r.stderr
    last = r.stderr.strip().splitlines()[-1]
    assert re.search(r"error: argument (--duration|--time-tolerance|N|seeds)", last), last


def test_multisine_refuses_a_bad_duration():
    from pm2dof.identification.signals import multisine
    m = pm2dof.load_model()
    for bad in (-1.0, 0.0, float("nan"), 1e9):
        with pytest.raises(pm2dof.ArgumentError, match="duration must be a number of seconds"):
            multisine(m, duration=bad)


def test_an_excitation_file_lists_every_problem(tmp_path):
    """Read like model and study files (core.validate): every problem at once, each with its key
    (as every input file's); before, the first missing key stopped the reading."""
    from pm2dof.identification.signals import ExcitationError
    text = EXAMPLE.read_text()
    lines = [ln for ln in text.splitlines() if not ln.startswith("b_y")]
    lines = [("periods = 0" if ln.startswith("periods") else
              "a_x = [0.1, nan]" if ln.startswith("a_x") else ln) for ln in lines]
    lines.insert(lines.index("[excitation]") + 1, "speed = 2")
    bad = tmp_path / "bad.toml"
    bad.write_text("\n".join(lines) + "\n")
    with pytest.raises(ExcitationError) as info:
        load_excitation(bad)
    err = info.value
    assert isinstance(err, pm2dof.InputFileError) and err.path == str(bad)
    assert [p.key for p in err.problems] == [
        "excitation.speed", "excitation.b_y", "excitation.periods",
        "excitation.a_x (harmonic 2)"], err.problems
    assert str(err).startswith(f"{bad}: 4 problems:\n  [excitation.speed] unknown key")
    assert "[excitation.b_y] missing (required)" in str(err)
