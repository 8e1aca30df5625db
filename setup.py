"""Build the pm2dof._cbind C extension (project metadata lives in pyproject.toml)."""

from setuptools import Extension, setup

setup(
    ext_modules=[
        Extension("pm2dof._cbind", ["pm2dof/_cbind.c"], extra_compile_args=["-O2"]),
    ],
)
