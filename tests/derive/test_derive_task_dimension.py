# Every generated function follows the task dimension m: a synthetic m = 3 platform through derive.
"""``pm2dof.derive`` must not hard-code the task dimension. The toy platform of
``toy_platform.py`` (m = 3: x, y, phi; four legs, two prismatic actuators, gravity) goes
through the whole derivation (:func:`pm2dof.derive.run.derive_functions`, every generated
function, and :func:`pm2dof.derive.run.derive_layouts`), as CasADi functions (no C compiled):

* every input and output, and every layout field, has the size the task dimension gives it
  (one table for all; the same table holds for the paper's robot, m = 2, which checks it);
* the functions agree with the toy's SymPy matrices evaluated directly (lambdify, float64):
  forward and inverse dynamics with gravity, the controller steps' task force S^T tau_a, the
  plant, the path coefficients and torques, the energies; the Jacobians agree with central
  differences of the functions they differentiate;
* T + V is conserved along the generated forward dynamics with torque and friction zero
  (RK4, h = 1 ms: drift ~h^4), which ties the gravity term, Ce and the energies together.

The toy's platform terms name the pose phi directly (not only through q), so functions of q
(``Me``, ``Ge``) bind it by fk and the Jacobians add its partial derivative.
"""
import casadi as ca
import numpy as np
import pytest
import toy_platform

from pm2dof.core.model_file import read_model_file
from pm2dof.core.paths import SHIPPED_MODELS
from pm2dof.derive.planning import facet_count
from pm2dof.derive.run import derive_functions, derive_layouts
from tests import derivations

pytestmark = pytest.mark.slow     # derives a toy platform with SymPy: make test-slow (CI)

XE = np.array([0.3, 0.4, 0.2])
XED = np.array([0.2, -0.3, 0.5])


def _derive(d):
    fs = derivations.functions(d, d.spec)     # the paper's: shared (tests/derivations.py)
    prefix = d.spec.name + "_"
    return {f.name()[len(prefix):]: f for f in fs}, derive_layouts(d)


@pytest.fixture(scope="module")
def toy():
    d = toy_platform.derivation()
    fs, lay = _derive(d)
    return d, fs, lay


@pytest.fixture(scope="module")
def paper():
    d = derivations.derivation(read_model_file(SHIPPED_MODELS / "shang2010.toml"))  # shared
    fs, lay = _derive(d)
    return d, fs, lay


def _law(name):
    return name.split("_")[0]


def _expected(name, arg, d, lay):
    """The size of input/output ``arg`` of generated function ``name`` for n legs, task
    dimension m, p parameters, F facets."""
    n, m, p = d.spec.n_legs, d.m, len(d.spec.param_names)
    F = facet_count(n, m)
    size = {k: v.size for k, v in lay.items()}
    if name.endswith("_closed_loop"):
        law = _law(name)
        return {"x": size["cl_state"], "x_next": size["cl_state"], "y": size["cl_output"],
                "u": size.get(f"{law}_cl_input", size["cl_input"]),
                "p": size[f"{law}_params"] + size["plant"]}[arg]
    if name.endswith("_step") and name not in ("plant_step", "sampled_step"):
        own = {"state": size["ctrl_state"], "state_next": size["ctrl_state"],
               "params": size[f"{_law(name)}_params"], "diag": 4 * m + 2, "status": 1,
               "K": 2 * m * n, "tau_ff": n}
        if arg in own:
            return own[arg]
    if name.startswith("path_"):
        own = {"stage": size["path_stage"], "pair": size["path_pair"],
               "input": size[f"{name}_input"] if name in ("path_backward", "path_forward")
               else size["path_forward_input"], "params": size["path_params"],
               "p": m, "x": 1, "x_next": 1, "x_next_max": 1, "x_max": 1, "x_mvc": 1,
               "y": size["path_forward_output"] if name == "path_forward" else 1,
               "u": m, "S": n * m}
        if arg in own:
            return own[arg]
    if name in ("plant_step", "sampled_step", "sampled_step_jacobians"):
        own = {"x": 2 * m, "x_next": 2 * m, "d_x": 4 * m * m, "d_tau_a": 2 * m * n}
        if arg in own:
            return own[arg]
    common = {
        "xe": m, "xed": m, "xrd": m, "xrdd": m, "xedd": m, "xd": m, "xd_dot": m, "xd_ddot": m,
        "u": m, "a": m, "b": m, "g": m, "Ge": m, "StF": m, "dp": m, "ddp": m,
        "Me": m * m, "Ce": m * m, "d_xe": m * m, "d_xed": m * m, "d_tau_a": m * n,
        "d_theta": m * p, "Y": m * p, "W": 2 * n * m, "Wdot": 2 * n * m, "S": n * m,
        "H": 2 * n - m, "A": (2 * n - m) * 2 * n,       # 2n - m closure constraints (eq. 5)
        "q": 2 * n, "qd": 2 * n, "M": 4 * n * n, "C": 4 * n * n, "qa": n, "tau_a": n,
        "tau_max": n, "preload": n, "preload_sign": n, "tau_min_norm": n, "tau_min_max": n,
        "tau_preload": n, "sin_ab": n, "residual": n, "v1": n, "theta": p, "plant": size["plant"],
        "N_min_norm": F * m, "N_min_max": F * m, "h_min_norm": F, "h_min_max": F,
        "sing": 2, "T": 1, "V": 1, "h": 1, "sd": 1, "sdd": 1, "min_max_ratio": 1,
        "preload_mode": 1,
    }
    return common[arg]


def _layout_expected(field, d, lay):
    n, m, p = d.spec.n_legs, d.m, len(d.spec.param_names)
    F = facet_count(n, m)
    size = {k: v.size for k, v in lay.items()}
    task = {"xe_prev", "v", "Kd", "Q", "Kp", "Kv", "xe", "xed", "xd", "xd_dot", "xd_ddot",
            "a", "b", "g"}
    if field in task:
        return m
    return {"K": 2 * m * n, "N": F * m, "h": F, "S": n * m, "ctrl_state": size["ctrl_state"],
            "stage": size["path_stage"], "next": size["path_stage"], "pair": size["path_pair"],
            "theta_hat": p, "theta": p, "Gamma": p}.get(field)


@pytest.mark.parametrize("which", ["toy", "paper"])
def test_every_generated_size_follows_the_task_dimension(which, request):
    d, fs, lay = request.getfixturevalue(which)
    assert d.m == (3 if which == "toy" else 2)
    for name, f in fs.items():
        for side, count, arg_name, sparsity in (("in", f.n_in(), f.name_in, f.sparsity_in),
                                                ("out", f.n_out(), f.name_out, f.sparsity_out)):
            for i in range(count):
                arg = arg_name(i)
                assert sparsity(i).numel() == _expected(name, arg, d, lay), (name, side, arg)
    for lname, layout in lay.items():
        for field, k in layout.fields:
            want = _layout_expected(field, d, lay)
            if want is not None:
                assert k == want, (lname, field)
    # the task-space gains and the stage's gravity force exist with the model's dimension
    assert dict(lay["na_params"].fields)["Kd"] == d.m
    assert ("g" in dict(lay["path_stage"].fields)) == (which == "toy")


# ---------------------------------------------------------------------------------------------
# the toy's functions against its SymPy matrices

class _Ref:
    """The toy's SymPy expressions evaluated directly (float64), at q = ik(xe)."""

    def __init__(self, d):
        sym, kin, dyn = d.sym, d.kin, d.dyn
        args = list(sym.q) + list(sym.xe) + list(sym.xed) + list(sym.theta) + list(sym.tau_a)
        self.d = d
        mods = [{"sgn": np.sign}, "numpy"]
        self._ik = derivations.plain_lambdify(list(sym.xe), kin.ik(), mods)
        self._f = {name: derivations.plain_lambdify(args, expr, mods) for name, expr in
                   (("Me", dyn.Me), ("Ce", dyn.Ce), ("Ge", dyn.Ge), ("StF", dyn.StF),
                    ("S", kin.S), ("W", kin.W))}
        self._T = derivations.plain_lambdify(
            args, dyn.T.subs(dict(zip(sym.qd, kin.W * sym.xed))), mods)
        self._V = derivations.plain_lambdify(args, dyn.V, mods)

    def q(self, xe):
        return np.asarray(self._ik(*xe), dtype=float).ravel()

    def __call__(self, name, xe, xed, theta, tau=None):
        tau = np.zeros(toy_platform.N_LEGS) if tau is None else tau
        f = {"T": self._T, "V": self._V}.get(name) or self._f[name]
        return np.asarray(f(*self.q(xe), *xe, *xed, *theta, *tau), dtype=float)

    def task_force(self, xe, xed, xedd, theta):
        """Me xedd + Ce xed + S^T f_a + Ge (eqs. 10-12 with gravity)."""
        return (self("Me", xe, xed, theta) @ xedd + self("Ce", xe, xed, theta) @ xed
                + self("StF", xe, xed, theta).ravel() + self("Ge", xe, xed, theta).ravel())


def _theta(d, friction=True, seed=0):
    rng = np.random.default_rng(seed)
    out = []
    for name in d.spec.param_names:
        base = name.rstrip("0123456789")
        out.append({"alpha": 0.2, "gamma": 0.1, "beta": 0.05, "mp": 2.0, "mx": 0.2, "Ip": 0.3}.get(base)
                   or (rng.uniform(-0.2, 0.2) if base == "lg" else
                       rng.uniform(0.1, 1.0) * friction))
    return np.array(out, dtype=float)


def _v(x):
    return np.asarray(x, dtype=float).ravel()


def test_toy_dynamics_agree_with_the_sympy_matrices(toy):
    d, fs, _ = toy
    ref, th = _Ref(d), _theta(d)
    n = d.spec.n_legs
    q = ref.q(XE)
    tau = np.array([3.0, -2.0, 1.5, 0.5])
    xedd = _v(fs["forward_dynamics"](XE, XED, tau, th)[0])
    S = ref("S", XE, XED, th)
    np.testing.assert_allclose(ref.task_force(XE, XED, xedd, th), S.T @ tau, rtol=1e-10, atol=1e-10)
    assert np.abs(ref("Ge", XE, XED, th)).max() > 1, "the toy's gravity must be exercised"
    # model functions of q, and the inverse dynamics / its Jacobian functions
    np.testing.assert_allclose(_v(fs["Me"](q, th)[0]), ref("Me", XE, XED, th).ravel(), rtol=1e-12)
    np.testing.assert_allclose(_v(fs["Ge"](q, th)[0]), ref("Ge", XE, XED, th).ravel(), rtol=1e-12)
    np.testing.assert_allclose(_v(fs["W"](q)[0]), ref("W", XE, XED, th).ravel(), rtol=1e-12)
    np.testing.assert_allclose(_v(fs["ik"](XE)), q, rtol=1e-14)
    xe_fk, residual = fs["fk"](q[:n])
    np.testing.assert_allclose(_v(xe_fk), XE, rtol=1e-13)
    assert np.abs(_v(residual)).max() < 1e-13
    u = _v(fs["inverse_dynamics"](XE, XED, xedd, th)[0])
    np.testing.assert_allclose(u, S.T @ tau, rtol=1e-10)
    np.testing.assert_allclose(_v(fs["forward_dynamics_jacobians"](XE, XED, tau, th)[0]), xedd,
                               rtol=1e-10)
    # energies: T = 1/2 xed^T Me xed, V of the toy
    T = float(fs["kinetic_energy"](XE, XED, th))
    assert T == pytest.approx(0.5 * XED @ ref("Me", XE, XED, th) @ XED, rel=1e-12)
    assert T == pytest.approx(float(ref("T", XE, XED, th)), rel=1e-12)
    assert float(fs["potential_energy"](XE, th)) == pytest.approx(float(ref("V", XE, XED, th)),
                                                                  rel=1e-12)
    # torque splits of the model functions deliver u
    r = fs["torque_splits"](q, u, np.full(n, 1e3), np.ones(n), np.full(n, 0.01))
    for k in (0, 1, 3):
        np.testing.assert_allclose(S.T @ _v(r[k]), u, rtol=1e-10, atol=1e-10)


def _central(f, x, k, h=1e-6):
    e = np.zeros_like(x)
    e[k] = h
    return (f(x + e) - f(x - e)) / (2 * h)


def test_toy_jacobians_are_the_derivatives(toy):
    """d xedd / d xe through the prismatic coordinates' chain rule (d r / d xe = W rows), and
    the sampled step's Jacobian, against central differences."""
    d, fs, _ = toy
    th, tau = _theta(d), np.array([3.0, -2.0, 1.5, 0.5])
    m = d.m
    J = fs["forward_dynamics_jacobians"](XE, XED, tau, th)
    fd = lambda xe: _v(fs["forward_dynamics"](xe, XED, tau, th)[0])
    num = np.column_stack([_central(fd, XE, k) for k in range(m)])
    np.testing.assert_allclose(_v(J[1]).reshape(m, m), num, rtol=1e-6, atol=1e-6)
    ui = lambda xe: _v(fs["inverse_dynamics"](xe, XED, np.ones(m), th)[0])
    num = np.column_stack([_central(ui, XE, k) for k in range(m)])
    np.testing.assert_allclose(_v(fs["inverse_dynamics_jacobians"](XE, XED, np.ones(m), th)[1])
                               .reshape(m, m), num, rtol=1e-6, atol=1e-6)
    x0, T = np.r_[XE, XED], 0.002
    step = lambda x: _v(fs["sampled_step"](x, tau, th, T)[0])
    num = np.column_stack([_central(step, x0, k) for k in range(2 * m)])
    got = _v(fs["sampled_step_jacobians"](x0, tau, th, T)[1]).reshape(2 * m, 2 * m)
    np.testing.assert_allclose(got, num, rtol=1e-6, atol=1e-8)


def test_toy_energy_is_conserved_along_the_forward_dynamics(toy):
    d, fs, _ = toy
    th = _theta(d, friction=False)
    m, h = d.m, 1e-3
    tau = np.zeros(d.spec.n_legs)

    def f(z):
        return np.r_[z[m:], _v(fs["forward_dynamics"](z[:m], z[m:], tau, th)[0])]

    def energy(z):
        return float(fs["kinetic_energy"](z[:m], z[m:], th)) + float(fs["potential_energy"](z[:m], th))

    z = np.r_[XE, XED]
    E0, T0 = energy(z), float(fs["kinetic_energy"](z[:m], z[m:], th))
    for _ in range(300):
        k1 = f(z)
        k2 = f(z + h / 2 * k1)
        k3 = f(z + h / 2 * k2)
        k4 = f(z + h * k3)
        z = z + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    assert np.abs(z[:m] - XE).max() > 0.01, "the toy must move"
    assert abs(energy(z) - E0) <= 1e-9 * T0, (energy(z) - E0, T0)
    # and it is not conserved if gravity is left out of the dynamics: the check can fail
    V_change = float(fs["potential_energy"](z[:m], th)) - float(fs["potential_energy"](XE, th))
    assert abs(V_change) > 1e-4 * T0


def test_toy_plant_and_encoder(toy):
    """The plant (its inertial fields from theta's names, gravity) with its friction zero is
    the model's forward dynamics with friction zero; the encoder reads ik's active coordinates,
    prismatic ones included."""
    d, fs, lay = toy
    th = _theta(d, friction=False)
    P = lay["plant"]
    names = d.spec.param_names
    fields = {}
    for name, value in zip(names, th):
        base = name.rstrip("0123456789")
        fields.setdefault(base, []).append(value)
    vec = P.pack(**{k: np.array(fields[k]) for k, _ in P.fields if k in fields and k not in ("fv", "fc")},
                 fv=np.zeros(4), fc=np.zeros(4), fs=np.zeros(4), stribeck_velocity=1.0,
                 coulomb_smoothing_velocity=1.0, encoder_step=0.0,
                 linear_encoder_step=0.0)
    tau = np.array([3.0, -2.0, 1.5, 0.5])
    np.testing.assert_allclose(_v(fs["plant_xedd"](XE, XED, tau, vec)),
                               _v(fs["forward_dynamics"](XE, XED, tau, th)[0]), rtol=1e-10)
    np.testing.assert_allclose(_v(fs["measure"](XE, vec)), _Ref(d).q(XE)[:4], rtol=1e-14)
    x_next = _v(fs["plant_step"](np.r_[XE, XED], tau, vec, 0.001))
    assert x_next.shape == (6,) and np.all(np.isfinite(x_next))


def test_toy_controller_steps_deliver_the_model_task_force(toy):
    """At a sample with e = edot = 0 (xd = fk(qa), xd_dot = v, velocity filter off) NA, APD and
    CTC all ask for u = Me xd_ddot + Ce v + S^T f_a(v) + Ge (eqs. 13, 29, 40 with gravity), with
    every split; LQR gives its feedforward torque."""
    d, fs, lay = toy
    ref, th = _Ref(d), _theta(d)
    n, m = d.spec.n_legs, d.m
    qa = ref.q(XE)[:n]
    xdd = np.array([0.5, -0.2, 0.3])
    u_want = ref.task_force(XE, XED, xdd, th)
    S = ref("S", XE, XED, th)
    state = lay["ctrl_state"].pack(xe_prev=XE, v=XED, theta_hat=th)
    common = dict(T=0.002, vel_alpha=0.0, sing_threshold=0.0, parallel_sing_threshold=0.0,
                  tau_max=np.full(n, 1e4), preload_sign=np.ones(n), preload=np.full(n, 0.01),
                  closure_tol=1e-9)
    gains = {"na": dict(Kd=np.full(m, 5.0), Q=np.full(m, 2.0), Gamma=np.ones(len(th)),
                        freeze_saturated=0.0),
             "apd": dict(Kp=np.full(m, 5.0), Kv=np.full(m, 2.0)),
             "ctc": dict(Kp=np.full(m, 5.0), Kv=np.full(m, 2.0)), "lqr": {}}
    steps = [k for k in fs if k.endswith("_step") and _law(k) in gains]
    assert len(steps) == 15
    for name in steps:
        law = _law(name)
        params = lay[f"{law}_params"].pack(**gains[law], **common)
        extra = [np.arange(2 * m * n, dtype=float), np.array([1.0, -2.0, 3.0, -4.0])] \
            if law == "lqr" else []
        xd = XE + (np.array([0.01, -0.02, 0.03]) if law == "lqr" else 0)
        tau, state_next, status, diag = fs[name](state, qa, xd, XED, xdd, params, *extra)
        tau, diag = _v(tau), _v(diag)
        assert int(status) == 0, name
        np.testing.assert_allclose(diag[:m], XE, rtol=1e-13)
        if law == "lqr":   # u = S^T (tau_ff - K [xe - xd; v - xd_dot]), K (n, 2m) row-major
            K = extra[0].reshape(n, 2 * m)
            u_lqr = S.T @ (extra[1] - K @ np.r_[XE - xd, np.zeros(m)])
            np.testing.assert_allclose(S.T @ tau, u_lqr, rtol=1e-9, err_msg=name)
        else:
            np.testing.assert_allclose(S.T @ tau, u_want, rtol=1e-9, atol=1e-9, err_msg=name)


def test_toy_path_functions_carry_gravity(toy):
    d, fs, lay = toy
    ref, th = _Ref(d), _theta(d)
    n, m = d.spec.n_legs, d.m
    dp, ddp = np.array([0.6, 0.8, 0.5]), np.array([0.1, -0.2, 0.3])
    out = dict(zip([fs["path_coefficients"].name_out(i) for i in range(fs["path_coefficients"].n_out())],
                   fs["path_coefficients"](XE, dp, ddp, th, np.full(n, 20.0))))
    Me, Ge = ref("Me", XE, dp, th), ref("Ge", XE, dp, th).ravel()
    np.testing.assert_allclose(_v(out["a"]), Me @ dp, rtol=1e-12)
    np.testing.assert_allclose(_v(out["b"]), Me @ ddp + ref("Ce", XE, dp, th) @ dp, rtol=1e-10)
    np.testing.assert_allclose(_v(out["g"]), Ge, rtol=1e-12)
    F = facet_count(n, m)
    stage = lay["path_stage"].pack(N=_v(out["N_min_max"]), h=_v(out["h_min_max"]), a=_v(out["a"]),
                                   b=_v(out["b"]), g=_v(out["g"]), S=_v(out["S"]), v1=_v(out["v1"]),
                                   rho=np.zeros(n), delta=0.01, x_cap=1e6)
    assert lay["path_stage"].size == F * m + F + 3 * m + n * m + 2 * n + 2
    sd, sdd = 0.3, 0.2
    params = lay["path_params"].pack(v_top=10.0, theta=th)
    u = _v(fs["path_torques"](stage, sd, sdd, params, np.full(n, 20.0))[0])
    np.testing.assert_allclose(u, ref.task_force(XE, dp * sd, dp * sdd + ddp * sd * sd, th),
                               rtol=1e-9)
    assert float(fs["path_mvc"](stage, params)) > 0


def test_paper_energies_and_no_gravity(paper):
    """The shipped (horizontal) robot: T = 1/2 xed^T Me xed, V = 0 and Ge = 0 (its C is
    unchanged by the gravity code: nothing is added where Ge is zero)."""
    d, fs, _ = paper
    theta = np.linspace(0.02, 0.1, len(d.spec.param_names))
    xed = np.array([0.3, -0.2])
    grid = [np.array([x, y]) for x in np.linspace(0.1, 0.4, 7) for y in np.linspace(0.1, 0.4, 7)]
    poses = [xe for xe in grid if np.all(np.isfinite(_v(fs["ik"](xe))))][:3]
    assert poses, "no reachable pose on the grid"
    for xe in poses:
        q = _v(fs["ik"](xe))
        Me = _v(fs["Me"](q, theta)[0]).reshape(2, 2)
        assert float(fs["kinetic_energy"](xe, xed, theta)) == pytest.approx(0.5 * xed @ Me @ xed,
                                                                            rel=1e-12)
        assert float(fs["potential_energy"](xe, theta)) == 0
        assert np.all(_v(fs["Ge"](q, theta)[0]) == 0)



def test_type_two_measure_in_three_dimensions(toy):
    """The least eigenvalue of a symmetric 3 x 3 matrix in closed form (the platform's type II
    measure) against LAPACK, isotropic and NaN matrices included; the toy's measures lie in
    [0, 1]."""
    from pm2dof.derive.model_functions import _least_eigenvalue
    G = ca.SX.sym("G", 3, 3)
    f = ca.Function("lam", [G], [_least_eigenvalue(G)])
    rng = np.random.default_rng(5)
    for k in range(200):
        U = rng.normal(size=(4, 3))
        if k % 3 == 0:
            U[:, 2] = U[:, 0] * rng.normal() + U[:, 1] * rng.normal()   # singular: lambda = 0
        A = U.T @ U
        assert float(f(A)) == pytest.approx(np.linalg.eigvalsh(A)[0], abs=1e-9 * np.trace(A))
    assert float(f(np.eye(3) * 2.5)) == pytest.approx(2.5, rel=1e-15)
    assert np.isnan(float(f(np.full((3, 3), np.nan))))
    d, fs, _ = toy
    sing = _v(fs["singularity_measures"](_Ref(d).q(XE)))
    assert np.all((sing > 0) & (sing <= 1)), sing


def test_other_task_dimensions_are_refused():
    import types

    from pm2dof.derive.run import DeriveError
    spec = types.SimpleNamespace(name="four", task_names=("x", "y", "z", "phi"))
    with pytest.raises(DeriveError, match="'four': task dimension 4"):
        derive_functions(types.SimpleNamespace(m=4, spec=spec), spec)



def test_manifest_names_the_task_coordinates(toy):
    import json

    from pm2dof.core.paths import SHIPPED_GENERATED
    from pm2dof.derive.run import task_names
    assert task_names(toy[0]) == ("x", "y", "phi")
    from pm2dof.core.model_file import read_model_file
    from pm2dof.core.paths import SHIPPED_MODELS
    for path in sorted(SHIPPED_GENERATED.glob("*/manifest.json")):
        spec = read_model_file(SHIPPED_MODELS / f"{path.parent.name}.toml")
        assert json.loads(path.read_text())["task_names"] == list(spec.task_names), path
