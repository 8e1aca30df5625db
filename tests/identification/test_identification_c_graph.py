# The generated C read back as SX (exact derivatives) and the design's chain-rule constraint Jacobian.
from pathlib import Path

import numpy as np
import pytest

import pm2dof
from pm2dof.identification.base import base_parameters, region_center
from pm2dof.identification.c_graph import CGraphError, c_body, read_body, sx_function
from pm2dof.identification.design import random_start, sample_function
from pm2dof.identification.fit import MIN_JOINT_SPEED
from pm2dof.identification.sampled import fourier_basis, motion_matrices, sampled_outputs

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

ca = pytest.importorskip("casadi")

DESIGN_FUNCTIONS = ("ik", "Y", "S", "singularity_measures")
MODELS = sorted(p.stem for p in (Path(pm2dof.__file__).parent / "models").glob("*.toml"))


def _inputs(model, f, rng):
    """Random arguments of ``f`` (an SX function read from the model's C): a pose near the
    region's centre for xe, its ik for q, normal draws for the rest."""
    x = region_center(model) + 0.005 * rng.normal(size=model.dof)
    out = []
    for k in range(f.n_in()):
        name, size = f.name_in(k), f.size1_in(k)
        out.append(x if name == "xe" else np.asarray(model.ik(x)) if name == "q"
                   else rng.normal(size=size))
    return out


@pytest.mark.parametrize("name", MODELS)
def test_sx_reading_is_the_compiled_function(name):
    """Each function the design uses, read from the C as SX, gives the compiled library's
    values (casadi.external on model.library) at random arguments, and its exact Jacobian
    matches central differences of the library."""
    model = pm2dof.load_model(name)
    rng = np.random.default_rng(7)
    for short in DESIGN_FUNCTIONS:
        f = sx_function(model, short)
        assert f.is_a("SXFunction")
        ext = ca.external(f"{model.name}_{short}", model.library)
        extra = [ca.DM(model.design)] if ext.n_in() > f.n_in() else []
        for _ in range(4):
            args = _inputs(model, f, rng)
            got = [np.array(o) for o in f.call(args)]
            want = [np.array(o) for o in ext.call(args + extra)]
            for g, w in zip(got, want):
                np.testing.assert_allclose(g, w, rtol=1e-13, atol=1e-13)
            # exact Jacobian of the first output with respect to the first input
            h = 1e-6
            sym = ca.SX.sym("u", f.size1_in(0))
            J = ca.Function("J", [sym], [ca.jacobian(f.call([sym] + [ca.DM(a) for a in
                                                                     args[1:]])[0], sym)])
            Jx = np.array(J(args[0]))
            fd = np.column_stack([
                (np.array(ext.call([args[0] + e] + args[1:] + extra)[0])
                 - np.array(ext.call([args[0] - e] + args[1:] + extra)[0])).ravel() / (2 * h)
                for e in h * np.eye(len(args[0]))])
            assert np.abs(Jx - fd).max() <= 1e-5 * max(1.0, np.abs(fd).max()), short


def test_not_straight_line_code_is_refused():
    """A body with anything but the straight-line forms (a loop, a call of another function,
    a name CasADi does not write) raises CGraphError naming the function and the line; an
    output left unwritten and an absent function too. The accepted forms read as SX."""
    src = ("/* toy_f:(x[2])->(y[2]) */\nstatic int casadi_f0(const casadi_real** arg, "
           "casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {\n"
           "  casadi_real a0;\n  a0=arg[0]? arg[0][0] : 0;\n  return 0;\n}\n")
    assert c_body(src, "toy_f") == ["  casadi_real a0;", "  a0=arg[0]? arg[0][0] : 0;",
                                    "  return 0;"]
    with pytest.raises(CGraphError, match="no function toy_g"):
        c_body(src, "toy_g")
    x = ca.SX.sym("x", 2)
    inputs = [x.nonzeros()]
    good = ["a0=arg[0]? arg[0][0] : 0;", "a1=arg[0]? arg[0][1] : 0;", "a2=atan2(a0,a1);",
            "a3=casadi_sq(a0);", "a3=(a3+a2);", "a4=(a0<a1);", "a4=(a4?a3:0);",
            "if (res[0]!=0) res[0][0]=a4;", "if (res[0]!=0) res[0][1]=a2;"]
    y = read_body(good, inputs, [2], "toy_f")[0]
    f = ca.Function("f", [x], [ca.vertcat(*y)])
    np.testing.assert_allclose(np.array(f([0.3, 0.7])).ravel(),
                               [0.09 + np.arctan2(0.3, 0.7), np.arctan2(0.3, 0.7)], rtol=1e-15)
    np.testing.assert_allclose(np.array(f([0.7, 0.3])).ravel(), [0.0, np.arctan2(0.7, 0.3)],
                               rtol=1e-15)
    for bad, why in ((["for (i=0; i<2; ++i) w[i] = 0;"], "not straight-line"),
                     (["casadi_f3(arg, res, iw, w, 0);"], "not straight-line"),
                     (["a0=system(a1);"], "cannot read"),
                     (['a0=eval("1");'], "cannot read"),
                     (["a0=(1.).__class__;"], "cannot read"),        # no attribute access
                     (["a0=1.0.real;"], "cannot read"),
                     (["a0=__import__;"], "cannot read"),
                     (["a0=arg[0]? arg[0][0] : 0;", "if (res[0]!=0) res[0][0]=a0;"],
                      r"output\(s\) \[0\] not written")):
        with pytest.raises(CGraphError, match=why):
            read_body(bad, inputs, [2], "toy_f")


def test_design_uses_the_exact_graph():
    """The design's per-sample function is SX (exact derivatives) for every shipped model, with
    the finite-difference version's values."""
    for name in ("shang2010", "rrr3_platform"):
        model = pm2dof.load_model(name)
        I = list(base_parameters(model).independent)
        f = sample_function(model, I, smooth_sign=MIN_JOINT_SPEED)
        assert f.is_a("SXFunction")


@pytest.mark.parametrize("name", ["shang2010", "rrr3_platform"])
def test_chain_rule_constraints_equal_the_direct_graph(name):
    """sampled_outputs (torque, singularity measures at K samples, Jacobian per sample x basis)
    gives the values and the Jacobian of the direct formulation (the motion as an MX graph of
    z, the per-sample function mapped over it, CasADi's own AD) at random coefficients."""
    model = pm2dof.load_model(name)
    m, L, K, f0 = model.dof, 4, 60, 0.5
    I = list(base_parameters(model).independent)
    per_sample = sample_function(model, I, smooth_sign=MIN_JOINT_SPEED)
    z = ca.MX.sym("z", 2 * m * L + m)
    A, B, c = ca.reshape(z[:m * L], L, m), ca.reshape(z[m * L:2 * m * L], L, m), z[2 * m * L:]
    Pa, Pb, Va, Vb, Aa, Ab = (ca.DM(M) for M in fourier_basis(f0, L, np.arange(K) / (K * f0)))
    X = ca.mtimes(Pa, A) + ca.mtimes(Pb, B) + ca.repmat(c.T, K, 1)
    V, Acc = ca.mtimes(Va, A) + ca.mtimes(Vb, B), ca.mtimes(Aa, A) + ca.mtimes(Ab, B)
    _, T, S = per_sample.map(K)(X.T, V.T, Acc.T)
    direct = ca.vertcat(ca.vec(T), ca.vec(S))
    chained = sampled_outputs(per_sample, (1, 2), f0, L, m, np.arange(K) / (K * f0))(z)
    both = ca.Function("both", [z], [direct, chained, ca.jacobian(direct, z),
                                     ca.jacobian(chained, z)])
    for seed in range(3):
        start = random_start(model, base_hz=f0, harmonics=L, periods=1, v_max=0.5, a_max=10.0,
                             radius=0.06, seed=seed)
        z0 = np.concatenate([start.a.ravel(), start.b.ravel(), start.center])
        g1, g2, J1, J2 = (np.array(o) for o in both(z0))
        np.testing.assert_allclose(g2, g1, rtol=1e-13, atol=1e-12)
        np.testing.assert_allclose(J2, J1, rtol=1e-10, atol=1e-10 * np.abs(J1).max())


def test_motion_matrices_are_the_series():
    """motion_matrices maps z to the series' x, xd, xdd of FourierExcitation.evaluate."""
    from pm2dof.identification.signals import FourierExcitation
    rng = np.random.default_rng(3)
    m, L, f0 = 3, 5, 0.4
    a, b, c = rng.normal(size=(m, L)), rng.normal(size=(m, L)), rng.normal(size=m)
    z = np.concatenate([a.ravel(), b.ravel(), c])
    t = np.linspace(0, 2.5, 17)
    D = motion_matrices(f0, L, m, t)
    x, v, acc = FourierExcitation(f0, 1, c, a, b).evaluate(t)
    got = np.column_stack([d @ z for d in D])
    np.testing.assert_allclose(got, np.hstack([x, v, acc]), rtol=1e-12, atol=1e-12)
