# Layer 4, presentation: matplotlib figures and the demo that writes them.
"""Figures (PNG, with provenance) of the analyses; the only layer that imports matplotlib.

* :mod:`.experiment` -- errors like the paper's Figs. 4-5, torques, theta_hat, repeated runs;
* :mod:`.demo` -- the main job (``make demo``): the experiment, its figures and results.json.
"""
from .experiment import experiment_figures, write_figures

__all__ = ["write_figures", "experiment_figures"]
