# Stack: the worst-case stack of a library's functions, from GCC's call graph (-fcallgraph-info).
"""The deepest stack a call of the exported library can use, from what GCC measured.

``gcc -fcallgraph-info=su`` (GCC 10 or later) writes, beside each object, a ``.ci`` file: one
node per function with its frame size (``-fstack-usage``'s ``N bytes (static)``, or
``dynamic``/``dynamic,bounded``) and one edge per call. The worst stack of a function is its
frame plus the worst stack of the callees, along the deepest chain. Functions GCC did not
compile (the math library, libgcc's floating-point routines, ``memset``) have no frame in the
graph: they are listed apart, as ``external``, and are not counted.

The library's step reaches its generated step by a direct call, so the chain is whole. A
function whose frame is ``dynamic`` (unbounded), a call through a pointer, or recursion makes
the figure a lower bound; :func:`worst_stack` says so.

:func:`measure` compiles the library's one translation unit with a cross compiler and returns
each function's figure; ``pm2dof export`` calls it when ``arm-none-eabi-gcc`` is on the PATH
and writes the figures into the export's README. ``embedded/stack.awk`` of an export computes
the same from the ``.ci`` files of ``make -C embedded stack``.
"""
import re
import shutil
import subprocess
import tempfile
from pathlib import Path
from typing import NamedTuple

__all__ = ["CallGraph", "Stack", "Measured", "read_callgraph", "worst_stack", "measure",
           "CROSS_GCC", "TARGET_FLAGS", "BUILD_FLAGS"]

CROSS_GCC = "arm-none-eabi-gcc"
#: the Cortex-M4F of make embedded (embedded/Makefile's CPU_m4f), its single-precision FPU
TARGET_FLAGS = {"Cortex-M4F": ("-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard",
                               "-mfpu=fpv4-sp-d16")}
#: as the exported CMakeLists.txt and embedded/Makefile build the library
BUILD_FLAGS = ("-std=c99", "-O2", "-ffp-contract=off", "-ffunction-sections", "-fdata-sections")

_NODE = re.compile(r'^node: \{ title: "([^"]*)" label: "([^"]*)"', re.M)
_EDGE = re.compile(r'^edge: \{ sourcename: "([^"]*)" targetname: "([^"]*)"', re.M)
_FRAME = re.compile(r"(\d+) bytes \(([a-z,]+)\)")


class CallGraph(NamedTuple):
    """Frames and calls read from ``.ci`` files: ``frames`` {node: (bytes, kind)} for the
    functions GCC compiled (kind ``static``, ``dynamic,bounded`` or ``dynamic``), ``calls``
    {node: set of nodes}, ``names`` {node: function name}."""
    frames: dict
    calls: dict
    names: dict


class Stack(NamedTuple):
    """The worst stack of one function: ``bytes`` along ``chain`` (function names, outermost
    first); ``external``: the functions reached that have no frame in the graph (not
    counted); ``bounded``: False when a dynamic frame or recursion makes ``bytes`` a lower
    bound."""
    bytes: int
    chain: tuple
    external: tuple
    bounded: bool


def read_callgraph(paths):
    """The call graph of the ``.ci`` files ``paths`` (:class:`CallGraph`)."""
    frames, calls, names = {}, {}, {}
    for path in paths:
        text = Path(path).read_text()
        for title, label in _NODE.findall(text):
            names[title] = label.split("\\n")[0]
            m = _FRAME.search(label)
            if m:
                frames[title] = (int(m.group(1)), m.group(2))
        for src, dst in _EDGE.findall(text):
            calls.setdefault(src, set()).add(dst)
    return CallGraph(frames, calls, names)


def worst_stack(graph, function):
    """The worst stack of ``function`` (a node title: the symbol of an external function) in
    ``graph`` (:class:`Stack`)."""
    memo = {}

    def visit(node, active):
        if node in memo:
            return memo[node]
        if node not in graph.frames:
            return 0, (), {node}, True
        size, kind = graph.frames[node]
        best, external, bounded = (0, ()), set(), kind != "dynamic"
        for callee in sorted(graph.calls.get(node, ())):
            if callee in active:            # recursion: no bound from the graph
                bounded = False
                continue
            b, chain, ext, ok = visit(callee, active | {node})
            external |= ext
            bounded &= ok
            if b > best[0]:
                best = (b, chain)
        memo[node] = (size + best[0], (graph.names.get(node, node), *best[1]), external,
                      bounded)
        return memo[node]

    if function not in graph.frames:
        raise KeyError(f"{function} has no frame in the call graph")
    b, chain, ext, ok = visit(function, frozenset())
    return Stack(b, chain, tuple(sorted(ext)), ok)


class Measured(NamedTuple):
    """What :func:`measure` found: ``stacks`` {function: :class:`Stack`}, for ``target``
    compiled by ``compiler`` (its version line) with ``flags``."""
    stacks: dict
    target: str
    compiler: str
    flags: tuple


def measure(source, include, functions, target="Cortex-M4F", compiler=CROSS_GCC,
            progress=None):
    """Compile ``source`` (the library's translation unit, headers in ``include``) for
    ``target`` with ``compiler`` and measure the worst stack of ``functions`` (symbols: the
    API's link names). Returns :class:`Measured`, or None when the compiler is not on the
    PATH, is older than GCC 10 or fails (the export then says how to measure instead).
    ``progress`` is called with a line before the compile."""
    cc = shutil.which(compiler)
    if cc is None:
        return None
    flags = (*TARGET_FLAGS[target], *BUILD_FLAGS)
    if progress is not None:
        progress(f"measuring the stack of each function: {compiler} {' '.join(flags)} "
                 f"({target})")
    with tempfile.TemporaryDirectory(prefix="pm2dof_stack_") as tmp:
        obj = Path(tmp) / "lib.o"
        try:
            subprocess.run([cc, *flags, f"-I{include}", "-fcallgraph-info=su", "-c",
                            str(source), "-o", str(obj)], check=True, capture_output=True,
                           timeout=900)
            version = subprocess.run([cc, "--version"], capture_output=True, text=True,
                                     timeout=60).stdout.splitlines()[0]
        except (OSError, subprocess.SubprocessError, IndexError):
            return None
        if not obj.with_suffix(".ci").is_file():
            return None
        graph = read_callgraph([obj.with_suffix(".ci")])
    return Measured({f: worst_stack(graph, f) for f in functions if f in graph.frames},
                    target, version, flags)
