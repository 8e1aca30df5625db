#!/usr/bin/env bash
# The install check (make check-install, CI): the wheel and the sdist of DIST installed into fresh
# virtual environments OUTSIDE the checkout, used from an empty temporary folder.
#   bash tests/install/smoke.sh DIST
set -euo pipefail
dist=$(cd "$1" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
checkout=$(cd "$here/../.." && pwd)
python=${PYTHON:-python3}
wheel=$(ls "$dist"/pm2dof-*.whl)
sdist=$(ls "$dist"/pm2dof-*.tar.gz)
tmp=$(mktemp -d /tmp/pm2dof-install.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
step() { printf '\n[check-install %3ss] %s\n' "$SECONDS" "$*"; }

# the checkout's own answer, to compare with
"$checkout/.venv/bin/pm2dof" table3 --json > "$tmp/table3_checkout.json"

step "wheel $(basename "$wheel") with [derive,studies,design] into a fresh venv"
"$python" -m venv "$tmp/venv"
"$tmp/venv/bin/pip" install --quiet --upgrade pip
"$tmp/venv/bin/pip" install --quiet "$wheel[derive,studies,design]"
mkdir "$tmp/work"
cd "$tmp/work"       # an empty folder, no checkout on the path
PYTHONPATH= "$tmp/venv/bin/python" "$here/smoke.py" "$tmp/table3_checkout.json"

step "sdist $(basename "$sdist") (no extras) into another fresh venv: shipped models, no SymPy/CasADi"
"$python" -m venv "$tmp/venv2"
"$tmp/venv2/bin/pip" install --quiet --upgrade pip
"$tmp/venv2/bin/pip" install --quiet "$sdist"
"$tmp/venv2/bin/pm2dof" table3 --json > "$tmp/table3_sdist.json"
cmp "$tmp/table3_checkout.json" "$tmp/table3_sdist.json"
echo "sdist: pm2dof table3 --json is identical to the checkout's"
if "$tmp/venv2/bin/pm2dof" derive --model "$tmp/work/myrobot.toml" > "$tmp/derive.out" 2>&1; then
    echo "pm2dof derive without the [derive] extra should fail"; exit 1
fi
grep -q "pip install 'pm2dof\[derive\]'" "$tmp/derive.out" || { cat "$tmp/derive.out"; exit 1; }
echo "sdist without extras: pm2dof derive says: $(cat "$tmp/derive.out")"
(cd "$tmp/work" && "$tmp/venv2/bin/pm2dof" demo --out "$tmp/demo" --runs 2 --quiet > "$tmp/demo.out")
grep -q "Robustness study skipped: it needs" "$tmp/demo.out"
test -s "$tmp/demo/results.json" && test -s "$tmp/demo/move_high_na.gif"
echo "sdist without extras: pm2dof demo ran (the robustness study skipped, naming the extra)"
# pm2dof export without the [derive] extra: the generated C is copied, not re-derived. The
# user's model (derived above in the first venv) is exported, built with warnings as errors and
# tested (ctest: the C closed loop equals pm2dof.simulate's); a shipped model is exported too.
"$tmp/venv2/bin/pm2dof" export shang2010 --out "$tmp/export_shang2010" --controllers na,apd
"$tmp/venv2/bin/pm2dof" export "$tmp/work/myrobot.toml" --out "$tmp/export_myrobot"
if command -v cmake > /dev/null; then
    cmake -S "$tmp/export_myrobot" -B "$tmp/export_myrobot/build" -DMYROBOT_PM2DOF_WERROR=ON \
        > /dev/null
    cmake --build "$tmp/export_myrobot/build" -j 2 > /dev/null
    ctest --test-dir "$tmp/export_myrobot/build" --output-on-failure | tail -3
    echo "sdist without extras: pm2dof export of the user's model builds and passes its ctest"
else
    echo "sdist without extras: pm2dof export wrote the projects (no cmake here: not built)"
fi
step "install check passed"
