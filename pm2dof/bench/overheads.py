# What each per-sample Model method costs from Python beyond its C: (Python - C) / C, paired rounds.
"""The binding's overhead of every per-sample :class:`pm2dof.Model` method.

For each method of :data:`OVERHEAD_METHODS`, in interleaved rounds (every round times each
of these once, so the ratios of a round are paired under the same machine load):

* the method from Python with ``out=`` an array it returned before (no allocation; the
  energies, which return a float, without), its arguments float64 arrays, in
  :mod:`timeit`'s loop;
* its generated function ``<name>_<method>`` in a C loop (``Function.time_calls``) with the
  same inputs and preallocated outputs: the C time of one call.

The overhead of a method is its Python time minus its C time, reported as a ratio to its C
time (``overhead_over_c_<method>``, the median over the rounds of each round's ratio), beside
both times (``overhead_python_ns_<method>``, ``overhead_c_ns_<method>``). The state is the
forward dynamics' of :mod:`.derivatives` (the middle of the bench's move, its model torque).
"""
from itertools import repeat

import numpy as np

from .derivatives import dynamics_state
from .timing import stats, time_interleaved

__all__ = ["OVERHEAD_METHODS", "UNTARGETED", "overhead_bench"]

#: The per-sample Model methods timed, each with the names of its arguments (the state of
#: :func:`_arguments`), in the generated function's input order.
OVERHEAD_METHODS = (
    ("forward_dynamics", ("xe", "xed", "tau", "theta")),
    ("forward_dynamics_jacobians", ("xe", "xed", "tau", "theta")),
    ("sampled_step", ("x", "tau", "theta", "period")),
    ("sampled_step_jacobians", ("x", "tau", "theta", "period")),
    ("inverse_dynamics", ("xe", "xed", "xedd", "theta")),
    ("inverse_dynamics_jacobians", ("xe", "xed", "xedd", "theta")),
    ("Me", ("q", "theta")),
    ("Ce", ("q", "xed", "theta")),
    ("Y", ("q", "xed", "xed", "xedd")),
    ("StF", ("q", "xed", "theta")),
    ("Ge", ("q", "theta")),
    ("M", ("q", "theta")),
    ("C", ("q", "qd", "theta")),
    ("W", ("q",)),
    ("S", ("q",)),
    ("Wdot", ("q", "xed")),
    ("ik", ("xe",)),
    ("fk", ("qa",)),
    ("H", ("q",)),
    ("A", ("q",)),
    ("singularity", ("q",)),
    ("singularity_measures", ("q",)),
    ("kinetic_energy", ("xe", "xed", "theta")),
    ("potential_energy", ("xe", "theta")),
)

#: The methods that return a float and take no ``out=``.
_NO_OUT = ("kinetic_energy", "potential_energy")

#: Reported without a target: the energies, whose C is a few ns (a horizontal model's
#: potential energy is the constant 0): any Python call is many times that.
UNTARGETED = _NO_OUT


def _arguments(model, traj):
    """{name: value} of the arguments of :data:`OVERHEAD_METHODS` at the middle of ``traj``."""
    xe, xed, tau, th = dynamics_state(model, traj, len(traj.t) // 2)
    q = model.ik(xe)
    return {"xe": xe, "xed": xed, "tau": tau, "theta": th, "q": q,
            "qa": np.ascontiguousarray(q[:model.n_legs]), "qd": model.W(q) @ xed,
            "xedd": model.forward_dynamics(xe, xed, tau, th), "x": np.concatenate([xe, xed]),
            "period": model.sample_period}


def _python_run(meth, args, out):
    """run(k): k calls ``meth(*args, out=out)`` (``out`` None: without it), the arguments
    spelt out (a call through ``*args`` costs more than a user's call), in :mod:`timeit`'s
    loop (``itertools.repeat``: a ``range`` past 256 makes and frees an int per call, about
    50 instructions that are the loop's, not the call's)."""
    n = len(args)
    if out is None:
        if n == 2:
            a, b = args

            def run(k):
                for _ in repeat(None, k):
                    meth(a, b)
        else:
            a, b, c = args

            def run(k):
                for _ in repeat(None, k):
                    meth(a, b, c)
        return run
    if n == 1:
        (a,) = args

        def run(k):
            for _ in repeat(None, k):
                meth(a, out=out)
    elif n == 2:
        a, b = args

        def run(k):
            for _ in repeat(None, k):
                meth(a, b, out=out)
    elif n == 3:
        a, b, c = args

        def run(k):
            for _ in repeat(None, k):
                meth(a, b, c, out=out)
    else:
        a, b, c, d = args

        def run(k):
            for _ in repeat(None, k):
                meth(a, b, c, d, out=out)
    return run


def overhead_bench(model, traj, repeats, batch_s, c_inner):
    """The measurements of the module docstring.

    Parameters
    ----------
    model : Model
        The robot.
    traj : Trajectory
        The bench's move; its middle sample is the state.
    repeats : int
        Rounds.
    batch_s : float
        Seconds per Python batch (split over the methods: each run gets a fifth of it).
    c_inner : int
        C calls per C-loop batch; a tenth of it per Python call of the C-loop run.

    Returns
    -------
    dict
        ``overhead_over_c_<method>``, ``overhead_python_ns_<method>``,
        ``overhead_c_ns_<method>`` per method, ``overhead_over_c_max`` and
        ``overhead_over_c_worst`` (the method) over those with a target (not
        :data:`UNTARGETED`).
    """
    vals = _arguments(model, traj)
    c_calls = max(1, c_inner // 10)
    runs = {}
    for name, names in OVERHEAD_METHODS:
        args = tuple(vals[k] for k in names)
        meth, f = getattr(model, name), model.function(name)
        out = None if name in _NO_OUT else meth(*args)
        runs[name] = _python_run(meth, args, out)
        outs = [np.empty(s) for s in f.sizes_out]

        def run_c(k, f=f, args=args, outs=outs):
            f.time_calls(c_calls * k, 1, *args, *outs)
        runs[name + " C"] = run_c
    t = time_interleaved(runs, repeats, batch_s / 5)
    res = {}
    for name, _ in OVERHEAD_METHODS:
        py, c = t[name], [x / c_calls for x in t[name + " C"]]
        res[f"overhead_python_ns_{name}"] = stats(py)["median"]
        res[f"overhead_c_ns_{name}"] = stats(c)["median"]
        res[f"overhead_over_c_{name}"] = stats([(p - q) / q for p, q in
                                                zip(py, c, strict=True)])["median"]
    worst = max((name for name, _ in OVERHEAD_METHODS if name not in UNTARGETED),
                key=lambda k: res[f"overhead_over_c_{k}"])
    res["overhead_over_c_worst"] = worst
    res["overhead_over_c_max"] = res[f"overhead_over_c_{worst}"]
    return res
