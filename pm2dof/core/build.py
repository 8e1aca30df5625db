# pm2dof.core.build: compile one CasADi-generated C file into a shared library for pm2dof.core._cbind.
"""Compile a CasADi-generated C file into a shared library.

The library is meant to be loaded with :class:`pm2dof.core._cbind.Library`. Compilation
writes to a temporary file next to the target and renames it into place, so a
process that loads the target path never sees a half-written library.
"""

from __future__ import annotations

import os
import pathlib
import shlex
import subprocess
import sysconfig
import tempfile
import time
from collections.abc import Iterable

__all__ = ["compile_library", "library_is_fresh", "BuildError", "STALE_TMP_AGE_S", "FLAGS",
           "PORTABLE_FLAGS", "COMPILE_SECONDS_PER_MB", "compile_estimate"]

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
#: ``-ffast-math`` is deliberately absent: it lets the compiler assume there are no
#: NaNs or infinities (breaking ``isfinite`` checks) and reassociate arithmetic
#: (breaking agreement with CasADi's reference evaluation).
FLAGS: tuple[str, ...] = (
    "-O3",
    "-march=native",
    "-ffp-contract=off",
    "-fPIC",
    "-shared",
    "-fno-math-errno",
    "-fno-semantic-interposition",
)

#: :data:`FLAGS` without ``-march=native``: for libraries that travel to other machines (the
#: shipped models' libraries inside a wheel). Results are the same bit for bit: without
#: ``-ffast-math`` and with ``-ffp-contract=off`` the compiler may not reorder or fuse
#: floating-point operations, whichever instructions it picks.
PORTABLE_FLAGS: tuple[str, ...] = tuple(f for f in FLAGS if f != "-march=native")

#: Processor seconds per megabyte (1e6 bytes) of generated C that :func:`compile_library`'s
#: gcc 12 ``-O3 -march=native`` took on the shipped models, one processor each (user time):
#: fivebar 0.63 MB 10.2 s, shang2010 0.88 MB 14.5 s, prr3_platform 1.51 MB 21.6 s,
#: rrr4_platform 2.16 MB 33.8 s (14-16 s per MB). The wall time is that on an idle processor,
#: several times more while other programs use it (the same rrr4_platform: 89 s beside three
#: other compilers on two processors).
COMPILE_SECONDS_PER_MB = 16.0

#: Libraries linked after the source file: the generated code calls libm.
LIBS: tuple[str, ...] = ("-lm",)


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
    """Whether ``lib_path`` was compiled from the current content of ``c_path``.

    The build record (:func:`stamp_path`) holds the SHA-256 of the source it was built from.
    Fast path: the record matches ``c_sha256`` (the manifest's hash of the C file) and the
    library is not older than the source. Otherwise the source is hashed (file times are not
    kept by every installer, so an older-looking library may still be right).
    """
    import json
    lib_path, c_path = pathlib.Path(lib_path), pathlib.Path(c_path)
    try:
        built_from = json.loads(stamp_path(lib_path).read_text())["source_sha256"]
        lib_mtime = lib_path.stat().st_mtime
    except (OSError, ValueError, KeyError, TypeError):
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
    The command is ``CC FLAGS extra_flags -o TMP c_path -lm``, where ``TMP`` is a
    fresh file in the directory of ``out_path`` that is then renamed onto
    ``out_path`` with :func:`os.replace` (atomic on POSIX), so a concurrently
    running process sees either the old or the new library, never a partial one.

    A process that already has ``out_path`` open through ``dlopen`` keeps the old
    code: ``dlopen`` hands back the loaded library for a path that is still open.

    After the library, a build record :func:`stamp_path` is written (source hash, flags), which
    :func:`library_is_fresh` reads.
    """
    c_path = pathlib.Path(c_path)
    out_path = pathlib.Path(out_path).absolute()
    if not c_path.is_file():
        raise FileNotFoundError(f"C source not found: {c_path}")
    out_path.parent.mkdir(parents=True, exist_ok=True)
    remove_stale_temporaries(out_path)

    fd, tmp_name = tempfile.mkstemp(
        prefix=f".{out_path.name}.", suffix=".tmp", dir=out_path.parent
    )
    os.close(fd)
    tmp = pathlib.Path(tmp_name)
    flags = [*(PORTABLE_FLAGS if portable else FLAGS), *[str(f) for f in extra_flags]]
    cmd = [
        *_compiler(),
        *flags,
        "-o",
        str(tmp),
        str(c_path),
        *LIBS,
    ]
    if progress is not None:
        size = c_path.stat().st_size
        progress(f"compiling {c_path.name} ({size / 1e6:.1f} MB of C) with {cmd[0]} "
                 f"{flags[0]}: about {compile_estimate(c_path):.0f} s on an idle processor "
                 f"({COMPILE_SECONDS_PER_MB:.0f} s per MB), longer while other programs use it")
    t0 = time.monotonic()
    try:
        try:
            proc = subprocess.run(cmd, capture_output=True, text=True, check=False)
        except FileNotFoundError:
            raise BuildError(f"{NO_COMPILER}\ncommand: {shlex.join(cmd)}") from None
        except OSError as exc:
            raise BuildError(
                f"cannot run the C compiler: {exc}\ncommand: {shlex.join(cmd)}"
            ) from exc
        if proc.returncode != 0:
            raise BuildError(
                f"C compiler failed with exit status {proc.returncode}\n"
                f"command: {shlex.join(cmd)}\n"
                f"stderr:\n{proc.stderr.strip()}"
            )
        # mkstemp creates the file with mode 0600; a library is normally 0755.
        os.chmod(tmp, 0o755)
        os.replace(tmp, out_path)
    finally:
        if tmp.exists():
            tmp.unlink()
    _write_stamp(out_path, c_path, cmd[0], flags)
    if progress is not None:
        progress(f"compiled {out_path} in {time.monotonic() - t0:.1f} s")
    return out_path


def _write_stamp(lib_path, c_path, compiler, flags):
    """The build record, written atomically after the library."""
    import json
    record = {"source": c_path.name, "source_sha256": _sha256(c_path), "flags": flags,
              "compiler": compiler}
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
