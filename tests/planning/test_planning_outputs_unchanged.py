# `pm2dof plan --json` is the same, number for number, as before the planner's problem object
# and its speed-ups (the grid refined in place): the outputs were saved first.
"""The planner's results, byte for byte, against files written before the refactoring.

tests/planning/data/plan_<case>.json were written by this module's :func:`record` (``python
tests/planning/test_planning_outputs_unchanged.py``) on the commit before the problem object
(``PlanProblem``) and the speed-ups (the grid refined in place). What depends on the run, not on the
plan, is left out: the provenance's machine-, checkout- and command-specific entries and the
wall times (``compute_ms``, ``solve_time_s``). Re-recorded once, on purpose, when the results
gained ``units`` and ``tau_peak`` beside ``tau_peak_N_m`` (efforts by their actuator's unit):
keys added, every earlier key and value unchanged (checked before re-recording)."""
import contextlib
import io
import json
import sys
from pathlib import Path

import pytest

from pm2dof.cli import main
from pm2dof.infra.results import dumps

DATA = Path(__file__).resolve().parent / "data"
#: name -> the arguments of `pm2dof plan` (each with --json)
CASES = {
    "pick_and_place": ["--path", "pick_and_place"],
    "curve": ["--path", "curve"],
    "move_high": ["--move", "high"],
    "move_low_min_max_margin": ["--move", "low", "--split", "min_max", "--tau-max", "8",
                                "--margin", "0.9", "--grid", "300"],
    "move_low_smooth": ["--move", "low", "--smooth"],
}
_RUN = ("model_file", "generated", "library", "git_commit", "command_line", "machine",
        "python", "numpy", "pm2dof", "generated_with")
_WALL = ("compute_ms", "solve_time_s")


def _strip(obj):
    if isinstance(obj, dict):
        return {k: _strip(v) for k, v in obj.items() if k not in _WALL}
    if isinstance(obj, list):
        return [_strip(v) for v in obj]
    return obj


def _output(args, run):
    """The JSON of `pm2dof plan ARGS --json` (``run``: a function of the argv returning its
    stdout) less what depends on the run."""
    res = json.loads(run(["plan", *args, "--json"]))
    res["provenance"] = {k: v for k, v in res["provenance"].items() if k not in _RUN}
    return dumps(_strip(res))


def _stdout(argv):
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        assert main(argv) == 0
    return buf.getvalue()


@pytest.mark.parametrize("case", sorted(CASES))
def test_plan_json_is_unchanged(case):
    want = (DATA / f"plan_{case}.json").read_text()
    assert _output(CASES[case], _stdout) == want


def record():
    """Write the files (run once, before a change that must not change them)."""
    DATA.mkdir(exist_ok=True)
    for case, args in CASES.items():
        (DATA / f"plan_{case}.json").write_text(_output(args, _stdout))
        print("wrote", case, file=sys.stderr)


if __name__ == "__main__":
    record()
