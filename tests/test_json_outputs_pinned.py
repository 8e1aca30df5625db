# Every command's --json, on every kind of robot, as pinned: code that moves keeps the outputs.
"""The ``--json`` outputs of pm2dof's commands, byte for byte as pinned in
``cli_expected/json/``, on the paper's robot, a platform, linear actuators and gravity.

A change that only moves code (where a fact lives, which layer holds what) must leave every
number and key as it was: these tests say so. What the machine, the checkout or the clock
decides is taken out before comparing (:data:`VOLATILE`): the provenance's paths, git commit,
package versions and machine, and compute times.

The pinned files were written by the code at a commit whose outputs were checked by the rest of
the suite. Floating point may round differently on another install (BLAS, libm): regenerate
them there from a commit known to be right (``PM2DOF_REPIN=1 pytest -m slow
tests/test_json_outputs_pinned.py`` at that commit), never from code under change.
"""
import json
import os
import re
from pathlib import Path

import pytest

from pm2dof import cli

EXPECTED = Path(__file__).resolve().parent / "cli_expected" / "json"

#: provenance entries that depend on the checkout, the install or the machine
VOLATILE = {"model_file", "generated", "library", "git_commit", "python", "numpy", "machine",
            "generated_with", "scipy", "casadi", "sympy", "dask", "pyarrow", "created",
            "hostname", "platform"}
#: keys that hold a measured time
TIMED = re.compile(r"(^|_)(ms|us|elapsed|seconds|wall|compute_s|time_s)$")

#: (id, argv): one case per command and kind; ids name the pinned file
CASES = [
    ("table3_rrr4_platform", ["table3", "--model", "rrr4_platform", "--json"]),
    ("table3_prr3_platform", ["table3", "--model", "prr3_platform", "--json"]),
    ("table3_shang2010_vertical", ["table3", "--model", "shang2010_vertical", "--json"]),
    ("splits_shang2010", ["splits", "--json"]),
    ("splits_rpr3_platform", ["splits", "--model", "rpr3_platform", "--json"]),
    ("plan_shang2010", ["plan", "--path", "pick_and_place", "--tau-max", "6", "--json"]),
    ("plan_shang2010_vertical", ["plan", "--model", "shang2010_vertical", "--path",
                                 "pick_and_place", "--tau-max", "30", "--json"]),
    ("maps_prr3_platform", ["maps", "--model", "prr3_platform", "--resolution", "11",
                            "--json", "--out", "{tmp}"]),
    ("maps_shang2010_vertical", ["maps", "--model", "shang2010_vertical", "--resolution", "11",
                                 "--json", "--out", "{tmp}"]),
    ("identify_fit_rrr3_platform", ["identify", "fit", "--model", "rrr3_platform",
                                    "--duration", "2", "--json"]),
]


def normalise(obj):
    """``obj`` without :data:`VOLATILE` provenance entries and measured times."""
    if isinstance(obj, dict):
        out = {}
        for k, v in obj.items():
            if TIMED.search(k):
                continue
            if k == "provenance" and isinstance(v, dict):
                v = {pk: pv for pk, pv in v.items() if pk not in VOLATILE}
            out[k] = normalise(v)
        return out
    if isinstance(obj, list):
        return [normalise(v) for v in obj]
    return obj


@pytest.mark.slow
@pytest.mark.parametrize("case, argv", CASES, ids=[c for c, _ in CASES])
def test_json_output_is_as_pinned(case, argv, tmp_path, capsys):
    argv = [a.format(tmp=tmp_path / "out") for a in argv]
    assert cli.main(argv) == 0, capsys.readouterr().err
    text = json.dumps(normalise(json.loads(capsys.readouterr().out)), indent=1,
                      sort_keys=True) + "\n"
    text = text.replace(str(tmp_path), "{tmp}")
    pinned = EXPECTED / f"{case}.json"
    if os.environ.get("PM2DOF_REPIN") == "1":
        EXPECTED.mkdir(parents=True, exist_ok=True)
        pinned.write_text(text)
    assert pinned.is_file(), f"{pinned} is missing: pin it at a commit known to be right"
    assert text == pinned.read_text(), f"pm2dof {' '.join(argv)}: --json differs from {pinned}"
