# Generated plant: truth dynamics with Stribeck friction, RK4 under a zero-order hold, encoder.
import casadi as ca
import sympy as sp

from pm2dof.core.contract import STEPS

from .controllers import controller_layouts, per_sample_inputs
from .factored import solve_small, task_gravity, task_inertia_coriolis
from .layouts import Layout

__all__ = ["plant_layout", "model_plant_layout", "inertial_fields", "plant_functions",
           "closed_loop_layouts", "closed_loop_functions"]


def inertial_fields(param_names, friction_names):
    """The plant's inertial fields from theta's names, in order: (base name, count), one entry
    per base name (trailing digits stripped: alpha1..alpha_n -> ("alpha", n)); friction
    parameters left out (the plant has its own friction law)."""
    fields = {}
    for name in param_names:
        base = name.rstrip("0123456789")
        if base not in friction_names:
            fields[base] = fields.get(base, 0) + 1
    return list(fields.items())


def _field_index(name):
    """(field, index) of a parameter name: 'gamma3' -> ('gamma', 2), 'mp' -> ('mp', 0)."""
    base = name.rstrip("0123456789")
    return base, (int(name[len(base):]) - 1 if len(base) < len(name) else 0)


def plant_layout(n, param_names, friction_names, linear=False):
    """Plant truth: the model's inertial parameters (:func:`inertial_fields`; the RR legs'
    alpha, beta, gamma), payload-augmented; friction with a Stribeck part; the encoder step
    of the angular actuators (rad) and, when some actuator is ``linear`` (PRR, RPR legs),
    that of the linear encoders (m)."""
    friction = [("fv", n), ("fc", n), ("fs", n), ("stribeck_velocity", 1),
                ("coulomb_smoothing_velocity", 1), ("encoder_step", 1)]
    return Layout(inertial_fields(param_names, friction_names) + friction
                  + ([("linear_encoder_step", 1)] if linear else []))


def model_plant_layout(spec):
    """:func:`plant_layout` of a model: its own inertial parameters."""
    from pm2dof.core.mechanism import FRICTION_MODELS
    linear = any(leg.kind != "RRR" for leg in spec.legs)
    return plant_layout(spec.n_legs, spec.param_names, FRICTION_MODELS[spec.friction], linear)


def closed_loop_layouts(n, p, m):
    """cl_state, cl_input (the desired motion), cl_output, and ``<law>_cl_input`` for a law
    whose step takes per-sample inputs (the desired motion, then those); task dimension m."""
    ctrl = controller_layouts(n, p, m)
    x = Layout([("xe", m), ("xed", m), ("ctrl_state", ctrl["ctrl_state"].size)])
    motion = [("xd", m), ("xd_dot", m), ("xd_ddot", m)]
    y = Layout([("xe", m), ("xed", m), ("tau_a", n), ("status", 1), ("theta_hat", p)])
    out = {"cl_state": x, "cl_input": Layout(motion), "cl_output": y}
    for law in dict.fromkeys(law for _, law, _ in STEPS):
        if per_sample_inputs(law, n, m):
            out[f"{law}_cl_input"] = Layout(motion + per_sample_inputs(law, n, m))
    return out


def _inertial_pairs(d, P):
    """(sympy symbols, SX) pairs binding theta's inertial parameters to the plant's fields."""
    from pm2dof.core.mechanism import FRICTION_MODELS
    pairs = []
    for base, count in inertial_fields(d.spec.param_names, FRICTION_MODELS[d.spec.friction]):
        syms = [None] * count
        for name in d.spec.param_names:
            b, k = _field_index(name)
            if b == base:
                if not 0 <= k < count or syms[k] is not None:
                    raise ValueError(f"parameter {name!r}: the plant layout needs {base}1.."
                                     f"{base}{count} (or one {base} without a number)")
                syms[k] = d.sym.param[name]
        pairs.append((sp.Matrix(syms), P[base]))
    return pairs


def plant_functions(d, prefix):
    """``<prefix>_plant_xedd``, ``<prefix>_plant_step`` (one RK4 step of h s), ``<prefix>_measure``."""
    n, m = d.spec.n_legs, d.m
    sym, kin = d.sym, d.kin
    lay = model_plant_layout(d.spec)
    xe, xed, tau = ca.SX.sym("xe", m), ca.SX.sym("xed", m), ca.SX.sym("tau_a", n)
    pp = ca.SX.sym("plant", lay.size)
    P = lay.split(pp)
    inertial = _inertial_pairs(d, P)
    conv = d.converter_xe(xe)
    Me, Ce_v, S, _ = task_inertia_coriolis(d, conv, xed, inertial)  # eq. 12
    va = S @ xed
    # truth friction: Coulomb smoothed over +-coulomb_smoothing_velocity (algebraic sign
    # v / sqrt(v^2 + eps^2)), Stribeck excess fs with a Lorentzian decay 1 / (1 + (v/vs)^2);
    # algebraic forms: a sqrt and a division instead of tanh and exp (4x cheaper here)
    eps2 = P["coulomb_smoothing_velocity"] ** 2
    smooth_sign = va / ca.sqrt(va * va + eps2)
    stribeck = P["fs"] / (1 + (va / P["stribeck_velocity"]) ** 2)
    fric = (P["fc"] + stribeck) * smooth_sign + P["fv"] * va
    rhs = S.T @ (tau - fric) - Ce_v                      # eq. 10 with the plant's friction
    Ge = task_gravity(d, conv, inertial)
    if Ge is not None:                                   # eq. 10 with gravity
        rhs = rhs - Ge
    xedd = solve_small(Me, rhs)
    f_xedd = d.function(f"{prefix}_plant_xedd", [xe, xed, tau, pp], [xedd],
                        ["xe", "xed", "tau_a", "plant"], ["xedd"])
    design = d.design_args(f_xedd, d.design_sx)
    x = ca.SX.sym("x", 2 * m)
    h = ca.SX.sym("h")

    def f(z):
        return ca.vertcat(z[m:2 * m], f_xedd(z[0:m], z[m:2 * m], tau, pp, *design))
    k1 = f(x)
    k2 = f(x + h / 2 * k1)
    k3 = f(x + h / 2 * k2)
    k4 = f(x + h * k3)
    x_next = x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)   # classical RK4
    f_step = d.function(f"{prefix}_plant_step", [x, tau, pp, h], [x_next],
                        ["x", "tau_a", "plant", "h"], ["x_next"])
    # encoder: the active coordinates of the true pose (angles from their unit vectors,
    # prismatic ones from the inverse kinematics), quantised to encoder_step, rad, or
    # linear_encoder_step, m (0: exact)
    cik = d.converter_xe(xe)
    ua = kin.unit_vectors_from_xe()
    qa_meas = []
    for i in range(n):
        if d.angular[i]:
            q, step = ca.atan2(cik(ua[sym.qa[i]][1]), cik(ua[sym.qa[i]][0])), P["encoder_step"]
        else:
            q, step = cik(sym.qa[i]), P["linear_encoder_step"]
        qa_meas.append(ca.if_else(step > 0, step * ca.floor(q / step + 0.5), q))
    qa_meas = ca.vertcat(*qa_meas)
    f_meas = d.function(f"{prefix}_measure", [xe, pp], [qa_meas], ["xe", "plant"], ["qa"])
    return [f_xedd, f_step, f_meas]


def closed_loop_functions(d, prefix, ctrl_fns, plant_fns, substeps):
    """``<prefix>_<law>_closed_loop(x, u, p) -> (x_next, y)``: one control sample.

    Measure qa from the true pose, run the controller step, hold its torque for ``substeps``
    RK4 steps of the plant. y records the true state at the sample, the torque, the status
    and theta_hat after the update. Shaped for pm2dof.core._cbind.Function.accumulate.
    """
    n, p, m = d.spec.n_legs, len(d.spec.param_names), d.m
    lay = closed_loop_layouts(n, p, m)
    ctrl_lay = controller_layouts(n, p, m)
    f_step, f_meas = plant_fns[1], plant_fns[2]
    out = []
    for step in ctrl_fns:
        name = step.name()[len(prefix) + 1:-len("_step")]          # e.g. na_proj_minmax
        law = name.split("_")[0]                                    # na, apd, ctc, lqr
        ulay = lay.get(f"{law}_cl_input", lay["cl_input"])
        x = ca.MX.sym("x", lay["cl_state"].size)
        u = ca.MX.sym("u", ulay.size)
        npar = ctrl_lay[f"{law}_params"].size
        prm = ca.MX.sym("p", npar + model_plant_layout(d.spec).size)
        X, U = lay["cl_state"].split(x), ulay.split(u)
        cp, pp = prm[:npar], prm[npar:]
        h = cp[ctrl_lay[f"{law}_params"].offsets()["T"][0]] / substeps  # zero-order hold
        # the [design] input of the functions called, one input of the closed loop
        dm = ca.MX.sym("design", d.design_sx.numel()) if d.design_sx is not None else None
        qa = f_meas(X["xe"], pp, *d.design_args(f_meas, dm))
        extra = [U[k] for k, _ in per_sample_inputs(law, n, m)]     # e.g. LQR's K_k, tau_ff_k
        tau, cs_next, status, _ = step(X["ctrl_state"], qa, U["xd"], U["xd_dot"], U["xd_ddot"], cp,
                                       *extra, *d.design_args(step, dm))
        z = ca.vertcat(X["xe"], X["xed"])
        for _ in range(substeps):
            z = f_step(z, tau, pp, h, *d.design_args(f_step, dm))
        x_next = ca.vertcat(z, cs_next)
        theta_hat = cs_next[ctrl_lay["ctrl_state"].offsets()["theta_hat"][0]:]
        y = lay["cl_output"].pack(xe=X["xe"], xed=X["xed"], tau_a=tau, status=status,
                                  theta_hat=theta_hat)
        ins, names_in = [x, u, prm], ["x", "u", "p"]
        if dm is not None:
            ins, names_in = ins + [dm], names_in + ["design"]
        out.append(ca.Function(f"{prefix}_{name}_closed_loop", ins, [x_next, y],
                               names_in, ["x_next", "y"]))
    return out
