# Pruning: the generated C cut down to the functions an export calls, with internal linkage.
"""The generated C of ``pm2dof derive``, pruned to what a set of entry points reaches.

``pm2dof derive`` generates every function of the model into one C file (CasADi's
``CodeGenerator``): the controllers' steps, fk, ik and the splits, but also the model's
matrices, the regressor, the planner's and the identification's functions. A controller
library needs a few of them. The export runs from a wheel without CasADi, so it reads the C
text, whose layout CasADi writes regularly:

* a preamble (``#include``, ``#define casadi_real``, one ``#define casadi_<x>
  CASADI_PREFIX(<x>)`` per internal symbol, the ``CASADI_SYMBOL_EXPORT`` macro);
* top-level items, one per definition: CasADi's helper functions (``casadi_sq``,
  ``casadi_copy``; external in CasADi's output), the sparsity arrays ``casadi_s<k>``,
  ``casadi_zeros``, the bodies ``static int casadi_f<k>(...)``, each preceded by its signature
  as a comment, and the public wrappers ``<model>_<function>`` (the call itself, ``_work``,
  ``_sparsity_in``, ``_n_in``, ...), and a few ``#define`` lines between them;
* a trailer closing ``extern "C"``.

:func:`prune` keeps the items reachable from the entry points' wrappers (a body may call
another body: ``casadi_f16`` inside a step) and makes all of them ``static``, the entry points
included unless asked otherwise. :func:`math_calls` lists the ``<math.h>`` functions a C text
calls, for the header's list of what the library needs.
"""
import re

from ..core.errors import StaleGeneratedCodeError

__all__ = ["prune", "math_calls", "function_count", "MATH_FUNCTIONS", "COMPILER_CALLS"]

#: the <math.h> functions CasADi's generated code may call (and their float versions, + "f")
MATH_FUNCTIONS = ("sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh",
                  "asinh", "acosh", "atanh", "exp", "expm1", "log", "log1p", "log10", "pow",
                  "sqrt", "cbrt", "floor", "ceil", "fabs", "fmin", "fmax", "fmod", "copysign",
                  "erf", "erfc", "hypot", "round", "trunc")
#: functions a C compiler may call although the text does not: memset, memcpy and memmove for
#: loops that clear or copy arrays (GCC at -O2 and above), and sincos (GCC, a GNU extension of
#: glibc and newlib) for the sine and the cosine of one angle
COMPILER_CALLS = ("memset", "memcpy", "memmove", "sincos")

_CALL = re.compile(r"(?<![\w.])(" + "|".join(MATH_FUNCTIONS) + r")(f?)\s*\(")
_HELPER = re.compile(r"^(?:casadi_real|void) casadi_\w+\(")
_WRAPPER = "CASADI_SYMBOL_EXPORT "
_NAME = re.compile(r"(\w+)\s*[(\[]")
_WORD = re.compile(r"\b\w+\b")
_COMMENT_OR_STRING = re.compile(r'/\*.*?\*/|"(?:[^"\\]|\\.)*"|//[^\n]*')


def _layout_error(what):
    return StaleGeneratedCodeError(
        f"the generated C does not have the layout pm2dof export reads ({what}); re-derive the "
        f"model with this pm2dof (`pm2dof derive`)")


def _items(body):
    """The top-level items of the text between preamble and trailer: a list of
    [name or None, text]; None for a preprocessor line between items (always kept)."""
    items, lines, depth, pending = [], body.splitlines(keepends=True), 0, ""
    cur, in_comment = None, False
    for line in lines:
        stripped = line.strip()
        if cur is None:                       # between items
            if in_comment or stripped.startswith("/*"):
                pending += line
                in_comment = "*/" not in (line if in_comment else line[line.index("/*"):])
                continue
            if not stripped:
                pending += line
                continue
            if stripped.startswith("#"):
                items.append([None, pending + line])
                pending = ""
                continue
            cur, pending = pending + line, ""
        else:
            cur += line
        depth += sum(1 if c == "{" else -1 for c in
                     _COMMENT_OR_STRING.sub("", line) if c in "{}")
        if depth < 0:
            raise _layout_error("unbalanced braces")
        code = _COMMENT_OR_STRING.sub("", line).rstrip()
        if depth == 0 and (code.endswith("}") or code.endswith(";")):
            head = _COMMENT_OR_STRING.sub("", cur)
            m = _NAME.search(head)
            if m is None:
                raise _layout_error(f"a definition without a name: {head.strip()[:60]!r}")
            items.append([m.group(1), cur])
            cur = None
    if cur is not None or depth:
        raise _layout_error("a definition does not end")
    if pending.strip():
        items.append([None, pending])
    return items


def _split(c_text):
    lines = c_text.splitlines(keepends=True)
    first = next((i for i, s in enumerate(lines) if _HELPER.match(s)
                  or s.startswith(("static ", _WRAPPER))), None)
    last = max((i for i, s in enumerate(lines) if s.startswith("#ifdef __cplusplus")),
               default=None)
    if first is None or last is None or last < first:
        raise _layout_error("no CasADi helper or function definitions")
    return "".join(lines[:first]), "".join(lines[first:last]), "".join(lines[last:])


def prune(c_text, name, entries, *, external=False):
    """The generated C text ``c_text`` of model ``name`` pruned to what ``entries`` reach.

    Parameters
    ----------
    c_text : str
        The generated C (``<name>.c`` of ``pm2dof derive``).
    name : str
        The model's name: the prefix of the public wrappers (``<name>_fk``).
    entries : iterable of str
        The functions wanted, without the prefix (``"fk"``, ``"na_step"``).
    external : bool
        False (default): every function is ``static``, the entry points included (the text
        is then compiled inside the translation unit that calls them). True: the entry
        points keep external linkage, every other function is ``static``.

    Returns
    -------
    str
        The pruned C: the preamble (without the prefix macros of what was dropped), the
        helpers, sparsity arrays, bodies and entry points reached, in their original order.

    Raises
    ------
    StaleGeneratedCodeError
        An entry point is not in the text, or the text is not laid out as CasADi writes it.
    """
    preamble, body, trailer = _split(c_text)
    items = _items(body)
    by_name = {}
    for item in items:
        if item[0] is not None:
            by_name.setdefault(item[0], item)
    roots = [f"{name}_{e}" for e in entries]
    missing = [r for r in roots if r not in by_name]
    if missing:
        raise StaleGeneratedCodeError(f"the generated C of {name!r} has no function "
                                      f"{', '.join(missing)}; re-derive it (`pm2dof derive`)")
    keep, todo = set(), list(roots)
    while todo:
        n = todo.pop()
        if n in keep:
            continue
        keep.add(n)
        text = _COMMENT_OR_STRING.sub("", by_name[n][1])
        todo += [w for w in set(_WORD.findall(text)) if w in by_name and w not in keep]
    out = []
    for n, text in items:
        if n is None:
            out.append(text)
        elif n in keep:
            if _WRAPPER in text and not (external and n in roots):
                text = text.replace(_WRAPPER, "static ", 1)
            else:                   # CasADi's helpers are external: make them static
                text = re.sub(r"^(casadi_real|void) (casadi_\w+\()", r"static \1 \2", text,
                              count=1, flags=re.M)
            out.append(text)
    kept_macros = {n[len("casadi_"):] for n in keep if n.startswith("casadi_")}
    preamble = re.sub(r"^#define casadi_(\w+) CASADI_PREFIX\(\1\)\n",
                      lambda m: m.group(0) if m.group(1) in kept_macros else "", preamble,
                      flags=re.M)
    return preamble + "".join(out) + trailer


def function_count(c_text):
    """The number of function definitions in a generated (or pruned) C text."""
    _, body, _ = _split(c_text)
    return sum(1 for n, text in _items(body)
               if n is not None and "(" in _COMMENT_OR_STRING.sub("", text).split("{")[0])


def math_calls(*texts):
    """The <math.h> functions the C ``texts`` call (``sinf`` in single precision), sorted."""
    found = set()
    for text in texts:
        for m in _CALL.finditer(_COMMENT_OR_STRING.sub("", text)):
            found.add(m.group(1) + m.group(2))
    return sorted(found)
