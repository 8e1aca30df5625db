# Table 3 when a run does not complete: printed as such, and valid JSON (no Infinity, no NaN).
import json
import subprocess
import sys

from pm2dof.core.paths import SHIPPED_GENERATED, SHIPPED_MODELS


def test_a_diverging_controller_is_reported_not_hidden(tmp_path):
    """NA with Kd = 1e4 N s/m and torque limits far above the motors' (1e6 N m) is unstable at
    2 ms: its runs leave the workspace. The text table says "failed" and lists why; the JSON is
    valid (the infinite RMSE as null, the RPE as null) with each outcome named."""
    text = (SHIPPED_MODELS / "shang2010.toml").read_text()
    text = text.replace("Kd = [195.0, 195.0]", "Kd = [10000.0, 10000.0]", 1)
    text = text.replace("tau_max = [30.0, 30.0, 30.0]", "tau_max = [1e6, 1e6, 1e6]", 1)
    assert "Kd = [10000.0, 10000.0]" in text and "tau_max = [1e6, 1e6, 1e6]" in text
    path = tmp_path / "unstable.toml"
    path.write_text(text)
    cmd = [sys.executable, "-m", "pm2dof", "table3", "--model", str(path), "--generated",
           str(SHIPPED_GENERATED / "shang2010")]
    r = subprocess.run(cmd + ["--json"], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert "Infinity" not in r.stdout and "NaN" not in r.stdout
    high = json.loads(r.stdout)["high"]
    assert high["na_rmse"] is None and high["rpe_percent"] is None
    assert high["apd_rmse"] > 0                                  # APD is unaffected
    assert high["outcomes"]["na"].startswith(("left_workspace during sample",
                                              "diverged during sample")), high["outcomes"]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    row = next(line for line in r.stdout.splitlines() if line.startswith("high "))
    assert row.split()[2] == "failed" and "n/a" in row, row
    assert "Runs that did not complete (their RMSE is infinite):" in r.stdout
    assert "nan" not in r.stdout.lower().replace("nanny", "")
