# A folder of generated code's manifest.json: who derived it, its hashes, its functions' sizes.
"""The one reader of ``manifest.json``, the record ``pm2dof derive`` writes beside its C.

:class:`Manifest` loads it, names the model file that owns the folder, compares its hashes
with a model file and this install, checks the generated files against their recorded
hashes, and gives each function's signature and work sizes (as the generated C declares
them in ``<f>_work``, recorded at derive time). :func:`pm2dof.load_model`,
:func:`pm2dof.core.generated.up_to_date`, ``pm2dof derive`` and ``pm2dof export`` all read
the manifest through it. Needs neither SymPy nor CasADi.
"""
import hashlib
import json
from importlib import metadata
from pathlib import Path

from . import build
from .status import Status

__all__ = ["Manifest", "MANIFEST", "derive_sources_sha256", "file_sha256"]

MANIFEST = "manifest.json"
DERIVE_DIR = Path(__file__).resolve().parent.parent / "derive"
#: a function's work sizes in the manifest, in CasADi's ``<f>_work`` order
WORK_FIELDS = ("arg", "res", "iw", "w")


def derive_sources_sha256():
    """Hash of every derivation source file (``pm2dof/derive/*.py``, name and content), in
    sorted order: the manifest's ``derive_sources_sha256``."""
    h = hashlib.sha256()
    for path in sorted(DERIVE_DIR.glob("*.py")):
        h.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    return h.hexdigest()


def file_sha256(path):
    """SHA-256 of a file's bytes, hex."""
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def _version(name):
    try:
        return metadata.version(name)
    except metadata.PackageNotFoundError:
        return None


class Manifest:
    """The manifest of the generated code in ``folder``; build with :meth:`read`.

    Attributes: ``folder`` (Path), ``data`` (the parsed JSON, a dict), ``name`` (the model's
    name, the prefix of every generated function).
    """

    def __init__(self, folder, data):
        self.folder = Path(folder)
        self.data = data
        self.name = data.get("model")

    @classmethod
    def read(cls, folder):
        """The manifest of ``folder``, or None when it has no readable ``manifest.json``."""
        try:
            data = json.loads((Path(folder) / MANIFEST).read_text())
        except (OSError, ValueError):
            return None
        return cls(folder, data) if isinstance(data, dict) else None

    def get(self, key, default=None):
        return self.data.get(key, default)

    @property
    def path(self):
        return self.folder / MANIFEST

    # --- owner ---------------------------------------------------------------------------
    def model_file(self):
        """The model file the folder was derived from (resolved), or None if not recorded."""
        recorded = self.data.get("model_file")
        return (self.folder / recorded).resolve() if recorded else None

    def owned_by(self, model_path):
        """True if the folder was derived from the model file ``model_path``."""
        return model_path is not None and self.model_file() == Path(model_path).resolve()

    # --- hashes --------------------------------------------------------------------------
    def what_changed(self, spec):
        """"" if the manifest records ``spec`` (a ModelSpec) and this install (the derivation's
        sources, SymPy, CasADi, the status codes); else what differs, e.g. "the model file
        changed"."""
        checks = {"the model file": (self.data.get("model_file_sha256"), spec.file_sha256),
                  "the formulation": (self.data.get("formulation_sha256"),
                                      spec.formulation_sha256),
                  "the derivation's sources": (self.data.get("derive_sources_sha256"),
                                               derive_sources_sha256()),
                  "the SymPy and CasADi versions": (self.data.get("versions"),
                                                    {"sympy": _version("sympy"),
                                                     "casadi": _version("casadi")}),
                  "the status codes": (self.data.get("status_codes"), Status.codes()),
                  "rk4_substeps": (self.data.get("rk4_substeps"), spec.rk4_substeps)}
        for what, (have, want) in checks.items():
            if have != want:
                return f"{what} changed"
        return ""

    def file_differs(self, name):
        """True if the generated file ``name`` is missing or its hash is not the recorded one
        (a file the manifest does not record counts as differing)."""
        want = self.data.get("files", {}).get(name)
        p = self.folder / name
        return want is None or not p.is_file() or file_sha256(p) != want

    def files_differing(self):
        """The recorded files that are missing or differ from their hashes, in order."""
        return [name for name in self.data.get("files", {}) if self.file_differs(name)]

    @property
    def c_file(self):
        return self.folder / f"{self.name}.c"

    @property
    def library(self):
        return self.folder / f"lib{self.name}.so"

    def library_is_fresh(self):
        """True if the compiled library was built from the recorded C
        (:func:`pm2dof.core.build.library_is_fresh`)."""
        return build.library_is_fresh(self.c_file, self.library,
                                      self.data.get("files", {}).get(self.c_file.name))

    # --- functions -----------------------------------------------------------------------
    def function_names(self):
        """The short names of the generated functions (the model's prefix stripped)."""
        k = len(self.name) + 1
        return tuple(f[k:] for f in self.data.get("functions", {}))

    def signature(self, short):
        """{"inputs": [[name, count], ...], "outputs": [...]} of ``<model>_<short>``, or None."""
        f = self.data.get("functions", {}).get(f"{self.name}_{short}")
        return None if f is None else {"inputs": f.get("inputs"), "outputs": f.get("outputs")}

    def work_sizes(self, short):
        """(sz_arg, sz_res, sz_iw, sz_w) of ``<model>_<short>``, as its ``<f>_work`` in the
        generated C declares them; None when the function or its sizes are not recorded."""
        f = self.data.get("functions", {}).get(f"{self.name}_{short}")
        work = None if f is None else f.get("work")
        return None if work is None else tuple(int(work[k]) for k in WORK_FIELDS)
