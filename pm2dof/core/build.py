# pm2dof.core.build: compile CasADi-generated C files into shared libraries for pm2dof.core._cbind.
"""Compile CasADi-generated C files into shared libraries.

The library is meant to be loaded with :class:`pm2dof.core._cbind.Library`. Compilation
writes to a temporary file next to the target and renames it into place, so a
process that loads the target path never sees a half-written library.

A CasADi file is cut into translation units (:mod:`pm2dof.core.csplit`) compiled on every
processor at once, then linked: with :data:`FLAGS`, at ``-O3`` the functions that hold a
loop, at ``-O2`` the straight-line ones (:func:`pm2dof.core.csplit.opt_levels`).
:func:`compile_libraries` compiles several libraries on one pool of processors (setup.py and
``make libs`` still compile one library per call). Any other C file is compiled whole, as one
command.
"""

from __future__ import annotations

import os
import pathlib
import platform
import shlex
import subprocess
import sysconfig
import tempfile
import threading
import time
from collections.abc import Iterable
from concurrent.futures import ThreadPoolExecutor

__all__ = ["compile_library", "compile_libraries", "library_is_fresh", "BuildError",
           "STALE_TMP_AGE_S", "FLAGS", "PORTABLE_FLAGS", "SPLIT_FLAGS",
           "COMPILE_SECONDS_PER_MB", "compile_estimate", "build_jobs"]

#: Temporary libraries (``.lib<name>.so.*.tmp``) older than this are left-overs of a build that
#: was killed; :func:`compile_library` removes them. Younger ones may belong to a build that is
#: running now (a build takes 10 s to a few minutes), so they are left alone.
STALE_TMP_AGE_S = 600.0

#: Compiler flags used by :func:`compile_library`, in order:
#:
#: ``-O3``
#:     Full optimisation of the straight-line code CasADi generates.
#: ``-march=native``
#:     Use every instruction-set extension of the building machine (AVX2, ...).
#:     The library is therefore only meant to run on the machine that built it.
#: ``-ffp-contract=off``
#:     Do not fuse ``a*b + c`` into FMA instructions (GCC fuses by default in GNU C
#:     mode once ``-march=native`` enables FMA). Fusing changes rounding, so results
#:     would no longer agree bit for bit with CasADi's own evaluation.
#: ``-fPIC``
#:     Position-independent code, required for a shared library.
#: ``-shared``
#:     Produce a shared library that ``dlopen`` can load.
#: ``-fno-math-errno``
#:     Math functions need not set ``errno``, so ``sqrt`` and friends compile to
#:     single instructions; results are unchanged (IEEE semantics are kept).
#: ``-fno-semantic-interposition``
#:     CasADi writes its helpers (``casadi_sq``, ``casadi_fabs``, ``casadi_fmax``, ...) as
#:     global functions; in position-independent code the compiler would otherwise call each
#:     through the PLT (no inlining, every live register spilled around it: a 4-RRR NA step
#:     made ~200 such calls). The library's own definitions are the ones used (nothing
#:     interposes them), so they are inlined; results are unchanged (the same operations).
#:
#: ``-DPM2DOF_INLINE_FMINMAX``
#:     ``fmax`` and ``fmin`` inline in a CasADi file's units, computing glibc's results bit for
#:     bit (:data:`pm2dof.core.csplit.MINMAX_PRELUDE`; x86-64 with glibc only, else libm's):
#:     like CasADi's helpers above, each was a call around which every live register was
#:     spilled (a plan's maximum-velocity curve and passes, the controllers' torque splits).
#:     A library built without it is built again (:func:`library_is_fresh`).
#:
#: ``-mno-fma`` (x86 only)
#:     No fused multiply-add instructions at all. ``-ffp-contract=off`` alone does not keep GCC 12
#:     from fusing: its SLP vectoriser turns a multiplication feeding an alternating
#:     add/subtract into ``vfmaddsub``/``vfmsubadd`` (found in the 3-PRR point and the 4-RRR
#:     design libraries), and whether it does depends on the code around it, so the results of
#:     one function changed in the last bit with the translation unit it was compiled in.
#:     Without FMA the compiler cannot fuse, and the results are those of the C text, however
#:     it is cut (and the same as :data:`PORTABLE_FLAGS`', which never had FMA).
#:
#: ``-ffast-math`` is deliberately absent: it lets the compiler assume there are no
#: NaNs or infinities (breaking ``isfinite`` checks) and reassociate arithmetic
#: (breaking agreement with CasADi's reference evaluation).
_X86 = platform.machine().lower() in ("x86_64", "amd64", "i386", "i686")

FLAGS: tuple[str, ...] = (
    "-O3",
    "-march=native",
    "-ffp-contract=off",
    "-fPIC",
    "-shared",
    "-fno-math-errno",
    "-fno-semantic-interposition",
    "-DPM2DOF_INLINE_FMINMAX",
    *(("-mno-fma",) if _X86 else ()),
)

#: :data:`FLAGS` without ``-march=native``: for libraries that travel to other machines (the
#: shipped models' libraries inside a wheel). Results are the same bit for bit: without
#: ``-ffast-math`` and with ``-ffp-contract=off`` the compiler may not reorder or fuse
#: floating-point operations, whichever instructions it picks.
PORTABLE_FLAGS: tuple[str, ...] = tuple(f for f in FLAGS if f != "-march=native")

#: Added to the flags of every translation unit of a CasADi file cut by
#: :mod:`pm2dof.core.csplit`: ``-fvisibility=hidden`` keeps the functions the units share
#: (``casadi_fN``) inside the library; ``-DGCC_HASCLASSVISIBILITY`` makes CasADi's
#: ``CASADI_SYMBOL_EXPORT`` mark its entry points visible, so they are the library's only
#: exported symbols; ``-pipe``: no temporary assembler files.
SPLIT_FLAGS: tuple[str, ...] = ("-fvisibility=hidden", "-DGCC_HASCLASSVISIBILITY", "-pipe")

#: Processor seconds per megabyte (1e6 bytes) of generated C that :func:`compile_library`'s
#: gcc 12 ``-O3 -march=native`` took on the shipped models, one processor each (user time):
#: fivebar 0.63 MB 10.2 s, shang2010 0.88 MB 14.5 s, prr3_platform 1.51 MB 21.6 s,
#: rrr4_platform 2.16 MB 33.8 s (14-16 s per MB). The wall time is that on an idle processor,
#: several times more while other programs use it (the same rrr4_platform: 89 s beside three
#: other compilers on two processors).
COMPILE_SECONDS_PER_MB = 16.0

#: Libraries linked after the source file: the generated code calls libm.
LIBS: tuple[str, ...] = ("-lm",)

#: Environment variable: how many compilers run at once (default: the processors this process
#: may use, :func:`build_jobs`).
JOBS_ENV = "PM2DOF_BUILD_JOBS"


def build_jobs() -> int:
    """How many compilers run at once: ``$PM2DOF_BUILD_JOBS`` if set to a positive integer, else
    the processors this process may run on."""
    try:
        jobs = int(os.environ.get(JOBS_ENV, ""))
    except ValueError:
        jobs = 0
    if jobs > 0:
        return jobs
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def _csplit():
    """pm2dof.core.csplit, also when this module was loaded as a file (setup.py, make libs)."""
    try:
        from . import csplit
    except ImportError:
        import importlib.util
        import sys
        name = "_pm2dof_csplit"
        if name not in sys.modules:
            spec = importlib.util.spec_from_file_location(
                name, pathlib.Path(__file__).with_name("csplit.py"))
            mod = importlib.util.module_from_spec(spec)
            sys.modules[name] = mod
            spec.loader.exec_module(mod)
        csplit = sys.modules[name]
    return csplit


try:
    from .errors import Pm2dofError
except ImportError:       # loaded as a file by setup.py, outside the package: a stand-in base
    class Pm2dofError(Exception):
        """Stand-in for pm2dof.core.errors.Pm2dofError when built without the package."""


class BuildError(Pm2dofError, RuntimeError):
    """The C compiler failed or is missing; the message holds the command and its stderr, or
    what to install."""


#: What to install when there is no C compiler (the message of :class:`BuildError`).
NO_COMPILER = ("no C compiler found: pm2dof compiles a model's generated C once, on first use. "
               "Install one (Debian/Ubuntu: `sudo apt install gcc`; Fedora: `sudo dnf install "
               "gcc`; macOS: `xcode-select --install`) or name it in the CC environment "
               "variable. The shipped models need none: their libraries come with the wheel")


def stamp_path(lib_path):
    """The build record written next to a compiled library: ``lib<name>.so.json``."""
    lib_path = pathlib.Path(lib_path)
    return lib_path.with_name(lib_path.name + ".json")


def _sha256(path):
    import hashlib
    return hashlib.sha256(pathlib.Path(path).read_bytes()).hexdigest()


def library_is_fresh(c_path, lib_path, c_sha256=None):
    """Whether ``lib_path`` was compiled from the current content of ``c_path``, with this
    version's flags.

    The build record (:func:`stamp_path`) holds the SHA-256 of the source it was built from
    and the compiler flags. The flags must include every one of :data:`PORTABLE_FLAGS` (what
    :data:`FLAGS` and a wheel's build share): a library compiled before a flag that decides
    its results was added (``-mno-fma``: GCC had fused multiply-adds into some functions) is
    compiled again, as is one whose record names no flags.
    Fast path: the record matches ``c_sha256`` (the manifest's hash of the C file) and the
    library is not older than the source. Otherwise the source is hashed (file times are not
    kept by every installer, so an older-looking library may still be right).
    """
    import json
    lib_path, c_path = pathlib.Path(lib_path), pathlib.Path(c_path)
    try:
        record = json.loads(stamp_path(lib_path).read_text())
        built_from, flags = record["source_sha256"], record["flags"]
        lib_mtime = lib_path.stat().st_mtime
    except (OSError, ValueError, KeyError, TypeError):
        return False
    if not isinstance(flags, list) or not set(PORTABLE_FLAGS) <= set(flags):
        return False
    if built_from == c_sha256 and lib_mtime >= c_path.stat().st_mtime:
        return True
    return built_from == _sha256(c_path)


def compile_estimate(c_path) -> float:
    """Seconds :func:`compile_library` will take for ``c_path`` on an idle processor, from the
    file's size (:data:`COMPILE_SECONDS_PER_MB`); a rough figure (another compiler, another
    processor, a busy machine: more or less)."""
    return pathlib.Path(c_path).stat().st_size / 1e6 * COMPILE_SECONDS_PER_MB


def _compiler() -> list[str]:
    """Return the C compiler command as an argument list.

    Returns
    -------
    list of str
        ``$CC`` if set and non-empty, else Python's configured ``CC``
        (``sysconfig.get_config_var("CC")``), else ``cc``; split with
        :func:`shlex.split` so values such as ``"gcc -pthread"`` work.
    """
    cc = os.environ.get("CC") or sysconfig.get_config_var("CC") or "cc"
    return shlex.split(cc) or ["cc"]


def compile_library(
    c_path: str | os.PathLike[str],
    out_path: str | os.PathLike[str],
    *,
    extra_flags: Iterable[str] = (),
    portable: bool = False,
    progress=None,
    jobs: int | None = None,
) -> pathlib.Path:
    """Compile one C file into a shared library, atomically replacing ``out_path``.

    Parameters
    ----------
    c_path : str or os.PathLike
        The C source, typically written by ``casadi.CodeGenerator``.
    out_path : str or os.PathLike
        Where the shared library goes (e.g. ``.../model.so``). Its directory is
        created if needed.
    extra_flags : iterable of str, optional
        Further compiler arguments, placed after :data:`FLAGS`.
    portable : bool, optional
        Use :data:`PORTABLE_FLAGS` (no ``-march=native``): for a library built into a wheel.
    progress : callable(str), optional
        Receives a line before the compiler starts (the C file's size and
        :func:`compile_estimate`) and one when it is done (the elapsed time).
    jobs : int, optional
        Compilers run at once on a CasADi file's units; default :func:`build_jobs`.

    Returns
    -------
    pathlib.Path
        The absolute path of the library, suitable for
        :class:`pm2dof.core._cbind.Library`.

    Raises
    ------
    FileNotFoundError
        If ``c_path`` does not exist.
    BuildError
        If there is no compiler (the message says what to install), or it exits with a
        non-zero status (the message contains the full command line and its stderr).

    Notes
    -----
    The compiler is ``$CC``, else ``sysconfig.get_config_var("CC")``, else ``cc``.
    A C file that is not laid out as CasADi writes it is compiled whole:
    ``CC FLAGS extra_flags -o TMP c_path -lm``. A CasADi file is cut into translation units
    (:func:`pm2dof.core.csplit.plan_units`), each compiled with ``CC FLAGS SPLIT_FLAGS
    extra_flags -c`` (the unit's level in place of ``-O3``), ``jobs`` at a time, costliest first,
    then linked into ``TMP``. ``TMP`` is a fresh file in the directory of ``out_path`` that is
    then renamed onto ``out_path`` with :func:`os.replace` (atomic on POSIX), so a concurrently
    running process sees either the old or the new library, never a partial one.

    A process that already has ``out_path`` open through ``dlopen`` keeps the old
    code: ``dlopen`` hands back the loaded library for a path that is still open.

    After the library, a build record :func:`stamp_path` is written (source hash, flags), which
    :func:`library_is_fresh` reads.
    """
    return compile_libraries([(c_path, out_path)], extra_flags=extra_flags, portable=portable,
                             progress=progress, jobs=jobs)[0]


def compile_libraries(pairs, *, extra_flags: Iterable[str] = (), portable: bool = False,
                      progress=None, jobs: int | None = None) -> list[pathlib.Path]:
    """Compile several C files into their libraries on one pool of ``jobs`` compilers.

    Every library's translation units (see :func:`compile_library`) are queued together,
    largest first, so the processors stay busy until the last library is linked.

    Parameters
    ----------
    pairs : iterable of (path, path)
        ``(c_path, out_path)`` of each library.
    extra_flags, portable, progress, jobs
        As in :func:`compile_library`; ``progress`` receives the lines of every library.

    Returns
    -------
    list of pathlib.Path
        The absolute path of each library, in the order of ``pairs``.

    Raises
    ------
    FileNotFoundError
        If a C file does not exist (before anything is compiled).
    BuildError
        The first failure (the other libraries' builds are stopped); no library of a failed
        build is replaced.
    """
    extra = [str(f) for f in extra_flags]
    builds = [_Build(c, o, extra, portable, progress) for c, o in pairs]
    jobs = build_jobs() if jobs is None else max(1, int(jobs))
    failed = threading.Event()

    def run(task):
        b, u = task
        if not failed.is_set():
            try:
                b.compile_unit(u)
            except BaseException:
                failed.set()
                raise
    try:
        for b in builds:
            b.start()
        for b in builds:
            b.say_start(jobs)
        # costliest first over every library: the processors stay busy until the last link
        tasks = sorted(((b, u) for b in builds for u in range(len(b.units))),
                       key=lambda bu: -bu[0].units[bu[1]][0])
        if len(tasks) <= 1 or jobs == 1:
            for task in tasks:
                run(task)
        else:
            with ThreadPoolExecutor(max_workers=min(jobs, len(tasks))) as pool:
                futures = [pool.submit(run, task) for task in tasks]
                for fut in futures:
                    fut.result()
        return [b.finish() for b in builds]
    finally:
        for b in builds:
            b.cleanup()


class _Build:
    """One library being built: its units' commands, temporary files, the link, the record."""

    def __init__(self, c_path, out_path, extra, portable, progress):
        self.c_path = pathlib.Path(c_path)
        self.out_path = pathlib.Path(out_path).absolute()
        if not self.c_path.is_file():
            raise FileNotFoundError(f"C source not found: {self.c_path}")
        self.progress, self.cc = progress, _compiler()
        self.flags = [*(PORTABLE_FLAGS if portable else FLAGS), *extra]
        self.tmp = self.objdir = None
        text = self.c_path.read_text(errors="replace")
        csplit = _csplit()
        split = csplit.split_casadi_c(text, str(self.c_path))
        self.units = []                           # (cost, flags, C text or None)
        if split is None:                         # not CasADi's layout: one command, as is
            self.units.append((len(text), self.flags, None))
            self.link_flags = None
            return
        self._plan = (csplit, split, csplit.opt_levels(split))
        self.link_flags = ["-shared", *extra]

    def unit_flags(self, opt):
        """The flags of a unit compiled at ``opt`` (``("-O2",)``, ...): :attr:`flags` with
        ``opt`` in place of the first (``-O3``; ``extra_flags`` come later, so they still win),
        without ``-shared``, with :data:`SPLIT_FLAGS`."""
        return [*opt, *(f for f in self.flags[1:] if f != "-shared"), *SPLIT_FLAGS]

    def start(self):
        """Plan the units, make the temporaries, say what starts."""
        self.out_path.parent.mkdir(parents=True, exist_ok=True)
        remove_stale_temporaries(self.out_path)
        if self.link_flags is not None:
            csplit, split, levels = self._plan
            plan = csplit.plan_units(split, levels)
            # (cost, flags, C text): the first unit holds the configuration entry points
            self.units = [(cost, self.unit_flags(opt), split.unit(blocks, first=i == 0))
                          for i, (opt, blocks, cost) in enumerate(plan)]
            self.levels = {opt: sum(o == opt for o, _, _ in plan) for opt, _, _ in plan}
            self.objdir = pathlib.Path(tempfile.mkdtemp(prefix="pm2dof-build-"))
        fd, tmp_name = tempfile.mkstemp(prefix=f".{self.out_path.name}.", suffix=".tmp",
                                        dir=self.out_path.parent)
        os.close(fd)
        self.tmp = pathlib.Path(tmp_name)
        self.t0 = time.monotonic()

    def say_start(self, jobs):
        """The progress line before the compilers start."""
        if self.progress is None:
            return
        size, est = self.c_path.stat().st_size, compile_estimate(self.c_path)
        if self.link_flags is None:
            how, when = "", f"about {est:.0f} s on an idle processor"
        else:
            k = min(jobs, len(self.units))
            levels = ", ".join(f"{n} at {opt[0]}" for opt, n in sorted(self.levels.items(),
                                                                       reverse=True))
            how = f" in {len(self.units)} units ({levels}), {k} at a time"
            when = (f"about {est:.0f} s of processor time, {est / k:.0f} s on {k} idle "
                    f"processor{'s' if k > 1 else ''}")
        self.progress(f"compiling {self.c_path.name} ({size / 1e6:.1f} MB of C) with "
                      f"{self.cc[0]} {self.flags[0]}{how}: {when} "
                      f"({COMPILE_SECONDS_PER_MB:.0f} s per MB), longer while other "
                      f"programs use it")
        self.t0 = time.monotonic()

    def _obj(self, u):
        return self.objdir / f"unit{u}.o"

    def compile_unit(self, u):
        """Compile unit ``u`` (the whole library when the file is not cut)."""
        _, flags, text = self.units[u]
        if text is None:
            _run([*self.cc, *flags, "-o", str(self.tmp), str(self.c_path), *LIBS])
        else:
            _run([*self.cc, *flags, "-c", "-x", "c", "-o", str(self._obj(u)), "-"], text)

    def finish(self):
        """Link the units (when cut), put the library in place, write its record."""
        if self.link_flags is not None:
            _run([*self.cc, *self.link_flags, "-o", str(self.tmp),
                  *(str(self._obj(u)) for u in range(len(self.units))), *LIBS])
        # mkstemp creates the file with mode 0600; a library is normally 0755.
        os.chmod(self.tmp, 0o755)
        os.replace(self.tmp, self.out_path)
        extra = None
        if self.link_flags is not None:
            extra = {"split_flags": list(SPLIT_FLAGS), "units": len(self.units),
                     "unit_levels": {" ".join(opt): n for opt, n in sorted(self.levels.items())}}
        _write_stamp(self.out_path, self.c_path, self.cc[0], self.flags, extra)
        if self.progress is not None:
            self.progress(f"compiled {self.out_path} in {time.monotonic() - self.t0:.1f} s")
        return self.out_path

    def cleanup(self):
        """Remove what a failed or finished build leaves: the temporary library, the objects."""
        if self.tmp is not None and self.tmp.exists():
            self.tmp.unlink()
        if self.objdir is not None:
            import shutil
            shutil.rmtree(self.objdir, ignore_errors=True)


def _run(cmd, stdin=None):
    """Run one compiler command; :class:`BuildError` with the command and its stderr."""
    try:
        proc = subprocess.run(cmd, input=stdin, capture_output=True, text=True, check=False)
    except FileNotFoundError:
        raise BuildError(f"{NO_COMPILER}\ncommand: {shlex.join(cmd)}") from None
    except OSError as exc:
        raise BuildError(f"cannot run the C compiler: {exc}\ncommand: {shlex.join(cmd)}") from exc
    if proc.returncode != 0:
        raise BuildError(
            f"C compiler failed with exit status {proc.returncode}\n"
            f"command: {shlex.join(cmd)}\n"
            f"stderr:\n{proc.stderr.strip()}"
        )


def _write_stamp(lib_path, c_path, compiler, flags, extra=None):
    """The build record, written atomically after the library (``extra``: more keys)."""
    import json
    record = {"source": c_path.name, "source_sha256": _sha256(c_path), "flags": flags,
              "compiler": compiler, **(extra or {})}
    stamp = stamp_path(lib_path)
    fd, tmp = tempfile.mkstemp(prefix=f".{stamp.name}.", suffix=".tmp", dir=stamp.parent)
    with os.fdopen(fd, "w") as fh:
        fh.write(json.dumps(record, indent=1, sort_keys=True) + "\n")
    os.chmod(tmp, 0o644)
    os.replace(tmp, stamp)


def remove_stale_temporaries(out_path, max_age_s=STALE_TMP_AGE_S):
    """Delete ``.<library name>.*.tmp`` files next to ``out_path`` older than ``max_age_s``:
    what a build killed between compiling and renaming leaves behind. Returns their paths."""
    out_path = pathlib.Path(out_path)
    now, removed = time.time(), []
    for tmp in out_path.parent.glob(f".{out_path.name}.*.tmp"):
        try:
            if now - tmp.stat().st_mtime > max_age_s:
                tmp.unlink()
                removed.append(tmp)
        except FileNotFoundError:  # removed by a concurrent build meanwhile
            pass
    return removed


def _main(argv=None):
    """``python pm2dof/core/build.py SOURCE.c OUT.so``: the Makefile's rule of each library
    (``make libs``), not a user's entry point (that is ``pm2dof``): compile ``SOURCE.c`` into
    ``OUT.so`` unless the library was built from that C (:func:`library_is_fresh`: then only
    its time is renewed, so that make sees it newer than the C file). It runs as a file,
    before the package may import (standard library only, as setup.py loads this module);
    returns the exit status: 0, 1 (the compiler failed, or no source), 2 (usage)."""
    import sys
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 2:
        print("usage: python pm2dof/core/build.py SOURCE.c OUT.so", file=sys.stderr)
        return 2
    if library_is_fresh(args[0], args[1]):     # a touched but unchanged C file: nothing to do
        os.utime(args[1])                       # (newer than the C file again, for make)
        print(f"{args[1]} is up to date with {args[0]}", flush=True)
        return 0
    try:
        compile_library(args[0], args[1], progress=lambda msg: print(msg, flush=True))
    except (BuildError, FileNotFoundError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(_main())
