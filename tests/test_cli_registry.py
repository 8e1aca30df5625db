# The CLI's registry: every command a module with add_parser and run; outputs as before the split.
"""``pm2dof/cli/`` is a registry of command modules. Every command is registered
and its module has ``add_parser`` and ``run``; every module under ``pm2dof/cli/commands/`` is
registered; a command line imports its own command's module only. ``pm2dof table3 --json`` and
every ``--help`` text equal the files in tests/cli_expected/, captured from the CLI before it
was split into modules (a change of them is a change of the command's interface)."""
import importlib
import subprocess
import sys
from pathlib import Path

import pytest

from pm2dof import cli
from pm2dof.cli.commands import COMMANDS

EXPECTED = Path(__file__).resolve().parent / "cli_expected"
COMMANDS_DIR = Path(cli.__file__).resolve().parent / "commands"

#: the command lines whose --help tests/cli_expected/help/ holds (besides `pm2dof --help`)
SUB_COMMANDS = {"identify": ["report", "excite", "fit", "design", "monte-carlo"],
                "study": ["run", "show", "report", "bench"],
                "design": ["run", "show", "pick"]}
HELP_LINES = [[]] + [[c] for c in COMMANDS] + [[c, s] for c, subs in SUB_COMMANDS.items()
                                               for s in subs]


def test_every_command_is_a_registered_module_with_add_parser_and_run():
    files = {p.stem for p in COMMANDS_DIR.glob("*.py")} - {"__init__"}
    assert files == set(COMMANDS), "a module under pm2dof/cli/commands/ is not registered"
    for name, module in COMMANDS.items():
        assert module == f"pm2dof.cli.commands.{name}"
        mod = importlib.import_module(module)
        assert callable(mod.add_parser) and callable(mod.run), name
    parser = cli.build_parser()
    sub = next(a for a in parser._actions if a.dest == "command")
    assert list(sub.choices) == list(COMMANDS)
    assert [a.dest for a in sub._choices_actions] == list(COMMANDS)   # each one listed with help
    for name, p in sub.choices.items():
        assert p.get_default("func") is importlib.import_module(COMMANDS[name]).run, name


def test_every_help_file_is_a_command_line_here():
    names = {"_".join(["pm2dof", *line]).replace("-", "_") for line in HELP_LINES}
    assert names == {p.stem for p in (EXPECTED / "help").glob("*.txt")}


@pytest.mark.parametrize("line", HELP_LINES, ids=lambda line: " ".join(line) or "pm2dof")
def test_help_text_is_unchanged(line, capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")        # argparse wraps to the terminal's width
    with pytest.raises(SystemExit) as stop:
        cli.main([*line, "--help"])
    assert stop.value.code == 0
    name = "_".join(["pm2dof", *line]).replace("-", "_")
    assert capsys.readouterr().out == (EXPECTED / "help" / f"{name}.txt").read_text()


def test_table3_json_is_unchanged(capsys):
    assert cli.main(["table3", "--json"]) == 0
    out = capsys.readouterr().out
    assert out == (EXPECTED / "table3.json").read_text()


def test_a_command_line_imports_its_own_command_module_only():
    """`pm2dof report ...` builds the report command's parser alone (the others stay choices),
    so a command starts without importing the other commands, and `pm2dof --help` without
    importing a layer above infra."""
    code = ("import sys; from pm2dof.cli import build_parser\n"
            "p = build_parser('report'); p.parse_args(['report', '--model', 'fivebar'])\n"
            "print(sorted(m for m in sys.modules if m.startswith('pm2dof.cli.commands.')))\n"
            "build_parser()\n"
            "print(sorted({m.split('.')[1] for m in sys.modules if m.startswith('pm2dof.')}))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    own, layers = r.stdout.splitlines()
    assert own == "['pm2dof.cli.commands.report']"
    assert not set(eval(layers)) & {"analysis", "identification", "planning", "studies",
                                     "figures", "derive", "export"}, layers
