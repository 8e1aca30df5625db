# Benchmark of the build: derive and compile the 4-RRR platform beside gcc on the paper's C.
"""How long ``pm2dof derive`` of the shipped ``rrr4_platform`` takes (SymPy, CasADi, the C
compile: the command a user waits for), as a ratio to the time gcc ``-O3`` takes for the paper
robot's generated C compiled whole in one command with :data:`pm2dof.core.build.FLAGS` (0.88 MB
of C), both measured in the same run, so that the ratio holds on another machine or under
another load.

Each round runs the two back to back, in alternating order; the ratio is the median of the
rounds' ratios. The derive runs as its own process (``python -m pm2dof derive MODEL --force
--quiet``, interpreter start and imports included) on a copy of the shipped model file in a
temporary folder; the gcc command compiles the shipped ``shang2010.c`` into a temporary library.

Also ``python -m pm2dof.bench.build_time [ROUNDS]`` prints the rows as JSON.
"""
from __future__ import annotations

import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from ..core import build
from ..core.paths import SHIPPED_GENERATED, SHIPPED_MODELS
from .timing import stats

__all__ = ["build_bench", "DERIVED_MODEL", "PAPER_MODEL"]

#: The model whose derive is timed (the largest shipped C, 2.2 MB) and the one whose C gcc
#: compiles whole as the yardstick.
DERIVED_MODEL, PAPER_MODEL = "rrr4_platform", "shang2010"


def _timed(cmd, cwd, env=None):
    """Run ``cmd``; (wall s, processor s of the children: user + system). Raises
    RuntimeError with its stderr when it fails."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, check=False)
    wall = time.perf_counter() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(map(str, cmd))} failed ({proc.returncode}):\n"
                           f"{proc.stderr.strip()[-2000:]}")
    return wall, (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)


def build_bench(rounds=1, say=None):
    """Time ``pm2dof derive`` of :data:`DERIVED_MODEL` and gcc on :data:`PAPER_MODEL`'s C.

    Parameters
    ----------
    rounds : int
        Rounds of the two commands back to back (about a minute each on two idle processors).
    say : callable(str), optional
        Receives a line per command.

    Returns
    -------
    dict
        ``derive_rrr4_s``, ``gcc_paper_s``: medians of the wall times, s;
        ``derive_rrr4_cpu_s``, ``gcc_paper_cpu_s``: medians of their processor time (user +
        system, every process they started), s; ``derive_rrr4_over_gcc_paper``: the median of
        the rounds' ratios of wall times; ``derive_rrr4_cpu_over_gcc_paper_cpu`` the same of
        processor times (what the wall ratio tends to while other programs keep every
        processor busy: Linux shares the processors between sessions, however many compilers
        one runs); ``build_rounds``: the rounds' (derive, gcc) wall times, s; ``build_jobs``:
        the compilers the derive ran at once.
    """
    say = say or (lambda msg: None)
    pkg_root = str(Path(__file__).resolve().parents[2])
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([pkg_root, *filter(None, [env.get("PYTHONPATH")])])
    paper_c = SHIPPED_GENERATED / PAPER_MODEL / f"{PAPER_MODEL}.c"
    per = {"derive": [], "gcc": [], "derive_cpu": [], "gcc_cpu": []}
    with tempfile.TemporaryDirectory(prefix="pm2dof-build-bench-") as tmp:
        tmp = Path(tmp)
        model_file = tmp / f"{DERIVED_MODEL}.toml"
        shutil.copyfile(SHIPPED_MODELS / f"{DERIVED_MODEL}.toml", model_file)
        derive = [sys.executable, "-m", "pm2dof", "derive", str(model_file), "--force", "--quiet"]
        gcc = [*build._compiler(), *build.FLAGS, "-o", str(tmp / f"lib{PAPER_MODEL}.so"),
               str(paper_c), *build.LIBS]
        for r in range(rounds):
            order = ("gcc", "derive") if r % 2 == 0 else ("derive", "gcc")
            for what in order:
                say(f"round {r + 1}/{rounds}: " + (f"pm2dof derive {DERIVED_MODEL}"
                    if what == "derive" else f"gcc {build.FLAGS[0]} {paper_c.name} (whole)"))
                wall, cpu = _timed(derive if what == "derive" else gcc, tmp, env)
                per[what].append(wall)
                per[f"{what}_cpu"].append(cpu)
    return {"derive_rrr4_s": stats(per["derive"])["median"],
            "gcc_paper_s": stats(per["gcc"])["median"],
            "derive_rrr4_cpu_s": stats(per["derive_cpu"])["median"],
            "gcc_paper_cpu_s": stats(per["gcc_cpu"])["median"],
            "derive_rrr4_over_gcc_paper": stats([d / g for d, g in
                                                 zip(per["derive"], per["gcc"])])["median"],
            "derive_rrr4_cpu_over_gcc_paper_cpu": stats([d / g for d, g in zip(
                per["derive_cpu"], per["gcc_cpu"])])["median"],
            "build_rounds": [list(p) for p in zip(per["derive"], per["gcc"])],
            "build_jobs": build.build_jobs()}


def _main(argv=None):
    """``python -m pm2dof.bench.build_time [ROUNDS]``: the rows of :func:`build_bench` as JSON."""
    import json
    args = sys.argv[1:] if argv is None else argv
    rounds = int(args[0]) if args else 1
    res = build_bench(rounds, say=lambda msg: print(msg, file=sys.stderr, flush=True))
    print(json.dumps(res, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(_main())
