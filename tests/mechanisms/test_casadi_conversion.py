"""Issue 26: every expression the generic derivation hands to CasADi converts (Converter), and
gives the lambdified value: q's trig from the angular coordinates only (kin.angular), the
prismatic coordinates as values; the platform's fk step; the energies."""
import casadi as ca
import numpy as np
import pytest
import sympy as sp

from pm2dof.derive.to_casadi import Converter
from tests.mechanisms.test_independent import Setup

CASES = ["shang2010_vertical", "prr_point_gravity", "rpr_point_gravity", "rrr3_platform",
         "mixed_platform_gravity"]


@pytest.mark.parametrize("name", CASES)
def test_expressions_convert_and_agree(name):
    s = Setup(name, seed=10)
    lam, kin, dyn, sym = s.lam, s.lam.kin, s.lam.dyn, s.lam.sym
    xe, q, xed = s.state()
    xrd, xrdd = s.rng.normal(size=lam.m), s.rng.normal(size=lam.m)
    tau = s.rng.normal(size=lam.n)
    values = {**dict(zip(sym.q, q)), **dict(zip(sym.xe, xe)), **dict(zip(sym.xed, xed)),
              **dict(zip(sym.xrd, xrd)), **dict(zip(sym.xrdd, xrdd)),
              **dict(zip(sym.tau_a, tau)), **dict(zip(sym.theta, s.theta)),
              **dict(zip(sym.qd, lam.W(q, xe) @ xed))}
    symbols = {k: ca.SX(float(v)) for k, v in values.items()}
    trig = {sym.q[k]: (ca.SX(np.cos(q[k])), ca.SX(np.sin(q[k])))
            for k in range(2 * lam.n) if kin.angular[k]}
    assert kin.angular == [k == "RRR" for k in kin.kinds] + [True] * lam.n
    conv = Converter(symbols, trig)
    exprs = {"W": kin.W, "Wdot": kin.Wdot, "Me": dyn.Me, "Ce": dyn.Ce, "Ge": dyn.Ge,
             "StF": dyn.StF, "Y": dyn.Y, "xedd": dyn.xedd, "ik": kin.ik(),
             "T": sp.Matrix([dyn.kinetic_energy]), "V": sp.Matrix([dyn.potential_energy]),
             "measures": sp.Matrix([kin.leg_measure(i) for i in range(lam.n)]),
             "lines": kin.wrench_lines(), "pose": kin.pose_from_q(),
             "residual": kin.fk_residual()}
    if kin.platform:
        exprs["newton"] = kin.fk_newton_step()
        exprs["parallel_measure"] = sp.Matrix([kin.parallel_measure()])
    else:
        exprs["fk"] = kin.fk()
    for what, e in exprs.items():
        got = np.array(ca.evalf(conv(e)), dtype=float).ravel()
        want = np.array(sp.lambdify([], e.xreplace(values), "numpy")(), dtype=float).ravel() \
            if what not in ("StF", "Y", "xedd") else None
        if want is None:   # sgn(): evaluate by lambdify with the same mapping as the tests
            fn = {"StF": lam.StF, "Y": lam.Y, "xedd": lam.xedd}[what]
            want = np.asarray(fn(q, xe, xed, xrd, xrdd, tau, s.theta), float).ravel()
        np.testing.assert_allclose(got, want, rtol=1e-10, atol=1e-12 * max(1, np.abs(want).max()),
                                   err_msg=what)
        # no cos/sin of a prismatic coordinate anywhere
        for f in e.atoms(sp.cos, sp.sin):
            for k in range(2 * lam.n):
                if not kin.angular[k]:
                    assert sym.q[k] not in f.free_symbols, (what, f)
