# pm2dof.core.measures (the model-file check's NumPy measures) against the generated C's.
"""The singularity measures of pm2dof.core.measures, computed from the model file's geometry
before any code is derived, against the generated ``singularity_measures`` (SymPy -> C), on
every shipped model (RRR, PRR and RPR legs, points and platforms, gravity) and at poses where a
measure vanishes by construction."""
import math

import numpy as np
import pytest

import pm2dof
from pm2dof.core.measures import pose_measures, singularity_words
from pm2dof.core.model_file import Leg


def test_the_measures_are_the_generated_ones(model, sample_xe):
    """Every shipped model, 15 poses around its first move: both measures to rounding."""
    for xe in sample_xe(model, 7, 15, sing_min=0.0):
        want = model.singularity_measures(model.ik(xe))
        type1, type2, per_leg = pose_measures(model.spec.legs, xe)
        assert abs(type1 - want[0]) <= 1e-13 and abs(type2 - want[1]) <= 1e-12, \
            (model.name, xe.tolist(), want, type1, type2)
        assert min(per_leg) == type1


def test_rpr_lines_through_the_platforms_origin_are_type_ii():
    """rpr3_platform turned by -60 degrees: its attachment points (on a circle of 0.08 m at 270,
    30, 150 degrees) come onto the lines from the origin to its bases (210, 330, 90 degrees), so
    the three legs' lines meet at the origin: S has rank 2 and both codes say 0 (to the
    rounding of a cube root of a determinant of ~1e-17, and of the file's 4-digit bases)."""
    m = pm2dof.load_model("rpr3_platform")
    xe = [0.0, 0.0, -math.pi / 3]
    type1, type2, _ = pose_measures(m.spec.legs, xe)
    generated = m.singularity_measures(m.ik(xe))
    assert type1 == 1.0 and type2 < 1e-4 and abs(type2 - generated[1]) < 1e-6, (type2, generated)
    assert np.linalg.matrix_rank(m.S(m.ik([0.0, 0.0, 0.0])), tol=1e-6) == 3   # home is clear


def test_a_prr_link_nearly_across_its_rail_is_type_i():
    """prr_point's leg 1 with the point at 0.999 lb from the rail's line: its link makes the
    angle acos(0.999) with the rail's normal, so |d . u(qb)| = sqrt(1 - 0.999^2) = 0.0447, in
    either branch."""
    spec = pm2dof.load_model("prr_point").spec
    leg = spec.legs[0]
    d = np.subtract(leg.rail_end, leg.base) / leg.rail_length
    point = np.asarray(leg.base) + 0.5 * leg.rail_length * d + 0.999 * leg.lb * np.array(
        [-d[1], d[0]])
    assert pose_measures(spec.legs, point)[2][0] == pytest.approx(math.sqrt(1 - 0.999 ** 2),
                                                                  rel=1e-9)


@pytest.mark.parametrize("name,pose", [("shang2010", [2.0, 2.0]),
                                       ("prr3_platform", [0.0, 0.5, 0.0])])
def test_no_solution_is_nan(name, pose):
    """An RRR leg outside its annulus, a PRR leg farther than lb from its rail's line."""
    spec = pm2dof.load_model(name).spec
    assert all(math.isnan(v) for v in pose_measures(spec.legs, pose)[:2])


def _leg(kind):
    if kind == "RRR":
        return Leg(base=(0.0, 0.0), la=0.2, lb=0.2, elbow=1)
    if kind == "PRR":
        return Leg(base=(0.0, 0.0), la=None, lb=0.2, elbow=1, kind="PRR", rail_end=(1.0, 0.0))
    return Leg(base=(0.0, 0.0), la=None, lb=None, elbow=None, kind="RPR", stroke=(0.1, 0.4))


@pytest.mark.parametrize("kinds,effector,one,two", [
    (("RRR",) * 3, "point", ("a leg's links aligned", "min_i |sin(qb_i - qa_i)|"),
     ("all distal links aligned", "sqrt(n/2)")),
    (("PRR",) * 3, "point", ("link across its rail", "min_i |d_i . u(qb_i)|"),
     ("all distal links aligned", "sqrt(n/2)")),
    (("RPR",) * 3, "platform", ("none within an RPR leg's stroke", "min_i 1"),
     ("concurrent or all parallel", "(det U^T U)^(1/3) / (n/3)")),
    (("RRR", "RRR", "PRR"), "platform",
     ("links aligned or a PRR leg's link across its rail",
      "|sin(qb_i - qa_i)| (RRR legs 1, 2) and |d_i . u(qb_i)| (PRR leg 3)"),
     ("concurrent or all parallel", "(det U^T U)^(1/3) / (n/3)")),
])
def test_each_kind_names_its_own_measures(kinds, effector, one, two):
    (name1, what1), (name2, what2) = singularity_words([_leg(k) for k in kinds], effector)
    assert name1.startswith("type I (") and one[0] in name1 and one[1] in what1, (name1, what1)
    assert name2.startswith("type II (") and two[0] in name2 and two[1] in what2, (name2, what2)
    if "RRR" not in kinds:
        assert "sin(qb" not in what1
    if effector == "platform":
        assert "distal links" not in name2 and "sqrt(n/2)" not in what2
