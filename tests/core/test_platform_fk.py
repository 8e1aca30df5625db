# A platform's fk (Gauss-Newton from [platform] home) returns a pose in the model's working modes
# of the legs, or refuses with WorkspaceError: it returned another assembly silently before.

import numpy as np
import pytest

import pm2dof

PLATFORMS = ["rrr3_platform", "rrr4_platform", "prr3_platform", "rpr3_platform"]


def _active_diff(model, a, b):
    """a - b of active coordinates, angles of revolute actuators modulo 2 pi."""
    d = np.asarray(a, dtype=float) - np.asarray(b, dtype=float)
    for i, leg in enumerate(model.spec.legs):
        if leg.actuator == "revolute":
            d[i] = (d[i] + np.pi) % (2 * np.pi) - np.pi
    return d


@pytest.mark.parametrize("name", PLATFORMS)
def test_fk_is_in_the_models_working_modes_or_refuses(name):
    """Random poses up to 0.12 m and 0.6 rad from home (beyond the documented 0.05 m / 0.2 rad
    where fk from home is reliable), 5 seeds: whatever fk returns, the model's legs reach it
    with the given active coordinates (ik round trip). A pose returned in another working mode
    differs there by 10-79 closure tolerances per link length even near a leg singularity
    (review of this check); a pose in the model's modes, by at most 2.3 (the Gauss-Newton stops
    within the closure tolerance, short of rounding): 5 separates them. Several assemblies can
    share the legs' working modes, so fk(ik(x)) == x is not asserted far from home."""
    m = pm2dof.load_model(name)
    n, home = m.n_legs, np.array(m.spec.home)
    tol = m.spec.sensing["closure_tolerance"]
    scale = np.array([leg.la if leg.actuator == "revolute" else 1.0 for leg in m.spec.legs])
    refused = returned = 0
    for seed in range(5):
        rng = np.random.default_rng(seed)
        for _ in range(300):
            x = home + rng.uniform(-1, 1, 3) * np.array([0.12, 0.12, 0.6])
            try:
                qa = m.ik(x)[:n]
            except pm2dof.WorkspaceError:
                continue
            try:
                xe = m.fk(qa)
            except pm2dof.ClosureError:          # diverged: the residual names it (documented)
                continue
            except pm2dof.WorkspaceError as exc:
                assert "in the other working mode" in str(exc) and "[platform] home" in str(exc)
                refused += 1
                continue
            returned += 1
            assert (np.abs(_active_diff(m, m.ik(xe)[:n], qa)) <= 5 * tol / scale).all(), (x, xe)
    assert returned >= 50
    if name == "rrr3_platform":               # ends in another working mode in this sample
        assert refused > 0


def test_an_other_mode_pose_near_a_leg_singularity_is_refused():
    """A pose whose qa differs from ik's by only 10-79 tolerances (a leg near its type I
    singularity): the first check, on qa, let it through; the elbow's side does not."""
    m = pm2dof.load_model("rrr3_platform")
    qa = m.ik([-0.079, 0.114, 0.091])[:3]
    with pytest.raises(pm2dof.WorkspaceError, match=r"with leg\(s\) [0-9, ]+ in the other "
                                                    r"working mode \(elbow or branch\)"):
        m.fk(qa)


@pytest.mark.parametrize("name", PLATFORMS)
def test_fk_near_home_round_trips(name):
    m = pm2dof.load_model(name)
    home = np.array(m.spec.home)
    for dx in ([0.0, 0.0, 0.0], [0.01, -0.01, 0.05], [-0.01, 0.01, -0.1]):
        x = home + dx
        np.testing.assert_allclose(m.fk(m.ik(x)[:m.n_legs]), x, atol=1e-9)


# --- fk's messages give each actuator kind's unit ---------------------------------------------

@pytest.mark.parametrize("name,unit", [("rpr3_platform", "m"), ("prr3_platform", "m"),
                                       ("rrr3_platform", "rad"), ("shang2010_vertical", "rad")])
def test_inconsistent_coordinates_are_named_in_their_actuators_unit(name, unit):
    """Active coordinates no assembly has: a redundant robot's (shang2010_vertical) leg 1 moved
    0.05 rad from ik's at its first move's start; a non-redundant platform's all 0 (every
    nearby qa has an assembly). Lengths in m (PRR slider, RPR cylinder), angles in rad (RRR):
    fk's error used to print rad for all."""
    m = pm2dof.load_model(name)
    qa = m.ik(m.spec.trajectories["low"]["start"])[:m.n_legs].copy()
    if m.n_legs > m.dof:
        qa[0] += 0.05
    else:
        qa[:] = 0.0
    with pytest.raises(pm2dof.ClosureError) as info:
        m.fk(qa)
    msg = str(info.value)
    other = {"m": "rad", "rad": "m"}[unit]
    assert f"qa = {qa.tolist()} {unit} do not close the loops" in msg, msg
    assert f"{qa.tolist()} {other}" not in msg, msg


def test_a_platforms_gauss_newton_without_a_pose_says_so_in_m():
    """rpr3_platform's legs 1e150 m long: the Gauss-Newton from home overflows. It used to say
    "no assembly of the legs has active angles qa = [...] rad"."""
    m = pm2dof.load_model("rpr3_platform")
    with pytest.raises(pm2dof.WorkspaceError) as info:
        m.fk([1e150, 1e150, 1e150])
    msg = str(info.value)
    assert ("fk of qa = [1e+150, 1e+150, 1e+150] m: the Gauss-Newton from [platform] home = "
            "[0.0, 0.0, 0.0] found no pose" in msg), msg


def test_a_five_bar_without_an_assembly_says_rad():
    m = pm2dof.load_model("fivebar")
    with pytest.raises(pm2dof.WorkspaceError,
                       match=r"no assembly of the legs has the active coordinates qa = "
                             r"\[3\.0, 0\.2\] rad$"):
        m.fk([3.0, 0.2])


def test_mixed_actuators_name_each_unit_with_its_legs():
    """No shipped model mixes revolute and linear actuators; the text of one that does."""
    from pm2dof.core.model_file import Leg
    from pm2dof.core.task import active_coordinates
    rrr = Leg(base=(0.0, 0.0), la=0.2, lb=0.2, elbow=1)
    rpr = Leg(base=(0.0, 0.0), la=None, lb=None, elbow=None, kind="RPR", stroke=(0.1, 0.4))
    actuators = tuple(leg.actuator for leg in (rrr, rrr, rpr))
    assert active_coordinates(actuators, [0.1, 0.2, 0.3]) == \
        "[0.1, 0.2, 0.3] (rad for legs 1, 2; m for leg 3)"
