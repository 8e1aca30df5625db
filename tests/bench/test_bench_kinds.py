"""``pm2dof bench --model`` on every kind: a platform (rrr3_platform), linear actuators
(prr3_platform) and gravity (shang2010_vertical).

Each runs the command's whole code path once in quick mode (3 short batches: the numbers are
noise, no speed target is checked here). What is checked: the run completes; every required
number is a positive number or n/a with a note naming the model and why (the NumPy reference,
the SymPy-lambdify step and the peers Pinocchio and MuJoCo model the paper's family only);
and the agreements that are independent of the generated code hold on each kind: the
forward-dynamics Jacobians against central differences, toppra's time-optimal duration
against pm2dof's on the same problem, the lambdify step against the C step (gravity), the
closed-loop rollout tracking its move (a platform's orientation included).
"""
import contextlib
import io
import json
import math

import pytest

from pm2dof import bench, cli, load_model

pytestmark = pytest.mark.slow     # long runs (builds, full benches, Dask clusters): make test-slow (CI)

#: model -> the required keys that are n/a on it (each with a note)
MODELS = {
    "rrr3_platform": {"na_step_numpy_us", "na_step_lambdify_us"},
    "prr3_platform": {"na_step_numpy_us", "na_step_lambdify_us"},
    "shang2010_vertical": {"na_step_numpy_us"},
}
PEER_KEYS = ("pinocchio_forward_dynamics_python_us", "mujoco_forward_python_us",
             "pinocchio_constraint_derivatives_python_us")


@pytest.fixture(scope="module", params=sorted(MODELS))
def run(request):
    """(model, the JSON of ``pm2dof bench --model NAME --quick --json``)."""
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        rc = cli.main(["bench", "--model", request.param, "--quick", "--json"])
    assert rc == 0, out.getvalue()[-2000:]
    return load_model(request.param), json.loads(out.getvalue())


def _positive_finite(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) and v > 0


def test_required_keys_are_numbers_or_na_with_a_reason(run):
    model, r = run
    assert r["model"] == model.name and r["n_legs"] == model.n_legs
    na = MODELS[model.name]
    for key in bench.REQUIRED_KEYS:
        if key in na:
            assert r[key] is None, key
            assert model.name in r["notes"][key], (key, r["notes"].get(key))
        else:
            assert _positive_finite(r[key]), (key, r[key])
    # the peers model RR legs at a point in a horizontal plane: n/a, saying why
    for key in PEER_KEYS:
        assert r[key] is None and model.name in r["notes"][key], key
    why = r["notes"]["mujoco_forward_python_us"]
    assert ("gravity" in why) == model.spec.has_gravity
    assert ("moving platform" in why) == (model.dof == 3)
    for key, t in r["targets"].items():
        assert (t["pass"] is None) == (t["value"] is None), key
    table = bench.format_bench(r)
    assert f"model {model.name!r}" in table and "targets met" in table
    assert "note: na_step_numpy_us: " in table


def test_jacobians_agree_with_central_differences(run):
    """The forward-dynamics Jacobians (m rows: a platform's phi included) against central
    differences of the forward dynamics, over xe, xed (m each), tau_a (n) and theta (p)."""
    model, r = run
    assert r["agreement_fd_jacobians_vs_finite_differences"] < 1e-6
    assert _positive_finite(r["fd_jacobians_python_us"])
    assert r["agreement_casadi_function_vs_c"] == 0.0       # the same compiled code


def test_toppra_finds_the_same_duration(run):
    """toppra (an independent time-optimal planner) on the same friction-free problem, given
    the generated Me, Ce (and Ge under gravity) end to end, or the coefficients: the same
    duration as plan_time_optimal."""
    model, r = run
    if r["toppra_ms"] is None:
        pytest.skip(r["notes"]["toppra"])
    pm = r["plan_duration_friction_free_s"]
    assert abs(r["toppra_duration_s"] / pm - 1) < 1e-4
    assert abs(r["toppra_given_duration_s"] / pm - 1) < 1e-4
    for cases in r["plan_paths"].values():
        for c in cases.values():
            assert _positive_finite(c["refined_ms"]) and c["grid"] >= 1000


def test_rollout_tracks_the_move(run):
    """The closed loop in C along the model's high-speed move and back: no singular sample,
    the position within 1 cm (and a platform's orientation within 0.02 rad) of the move."""
    model, r = run
    assert r["rollout_singular_samples"] == 0
    assert 0 < r["rollout_max_error_m"] < 1e-2
    if model.dof == 3:
        assert 0 < r["rollout_max_error_phi_rad"] < 0.02
    else:
        assert "rollout_max_error_phi_rad" not in r
    assert r["rk4_substeps"] == model.spec.rk4_substeps


def test_lambdify_step_agrees_under_gravity(run):
    """The step composed from the SymPy expressions (theta with kappa, the gravity columns of
    Y) against the generated C, over the operating point and random states."""
    model, r = run
    if r["na_step_lambdify_us"] is None:
        assert model.dof == 3 and "moving platform" in r["notes"]["na_step_lambdify_us"]
        return
    assert r["agreement_c_vs_lambdify"] < 1e-10
    assert r["speedup_c_vs_lambdify"] > 0


def test_op_counts_of_every_kind(run):
    model, r = run
    ops = r["op_counts"]
    assert set(ops) == set(bench.OPS_FUNCTIONS)
    cl, step, plant = ops["na_closed_loop"], ops["na_step"], ops["plant_step"]
    assert cl["flops"] >= step["flops"] + plant["flops"] > 0


def test_toppra_runner_on_a_platform_with_more_facets_than_actuators():
    """The bench's toppra end to end on the 4-RRR, whose force polytope has 6 facet pairs in
    3-D for 4 actuators (the 3-D platforms of the quick runs above have 3 and 3): toppra and
    pm2dof's planner on the same 300-point grid find the same duration."""
    from pm2dof.bench.planning import _toppra_duration, friction_free, toppra_runner
    from pm2dof.control.trajectory import line_moves
    from pm2dof.planning.pathfile import model_move_path
    from pm2dof.planning.stages import grid_points, params
    from pm2dof.planning.topp import plan_on_grid
    pytest.importorskip("toppra")
    model = load_model("rrr4_platform")
    path = model_move_path(model, line_moves(model)[0]).path
    s, th = grid_points(path, 300), friction_free(model)
    sd = toppra_runner(model, path, s, "min_max", params(model, th)[1])()
    plan = plan_on_grid(model, path, s, split="min_max", theta=th)
    assert abs(_toppra_duration(sd, s) / plan.duration - 1) < 1e-4
