# The model a log or an excitation file was made for: recorded relative to the file, checked.
"""The model a log or an excitation file names, so that a folder holding a log, an excitation
file and the model file can be moved or shared together.

A file records three entries (CSV ``# key = value`` lines, Parquet metadata, or keys of the
excitation file's ``[excitation]`` table):

``model``
    A shipped model by its name (``shang2010``), any other model file by its path relative to
    the folder of the file that records it (``../robots/myrobot.toml``).
``model_name``
    The model file's ``[model].name``.
``formulation_sha256``
    The hash of what the generated code depends on (legs, geometry, friction model).

Files written before these entries name their model by ``model`` alone, usually a name: they
are still read. :func:`model_for` picks the model of a command (``--model``, else the file's,
else the paper's robot) and refuses a file made for another model.
"""
import os
from pathlib import Path

from ..core.errors import ArgumentError, ModelFileError
from ..core.paths import is_shipped, resolve_model

__all__ = ["model_entries", "rebase", "resolve", "mismatch", "model_for"]


def model_entries(model, folder=None):
    """The entries a file in ``folder`` records for ``model`` (dict of str).

    ``folder`` None (a log still in memory): a model file other than a shipped one is
    recorded by its absolute path; writing the log into a file makes it relative
    (:func:`rebase`).
    """
    path = Path(model.spec.path).absolute()
    if is_shipped(path):
        ref = path.stem
    elif folder is None:
        ref = str(path)
    else:
        ref = Path(os.path.relpath(path, Path(folder).absolute())).as_posix()
    return {"model": ref, "model_name": model.name,
            "formulation_sha256": model.spec.formulation_sha256}


def resolve(ref, folder=None):
    """The model file ``ref`` names, a path taken relative to ``folder``; None for a bare name
    that is neither a shipped model nor a file in ``folder`` (a file that names its model by
    name only, as files written before pm2dof 0.3 may)."""
    try:
        return Path(os.path.normpath(resolve_model(ref, relative_to=folder)))
    except ModelFileError:
        return None


def rebase(ref, from_folder, to_folder):
    """``ref`` as recorded by a file in ``from_folder`` (None: the working directory), for a
    file in ``to_folder``: a shipped model and an unresolvable name stay as they are, a path
    becomes relative to ``to_folder``."""
    path = resolve(ref, from_folder)
    if path is None or is_shipped(path):
        return ref if path is None else path.stem
    return Path(os.path.relpath(path, Path(to_folder).absolute())).as_posix()


def _recorded(entries, folder):
    """(name, formulation hash, where) a file's entries record; name or hash None if unknown.
    A file that records only ``model`` is completed from the model file it names, if any."""
    ref = entries.get("model")
    name, sha = entries.get("model_name"), entries.get("formulation_sha256")
    if ref is not None and name is None and sha is None:
        path = resolve(ref, folder)
        if path is None:
            name = str(ref)
        elif path.is_file():
            from ..core.model_file import read_model_file
            spec = read_model_file(path)
            name, sha = spec.name, spec.formulation_sha256
    return name, sha, (ref if ref is not None else "?")


def mismatch(model, entries, folder=None, source="the file"):
    """A message if ``entries`` (a file's recorded model) name another model than ``model``
    (by name or by formulation hash), else None. ``folder``: where a relative ``model`` path
    starts (the file's folder)."""
    name, sha, ref = _recorded(entries, folder)
    if (name is None or name == model.name) and (sha is None
                                                 or sha == model.spec.formulation_sha256):
        return None
    had = ", ".join([f"model {ref}"] + ([f"formulation {sha[:12]}"] if sha else []))
    return (f"{source} was written for model {name if name is not None else ref!r} ({had}), "
            f"not {model.name!r} ({model.spec.path}, formulation "
            f"{model.spec.formulation_sha256[:12]}): leave --model out to use the file's model, "
            f"or give the model it was made for")


def model_for(entries, folder=None, source="the file", *, model=None, generated=None,
              error=ArgumentError):
    """The model of a command that reads a file recording ``entries``.

    Parameters
    ----------
    entries : dict
        The file's recorded model (``model``, ``model_name``, ``formulation_sha256``; any may
        be missing).
    folder : path, optional
        The file's folder (where a relative ``model`` path starts).
    source : str
        The file, for messages.
    model : str, os.PathLike or Model, optional
        ``--model``: a shipped model's name, a model file, or a loaded Model. Default: the
        file's model, or without one the paper's robot.
    generated : path, optional
        ``--generated``.
    error : type
        The error raised (e.g. :class:`~pm2dof.identification.log.LogError`).

    Raises
    ------
    error
        The file names another model than ``model`` (both named), or its model file cannot be
        found (no ``model`` given).
    """
    from ..core.model import Model, load_model
    if model is None:
        ref = entries.get("model")
        path = None if ref is None else resolve(ref, folder)
        if ref is not None and path is None:
            raise error(f"{source} names its model {ref!r} by name only, and that is not a "
                        f"shipped model: pass --model with its model file")
        if path is not None and not path.is_file():
            raise error(f"{source} names its model file {ref!r} (relative to the file's folder: "
                        f"{path}), which does not exist: keep the model file beside it as "
                        f"recorded, or pass --model")
        model = path
    m = model if isinstance(model, Model) else load_model(model, generated)
    msg = mismatch(m, entries, folder, source)
    if msg:
        raise error(msg)
    return m
