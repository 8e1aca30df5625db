# The package's layers: imports point down only, and the runtime layers pull in no heavy library.
"""Import direction of ``pm2dof``'s sub-packages.

* Static: every import statement of every module (top level and inside functions, absolute or
  relative) is resolved, and a module of one sub-package may import only the sub-packages and
  third-party libraries its layer allows (:data:`ALLOWED`, :data:`THIRD_PARTY`).
* docs/developing.md's table of the layers says the same as :data:`ALLOWED` and
  :data:`THIRD_PARTY`.
* Static: no import cycle between the modules of ``pm2dof`` (:func:`_import_cycles`), imports
  inside functions included: two modules that need each other are one job split badly.
* Dynamic: in a fresh interpreter, ``import pm2dof`` (and its core and control layers, and a
  controller step and a rollout) loads none of SymPy, CasADi, matplotlib, Dask, pyarrow, SciPy.

A new sub-package must be entered in :data:`ALLOWED`, which is where its layer is decided.
"""
import ast
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

PKG = Path(__file__).resolve().parent.parent / "pm2dof"

# sub-package (or top-level module) -> the pm2dof sub-packages it may import
_RUNTIME = {"core", "control"}
ALLOWED = {
    "core": {"core"},                                   # 1: the thin runtime
    "derive": {"core", "derive"},                       # build time: SymPy, CasADi -> C
    "control": {"core", "control"},                     # 2: controllers, rollouts
    "reference": {"core", "reference"},                 # beside: NumPy formulations
    "infra": {"core", "infra"},                         # below 3: result files, progress
    "linear": _RUNTIME | {"linear"},                    # 3: linearisation, LQR (SciPy)
    "analysis": _RUNTIME | {"infra", "analysis", "linear"},   # 3: experiment, reports, maps
    "identification": _RUNTIME | {"infra", "identification"},   # 3: logs, excitation, fit
    "planning": _RUNTIME | {"infra", "planning"},       # 3: motion planning
    # bench/synthesis.py times design studies (synthesis) on Dask (studies' connect)
    "bench": _RUNTIME | {"infra", "reference", "bench", "derive", "planning", "linear",
                         "studies", "synthesis"},
    "export": _RUNTIME | {"export"},                    # beside bench: C projects
    "studies": _RUNTIME | {"infra", "identification", "studies", "linear"},   # 3: Dask
    # 3: design studies (pymoo's optimisers, Dask, Parquet), at the studies' level
    "synthesis": _RUNTIME | {"infra", "analysis", "planning", "linear", "studies", "synthesis"},
    "figures": _RUNTIME | {"infra", "analysis", "studies", "synthesis", "figures", "planning",
                           "linear"},                                                     # 4
    # 4: the CLI, a package: its commands (cli/commands/), their registry, the shared options
    # and the error mapping; it may import every layer, and no layer imports it
    "cli": _RUNTIME | {"infra", "analysis", "identification", "bench", "studies", "synthesis",
                       "figures", "cli", "derive", "planning", "linear", "export"},       # 4
    "__init__": _RUNTIME,                               # the public API (lazy names aside)
    "__main__": {"cli"},
}
# sub-package -> third-party top-level modules it may import (besides the standard library)
_HEAVY = {"sympy", "casadi", "matplotlib", "dask", "distributed", "pyarrow", "scipy"}
THIRD_PARTY = {
    "core": {"numpy"}, "control": {"numpy"}, "reference": {"numpy"}, "__init__": set(),
    "__main__": set(),
    "infra": {"numpy", "tqdm", "pyarrow"},     # tqdm: the progress bars; pyarrow: Parquet tables,
    #                                            lazily (infra/tables.py)
    "analysis": {"numpy"},
    "identification": {"numpy", "scipy", "casadi", "pyarrow"},   # the ident extra; lazily
    "linear": {"numpy", "scipy", "control"},            # the [control] extra (python-control)
    "derive": {"numpy", "sympy", "casadi"},             # the [derive] extra
    "bench": {"numpy", "casadi", "sympy", "toppra", "pinocchio", "mujoco"},  # optional baselines
    "studies": {"numpy", "dask", "distributed", "pyarrow"},
    "synthesis": {"numpy", "pymoo", "dask", "distributed", "pyarrow"},   # the design extra; lazily
    "planning": {"numpy", "casadi"},                    # CasADi only in plan_smooth (lazily)
    "export": {"numpy"},                                # copies generated C: no CasADi
    "figures": {"numpy", "matplotlib", "PIL", "pyarrow"},
    "cli": set(),
}
STDLIB = set(sys.stdlib_module_names)


def _unit(path):
    """The layer unit of a module file: its sub-package, or the top-level module's stem."""
    rel = path.relative_to(PKG)
    return rel.parts[0] if len(rel.parts) > 1 else rel.stem


def _imports(path, root=PKG):
    """(line, absolute module name) of every import in the file (of the package at ``root``),
    relative ones resolved."""
    rel = path.relative_to(root.parent).with_suffix("")
    package = list(rel.parts[:-1])  # the package a relative import starts from (also for __init__)
    out = []
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.Import):
            out += [(node.lineno, a.name) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[:len(package) - node.level + 1]
                mod = ".".join(base + ([node.module] if node.module else []))
                if node.module is None:  # from . import x, y: each is a module of base
                    out += [(node.lineno, ".".join(base + [a.name])) for a in node.names]
                    continue
            else:
                mod = node.module
            out.append((node.lineno, mod))
    return out


MODULES = sorted(p for p in PKG.rglob("*.py"))


def test_every_sub_package_has_a_declared_layer():
    units = {_unit(p) for p in MODULES}
    assert units <= set(ALLOWED), f"undeclared sub-packages: {sorted(units - set(ALLOWED))}"
    assert units <= set(THIRD_PARTY)
    assert {"core", "control", "infra", "analysis", "identification", "bench", "figures",
            "reference", "cli", "derive"} <= units


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PKG)))
def test_imports_point_down_the_layers(path):
    unit = _unit(path)
    bad = []
    for line, mod in _imports(path):
        top = mod.split(".")[0]
        if top == "pm2dof":
            parts = mod.split(".")
            target = parts[1] if len(parts) > 1 else "__init__"
            if target not in ALLOWED[unit]:
                bad.append(f"line {line}: {mod} (layer {target!r} is not below {unit!r})")
        elif top not in STDLIB and top not in THIRD_PARTY[unit]:
            bad.append(f"line {line}: third-party {mod!r} is not allowed in {unit!r}")
    assert not bad, f"{path.relative_to(PKG.parent)}:\n  " + "\n  ".join(bad)


def test_the_checker_sees_relative_and_function_level_imports(tmp_path):
    """The static check would catch a violation (it is not vacuous)."""
    src = PKG / "core" / "model.py"
    found = {m for _, m in _imports(src)}
    assert {"pm2dof.core._cbind", "pm2dof.core.errors", "numpy"} <= found, found
    found = {m for _, m in _imports(PKG / "figures" / "experiment.py")}
    assert "matplotlib" in found and "pm2dof.infra.results" in found, found


def _module_file(name, root):
    """The file of module ``name`` (dotted, from ``root``'s package), or of the longest module
    prefix of it (``pkg.mod.Name`` names ``pkg/mod.py``); None outside the package and for a
    compiled extension (``pm2dof.core._cbind``: it imports no Python module)."""
    from importlib.machinery import EXTENSION_SUFFIXES
    parts = name.split(".")
    if parts[0] != root.name:
        return None
    while parts:
        base = root.parent.joinpath(*parts)
        if any(base.with_name(base.name + s).is_file() for s in EXTENSION_SUFFIXES + [".c"]):
            return None
        for f in (base.with_suffix(".py"), base / "__init__.py"):
            if f.is_file():
                return f
        parts.pop()
    return None


def _import_cycles(root=PKG):
    """The import cycles among the modules of the package at ``root``: each strongly connected
    component of the import graph with more than one module (or a module importing itself),
    as a sorted list of paths relative to ``root``. Every import counts, inside functions too."""
    files = sorted(root.rglob("*.py"))
    graph = {f: {g for _, mod in _imports(f, root) if (g := _module_file(mod, root))}
             for f in files}
    index, low, stack, on, found = {}, {}, [], set(), []

    def visit(v):                             # Tarjan's strongly connected components
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            part = []
            while True:
                w = stack.pop()
                on.discard(w)
                part.append(w)
                if w == v:
                    break
            if len(part) > 1 or v in graph[v]:
                found.append(sorted(str(p.relative_to(root)) for p in part))

    for f in files:
        if f not in index:
            visit(f)
    return sorted(found)


def test_no_import_cycle_inside_pm2dof():
    assert _import_cycles() == []


def test_the_cycle_checker_finds_a_cycle_through_a_function_level_import(tmp_path):
    """Not vacuous: a -> b at the top, b -> a inside a function (the shape identification's
    design and excitation had) is a cycle; c -> a alone is not."""
    pkg = tmp_path / "pkg"
    (pkg / "sub").mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "sub" / "__init__.py").write_text("")
    (pkg / "sub" / "a.py").write_text("from .b import thing\n")
    (pkg / "sub" / "b.py").write_text("def thing():\n    from pkg.sub.a import x\n")
    (pkg / "c.py").write_text("from .sub import a\n")
    assert _import_cycles(pkg) == [["sub/a.py", "sub/b.py"]]


_PROBE = r"""
import sys
import numpy as np
import pm2dof, pm2dof.core, pm2dof.control
m = pm2dof.load_model()
c = pm2dof.NAController(m)
q = m.ik([0.245, 0.265])
c.reset(q[:m.n_legs])
c.step(q[:m.n_legs], np.array([0.245, 0.265]), np.zeros(2), np.zeros(2))
pm2dof.simulate(m, pm2dof.APDController(m), pm2dof.paper_move("high"))
heavy = sorted({k.split(".")[0] for k in sys.modules} & HEAVY)
heavy += sorted(k for k in sys.modules if k.startswith("pm2dof.derive"))
print(",".join(heavy))
"""


def test_runtime_layers_load_no_heavy_library():
    code = f"HEAVY = {sorted(_HEAVY)!r}\nHEAVY = set(HEAVY)\n" + _PROBE
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120,
                       cwd=PKG.parent)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "", f"runtime imports loaded {r.stdout.strip()}"


def test_importing_an_unbuilt_source_tree_says_what_is_missing(tmp_path):
    """A copy of the package without its compiled extension: one sentence naming what is not
    built and the command that builds it (not Python's 'circular import' guess)."""
    import shutil
    shutil.copytree(PKG, tmp_path / "pm2dof",
                    ignore=shutil.ignore_patterns("*.so", "__pycache__", "generated"))
    r = subprocess.run([sys.executable, "-c", "import pm2dof"], capture_output=True, text=True,
                       timeout=60, cwd=tmp_path, env={"PYTHONPATH": str(tmp_path), "PATH": ""})
    assert r.returncode != 0
    last = r.stderr.strip().splitlines()[-1]
    assert last == (f"ImportError: pm2dof is not built: its C extension pm2dof.core._cbind is "
                    f"missing from {tmp_path / 'pm2dof' / 'core'}; build it with `pip install "
                    f"-e .` (or `make install`) in the source tree"), r.stderr
    assert "circular import" not in r.stderr


def test_the_developing_page_lists_every_layer_as_here():
    """docs/developing.md's table of the layers is ALLOWED and THIRD_PARTY, row for row."""
    import re
    page = (PKG.parent / "docs" / "developing.md").read_text()
    rows = {}
    for line in page.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 5 and re.fullmatch(r"`\w+`", cells[0]):
            rows[cells[0].strip("`")] = (set(re.findall(r"`(\w+)`", cells[3])),
                                         set(re.findall(r"`(\w+)`", cells[4])))
    assert set(rows) == set(ALLOWED), sorted(set(rows) ^ set(ALLOWED))
    for unit, (pm2dof, third) in rows.items():
        assert pm2dof == ALLOWED[unit], (unit, sorted(pm2dof ^ ALLOWED[unit]))
        assert third == THIRD_PARTY[unit], (unit, sorted(third ^ THIRD_PARTY[unit]))
