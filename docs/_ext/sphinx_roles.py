# Griffe extension for the docs site: Sphinx roles in pm2dof's docstrings rendered as code.
"""pm2dof's numpydoc docstrings cross-reference with Sphinx roles (:func:`load_model`,
:class:`~pm2dof.core.layout.Layout`). mkdocstrings renders Markdown, where a role would show
as literal text, so this extension rewrites each role to inline code before the docstring is
parsed: ``:func:`load_model``` -> ```load_model```, and a leading ``~`` keeps only the last
dotted component, as Sphinx does. The docstrings themselves stay as they are.
"""
import re

import griffe

_ROLE = re.compile(r":(?:py:)?(?:class|func|meth|attr|mod|data|exc|obj|const):`(~?)([^`]+)`")


def _code(match):
    target = match.group(2)
    return f"`{target.rsplit('.', 1)[-1] if match.group(1) else target}`"


def rewrite_roles(text):
    """``text`` with every Sphinx role replaced by inline code of its target."""
    return _ROLE.sub(_code, text)


class SphinxRolesAsCode(griffe.Extension):
    """Rewrite Sphinx roles to inline code in every loaded object's docstring."""

    def on_instance(self, *, obj, **kwargs):  # griffe calls it once per loaded object
        if obj.docstring is not None:
            obj.docstring.value = rewrite_roles(obj.docstring.value)
