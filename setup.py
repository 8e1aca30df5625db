"""Build the pm2dof.core._cbind C extension (project metadata lives in pyproject.toml)."""

from setuptools import Extension, setup

setup(
    ext_modules=[
        Extension("pm2dof.core._cbind", ["pm2dof/core/_cbind.c"], extra_compile_args=["-O2"]),
    ],
)
