# `plan --smooth` says what it does while IPOPT runs, and Ctrl-C stops it as every command: 130.
"""Two findings on a redundant 4-RPR platform: ``plan --smooth --split min_max`` ran 201 s with
no output (stderr not a terminal), and a Ctrl-C during it read as a solver failure,
``IPOPT did not converge (NonIpopt_Exception_Thrown)``, exit 2 (CasADi caught the
KeyboardInterrupt inside IPOPT). Here: the stage lines with stderr a pipe, a line every
LINE_EVERY s while IPOPT iterates, and Ctrl-C at a known iteration (in-process: the progress
callable sends SIGINT from inside IPOPT's iteration callback) and from a terminal (a pty, the
command's exit status and its last line)."""
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof.core.task import orientation_length
from pm2dof.infra.interrupt import noticing_ctrl_c
from pm2dof.planning import watch

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

ROOT = Path(__file__).resolve().parents[2]


def _low(m):
    mv = m.spec.trajectories["low"]
    return pm2dof.TaskPath.line(mv["start"], mv["end"], orientation_length(m))


@pytest.fixture
def sigint_raises():
    """SIGINT as a terminal leaves it (Python's KeyboardInterrupt), whatever started pytest."""
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, before)


@pytest.mark.parametrize("name", ["rrr4_platform", "shang2010_vertical"])
def test_ctrl_c_inside_ipopt_stops_it_as_an_interrupt(name, monkeypatch, sigint_raises):
    """SIGINT at IPOPT's iteration 3: a KeyboardInterrupt naming the iterations, no PlanError
    (it was `IPOPT did not converge (NonIpopt_Exception_Thrown)`), SIGINT's handler restored."""
    monkeypatch.setattr(watch, "LINE_EVERY", 0.0)          # a line at every iteration
    m = pm2dof.load_model(name)
    heard = []

    def progress(msg):
        heard.append(msg)
        if re.search(r": iteration 3, \d+ s$", msg):
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt, match=r"^IPOPT stopped after 3 iterations, "
                                                r"[0-9.]+ s; no smoothed plan$"):
        pm2dof.plan_smooth(m, _low(m), split="min_max", progress=progress)
    its = [int(re.search(r"iteration (\d+)", h).group(1)) for h in heard if "iteration" in h]
    assert its == [0, 1, 2, 3], heard                       # stopped at the iteration after
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    plan = pm2dof.plan_smooth(m, _low(m), split="min_max")  # and the next solve is whole
    assert plan.info["ipopt_status"] == "Solve_Succeeded"


def test_stage_lines_while_ipopt_runs(monkeypatch):
    """Without a bar (not a terminal) a line every LINE_EVERY s: with 0 s, one per iteration,
    counted from IPOPT's 0, then the status and the count."""
    monkeypatch.setattr(watch, "LINE_EVERY", 0.0)
    m = pm2dof.load_model("rrr4_platform")
    heard = []
    plan = pm2dof.plan_smooth(m, _low(m), split="min_max", progress=heard.append)
    n = plan.info["iterations"]
    assert heard[0].startswith(f"smoothing (min_max): IPOPT on {plan.info['grid']} grid points")
    its = [int(re.search(r": iteration (\d+), \d+ s$", h).group(1)) for h in heard[1:-1]]
    assert its == list(range(n + 1)), heard        # IPOPT calls back at iterations 0..n
    assert re.fullmatch(rf"smoothing \(min_max\): IPOPT Solve_Succeeded after {n} iterations, "
                        r"[0-9.]+ s", heard[-1])


def test_plan_smooth_prints_stages_when_stderr_is_not_a_terminal(capsys):
    """The command, stderr not a terminal (as in a log): the path, the size of the problem and
    IPOPT's outcome, on stderr; stdout the report as before; --quiet: nothing on stderr."""
    from pm2dof.cli import main
    assert main(["plan", "--model", "rrr4_platform", "--move", "low", "--smooth", "--split",
                 "min_max"]) == 0
    out, err = capsys.readouterr()
    lines = err.splitlines()
    assert lines[0].startswith("  .. planning low (") and lines[0].endswith(
        "time-optimal with min_max, then smoothed"), lines
    assert re.fullmatch(r"  \.\. smoothing \(min_max\): IPOPT on \d+ grid points, \d+ variables, "
                        r"\d+ constraints \(friction .*\)", lines[1]), lines
    assert re.fullmatch(r"  \.\. smoothing \(min_max\): IPOPT Solve_Succeeded after \d+ "
                        r"iterations, [0-9.]+ s", lines[-1]), lines
    assert "smoothed, min_max" in out and ".." not in out
    assert main(["plan", "--model", "rrr4_platform", "--move", "low", "--smooth", "--split",
                 "min_max", "--quiet"]) == 0
    assert capsys.readouterr().err == ""


def test_ctrl_c_from_a_terminal_exits_130_with_one_line(tmp_path):
    """Ctrl-C on `plan --smooth` from a terminal (a pty: IPOPT's bar drawn there), sent once the
    bar shows an iteration: exit 130, `pm2dof: interrupted (IPOPT stopped after ...)` as the
    last line, no CasADi warning, no traceback, nothing written."""
    import fcntl
    import struct
    import termios
    import time

    from tests.processes import from_a_terminal
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    master, slave = os.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 120, 0, 0))
    out = tmp_path / "out"
    p = subprocess.Popen(from_a_terminal([sys.executable, "-m", "pm2dof", "plan", "--path",
                                          "pick_and_place", "--tau-max", "6", "--smooth",
                                          "--split", "min_max", "--out", out]),
                         stdout=subprocess.PIPE, stderr=slave, text=True, env=env)
    os.close(slave)

    def read():
        try:
            return os.read(master, 65536).decode(errors="replace")
        except OSError:                          # EIO: the command closed its terminal
            return ""
    err, t0 = "", time.monotonic()
    try:
        while not re.search(r"smoothing \(min_max\)[^\r\n]*\b[1-9][0-9]*/1000\b", err):
            chunk = read()
            assert chunk, f"the plan ended before IPOPT iterated: {err}"
            assert time.monotonic() - t0 < 300, err
            err += chunk
        p.send_signal(signal.SIGINT)
        rest = ""
        while chunk := read():
            rest += chunk
        stdout = p.communicate(timeout=300)[0]
    finally:
        p.kill()
        p.wait()
        os.close(master)
    assert p.returncode == 130, (stdout, rest)
    last = rest.strip().splitlines()[-1]
    assert re.fullmatch(r"pm2dof: interrupted \(IPOPT stopped after \d+ iterations, [0-9.]+ s; "
                        r"no smoothed plan\)", last), rest
    assert "WARNING" not in rest and "Traceback" not in rest and "converge" not in rest, rest
    assert stdout == "" and not out.exists()


def test_noticing_ctrl_c_leaves_a_foreign_handler_alone():
    """Where Python does not own SIGINT (here: another handler), nothing is replaced."""
    def mine(signum, frame):
        return None
    before = signal.signal(signal.SIGINT, mine)
    try:
        with noticing_ctrl_c() as hit:
            assert signal.getsignal(signal.SIGINT) is mine and hit == []
        assert signal.getsignal(signal.SIGINT) is mine
    finally:
        signal.signal(signal.SIGINT, before)
    assert np.isfinite(watch.LINE_EVERY) and watch.LINE_EVERY > 0
