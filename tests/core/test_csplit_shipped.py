# core/build.py on shipped models: the library cut into units gives the whole file's bits (slow).
"""A shipped model's C compiled whole (one gcc command with FLAGS, as before the cut) and cut
into translation units (compile_library: loops -O3, the rest -O2): every generated function
gives the same bits on random inputs (NaN outputs: NaN in both; which NaN, its sign and payload,
may differ with the order of a commutative operation). The 3-PRR point model is the one whose
path coefficients changed in the last bit when GCC fused a vfmaddsub in one unit and not in the
other (before -mno-fma); the paper's robot is the one the pinned numbers come from."""
import subprocess

import numpy as np
import pytest

from pm2dof.core import _cbind, build
from pm2dof.core.manifest import Manifest
from pm2dof.core.paths import SHIPPED_GENERATED

pytestmark = pytest.mark.slow


@pytest.mark.parametrize("name", ["prr_point", "shang2010"])
def test_cut_library_gives_the_whole_files_bits(tmp_path, name):
    gen = SHIPPED_GENERATED / name
    c = gen / f"{name}.c"
    whole = tmp_path / "whole" / f"lib{name}.so"
    whole.parent.mkdir()
    subprocess.run([*build._compiler(), *build.FLAGS, "-o", str(whole), str(c), "-lm"],
                   check=True)
    cut = build.compile_library(c, tmp_path / "cut" / f"lib{name}.so", jobs=3)
    la, lb = _cbind.Library(str(whole)), _cbind.Library(str(cut))
    rng = np.random.default_rng(7)
    names = Manifest.read(gen).function_names()
    assert len(names) > 50
    for short in names:
        fa = _cbind.Function(la, f"{name}_{short}")
        fb = _cbind.Function(lb, f"{name}_{short}")
        fa.check_outputs = fb.check_outputs = False
        for trial in range(12):
            ins = [rng.uniform(-1, 1, k) * (0.3 if trial % 2 else 3) for k in fa.sizes_in]
            oa = [np.full(k, -7.0) for k in fa.sizes_out]
            ob = [np.full(k, -7.0) for k in fa.sizes_out]
            fa(*ins, *oa)
            fb(*ins, *ob)
            for out, x, y in zip(fa.names_out, oa, ob):
                nan = np.isnan(x)
                assert np.array_equal(nan, np.isnan(y)), (short, out, trial)
                assert np.array_equal(x[~nan].view(np.int64), y[~nan].view(np.int64)), \
                    (short, out, trial, x[~nan] - y[~nan])
