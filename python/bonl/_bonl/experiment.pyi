"""
The paper's experiment on the simulated plant (bonl/experiment.hpp): ``run_paper_experiment`` and its
result, and the records' signal processing (``low_pass``, ``differentiate``).
"""
from __future__ import annotations
import bonl._bonl
import bonl._bonl.plant
import numpy
import numpy.typing
import typing
__all__: tuple = ('run_paper_experiment', 'PaperExperimentResult', 'MethodResult', 'ModelResult', 'Record', 'Timings', 'run_tracking_experiment', 'TrackingResult', 'TrackingRun', 'published_score', 'low_pass', 'differentiate')
class Record:
    """
    One processed record of the experiment, on the output grid (bonl/experiment/records.hpp).
    """
    def __repr__(self) -> str:
        ...
    @property
    def angle(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the averaged, low-passed measured angle [rad].
        """
    @property
    def input(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: u = V - V0 [V], the identification input.
        """
    @property
    def max_position(self) -> float:
        """
        float: largest piston position of the plant's run [m].
        """
    @property
    def min_position(self) -> float:
        """
        float: smallest piston position of the plant's run [m].
        """
    @property
    def reached_end_stop(self) -> bool:
        """
        bool: the piston left the stroke during the run.
        """
    @property
    def steps(self) -> int:
        """
        int: CVODE's internal steps for the run.
        """
    @property
    def time(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: [s].
        """
    @property
    def true_velocity(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the plant's joint rate, noise-free and unfiltered [rad/s].
        """
    @property
    def velocity(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: y, its numerical derivative [rad/s]: what the models are fitted on.
        """
class ModelResult:
    """
    One model of one method: the identified model, the online estimate and their scores.
    """
    def __repr__(self) -> str:
        ...
    @property
    def label(self) -> str:
        """
        str: how the paper's tables write it (e.g. 'H-W').
        """
    @property
    def model(self) -> bonl._bonl.ARX | bonl._bonl.Hammerstein | bonl._bonl.HammersteinWiener | bonl._bonl.PseudoHammersteinWiener | bonl._bonl.Wiener | bonl._bonl.WienerHammerstein | bonl._bonl.NonlinearFeedback | bonl._bonl.PrandtlIshlinskiiHammerstein | bonl._bonl.BoucWenFeedback | None:
        """
        The identified model (identify(): the recursive estimate refined), as its bonl class; None if
        its parameters are not finite.
        """
    @property
    def mse(self) -> float:
        """
        float: validation MSE of the velocity, free-run [(rad/s)^2]; inf when unstable.
        """
    @property
    def name(self) -> str:
        """
        str: the model's name (its class name, e.g. 'HammersteinWiener').
        """
    @property
    def online_model(self) -> bonl._bonl.ARX | bonl._bonl.Hammerstein | bonl._bonl.HammersteinWiener | bonl._bonl.PseudoHammersteinWiener | bonl._bonl.Wiener | bonl._bonl.WienerHammerstein | bonl._bonl.NonlinearFeedback | bonl._bonl.PrandtlIshlinskiiHammerstein | bonl._bonl.BoucWenFeedback | None:
        """
        The recursive estimator's model alone after one pass (no refinement); None if not finite.
        """
    @property
    def online_mse(self) -> float:
        """
        float: the online estimate's validation MSE [(rad/s)^2].
        """
    @property
    def online_seconds(self) -> float:
        """
        float: wall time of the one-pass recursive estimate [s].
        """
    @property
    def parameters(self) -> list[tuple[str, float]]:
        """
        list of (str, float): the parameters as the rows of the paper's Table 1, ('b0', b_0), ...
        """
    @property
    def params(self) -> dict[str, float | list[float]]:
        """
        dict: every parameter block by name (lists of float, a float for a one-number block).
        """
    @property
    def robustness_mse(self) -> list[float]:
        """
        list of float: validation MSE on each robustness trajectory (empty when not run).
        """
    @property
    def seconds(self) -> float:
        """
        float: wall time of identify() [s].
        """
    @property
    def simulated(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the free-run validation velocity [rad/s]; NaN when unstable.
        """
class MethodResult:
    """
    One estimator method's results, for every model of the experiment.
    """
    def __repr__(self) -> str:
        ...
    @property
    def method(self) -> str:
        """
        str: 'output_error' or 'paper'.
        """
    @property
    def models(self) -> dict[str, ModelResult]:
        """
        dict[str, ModelResult]: by model name, in the order of the paper's equations (ARX first).
        """
    @property
    def mse(self) -> dict[str, float]:
        """
        dict[str, float]: validation MSE by model name [(rad/s)^2].
        """
    @property
    def online_mse(self) -> dict[str, float]:
        """
        dict[str, float]: the online estimates' validation MSE by model name [(rad/s)^2].
        """
class Timings:
    """
    The wall time of each stage of the paper's experiment [s].
    """
    def to_dict(self) -> dict[str, float]:
        """
        Every stage by name.
        
        Returns
        -------
        dict[str, float]
        """
    @property
    def identification(self) -> float:
        """
        float: identification and validation, both methods, identify() and online [s].
        """
    @property
    def plant(self) -> float:
        """
        float: simulation and processing of the two records [s].
        """
    @property
    def robustness(self) -> float:
        """
        float: the robustness check (0 when it was not run) [s].
        """
class PaperExperimentResult:
    """
    Everything the paper's experiment gives (run_paper_experiment): the plant, the two records, both
    methods' results for every model, and the wall times.
    """
    def __repr__(self) -> str:
        ...
    def method(self, name: str) -> MethodResult:
        """
        One method's results.
        
        Parameters
        ----------
        name : str
            'output_error' or 'paper'.
        
        Returns
        -------
        MethodResult
        
        Raises
        ------
        ValueError
            For a method the experiment did not run.
        """
    @property
    def identification(self) -> Record:
        """
        Record: the identification record (the paper's multi-sine).
        """
    @property
    def methods(self) -> dict[str, MethodResult]:
        """
        dict[str, MethodResult]: {'output_error': ..., 'paper': ...}.
        """
    @property
    def model_names(self) -> tuple[str, ...]:
        """
        tuple of str: the experiment's models, in the order of the paper's equations (ARX first).
        """
    @property
    def parameters(self) -> bonl._bonl.plant.Parameters:
        """
        bonl.plant.Parameters: the plant the experiment ran on.
        """
    @property
    def robustness_trajectories(self) -> int:
        """
        int: trajectories of the robustness check (0 when it was not run).
        """
    @property
    def seconds(self) -> Timings:
        """
        Timings: wall time of each stage [s]: plant (records), identification (both methods,
        identify() and online), robustness.
        """
    @property
    def validation(self) -> Record:
        """
        Record: the validation record (a smooth random signal).
        """
class TrackingRun:
    """
    One controller's run of ``run_tracking_experiment``.
    """
    def __repr__(self) -> str:
        ...
    @property
    def command(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: V(k) applied [V].
        """
    @property
    def controller(self) -> str:
        """
        str: 'PI', a model's name (PI plus its inverse as feedforward), or '<model> (adaptive)'.
        """
    @property
    def feedforward(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the feedforward's part of the command [V] (0 for PI).
        """
    @property
    def inexact(self) -> int:
        """
        int: feedforward samples whose InverseStatus was not Exact.
        """
    @property
    def joint_rate(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the plant's true joint rate [rad/s].
        """
    @property
    def label(self) -> str:
        """
        str: as the tables write it: 'PI', 'PI + P-H-W', 'PI + P-H-W (adaptive)'.
        """
    @property
    def plant_changes(self) -> bool:
        """
        bool: the plant changed at change_time.
        """
    @property
    def rederivations(self) -> int:
        """
        int: adaptive: inverses derived from the estimate.
        """
    @property
    def refused(self) -> int:
        """
        int: adaptive: estimates the guard refused.
        """
    @property
    def rms(self) -> float:
        """
        float: RMS of reference - joint rate over [period, duration] [rad/s].
        """
    @property
    def rms_after_change(self) -> float:
        """
        float: the same over [change_time + period, change_time + 2 period].
        """
    @property
    def rms_before_change(self) -> float:
        """
        float: the same over the period before change_time.
        """
class TrackingResult:
    """
    What ``run_tracking_experiment`` gives.
    """
    def run(self, controller: str, plant_changes: bool = False) -> TrackingRun:
        """
        The run of a controller, with or without the plant change.
        
        Parameters
        ----------
        controller : str
            Its label, e.g. "PI + P-H-W".
        plant_changes : bool, default False
            True: the run with the plant change at 40 s.
        
        Returns
        -------
        TrackingRun
            The run.
        
        Raises
        ------
        ValueError
            When there is no such run.
        """
    @property
    def integral_time(self) -> float:
        """
        float: the PI's tau_I [s].
        """
    @property
    def proportional_gain(self) -> float:
        """
        float: the PI's Kc [V/(rad/s)].
        """
    @property
    def reference(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the reference joint velocity [rad/s].
        """
    @property
    def runs(self) -> list[TrackingRun]:
        """
        list of TrackingRun: PI and each model's feedforward; then PI, P-H-W and adaptive P-H-W under the plant change.
        """
    @property
    def time(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: t_k [s].
        """
    @property
    def tracking_rms(self) -> dict[str, float]:
        """
        dict: controller name -> tracking RMS, for the runs without the plant change (bonl_demo --control --json).
        """
def differentiate(x: numpy.typing.ArrayLike, ts: typing.SupportsFloat | typing.SupportsIndex) -> numpy.typing.NDArray[numpy.float64]:
    """
    Numerical derivative: central differences, one-sided at both ends.
    
    Parameters
    ----------
    x : array_like, 1-D
        Finite samples, at least 2.
    ts : float
        Sample time [s].
    
    Returns
    -------
    numpy.ndarray
    
    Raises
    ------
    ValueError
        When ``x`` is not 1-D, not finite or shorter than 2, or ts is not > 0.
    """
def low_pass(x: numpy.typing.ArrayLike, cutoff_hz: typing.SupportsFloat | typing.SupportsIndex, ts: typing.SupportsFloat | typing.SupportsIndex) -> numpy.typing.NDArray[numpy.float64]:
    """
    First-order low-pass z[k] = z[k-1] + alpha (x[k] - z[k-1]), alpha = 1 - exp(-2 pi fc ts), z[0] = x[0].
    
    Parameters
    ----------
    x : array_like, 1-D
        Finite samples.
    cutoff_hz : float
        fc [Hz].
    ts : float
        Sample time [s].
    
    Returns
    -------
    numpy.ndarray
    
    Raises
    ------
    ValueError
        When ``x`` is not 1-D or not finite, or fc or ts is not > 0.
    """
def published_score(name: str) -> tuple[float, int] | None:
    """
    The paper's Table 2 (the real excavator) for a model, for comparison.
    
    Parameters
    ----------
    name : str
        The model's name, e.g. 'HammersteinWiener'.
    
    Returns
    -------
    tuple of (float, int) or None
        Its validation MSE as published [(rad/s)^2] and how much lower the proposed model's
        (PseudoHammersteinWiener) is, in percent, as the paper states it (0 for the proposed model);
        None for a model the paper does not report.
    """
def run_paper_experiment(parameters: bonl._bonl.plant.Parameters | None = None, *, robustness: bool = False) -> PaperExperimentResult:
    """
    The paper's experiment on the plant, as ``bonl_demo`` runs it (docs/explanation/plant.md).
    
    Identification record from the paper's multi-sine, validation record from a smooth random
    signal (each 50 s at 100 Hz, 10 repeats averaged, 10 Hz low-pass, differentiated); every model of
    the experiment (ARX, Hammerstein, HammersteinWiener, PseudoHammersteinWiener, and beside them the
    PrandtlIshlinskiiHammerstein, which the paper does not have) identified with the paper's orders
    (na = 3, nb = 2, nk = 8, r = r1 = 3; np = 3 plays, their thresholds spread over the identification
    input's half-range) by the output-error and the paper's methods and validated by free-run
    simulation; also the online estimates (the estimator with its defaults, one pass, no offline refinement). The
    GIL is released during the computation.
    
    Parameters
    ----------
    parameters : bonl.plant.Parameters, optional
        The plant; None: ``bonl.plant.Parameters.excavator_20t()``.
    robustness : bool, optional
        Also validate on the eight further trajectories of ``bonl_demo``'s robustness check.
    
    Returns
    -------
    PaperExperimentResult
    
    Raises
    ------
    ValueError
        For non-physical parameters.
    """
def run_tracking_experiment(parameters: bonl._bonl.plant.Parameters | None = None, *, method: str = 'paper', reference_seed: typing.SupportsInt | typing.SupportsIndex = 2020, noise_seed: typing.SupportsInt | typing.SupportsIndex = 99) -> TrackingResult:
    """
    The tracking experiment, as ``bonl_demo --control`` runs it (docs/how-to/control.md).
    
    The paper experiment's models are identified on the plant; then the plant, stepped with its sensor
    noise, tracks a reference joint velocity under a PI loop alone (SIMC from the ARX model), the PI
    loop plus each model's inverse as feedforward, and, while the plant changes at 40 s (pilot
    hysteresis doubled, bulk modulus -30%), the PI alone, the P-H-W feedforward and the adaptive P-H-W
    feedforward (bonl.control.AdaptiveInverse in C++). The GIL is released.
    
    Parameters
    ----------
    parameters : bonl.plant.Parameters, optional
        The plant; None: the default.
    method : str, optional
        Which method's models feed forward: 'paper' (default) or 'output_error'.
    reference_seed, noise_seed : int, optional
        The reference's and the sensor noise's seeds.
    
    Returns
    -------
    TrackingResult
    
    Raises
    ------
    ValueError
        For non-physical parameters, an unknown method, or a model without an inverse.
    """
