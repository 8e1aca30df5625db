# What the exported test compares with: pm2dof's own closed loops on the model's move, as C data.
"""Reference data of an export: ``tests/<name>_reference.h``.

The move (the model file's ``[trajectories.high]``, else its first line move, or the one
named), the plant's
truth, and for each exported controller with a reference (NA, APD, CTC) the RMSE (eq. 41),
the torques and the encoder readings of :func:`pm2dof.simulate`. LQR's gains come from a
Riccati solver (the ``control`` extra), so its reference is one step of the generated
``<name>_lqr_step`` with fixed gains, evaluated by pm2dof. Values are written with 17
significant digits: read back they are the same doubles.
"""
import numpy as np

from ..control.controllers import APDController, CTCController, NAController
from ..control.plant import plant_vector
from ..control.simulate import simulate
from ..control.trajectory import line_moves, model_move
from ..core.errors import Pm2dofError
from ..core.status import Status

__all__ = ["REFERENCE_LAWS", "reference_move", "reference_data", "reference_header",
           "encoder_counts", "tip_moves"]

#: the controllers with a closed-loop reference, in the order of the exported example
REFERENCE_LAWS = {"na": NAController, "apd": APDController, "ctc": CTCController}


#: the bounds of a single-precision build against pm2dof's double results (docs/deploying.md)
SINGLE_BOUNDS = """/* single precision against pm2dof's double results:
 * - replay (the step fed pm2dof's encoder readings): float keeps xe to 2^-24 of its size
 *   (3e-8 m at 0.5 m), the backward difference turns that into 1.5e-5 m/s over T = 2 ms, and
 *   K_d (195 N s/m) into 3e-3 N per ulp; measured on shang2010's high-speed move: at most
 *   0.010 N m (torques up to 7.4 N m); bound 0.05 N m, and 0.2 N for a linear actuator's
 *   force (the same task force without the 0.244 m lever of shang2010's proximal link);
 *   where an actuator is at rest its Coulomb sign may flip: ref_replay_flip below;
 * - closed loop: a rounding difference moves the robot by far less than an encoder count,
 *   but a reading that then falls into the next count changes the velocity estimate by one
 *   count per T (1.2e-5 m / 2 ms = 6e-3 m/s, 1.2 N of K_d s): the run is another run of the
 *   same loop, the torques are not compared sample by sample, and the RMSE may differ by a
 *   fraction of what one count moves the tip; measured on shang2010: 3.3e-7 m (high-speed
 *   move) and 4.6e-7 m (low-speed) for NA, below 8e-8 m for APD and CTC; bound a quarter
 *   of the largest joint move of one encoder count (la times a count for a revolute
 *   actuator, the linear resolution for a linear one), {atol:.3g} m;
 * - fk(ik(xe)) = xe to 1e-6 m (30 float ulps at 0.3 m). */
#define REF_RMSE_RTOL 0.0
#define REF_RMSE_ATOL {atol!r}
#define REF_REPLAY_ATOL {replay_atol!r}
#define REF_FK_ATOL 1e-6
"""


def tip_moves(model, plant):
    """How far one encoder count of each actuator moves its leg's joint, m (n,): la times the
    plant's encoder step for a revolute actuator, its linear step for a linear one."""
    lay = model.layout("plant")
    rad = plant[lay.slices["encoder_step"]][0]
    lin = plant[lay.slices["linear_encoder_step"]][0] if "linear_encoder_step" in lay.slices else 0
    return np.array([leg.la * rad if leg.actuator == "revolute" else lin
                     for leg in model.spec.legs])


def reference_move(model, name=None):
    """(name, Trajectory): the model file's move ``name``; default its "high" move, else its
    first line move (TrajectoryError naming the moves for an unknown name)."""
    moves = line_moves(model)
    if name is None:
        name = "high" if "high" in moves else moves[0]
    return name, model_move(model, name)


def _measure(model, plant, xe):
    """The encoder readings (N, n) of the true poses ``xe`` (N, m)."""
    f = model.function("measure")
    qa = np.empty((len(xe), model.n_legs))
    for k, x in enumerate(xe):
        f(np.ascontiguousarray(x), plant, qa[k])
    return qa


def encoder_counts(model):
    """One encoder count of each actuator (n,): 2 pi / ``encoder_counts_per_rev`` rad for a
    revolute actuator, ``[sensing] linear_encoder_resolution`` m for a linear one (a
    resolution of 0, exact encoders: 2 pi / 2^17 rad, 1e-6 m)."""
    sensing = model.spec.sensing
    counts = sensing["encoder_counts_per_rev"]
    rad = 2 * np.pi / (counts if counts > 0 else 131072)
    m = float(sensing.get("linear_encoder_resolution") or 0.0) or 1e-6
    return np.array([rad if leg.actuator == "revolute" else m for leg in model.spec.legs])


def _lqr_step(model, move, plant, params):
    """One LQR step from rest at the move's start, with fixed gains (no Riccati solver)."""
    n, dim = model.n_legs, model.dof
    qa0 = _measure(model, plant, move.xd[:1])[0]
    lay = model.layout("ctrl_state")
    state = np.zeros(lay.size)
    s = lay.unpack(state)
    s["xe_prev"][:] = model.fk(qa0)
    s["theta_hat"][:] = model.theta_nominal
    # gains of plausible size (N m or N per m, per m/s) and a feedforward, all entries
    # distinct: K is n x 2m row-major (pm2dof.linear.lqr); scaled down by 10 while the step
    # saturates (a clipped effort would not depend on K)
    tau_ff = np.linspace(0.1, 0.3, n)
    qa1 = qa0 + encoder_counts(model) * np.arange(1, n + 1)     # the next reading: a few counts
    tau, st1, status = np.empty(n), np.empty(lay.size), np.empty(1)
    diag = np.empty(4 * dim + 2)
    for scale in (10.0, 1.0, 0.1, 0.01):
        K = np.ascontiguousarray(np.arange(1, 2 * dim * n + 1, dtype=float) * scale)
        model.function("lqr_step")(state, qa1, np.ascontiguousarray(move.xd[1]),
                                   np.ascontiguousarray(move.xd_dot[1]),
                                   np.ascontiguousarray(move.xd_ddot[1]), params, K, tau_ff,
                                   tau, st1, status, diag)
        if status[0] != Status.SATURATED:
            break
    return {"qa0": qa0, "qa1": qa1, "K": K, "tau_ff": tau_ff, "tau": tau,
            "status": float(status[0])}


def reference_data(model, laws, lqr_params=None, move=None):
    """The reference of ``laws`` (a subset of na, apd, ctc, lqr) along the model file's move
    ``move`` (default as :func:`reference_move`), as arrays (module doc). ``lqr_params``:
    LQR's parameter vector (``lqr_params`` layout)."""
    name, move = reference_move(model, move)
    plant = plant_vector(model)
    out = {"move": name, "trajectory": move, "plant": plant, "laws": [], "rmse": [],
           "tau": [], "qa": [], "theta_hat": [], "vel_alpha": []}
    for law in laws:
        if law not in REFERENCE_LAWS:
            continue
        ctl = REFERENCE_LAWS[law](model, on_singular="zero")
        r = simulate(model, ctl, move)
        out["laws"].append(law)
        out["rmse"].append(r.rmse)
        out["tau"].append(r.tau_a)
        out["qa"].append(_measure(model, plant, r.xe))
        out["theta_hat"].append(r.theta_hat)
        lay = model.layout(f"{law}_params")
        out["vel_alpha"].append(float(ctl.params[lay.slices["vel_alpha"]][0]))
    if "lqr" in laws:
        out["lqr"] = _lqr_step(model, move, plant, lqr_params)
    return out


def coulomb_flip_bounds(model, qa, theta_hat, vel_alpha):
    """Single precision's replay: the extra effort difference allowed at each sample (N,).

    The regressor's Coulomb columns take the sign of each actuator's velocity estimate, the
    joint part of W(xe) v. Where an actuator's reading has not moved, that estimate is only
    what the other joints' counts leave through W, and float's rounding of fk (a few 1e-8 m)
    can flip its sign: the effort then differs by the flipped Coulomb term, 2 (fc_i + fs_i)
    of theta_hat, which the minimum-norm split (a projection, eq. 21) does not enlarge. A
    sample gets that allowance, 2 ||fc + fs||_2 at its theta_hat, when some actuator's
    velocity estimate is below a quarter of one encoder count per sample period (in double
    the same arithmetic runs and no allowance is made)."""
    T = model.spec.sensing["sample_period"]
    slow = 0.25 * encoder_counts(model) / T
    n = model.n_legs
    # (n, p): row i sums actuator i's fc_i and fs_i out of theta
    coulomb = np.array([[float(nm in (f"fc{i + 1}", f"fs{i + 1}")) for nm in model.param_names]
                        for i in range(n)])
    out = np.zeros(len(qa))
    xe_prev, v = model.fk(qa[0]), np.zeros(model.dof)
    for k in range(len(qa)):            # k = 0: at rest after reset, v = 0 in double
        try:
            xe = model.fk(qa[k])
            qd = (model.W(model.ik(xe)) @ (v + vel_alpha * ((xe - xe_prev) / T - v)))[:n]
        except Pm2dofError:     # a pose the step refuses: no allowance, the check stands
            continue
        v = v + vel_alpha * ((xe - xe_prev) / T - v)
        xe_prev = xe
        if np.any(np.abs(qd) < slow):       # theta_hat before and after the sample
            th = np.maximum(np.abs(theta_hat[max(k - 1, 0)]), np.abs(theta_hat[k]))
            out[k] = 2 * float(np.linalg.norm(coulomb @ th))
    return out


def _c_array(name, values, dims=None):
    v = np.asarray(values, dtype=float)
    if dims is not None and len(dims) == 2:        # rows in braces
        body = ",\n    ".join("{" + ", ".join(repr(float(x)) for x in row) + "}"
                              for row in v.reshape(v.shape[0], -1))
    else:
        body = ", ".join(repr(float(x)) for x in v.ravel())
    shape = "".join(f"[{d}]" for d in (dims or [v.size]))
    return f"static const double {name}{shape} REF_UNUSED = {{{body}}};\n"


def reference_header(model, ref, precision):
    """``tests/<name>_reference.h``: the reference as C (doubles, whatever the precision)."""
    move, n = ref["trajectory"], model.n_legs
    N = len(move.t)
    single = precision == "single"
    lines = [
        f"/* {model.name}_reference.h: what pm2dof computed at export, for the test and the\n"
        f" * example. The move \"{ref['move']}\" of the model file, {N} samples; the plant's\n"
        f" * truth ([plant], payload booked in: pm2dof.plant_vector); per controller the RMSE\n"
        f" * over the move (eq. 41), the torques and the encoder readings of pm2dof.simulate.\n"
        f" * Doubles with 17 significant digits (exact). */\n",
        f"#ifndef {model.name.upper()}_REFERENCE_H\n#define {model.name.upper()}_REFERENCE_H\n",
        "#if defined(__GNUC__)\n#define REF_UNUSED __attribute__((unused))\n#else\n"
        "#define REF_UNUSED\n#endif\n",
        f"#define REF_N {N}\n#define REF_PERIOD {move.period!r}\n"
        f"#define REF_RK4_SUBSTEPS {model.spec.rk4_substeps}\n",
        f"#define REF_N_LAWS {len(ref['laws'])}\n",
    ]
    if single:
        linear = any(leg.actuator != "revolute" for leg in model.spec.legs)
        lines.append(SINGLE_BOUNDS.format(atol=float(0.25 * max(tip_moves(model, ref["plant"]))),
                                          replay_atol=0.2 if linear else 0.05))
    else:
        lines.append("/* double precision: the same generated arithmetic as pm2dof */\n"
                     "#define REF_RMSE_RTOL 1e-12\n#define REF_RMSE_ATOL 0.0\n"
                     "#define REF_REPLAY_ATOL 1e-12\n"
                     "#define REF_FK_ATOL 1e-12\n")
    dim = model.dof
    lines += [_c_array("ref_xd", move.xd, ["REF_N", dim]),
              _c_array("ref_xd_dot", move.xd_dot, ["REF_N", dim]),
              _c_array("ref_xd_ddot", move.xd_ddot, ["REF_N", dim]),
              _c_array("ref_plant", ref["plant"])]
    k = max(len(ref["laws"]), 1)
    pad = np.zeros((k - len(ref["laws"]), N * n))
    lines += [f"/* in the order {', '.join(ref['laws']) or '(none)'} */\n",
              _c_array("ref_rmse", ref["rmse"] or [0.0]),
              _c_array("ref_tau", np.vstack([np.reshape(t, (1, -1)) for t in ref["tau"]]
                                            + [pad]) if ref["laws"] else pad,
                       [k, f"REF_N * {n}"]),
              _c_array("ref_qa", np.vstack([np.reshape(t, (1, -1)) for t in ref["qa"]]
                                           + [pad]) if ref["laws"] else pad,
                       [k, f"REF_N * {n}"])]
    if single:
        bounds = [coulomb_flip_bounds(model, qa, th, a) for qa, th, a in
                  zip(ref["qa"], ref["theta_hat"], ref["vel_alpha"])]
        lines += ["/* single: per law and sample, the effort difference a flipped Coulomb sign "
                  "may add\n * (pm2dof.export.reference.coulomb_flip_bounds) */\n",
                  _c_array("ref_replay_flip", np.vstack(bounds + [np.zeros((k - len(bounds),
                                                                            N))]),
                           [k, "REF_N"])]
    if "lqr" in ref:
        q = ref["lqr"]
        lines += ["/* LQR: one step from rest, fixed gains, by pm2dof's generated lqr_step */\n"]
        lines += [_c_array(f"ref_lqr_{key}", q[key]) for key in ("qa0", "qa1", "K", "tau_ff",
                                                                 "tau")]
        lines.append(f"#define ref_lqr_status {q['status']!r}\n")
    lines.append("#endif\n")
    return "".join(lines)
