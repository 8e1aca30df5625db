# A model's generated C read back as a CasADi SX graph: exact derivatives of the same code.
"""The model's generated functions as CasADi SX expressions, read from their C.

The generated C is CasADi's code generation of SX functions: for the functions the excitation
design needs (ik, Y, S, singularity_measures) each body is straight-line code, one operation a
line (``a07=atan2(a01,a06);``, ``if (res[0]!=0) res[0][3]=a00;``). :func:`sx_function` reads
such a body back into an SX :class:`casadi.Function` with the inputs and outputs of the
compiled one. It computes the same operations in the same order, so its values agree with the
library to rounding, and CasADi differentiates it exactly: no finite differences, no
re-derivation (the model's SymPy derivation is not run).

Only the handful of statement forms CasADi writes for straight-line SX code are accepted; a
body with anything else (a loop, a call of another function, a work vector) raises
:class:`CGraphError`, and callers fall back to ``casadi.external`` with finite differences.
"""
import re

import numpy as np

__all__ = ["CGraphError", "sx_function", "c_body", "read_body"]


class CGraphError(ValueError):
    """A generated function whose C is not straight-line code of the accepted forms."""


#: RHS token -> Python: C's casadi_* helpers and the math functions CasADi writes
_FUNCTIONS = ("sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh",
              "exp", "log", "sqrt", "floor", "ceil", "fmod", "erf")
_HELPERS = {"casadi_sq": "_sq", "casadi_fabs": "fabs", "casadi_sign": "sign",
            "casadi_fmin": "fmin", "casadi_fmax": "fmax", "casadi_nan": "_nan",
            "casadi_inf": "_inf"}
_ARG = re.compile(r"arg\[(\d+)\]\? arg\[\1\]\[(\d+)\] : 0")
_IFZ = re.compile(r"\((a\d+)\?(a\d+):0\)")
_NOT = re.compile(r"\(!(a\d+)\)")
_LOGIC = re.compile(r"\((a\d+)(&&|\|\||==|!=)(a\d+)\)")
_ASSIGN = re.compile(r"(a\d+)=(.+);")
_RESULT = re.compile(r"if \(res\[(\d+)\]!=0\) res\[\1\]\[(\d+)\]=(a\d+);")
#: what a translated right-hand side may contain: names, numbers, operators, brackets
#: an attribute access or a dunder name ("1.0.__class__", "__import__"): never in CasADi's
#: straight-line code, refused before evaluating (the namespace has no builtins)
_ATTRIBUTE = re.compile(r"__|\.\s*[A-Za-df-zA-DF-Z_]|\.\s*[eE](?![-+]?\d)")
_SAFE = re.compile(r"(?:[A-Za-z_]\w*|\d+\.?\d*(?:e[-+]?\d+)?|\.\d+(?:e[-+]?\d+)?|[-+*/<>=(),\[\]\s])*")


def c_body(source, name):
    """The statements of generated function ``name`` (e.g. ``shang2010_ik``) in the C text
    ``source``: the lines of its ``static int casadi_fN`` body. CGraphError if absent."""
    head = re.search(r"/\* " + re.escape(name) + r":\(.*\*/\nstatic int (casadi_f\d+)\(",
                     source)
    if head is None:
        raise CGraphError(f"no function {name} in the generated C")
    start = source.index("{\n", head.end()) + 2
    return source[start:source.index("\n}\n", start)].splitlines()


def _translate(rhs):
    """A C right-hand side as a Python expression over the namespace of :func:`_namespace`."""
    py = _ARG.sub(r"_in[\1][\2]", rhs)
    py = _IFZ.sub(r"_ifz(\1,\2)", py)
    py = _NOT.sub(r"_not(\1)", py)
    py = _LOGIC.sub(lambda m: {"&&": "_and", "||": "_or", "==": "_eq", "!=": "_ne"}[m.group(2)]
                    + f"({m.group(1)},{m.group(3)})", py)
    for c_name, py_name in _HELPERS.items():
        py = re.sub(r"\b" + c_name + r"\b", py_name, py)
    return py


def _namespace():
    import casadi as ca
    ns = {f: getattr(ca, f) for f in _FUNCTIONS}
    ns.update(pow=ca.power, fabs=ca.fabs, sign=ca.sign, fmin=ca.fmin, fmax=ca.fmax,
              _sq=lambda a: a * a, _nan=ca.SX(np.nan), _inf=ca.SX(np.inf),
              _ifz=lambda c, x: ca.if_else(c, x, 0),
              _not=ca.logic_not, _and=ca.logic_and, _or=ca.logic_or, _eq=ca.eq, _ne=ca.ne)
    return ns


def sx_function(model, short):
    """``model``'s generated function ``short`` (``"ik"``, ``"Y"``, ...) as an SX
    :class:`casadi.Function` read from its C (module docstring), with the compiled function's
    input and output names and sparsity; a last input ``design`` is bound to ``model.design``
    (a model at a design: :meth:`pm2dof.Model.at_design`) and dropped from the inputs.

    Raises
    ------
    CGraphError
        The body is not straight-line code of the accepted forms, or leaves an output entry
        unwritten.
    """
    import casadi as ca
    name = f"{model.name}_{short}"
    ext = ca.external(name, model.library)
    source = model._manifest_obj.c_file.read_text()
    n_in = ext.n_in()
    bound = n_in > 0 and ext.name_in(n_in - 1) == "design"
    syms = [ca.SX.sym(ext.name_in(k), ext.sparsity_in(k)) for k in range(n_in - bound)]
    inputs = [s.nonzeros() for s in syms]
    if bound:
        inputs.append([ca.SX(float(v)) for v in np.asarray(model.design, float).ravel()])
    outs = read_body(c_body(source, name), inputs,
                     [ext.sparsity_out(k).nnz() for k in range(ext.n_out())], name)
    results = [ca.SX(ext.sparsity_out(k), ca.vertcat(*o) if o else ca.SX(0, 1))
               for k, o in enumerate(outs)]
    return ca.Function(short, syms, results, [ext.name_in(k) for k in range(n_in - bound)],
                       [ext.name_out(k) for k in range(ext.n_out())])


def read_body(lines, inputs, sizes_out, name):
    """The outputs of the straight-line C body ``lines`` (:func:`c_body`) as SX: a list per
    output of its ``sizes_out[k]`` nonzeros, given ``inputs`` (per input, the SX of its
    nonzeros, what ``arg[i][j]`` reads). ``name`` names the function in errors.

    Raises
    ------
    CGraphError
        A statement that is not one of the accepted forms, or an output entry not written.
    """
    outs = [[None] * k for k in sizes_out]
    ns = _namespace()
    ns["_in"] = inputs
    for line in lines:
        line = line.strip()
        if not line or line.startswith("casadi_real ") or line == "return 0;":
            continue
        assign, result = _ASSIGN.fullmatch(line), _RESULT.fullmatch(line)
        if result:
            outs[int(result.group(1))][int(result.group(2))] = ns[result.group(3)]
        elif assign:
            py = _translate(assign.group(2))
            if not _SAFE.fullmatch(py) or _ATTRIBUTE.search(py):
                raise CGraphError(f"{name}: cannot read {line!r}")
            try:
                ns[assign.group(1)] = eval(py, {"__builtins__": {}}, ns)   # noqa: S307
            except (NameError, TypeError, SyntaxError, IndexError) as err:
                raise CGraphError(f"{name}: cannot read {line!r} ({err})") from None
        else:
            raise CGraphError(f"{name}: not straight-line code at {line!r}")
    missing = [k for k, o in enumerate(outs) if any(v is None for v in o)]
    if missing:
        raise CGraphError(f"{name}: output(s) {missing} not written in full")
    return outs
