"""``pm2dof bench --strict`` exits non-zero when a target is missed; the bench reports the
compiler flags of the library's build record, not pm2dof's defaults."""
import json

import pytest

import pm2dof.bench as bench_pkg
from pm2dof import cli, load_model
from pm2dof.bench import machine as bench_machine
from pm2dof.core import build


def _fake_results(passes):
    targets = {f"t{i}": {"value": 1.0, "target": 1.0, "op": "<=", "unit": "x", "what": "t",
                         "pass": p} for i, p in enumerate(passes)}
    return {"model": "shang2010", "n_legs": 3, "quick": True, "repeats": 1, "notes": {},
            "targets": targets, "machine": {}}


@pytest.mark.parametrize("passes, strict, rc", [
    ((True, True), True, 0),
    ((True, False), True, 1),       # a missed target fails CI
    ((True, False), False, 0),      # without --strict the bench only reports
    ((True, None), True, 0),        # n/a (a baseline not installed) is not a miss
])
def test_strict_exits_non_zero_on_a_missed_target(monkeypatch, capsys, passes, strict, rc):
    monkeypatch.setattr(bench_pkg, "run_bench", lambda *a, **k: _fake_results(passes))
    argv = ["bench", "--quick", "--json"] + ["--strict"] * strict
    assert cli.main(argv) == rc
    out, err = capsys.readouterr()
    json.loads(out)
    assert ("target(s) missed: t1" in err) == (rc == 1)


def test_flags_come_from_the_build_record(tmp_path):
    m = load_model()
    lib = tmp_path / "libx.so"
    lib.write_bytes(b"")
    portable = [f for f in build.FLAGS if f != "-march=native"]
    build.stamp_path(lib).write_text(json.dumps({"compiler": "cc-of-the-wheel",
                                                 "flags": portable}))
    mach = bench_machine.machine(str(lib))
    assert "-march=native" not in mach["compiler_flags"]
    assert mach["compiler_flags"].split()[:len(portable)] == portable
    assert mach["compiler"] == "cc-of-the-wheel" and str(lib) in mach["compiler_flags_source"]
    # the shipped model's library: its own record, whatever it says
    rec = json.loads(build.stamp_path(m.library).read_text())
    assert bench_machine.machine(m.library)["compiler_flags"].startswith(" ".join(rec["flags"]))
    # no record: the flags are unknown, not pm2dof's defaults
    assert bench_machine.machine(str(tmp_path / "libnone.so"))["compiler_flags"] == "unknown"
