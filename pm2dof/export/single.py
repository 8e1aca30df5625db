# Single precision: the generated C rewritten for float, and the checks that say where it breaks.
"""The generated C in single precision.

CasADi writes ``casadi_real`` (``double`` unless defined) for every value, double literals
(``2.4399999999999999e-01``) and the ``double`` math functions (``sin``, ``sqrt``). Defining
``casadi_real`` as ``float`` alone would store floats but compute every literal product and
every math call in double (and emulate it in software on a single-precision FPU such as the
Cortex-M4F's). :func:`to_single` therefore rewrites a copy: ``casadi_real`` is ``float``, the
literals carry an ``f`` suffix, and each call of a math function calls its float version
(``sin(`` -> ``sinf(``; C99's ``<tgmath.h>`` would do the same, but newlib's does not compile
with GCC's ``__builtin_tgmath``).

Where float is not enough, :func:`single_problems` says so and the export refuses:

* a literal outside float's normal range (it would become 0 or inf);
* the min-max and preload torque splits: they choose among candidate optima with tolerances
  of 1e-10 and 1e-12 relative (pm2dof/derive/splits.py), far below float's resolution
  (FLT_EPSILON = 1.2e-7), so a step with those splits is refused (the minimum-norm split,
  eq. 21, is a closed form and has no tolerance);
* a closure tolerance or a singularity threshold too small for float: the residual of the
  loop closure computed in float is a few FLT_EPSILON times the leg's reach, so a tolerance
  below :data:`CLOSURE_ULPS` of those would reject good encoder readings (the reach of
  :func:`leg_reach`).
"""
import re

__all__ = ["to_single", "single_problems", "leg_reach", "FLT_EPSILON", "CLOSURE_ULPS"]

FLT_EPSILON = 2.0 ** -23        # float's resolution at 1
FLT_MIN, FLT_MAX = 2.0 ** -126, (2 - 2.0 ** -23) * 2.0 ** 127
#: the closure tolerance must exceed this many FLT_EPSILON times the reach (la + lb)
CLOSURE_ULPS = 64
#: a singularity threshold must exceed this many FLT_EPSILON
THRESHOLD_ULPS = 1024

# a floating literal: digits with a point (and exponent) or digits with an exponent, not part
# of an identifier or of a longer number (CasADi's "3.8.2" in a comment is left alone)
_LITERAL = re.compile(r"(?<![\w.])(\d+\.\d*(?:[eE][+-]?\d+)?|\d+[eE][+-]?\d+)(?![\w.])")


#: the <math.h> functions that have float versions (name + "f"), as CasADi may call them
_MATH = ("sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh", "asinh",
         "acosh", "atanh", "exp", "expm1", "log", "log1p", "log10", "pow", "sqrt", "cbrt",
         "floor", "ceil", "fabs", "fmin", "fmax", "fmod", "copysign", "erf", "erfc", "hypot",
         "round", "trunc")
_CALL = re.compile(r"(?<![\w.])(" + "|".join(_MATH) + r")\(")


def _literals(text):
    return [m.group(1) for m in _LITERAL.finditer(text)]


def to_single(c_text):
    """The generated C file (or header) ``c_text`` rewritten for float (module doc)."""
    out = c_text.replace("#define casadi_real double", "#define casadi_real float")
    if "casadi_real casadi_sq(" in out or "casadi_f0(" in out:    # code, not the header
        out = _LITERAL.sub(lambda m: m.group(1) + "f", out)
        out = _CALL.sub(lambda m: m.group(1) + "f(", out)
    return out


def leg_reach(leg):
    """How far a leg's tip can be from its base point, m: la + lb (RRR), the rail's length +
    lb (PRR), the longest stroke (RPR). The loop closure's residual is computed from
    coordinates of this size."""
    if leg.kind == "PRR":
        return leg.rail_length + leg.lb
    if leg.kind == "RPR":
        return max(leg.stroke)
    return leg.la + leg.lb


def single_problems(c_text, model, split):
    """What single precision would break for this model's exported code: a list of sentences
    (empty when float will do)."""
    problems = []
    bad = sorted({s for s in _literals(c_text)
                  if float(s) != 0 and not FLT_MIN <= abs(float(s)) <= FLT_MAX})
    if bad:
        problems.append(f"the generated code has constants outside float's range "
                        f"({', '.join(bad[:5])})")
    if split != "min_norm":
        problems.append(f"[control] split = {split!r}: the min-max and preload splits choose "
                        f"among candidate optima with tolerances of 1e-10 relative, below "
                        f"float's resolution (1.2e-7); export the min_norm split (eq. 21) in "
                        f"single precision, or this split in double")
    reach = max(leg_reach(leg) for leg in model.spec.legs)
    need = CLOSURE_ULPS * FLT_EPSILON * reach
    if model.closure_tolerance < need:
        problems.append(f"[sensing] closure_tolerance = {model.closure_tolerance:.3g} m is "
                        f"below float's resolution of the loop closure ({CLOSURE_ULPS} x "
                        f"FLT_EPSILON x reach = {need:.3g} m): good encoder readings would be "
                        f"refused as inconsistent")
    for name, thr in (("singularity_threshold", model.singularity_threshold),
                      ("parallel_singularity_threshold", model.parallel_singularity_threshold)):
        if thr < THRESHOLD_ULPS * FLT_EPSILON:
            problems.append(f"[limits] {name} = {thr:.3g} is below {THRESHOLD_ULPS} x "
                            f"FLT_EPSILON = {THRESHOLD_ULPS * FLT_EPSILON:.3g}: float cannot "
                            f"tell such a pose from a singular one")
    return problems
