# Plan.tau where the path speed is 0: friction's one-sided limit, as documented, with the number.
"""``Plan.tau`` at a rest point (the ends, an interior stop) includes Coulomb friction in the
direction of motion (s_d -> 0+), while ``Model.inverse_dynamics`` at that state (velocity 0)
uses sign(0) = 0. Checked here against ``Model.inverse_dynamics`` and ``Model.torque_splits``
(not the planner's own ``path_torques``): with a vanishing velocity along the path the two
agree; at velocity 0 they differ by the amount the Plan docstring and docs/using-planning.md
quote, recomputed here."""
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof.planning.pathfile import model_move_path, read_path_file

DOCS = Path(__file__).resolve().parents[2] / "docs"
DOC = " ".join((DOCS / "using-planning.md").read_text().split())
RESULTS = " ".join((DOCS / "results-planning.md").read_text().split())
PLAN_DOC = " ".join(pm2dof.Plan.__doc__.split())
EPS = 1e-9          # m/s along the path: the one-sided limit, the viscous term 1e-9 of fv


def _at_rest(m, plan):
    """Per rest point k of ``plan``: (Plan.tau[k], efforts at velocity EPS p'(s) along the
    path, efforts at velocity 0), each by Model.inverse_dynamics and Model.torque_splits with
    the plan's own acceleration p' s_dd (s_d = 0), the departing piece's p' (side "right")."""
    out = []
    for k in np.flatnonzero(plan.sdot == 0):
        p, dp, _ = plan.path.evaluate([plan.s[k]])
        xe, acc = p[0], dp[0] * plan.sddot[k]
        q = m.ik(xe)
        split = [m.torque_splits(q, m.inverse_dynamics(xe, v, acc, m.theta_nominal),
                                 plan.tau_max)[plan.split]
                 for v in (EPS * dp[0], np.zeros(m.dof))]
        out.append((plan.tau[k], *split))
    return out


def _largest_difference(m, paths, limits):
    """max over the paths, both splits, each limit and every rest point of |tau_plan -
    tau_(sign(0)=0)|, N m, after checking that the plan is the one-sided limit."""
    worst = 0.0
    for path in paths:
        for tau in limits:
            for split in ("min_norm", "min_max"):
                plan = pm2dof.plan_time_optimal(m, path, tau_max=tau, split=split)
                rest = _at_rest(m, plan)
                assert len(rest) == len(plan.path.stops)
                for planned, one_sided, at_zero in rest:
                    np.testing.assert_allclose(planned, one_sided, rtol=0,
                                               atol=1e-6 * max(plan.tau_max))
                    worst = max(worst, float(np.abs(planned - at_zero).max()))
    return worst


def test_paper_robot_rest_torques_are_the_one_sided_limit_as_documented():
    """The paper's robot on the shipped paths at 30 and 6 N m: the one-sided value to 1e-6 of
    tau_max, and the documented difference from sign(0) = 0 (measured 0.572 N m, curve,
    min-norm; 1.9 % of 30 N m, 9.5 % of 6 N m)."""
    m = pm2dof.load_model("shang2010")
    paths = [model_move_path(m, "high").path, read_path_file("pick_and_place").path,
             read_path_file("curve").path]
    worst = _largest_difference(m, paths, (30.0, 6.0))
    assert worst > 0.1                                   # the Coulomb term, not rounding
    for text, unit, of_30 in ((DOC, "N·m", "of τ_max at 30 N·m"),
                              (PLAN_DOC, "N m", "of tau_max = 30 N m")):
        assert f"up to {worst:.2f} {unit}" in text, worst
        assert f"{100 * worst / 30:.1f} % {of_30}" in text, worst
        assert f"{100 * worst / 6:.1f} % at 6 {unit}" in text, worst
    assert f"by the Coulomb term, up to {worst:.2f} N·m on the shipped paths" in RESULTS


@pytest.mark.parametrize("name", ["rrr4_platform", "shang2010_vertical", "prr3_platform"])
def test_other_kinds_rest_torques(name):
    """A platform with the same Coulomb law (rrr4_platform: the documented 0.21 N m, 1.0 % of
    20 N m), the gravity model (gravity included in both, the same friction difference as the
    paper's robot on its line), and a linear platform with a smoothed sign (the two agree)."""
    m = pm2dof.load_model(name)
    worst = _largest_difference(m, [model_move_path(m, "low").path], (None,))
    if name == "rrr4_platform":
        tau = float(m.spec.limits["tau_max"][0])
        for text, unit in ((DOC, "N·m"), (PLAN_DOC, "N m")):
            assert f"{worst:.2f} {unit} ({100 * worst / tau:.1f} % of its {tau:g} {unit})" \
                in text, worst
    elif name == "shang2010_vertical":
        assert 0.1 < worst <= 0.572
    else:
        assert worst < 1e-6 * max(m.spec.limits["tau_max"])
