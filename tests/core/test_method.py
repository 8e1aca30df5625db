"""pm2dof.core._cbind.Method, the fast path of the Model methods and controller steps: what it
accepts it computes exactly as the plain call does; everything else it refuses (Refused, no
message, nothing changed) so that the caller's checked path names the problem."""
import numpy as np
import pytest

from pm2dof import load_model
from pm2dof.core import _cbind


@pytest.fixture(scope="module")
def m():
    return load_model()


@pytest.fixture
def fd(m):
    f = m.function("forward_dynamics")
    sing = np.zeros(2)
    return f, sing, _cbind.Method(f, (None,) * 4, ((2,), sing), empty=np.empty, finite=True,
                                  guard=(1, "at_least", (m.singularity_threshold,
                                                         m.parallel_singularity_threshold)))


def _args(m):
    return (np.array([0.25, 0.26]), np.array([0.1, -0.2]), np.array([0.3, -0.1, 0.2]),
            np.array(m.theta_nominal))


def test_it_computes_what_the_plain_call_does(m, fd):
    f, sing, meth = fd
    args = _args(m)
    ref, s = np.empty(2), np.empty(2)
    f(*args, ref, s)
    new = meth(*args, None)
    assert type(new) is np.ndarray and new.shape == (2,) and np.array_equal(new, ref)
    out = np.empty(2)
    assert meth(*args, out) is out and np.array_equal(out, ref)
    assert np.array_equal(sing, s)                  # the scratch output holds the measures


@pytest.mark.parametrize("bad", [
    lambda a: (None, *a[1:]),                       # an input None
    lambda a: ([0.25, 0.26], *a[1:]),               # a list: the checked path converts it
    lambda a: (a[0].astype(np.float32), *a[1:]),    # another dtype
    lambda a: (np.array([np.nan, 0.26]), *a[1:]),   # a NaN input
    lambda a: (np.array([0.25, 0.26, 0.0]), *a[1:]),  # a wrong length
    lambda a: (np.array([5.0, 5.0]), *a[1:]),       # out of reach: non-finite result
])
def test_it_refuses_what_it_does_not_accept(m, fd, bad):
    _, _, meth = fd
    with pytest.raises(_cbind.Refused) as exc:
        meth(*bad(_args(m)), None)
    assert str(exc.value) == ""


@pytest.mark.parametrize("out", [np.empty(3), np.empty((1, 2)), np.empty(2, dtype=np.float32),
                                 np.empty(4)[::2], [0.0, 0.0]])
def test_it_refuses_an_out_of_another_shape_type_or_layout(m, fd, out):
    with pytest.raises(_cbind.Refused):
        fd[2](*_args(m), out)


def test_it_refuses_an_out_that_shares_memory_with_an_input(m, fd):
    xe, xed, tau, th = _args(m)
    with pytest.raises(_cbind.Refused):
        fd[2](xe, xed, tau, th, xe)
    assert np.array_equal(xe, [0.25, 0.26])         # nothing was written


def test_a_singular_pose_trips_the_guard(m, fd):
    _, sing, meth = fd
    # raise the thresholds above any pose's measures: every call is refused
    strict = _cbind.Method(meth.function, (None,) * 4, ((2,), sing), empty=np.empty,
                           guard=(1, "at_least", (2.0, 2.0)))
    with pytest.raises(_cbind.Refused):
        strict(*_args(m), None)
    assert 0 < sing[0] < 2.0                        # it ran; the guard refused the result


def test_feedback_copies_the_state_and_a_tripped_guard_reports_after_it(m):
    f = m.function("na_step")
    from pm2dof import NAController
    na = NAController(m)
    n = m.n_legs
    state, nxt, status, diag = na._state.copy(), np.zeros(len(na._state)), np.zeros(1), \
        np.zeros(10)
    state[:2] = [0.25, 0.26]
    state[4:] = m.theta_nominal
    qa = m.ik([0.25, 0.26])[:n].copy()
    z = np.zeros(2)
    ref_next = np.empty(len(state))
    f(state, qa, np.array([0.25, 0.26]), z, z, na.params, np.empty(n), ref_next, status, diag)
    meth = _cbind.Method(f, (state, None, None, None, None, na.params),
                         ((n,), nxt, status, diag), empty=np.empty, feedback=(1, 0),
                         guard=(2, "not_equal", float(status[0])))   # trips on this status
    with pytest.raises(_cbind.GuardTripped):
        meth(qa, np.array([0.25, 0.26]), z, z, None)
    assert np.array_equal(state, ref_next)          # the step ran: state <- state_next
    # the next step starts from there
    ref_tau2, ref_next2 = np.empty(n), np.empty(len(state))
    f(ref_next, qa, np.array([0.25, 0.26]), z, z, na.params, ref_tau2, ref_next2, status, diag)
    meth.guard_on = False
    assert np.array_equal(meth(qa, np.array([0.25, 0.26]), z, z, None), ref_tau2)
    assert np.array_equal(state, ref_next2)


def test_several_outputs_come_back_as_the_kind(m):
    J = m.forward_dynamics_jacobians(*_args(m))
    assert type(J).__name__ == "ForwardDynamicsJacobians" and J.d_tau_a.shape == (2, m.n_legs)
    again = m.forward_dynamics_jacobians(*_args(m), out=J)
    assert again is J
    n, p = m.n_legs, len(m.param_names)
    ref = m._eval_jacobians("forward_dynamics_jacobians", type(J),
                            ((2, 2), (2, 2), (2, n), (2, p)), None, _args(m))
    assert all(np.array_equal(a, b) for a, b in zip(J, ref, strict=True))


@pytest.mark.parametrize("kw, match", [
    ({"outputs": (None, None)}, "at least one returned output"),
    ({"outputs": ((3,), None)}, "has 2 elements"),
    ({"inputs": (np.zeros(3), None, None, None)}, "input #0 must be"),
    ({"guard": (0, "at_least", (0.0, 0.0))}, "scratch output"),
])
def test_construction_checks_the_layout(m, kw, match):
    f = m.function("forward_dynamics")
    args = {"inputs": (None,) * 4, "outputs": ((2,), np.zeros(2))} | kw
    with pytest.raises(ValueError, match=match):
        _cbind.Method(f, args["inputs"], args["outputs"], empty=np.empty,
                      guard=kw.get("guard"))


def test_positive_takes_a_float_above_zero_and_refuses_anything_else(m):
    f = m.function("sampled_step")
    sing = np.zeros(2)
    meth = _cbind.Method(f, (None,) * 4, ((4,), sing), empty=np.empty, finite=True,
                         positive=(3,))
    x, tau, th = np.array([0.25, 0.26, 0.1, -0.2]), np.zeros(3), np.array(m.theta_nominal)
    ref, s = np.empty(4), np.empty(2)
    f(x, tau, th, 0.002, ref, s)
    assert np.array_equal(meth(x, tau, th, 0.002, None), ref)
    assert np.array_equal(meth(x, tau, th, np.float64(0.002), None), ref)
    for bad in (0.0, -0.002, np.inf, np.nan, None, 1, np.array([0.002]), np.float32(0.002)):
        with pytest.raises(_cbind.Refused):
            meth(x, tau, th, bad, None)
    with pytest.raises(ValueError):          # only a given input of one element
        _cbind.Method(f, (None,) * 4, ((4,), sing), empty=np.empty, positive=(0,))


def test_scalar_returns_a_float_from_its_own_array(m):
    f = m.function("kinetic_energy")
    meth = _cbind.Method(f, (None,) * 3, ((1,),), empty=np.empty, finite=True, scalar=True)
    args = (np.array([0.25, 0.26]), np.array([0.1, -0.2]), np.array(m.theta_nominal))
    ref = np.empty(1)
    f(*args, ref)
    v = meth(*args, None)
    assert type(v) is float and v == ref[0]
    with pytest.raises(_cbind.Refused):      # out of reach: not finite
        meth(np.array([5.0, 5.0]), *args[1:], None)
    with pytest.raises(ValueError):          # one returned output of one element only
        _cbind.Method(m.function("ik"), (None,), ((6,),), empty=np.empty, scalar=True)
