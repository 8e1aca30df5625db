# Griffe extension for the docs site: Sphinx roles in pm2dof's docstrings as cross-links.
"""pm2dof's numpydoc docstrings cross-reference with Sphinx roles (:func:`load_model`,
:class:`~pm2dof.core.layout.Layout`). mkdocstrings renders Markdown, where a role would show as
literal text, so once the package is loaded this extension rewrites each role before the
docstrings are parsed (the docstrings in the code stay as they are):

* the target is resolved as Sphinx's Python domain would: in the scope of the docstring's
  object (the object itself when it is a class or a module, then each enclosing class, module
  and package up to the top, then the subclasses of those classes, for a mixin's docstrings),
  then as a full dotted path, then as the one object of the package (of the role's kind) whose
  path ends with the target (a leading ``.``, or a name the package resolves on first access);
* a target the site renders becomes an optional mkdocs-autorefs cross-reference,
  ``<autoref identifier="pm2dof.Model" optional>`Model`</autoref>``, to the entry's own
  identifier: the name after ``:::`` in the docs pages (``pm2dof.Model``), or that entry's
  identifier and the member's name for a method or attribute (``pm2dof.Model.linearize``, also
  when the method is inherited from a base class the site does not render);
* any other target (outside the package, not rendered, a method that several entries inherit
  from one base class) becomes plain inline code, as do all roles when ``obj`` is unknown.

The title is the target as written, without its leading dots; a leading ``~`` keeps only the
last dotted component, and a leading ``!`` never links, as in Sphinx.
"""
import re
from pathlib import Path

import griffe

ROLE = re.compile(r":(?:py:)?(class|func|meth|attr|mod|data|exc|obj|const):`([~!]*)([^`]+)`")
#: role -> the kind of object it names (a role not here names any kind)
KINDS = {"class": "class", "exc": "class", "func": "function", "meth": "function",
         "attr": "attribute", "data": "attribute", "const": "attribute", "mod": "module"}
#: the pages whose ``::: identifier`` lines the site renders (this file is in docs/_ext/)
DOCS = Path(__file__).resolve().parent.parent
_LOOKUP_ERRORS = (KeyError, ValueError, griffe.AliasResolutionError, griffe.CyclicAliasError)


def rendered_identifiers(docs=DOCS):
    """Every identifier a ``:::`` line of the Markdown pages under ``docs`` renders."""
    return [m.group(1) for page in sorted(docs.glob("*.md"))
            for m in re.finditer(r"^:::[ \t]+(\S+)", page.read_text(encoding="utf-8"), re.M)]


def _title(prefix, target):
    title = target.lstrip(".")
    return title.rsplit(".", 1)[-1] if "~" in prefix else title


def _objects(pkg):
    """Every object defined in ``pkg`` (not the aliases: their docstrings are their targets')."""
    stack = [pkg]
    while stack:
        obj = stack.pop()
        yield obj
        stack.extend(m for m in obj.members.values() if not m.is_alias)


def _subclasses(cls):
    """The package's classes deriving from ``cls``."""
    for obj in _objects(cls.package):
        if obj.is_class:
            try:
                bases = [base.path for base in obj.resolved_bases]
            except _LOOKUP_ERRORS:
                continue
            if cls.path in bases:
                yield obj


def _scopes(obj):
    """The object (a class or a module) or its parent, then each enclosing scope to the top,
    then the subclasses of the classes among them."""
    scope = obj if (obj.is_class or obj.is_module) else obj.parent
    chain = []
    while scope is not None:
        chain.append(scope)
        scope = scope.parent
    yield from chain
    for scope in chain:
        if scope.is_class:
            yield from _subclasses(scope)


def _member(scope, dotted):
    try:
        return scope[dotted]
    except _LOOKUP_ERRORS:
        return None


def _canonical(found):
    try:
        return found.canonical_path
    except _LOOKUP_ERRORS:
        return None


def _by_suffix(package, suffix, kind):
    """The one object of ``package`` of ``kind`` (None: any) whose path ends with ``.suffix``,
    or None when none or several do."""
    hits = [obj for obj in _objects(package) if obj.path.endswith("." + suffix)
            and (kind is None or obj.kind.value == kind)]
    return hits[0] if len(hits) == 1 else None


def find(obj, target, role=None):
    """The object that ``target`` (of the Sphinx ``role``, e.g. ``"func"``) names as seen from
    ``obj``'s docstring, or None when it names nothing of ``obj``'s package."""
    name = target.lstrip(".")
    for scope in _scopes(obj):
        if (found := _member(scope, name)) is not None:
            return found
    top = obj.package
    if name == top.name:
        return top
    if name.startswith(top.name + ".") and (found := _member(top, name[len(top.name) + 1:])):
        return found
    # a name the package resolves on first access (pm2dof.__getattr__), or a leading-dot target
    return _by_suffix(top, name.removeprefix(top.name + "."), KINDS.get(role))


def identifier(found, entries):
    """The site's identifier of ``found``, or None when the site does not render it.
    ``entries`` maps the canonical path of each rendered entry to its ``:::`` identifier."""
    if found is None or (path := _canonical(found)) is None:
        return None
    if path in entries:
        return entries[path]
    inherited = found.is_alias and found.inherited
    owner = found.parent if inherited else _member(found.package, path.split(".", 1)[1]).parent
    if owner is None or not owner.is_class:
        return None
    if (cls := entries.get(_canonical(owner))) is not None:
        return f"{cls}.{found.name}"
    # a base class's member rendered under the one rendered class that inherits it
    heirs = {entries[c] for sub in _subclasses(owner) if found.name not in sub.members
             and (c := _canonical(sub)) in entries}
    return f"{heirs.pop()}.{found.name}" if len(heirs) == 1 else None


def rewrite_roles(text, obj=None, entries=None):
    """``text`` with every Sphinx role replaced by an optional autoref to its target's entry
    (resolved from ``obj``'s scope; ``entries`` as in :func:`identifier`), or by inline code when
    the site renders no entry for it (or ``obj`` is None)."""
    def repl(match):
        role, prefix, target = match.groups()
        code = f"`{_title(prefix, target)}`"
        link = None if (obj is None or "!" in prefix) else \
            identifier(find(obj, target, role), entries or {})
        return code if link is None else f'<autoref identifier="{link}" optional>{code}</autoref>'
    return ROLE.sub(repl, text)


def entries_of(pkg, identifiers):
    """canonical path -> identifier, for each of ``identifiers`` naming an object of ``pkg``."""
    out = {}
    for ident in identifiers:
        if ident == pkg.name or ident.startswith(pkg.name + "."):
            found = pkg if ident == pkg.name else _member(pkg, ident[len(pkg.name) + 1:])
            if found is not None and (path := _canonical(found)) is not None:
                out.setdefault(path, ident)
    return out


class SphinxRolesAsAutorefs(griffe.Extension):
    """Rewrite the Sphinx roles of every docstring of a loaded package to cross-references."""

    def on_package(self, *, pkg, **kwargs):  # griffe calls it once the whole package is loaded
        entries = entries_of(pkg, rendered_identifiers())
        originals = [(obj, obj.docstring.value) for obj in _objects(pkg)
                     if obj.docstring is not None]
        # resolve every role against the docstrings as loaded, then write the rewrites
        for obj, text in [(obj, rewrite_roles(text, obj, entries)) for obj, text in originals]:
            obj.docstring.value = text
