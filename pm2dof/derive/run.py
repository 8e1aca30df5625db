# Derive one model file: SymPy derivation -> CasADi functions -> C, header, manifest -> library.
"""``derive(model, out=None)``: the whole build-time pipeline for one model file.

Writes ``OUT/<name>.c``, ``OUT/<name>.h`` and ``OUT/manifest.json`` (``OUT`` defaults to
``generated/<stem>/`` beside the model file, :func:`pm2dof.core.paths.default_generated_dir`),
then compiles ``OUT/lib<name>.so``. Refuses to write into an installed pm2dof package, and to
overwrite generated code that came from another model file unless ``force``.
"""
import os
import time
from pathlib import Path

import casadi as ca

from pm2dof.core import paths
from pm2dof.core.errors import ModelFileError, OutputError
from pm2dof.core.manifest import Manifest
from pm2dof.core.model_file import read_model_file

from .controllers import STATUS, controller_functions, controller_layouts
from .derivatives import derivative_functions
from .export import MANIFEST, export
from .factored import has_gravity
from .model_functions import Derivation, energy_functions, model_functions
from .planning import path_functions, path_layouts
from .plant import closed_loop_functions, closed_loop_layouts, model_plant_layout, plant_functions

__all__ = ["derive", "DeriveError"]


class DeriveError(ModelFileError):
    """Derivation refused: the output folder belongs to another model file or to the installed
    package (the message names both files, or what to do instead), or the model's task
    dimension is neither 2 nor 3."""


def _finalize(f):
    """Dense outputs (the C binding takes dense buffers only) and, for SX functions, common
    subexpressions merged across all outputs (ca.cse): identical nodes built by separate
    conversions — e.g. cos(qa_i) — are computed once."""
    if not f.is_a("SXFunction"):
        assert all(f.sparsity_out(i).is_dense() for i in range(f.n_out())), f.name()
        return f
    ins = f.sx_in()
    outs = ca.cse([ca.densify(o) for o in f.call(ins)])
    return ca.Function(f.name(), ins, outs, f.name_in(), f.name_out())


def _check_out(model_path, out, force):
    """Refuse the installed package, and a folder generated from another model file."""
    if paths.in_installed_package(out):
        raise DeriveError(
            f"{out} is inside the installed pm2dof package, which pm2dof never writes to. Copy "
            f"the model file into a folder of yours and derive that copy: cp {model_path} "
            f"~/robots/ && pm2dof derive ~/robots/{Path(model_path).name}")
    if force or not (out / MANIFEST).is_file():
        return
    manifest = Manifest.read(out)            # None: unreadable, so its owner is unknown
    source = manifest.model_file() if manifest is not None else None
    if manifest is None or not manifest.owned_by(model_path):
        raise DeriveError(
            f"{out} holds code generated from another model file ({source or 'unknown'}), not "
            f"from {model_path}; refusing to overwrite it. Use another --out, or --force to "
            f"overwrite")


def derive(model, out=None, *, force=False, build=True, progress=print):
    """Derive a model file, write its generated C and manifest, and compile it.

    Parameters
    ----------
    model : str or os.PathLike
        A model file, or a shipped model's name.
    out : str or os.PathLike, optional
        Folder for the generated code; default ``generated/<stem>/`` beside the model file.
    force : bool
        Overwrite a folder that holds code generated from another model file.
    build : bool
        Compile the shared library after writing the C.
    progress : callable(str) or None
        Receives one line per stage.

    Returns
    -------
    pathlib.Path
        The output folder.
    """
    t0 = time.perf_counter()

    def say(msg):
        if progress:
            progress(f"[derive {time.perf_counter() - t0:5.1f}s] {msg}")

    model_path = paths.resolve_model(model)
    spec = read_model_file(model_path)
    out = (Path(out).expanduser().absolute() if out is not None
           else paths.default_generated_dir(model_path))
    _check_out(model_path, out, force)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot create the output folder {out}: {exc.strerror or exc}") \
            from None
    say(f"model {spec.name!r} ({model_path}): {spec.n_legs} legs, {len(spec.param_names)} "
        f"parameters, friction {spec.friction!r}")
    d = Derivation(spec)
    say("SymPy: H, A, W, Wdot, S, M, C, Me, Ce, S^T f_a, Y, forward dynamics derived")
    functions = derive_functions(d, spec)
    say(f"CasADi: {len(functions)} functions, "
        f"{sum(f.n_instructions() for f in functions)} instructions")
    extra = {"layouts": {k: v.to_json() for k, v in derive_layouts(d).items()},
             "status_codes": STATUS, "rk4_substeps": spec.rk4_substeps,
             "task_names": list(task_names(d))}      # the task dimension m and its coordinates
    design = spec.design
    if design is not None:   # the functions' input ``design``: its order; defaults for reference
        extra["design"] = {"names": list(design.names),
                           "keys": [list(labels) for labels in design.labels],
                           "default": list(design.default), "bounds": [list(b) for b in design.bounds]}
    # the model file as seen from the output folder, so the pair can be moved together
    label = Path(os.path.relpath(model_path.resolve(), out.resolve())).as_posix()
    manifest = export(spec, functions, out, label, extra, task_names(d))
    say(f"wrote {', '.join(manifest['files'])}, {MANIFEST} in {out}")
    if build:
        from pm2dof.core.build import compile_library
        lib = compile_library(out / f"{spec.name}.c", out / f"lib{spec.name}.so")
        say(f"compiled {lib}")
    return out


def task_names(d):
    """The names of the task coordinates: the model's ``task_names``."""
    return tuple(d.spec.task_names)


def derive_functions(d, spec):
    """Every generated function of a derivation, finalized, in the order of the C file.
    Refuses (DeriveError) a task dimension other than 2 (a point) or 3 (a platform's x, y,
    phi): the closed-form splits, solves and singularity measures exist for those."""
    if d.m not in (2, 3):
        raise DeriveError(f"model {spec.name!r}: task dimension {d.m} (task coordinates "
                          f"{task_names(d)}); pm2dof derives 2 (x, y) or 3 (x, y, phi)")
    ctrl = [_finalize(f) for f in controller_functions(d, spec.name)]
    plant = [_finalize(f) for f in plant_functions(d, spec.name)]
    loops = closed_loop_functions(d, spec.name, ctrl, plant, spec.rk4_substeps)
    functions = [_finalize(f) for f in model_functions(d, spec.name)] + ctrl + plant + loops
    functions += [_finalize(f) for f in path_functions(d, spec.name)]       # motion planning
    functions += derivative_functions(d, spec.name, spec.rk4_substeps, _finalize)
    functions += [_finalize(f) for f in energy_functions(d, spec.name)]    # Ge, T, V
    return functions


def derive_layouts(d):
    """The manifest's flat-vector layouts of a derivation (task dimension d.m)."""
    n, p, m = d.spec.n_legs, len(d.spec.param_names), d.m
    return {**controller_layouts(n, p, m), **closed_loop_layouts(n, p, m),
            "plant": model_plant_layout(d.spec), **path_layouts(n, p, m, has_gravity(d))}
