# External names: the exported library's link names, unique in the first 31 characters.
"""The link names of an exported library's functions.

C99 (5.2.4.1) guarantees only the first 31 characters of an external identifier to be
significant, and MISRA C:2012 rule 5.1 asks external identifiers to be distinct in them. The
API's names are ``<model>_pm2dof_<what>``: with a long model name two of them can share their
first 31 characters (``shang2010_vertical_pm2dof_theta_nominal`` and ``..._theta_hat``). Then
the header maps every API name to a shorter link name by a macro, as ICU does for its
versioned symbols: ``<the model name's first 8 characters>_<6 hex digits of its SHA-256>_<what>``.
The source keeps the API's names; the object files, the linker and a debugger see the link
names. Where the API's names are already distinct in 31 characters, nothing is renamed.
"""
import hashlib
import re

__all__ = ["SIGNIFICANT", "api_functions", "link_names", "link_prefix", "with_link_names",
           "collisions"]

#: characters of an external identifier that C99 guarantees significant (MISRA C:2012 5.1)
SIGNIFICANT = 31


def api_functions(header, name):
    """The functions the API header declares: every ``<name>_pm2dof_<what>(``, sorted."""
    return sorted(set(re.findall(rf"\b({re.escape(name)}_pm2dof_\w+)\s*\(", header)))


def collisions(names, n=SIGNIFICANT):
    """Groups (sorted lists) of ``names`` that share their first ``n`` characters."""
    groups = {}
    for s in names:
        groups.setdefault(s[:n], []).append(s)
    return sorted(sorted(g) for g in groups.values() if len(g) > 1)


def link_prefix(name):
    """The start of the short link names of model ``name``'s library: ``<name[:8]>_<6 hex>_``
    (the hash keeps two models' libraries apart when their names share 8 characters)."""
    return f"{name[:8]}_{hashlib.sha256(name.encode()).hexdigest()[:6]}_"


def link_names(header, name):
    """{API name: link name} for the functions of ``header``; empty when the API's names are
    distinct in their first :data:`SIGNIFICANT` characters.

    Raises
    ------
    RuntimeError
        The short link names still share their first 31 characters (two API names whose
        ``<what>`` parts agree in their first 15 characters): a bug of the templates.
    """
    funcs = api_functions(header, name)
    if not collisions(funcs):
        return {}
    prefix = link_prefix(name)
    out = {f: prefix + f[len(f"{name}_pm2dof_"):] for f in funcs}
    if collisions(out.values()):
        raise RuntimeError(f"the link names of {name}'s API are not distinct in "
                           f"{SIGNIFICANT} characters: {collisions(out.values())}")
    return out


def with_link_names(header, guard, names):
    """``header`` with the ``#define <API name> <link name>`` lines of ``names`` after its
    include guard ``#define <guard>``."""
    if not names:
        return header
    block = ("\n/* Link names: C99 guarantees only the first 31 characters of an external name "
             "(MISRA C:2012\n * rule 5.1), and some of this API's names share those. Each "
             "function below is\n * therefore linked under a shorter name (the objects and a "
             "debugger show it). */\n"
             + "".join(f"#define {api} {short}\n" for api, short in sorted(names.items())))
    mark = f"#define {guard}\n"
    if mark not in header:
        raise RuntimeError(f"the header has no include guard {guard}")
    return header.replace(mark, mark + block, 1)
