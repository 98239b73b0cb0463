"""The paper's experiment on the simulated excavator dipper joint (docs/explanation/plant.md).

- :func:`run_paper_experiment`: what ``bonl_demo`` runs, in one call: the identification and the
  validation records, every model of the experiment identified with the paper's orders by the
  output-error method (bonl's default) and the paper's, validated by free-run simulation, the online
  estimates alone, and with ``robustness=True`` the robustness check;
- :class:`PaperExperimentResult` (its result), :class:`MethodResult`, :class:`ModelResult`,
  :class:`Record`: each model is named by its class name (``result.method("paper").models["ARX"]``);
- :func:`run_tracking_experiment`: what ``bonl_demo --control`` runs: a reference joint velocity
  tracked by a PI loop alone, with each identified model's inverse as feedforward, and with the
  adaptive P-H-W feedforward while the plant changes (docs/how-to/control.md); :class:`TrackingResult`,
  :class:`TrackingRun`;
- :func:`published_score`: the paper's own Table 2, for comparison;
- :func:`low_pass`, :func:`differentiate`: the records' signal processing.

Examples
--------
>>> from bonl import experiment
>>> result = experiment.run_paper_experiment()
>>> sorted(result.method("output_error").mse) == sorted(result.model_names)
True
"""

from ._bonl.experiment import *  # noqa: F401,F403

__all__ = [
    "run_paper_experiment",
    "PaperExperimentResult",
    "MethodResult",
    "ModelResult",
    "Record",
    "Timings",
    "run_tracking_experiment",
    "TrackingResult",
    "TrackingRun",
    "published_score",
    "low_pass",
    "differentiate",
]
