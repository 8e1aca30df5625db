# Smoke test of an installed pm2dof, run by tests/install/smoke.sh from an empty folder.
"""Checks an installed pm2dof (a wheel in a fresh virtual environment), from an empty folder:

1. it is imported from site-packages, not from a checkout;
2. ``pm2dof table3 --json`` gives the checkout's numbers (byte for byte);
3. a model file written here is derived (``pm2dof derive``), loaded by path, passes the
   fk(ik(x)) round trip and runs a closed loop;
4. editing that model file's geometry makes loading fail, naming ``pm2dof derive``;
5. a study file here, naming that model by a relative path, runs with ``--quick``;
6. the shipped design study ``paper_legs`` runs with ``--quick``, and a design picked from
   its front is derived like a user's model file; the platform's ``rrr4_platform_legs`` runs,
   shows the same front and picks a plain model file;
7. the installed package's files are unchanged (hashes before and after).

Usage: python smoke.py TABLE3_OF_THE_CHECKOUT.json
"""
import hashlib
import json
import re
import subprocess
import sys
from pathlib import Path

import numpy as np

BIN = Path(sys.executable).parent
WORK = Path.cwd()


def pm2dof(*args, check=True):
    r = subprocess.run([str(BIN / "pm2dof"), *args], capture_output=True, text=True, timeout=600)
    if check and r.returncode != 0:
        sys.exit(f"`pm2dof {' '.join(args)}` failed ({r.returncode}):\n{r.stdout}\n{r.stderr}")
    return r


def tree_hashes(root):
    return {str(p.relative_to(root)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(root.rglob("*")) if p.is_file() and "__pycache__" not in p.parts}


def main(checkout_table3):
    import pm2dof as pkg
    package = Path(pkg.__file__).resolve().parent
    assert "site-packages" in package.parts, f"pm2dof imported from {package}, not site-packages"
    before = tree_hashes(package)
    print(f"pm2dof {pkg.__version__} from {package} ({len(before)} files)")
    print(pm2dof("--version").stdout.strip())
    print(pm2dof("models").stdout.splitlines()[0], "...")

    # 2. the paper's experiment: the same numbers as the checkout
    got = pm2dof("table3", "--json").stdout
    want = Path(checkout_table3).read_text()
    assert got == want, f"table3 differs from the checkout's:\n{got}\nvs\n{want}"
    print("table3 --json: identical to the checkout's")

    # 3. a model file of our own, derived here and loaded by path
    text = (package / "models" / "shang2010.toml").read_text()
    assert text.count('name = "shang2010"') == 1 and text.count("la = 0.244") >= 1
    text = text.replace('name = "shang2010"', 'name = "myrobot"')
    text = text.replace("la = 0.244", "la = 0.246", 1)       # leg 1's active link, 2 mm longer
    model_file = WORK / "myrobot.toml"
    model_file.write_text(text)
    out = pm2dof("derive", str(model_file)).stdout
    gen = WORK / "generated" / "myrobot"
    assert (gen / "myrobot.c").is_file() and (gen / "libmyrobot.so").is_file(), out
    m = pkg.load_model(str(model_file))
    assert m.name == "myrobot" and Path(m.generated) == gen, (m, m.generated)
    rng = np.random.default_rng(0)
    t = m.spec.trajectories["high"]
    worst = 0.0
    for x in (np.asarray(t["start"]) + np.asarray(t["end"])) / 2 + rng.uniform(-0.03, 0.03, (50, 2)):
        q = m.ik(x)
        worst = max(worst, float(np.abs(m.fk(q[:m.n_legs]) - x).max()))
    assert worst < 1e-12, worst
    r = pkg.simulate(m, pkg.NAController(m), pkg.paper_move("high"))
    assert np.isfinite(r.rmse) and r.rmse < 1e-3 and r.n_singular == 0, r.rmse
    print(f"myrobot: derived into {gen}; fk(ik(x)) round trip {worst:.1e} m over 50 poses; "
          f"NA on the high-speed move RMSE {r.rmse:.3e} m")

    # 4. an edited geometry makes the generated code stale; the message names the command
    model_file.write_text(text.replace("la = 0.246", "la = 0.247", 1))
    r = pm2dof("table3", "--model", str(model_file), check=False)
    assert r.returncode == 2 and f"pm2dof derive {model_file}" in r.stderr, r.stderr
    print(f"edited model file refused: {r.stderr.strip()[:160]}...")
    model_file.write_text(text)

    # 5. a study file here naming the model by a path relative to itself
    study = pm2dof("study", "show", "robustness").stdout
    study = study.replace('model = "shang2010"', 'model = "myrobot.toml"', 1)
    assert 'model = "myrobot.toml"' in study
    (WORK / "studies").mkdir()
    (WORK / "studies" / "mine.toml").write_text(study.replace('model = "myrobot.toml"',
                                                              'model = "../myrobot.toml"'))
    r = pm2dof("study", "run", "studies/mine.toml", "--quick", "--out", "rob", "--workers", "2",
               "--no-progress")
    rows = json.loads((WORK / "rob" / "study.json").read_text())
    assert rows["rows"] > 0 and Path(rows["provenance"]["model_file"]) == model_file, rows
    print(f"study: {r.stdout.strip()}")

    # 6. a shipped design study, and its pick derived as a user's model file
    r = pm2dof("design", "run", "paper_legs", "--quick", "--out", "legs", "--workers", "1",
               "--json")
    front = json.loads(r.stdout)
    assert front["front"] and [o["name"] for o in front["objectives"]], front
    pm2dof("design", "pick", "legs", "0", "--out", "picked/robot.toml")
    pm2dof("derive", "picked/robot.toml")
    print(f"design: {len(front['front'])} designs on paper_legs' quick front; design 0 derived")
    # ... and the shipped platform study: run, show, pick (a model file without [design])
    r = pm2dof("design", "run", "rrr4_platform_legs", "--quick", "--out", "r4", "--workers",
               "1", "--json")
    front = json.loads(r.stdout)
    assert front["front"] and set(front["front"][0]["design"]) == {"la", "lb"}, front
    shown = pm2dof("design", "show", "r4", "--json")
    assert json.loads(shown.stdout)["front"] == front["front"]
    pm2dof("design", "pick", "r4", "0", "--out", "picked/platform.toml")
    text = (WORK / "picked" / "platform.toml").read_text()
    tables = re.findall(r"^\[(\w+)\]", text, re.M)
    assert "design" not in tables and "platform" in tables, tables
    print(f"design: {len(front['front'])} designs on rrr4_platform_legs' quick front; design 0 "
          f"picked")

    # 7. nothing was written into the installed package
    after = tree_hashes(package)
    changed = sorted(k for k in set(before) | set(after) if before.get(k) != after.get(k))
    assert not changed, f"the installed package changed: {changed[:10]}"
    print(f"installed package unchanged ({len(after)} files)")


if __name__ == "__main__":
    main(sys.argv[1])
