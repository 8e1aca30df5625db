# `pm2dof design run/show/pick` end to end, on the analytic stand-in for the objectives.
"""The commands as a user runs them (``pm2dof.cli.main``): ``design run --json`` prints the
contract ``{"objectives": [...], "front": [...]}`` and equals ``design show --json``; a rerun
evaluates nothing; ``--optimizer grid --grid N`` overrides the study's optimiser; ``show``
writes the figures; ``pick`` writes a model file that reads back at the design.

The study file reader and the objectives are stand-ins (tests/synthesis/analytic.py) put in
place of ``pm2dof.synthesis.spec`` and ``.objectives``; the cluster is an in-process one
(threads) in place of the embedded LocalCluster's processes (tests/synthesis/test_runner.py
runs those). The model is the shipped shang2010_design, drawn at each design by
``Model.at_design``."""
import json
import re
import sys
import types

import numpy as np
import pytest

from pm2dof import cli
from pm2dof.core.model_file import read_model_file
from pm2dof.synthesis import runner
from pm2dof.synthesis.front import read_front
from tests.synthesis import analytic

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

BOUNDS = ((0.18, 0.32), (0.18, 0.32))


@pytest.fixture
def stand_ins(monkeypatch):
    made = {}

    def read_design_study(path):
        return analytic.study(name=str(path), bounds=BOUNDS)

    def with_overrides(study, quick=False, optimizer=None, grid=None):
        opt = dict(study.optimizer)
        if quick:
            opt.update(study.quick)
        if optimizer:
            opt["kind"] = optimizer
        if grid:
            opt["grid"] = grid
        made["optimizer"] = opt
        return analytic.study(optimizer=opt, name=study.name, bounds=BOUNDS)

    spec = types.ModuleType("pm2dof.synthesis.spec")
    spec.find_design_study = lambda name: name
    spec.read_design_study = read_design_study
    spec.with_overrides = with_overrides
    objectives = types.ModuleType("pm2dof.synthesis.objectives")
    objectives.evaluate_batch = analytic.evaluate_batch
    objectives.units = lambda study, model: {o.name: "J" for o in study.objectives}
    monkeypatch.setitem(sys.modules, "pm2dof.synthesis.spec", spec)
    monkeypatch.setitem(sys.modules, "pm2dof.synthesis.objectives", objectives)

    def connect(workers=None, scheduler=None, timeout=10.0):
        from distributed import Client, LocalCluster
        cluster = LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                               dashboard_address=":0")
        client = Client(cluster)
        client._pm2dof_owns_cluster = cluster
        made["connects"] = made.get("connects", 0) + 1
        return client

    monkeypatch.setattr(runner, "connect", connect)
    return made


def _main(capsys, *args):
    rc = cli.main(list(map(str, args)))
    out = capsys.readouterr()
    return rc, out.out, out.err


def test_run_json_contract_rerun_show_and_figures(tmp_path, capsys, stand_ins):
    out = tmp_path / "run"
    rc, text, err = _main(capsys, "design", "run", "paper_legs", "--quick", "--out", out,
                          "--json", "--quiet")
    assert rc == 0, err
    assert stand_ins["optimizer"]["generations"] == 3 and stand_ins["connects"] == 1
    got = json.loads(text)
    assert set(got) == {"objectives", "front", "file_design"}
    # the model file's design (the paper's la = lb = 0.244 m), evaluated once and not on the
    # list: ZDT1's front is lb at its bound, which this design is not
    fd = got["file_design"]
    assert fd["design"] == {"la": 0.244, "lb": 0.244} and fd["feasible"]
    assert not fd["on_front"] and fd["dominated_by"] and fd["distance"] > 0
    assert fd["design"] not in [e["design"] for e in got["front"]]
    assert got["objectives"] == [{"name": "f1", "sense": "min"},
                                 {"name": "score", "sense": "max"}]
    assert got == read_front(out).payload() and len(got["front"]) >= 3
    for e in got["front"]:
        assert set(e) == {"design", "objectives"} and set(e["design"]) == {"la", "lb"}
        assert all(lo <= e["design"][v] <= hi for v, (lo, hi) in zip(("la", "lb"), BOUNDS))
    # no design of the front dominates another (f1 min, score max)
    pts = np.array([[e["objectives"]["f1"], -e["objectives"]["score"]] for e in got["front"]])
    for p in pts:
        assert not np.any(np.all(pts <= p, axis=1) & np.any(pts < p, axis=1))
    rc, text, err = _main(capsys, "design", "run", "paper_legs", "--quick", "--out", out,
                          "--quiet")
    assert rc == 0, err
    assert "all were already evaluated, nothing to run" in text and stand_ins["connects"] == 1
    assert "f1 (J) min" in text and "score (J) max" in text       # the table, with units
    assert "the model file's design (la = 0.244 m, lb = 0.244 m): f1 " in text
    assert f"not on the front: dominated by #{fd['dominated_by'][0]}" in text
    assert f"the best of them, #{fd['beaten_most_by']}, is " in text
    rc, text, err = _main(capsys, "design", "show", out, "--json")
    assert rc == 0, err
    assert json.loads(text) == got
    for name in ("front.png", "designs.png"):
        assert (out / "figures" / name).stat().st_size > 10_000, name
        assert f"wrote {out / 'figures' / name}" in err
    rc, text, err = _main(capsys, "design", "show", out, "--draw", 0, len(got["front"]) - 1)
    assert rc == 0, err
    rc, _, err = _main(capsys, "design", "show", out, "--draw", len(got["front"]))
    assert rc == 2 and f"--draw: INDEX must be in 0..{len(got['front']) - 1}" in err


def test_grid_override_and_its_refusals(tmp_path, capsys, stand_ins):
    out = tmp_path / "grid"
    rc, text, err = _main(capsys, "design", "run", "s.toml", "--grid", "12", "--out", out,
                          "--json", "--quiet")
    assert rc == 0, err
    assert stand_ins["optimizer"]["kind"] == "grid"
    front = json.loads(text)["front"]
    # ZDT1's front on the grid: the first variable's 12 values, the second at its bound
    assert [e["design"]["lb"] for e in front] == [0.18] * 12
    np.testing.assert_allclose([e["design"]["la"] for e in front], np.linspace(0.18, 0.32, 12),
                               rtol=0, atol=1e-15)
    rc, _, err = _main(capsys, "design", "run", "s.toml", "--grid", "12", "--optimizer",
                       "nsga2", "--out", tmp_path / "x")
    assert rc == 2 and "--grid sets the grid optimiser's size" in err
    rc, _, err = _main(capsys, "design", "run", "s.toml", "--workers", "2", "--scheduler",
                       "tcp://127.0.0.1:1", "--out", tmp_path / "y")
    assert rc == 2 and "not both" in err
    rc, _, err = _main(capsys, "design", "run", "s.toml", "--quick", "--out", out)
    assert rc == 2 and "another design run" in err


def test_pick_writes_a_model_file_at_the_design(tmp_path, capsys, stand_ins):
    out = tmp_path / "run"
    rc, text, err = _main(capsys, "design", "run", "s.toml", "--grid", "5", "--out", out,
                          "--json", "--quiet")
    assert rc == 0, err
    front = json.loads(text)["front"]
    i = len(front) - 1
    picked = tmp_path / "my_robot.toml"
    rc, text, err = _main(capsys, "design", "pick", out, i, "--out", picked)
    assert rc == 0, err
    assert f"wrote {picked}" in text and "pm2dof derive" in text
    body = picked.read_text()
    assert not re.search(r"^\s*\[design", body, re.M) and "b2x = {" not in body
    assert "# active (proximal) link, m" in body and "# Tables 1-2" in body
    spec = read_model_file(picked)
    want = front[i]["design"]
    assert [leg.la for leg in spec.legs] == [want["la"]] * 3
    assert [leg.lb for leg in spec.legs] == [want["lb"]] * 3
    assert spec.legs[1].base == (0.433, 0.0)                 # b2x not searched: the file's
    fixed = read_model_file(analytic.SHIPPED_MODELS / "shang2010_design.toml")
    assert spec.legs[0].base == fixed.legs[0].base
    np.testing.assert_array_equal(spec.theta_nominal, fixed.theta_nominal)
    rc, _, err = _main(capsys, "design", "pick", out, len(front), "--out", picked)
    assert rc == 2 and f"INDEX must be in 0..{len(front) - 1}" in err


@pytest.mark.parametrize("model, table, values, check", [
    ("prr_point", 'rs = { keys = ["legs.2.rail.start.y", "legs.2.rail.end.y"], '
     'bounds = [0.4, 0.6] }\nlb = { keys = ["legs.1.lb", "legs.2.lb", "legs.3.lb"], '
     'bounds = [0.25, 0.35] }',
     {"rs": 0.52, "lb": 0.31},
     lambda legs: (legs[1].base[1], legs[1].rail_end[1], legs[0].lb, legs[2].lb)
     == (0.52, 0.52, 0.31, 0.31) and legs[1].base[0] == 0.0 and legs[1].rail_end[0] == 0.5),
    ("rrr3_platform", '# a comment inside the table\n'
     'a3y = { keys = ["legs.3.attach.y"], bounds = [0.03, 0.07] }',
     {"a3y": 0.061},
     lambda legs: legs[2].attach == (0.0, 0.061) and legs[0].attach == (-0.0433, -0.025)),
], ids=["prr_point", "rrr3_platform"])
def test_text_at_design_on_rails_and_attachments(tmp_path, model, table, values, check):
    """The text edit on the other designable keys (a rail moved sideways, an attachment
    point), read back as model files: the legs carry the values, everything else of the
    file is the same (TOML-equal)."""
    import tomllib

    from pm2dof.core.paths import SHIPPED_MODELS
    from pm2dof.synthesis.pick import text_at_design
    text = (SHIPPED_MODELS / f"{model}.toml").read_text()
    text = text.replace("\n[nominal]", f"\n[design]\n{table}\n\n[nominal]", 1)
    new, expected = text_at_design(text, values)
    assert tomllib.loads(new) == expected
    assert {k: v for k, v in tomllib.loads(text).items() if k not in ("design", "legs")} == \
        {k: v for k, v in expected.items() if k != "legs"}
    assert "[design]" not in new and "a comment inside the table" not in new
    assert new.count("\n#") == text.count("\n#") - table.count("# ")   # other comments kept
    p = tmp_path / f"{model}.toml"
    p.write_text(new)
    assert check(read_model_file(p).legs)
