# `pm2dof export --embedded`: the Cortex-M check as an option of the one CLI (what make embedded runs).
"""``make embedded`` runs ``pm2dof export --embedded --out DIR``; the check itself
(:func:`pm2dof.export.embedded.run_embedded`) is run by ``make embedded`` in CI (minutes: four
cross-compiles and QEMU). Here: the Makefile's recipe is that command line, the options it
cannot take are refused by name, missing tools are a typed error naming them, and the module has
no entry point of its own."""
import re
from pathlib import Path

from pm2dof import cli
from pm2dof.cli import build_parser
from pm2dof.export import embedded

ROOT = Path(__file__).resolve().parents[2]


def test_make_embedded_runs_the_cli():
    recipe = [ln.strip() for ln in (ROOT / "Makefile").read_text().splitlines()
              if "bin/pm2dof export" in ln]
    assert recipe == ["$(VENV)/bin/pm2dof export $(MODEL) --embedded --out $(EMBEDDED_OUT)"], recipe
    args = build_parser().parse_args(["export", "--embedded", "--out", "build/embedded"])
    assert args.embedded and args.out == "build/embedded" and args.path is None
    assert not hasattr(embedded, "main")
    assert not re.search(r"^import argparse|__main__", Path(embedded.__file__).read_text(), re.M)


def test_options_of_one_project_are_refused_with_embedded(tmp_path, capsys):
    for extra in (["--precision", "single"], ["--controllers", "na"], ["--move", "low"],
                  ["--force"], ["--generated", str(tmp_path)]):
        assert cli.main(["export", "--embedded", "--out", str(tmp_path / "e"), *extra]) == 2
        err = capsys.readouterr().err
        assert err.startswith("pm2dof: error: --embedded exports both precisions") and \
            f"{extra[0]} cannot be given with it" in err and err.count("\n") == 1, err
    assert not (tmp_path / "e").exists()


def test_missing_tools_are_named_before_any_work(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("PATH", str(tmp_path / "nothing"))
    assert cli.main(["export", "rrr3_platform", "--embedded", "--out", str(tmp_path / "e")]) == 2
    err = capsys.readouterr().err
    assert err == ("pm2dof: error: pm2dof export --embedded needs arm-none-eabi-gcc, "
                   "arm-none-eabi-size, arm-none-eabi-nm, arm-none-eabi-readelf, qemu-system-arm: "
                   "apt-get install "
                   "gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm (Debian)\n"), err
    assert not (tmp_path / "e").exists()
