# The extra legs check the encoders: fk and the controller steps refuse angles that do not close.
"""``fk`` returned poses the robot cannot be in.

With three encoders for two degrees of freedom, fk fits the tip to all elbow circles by least
squares; the closure residual |O - B_i| - lb_i of every leg measures how inconsistent the
angles are. ``fk`` raises :class:`pm2dof.ClosureError` (a WorkspaceError) naming the leg and the
residual in m beyond ``[sensing] closure_tolerance``; the controller steps report status
``inconsistent_encoders`` with zero torque and the state kept. Checked against the independent
NumPy reference (:mod:`pm2dof.reference`).
"""
import math

import numpy as np
import pytest

import pm2dof
from pm2dof.core.paths import SHIPPED_GENERATED, SHIPPED_MODELS
from pm2dof.reference import control as rc
from pm2dof.reference import model as ref

XE = np.array([0.245, 0.265])


@pytest.fixture(scope="module")
def m():
    return pm2dof.load_model()


def _geometry(model):
    s = model.spec
    return ref.Geometry(bases=s.bases, la=[l.la for l in s.legs], lb=[l.lb for l in s.legs],
                        elbow=[l.elbow for l in s.legs], fk_branch=s.fk_branch)


def test_the_issue_pose_is_refused_naming_leg_and_residual(m):
    """m.fk([0, pi, 0]) used to return [0.661, 0.027], a point ik says leg 1 cannot reach."""
    with pytest.raises(pm2dof.ClosureError) as info:
        m.fk([0, np.pi, 0])
    assert isinstance(info.value, pm2dof.WorkspaceError)
    msg = str(info.value)
    B = m.spec.bases + np.array([[l.la * math.cos(a), l.la * math.sin(a)]
                                 for l, a in zip(m.spec.legs, [0, np.pi, 0])])
    O = np.linalg.lstsq(2 * (B[1:] - B[0]), np.sum(B[1:] ** 2, 1) - np.sum(B[0] ** 2)
                        - np.array([l.lb ** 2 for l in m.spec.legs[1:]]) + m.spec.legs[0].lb ** 2,
                        rcond=None)[0]                       # the least-squares tip, in NumPy
    r = np.hypot(*(O - B).T) - [l.lb for l in m.spec.legs]
    worst = int(np.argmax(np.abs(r)))
    assert f"leg {worst + 1}'s tip misses the common point by {r[worst]:+.3g} m" in msg, msg
    assert "closure_tolerance" in msg


@pytest.mark.parametrize("leg", [0, 1, 2])
def test_an_inconsistent_encoder_is_refused(m, leg):
    qa = m.ik(XE)[:3].copy()
    qa[leg] += 0.05                                          # 0.05 rad: a leg that cannot close
    with pytest.raises(pm2dof.ClosureError, match=r"do not close the loops: leg \d's tip"):
        m.fk(qa)


def test_quantised_encoders_pass_with_margin(m):
    """17-bit encoders, up to one count of error on top of the rounding, over the workspace
    clear of both singularity thresholds: the worst residual against the default tolerance
    (5 encoder steps at la). This measures the margin the default was chosen by."""
    step = 2 * np.pi / m.spec.sensing["encoder_counts_per_rev"]
    la = max(l.la for l in m.spec.legs)
    rng = np.random.default_rng(7)
    g, worst, n_poses = _geometry(m), 0.0, 0
    for k in range(4000):
        x = XE + rng.uniform(-0.08, 0.08, 2)
        try:
            q = m.ik(x)
        except pm2dof.WorkspaceError:
            continue
        if min(m.singularity_measures(q)) < 0.1:
            continue
        qa = step * np.floor(q[:3] / step + 0.5) + rng.uniform(-0.5, 0.5, 3) * step
        xe = m.fk(qa)                                        # must not raise
        worst = max(worst, float(np.abs(ref.closure_residuals(g, qa, xe)).max()))
        n_poses += 1
    assert n_poses > 2000
    print(f"\n[closure] worst residual over {n_poses} poses: {worst:.3g} m = "
          f"{worst / (la * step):.2f} encoder steps at la; tolerance {m.closure_tolerance:.3g} m")
    assert worst < m.closure_tolerance / 2, (worst, m.closure_tolerance)
    assert m.closure_tolerance == pytest.approx(5 * la * step)


def test_residual_of_the_generated_fk_equals_the_reference(model):
    """Every shipped model: the C's residual output against NumPy's at perturbed angles."""
    g = _geometry(model)
    n = model.n_legs
    t = next(iter(model.spec.trajectories.values()))
    x = (np.asarray(t["start"]) + np.asarray(t["end"])) / 2
    rng = np.random.default_rng(3)
    f = model.function("fk")
    for _ in range(20):
        qa = model.ik(x + rng.uniform(-0.01, 0.01, 2))[:n] + rng.normal(0, 1e-3, n)
        xe, r = np.empty(2), np.empty(n)
        f(qa, xe, r)
        if n == 2:                                           # a five-bar's fk meets both circles
            assert np.abs(r).max() < 1e-14
            continue
        assert np.allclose(xe, ref.fk(g, qa), rtol=0, atol=1e-13)
        assert np.allclose(r, ref.closure_residuals(g, qa, xe), rtol=0, atol=1e-13)


@pytest.mark.parametrize("cls", [pm2dof.NAController, pm2dof.APDController])
def test_controller_step_reports_inconsistent_encoders_and_keeps_its_state(m, cls):
    c = cls(m)
    q = m.ik(XE)
    c.reset(q[:3])
    zeros = np.zeros(2)
    c.step(q[:3], XE, zeros, zeros)
    before = c.state
    bad = q[:3] + np.array([0.0, 0.0, 0.05])
    tau = c.step(bad, XE, zeros, zeros)                       # no exception: a status
    assert c.status == "inconsistent_encoders" and np.all(tau == 0)
    after = c.state
    for k in before:
        assert np.array_equal(before[k], after[k]), k         # no wrong pose carried on
    c.step(q[:3], XE, zeros, zeros)
    assert c.status == "ok"
    # the NumPy reference step agrees on the status and the safe output
    lay = rc.layouts(3)
    law = "na" if cls is pm2dof.NAController else "apd"
    step = rc.na_step if law == "na" else rc.apd_step
    tau_r, state_r, status_r, _ = step(_geometry(m), lay["ctrl_state"].pack(**before), bad, XE,
                                       zeros, zeros, c.params)
    assert status_r == rc.STATUS["inconsistent_encoders"] and np.all(tau_r == 0)
    assert np.array_equal(state_r, lay["ctrl_state"].pack(**before))


def test_closure_tolerance_is_settable_in_the_model_file(tmp_path, m):
    text = (SHIPPED_MODELS / "shang2010.toml").read_text()
    qa = m.ik(XE)[:3] + np.array([0.0, 0.0, 0.05])
    loose = tmp_path / "loose.toml"
    loose.write_text(text.replace("[sensing]\n", "[sensing]\nclosure_tolerance = 0.05\n", 1))
    ml = pm2dof.load_model(loose, generated=SHIPPED_GENERATED / "shang2010")
    assert ml.closure_tolerance == 0.05
    ml.fk(qa)                                                 # 12 mm residual < 50 mm
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace("[sensing]\n", "[sensing]\nclosure_tolerance = -1\n", 1))
    with pytest.raises(pm2dof.ModelFileError, match=r"sensing\.closure_tolerance"):
        pm2dof.load_model(bad, generated=SHIPPED_GENERATED / "shang2010")
