# Static operation counts of the generated C: multiplications, additions, math calls per function.
"""Count the operations of generated functions by reading CasADi's C output (no compiler needed)."""
import re

__all__ = ["count_ops", "OPS_FUNCTIONS"]

# Functions whose generated C body is measured, by short name.
OPS_FUNCTIONS = ("na_step", "apd_step", "na_closed_loop", "plant_step", "Y", "forward_dynamics")

# Math-library / CasADi helper calls counted in a body.
_CALLS = ("sin", "cos", "tan", "sqrt", "atan2", "exp", "log", "tanh", "acos", "asin", "atan",
          "floor", "pow", "fmin", "fmax", "fabs", "sq")

_BODY_START = re.compile(r"^static int (casadi_f\d+)\(const casadi_real\*\* arg", re.M)
_WRAPPER = re.compile(r"^CASADI_SYMBOL_EXPORT int (\w+)\(const casadi_real\*\* arg[^{]*\{\s*"
                      r"return (casadi_f\d+)\(arg, res, iw, w, mem\);", re.M)
_BINARY = re.compile(r"=\s*\(\s*[\w.]+\s*([-+*/])\s*[\w.]+\s*\)\s*;")
_COMPOUND = re.compile(r"^\s*[\w\[\]]+\s*([-+*/])=\s*[\w.]+\s*;")
_NEG = re.compile(r"=\s*\(\s*-\s*\w+\s*\)\s*;")
_CMP = re.compile(r"=\s*\(\s*\w+\s*(<=|>=|<|>|==|!=)\s*\w+\s*\)\s*;")
_SELECT = re.compile(r"=\s*\(\s*\w+\s*\?\s*\w+\s*:\s*[\w.]+\s*\)\s*;")
_CALL = re.compile(r"\b(?:casadi_)?(" + "|".join(_CALLS) + r")\s*\(")
_SUBCALL = re.compile(r"\b(casadi_f\d+)\s*\(arg1")


def _bodies(src):
    """{casadi_fN: body text} of the generated C."""
    out = {}
    for m in _BODY_START.finditer(src):
        end = src.find("\n}\n", m.end())
        out[m.group(1)] = src[m.end():end if end >= 0 else len(src)]
    return out


def _own_counts(body):
    c = {"mul": 0, "add": 0, "sub": 0, "div": 0, "neg": 0, "cmp": 0, "select": 0,
         **{k: 0 for k in _CALLS}}
    sym = {"*": "mul", "+": "add", "-": "sub", "/": "div"}
    for line in body.splitlines():
        m = _BINARY.search(line) or _COMPOUND.search(line)
        if m:
            c[sym[m.group(1)]] += 1
        elif _NEG.search(line):
            c["neg"] += 1
        elif _CMP.search(line):
            c["cmp"] += 1
        elif _SELECT.search(line):
            c["select"] += 1
        for name in _CALL.findall(line):
            c[name] += 1
    return c


def count_ops(c_source, public_names):
    """Static operation counts of generated functions, read from their C source.

    Parameters
    ----------
    c_source : str
        Text of ``generated/<name>/<name>.c``.
    public_names : iterable of str
        Exported names (``shang2010_na_step``, ...).

    Returns
    -------
    dict
        {public name: {"body": casadi_fN, "mul", "add", "sub", "div", "neg", "cmp", "select",
        one count per math call (sin, cos, sqrt, atan2, exp, tanh, fmin, fmax, fabs, sq, ...),
        "flops" (mul + add + sub + div + neg + sq), "transcendental" (sin + cos + ... + tanh),
        "calls" {callee body: times}}}. Counts are of statements in the straight-line code
        CasADi writes, inclusive of the functions a body calls (the closed loop calls the step,
        the encoder and 4 plant steps); ``sq`` is x*x, counted apart from ``mul``.
    """
    bodies = _bodies(c_source)
    wrappers = dict(_WRAPPER.findall(c_source))
    memo = {}

    def inclusive(fn, depth=0):
        if fn in memo:
            return memo[fn]
        if depth > 50:
            raise RecursionError(fn)
        body = bodies[fn]
        c = _own_counts(body)
        calls = {}
        for callee in _SUBCALL.findall(body):
            calls[callee] = calls.get(callee, 0) + 1
            sub = inclusive(callee, depth + 1)
            for k, v in sub.items():
                if k not in ("calls", "body"):
                    c[k] += v
        c["calls"] = calls
        memo[fn] = c
        return c

    out = {}
    for name in public_names:
        fn = wrappers.get(name)
        if fn is None or fn not in bodies:
            raise KeyError(f"no generated body for {name} in the C source")
        c = dict(inclusive(fn))
        c["flops"] = c["mul"] + c["add"] + c["sub"] + c["div"] + c["neg"] + c["sq"]
        c["transcendental"] = sum(c[k] for k in ("sin", "cos", "tan", "sqrt", "atan2", "exp",
                                                 "log", "tanh", "acos", "asin", "atan", "pow"))
        out[name] = {"body": fn, **c}
    return out
