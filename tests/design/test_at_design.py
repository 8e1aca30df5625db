# Model.at_design rebinds the functions it already resolved: the same bits, independent models.
"""``Model.at_design`` clones each of the model's bound functions at the new design
(``Function.clone``: no symbol lookup, no sparsity read) instead of resolving the library again.

The reference is the library's own function without a bound design, resolved here afresh and
called with the design as its last input: every generated function of a model at a design gives
its bits, on the paper's robot (la, lb, b2x) and on the 4-RRR platform (la, lb). Two models of
one library at different designs, and the model they came from, stay independent however their
calls interleave and whichever is dropped first; each keeps its own scratch buffers and working
modes. A model is immutable.
"""
import gc

import numpy as np
import pytest

import pm2dof
from pm2dof.core import _cbind
from pm2dof.core.model import Model

#: (model, a pose inside every design's workspace, designs to try)
CASES = {
    "shang2010_design": ((0.25, 0.26), ({"la": 0.21, "lb": 0.30, "b2x": 0.40},
                                        {"la": 0.30, "lb": 0.27, "b2x": 0.47})),
    "rrr4_platform_design": ((0.01, 0.01, 0.05), ({"la": 0.17, "lb": 0.24},
                                                  {"la": 0.25, "lb": 0.16})),
}


@pytest.fixture(scope="module", params=sorted(CASES))
def base(request):
    return pm2dof.load_model(request.param)


def _inputs(model, f, pose, rng):
    """Inputs for ``f`` by name: the pose, its joint coordinates, the nominal theta; small
    random numbers for the rest (the same for both calls compared)."""
    q = model.ik(np.array(pose))
    n, m = model.n_legs, model.dof
    known = {("q", 2 * n): q, ("qa", n): q[:n], ("theta", len(model.param_names)):
             np.array(model.theta_nominal)}
    out = []
    for name, size in zip(f.names_in, f.sizes_in):
        if (name, size) in known:
            out.append(np.ascontiguousarray(known[name, size], dtype=float))
        elif size == m and name in ("xe", "xd", "p"):
            out.append(np.array(pose, dtype=float))
        else:
            out.append(0.01 * rng.standard_normal(size))
    return out


def _call(f, args):
    outs = [np.empty(k) for k in f.sizes_out]
    f(*args, *outs)
    return outs


def test_every_function_at_a_design_equals_the_unbound_function_given_the_design(base):
    pose, designs = CASES[base.name]
    lib = _cbind.Library(base.library)
    for design in designs:
        m2 = base.at_design(design)
        d = np.array([design[k] for k in base.design_names])
        np.testing.assert_array_equal(m2.design, d)
        for short, f in m2._f.items():
            mine = base._f[short]
            assert f is not mine and f.library is mine.library is base._lib
            assert f.check_outputs == mine.check_outputs
            plain = _cbind.Function(lib, f.name)
            plain.check_outputs = f.check_outputs = False            # compare NaN too
            rng = np.random.default_rng(abs(hash(short)) % 2 ** 32)
            args = _inputs(m2, f, pose, rng)
            if mine.fixed is None:                                   # the design not an input
                assert f.fixed is None and plain.signature == f.signature
                want = _call(plain, args)
            else:
                assert f.fixed == tuple(d) and mine.fixed == tuple(base.design)
                want = _call(plain, args + [d])
            for got, ref in zip(_call(f, args), want):
                np.testing.assert_array_equal(got, ref, err_msg=f"{base.name} {short}")


def test_the_models_match_one_resolved_afresh(base):
    """at_design's clones and the full path (every function resolved again, its signature
    checked against the manifest) give the same model."""
    pose, designs = CASES[base.name]
    from pm2dof.core.design import spec_at_design
    spec = spec_at_design(base.spec, designs[0])
    fresh = Model.__new__(Model)
    fresh._bind(spec, base.generated, base._manifest_obj, base.library,
                _cbind.Library(base.library))
    m2 = base.at_design(designs[0])
    assert set(fresh._f) == set(m2._f)
    assert m2._layouts is base._layouts and m2.manifest is base.manifest
    q = m2.ik(np.array(pose))
    np.testing.assert_array_equal(q, fresh.ik(np.array(pose)))
    np.testing.assert_array_equal(m2.fk(q[:m2.n_legs]), fresh.fk(q[:m2.n_legs]))
    np.testing.assert_array_equal(m2.Me(q, m2.theta_nominal), fresh.Me(q, fresh.theta_nominal))
    np.testing.assert_array_equal(m2.theta_nominal, fresh.theta_nominal)
    np.testing.assert_array_equal(m2.W(q), fresh.W(q))
    assert m2._modes == fresh._modes


def test_models_at_two_designs_and_their_source_stay_independent(base):
    pose, (d1, d2) = CASES[base.name]
    x = np.array(pose)
    want = {}
    for d in (d1, d2):
        alone = base.at_design(d)
        want[tuple(d.values())] = (alone.ik(x), alone.Me(alone.ik(x), alone.theta_nominal))
    q0, Me0 = base.ik(x), base.Me(base.ik(x), base.theta_nominal)
    m1, m2 = base.at_design(d1), base.at_design(d2)
    assert not np.array_equal(m1.ik(x), m2.ik(x))
    for _ in range(3):                                               # interleaved
        for m, d in ((m1, d1), (base, None), (m2, d2)):
            q, Me = (q0, Me0) if d is None else want[tuple(d.values())]
            np.testing.assert_array_equal(m.ik(x), q)
            np.testing.assert_array_equal(m.Me(m.ik(x), m.theta_nominal), Me)
    assert m1._sing is not m2._sing and m1._residual is not base._residual
    assert m1._fast["ik"] is not m2._fast["ik"]
    again = m1.at_design(d2)                                         # a model of a model
    np.testing.assert_array_equal(again.ik(x), want[tuple(d2.values())][0])
    del m1
    gc.collect()
    np.testing.assert_array_equal(m2.ik(x), want[tuple(d2.values())][0])
    np.testing.assert_array_equal(base.ik(x), q0)
    with pytest.raises(AttributeError, match="immutable"):
        m2._f = {}
    with pytest.raises(TypeError):
        m2._f["ik"] = m2._f["fk"]


def test_a_refused_design_leaves_the_source_as_it_was(base):
    pose, _ = CASES[base.name]
    q0 = base.ik(np.array(pose))
    lo = base.design_bounds[0, 0]
    with pytest.raises(pm2dof.DesignError, match=base.design_names[0]):
        base.at_design({base.design_names[0]: lo - 0.01})
    np.testing.assert_array_equal(base.ik(np.array(pose)), q0)
    assert all(f.fixed in (None, tuple(base.design)) for f in base._f.values())


def test_a_design_binds_only_what_it_uses_and_every_view_sees_all(base):
    pose, (d1, _) = CASES[base.name]
    m2 = base.at_design(d1)
    inner = gc.get_referents(m2._f)[0]                                # behind the proxy
    n_bound = dict.__len__(inner)
    assert n_bound == (1 if base.dof == 3 else 0)                     # a platform's ik at home
    assert list(m2._f.copy()) == list(base._f) and len(m2._f) == len(base._f)
    assert dict.__len__(inner) == len(base._f)
    m3 = base.at_design(d1)
    f = m3.function("ik")
    assert m3.function("ik") is f and "Me" in m3._f and "nosuch" not in m3._f
    with pytest.raises(KeyError):
        m3.function("nosuch")
    assert m3._f.get("nosuch") is None and m3._f.get("ik") is f
    assert list(m3._f) == list(base._f)                               # the loaded model's order
    assert [g.name for g in m3._f.values()] == [g.name for g in base._f.values()]
    assert m3.function("ik") is f                                     # kept when the rest bound
    m4 = base.at_design(d1)
    assert "W" not in m4._fast                                        # nothing built yet
    q = m4.ik(np.array(pose))
    W = m4.W(q)                                                       # built on its first call
    assert "W" in m4._fast and type(m4._fast["W"]) is _cbind.Method
    assert "Me" not in m4._fast                                       # only what it called
    np.testing.assert_array_equal(W, m2.W(q))
    chain = base
    for _ in range(3):                                                # a model of a model of ...
        chain = chain.at_design(d1)
    assert chain._root is base._root
    np.testing.assert_array_equal(chain.W(q), W)


def test_a_model_at_a_design_is_freed_without_the_garbage_collector(base):
    """No reference cycle (the fast paths built on first use hold the model's functions and
    buffers, not the model): a design study's thousands of models go as soon as they are
    dropped, also with gc off (the benchmarks)."""
    import weakref
    pose, (d1, _) = CASES[base.name]
    x = np.array(pose)
    gc.disable()
    try:
        for _ in range(3):
            m2 = base.at_design(d1)
            q = m2.ik(x)
            m2.W(q)
            m2.function("singularity_measures")
            ref = weakref.ref(m2)
            Me = m2.Me(q, base.theta_nominal)
            fast = m2._fast["Me"]                       # a fast path, kept beyond the model
            del m2
            assert ref() is None
            np.testing.assert_array_equal(fast(q, base.theta_nominal, None), Me)
    finally:
        gc.enable()
