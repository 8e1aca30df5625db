# The API page cross-links the Sphinx roles of the docstrings (docs/_ext/sphinx_roles.py).
"""The site is built here as ``make docs`` builds it (``mkdocs build --strict``, into a temporary
folder), and its API page is read back: every cross-reference link lands on an anchor of the
page, a sample of roles of rendered docstrings are links to their entries (a function, a class
by a re-exported name, a ``~`` title, a method inherited from a mixin, a method inherited from a
private base that several entries render), and roles naming what the page does not render are
plain code. The rewriting itself is checked on the package as griffe loads it, without MkDocs.
"""
import importlib.util
import inspect
import os
import re
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path

import pytest

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

ROOT = Path(__file__).resolve().parent.parent
griffe = pytest.importorskip("griffe", reason="make docs needs pm2dof[docs]")


def _extension():
    spec = importlib.util.spec_from_file_location("sphinx_roles",
                                                  ROOT / "docs" / "_ext" / "sphinx_roles.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


roles = _extension()

#: (rendered entry, a role in its docstring, the anchor it must link to, the link's text)
LINKED = [
    ("pm2dof.planning.plan_smooth", ":func:`plan_time_optimal`",
     "pm2dof.planning.plan_time_optimal", "plan_time_optimal"),
    ("pm2dof.identification.excitation.excite", ":class:`pm2dof.Trajectory`",
     "pm2dof.Trajectory", "pm2dof.Trajectory"),
    ("pm2dof.Model", ":class:`SingularityError`", "pm2dof.SingularityError", "SingularityError"),
    ("pm2dof.identification.log.LogError", ":class:`~pm2dof.core.errors.InputFileError`",
     "pm2dof.InputFileError", "InputFileError"),
    ("pm2dof.studies.run_study", ":func:`~pm2dof.studies.spec.read_study`",
     "pm2dof.studies.read_study", "read_study"),
    # methods of the mixin DerivativeMethods, rendered as Model's
    ("pm2dof.linear.statespace.statespace", ":meth:`pm2dof.Model.linearize`",
     "pm2dof.Model.linearize", "pm2dof.Model.linearize"),
    ("pm2dof.linear.statespace.statespace", ":meth:`Model.inverse_dynamics`",
     "pm2dof.Model.inverse_dynamics", "Model.inverse_dynamics"),
    ("pm2dof.Model.sampled_step_jacobians", ":meth:`forward_dynamics_jacobians`",
     "pm2dof.Model.forward_dynamics_jacobians", "forward_dynamics_jacobians"),
    # _Controller.step, rendered under each controller
    ("pm2dof.linear.lqr.LQRController.step", ":meth:`pm2dof.NAController.step`",
     "pm2dof.NAController.step", "pm2dof.NAController.step"),
]
#: (rendered entry, a role in its docstring naming nothing the page renders, its code text)
PLAIN = [
    ("pm2dof.identification.excitation.excite", ":func:`~.signals.multisine`", "multisine"),
    ("pm2dof.studies.run_study", ":class:`~pm2dof.studies.spec.Study`", "Study"),
    ("pm2dof.linear.statespace.statespace", ":func:`state_names`", "state_names"),
]


def _python_object(path):
    """The object at dotted ``path``: its longest importable module, then attributes."""
    parts = path.split(".")
    for i in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:i]))
            break
        except ImportError:
            continue
    for name in parts[i:]:
        obj = getattr(obj, name)
    return obj


class _Page(HTMLParser):
    """The ids of a page, and its cross-reference links as (href, text, entry they sit in)."""

    def __init__(self):
        super().__init__()
        self.ids, self.links, self._entry, self._link = set(), [], None, None

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if "id" in attrs:
            self.ids.add(attrs["id"])
        if "doc-heading" in (attrs.get("class") or "").split():
            self._entry = attrs.get("id")
        if tag == "a" and "autorefs" in (attrs.get("class") or "").split():
            self._link = [attrs.get("href"), ""]

    def handle_data(self, data):
        if self._link is not None:
            self._link[1] += data

    def handle_endtag(self, tag):
        if tag == "a" and self._link is not None:
            self.links.append((*self._link, self._entry))
            self._link = None


#: the tests that read the built site are marked slow (building it takes 8 s: make test-slow,
#: which CI runs; CI's make docs builds the same site with --strict); the rewriting is checked on
#: the package without MkDocs in make test
reads_the_site = pytest.mark.slow


@pytest.fixture(scope="module")
def api_html(tmp_path_factory):
    """site/api.html as ``make docs`` builds it (warnings are errors)."""
    pytest.importorskip("mkdocstrings", reason="make docs needs pm2dof[docs]")
    site = tmp_path_factory.mktemp("site")
    env = {**os.environ, "NO_MKDOCS_2_WARNING": "1", "PYTHONPATH": str(ROOT)}
    run = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--site-dir",
                          str(site)], cwd=ROOT, env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr[-4000:]
    return (site / "api.html").read_text(encoding="utf-8")


@pytest.fixture(scope="module")
def page(api_html):
    parsed = _Page()
    parsed.feed(api_html)
    return parsed


@reads_the_site
def test_every_link_lands_on_an_entry_of_the_page(page):
    internal = [href for href, _, _ in page.links if href.startswith("#")]
    assert len(internal) >= len(LINKED)
    assert [href for href, _, _ in page.links if not href.startswith("#")] == []
    assert sorted({h for h in internal if h[1:] not in page.ids}) == []


@reads_the_site
def test_no_role_or_autoref_markup_is_left(api_html):
    assert re.findall(r":(?:func|class|meth|attr|mod|data|exc|obj|const):`", api_html) == []
    assert "autoref " not in api_html and "&lt;autoref" not in api_html


@reads_the_site
@pytest.mark.parametrize("entry, role, anchor, text", LINKED)
def test_sample_roles_link_to_their_entries(page, entry, role, anchor, text):
    assert role in inspect.getdoc(_python_object(entry))
    assert anchor in page.ids
    assert ("#" + anchor, text, entry) in page.links


@reads_the_site
@pytest.mark.parametrize("entry, role, text", PLAIN)
def test_roles_the_page_does_not_render_are_plain_code(api_html, page, entry, role, text):
    assert role in inspect.getdoc(_python_object(entry))
    assert not [link for link in page.links if link[1] == text and link[2] == entry]
    start = api_html.index(">", api_html.index(f'id="{entry}"'))  # the end of its heading
    section = api_html[start:api_html.find("doc-heading", start)]
    assert f"<code>{text}</code>" in section


@pytest.fixture(scope="module")
def package():
    return griffe.GriffeLoader(search_paths=[str(ROOT)]).load("pm2dof")


@pytest.fixture(scope="module")
def entries(package):
    return roles.entries_of(package, roles.rendered_identifiers())


def test_rewrite_links_rendered_targets_and_leaves_others_as_code(package, entries):
    statespace = package["linear.statespace.statespace"]
    text = (":meth:`pm2dof.Model.linearize` :class:`~pm2dof.core.errors.InputFileError` "
            ":func:`numpy.gradient` :func:`no_such_name` :meth:`!pm2dof.Model.linearize` "
            ":func:`state_names`")
    assert roles.rewrite_roles(text, statespace, entries) == " ".join([
        '<autoref identifier="pm2dof.Model.linearize" optional>`pm2dof.Model.linearize`</autoref>',
        '<autoref identifier="pm2dof.InputFileError" optional>`InputFileError`</autoref>',
        "`numpy.gradient`", "`no_such_name`", "`pm2dof.Model.linearize`", "`state_names`"])
    assert roles.rewrite_roles(text) == ("`pm2dof.Model.linearize` `InputFileError` "
                                         "`numpy.gradient` `no_such_name` "
                                         "`pm2dof.Model.linearize` `state_names`")


def test_a_base_method_several_entries_inherit_is_plain_code(package, entries):
    """``_Controller.step`` is rendered under NAController, APDController, CTCController and
    LQRController: seen from the base class, no one of them is the link."""
    base = package["control.controllers._Controller"]
    found = roles.find(base, "step", "meth")
    assert found.path == "pm2dof.control.controllers._Controller.step"
    assert roles.identifier(found, entries) is None
    assert roles.rewrite_roles(":meth:`step`", base, entries) == "`step`"
