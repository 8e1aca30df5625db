# The standalone C example (examples/c): it builds from the generated code alone and tracks as
# the Python rollout does.
"""``make -C examples/c`` compiles ``na_loop.c`` against the shipped generated C with no Python;
run unpaced, its RMSE over the high-speed move equals :func:`pm2dof.simulate`'s to the digits
it prints (same generated steps, same plant, same encoder). Catches a layout change that the
example was not updated for (its parameter vector is written out by hand in C).

The example's own C keeps the Makefile's flags; the generated model C (880 kB) is compiled
here at -O0 with the Makefile's other flags (``GEN_CFLAGS``): 2.5 s instead of 8.5 s of
gcc -O3, the same results (no -ffast-math, -ffp-contract=off: IEEE operations in the same
order at any -O). gcc -O3 -march=native on generated C is what every first use of a user's
model does (tests/core/test_install_paths.py compiles one).
"""
import re
import shutil
import subprocess
from pathlib import Path

import pytest

import pm2dof

pytestmark = pytest.mark.slow     # builds and runs the C example: make test-slow (CI)

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "c"


def _gen_cflags_o0():
    """The Makefile's GEN_CFLAGS, its OPT's -O3 -march=native replaced by -O0 (module
    docstring)."""
    text = (EXAMPLE / "Makefile").read_text()
    var = {k: re.search(rf"^{k}\s*\?=\s*(.*)$", text, re.M)[1].strip()
           for k in ("OPT", "GEN_CFLAGS")}
    assert "-O3 -march=native" in var["OPT"], var
    return var["GEN_CFLAGS"].replace("$(OPT)", var["OPT"].replace("-O3 -march=native", "-O0"))


@pytest.mark.skipif(shutil.which("make") is None, reason="needs make and a C compiler")
def test_c_example_tracks_like_the_python_rollout(tmp_path):
    r = subprocess.run(["make", "-s", "-C", str(EXAMPLE), f"BUILD={tmp_path}", "run",
                        "RUN_ARGS=--no-sleep", f"GEN_CFLAGS={_gen_cflags_o0()}"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    rmse = float(re.search(r"RMSE over the move ([0-9.e+-]+) m", r.stdout)[1])
    m = pm2dof.load_model()
    want = pm2dof.simulate(m, pm2dof.NAController(m), pm2dof.paper_move("high")).rmse
    assert rmse == pytest.approx(want, rel=5e-7), (rmse, want)   # C prints 7 digits
    assert "samples singular 0" in r.stdout
