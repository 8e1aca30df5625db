# pm2dof.core.csplit: cut one CasADi-generated C file into translation units compiled in parallel.
"""Cut a CasADi-generated C file into translation units that compile in parallel.

CasADi writes one C file per model: a head (macros, small helper functions, the sparsity
patterns), then one block per generated function: ``static int casadi_fN(...)`` (its body)
followed by its exported entry points (``<name>_<function>``, ``..._n_in``, ``..._work``, ...).
Blocks call each other's ``casadi_fN``. This module rewrites nothing inside a body; it only

- gives every ``casadi_fN`` that another block calls external linkage (``static`` dropped) and
  puts one prototype of each in every unit, so that a block may call a function compiled in
  another unit (the others stay ``static``, inlined into their entry point as before); the
  library is compiled with ``-fvisibility=hidden`` so that these stay internal to it, and with
  ``GCC_HASCLASSVISIBILITY`` defined so that CasADi's ``CASADI_SYMBOL_EXPORT`` entry points are
  the library's only exported symbols;
- makes the head's helper functions (``casadi_sq``, ``casadi_copy``, ...) ``static`` in every unit
  (each unit has its own copy, inlined as before);
- keeps the head's exported configuration functions (``<name>_casadi_version``, ...) in the first
  unit only;
- puts a ``#line`` directive before every block, so that the compiler's messages name the lines
  of the original file;
- after the head's ``#include <math.h>``, puts :data:`MINMAX_PRELUDE`: with
  ``PM2DOF_INLINE_FMINMAX`` defined (:data:`pm2dof.core.build.FLAGS`), on x86-64 with glibc,
  ``fmax`` and ``fmin`` (which CasADi's ``casadi_fmax``, ``casadi_fmin`` call) are inline
  functions computing what glibc's do, bit for bit, instead of calls into libm.

The arithmetic of every function is the same text, compiled with the same floating-point flags,
so the results are the same bit for bit (checked by the tests on the shipped models). ``fmax`` and
``fmin`` give libm's bits for the operands in the C's order; the whole file's calls into libm
need not keep that order (gcc 12 swaps them, C leaving the sign of a zero they return
unspecified), so on a tie of zeros of opposite signs the two libraries may return different
zeros.

Standard library only: setup.py loads :mod:`pm2dof.core.build` (which uses this module) as a file,
before the package can be imported.
"""

from __future__ import annotations

import re
from typing import NamedTuple

__all__ = ["Block", "Split", "split_casadi_c", "has_loop", "opt_levels", "plan_units",
           "FN_SIGNATURE", "MINMAX_PRELUDE", "LOOP_OPT", "STRAIGHT_OPT", "OPT_COST", "UNIT_BYTES"]

#: The signature CasADi gives every ``casadi_fN``.
FN_SIGNATURE = ("(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, "
                "int mem)")

_FN_DEF = re.compile(r"^static int (casadi_f\d+)" + re.escape(FN_SIGNATURE) + r" \{$", re.M)
_COMMENT = re.compile(r"^/\* (\w+):\(.*\*/\n\Z")
_HELPER = re.compile(r"^(casadi_real|casadi_int|void|int) (casadi_\w+)\(", re.M)
_LOOP = re.compile(r"\bfor \(")
# a helper's definition in the head (after _HELPER made it static): its name, then its body up
# to the next definition
_HELPER_DEF = re.compile(r"^static (casadi_real|casadi_int|void|int) (casadi_\w+)\(", re.M)
_CONFIG_START = "/* Configuration this file was compiled with */\n"
_MATH_H = "#include <math.h>\n"

#: Put after the head's ``#include <math.h>``. glibc's x86-64 ``fmax(x, y)`` is ``maxsd`` when
#: both are numbers (``x > y ? x : y``: ``y`` on a tie, so ``fmax(-0., +0.)`` is ``+0.`` and
#: ``fmax(+0., -0.)`` is ``-0.``) and the number when one is NaN; ``fmin`` likewise with
#: ``minsd``. The inline functions below give the same bits (a signalling NaN aside, which
#: glibc quiets), without a call into libm, around which every live register is spilled: the
#: 4-RRR preload split calls each 115 times. Elsewhere (another processor, another C library,
#: whose ``fmax`` may order the zeros otherwise) libm's are kept.
MINMAX_PRELUDE = """
/* pm2dof: fmax and fmin inline, as glibc's x86-64 ones compute them (pm2dof.core.csplit) */
#if defined(PM2DOF_INLINE_FMINMAX) && defined(__x86_64__) && defined(__GLIBC__)
static inline double pm2dof_fmax(double x, double y) { return y != y ? x : x > y ? x : y; }
static inline double pm2dof_fmin(double x, double y) { return y != y ? x : x < y ? x : y; }
#define fmax(x, y) pm2dof_fmax(x, y)
#define fmin(x, y) pm2dof_fmin(x, y)
#endif
"""
_TAIL = "\n#ifdef __cplusplus\n} /* extern \"C\" */\n#endif\n"


class Block(NamedTuple):
    """One generated function of the file: its ``casadi_fN`` body and the entry points after it.

    Attributes
    ----------
    fn : str
        The body's name in the file, ``casadi_f<N>``.
    name : str
        The function's name in CasADi's comment above it, e.g. ``shang2010_na_step`` (an
        exported entry point of that name follows, unless the function is only called by others).
    text : str
        The block's text: the comment, the body (``static`` dropped when another block calls it)
        and the entry points.
    line : int
        The 1-based line of the original file on which ``text`` starts.
    calls : frozenset of str
        The other ``casadi_fN`` the block calls.
    """

    fn: str
    name: str
    text: str
    line: int
    calls: frozenset


class Split(NamedTuple):
    """A CasADi C file cut into a shared head and per-function blocks.

    Attributes
    ----------
    head : str
        What every unit starts with: the file's head with its helpers ``static`` and without its
        configuration entry points, then a prototype of every ``casadi_fN`` another calls.
    config : str
        The configuration entry points (``<name>_casadi_version``, ...): in one unit only.
    blocks : tuple of Block
        The generated functions in file order.
    tail : str
        The closing ``extern "C"`` lines.
    path : str
        The original file's name, for the ``#line`` directives.
    """

    head: str
    config: str
    blocks: tuple
    tail: str
    path: str

    def unit(self, blocks, first=False) -> str:
        """The C text of one translation unit holding ``blocks`` (with :attr:`config` when
        ``first``)."""
        parts = [self.head]
        if first:
            parts.append(self.config)
        for b in blocks:
            parts.append(f'#line {b.line} "{self.path}"\n{b.text}')
        parts.append(self.tail)
        return "".join(parts)


def split_casadi_c(text: str, path: str = "generated.c") -> Split | None:
    """Cut the text of a CasADi-generated C file into a :class:`Split`.

    Parameters
    ----------
    text : str
        The whole file, as ``casadi.CodeGenerator`` wrote it.
    path : str, optional
        The file's name for the ``#line`` directives (the compiler's messages).

    Returns
    -------
    Split or None
        None when the text is not laid out as this module expects (another CasADi version, a
        hand-written file): the caller then compiles the file whole.
    """
    defs = list(_FN_DEF.finditer(text))
    if not defs or not text.endswith(_TAIL) or text.count(_CONFIG_START) != 1:
        return None
    # each block starts at the comment line just above its body (when there is one)
    starts = []
    for m in defs:
        line_start = text.rfind("\n", 0, m.start() - 1) + 1
        comment = _COMMENT.match(text[line_start:m.start()])
        starts.append((line_start if comment else m.start(), comment.group(1) if comment
                       else m.group(1)))
    head, config_at = text[:starts[0][0]], text.index(_CONFIG_START)
    if config_at > starts[0][0]:
        return None
    config_end = head.find("\nstatic const ", config_at)
    if config_end < 0:
        return None
    config, head = head[config_at:config_end + 1], head[:config_at] + head[config_end + 1:]
    names = [m.group(1) for m in defs]
    if len(set(names)) != len(names):
        return None
    head = _HELPER.sub(r"static \1 \2(", head)
    if _MATH_H in head:
        head = head.replace(_MATH_H, _MATH_H + MINMAX_PRELUDE, 1)
    body_end = len(text) - len(_TAIL)
    chunks, calls_of = [], []
    called = re.compile(r"\b(casadi_f\d+)\(")
    for i, (m, (start, _)) in enumerate(zip(defs, starts)):
        end = starts[i + 1][0] if i + 1 < len(starts) else body_end
        chunks.append(text[start:end])
        calls_of.append(frozenset(c for c in called.findall(chunks[-1]) if c != m.group(1)))
        if not calls_of[-1] <= set(names):
            return None
    # a function another block calls may be in another unit: external linkage (hidden by
    # -fvisibility=hidden) and a prototype in every unit; the others stay static, as in the file
    shared = set().union(*calls_of)
    protos = "".join(f"int {n}{FN_SIGNATURE};\n" for n in names if n in shared)
    head += "\n/* the generated functions other functions call, each in one unit */\n" + protos
    blocks = []
    for m, (start, name), chunk, calls in zip(defs, starts, chunks, calls_of):
        if m.group(1) in shared:
            chunk = chunk.replace(f"static int {m.group(1)}(", f"int {m.group(1)}(", 1)
        blocks.append(Block(m.group(1), name, chunk, text.count("\n", 0, start) + 1, calls))
    return Split(head, config, tuple(blocks), _TAIL, path)


#: The optimisation of a function with a loop (the closed loops, the sampled step and its
#: Jacobians: the plant's Runge-Kutta substeps, CasADi's array copies): ``-O3`` unrolls the
#: loops (at ``-O2`` the paper robot's sampled-step Jacobians ran 27 % more instructions).
LOOP_OPT = ("-O3",)
#: The optimisation of a function without a loop (CasADi's SX functions: straight-line code,
#: the controller steps, the dynamics and their Jacobians, the path functions, ``Me``, ``ik``,
#: ...): ``-O2`` gives them the instructions of ``-O3`` (callgrind, the paper robot's and the
#: 4-RRR platform's functions: within 1 %) in about 10 % less compile time.
#:
#: Not lower, not even for the functions no controller or planner calls: every function is a
#: per-sample ``Model`` method. ``-O1`` ran the steps 30-40 % more instructions (CasADi's
#: ``casadi_sq``, ``casadi_fmax``, ... not inlined, the output pointers loaded again after
#: every store); ``-O1 -fstrict-aliasing -fexpensive-optimizations`` with those helpers inline
#: matched ``-O3``'s instructions on straight-line code in 60-70 % of the compile time, but ran
#: the preload split 20 % more instructions, ``StF`` 5-7 % and the NA step 4-7 % slower in
#: paired C loops; ``-O2 -fno-tree-pre -fno-gcse`` ran the preload split 15 % more.
STRAIGHT_OPT = ("-O2",)
#: Compile time per byte of C at each level, relative to ``-O3`` (gcc 12, the 4-RRR platform's
#: functions compiled one by one): the cost :func:`plan_units` balances.
OPT_COST = {LOOP_OPT: 1.0, STRAIGHT_OPT: 0.9}

#: Bytes of generated C per translation unit (about 1.5 processor seconds at ``-O3``): units
#: small enough that two or more processors stay busy to the end, large enough that the head
#: every unit repeats (a few hundredths of a second each) stays a few per cent of the work.
UNIT_BYTES = 100_000


def has_loop(split: Split, block: Block) -> bool:
    """Whether ``block`` runs a loop: a ``for`` of its own, or a call of one of the head's
    helpers that loops (``casadi_copy``, ``casadi_mtimes``, ...: inlined into it). CasADi's
    SX functions are straight-line code; its MX functions (the closed loops, the sampled step
    and its Jacobians) copy and multiply arrays in loops."""
    names = [m.group(2) for m in _HELPER_DEF.finditer(split.head)]
    bodies = _HELPER_DEF.split(split.head)[3::3]
    looping = [n for n, body in zip(names, bodies) if _LOOP.search(body)]
    return bool(_LOOP.search(block.text) or (looping and re.search(
        r"\b(?:" + "|".join(map(re.escape, looping)) + r")\(", block.text)))


def opt_levels(split: Split) -> dict:
    """``{casadi_fN: optimisation flags}`` of every block: :data:`LOOP_OPT` for a block with a
    loop (:func:`has_loop`), :data:`STRAIGHT_OPT` for the others."""
    return {b.fn: LOOP_OPT if has_loop(split, b) else STRAIGHT_OPT for b in split.blocks}


def plan_units(split: Split, levels: dict, unit_bytes: int = UNIT_BYTES):
    """Share the blocks among translation units, one optimisation level per unit.

    Within each level the blocks go, largest first, to the unit holding the fewest bytes so
    far (longest-processing-time first), so the units of a level are of about equal size.

    Parameters
    ----------
    split : Split
    levels : dict of str to tuple of str
        The optimisation flags of each ``casadi_fN`` (:func:`opt_levels`).
    unit_bytes : int, optional
        Bytes of C per unit aimed at.

    Returns
    -------
    list of (tuple of str, list of Block, float)
        ``(flags, blocks, cost)`` per unit, costliest first: its blocks in file order, its
        estimated compile time in units of a byte at ``-O3`` (:data:`OPT_COST`, the head
        included); empty units are left out.
    """
    order = {b.fn: i for i, b in enumerate(split.blocks)}
    units = []
    for flag in dict.fromkeys(levels[b.fn] for b in split.blocks):
        group = sorted((b for b in split.blocks if levels[b.fn] == flag),
                       key=lambda b: -len(b.text))
        size = sum(len(b.text) for b in group)
        n = min(len(group), max(1, round(size / unit_bytes)))
        bins = [[0, []] for _ in range(n)]
        for b in group:
            target = min(bins, key=lambda x: x[0])
            target[0] += len(b.text)
            target[1].append(b)
        cost = OPT_COST.get(flag, 1.0)
        units += [(flag, sorted(blocks, key=lambda b: order[b.fn]),
                   (size + len(split.head)) * cost) for size, blocks in bins if blocks]
    return sorted(units, key=lambda u: -u[2])
