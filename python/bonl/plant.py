"""The excavator dipper-joint plant (docs/explanation/plant.md), integrated by SUNDIALS CVODE.

A valve with dead band and pilot-stage hysteresis, an asymmetric cylinder, the linkage to the
joint angle, pin backlash and an inclinometer: the plant the paper's experiment is run on.

- :class:`Parameters`, ``Parameters.excavator_20t()`` (the default, 20 t), ``Parameters.excavator_5t()`` (5-6 t);
- :class:`Command` and the submodule :mod:`bonl.plant.excitation` (step, multi-sine, the paper's
  multi-sine, smooth random, chirp, sampled hold);
- :func:`simulate`: every state, flow and angle on the output grid, as a :class:`Trajectory` of numpy arrays;
- :class:`SteppingPlant`: the same plant one sample per call, ``measurement = plant.step(command)``
  (a :class:`Measurement`), equal to :func:`simulate` sample for sample; :class:`SteppingEnv` is a
  gymnasium-style ``reset``/``step`` over it;
- :func:`initial_state`, :func:`derivative`: the right-hand side, for independent checks.

The paper's identification experiment on this plant, and the records' signal processing, are
:mod:`bonl.experiment`.

Examples
--------
>>> from bonl import plant
>>> run = plant.simulate(plant.excitation.paper_multisine(), duration=5.0)
>>> run.joint_rate.shape
(501,)
"""

import numpy as np

from ._bonl.plant import *  # noqa: F401,F403
from ._bonl.plant import SteppingPlant, excitation  # noqa: F401

__all__ = [
    "Parameters",
    "Command",
    "excitation",
    "simulate",
    "Trajectory",
    "initial_state",
    "derivative",
    "SteppingPlant",
    "Measurement",
    "SteppingEnv",
]


class SteppingEnv:
    """A gymnasium-style environment over :class:`SteppingPlant`, without depending on gymnasium.

    The action is the command voltage [V] (a float or a 1-element array), the observation the
    measured angle as a 1-element float64 array [rad], ``info`` the :class:`Measurement` as a dict
    (the true states). The reward is 0.0 (the task is the caller's); ``terminated`` is True when the
    step reached an end stop; ``truncated`` is always False. There are no ``observation_space`` or
    ``action_space`` objects (they are gymnasium's).

    Parameters
    ----------
    parameters : Parameters, optional
        The plant; None: ``Parameters.excavator_20t()``.
    **options
        :class:`SteppingPlant`'s keyword options (``sample_time``, ``noise_seed``, ``load``, ...).

    Examples
    --------
    >>> env = SteppingEnv(sample_time=0.01)
    >>> observation, info = env.reset(seed=3)
    >>> observation, reward, terminated, truncated, info = env.step(2.8)
    >>> info["time"]
    0.01
    """

    def __init__(self, parameters=None, **options):
        self.plant = SteppingPlant(parameters, **options)

    def reset(self, *, seed=None, options=None):
        """Back to rest at t = 0.

        Parameters
        ----------
        seed : int, optional
            The sensor noise's seed (None: the plant's, so that every episode replays the same noise).
        options : dict, optional
            May hold ``initial_position`` [m]; ValueError for any other key.

        Returns
        -------
        tuple
            ``(observation, info)``: the measured angle [rad] as a 1-element array, and the
            measurement as a dict.
        """
        options = dict(options or {})
        initial_position = options.pop("initial_position", None)
        if options:
            raise ValueError("bonl: SteppingEnv.reset: unknown options %s (initial_position)" % sorted(options))
        measurement = self.plant.reset(initial_position=initial_position, noise_seed=seed)
        return self._observation(measurement), measurement.to_dict()

    def step(self, action):
        """Hold the command over one sample.

        Parameters
        ----------
        action : float or 1-element array
            The command [V].

        Returns
        -------
        tuple
            ``(observation, reward, terminated, truncated, info)``: the measured angle [rad] as a
            1-element array, 0.0, whether the piston reached an end stop, False, and the measurement as
            a dict.
        """
        if np.ndim(action) == 1 and len(action) == 1:
            action = action[0]
        measurement = self.plant.step(action)
        return self._observation(measurement), 0.0, measurement.reached_end_stop, False, measurement.to_dict()

    @staticmethod
    def _observation(measurement):
        return np.array([measurement.measured_angle])
