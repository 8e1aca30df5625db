# A model with [design] beside its fixed-geometry twin: the speed of a call does not depend on
# how the model was made (Model.at_design binds the geometry once; the C takes it as an input).
"""The paper's robot with its geometry as a run-time input (``shang2010_design``: la, lb tied
across the legs, and b2x) beside the fixed-geometry model (``shang2010``), in one run.

In interleaved rounds (:func:`pm2dof.bench.timing.time_interleaved`), at the NA operating point
of each model's high-speed move and at the same (the paper's) geometry:

* ``Model.forward_dynamics(..., out=buf)`` and ``NAController.step(..., out=buf)`` from Python;
* the same two functions in a C loop (``time_calls``).

The ratios design / fixed are paired per round, then the median taken. The generated operation
counts of both models' forward dynamics and NA step are read from their C
(:func:`pm2dof.bench.opcount.count_ops`).
"""
from pathlib import Path

from ..core.model import load_model
from .models import _calls, _paired
from .opcount import count_ops
from .timing import stats, time_interleaved

__all__ = ["DESIGN_MODELS", "design_bench"]

#: (the fixed-geometry model, the same robot with a [design] table)
DESIGN_MODELS = ("shang2010", "shang2010_design")


def _ops(model):
    """flops and transcendental calls of the forward dynamics and the NA step."""
    c_text = Path(model.library).with_name(f"{model.name}.c").read_text()
    names = {f"{model.name}_{s}": s for s in ("forward_dynamics", "na_step")}
    ops = count_ops(c_text, list(names))
    return {names[k]: {"flops": v["flops"], "transcendental": v["transcendental"]}
            for k, v in ops.items()}


def design_bench(repeats, batch_s, c_inner, say=None, names=DESIGN_MODELS):
    """The measurements of the module docstring: ``repeats`` rounds, Python batches of about
    ``batch_s`` s, ``c_inner`` // 10 calls per C-loop batch.

    Returns a JSON-able dict: ``design_rows`` {name: {forward_dynamics_python_ns,
    forward_dynamics_c_ns, na_step_python_ns, na_step_c_ns, ops}}, and the targets' values
    ``design_fd_ratio`` and ``design_na_step_ratio`` (design / fixed, from Python, paired per
    round), with the C-loop ratios ``design_fd_c_ratio`` and ``design_na_step_c_ratio``."""
    say = say or (lambda msg: None)
    models = {name: load_model(name) for name in names}
    fixed, design = names
    c_calls = max(1, c_inner // 10)
    runs = {}
    for name, model in models.items():
        _, calls = _calls(model, c_calls)
        runs.update({(name, k): calls[k] for k in ("na_py", "na_c", "fd_py", "fd_c")})
    say(f"design: forward dynamics and NA step, C and Python, interleaved over {fixed} and "
        f"{design} (design {dict(zip(models[design].design_names, models[design].design))})")
    t = time_interleaved(runs, repeats, batch_s)
    for key in runs:
        if key[1] in ("na_c", "fd_c"):
            t[key] = [x / c_calls for x in t[key]]
    rows = {}
    for name, model in models.items():
        r = rows[name] = {"ops": _ops(model)}
        for call, label in (("na", "na_step"), ("fd", "forward_dynamics")):
            r[f"{label}_python_ns"] = stats(t[name, f"{call}_py"])["median"]
            r[f"{label}_c_ns"] = stats(t[name, f"{call}_c"])["median"]
    return {"design_rows": rows,
            "design_fd_ratio": _paired(t[design, "fd_py"], t[fixed, "fd_py"]),
            "design_na_step_ratio": _paired(t[design, "na_py"], t[fixed, "na_py"]),
            "design_fd_c_ratio": _paired(t[design, "fd_c"], t[fixed, "fd_c"]),
            "design_na_step_c_ratio": _paired(t[design, "na_c"], t[fixed, "na_c"])}
