# The design study file: what it reads, the problems it names (all at once), the overrides.
import dataclasses
import pickle

import pytest

import pm2dof
from pm2dof.core.design import Design
from pm2dof.core.paths import SHIPPED_MODELS
from pm2dof.synthesis import objectives as obj
from pm2dof.synthesis.spec import (
    DesignStudyError,
    find_design_study,
    read_design_study,
    shipped_design_studies,
    with_overrides,
)

FULL = '''
[study]
name = "full"
description = "every section"
model = "shang2010"
[task]
region = { x = [0.2, 0.29], y = [0.22, 0.31], n = 9 }
paths = ["curve"]
[[objectives]]
measure = "dexterity_mean"
[[objectives]]
name = "t_high"
measure = "duration"
path = "high"
split = "min_norm"
tau_max = [20.0, 20.0, 25.0]
[[constraints]]
measure = "margin"
paths = ["curve", "low"]
ge = 0.02
[[constraints]]
name = "rmse_na"
measure = "rmse"
law = "na"
path = "curve"
Kd = [150.0, 150.0]
Gamma_scale = 0.0
le = 1e-3
[optimizer]
population = 12
seed = 7
[quick]
population = 4
generations = 1
n = 5
'''


def _write(tmp_path, text, name="s.toml"):
    p = tmp_path / name
    p.write_text(text)
    return p


def _problems(tmp_path, text, **kw):
    with pytest.raises(DesignStudyError) as e:
        read_design_study(_write(tmp_path, text), **kw)
    return {str(p.key): p.reason for p in e.value.problems}


def test_a_full_file(tmp_path):
    s = read_design_study(_write(tmp_path, FULL), check_design=False)
    assert s.name == "full" and s.description == "every section"
    assert s.model_path == str((SHIPPED_MODELS / "shang2010.toml").resolve())
    assert s.variables == () and s.bounds == ()
    assert dict(s.region) == {"x": (0.2, 0.29), "y": (0.22, 0.31), "n": 9, "phi": None,
                              "n_phi": 1}
    assert len(s.paths) == 1 and s.paths[0].endswith("planning/shipped/curve.toml")
    dex, t = s.objectives
    assert (dex.name, dex.measure, dex.sense, dict(dex.options)) == \
        ("dexterity_mean", "dexterity_mean", "max", {})
    assert (t.name, t.sense, dict(t.options)) == \
        ("t_high", "min", {"path": "high", "split": "min_norm", "tau_max": (20.0, 20.0, 25.0)})
    margin, rmse = s.constraints
    assert (margin.op, margin.limit, margin.sense) == ("ge", 0.02, "")
    assert margin.options["paths"] == ("curve", "low")
    assert (rmse.op, rmse.limit) == ("le", 1e-3)
    assert dict(rmse.options) == {"law": "na", "path": "curve", "Kd": (150.0, 150.0),
                                  "Gamma_scale": 0.0}
    assert dict(s.optimizer) == {"kind": "nsga2", "population": 12, "generations": 30,
                                 "grid": 11, "seed": 7}
    assert dict(s.quick) == {"population": 4, "generations": 1, "n": 5}
    import hashlib
    assert s.file_sha256 == hashlib.sha256(FULL.encode()).hexdigest()
    with pytest.raises(dataclasses.FrozenInstanceError):
        s.name = "x"
    with pytest.raises(TypeError):
        s.optimizer["seed"] = 1
    with pytest.raises(TypeError):
        s.objectives[1].options.update(split="min_max")
    again = pickle.loads(pickle.dumps(s))          # sent as is to the workers
    assert again == s and hash(again) == hash(s)
    assert type(again.objectives[1].options) is type(s.objectives[1].options)
    # the file's objectives run on the model
    values, status = obj.evaluate_with_status(pm2dof.load_model("shang2010"), s)
    assert status == "ok" and set(values) == {"dexterity_mean", "t_high", "margin", "rmse_na"}


def test_every_problem_at_once(tmp_path):
    text = '''
extra = 1
[study]
name = "bad"
model = "shang2010"
colour = "red"
[task]
region = { x = [0.3, 0.2], y = [0.2, 0.3], n = 1, phi = [0.0, 0.1] }
paths = ["no_such_path"]
[[objectives]]
measure = "dexterity"
[[objectives]]
measure = "duration"
split = "fastest"
[[objectives]]
name = "d"
measure = "duration"
path = "nowhere"
sense = "up"
[[objectives]]
name = "d"
measure = "force"
path = "high"
[[constraints]]
measure = "margin"
[[constraints]]
name = "r"
measure = "rmse"
path = "high"
Kd = 5.0
[[constraints]]
name = "r2"
measure = "rmse"
law = "apd"
path = "high"
Kd = 5.0
le = 1.0
[optimizer]
kind = "ga"
population = 1
[quick]
draws = 3
'''
    found = _problems(tmp_path, text, check_design=False)
    want = {
        "extra": "unknown key",
        "study.colour": "unknown key",
        "task.region.x": "empty range [0.3, 0.2]",
        "task.region.n": "must be >= 2, got 1",
        "task.region.phi": "point end effector",
        "task.paths (entry 1)": "no shipped path named 'no_such_path'",
        "objectives.measure (entry 1)": "must be one of",
        "objectives.split (entry 2)": "must be one of ['min_max', 'min_norm'], got 'fastest'",
        "objectives.path (entry 2)": "missing (required by 'duration')",
        "objectives.path (entry 3)": "'nowhere' is neither a path of [task] paths",
        "objectives.sense (entry 3)": "must be one of ['max', 'min'], got 'up'",
        "objectives.name (entry 4)": "'d' is used twice",
        "objectives.path (entry 4)": "unknown key",
        "constraints (entry 1)": "give exactly one of ge = <limit>",
        "constraints.law (entry 2)": "missing (required by 'rmse')",
        "constraints (entry 2)": "give exactly one of ge",
        "constraints.Kd (entry 3)": "unknown key",
        "optimizer.population": "must be >= 2, got 1",
        "optimizer.kind": "'ga' optimises one objective",
        "quick.draws": "unknown key",
    }
    for key, reason in want.items():
        assert key in found and reason in found[key], (key, found.get(key), found)
    with pytest.raises(DesignStudyError) as e:
        read_design_study(_write(tmp_path, text), check_design=False)
    assert str(e.value).startswith(f"{tmp_path / 's.toml'}: ")
    assert isinstance(e.value, pm2dof.InputFileError) and isinstance(e.value, ValueError)
    again = pickle.loads(pickle.dumps(e.value))
    assert again.problems == e.value.problems


def test_file_level_problems(tmp_path):
    assert "not valid TOML" in _problems(tmp_path, "[study\n")["None"]
    with pytest.raises(DesignStudyError, match="cannot read the design study file"):
        read_design_study(tmp_path / "missing.toml")
    found = _problems(tmp_path, '[study]\nname = "x"\nmodel = "no_such_model"\n'
                                '[[objectives]]\nmeasure = "link_length"\n')
    assert "neither a shipped model" in found["study.model"]
    found = _problems(tmp_path, 'objectives = []\n[study]\nname = "x"\nmodel = "shang2010"\n')
    assert "at least one" in found["objectives"]
    found = _problems(tmp_path, '[study]\nname = "x"\nmodel = "shang2010"\n')
    assert found["objectives"] == "missing (required)"
    found = _problems(tmp_path, '[study]\nname = "x"\nmodel = "shang2010"\n'
                                '[[objectives]]\nmeasure = "force"\n'
                                '[[objectives]]\nmeasure = "moving_mass"\n', check_design=False)
    assert "give [task] region" in found["objectives (entry 1)"]
    assert "lumped inertia only" in found["objectives.measure (entry 2)"]


class _WithDesign:
    """A ModelSpec with a [design] table (la, lb tied over 3 legs) over a fixed file."""

    def __init__(self, spec):
        self._spec = spec
        self.design = Design(names=("la", "lb"),
                             keys=(tuple((i, "la", None) for i in range(3)),
                                   tuple((i, "lb", None) for i in range(3))),
                             labels=(tuple(f"legs.{i + 1}.la" for i in range(3)),
                                     tuple(f"legs.{i + 1}.lb" for i in range(3))),
                             bounds=((0.18, 0.32), (0.18, 0.32)), values=(0.244, 0.244),
                             default=(0.244, 0.244), signs=(1, 1))

    def __getattr__(self, k):
        return getattr(self._spec, k)


@pytest.fixture
def designed(monkeypatch):
    """read_model_file gives shang2010 a [design] table (until the design model ships)."""
    import pm2dof.core.model_file as mf
    real = mf.read_model_file
    monkeypatch.setattr(mf, "read_model_file", lambda p: _WithDesign(real(p)))


BASE = ('[study]\nname = "v"\nmodel = "shang2010"\n{extra}\n'
        '[[objectives]]\nmeasure = "link_length"\n'
        '[[objectives]]\nmeasure = "duration"\npath = "high"\n')


def test_variables_and_bounds(tmp_path, designed):
    s = read_design_study(_write(tmp_path, BASE.format(extra="")))
    assert s.variables == ("la", "lb") and s.bounds == ((0.18, 0.32), (0.18, 0.32))
    s = read_design_study(_write(tmp_path, BASE.format(
        extra='variables = ["lb"]\nbounds = { lb = [0.2, 0.3] }')))
    assert s.variables == ("lb",) and s.bounds == ((0.2, 0.3),)
    found = _problems(tmp_path, BASE.format(
        extra='variables = ["lb", "b2x"]\nbounds = { lb = [0.1, 0.3], la = [0.2, 0.3] }'))
    assert "'b2x' is not a design variable" in found["study.variables"]
    assert "outside the model file's bounds [0.18, 0.32]" in found["study.bounds.lb"]
    assert "not a searched variable" in found["study.bounds.la"]


def test_a_model_without_design(tmp_path):
    found = _problems(tmp_path, BASE.format(extra=""))
    assert "has no [design] table" in found["study.model"]
    s = read_design_study(_write(tmp_path, BASE.format(extra='variables = ["la"]')),
                          check_design=False)
    assert s.variables == ()


def test_overrides(tmp_path, designed):
    s = read_design_study(_write(tmp_path, FULL.replace("[optimizer]", "[optimizer]\ngrid = 9")))
    q = with_overrides(s, quick=True)
    assert dict(q.optimizer) == {"kind": "nsga2", "population": 4, "generations": 1, "grid": 9,
                                 "seed": 7}
    assert q.region["n"] == 5 and s.region["n"] == 9
    g = with_overrides(s, quick=True, optimizer="grid", grid=5)
    assert (g.optimizer["kind"], g.optimizer["grid"]) == ("grid", 5)
    with pytest.raises(DesignStudyError, match="'cmaes' optimises one objective"):
        with_overrides(s, optimizer="cmaes")
    with pytest.raises(DesignStudyError, match="must be one of"):
        with_overrides(s, optimizer="pso")
    three = dataclasses.replace(s, variables=("la", "lb", "b2x"))
    with pytest.raises(DesignStudyError, match="one or two variables"):
        with_overrides(three, optimizer="grid")
    with pytest.raises(DesignStudyError, match="must be >= 2"):
        with_overrides(s, grid=1)


@pytest.mark.parametrize("name, fixed", [("paper_legs", "shang2010"),
                                         ("rrr4_platform_legs", "rrr4_platform")])
def test_the_shipped_studies(name, fixed, tmp_path):
    """Found by name; read on their design model once it ships, else on its fixed model; run
    at the fixed model's geometry, all clear, in well under a second under --quick."""
    assert name in shipped_design_studies()
    path = find_design_study(name)
    assert path.endswith(f"synthesis/shipped/{name}.toml")
    assert find_design_study("./x.toml") == "x.toml"
    s = read_design_study(name, model=fixed, check_design=False)
    assert s.name == name and len(s.objectives) == 2 and s.optimizer["kind"] == "nsga2"
    if (SHIPPED_MODELS / f"{fixed}_design.toml").is_file():
        full = read_design_study(name)
        assert full.variables == ("la", "lb") and full.region == s.region
    q = with_overrides(s, quick=True)
    assert q.optimizer["population"] * q.optimizer["generations"] <= 12
    values, status = obj.evaluate_with_status(pm2dof.load_model(fixed), q)
    assert status == "ok", status
    assert values["region_margin"] > 0
    units = obj.units(q, pm2dof.load_model(fixed))
    assert units["duration_high"] == "s"


def test_the_shipped_paper_redesign():
    """paper_redesign: the paper's robot on four objectives. Read on the fixed paper robot, at
    its geometry: the region clear, NA's RMSE on the high move equal to pm2dof.simulate's (the
    Table 3 run), and --quick small."""
    assert "paper_redesign" in shipped_design_studies()
    s = read_design_study("paper_redesign", model="shang2010", check_design=False)
    assert [(o.name, o.measure, o.sense) for o in s.objectives] == [
        ("dexterity_mean", "dexterity_mean", "max"), ("force_min", "force", "max"),
        ("duration_high", "duration", "min"), ("rmse_na_high", "rmse", "min")]
    full = read_design_study("paper_redesign")
    assert full.variables == ("la", "lb") and full.model_path.endswith("shang2010_design.toml")
    q = with_overrides(s, quick=True)
    assert q.optimizer["population"] * q.optimizer["generations"] <= 12
    m = pm2dof.load_model("shang2010")
    values, status = obj.evaluate_with_status(m, q)
    assert status == "ok", status
    assert values["region_margin"] > 0
    na = pm2dof.simulate(m, pm2dof.NAController(m), pm2dof.paper_move("high")).rmse
    assert values["rmse_na_high"] == pytest.approx(na, rel=1e-9, abs=0)
