# The machine a benchmark ran on: CPU, cores, compiler, flags, Python and NumPy versions.
import os
import platform
import subprocess
import sys
from pathlib import Path

import numpy as np

__all__ = ["machine"]


def machine():
    from ..core.build import FLAGS, LIBS, _compiler
    cpu = None
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    cc = _compiler()
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
            "compiler_flags": " ".join((*FLAGS, *LIBS))}
