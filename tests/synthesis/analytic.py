# Stand-ins for the design studies' inputs: an analytic two-objective problem and a study record.
"""What the synthesis machinery is tested with, independently of the real objectives.

* :func:`zdt` -- ZDT1 in two variables on [0, 1]^2 (Zitzler, Deb & Thiele 2000): f1 = x1,
  g = 1 + 9 x2, f2 = g (1 - sqrt(f1 / g)), both minimised; the Pareto-optimal designs are
  x2 = 0, where f2 = 1 - sqrt(f1) (a convex front). With ``constrained``, x1 + x2 >= 0.3 (the
  unconstrained front below x1 = 0.3 becomes infeasible).
* :func:`evaluate_batch` -- the signature of ``pm2dof.synthesis.objectives.evaluate_batch``
  (``(study, X) -> (F, G, rows)``) on :func:`zdt`, with the second objective reported as a
  maximised ``-f2`` so that the sign convention is exercised; importable by Dask workers.
* :func:`study` -- a record with the fields of ``pm2dof.synthesis.spec.DesignStudy`` that the
  runner reads.
"""
import hashlib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from pm2dof.core.paths import SHIPPED_MODELS

#: the seconds each design takes in :func:`evaluate_batch` (raised by the kill test)
DELAY_ENV = "PM2DOF_TEST_DESIGN_DELAY"


def zdt(X, constrained=False):
    """(F (N, 2) minimised, G (N, 0 or 1) feasible <= 0) of ZDT1 in two variables."""
    X = np.asarray(X, dtype=float)
    f1 = X[:, 0]
    g = 1.0 + 9.0 * X[:, 1]
    f2 = g * (1.0 - np.sqrt(f1 / g))
    G = (0.3 - X[:, 0] - X[:, 1])[:, None] if constrained else np.zeros((len(X), 0))
    return np.column_stack([f1, f2]), G


@dataclass(frozen=True)
class Objective:
    name: str
    measure: str
    sense: str
    options: dict = field(default_factory=dict)
    limit: float | None = None
    op: str = ""


@dataclass(frozen=True)
class Study:
    name: str
    path: str
    model_path: str
    variables: tuple
    bounds: tuple
    region: dict
    paths: tuple
    objectives: tuple
    constraints: tuple
    optimizer: dict
    quick: dict
    file_sha256: str


def study(optimizer=None, constrained=False, variables=("la", "lb"), name="analytic",
          bounds=None):
    """A stand-in design study on the paper's robot with la and lb as design variables (its
    model file: the shipped shang2010_design)."""
    opt = {"kind": "nsga2", "population": 20, "generations": 6, "grid": 10, "seed": 7}
    opt.update(optimizer or {})
    cons = (Objective("reach", "margin", "", {}, 0.3, "ge"),) if constrained else ()
    bounds = tuple(map(tuple, bounds)) if bounds else ((0.0, 1.0),) * len(variables)
    text = f"{name} {sorted(opt.items())} {constrained} {variables} {bounds}"
    return Study(name=name, path=f"/nowhere/{name}.toml",
                 model_path=str(SHIPPED_MODELS / "shang2010_design.toml"), variables=tuple(variables),
                 bounds=bounds,
                 region={"x": (0.2, 0.3), "y": (0.2, 0.3), "phi": None, "n": 5}, paths=(),
                 objectives=(Objective("f1", "analytic", "min"),
                             Objective("score", "analytic", "max")),
                 constraints=cons, optimizer=opt, quick={"generations": 3, "grid": 5},
                 file_sha256=hashlib.sha256(text.encode()).hexdigest())


def evaluate_batch(study, X):
    """``objectives.evaluate_batch``'s contract on :func:`zdt` of the designs scaled to the unit
    square by the study's bounds: ``score = -f2`` is maximised, so ``F = [f1, -score]``; the
    constraint ``reach = u1 + u2 >= 0.3``."""
    import os
    import time
    delay = float(os.environ.get(DELAY_ENV, "0"))
    if delay:
        time.sleep(delay * len(X))
    X = np.asarray(X, dtype=float)
    lo, hi = np.array(study.bounds, dtype=float).T
    U = (X - lo) / (hi - lo)                    # ZDT1 on the unit square
    F, G = zdt(U, constrained=bool(study.constraints))
    rows = []
    for x, u, f in zip(X, U, F):
        row = dict(zip(study.variables, map(float, x)))
        row.update(f1=float(f[0]), score=float(-f[1]), status="ok")
        if study.constraints:
            row["reach"] = float(u[0] + u[1])
        rows.append(row)
    return F, G, rows


def model_file(tmp_path):
    """A copy of the paper's model file with a [design] table: la, lb tied over the legs, b2x
    (as the issue writes it), and comments to keep."""
    text = (SHIPPED_MODELS / "shang2010.toml").read_text()
    design = ('\n# The design variables (searched by the study)\n[design]\n'
              'la = { keys = ["legs.1.la", "legs.2.la", "legs.3.la"], bounds = [0.18, 0.32] }\n'
              'lb = { keys = ["legs.1.lb", "legs.2.lb", "legs.3.lb"], bounds = [0.18, 0.32] }\n'
              'b2x = { keys = ["legs.2.base.x"], bounds = [0.35, 0.50] }\n')
    marker = "# Tables 1-2"
    assert marker in text
    p = Path(tmp_path) / "robot.toml"
    p.write_text(text.replace(marker, design.lstrip("\n") + "\n" + marker, 1))
    return p
