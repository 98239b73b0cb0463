"""bonl: identification of block-oriented nonlinear models of electro-hydraulic machines.

Models (after Yan et al., the excavator-arm paper, the Wiener, the Wiener-Hammerstein, the
nonlinear-feedback (Lur'e), the Prandtl-Ishlinskii Hammerstein and the Bouc-Wen feedback model): every
class of :data:`MODELS` (:class:`ARX`, :class:`Hammerstein`, :class:`HammersteinWiener`,
:class:`PseudoHammersteinWiener`, :class:`Wiener`, :class:`WienerHammerstein`, :class:`NonlinearFeedback`,
:class:`PrandtlIshlinskiiHammerstein`, :class:`BoucWenFeedback`); whole-record identification with :func:`identify`,
online estimation with :class:`Estimator`; :mod:`bonl.metrics`; the inverse models for control in
:mod:`bonl.control`; the simulated excavator dipper joint in :mod:`bonl.plant`, and
:mod:`bonl.experiment`, the paper's experiment on it (:func:`bonl.experiment.run_paper_experiment`).
"""

import importlib as _importlib

# Every public name of the C++ core: the model classes (one per entry of C++'s bonl::Models, so a
# new model needs no edit here), MODELS, identify, Estimator, load_model, ...
from ._bonl import *  # noqa: F401,F403
from ._bonl import __all__ as _core_names
from ._bonl import __version__

# The extension registers the exception without a docstring (pybind11's register_exception takes none).
NumericalError.__doc__ = (  # noqa: F405
    "Numerical trouble found while computing: a diverging simulation, a covariance that lost\n"
    "positiveness, a non-finite intermediate result. The message says where. Bad input raises\n"
    "ValueError instead. A subclass of ArithmeticError."
)

# The Python modules over the C++ submodules. Imported by name: the star import above already bound
# these names to the C++ submodules, and `from . import metrics` would keep those.
control = _importlib.import_module(".control", __name__)
experiment = _importlib.import_module(".experiment", __name__)
metrics = _importlib.import_module(".metrics", __name__)
plant = _importlib.import_module(".plant", __name__)

from .selection import Selection, grid, named_orders, select  # noqa: E402  (order and structure selection)
from .structure_search import SearchResult, place_from_data, search  # noqa: E402  (a structure search, no grid)
from .data_file import read_columns, write_columns  # noqa: E402  (records from CSV files)
from .report import plot_fit, summary  # noqa: E402  (a model in words, its fit in a figure)

__all__ = sorted({*_core_names, "__version__", "control", "experiment", "metrics", "plant", "SearchResult", "Selection", "grid", "named_orders", "place_from_data", "plot_fit", "read_columns", "search", "select", "summary", "write_columns"})
