"""The excavator dipper-joint plant (docs/plant.md), integrated by SUNDIALS CVODE.

A valve with dead band and pilot-stage hysteresis, an asymmetric cylinder, the linkage to the
joint angle, pin backlash and an inclinometer: the plant the paper's experiment is run on.

- :class:`Parameters`, :func:`default_parameters` (20 t), :func:`small_parameters` (5-6 t);
- :class:`Command` and the submodule :mod:`bonl.plant.excitation` (step, multi-sine, the paper's
  multi-sine, smooth random, chirp, sampled hold);
- :func:`simulate`: every state, flow and angle on the output grid, as a dict of numpy arrays;
- :func:`initial_state`, :func:`derivative`: the right-hand side, for independent checks.

The paper's identification experiment on this plant, and the records' signal processing, are
:mod:`bonl.experiment`.

Examples
--------
>>> from bonl import plant
>>> run = plant.simulate(plant.excitation.paper_multisine(), duration=5.0)
>>> run["joint_rate"].shape
(501,)
"""

from ._bonl.plant import *  # noqa: F401,F403
from ._bonl.plant import excitation  # noqa: F401

__all__ = [
    "Parameters",
    "default_parameters",
    "small_parameters",
    "Command",
    "excitation",
    "simulate",
    "initial_state",
    "derivative",
]
