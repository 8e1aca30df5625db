# pm2dof export: a model's controllers as a self-contained C99 project (CMake, static library).
"""Write a standalone C project for a model: ``pm2dof export MODEL --out DIR``.

The project holds the model's generated C (copied, never re-derived: the export works from an
installed wheel without the derive extra), a hand-written API (``include/<name>_pm2dof.h``,
``src/<name>_pm2dof.c``) with one ``step`` per controller, a CMakeLists.txt that builds a static
library and installs it with a package config, a closed-loop example against the generated
plant, a ctest comparing the C closed loop with :func:`pm2dof.simulate`, and ``embedded/`` to
cross-compile for a Cortex-M and run it under QEMU (docs/deploying.md).
"""
import json
import re
from importlib import resources
from pathlib import Path

from ..control.controllers import law_params
from ..core import contract, paths
from ..core.errors import ArgumentError, OutputError, StaleGeneratedCodeError
from ..core.layout import Layout
from ..core.manifest import Manifest
from ..core.model import Model, load_model
from ..core.status import Status
from ..core.task import mechanism
from ..core.version import __version__
from . import checks, names, prune, reference, single, stack
from .design import bind_design
from .units import export_units

__all__ = ["export_project", "LAWS", "PRECISIONS", "ExportError"]

#: the controllers an export can hold, in this order (pm2dof.core.contract)
LAWS = contract.LAWS
PRECISIONS = ("double", "single")
RECORD = "pm2dof_export.json"          # what an export wrote (for --force and for tools)

_TITLES = {"na": "NA: the nonlinear adaptive controller (eqs. 14-29)",
           "apd": "APD: the augmented PD controller (eq. 40)",
           "ctc": "CTC: computed torque with the nominal model",
           "lqr": "LQR: time-varying LQR tracking, gains per sample"}
_WHAT = {"na": "the NA law (eqs. 14-17, 29) and the update of theta_hat (eq. 28)",
         "apd": "the APD law (eq. 40) with the nominal theta",
         "ctc": "computed torque u = Me (xd_ddot + Kv edot + Kp e) + Ce xed + S^T f_a",
         "lqr": "u = S^T (tau_ff - K [xe - xd, v - xd_dot])"}
_CLASS = {"na": "NAController", "apd": "APDController", "ctc": "CTCController",
          "lqr": "LQRController (its K and tau_ff are inputs of each step)"}


def _field_docs(u):
    """Units and meaning of each parameter and state field for the model's units ``u``
    (:class:`.units.ExportUnits`): ({field: text}, {law: {field: text}} overrides)."""
    fields = {
        "Kd": f"{u.kd}, K_d of eq. 29 (diagonal)", "Q": "1/s, Q of eqs. 15-17 (diagonal)",
        "Gamma": "adaptation gain of eq. 28 (diagonal, theta order)",
        "freeze_saturated": "1: theta_hat held on a saturated sample, 0: adapt (the paper)",
        "T": "s, sample period", "vel_alpha": "velocity low-pass gain a in (0, 1] (1: none)",
        "sing_threshold": "type I singularity threshold (legs)",
        "parallel_sing_threshold": "type II singularity threshold (actuation)",
        "tau_max": f"{u.effort}, limit per actuator", "preload_sign": "+-1, preload split only",
        "preload": f"{u.effort}, preload split only", "closure_tol": "m, largest closure residual",
        "xe_prev": f"{u.pos}, last pose estimate", "v": f"{u.vel}, velocity estimate",
        "theta_hat": "theta estimate (theta order)", "xe": f"{u.pos}, pose from fk",
        "e": f"{u.pos}, e = xd - xe (eq. 14)", "edot": f"{u.vel}, xd_dot - v",
        "sing": "type I, type II singularity measures",
    }
    laws = {"apd": {"Kp": f"{u.kp}, eq. 40 (diagonal)", "Kv": f"{u.kd}, eq. 40 (diagonal)"},
            "ctc": {"Kp": "1/s^2 (diagonal)", "Kv": "1/s (diagonal)"}}
    return fields, laws


def _gravity_note(model):
    """The header's sentence on gravity: the steps hold the gravity term."""
    if not model.spec.has_gravity:
        return "a horizontal plane (no gravity)"
    return (f"gravity {', '.join(f'{v:g}' for v in model.spec.gravity)} m/s^2 in the base frame, compensated "
            f"by the steps' gravity term (theta's first moments)")


class ExportError(ArgumentError):
    """The export cannot be written as asked (single precision where float is not enough)."""


def _template(rel):
    return resources.files("pm2dof.export").joinpath("templates", rel).read_text()


def _render(text, values):
    for key, value in values.items():
        text = text.replace(f"@{key}@", str(value))
    return text


def _check_choice(what, value, allowed):
    if value not in allowed:
        raise ArgumentError(f"unknown {what} {value!r}; choose from {', '.join(allowed)}")


def parse_controllers(text):
    """``"na,apd"`` -> ("na", "apd") in :data:`LAWS` order; ArgumentError (one line) naming an
    unknown one."""
    names = [s.strip().lower() for s in str(text).split(",") if s.strip()]
    if not names:
        raise ArgumentError(f"--controllers needs at least one of {', '.join(LAWS)}")
    for s in names:
        _check_choice("controller", s, LAWS)
    return tuple(law for law in LAWS if law in names)


def _prepare_out(out, force):
    out = Path(out).expanduser()
    if out.exists() and not out.is_dir():
        raise OutputError(f"cannot export into {out}: it is a file, not a folder")
    if out.is_dir() and any(out.iterdir()):
        if not force:
            raise OutputError(f"{out} exists and is not empty; choose an empty or new folder, "
                              f"or pass --force to write over it")
        record = out / RECORD
        if record.is_file():            # a previous export: remove what it wrote
            for rel in json.loads(record.read_text()).get("files", []):
                (out / rel).unlink(missing_ok=True)
    out.mkdir(parents=True, exist_ok=True)
    return out


def _generated_sources(model):
    """(c text, h text) of the model's generated code, checked against its manifest, and the
    manifest (:class:`~pm2dof.core.manifest.Manifest`)."""
    gen = Path(model.generated)
    manifest = Manifest.read(gen) or Manifest(gen, {})
    if manifest.name is None:
        manifest.name = model.name
    texts = []
    for suffix in (".c", ".h"):
        f = gen / f"{manifest.name}{suffix}"
        if manifest.file_differs(f.name):
            how = ("reinstall pm2dof" if paths.in_installed_package(gen)
                   else f"run `{paths.derive_command(model.spec.path, gen)}`")
            raise StaleGeneratedCodeError(f"{f} is missing or differs from the one "
                                          f"{gen / 'manifest.json'} records; {how}")
        texts.append(f.read_text())
    return (*texts, manifest)


def _work_sizes(manifest, functions, model_path):
    """{function: (sz_arg, sz_res, sz_iw, sz_w)} as the manifest records them (derive time)."""
    out = {}
    for f in functions:
        out[f] = manifest.work_sizes(f)
        if out[f] is None:
            raise StaleGeneratedCodeError(
                f"{manifest.path} records no work sizes of {manifest.name}_{f}; run "
                f"`{paths.derive_command(model_path, manifest.folder)} --force`")
    return out


def _generated_calls(api_c, c_text, name):
    """The generated functions (without the ``<name>_`` prefix) that the API source ``api_c``
    names (calls, or takes the address of), in the order of their first mention: those of its
    ``<name>_<f>`` words that are public functions of the generated C."""
    public = set(re.findall(rf"^CASADI_SYMBOL_EXPORT int {name}_(\w+)\(const casadi_real\*\* arg",
                            c_text, re.M))
    calls = re.findall(rf"\b{name}_(\w+)\b", api_c)
    return list(dict.fromkeys(f for f in calls if f in public))


def _generated_inc(text, name, entries):
    """The pruned generated code as the file the API's source includes."""
    return (f"/* {name}_generated.inc: the code `pm2dof derive` generated for {name} (CasADi), "
            f"pruned to the\n * functions {name}_pm2dof.c calls ({', '.join(entries)}) and "
            f"what they call, all static.\n * Included by {name}_pm2dof.c, not compiled on its "
            f"own. */\n"
            "#if defined(__GNUC__)  /* CasADi's functions keep arguments they do not use */\n"
            "#pragma GCC diagnostic push\n"
            "#pragma GCC diagnostic ignored \"-Wunused-parameter\"\n#endif\n"
            + text + "#if defined(__GNUC__)\n#pragma GCC diagnostic pop\n#endif\n")


def _needs_doc(functions, precision):
    """The header's sentence on what the library calls: ``functions``, those of <math.h> that
    the code calls (:func:`.prune.math_calls`), and what a compiler may add."""
    sincos = "sincosf" if precision == "single" else "sincos"
    text = (f"a C99 compiler and these functions of the C library: {', '.join(functions)} from "
            f"<math.h> (and its macro isfinite), which the code calls; a compiler may add "
            f"memset, memcpy and memmove (for loops that clear or copy arrays) and GCC "
            f"{sincos} (the sine and cosine of one angle, in glibc and newlib).")
    return _wrap_comment(text, first=len(" * What it needs: "))


def _wrap_comment(text, first, width=92):
    """``text`` wrapped into C comment lines (`` * ``), the first line ``first`` characters
    in."""
    lines, line, used = [], "", first
    for word in text.split():
        if line and used + len(line) + 1 + len(word) > width:
            lines.append(line)
            line, used = word, 3
        else:
            line = f"{line} {word}" if line else word
    lines.append(line)
    return "\n * ".join(lines)


def _link_doc(name, link):
    """The header's sentence on the library's external names (:mod:`.names`)."""
    if not link:
        return _wrap_comment(f"every external name is one of the functions below, starts with "
                             f"{name}_pm2dof_ and is distinct from the others in its first "
                             f"{names.SIGNIFICANT} characters (C99, MISRA C:2012 rule 5.1).",
                             first=len(" * libraries link into one program: "))
    return _wrap_comment(f"every external name is one of the functions below, linked under a "
                         f"short name that starts with {names.link_prefix(name)} (the list after the include "
                         f"guard), distinct from the others in its first {names.SIGNIFICANT} "
                         f"characters (C99, MISRA C:2012 rule 5.1).",
                         first=len(" * libraries link into one program: "))


def _layout_defines(prefix, tag, layout, docs, law=None, defaults=None):
    fields, law_fields = docs
    lines = []
    for field, size in layout.fields:
        sl = layout.slices[field]
        doc = (law_fields.get(law, {}).get(field) or fields.get(field) or field)
        val = ""
        if defaults is not None:
            vals = ", ".join(f"{v:.6g}" for v in defaults[sl])
            val = f"; default {vals}" if size <= 4 else f"; default {{{vals}}}"
        lines.append(f"#define {prefix}_{tag}_{field.upper()} {sl.start}  /* [{size}] {doc}"
                     f"{val} */")
    if law:                 # (STATE_SIZE and DIAG_SIZE are among the sizes above)
        lines.append(f"#define {prefix}_{tag}_PARAMS_SIZE {layout.size}")
    return "\n".join(lines) + "\n"


def _c_list(values, suffix):
    return ", ".join(f"{float(v)!r}{suffix}" for v in values)


def _law_params(model):
    """{law: default parameter vector}: the model file's gains and settings, packed and checked
    as pm2dof's controllers pack them (:func:`pm2dof.control.controllers.law_params`)."""
    return {law: law_params(model, law) for law in LAWS}


def export_project(model=None, out=None, *, precision="double", controllers=LAWS, force=False,
                   generated=None, move=None, measure_stack=True, progress=None):
    """Write the C project of ``model``'s controllers into the folder ``out``.

    Parameters
    ----------
    model : str, Path or pm2dof.Model, optional
        A shipped model's name or a model file (default the paper's robot), or a loaded
        Model: a model with a [design] table is exported at its design (``Model.at_design``),
        the geometry then constants of the library.
    out : str or Path
        The project folder; refused if it exists and is not empty, unless ``force``.
    precision : {"double", "single"}
        ``single`` rewrites the generated C for float (:mod:`pm2dof.export.single`) and is
        refused (:class:`ExportError`) where float is not enough.
    controllers : iterable of {"na", "apd", "ctc", "lqr"}
    force : bool
        Write into a non-empty folder (a previous export's files are replaced).
    generated : str or Path, optional
        The folder of the model's generated C (default as :func:`pm2dof.load_model`).
    move : str, optional
        The model file's move that the example and the test run (default "high", else the
        file's first line move).
    measure_stack : bool
        Measure each function's worst-case stack for a Cortex-M4F when ``arm-none-eabi-gcc``
        is on the PATH (:mod:`pm2dof.export.stack`) and write it into the README (default);
        False: the README says how to measure it.
    progress : callable, optional
        Called with a line before the stack is measured (a compile of about 5-40 s).

    Returns
    -------
    Path
        The project folder.

    Raises
    ------
    StaleGeneratedCodeError
        The generated code is missing or stale (the message names ``pm2dof derive``).
    ArgumentError
        An unknown precision or controller.
    OutputError
        ``out`` is a file, or a non-empty folder without ``force``.
    """
    _check_choice("precision", precision, PRECISIONS)
    laws = parse_controllers(",".join(controllers) if not isinstance(controllers, str)
                             else controllers)
    if out is None:
        raise ArgumentError("export_project: give the output folder (out=...)")
    m = model if isinstance(model, Model) else load_model(model, generated)
    move_name = reference.reference_move(m, move)[0]     # an unknown move: refused here
    c_text, _, manifest = _generated_sources(m)
    c_text = bind_design(c_text, m, manifest)     # a [design] model: its geometry as constants
    name, n, p, dim = m.name, m.n_legs, len(m.param_names), m.dof
    units = export_units(m)
    docs = _field_docs(units)
    diag = m.layout("diag").fields                        # the step's diag (the manifest's)
    split = m.spec.control["split"]
    if precision == "single":
        problems = single.single_problems(c_text, m, split)
        if problems:
            raise ExportError(f"single precision is refused for model {name!r}: "
                              + "; ".join(problems))
    out = _prepare_out(out, force)
    gen = {law: contract.step_name(law, split) for law in laws}
    proj = [contract.step_name("na_proj", split)] if "na" in laws else []   # NA's option
    lays = {k: Layout(k, v) for k, v in m.manifest["layouts"].items()}
    defaults = _law_params(m)
    real, fsuffix = ("float", "f") if precision == "single" else ("double", "")
    uname = f"{name.upper()}_PM2DOF"
    common = {"NAME": name, "UNAME": name.upper(), "VERSION": __version__,
              "CMAKE_VERSION": ".".join(re.findall(r"\d+", __version__)[:3]) or "0",
              "PRECISION": precision, "REAL": real, "SINGLE": int(precision == "single"),
              "FABS": "fabs" + fsuffix,      # the real type's: fabsf(float) is float
              "MODEL_FILE": Path(m.spec.path).name, "FORMULATION": m.spec.formulation_sha256[:12],
              "FORMULATION_SHA256": m.spec.formulation_sha256,
              "N": n, "NQ": 2 * n, "TASK_DIM": dim, "P": p,
              "STATE_SIZE": lays["ctrl_state"].size, "DIAG_SIZE": sum(k for _, k in diag),
              "SAMPLE_PERIOD": repr(m.spec.sensing["sample_period"]),
              "CLOSURE_TOL": repr(m.closure_tolerance),
              "SING_THRESHOLD": repr(m.singularity_threshold) + fsuffix,
              "PARALLEL_SING_THRESHOLD": repr(m.parallel_singularity_threshold) + fsuffix,
              "MOVE": move_name, "RK4": m.spec.rk4_substeps,
              "TASK_NAMES": units.task, "POS_UNIT": units.pos, "VEL_UNIT": units.vel,
              "ACC_UNIT": units.acc, "FORCE_UNIT": units.force, "QA_UNIT": units.qa,
              "EFFORT_UNIT": units.effort, "EFFORTS": units.efforts,
              "MECHANISM": mechanism(m.spec), "GRAVITY_NOTE": _gravity_note(m),
              # an RPR leg has a length for every pose: ik refuses a far pose only when some
              # leg is RRR or PRR (pm2dof.Model.ik does not check an RPR leg's stroke)
              "IK_BOUNDED": int(any(leg.kind != "RPR" for leg in m.spec.legs)),
              "IK_NOTE": ("" if all(leg.kind != "RPR" for leg in m.spec.legs) else
                          "\n * An RPR leg has a length for every pose; ik does not check its "
                          "stroke (as pm2dof.Model.ik).")}

    theta_doc = "\n".join(f" *   [{i:2d}] {nm:8s} nominal {v:.6g}" for i, (nm, v) in
                          enumerate(zip(m.param_names, m.theta_nominal)))
    layout_defines = ("/* ctrl_state: what a controller carries between samples */\n"
                      + _layout_defines(uname, "STATE", lays["ctrl_state"], docs)
                      + "/* diag: the last step's signal processing */\n"
                      + _layout_defines(uname, "DIAG", Layout("diag", diag), docs))
    law_decls, law_defs, law_defaults = [], [], []
    for law in laws:
        lay = lays[f"{law}_params"]
        layout_defines += (f"/* {law}_params: the {law.upper()} controller's parameters */\n"
                           + _layout_defines(uname, law.upper(), lay, docs, law, defaults[law]))
        lqr = law == "lqr"
        first_bad, rule_texts = checks.param_checks(law, lay, uname)
        v = dict(common, LAW=law, ULAW=law.upper(), GEN=f"{name}_{gen[law]}",
                 FIRST_BAD=first_bad, RULE_TEXTS=rule_texts,
                 RULES_DOC=checks.rules_doc(law, lay), **_law_options(law, name, gen, proj, uname),
                 LAW_TITLE=_TITLES[law], LAW_WHAT=_WHAT[law], SPLIT=split, CLASS=_CLASS[law],
                 DEFAULTS_FROM=f"[gains.{law}], [limits], [sensing], [control]",
                 STEP_DOC=("\n *   K         [LQR_K_SIZE = N_LEGS x 2 TASK_DIM] the sample's gain,"
                           f" row-major,\n *             {units.effort} per [xe - xd "
                           f"({units.pos}),\n *             v - xd_dot ({units.vel})]"
                           f"\n *   tau_ff    [N_LEGS] the sample's feedforward, {units.effort}")
                 if lqr else "",
                 STEP_EXTRA_DECL=(f"\n                            const {name}_pm2dof_real "
                                  f"K[{uname}_LQR_K_SIZE],\n                            "
                                  f"const {name}_pm2dof_real tau_ff[{uname}_N_LEGS],")
                 if lqr else "",
                 STEP_EXTRA_CALL=f"K, {uname}_LQR_K_SIZE, tau_ff" if lqr else "NULL, 0, NULL")
        law_decls.append(_render(_template("include/law.h.in"), v))
        law_defs.append(_render(_template("src/law.c.in"), v))
        law_defaults.append(f"static const real {law}_defaults[{uname}_{law.upper()}_PARAMS_SIZE]"
                            f" = {{{_c_list(defaults[law], fsuffix)}}};\n")
    for law in LAWS:
        if law not in laws:
            layout_defines += f"#define {uname}_HAVE_{law.upper()} 0\n"

    values = dict(common, THETA_DOC=theta_doc, LAYOUT_DEFINES=layout_defines,
                  STATUS_CASES=checks.status_cases(uname), STATUS_CODES=checks.status_codes(),
                  STATUS_ENUM="\n".join(f"    {uname}_{s.name} = {int(s)},  /* {s.label} */"
                                        for s in Status),
                  LAW_DECLS="".join(law_decls), LAW_DEFS="".join(law_defs),
                  LAW_DEFAULTS="".join(law_defaults),
                  THETA_NOMINAL=_c_list(m.theta_nominal, fsuffix),
                  SPLITS_NOTE=(" In single precision only min_norm is reliable: the min-max and"
                               "\n * preload splits choose among candidates with tolerances of "
                               "1e-10, below float's\n * resolution." if precision == "single"
                               else ""))
    files = {}
    # the API's source first: the generated functions it calls are the entry points of the
    # pruned generated code, and their work sizes those of the header
    api_c = _render(_template("src/api.c.in"), values)
    entries = _generated_calls(api_c, c_text, name)
    sizes = _work_sizes(manifest, entries, m.spec.path)
    generated = prune.prune(c_text, name, entries)
    if precision == "single":
        generated = single.to_single(generated)
    values.update(ARG_SIZE=max(s[0] for s in sizes.values()),
                  RES_SIZE=max(s[1] for s in sizes.values()),
                  IWORK_SIZE=max(s[2] for s in sizes.values()),
                  WORK_SIZE=max(s[3] for s in sizes.values()),
                  NEEDS_DOC=_needs_doc(prune.math_calls(generated, api_c), precision))
    header = _render(_template("include/api.h.in"), values)
    link = names.link_names(header, name)
    header = names.with_link_names(_render(header, {"LINK_DOC": _link_doc(name, link)}),
                                   f"{uname}_H", link)
    files[f"include/{name}_pm2dof.h"] = header
    files[f"src/{name}_pm2dof.c"] = api_c
    files[f"src/{name}_generated.inc"] = _generated_inc(generated, name, entries)
    # the simulated robot of the example and the test: the generated plant and encoders in
    # double precision, outside the library (its two entry points renamed <name>_sim_)
    sim_prefix, sim_sources = f"{name}_sim_", f"sim/{name}_sim.c"
    sim_entries = ("measure", "plant_step")
    files[sim_sources] = re.sub(rf"\b{name}_", sim_prefix,
                                prune.prune(c_text, name, sim_entries, external=True))
    sim = list(_work_sizes(manifest, sim_entries, m.spec.path).values())
    files[f"tests/{name}_sim.h"] = (
        f"/* The simulated robot, double precision: the generated plant and encoders. */\n"
        f"#ifndef {name.upper()}_SIM_H\n#define {name.upper()}_SIM_H\n"
        f"#define SIM_MEASURE {sim_prefix}measure\n#define SIM_PLANT_STEP {sim_prefix}plant_step\n"
        f"#define SIM_ARG_SIZE {max(s[0] for s in sim)}\n#define SIM_RES_SIZE "
        f"{max(s[1] for s in sim)}\n#define SIM_IWORK_SIZE {max(max(s[2] for s in sim), 1)}\n"
        f"#define SIM_WORK_SIZE {max(max(s[3] for s in sim), 1)}\n"
        f"int SIM_MEASURE(const double **arg, double **res, long long *iw, double *w, int mem);\n"
        f"int SIM_PLANT_STEP(const double **arg, double **res, long long *iw, double *w, "
        f"int mem);\n#endif\n")
    ref = reference.reference_data(m, laws, defaults["lqr"], move_name)
    files[f"tests/{name}_reference.h"] = reference.reference_header(m, ref, precision)
    ops, ctls = [], []
    for law in ref["laws"]:
        ops.append(
            f"static {name}_pm2dof_{law} {law}_ctl;\n"
            f"static int {law}_init(void *c) {{ return {name}_pm2dof_{law}_init(c, NULL); }}\n"
            f"static int {law}_reset(void *c, const real *qa0)\n"
            f"{{\n    return {name}_pm2dof_{law}_reset(c, qa0, NULL);\n}}\n"
            f"static int {law}_step(void *c, const real *qa, const real *xd, const real *xd_dot,\n"
            f"                   const real *xd_ddot, real *tau_a)\n"
            f"{{\n    return {name}_pm2dof_{law}_step(c, qa, xd, xd_dot, xd_ddot, tau_a);\n}}\n"
            f"static const real *{law}_state(const void *c)\n"
            f"{{\n    return {name}_pm2dof_state(&((const {name}_pm2dof_{law} *)c)->core);\n}}\n")
        ctls.append(law)
    ops.append("static const law_ops laws[] = {"
               + ", ".join(f'{{"{law}", {law}_init, {law}_reset, {law}_step, {law}_state}}'
                           for law in ctls) + (" {0}" if not ctls else "") + "};\n"
               + "static void *const law_state[] = {"
               + ", ".join(f"&{law}_ctl" for law in ctls) + ("0" if not ctls else "") + "};\n"
               + f"#define N_LAWS {len(ctls)}\n")
    files["examples/closed_loop.c"] = _render(_template("examples/closed_loop.c.in"),
                                              dict(values, LAW_OPS="".join(ops)))
    files[f"tests/test_{name}.c"] = _render(_template("tests/test.c.in"), values)
    files["CMakeLists.txt"] = _render(_template("CMakeLists.txt.in"),
                                      dict(values, SIM_SOURCES=sim_sources))
    files[f"cmake/{name}_pm2dofConfig.cmake.in"] = _render(_template("cmake/Config.cmake.in"),
                                                           values)
    for rel in ("embedded/Makefile", "embedded/startup.c", "embedded/mps2.ld",
                "embedded/replay.c", "embedded/stack.awk"):
        files[rel] = _render(_template(rel + (".in" if rel.endswith("replay.c") else "")),
                             dict(values, LAW_OPS="".join(ops)))
    files["manifest.json"] = json.dumps(_thaw(m.manifest), indent=1, sort_keys=True) + "\n"
    pruned = {"functions": prune.function_count(generated),
              "lines": generated.count("\n"),
              "of_functions": prune.function_count(c_text), "of_lines": c_text.count("\n")}
    files["README.md"] = ""                 # written below, after the stack is measured
    # the model file's name only: not the exporting machine's folders
    record = {"pm2dof": __version__, "model": name, "model_file": Path(m.spec.path).name,
              "formulation_sha256": m.spec.formulation_sha256, "precision": precision,
              "controllers": list(laws), "split": split, "move": ref["move"],
              "reference_rmse": dict(zip(ref["laws"], ref["rmse"])),
              "generated_entries": entries, "generated_pruned": pruned,
              "files": sorted([*files, RECORD])}
    _write(out, files)
    api = names.api_functions(header, name)
    measured = (stack.measure(out / "src" / f"{name}_pm2dof.c", out / "include",
                              [link.get(f, f) for f in api], progress=progress)
                if measure_stack else None)
    if measured is not None:
        record["stack"] = {"target": measured.target, "compiler": measured.compiler,
                           "flags": list(measured.flags),
                           "bytes": {f: measured.stacks[link.get(f, f)].bytes for f in api
                                     if link.get(f, f) in measured.stacks}}
    readme = _render(_template("README.md.in"), dict(
        values, GENERATED_STATS=(f"{pruned['functions']} of {pruned['of_functions']} functions, "
                                 f"{pruned['lines']:,} of {pruned['of_lines']:,} lines"),
        STACK_DOC=_stack_doc(name, api, link, measured, precision)))
    _write(out, {"README.md": readme, RECORD: json.dumps(record, indent=1) + "\n"})
    return out


def _write(out, files):
    try:
        for rel, text in files.items():
            path = out / rel
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
    except OSError as exc:
        raise OutputError(f"cannot write into {out}: {exc.strerror or exc}") from None


def _stack_doc(name, api, link, measured, precision):
    """The README's section on the stack: the figures measured at export (:mod:`.stack`), or
    how to measure them."""
    how = (f"To measure on your target and with your flags: compile `src/{name}_pm2dof.c` with "
           f"GCC 10 or later and `-fcallgraph-info=su`, then `awk -f embedded/stack.awk "
           f"{name}_pm2dof.ci` prints each function's worst-case stack in bytes; `make -C "
           f"embedded stack` does this for the Cortex-M4F and the Cortex-M7 of `embedded/`.")
    if measured is None:
        return ("Not measured at export: `arm-none-eabi-gcc` was not on the exporting "
                "machine's PATH (or `--no-stack` was given). " + how)
    rows = []
    for f in api:
        s = measured.stacks.get(link.get(f, f))
        if s is None or not re.search(r"_(step|reset|fk|ik|torque_splits)$", f):
            continue
        ext = [e for e in s.external if not e.startswith("__aeabi_")]
        rows.append(f"| `{f}` | {s.bytes:,}{'' if s.bounded else ' (lower bound)'} | "
                    f"{' > '.join(c.split('.')[0] for c in s.chain)} | "
                    f"{', '.join(ext) or '-'} |")
    return (f"The worst-case stack of each call, measured at export: {precision} precision, "
            f"{measured.target}, `{measured.compiler}` with `{' '.join(measured.flags)}` and "
            f"`-fcallgraph-info=su`. Each figure is the deepest chain of frames through the "
            f"call graph (the step calls the generated step directly, so the chain is whole). "
            f"The math library's, libgcc's and `memset`'s own frames are not in the graph and "
            f"not counted; `make -C embedded run` paints the stack and measures them too.\n\n"
            f"| function | bytes | chain | not counted (C library) |\n|---|---|---|---|\n"
            + "\n".join(rows) + "\n\n" + how)


def _law_options(law, name, gen, proj, uname):
    """Render values of what one law has beyond the others: NA's projection (the na_proj
    step, chosen by the params struct's ``project``), its freeze and how to pause it."""
    if law != "na":
        return {"LAW_NOTES": "", "PARAMS_EXTRA": "", "DEFAULTS_EXTRA": "",
                "SET_PARAMS_NOTE": "", "STEP_HELPERS": "",
                "STEP_CALL": f"    s = {name}_{gen[law]}(arg, res, ctl->core.work.iw, "
                             f"ctl->core.work.w, 0);"}
    return {
        "LAW_NOTES": (
            "\n * Options (off by default: the paper's law):\n"
            " * - params.project = 1: theta_hat is projected after each update onto physical "
            "values\n *   (alpha_i, gamma_i >= 1e-6 kg m^2, beta_i^2 <= alpha_i gamma_i, "
            "friction >= 0; the\n *   generated " f"{name}_{proj[0]}" "), as "
            "pm2dof.NAController(project=True);\n"
            f" * - params.p[{uname}_NA_FREEZE_SATURATED] = 1 (recommended): theta_hat is held on "
            "a\n *   saturated sample (the clipped torque is not the law's, and eq. 28 would "
            "integrate an\n *   error the actuators cannot act on), as "
            "NAController(freeze_when_saturated=True).\n"
            " * To pause adaptation without losing the state, set_params with Gamma zero; "
            "set_params\n * with the former Gamma resumes it."),
        "PARAMS_EXTRA": ("\n    int project;  /* NA only, not in the layout: nonzero projects "
                         "theta_hat (see above) */"),
        "DEFAULTS_EXTRA": "\n    params->project = 0;",
        "SET_PARAMS_NOTE": "\n * NA: Gamma zero pauses adaptation; the former Gamma resumes it.",
        # two direct calls (not a pointer: the call graph, and so the stack figures, see
        # both, and the pruning keeps both since the API's source names both)
        "STEP_HELPERS": _na_helpers(name, gen["na"], proj[0]),
        "STEP_CALL": ("    if (ctl->params.project)     /* the projected law */\n"
                      "        s = na_projected_step(arg, res, &ctl->core.work);\n    else\n"
                      "        s = na_paper_step(arg, res, &ctl->core.work);")}


def _na_helpers(name, step, proj):
    """NA's two generated steps (the paper's law ``step``, the projected ``proj``), each in a
    function of its own that the compiler keeps as a call. Inlined into NA's step, the body of
    one stayed in the step's frame while the other ran: GCC -O2 for a Cortex-M4F in double
    inlined the paper's law of rrr4_platform and called the projected one, 2,640 B of stack
    against 1,400 B as two calls."""
    def one(helper, fn, what):
        return (f"static NOINLINE int {helper}(const casadi_real **arg, casadi_real **res,\n"
                f"{' ' * (len(helper) + 21)}{name}_pm2dof_work *work)\n"
                f"{{\n    return {name}_{fn}(arg, res, work->iw, work->w, 0);  /* {what} */\n"
                f"}}\n\n")
    return ("/* NA's two generated steps, each kept as a call: inlined into the step, one's frame "
            "would stay\n * on the stack while the other runs */\n"
            + one("na_paper_step", step, "the paper's law")
            + one("na_projected_step", proj, "the projected law"))


def _thaw(obj):
    """The model's read-only manifest as plain JSON data."""
    if hasattr(obj, "items"):
        return {k: _thaw(v) for k, v in obj.items()}
    if isinstance(obj, tuple):
        return [_thaw(v) for v in obj]
    return obj
