# Both singularity measures of every leg kind against NumPy written from the model-file reference.
"""Type I and type II measures on every model, any leg kind and end effector.

Written from docs/model-file.md ("Singularities"), not from the derivation's code:

* type I, min over the legs of: RRR |sin(qb - qa)|; PRR |d . u(qb)| (d the rail's unit
  direction); RPR 1;
* type II, from the lines along which the legs push, u(qb_i): a point's sqrt(1 - |z| / n),
  z = sum_i exp(2 i qb_i); a platform's (det U^T U)^(1/3) / (n / 3), U's rows
  (u(qb_i), ((R(phi) a_i) x u(qb_i)) / L) scaled to unit length, L the RMS distance of the
  attachment points a_i from the platform's origin.

And the structure behind type II: row i of S is a multiple of U's row i (the leg pushes along
its line), so the measure vanishes exactly when S loses rank.
"""
import numpy as np
import pytest

EPS = np.finfo(float).eps


def _u(a):
    return np.stack([np.cos(a), np.sin(a)], axis=-1)


def _type_one(model, q):
    n = model.n_legs
    out = []
    for i, leg in enumerate(model.spec.legs):
        qa, qb = q[i], q[n + i]
        if leg.kind == "RRR":
            out.append(abs(np.sin(qb - qa)))
        elif leg.kind == "PRR":
            d = np.subtract(leg.rail_end, leg.base)
            out.append(abs(d @ _u(qb)) / np.linalg.norm(d))
        else:                                   # RPR
            out.append(1.0)
    return min(out)


def _lines(model, q, xe):
    """U (n, m): each leg's line of action, with a platform's moment over L, unit rows."""
    n = model.n_legs
    u = _u(q[n:2 * n])
    if model.dof == 2:
        return u
    a = np.array([leg.attach for leg in model.spec.legs], dtype=float)
    L = np.sqrt(np.mean(np.sum(a ** 2, axis=1)))
    c, s = np.cos(xe[2]), np.sin(xe[2])
    ra = a @ np.array([[c, s], [-s, c]])            # rows R(phi) a_i
    moment = ra[:, 0] * u[:, 1] - ra[:, 1] * u[:, 0]
    U = np.column_stack([u, moment / L])
    return U / np.linalg.norm(U, axis=1, keepdims=True)


def _type_two(model, q, xe):
    n = model.n_legs
    if model.dof == 2:
        z = np.sum(np.exp(2j * q[n:2 * n]))
        return np.sqrt(max(1.0 - abs(z) / n, 0.0))
    U = _lines(model, q, xe)
    return np.linalg.det(U.T @ U) ** (1 / 3) / (n / 3)


def test_measures_follow_the_model_file_reference(model, sample_xe):
    for xe in sample_xe(model, 19, 12):
        q = model.ik(xe)
        c = model.singularity_measures(q)
        assert abs(c[0] - _type_one(model, q)) <= 8 * EPS, (model.name, xe, c)
        t2 = _type_two(model, q, xe)
        assert abs(c[1] ** 2 - t2 ** 2) <= 64 * EPS, (model.name, xe, c[1], t2)
        assert 0.0 < c[1] <= 1.0 + 8 * EPS


def test_rows_of_S_push_along_the_legs_lines(model, sample_xe):
    """S's row i is parallel to U's row i (a platform's moment scaled back by L): the type II
    measure is that of S's row space."""
    n = model.n_legs
    for xe in sample_xe(model, 23, 6):
        q = model.ik(xe)
        S = model.S(q)
        U = _lines(model, q, xe)
        if model.dof == 3:
            a = np.array([leg.attach for leg in model.spec.legs], dtype=float)
            U = U * np.array([1.0, 1.0, np.sqrt(np.mean(np.sum(a ** 2, axis=1)))])
        for i in range(n):
            cross = np.linalg.norm(np.outer(S[i], U[i]) - np.outer(U[i], S[i]))
            assert cross <= 1e-12 * np.linalg.norm(S[i]) * np.linalg.norm(U[i]), \
                (model.name, i, S[i], U[i])


# --- the words of a SingularityError follow the kind -----------------------------------------

def test_type_ii_on_a_platform_names_the_platforms_measure():
    """rpr3_platform turned by -60 degrees: its attachment points come onto the lines from its
    bases to the origin, the three legs' lines meet there (S has rank 2). The error used to say
    "all distal links aligned" and "sigma_min(S with unit rows) / sqrt(n/2)", a point's."""
    import pm2dof
    m = pm2dof.load_model("rpr3_platform")
    q = m.ik([0.0, 0.0, -np.pi / 3])
    value = m.singularity_measures(q)[1]
    with pytest.raises(pm2dof.SingularityError) as info:
        m.W(q)
    msg = str(info.value)
    for words in ("type II (parallel: the legs' lines of action concurrent or all parallel",
                  f"(det U^T U)^(1/3) / (n/3) of the legs' unit wrench lines U = {value:.4g} < "
                  f"threshold 0.1 (limits.parallel_singularity_threshold)"):
        assert words in msg, msg
    assert "distal links" not in msg and "sqrt(n/2)" not in msg, msg


def test_type_i_on_a_prr_leg_names_the_cosine_between_rail_and_link():
    """prr_point at (0.28, 0.2995): leg 1's rail runs along y = 0 and its link (0.3 m) reaches
    up to 0.2995 m from it, nearly across it: |d . u(qb)| = sqrt(1 - (0.2995/0.3)^2) = 0.0577
    (legs 2 and 3: 0.744 and 0.359). The error used to name |sin(qb_i - qa_i)|, an RRR leg's."""
    import pm2dof
    m = pm2dof.load_model("prr_point")
    q = m.ik([0.28, 0.2995])
    value = np.sqrt(1 - (0.2995 / 0.3) ** 2)
    with pytest.raises(pm2dof.SingularityError) as info:
        m.W(q)
    msg = str(info.value)
    assert ("type I (a PRR leg's link across its rail" in msg
            and f"min_i |d_i . u(qb_i)| = {value:.4g} < threshold 0.1 "
                f"(limits.singularity_threshold)" in msg), msg
    assert "sin(qb" not in msg, msg


@pytest.mark.parametrize("name", ["shang2010", "shang2010_vertical"])
def test_type_i_on_rrr_legs_keeps_the_sine(name):
    """RRR legs (the paper's robot, and in a vertical plane): leg 1 almost stretched, 0.9995 of
    la + lb from its base: |sin(qb - qa)| of that leg, and the words of an RRR leg."""
    import pm2dof
    m = pm2dof.load_model(name)
    leg = m.spec.legs[0]
    d = np.array([0.25, 0.265]) - leg.base
    q = m.ik(np.asarray(leg.base) + d / np.hypot(*d) * (leg.la + leg.lb) * 0.9995)
    value = abs(np.sin(q[m.n_legs] - q[0]))
    with pytest.raises(pm2dof.SingularityError) as info:
        m.W(q)
    msg = str(info.value)
    assert ("type I (a leg's links aligned)" in msg
            and f"min_i |sin(qb_i - qa_i)| = {value:.4g} < threshold" in msg), msg
