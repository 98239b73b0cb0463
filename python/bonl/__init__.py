"""bonl: identification of block-oriented nonlinear models of electro-hydraulic machines.

Models (after Yan et al., the excavator-arm paper, and the Wiener model): every class of
:data:`MODELS` (:class:`ARX`, :class:`Hammerstein`, :class:`HammersteinWiener`,
:class:`PseudoHammersteinWiener`, :class:`Wiener`); whole-record identification with :func:`identify`,
online estimation with :class:`Estimator`; :mod:`bonl.metrics`; the simulated excavator dipper joint
in :mod:`bonl.plant`, and :mod:`bonl.experiment`, the paper's experiment on it
(:func:`bonl.experiment.run_paper_experiment`).
"""

# Every public name of the C++ core: the model classes (one per entry of C++'s bonl::Models, so a
# new model needs no edit here), MODELS, identify, Estimator, load_model, ...
from ._bonl import *  # noqa: F401,F403
from ._bonl import __all__ as _core_names
from ._bonl import __version__
from . import experiment, metrics, plant

__all__ = sorted({*_core_names, "__version__", "experiment", "metrics", "plant"})
