# pm2dof export: what the library holds (pruned generated code, external names, math functions,
# stack figures) and its install for find_package.
"""The exported library's contents, checked from outside: ``nm`` of its object compiled with
the host's compiler (the names it defines and the functions it needs), GCC's call graph (the
step reaches the generated step), the README's stack figures against the exported project's
own ``make -C embedded`` build and ``stack.awk``, and a consumer project built against the
library installed into a temporary prefix with ``cmake --install`` (find_package).

Models: the paper's robot (shang2010), a platform (rrr4_platform, the largest generated code),
a platform on linear actuators (prr3_platform) and the paper's robot under gravity
(shang2010_vertical, whose name is long enough that the API's names share 31 characters).
"""
import ctypes
import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow  # compiles and builds C projects for minutes in all: make test-slow (CI)

import pm2dof
from pm2dof.export import export_project
from pm2dof.export.stack import read_callgraph, worst_stack

HAVE_CC = shutil.which("cc") is not None and shutil.which("nm") is not None
needs_cc = pytest.mark.skipif(not HAVE_CC, reason="needs a C compiler and nm")
needs_cmake = pytest.mark.skipif(shutil.which("cmake") is None or not HAVE_CC,
                                 reason="needs cmake and a C compiler")
needs_cross = pytest.mark.skipif(
    shutil.which("arm-none-eabi-gcc") is None or shutil.which("make") is None
    or shutil.which("awk") is None, reason="needs arm-none-eabi-gcc, make and awk")

MODELS = ("shang2010", "rrr4_platform", "prr3_platform", "shang2010_vertical")
#: calls a compiler may add on its own (the header says so): loops that clear or copy arrays,
#: the sine and cosine of one angle
COMPILER_CALLS = {"memset", "memcpy", "memmove", "sincos", "sincosf"}


def _run(cmd, **kw):
    r = subprocess.run([str(c) for c in cmd], capture_output=True, text=True, timeout=900, **kw)
    assert r.returncode == 0, f"{' '.join(map(str, cmd))}\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}"
    return r


def _nm(objs, *flags):
    """The symbols nm lists for the object files or archives ``objs`` (one or a list)."""
    objs = objs if isinstance(objs, list) else [objs]
    return set(_run(["nm", *flags, "--format=just-symbols", *objs]).stdout.split())


@pytest.fixture(scope="module")
def exports(tmp_path_factory):
    """{name: (project folder, the library's objects compiled at -O0 -fno-builtin)}: every math call
    stays a call, so nm lists exactly the functions the code calls; nothing is inlined, so
    GCC's call graph (-fcallgraph-info, beside the object, where the compiler has it) shows
    every call."""
    root = tmp_path_factory.mktemp("export_library")
    out = {}
    for name in MODELS:
        proj = export_project(name, root / name, controllers=("na", "apd"), measure_stack=False)
        objs = []
        # the library's sources, as its CMakeLists.txt lists them
        sources = re.search(rf"add_library\({name}_pm2dof STATIC ([^)]*)\)",
                            (proj / "CMakeLists.txt").read_text()).group(1).split()
        for k, src in enumerate(sources if HAVE_CC else ()):
            objs.append(root / f"{name}_{k}.o")
            cmd = ["cc", "-std=c99", "-O0", "-fno-builtin", "-ffp-contract=off",
                   f"-I{proj / 'include'}", "-c", proj / src, "-o", objs[-1]]
            r = subprocess.run([str(c) for c in [*cmd, "-fcallgraph-info=su"]],
                               capture_output=True, text=True, timeout=900)
            if r.returncode != 0:           # a compiler without -fcallgraph-info (GCC < 10)
                _run(cmd)
        out[name] = proj, objs
    return out


def _header(proj, name):
    return (proj / "include" / f"{name}_pm2dof.h").read_text()


def _declared(header, name):
    """The header's functions, each as the symbol it links under (its #define, if any)."""
    links = dict(re.findall(r"^#define (\w+) (\w+)$", header, re.M))
    api = set(re.findall(rf"\b({name}_pm2dof_\w+)\s*\(", header))
    return {links.get(f, f) for f in api}


def _listed(header):
    """The functions of the C library the header says the library calls."""
    m = re.search(r"these functions of the C library:(.*?)from <math\.h>", header, re.S)
    assert m, "the header lists no math functions"
    return {s.strip(" *\n") for s in m.group(1).replace("\n", " ").split(",")}


@pytest.mark.parametrize("name", MODELS)
def test_the_generated_code_is_pruned_to_what_the_api_calls(exports, name):
    """The copy holds the generated functions the API calls and what they call, all static:
    every function is defined static, none of CasADi's public wrappers (_work, _sparsity_in,
    _n_in, ...) remains, and far fewer lines than the generated file."""
    proj, _ = exports[name]
    inc = (proj / "src" / f"{name}_generated.inc").read_text()
    full = (Path(pm2dof.load_model(name).generated) / f"{name}.c").read_text()
    api = (proj / "src" / f"{name}_pm2dof.c").read_text()
    assert not (proj / "src" / f"{name}.c").exists() and not (proj / "src" / f"{name}.h").exists()
    top = re.findall(r"^(?!static |#|/\*| |\}|$)(.*\()", inc, re.M)
    assert top == [], top[:5]                                # nothing external
    for suffix in ("_work(", "_sparsity_in(", "_n_in(", "_checkout(", "_name_in("):
        assert suffix not in inc, suffix
    called = set(re.findall(rf"\b{name}_(\w+_step|fk|ik|torque_splits)\(arg", api))
    defined = set(re.findall(rf"^static int {name}_(\w+)\(const casadi_real\*\* arg", inc, re.M))
    assert called and defined == called, (defined, called)
    assert len(inc.splitlines()) < len(full.splitlines()) / 3
    record = json.loads((proj / "pm2dof_export.json").read_text())["generated_pruned"]
    assert record["of_lines"] == full.count("\n") and record["lines"] < inc.count("\n")
    assert len(called) < record["functions"] < record["of_functions"] / 20


@pytest.mark.parametrize("name", MODELS)
def test_the_work_sizes_cover_every_generated_call(exports, name):
    """The header's work sizes against what each generated function the library calls (NA's
    projected step among them) asks for, read from pm2dof's compiled copy of the generated code through CasADi's public
    <f>_work (not from the C text the export parses)."""
    proj, _ = exports[name]
    header = _header(proj, name)
    size = {k: int(v) for k, v in re.findall(
        rf"#define {name.upper()}_PM2DOF_(ARG_SIZE|RES_SIZE|IWORK_SIZE|WORK_SIZE) (\d+)", header)}
    m = pm2dof.load_model(name)
    lib = ctypes.CDLL(str(Path(m.generated) / f"lib{name}.so"))
    entries = json.loads((proj / "pm2dof_export.json").read_text())["generated_entries"]
    assert {"fk", "ik", "torque_splits", "na_step", "na_proj_step", "apd_step"} <= set(entries)
    for f in entries:
        n = [ctypes.c_longlong() for _ in range(4)]
        assert getattr(lib, f"{name}_{f}_work")(*map(ctypes.byref, n)) == 0
        a, r, iw, w = (v.value for v in n)
        assert (a <= size["ARG_SIZE"] and r <= size["RES_SIZE"] and iw <= size["IWORK_SIZE"]
                and w <= size["WORK_SIZE"]), (f, a, r, iw, w, size)


@needs_cc
@pytest.mark.parametrize("name", MODELS)
def test_the_library_defines_only_the_api_distinct_in_31_characters(exports, name):
    """nm: the library's external symbols are exactly the header's functions (under their
    link names), and no two share their first 31 characters (C99 5.2.4.1, MISRA C 5.1)."""
    proj, objs = exports[name]
    defined = _nm(objs, "-g", "--defined-only")
    assert defined == _declared(_header(proj, name), name)
    assert len({s[:31] for s in defined}) == len(defined), sorted(defined)
    kinds = {line.split()[-2] for line in _run(["nm", "--defined-only", *objs]).stdout.splitlines()
             if len(line.split()) == 3}
    assert kinds <= set("tTrR"), kinds        # code and read-only tables: no writable data


def test_a_long_model_name_gets_short_link_names(exports):
    """shang2010_vertical_pm2dof_theta_nominal and ..._theta_hat share 31 characters: the
    header maps every API name to a short link name; shang2010's names need none."""
    header = _header(exports["shang2010_vertical"][0], "shang2010_vertical")
    links = dict(re.findall(r"^#define (shang2010_vertical_pm2dof_\w+) (\w+)$", header, re.M))
    assert "shang2010_vertical_pm2dof_theta_hat" in links
    assert all(len(v) < len(k) and v.startswith("shang201_") for k, v in links.items())
    assert "#define shang2010_pm2dof_" not in _header(exports["shang2010"][0], "shang2010")


@needs_cc
@pytest.mark.parametrize("name", MODELS)
def test_the_header_lists_every_function_the_library_needs(exports, name):
    """The header's list of C library functions is what nm finds undefined, when every math
    call stays a call (-O0 -fno-builtin); an optimised build may also call what the header says
    a compiler adds (memset, memcpy, memmove, sincos)."""
    proj, objs = exports[name]
    header = _header(proj, name)
    assert _nm(objs, "-u") - _nm(objs, "--defined-only") == _listed(header)
    said = re.search(r"a compiler may add(.*?)\.", header, re.S).group(1)
    assert all(f in said for f in ("memset", "memcpy", "memmove", "sincos"))


#: <math.h>'s double-precision functions (their float versions end in f)
DOUBLE_MATH = {"sin", "cos", "tan", "asin", "acos", "atan", "atan2", "exp", "log", "pow", "sqrt",
               "cbrt", "floor", "ceil", "fabs", "fmin", "fmax", "fmod", "hypot", "copysign",
               "round", "trunc", "sincos"}


@needs_cc
@pytest.mark.parametrize("name", ["shang2010", "prr3_platform", "shang2010_vertical"])
def test_single_precision_computes_nothing_in_double(tmp_path, name):
    """In single precision the API source promotes no float to double (-Wdouble-promotion, an
    error here) and calls no double math function (nm at -O0 -fno-builtin; the header's list
    says the same): fk's closure check took fabs of a float residual, in double."""
    proj = export_project(name, tmp_path / name, precision="single", controllers=("na", "apd"),
                          measure_stack=False)
    obj = tmp_path / "api.o"
    _run(["cc", "-std=c99", "-O0", "-fno-builtin", "-Wdouble-promotion", "-Werror",
          f"-I{proj / 'include'}", "-c", proj / "src" / f"{name}_pm2dof.c", "-o", obj])
    undefined = _nm(obj, "-u")
    assert undefined & {f + "f" for f in DOUBLE_MATH}, undefined     # the float ones are called
    assert not undefined & DOUBLE_MATH, sorted(undefined & DOUBLE_MATH)
    assert not _listed(_header(proj, name)) & DOUBLE_MATH


@pytest.mark.parametrize("precision", ["double", "single"])
def test_the_files_deploying_md_lists_are_written(exports, tmp_path, precision):
    """docs/deploying.md's table of the files an export writes, against an export in each
    precision (the simulated robot, sim/<name>_sim.c, was missing from a double export)."""
    page = (Path(pm2dof.__file__).parents[1] / "docs" / "deploying.md").read_text()
    table = page[page.index("| `include/<name>_pm2dof.h`"):]
    table = table[:table.index("\n\n")]
    listed = [p.replace("<name>", "shang2010") for row in table.splitlines()
              for p in re.findall(r"`([^`]+)`", row.split("|")[1])]
    assert len(listed) >= 12, listed
    proj = (exports["shang2010"][0] if precision == "double" else
            export_project("shang2010", tmp_path / "s", precision="single",
                           controllers=("na",), measure_stack=False))
    written = set(json.loads((proj / "pm2dof_export.json").read_text())["files"])
    for p in listed:
        assert ((proj / p).is_dir() and any(f.startswith(p) for f in written)) or p in written, p


# ---- the stack ------------------------------------------------------------------------------

CI = """graph: { title: "lib.c"
node: { title: "api_step" label: "api_step\\nlib.c:1:1\\n16 bytes (static)" }
node: { title: "lib.c:core" label: "core\\nlib.c:2:1\\n32 bytes (static)" }
node: { title: "lib.c:gen" label: "gen\\nlib.c:3:1\\n100 bytes (static)" }
node: { title: "lib.c:small" label: "small\\nlib.c:4:1\\n8 bytes (static)" }
node: { title: "sin" label: "sin\\nmath.h:1:1" shape : ellipse }
node: { title: "api_dyn" label: "api_dyn\\nlib.c:5:1\\n24 bytes (dynamic)" }
edge: { sourcename: "api_step" targetname: "lib.c:core" label: "lib.c:1:2" }
edge: { sourcename: "api_step" targetname: "lib.c:small" label: "lib.c:1:3" }
edge: { sourcename: "lib.c:core" targetname: "lib.c:gen" label: "lib.c:2:2" }
edge: { sourcename: "lib.c:gen" targetname: "sin" label: "lib.c:3:2" }
edge: { sourcename: "api_dyn" targetname: "lib.c:small" label: "lib.c:5:2" }
}
"""


def test_worst_stack_of_a_call_graph(tmp_path):
    """16 + 32 + 100 along api_step > core > gen (the other branch, small, is 8); sin has no
    frame and is listed apart; a dynamic frame is a lower bound. stack.awk agrees."""
    (tmp_path / "lib.ci").write_text(CI)
    g = read_callgraph([tmp_path / "lib.ci"])
    s = worst_stack(g, "api_step")
    assert (s.bytes, s.chain, s.external, s.bounded) == (148, ("api_step", "core", "gen"),
                                                         ("sin",), True)
    d = worst_stack(g, "api_dyn")
    assert (d.bytes, d.bounded) == (32, False)
    if shutil.which("awk"):
        awk = pm2dof.export.__path__[0] + "/templates/embedded/stack.awk"
        out = _run(["awk", "-f", awk, tmp_path / "lib.ci"]).stdout
        assert sorted(out.splitlines()) == sorted(["    148 api_step",
                                                   "     32 api_dyn (lower bound)"])


@needs_cc
@pytest.mark.parametrize("name", ["shang2010", "rrr4_platform"])
def test_the_step_calls_the_generated_step_directly(exports, name):
    """GCC's call graph at -O0 (nothing inlined): the API's NA step reaches both generated NA
    steps (the paper's law and the projected one, chosen by params.project) by direct calls,
    and its worst chain runs into one of them and its body (a call through a function pointer
    ended it at the step's core), deeper than the API's own frames."""
    _, objs = exports[name]
    if not objs[0].with_suffix(".ci").is_file():
        pytest.skip("the C compiler has no -fcallgraph-info (GCC 10 or later)")
    g = read_callgraph([o.with_suffix(".ci") for o in objs])
    reached, todo = set(), [f"{name}_pm2dof_na_step"]
    while todo:
        for c in g.calls.get(todo.pop(), ()):
            if g.names.get(c, c) not in reached:
                reached.add(g.names.get(c, c))
                todo.append(c)
    assert {f"{name}_na_step", f"{name}_na_proj_step"} <= reached, reached
    s = worst_stack(g, f"{name}_pm2dof_na_step")
    assert {f"{name}_na_step", f"{name}_na_proj_step"} & set(s.chain), s.chain
    assert any(re.fullmatch(rf"{name}_f\d+", c) for c in s.chain), s.chain
    assert s.bounded
    api_only = sum(g.frames[t][0] for t in g.frames if t.endswith(("core_begin", "core_end"))
                   or t == f"{name}_pm2dof_na_step")
    assert s.bytes > api_only


def _m4f_na_stack(proj, name, tmp_path, api_text):
    """The worst-case stack of the API's NA step in ``api_text``, compiled as embedded/Makefile
    compiles the library for the Cortex-M4F (-O2), from GCC's call graph."""
    src = tmp_path / f"{name}_pm2dof.c"
    src.write_text(api_text)
    _run(["arm-none-eabi-gcc", "-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard",
          "-mfpu=fpv4-sp-d16", "-std=c99", "-O2", "-ffp-contract=off", "-ffunction-sections",
          "-fdata-sections", f"-I{proj / 'include'}", f"-I{proj / 'src'}",
          "-fcallgraph-info=su", "-c", src, "-o", tmp_path / f"{name}_pm2dof.o"],
         cwd=tmp_path)
    g = read_callgraph([tmp_path / f"{name}_pm2dof.ci"])
    links = dict(re.findall(r"^#define (\w+) (\w+)$", _header(proj, name), re.M))
    return worst_stack(g, links.get(f"{name}_pm2dof_na_step", f"{name}_pm2dof_na_step")).bytes


@needs_cross
@pytest.mark.parametrize("name", ["rrr4_platform", "prr3_platform", "shang2010_vertical"])
def test_the_projection_option_costs_no_stack(tmp_path, name):
    """NA's step chooses between two generated steps. Its worst-case stack (Cortex-M4F, double,
    -O2) is that of the deeper of the two alone (the choice fixed at compile time), not their
    sum: the paper's law inlined into the step kept its frame on the stack while the projected
    one ran (rrr4_platform: 2,584 B against 1,296 B for the deeper alone; prr3_platform 2,072 B
    against 1,032 B)."""
    proj = export_project(name, tmp_path / "p", controllers=("na",), measure_stack=False)
    api = (proj / "src" / f"{name}_pm2dof.c").read_text()
    choice = "if (ctl->params.project)"
    assert api.count(choice) == 1
    both = _m4f_na_stack(proj, name, tmp_path, api)
    alone = [_m4f_na_stack(proj, name, tmp_path, api.replace(choice, f"if ({k})"))
             for k in (0, 1)]
    assert both <= max(alone), (both, alone)


@needs_cross
def test_the_readme_states_the_stack_measured_for_a_cortex_m4f(tmp_path):
    """prr3_platform, single precision: the README's figure for each step equals what the
    exported project's own embedded/Makefile build (M4F, -O2) and stack.awk give."""
    proj = export_project("prr3_platform", tmp_path / "p", precision="single",
                          controllers=("na", "ctc"))
    readme = (proj / "README.md").read_text()
    rows = dict(re.findall(r"^\| `(prr3_platform_pm2dof_\w+)` \| ([\d,]+) \|", readme, re.M))
    assert {"prr3_platform_pm2dof_na_step", "prr3_platform_pm2dof_ctc_step",
            "prr3_platform_pm2dof_fk"} <= rows.keys(), readme[-3000:]
    assert "Cortex-M4F" in readme and "single precision" in readme
    obj = "build/m4f/prr3_platform_pm2dof.o"
    _run(["make", "-s", "-C", proj / "embedded", obj])
    awk = _run(["awk", "-f", proj / "embedded" / "stack.awk",
                proj / "embedded" / "build" / "m4f" / "prr3_platform_pm2dof.ci"]).stdout
    measured = {f: int(b) for b, f in (line.split()[:2] for line in awk.splitlines())}
    for f, b in rows.items():
        assert int(b.replace(",", "")) == measured[f], (f, b, measured[f])
    record = json.loads((proj / "pm2dof_export.json").read_text())
    assert record["stack"]["bytes"]["prr3_platform_pm2dof_na_step"] == measured[
        "prr3_platform_pm2dof_na_step"]


def test_without_a_measure_the_readme_says_how(exports):
    readme = (exports["shang2010"][0] / "README.md").read_text()
    assert "Not measured at export" in readme and "embedded/stack.awk" in readme
    assert "make -C embedded stack" in readme


# ---- the install ------------------------------------------------------------------------------

CONSUMER = """cmake_minimum_required(VERSION 3.13)
project(consumer C)
find_package(prr3_platform_pm2dof REQUIRED)
add_executable(consumer main.c)
target_link_libraries(consumer PRIVATE pm2dof::prr3_platform_pm2dof)
"""
CONSUMER_MAIN = r"""#include <stdio.h>
#include "prr3_platform_pm2dof.h"
int main(void)
{
    static prr3_platform_pm2dof_na ctl;
    prr3_platform_pm2dof_work w;
    prr3_platform_pm2dof_real x[PRR3_PLATFORM_PM2DOF_TASK_DIM] = {%s}, q[PRR3_PLATFORM_PM2DOF_N_Q],
                              y[PRR3_PLATFORM_PM2DOF_TASK_DIM];
    int s = prr3_platform_pm2dof_na_init(&ctl, NULL);
    s += prr3_platform_pm2dof_ik(x, q, &w) + prr3_platform_pm2dof_fk(q, y, NULL, &w);
    printf("%%d %%.17g %%.17g %%.17g\n", s, y[0], y[1], y[2]);
    return s;
}
"""


@needs_cmake
def test_find_package_after_cmake_install(exports, tmp_path):
    """deploying.md's recipe on one export alone: build (-O2), `cmake --install --prefix`,
    then a consumer project finds the package, compiles against the installed header (the
    target's include directory) and links: fk(ik(x)) = x from the installed library. The
    optimised library calls only functions the header lists or says a compiler adds."""
    proj, _ = exports["prr3_platform"]
    prefix = tmp_path / "opt" / "robot"
    _run(["cmake", "-S", proj, "-B", tmp_path / "b", "-DBUILD_TESTING=OFF",
          "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_C_FLAGS_RELEASE=-O2"])
    _run(["cmake", "--build", tmp_path / "b"])
    _run(["cmake", "--install", tmp_path / "b", "--prefix", prefix])
    assert not (prefix / "include" / "prr3_platform_generated.inc").exists()
    x = [float(v) for v in pm2dof.load_model("prr3_platform").spec.trajectories["high"]["end"]]
    (tmp_path / "c").mkdir()
    (tmp_path / "c" / "CMakeLists.txt").write_text(CONSUMER)
    (tmp_path / "c" / "main.c").write_text(CONSUMER_MAIN % ", ".join(map(repr, x)))
    _run(["cmake", "-S", tmp_path / "c", "-B", tmp_path / "cb", f"-DCMAKE_PREFIX_PATH={prefix}",
          "-DCMAKE_C_FLAGS=-Wall -Wextra -Werror"])
    _run(["cmake", "--build", tmp_path / "cb"])
    s, *y = _run([tmp_path / "cb" / "consumer"]).stdout.split()
    assert s == "0"
    assert [float(v) for v in y] == pytest.approx(x, abs=1e-12)
    undefined = _nm(prefix / "lib" / "libprr3_platform_pm2dof.a", "-u") - {"_GLOBAL_OFFSET_TABLE_"}
    assert undefined and undefined <= _listed(_header(proj, "prr3_platform")) | COMPILER_CALLS
