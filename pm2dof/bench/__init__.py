# The benchmark (`pm2dof bench`): the generated step and rollout against the real-time budget.
"""Benchmark of the generated controller step and closed-loop rollout, split by job.

* :mod:`.run` -- :func:`run_bench`, the measurements and the targets;
* :mod:`.timing` -- the timing harness (calibrated batches, medians);
* :mod:`.baselines` -- the NumPy reference and SymPy-lambdify steps, the workloads;
* :mod:`.opcount` -- static operation counts read from the generated C;
* :mod:`.machine` -- what machine and compiler the numbers come from;
* :mod:`.report` -- :func:`format_bench`, the text table.

A development tool, above the runtime: it may import CasADi, SymPy and the build-time
``derive`` package (each optional; where one is missing the result says why).
"""
from .opcount import OPS_FUNCTIONS, count_ops
from .report import format_bench
from .run import REQUIRED_KEYS, TARGETS, run_bench

__all__ = ["run_bench", "format_bench", "TARGETS", "REQUIRED_KEYS", "count_ops", "OPS_FUNCTIONS"]
