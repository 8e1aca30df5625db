# bench/build_time.py: pm2dof derive of the 4-RRR platform beside gcc on the paper robot's C.
"""The build row of ``pm2dof bench``: the two commands back to back in alternating order, the
ratio the median of the rounds' ratios (with stand-in timings), and one real round (slow)."""
import sys

import pytest

from pm2dof.bench import build_time
from pm2dof.core import build
from pm2dof.core.paths import SHIPPED_GENERATED


def test_rounds_alternate_and_the_ratio_is_the_median_of_the_rounds(monkeypatch):
    calls = []
    walls = {"derive": iter([30.0, 24.0, 27.0]), "gcc": iter([10.0, 20.0, 9.0])}

    def fake(cmd, cwd, env=None):
        what = "derive" if cmd[:4] == [sys.executable, "-m", "pm2dof", "derive"] else "gcc"
        calls.append((what, cmd, env))
        return next(walls[what]), 1.0 if what == "gcc" else 2.0

    monkeypatch.setattr(build_time, "_timed", fake)
    said = []
    res = build_time.build_bench(3, said.append)
    assert [c[0] for c in calls] == ["gcc", "derive", "derive", "gcc", "gcc", "derive"]
    assert len(said) == 6
    derive = next(c for c in calls if c[0] == "derive")
    assert derive[1][4].endswith(f"{build_time.DERIVED_MODEL}.toml")
    assert {"--force", "--quiet"} <= set(derive[1])
    gcc = next(c for c in calls if c[0] == "gcc")[1]
    assert gcc[-len(build.LIBS) - 1] == str(SHIPPED_GENERATED / "shang2010" / "shang2010.c")
    assert gcc[len(build._compiler()):][:len(build.FLAGS)] == list(build.FLAGS)
    # the ratio: median of 3.0, 1.2, 3.0 (not the ratio of the medians, 27 / 10)
    assert res["derive_rrr4_over_gcc_paper"] == 3.0
    assert res["derive_rrr4_s"] == 27.0 and res["gcc_paper_s"] == 10.0
    assert res["derive_rrr4_cpu_s"] == 2.0 and res["gcc_paper_cpu_s"] == 1.0
    assert res["derive_rrr4_cpu_over_gcc_paper_cpu"] == 2.0
    assert res["build_rounds"] == [[30.0, 10.0], [24.0, 20.0], [27.0, 9.0]]
    assert res["build_jobs"] == build.build_jobs()


def test_a_failed_command_says_which_and_why(tmp_path):
    with pytest.raises(RuntimeError, match="no-such-file.c"):
        build_time._timed([*build._compiler(), "-c", "no-such-file.c"], tmp_path)


@pytest.mark.slow
def test_one_real_round():
    pytest.importorskip("sympy")
    pytest.importorskip("casadi")
    res = build_time.build_bench(1)
    (d, g), = res["build_rounds"]
    assert res["derive_rrr4_over_gcc_paper"] == pytest.approx(d / g)
    assert d > 1.0 and g > 1.0 and res["derive_rrr4_cpu_s"] > res["gcc_paper_cpu_s"] > 0
