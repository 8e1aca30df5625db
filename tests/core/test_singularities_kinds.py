# Both singularity measures of issue 26's kinds against NumPy written from the model-file reference.
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
