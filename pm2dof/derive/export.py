# CasADi export: one CodeGenerator -> generated/<name>/<name>.c/.h, a documenting header, a manifest.
import json
import re

import casadi as ca
import sympy

from pm2dof.core.manifest import MANIFEST, WORK_FIELDS, derive_sources_sha256, file_sha256

__all__ = ["export", "MANIFEST"]


def _work_sizes(c_text, f):
    """{"arg", "res", "iw", "w"}: the work sizes the generated C declares in ``<f>_work``, read
    once here, where the C was just written (the manifest carries them to the runtime and the
    export). The C's sz_arg, sz_res equal CasADi's ``f.sz_arg()``, ``f.sz_res()``; its sz_iw,
    sz_w are at most ``f.sz_iw()``, ``f.sz_w()`` (the C keeps an SX function's work in local
    variables, so it often needs less)."""
    m = re.search(rf"int {f.name()}_work\([^)]*\) {{\s*if \(sz_arg\) \*sz_arg = (\d+);\s*"
                  rf"if \(sz_res\) \*sz_res = (\d+);\s*if \(sz_iw\) \*sz_iw = (\d+);\s*"
                  rf"if \(sz_w\) \*sz_w = (\d+);", c_text)
    if m is None:
        raise RuntimeError(f"{f.name()}_work not found in the generated C")
    sizes = dict(zip(WORK_FIELDS, (int(g) for g in m.groups())))
    own = dict(zip(WORK_FIELDS, (f.sz_arg(), f.sz_res(), f.sz_iw(), f.sz_w())))
    if (sizes["arg"], sizes["res"]) != (own["arg"], own["res"]) or \
            sizes["iw"] > own["iw"] or sizes["w"] > own["w"]:
        raise RuntimeError(f"{f.name()}: the C's work sizes {sizes} do not fit CasADi's {own}")
    return sizes


def _signature(f):
    def side(n, name, sparsity):
        return [[name(i), sparsity(i).size1() * sparsity(i).size2()] for i in range(n)]
    return {"inputs": side(f.n_in(), f.name_in, f.sparsity_in),
            "outputs": side(f.n_out(), f.name_out, f.sparsity_out)}


def _task_line(task_names):
    """The header's line on the task coordinates xe."""
    if tuple(task_names) == ("x", "y"):
        return " * xe    = [x, y] end-effector position, m;  xed, xrd, xrdd: velocities m/s, accel. m/s^2"
    return (f" * xe    = [{', '.join(task_names)}] pose (m, angles in rad);  xed, xrd, xrdd: "
            f"its rates and accelerations")


def _sing_lines(n, m):
    """The header's lines on theta's units and the singularity measures."""
    if m == 2:
        return [" *         (alpha, beta, gamma in kg*m^2; fv in N*m*s/rad; fc, fs in N*m)",
                " * sing  = [min_i |sin(qb_i - qa_i)| (type I, legs), sqrt(1 - |sum_i exp(2 i qb_i)| / n)",
                " *         (type II, actuation: sigma_min of S with unit rows over sqrt(n/2))]"]
    return [" * sing  = [the legs' type I measure (min over the legs), sigma_min of S with unit rows",
            f" *         over sqrt(n/{m}) (type II, actuation)]"]


def _design_lines(spec):
    """The header's line on the [design] input (none without a [design] table)."""
    design = spec.design
    if design is None:
        return []
    return [f" * design = [{', '.join(design.names)}]  the model file's [design] variables, m: "
            "the last input of every function that lists it"]


def _header_doc(spec, functions, layouts, status_codes, task_names=("x", "y")):
    """A comment block for the top of the generated header: argument order and layouts."""
    n = spec.n_legs
    lines = [
        f"/* pm2dof generated code for model '{spec.name}' ({n} legs, friction '{spec.friction}').",
        " * Written by `pm2dof derive` from the model file; do not edit.",
        " *",
        " * Every function follows CasADi's C API: int f(const double** arg, double** res,",
        " * long long* iw, double* w, int mem), with work sizes from f_work(). All inputs and",
        " * outputs are dense; matrices are stored ROW-MAJOR (flattened row by row). SI units.",
        " *",
        f" * q     = [qa_1..qa_{n}, qb_1..qb_{n}]  absolute joint angles, rad (eq. 3 order)",
        f" * qa    = [qa_1..qa_{n}]  measured active angles, rad",
        _task_line(task_names),
        f" * theta = [{', '.join(spec.param_names)}]",
        *_sing_lines(n, len(task_names)),
        *_design_lines(spec),
        " *",
        " * Functions (inputs -> outputs, element counts):",
    ]
    for f in functions:
        sig = _signature(f)
        ins = ", ".join(f"{a}[{k}]" for a, k in sig["inputs"])
        outs = ", ".join(f"{a}[{k}]" for a, k in sig["outputs"])
        lines.append(f" *   {f.name()}({ins}) -> ({outs})")
    # diag is a step's output, documented by the steps' lines above
    layouts = {k: v for k, v in layouts.items() if k != "diag"}
    if layouts:
        lines += [" *", " * Flat vectors of the controllers, plant and closed loop (field[count], in order):"]
        for name, fields in layouts.items():
            lines.append(f" *   {name}: " + ", ".join(f"{f}[{k}]" for f, k in fields))
    if status_codes:
        lines.append(" *   status of a controller step: " + ", ".join(
            f"{v} {k}" for k, v in sorted(status_codes.items(), key=lambda kv: kv[1])))
    lines.append(" */")
    return "\n".join(lines) + "\n"


def export(spec, functions, out_dir, model_file_label, extra=None, task_names=("x", "y")):
    """Generate C for ``functions`` into ``out_dir`` and write the manifest.

    Parameters
    ----------
    spec : pm2dof.core.model_file.ModelSpec
    functions : list of casadi.Function
        Named functions with named inputs and outputs; all outputs are densified.
    out_dir : pathlib.Path
        ``generated/<name>/``; created if missing. Only files this function writes change.
    model_file_label : str
        How the manifest names the model file (repository-relative when possible).
    extra : dict, optional
        More manifest entries (vector layouts, status codes).
    task_names : tuple of str
        The task coordinates xe (the model's ``task_names``), for the header's comment.

    Returns
    -------
    dict
        The manifest.
    """
    out_dir.mkdir(parents=True, exist_ok=True)
    cg = ca.CodeGenerator(f"{spec.name}.c", {"with_header": True, "verbose": False})
    for f in functions:
        cg.add(f)
    cg.generate(str(out_dir) + "/")
    c_text = (out_dir / f"{spec.name}.c").read_text()
    header = out_dir / f"{spec.name}.h"
    header.write_text(_header_doc(spec, functions, (extra or {}).get("layouts", {}),
                                  (extra or {}).get("status_codes", {}), task_names)
                      + header.read_text())
    manifest = {
        "model": spec.name,
        "model_file": model_file_label,
        "model_file_sha256": spec.file_sha256,
        "formulation_sha256": spec.formulation_sha256,
        "derive_sources_sha256": derive_sources_sha256(),
        "versions": {"sympy": sympy.__version__, "casadi": ca.__version__},
        "param_names": list(spec.param_names),
        "files": {p.name: file_sha256(p) for p in (out_dir / f"{spec.name}.c", header)},
        "functions": {f.name(): {**_signature(f), "work": _work_sizes(c_text, f)}
                      for f in functions},
        **(extra or {}),
    }
    (out_dir / MANIFEST).write_text(json.dumps(manifest, indent=1, sort_keys=True) + "\n")
    return manifest
