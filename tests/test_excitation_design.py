# Optimal excitation: constraints hold at dense samples, rest at both ends, the CasADi graph is the model's C, file round trip.
import numpy as np
import pytest

import pm2dof
from pm2dof import cli
from pm2dof.analysis.excitation_design import (ExcitationError, FourierExcitation,
                                               check_excitation, design_excitation,
                                               load_excitation, regressor_condition,
                                               sample_function, trajectory_of, write_excitation)
from pm2dof.analysis.ident_log import read_log
from pm2dof.analysis.identify import identifiability

LIMITS = {"v_max": 0.4, "a_max": 6.0, "tau_fraction": 0.3}


@pytest.fixture(scope="module")
def m():
    return pm2dof.load_model()


@pytest.fixture(scope="module")
def designed(m):
    """A small design (4 harmonics of 0.5 Hz, one 2 s period; a few seconds of IPOPT) with
    limits below the defaults, so that some of them bind."""
    return design_excitation(m, base_hz=0.5, harmonics=4, periods=1, samples=80,
                             constraint_samples=200, **LIMITS)


def test_design_meets_every_constraint_every_millisecond(m, designed):
    exc = designed
    assert exc.info["ipopt_status"] == "Solve_Succeeded"
    tau_limit = LIMITS["tau_fraction"] * np.max(m.spec.limits["tau_max"])
    chk = check_excitation(m, exc, v_max=LIMITS["v_max"], a_max=LIMITS["a_max"],
                           tau_limit=tau_limit, sing_min=0.2, radius=0.06, step=1e-3)
    assert chk["ok"], chk
    # the design uses its room: the speed limit binds (within the 2 % safety factor)
    assert chk["speed"] > 0.95 * LIMITS["v_max"], chk
    # starts and ends at rest, and is periodic
    x, v, a = exc.evaluate([0.0, exc.duration])
    assert np.abs(v).max() < 1e-12 and np.abs(a).max() < 1e-9
    assert np.allclose(x[0], x[1], rtol=0, atol=1e-12)
    # better conditioned than its random start, and more informative
    assert exc.info["cond_after"] < exc.info["cond_before"] / 2
    assert exc.info["logdet_after"] > exc.info["logdet_before"]


def test_casadi_graph_is_the_model_c(m):
    """The design's per-sample function (casadi.external on the compiled library) gives the
    Model's Y, min-norm torque and singularity measures."""
    ident = identifiability(m)
    I = ident["independent"]
    f = sample_function(m, I)
    # the design's smooth Coulomb columns S^T e_i tanh(qd_i / d) become the C's sign() as d -> 0
    f_sharp = sample_function(m, I, smooth_sign=1e-12)
    rng = np.random.default_rng(4)
    for _ in range(5):
        x = np.array([0.245, 0.265]) + rng.uniform(-0.04, 0.04, 2)
        v, a = rng.normal(0, 0.3, 2), rng.normal(0, 5, 2)
        Yv, tau, sing = (np.array(o).ravel() for o in f(x, v, a))
        q = m.ik(x)
        assert np.allclose(Yv.reshape(len(I), 2).T, m.Y(q, v, v, a)[:, I], rtol=1e-12, atol=1e-12)
        assert np.allclose(np.array(f_sharp(x, v, a)[0]).ravel(), Yv, rtol=1e-12, atol=1e-12)
        S = m.S(q)
        ref = m.torque_splits(q, m.Y(q, v, v, a) @ m.theta_nominal)["min_norm"]  # eq. 21 in C
        assert np.allclose(tau, ref, rtol=1e-10, atol=1e-10)
        assert np.allclose(S.T @ tau, m.Y(q, v, v, a) @ m.theta_nominal, rtol=1e-10, atol=1e-10)
        assert np.allclose(sing, m.singularity_measures(q), rtol=0, atol=1e-14)
        # and its finite-difference derivative agrees with differences of the Model's Y
        import casadi as ca
        xs = ca.MX.sym("x", 2)
        J = ca.Function("J", [xs], [ca.jacobian(f(xs, v, a)[0], xs)])(x).full()
        h = 1e-6
        fd = np.column_stack([(m.Y(m.ik(x + e), v, v, a)[:, I] - m.Y(m.ik(x - e), v, v, a)[:, I]
                               ).T.ravel() / (2 * h) for e in (np.array([h, 0]), np.array([0, h]))])
        assert np.abs(J - fd).max() < 1e-4 * max(1.0, np.abs(fd).max())


def test_file_round_trip_and_bad_files(tmp_path, m, designed):
    p = write_excitation(tmp_path / "exc.toml", designed, m)
    back = load_excitation(p, m)
    for k in ("center", "a", "b"):
        assert np.array_equal(getattr(back, k), getattr(designed, k)), k
    assert back.base_hz == designed.base_hz and back.periods == designed.periods
    assert back.info["cond_after"] == designed.info["cond_after"]
    text = p.read_text()
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace('model = "shang2010"', 'model = "fivebar"'))
    with pytest.raises(ExcitationError, match="model 'fivebar', not 'shang2010'"):
        load_excitation(bad, m)
    bad.write_text("\n".join(l for l in text.splitlines() if not l.startswith("b_y")))
    with pytest.raises(ExcitationError, match="misses key 'b_y'"):
        load_excitation(bad, m)
    moving = FourierExcitation(0.5, 1, designed.center, designed.a + 0.01, designed.b)
    write_excitation(bad, moving, m)
    with pytest.raises(ExcitationError, match="does not start at rest"):
        load_excitation(bad, m)


def test_excite_runs_the_file(tmp_path, m, designed, capsys):
    p = write_excitation(tmp_path / "exc.toml", designed, m)
    logp = tmp_path / "run.parquet"
    assert cli.main(["identify", "--excite", "--excitation", str(p), "--out", str(logp)]) == 0
    capsys.readouterr()
    log = read_log(logp)
    traj = trajectory_of(m, designed)
    assert len(log.t) == len(traj.t) and float(log.meta["excitation_max_hz"]) == 2.0
    # the optimised motion is better conditioned than the default multi-sine of --excite
    from pm2dof.analysis.identify import excitation
    ident = identifiability(m)
    assert (regressor_condition(m, ident, traj)[0]
            < regressor_condition(m, ident, excitation(m, duration=designed.duration))[0])
