# Where model files and their generated C live: shipped models by name, a user's files by path.
"""Resolve model references and their generated-code folders.

A *model reference* is either the name of a model shipped with pm2dof (``"shang2010"``,
``"fivebar"``: the files of ``pm2dof/models/``) or the path of a model file (``str`` or
:class:`pathlib.Path`; ``~`` is expanded). A bare word without ``.toml`` and without a folder
names a shipped model; anything else is a path.

Generated code lives in a folder of its own per model file:

* a shipped model ``pm2dof/models/<name>.toml``: ``pm2dof/generated/<name>/``, built into the
  wheel, never written by pm2dof once installed;
* any other model file ``DIR/<stem>.toml``: ``DIR/generated/<stem>/`` (the default of
  ``pm2dof derive`` and of :func:`pm2dof.load_model`), or the folder given by ``--out`` /
  ``--generated`` / ``generated=``.
"""
import os
import tomllib
from pathlib import Path

from .errors import ModelFileError

__all__ = ["PACKAGE", "SHIPPED_MODELS", "SHIPPED_GENERATED", "DEFAULT_MODEL_NAME",
           "shipped_models", "resolve_model", "default_generated_dir", "is_shipped",
           "in_installed_package", "derive_command"]

PACKAGE = Path(__file__).resolve().parents[1]           # .../pm2dof
SHIPPED_MODELS = PACKAGE / "models"
SHIPPED_GENERATED = PACKAGE / "generated"
DEFAULT_MODEL_NAME = "shang2010"                          # the paper's robot


def shipped_models():
    """The shipped models: ``{name: (path, one-line description)}``, sorted by name."""
    out = {}
    for path in sorted(SHIPPED_MODELS.glob("*.toml")):
        try:
            desc = tomllib.loads(path.read_text()).get("model", {}).get("description", "")
        except (OSError, tomllib.TOMLDecodeError):
            desc = ""
        out[path.stem] = (path, " ".join(str(desc).split()))
    return out


def _is_name(ref):
    s = str(ref)
    return (isinstance(ref, str) and s and "/" not in s and os.sep not in s
            and not s.endswith(".toml") and s not in (".", ".."))


def resolve_model(ref=None, relative_to=None):
    """The model file a reference names.

    Parameters
    ----------
    ref : str or os.PathLike, optional
        A shipped model's name, or a model file's path; default the paper's robot.
    relative_to : str or os.PathLike, optional
        A folder that a relative path is taken from (the folder of a study file, an excitation
        file or a log that names its model); default the working directory.

    Returns
    -------
    pathlib.Path
        An absolute path (not checked for existence when ``ref`` is a path: reading the file
        reports that).

    Raises
    ------
    ModelFileError
        An unknown shipped-model name (the message lists the shipped ones).
    """
    if ref is None:
        ref = DEFAULT_MODEL_NAME
    if not str(ref).strip():
        names = ", ".join(shipped_models()) or "(none)"
        raise ModelFileError(f"the model is an empty string: give a shipped model's name "
                             f"({names}) or the path of a model file (.toml)")
    if _is_name(ref):
        shipped = SHIPPED_MODELS / f"{ref}.toml"
        if shipped.is_file():
            return shipped
        local = Path(relative_to or ".") / ref
        if not local.is_file():  # a file literally named like a model name wins, else refuse
            names = ", ".join(shipped_models()) or "(none)"
            raise ModelFileError(f"{ref!r} is neither a shipped model ({names}) nor a model "
                                 f"file; give the path of a .toml file for your own robot")
        ref = local
    path = Path(ref).expanduser()
    if not path.is_absolute() and relative_to is not None:
        path = Path(relative_to) / path
    return path.absolute()


def is_shipped(model_path):
    """Whether ``model_path`` is one of the files of ``pm2dof/models/``."""
    p = Path(model_path).resolve()
    return p.parent == SHIPPED_MODELS and p.suffix == ".toml"


def default_generated_dir(model_path):
    """The folder of a model file's generated C when none is named (see the module doc)."""
    p = Path(model_path).absolute()
    if is_shipped(p):
        return SHIPPED_GENERATED / p.stem
    return p.parent / "generated" / p.stem


def in_installed_package(path):
    """Whether ``path`` lies inside an installed (not a source checkout's) pm2dof package:
    pm2dof never writes there."""
    if (PACKAGE.parent / "pyproject.toml").is_file():  # a source checkout (editable install)
        return False
    try:
        Path(path).resolve().relative_to(PACKAGE)
    except ValueError:
        return False
    return True


def derive_command(model_path, gen_dir=None):
    """The exact ``pm2dof derive ...`` command that (re)generates ``model_path``'s code."""
    import shlex
    cmd = ["pm2dof", "derive", str(model_path)]
    if gen_dir is not None and Path(gen_dir).absolute() != default_generated_dir(model_path):
        cmd += ["--out", str(gen_dir)]
    return shlex.join(cmd)
