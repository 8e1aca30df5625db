# The generated code's contract: the names of its functions, the laws and splits, the step's diag.
"""What ``pm2dof derive`` generates and the runtime binds, named once.

derive/ builds its functions and the manifest from these names; core binds them
(:class:`pm2dof.Model`), control runs them, export and bench pick them by name. Every
generated function is ``<model>_<short name>``; :func:`function_names` lists the short names
a derivation writes (the manifest's ``functions``, the model's prefix stripped).

* Torque splits (:data:`SPLITS`): the split's name -> the suffix of its functions,
  ``<law><suffix>_step`` and ``<law><suffix>_closed_loop``.
* Control laws (:data:`LAWS`): each has a ``<law>_params`` layout and ``[gains.<law>]``.
  :data:`STEPS` lists the generated steps: NA twice, its projected variant ``na_proj``
  (theta_hat projected after each update) sharing ``na_params``.
* A step (:data:`STEP_INPUTS` -> :data:`STEP_OUTPUTS`) reports its signal processing in
  ``diag``, laid out by :func:`diag_layout` (the manifest's ``diag`` layout).
"""

__all__ = ["SPLITS", "LAWS", "STEPS", "STEP_INPUTS", "STEP_OUTPUTS", "MODEL_FUNCTIONS",
           "PLANT_FUNCTIONS", "PATH_FUNCTIONS", "DERIVATIVE_FUNCTIONS", "ENERGY_FUNCTIONS",
           "step_name", "closed_loop_name", "step_names", "closed_loop_names", "function_names",
           "reports_by_status", "diag_layout"]

#: torque split -> suffix of its generated functions (min_norm: eq. 21; derive/splits.py)
SPLITS = {"min_norm": "", "min_max": "_minmax", "preload": "_preload"}
#: the control laws, in this order: NA (eqs. 14-29), APD (eq. 40), computed torque, LQR
LAWS = ("na", "apd", "ctc", "lqr")
#: the generated steps: (base name, law whose params it takes, theta_hat projected)
STEPS = (("na", "na", False), ("na_proj", "na", True), ("apd", "apd", False),
         ("ctc", "ctc", False), ("lqr", "lqr", False))
#: a step's inputs (a law with per-sample inputs, LQR, appends its own) and outputs
STEP_INPUTS = ("state", "qa", "xd", "xd_dot", "xd_ddot", "params")
STEP_OUTPUTS = ("tau_a", "state_next", "status", "diag")
#: the model's functions of the pose and its rates (eqs. 3-13), and the torque splits
MODEL_FUNCTIONS = ("ik", "fk", "H", "A", "singularity", "singularity_measures", "W", "S",
                   "Wdot", "M", "C", "Me", "Ce", "StF", "Y", "torque_splits",
                   "forward_dynamics", "Ge")
#: the simulated robot: its dynamics, one RK4 step, its encoders
PLANT_FUNCTIONS = ("plant_xedd", "plant_step", "measure")
#: motion planning (pm2dof.planning): per-grid-point path dynamics
PATH_FUNCTIONS = ("path_coefficients", "path_mvc", "path_backward", "path_forward",
                  "path_torques")
#: Jacobians, the sampled step and inverse dynamics (pm2dof.core.derivatives)
DERIVATIVE_FUNCTIONS = ("forward_dynamics_jacobians", "sampled_step", "sampled_step_jacobians",
                        "inverse_dynamics", "inverse_dynamics_jacobians")
#: the energies T and V of a pose and its rates
ENERGY_FUNCTIONS = ("kinetic_energy", "potential_energy")


def step_name(base, split="min_norm"):
    """``<base><suffix>_step``: a step's short name, e.g. ("na", "min_max") -> na_minmax_step."""
    return f"{base}{SPLITS[split]}_step"


def closed_loop_name(base, split="min_norm"):
    """``<base><suffix>_closed_loop``: one control sample of a step against the plant."""
    return f"{base}{SPLITS[split]}_closed_loop"


def step_names():
    """Every generated step's short name, laws (:data:`STEPS`) outer, splits inner."""
    return tuple(step_name(base, split) for base, _, _ in STEPS for split in SPLITS)


def closed_loop_names():
    """Every generated closed loop's short name, in :func:`step_names` order."""
    return tuple(closed_loop_name(base, split) for base, _, _ in STEPS for split in SPLITS)


def function_names():
    """The short names of every function a derivation generates (the manifest's
    ``functions`` without the model's prefix)."""
    return (MODEL_FUNCTIONS + step_names() + PLANT_FUNCTIONS + closed_loop_names()
            + PATH_FUNCTIONS + DERIVATIVE_FUNCTIONS + ENERGY_FUNCTIONS)


def reports_by_status(short):
    """True for a function that reports a bad input or result itself, so its outputs are not
    checked for NaN by the binding: the steps and closed loops (their status), the plant, the
    path dynamics (their flags), ik and fk (NaN -> WorkspaceError) and the energies (a pose
    out of reach)."""
    return short in (step_names() + closed_loop_names() + PLANT_FUNCTIONS + PATH_FUNCTIONS
                     + ENERGY_FUNCTIONS + ("ik", "fk"))


def diag_layout(m):
    """The fields of a step's ``diag`` output for task dimension ``m``: [(name, size)] of xe
    (the pose from fk), v (the filtered velocity), e = xd - xe (eq. 14), edot = xd_dot - v,
    m each, and sing (2: the type I and type II singularity measures)."""
    return [("xe", m), ("v", m), ("e", m), ("edot", m), ("sing", 2)]
