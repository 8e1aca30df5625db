# The planner is runtime code: planning a path loads no SymPy, CasADi, matplotlib, SciPy, Dask.
import subprocess
import sys

import pm2dof

PROBE = r"""
import sys
import pm2dof
m = pm2dof.load_model()
path = pm2dof.TaskPath.spline([[0.22, 0.29], [0.25, 0.25], [0.27, 0.24]])
pm2dof.check_path(m, path)
plan = pm2dof.plan_time_optimal(m, path, split="min_max", grid=300)
pm2dof.simulate(m, pm2dof.NAController(m), plan.trajectory)
pm2dof.plan_kinematic(path, 0.5, 10.0, 400.0)
heavy = {"sympy", "casadi", "matplotlib", "scipy", "dask", "distributed", "pyarrow", "toppra"}
print(",".join(sorted({k.split(".")[0] for k in sys.modules} & heavy)))
"""


def test_planning_loads_no_heavy_library():
    r = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "", f"planning loaded {r.stdout.strip()}"


def test_public_names():
    for name in ("TaskPath", "check_path", "plan_kinematic", "plan_time_optimal", "plan_smooth",
                 "Plan", "PlanError"):
        assert name in pm2dof.__all__ and getattr(pm2dof, name) is not None
