# The simulated robot's truth: the model file's [plant] with its payload, as the plant's vector.
"""The plant of the closed-loop rollouts: what the simulated robot really is.

The truth (:func:`plant_truth`) is the model file's ``[plant]`` with the payload booked
(:func:`pm2dof.core.mechanism.payload_increments`); :func:`plant_vector` packs it with the encoder's step for the generated
plant (manifest layout ``plant``); :func:`theta_truth` gives it in theta's coordinates, to
compare with an estimate. :mod:`.simulate` runs the controllers against it.
"""
import functools
import math
from collections.abc import Mapping

import numpy as np

from ..core.errors import ArgumentError, ArgumentTypeError
from ..core.mechanism import payload_increments

__all__ = ["plant_truth", "plant_vector", "theta_truth"]


def plant_truth(model, **overrides):
    """The plant's truth as a dict: the model file's ``[plant]`` with the payload booked in.

    The payload's mass m is booked by ``pm2dof.core.mechanism.payload_increments``: a
    platform carries it at its origin (m_p += m); a point end effector books it to the tip of
    leg j's distal link (j = ``payload_leg``, counted from 1 as in the paper): an RRR leg's
    alpha_j, beta_j, gamma_j, kappa_j gain m la^2, m la lb, m lb^2, m la (its kinetic energy
    1/2 m |tip velocity|^2 in the leg's angles, its potential energy), a PRR leg's m, m lb,
    m lb^2, an RPR leg's alpha_j m.

    Parameters
    ----------
    model : Model
        The robot; its model file's ``[plant]`` is the truth.
    **overrides
        Replace fields of ``[plant]`` (e.g. ``payload_mass=0``); a ``payload_leg`` outside
        1..n raises ArgumentError.
    """
    p = dict(model.spec.plant)
    unknown = sorted(set(overrides) - set(p))
    if unknown:
        raise ArgumentTypeError(f"unknown plant field(s) {unknown}; fields are {sorted(p)}")
    p.update(overrides)
    platform = model.spec.end_effector == "platform"
    leg_no = 1 if platform else p["payload_leg"]
    if not (isinstance(leg_no, (int, float, np.number)) and not isinstance(leg_no, bool)
            and leg_no == int(leg_no) and 1 <= leg_no <= model.n_legs):
        raise ArgumentError(f"payload_leg must be a leg number 1..{model.n_legs} (legs count from 1, "
                         f"as in the paper), got {leg_no!r}")
    j = int(leg_no) - 1
    inertial = [f for f, _ in model.layout("plant").fields if f in p and f not in
                ("fv", "fc", "fs", "stribeck_velocity", "coulomb_smoothing_velocity")]
    truth = {k: np.array(p[k], dtype=float) for k in inertial}
    for name, inc in payload_increments(model.spec.legs[j], model.spec.end_effector,
                                        float(p["payload_mass"])).items():
        if name in truth:                      # e.g. no kappa without gravity
            if truth[name].ndim:
                truth[name][j] += inc
            else:
                truth[name] = truth[name] + inc
    return {**truth, **{k: np.array(p[k], dtype=float) for k in ("fv", "fc", "fs")},
            "stribeck_velocity": float(p["stribeck_velocity"]),
            "coulomb_smoothing_velocity": float(p["coulomb_smoothing_velocity"])}


def plant_vector(model, truth=None, quantise=True, encoder_counts_per_rev=None):
    """The generated plant's parameter vector (manifest layout ``plant``): the truth (default
    :func:`plant_truth`) and the encoder step 2 pi / encoder_counts_per_rev (0 when
    ``quantise`` is false or the resolution is 0), and for linear actuators (PRR, RPR legs)
    ``[sensing] linear_encoder_resolution``, m (0 when ``quantise`` is false). ``encoder_counts_per_rev`` replaces the model
    file's ``[sensing]`` value."""
    counts = (model.spec.sensing["encoder_counts_per_rev"] if encoder_counts_per_rev is None
              else encoder_counts_per_rev)
    if not (isinstance(counts, (int, float, np.integer, np.floating)) and counts >= 0
            and float(counts).is_integer()):
        raise ArgumentError(f"encoder_counts_per_rev must be a whole number >= 0, got {counts!r}")
    truth = plant_truth(model) if truth is None else truth
    if not isinstance(truth, Mapping):
        raise ArgumentTypeError(f"truth must be a dict like pm2dof.plant_truth(model) (fields "
                                f"{sorted(plant_truth(model))}), got {type(truth).__name__}; "
                                f"plant_truth(model, alpha=..., fv=...) makes one")
    lay = model.layout("plant")
    steps = {"encoder_step": (2 * math.pi / counts) if (quantise and counts > 0) else 0.0}
    if "linear_encoder_step" in lay.slices:      # PRR, RPR legs: m per count
        steps["linear_encoder_step"] = (
            float(model.spec.sensing["linear_encoder_resolution"]) if quantise else 0.0)
    try:
        vec = lay.pack(**truth, **steps)
    except (TypeError, ValueError) as exc:
        raise ArgumentError(f"truth: {exc}") from None
    return vec


def theta_truth(model, truth=None):
    """The truth in theta's coordinates (``model.param_names`` order): inertias with payload,
    fv, fc, and fs when the model's friction has a Stribeck term.

    The paper's model (eq. 2) has no coordinate for the Stribeck excess; it is left out.
    Smooth-sign or Stribeck shapes of the controller's model differ from the plant's, so
    only the coefficients are compared.

    Parameters
    ----------
    model : Model
        The robot.
    truth : dict, optional
        A plant truth (:func:`plant_truth`'s dict); default the model file's ``[plant]``.
    """
    t = plant_truth(model) if truth is None else truth
    return np.array([np.ravel(t[base])[i] for base, i in _param_index(model.param_names)])


@functools.lru_cache(maxsize=16)
def _param_index(names):
    """(field, leg index) of each parameter name, e.g. 'gamma3' -> ('gamma', 2), 'm_p' ->
    ('m_p', 0) (the platform's parameters carry no leg number)."""
    out = []
    for name in names:
        base = name.rstrip("0123456789")
        out.append((base, int(name[len(base):]) - 1 if len(base) < len(name) else 0))
    return tuple(out)
