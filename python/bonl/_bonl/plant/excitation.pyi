"""
Command signals V(t) for the plant, on the 0-5 V scale around the neutral voltage (bonl/plant/excitation.hpp).
"""
from __future__ import annotations
import bonl._bonl.plant
import collections.abc
import numpy.typing
import typing
__all__: tuple = ('step', 'multisine', 'paper_multisine', 'smooth_random', 'chirp', 'sampled')
def chirp(f0_hz: typing.SupportsFloat | typing.SupportsIndex, f1_hz: typing.SupportsFloat | typing.SupportsIndex, duration: typing.SupportsFloat | typing.SupportsIndex, amplitude: typing.SupportsFloat | typing.SupportsIndex, offset: typing.SupportsFloat | typing.SupportsIndex = 2.5) -> bonl._bonl.plant.Command:
    """
    Linear chirp from f0 to f1 over [0, duration], then at f1 with a continuous phase.
    
    Parameters
    ----------
    f0_hz, f1_hz : float
        Start and end frequencies [Hz].
    duration : float
        [s].
    amplitude : float
        [V].
    offset : float, optional
        [V].
    
    Returns
    -------
    Command
    """
def multisine(frequencies_hz: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], amplitude: typing.SupportsFloat | typing.SupportsIndex, offset: typing.SupportsFloat | typing.SupportsIndex = 2.5, phases: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex] = []) -> bonl._bonl.plant.Command:
    """
    offset + amplitude * sum_i sin(2 pi f_i t + phase_i).
    
    Parameters
    ----------
    frequencies_hz : sequence of float
        Tones [Hz], finite and >= 0.
    amplitude : float
        Per tone [V].
    offset : float, optional
        [V].
    phases : sequence of float, optional
        [rad], one per tone; empty: Schroeder's phi_k = -pi k (k + 1) / n.
    
    Returns
    -------
    Command
    """
def paper_multisine(amplitude: typing.SupportsFloat | typing.SupportsIndex = 0.4, offset: typing.SupportsFloat | typing.SupportsIndex = 2.5) -> bonl._bonl.plant.Command:
    """
    The paper's identification input: tones 0.1, 0.2, 0.4, 0.5, 1 Hz, Schroeder phases.
    
    Parameters
    ----------
    amplitude : float, optional
        Per tone [V].
    offset : float, optional
        [V].
    
    Returns
    -------
    Command
    """
def sampled(values: numpy.typing.ArrayLike, ts: typing.SupportsFloat | typing.SupportsIndex, t0: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> bonl._bonl.plant.Command:
    """
    A sampled sequence held between samples (zero-order hold).
    
    values[k] on [t0 + k ts, t0 + (k+1) ts); before t0 the first value, after the end the last.
    
    Parameters
    ----------
    values : array_like, 1-D
        Finite voltages [V].
    ts : float
        Sample time [s].
    t0 : float, optional
        Time of the first sample [s].
    
    Returns
    -------
    Command
    
    Raises
    ------
    ValueError
        When ``values`` is empty, not 1-D or not finite, or ``ts`` is not > 0.
    """
def smooth_random(bandwidth_hz: typing.SupportsFloat | typing.SupportsIndex, rms: typing.SupportsFloat | typing.SupportsIndex, duration: typing.SupportsFloat | typing.SupportsIndex, seed: typing.SupportsInt | typing.SupportsIndex, offset: typing.SupportsFloat | typing.SupportsIndex = 2.5) -> bonl._bonl.plant.Command:
    """
    A smooth random signal band-limited to ``bandwidth_hz``.
    
    Equal sines at k / duration Hz for k = 1..floor(bandwidth_hz duration) with random phases, scaled
    so that its RMS over one period [0, duration] is exactly ``rms``, around ``offset``.
    
    Parameters
    ----------
    bandwidth_hz : float
        [Hz].
    rms : float
        [V].
    duration : float
        Period [s]; bandwidth_hz * duration must be >= 1.
    seed : int
        Random phases' seed.
    offset : float, optional
        [V].
    
    Returns
    -------
    Command
    """
def step(level: typing.SupportsFloat | typing.SupportsIndex, t_step: typing.SupportsFloat | typing.SupportsIndex = 0.0, before: typing.SupportsFloat | typing.SupportsIndex = 2.5) -> bonl._bonl.plant.Command:
    """
    A step: ``before`` until t_step, then ``level`` (at t_step itself: ``level``).
    
    Parameters
    ----------
    level : float
        Voltage after the step [V].
    t_step : float, optional
        Time of the step [s].
    before : float, optional
        Voltage before it [V].
    
    Returns
    -------
    Command
    """
