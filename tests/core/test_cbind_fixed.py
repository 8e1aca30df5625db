"""``Function(library, name, fixed=d)``: the last input "design" bound once for all.

The reference is the same generated function without ``fixed``, called with ``d`` as its last
input: every path of the bound Function (a plain call, ``Method``, ``map``, ``accumulate``,
``accumulate_batch``, ``time_calls``; a temporary work area when the Function is busy) must
give the same bits. CasADi's own evaluation checks the reference itself. The library holds an
SX function, an MX function calling a nested function (its generated code writes the nested
call's arguments into ``arg[n_in:]``, beyond the bound slot), a closed-loop step whose
visible inputs fit ``accumulate``, and functions ``fixed`` must refuse. A small hand-written C
function (CasADi's external API) calls back into Python while it runs, so a second call finds
the Function busy, deterministically.
"""

from __future__ import annotations

import array
import ctypes
import gc
import sys
import threading
import tracemalloc

import casadi as ca
import numpy as np
import pytest

from pm2dof.core import _cbind, binding, build
from pm2dof.core.errors import ArgumentError, ArgumentTypeError

D_SX = np.array([0.7, -1.3])            # a design for sxd and stepd
D_MX = np.array([0.4, 1.1, -0.6])       # a design for mxd


def _casadi_functions() -> dict[str, ca.Function]:
    q, p, d = ca.SX.sym("q", 3), ca.SX.sym("p", 2), ca.SX.sym("design", 2)
    sxd = ca.Function(
        "sxd", [q, p, d],
        [ca.vertcat(ca.sin(q[0]) * d[0] + p[0] * q[1], ca.cos(q[1] * d[1]) + q[2] * p[1],
                    d[0] * d[1] * q[2] + ca.exp(-p[1] ** 2)),
         ca.densify(ca.horzcat(q[0:2] * d[0], q[1:3] * d[1] + p[0]))],
        ["q", "p", "design"], ["v", "M"])

    a, dd, z = ca.SX.sym("a", 2), ca.SX.sym("d", 3), ca.SX.sym("z")
    inner = ca.Function("inner", [a, dd, z],
                        [ca.vertcat(ca.sin(a[0]) * dd[0] + a[1] * dd[1], a[0] * a[1] + dd[2] * z)],
                        ["a", "d", "z"], ["b"])
    qm, D = ca.MX.sym("q", 2), ca.MX.sym("design", 3)
    b1 = inner(qm, D, 0.5)
    b2 = inner(b1, D, qm[0])                 # nested calls: not inlined into mxd
    mxd = ca.Function("mxd", [qm, D], [b2, ca.sum1(b1)], ["q", "design"], ["y", "s"])

    x, u, k, ds = ca.SX.sym("x", 3), ca.SX.sym("u", 2), ca.SX.sym("p"), ca.SX.sym("design", 2)
    A = ca.vertcat(ca.horzcat(0.9 * ds[0], 0.1, 0.0), ca.horzcat(-0.1, 0.8, 0.05 * ds[1]),
                   ca.horzcat(0.0, 0.02, 0.95))
    B = ca.DM([[1.0, 0.0], [0.5, 0.25], [0.0, 1.0]])
    stepd = ca.Function("stepd", [x, u, k, ds],
                        [A @ x + B @ u * k, ca.vertcat(x[0] * ds[1], x[1] - x[2])],
                        ["x", "u", "p", "design"], ["x_next", "y"])

    xn, pn = ca.SX.sym("x", 2), ca.SX.sym("p", 2)
    nodesign = ca.Function("nodesign", [xn, pn], [xn * pn], ["x", "p"], ["y"])
    dm = ca.SX.sym("design", 2, 2)
    matd = ca.Function("matd", [xn, dm], [ca.densify(dm @ xn)], ["x", "design"], ["y"])
    d1 = ca.SX.sym("design")
    only = ca.Function("only", [d1], [ca.vertcat(d1 * 2, ca.sin(d1))], ["design"], ["y"])
    return {"sxd": sxd, "mxd": mxd, "stepd": stepd, "nodesign": nodesign, "matd": matd,
            "only": only}


@pytest.fixture(scope="module")
def generated(tmp_path_factory):
    """(library, {name: casadi.Function}) for CasADi-generated code."""
    d = tmp_path_factory.mktemp("gen_fixed")
    funcs = _casadi_functions()
    cg = ca.CodeGenerator("fixed.c", {"with_header": True})
    for f in funcs.values():
        cg.add(f)
    cg.generate(str(d) + "/")
    so = build.compile_library(d / "fixed.c", d / "libfixed.so")
    return _cbind.Library(str(so)), funcs


@pytest.fixture(scope="module")
def lib(generated):
    return generated[0]


HOOK_C = r"""
/* hookd(x[2], design[2]) -> (y[2]) in CasADi's external C API. It calls a hook (set from
   Python through ctypes) before it reads its arguments, once per setting: the hook calls the
   same Function again, which finds its work area busy. Lifecycle counters for the tests. */
typedef long long int casadi_int;
typedef double casadi_real;
typedef void (*hook_t)(void);
static hook_t hook;
void set_hook(hook_t h) { hook = h; }
int n_incref, n_decref, n_checkout, n_release;
int stub_counter(int i) {
  return i == 0 ? n_incref : i == 1 ? n_decref : i == 2 ? n_checkout : n_release;
}
static const casadi_int sp_v2[3] = {2, 1, 1};
int hookd(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  (void)iw; (void)w; (void)mem;
  hook_t h = hook;
  hook = 0;
  if (h) h();
  if (res[0]) {
    res[0][0] = arg[0][0] * arg[1][0] + arg[1][1];
    res[0][1] = arg[0][1] * arg[1][1] - arg[1][0];
  }
  return 0;
}
casadi_int hookd_n_in(void) { return 2; }
casadi_int hookd_n_out(void) { return 1; }
const casadi_int* hookd_sparsity_in(casadi_int i) { return i <= 1 ? sp_v2 : 0; }
const casadi_int* hookd_sparsity_out(casadi_int i) { return i == 0 ? sp_v2 : 0; }
int hookd_work(casadi_int* a, casadi_int* r, casadi_int* iw, casadi_int* w) {
  if (a) *a = 2; if (r) *r = 1; if (iw) *iw = 0; if (w) *w = 0; return 0;
}
static const char* names_in[2] = {"x", "design"};
const char* hookd_name_in(casadi_int i) { return i >= 0 && i < 2 ? names_in[i] : 0; }
const char* hookd_name_out(casadi_int i) { return i == 0 ? "y" : 0; }
int hookd_checkout(void) { n_checkout++; return 0; }
void hookd_release(int mem) { (void)mem; n_release++; }
void hookd_incref(void) { n_incref++; }
void hookd_decref(void) { n_decref++; }
"""


@pytest.fixture(scope="module")
def hook_path(tmp_path_factory):
    d = tmp_path_factory.mktemp("hook")
    (d / "hook.c").write_text(HOOK_C)
    return build.compile_library(d / "hook.c", d / "libhook.so", extra_flags=["-Wall"])


@pytest.fixture(scope="module")
def hook_lib(hook_path):
    """(Library, ctypes view of the same loaded object: set_hook, stub_counter)."""
    return _cbind.Library(str(hook_path)), ctypes.CDLL(str(hook_path))


def _hookd_ref(x, d):
    return np.array([x[0] * d[0] + d[1], x[1] * d[1] - d[0]])


# --------------------------------------------------------------------------------------
# What the bound Function shows
# --------------------------------------------------------------------------------------


def test_the_bound_function_shows_the_other_inputs(lib):
    plain = _cbind.Function(lib, "sxd")
    f = _cbind.Function(lib, "sxd", fixed=D_SX)
    assert plain.fixed is None and _cbind.Function(lib, "sxd", fixed=None).fixed is None
    assert f.fixed == (0.7, -1.3) and all(type(v) is float for v in f.fixed)
    assert (f.n_in, f.n_out) == (2, 2)
    assert f.names_in == ("q", "p") and f.sizes_in == (3, 2)
    assert f.shapes_in == ((3, 1), (2, 1))
    assert f.names_out == plain.names_out and f.sizes_out == plain.sizes_out
    assert f.shapes_out == plain.shapes_out == ((3, 1), (2, 2))
    assert f.signature == "sxd(q[3], p[2]) -> (v[3], M[4])"
    assert plain.signature == "sxd(q[3], p[2], design[2]) -> (v[3], M[4])"
    assert repr(f) == "<Function sxd(q[3], p[2]) -> (v[3], M[4]), design[2] fixed>"
    with pytest.raises(AttributeError):
        f.fixed = (1.0, 2.0)                                   # read-only
    with pytest.raises(TypeError):
        _cbind.Function(lib, "sxd", D_SX)                      # keyword-only
    step = _cbind.Function(lib, "stepd", fixed=D_SX)
    assert step.signature == "stepd(x[3], u[2], p[1]) -> (x_next[3], y[2])"
    only = _cbind.Function(lib, "only", fixed=0.25)            # no visible input left
    assert only.n_in == 0 and only.names_in == () and only.fixed == (0.25,)
    y = np.empty(2)
    only(y)
    np.testing.assert_array_equal(y, [0.5, np.sin(0.25)])


@pytest.mark.parametrize("values", [
    [0.7, -1.3], (0.7, -1.3), np.array([0.7, -1.3]), array.array("d", [0.7, -1.3]),
    np.array([0.7, 9.0, -1.3])[::2],                            # strided: copied in order
    [np.float64(0.7), -1.3], memoryview(np.array([0.7, -1.3])),
])
def test_accepted_forms_of_the_values(lib, values):
    assert _cbind.Function(lib, "sxd", fixed=values).fixed == (0.7, -1.3)


def test_integers_are_real_numbers(lib):
    assert _cbind.Function(lib, "sxd", fixed=[1, -2]).fixed == (1.0, -2.0)
    assert _cbind.Function(lib, "only", fixed=3).fixed == (3.0,)
    assert _cbind.Function(lib, "only", fixed=np.array(0.5)).fixed == (0.5,)   # 0-d


# --------------------------------------------------------------------------------------
# Every call path gives the bits of the unbound function called with the design
# --------------------------------------------------------------------------------------


def test_plain_call_equals_the_unbound_function_and_casadi(generated, lib):
    _, funcs = generated
    plain = _cbind.Function(lib, "sxd")
    f = _cbind.Function(lib, "sxd", fixed=D_SX)
    rng = np.random.default_rng(1)
    for _ in range(100):
        q, p = rng.standard_normal(3), rng.standard_normal(2)
        v, M, v0, M0 = np.empty(3), np.empty(4), np.empty(3), np.empty(4)
        f(q, p, v, M)
        plain(q, p, D_SX, v0, M0)
        np.testing.assert_array_equal(v, v0)
        np.testing.assert_array_equal(M, M0)
        ref_v, ref_M = (np.asarray(r) for r in funcs["sxd"](q, p, D_SX))
        np.testing.assert_array_equal(v, ref_v.ravel())       # -ffp-contract=off: same bits
        np.testing.assert_array_equal(M, ref_M.ravel(order="F"))
    v = np.empty(3)
    f(q, p, v, None)                                          # an output skipped
    np.testing.assert_array_equal(v, v0)


def test_nested_calls_do_not_overwrite_the_bound_slot(generated, lib):
    # mxd's generated code passes its nested calls' arguments in arg[2:] (its own n_in = 2):
    # the bound design in arg[1] must survive every call, so repeated calls agree.
    _, funcs = generated
    plain = _cbind.Function(lib, "mxd")
    f = _cbind.Function(lib, "mxd", fixed=D_MX)
    assert f.signature == "mxd(q[2]) -> (y[2], s[1])"
    rng = np.random.default_rng(2)
    for _ in range(50):
        q = rng.standard_normal(2)
        y, s, y0, s0 = np.empty(2), np.empty(1), np.empty(2), np.empty(1)
        f(q, y, s)
        plain(q, D_MX, y0, s0)
        np.testing.assert_array_equal(y, y0)
        np.testing.assert_array_equal(s, s0)
        ref_y, ref_s = (np.asarray(r).ravel() for r in funcs["mxd"](q, D_MX))
        np.testing.assert_allclose(y, ref_y, rtol=0, atol=1e-14)
        np.testing.assert_allclose(s, ref_s, rtol=0, atol=1e-14)
    assert f.fixed == tuple(D_MX)


def test_method_equals_the_unbound_function(lib):
    plain = _cbind.Function(lib, "sxd")
    f = _cbind.Function(lib, "sxd", fixed=D_SX)
    M_scratch = np.empty(4)
    meth = _cbind.Method(f, (None, None), ((3,), M_scratch), empty=np.empty)
    p = np.array([0.3, -0.2])
    preset = _cbind.Method(f, (None, p), ((3,), None), empty=np.empty, finite=True)
    rng = np.random.default_rng(3)
    for _ in range(20):
        q = rng.standard_normal(3)
        v0, M0 = np.empty(3), np.empty(4)
        plain(q, p, D_SX, v0, M0)
        v = meth(q, p, None)
        np.testing.assert_array_equal(v, v0)
        np.testing.assert_array_equal(M_scratch, M0)
        out = np.empty(3)
        assert preset(q, out) is out
        np.testing.assert_array_equal(out, v0)
    with pytest.raises(_cbind.Refused):                         # the checks still apply
        preset(np.array([np.nan, 0.0, 0.0]), None)


def test_map_equals_the_unbound_function(lib):
    plain = _cbind.Function(lib, "sxd")
    f = _cbind.Function(lib, "sxd", fixed=D_SX)
    rng = np.random.default_rng(4)
    K = 13
    Q, P = rng.standard_normal((K, 3)), rng.standard_normal((K, 2))
    V, M = np.empty((K, 3)), np.empty((K, 4))
    f.map(K, Q, P, V, M)
    V0, M0 = np.empty((K, 3)), np.empty((K, 4))
    plain.map(K, Q, P, D_SX, V0, M0)                          # the design broadcast
    np.testing.assert_array_equal(V, V0)
    np.testing.assert_array_equal(M, M0)
    for k in range(K):
        v, m = np.empty(3), np.empty(4)
        plain(Q[k], P[k], D_SX, v, m)
        np.testing.assert_array_equal(V[k], v)
        np.testing.assert_array_equal(M[k], m)
    V2 = np.empty((K, 3))
    f.map(K, Q, P[0], V2, None)                               # broadcast a visible input
    for k in range(K):
        v = np.empty(3)
        plain(Q[k], P[0], D_SX, v, None)
        np.testing.assert_array_equal(V2[k], v)
    with pytest.raises(TypeError, match=r"takes 5 arguments \(K, 2 inputs, 2 outputs\), got 6"):
        f.map(K, Q, P, np.tile(D_SX, (K, 1)), V, M)           # the design is no argument
    Ym, Sm = np.empty((K, 2)), np.empty((K, 1))
    fm = _cbind.Function(lib, "mxd", fixed=D_MX)
    fm.map(K, P, Ym, Sm)
    for k in range(K):
        y, s = np.empty(2), np.empty(1)
        _cbind.Function(lib, "mxd")(P[k], D_MX, y, s)
        np.testing.assert_array_equal(Ym[k], y)
        np.testing.assert_array_equal(Sm[k], s)


def _python_rollout(plain, x0, u_seq, p, design):
    x = np.array(x0, dtype=float)
    ys = []
    for u in u_seq:
        x_next, y = np.empty(3), np.empty(2)
        plain(x, u, p, design, x_next, y)
        x = x_next
        ys.append(y)
    return x, np.array(ys)


def test_accumulate_equals_a_loop_of_the_unbound_function(generated, lib):
    _, funcs = generated
    plain = _cbind.Function(lib, "stepd")
    f = _cbind.Function(lib, "stepd", fixed=D_SX)
    with pytest.raises(TypeError, match=r"stepd\.accumulate requires a function with 3 inputs"):
        plain.accumulate(np.zeros(3), np.zeros(2), 1.0, None)   # 4 inputs: does not fit
    rng = np.random.default_rng(5)
    for n in (1, 2, 301):                                     # odd and even step counts
        u_seq = rng.standard_normal((n, 2))
        x0 = rng.standard_normal(3)
        x_ref, y_ref = _python_rollout(plain, x0, u_seq, 0.7, D_SX)
        x, y_seq = x0.copy(), np.empty((n, 2))
        assert f.accumulate(x, u_seq, 0.7, y_seq) is None
        np.testing.assert_array_equal(x, x_ref)
        np.testing.assert_array_equal(y_seq, y_ref)
    xc = x0.copy()
    for k in range(3):                                        # and CasADi itself
        xn, yk = funcs["stepd"](xc, u_seq[k], 0.7, D_SX)
        np.testing.assert_array_equal(y_seq[k], np.asarray(yk).ravel())
        xc = np.asarray(xn).ravel()


def test_accumulate_batch_equals_a_loop_of_the_unbound_function(lib):
    plain = _cbind.Function(lib, "stepd")
    f = _cbind.Function(lib, "stepd", fixed=D_SX)
    rng = np.random.default_rng(6)
    n, K = 9, 4
    u_seq = rng.standard_normal((n, 2))
    X0, P = rng.standard_normal((K, 3)), rng.uniform(0.1, 0.9, (K, 1))
    X, Y = X0.copy(), np.empty((K, n, 2))
    f.accumulate_batch(X, u_seq, P, Y)
    for r in range(K):
        x_ref, y_ref = _python_rollout(plain, X0[r], u_seq, P[r], D_SX)
        np.testing.assert_array_equal(X[r], x_ref)
        np.testing.assert_array_equal(Y[r], y_ref)


def test_time_calls_runs_at_the_design(lib):
    plain = _cbind.Function(lib, "mxd")
    f = _cbind.Function(lib, "mxd", fixed=D_MX)
    q = np.array([0.3, -0.8])
    y, s, y0, s0 = np.full(2, np.nan), np.full(1, np.nan), np.empty(2), np.empty(1)
    times = f.time_calls(5, 2, q, y, s)
    assert len(times) == 2 and all(t > 0 for t in times)
    plain(q, D_MX, y0, s0)
    np.testing.assert_array_equal(y, y0)                      # the last evaluation's result
    np.testing.assert_array_equal(s, s0)


# --------------------------------------------------------------------------------------
# A busy Function: temporary work areas carry the design too
# --------------------------------------------------------------------------------------


def test_a_reentrant_call_uses_a_temporary_work_area_with_the_design(hook_lib):
    lib, c = hook_lib
    d = np.array([1.5, -0.25])
    f = _cbind.Function(lib, "hookd", fixed=d)
    inner = {}

    def reenter():                                            # runs inside f's evaluation
        xi = np.array([2.0, 3.0])
        y = np.empty(2)
        f(xi, y)
        Y = np.empty((3, 2))
        f.map(3, np.arange(6.0), Y)
        t = np.empty(2)
        f.time_calls(2, 1, xi, t)
        inner.update(y=y, Y=Y, t=t)

    cb = ctypes.CFUNCTYPE(None)(reenter)
    checkouts, releases = c.stub_counter(2), c.stub_counter(3)
    c.set_hook(cb)
    x, y = np.array([-1.0, 4.0]), np.empty(2)
    f(x, y)
    assert c.stub_counter(2) - checkouts == 3                 # three temporary work areas,
    assert c.stub_counter(3) - releases == 3                  # each released after its call
    np.testing.assert_array_equal(y, _hookd_ref(x, d))        # the outer call, after them
    np.testing.assert_array_equal(inner["y"], _hookd_ref([2.0, 3.0], d))
    np.testing.assert_array_equal(inner["t"], _hookd_ref([2.0, 3.0], d))
    for k in range(3):
        np.testing.assert_array_equal(inner["Y"][k], _hookd_ref([2.0 * k, 2.0 * k + 1], d))
    # and the primary work area still holds the design afterwards
    f(x, y)
    np.testing.assert_array_equal(y, _hookd_ref(x, d))


def test_calls_while_a_rollout_runs_without_the_gil(lib):
    # accumulate releases the GIL while it holds the primary work area: calls from the main
    # thread meanwhile get temporary ones, which must be bound to the design as well.
    plain = _cbind.Function(lib, "stepd")
    f = _cbind.Function(lib, "stepd", fixed=D_SX)
    rng = np.random.default_rng(7)
    n = 100000
    u_seq = rng.standard_normal((n, 2)) * 0.01
    x0 = np.array([0.1, 0.2, 0.3])
    x_ref = x0.copy()
    f.accumulate(x_ref, u_seq, 0.9, None)
    errors, started = [], threading.Event()

    def worker():
        try:
            for _ in range(3):
                x = x0.copy()
                started.set()
                f.accumulate(x, u_seq, 0.9, None)
                assert np.array_equal(x, x_ref)
        except BaseException as exc:  # pragma: no cover - reported below
            errors.append(exc)

    t = threading.Thread(target=worker)
    t.start()
    started.wait()
    expected, single = np.empty(3), np.empty(3)
    plain(x0, u_seq[0], 0.9, D_SX, expected, None)
    calls = 0
    while t.is_alive() or calls < 100:
        f(x0, u_seq[0], 0.9, single, None)
        assert np.array_equal(single, expected), calls
        calls += 1
    t.join()
    assert errors == []


# --------------------------------------------------------------------------------------
# The values are a copy; refusals; references and memory
# --------------------------------------------------------------------------------------


def test_the_values_are_copied(lib):
    src = np.array([0.7, -1.3])
    f = _cbind.Function(lib, "sxd", fixed=src)
    q, p = np.array([0.1, 0.2, 0.3]), np.array([-0.4, 0.5])
    before = np.empty(3)
    f(q, p, before, None)
    src[:] = [5.0, 6.0]                                       # the caller's array changes
    after = np.empty(3)
    f(q, p, after, None)
    np.testing.assert_array_equal(after, before)
    assert f.fixed == (0.7, -1.3)
    buf = array.array("d", [0.7, -1.3])
    _cbind.Function(lib, "sxd", fixed=buf)
    buf.append(1.0)                                           # no buffer export left held


@pytest.mark.parametrize("name, values, exc, pattern", [
    ("nodesign", [1.0, 2.0], ValueError,
     r"^nodesign: fixed= binds a last input named 'design', but the inputs are \('x', 'p'\)$"),
    ("matd", [1.0, 2.0, 3.0, 4.0], ValueError,
     r"^matd: fixed= binds a vector, but input 'design' \(#1\) has shape \(2, 2\)$"),
    ("sxd", [1.0, 2.0, 3.0], ValueError,
     r"^sxd: fixed must have 2 values \(the 'design' input has 2 elements\), got 3$"),
    ("sxd", [], ValueError, r"fixed must have 2 values .*got 0$"),
    ("sxd", 1.0, ValueError, r"fixed must have 2 values .*got 1$"),
    ("only", [1.0, 2.0], ValueError, r"fixed must have 1 value \(the 'design' input has 1 "
                                     r"element\), got 2$"),
    ("sxd", [1.0, np.nan], ValueError,
     r"^sxd: fixed \(the 'design' input\) has a non-finite value at index 1 \(nan\)$"),
    ("sxd", np.array([-np.inf, 0.0]), ValueError, r"non-finite value at index 0 \(-inf\)"),
    ("only", float("inf"), ValueError, r"non-finite value at index 0 \(inf\)"),
    ("sxd", np.zeros((1, 2)), ValueError, r"must be one-dimensional, got 2 dimensions"),
    ("sxd", [10 ** 400, 1.0], ValueError, r"must be real numbers, value 0 is int"),
    ("only", 10 ** 400, ValueError, r"an int too large for a float64"),
    ("sxd", "ab", TypeError, r"^sxd: fixed \(the 'design' input\) must be real numbers, got str"),
    ("sxd", ["a", 1.0], TypeError, r"must be real numbers, value 0 is str"),
    ("sxd", [1.0, 2j], TypeError, r"must be real numbers, value 1 is complex"),
    ("sxd", [[1.0], [2.0]], TypeError, r"value 0 is list"),
    ("sxd", {1.0, 2.0}, TypeError, r"must be a float64 buffer or a sequence of real numbers, "
                                   r"got set"),
    ("sxd", object(), TypeError, r"got object"),
    ("sxd", np.array([1, 2]), TypeError, r"must be float64 values, got a buffer of format"),
    ("sxd", np.array([1.0, 2.0], dtype=np.float32), TypeError, r"format 'f'"),
    ("sxd", b"\0" * 16, TypeError, r"format 'B' \(itemsize 1\) from bytes"),
    ("sxd", np.array([1.0, None]), TypeError, r"format 'O'"),
    ("sxd", np.array(["2020-01-01", "2020-01-02"], dtype="datetime64[D]"), TypeError,
     r"cannot export a float64 buffer from numpy.ndarray: cannot include dtype 'M'"),
])
def test_refusals_name_the_function_and_the_rule(lib, name, values, exc, pattern):
    with pytest.raises(exc, match=pattern):
        _cbind.Function(lib, name, fixed=values)


def test_binding_function_raises_typed_errors(lib):
    f = binding.function(lib, "sxd", fixed=D_SX)
    assert isinstance(f, binding.Function) and f.fixed == (0.7, -1.3)
    assert binding.function(lib, "sxd").fixed is None
    with pytest.raises(ArgumentError, match=r"binds a last input named 'design'"):
        binding.function(lib, "nodesign", fixed=[1.0, 2.0])
    with pytest.raises(ArgumentError, match=r"non-finite value at index 0"):
        binding.function(lib, "sxd", fixed=[np.nan, 1.0])
    with pytest.raises(ArgumentTypeError, match=r"must be real numbers, value 1 is str"):
        binding.function(lib, "sxd", fixed=[1.0, "x"])
    with pytest.raises(LookupError):
        binding.function(lib, "nosuchfn", fixed=[1.0])


def test_lifecycle_is_balanced_with_and_without_a_refusal(hook_lib):
    lib, c = hook_lib

    def state():
        return [c.stub_counter(i) for i in range(4)]          # incref, decref, checkout, release

    before = state()
    with pytest.raises(ValueError):
        _cbind.Function(lib, "hookd", fixed=[1.0, np.nan])
    gc.collect()
    assert state() == before                                  # refused before any of them
    f = _cbind.Function(lib, "hookd", fixed=[1.0, 2.0])
    assert [a - b for a, b in zip(state(), before)] == [1, 0, 1, 0]
    del f
    gc.collect()
    assert [a - b for a, b in zip(state(), before)] == [1, 1, 1, 1]


def test_no_reference_leaks(lib):
    src = np.array([0.7, -1.3])
    q, p, v, M = np.ones(3), np.ones(2), np.empty(3), np.empty(4)
    objs = (src, q, p, v, M, lib)
    refs = [sys.getrefcount(o) for o in objs]
    src_refs = sys.getrefcount(src)
    f = _cbind.Function(lib, "sxd", fixed=src)
    assert sys.getrefcount(src) == src_refs                   # the values are not held
    for _ in range(1000):
        f(q, p, v, M)
        assert f.fixed == (0.7, -1.3)
    for _ in range(10):
        f.map(1, q, p, v, M)
        f.time_calls(1, 1, q, p, v, M)
    del f
    gc.collect()
    assert [sys.getrefcount(o) for o in objs] == refs


def test_no_memory_leak_over_many_functions(lib):
    src = np.arange(2.0)

    def churn():
        for _ in range(2000):
            f = _cbind.Function(lib, "mxd", fixed=D_MX)
            assert f.fixed == tuple(D_MX)
            del f
            try:
                _cbind.Function(lib, "sxd", fixed=[1.0, np.nan])
            except ValueError:
                pass
            _cbind.Function(lib, "sxd", fixed=src)

    churn()                                                   # warm caches up
    gc.collect()
    tracemalloc.start()
    try:
        base = tracemalloc.get_traced_memory()[0]
        churn()
        gc.collect()
        grown = tracemalloc.get_traced_memory()[0] - base
    finally:
        tracemalloc.stop()
    assert grown < 8000, grown                                # a leak of 16 B/Function: 64 kB


# --------------------------------------------------------------------------------------
# clone(): the same function from what a Function resolved, at another design
# --------------------------------------------------------------------------------------


D_SX2 = np.array([-0.2, 2.5])


def test_a_clone_at_another_design_equals_the_unbound_function_on_every_path(lib):
    plain = _cbind.Function(lib, "stepd")
    f = _cbind.Function(lib, "stepd", fixed=D_SX)
    g = f.clone(fixed=D_SX2)
    assert g is not f and type(g) is _cbind.Function
    assert g.fixed == tuple(D_SX2) and f.fixed == tuple(D_SX)        # the source keeps its own
    for attr in ("name", "signature", "names_in", "names_out", "sizes_in", "sizes_out",
                 "shapes_in", "shapes_out", "n_in", "n_out", "library"):
        assert getattr(g, attr) == getattr(f, attr), attr
    assert g.library is f.library
    rng = np.random.default_rng(11)
    x, u, p = rng.standard_normal(3), rng.standard_normal(2), 0.7
    for fn, d in ((f, D_SX), (g, D_SX2), (f, D_SX)):                  # interleaved
        xn, y, xn0, y0 = np.empty(3), np.empty(2), np.empty(3), np.empty(2)
        fn(x, u, p, xn, y)
        plain(x, u, p, d, xn0, y0)
        np.testing.assert_array_equal(xn, xn0)
        np.testing.assert_array_equal(y, y0)
    K = 9
    U = rng.standard_normal((K, 2))
    X, Y, X0, Y0 = np.empty((K, 3)), np.empty((K, 2)), np.empty((K, 3)), np.empty((K, 2))
    g.map(K, np.tile(x, (K, 1)), U, np.full(K, p), X, Y)
    plain.map(K, np.tile(x, (K, 1)), U, np.full(K, p), D_SX2, X0, Y0)
    np.testing.assert_array_equal(X, X0)
    np.testing.assert_array_equal(Y, Y0)
    xa, xr = x.copy(), x.copy()
    g.accumulate(xa, U, p, None)
    for k in range(K):                                                # the rollout by hand
        xn = np.empty(3)
        plain(xr, U[k], p, D_SX2, xn, None)
        xr = xn
    np.testing.assert_array_equal(xa, xr)
    meth = _cbind.Method(g, (None, None, None), ((3,), None), empty=np.empty)
    xn0 = np.empty(3)
    plain(x, u, p, D_SX2, xn0, None)
    np.testing.assert_array_equal(meth(x, u, p, None), xn0)
    assert len(g.time_calls(10, 2, x, u, p, np.empty(3), None)) == 2


def test_a_clone_keeps_the_design_and_check_outputs_and_outlives_its_source(lib):
    f = _cbind.Function(lib, "sxd", fixed=D_SX)
    f.check_outputs = True
    g = f.clone()
    assert g.fixed == f.fixed == tuple(D_SX) and g.check_outputs
    g.check_outputs = False                                           # its own attribute
    assert f.check_outputs and not g.clone().check_outputs
    q, p = np.array([0.1, 0.2, 0.3]), np.array([-0.4, 0.5])
    v0 = np.empty(3)
    f(q, p, v0, None)
    del f
    gc.collect()
    v = np.empty(3)
    g(q, p, v, None)
    np.testing.assert_array_equal(v, v0)
    plain = _cbind.Function(lib, "nodesign")
    c = plain.clone()
    assert c.fixed is None and c.signature == plain.signature
    x, pp, y, y0 = np.array([1.0, 2.0]), np.array([3.0, -4.0]), np.empty(2), np.empty(2)
    c(x, pp, y)
    plain(x, pp, y0)
    np.testing.assert_array_equal(y, y0)


@pytest.mark.parametrize("values, exc, pattern", [
    ([1.0, np.nan], ValueError, r"^sxd: fixed \(the 'design' input\) has a non-finite value "
                                r"at index 1 \(nan\)$"),
    ([1.0, 2.0, 3.0], ValueError, r"^sxd: fixed must have 2 values"),
    (["a", 1.0], TypeError, r"must be real numbers, value 0 is str"),
    (np.array([1, 2]), TypeError, r"must be float64 values"),
])
def test_a_clone_refuses_what_the_constructor_refuses(lib, values, exc, pattern):
    f = _cbind.Function(lib, "sxd", fixed=D_SX)
    with pytest.raises(exc, match=pattern):
        f.clone(fixed=values)
    assert f.fixed == tuple(D_SX)


def test_a_function_made_without_a_design_has_none_to_rebind(lib):
    with pytest.raises(ValueError, match=r"^nodesign: clone\(fixed=\.\.\.\) rebinds the 'design' "
                                         r"input of a Function made with fixed=; this one was "
                                         r"made without \(inputs \('x', 'p'\)\)$"):
        _cbind.Function(lib, "nodesign").clone(fixed=[1.0, 2.0])
    with pytest.raises(TypeError):
        _cbind.Function(lib, "sxd", fixed=D_SX).clone(D_SX2)         # keyword-only


def test_a_clone_checks_out_and_releases_its_own_memory(hook_lib):
    lib, c = hook_lib

    def state():
        return [c.stub_counter(i) for i in range(4)]          # incref, decref, checkout, release

    f = _cbind.Function(lib, "hookd", fixed=[1.0, 2.0])
    before = state()
    with pytest.raises(ValueError):
        f.clone(fixed=[1.0, np.inf])
    gc.collect()
    assert state() == before                                  # refused: nothing taken
    g = f.clone(fixed=[3.0, -1.0])
    assert [a - b for a, b in zip(state(), before)] == [1, 0, 1, 0]
    y = np.empty(2)
    g(np.array([0.5, 2.0]), y)
    np.testing.assert_array_equal(y, _hookd_ref([0.5, 2.0], [3.0, -1.0]))
    del g
    gc.collect()
    assert [a - b for a, b in zip(state(), before)] == [1, 1, 1, 1]


def test_a_busy_clone_uses_a_temporary_work_area_at_its_design(hook_lib):
    lib, c = hook_lib
    g = _cbind.Function(lib, "hookd", fixed=[1.0, 2.0]).clone(fixed=[-0.5, 4.0])
    x, inner = np.array([0.3, -0.7]), np.empty(2)

    @ctypes.CFUNCTYPE(None)
    def hook():
        g(x, inner)                                           # g's primary area is in use

    c.set_hook(hook)
    outer = np.empty(2)
    g(x, outer)
    np.testing.assert_array_equal(inner, _hookd_ref(x, [-0.5, 4.0]))
    np.testing.assert_array_equal(outer, inner)


def test_clones_leak_no_memory_and_no_references(lib):
    f = _cbind.Function(lib, "mxd", fixed=D_MX)
    d2 = np.array([0.1, 0.2, 0.3])
    refs = [sys.getrefcount(o) for o in (lib, f.name, f.names_in, d2)]

    def churn():
        for _ in range(2000):
            g = f.clone(fixed=d2)
            assert g.fixed == (0.1, 0.2, 0.3)
            del g
            try:
                f.clone(fixed=[np.nan, 0.0, 0.0])
            except ValueError:
                pass
            f.clone()

    churn()
    gc.collect()
    tracemalloc.start()
    try:
        base = tracemalloc.get_traced_memory()[0]
        churn()
        gc.collect()
        grown = tracemalloc.get_traced_memory()[0] - base
    finally:
        tracemalloc.stop()
    assert grown < 8000, grown
    assert [sys.getrefcount(o) for o in (lib, f.name, f.names_in, d2)] == refs
