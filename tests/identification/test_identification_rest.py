# Issue 25: a sample at zero velocity has no Coulomb friction column (eq. 2, sign(0) = 0).
"""The regressor the fit stacks (:func:`pm2dof.identification.fit.stack_regressor`, eq. 13
with xrd = xed, xrdd = xedd) at samples where the robot is at rest: the fc (and fs) columns
are exactly zero on every model with a Coulomb law (sign(0) = +1 gave them S^T e_i), and so is
the whole row (Me 0 + Ce 0 + S^T f_a(0) = 0). The log is one held pose, stacked with every
sample kept (``min_joint_speed=0``: by default slow samples are left out)."""
import numpy as np

from pm2dof.identification.base import base_parameters
from pm2dof.identification.fit import stack_regressor


def test_rest_samples_have_no_friction_columns(model):
    n, N = model.n_legs, 400
    T = model.spec.sensing["sample_period"]
    x0 = np.asarray(next(iter(model.spec.trajectories.values()))["start"], dtype=float)
    base = base_parameters(model)
    names = [model.param_names[j] for j in base.independent]
    friction = [k for k, name in enumerate(names) if name.rstrip("0123456789") in ("fc", "fs")]
    assert friction, f"{model.name}: no Coulomb column among the base parameters {names}"
    st = stack_regressor(model, base, np.arange(N) * T, np.tile(x0, (N, 1)), np.zeros((N, n)),
                         10.0, decimate=1, min_joint_speed=0.0)
    assert len(st["Phi"]) == st["n_candidates"] > 0 and not st["xed"].any() and not st["xedd"].any()
    assert np.all(st["Phi"][:, :, friction] == 0.0), \
        f"{model.name}: friction columns at rest {np.abs(st['Phi'][:, :, friction]).max()}"
    assert np.all(st["Phi"] == 0.0)
    # the regressor itself at one rest sample
    Y = model.Y(model.ik(x0), np.zeros(2), np.zeros(2), np.zeros(2))
    assert np.all(Y == 0.0), f"{model.name}: Y at rest {Y}"
