# A model with a [design] table, exported at one design: the geometry becomes constants again.
"""The generated functions of a model with a [design] table take the geometry as their last
input, ``design`` (``pm2dof derive``). An exported library is one robot, so :func:`bind_design`
rewrites each such public entry point of the generated C to set that input itself, from a
constant array of the model's design (:attr:`pm2dof.Model.design`): the API source, the
simulated robot and the tests call them exactly as they call a fixed-geometry model's. The
work sizes do not change (CasADi's ``sz_arg`` already counts the input)."""
import re

__all__ = ["bind_design"]


def bind_design(c_text, model, manifest):
    """``c_text`` (the generated C of ``model``) with every public function whose manifest
    signature ends with the input ``design`` bound to ``model.design``; unchanged for a model
    without a [design] table.

    Parameters
    ----------
    c_text : str
        The generated C (``<name>.c``).
    model : pm2dof.Model
        The model at the design to export (:meth:`pm2dof.Model.at_design`).
    manifest : pm2dof.core.manifest.Manifest
        Its generated code's manifest (the signatures).

    Returns
    -------
    str
    """
    if not model.design_names:
        return c_text
    values = ", ".join(repr(float(v)) for v in model.design)
    k = len(model.design_names)
    for short in manifest.function_names():
        inputs = manifest.signature(short)["inputs"]
        if not inputs or inputs[-1][0] != "design":
            continue
        head = (rf"(CASADI_SYMBOL_EXPORT int {re.escape(model.name)}_{short}\(const casadi_real\*\* "
                rf"arg, casadi_real\*\* res, casadi_int\* iw, casadi_real\* w, int mem\)\{{\n)")
        body = (f"  /* the design {', '.join(model.design_names)}, m: input {len(inputs) - 1} */\n"
                f"  static const casadi_real design[{k}] = {{{values}}};\n"
                f"  arg[{len(inputs) - 1}] = design;\n")
        c_text, count = re.subn(head, lambda mo, body=body: mo.group(1) + body, c_text, count=1)
        if count != 1:
            raise ValueError(f"no public function {model.name}_{short} in the generated C")
    return c_text
