"""
Inverse models: the command that makes an identified model follow a reference (docs/how-to/control.md).
"""
from __future__ import annotations
import bonl._bonl
import numpy
import numpy.typing
import typing
__all__: list[str] = ['AdaptiveInverse', 'AdaptiveInverseHealth', 'InverseModel', 'InverseRun', 'InverseStatus', 'InverseStep']
class InverseStatus:
    """
    What an inverse reports with a command: flags, exact (0) when the model follows the reference. Combined flags are their sum (status & InverseStatus.saturated).
    
    Members:
    
      exact : the command makes the model reach the reference
    
      saturated : the command is at the end of its range (or of the input polynomial's monotone branch)
    
      dead_band : the reference asks for a w between the input polynomial's two segments at u = 0: command 0
    
      out_of_range : the output polynomial's monotone branch through 0 does not reach the reference: its end is used
    
      rejected_non_finite : a reference was NaN or infinite; the inverse is untouched
    
      rejected_overflow : the reference is so large that the inverse's arithmetic overflowed; the inverse is untouched
    
      rejected_short_preview : the reference window was shorter than window_size; the inverse is untouched
    """
    __members__: typing.ClassVar[dict[str, InverseStatus]]
    dead_band: typing.ClassVar[InverseStatus]
    exact: typing.ClassVar[InverseStatus]
    out_of_range: typing.ClassVar[InverseStatus]
    rejected_non_finite: typing.ClassVar[InverseStatus]
    rejected_overflow: typing.ClassVar[InverseStatus]
    rejected_short_preview: typing.ClassVar[InverseStatus]
    saturated: typing.ClassVar[InverseStatus]
    @typing.overload
    def __eq__(self, other: InverseStatus) -> bool:
        ...
    @typing.overload
    def __eq__(self, other: typing.Any) -> bool:
        ...
    @typing.overload
    def __ge__(self, other: InverseStatus) -> bool:
        ...
    @typing.overload
    def __ge__(self, other: typing.Any) -> None:
        ...
    def __getstate__(self) -> int:
        ...
    @typing.overload
    def __gt__(self, other: InverseStatus) -> bool:
        ...
    @typing.overload
    def __gt__(self, other: typing.Any) -> None:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self) -> int:
        ...
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __int__(self) -> int:
        ...
    @typing.overload
    def __le__(self, other: InverseStatus) -> bool:
        ...
    @typing.overload
    def __le__(self, other: typing.Any) -> None:
        ...
    @typing.overload
    def __lt__(self, other: InverseStatus) -> bool:
        ...
    @typing.overload
    def __lt__(self, other: typing.Any) -> None:
        ...
    @typing.overload
    def __ne__(self, other: InverseStatus) -> bool:
        ...
    @typing.overload
    def __ne__(self, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class InverseStep:
    """
    One command and what the inverse reports.
    """
    def __repr__(self) -> str:
        ...
    @property
    def status(self) -> int:
        """
        int: the InverseStatus flags (0: exact)
        """
    @property
    def value(self) -> float:
        """
        float: the command u(k)
        """
class InverseRun:
    """
    The commands for a whole reference.
    """
    @property
    def command(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: u(k) for every sample of the reference
        """
    @property
    def status(self) -> numpy.typing.NDArray[numpy.uint8]:
        """
        numpy.ndarray of uint8: each command's InverseStatus flags
        """
class InverseModel:
    """
    The inverse of an identified model.
    
    Per sample, given the reference output ``preview`` samples ahead, the command that makes the model
    follow it: the backlash inverse (P-H-W) or the output polynomial's inverse (H-W, Wiener), the linear
    block's inverse (exact where B is minimum phase, ZPETC where not), the input polynomial's inverse
    (Hammerstein, H-W, P-H-W) or the input hysteresis' (Prandtl-Ishlinskii Hammerstein, its plays' memory
    followed). docs/how-to/control.md.
    
    Parameters
    ----------
    model : one of bonl.MODELS
    command_min, command_max : float, optional
        The command range (the model's input units); it must contain the operating point's u0. Default:
        the model's input_range. Models with an input polynomial need it finite.
    backlash_band : float, default 0
        P-H-W: the backlash inverse's transition band (the output's units); 0 is the exact switch.
    backlash_band_per_c : float, default 0
        P-H-W: added to the band, times the model's c (1: a band of c).
    
    Raises ValueError where the model has no inverse (b_0 = 0, a zero of B at z = 1, q_1 = 0, an input
    polynomial that is not monotone through 0, input hysteresis whose slope can take either sign near 0).
    """
    @typing.overload
    def __init__(self, model: bonl._bonl.ARX, *, command_min: typing.SupportsFloat | typing.SupportsIndex | None = None, command_max: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_band: typing.SupportsFloat | typing.SupportsIndex = 0.0, backlash_band_per_c: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.Hammerstein, *, command_min: typing.SupportsFloat | typing.SupportsIndex | None = None, command_max: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_band: typing.SupportsFloat | typing.SupportsIndex = 0.0, backlash_band_per_c: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.HammersteinWiener, *, command_min: typing.SupportsFloat | typing.SupportsIndex | None = None, command_max: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_band: typing.SupportsFloat | typing.SupportsIndex = 0.0, backlash_band_per_c: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.PseudoHammersteinWiener, *, command_min: typing.SupportsFloat | typing.SupportsIndex | None = None, command_max: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_band: typing.SupportsFloat | typing.SupportsIndex = 0.0, backlash_band_per_c: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.Wiener, *, command_min: typing.SupportsFloat | typing.SupportsIndex | None = None, command_max: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_band: typing.SupportsFloat | typing.SupportsIndex = 0.0, backlash_band_per_c: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.WienerHammerstein, **kwargs) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.NonlinearFeedback, **kwargs) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.PrandtlIshlinskiiHammerstein, *, command_min: typing.SupportsFloat | typing.SupportsIndex | None = None, command_max: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_band: typing.SupportsFloat | typing.SupportsIndex = 0.0, backlash_band_per_c: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.BoucWenFeedback, **kwargs) -> None:
        ...
    def commands(self, reference: numpy.typing.ArrayLike) -> InverseRun:
        """
        The commands for a whole reference r(0..N-1), from rest (this object's state is not used).
        
        u(k) is computed from r(k + nk), ..., r(k + preview), the reference held at its last value beyond its end;
        model.simulate(run.command) then follows r from k = nk on where every status is exact.
        
        Parameters
        ----------
        reference : array_like, shape (N,)
            r(0..N-1), in the model's output units; finite, longer than preview (else ValueError).
        
        Returns
        -------
        InverseRun
            ``command``, the N commands, and ``status``, each command's InverseStatus.
        """
    def reset(self) -> None:
        """
        Back to rest, as the model's free run starts.
        """
    def step(self, reference: float | numpy.typing.ArrayLike) -> InverseStep:
        """
        The command u(k) for the reference ahead.
        
        Parameters
        ----------
        reference : float or 1-D array
            r(k + nk) (a float, where window_size is 1), or the window r(k + nk), ..., r(k + preview) (at
            least window_size entries).
        
        Returns
        -------
        InverseStep: ``value`` (the command) and ``status`` (InverseStatus flags). A non-finite reference or a
        window too short raises ValueError and leaves the inverse untouched.
        """
    @property
    def command_max(self) -> float:
        """
        float: the command range's upper end
        """
    @property
    def command_min(self) -> float:
        """
        float: the command range's lower end
        """
    @property
    def minimum_phase(self) -> bool:
        """
        bool: B's zeros all inside the unit circle (the exact inverse; else ZPETC)
        """
    @property
    def nk(self) -> int:
        """
        int: the model's delay
        """
    @property
    def preview(self) -> int:
        """
        int: how far ahead the last reference of a step lies (nk, plus ZPETC's preview)
        """
    @property
    def stable_factor(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: B_a, B's factor with the zeros inside the unit circle (b_0 included)
        """
    @property
    def unstable_factor(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: B_u, the factor with the others, leading 1 ([1.0] when minimum phase)
        """
    @property
    def window_size(self) -> int:
        """
        int: how many reference samples a step takes (1 when B is minimum phase)
        """
class AdaptiveInverseHealth:
    """
    What an AdaptiveInverse's guard did.
    """
    def __repr__(self) -> str:
        ...
    @property
    def last_refusal(self) -> str:
        """
        str: why the last refused estimate was refused ('' if none)
        """
    @property
    def rederivations(self) -> int:
        """
        int: new inverses put in use
        """
    @property
    def refused_covariance(self) -> int:
        """
        int: estimates refused: trace(P) above the limit
        """
    @property
    def refused_diverged(self) -> int:
        """
        int: estimates refused: the estimator had diverged
        """
    @property
    def refused_no_inverse(self) -> int:
        """
        int: estimates refused: InverseModel refused the estimate
        """
    @property
    def refused_unstable(self) -> int:
        """
        int: estimates refused: a pole at or beyond stability_radius
        """
class AdaptiveInverse:
    """
    The online estimator and the inverse together.
    
    ``update(u, y)`` feeds the command applied (feedback included) and the output measured to the
    estimator, warm-started from ``model``; every ``rederive_every`` samples the inverse is derived
    again from the estimate, if the guard trusts it (the estimator has not diverged, trace(P) <=
    max_covariance_trace * n * p0, every pole inside stability_radius, the estimate has an inverse), and
    goes on from where the old one was. ``step`` is the inverse in use. docs/how-to/control.md, "Adaptive use".
    
    Parameters
    ----------
    model : one of bonl.MODELS
        The identified model to start from.
    command_min, command_max, backlash_band, backlash_band_per_c
        As for InverseModel.
    method : {'output_error', 'equation_error', 'paper'}, default 'output_error'
        The recursive estimator (docs/explanation/algorithm.md). 'output_error': recursive prediction-error
        method on the free-run simulation error. 'equation_error': internal variables from the measured
        output (ARX: least squares). 'paper': eqs. (21)-(31) as written.
    forgetting : float, tuple or 'adaptive', optional
        Forgetting factor: a constant in (0, 1], (initial, initial_samples, final), or 'adaptive' (the
        adaptive memory). Default: 'adaptive' for output_error, the paper's 0.98 for 200 samples then 1
        for the others.
    p0 : float, optional
        P(0) = p0 I. Default: 10 for output_error, 1e6 for the others.
    rederive_every : int, default 100
    max_covariance_trace : float, default 10
    stability_radius : float, default 0.999
    
    Raises ValueError for bad options or a model without an inverse.
    """
    @typing.overload
    def __init__(self, model: bonl._bonl.ARX, *, command_min: typing.SupportsFloat | typing.SupportsIndex | None = None, command_max: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_band: typing.SupportsFloat | typing.SupportsIndex = 0.0, backlash_band_per_c: typing.SupportsFloat | typing.SupportsIndex = 0.0, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, rederive_every: typing.SupportsInt | typing.SupportsIndex = 100, max_covariance_trace: typing.SupportsFloat | typing.SupportsIndex = 10.0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.Hammerstein, *, command_min: typing.SupportsFloat | typing.SupportsIndex | None = None, command_max: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_band: typing.SupportsFloat | typing.SupportsIndex = 0.0, backlash_band_per_c: typing.SupportsFloat | typing.SupportsIndex = 0.0, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, rederive_every: typing.SupportsInt | typing.SupportsIndex = 100, max_covariance_trace: typing.SupportsFloat | typing.SupportsIndex = 10.0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.HammersteinWiener, *, command_min: typing.SupportsFloat | typing.SupportsIndex | None = None, command_max: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_band: typing.SupportsFloat | typing.SupportsIndex = 0.0, backlash_band_per_c: typing.SupportsFloat | typing.SupportsIndex = 0.0, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, rederive_every: typing.SupportsInt | typing.SupportsIndex = 100, max_covariance_trace: typing.SupportsFloat | typing.SupportsIndex = 10.0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.PseudoHammersteinWiener, *, command_min: typing.SupportsFloat | typing.SupportsIndex | None = None, command_max: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_band: typing.SupportsFloat | typing.SupportsIndex = 0.0, backlash_band_per_c: typing.SupportsFloat | typing.SupportsIndex = 0.0, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, rederive_every: typing.SupportsInt | typing.SupportsIndex = 100, max_covariance_trace: typing.SupportsFloat | typing.SupportsIndex = 10.0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.Wiener, *, command_min: typing.SupportsFloat | typing.SupportsIndex | None = None, command_max: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_band: typing.SupportsFloat | typing.SupportsIndex = 0.0, backlash_band_per_c: typing.SupportsFloat | typing.SupportsIndex = 0.0, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, rederive_every: typing.SupportsInt | typing.SupportsIndex = 100, max_covariance_trace: typing.SupportsFloat | typing.SupportsIndex = 10.0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.WienerHammerstein, **kwargs) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.NonlinearFeedback, **kwargs) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.PrandtlIshlinskiiHammerstein, *, command_min: typing.SupportsFloat | typing.SupportsIndex | None = None, command_max: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_band: typing.SupportsFloat | typing.SupportsIndex = 0.0, backlash_band_per_c: typing.SupportsFloat | typing.SupportsIndex = 0.0, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, rederive_every: typing.SupportsInt | typing.SupportsIndex = 100, max_covariance_trace: typing.SupportsFloat | typing.SupportsIndex = 10.0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999) -> None:
        ...
    @typing.overload
    def __init__(self, model: bonl._bonl.BoucWenFeedback, **kwargs) -> None:
        ...
    def rederive(self) -> bool:
        """
        Derive the inverse from the estimate now, if the guard trusts it.
        
        Returns
        -------
        bool
            Whether the new inverse is in use; if not, the last good one stays and health says why.
        """
    def step(self, reference: float | numpy.typing.ArrayLike) -> InverseStep:
        """
        The command u(k) for the reference ahead.
        
        Parameters
        ----------
        reference : float or 1-D array
            r(k + nk) (a float, where window_size is 1), or the window r(k + nk), ..., r(k + preview) (at
            least window_size entries).
        
        Returns
        -------
        InverseStep: ``value`` (the command) and ``status`` (InverseStatus flags). A non-finite reference or a
        window too short raises ValueError and leaves the inverse untouched.
        """
    def update(self, u: float, y: float) -> bonl._bonl.UpdateStatus:
        """
        One sample of the plant, to the estimator; every rederive_every samples, rederive().
        
        Parameters
        ----------
        u : float
            The command applied (the whole command, feedback included).
        y : float
            The output measured.
        
        Returns
        -------
        UpdateStatus
            The estimator's (rejected_non_finite for a NaN or infinite value: nothing changes).
        """
    @property
    def estimate(self) -> bonl._bonl.ARX | bonl._bonl.Hammerstein | bonl._bonl.HammersteinWiener | bonl._bonl.PseudoHammersteinWiener | bonl._bonl.Wiener | bonl._bonl.PrandtlIshlinskiiHammerstein:
        """
        The estimator's current estimate, as a model.
        """
    @property
    def health(self) -> AdaptiveInverseHealth:
        """
        AdaptiveInverseHealth: rederivations, the refusals by reason (refused_diverged,
        refused_covariance, refused_unstable, refused_no_inverse) and last_refusal (why, '' if none).
        """
    @property
    def model(self) -> bonl._bonl.ARX | bonl._bonl.Hammerstein | bonl._bonl.HammersteinWiener | bonl._bonl.PseudoHammersteinWiener | bonl._bonl.Wiener | bonl._bonl.PrandtlIshlinskiiHammerstein:
        """
        The model the inverse in use was derived from.
        """
