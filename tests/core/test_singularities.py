# Both kinds of singularity and the assembly mode: round trips, the five-bar's singular curve, crossing it.
"""Type I (a leg) and type II (parallel: the actuation) singularities, and assembly modes.

* Round trip on every model: wherever ``ik`` answers, ``fk(ik(x)[:n]) == x``. On the five-bar,
  ``ik`` refuses exactly the positions whose pose lies in the other assembly mode -- confirmed
  independently: the NumPy reference with the other ``fk_branch`` reaches them and returns.
  (This is the test that would have caught the 197-of-400 failure of the capability maps.)
* The type II measure of the C equals an SVD of S with unit rows (NumPy reference) on every
  model, and vanishes on the five-bar's singular curve (distal links aligned, det S = 0).
* Redundancy removes type II singularities: the 3- and 4-leg models never come near one.
* Crossing the five-bar's singular curve: the trajectory check, ``simulate``, the model
  functions and the controller step all refuse, naming the kind; errors name the key.

The round-trip tolerance follows the conditioning of fk at the pose (:func:`_fk_tolerance`):
for two legs it grows like 1 / kappa_II near the singular curve.
"""
import numpy as np
import pytest

import pm2dof
from pm2dof.core.paths import SHIPPED_MODELS
from pm2dof.reference import model as ref

EPS = np.finfo(float).eps


def _geometry(m, branch=None):
    legs = m.spec.legs
    return ref.Geometry(bases=m.bases, la=[lg.la for lg in legs], lb=[lg.lb for lg in legs],
                        elbow=[lg.elbow for lg in legs],
                        fk_branch=m.spec.fk_branch if branch is None else branch)


def _reachable_points(m, count, seed, spread=0.3):
    """``count`` positions around the bases' centroid that every leg reaches (either mode)."""
    rng = np.random.default_rng(seed)
    c = np.mean(m.bases, axis=0)
    X = c + rng.uniform(-spread, spread, (40 * count, 2))
    t1, _, _ = m.pose_measures(X)
    X = X[np.isfinite(t1) & (t1 > 1e-6)]
    assert len(X) >= count, f"{m.name}: only {len(X)} reachable points"
    return X[:count]


def _fk_tolerance(m, q, reach):
    """Rounding bound of fk at the pose q. Two legs: the circle intersection, error ~ eps (la +
    lb) / kappa_II (measured error * kappa_II <= 2.1e-16 m): 16 eps reach / kappa_II. More legs:
    the linear system 2 (B_j - B_1) O = |B_j|^2 - |B_1|^2 + ..., whose right side carries
    rounding eps max|B|^2, solved with sigma_min(G): 64 eps max|B|^2 / sigma_min(G) (measured
    ratio <= 14)."""
    n = m.n_legs
    if n == 2:
        return 16 * EPS * reach / max(m.singularity_measures(q)[1], 1e-300)
    la = np.array([lg.la for lg in m.spec.legs])[:, None]
    B = m.bases + la * np.stack([np.cos(q[:n]), np.sin(q[:n])], axis=1)
    sv = np.linalg.svd(2 * (B[1:] - B[0]), compute_uv=False)
    return 64 * EPS * np.max(np.sum(B ** 2, axis=1)) / sv[-1]


def test_round_trip_wherever_ik_answers(model):
    """The issue's experiment on every model: 400 random reachable positions around the bases'
    centroid. ik answers with a pose fk returns to, or refuses with a WorkspaceError that names
    the assembly mode -- and then the pose really is the other mode's."""
    m, n = model, model.n_legs
    reach = max(lg.la + lg.lb for lg in m.spec.legs)
    answered = refused = 0
    for x in _reachable_points(m, 400, seed=11):
        try:
            q = m.ik(x)
        except pm2dof.WorkspaceError as exc:
            assert n == 2 and "assembly mode" in str(exc) and "fk_branch" in str(exc), str(exc)
            other = _geometry(m, branch=-m.spec.fk_branch)   # independent: NumPy, other mode
            back = ref.fk(other, ref.ik(other, x)[:n])
            assert np.allclose(back, x, atol=1e-9), (x, back)
            refused += 1
            continue
        err = float(np.hypot(*(m.fk(q[:n]) - x)))
        assert err <= _fk_tolerance(m, q, reach), (m.name, x.tolist(), err)
        answered += 1
    assert answered >= 150, (answered, refused)
    if n == 2:  # the five-bar: about half the reachable points are the other assembly mode
        assert refused >= 100, (answered, refused)
    else:
        assert refused == 0


def test_measures_agree_with_an_svd_of_S(model, sample_xe):
    """C's closed form sqrt(1 - |sum exp(2i qb)|/n) against NumPy's SVD of S with unit rows.
    Compared as squares: sqrt amplifies rounding near 0 (kappa^2 is what both compute to
    within a few eps)."""
    g = _geometry(model)
    for x in _reachable_points(model, 60, seed=5) if model.n_legs == 2 else sample_xe(model, 3, 60):
        try:
            q = model.ik(x)
        except pm2dof.WorkspaceError:
            continue
        c = model.singularity_measures(q)
        r = ref.singularity_measures(g, q)
        assert abs(c[0] - r[0]) <= 8 * EPS, (x, c, r)
        assert abs(c[1] ** 2 - r[1] ** 2) <= 64 * EPS, (x, c, r)
        assert 0.0 <= c[1] <= 1.0


def _crossing(m, seed=3):
    """Two five-bar positions, one in each assembly mode, with every point of the segment
    between them reachable by both legs (so the segment crosses the singular curve)."""
    rng = np.random.default_rng(seed)
    s = np.linspace(0, 1, 401)[:, None]
    for _ in range(20000):
        a, b = _reachable_points(m, 2, seed=int(rng.integers(1 << 30)), spread=0.25)
        seg = a + s * (b - a)
        t1, _, side = m.pose_measures(seg)
        if np.all(t1 > 0.3) and side[0] > 0 and side[-1] < 0 and np.hypot(*(b - a)) > 0.05:
            return a, b
    raise AssertionError("no crossing segment found")


def _on_curve(m, a, b):
    """Bisect the segment a -> b to the point where the assembly side changes sign."""
    lo, hi = 0.0, 1.0
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        _, _, side = m.pose_measures((a + mid * (b - a))[None, :])
        lo, hi = (mid, hi) if side[0] > 0 else (lo, mid)
    return a + lo * (b - a), (b - a) / np.hypot(*(b - a))


@pytest.fixture(scope="module")
def fivebar():
    return pm2dof.load_model(SHIPPED_MODELS / "fivebar.toml")


def test_fivebar_singular_curve_is_where_the_distal_links_align(fivebar):
    m, g = fivebar, _geometry(fivebar)
    rng = np.random.default_rng(0)
    for k in range(8):
        a, b = _crossing(m, seed=int(rng.integers(1 << 30)))
        x, u = _on_curve(m, a, b)
        q = ref.ik(g, x - 1e-9 * u)  # just on the model's side
        qb = q[2:]
        assert abs(np.sin(qb[0] - qb[1])) < 1e-6, f"distal links not aligned at {x}: {qb}"
        S = ref.S(g, q)
        assert abs(np.linalg.det(S)) < 1e-5 * np.linalg.norm(S) ** 2, (x, np.linalg.det(S))
        kappa = m.singularity_measures(q)[1]
        assert kappa < 1e-3, (x, kappa)
        # the measure grows with the distance from the curve (here about linearly)
        for dist in (1e-3, 4e-3):
            q2 = m.ik(x - dist * u)
            assert m.singularity_measures(q2)[1] > kappa
        with pytest.raises(pm2dof.SingularityError, match=r"type II .*parallel_singularity_"
                                                          r"threshold"):
            m.S(q)
        with pytest.raises(pm2dof.WorkspaceError, match="assembly mode"):
            m.ik(x + 1e-4 * u)  # just past the curve: the other mode


def test_redundant_models_have_no_parallel_singularity_in_reach(model):
    """Three or four legs: type II needs every distal link parallel, i.e. all elbows on one
    line through O at their lb from it -- not reachable here. The smallest measure over
    the reachable workspace stays far above the threshold."""
    if model.n_legs == 2:
        pytest.skip("the five-bar has a singular curve inside its workspace")
    X = _reachable_points(model, 3000, seed=2, spread=0.4)
    _, t2, _ = model.pose_measures(X)
    assert np.nanmin(t2) > 3 * model.parallel_singularity_threshold, np.nanmin(t2)


def test_crossing_the_curve_is_refused_before_the_run(fivebar):
    m = fivebar
    a, b = _crossing(m)
    traj = pm2dof.line(a, b, 0.2, 5.0, 200.0)
    with pytest.raises(pm2dof.SingularityError, match=r"trajectory sample \d+ .*type II"):
        pm2dof.check_trajectory(m, traj)
    with pytest.raises(pm2dof.SingularityError, match="type II"):
        pm2dof.simulate(m, pm2dof.APDController(m), traj)
    # the first refused sample is the first within the threshold of the curve
    _, t2, side = m.pose_measures(traj.xd)
    k = int(np.flatnonzero(t2 < m.parallel_singularity_threshold)[0])
    assert np.all(side[:k + 1] > 0), "the check passed a sample of the other mode"
    msg = ""
    try:
        pm2dof.check_trajectory(m, traj)
    except pm2dof.SingularityError as exc:
        msg = str(exc)
    assert msg.startswith(f"trajectory sample {k} "), (k, msg)


def test_controller_step_near_the_curve_gives_zero_torque_and_names_the_kind(fivebar):
    m = fivebar
    a, b = _crossing(m, seed=9)
    x, u = _on_curve(m, a, b)
    for dist in np.linspace(1e-4, 0.05, 200):   # a pose in the good mode, inside the band
        q = m.ik(x - dist * u)
        k2 = m.singularity_measures(q)[1]
        if 0.2 * m.parallel_singularity_threshold < k2 < m.parallel_singularity_threshold:
            break
    else:
        raise AssertionError("no pose inside the type II band")
    qa, xd, z = q[:2].copy(), x - dist * u, np.zeros(2)
    for cls in (pm2dof.NAController, pm2dof.APDController):
        c = cls(m)
        c.reset(qa)
        with pytest.raises(pm2dof.SingularityError, match=r"type II .*theta_hat was not updated"):
            c.step(qa, xd, z, z)
        c = cls(m, on_singular="zero")
        c.reset(qa)
        theta = c.state["theta_hat"]
        tau = c.step(qa, xd, z, z)
        assert c.status == "singular" and np.all(tau == 0.0)
        assert np.array_equal(c.state["theta_hat"], theta)
        assert c.diag["sing_parallel"] == pytest.approx(k2, abs=1e-9)
        assert c.diag["sing"] >= m.singularity_threshold   # not a type I case


def test_type_one_errors_say_type_one():
    m = pm2dof.load_model()
    leg = m.spec.legs[0]
    # leg 1 almost stretched: O nearly at distance la + lb from A1, toward the workspace
    d = np.array([0.25, 0.265]) - leg.base
    x = np.asarray(leg.base) + d / np.hypot(*d) * (leg.la + leg.lb) * 0.9995
    q = m.ik(x)
    assert m.singularity_measures(q)[0] < m.singularity_threshold
    with pytest.raises(pm2dof.SingularityError,
                       match=r"type I \(a leg's links aligned\).*limits\.singularity_threshold"):
        m.W(q)


@pytest.mark.parametrize("value,ok", [(0.05, True), (0.0, False), (-0.1, False), (1.0, False),
                                      ("x", False)])
def test_parallel_threshold_in_the_model_file(tmp_path, value, ok):
    from pm2dof.core.model_file import DEFAULT_PARALLEL_THRESHOLD, read_model_file
    src = "\n".join(line for line in (SHIPPED_MODELS / "shang2010.toml").read_text().splitlines()
                    if not line.startswith("parallel_singularity_threshold")) + "\n"
    text = src.replace("[limits]\n", f"[limits]\nparallel_singularity_threshold = {value!r}\n"
                       .replace("'", '"'), 1)
    path = tmp_path / "m.toml"
    path.write_text(text)
    if ok:
        assert read_model_file(path).limits["parallel_singularity_threshold"] == value
    else:
        with pytest.raises(pm2dof.ModelFileError, match="limits.parallel_singularity_threshold"):
            read_model_file(path)
    # a model file without the key gets the documented default
    bare = tmp_path / "bare.toml"
    bare.write_text(src)
    assert (read_model_file(bare).limits["parallel_singularity_threshold"]
            == DEFAULT_PARALLEL_THRESHOLD)
