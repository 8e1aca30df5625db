# pm2dof export: a model's controllers as a self-contained C99 project (CMake, static library).
"""Write a standalone C project for a model: ``pm2dof export MODEL --out DIR``.

The project holds the model's generated C (copied, never re-derived: the export works from an
installed wheel without the derive extra), a hand-written API (``include/<name>_pm2dof.h``,
``src/<name>_pm2dof.c``) with one ``step`` per controller, a CMakeLists.txt that builds a static
library and installs it with a package config, a closed-loop example against the generated
plant, a ctest comparing the C closed loop with :func:`pm2dof.simulate`, and ``embedded/`` to
cross-compile for a Cortex-M and run it under QEMU (docs/deploying.md).
"""
import hashlib
import json
import re
from importlib import resources
from pathlib import Path

from ..control.controllers import SPLITS, APDController, CTCController, NAController
from ..core import paths
from ..core.errors import ArgumentError, OutputError, StaleGeneratedCodeError
from ..core.layout import Layout
from ..core.model import load_model
from ..core.status import Status
from ..core.task import mechanism
from ..core.version import __version__
from . import checks, reference, single
from .units import export_units

__all__ = ["export_project", "LAWS", "PRECISIONS", "ExportError"]

#: the controllers an export can hold, in this order
LAWS = ("na", "apd", "ctc", "lqr")
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


def _diag_fields(dim):
    """The diag layout of a step's signal processing, task dimension ``dim``."""
    return [("xe", dim), ("v", dim), ("e", dim), ("edot", dim), ("sing", 2)]


def _gravity_note(model):
    """The header's sentence on gravity: the steps hold the gravity term (issue 26)."""
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


def _sha256(path):
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


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
    """(c text, h text) of the model's generated code, checked against its manifest."""
    gen = Path(model.generated)
    name = model.manifest.get("model", model.name)
    texts = []
    for suffix in (".c", ".h"):
        f = gen / f"{name}{suffix}"
        want = model.manifest.get("files", {}).get(f.name)
        if not f.is_file() or (want is not None and _sha256(f) != want):
            how = ("reinstall pm2dof" if paths.in_installed_package(gen)
                   else f"run `{paths.derive_command(model.spec.path, gen)}`")
            raise StaleGeneratedCodeError(f"{f} is missing or differs from the one "
                                          f"{gen / 'manifest.json'} records; {how}")
        texts.append(f.read_text())
    return texts


def _work_sizes(c_text, name, functions):
    """{function: (sz_arg, sz_res, sz_iw, sz_w)} read from the generated <f>_work bodies."""
    out = {}
    for f in functions:
        m = re.search(rf"int {name}_{f}_work\([^)]*\) {{\s*if \(sz_arg\) \*sz_arg = (\d+);\s*"
                      rf"if \(sz_res\) \*sz_res = (\d+);\s*if \(sz_iw\) \*sz_iw = (\d+);\s*"
                      rf"if \(sz_w\) \*sz_w = (\d+);", c_text)
        if m is None:
            raise StaleGeneratedCodeError(f"{name}_{f}_work not found in the generated C")
        out[f] = tuple(int(g) for g in m.groups())
    return out


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
    """{law: default parameter vector} from pm2dof's controllers (the model file's values)."""
    out = {"na": NAController(model).params, "apd": APDController(model).params,
           "ctc": CTCController(model).params}
    lqr = Layout("lqr_params", model.manifest["layouts"]["lqr_params"])
    na = Layout("na_params", model.manifest["layouts"]["na_params"]).unpack(out["na"])
    out["lqr"] = lqr.pack(**{f: na[f] for f, _ in lqr.fields})
    return out


def export_project(model=None, out=None, *, precision="double", controllers=LAWS, force=False,
                   generated=None, move=None):
    """Write the C project of ``model``'s controllers into the folder ``out``.

    Parameters
    ----------
    model : str or Path, optional
        A shipped model's name or a model file (default the paper's robot).
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
    m = load_model(model, generated)
    move_name = reference.reference_move(m, move)[0]     # an unknown move: refused here
    c_text, h_text = _generated_sources(m)
    name, n, p, dim = m.name, m.n_legs, len(m.param_names), m.dof
    units = export_units(m)
    docs = _field_docs(units)
    diag = _diag_fields(dim)
    split = m.spec.control["split"]
    if precision == "single":
        problems = single.single_problems(c_text, m, split)
        if problems:
            raise ExportError(f"single precision is refused for model {name!r}: "
                              + "; ".join(problems))
    out = _prepare_out(out, force)
    sfx = SPLITS[split]
    gen = {law: f"{law}{sfx}_step" for law in laws}
    proj = [f"na_proj{sfx}_step"] if "na" in laws else []    # NA's projected law (an option)
    sizes = _work_sizes(c_text, name, [*gen.values(), *proj, "fk", "ik", "torque_splits",
                                       "plant_step", "measure"])
    lays = {k: Layout(k, v) for k, v in m.manifest["layouts"].items()}
    defaults = _law_params(m)
    real, fsuffix = ("float", "f") if precision == "single" else ("double", "")
    uname = f"{name.upper()}_PM2DOF"
    common = {"NAME": name, "UNAME": name.upper(), "VERSION": __version__,
              "CMAKE_VERSION": ".".join(re.findall(r"\d+", __version__)[:3]) or "0",
              "PRECISION": precision, "REAL": real, "SINGLE": int(precision == "single"),
              "MODEL_FILE": Path(m.spec.path).name, "FORMULATION": m.spec.formulation_sha256[:12],
              "FORMULATION_SHA256": m.spec.formulation_sha256,
              "N": n, "NQ": 2 * n, "TASK_DIM": dim, "P": p,
              "STATE_SIZE": lays["ctrl_state"].size, "DIAG_SIZE": sum(k for _, k in diag),
              "ARG_SIZE": max(s[0] for s in sizes.values()),
              "RES_SIZE": max(s[1] for s in sizes.values()),
              "IWORK_SIZE": max(s[2] for s in sizes.values()),
              "WORK_SIZE": max(s[3] for s in sizes.values()),
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
    files[f"include/{name}_pm2dof.h"] = _render(_template("include/api.h.in"), values)
    files[f"src/{name}_pm2dof.c"] = _render(_template("src/api.c.in"), values)
    if precision == "single":
        files[f"src/{name}.c"] = single.to_single(c_text)
        files[f"src/{name}.h"] = single.to_single(h_text)
        # the simulated robot of the example and the test stays double: a renamed copy
        files[f"sim/{name}_sim.c"] = re.sub(rf"\b{name}_", f"{name}_sim_", c_text)
        sim_prefix, sim_sources = f"{name}_sim_", f"sim/{name}_sim.c"
    else:
        files[f"src/{name}.c"], files[f"src/{name}.h"] = c_text, h_text
        sim_prefix, sim_sources = f"{name}_", ""
    sim = [sizes["measure"], sizes["plant_step"]]
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
    check_work = "".join(f'    check_work("{name}_{gen[law]}_work", {name}_{gen[law]}_work);\n'
                         for law in laws if law != "lqr")
    files[f"tests/test_{name}.c"] = _render(
        _template("tests/test.c.in"),
        dict(values, CHECK_WORK=check_work, GEN_LQR=f"{name}_{gen.get('lqr', 'lqr_step')}"))
    files["CMakeLists.txt"] = _render(_template("CMakeLists.txt.in"),
                                      dict(values, SIM_SOURCES=sim_sources))
    files[f"cmake/{name}_pm2dofConfig.cmake.in"] = _render(_template("cmake/Config.cmake.in"),
                                                           values)
    for rel in ("embedded/Makefile", "embedded/startup.c", "embedded/mps2.ld",
                "embedded/replay.c", "README.md"):
        files[rel] = _render(_template(rel + (".in" if rel.endswith((".md", "replay.c"))
                                              else "")), dict(values, LAW_OPS="".join(ops)))
    files["manifest.json"] = json.dumps(_thaw(m.manifest), indent=1, sort_keys=True) + "\n"
    # the model file's name only: not the exporting machine's folders
    record = {"pm2dof": __version__, "model": name, "model_file": Path(m.spec.path).name,
              "formulation_sha256": m.spec.formulation_sha256, "precision": precision,
              "controllers": list(laws), "split": split, "move": ref["move"],
              "reference_rmse": dict(zip(ref["laws"], ref["rmse"])),
              "files": sorted([*files, RECORD])}
    files[RECORD] = json.dumps(record, indent=1) + "\n"
    try:
        for rel, text in files.items():
            path = out / rel
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
    except OSError as exc:
        raise OutputError(f"cannot write into {out}: {exc.strerror or exc}") from None
    return out


def _law_options(law, name, gen, proj, uname):
    """Render values of what one law has beyond the others: NA's projection (the na_proj
    step, chosen by the params struct's ``project``), its freeze and how to pause it."""
    if law != "na":
        return {"LAW_NOTES": "", "PARAMS_EXTRA": "", "DEFAULTS_EXTRA": "",
                "SET_PARAMS_NOTE": "", "STEP_FN": f"{name}_{gen[law]}"}
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
        "STEP_FN": f"(ctl->params.project ? {name}_{proj[0]} : {name}_{gen[law]})"}


def _thaw(obj):
    """The model's read-only manifest as plain JSON data."""
    if hasattr(obj, "items"):
        return {k: _thaw(v) for k, v in obj.items()}
    if isinstance(obj, tuple):
        return [_thaw(v) for v in obj]
    return obj
