"""The per-sample Model methods called from C (pm2dof.core.fastmethod, _cbind.FastMethod):
what the descriptor's fast path returns is bit for bit what the method's Python body (its
checked path, ``__wrapped__``) returns; ``out=`` is written and returned; whatever the fast
path refuses or does not map takes the body, so every typed error is the body's."""
import functools
import inspect

import numpy as np
import pytest

from pm2dof import (
    ArgumentError,
    ArgumentTypeError,
    ClosureError,
    Model,
    SingularityError,
    WorkspaceError,
    load_model,
)
from pm2dof.core import _cbind
from pm2dof.core.derivatives import ForwardDynamicsJacobians

M = load_model()
N, P = M.n_legs, len(M.param_names)
XE = np.array([0.245, 0.265])


def _state(model, xe):
    n, m = model.n_legs, model.dof
    th = np.array(model.theta_nominal)
    xed = np.linspace(0.1, -0.2, m)
    tau = np.linspace(-0.3, 0.4, n)
    q = model.ik(xe)
    try:
        qd = model.W(q) @ xed
    except SingularityError:
        qd = np.zeros(2 * n)
    return {"xe": xe, "xed": xed, "tau": tau, "theta": th, "q": q,
            "qa": np.ascontiguousarray(q[:n]), "qd": qd,
            "xedd": np.linspace(1.0, -2.0, m), "x": np.concatenate([xe, xed]),
            "period": model.sample_period}


#: method -> its arguments (keys of _state), as bench/overheads.py times them
CALLS = {
    "forward_dynamics": ("xe", "xed", "tau", "theta"),
    "forward_dynamics_jacobians": ("xe", "xed", "tau", "theta"),
    "sampled_step": ("x", "tau", "theta", "period"),
    "sampled_step_jacobians": ("x", "tau", "theta", "period"),
    "inverse_dynamics": ("xe", "xed", "xedd", "theta"),
    "inverse_dynamics_jacobians": ("xe", "xed", "xedd", "theta"),
    "Me": ("q", "theta"), "Ce": ("q", "xed", "theta"), "Y": ("q", "xed", "xed", "xedd"),
    "StF": ("q", "xed", "theta"), "Ge": ("q", "theta"), "M": ("q", "theta"),
    "C": ("q", "qd", "theta"), "W": ("q",), "S": ("q",), "Wdot": ("q", "xed"), "ik": ("xe",),
    "fk": ("qa",), "H": ("q",), "A": ("q",), "singularity": ("q",),
    "singularity_measures": ("q",),
}
ENERGIES = {"kinetic_energy": ("xe", "xed", "theta"), "potential_energy": ("xe", "theta")}
#: the methods that check the pose (a singular one raises SingularityError)
GUARDED = {"forward_dynamics", "forward_dynamics_jacobians", "sampled_step",
           "sampled_step_jacobians", "inverse_dynamics", "inverse_dynamics_jacobians", "Me",
           "Ce", "Y", "StF", "Ge", "W", "S", "Wdot"}
S0 = _state(M, XE)


def _args(name, state=S0):
    return tuple(state[k] for k in (CALLS | ENERGIES)[name])


def _same(a, b):
    if isinstance(a, tuple):
        return type(a) is type(b) and all(_same(x, y) for x, y in zip(a, b, strict=True))
    if isinstance(a, float):
        return type(b) is float and (a == b or (a != a and b != b))
    return type(a) is np.ndarray and a.shape == b.shape and np.array_equal(a, b)


def _body(name):
    return getattr(Model, name).__wrapped__


def _outcome(call):
    """("ok", the result) or (the exception's type, its message)."""
    try:
        return "ok", call()
    except Exception as exc:  # noqa: BLE001  (any outcome is compared)
        return type(exc), str(exc)


def _same_outcome(name, model, *args, **kw):
    """The method (its fast path) and its body give the same result or the same error;
    returns that outcome."""
    a = _outcome(lambda: getattr(model, name)(*args, **kw))
    b = _outcome(lambda: _body(name)(model, *args, **kw))
    assert a[0] == b[0], (name, a, b)
    assert _same(a[1], b[1]) if a[0] == "ok" else a[1] == b[1], (name, a, b)
    return a


@pytest.mark.parametrize("name", sorted(CALLS | ENERGIES))
def test_every_per_sample_method_is_a_fast_method_with_its_body_signature_and_doc(name):
    d = getattr(Model, name)
    assert type(d) is _cbind.FastMethod
    assert inspect.isfunction(d.__wrapped__) and d.__doc__ == d.__wrapped__.__doc__
    assert d.__name__ == name and d.__module__.startswith("pm2dof.core")
    assert inspect.signature(getattr(M, name)) == inspect.signature(
        d.__wrapped__.__get__(M))


@pytest.mark.parametrize("name", sorted(CALLS | ENERGIES))
def test_the_fast_path_returns_what_the_checked_path_does_bit_for_bit(name):
    args = _args(name)
    fast, checked = getattr(M, name)(*args), _body(name)(M, *args)
    assert _same(fast, checked), name
    listed = getattr(M, name)(*(a.tolist() if isinstance(a, np.ndarray) else a for a in args))
    assert _same(listed, checked), name            # lists: the body converts them


@pytest.mark.parametrize("name", sorted(CALLS))
def test_out_is_written_and_returned(name):
    args = _args(name)
    ref = getattr(M, name)(*args)
    out = tuple(np.full_like(a, np.nan) for a in ref) if isinstance(ref, tuple) \
        else np.full_like(ref, np.nan)
    if isinstance(ref, tuple):
        out = type(ref)(*out)
    assert getattr(M, name)(*args, out=out) is out
    assert _same(out, ref)
    assert getattr(M, name)(*args, out) is out   # out given by position too


@pytest.mark.parametrize("name", sorted(CALLS))
def test_a_wrong_out_is_the_bodys_typed_error(name):
    args = _args(name)
    ref = getattr(M, name)(*args)
    if isinstance(ref, tuple):
        bad = [tuple(np.empty(a.size + 1) for a in ref), list(ref), ref[:-1],
               type(ref)(*(a.astype(np.float32) for a in ref))]
    else:
        bad = [np.empty(ref.size + 1), ref.tolist(), np.empty(ref.shape, dtype=np.float32),
               np.empty(2 * ref.size)[::2].reshape(ref.shape)]
    for out in bad:
        kind, _ = _same_outcome(name, M, *args, out=out)
        assert kind in (ArgumentError, ArgumentTypeError), (name, out)
    if isinstance(ref, np.ndarray) and ref.size >= 2:      # out sharing memory with an input
        first = np.asarray(args[0])
        if first.size >= ref.size:
            alias = first.copy()
            call_args = (alias, *args[1:])
            view = alias[:ref.size].reshape(ref.shape) if ref.ndim == 1 else None
            if view is not None:
                _same_outcome(name, M, *call_args, out=view)


@pytest.mark.filterwarnings("ignore::numpy.exceptions.ComplexWarning")
@pytest.mark.parametrize("name", sorted(CALLS | ENERGIES))
def test_bad_inputs_raise_the_bodys_typed_errors(name):
    args = list(_args(name))
    for i, a in enumerate(args):
        if not isinstance(a, np.ndarray):
            continue
        for bad, kinds in ((np.where(np.arange(a.size) == 0, np.nan, a), (ArgumentError,)),
                           (np.where(np.arange(a.size) == 0, np.inf, a), (ArgumentError,)),
                           (a[:-1], (ArgumentError,)), (np.append(a, 0.0), (ArgumentError,)),
                           (a.reshape(1, -1), (ArgumentError,)), (None, (ArgumentTypeError,)),
                           (a.astype(complex), (ArgumentTypeError,))):
            kind, _ = _same_outcome(name, M, *args[:i], bad, *args[i + 1:])
            if name in ENERGIES and i == len(args) - 1 and (bad is None or bad.dtype == complex):
                # theta None is the nominal one; a complex theta goes through checked_theta's
                # np.array(theta, dtype=float) (the body's own rule, kept: a ComplexWarning)
                kinds = ("ok",)
            assert kind in kinds, (name, i, bad, kind)
        for fine in (a.astype(np.float32), a.tolist(), np.asfortranarray(a)):
            assert _same_outcome(name, M, *args[:i], fine, *args[i + 1:])[0] == "ok"


@pytest.mark.parametrize("name", sorted(CALLS))
def test_keywords_map_and_unknown_ones_are_the_bodys_type_error(name):
    params = list(inspect.signature(getattr(M, name)).parameters)
    args = _args(name)
    ref = getattr(M, name)(*args)
    assert _same(getattr(M, name)(**dict(zip(params, args))), ref)
    with pytest.raises(TypeError):
        getattr(M, name)(*args, bogus=1)
    with pytest.raises(TypeError):
        getattr(M, name)()
    with pytest.raises(TypeError):
        getattr(M, name)(*args, **{params[0]: args[0]})    # given twice


@pytest.mark.parametrize("name", sorted(CALLS))
def test_every_way_of_giving_out_writes_the_same_bits(name):
    """The descriptor's shortcut (every input by position, ``out=`` by keyword or absent) and
    its general mapping (``out`` by position, inputs by keyword) give the same result; an out
    that shares memory with an input and an input with a NaN take the body's errors."""
    args = _args(name)
    ref = getattr(M, name)(*args)
    params = list(inspect.signature(getattr(M, name)).parameters)
    kw = dict(zip(params, args))

    def fresh():
        return (type(ref)(*(np.full_like(r, np.nan) for r in ref)) if isinstance(ref, tuple)
                else np.full_like(ref, np.nan))
    for call in (lambda o: getattr(M, name)(*args, out=o),
                 lambda o: getattr(M, name)(*args, o),
                 lambda o: getattr(M, name)(**kw, out=o),
                 lambda o: getattr(M, name)(*args[:1], **dict(list(kw.items())[1:]), out=o)):
        o = fresh()
        assert call(o) is o
        assert _same(o, ref)
    bad = list(args)
    k = next(i for i, a in enumerate(bad) if isinstance(a, np.ndarray))
    bad[k] = bad[k].copy()
    bad[k][-1] = np.nan
    assert _same_outcome(name, M, *bad)[0] is ArgumentError
    if not isinstance(ref, tuple):      # out on an input's memory: the body's ArgumentError
        big = np.zeros(args[k].size + ref.size)
        shared = list(args)
        shared[k] = big[:args[k].size]
        shared[k][:] = args[k]
        out = big[args[k].size - 1:args[k].size - 1 + ref.size].reshape(ref.shape)
        assert _same_outcome(name, M, *shared, out=out)[0] is ArgumentError


def _singular_xe(model):
    """A reachable pose near a type I singularity: leg 1 almost stretched, towards XE."""
    leg = model.spec.legs[0]
    u = (XE - leg.base) / np.linalg.norm(XE - leg.base)
    for frac in (1 - 1e-7, 1 - 1e-6, 1 - 1e-5):
        xe = leg.base + (leg.la + leg.lb) * frac * u
        try:
            q = model.ik(xe)
        except WorkspaceError:
            continue
        if model.singularity_measures(q)[0] < model.singularity_threshold:
            return xe
    raise AssertionError("no singular reachable pose found")


@pytest.mark.parametrize("name", sorted(GUARDED))
def test_a_singular_pose_is_a_singularity_error(name):
    state = _state(M, _singular_xe(M))
    kind, msg = _same_outcome(name, M, *_args(name, state))
    assert kind is SingularityError and "type I" in msg, (name, kind, msg)
    _same_outcome(name, M, *_args(name))          # the model still answers after it


def test_ik_out_of_reach_and_fk_not_closing_are_workspace_errors():
    with pytest.raises(WorkspaceError, match="leg"):
        M.ik(np.array([5.0, 5.0]))
    qa = S0["qa"].copy()
    qa[0] += 0.05
    with pytest.raises(ClosureError):
        M.fk(qa)
    with pytest.raises(ClosureError):
        M.fk(qa, out=np.empty(2))


@pytest.mark.parametrize("period", [0.0, -0.002, np.inf, np.nan, np.array(0.002),
                                    np.array([0.002]), "0.002", True])
def test_a_bad_period_is_the_bodys_error(period):
    for name in ("sampled_step", "sampled_step_jacobians"):
        args = (S0["x"], S0["tau"], S0["theta"], period)
        kind, _ = _same_outcome(name, M, *args)
        assert kind != "ok" or period is True, (name, period)    # True: checked_period's 1 s
        _same_outcome(name, M, *args[:3], period=period)


@pytest.mark.parametrize("period", [None, 0.002, np.float64(0.001), 1, np.int64(1),
                                    np.float32(0.002)])
def test_a_good_period_gives_the_bodys_result(period):
    for name in ("sampled_step", "sampled_step_jacobians"):
        args = (S0["x"], S0["tau"], S0["theta"], period)
        _same_outcome(name, M, *args)       # a 1 s period: both raise NonFiniteError
        _same_outcome(name, M, *args[:3], period=period)


@pytest.mark.parametrize("model", ["shang2010", "shang2010_vertical"])
def test_the_energies_default_theta_and_out_of_reach(model):
    mod = load_model(model)
    s = _state(mod, XE)
    for name in ENERGIES:
        a = _args(name, s)
        assert _same_outcome(name, mod, *a)[0] == "ok"
        assert _same_outcome(name, mod, *a[:-1])[0] == "ok"      # theta None: nominal
        assert _same(getattr(mod, name)(*a[:-1], None), getattr(mod, name)(*a))
        _same_outcome(name, mod, np.array([5.0, 5.0]), *a[1:])  # out of reach
    with pytest.raises(WorkspaceError):
        mod.kinetic_energy(np.array([5.0, 5.0]), s["xed"], s["theta"])


def test_the_jacobians_out_is_a_tuple_of_the_result_type():
    a = _args("forward_dynamics_jacobians")
    J = M.forward_dynamics_jacobians(*a)
    out = ForwardDynamicsJacobians(*(np.empty_like(x) for x in J))
    assert M.forward_dynamics_jacobians(*a, out=out) is out and _same(out, J)
    plain = tuple(np.empty_like(x) for x in J)   # a plain tuple: the body accepts it too
    res = M.forward_dynamics_jacobians(*a, out=plain)
    assert type(res) is ForwardDynamicsJacobians and all(
        r is p for r, p in zip(res, plain, strict=True)) and _same(res, J)


def test_a_platforms_fk_keeps_its_working_mode_check_in_the_body():
    plat = load_model("rrr3_platform")
    xe = np.array(plat.spec.home, dtype=float)
    s = _state(plat, xe)
    for name in CALLS:
        args = _args(name, s)
        assert _same(getattr(plat, name)(*args), _body(name)(plat, *args)), name
    assert _same(plat.fk(s["qa"]), xe) or np.allclose(plat.fk(s["qa"]), xe, atol=1e-9)


def test_at_design_models_take_their_own_fast_path():
    base = load_model("shang2010_design")
    other = base.at_design({base.design_names[0]: base.design[0] * 1.01})
    for model in (base, other):
        s = _state(model, XE)
        for name in ("forward_dynamics", "forward_dynamics_jacobians", "ik", "Me"):
            args = _args(name, s)
            assert _same(getattr(model, name)(*args), _body(name)(model, *args)), name
    assert not np.array_equal(base.ik(XE), other.ik(XE))


def test_fast_method_falls_back_for_any_object_without_the_method():
    class NotAModel:
        __slots__ = ("_fast",)

    obj = NotAModel()
    for fast in (None, {}, {"W": "not a Method"}):
        if fast is not None:
            obj._fast = fast
        a = _outcome(lambda: Model.W(obj, S0["q"]))        # the body runs, with its error
        b = _outcome(lambda: Model.W.__wrapped__(obj, S0["q"]))
        assert a[0] is b[0] and a[1] == b[1] and a[0] != "ok", (a, b)


def test_a_fast_dict_that_changed_or_another_one_finds_its_own_method():
    """The descriptor keeps the Method it found last, with the dict it came from and that
    dict's version (CPython 3.11): a dict that gained or changed a key since, another dict, or
    another model's, is looked up again, and each call is its own Method's result."""
    other = load_model("unequal")                 # other links: another ik at the same point
    mine, theirs = M.ik(XE), other.ik(XE)
    assert not np.array_equal(mine, theirs)

    class Holder:
        __slots__ = ("_fast",)

    h = Holder()
    h._fast = {"ik": M._fast["ik"]}
    for _ in range(3):                            # found, then kept
        assert np.array_equal(Model.ik(h, XE), mine)
    h._fast["ik"] = other._fast["ik"]             # the same dict, changed in place
    assert np.array_equal(Model.ik(h, XE), theirs)
    h._fast["W"] = M._fast["W"]                   # a key added: looked up again, same Method
    assert np.array_equal(Model.ik(h, XE), theirs)
    for fast, want in (({"ik": M._fast["ik"]}, mine), ({"ik": other._fast["ik"]}, theirs)):
        h._fast = fast                            # another dict (perhaps at the same address)
        assert np.array_equal(Model.ik(h, XE), want)
    for _ in range(3):                            # two models in turn, each its own
        assert np.array_equal(M.ik(XE), mine) and np.array_equal(other.ik(XE), theirs)
    del h._fast["ik"]                             # gone: the body's path, with its error
    with pytest.raises(KeyError):
        Model.ik(h, XE)


def test_a_non_finite_element_anywhere_in_a_short_or_long_input_is_refused():
    """The finiteness check takes an input of fewer than 8 elements element by element (xe: 2,
    q: 6) and a longer one in four chains and a tail (theta: 15): NaN, +inf and -inf at every
    position of each are the body's ArgumentError."""
    q, th = M.ik(XE), np.array(M.theta_nominal)
    assert len(th) >= 12 and len(th) % 4 and len(q) < 8
    for bad in (np.nan, np.inf, -np.inf):
        for call, a in ((lambda v: M.ik(v), XE), (lambda v: M.Me(v, th), q),
                        (lambda v: M.Me(q, v), th)):
            for k in range(len(a)):
                b = a.copy()
                b[k] = bad
                with pytest.raises(ArgumentError):
                    call(b)
            call(a.copy())                                      # finite: bound, no error


#: every kind: a point on revolute legs, with gravity, on linear actuators; two platforms
KINDS = ("shang2010", "shang2010_vertical", "prr_point", "rpr3_platform", "rrr3_platform")


@functools.cache
def _kind_state(kind):
    """A model of each kind and the state of _state at the middle of its own first move."""
    from pm2dof.control.trajectory import model_move
    model = load_model(kind)
    traj = model_move(model, "high")
    k = len(traj.t) // 2
    st = _state(model, np.ascontiguousarray(traj.xd[k]))
    st["xed"] = np.ascontiguousarray(traj.xd_dot[k])
    st["qd"] = model.W(st["q"]) @ st["xed"]
    st["x"] = np.concatenate([st["xe"], st["xed"]])
    return model, st


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("name", sorted(CALLS))
def test_an_out_on_any_inputs_memory_is_refused_and_one_beside_it_is_not(kind, name):
    """Every caller's input, with a returned array of ``out`` ending on its first element,
    starting on its last, or just beside it in the same buffer (correct, then): the fast
    path's overlap test is exact, for one returned array and for several (an input lying
    between two of them shares memory with neither), on every kind of model."""
    model, state = _kind_state(kind)
    args = _args(name, state)
    ref = getattr(model, name)(*args)
    refs = tuple(ref) if isinstance(ref, tuple) else (ref,)

    def outs(arrays):
        return type(ref)(*arrays) if isinstance(ref, tuple) else arrays[0]
    for k, a in enumerate(args):
        if not isinstance(a, np.ndarray):
            continue
        n = a.size
        for r, rr in enumerate(refs):
            m = rr.size
            room = max(x.size for x in refs) + 1      # before the input, after it
            for start, clash in ((n, False), (n - 1, True), (-m, False), (-m + 1, True)):
                big = np.zeros(room + n + room)
                base = room                                 # the input at big[base:base + n]
                shared = list(args)
                shared[k] = big[base:base + n]
                shared[k][:] = a
                arrays = [np.full_like(x, np.nan) for x in refs]
                arrays[r] = big[base + start:base + start + m].reshape(rr.shape)
                if len(refs) > 1 and not clash and start == n:   # another one before it
                    other = (r + 1) % len(refs)
                    arrays[other] = big[base - refs[other].size:base].reshape(
                        refs[other].shape)
                o = outs(arrays)
                if clash:
                    assert _same_outcome(name, model, *shared, out=o)[0] is ArgumentError, \
                        (name, k, r, start)
                else:
                    assert getattr(model, name)(*shared, out=o) is o
                    assert _same(o, ref), (name, k, r, start)
                    assert np.array_equal(big[base:base + n], a)
