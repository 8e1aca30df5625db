# Identifiability: the regressor's null space matches physics; BaseParameters folds theta as Y does.
import numpy as np
import pytest

import pm2dof
from pm2dof import theta_truth
from pm2dof.identification.base import BaseParameters, identifiability
from pm2dof.identification.excitation import simulated_log
from pm2dof.identification.fit import identify_log
from pm2dof.identification.signals import multisine, trajectory_of


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


def _states(m, n, seed):
    rng = np.random.default_rng(seed)
    for _ in range(n):
        q = m.ik(np.array([0.245, 0.265]) + rng.uniform(-0.03, 0.03, 2))
        yield q, m.Y(q, rng.normal(size=2), rng.normal(size=2), rng.normal(size=2))


def test_rank_is_13_of_15_for_the_paper_robot(ident):
    # 3 legs meeting at one point: 2 = n_legs - 1 point-mass bookings are invisible
    assert ident.rank == 13, ident.singular_values
    assert ident.base.r == 13 and len(ident.base.dependent) == 2
    assert ident.null_space.shape == (15, 2)


def test_null_space_is_the_point_mass_bookings(m, ident):
    """The physically predicted directions lie in the computed null space, and Y v = 0."""
    N = ident.null_space
    for i, j in ((0, 1), (0, 2), (1, 2)):
        v = _point_mass_direction(m, i, j)
        resid = v - N @ (N.T @ v)
        # N is orthonormal from an SVD of O(1e2)-scaled data: projection exact to ~1e-12
        assert np.linalg.norm(resid) < 1e-9 * np.linalg.norm(v), (i, j, resid)
        for _, Y in _states(m, 5, 3):
            # Y entries are O(10); cancellation leaves rounding ~1e-15 * |Y| |v|
            assert np.abs(Y @ v).max() < 1e-12 * np.abs(Y).max() * np.abs(v).max() * 10, Y @ v


def test_fold_predicts_the_torque_of_the_full_theta(m, ident):
    """The fold against a direct computation: for any theta, the base columns of Y times
    fold(theta) are Y theta (the task force of eq. 13), at random states."""
    base = ident.base
    I = list(base.independent)
    rng = np.random.default_rng(7)
    for _ in range(5):
        theta = rng.normal(size=15) * np.abs(m.theta_nominal)
        pi = base.fold(theta)
        assert pi.shape == (13,)
        # and as the matrix P of the physically consistent solution sees it
        assert np.allclose(base.matrix() @ theta, pi, rtol=0, atol=1e-15 * np.abs(theta).max())
        for _, Y in _states(m, 5, 11):
            assert np.allclose(Y[:, I] @ pi, Y @ theta, rtol=0,
                               atol=1e-12 * np.abs(Y).max() * np.abs(theta).max())
        # moving theta along the null space changes no base parameter
        assert np.allclose(base.fold(theta + ident.null_space @ rng.normal(size=2)), pi,
                           rtol=0, atol=1e-12)


def test_unfold_keeps_the_dependent_entries(m, ident):
    base = ident.base
    pi = base.fold(theta_truth(m))
    th = base.unfold(pi, m.theta_nominal)
    assert np.allclose(base.fold(th), pi, rtol=1e-13, atol=1e-15)
    D = list(base.dependent)
    assert np.array_equal(th[D], m.theta_nominal[D])


def test_base_parameters_are_frozen_and_checked(m, ident):
    base = ident.base
    with pytest.raises(ValueError):
        base.beta[0, 0] = 1.0
    with pytest.raises(AttributeError):
        base.independent = (0,)
    with pytest.raises(pm2dof.ArgumentError, match=r"must split the 15 parameter indices"):
        BaseParameters(base.independent[:-1], base.dependent, base.beta[:-1], base.names)
    with pytest.raises(pm2dof.ArgumentError, match=r"theta must have shape \(15,\), got \(14,\)"):
        base.fold(np.zeros(14))
    assert base == BaseParameters(list(base.independent), list(base.dependent),
                                  base.beta.copy(), list(base.names))
    assert base.labels()[0] == "alpha1 + 1 gamma2 + 1 gamma3"
    assert base.inertial.tolist() == [True] * 7 + [False] * 6


def test_multisine_starts_at_rest_and_is_consistent(m):
    ex = trajectory_of(m, multisine(m, duration=1.0))
    assert np.allclose(ex.xd_dot[0], 0.0, atol=1e-15)
    T = ex.period
    # central differences of the analytic signal match its derivatives to O(T^2 w^3 a)
    fd = (ex.xd[2:] - ex.xd[:-2]) / (2 * T)
    assert np.abs(fd - ex.xd_dot[1:-1]).max() < 1e-3 * np.abs(ex.xd_dot).max()


def test_fit_of_the_simulated_multisine_recovers_viscous_friction(m, ident):
    """Exact encoders, the default 4 s multi-sine through the log pipeline: viscous friction
    within 2 % of the truth (the Stribeck excess, which eq. 2 has no coordinate for, and the
    discretisation of the derivatives bias the rest)."""
    res = identify_log(m, simulated_log(m, quantise=False), base=ident.base, consistent=False)
    truth = ident.base.fold(theta_truth(m))
    for k, name in enumerate(res.independent_names):
        if name.startswith("fv"):
            assert abs(res.estimate[k] - truth[k]) < 0.02 * truth[k], (name, res.estimate[k])
    # the full theta keeps the dependent parameters at nominal and folds into the estimate
    th = res.theta0
    assert th.shape == (15,) and np.isfinite(th).all()
    assert np.allclose(ident.base.fold(th), res.estimate, rtol=1e-12, atol=1e-14)
    # the truth used for comparison is the plant's, not the nominal one
    assert not np.allclose(theta_truth(m), m.theta_nominal)
