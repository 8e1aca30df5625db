# The plant of one random draw: sampled from (seed, draw) only, applied to the model file's [plant].
"""Random draws of the plant's truth.

Draw ``d`` uses ``numpy.random.default_rng([seed, d])`` and samples the uncertainty keys in
the fixed order of :data:`pm2dof.studies.spec.UNCERTAINTY`, so its values depend on nothing
else (not the worker, the chunk or the other draws). The plant is the model file's
``[plant]`` with the draw applied; the controllers keep their own nominal model (Tables 1-2).
"""
import functools

import numpy as np

from ..control.plant import plant_truth
from ..core.mechanism import INERTIAL

__all__ = ["sample_draw", "draw_columns", "plant_of"]


def sample_draw(study, d, n_legs):
    """The sampled values of draw ``d``: {key: float, or (3n,) array for the inertia errors}."""
    rng = np.random.default_rng([study.seed, d])
    out = {}
    for key, dist in study.uncertainty:
        if key == "inertia_error_percent":
            out[key] = np.asarray(dist.sample(rng, 3 * n_legs), dtype=float)
        else:
            out[key] = dist.sample(rng)
    return out


def draw_columns(study, n_legs):
    """Result columns of the sampled values, in order: the inertia errors get one column per
    parameter (``inertia_error_percent_alpha1`` ...); ``payload_mass`` is the mass in the run's
    plant (after a payload change)."""
    cols = []
    for key, _ in study.uncertainty:
        if key == "inertia_error_percent":
            cols += list(_inertia_columns(n_legs))
        else:
            cols.append(key)
    if study.payload_change and "payload_mass" not in cols:
        cols.insert(0, "payload_mass")
    return cols


@functools.lru_cache(maxsize=8)
def _inertia_columns(n):
    return tuple(f"inertia_error_percent_{p}{i + 1}" for p in INERTIAL for i in range(n))


def plant_of(model, study, values, run):
    """(truth dict for :func:`pm2dof.simulate`, encoder counts or None, column values) of one
    draw's ``values`` in repetition ``run``."""
    base = model.spec.plant
    over, cols = {}, {}
    n = model.n_legs
    for key, v in values.items():
        if key == "inertia_error_percent":
            for j, p in enumerate(INERTIAL):
                e = v[j * n:(j + 1) * n]
                over[p] = np.asarray(base[p], dtype=float) * (1 + e / 100)
            cols.update(zip(_inertia_columns(n), v.tolist()))
        elif key == "payload_mass":
            over["payload_mass"] = v
        elif key in ("fv_scale", "fc_scale", "stribeck_scale"):
            field = {"fv_scale": "fv", "fc_scale": "fc", "stribeck_scale": "fs"}[key]
            over[field] = np.asarray(base[field], dtype=float) * v
            cols[key] = v
    if study.payload_change and run >= study.payload_change[0]:
        over["payload_mass"] = study.payload_change[1]
    if "payload_mass" in values or study.payload_change:
        cols["payload_mass"] = over.get("payload_mass", base["payload_mass"])
    counts = values.get("encoder_counts_per_rev")
    if counts is not None:
        cols["encoder_counts_per_rev"] = counts
    return plant_truth(model, **over), counts, cols
