# The mechanism's rules: leg kinds, theta's layout, lumped parameters, payload, reach (no file I/O).
"""What follows from a mechanism's legs alone, whoever describes them.

The model file's reader (:mod:`pm2dof.core.model_file`) reads and checks a file and builds its
legs; the rules that turn legs into numbers live here, one home each:

* the leg kinds (:data:`LEG_KINDS`, :data:`ACTUATORS`) and the end effectors
  (:data:`END_EFFECTORS`);
* theta's layout: :func:`theta_groups` (which parameters, in which order), :func:`theta_names`,
  :data:`FRICTION_MODELS` and :func:`is_friction_param`;
* physical parameters: :func:`inertia_problem`, :func:`platform_inertia_problem`;
* from bodies to theta: :func:`lumped_from_links` (:data:`LINK_BODIES`; a body with a length
  may be a uniform rod, :data:`ROD_LENGTH`, :func:`rod_body`), :func:`platform_from_body`, and
  a payload's share, :func:`payload_increments`;
* geometry: :func:`attachment_points`, :func:`leg_reach_problem`, :func:`reach_problems`;
* sensing: :func:`default_closure_tolerance`.

A leg is any object with the attributes of :class:`pm2dof.core.model_file.Leg` that the rule
reads (``kind``, ``base``, ``la``, ``lb``, ``elbow``, ``rail_end``, ``rail_length``,
``stroke``, ``attach``). docs/model-file.md gives the rules in words. Pure Python and NumPy-free.
"""
import math

__all__ = ["LEG_KINDS", "ACTUATORS", "END_EFFECTORS", "INERTIAL", "FIRST_MOMENT",
           "PLATFORM_PARAMS", "FRICTION_MODELS", "FRICTION_CONSTANTS", "LINK_BODIES",
           "ROD_LENGTH", "CLOSURE_FLOOR",
           "theta_groups", "theta_names", "is_friction_param", "inertia_problem",
           "platform_inertia_problem", "rod_body", "solid_bodies", "lumped_from_links",
           "platform_from_body", "payload_increments", "attachment_points", "leg_reach_problem",
           "reach_problems", "default_closure_tolerance"]

#: each leg kind's actuated joint (docs/model-file.md, [[legs]]): RRR's revolute at the base,
#: PRR's slider on its rail, RPR's length (a cylinder between two passive revolutes)
ACTUATORS = {"RRR": "revolute", "PRR": "prismatic", "RPR": "prismatic"}
#: the leg kinds (their one home)
LEG_KINDS = tuple(ACTUATORS)
#: end effectors: task coordinates and their count m
END_EFFECTORS = {"point": ("x", "y"), "platform": ("x", "y", "phi")}
#: each leg's inertial parameters of eq. 1 (kg m^2, or kg for a prismatic joint's entries)
INERTIAL = ("alpha", "beta", "gamma")
#: the first moment of a leg's links in the gravity term (kg m), for the kinds that need one
FIRST_MOMENT = "kappa"
#: the platform's parameters in theta: mass (kg), first moments m c_x, m c_y in the platform
#: frame (kg m), inertia about the platform's origin, the task point (kg m^2)
PLATFORM_PARAMS = ("m_p", "mx_p", "my_p", "I_p")
#: friction model -> its per-leg parameters after the inertial ones (eq. 2 and extensions)
FRICTION_MODELS = {
    "coulomb_viscous": ("fv", "fc"),                 # eq. 2, sign(0) = 0
    "coulomb_viscous_stribeck": ("fv", "fc", "fs"),  # + fs sign(v) / (1 + (v/vs)^2)
    "smooth_sign": ("fv", "fc"),                     # sign(v) -> v / sqrt(v^2 + eps^2)
}
#: formulation constants each friction model needs (keys of the model file's [model])
FRICTION_CONSTANTS = {
    "coulomb_viscous": (),
    "coulomb_viscous_stribeck": ("stribeck_velocity",),
    "smooth_sign": ("sign_smoothing_velocity",),
}
#: the bodies of each leg kind and their keys: mass (kg), com (m, the centre of mass's
#: distance along the body from its joint; RPR rod: back from the platform's joint), inertia
#: (kg m^2, about the centre of mass). A slider has a mass only.
LINK_BODIES = {"RRR": {"proximal": ("mass", "com", "inertia"),
                       "distal": ("mass", "com", "inertia")},
               "PRR": {"slider": ("mass",), "link": ("mass", "com", "inertia")},
               "RPR": {"cylinder": ("mass", "com", "inertia"), "rod": ("mass", "com", "inertia")}}
#: the bodies with a length, which may be given as a uniform rod { density } (kg/m), and the
#: Leg field that is their length: RRR proximal (la) and distal (lb), PRR link (lb)
ROD_LENGTH = {"RRR": {"proximal": "la", "distal": "lb"}, "PRR": {"link": "lb"}}
#: smallest default [sensing] closure_tolerance, m (exact encoders still meet rounding)
CLOSURE_FLOOR = 1e-6


def theta_groups(legs, effector, gravity, friction):
    """theta's layout: (key, legs) pairs in order, ``legs`` the 0-based legs of a per-leg
    array, None for a scalar. alpha, beta, gamma for every leg; kappa (the gravity term's first
    moment, docs/model-file.md) for the RRR and RPR legs when there is gravity; the platform's
    m_p, mx_p, my_p, I_p; then the friction parameters of every leg."""
    every = list(range(len(legs)))
    groups = [(key, every) for key in INERTIAL]
    if any(g != 0.0 for g in gravity):
        moments = [i for i, leg in enumerate(legs) if leg.kind in ("RRR", "RPR")]
        if moments:
            groups.append((FIRST_MOMENT, moments))
    if effector == "platform":
        groups += [(key, None) for key in PLATFORM_PARAMS]
    return groups + [(key, every) for key in FRICTION_MODELS[friction]]


def theta_names(groups):
    """theta's names in order for :func:`theta_groups`' ``groups``: a per-leg key with the
    leg's number from 1 (alpha1, alpha2, ..., kappa1, ...), a scalar key as it is (m_p)."""
    return tuple(key if idx is None else f"{key}{i + 1}" for key, idx in groups
                 for i in (idx if idx is not None else [0]))


def is_friction_param(name, friction):
    """Whether theta's entry ``name`` (a key and a leg number: fv2, fc1, ...) is a parameter of
    the friction law ``friction`` (a key of FRICTION_MODELS)."""
    return name.rstrip("0123456789") in FRICTION_MODELS[friction]


def inertia_problem(alpha, beta, gamma):
    """Why one leg's M_i (eq. 1) is not positive definite for every c_i, or None: the rule for
    [nominal] and for any theta a plan takes (alpha, gamma > 0, beta^2 < alpha gamma)."""
    if not (alpha > 0 and gamma > 0):
        return f"alpha and gamma must be > 0, got alpha = {alpha:.6g}, gamma = {gamma:.6g}"
    if beta * beta >= alpha * gamma:
        return (f"inertia is not positive definite: beta^2 = {beta * beta:.6g} >= "
                f"alpha*gamma = {alpha * gamma:.6g}")
    return None


def platform_inertia_problem(m, mx, my, inertia):
    """Why the platform's parameters (m_p, mx_p, my_p, I_p) are not a rigid body's, or None:
    m > 0 and I_p - (mx^2 + my^2) / m > 0 (the inertia about the centre of mass)."""
    if not m > 0:
        return f"m_p must be > 0, got {m:.6g}"
    if not inertia * m > mx * mx + my * my:
        return (f"the inertia about the centre of mass, I_p - (mx_p^2 + my_p^2) / m_p = "
                f"{inertia - (mx * mx + my * my) / m:.6g}, must be > 0")
    return None


def rod_body(density, length):
    """A uniform rod of ``density`` kg/m and ``length`` m as a body: {mass (kg), com (m from
    its joint, the middle), inertia (kg m^2 about the centre of mass, as LINK_BODIES)}."""
    return {"mass": density * length, "com": length / 2,
            "inertia": density * length ** 3 / 12}


def solid_bodies(leg, bodies):
    """``bodies`` ({body: {mass, com, inertia}} or {body: {density}}, LINK_BODIES and
    ROD_LENGTH) with every rod replaced by its :func:`rod_body` at ``leg``'s lengths."""
    lengths = ROD_LENGTH.get(leg.kind, {})
    return {name: rod_body(body["density"], getattr(leg, lengths[name]))
            if "density" in body else body for name, body in bodies.items()}


def lumped_from_links(leg, bodies):
    """{alpha, beta, gamma, kappa} of one leg from its bodies ({body: {mass, com, inertia}},
    LINK_BODIES, or a rod {density}, ROD_LENGTH), by the rule of docs/model-file.md ("From the
    links to theta"); PRR legs have no kappa."""
    bodies = solid_bodies(leg, bodies)
    if leg.kind == "RRR":
        a, b = bodies["proximal"], bodies["distal"]
        return {"alpha": a["inertia"] + a["mass"] * a["com"] ** 2 + b["mass"] * leg.la ** 2,
                "beta": b["mass"] * leg.la * b["com"],
                "gamma": b["inertia"] + b["mass"] * b["com"] ** 2,
                FIRST_MOMENT: a["mass"] * a["com"] + b["mass"] * leg.la}
    if leg.kind == "PRR":
        sl, b = bodies["slider"], bodies["link"]
        return {"alpha": sl["mass"] + b["mass"], "beta": b["mass"] * b["com"],
                "gamma": b["inertia"] + b["mass"] * b["com"] ** 2}
    c, r = bodies["cylinder"], bodies["rod"]
    return {"alpha": r["mass"], "beta": r["mass"] * r["com"],
            "gamma": (c["inertia"] + c["mass"] * c["com"] ** 2 + r["inertia"]
                      + r["mass"] * r["com"] ** 2),
            FIRST_MOMENT: c["mass"] * c["com"]}


def platform_from_body(mass, com, inertia):
    """(m_p, mx_p, my_p, I_p) of a platform of ``mass`` kg, centre of mass ``com`` (platform
    frame, m) and ``inertia`` about it (kg m^2)."""
    return mass, mass * com[0], mass * com[1], inertia + mass * (com[0] ** 2 + com[1] ** 2)


def payload_increments(leg, end_effector, mass):
    """What a point payload of ``mass`` kg adds to theta's inertial entries: {name: increment},
    names without the leg's number. A platform carries it at its origin (m_p += mass); a point
    end effector books it to the tip of ``leg`` (docs/model-file.md, [plant]): RRR alpha
    += m la^2, beta += m la lb, gamma += m lb^2, kappa += m la; PRR alpha += m, beta += m lb,
    gamma += m lb^2; RPR alpha += m (a mass at the leg's length qa from its base)."""
    if end_effector == "platform":
        return {"m_p": mass}
    if leg.kind == "RRR":
        return {"alpha": mass * leg.la ** 2, "beta": mass * leg.la * leg.lb,
                "gamma": mass * leg.lb ** 2, FIRST_MOMENT: mass * leg.la}
    if leg.kind == "PRR":
        return {"alpha": mass, "beta": mass * leg.lb, "gamma": mass * leg.lb ** 2}
    return {"alpha": mass}


def attachment_points(legs, pose):
    """The legs' attachment points in the base frame at a task pose: (x, y) for a point, the
    platform's p + R(phi) a_i for a pose (x, y, phi)."""
    if len(pose) == 2:
        return [tuple(pose)] * len(legs)
    c, s = math.cos(pose[2]), math.sin(pose[2])
    return [(pose[0] + c * lg.attach[0] - s * lg.attach[1],
             pose[1] + s * lg.attach[0] + c * lg.attach[1]) for lg in legs]


def reach_problems(legs, pose):
    """[(leg index from 0, why)] for every leg that cannot reach the task pose (x, y) or
    (x, y, phi) (:func:`leg_reach_problem`; a platform's legs at their attachment points)."""
    pose = [float(v) for v in pose]
    return [(i, why) for i, (leg, point) in enumerate(zip(legs, attachment_points(legs, pose)))
            if (why := leg_reach_problem(leg, point)) is not None]


def leg_reach_problem(leg, point):
    """Why ``leg`` cannot put its tip at ``point`` (x, y) in m in its configured branch (a
    phrase that follows "leg i"), or None.

    RRR: |point - A| within [|la - lb|, la + lb]. PRR: within lb of the rail's line, with the
    slider of the chosen branch on the rail (0 <= qa <= its length). RPR: |point - A| within
    the stroke."""
    e = (point[0] - leg.base[0], point[1] - leg.base[1])
    dist = math.hypot(*e)
    if leg.kind == "RRR":
        lo, hi = abs(leg.la - leg.lb), leg.la + leg.lb
        if not lo <= dist <= hi:
            return f"is {dist:.4g} m from its base, its reach is [{lo:.4g}, {hi:.4g}] m"
        return None
    if leg.kind == "RPR":
        lo, hi = leg.stroke
        if not lo <= dist <= hi:
            return f"is {dist:.4g} m from its base, its stroke is [{lo:.4g}, {hi:.4g}] m"
        return None
    length = leg.rail_length
    d = ((leg.rail_end[0] - leg.base[0]) / length, (leg.rail_end[1] - leg.base[1]) / length)
    h = d[0] * e[1] - d[1] * e[0]                        # signed distance from the rail's line
    if abs(h) > leg.lb:
        return f"is {abs(h):.4g} m from its rail's line, farther than its link lb = {leg.lb:.4g} m"
    s = d[0] * e[0] + d[1] * e[1] + leg.elbow * math.sqrt(leg.lb ** 2 - h ** 2)
    if not 0.0 <= s <= length:
        return (f"would need its slider at {s:.4g} m along its rail, which runs from 0 to "
                f"{length:.4g} m")
    return None


def default_closure_tolerance(legs, encoder_counts_per_rev, linear_resolution=0.0):
    """[sensing] closure_tolerance when a model file does not set it, m: five encoder steps at
    the longest active link, at least 1 um. (One step moves an elbow by la * 2 pi / counts;
    quantised angles over the paper robot's workspace give residuals up to 0.8 of that, and
    up to 1.3 with a full step of error: tests/core/test_closure.py measures it.) A prismatic
    actuator's step moves its joint by ``linear_resolution`` m."""
    step = 2 * math.pi / encoder_counts_per_rev if encoder_counts_per_rev > 0 else 0.0
    moves = [leg.la * step if leg.actuator == "revolute" else linear_resolution or 0.0
             for leg in legs]
    return max(CLOSURE_FLOOR, 5 * max(moves))
