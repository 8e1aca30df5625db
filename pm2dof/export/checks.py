# The exported C's checks written from pm2dof's own tables: parameter rules and status codes.
"""C text for the exported API, generated from the one home of each rule.

* :func:`param_checks` -- a law's ``<law>_first_bad`` (the offset of the first parameter entry
  that breaks its rule of :data:`pm2dof.control.rules.RULES`, or -1) and the rules' texts that
  ``<name>_pm2dof_<law>_param_rule`` returns;
* :func:`rules_doc` -- the header's list of a law's rules, one line a field;
* :func:`status_cases` -- ``<name>_pm2dof_status_string``'s cases, from
  :class:`pm2dof.Status` and the API's own codes;
* :func:`status_codes` -- the codes the generated steps write (``status_code`` maps the real
  they write onto them).
"""
import math

from ..control.rules import rule
from ..core.status import Status

__all__ = ["param_checks", "rules_doc", "status_cases", "status_codes", "API_CODES"]

#: the API's codes beyond pm2dof.Status: (name, code, label)
API_CODES = (("NOT_RESET", -1, "not_reset"), ("BAD_PARAMS", -2, "bad_params"))


def _literal(x):
    """A C literal of the library's real type for the float ``x``."""
    return f"(real){float(x)!r}"


def _condition(r, x, bound):
    """The C expression that is true when the entry ``x`` keeps the rule ``r`` (false for NaN:
    every comparison with NaN is false; an infinite entry fails an upper bound or isfinite)."""
    if r.values:
        return " || ".join(f"{x} == {_literal(v)}" for v in r.values)
    parts = []
    if not (math.isfinite(r.lo) and math.isfinite(r.hi)):
        parts.append(f"isfinite({x})")
    if math.isfinite(r.lo):
        parts.append(f"{x} {'>' if r.lo_open else '>='} {_literal(r.lo)}")
    if math.isfinite(r.hi):
        parts.append(f"{x} {'<' if r.hi_open else '<='} {_literal(r.hi)}")
    if r.below:
        parts.append(f"{x} < {bound}")
    return " && ".join(parts)


def param_checks(law, layout, uname):
    """(C body of ``static int <law>_first_bad(const real *p)``, C body of ``<law>_param_rule
    (int offset)``: the rule's text of the field holding the offset, string literals only, so
    the library keeps no table of pointers) for ``law``'s parameter ``layout`` (a
    :class:`pm2dof.core.layout.Layout`); ``uname``: the header's prefix
    (``SHANG2010_PM2DOF``)."""
    body, texts = ["    int i;"], []
    for field, size in layout.fields:
        r = rule(law, field)
        off = f"{uname}_{law.upper()}_{field.upper()}"
        bound = f"p[{uname}_{law.upper()}_{r.below.upper()} + i]" if r.below else ""
        cond = _condition(r, f"p[{off} + i]", bound)
        body.append(f"    for (i = 0; i < {size}; i++)   /* {field}: {r.condition} */\n"
                    f"        if (!({cond}))\n            return {off} + i;")
        what = f"{field}: every entry finite and {r.condition}"
        texts.append(f"    if (offset >= {off} && offset < {off} + {size})\n"
                     f'        return "{what}";')
    body.append("    return -1;")
    texts.append("    return NULL;")
    return "\n".join(body), "\n".join(texts)


def rules_doc(law, layout):
    """The header's list of a law's parameter rules, one comment line a field."""
    return "\n".join(f" *   {field:24s} {rule(law, field).condition}"
                     for field, _ in layout.fields)


def status_cases(uname):
    """The ``case ...: return "label";`` lines of ``<name>_pm2dof_status_string``."""
    lines = [f'    case {uname}_{s.name}:\n        return "{s.label}";' for s in Status]
    lines += [f'    case {uname}_{name}:\n        return "{label}";'
              for name, _, label in API_CODES]
    return "\n".join(lines)


def status_codes():
    """The codes of :class:`pm2dof.Status`, as a C initialiser list."""
    return ", ".join(str(int(s)) for s in Status)
