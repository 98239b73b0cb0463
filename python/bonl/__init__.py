"""bonl: identification of block-oriented nonlinear models of electro-hydraulic machines.

Models (after Yan et al., the excavator-arm paper): :class:`ARX`, :class:`Hammerstein`,
:class:`HammersteinWiener` and :class:`PseudoHammersteinWiener`; whole-record identification with
:func:`identify`, online estimation with :class:`Estimator`; :mod:`bonl.metrics`; the simulated
excavator dipper joint in :mod:`bonl.plant`, and :func:`experiment`, the paper's experiment on it.
"""

from ._bonl import (
    ARX,
    Estimator,
    Hammerstein,
    HammersteinWiener,
    NumericalError,
    PseudoHammersteinWiener,
    UpdateStatus,
    __version__,
    identify,
    load_model,
)
from . import metrics, plant
from .plant import experiment

__all__ = [
    "ARX",
    "Estimator",
    "Hammerstein",
    "HammersteinWiener",
    "NumericalError",
    "PseudoHammersteinWiener",
    "UpdateStatus",
    "__version__",
    "experiment",
    "identify",
    "load_model",
    "metrics",
    "plant",
]
