# The machine a benchmark ran on: CPU, cores, compiler, flags, Python and NumPy versions.
import os
import platform
import subprocess
import sys
from pathlib import Path

import numpy as np

__all__ = ["machine"]


def build_record(library):
    """The compiler and flags ``library`` was built with, from its build record
    (``lib<name>.so.json``, :func:`pm2dof.core.build.stamp_path`): (compiler, flags, where
    they come from); (None, None, why) without a readable record."""
    import json

    from ..core.build import stamp_path
    path = stamp_path(library)
    try:
        rec = json.loads(Path(path).read_text())
        return rec["compiler"], list(rec["flags"]), f"the build record {path}"
    except (OSError, ValueError, KeyError, TypeError) as exc:
        return None, None, f"no readable build record {path}: {exc}"


def machine(library=None):
    """The machine, and the compiler and flags of ``library`` (a model's compiled C) as its
    build record says (what the library was built with, not what this pm2dof would use)."""
    from ..core.build import FLAGS, LIBS, _compiler
    cpu = None
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    cc, flags, source = _compiler(), [*FLAGS, *LIBS], "this pm2dof's default, no library given"
    if library is not None:
        rec_cc, rec_flags, source = build_record(library)
        cc, flags = ([rec_cc], [*rec_flags, *LIBS]) if rec_flags is not None else (cc, None)
    try:
        cc_version = subprocess.run([*cc, "--version"], capture_output=True, text=True,
                                    timeout=10).stdout.splitlines()[0]
    except (OSError, IndexError, subprocess.SubprocessError):
        cc_version = None
    try:
        affinity = len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        affinity = None
    return {"cpu": cpu or platform.processor() or None, "cores": os.cpu_count(),
            "cores_available": affinity, "platform": platform.platform(),
            "python": sys.version.split()[0], "numpy": np.__version__,
            "compiler": " ".join(cc), "compiler_version": cc_version,
            "compiler_flags": " ".join(flags) if flags is not None else "unknown",
            "compiler_flags_source": source}
