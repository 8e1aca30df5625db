# `python -m derive MODEL.toml`: derive the model, generate C into generated/<name>/, build it.
"""Derive a model file and generate its C code.

Usage: python -m derive [MODEL.toml] [--out DIR] [--no-build]

Writes DIR/<name>.c, DIR/<name>.h and DIR/manifest.json (DIR defaults to
generated/<name>/), then compiles DIR/lib<name>.so unless --no-build.
"""
import argparse
import sys
import time
from pathlib import Path

import casadi as ca

from pm2dof.core.model_file import read_model_file
from pm2dof.core.errors import ModelFileError

from .controllers import STATUS, controller_functions, controller_layouts
from .export import export
from .model_functions import Derivation, model_functions
from .plant import closed_loop_functions, closed_loop_layouts, plant_functions, plant_layout

REPO = Path(__file__).resolve().parent.parent


def _label(path):
    path = Path(path).resolve()
    try:
        return str(path.relative_to(REPO))
    except ValueError:
        return path.name


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


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m derive", description=__doc__.split("\n\n")[0])
    ap.add_argument("model", nargs="?", default=str(REPO / "models" / "shang2010.toml"))
    ap.add_argument("--out", help="output folder (default generated/<name>/)")
    ap.add_argument("--no-build", action="store_true", help="do not compile the shared library")
    args = ap.parse_args(argv)
    t0 = time.perf_counter()

    def say(msg):
        print(f"[derive {time.perf_counter() - t0:5.1f}s] {msg}", flush=True)

    try:
        spec = read_model_file(args.model)
    except ModelFileError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    out = Path(args.out) if args.out else REPO / "generated" / spec.name
    say(f"model {spec.name!r}: {spec.n_legs} legs, {len(spec.param_names)} parameters, "
        f"friction {spec.friction!r}")
    d = Derivation(spec)
    say("SymPy: H, A, W, Wdot, S, M, C, Me, Ce, S^T f_a, Y, forward dynamics derived")
    n, p = spec.n_legs, len(spec.param_names)
    ctrl = [_finalize(f) for f in controller_functions(d, spec.name)]
    plant = [_finalize(f) for f in plant_functions(d, spec.name)]
    loops = closed_loop_functions(d, spec.name, ctrl, plant, spec.rk4_substeps)
    functions = [_finalize(f) for f in model_functions(d, spec.name)] + ctrl + plant + loops
    say(f"CasADi: {len(functions)} functions, "
        f"{sum(f.n_instructions() for f in functions)} instructions")
    layouts = {**controller_layouts(n, p), **closed_loop_layouts(n, p), "plant": plant_layout(n)}
    extra = {"layouts": {k: v.to_json() for k, v in layouts.items()}, "status_codes": STATUS,
             "rk4_substeps": spec.rk4_substeps}
    manifest = export(spec, functions, out, _label(args.model), extra)
    say(f"wrote {', '.join(manifest['files'])}, manifest.json in {_label(out)}")
    if not args.no_build:
        from pm2dof.core.build import compile_library
        lib = compile_library(out / f"{spec.name}.c", out / f"lib{spec.name}.so")
        say(f"compiled {_label(lib)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
