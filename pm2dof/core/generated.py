# Is a model file's generated code current? (`pm2dof derive` re-run on an unchanged model.)
"""Whether a folder of generated code is what ``pm2dof derive`` would write now.

:func:`up_to_date` compares the folder's ``manifest.json`` with the model file and this
install, without importing SymPy or CasADi (a re-derivation takes tens of seconds; this check
a fraction of one): the model file (its bytes and its formulation), the derivation's sources
(``pm2dof/derive/*.py``), the SymPy and CasADi versions, the status codes, the generated
files' hashes, and the compiled library's build record (:func:`pm2dof.core.build.library_is_fresh`).
"""
from pathlib import Path

from .manifest import Manifest, derive_sources_sha256

__all__ = ["up_to_date", "derive_is_current", "derive_sources_sha256"]


def up_to_date(spec, out, *, library=True):
    """(True, "") if ``out`` holds the code ``pm2dof derive`` would generate from ``spec`` (a
    :class:`~pm2dof.core.model_file.ModelSpec`) now, and with ``library`` its compiled library;
    else (False, what differs)."""
    manifest = Manifest.read(out)
    if manifest is None:
        return False, "no readable manifest.json"
    if not manifest.owned_by(spec.path):
        return False, "generated from another model file"
    changed = manifest.what_changed(spec)
    if changed:
        return False, changed
    differing = manifest.files_differing()
    if differing:
        return False, f"{differing[0]} differs from its manifest"
    if manifest.name is None:
        manifest.name = spec.name
    if library and not manifest.library_is_fresh():
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
