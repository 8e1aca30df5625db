# Is a model file's generated code current? (`pm2dof derive` re-run on an unchanged model.)
"""Whether a folder of generated code is what ``pm2dof derive`` would write now.

:func:`up_to_date` compares the folder's ``manifest.json`` with the model file and this
install, without importing SymPy or CasADi (a re-derivation takes tens of seconds; this check
a fraction of one): the model file (its bytes and its formulation), the derivation's sources
(``pm2dof/derive/*.py``), the SymPy and CasADi versions, the status codes, the generated
files' hashes, and the compiled library's build record (:func:`pm2dof.core.build.library_is_fresh`).
"""
import hashlib
import json
from importlib import metadata
from pathlib import Path

from . import build
from .status import Status

__all__ = ["up_to_date", "derive_is_current", "derive_sources_sha256"]

DERIVE_DIR = Path(__file__).resolve().parent.parent / "derive"


def derive_sources_sha256():
    """Hash of every derivation source file (name and content), in sorted order: the manifest's
    ``derive_sources_sha256`` (as :func:`pm2dof.derive.export.derive_sources_sha256` computes it
    when it writes one; kept here so that the check needs no SymPy)."""
    h = hashlib.sha256()
    for path in sorted(DERIVE_DIR.glob("*.py")):
        h.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    return h.hexdigest()


def _version(name):
    try:
        return metadata.version(name)
    except metadata.PackageNotFoundError:
        return None


def up_to_date(spec, out, *, library=True):
    """(True, "") if ``out`` holds the code ``pm2dof derive`` would generate from ``spec`` (a
    :class:`~pm2dof.core.model_file.ModelSpec`) now, and with ``library`` its compiled library;
    else (False, what differs)."""
    out = Path(out)
    try:
        manifest = json.loads((out / "manifest.json").read_text())
    except (OSError, ValueError):
        return False, "no readable manifest.json"
    recorded = manifest.get("model_file")
    if not recorded or (out / recorded).resolve() != Path(spec.path).resolve():
        return False, "generated from another model file"
    checks = {"the model file": (manifest.get("model_file_sha256"), spec.file_sha256),
              "the formulation": (manifest.get("formulation_sha256"), spec.formulation_sha256),
              "the derivation's sources": (manifest.get("derive_sources_sha256"),
                                           derive_sources_sha256()),
              "the SymPy and CasADi versions": (manifest.get("versions"),
                                                {"sympy": _version("sympy"),
                                                 "casadi": _version("casadi")}),
              "the status codes": (manifest.get("status_codes"), Status.codes()),
              "rk4_substeps": (manifest.get("rk4_substeps"), spec.rk4_substeps)}
    for what, (have, want) in checks.items():
        if have != want:
            return False, f"{what} changed"
    files = manifest.get("files", {})
    for name, sha in files.items():
        p = out / name
        if not p.is_file() or hashlib.sha256(p.read_bytes()).hexdigest() != sha:
            return False, f"{name} differs from its manifest"
    name = manifest.get("model", spec.name)
    if library and not build.library_is_fresh(out / f"{name}.c", out / f"lib{name}.so",
                                              files.get(f"{name}.c")):
        return False, "the compiled library is missing or not built from the C"
    return True, ""


def derive_is_current(model, out=None, *, library=True):
    """``pm2dof derive``'s first step: (out folder, up to date?, what differs) for a model
    file or a shipped model's name, ``out`` defaulting as ``derive`` does."""
    from .model_file import read_model_file
    from .paths import default_generated_dir, resolve_model
    model_path = resolve_model(model)
    out = Path(out).expanduser().absolute() if out is not None else default_generated_dir(
        model_path)
    return (out, *up_to_date(read_model_file(model_path), out, library=library))
