# Property tests (hypothesis, derandomised) of every pm2dof.Model function on good and bad input.
"""Every Model function, over random reachable poses and over random bad inputs.

* Good input: random xe in a box +-0.05 m around (0.245, 0.265) m (the middle of the paper's
  path), kept if every leg reaches it and min_i |sin(qb_i - qa_i)| is above the model's
  singularity threshold, with random velocities and physically consistent theta. Every
  function returns a finite array of the documented shape; ``out=`` returns the same numbers
  in the given array; lists, float32 and read-only/strided arrays give the same numbers.
* Bad input: one or more arguments replaced by NaN/inf anywhere, a wrong length, a 2-D array
  of the wrong size, a string, None, an object array, float32, a list of ints, huge values
  (1e308), zeros, nested lists ... and ``out=`` misuse. Each call either returns a finite
  array of the right shape or raises ValueError/TypeError (subclasses included) whose
  message names a bad argument (or, for WorkspaceError/SingularityError, the leg and its
  distance / the singularity measure); never another exception type, never a silent NaN or
  inf in the output, and the model still gives the right answer on the next good call.
* Domain errors: unreachable xe -> WorkspaceError naming the leg and the distance; a pose
  with min_i |sin(qb_i - qa_i)| below the threshold -> SingularityError carrying the measure.

All hypothesis tests use ``derandomize=True`` so CI is deterministic; failing inputs are
printed by hypothesis and repeated in the assertion messages.
"""
from __future__ import annotations

import math
import re
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import pm2dof
from pm2dof import SingularityError, WorkspaceError

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

CENTRE = np.array([0.245, 0.265])
HALF = 0.05
FAST = settings(derandomize=True, max_examples=150, deadline=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])

M = pm2dof.load_model()
N = M.n_legs
P = len(M.param_names)
THR = M.singularity_threshold

# method -> (Python argument names, output shape); the argument names are the C input names
SIGNATURES = {
    "ik": (("xe",), (2 * N,)),
    "fk": (("qa",), (2,)),
    "H": (("q",), (2 * (N - 1),)),
    "A": (("q",), (2 * (N - 1), 2 * N)),
    "singularity": (("q",), (N,)),
    "W": (("q",), (2 * N, 2)),
    "S": (("q",), (N, 2)),
    "Wdot": (("q", "xed"), (2 * N, 2)),
    "M": (("q", "theta"), (2 * N, 2 * N)),
    "C": (("q", "qd", "theta"), (2 * N, 2 * N)),
    "Me": (("q", "theta"), (2, 2)),
    "Ce": (("q", "xed", "theta"), (2, 2)),
    "StF": (("q", "xed", "theta"), (2,)),
    "Y": (("q", "xed", "xrd", "xrdd"), (2, P)),
    "forward_dynamics": (("xe", "xed", "tau_a", "theta"), (2,)),
}
NEEDS_W = {"W", "S", "Wdot", "Me", "Ce", "StF", "Y", "forward_dynamics"}
SIZES = {"xe": 2, "qa": N, "q": 2 * N, "xed": 2, "qd": 2 * N, "theta": P, "xrd": 2, "xrdd": 2,
         "tau_a": N}
MEASURE_RE = re.compile(r"min_i \|sin\(qb_i - qa_i\)\| = ([-+0-9.eE]+|nan)")


def test_signatures_match_the_generated_functions():
    """The table above is what the generated C declares (so 'names the argument' is exact)."""
    import inspect
    for name, (args, shape) in SIGNATURES.items():
        f = M.function(name)
        assert tuple(f.names_in) == args, (name, f.names_in)
        assert tuple(f.sizes_in) == tuple(SIZES[a] for a in args), (name, f.sizes_in)
        assert f.sizes_out[0] == int(np.prod(shape)), (name, f.sizes_out, shape)
        assert tuple(inspect.signature(getattr(M, name)).parameters) == args + ("out",), name


def good_args(xe=CENTRE, xed=(0.1, -0.2), theta=None):
    """Consistent arguments of every function at the pose ``xe``."""
    xe = np.asarray(xe, dtype=float)
    q = M.ik(xe)
    xed = np.asarray(xed, dtype=float)
    theta = np.array(M.theta_nominal) if theta is None else np.asarray(theta, dtype=float)
    return {"xe": xe, "qa": q[:N].copy(), "q": q, "xed": xed, "qd": M.W(q) @ xed,
            "theta": theta, "xrd": xed + 0.01, "xrdd": np.array([1.0, -2.0]),
            "tau_a": np.linspace(-1.0, 1.0, N)}


BASE = good_args()
BASELINE = {name: getattr(M, name)(*(BASE[a] for a in args)) for name, (args, _) in
            SIGNATURES.items()}


def measure(q):
    q = np.asarray(q, dtype=float)
    return float(np.min(np.abs(np.sin(q[N:] - q[:N]))))


def reach_violation(xe):
    """[(leg number 1-based, distance, lo, hi)] of the legs that cannot reach xe."""
    out = []
    for i, leg in enumerate(M.spec.legs):
        d = float(np.hypot(*(np.asarray(xe, float) - np.asarray(leg.base))))
        lo, hi = abs(leg.la - leg.lb), leg.la + leg.lb
        if not lo <= d <= hi:
            out.append((i + 1, d, lo, hi))
    return out


# --------------------------------------------------------------------------------------
# 1. Random reachable poses: finite output of the right shape, every function
# --------------------------------------------------------------------------------------

@st.composite
def thetas(draw):
    fl = lambda lo, hi: st.floats(lo, hi, allow_nan=False, allow_infinity=False)  # noqa: E731
    a = np.array([draw(fl(0.005, 0.15)) for _ in range(N)])
    g = np.array([draw(fl(0.005, 0.08)) for _ in range(N)])
    b = np.array([draw(fl(-0.95, 0.95)) for _ in range(N)]) * np.sqrt(a * g)
    rest = np.array([draw(fl(0.0, 5.0)) for _ in range(P - 3 * N)])
    return np.concatenate([a, b, g, rest])


vec2 = st.tuples(st.floats(-1.0, 1.0), st.floats(-1.0, 1.0)).map(np.array)


@FAST
@given(dx=st.floats(-HALF, HALF), dy=st.floats(-HALF, HALF), xed=vec2, theta=thetas(),
       xrd=vec2, xrdd=vec2.map(lambda v: 10 * v), tau=st.lists(st.floats(-20, 20), min_size=N,
                                                                max_size=N))
def test_reachable_poses_give_finite_outputs_of_the_right_shape(dx, dy, xed, theta, xrd, xrdd,
                                                                tau):
    xe = CENTRE + [dx, dy]
    assume(not reach_violation(xe))
    q = M.ik(xe)
    assume(measure(q) > THR * 1.01)
    a = {"xe": xe, "qa": q[:N].copy(), "q": q, "xed": xed, "qd": M.W(q) @ xed, "theta": theta,
         "xrd": xrd, "xrdd": xrdd, "tau_a": np.array(tau)}
    info = f"xe={xe.tolist()} xed={xed.tolist()} theta={theta.tolist()} measure={measure(q)}"
    for name, (args, shape) in SIGNATURES.items():
        f = getattr(M, name)
        r = f(*(a[k] for k in args))
        assert type(r) is np.ndarray and r.shape == shape and r.dtype == np.float64, (
            f"{name}: got {type(r).__name__} {getattr(r, 'shape', None)}, expected {shape}; {info}")
        assert np.isfinite(r).all(), f"{name} returned non-finite {r.tolist()} at {info}"
        out = np.full(shape, np.nan)
        r2 = f(*(a[k] for k in args), out=out)
        assert r2 is out and np.array_equal(out, r), f"{name}: out= differs from the return; {info}"
        r3 = f(*(a[k].tolist() for k in args))  # the conversion path: same numbers
        assert np.array_equal(r3, r), f"{name}: list inputs give {r3} != {r}; {info}"
    # consistency of what was computed
    assert np.max(np.abs(M.fk(q[:N]) - xe)) < 1e-9, f"fk(ik(xe)) != xe at {info}"
    assert np.max(np.abs(M.H(q))) < 1e-9, f"H(ik(xe)) = {M.H(q)} != 0 at {info}"
    assert abs(np.min(np.abs(M.singularity(q))) - measure(q)) < 1e-12, info
    assert np.max(np.abs(M.A(q) @ M.W(q))) < 1e-9, f"A W != 0 at {info}"


# --------------------------------------------------------------------------------------
# 2. Random bad inputs
# --------------------------------------------------------------------------------------

# right_size_2d (e.g. (1, 6) for q) is refused: only the documented shape (k,) is accepted
VALID_KINDS = {"float32", "int_list", "object_numeric", "strided", "readonly", "big_endian",
               "list", "tuple", "bool"}


@st.composite
def corrupt(draw, good):
    """(kind, bad value) for an argument whose good value is ``good`` (1-D float64)."""
    size = good.size
    kind = draw(st.sampled_from([
        "nan", "inf", "all_nan", "wrong_length", "wrong_size_2d", "right_size_2d", "string",
        "none", "object_numeric", "object_none", "object_str", "float32", "int_list", "huge",
        "all_huge", "tiny", "zeros", "scalar", "nested", "empty", "strided", "readonly",
        "big_endian", "list", "tuple", "bool", "ragged", "dict"]))
    i = draw(st.integers(0, size - 1))
    v = good.copy()
    if kind == "nan":
        v[i] = np.nan
        return kind, v
    if kind == "inf":
        v[i] = draw(st.sampled_from([np.inf, -np.inf]))
        return kind, v
    if kind == "all_nan":
        return kind, np.full(size, np.nan)
    if kind == "wrong_length":
        n = draw(st.integers(0, size + 4).filter(lambda k: k != size))
        return kind, np.resize(good, n)
    if kind == "wrong_size_2d":
        r, c = draw(st.integers(1, 5)), draw(st.integers(2, 5))
        assume(r * c != size)
        return kind, np.ones((r, c))
    if kind == "right_size_2d":
        return kind, draw(st.sampled_from([good[None, :], good[:, None]])).copy()
    if kind == "string":
        return kind, draw(st.sampled_from(["", "abc", "1,2", "nan", " ".join(["1"] * size)]))
    if kind == "none":
        return kind, None
    if kind == "object_numeric":
        return kind, good.astype(object)
    if kind == "object_none":
        o = good.astype(object)
        o[i] = None
        return kind, o
    if kind == "object_str":
        o = good.astype(object)
        o[i] = "x"
        return kind, o
    if kind == "float32":
        return kind, good.astype(np.float32)
    if kind == "int_list":
        return kind, [int(round(x)) for x in good]
    if kind == "huge":
        v[i] = draw(st.sampled_from([1e308, -1e308, 1.7976931348623157e308, 1e200]))
        return kind, v
    if kind == "all_huge":
        return kind, np.full(size, draw(st.sampled_from([1e308, -1e308, 1e200])))
    if kind == "tiny":
        v[i] = 5e-324
        return kind, v
    if kind == "zeros":
        return kind, np.zeros(size)
    if kind == "scalar":
        return kind, draw(st.sampled_from([0.5, 1, np.float64(0.3)]))
    if kind == "nested":
        return kind, [good.tolist()] * draw(st.integers(2, 3))
    if kind == "empty":
        return kind, np.array([])
    if kind == "strided":
        return kind, np.repeat(good, 2)[::2]
    if kind == "readonly":
        v.setflags(write=False)
        return kind, v
    if kind == "big_endian":
        return kind, good.astype(">f8")
    if kind == "list":
        return kind, good.tolist()
    if kind == "tuple":
        return kind, tuple(good.tolist())
    if kind == "bool":
        return kind, good > 0
    if kind == "ragged":
        return kind, [good.tolist(), [1.0]]
    return kind, {"x": 1.0}


def names_argument(msg, names):
    return any(re.search(rf"(?<![A-Za-z0-9_]){re.escape(n)}(?![A-Za-z0-9_])", msg) for n in names)


def check_outcome(name, call, bad_names, info, out_names=()):
    """Run ``call``: a finite result of the right shape, or a clear ValueError/TypeError."""
    shape = SIGNATURES[name][1]
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # a RuntimeWarning is not the contract here
            r = call()
    except WorkspaceError as exc:
        msg = str(exc)
        ok = (re.search(r"\bleg \d+\b", msg) and "distance" in msg) or names_argument(
            msg, bad_names)
        assert ok, f"{name}: WorkspaceError names neither a leg and distance nor an argument: " \
                   f"{msg!r}; {info}"
        return "workspace"
    except SingularityError as exc:
        msg = str(exc)
        m = MEASURE_RE.search(msg)
        assert m and "threshold" in msg, f"{name}: SingularityError without the measure: " \
                                         f"{msg!r}; {info}"
        return "singular"
    except (ValueError, TypeError) as exc:
        msg = str(exc)
        assert names_argument(msg, tuple(bad_names) + tuple(out_names)), (
            f"{name}: {type(exc).__name__} message does not name a bad argument "
            f"{list(bad_names) + list(out_names)}: {msg!r}; {info}")
        return "error"
    except BaseException as exc:  # noqa: BLE001 - the property under test
        raise AssertionError(f"{name} raised {type(exc).__name__}: {exc}; {info}") from exc
    assert isinstance(r, np.ndarray) and r.shape == shape, (
        f"{name} returned {type(r).__name__} {getattr(r, 'shape', None)}, expected {shape}; "
        f"{info}")
    assert np.isfinite(r).all(), f"{name} silently returned non-finite {r.tolist()}; {info}"
    return "ok"


def assert_model_still_good(name):
    args = SIGNATURES[name][0]
    r = getattr(M, name)(*(BASE[a] for a in args))
    assert np.array_equal(r, BASELINE[name]), f"{name}: a good call after a bad one gives {r}"


@st.composite
def bad_calls(draw):
    name = draw(st.sampled_from(sorted(SIGNATURES)))
    args = SIGNATURES[name][0]
    which = draw(st.lists(st.sampled_from(range(len(args))), min_size=1, max_size=len(args),
                          unique=True))
    values = [BASE[a] for a in args]
    kinds = {}
    for k in which:
        kinds[args[k]], values[k] = draw(corrupt(BASE[args[k]]))
    return name, values, kinds


def _fmt(v):
    if isinstance(v, np.ndarray):
        return f"array({v.tolist()!r}, dtype={v.dtype}, shape={v.shape})"
    return repr(v)


@settings(derandomize=True, max_examples=600, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(case=bad_calls())
def test_bad_inputs_raise_clearly_or_give_finite_output(case):
    name, values, kinds = case
    args = SIGNATURES[name][0]
    info = f"{name}(" + ", ".join(f"{a}={_fmt(v)}" for a, v in zip(args, values)) + f") {kinds}"
    outcome = check_outcome(name, lambda: getattr(M, name)(*values), list(kinds), info)
    if set(kinds.values()) <= VALID_KINDS - {"int_list", "bool"}:
        # only the representation changed (float32 rounds): the same numbers, or near them
        assert outcome == "ok", f"{name}: a valid representation was refused ({outcome}); {info}"
        tol = 1e-4 if "float32" in kinds.values() else 0.0
        r = getattr(M, name)(*values)
        scale = 1.0 + np.max(np.abs(BASELINE[name]))
        assert np.max(np.abs(r - BASELINE[name])) <= tol * scale, f"{name}: {r} != baseline; {info}"
    if any(k in ("nan", "inf", "all_nan", "object_none") for k in kinds.values()):
        assert outcome == "error", f"{name}: a non-finite argument was not refused ({outcome}); {info}"
    if any(k in ("wrong_length", "wrong_size_2d", "string", "none", "object_str", "scalar",
                 "nested", "empty", "ragged", "dict") for k in kinds.values()):
        assert outcome == "error", f"{name}: a malformed argument was not refused ({outcome}); {info}"
    assert_model_still_good(name)


def bad_outs(shape):
    size = int(np.prod(shape))
    return [
        ("wrong_shape", np.empty(size + 1)),
        ("flat", np.empty(size) if len(shape) > 1 else np.empty((size, 1))),
        ("transposed", np.empty(shape[::-1]) if len(shape) > 1 and shape[0] != shape[1]
         else np.empty((1, size))),
        ("float32", np.empty(shape, dtype=np.float32)),
        ("int64", np.empty(shape, dtype=np.int64)),
        ("strided", np.empty(shape + (2,))[..., 0]),
        ("fortran", np.asfortranarray(np.empty(shape)) if len(shape) > 1 and min(shape) > 1
         else np.empty(2 * size)[::2]),
        ("readonly", np.frombuffer(np.zeros(size).tobytes()).reshape(shape)),
        ("list", np.zeros(shape).tolist()),
        ("string", "out"),
        ("tuple", tuple(np.zeros(size))),
        ("subclass", np.ma.masked_array(np.zeros(shape))),
        ("big_endian", np.empty(shape, dtype=">f8")),
    ]


@pytest.mark.parametrize("name", sorted(SIGNATURES))
def test_out_misuse_raises_clearly(name):
    args, shape = SIGNATURES[name]
    out_names = ("out",) + tuple(M.function(name).names_out)
    for kind, out in bad_outs(shape):
        info = f"{name}(..., out={kind} {type(out).__name__} {getattr(out, 'shape', '')})"
        try:
            r = getattr(M, name)(*(BASE[a] for a in args), out=out)
        except (ValueError, TypeError) as exc:
            assert names_argument(str(exc), out_names), f"{info}: message {exc!s} names no " \
                                                        f"output {out_names}"
            if kind == "readonly":
                assert not np.any(out), f"{info}: the read-only out was written: {out}"
        except BaseException as exc:  # noqa: BLE001
            raise AssertionError(f"{info} raised {type(exc).__name__}: {exc}") from exc
        else:  # accepted: then it must be the documented result, in out, returned
            assert r is out and np.array_equal(np.asarray(r), BASELINE[name]), (
                f"{info} accepted but returned {type(r).__name__} {r!r}")
        assert_model_still_good(name)


def test_out_aliasing_an_input_is_refused_or_correct():
    """out= the very array that holds an input of the same size."""
    for name, (args, shape) in SIGNATURES.items():
        for k, a in enumerate(args):
            if SIZES[a] != int(np.prod(shape)) or len(shape) != 1:
                continue
            vals = [BASE[x].copy() for x in args]
            alias = vals[k]
            try:
                r = getattr(M, name)(*vals, out=alias)
            except (ValueError, TypeError) as exc:
                assert names_argument(str(exc), ("out", a) + tuple(M.function(name).names_out)), \
                    f"{name}: out aliasing {a}: {exc}"
            else:
                assert np.array_equal(r, BASELINE[name]), f"{name}: out aliasing {a} gave {r}"
            assert_model_still_good(name)


def test_complex_input_is_refused():
    """A complex array is a wrong dtype: its imaginary part must not be dropped silently."""
    for name, (args, _) in SIGNATURES.items():
        vals = [BASE[a] for a in args]
        vals[0] = vals[0] + 1j
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            with pytest.raises((TypeError, ValueError), match=re.escape(args[0])):
                getattr(M, name)(*vals)


def test_non_finite_input_messages_name_argument_and_index():
    for name, (args, _) in SIGNATURES.items():
        for k, a in enumerate(args):
            vals = [BASE[x].copy() for x in args]
            j = SIZES[a] - 1
            vals[k][j] = np.nan
            with pytest.raises(ValueError) as info:
                getattr(M, name)(*vals)
            msg = str(info.value)
            assert names_argument(msg, (a,)) and "non-finite" in msg and str(j) in msg, \
                f"{name}: NaN in {a}[{j}]: {msg}"
            assert not isinstance(info.value, (WorkspaceError, SingularityError)), msg


# --------------------------------------------------------------------------------------
# 3. Workspace and singularity errors
# --------------------------------------------------------------------------------------

@FAST
@given(x=st.floats(-1.5, 1.5), y=st.floats(-1.5, 1.5))
def test_unreachable_xe_raises_workspace_error_naming_leg_and_distance(x, y):
    xe = np.array([x, y])
    bad = reach_violation(xe)
    assume(bad)
    # no pose within 1e-9 m of a reach boundary (rounding could go either way there)
    for leg in M.spec.legs:
        d = float(np.hypot(*(xe - np.asarray(leg.base))))
        assume(min(abs(d - abs(leg.la - leg.lb)), abs(d - leg.la - leg.lb)) > 1e-9)
    leg, dist, lo, hi = bad[0]
    for call in (lambda: M.ik(xe), lambda: M.forward_dynamics(xe, BASE["xed"], BASE["tau_a"],
                                                               BASE["theta"])):
        with pytest.raises(WorkspaceError) as info:
            call()
        msg = str(info.value)
        assert f"leg {leg}" in msg, f"xe={xe.tolist()}: message names no leg {leg}: {msg}"
        assert f"{dist:.6g}" in msg, f"xe={xe.tolist()}: distance {dist:.6g} not in {msg}"
        assert f"{hi:.6g}" in msg, f"xe={xe.tolist()}: reach {hi:.6g} not in {msg}"
        assert isinstance(info.value, ValueError)


@FAST
@given(q0=st.lists(st.floats(-math.pi, math.pi), min_size=2 * N, max_size=2 * N),
       leg=st.integers(0, N - 1), delta=st.floats(-0.095, 0.095), flip=st.booleans(),
       xed=vec2)
def test_singular_q_raises_singularity_error_with_the_measure(q0, leg, delta, flip, xed):
    q = np.array(q0)
    q[N + leg] = q[leg] + delta + (math.pi if flip else 0.0)
    mu = measure(q)
    assume(mu < THR * 0.999)
    theta = BASE["theta"]
    info = f"q={q.tolist()} measure={mu!r}"
    calls = {"W": (q,), "S": (q,), "Wdot": (q, xed), "Me": (q, theta), "Ce": (q, xed, theta),
             "StF": (q, xed, theta), "Y": (q, xed, xed, xed)}
    for name, args in calls.items():
        with pytest.raises(SingularityError) as exc:
            getattr(M, name)(*args)
        msg = str(exc.value)
        found = MEASURE_RE.search(msg)
        assert found, f"{name}: no measure in {msg!r}; {info}"
        assert float(found.group(1)) == pytest.approx(mu, rel=1e-3, abs=1e-12), (
            f"{name}: message measure {found.group(1)} != {mu:.4g}; {info}")
        assert str(THR) in msg, f"{name}: threshold not in {msg!r}; {info}"
    for name, args in {"H": (q,), "A": (q,), "singularity": (q,), "M": (q, theta),
                       "C": (q, np.zeros(2 * N), theta)}.items():
        r = getattr(M, name)(*args)  # these do not need W: they work at a singular pose
        assert np.isfinite(r).all(), f"{name} at a singular pose: {r}; {info}"


def _singular_reachable_xe(lo, hi, seed=0):
    rng = np.random.default_rng(seed)
    for _ in range(200000):
        xe = rng.uniform([0.0, 0.0], [0.45, 0.5])
        if reach_violation(xe):
            continue
        mu = measure(M.ik(xe))
        if lo < mu < hi:
            return xe, mu
    raise AssertionError(f"no reachable pose with {lo} < measure < {hi}")


def test_forward_dynamics_at_a_singular_reachable_pose():
    xe, mu = _singular_reachable_xe(0.01, 0.9 * THR)
    with pytest.raises(SingularityError) as info:
        M.forward_dynamics(xe, BASE["xed"], BASE["tau_a"], BASE["theta"])
    found = MEASURE_RE.search(str(info.value))
    assert found and float(found.group(1)) == pytest.approx(mu, rel=1e-3), (
        f"xe={xe.tolist()} measure {mu}: {info.value}")


def test_threshold_is_the_boundary():
    """Just above the threshold W works; just below it raises (the comparison is >=)."""
    q = BASE["q"].copy()
    for d, ok in ((math.asin(THR) + 1e-9, True), (math.asin(THR) - 1e-9, False)):
        q2 = q.copy()
        q2[N] = q2[0] + d
        assert (measure(q2) >= THR) == ok
        if ok:
            assert np.isfinite(M.W(q2)).all()
        else:
            with pytest.raises(SingularityError):
                M.W(q2)


def test_huge_finite_inputs_never_give_silent_non_finite_output():
    """Finite inputs whose result overflows: the result is finite, or a ValueError is raised
    (the issue: no silent NaN; non-finite values raise ValueError)."""
    q, xed, theta = BASE["q"], BASE["xed"], BASE["theta"]
    cases = {
        "Me(theta=1e308)": lambda: M.Me(q, np.full(P, 1e308)),
        "Ce(xed=1e308)": lambda: M.Ce(q, np.full(2, 1e308), theta),
        "StF(xed=1e308)": lambda: M.StF(q, np.full(2, 1e308), theta),
        "Y(xrdd=1e308)": lambda: M.Y(q, xed, xed, np.full(2, 1e308)),
        "Wdot(xed=1e308)": lambda: M.Wdot(q, np.full(2, 1e308)),
        "forward_dynamics(tau_a=1e308)": lambda: M.forward_dynamics(BASE["xe"], xed,
                                                                     np.full(N, 1e308), theta),
        "forward_dynamics(xed=1e200)": lambda: M.forward_dynamics(BASE["xe"], np.full(2, 1e200),
                                                                   BASE["tau_a"], theta),
        "forward_dynamics(theta=0)": lambda: M.forward_dynamics(BASE["xe"], xed, BASE["tau_a"],
                                                                 np.zeros(P)),
    }
    silent = []
    for label, call in cases.items():
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                r = call()
        except (ValueError, TypeError):
            continue
        if not np.isfinite(r).all():
            silent.append(f"{label} -> {r.tolist()}")
    assert not silent, "silent non-finite outputs:\n  " + "\n  ".join(silent)


@pytest.mark.parametrize("name", sorted(SIGNATURES))
def test_right_size_wrong_shape_is_refused_naming_argument_and_shape(name):
    """A float64 array with the right number of elements but not the shape (k,) -- (2, 3) or
    (1, 6) for q -- is refused with a ValueError naming the argument and the expected shape,
    on the fast path (float64) and on the converting path (a nested list) alike."""
    args = SIGNATURES[name][0]
    for j, arg in enumerate(args):
        good = np.asarray(BASE[arg], dtype=float)
        k = good.size
        shapes = [(1, k), (k, 1)] + ([(2, k // 2)] if k % 2 == 0 and k > 2 else [])
        for shape in shapes:
            for bad in (good.reshape(shape).copy(), good.reshape(shape).tolist()):
                values = [BASE[a] for a in args]
                values[j] = bad
                with pytest.raises(ValueError) as info:
                    getattr(M, name)(*values)
                msg = str(info.value)
                assert arg in msg and f"shape ({k},)" in msg and str(shape) in msg, (name, arg, msg)
        assert_model_still_good(name)
