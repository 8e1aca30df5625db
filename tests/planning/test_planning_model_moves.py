# A model file's [trajectories.<name>] may name a path file: planned by pm2dof.planning.
import subprocess
import sys

import numpy as np
import pytest

import pm2dof
from pm2dof.control.trajectory import line_moves
from pm2dof.core.paths import SHIPPED_GENERATED, SHIPPED_MODELS
from pm2dof.planning import model_move_path
from pm2dof.planning.pathfile import SHIPPED_PATHS, read_path_file

GEN = SHIPPED_GENERATED / "shang2010"


def _model_with(tmp_path, table):
    text = (SHIPPED_MODELS / "shang2010.toml").read_text() + "\n" + table + "\n"
    path = tmp_path / "m.toml"
    path.write_text(text)
    return path


def test_a_move_may_name_a_path_file(tmp_path):
    (tmp_path / "paths").mkdir()
    (tmp_path / "paths" / "mine.toml").write_text((SHIPPED_PATHS / "curve.toml").read_text())
    path = _model_with(tmp_path, '[trajectories.cycle]\npath = "pick_and_place"\n'
                                 '[trajectories.mine]\npath = "paths/mine.toml"\nv_max = 0.3\n'
                                 'a_max = 5.0\nj_max = 200.0')
    m = pm2dof.load_model(path, generated=GEN)
    assert line_moves(m) == ("low", "high")                 # what model_move samples
    with pytest.raises(pm2dof.TrajectoryError, match=r"follows the path 'pick_and_place': time "
                                                     r"it with `pm2dof plan --move cycle`"):
        pm2dof.model_move(m, "cycle")
    cyc = model_move_path(m, "cycle")                       # the shipped file, its own limits
    ref = read_path_file("pick_and_place")
    assert cyc.path.length == pytest.approx(ref.path.length, rel=0, abs=1e-15)
    assert cyc.kinematic == ref.kinematic
    mine = model_move_path(m, "mine")                       # relative to the model file
    assert mine.file == tmp_path / "paths" / "mine.toml"
    assert mine.kinematic == {"v_max": 0.3, "a_max": 5.0, "j_max": 200.0}
    plan = pm2dof.plan_kinematic(mine.path, **mine.kinematic)
    r = pm2dof.simulate(m, pm2dof.NAController(m), plan.trajectory)
    assert r.outcome == "completed" and np.isfinite(r.rmse)
    assert set(pm2dof.table3(m)) == {"low", "high"}          # table3 runs the line moves
    out = subprocess.run([sys.executable, "-m", "pm2dof", "plan", "--model", str(path),
                          "--generated", str(GEN), "--move", "cycle", "--json"],
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr


def test_a_path_move_is_validated(tmp_path):
    with pytest.raises(pm2dof.ModelFileError, match=r"trajectories\.bad\.path"):
        pm2dof.load_model(_model_with(tmp_path, "[trajectories.bad]\npath = 3"), generated=GEN)
    with pytest.raises(pm2dof.ModelFileError, match=r"trajectories\.bad\.v_max"):
        pm2dof.load_model(_model_with(tmp_path, '[trajectories.bad]\npath = "curve"\n'
                                                'v_max = -1.0'), generated=GEN)
