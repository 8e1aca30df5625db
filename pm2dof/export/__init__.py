# Layer beside bench: a model's controllers exported as a standalone C99 project.
"""``pm2dof export``: the controllers as a C library for a robot's firmware or real-time loop.

* :mod:`.project` -- :func:`export_project`: the project (generated C copied, API, CMake,
  example, ctest, ``embedded/``);
* :mod:`.prune` -- the generated C pruned to what the API calls, every function static;
* :mod:`.names` -- the library's link names, distinct in their first 31 characters;
* :mod:`.stack` -- each function's worst-case stack from GCC's call graph;
* :mod:`.checks` -- the API's parameter checks and status strings, written from
  :mod:`pm2dof.control.rules` and :class:`pm2dof.Status`;
* :mod:`.single` -- the generated C rewritten for ``float``, and where float is refused;
* :mod:`.reference` -- pm2dof's closed loops as C data, what the exported test compares with;
* :mod:`.embedded` -- ``make embedded``: cross-compile for Cortex-M4F and M7, run under QEMU.

Imports :mod:`pm2dof.core` and :mod:`pm2dof.control` only: no SymPy, no CasADi (the generated
C is copied, not re-derived), so it works from an installed wheel without the derive extra.
"""
from .project import LAWS, PRECISIONS, ExportError, export_project

__all__ = ["export_project", "ExportError", "LAWS", "PRECISIONS"]
