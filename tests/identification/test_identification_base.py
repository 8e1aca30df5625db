# Identification: the regressor's null space matches physics; least squares recovers friction.
import numpy as np
import pytest

import pm2dof
from pm2dof.identification.base import estimate, excitation, identifiability
from pm2dof import theta_truth


@pytest.fixture(scope="module")
def m():
    return pm2dof.load_model()


@pytest.fixture(scope="module")
def ident(m):
    return identifiability(m)


def _point_mass_direction(m, i, j):
    """theta change of moving a point mass at the common tip O from leg j's books to leg i's:
    it adds (la^2, la lb, lb^2) to (alpha_i, beta_i, gamma_i) and removes them from leg j."""
    v = np.zeros(len(m.param_names))
    for leg, sign in ((i, 1.0), (j, -1.0)):
        L = m.spec.legs[leg]
        for name, value in (("alpha", L.la ** 2), ("beta", L.la * L.lb), ("gamma", L.lb ** 2)):
            v[m.param_names.index(f"{name}{leg + 1}")] += sign * value
    return v


def test_rank_is_13_of_15_for_the_paper_robot(ident):
    # 3 legs meeting at one point: 2 = n_legs - 1 point-mass bookings are invisible
    assert ident["rank"] == 13, ident["singular_values"]
    assert len(ident["independent"]) == 13 and len(ident["dependent"]) == 2


def test_null_space_is_the_point_mass_bookings(m, ident):
    """The physically predicted directions lie in the computed null space, and Y v = 0."""
    N = ident["null_space"]
    rng = np.random.default_rng(3)
    for i, j in ((0, 1), (0, 2), (1, 2)):
        v = _point_mass_direction(m, i, j)
        resid = v - N @ (N.T @ v)
        # N is orthonormal from an SVD of O(1e2)-scaled data: projection exact to ~1e-12
        assert np.linalg.norm(resid) < 1e-9 * np.linalg.norm(v), (i, j, resid)
        for _ in range(5):
            xe = np.array([0.245, 0.265]) + rng.uniform(-0.03, 0.03, 2)
            q = m.ik(xe)
            Y = m.Y(q, rng.normal(size=2), rng.normal(size=2), rng.normal(size=2))
            # Y entries are O(10); cancellation leaves rounding ~1e-15 * |Y| |v|
            assert np.abs(Y @ v).max() < 1e-12 * np.abs(Y).max() * np.abs(v).max() * 10, (xe, Y @ v)


def test_base_parameters_reproduce_every_column(m, ident):
    rng = np.random.default_rng(5)
    I, D, beta = ident["independent"], ident["dependent"], ident["beta"]
    for _ in range(10):
        q = m.ik(np.array([0.245, 0.265]) + rng.uniform(-0.03, 0.03, 2))
        Y = m.Y(q, rng.normal(size=2), rng.normal(size=2), rng.normal(size=2))
        assert np.allclose(Y[:, I] @ beta, Y[:, D], rtol=0, atol=1e-10 * np.abs(Y).max())


def test_excitation_starts_at_rest_and_is_consistent(m):
    ex = excitation(m, duration=1.0)
    assert np.allclose(ex.xd_dot[0], 0.0, atol=1e-15)
    T = ex.period
    # central differences of the analytic signal match its derivatives to O(T^2 w^3 a)
    fd = (ex.xd[2:] - ex.xd[:-2]) / (2 * T)
    assert np.abs(fd - ex.xd_dot[1:-1]).max() < 1e-3 * np.abs(ex.xd_dot).max()


def test_least_squares_recovers_viscous_friction(m, ident):
    """Exact encoders: viscous friction within 5 % of the truth (the Stribeck excess and the
    filtered derivatives bias the rest; the tolerance is the physics, not a fit)."""
    e = estimate(m, duration=4.0, quantise=False, ident=ident)
    names = e["names"]
    for k, name in enumerate(names):
        if name.startswith("fv"):
            assert abs(e["estimate"][k] - e["truth"][k]) < 0.05 * e["truth"][k], (name, e["estimate"][k], e["truth"][k])
    # the full theta0 keeps the dependent parameters at nominal and folds the rest
    th = e["theta0"]
    assert th.shape == (15,) and np.isfinite(th).all()
    I, D = ident["independent"], ident["dependent"]
    assert np.allclose(th[I] + ident["beta"] @ th[D], e["estimate"], rtol=1e-12, atol=1e-14)
    # the truth vector used for comparison is the plant's, not the nominal one
    assert not np.allclose(theta_truth(m), m.theta_nominal)
