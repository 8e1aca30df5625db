# Numerical verification of the compiled model (pm2dof.Model) of every model file, at random reachable poses.
"""Tests of :class:`pm2dof.Model`: the CasADi-generated C as seen through the runtime API.

Which model
-----------
* The generic checks (sections 1-7) run over every ``models/*.toml`` through the ``model``
  fixture of ``conftest.py`` (test ids = model names): kinematics, W, A W = 0, Wdot, the
  properties of Me and Ce, the regressor identity, friction, forward dynamics. The comparison
  with the NumPy reference (``pm2dof.reference``) runs only where the reference applies: the
  paper's Coulomb + viscous friction (``coulomb_viscous_model``).
* The paper-only checks (sign(0) = 0 at an exact zero velocity, errors, the API contract,
  Tables 1-2, the bases of Sect. 2) use ``m``, the paper's robot ``models/shang2010.toml``.

Sampling
--------
Every generic check runs at random poses drawn with fixed seeds in a box +-0.05 m around the
midpoint of the model's first trajectory (``conftest.sample_xe``), keeping only poses that
every leg reaches and with min_i |sin(qb_i - qa_i)| > 0.2 (measured with
``Model.singularity``); the sampler fails if it finds too few. With link lengths >= 0.235 m
in every model file, |W| <= 1/(0.235 m * 0.2) ~ 21 rad/m and every derivative below is well
scaled. Velocities are up to the paper's high-speed v_max (0.5 m/s), accelerations up to
10 m/s^2; theta is random with every leg's inertia block positive definite. Every assertion
message carries the model and the failing input.

Error measures: ``err = max|actual - expected|`` (max-norm over the entries), compared with
``rtol * scale``, where ``scale`` is stated at each check (normally the max-norm of the
expected value, or of the terms that are summed to form it, so that cancellation in the
sum does not make the check depend on luck).

Tolerances, from the numerics (the observed largest errors, per model, are recorded by
``check`` and printed at the end of the module with ``pytest -s``):

* ``TOL_EXACT = 1e-12``: closed-form evaluations and algebraic identities in double
  precision. Inputs are O(1) (angles <= pi rad, lengths <= 0.6 m, parameters <= 5); each
  output is a straight-line expression of at most a few hundred flops with no cancellation
  worse than the singularity margin 1/0.2 = 5 per division by sin(qb - qa), so the rounding
  error is ~1e-15..1e-14 relative. 1e-12 leaves a >= 100x margin; it is not a fit to the
  observed values.
* ``TOL_FD = 1e-7``: central finite differences with step h = 1e-6 (m or s). Truncation
  is h^2/6 |f'''|, and with |d/dq| ~ |W| ~ 21 rad/m each derivative of W/q/Me costs a factor
  <= ~21, so h^2/6 * 21^3 ~ 1.5e-9 relative; round-off is ~ eps * cond / h ~
  2.2e-16 * 21 / 1e-6 ~ 5e-9 relative. 1e-7 is >= 20x above both bounds.
* ``TOL_KKT = 1e-9``: the Lagrange-multiplier solution uses Adot qd from finite
  differences of A (h = 1e-6 rad along qd): A is made of l*sin/l*cos, so the truncation is
  h^2/6 * l * |qd|^3 ~ 1e-12/6 * 0.25 * 10^3 ~ 4e-11 against |Adot qd| ~ l |qd|^2 ~ 25
  (relative ~2e-12), and round-off eps * l / h * |qd| ~ 5e-10 absolute (~2e-11 relative);
  the KKT solve multiplies this by cond(K) ~ 1e2. About 1e-10 relative in the worst case,
  so 1e-9 is a 10x margin.
"""
from __future__ import annotations

import numpy as np
import pytest

import pm2dof
from pm2dof.core.mechanism import PLATFORM_PARAMS
from pm2dof.reference import model as ref

pytestmark = pytest.mark.long     # over 1.5 s in all: make test runs it, make test-quick not

# --------------------------------------------------------------------------------------
# Constants, helpers
# --------------------------------------------------------------------------------------

# the paper's robot (docs/paper.md, the paper's Sect. 2): used by the paper-only checks
L = 0.244                     # all link lengths, m
BASES = np.array([[0.0, 0.25], [0.433, 0.0], [0.433, 0.5]])
N_LEGS = 3

N_POSES = 25                  # per test and model; every test is fast (one C call ~ 1 us)
H_FD = 1e-6                   # central finite-difference step, m or s
TOL_EXACT = 1e-12             # see module docstring
TOL_FD = 1e-7                 # see module docstring
TOL_KKT = 1e-9                # see module docstring

# largest observed error ratio err/scale, {model: {check: ratio}}, printed at module teardown (-s)
_OBSERVED: dict[str, dict[str, float]] = {}


def _record(model_name, name, err, scale=1.0):
    d = _OBSERVED.setdefault(model_name, {})
    d[name] = max(d.get(name, 0.0), float(err) / float(scale))


@pytest.fixture(scope="module", autouse=True)
def _report_observed():
    yield
    if _OBSERVED:
        print("\n[test_model] largest observed relative errors (err / scale), per model:")
        for model_name in sorted(_OBSERVED):
            print(f"  {model_name}:")
            for k in sorted(_OBSERVED[model_name]):
                print(f"    {k:<44s} {_OBSERVED[model_name][k]:.3e}")


@pytest.fixture(scope="module")
def m():
    """The paper's robot, models/shang2010.toml (the default model)."""
    return pm2dof.load_model()


def wrap(a):
    """Angles wrapped to (-pi, pi]: q is only defined modulo 2 pi per joint."""
    a = np.asarray(a, dtype=float)
    return -np.remainder(-a + np.pi, 2.0 * np.pi) + np.pi


def geometry(model):
    """(bases (n, 2), la (n,), lb (n,), elbow (n,) +1 left / -1 right) from the model file."""
    legs = model.spec.legs
    return (np.array([leg.base for leg in legs], float), np.array([leg.la for leg in legs]),
            np.array([leg.lb for leg in legs]), np.array([leg.elbow for leg in legs]))


def u(t):
    return np.array([np.cos(t), np.sin(t)])


def rail_direction(leg):
    """A PRR leg's rail direction d (2,), unit."""
    d = np.asarray(leg.rail_end, float) - np.asarray(leg.base, float)
    return d / np.hypot(*d)


def typed_tips(model, q):
    """(n, 2) leg i's tip, typed from docs/model-file.md ("Kinematics of every kind"):
    A + la u(qa) + lb u(qb) (RRR), A + qa d + lb u(qb) (PRR), A + qa u(qb) (RPR)."""
    n, out = model.n_legs, []
    for i, leg in enumerate(model.spec.legs):
        qa, qb, A = q[i], q[n + i], np.asarray(leg.base, float)
        if leg.kind == "RRR":
            out.append(A + leg.la * u(qa) + leg.lb * u(qb))
        elif leg.kind == "PRR":
            out.append(A + qa * rail_direction(leg) + leg.lb * u(qb))
        else:
            out.append(A + qa * u(qb))
    return np.array(out)


def attachment_points(model, xe):
    """(n, 2) P_i(xe): xe itself for a point, p + R(phi) a_i for a platform (docs/model-file.md)."""
    if model.spec.end_effector != "platform":
        return np.tile(xe, (model.n_legs, 1))
    c, s = np.cos(xe[2]), np.sin(xe[2])
    return np.array([xe[:2] + np.array([[c, -s], [s, c]]) @ np.asarray(leg.attach, float)
                     for leg in model.spec.legs])


def up(t):
    return np.array([-np.sin(t), np.cos(t)])


@pytest.fixture(scope="module")
def cases(sample_xe, random_theta, task_scale):
    """cases(model, seed, k) -> iterator of (xe, xed, xrd, xrdd, theta, tau_a), task arrays of
    m = model.dof: xed a random direction with |xed| in [0.05, 0.5] m/s for x, y (not ~0, so
    that Wdot, Ce are not vanishing and relative checks are meaningful; phi's rate scaled by
    conftest.PHI_PER_M), xrd in +-0.5, xrdd in +-10 (same scaling), random theta
    (conftest.random_theta) and tau_a in [-10, 10] N m (N for a prismatic actuator)."""
    def gen(model, seed, k=N_POSES):
        rng = np.random.default_rng(seed + 7919)
        w, m = task_scale(model, 1.0), model.dof
        for xe in sample_xe(model, seed, k):
            d = rng.normal(size=m)
            xed = rng.uniform(0.05, 0.5) * w * d / np.linalg.norm(d)
            yield (xe, xed, rng.uniform(-0.5, 0.5, m) * w, rng.uniform(-10.0, 10.0, m) * w,
                   random_theta(model, rng), rng.uniform(-10.0, 10.0, model.n_legs))
    return gen


def maxabs(a):
    return float(np.max(np.abs(a)))


def check(name, actual, expected, rtol, scale, info, model):
    """Assert max|actual - expected| <= rtol * scale and record the ratio under the model."""
    actual, expected = np.asarray(actual, float), np.asarray(expected, float)
    assert actual.shape == expected.shape, \
        f"{model.name}: {name}: shape {actual.shape} != {expected.shape} at {info}"
    err = maxabs(actual - expected)
    _record(model.name, name, err, scale)
    assert err <= rtol * scale, (
        f"{model.name}: {name}: max error {err:.3e} > {rtol:.0e} * scale {scale:.3e} at {info}\n"
        f"actual=\n{actual}\nexpected=\n{expected}")


def fmt(**kw):
    """The failing input, printed with full precision."""
    return ", ".join(f"{k}={np.array2string(np.asarray(v), precision=17, separator=',')}"
                     for k, v in kw.items())


def friction_typed(model, v, theta):
    """The actuated-joint friction f_a (n,) at joint velocities v (n,), typed here from the
    model file's comments (eq. 2 and its extensions), independent of derive/ and reference.py.
    Returns None for a friction model this test does not know."""
    spec, n = model.spec, model.n_legs
    names = list(model.param_names)
    par = lambda kind: theta[[names.index(f"{kind}{i + 1}") for i in range(n)]]  # noqa: E731
    v = np.asarray(v, float)
    sgn = np.sign(v)                                        # sign(0) = 0
    if spec.friction == "coulomb_viscous":                   # eq. 2
        return par("fc") * sgn + par("fv") * v
    if spec.friction == "coulomb_viscous_stribeck":          # eq. 2 + fs sign(v) / (1 + (v/vs)^2)
        vs = spec.friction_constants["stribeck_velocity"]
        return (par("fc") + par("fs") / (1.0 + (v / vs) ** 2)) * sgn + par("fv") * v
    if spec.friction == "smooth_sign":                       # sign(v) -> v / sqrt(v^2 + eps^2)
        eps = spec.friction_constants["sign_smoothing_velocity"]
        return par("fc") * v / np.sqrt(v ** 2 + eps ** 2) + par("fv") * v
    return None


def friction_index(model, param_index):
    """Indices of theta's friction parameters (everything but alpha, beta, gamma)."""
    return sorted(j for (kind, _), j in param_index(model).items()
                  if kind not in ("alpha", "beta", "gamma"))


# --------------------------------------------------------------------------------------
# 1. Kinematics: ik closes the loop, fk inverts ik (every model)
# --------------------------------------------------------------------------------------

def test_ik_closes_loop_and_fk_inverts_it(model, sample_xe):
    # H and xe are O(0.5 m) (phi O(1) rad) and computed from a few trig calls: rounding
    # ~1e-16; a platform's fk is a Gauss-Newton iteration, converged to rounding.
    n = model.n_legs
    rows = 2 * n if model.spec.end_effector == "platform" else 2 * (n - 1)   # eq. 5
    for xe in sample_xe(model, 1, N_POSES):
        q = model.ik(xe)
        info = fmt(xe=xe, q=q)
        check("H(ik(x)) [m]", model.H(q), np.zeros(rows), TOL_EXACT, 1.0, info, model)
        check("fk(ik(x)[:n]) - x [m]", model.fk(q[:n]), xe, TOL_EXACT, 1.0, info, model)
        # every leg's tip is at its P_i(xe) (typed from docs/model-file.md, per kind)
        check("tip_i(ik(x)) - P_i(x) [m]", typed_tips(model, q), attachment_points(model, xe),
              TOL_EXACT, 1.0, info, model)


def test_ik_elbows_are_on_the_side_the_model_file_chooses(model, sample_xe):
    """RRR: elbow = "right" (-1): B_i lies right of A_i -> P_i; "left" (+1): left. PRR:
    branch "ahead" (+1): the slider lies ahead of the foot of the perpendicular from P_i onto
    the rail, along its direction; "behind" (-1) behind it. RPR has no branch."""
    if all(leg.kind == "RPR" for leg in model.spec.legs):
        pytest.skip(f"{model.name}: RPR legs have no branch to choose (docs/model-file.md)")
    for xe in sample_xe(model, 2, N_POSES):
        q = model.ik(xe)
        P = attachment_points(model, xe)
        for i, leg in enumerate(model.spec.legs):
            d = P[i] - np.asarray(leg.base, float)
            if leg.kind == "RRR":
                b = leg.la * u(q[i])
                # |side| = |d| la |sin(angle at A_i)|, bounded away from 0 at admissible poses
                side = d[0] * b[1] - d[1] * b[0]
            elif leg.kind == "PRR":
                # qa - foot = lb |d . u(qb)|, the type I measure: away from 0 at these poses
                side = q[i] - d @ rail_direction(leg)
            else:
                continue
            assert np.sign(side) == leg.elbow, (f"{model.name}: leg {i + 1} ({leg.kind}) on "
                                                f"the wrong side: {side} at {fmt(xe=xe, q=q)}")


# --------------------------------------------------------------------------------------
# 2. W against finite differences of ik; A W = 0; A = dH/dq (every model)
# --------------------------------------------------------------------------------------

def test_W_is_the_derivative_of_ik(model, sample_xe):
    n = model.n_legs
    for xe in sample_xe(model, 3, N_POSES):
        q = model.ik(xe)
        Wq = model.W(q)
        fd = np.empty((2 * n, model.dof))
        for j in range(model.dof):                 # phi's step H_FD is in rad
            e = np.zeros(model.dof)
            e[j] = H_FD
            # wrap: ik returns each angle modulo 2 pi (a branch cut must not look like a jump;
            # a prismatic qa's difference, ~1e-6 m, is left as it is)
            fd[:, j] = wrap(model.ik(xe + e) - model.ik(xe - e)) / (2 * H_FD)
        check("W vs FD of ik (rel. max|W|)", Wq, fd, TOL_FD, maxabs(Wq), fmt(xe=xe, q=q), model)


def test_A_W_is_zero(model, sample_xe):
    n = model.n_legs
    for xe in sample_xe(model, 4, N_POSES):
        q = model.ik(xe)
        Aq, Wq = model.A(q), model.W(q)
        assert Aq.shape == (2 * (n - 1), 2 * n)
        # each entry of A W is a sum of 4 products of entries of A and W: rounding
        # <= 4 eps max|A| max|W|; the scale makes the check independent of units.
        check("A W = 0 (rel. max|A| max|W|)", Aq @ Wq, np.zeros((2 * (n - 1), model.dof)),
              TOL_EXACT, maxabs(Aq) * maxabs(Wq), fmt(xe=xe, q=q), model)


def test_A_is_the_jacobian_of_H(model, sample_xe):
    n = model.n_legs
    for xe in sample_xe(model, 5, N_POSES):
        q = model.ik(xe)
        fd = np.column_stack([(model.H(q + H_FD * e) - model.H(q - H_FD * e)) / (2 * H_FD)
                              for e in np.eye(2 * n)])
        Aq = model.A(q)
        check("A vs FD of H (rel. max|A|)", Aq, fd, TOL_FD, maxabs(Aq), fmt(xe=xe, q=q), model)


# --------------------------------------------------------------------------------------
# 3. Wdot against finite differences of W along the motion (every model)
# --------------------------------------------------------------------------------------

def test_Wdot_is_the_time_derivative_of_W(model, cases):
    for xe, xed, *_ in cases(model, 6):
        q = model.ik(xe)
        Wd = model.Wdot(q, xed)
        fd = (model.W(model.ik(xe + H_FD * xed)) - model.W(model.ik(xe - H_FD * xed))) / (2 * H_FD)
        check("Wdot vs FD of W (rel. max|Wdot|)", Wd, fd, TOL_FD, maxabs(Wd),
              fmt(xe=xe, xed=xed), model)


def test_S_is_the_active_rows_of_W(model, sample_xe):
    n = model.n_legs
    for xe in sample_xe(model, 7, N_POSES):
        q = model.ik(xe)
        np.testing.assert_array_equal(model.S(q), model.W(q)[:n], err_msg=f"{model.name}: {fmt(xe=xe)}")


# --------------------------------------------------------------------------------------
# 4. Me symmetric positive definite, Medot - 2 Ce skew-symmetric (every model)
# --------------------------------------------------------------------------------------

def _theta_cases(model, cases, seed):
    """Random PD theta and, for every pose, also the nominal theta of the model file."""
    for xe, xed, xrd, xrdd, theta, tau in cases(model, seed):
        yield "random", xe, xed, theta
        yield "nominal", xe, xed, np.array(model.theta_nominal)


def test_Me_symmetric_positive_definite(model, cases):
    for which, xe, xed, theta in _theta_cases(model, cases, 8):
        q = model.ik(xe)
        Me = model.Me(q, theta)
        info = fmt(xe=xe, theta=theta)
        check(f"Me - Me^T ({which}, rel. max|Me|)", Me, Me.T, TOL_EXACT, maxabs(Me), info, model)
        ev = np.linalg.eigvalsh((Me + Me.T) / 2)
        # Me = W^T M W with M PD and W of full column rank: the smallest eigenvalue is
        # bounded away from 0 at these poses (>= lambda_min(M) sigma_min(W)^2), far above
        # rounding; a sign test is enough.
        assert ev[0] > 0, f"{model.name}: Me not positive definite ({which}): eigenvalues {ev} at {info}"
        # M of eq. 3 itself: symmetric PD for these theta
        Mq = model.M(q, theta)
        np.testing.assert_array_equal(Mq, Mq.T, err_msg=f"{model.name}: {info}")
        assert np.linalg.eigvalsh(Mq)[0] > 0, f"{model.name}: M not PD ({which}) at {info}"


def test_Medot_minus_2Ce_is_skew_symmetric(model, cases):
    for which, xe, xed, theta in _theta_cases(model, cases, 9):
        q = model.ik(xe)
        Ce = model.Ce(q, xed, theta)
        Medot = (model.Me(model.ik(xe + H_FD * xed), theta)
                 - model.Me(model.ik(xe - H_FD * xed), theta)) / (2 * H_FD)
        N = Medot - 2 * Ce
        scale = maxabs(Medot) + 2 * maxabs(Ce)  # N is a difference of these two terms
        check(f"Medot - 2Ce + (..)^T ({which}, FD)", N + N.T, np.zeros((model.dof,) * 2), TOL_FD,
              scale, fmt(xe=xe, xed=xed, theta=theta), model)


def test_Mdot_minus_2C_is_skew_symmetric_joint_space(model, random_theta):
    """Eq. 3 property, with Mdot by central FD along qd (any q, any qd: M, C are open-chain)."""
    n = model.n_legs
    rng = np.random.default_rng(10)
    for _ in range(N_POSES):
        q, qd = rng.uniform(-np.pi, np.pi, 2 * n), rng.uniform(-5, 5, 2 * n)
        theta = random_theta(model, rng)
        Mdot = (model.M(q + H_FD * qd, theta) - model.M(q - H_FD * qd, theta)) / (2 * H_FD)
        Cq = model.C(q, qd, theta)
        N = Mdot - 2 * Cq
        scale = maxabs(Mdot) + 2 * maxabs(Cq)
        check("Mdot - 2C + (..)^T (FD)", N + N.T, np.zeros((2 * n, 2 * n)), TOL_FD, scale,
              fmt(q=q, qd=qd, theta=theta), model)


def test_M_C_typed_from_notes(model, random_theta):
    """M and C of eq. 3 at arbitrary q, qd, typed from docs/paper.md (n legs)."""
    n = model.n_legs
    rng = np.random.default_rng(15)
    for _ in range(N_POSES):
        q, qd = rng.uniform(-np.pi, np.pi, 2 * n), rng.uniform(-5, 5, 2 * n)
        theta = random_theta(model, rng)
        Mw, Cw = _M_notes(model, q, theta), _C_notes(model, q, qd, theta)
        info = fmt(q=q, qd=qd, theta=theta)
        check("M vs docs/paper.md", model.M(q, theta), Mw, TOL_EXACT, maxabs(Mw), info, model)
        check("C vs docs/paper.md", model.C(q, qd, theta), Cw, TOL_EXACT, maxabs(Cw), info, model)


# --------------------------------------------------------------------------------------
# 5. The regressor: Y theta = Me xrdd + Ce xrd + S^T f_a (every model)
# --------------------------------------------------------------------------------------

def test_Y_theta_equals_the_dynamics(model, cases):
    """Eq. 13 for random theta. For friction models other than eq. 2 the identity holds as
    well: StF comes from the same model, and every friction law is linear in its parameters."""
    p = len(model.param_names)
    for xe, xed, xrd, xrdd, theta, _ in cases(model, 11):
        q = model.ik(xe)
        Me, Ce, StF = model.Me(q, theta), model.Ce(q, xed, theta), model.StF(q, xed, theta)
        Yq = model.Y(q, xed, xrd, xrdd)
        assert Yq.shape == (model.dof, p)
        Ge = model.Ge(q, theta)                  # the gravity term (zero in a horizontal plane)
        rhs = Me @ xrdd + Ce @ xrd + StF + Ge
        # the scale is the size of the summed terms (cancellation must not tighten the check)
        scale = maxabs(Me @ xrdd) + maxabs(Ce @ xrd) + maxabs(StF) + maxabs(Ge)
        check("Y theta vs Me xrdd + Ce xrd + StF", Yq @ theta, rhs, TOL_EXACT, scale,
              fmt(xe=xe, xed=xed, xrd=xrd, xrdd=xrdd, theta=theta), model)


def test_StF_is_S_transpose_friction(model, cases):
    """S^T f_a(S xed) with f_a typed from the model file's friction law (friction_typed)."""
    if friction_typed(model, np.zeros(model.n_legs), np.array(model.theta_nominal)) is None:
        pytest.skip(f"no hand-typed law for friction {model.spec.friction!r} in this test")
    n = model.n_legs
    for xe, xed, _, _, theta, _ in cases(model, 12):
        q = model.ik(xe)
        S = model.S(q)
        v = S @ xed
        fa = friction_typed(model, v, theta)
        want = S.T @ fa
        check("StF vs S^T f_a (typed)", model.StF(q, xed, theta), want, TOL_EXACT,
              maxabs(S) * maxabs(fa) * n, fmt(xe=xe, xed=xed, theta=theta), model)


# --------------------------------------------------------------------------------------
# 6. The C against the independent NumPy reference (models with eq. 2 friction)
# --------------------------------------------------------------------------------------

def reference_geometry(model):
    """pm2dof.reference.Geometry of the model file (legs, elbows, five-bar fk branch)."""
    bases, la, lb, elbow = geometry(model)
    return ref.Geometry(bases=bases, la=la, lb=lb, elbow=elbow, fk_branch=model.spec.fk_branch)


def test_reference_geometry_of_the_paper_is_geometry_paper(m):
    """The Geometry built from the model file is the reference's own paper geometry."""
    g, p = reference_geometry(m), ref.Geometry.paper()
    for f in ("bases", "la", "lb", "elbow"):
        np.testing.assert_array_equal(getattr(g, f), getattr(p, f), err_msg=f)


def test_C_agrees_with_numpy_reference(coulomb_viscous_model, cases):
    model = coulomb_viscous_model
    assert model.spec.friction == "coulomb_viscous"
    g = reference_geometry(model)
    n = model.n_legs
    for xe, xed, xrd, xrdd, theta, tau in cases(model, 14):
        q = model.ik(xe)
        qd = model.W(q) @ xed
        info = fmt(xe=xe, xed=xed, xrd=xrd, xrdd=xrdd, theta=theta, tau_a=tau)
        # ik: angles are equal modulo 2 pi (the C returns qb = atan2(.) in (-pi, pi]; the
        # reference returns qb with qb - qa in (-pi, pi]); both are valid representatives.
        check("ik vs ref (wrapped, rad)", wrap(q - ref.ik(g, xe)), np.zeros(2 * n), TOL_EXACT, 1.0,
              info, model)
        check("fk vs ref [m]", model.fk(q[:n]), ref.fk(g, q[:n]), TOL_EXACT, 1.0, info, model)
        for name, got, want in [
            ("H", model.H(q), ref.H(g, q)),
            ("A", model.A(q), ref.A(g, q)),
            ("W", model.W(q), ref.W(g, q)),
            ("S", model.S(q), ref.S(g, q)),
            ("Wdot", model.Wdot(q, xed), ref.Wdot(g, q, xed)),
            ("M", model.M(q, theta), ref.M(g, q, theta)),
            ("C", model.C(q, qd, theta), ref.C(g, q, qd, theta)),
            ("Me", model.Me(q, theta), ref.Me(g, q, theta)),
            ("Ce", model.Ce(q, xed, theta), ref.Ce(g, q, xed, theta)),
            ("StF", model.StF(q, xed, theta), ref.task_friction(g, q, xed, theta)),
            ("Y", model.Y(q, xed, xrd, xrdd), ref.Y(g, q, xed, xrd, xrdd)),
        ]:
            scale = max(maxabs(want), 1e-300)
            if name == "H":
                scale = 1.0  # H = 0 at a closed pose: absolute, in m
            check(f"{name} vs ref", got, want, TOL_EXACT, scale, info, model)
        # forward dynamics: xedd = Me^-1 (S^T tau - Ce xed - StF); relative to the size
        # of Me^-1 times the summed terms (the sum may cancel)
        Me = ref.Me(g, q, theta)
        terms = (maxabs(ref.S(g, q).T @ tau) + maxabs(ref.Ce(g, q, xed, theta) @ xed)
                 + maxabs(ref.task_friction(g, q, xed, theta)))
        scale = np.linalg.norm(np.linalg.inv(Me), np.inf) * terms
        check("forward_dynamics vs ref", model.forward_dynamics(xe, xed, tau, theta),
              ref.forward_dynamics(g, xe, xed, tau, theta), TOL_EXACT, scale, info, model)


# --------------------------------------------------------------------------------------
# 7. Task-space forward dynamics against the joint-space Lagrange-multiplier solution
# --------------------------------------------------------------------------------------
# Written here from docs/paper.md (eqs. 1-6), generalised to n legs with the model file's leg
# geometry; independent of derive/ and of reference.py.

def _leg_params(model, theta, kind):
    names = list(model.param_names)
    return np.array([theta[names.index(f"{kind}{i + 1}")] for i in range(model.n_legs)])


def _M_notes(model, q, theta):
    """Eq. 3: alpha_i at (i,i), gamma_i at (n+i,n+i), beta_i cos(qa_i - qb_i) off-diagonal."""
    n = model.n_legs
    al, be, ga = (_leg_params(model, theta, k) for k in ("alpha", "beta", "gamma"))
    Mq = np.zeros((2 * n, 2 * n))
    for i in range(n):
        c = np.cos(q[i] - q[n + i])
        Mq[i, i], Mq[n + i, n + i] = al[i], ga[i]
        Mq[i, n + i] = Mq[n + i, i] = be[i] * c
    return Mq


def _C_notes(model, q, qd, theta):
    """Eq. 1/3: C_i = [[0, beta_i s_i qd_bi], [-beta_i s_i qd_ai, 0]], s_i = sin(qa_i - qb_i)."""
    n = model.n_legs
    be = _leg_params(model, theta, "beta")
    Cq = np.zeros((2 * n, 2 * n))
    for i in range(n):
        s = np.sin(q[i] - q[n + i])
        Cq[i, n + i] = be[i] * s * qd[n + i]
        Cq[n + i, i] = -be[i] * s * qd[i]
    return Cq


def _A_hand(model, q):
    """Eq. 6 by hand: H = [tip_1 - tip_2; ...; tip_1 - tip_n], d tip_i/d qa_i = la_i (-sin, cos)."""
    n = model.n_legs
    _, la, lb, _ = geometry(model)
    Aq = np.zeros((2 * (n - 1), 2 * n))
    for k in range(1, n):
        r = slice(2 * (k - 1), 2 * k)
        Aq[r, 0], Aq[r, n] = la[0] * up(q[0]), lb[0] * up(q[n])
        Aq[r, k], Aq[r, n + k] = -la[k] * up(q[k]), -lb[k] * up(q[n + k])
    return Aq


def _joint_velocities(model, q, xed):
    """qd from xed, leg by leg: solve d tip_i/d(qa_i, qb_i) [qda_i; qdb_i] = xed."""
    n = model.n_legs
    _, la, lb, _ = geometry(model)
    qd = np.zeros(2 * n)
    for i in range(n):
        J = np.column_stack([la[i] * up(q[i]), lb[i] * up(q[n + i])])
        qd[i], qd[n + i] = np.linalg.solve(J, xed)
    return qd


def _xedd_lagrange(model, xe, xed, tau_a, theta, h=H_FD):
    """Eq. 4 with multipliers: [[M, -A^T], [A, 0]] [qdd; lam] = [tau - f - C qd; -Adot qd].

    f: the actuated-joint friction of the model file's law, typed here (friction_typed); for
    a law it does not know, f = 0 (the caller has set the friction parameters to zero)."""
    n = model.n_legs
    _, la, lb, _ = geometry(model)
    q = model.ik(xe)
    qd = _joint_velocities(model, q, xed)
    Aq = _A_hand(model, q)
    # Adot qd = d/dt (A) qd along the motion q(t) = q + t qd, central FD of the hand A
    Adot_qd = (_A_hand(model, q + h * qd) - _A_hand(model, q - h * qd)) / (2 * h) @ qd
    fa = friction_typed(model, qd[:n], theta)
    fa = np.zeros(n) if fa is None else fa
    tau = np.concatenate([tau_a, np.zeros(n)])
    f = np.concatenate([fa, np.zeros(n)])
    K = np.block([[_M_notes(model, q, theta), -Aq.T], [Aq, np.zeros((2 * (n - 1), 2 * (n - 1)))]])
    rhs = np.concatenate([tau - f - _C_notes(model, q, qd, theta) @ qd, -Adot_qd])
    sol = np.linalg.solve(K, rhs)
    qdd = sol[:2 * n]
    # the tip of leg i: xedd = la u'(qa) qdd_a + lb u'(qb) qdd_b - la u(qa) qd_a^2 - lb u(qb) qd_b^2
    tips = [la[i] * up(q[i]) * qdd[i] + lb[i] * up(q[n + i]) * qdd[n + i]
            - la[i] * u(q[i]) * qd[i] ** 2 - lb[i] * u(q[n + i]) * qd[n + i] ** 2 for i in range(n)]
    return tips, Aq, q


def test_forward_dynamics_matches_lagrange_multipliers(model, cases, param_index):
    """For a friction law this test cannot type, the friction parameters are set to zero
    (every law is linear in its parameters: asserted via StF = 0) and f = 0 in the KKT system."""
    n = model.n_legs
    known = friction_typed(model, np.zeros(n), np.array(model.theta_nominal)) is not None
    for xe, xed, _, _, theta, tau in cases(model, 16):
        if not known:
            theta = theta.copy()
            theta[friction_index(model, param_index)] = 0.0
            assert not model.StF(model.ik(xe), xed, theta).any(), "friction is not linear in theta"
        info = fmt(xe=xe, xed=xed, tau_a=tau, theta=theta)
        tips, Aq, q = _xedd_lagrange(model, xe, xed, tau, theta)
        check("hand A vs m.A", model.A(q), Aq, TOL_EXACT, maxabs(Aq), info, model)
        got = model.forward_dynamics(xe, xed, tau, theta)
        scale = max(maxabs(tips[0]), 1.0)  # m/s^2; |xedd| is O(1..1e3) here
        check("forward_dynamics vs Lagrange (tip 1)", got, tips[0], TOL_KKT, scale, info, model)
        # the constraint acceleration holds: all tips accelerate together
        for i in range(1, n):
            check("Lagrange tip i = tip 1", tips[i], tips[0], TOL_KKT, scale, f"leg {i + 1}, {info}",
                  model)


def test_forward_dynamics_at_rest_without_torque_is_friction_only(model, sample_xe, param_index):
    """xed = 0, tau = 0: Me xedd = -S^T f_a(0) = 0 (sign(0) = 0: f_a(0) = 0 for every law)."""
    n = model.n_legs
    theta = np.array(model.theta_nominal)
    fa0 = friction_typed(model, np.zeros(n), theta)
    if fa0 is None:
        pytest.skip(f"no hand-typed law for friction {model.spec.friction!r} in this test")
    for xe in sample_xe(model, 17, 10):
        q = model.ik(xe)
        Me, S = model.Me(q, theta), model.S(q)
        want = np.linalg.solve(Me, -S.T @ fa0)
        # scale: what friction of the size of the largest friction parameter would give (so
        # that a zero expected value, the smooth sign, is still checked at a meaningful size)
        fmax = maxabs(theta[friction_index(model, param_index)])
        scale = np.linalg.norm(np.linalg.inv(Me), np.inf) * maxabs(S) * n * fmax
        check("forward_dynamics at rest", model.forward_dynamics(xe, np.zeros(2), np.zeros(n), theta),
              want, TOL_EXACT, scale, fmt(xe=xe), model)


# --------------------------------------------------------------------------------------
# 5'. sign(0) = 0 in the friction of the regressor (paper only: eq. 2, its geometry)
# --------------------------------------------------------------------------------------

def _pose_with_qb1_zero(m):
    """A closed pose whose passive link 1 points exactly along +x (qb_1 = 0.0 exactly).

    Then cos(qb_1) = 1 and sin(qb_1) = 0 exactly, S[0] = (1, 0)/(l sin(qb_1 - qa_1)) has an
    exact zero, and xed = (0, v) gives qd_a1 = S[0] . xed = 0 exactly however the generated
    code groups the products: the only way to get an exactly zero active velocity at a
    genuine (closed) pose, independent of the expression tree.
    """
    qa1 = -0.3  # rad; O = A1 + l u(qa1) + l (1, 0) is inside the workspace
    xe = BASES[0] + L * np.array([np.cos(qa1), np.sin(qa1)]) + np.array([L, 0.0])
    q = m.ik(xe)
    assert abs(q[0] - qa1) < 1e-12 and abs(q[3]) < 1e-12, f"unexpected ik branch {q} at xe={xe}"
    q[0], q[3] = qa1, 0.0  # exact; H(q) stays ~1e-16 m
    return xe, q


@pytest.mark.parametrize("speed", [0.3, 1e-3, 2.0 ** -30])
def test_Y_friction_uses_sign_zero_zero(m, speed):
    xe, q = _pose_with_qb1_zero(m)
    S = m.S(q)
    assert S[0, 1] == 0.0, f"S[0] = {S[0]} is not axis-aligned at q={q}"
    # xed proportional to the perpendicular of S[0]: qd_a1 = 0 exactly
    xed = speed * np.array([-S[0, 1], S[0, 0]]) / abs(S[0, 0])
    assert S[0] @ xed == 0.0
    Yq = m.Y(q, xed, np.zeros(2), np.zeros(2))
    info = fmt(q=q, xed=xed, S=S)
    # columns: 9..11 = fv_i -> S[i] qd_ai; 12..14 = fc_i -> S[i] sign(qd_ai)
    v = S @ xed
    assert v[0] == 0.0
    np.testing.assert_array_equal(Yq[:, 9], S[0] * 0.0, err_msg=f"fv1 column at {info}")
    np.testing.assert_array_equal(Yq[:, 12], S[0] * 0.0, err_msg=f"fc1 column: sign(0) must be 0 at {info}")
    for i in (1, 2):  # the other legs move: their sign is the sign of qd_ai
        assert v[i] != 0.0
        check(f"Y fc{i + 1} column", Yq[:, 12 + i], np.sign(v[i]) * S[i], TOL_EXACT, maxabs(S[i]), info,
              m)
    # and StF: f_a1 = 0 at zero velocity
    theta = np.array(m.theta_nominal)
    fa = np.sign(v) * theta[12:15] + theta[9:12] * v
    check("StF at qd_a1 = 0", m.StF(q, xed, theta), S.T @ fa, TOL_EXACT,
          maxabs(S) * maxabs(fa) * 3, info, m)
    # the reference agrees (it has its own sign(0) = 0)
    check("Y at qd_a1 = 0 vs reference", Yq, ref.Y(ref.Geometry.paper(), q, xed, np.zeros(2),
                                                   np.zeros(2)), TOL_EXACT, maxabs(Yq), info, m)
    # a tiny velocity either way gives the fc1 column its sign
    Yneg = m.Y(q, xed + np.array([-1e-9, 0.0]) * np.sign(S[0, 0]), np.zeros(2), np.zeros(2))
    np.testing.assert_array_equal(Yneg[:, 12], -S[0], err_msg=f"fc1 column at qd_a1 < 0, {info}")
    Ypos = m.Y(q, xed + np.array([1e-9, 0.0]) * np.sign(S[0, 0]), np.zeros(2), np.zeros(2))
    np.testing.assert_array_equal(Ypos[:, 12], S[0], err_msg=f"fc1 column at qd_a1 > 0, {info}")


def test_Y_friction_perpendicular_xed_generic_poses(m, sample_xe):
    """xed = c * perp(S[i]) at generic poses: qd_ai = 0 up to rounding of the C's own S xed.

    The exact-zero case is above; here the fc_i column must be +-S[i] (qd_ai rounds to a tiny
    nonzero: its sign) or exactly 0 (qd_ai rounds to 0: sign(0) = 0), and the fv_i column ~0,
    i.e. the perpendicular direction really makes leg i's active joint still.
    """
    for k, xe in enumerate(sample_xe(m, 13, 10)):
        q = m.ik(xe)
        S = m.S(q)
        for i in range(3):
            xed = 0.25 * np.array([-S[i, 1], S[i, 0]])  # 0.25 = 2^-2: exact scaling
            Yq = m.Y(q, xed, np.zeros(2), np.zeros(2))
            info = fmt(xe=xe, leg=i + 1, xed=xed)
            check(f"Y fv{i + 1} column at perp xed", Yq[:, 9 + i], np.zeros(2), TOL_EXACT,
                  maxabs(S[i]) ** 2 * maxabs(xed), info, m)
            fc = Yq[:, 12 + i]
            assert (np.allclose(np.abs(fc), np.abs(S[i]), rtol=0, atol=1e-15 * maxabs(S[i]))
                    or not np.any(fc)), info


# --------------------------------------------------------------------------------------
# 8. Errors (the paper's robot, except the singular-pose guard: every model)
# --------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def singular_q(model, sample_xe):
    """A q of the model with the first leg that has a type I singularity at it
    (docs/model-file.md): RRR qb_i = qa_i (stretched, sin(qb_i - qa_i) = 0 exactly), PRR
    qb_i across the rail (d . u(qb_i) = 0 to rounding); None if every leg is RPR (none)."""
    n = model.n_legs
    q = model.ik(sample_xe(model, 0, 1)[0]).copy()
    for i, leg in enumerate(model.spec.legs):
        if leg.kind == "RRR":
            q[n + i] = q[i]
            return q
        if leg.kind == "PRR":
            d = rail_direction(leg)
            q[n + i] = np.arctan2(d[1], d[0]) + np.pi / 2
            return q
    return None


@pytest.mark.parametrize("call", [
    lambda m, q, v: m.W(q),
    lambda m, q, v: m.S(q),
    lambda m, q, v: m.Wdot(q, v),
    lambda m, q, v: m.Me(q, m.theta_nominal),
    lambda m, q, v: m.Ce(q, v, m.theta_nominal),
    lambda m, q, v: m.StF(q, v, m.theta_nominal),
    lambda m, q, v: m.Y(q, v, v[::-1], 10 * v),
], ids=["W", "S", "Wdot", "Me", "Ce", "StF", "Y"])
def test_singular_pose_raises(model, singular_q, call):
    """Every model with a leg that can be singular (paper-independent: the runtime's
    singularity guard); v (m,) a task velocity."""
    if singular_q is None:
        pytest.skip(f"{model.name}: RPR legs have no type I singularity (docs/model-file.md)")
    v = np.linspace(0.1, 0.2, model.dof)
    with pytest.raises(pm2dof.SingularityError, match="singularity"):
        call(model, singular_q, v)


def test_singularity_threshold_is_enforced(m):
    """Just below the threshold raises, just above does not (leg 1's sin set directly)."""
    q = m.ik([0.25, 0.26]).copy()
    thr = m.singularity_threshold
    for s, raises in ((0.5 * thr, True), (0.99 * thr, True), (1.01 * thr, False)):
        q[3] = q[0] + np.arcsin(s)
        assert abs(m.singularity(q)[0] - s) < 1e-15
        if raises:
            with pytest.raises(pm2dof.SingularityError):
                m.W(q)
        else:
            m.W(q)


def test_singularity_error_is_a_value_error():
    assert issubclass(pm2dof.SingularityError, ValueError)
    assert issubclass(pm2dof.WorkspaceError, ValueError)


def test_forward_dynamics_near_singular_xe_raises(m):
    # distance 0.4879 m from A1 = (0, 0.25): leg 1 almost stretched, |sin| ~ 0.04 < 0.1
    with pytest.raises(pm2dof.SingularityError):
        m.forward_dynamics([0.4879, 0.25], [0.0, 0.0], [0.0, 0.0, 0.0], m.theta_nominal)


@pytest.mark.parametrize("xe, leg", [([0.6, 0.25], 1), ([0.3, 0.0], 3), ([0.2, 0.45], 2),
                                     ([0.9, 0.25], 1), ([0.0, 0.8], 1)])
def test_ik_unreachable_raises_workspace_error_naming_leg(m, xe, leg):
    # [0.0, 0.8]: legs 1 and 2 are both out of reach; the first one is named
    first = next(i + 1 for i in range(3) if np.hypot(*(np.array(xe) - BASES[i])) > 2 * L)
    assert first == leg
    with pytest.raises(pm2dof.WorkspaceError, match=f"leg {leg}"):
        m.ik(xe)


@pytest.mark.parametrize("xe, leg", [([0.6, 0.25], 1), ([0.3, 0.0], 3), ([0.9, 0.25], 1)])
def test_forward_dynamics_unreachable_raises_workspace_error(m, xe, leg):
    """forward_dynamics at an xe some leg cannot reach must raise, never return NaN."""
    try:
        out = m.forward_dynamics(xe, [0.1, 0.0], [0.1, 0.2, 0.3], m.theta_nominal)
    except pm2dof.WorkspaceError as exc:
        assert f"leg {leg}" in str(exc)
    else:
        pytest.fail(f"forward_dynamics(xe={xe}) returned {out} instead of raising WorkspaceError "
                    f"(leg {leg} is out of reach)")


@pytest.mark.parametrize("call, name", [
    (lambda m, q: m.W([np.nan, *q[1:]]), "q"),
    (lambda m, q: m.W(np.r_[q[:5], np.inf]), "q"),
    (lambda m, q: m.ik([np.nan, 0.25]), "xe"),
    (lambda m, q: m.fk([0.1, np.nan, 0.2]), "qa"),
    (lambda m, q: m.Y(q, [0.1, np.inf], [0, 0], [0, 0]), "xed"),
    (lambda m, q: m.Y(q, [0.1, 0.1], [np.nan, 0], [0, 0]), "xrd"),
    (lambda m, q: m.Y(q, [0.1, 0.1], [0, 0], [0, np.nan]), "xrdd"),
    (lambda m, q: m.Me(q, np.r_[np.nan, m.theta_nominal[1:]]), "theta"),
    (lambda m, q: m.forward_dynamics([0.25, 0.26], [0, 0], [0, np.nan, 0], m.theta_nominal), "tau_a"),
], ids=["W-q-list", "W-q-inf", "ik-xe", "fk-qa", "Y-xed", "Y-xrd", "Y-xrdd", "Me-theta",
        "fd-tau_a"])
def test_nonfinite_input_raises_value_error_naming_input(m, call, name):
    q = m.ik([0.25, 0.26])
    with pytest.raises(ValueError, match=rf"\b{name}\b") as exc:
        call(m, q)
    assert not isinstance(exc.value, (pm2dof.SingularityError, pm2dof.WorkspaceError)), exc.value


@pytest.mark.parametrize("call, name", [
    (lambda m, q: m.W(q[:5]), "q"),
    (lambda m, q: m.W(np.r_[q, 0.0]), "q"),
    (lambda m, q: m.ik([0.25, 0.26, 0.0]), "xe"),
    (lambda m, q: m.fk(q[:2]), "qa"),
    (lambda m, q: m.Me(q, m.theta_nominal[:14]), "theta"),
    (lambda m, q: m.Y(q, [0.1], [0, 0], [0, 0]), "xed"),
    (lambda m, q: m.forward_dynamics([0.25, 0.26], [0, 0], [0, 0], m.theta_nominal), "tau_a"),
    (lambda m, q: m.C(q, np.zeros(5), m.theta_nominal), "qd"),
], ids=["W-short", "W-long", "ik", "fk", "Me-theta", "Y-xed", "fd-tau_a", "C-qd"])
def test_wrong_length_raises_value_error_naming_input(m, call, name):
    q = m.ik([0.25, 0.26])
    with pytest.raises(ValueError, match=rf"\b{name}\b"):
        call(m, q)


@pytest.mark.parametrize("bad", [np.empty((2, 6)), np.empty(12), np.empty((6, 3)),
                                 np.empty((12, 2))[::2], np.asfortranarray(np.empty((6, 2)))],
                         ids=["transposed", "flat", "too-wide", "strided", "fortran"])
def test_wrong_out_raises_value_error(m, bad):
    q = m.ik([0.25, 0.26])
    with pytest.raises(ValueError, match="out|W"):
        m.W(q, out=bad)


def test_wrong_out_dtype_raises(m):
    q = m.ik([0.25, 0.26])
    with pytest.raises((TypeError, ValueError)):
        m.W(q, out=np.empty((6, 2), dtype=np.float32))


def test_lists_and_other_dtypes_are_accepted(m):
    xe = [0.25, 0.26]
    q = m.ik(np.array(xe))
    theta = np.array(m.theta_nominal)
    np.testing.assert_array_equal(m.ik(xe), q)
    np.testing.assert_array_equal(m.ik((0.25, 0.26)), q)
    np.testing.assert_array_equal(m.W(q.tolist()), m.W(q))
    np.testing.assert_array_equal(m.fk(list(q[:3])), m.fk(q[:3]))
    np.testing.assert_array_equal(m.Y(list(q), [0.1, 0.2], [0, 1], [1, 0]),
                                  m.Y(q, np.array([0.1, 0.2]), np.array([0.0, 1.0]), np.array([1.0, 0.0])))
    np.testing.assert_array_equal(m.Me(q, theta.tolist()), m.Me(q, theta))
    np.testing.assert_array_equal(m.forward_dynamics(xe, [0, 0], [1, 2, 3], list(theta)),
                                  m.forward_dynamics(np.array(xe), np.zeros(2), np.array([1.0, 2, 3]), theta))
    qa32 = q[:3].astype(np.float32)
    np.testing.assert_array_equal(m.fk(qa32), m.fk(qa32.astype(np.float64)))
    qs = np.empty(12)
    qs[::2] = q  # a strided view
    np.testing.assert_array_equal(m.W(qs[::2]), m.W(q))


# --------------------------------------------------------------------------------------
# 9. API contract (the paper's robot: Tables 1-2, Sect. 2; output shapes: every model)
# --------------------------------------------------------------------------------------

PARAM_NAMES = ("alpha1", "alpha2", "alpha3", "beta1", "beta2", "beta3", "gamma1", "gamma2",
               "gamma3", "fv1", "fv2", "fv3", "fc1", "fc2", "fc3")
# docs/paper.md (the paper's Sect. 5), Tables 1 and 2, in the order of PARAM_NAMES
TABLE1_ALPHA = (0.0932, 0.0427, 0.0427)
TABLE1_BETA = (0.0381, 0.0085, 0.0085)
TABLE1_GAMMA = (0.0426, 0.0111, 0.0111)
TABLE2_FV = (2.9936, 2.7617, 2.8771)
TABLE2_FC = (0.4976, 0.4570, 0.3006)


def test_param_names(m):
    assert tuple(m.param_names) == PARAM_NAMES


def test_theta_nominal_is_tables_1_2(m):
    want = np.array(TABLE1_ALPHA + TABLE1_BETA + TABLE1_GAMMA + TABLE2_FV + TABLE2_FC)
    assert m.theta_nominal.shape == (15,)
    np.testing.assert_array_equal(m.theta_nominal, want)


def test_geometry_attributes(m):
    assert m.n_legs == 3
    np.testing.assert_array_equal(m.bases, [[0, 0.25], [0.433, 0], [0.433, 0.5]])
    assert m.bases.shape == (3, 2)


def test_output_shapes(model, sample_xe, param_index):
    n, p, m = model.n_legs, len(model.param_names), model.dof
    assert m == len(model.task_names) == (3 if model.spec.end_effector == "platform" else 2)
    h = 2 * n if model.spec.end_effector == "platform" else 2 * (n - 1)     # rows of H, eq. 5
    xe = sample_xe(model, 0, 1)[0]
    q = model.ik(xe)
    th = np.array(model.theta_nominal)
    z = np.zeros(m)
    shapes = {
        "ik": (model.ik(xe), (2 * n,)),
        "fk": (model.fk(q[:n]), (m,)),
        "H": (model.H(q), (h,)),
        "A": (model.A(q), (h, 2 * n)),
        "singularity": (model.singularity(q), (n,)),
        "W": (model.W(q), (2 * n, m)),
        "Wdot": (model.Wdot(q, z), (2 * n, m)),
        "S": (model.S(q), (n, m)),
        "M": (model.M(q, th), (2 * n, 2 * n)),
        "C": (model.C(q, np.zeros(2 * n), th), (2 * n, 2 * n)),
        "Me": (model.Me(q, th), (m, m)),
        "Ce": (model.Ce(q, z, th), (m, m)),
        "StF": (model.StF(q, z, th), (m,)),
        "Ge": (model.Ge(q, th), (m,)),
        "Y": (model.Y(q, z, z, z), (m, p)),
        "forward_dynamics": (model.forward_dynamics(xe, z, np.zeros(n), th), (m,)),
    }
    # theta: one value of each kind (alpha, beta, gamma, friction, a first moment kappa under
    # gravity ...) per leg, and a platform's four body parameters (no leg number)
    idx = param_index(model)
    kinds = {k for k, i in idx if i is not None}
    body = {k for k, i in idx if i is None}
    assert body == (set(PLATFORM_PARAMS) if model.spec.end_effector == "platform" else set())
    assert {"alpha", "beta", "gamma"} <= kinds and len(th) == p == len(idx)
    assert p == n * len(kinds) + len(body)
    assert set(idx) == {(k, i) for k in kinds for i in range(n)} | {(k, None) for k in body}
    for name, (val, shape) in shapes.items():
        assert isinstance(val, np.ndarray) and val.dtype == np.float64, f"{model.name}: {name}"
        assert val.shape == shape, f"{model.name}: {name}: shape {val.shape} != {shape}"


def test_model_is_immutable():
    m = pm2dof.load_model()  # its own instance: a failure here must not break other tests
    for attr, value in [("n_legs", 4), ("theta_nominal", np.zeros(15)), ("spec", None),
                        ("manifest", {}), ("library", "x"), ("new_attribute", 1), ("W", None)]:
        with pytest.raises(AttributeError):
            setattr(m, attr, value)
    for attr in ("spec", "manifest", "_f", "theta_nominal"):
        with pytest.raises(AttributeError):
            delattr(m, attr)
    with pytest.raises(ValueError):  # read-only arrays
        m.theta_nominal[0] = 1.0
    with pytest.raises(ValueError):
        m.bases[0, 0] = 1.0
    np.testing.assert_array_equal(m.bases, [[0, 0.25], [0.433, 0], [0.433, 0.5]])
    np.testing.assert_array_equal(m.theta_nominal[:1], [0.0932])


def test_out_is_written_in_place_and_returned(m):
    xe = np.array([0.25, 0.26])
    q = m.ik(xe)
    th = np.array(m.theta_nominal)
    xed = np.array([0.1, -0.2])
    for name, args, shape in [("ik", (xe,), (6,)), ("fk", (q[:3],), (2,)), ("W", (q,), (6, 2)),
                              ("Wdot", (q, xed), (6, 2)), ("Me", (q, th), (2, 2)),
                              ("Ce", (q, xed, th), (2, 2)), ("StF", (q, xed, th), (2,)),
                              ("Y", (q, xed, xed, xed), (2, 15)),
                              ("forward_dynamics", (xe, xed, np.ones(3), th), (2,))]:
        f = getattr(m, name)
        buf = np.full(shape, np.nan)
        res = f(*args, out=buf)
        assert res is buf, f"{name}: out= is not returned"
        np.testing.assert_array_equal(buf, f(*args), err_msg=name)
        fresh1, fresh2 = f(*args), f(*args)
        assert fresh1 is not fresh2, f"{name}: returns a shared buffer without out="
    # with lists as inputs (the slow conversion path) out= still works
    buf = np.empty((6, 2))
    assert m.W(q.tolist(), out=buf) is buf
    np.testing.assert_array_equal(buf, m.W(q))
