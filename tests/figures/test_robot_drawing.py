# The drawn robot (pm2dof.figures.robot) closes its loops: each leg's drawn tip is the point it
# must reach, for every leg kind and end effector (the animation of any mechanism).
"""At poses sampled by the generated ik: every leg's polyline ends at P_i(xe) (xe itself for a
point, a vertex of the drawn platform polygon for a platform), a PRR slider lies on its rail
within the rail's length, an RPR leg's drawn length is its actuated length qa_i and its
cylinder is no longer than the leg, and an RRR leg's links have their lengths."""
import numpy as np


def test_drawn_legs_reach_the_end_effector(model, sample_xe):
    from pm2dof.figures.robot import barrels, leg_points, platform_polygon
    n = model.n_legs
    for xe in sample_xe(model, 3, 4):
        q = model.ik(xe)
        legs, cyl, body = leg_points(model, q), barrels(model, q), platform_polygon(model, xe)
        tips = np.array([p[-1] for p in legs])
        if body is None:
            np.testing.assert_allclose(tips, np.tile(xe, (n, 1)), atol=1e-9)
        else:   # the polygon's vertices are the legs' tips, in some order
            assert body.shape == (n, 2)
            d = np.linalg.norm(tips[:, None, :] - body[None, :, :], axis=2)
            assert np.all(d.min(axis=1) < 1e-9) and len(set(d.argmin(axis=1))) == n, d
        for i, leg in enumerate(model.spec.legs):
            p = legs[i]
            if leg.kind == "RRR":
                np.testing.assert_allclose(np.linalg.norm(np.diff(p, axis=0), axis=1),
                                           [leg.la, leg.lb], rtol=1e-12)
            elif leg.kind == "PRR":
                a, e = np.asarray(leg.base), np.asarray(leg.rail_end)
                t = np.dot(p[0] - a, e - a) / np.dot(e - a, e - a)
                assert -1e-9 <= t <= 1 + 1e-9 and abs((e - a)[0] * (p[0] - a)[1] - (e - a)[1] * (p[0] - a)[0]) < 1e-12
                assert abs(np.linalg.norm(p[1] - p[0]) - leg.lb) < 1e-12
            else:
                assert abs(np.linalg.norm(p[1] - p[0]) - q[i]) < 1e-12
                assert np.linalg.norm(cyl[i][1] - cyl[i][0]) <= q[i] + 1e-12
        assert set(cyl) == {i for i, leg in enumerate(model.spec.legs) if leg.kind == "RPR"}
