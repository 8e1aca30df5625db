# The standalone C example (examples/c): it builds from the generated code alone and tracks as
# the Python rollout does.
"""``make -C examples/c`` compiles ``na_loop.c`` against the shipped generated C with no Python;
run unpaced, its RMSE over the high-speed move equals :func:`pm2dof.simulate`'s to the digits
it prints (same generated steps, same plant, same encoder). Catches a layout change that the
example was not updated for (its parameter vector is written out by hand in C).
"""
import re
import shutil
import subprocess
from pathlib import Path

import pytest

import pm2dof

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "c"


@pytest.mark.skipif(shutil.which("make") is None, reason="needs make and a C compiler")
def test_c_example_tracks_like_the_python_rollout(tmp_path):
    r = subprocess.run(["make", "-s", "-C", str(EXAMPLE), f"BUILD={tmp_path}", "run",
                        "RUN_ARGS=--no-sleep"], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    rmse = float(re.search(r"RMSE over the move ([0-9.e+-]+) m", r.stdout)[1])
    m = pm2dof.load_model()
    want = pm2dof.simulate(m, pm2dof.NAController(m), pm2dof.paper_move("high")).rmse
    assert rmse == pytest.approx(want, rel=5e-7), (rmse, want)   # C prints 7 digits
    assert "samples singular 0" in r.stdout
