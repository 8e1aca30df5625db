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

A model with a ``[design]`` table (:meth:`pm2dof.Model.at_design`) adds ``design``: its
variables' values as JSON (``{"la": 0.25, "lb": 0.24}``, m), which a command applies to the
file's model and which a given model must match.

A file records all three (:data:`ENTRIES`) or none (a log of a robot that pm2dof did not
write: the command's ``--model`` says which model it is). Some without the others is a file of
pm2dof before 0.3, which named its model by ``model`` alone: it is refused
(:func:`incomplete`), naming what is missing. :func:`model_for` picks the model of a command
(``--model``, else the file's, else the paper's robot) and refuses a file made for another
model.
"""
import json
import math
import os
from pathlib import Path

from ..core.errors import ArgumentError, ModelFileError
from ..core.paths import is_shipped, resolve_model

__all__ = ["ENTRIES", "model_entries", "incomplete", "rebase", "resolve", "mismatch",
           "model_for"]

#: the entries a file records for its model: all three, or none
ENTRIES = ("model", "model_name", "formulation_sha256")


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
    out = dict(zip(ENTRIES, (ref, model.name, model.spec.formulation_sha256)))
    if model.design_names:
        out["design"] = json.dumps(dict(zip(model.design_names, map(float, model.design))))
    return out


def _design(entries, source):
    """The ``design`` entry of a file as {name: value}, or None without one."""
    text = entries.get("design")
    if text in (None, ""):
        return None
    try:
        values = json.loads(text)
        if not (isinstance(values, dict) and all(isinstance(v, (int, float)) and math.isfinite(v)
                                                 for v in values.values())):
            raise ValueError("not a table of finite numbers")
    except ValueError as exc:
        raise ArgumentError(f"{source} records a design that cannot be read ({text!r}: {exc})") \
            from None
    return values


def incomplete(entries, source="the file"):
    """A message if ``entries`` hold some of :data:`ENTRIES` but not all (a file of pm2dof
    before 0.3, which named its model by ``model`` alone), else None."""
    have = [k for k in ENTRIES if k in entries]
    if not have or len(have) == len(ENTRIES):
        return None
    missing = [k for k in ENTRIES if k not in entries]
    return (f"{source} records its model by {', '.join(have)} without {', '.join(missing)}: "
            f"a file of pm2dof before 0.3, whose format this version does not read (it reads "
            f"files that record all of {', '.join(ENTRIES)}, or none). Write it again with "
            f"this pm2dof, or remove its {', '.join(have)} and give --model")


def resolve(ref, folder=None):
    """The model file ``ref`` names, a path taken relative to ``folder``; None for a bare name
    that is neither a shipped model nor a file in ``folder``."""
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


def mismatch(model, entries, folder=None, source="the file"):
    """A message if ``entries`` (a file's recorded model) name another model than ``model``
    (by name or by formulation hash), or are :func:`incomplete`, else None (also for a file
    that records no model). ``folder``: where a relative ``model`` path starts (the file's
    folder; the message names the path as recorded)."""
    old = incomplete(entries, source)
    if old is not None or not entries.get("model"):
        return old
    ref, name, sha = (entries[k] for k in ENTRIES)
    if name == model.name and sha == model.spec.formulation_sha256:
        design = _design(entries, source)
        have = dict(zip(model.design_names, map(float, model.design)))
        if design is None and not have or design == have:
            return None
        return (f"{source} was written for model {name!r} at design {design or 'none'}, not at "
                f"design {have or 'none'}: leave --model out to use the file's model at its "
                f"design, or give the model at that design (Model.at_design)")
    return (f"{source} was written for model {name!r} (model {ref}, formulation {sha[:12]}), "
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
    old = incomplete(entries, source)
    if old is not None:
        raise error(old)
    if model is None:
        ref = entries.get("model")
        path = None if ref is None else resolve(ref, folder)
        if ref is not None and path is None:
            raise error(f"{source} names its model {ref!r}, which is neither a shipped model "
                        f"nor a model file relative to it: pass --model with its model file")
        if path is not None and not path.is_file():
            raise error(f"{source} names its model file {ref!r} (relative to the file's folder: "
                        f"{path}), which does not exist: keep the model file beside it as "
                        f"recorded, or pass --model")
        model = path
    m = model if isinstance(model, Model) else load_model(model, generated)
    design = _design(entries, source)
    if design is not None and not isinstance(model, Model) and m.design_names \
            and entries.get("formulation_sha256") == m.spec.formulation_sha256:
        m = m.at_design(design)          # the file's model at the file's design
    msg = mismatch(m, entries, folder, source)
    if msg:
        raise error(msg)
    return m
