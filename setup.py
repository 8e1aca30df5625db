"""Build the pm2dof.core._cbind C extension and the shipped models' libraries (project metadata
lives in pyproject.toml).

The shipped models' generated C (pm2dof/generated/<name>/<name>.c) is compiled into
lib<name>.so beside it, so a wheel needs no compiler at install time (all of them on one pool
of compilers, one per processor: pm2dof.core.build.compile_libraries). In a wheel the
libraries use portable flags (no -march=native); in an editable install they are built in place
for this machine.

$PM2DOF_BUILD_MODELS (an editable install only) names the models compiled here, comma-separated,
or "none": the Makefile installs with "none" and compiles the libraries a target needs with its
own rules, on every processor at once (`make -j`); a library not compiled is compiled by
`load_model` on its first use.
"""
import importlib.util
import os
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = Path(__file__).resolve().parent


def _build_module():
    """pm2dof/core/build.py (standard library only), without importing the pm2dof package."""
    spec = importlib.util.spec_from_file_location("_pm2dof_build", HERE / "pm2dof/core/build.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


class BuildExtWithModels(build_ext):
    """build_ext, then compile every shipped model's generated C into its library."""

    def run(self):
        super().run()
        build = _build_module()
        only = os.environ.get("PM2DOF_BUILD_MODELS", "").strip() if self.inplace else ""
        names = None if not only else set() if only == "none" else set(only.split(","))
        pairs = []
        for c_file in sorted((HERE / "pm2dof" / "generated").glob("*/*.c")):
            rel = c_file.relative_to(HERE).parent / f"lib{c_file.stem}.so"
            target = HERE / rel if self.inplace else Path(self.build_lib) / rel
            if names is not None and c_file.stem not in names:
                continue
            if self.inplace and build.library_is_fresh(c_file, target):
                continue
            pairs.append((c_file, target))
        # every library's translation units on one pool of compilers, one per processor
        # ($PM2DOF_BUILD_JOBS), so that no processor waits for the last unit of a library
        build.compile_libraries(pairs, portable=not self.inplace,
                                progress=lambda msg: print(msg, flush=True))


setup(
    ext_modules=[
        Extension("pm2dof.core._cbind", ["pm2dof/core/_cbind.c"], extra_compile_args=["-O2"],
                  depends=["pm2dof/core/_cbind_api.h"]),
        # the planner's passes on one grid, calling the generated C through _cbind's C API
        Extension("pm2dof.planning._passes", ["pm2dof/planning/_passes.c"],
                  extra_compile_args=["-O2"],
                  depends=["pm2dof/core/_cbind_api.h", "pm2dof/planning/_buffers.h"]),
        # the NumPy formulas of TaskPath.evaluate bit for bit: no fused multiply-adds
        Extension("pm2dof.planning._pathc", ["pm2dof/planning/_pathc.c"],
                  extra_compile_args=["-O2", "-ffp-contract=off"],
                  depends=["pm2dof/planning/_buffers.h"]),
    ],
    cmdclass={"build_ext": BuildExtWithModels},
)
