"""Tests of pm2dof.bench: one quick run returns every number, the table renders.

No timing thresholds here: the targets are reported by the bench, never enforced.
"""
import json
import math

import pytest

from pm2dof import bench, load_model
from pm2dof.bench import baselines

pytestmark = pytest.mark.slow     # runs the bench: make test-slow (CI)


@pytest.fixture(scope="module")
def model():
    return load_model()


@pytest.fixture(scope="module")
def results(model):
    messages = []
    r = bench.run_bench(model, quick=True, progress=messages.append)
    r["_messages"] = messages
    return r


def _positive_finite(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) and v > 0


def test_required_keys_are_positive_numbers(results):
    for key in bench.REQUIRED_KEYS:
        assert key in results, key
        v = results[key]
        if v is None:  # only where a dependency is missing, and then with a note
            assert key in ("na_step_casadi_function_us", "na_step_lambdify_us"), key
            assert key in results["notes"], key
        else:
            assert _positive_finite(v), (key, v)


def test_minimums_and_ratios(results):
    for key in ("na_step_c_ns", "apd_step_c_ns", "na_step_python_us", "na_step_numpy_us"):
        assert _positive_finite(results[key + "_min"])
        assert results[key + "_min"] <= results[key] * (1 + 1e-12)
    for key in ("speedup_c_vs_numpy", "rollout_end_to_end_steps_per_s", "na_step_binding_us",
                "na_step_python_alloc_us"):
        assert _positive_finite(results[key]), key
    if results["na_step_casadi_function_us"] is not None:
        assert _positive_finite(results["speedup_binding_vs_casadi_function"])


def test_agreement_with_references(results):
    assert results["agreement_c_vs_numpy"] < 1e-10
    assert results["agreement_cases"] >= 2
    if results["na_step_lambdify_us"] is not None:
        assert results["agreement_c_vs_lambdify"] < 1e-10
    if results["na_step_casadi_function_us"] is not None:
        assert results["agreement_casadi_function_vs_c"] == 0.0  # the same compiled code


def test_rollout_tracks_without_singular_samples(results):
    assert results["rollout_singular_samples"] == 0
    assert results["rollout_max_error_m"] < 1e-2


def test_op_counts_are_positive(results):
    ops = results["op_counts"]
    assert set(ops) == set(bench.OPS_FUNCTIONS)
    for name, c in ops.items():
        assert c["mul"] > 0 and c["add"] > 0 and c["flops"] > 0, name
        assert all(isinstance(v, int) and v >= 0 for k, v in c.items()
                   if k not in ("body", "calls")), name
    # the controller reads three encoders: sin and cos of each active angle
    assert ops["na_step"]["sin"] >= 3 and ops["na_step"]["cos"] >= 3
    # the closed loop calls one step and the plant: its count includes theirs
    cl, step, plant = ops["na_closed_loop"], ops["na_step"], ops["plant_step"]
    assert cl["flops"] >= step["flops"] + plant["flops"]


def test_targets_and_machine(results):
    t = results["targets"]
    assert set(t) == {key for key, *_ in bench.TARGETS}
    for key, entry in t.items():
        assert entry["pass"] in (True, False, None)
        if entry["value"] is not None:
            assert entry["pass"] is not None
    m = results["machine"]
    assert m["python"] and m["compiler_flags"] and m["cores"] >= 1


def test_refined_plans_beside_unrefined_ones_and_toppra(results):
    """Refined plans on the model's fastest move, a half circle, a user's spline (the one
    the planner once exceeded tau_max on between its samples) and both shipped paths, both
    splits, with and without friction, timed beside an unrefined plan of the same final grid and
    (friction-free) toppra; the worst ratios are the targets' values."""
    rows = results["plan_paths"]
    assert set(rows) == {"line", "half_circle", "spline", "pick_and_place", "curve"}
    cases = [c for r in rows.values() for c in r.values()]
    assert len(cases) == 20 and results["plan_refined_cases"] >= 8
    for c in cases:
        assert _positive_finite(c["refined_ms"]) and _positive_finite(c["unrefined_ms"])
        assert c["grid"] >= 1000
    worst = max(c["refined_over_unrefined"] for c in cases
                if c["refinements"] or c["split_before"])
    assert results["plan_refined_over_unrefined_max"] == worst
    if results["toppra_ms"] is not None:
        speed = [c["speedup_vs_toppra"] for c in cases if c["toppra_ms"] is not None]
        assert len(speed) == 10 and results["speedup_vs_toppra_min"] == min(speed)
    assert "refined / unrefined of that grid" in bench.format_bench(results)


def test_json_and_format(results):
    text = json.dumps({k: v for k, v in results.items() if k != "_messages"})
    assert "na_step_c_ns" in text
    table = bench.format_bench(results)
    assert "NA step, C loop" in table and "rollout" in table and "targets met" in table
    assert results["_messages"], "progress callback was not called"


def test_format_handles_missing_values(results):
    r = dict(results)
    r["na_step_lambdify_us"] = r["na_step_lambdify_us_min"] = None
    r["notes"] = {"na_step_lambdify_us": "sympy is not importable"}
    assert "n/a" in bench.format_bench(r)


def test_missing_casadi_and_sympy_give_none_with_notes(model, monkeypatch):
    """Without casadi and the derive package the two baselines are None, with a note."""
    import sys

    monkeypatch.setitem(sys.modules, "casadi", None)  # import casadi -> ImportError

    def no_derive():
        raise ImportError("derive hidden by the test")

    monkeypatch.setattr(baselines, "_import_derive", no_derive)
    monkeypatch.setattr(baselines, "_LAMBDIFY_CACHE", {})
    r = bench.run_bench(model, quick=True)
    for key in ("na_step_casadi_function_us", "na_step_lambdify_us"):
        assert r[key] is None and key in r["notes"]
    assert r["speedup_binding_vs_casadi_function"] is None
    assert r["targets"]["speedup_binding_vs_casadi_function"]["pass"] is None
    for key in set(bench.REQUIRED_KEYS) - {"na_step_casadi_function_us", "na_step_lambdify_us"}:
        assert _positive_finite(r[key]), key
    assert "n/a" in bench.format_bench(r)


def test_count_ops_on_a_tiny_source():
    src = """
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1;
  a0=arg[0]? arg[0][0] : 0;
  a1=sin(a0);
  a0=cos(a0);
  a1=(a1*a0);
  a1=(a1/a0);
  a0=(a0+a1);
  a0=(a0-a1);
  a0=casadi_sq(a0);
  a0=(-a0);
  if (res[0]!=0) res[0][0]=a0;
  return 0;
}

CASADI_SYMBOL_EXPORT int m_f(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

static int casadi_f1(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real w0;
  w0 = 2.;
  w0 /= w0;
  if (casadi_f0(arg1, res1, iw, w, 0)) return 1;
  if (casadi_f0(arg1, res1, iw, w, 0)) return 1;
  return 0;
}

CASADI_SYMBOL_EXPORT int m_g(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f1(arg, res, iw, w, mem);
}
"""
    ops = bench.count_ops(src, ["m_f", "m_g"])
    f, g = ops["m_f"], ops["m_g"]
    assert (f["sin"], f["cos"], f["mul"], f["div"], f["add"], f["sub"], f["sq"], f["neg"]) == \
        (1, 1, 1, 1, 1, 1, 1, 1)
    assert f["flops"] == 6 and f["transcendental"] == 2
    assert g["calls"] == {"casadi_f0": 2}
    assert g["div"] == 2 * f["div"] + 1 and g["sin"] == 2


def test_platform_rows_beside_the_paper_robot():
    """The platforms' speed: the 3-RRR and 4-RRR beside the paper's robot in one run (tiny
    batches: the numbers are noise, their presence and the report's rows are checked)."""
    from pm2dof.bench.models import BENCH_MODELS, PAPER_MODEL, models_bench
    r = models_bench(repeats=2, batch_s=0.002, c_inner=200, n_roll=300)
    rows = r["model_rows"]
    assert list(rows) == list(BENCH_MODELS) and r["models_paper"] == PAPER_MODEL
    assert [(x["n_legs"], x["dof"]) for x in rows.values()] == [(3, 2), (3, 3), (4, 3)]
    for name, x in rows.items():
        for key in ("na_step_c_ns", "na_step_python_ns", "forward_dynamics_c_ns",
                    "forward_dynamics_python_ns", "rollout_steps_per_s", "plan_time_optimal_ms"):
            assert _positive_finite(x[key]), (name, key)
        for key in ("na_step_binding_overhead_ns", "forward_dynamics_binding_overhead_ns"):
            assert math.isfinite(x[key]), (name, key)     # a difference: may be noise-negative
        assert ("phi" in x["plan_path"]) == (x["dof"] == 3)
        if name != PAPER_MODEL:
            assert _positive_finite(x["na_step_c_over_paper"])
            assert math.isfinite(x["na_step_binding_overhead_over_paper"])
    assert r["rrr4_na_step_c_over_paper"] == rows["rrr4_platform"]["na_step_c_over_paper"]
    worst = max(rows[n][f"{c}_binding_overhead_over_paper"] for n in BENCH_MODELS[1:]
                for c in ("na_step", "forward_dynamics"))
    assert r["platform_binding_overhead_over_paper_max"] == worst
    res = {**r, "targets": bench.run.check_targets(r), "model": PAPER_MODEL}
    assert res["targets"]["rrr4_na_step_c_over_paper"]["pass"] in (True, False)
    table = bench.format_bench(res)
    assert "the platforms beside the paper's robot" in table
    assert "rrr4_platform" in table and "NA step in C, 4-RRR / paper's robot" in table
    assert "Pinocchio, MuJoCo) stay on the paper's robot" in table


def test_quick_run_leaves_the_platform_targets_unmeasured(results):
    for key in ("rrr4_na_step_c_over_paper", "platform_binding_overhead_over_paper_max"):
        assert results[key] is None and results["targets"][key]["pass"] is None
    assert "model_rows" not in results and "--models" in results["notes"]["model_rows"]
