"""pm2dof.bench.overheads: every per-sample Model method is timed beside its C, and each has
its target (the energies are reported without one). No timing thresholds: the numbers of a
tiny run are noise; what is checked is that every method runs, has its keys and its row."""
import math

import numpy as np
import pytest

from pm2dof import Model, bench, load_model
from pm2dof.bench.overheads import OVERHEAD_METHODS, UNTARGETED, _arguments, overhead_bench
from pm2dof.bench.report import _overhead_rows
from pm2dof.bench.run import check_targets
from pm2dof.control.trajectory import model_move
from pm2dof.core import _cbind


@pytest.fixture(scope="module")
def model():
    return load_model()


def test_every_timed_method_is_a_fast_method_and_its_arguments_fit(model):
    traj = model_move(model, "high")
    vals = _arguments(model, traj)
    for name, names in OVERHEAD_METHODS:
        assert type(getattr(Model, name)) is _cbind.FastMethod, name
        f = model.function(name)
        assert len(names) == f.n_in, name          # the C loop gets the same inputs
        for k, size in zip(names, f.sizes_in, strict=True):
            assert np.size(vals[k]) == size, (name, k)


def test_a_tiny_run_has_every_key_and_row(model):
    traj = model_move(model, "high")
    r = overhead_bench(model, traj, 1, 0.0005, 20)
    for name, _ in OVERHEAD_METHODS:
        for key in ("overhead_over_c_", "overhead_python_ns_", "overhead_c_ns_"):
            assert math.isfinite(r[key + name]), key + name
        assert r[f"overhead_python_ns_{name}"] > 0 and r[f"overhead_c_ns_{name}"] > 0
    assert r["overhead_over_c_worst"] not in UNTARGETED
    targets = check_targets(r)
    keyed = {k for k, *_ in bench.TARGETS if k.startswith("overhead_over_c_")}
    assert keyed == {f"overhead_over_c_{n}" for n, _ in OVERHEAD_METHODS if n not in UNTARGETED}
    rows = _overhead_rows(r, targets)
    for name, _ in OVERHEAD_METHODS:
        assert any(line.split()[:1] == [name] for line in rows), name
    assert all(("PASS" in line or "FAIL" in line) == (line.split()[0] not in UNTARGETED)
               for line in rows[3:-1])
