"""
bonl: identification of block-oriented nonlinear models (C++ core).
"""
from __future__ import annotations
from bonl import ExcitationWarning
from bonl import ExtrapolationWarning
from bonl import StabilityWarning
import collections.abc
import numpy
import numpy.typing
import typing
from . import metrics
from . import plant
from . import experiment
from . import control
__all__: list = ['ARX', 'BoucWenFeedback', 'Estimator', 'EstimatorHealth', 'EstimatorTrajectory', 'ExcitationWarning', 'ExtrapolationWarning', 'Hammerstein', 'HammersteinWiener', 'MODELS', 'NonlinearFeedback', 'NumericalError', 'PrandtlIshlinskiiHammerstein', 'PseudoHammersteinWiener', 'StabilityWarning', 'UpdateResults', 'UpdateStatus', 'Wiener', 'WienerHammerstein', 'WindowRefinementCounts', 'WindowRefinementOptions', 'control', 'experiment', 'identify', 'load_model', 'metrics', 'plant']
class NumericalError(ArithmeticError):
    """
    Numerical trouble found while computing: a diverging simulation, a covariance that lost
    positiveness, a non-finite intermediate result. The message says where. Bad input raises
    ValueError instead. A subclass of ArithmeticError.
    """
class ARX:
    """
    ARX model y(k) = -sum a_j y(k-j) + sum_{i=0..nb} b_i u(k-nk-i).
    
    Parameters
    ----------
    na : int
        poles of the linear block (na >= 1).
    nb : int
        B has nb + 1 coefficients b_0..b_nb.
    nk : int
        pure delay in samples.
    ni : int, optional
        integrators: poles fixed at 1 in the linear block's denominator (0..2); default 0.
    b : array_like, optional
        b_0..b_nb (b_0 is free for ARX).
    a : array_like, optional
        a_1..a_na.
    """
    ORDERS: typing.ClassVar[tuple] = ('na', 'nb', 'nk', 'ni')
    ORDER_DEFAULTS: typing.ClassVar[dict] = {'ni': 0}
    PAPER_ORDERS: typing.ClassVar[tuple] = (3, 2, 8, 0)
    def __copy__(self) -> ARX:
        ...
    def __deepcopy__(self, memo: dict) -> ARX:
        ...
    def __getstate__(self) -> str:
        ...
    def __init__(self, na: typing.SupportsInt | typing.SupportsIndex, nb: typing.SupportsInt | typing.SupportsIndex, nk: typing.SupportsInt | typing.SupportsIndex, ni: typing.SupportsInt | typing.SupportsIndex = 0, *, b: numpy.typing.ArrayLike | None = None, a: numpy.typing.ArrayLike | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: str) -> None:
        ...
    def extrapolated_samples(self, u: numpy.typing.ArrayLike) -> int:
        """
        How many samples of u lie outside input_range.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            An input record.
        
        Returns
        -------
        int
            The number of samples outside input_range (0: no extrapolation).
        """
    def predict(self, u: numpy.typing.ArrayLike, y: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        One-step-ahead prediction from measured data.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        y : array_like, shape (n,)
            Measured output; y[k] is used to predict y[k + 1].
        initial : (u_past, y_past), optional
            The measured samples just before u and y (None: from rest at the operating point).
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The prediction of y[k] from u up to k and y up to k - 1. Internal variables are taken from the
            measured output where the model lets them (Hammerstein: x = y; H-W: x = q^-1(y); P-H-W: the
            backlash memory is the measured y[k - 1]).
        """
    def rescaled(self, input_scale: typing.SupportsFloat | typing.SupportsIndex, output_scale: typing.SupportsFloat | typing.SupportsIndex) -> ARX:
        """
        The model of y = output_scale * model(u / input_scale): the same model for u and y in other units.
        
        Parameters
        ----------
        input_scale, output_scale : float
            The input's and the output's scale, finite and > 0.
        
        Returns
        -------
        model
            A model of this class, the parameters in the new units.
        """
    def simulate(self, u: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        Free-run simulation, from rest or after a measured past.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        initial : (u_past, y_past), optional
            The measured samples just before u. They set the model's state (its internal variables are what
            the measured past says, as predict() takes them); then the model runs on u alone. The
            benchmarks' state-initialisation window of m samples is
            ``model.simulate(u[m:], initial=(u[:m], y[:m]))``. None: from rest at the operating point.
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The model's output, driven by u alone after the initial state.
        
        Raises
        ------
        ValueError
            If u or the past is not a finite 1-D array, or u_past and y_past differ in length.
        bonl.NumericalError
            If the simulation leaves the finite numbers (an unstable model).
        """
    def to_json(self, indent: typing.SupportsInt | typing.SupportsIndex = -1) -> str:
        """
        The model in bonl's JSON model format (read by bonl.load_model and by C++'s bonl::io).
        
        Parameters
        ----------
        indent : int, default -1
            Spaces per level of nesting; -1 for one line.
        
        Returns
        -------
        str
            The model file's text.
        """
    @property
    def a(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: a_1..a_na.
        """
    @a.setter
    def a(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def b(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: b_0..b_nb (b_0 is free for ARX).
        """
    @b.setter
    def b(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def input_range(self) -> tuple[float, float]:
        """
        tuple (min, max): the inputs the model was identified on (identify() records them; (-inf, inf) unless set). simulate() gives a bonl.ExtrapolationWarning for inputs outside it.
        """
    @input_range.setter
    def input_range(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def na(self) -> int:
        """
        int: poles of the linear block (na >= 1).
        """
    @property
    def nb(self) -> int:
        """
        int: B has nb + 1 coefficients b_0..b_nb.
        """
    @property
    def ni(self) -> int:
        """
        int: integrators: poles fixed at 1 in the linear block's denominator (0..2).
        """
    @property
    def nk(self) -> int:
        """
        int: pure delay in samples.
        """
    @property
    def num_params(self) -> int:
        """
        int: number of identified parameters.
        """
    @property
    def operating_point(self) -> tuple[float, float]:
        """
        tuple (u0, y0): the input and output at which the model rests; its blocks map u - u0 to y - y0. (0, 0) unless set. identify() keeps the structure's.
        """
    @operating_point.setter
    def operating_point(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def orders(self) -> tuple[int, ...]:
        """
        tuple of int: the orders, as ORDERS names them.
        """
    @property
    def params(self) -> dict[str, float | numpy.typing.NDArray[numpy.float64]]:
        """
        dict: every parameter block by name, as the keyword arguments of the constructor take them.
        """
    @property
    def pole_radius(self) -> float:
        """
        float: the largest pole magnitude of the linear block: below 1 the model is stable, near 1 barely damped.
        """
    @property
    def theta(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the parameter vector in the order of eq. (19).
        """
    @theta.setter
    def theta(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
class Hammerstein:
    """
    Hammerstein model: two-segment input polynomial, then the linear block (b_0 = 1). w = sum_l f_l u^l + h(u) sum_l p_l u^l (h(u) = 1 for u < 0), x(k) = -sum a_j x(k-j) + sum b_i w(k-nk-i), y = x.
    
    Parameters
    ----------
    na : int
        poles of the linear block (na >= 1).
    nb : int
        B has nb + 1 coefficients b_0..b_nb, b_0 = 1.
    nk : int
        pure delay in samples.
    r : int
        degree of the input polynomials (r >= 1).
    ni : int, optional
        integrators: poles fixed at 1 in the linear block's denominator (0..2); default 0.
    b : array_like, optional
        b_0..b_nb with b_0 = 1.
    a : array_like, optional
        a_1..a_na.
    f : array_like, optional
        f_0..f_r, the input polynomial for u >= 0.
    p : array_like, optional
        p_0..p_r, its change for u < 0 (p_l = g_l - f_l).
    """
    ORDERS: typing.ClassVar[tuple] = ('na', 'nb', 'nk', 'r', 'ni')
    ORDER_DEFAULTS: typing.ClassVar[dict] = {'ni': 0}
    PAPER_ORDERS: typing.ClassVar[tuple] = (3, 2, 8, 3, 0)
    def __copy__(self) -> Hammerstein:
        ...
    def __deepcopy__(self, memo: dict) -> Hammerstein:
        ...
    def __getstate__(self) -> str:
        ...
    def __init__(self, na: typing.SupportsInt | typing.SupportsIndex, nb: typing.SupportsInt | typing.SupportsIndex, nk: typing.SupportsInt | typing.SupportsIndex, r: typing.SupportsInt | typing.SupportsIndex, ni: typing.SupportsInt | typing.SupportsIndex = 0, *, b: numpy.typing.ArrayLike | None = None, a: numpy.typing.ArrayLike | None = None, f: numpy.typing.ArrayLike | None = None, p: numpy.typing.ArrayLike | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: str) -> None:
        ...
    def extrapolated_samples(self, u: numpy.typing.ArrayLike) -> int:
        """
        How many samples of u lie outside input_range.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            An input record.
        
        Returns
        -------
        int
            The number of samples outside input_range (0: no extrapolation).
        """
    def predict(self, u: numpy.typing.ArrayLike, y: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        One-step-ahead prediction from measured data.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        y : array_like, shape (n,)
            Measured output; y[k] is used to predict y[k + 1].
        initial : (u_past, y_past), optional
            The measured samples just before u and y (None: from rest at the operating point).
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The prediction of y[k] from u up to k and y up to k - 1. Internal variables are taken from the
            measured output where the model lets them (Hammerstein: x = y; H-W: x = q^-1(y); P-H-W: the
            backlash memory is the measured y[k - 1]).
        """
    def rescaled(self, input_scale: typing.SupportsFloat | typing.SupportsIndex, output_scale: typing.SupportsFloat | typing.SupportsIndex) -> Hammerstein:
        """
        The model of y = output_scale * model(u / input_scale): the same model for u and y in other units.
        
        Parameters
        ----------
        input_scale, output_scale : float
            The input's and the output's scale, finite and > 0.
        
        Returns
        -------
        model
            A model of this class, the parameters in the new units.
        """
    def simulate(self, u: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        Free-run simulation, from rest or after a measured past.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        initial : (u_past, y_past), optional
            The measured samples just before u. They set the model's state (its internal variables are what
            the measured past says, as predict() takes them); then the model runs on u alone. The
            benchmarks' state-initialisation window of m samples is
            ``model.simulate(u[m:], initial=(u[:m], y[:m]))``. None: from rest at the operating point.
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The model's output, driven by u alone after the initial state.
        
        Raises
        ------
        ValueError
            If u or the past is not a finite 1-D array, or u_past and y_past differ in length.
        bonl.NumericalError
            If the simulation leaves the finite numbers (an unstable model).
        """
    def to_json(self, indent: typing.SupportsInt | typing.SupportsIndex = -1) -> str:
        """
        The model in bonl's JSON model format (read by bonl.load_model and by C++'s bonl::io).
        
        Parameters
        ----------
        indent : int, default -1
            Spaces per level of nesting; -1 for one line.
        
        Returns
        -------
        str
            The model file's text.
        """
    @property
    def a(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: a_1..a_na.
        """
    @a.setter
    def a(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def b(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: b_0..b_nb with b_0 = 1.
        """
    @b.setter
    def b(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def f(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: f_0..f_r, the input polynomial for u >= 0.
        """
    @f.setter
    def f(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def input_range(self) -> tuple[float, float]:
        """
        tuple (min, max): the inputs the model was identified on (identify() records them; (-inf, inf) unless set). simulate() gives a bonl.ExtrapolationWarning for inputs outside it.
        """
    @input_range.setter
    def input_range(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def na(self) -> int:
        """
        int: poles of the linear block (na >= 1).
        """
    @property
    def nb(self) -> int:
        """
        int: B has nb + 1 coefficients b_0..b_nb, b_0 = 1.
        """
    @property
    def ni(self) -> int:
        """
        int: integrators: poles fixed at 1 in the linear block's denominator (0..2).
        """
    @property
    def nk(self) -> int:
        """
        int: pure delay in samples.
        """
    @property
    def num_params(self) -> int:
        """
        int: number of identified parameters.
        """
    @property
    def operating_point(self) -> tuple[float, float]:
        """
        tuple (u0, y0): the input and output at which the model rests; its blocks map u - u0 to y - y0. (0, 0) unless set. identify() keeps the structure's.
        """
    @operating_point.setter
    def operating_point(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def orders(self) -> tuple[int, ...]:
        """
        tuple of int: the orders, as ORDERS names them.
        """
    @property
    def p(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: p_0..p_r, its change for u < 0 (p_l = g_l - f_l).
        """
    @p.setter
    def p(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def params(self) -> dict[str, float | numpy.typing.NDArray[numpy.float64]]:
        """
        dict: every parameter block by name, as the keyword arguments of the constructor take them.
        """
    @property
    def pole_radius(self) -> float:
        """
        float: the largest pole magnitude of the linear block: below 1 the model is stable, near 1 barely damped.
        """
    @property
    def r(self) -> int:
        """
        int: degree of the input polynomials (r >= 1).
        """
    @property
    def theta(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the parameter vector in the order of eq. (19).
        """
    @theta.setter
    def theta(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
class HammersteinWiener:
    """
    Hammerstein-Wiener model: the Hammerstein model followed by y = sum_{m=1..r1} q_m x^m (q_1 = 1).
    
    Parameters
    ----------
    na : int
        poles of the linear block (na >= 1).
    nb : int
        B has nb + 1 coefficients b_0..b_nb, b_0 = 1.
    nk : int
        pure delay in samples.
    r : int
        degree of the input polynomials (r >= 1).
    r1 : int
        degree of the output polynomial (2..32).
    ni : int, optional
        integrators: poles fixed at 1 in the linear block's denominator (0..2); default 0.
    b : array_like, optional
        b_0..b_nb with b_0 = 1.
    a : array_like, optional
        a_1..a_na.
    f : array_like, optional
        f_0..f_r, the input polynomial for u >= 0.
    p : array_like, optional
        p_0..p_r, its change for u < 0 (p_l = g_l - f_l).
    q : array_like, optional
        q_1..q_r1 with q_1 = 1.
    """
    ORDERS: typing.ClassVar[tuple] = ('na', 'nb', 'nk', 'r', 'r1', 'ni')
    ORDER_DEFAULTS: typing.ClassVar[dict] = {'ni': 0}
    PAPER_ORDERS: typing.ClassVar[tuple] = (3, 2, 8, 3, 3, 0)
    def __copy__(self) -> HammersteinWiener:
        ...
    def __deepcopy__(self, memo: dict) -> HammersteinWiener:
        ...
    def __getstate__(self) -> str:
        ...
    def __init__(self, na: typing.SupportsInt | typing.SupportsIndex, nb: typing.SupportsInt | typing.SupportsIndex, nk: typing.SupportsInt | typing.SupportsIndex, r: typing.SupportsInt | typing.SupportsIndex, r1: typing.SupportsInt | typing.SupportsIndex, ni: typing.SupportsInt | typing.SupportsIndex = 0, *, b: numpy.typing.ArrayLike | None = None, a: numpy.typing.ArrayLike | None = None, f: numpy.typing.ArrayLike | None = None, p: numpy.typing.ArrayLike | None = None, q: numpy.typing.ArrayLike | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: str) -> None:
        ...
    def extrapolated_samples(self, u: numpy.typing.ArrayLike) -> int:
        """
        How many samples of u lie outside input_range.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            An input record.
        
        Returns
        -------
        int
            The number of samples outside input_range (0: no extrapolation).
        """
    def predict(self, u: numpy.typing.ArrayLike, y: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        One-step-ahead prediction from measured data.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        y : array_like, shape (n,)
            Measured output; y[k] is used to predict y[k + 1].
        initial : (u_past, y_past), optional
            The measured samples just before u and y (None: from rest at the operating point).
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The prediction of y[k] from u up to k and y up to k - 1. Internal variables are taken from the
            measured output where the model lets them (Hammerstein: x = y; H-W: x = q^-1(y); P-H-W: the
            backlash memory is the measured y[k - 1]).
        """
    def rescaled(self, input_scale: typing.SupportsFloat | typing.SupportsIndex, output_scale: typing.SupportsFloat | typing.SupportsIndex) -> HammersteinWiener:
        """
        The model of y = output_scale * model(u / input_scale): the same model for u and y in other units.
        
        Parameters
        ----------
        input_scale, output_scale : float
            The input's and the output's scale, finite and > 0.
        
        Returns
        -------
        model
            A model of this class, the parameters in the new units.
        """
    def simulate(self, u: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        Free-run simulation, from rest or after a measured past.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        initial : (u_past, y_past), optional
            The measured samples just before u. They set the model's state (its internal variables are what
            the measured past says, as predict() takes them); then the model runs on u alone. The
            benchmarks' state-initialisation window of m samples is
            ``model.simulate(u[m:], initial=(u[:m], y[:m]))``. None: from rest at the operating point.
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The model's output, driven by u alone after the initial state.
        
        Raises
        ------
        ValueError
            If u or the past is not a finite 1-D array, or u_past and y_past differ in length.
        bonl.NumericalError
            If the simulation leaves the finite numbers (an unstable model).
        """
    def to_json(self, indent: typing.SupportsInt | typing.SupportsIndex = -1) -> str:
        """
        The model in bonl's JSON model format (read by bonl.load_model and by C++'s bonl::io).
        
        Parameters
        ----------
        indent : int, default -1
            Spaces per level of nesting; -1 for one line.
        
        Returns
        -------
        str
            The model file's text.
        """
    @property
    def a(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: a_1..a_na.
        """
    @a.setter
    def a(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def b(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: b_0..b_nb with b_0 = 1.
        """
    @b.setter
    def b(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def f(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: f_0..f_r, the input polynomial for u >= 0.
        """
    @f.setter
    def f(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def input_range(self) -> tuple[float, float]:
        """
        tuple (min, max): the inputs the model was identified on (identify() records them; (-inf, inf) unless set). simulate() gives a bonl.ExtrapolationWarning for inputs outside it.
        """
    @input_range.setter
    def input_range(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def na(self) -> int:
        """
        int: poles of the linear block (na >= 1).
        """
    @property
    def nb(self) -> int:
        """
        int: B has nb + 1 coefficients b_0..b_nb, b_0 = 1.
        """
    @property
    def ni(self) -> int:
        """
        int: integrators: poles fixed at 1 in the linear block's denominator (0..2).
        """
    @property
    def nk(self) -> int:
        """
        int: pure delay in samples.
        """
    @property
    def num_params(self) -> int:
        """
        int: number of identified parameters.
        """
    @property
    def operating_point(self) -> tuple[float, float]:
        """
        tuple (u0, y0): the input and output at which the model rests; its blocks map u - u0 to y - y0. (0, 0) unless set. identify() keeps the structure's.
        """
    @operating_point.setter
    def operating_point(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def orders(self) -> tuple[int, ...]:
        """
        tuple of int: the orders, as ORDERS names them.
        """
    @property
    def p(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: p_0..p_r, its change for u < 0 (p_l = g_l - f_l).
        """
    @p.setter
    def p(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def params(self) -> dict[str, float | numpy.typing.NDArray[numpy.float64]]:
        """
        dict: every parameter block by name, as the keyword arguments of the constructor take them.
        """
    @property
    def pole_radius(self) -> float:
        """
        float: the largest pole magnitude of the linear block: below 1 the model is stable, near 1 barely damped.
        """
    @property
    def q(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: q_1..q_r1 with q_1 = 1.
        """
    @q.setter
    def q(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def r(self) -> int:
        """
        int: degree of the input polynomials (r >= 1).
        """
    @property
    def r1(self) -> int:
        """
        int: degree of the output polynomial (2..32).
        """
    @property
    def theta(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the parameter vector in the order of eq. (19).
        """
    @theta.setter
    def theta(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
class PseudoHammersteinWiener:
    """
    Pseudo-Hammerstein-Wiener model: the Hammerstein model followed by a symmetric, unit-slope backlash of half-width c. y(k) = x(k) - c if x(k) > y(k-1) + c; x(k) + c if x(k) < y(k-1) - c; else y(k-1).
    
    Parameters
    ----------
    na : int
        poles of the linear block (na >= 1).
    nb : int
        B has nb + 1 coefficients b_0..b_nb, b_0 = 1.
    nk : int
        pure delay in samples.
    r : int
        degree of the input polynomials (r >= 1).
    ni : int, optional
        integrators: poles fixed at 1 in the linear block's denominator (0..2); default 0.
    b : array_like, optional
        b_0..b_nb with b_0 = 1.
    a : array_like, optional
        a_1..a_na.
    f : array_like, optional
        f_0..f_r, the input polynomial for u >= 0.
    p : array_like, optional
        p_0..p_r, its change for u < 0 (p_l = g_l - f_l).
    c : float, optional
        backlash half-width, >= 0.
    """
    ORDERS: typing.ClassVar[tuple] = ('na', 'nb', 'nk', 'r', 'ni')
    ORDER_DEFAULTS: typing.ClassVar[dict] = {'ni': 0}
    PAPER_ORDERS: typing.ClassVar[tuple] = (3, 2, 8, 3, 0)
    def __copy__(self) -> PseudoHammersteinWiener:
        ...
    def __deepcopy__(self, memo: dict) -> PseudoHammersteinWiener:
        ...
    def __getstate__(self) -> str:
        ...
    def __init__(self, na: typing.SupportsInt | typing.SupportsIndex, nb: typing.SupportsInt | typing.SupportsIndex, nk: typing.SupportsInt | typing.SupportsIndex, r: typing.SupportsInt | typing.SupportsIndex, ni: typing.SupportsInt | typing.SupportsIndex = 0, *, b: numpy.typing.ArrayLike | None = None, a: numpy.typing.ArrayLike | None = None, f: numpy.typing.ArrayLike | None = None, p: numpy.typing.ArrayLike | None = None, c: float | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: str) -> None:
        ...
    def extrapolated_samples(self, u: numpy.typing.ArrayLike) -> int:
        """
        How many samples of u lie outside input_range.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            An input record.
        
        Returns
        -------
        int
            The number of samples outside input_range (0: no extrapolation).
        """
    def predict(self, u: numpy.typing.ArrayLike, y: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        One-step-ahead prediction from measured data.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        y : array_like, shape (n,)
            Measured output; y[k] is used to predict y[k + 1].
        initial : (u_past, y_past), optional
            The measured samples just before u and y (None: from rest at the operating point).
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The prediction of y[k] from u up to k and y up to k - 1. Internal variables are taken from the
            measured output where the model lets them (Hammerstein: x = y; H-W: x = q^-1(y); P-H-W: the
            backlash memory is the measured y[k - 1]).
        """
    def rescaled(self, input_scale: typing.SupportsFloat | typing.SupportsIndex, output_scale: typing.SupportsFloat | typing.SupportsIndex) -> PseudoHammersteinWiener:
        """
        The model of y = output_scale * model(u / input_scale): the same model for u and y in other units.
        
        Parameters
        ----------
        input_scale, output_scale : float
            The input's and the output's scale, finite and > 0.
        
        Returns
        -------
        model
            A model of this class, the parameters in the new units.
        """
    def simulate(self, u: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        Free-run simulation, from rest or after a measured past.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        initial : (u_past, y_past), optional
            The measured samples just before u. They set the model's state (its internal variables are what
            the measured past says, as predict() takes them); then the model runs on u alone. The
            benchmarks' state-initialisation window of m samples is
            ``model.simulate(u[m:], initial=(u[:m], y[:m]))``. None: from rest at the operating point.
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The model's output, driven by u alone after the initial state.
        
        Raises
        ------
        ValueError
            If u or the past is not a finite 1-D array, or u_past and y_past differ in length.
        bonl.NumericalError
            If the simulation leaves the finite numbers (an unstable model).
        """
    def to_json(self, indent: typing.SupportsInt | typing.SupportsIndex = -1) -> str:
        """
        The model in bonl's JSON model format (read by bonl.load_model and by C++'s bonl::io).
        
        Parameters
        ----------
        indent : int, default -1
            Spaces per level of nesting; -1 for one line.
        
        Returns
        -------
        str
            The model file's text.
        """
    @property
    def a(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: a_1..a_na.
        """
    @a.setter
    def a(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def b(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: b_0..b_nb with b_0 = 1.
        """
    @b.setter
    def b(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def c(self) -> float:
        """
        float: backlash half-width.
        """
    @c.setter
    def c(self, arg1: float) -> None:
        ...
    @property
    def f(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: f_0..f_r, the input polynomial for u >= 0.
        """
    @f.setter
    def f(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def input_range(self) -> tuple[float, float]:
        """
        tuple (min, max): the inputs the model was identified on (identify() records them; (-inf, inf) unless set). simulate() gives a bonl.ExtrapolationWarning for inputs outside it.
        """
    @input_range.setter
    def input_range(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def na(self) -> int:
        """
        int: poles of the linear block (na >= 1).
        """
    @property
    def nb(self) -> int:
        """
        int: B has nb + 1 coefficients b_0..b_nb, b_0 = 1.
        """
    @property
    def ni(self) -> int:
        """
        int: integrators: poles fixed at 1 in the linear block's denominator (0..2).
        """
    @property
    def nk(self) -> int:
        """
        int: pure delay in samples.
        """
    @property
    def num_params(self) -> int:
        """
        int: number of identified parameters.
        """
    @property
    def operating_point(self) -> tuple[float, float]:
        """
        tuple (u0, y0): the input and output at which the model rests; its blocks map u - u0 to y - y0. (0, 0) unless set. identify() keeps the structure's.
        """
    @operating_point.setter
    def operating_point(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def orders(self) -> tuple[int, ...]:
        """
        tuple of int: the orders, as ORDERS names them.
        """
    @property
    def p(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: p_0..p_r, its change for u < 0 (p_l = g_l - f_l).
        """
    @p.setter
    def p(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def params(self) -> dict[str, float | numpy.typing.NDArray[numpy.float64]]:
        """
        dict: every parameter block by name, as the keyword arguments of the constructor take them.
        """
    @property
    def pole_radius(self) -> float:
        """
        float: the largest pole magnitude of the linear block: below 1 the model is stable, near 1 barely damped.
        """
    @property
    def r(self) -> int:
        """
        int: degree of the input polynomials (r >= 1).
        """
    @property
    def theta(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the parameter vector in the order of eq. (19).
        """
    @theta.setter
    def theta(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
class Wiener:
    """
    Wiener model: the linear block x(k) = -sum a_j x(k-j) + sum_{i=0..nb} b_i u(k-nk-i), then y = sum_{m=1..r1} q_m x^m (q_1 = 1).
    
    Parameters
    ----------
    na : int
        poles of the linear block (na >= 1).
    nb : int
        B has nb + 1 coefficients b_0..b_nb.
    nk : int
        pure delay in samples.
    r1 : int
        degree of the output polynomial (2..32).
    ni : int, optional
        integrators: poles fixed at 1 in the linear block's denominator (0..2); default 0.
    b : array_like, optional
        b_0..b_nb (b_0 is free: q_1 = 1 fixes the gain).
    a : array_like, optional
        a_1..a_na.
    q : array_like, optional
        q_1..q_r1 with q_1 = 1.
    """
    ORDERS: typing.ClassVar[tuple] = ('na', 'nb', 'nk', 'r1', 'ni')
    ORDER_DEFAULTS: typing.ClassVar[dict] = {'ni': 0}
    PAPER_ORDERS: typing.ClassVar[tuple] = (3, 2, 8, 3, 0)
    def __copy__(self) -> Wiener:
        ...
    def __deepcopy__(self, memo: dict) -> Wiener:
        ...
    def __getstate__(self) -> str:
        ...
    def __init__(self, na: typing.SupportsInt | typing.SupportsIndex, nb: typing.SupportsInt | typing.SupportsIndex, nk: typing.SupportsInt | typing.SupportsIndex, r1: typing.SupportsInt | typing.SupportsIndex, ni: typing.SupportsInt | typing.SupportsIndex = 0, *, b: numpy.typing.ArrayLike | None = None, a: numpy.typing.ArrayLike | None = None, q: numpy.typing.ArrayLike | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: str) -> None:
        ...
    def extrapolated_samples(self, u: numpy.typing.ArrayLike) -> int:
        """
        How many samples of u lie outside input_range.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            An input record.
        
        Returns
        -------
        int
            The number of samples outside input_range (0: no extrapolation).
        """
    def predict(self, u: numpy.typing.ArrayLike, y: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        One-step-ahead prediction from measured data.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        y : array_like, shape (n,)
            Measured output; y[k] is used to predict y[k + 1].
        initial : (u_past, y_past), optional
            The measured samples just before u and y (None: from rest at the operating point).
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The prediction of y[k] from u up to k and y up to k - 1. Internal variables are taken from the
            measured output where the model lets them (Hammerstein: x = y; H-W: x = q^-1(y); P-H-W: the
            backlash memory is the measured y[k - 1]).
        """
    def rescaled(self, input_scale: typing.SupportsFloat | typing.SupportsIndex, output_scale: typing.SupportsFloat | typing.SupportsIndex) -> Wiener:
        """
        The model of y = output_scale * model(u / input_scale): the same model for u and y in other units.
        
        Parameters
        ----------
        input_scale, output_scale : float
            The input's and the output's scale, finite and > 0.
        
        Returns
        -------
        model
            A model of this class, the parameters in the new units.
        """
    def simulate(self, u: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        Free-run simulation, from rest or after a measured past.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        initial : (u_past, y_past), optional
            The measured samples just before u. They set the model's state (its internal variables are what
            the measured past says, as predict() takes them); then the model runs on u alone. The
            benchmarks' state-initialisation window of m samples is
            ``model.simulate(u[m:], initial=(u[:m], y[:m]))``. None: from rest at the operating point.
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The model's output, driven by u alone after the initial state.
        
        Raises
        ------
        ValueError
            If u or the past is not a finite 1-D array, or u_past and y_past differ in length.
        bonl.NumericalError
            If the simulation leaves the finite numbers (an unstable model).
        """
    def to_json(self, indent: typing.SupportsInt | typing.SupportsIndex = -1) -> str:
        """
        The model in bonl's JSON model format (read by bonl.load_model and by C++'s bonl::io).
        
        Parameters
        ----------
        indent : int, default -1
            Spaces per level of nesting; -1 for one line.
        
        Returns
        -------
        str
            The model file's text.
        """
    @property
    def a(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: a_1..a_na.
        """
    @a.setter
    def a(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def b(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: b_0..b_nb (b_0 is free: q_1 = 1 fixes the gain).
        """
    @b.setter
    def b(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def input_range(self) -> tuple[float, float]:
        """
        tuple (min, max): the inputs the model was identified on (identify() records them; (-inf, inf) unless set). simulate() gives a bonl.ExtrapolationWarning for inputs outside it.
        """
    @input_range.setter
    def input_range(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def na(self) -> int:
        """
        int: poles of the linear block (na >= 1).
        """
    @property
    def nb(self) -> int:
        """
        int: B has nb + 1 coefficients b_0..b_nb.
        """
    @property
    def ni(self) -> int:
        """
        int: integrators: poles fixed at 1 in the linear block's denominator (0..2).
        """
    @property
    def nk(self) -> int:
        """
        int: pure delay in samples.
        """
    @property
    def num_params(self) -> int:
        """
        int: number of identified parameters.
        """
    @property
    def operating_point(self) -> tuple[float, float]:
        """
        tuple (u0, y0): the input and output at which the model rests; its blocks map u - u0 to y - y0. (0, 0) unless set. identify() keeps the structure's.
        """
    @operating_point.setter
    def operating_point(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def orders(self) -> tuple[int, ...]:
        """
        tuple of int: the orders, as ORDERS names them.
        """
    @property
    def params(self) -> dict[str, float | numpy.typing.NDArray[numpy.float64]]:
        """
        dict: every parameter block by name, as the keyword arguments of the constructor take them.
        """
    @property
    def pole_radius(self) -> float:
        """
        float: the largest pole magnitude of the linear block: below 1 the model is stable, near 1 barely damped.
        """
    @property
    def q(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: q_1..q_r1 with q_1 = 1.
        """
    @q.setter
    def q(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def r1(self) -> int:
        """
        int: degree of the output polynomial (2..32).
        """
    @property
    def theta(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the parameter vector in the order of eq. (19).
        """
    @theta.setter
    def theta(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
class WienerHammerstein:
    """
    Wiener-Hammerstein model: the linear block x1 = z^-nk B1/A1 u, then the static nonlinearity w = sum_{m=1..r} f_m x1^m + sum_{j=1..nh} g_j h(x1 - knots_j) (f_1 = 1; h the hinge, zero between 0 and its knot), then the linear block y = B2/A2 w (b2_0 = 1).
    
    Parameters
    ----------
    na1 : int
        poles of the first linear block (na1 >= 1).
    nb1 : int
        B1 has nb1 + 1 coefficients b1_0..b1_nb1.
    nk : int
        pure delay in samples (in the first block).
    r : int
        degree of the static polynomial (1..32; 1: no polynomial terms).
    nh : int
        hinges of the static nonlinearity, knots where its slope changes (0..32; 0: none).
    na2 : int
        poles of the second linear block (na2 >= 1).
    nb2 : int
        B2 has nb2 + 1 coefficients b2_0..b2_nb2, b2_0 = 1.
    ni : int, optional
        integrators: poles fixed at 1 in the linear block's denominator (0..2); default 0.
    b1 : array_like, optional
        b1_0..b1_nb1 (free: f_1 = b2_0 = 1 fix the other gains).
    a1 : array_like, optional
        a1_1..a1_na1.
    f : array_like, optional
        f_1..f_r with f_1 = 1.
    knots : array_like, optional
        knots_1..knots_nh, where the slope changes: strictly increasing, none at 0 (structure, not estimated).
    g : array_like, optional
        g_1..g_nh, the change of slope outward of each knot.
    b2 : array_like, optional
        b2_0..b2_nb2 with b2_0 = 1.
    a2 : array_like, optional
        a2_1..a2_na2.
    """
    ORDERS: typing.ClassVar[tuple] = ('na1', 'nb1', 'nk', 'r', 'nh', 'na2', 'nb2', 'ni')
    ORDER_DEFAULTS: typing.ClassVar[dict] = {'ni': 0}
    PAPER_ORDERS: typing.ClassVar[tuple] = (3, 2, 8, 3, 0, 3, 2, 0)
    def __copy__(self) -> WienerHammerstein:
        ...
    def __deepcopy__(self, memo: dict) -> WienerHammerstein:
        ...
    def __getstate__(self) -> str:
        ...
    def __init__(self, na1: typing.SupportsInt | typing.SupportsIndex, nb1: typing.SupportsInt | typing.SupportsIndex, nk: typing.SupportsInt | typing.SupportsIndex, r: typing.SupportsInt | typing.SupportsIndex, nh: typing.SupportsInt | typing.SupportsIndex, na2: typing.SupportsInt | typing.SupportsIndex, nb2: typing.SupportsInt | typing.SupportsIndex, ni: typing.SupportsInt | typing.SupportsIndex = 0, *, b1: numpy.typing.ArrayLike | None = None, a1: numpy.typing.ArrayLike | None = None, f: numpy.typing.ArrayLike | None = None, knots: numpy.typing.ArrayLike | None = None, g: numpy.typing.ArrayLike | None = None, b2: numpy.typing.ArrayLike | None = None, a2: numpy.typing.ArrayLike | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: str) -> None:
        ...
    def extrapolated_samples(self, u: numpy.typing.ArrayLike) -> int:
        """
        How many samples of u lie outside input_range.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            An input record.
        
        Returns
        -------
        int
            The number of samples outside input_range (0: no extrapolation).
        """
    def predict(self, u: numpy.typing.ArrayLike, y: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        One-step-ahead prediction from measured data.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        y : array_like, shape (n,)
            Measured output; y[k] is used to predict y[k + 1].
        initial : (u_past, y_past), optional
            The measured samples just before u and y (None: from rest at the operating point).
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The prediction of y[k] from u up to k and y up to k - 1. Internal variables are taken from the
            measured output where the model lets them (Hammerstein: x = y; H-W: x = q^-1(y); P-H-W: the
            backlash memory is the measured y[k - 1]).
        """
    def rescaled(self, input_scale: typing.SupportsFloat | typing.SupportsIndex, output_scale: typing.SupportsFloat | typing.SupportsIndex) -> WienerHammerstein:
        """
        The model of y = output_scale * model(u / input_scale): the same model for u and y in other units.
        
        Parameters
        ----------
        input_scale, output_scale : float
            The input's and the output's scale, finite and > 0.
        
        Returns
        -------
        model
            A model of this class, the parameters in the new units.
        """
    def simulate(self, u: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        Free-run simulation, from rest or after a measured past.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        initial : (u_past, y_past), optional
            The measured samples just before u. They set the model's state (its internal variables are what
            the measured past says, as predict() takes them); then the model runs on u alone. The
            benchmarks' state-initialisation window of m samples is
            ``model.simulate(u[m:], initial=(u[:m], y[:m]))``. None: from rest at the operating point.
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The model's output, driven by u alone after the initial state.
        
        Raises
        ------
        ValueError
            If u or the past is not a finite 1-D array, or u_past and y_past differ in length.
        bonl.NumericalError
            If the simulation leaves the finite numbers (an unstable model).
        """
    def to_json(self, indent: typing.SupportsInt | typing.SupportsIndex = -1) -> str:
        """
        The model in bonl's JSON model format (read by bonl.load_model and by C++'s bonl::io).
        
        Parameters
        ----------
        indent : int, default -1
            Spaces per level of nesting; -1 for one line.
        
        Returns
        -------
        str
            The model file's text.
        """
    @property
    def a1(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: a1_1..a1_na1.
        """
    @a1.setter
    def a1(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def a2(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: a2_1..a2_na2.
        """
    @a2.setter
    def a2(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def b1(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: b1_0..b1_nb1 (free: f_1 = b2_0 = 1 fix the other gains).
        """
    @b1.setter
    def b1(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def b2(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: b2_0..b2_nb2 with b2_0 = 1.
        """
    @b2.setter
    def b2(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def f(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: f_1..f_r with f_1 = 1.
        """
    @f.setter
    def f(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def g(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: g_1..g_nh, the change of slope outward of each knot.
        """
    @g.setter
    def g(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def input_range(self) -> tuple[float, float]:
        """
        tuple (min, max): the inputs the model was identified on (identify() records them; (-inf, inf) unless set). simulate() gives a bonl.ExtrapolationWarning for inputs outside it.
        """
    @input_range.setter
    def input_range(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def knots(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: knots_1..knots_nh, where the slope changes: strictly increasing, none at 0 (structure, not estimated).
        """
    @knots.setter
    def knots(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def na1(self) -> int:
        """
        int: poles of the first linear block (na1 >= 1).
        """
    @property
    def na2(self) -> int:
        """
        int: poles of the second linear block (na2 >= 1).
        """
    @property
    def nb1(self) -> int:
        """
        int: B1 has nb1 + 1 coefficients b1_0..b1_nb1.
        """
    @property
    def nb2(self) -> int:
        """
        int: B2 has nb2 + 1 coefficients b2_0..b2_nb2, b2_0 = 1.
        """
    @property
    def nh(self) -> int:
        """
        int: hinges of the static nonlinearity, knots where its slope changes (0..32; 0: none).
        """
    @property
    def ni(self) -> int:
        """
        int: integrators: poles fixed at 1 in the linear block's denominator (0..2).
        """
    @property
    def nk(self) -> int:
        """
        int: pure delay in samples (in the first block).
        """
    @property
    def num_params(self) -> int:
        """
        int: number of identified parameters.
        """
    @property
    def operating_point(self) -> tuple[float, float]:
        """
        tuple (u0, y0): the input and output at which the model rests; its blocks map u - u0 to y - y0. (0, 0) unless set. identify() keeps the structure's.
        """
    @operating_point.setter
    def operating_point(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def orders(self) -> tuple[int, ...]:
        """
        tuple of int: the orders, as ORDERS names them.
        """
    @property
    def params(self) -> dict[str, float | numpy.typing.NDArray[numpy.float64]]:
        """
        dict: every parameter block by name, as the keyword arguments of the constructor take them.
        """
    @property
    def pole_radius(self) -> float:
        """
        float: the largest pole magnitude of the linear block: below 1 the model is stable, near 1 barely damped.
        """
    @property
    def r(self) -> int:
        """
        int: degree of the static polynomial (1..32; 1: no polynomial terms).
        """
    @property
    def theta(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the parameter vector in the order of eq. (19).
        """
    @theta.setter
    def theta(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
class NonlinearFeedback:
    """
    Nonlinear-feedback (Lur'e) model: y(k) = -sum a_j y(k-j) + sum b_i u(k-nk-i) + sum_{j=1..nd} d_j f(s(k-j)), f(s) = sum_{m=2..r} f_m s^m + sum_{l=1..nh} g_l h(s - knots_l) (h the hinge, zero between 0 and its knot) + sum_{i=1..np} w_i play_{r_i}[s] (play operators, hysteresis with memory), d_1 = 1, s = y (nv = 0) or y(k) - y(k-1) (nv = 1).
    
    Parameters
    ----------
    na : int
        poles of the linear block (na >= 1).
    nb : int
        B has nb + 1 coefficients b_0..b_nb.
    nk : int
        pure delay of the input in samples.
    r : int
        degree of the feedback polynomial (1..32; 1: no polynomial terms).
    nh : int
        hinges of the feedback nonlinearity, knots where its slope changes (0..32; 0: none).
    nd : int
        taps of the feedback block D = d_1 q^-1 + ... + d_nd q^-nd, d_1 = 1 (1..32).
    nv : int
        what the nonlinearity sees: 0 the output y, 1 its first difference (a velocity).
    np : int, optional
        play operators of the feedback's hysteresis (0..32; 0: none); default 0.
    ni : int, optional
        integrators: poles fixed at 1 in the linear block's denominator (0..2); default 0.
    b : array_like, optional
        b_0..b_nb.
    a : array_like, optional
        a_1..a_na.
    f : array_like, optional
        f_2..f_r, the feedback polynomial's coefficients (none for r = 1).
    knots : array_like, optional
        knots_1..knots_nh, where the slope changes: strictly increasing, none at 0 (structure, not estimated).
    g : array_like, optional
        g_1..g_nh, the change of slope outward of each knot.
    thresholds : array_like, optional
        r_1..r_np, the plays' thresholds: strictly increasing, > 0 (structure, not estimated).
    w : array_like, optional
        w_1..w_np, the plays' weights.
    d : array_like, optional
        d_1..d_nd with d_1 = 1.
    """
    ORDERS: typing.ClassVar[tuple] = ('na', 'nb', 'nk', 'r', 'nh', 'nd', 'nv', 'np', 'ni')
    ORDER_DEFAULTS: typing.ClassVar[dict] = {'np': 0, 'ni': 0}
    PAPER_ORDERS: typing.ClassVar[tuple] = (3, 2, 8, 3, 0, 2, 0, 0, 0)
    def __copy__(self) -> NonlinearFeedback:
        ...
    def __deepcopy__(self, memo: dict) -> NonlinearFeedback:
        ...
    def __getstate__(self) -> str:
        ...
    def __init__(self, na: typing.SupportsInt | typing.SupportsIndex, nb: typing.SupportsInt | typing.SupportsIndex, nk: typing.SupportsInt | typing.SupportsIndex, r: typing.SupportsInt | typing.SupportsIndex, nh: typing.SupportsInt | typing.SupportsIndex, nd: typing.SupportsInt | typing.SupportsIndex, nv: typing.SupportsInt | typing.SupportsIndex, np: typing.SupportsInt | typing.SupportsIndex = 0, ni: typing.SupportsInt | typing.SupportsIndex = 0, *, b: numpy.typing.ArrayLike | None = None, a: numpy.typing.ArrayLike | None = None, f: numpy.typing.ArrayLike | None = None, knots: numpy.typing.ArrayLike | None = None, g: numpy.typing.ArrayLike | None = None, thresholds: numpy.typing.ArrayLike | None = None, w: numpy.typing.ArrayLike | None = None, d: numpy.typing.ArrayLike | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: str) -> None:
        ...
    def extrapolated_samples(self, u: numpy.typing.ArrayLike) -> int:
        """
        How many samples of u lie outside input_range.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            An input record.
        
        Returns
        -------
        int
            The number of samples outside input_range (0: no extrapolation).
        """
    def predict(self, u: numpy.typing.ArrayLike, y: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        One-step-ahead prediction from measured data.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        y : array_like, shape (n,)
            Measured output; y[k] is used to predict y[k + 1].
        initial : (u_past, y_past), optional
            The measured samples just before u and y (None: from rest at the operating point).
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The prediction of y[k] from u up to k and y up to k - 1. Internal variables are taken from the
            measured output where the model lets them (Hammerstein: x = y; H-W: x = q^-1(y); P-H-W: the
            backlash memory is the measured y[k - 1]).
        """
    def rescaled(self, input_scale: typing.SupportsFloat | typing.SupportsIndex, output_scale: typing.SupportsFloat | typing.SupportsIndex) -> NonlinearFeedback:
        """
        The model of y = output_scale * model(u / input_scale): the same model for u and y in other units.
        
        Parameters
        ----------
        input_scale, output_scale : float
            The input's and the output's scale, finite and > 0.
        
        Returns
        -------
        model
            A model of this class, the parameters in the new units.
        """
    def simulate(self, u: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        Free-run simulation, from rest or after a measured past.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        initial : (u_past, y_past), optional
            The measured samples just before u. They set the model's state (its internal variables are what
            the measured past says, as predict() takes them); then the model runs on u alone. The
            benchmarks' state-initialisation window of m samples is
            ``model.simulate(u[m:], initial=(u[:m], y[:m]))``. None: from rest at the operating point.
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The model's output, driven by u alone after the initial state.
        
        Raises
        ------
        ValueError
            If u or the past is not a finite 1-D array, or u_past and y_past differ in length.
        bonl.NumericalError
            If the simulation leaves the finite numbers (an unstable model).
        """
    def to_json(self, indent: typing.SupportsInt | typing.SupportsIndex = -1) -> str:
        """
        The model in bonl's JSON model format (read by bonl.load_model and by C++'s bonl::io).
        
        Parameters
        ----------
        indent : int, default -1
            Spaces per level of nesting; -1 for one line.
        
        Returns
        -------
        str
            The model file's text.
        """
    @property
    def a(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: a_1..a_na.
        """
    @a.setter
    def a(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def b(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: b_0..b_nb.
        """
    @b.setter
    def b(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def d(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: d_1..d_nd with d_1 = 1.
        """
    @d.setter
    def d(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def f(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: f_2..f_r, the feedback polynomial's coefficients (none for r = 1).
        """
    @f.setter
    def f(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def g(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: g_1..g_nh, the change of slope outward of each knot.
        """
    @g.setter
    def g(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def input_range(self) -> tuple[float, float]:
        """
        tuple (min, max): the inputs the model was identified on (identify() records them; (-inf, inf) unless set). simulate() gives a bonl.ExtrapolationWarning for inputs outside it.
        """
    @input_range.setter
    def input_range(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def knots(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: knots_1..knots_nh, where the slope changes: strictly increasing, none at 0 (structure, not estimated).
        """
    @knots.setter
    def knots(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def na(self) -> int:
        """
        int: poles of the linear block (na >= 1).
        """
    @property
    def nb(self) -> int:
        """
        int: B has nb + 1 coefficients b_0..b_nb.
        """
    @property
    def nd(self) -> int:
        """
        int: taps of the feedback block D = d_1 q^-1 + ... + d_nd q^-nd, d_1 = 1 (1..32).
        """
    @property
    def nh(self) -> int:
        """
        int: hinges of the feedback nonlinearity, knots where its slope changes (0..32; 0: none).
        """
    @property
    def ni(self) -> int:
        """
        int: integrators: poles fixed at 1 in the linear block's denominator (0..2).
        """
    @property
    def nk(self) -> int:
        """
        int: pure delay of the input in samples.
        """
    @property
    def np(self) -> int:
        """
        int: play operators of the feedback's hysteresis (0..32; 0: none).
        """
    @property
    def num_params(self) -> int:
        """
        int: number of identified parameters.
        """
    @property
    def nv(self) -> int:
        """
        int: what the nonlinearity sees: 0 the output y, 1 its first difference (a velocity).
        """
    @property
    def operating_point(self) -> tuple[float, float]:
        """
        tuple (u0, y0): the input and output at which the model rests; its blocks map u - u0 to y - y0. (0, 0) unless set. identify() keeps the structure's.
        """
    @operating_point.setter
    def operating_point(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def orders(self) -> tuple[int, ...]:
        """
        tuple of int: the orders, as ORDERS names them.
        """
    @property
    def params(self) -> dict[str, float | numpy.typing.NDArray[numpy.float64]]:
        """
        dict: every parameter block by name, as the keyword arguments of the constructor take them.
        """
    @property
    def pole_radius(self) -> float:
        """
        float: the largest pole magnitude of the linear block: below 1 the model is stable, near 1 barely damped.
        """
    @property
    def r(self) -> int:
        """
        int: degree of the feedback polynomial (1..32; 1: no polynomial terms).
        """
    @property
    def theta(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the parameter vector in the order of eq. (19).
        """
    @theta.setter
    def theta(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def thresholds(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: r_1..r_np, the plays' thresholds: strictly increasing, > 0 (structure, not estimated).
        """
    @thresholds.setter
    def thresholds(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def w(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: w_1..w_np, the plays' weights.
        """
    @w.setter
    def w(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
class PrandtlIshlinskiiHammerstein:
    """
    Prandtl-Ishlinskii Hammerstein model: input hysteresis w = sum_{l=0..r} f_l u^l + sum_{i=1..np} g_i play_{r_i}[u] (play_r[u](k) = min(max(P(k-1), u(k) - r), u(k) + r), P = 0 at rest; thresholds r_i structure), then the linear block (b_0 = 1): x(k) = -sum a_j x(k-j) + sum b_i w(k-nk-i), y = x.
    
    Parameters
    ----------
    na : int
        poles of the linear block (na >= 1).
    nb : int
        B has nb + 1 coefficients b_0..b_nb, b_0 = 1.
    nk : int
        pure delay in samples.
    r : int
        degree of the input polynomials (r >= 1).
    np : int
        play operators of the input hysteresis (1..32).
    ni : int, optional
        integrators: poles fixed at 1 in the linear block's denominator (0..2); default 0.
    b : array_like, optional
        b_0..b_nb with b_0 = 1.
    a : array_like, optional
        a_1..a_na.
    f : array_like, optional
        f_0..f_r, the input polynomial.
    thresholds : array_like, optional
        r_1..r_np, the plays' thresholds: strictly increasing, > 0 (structure, not estimated).
    g : array_like, optional
        g_1..g_np, the plays' weights.
    """
    ORDERS: typing.ClassVar[tuple] = ('na', 'nb', 'nk', 'r', 'np', 'ni')
    ORDER_DEFAULTS: typing.ClassVar[dict] = {'ni': 0}
    PAPER_ORDERS: typing.ClassVar[tuple] = (3, 2, 8, 3, 1, 0)
    def __copy__(self) -> PrandtlIshlinskiiHammerstein:
        ...
    def __deepcopy__(self, memo: dict) -> PrandtlIshlinskiiHammerstein:
        ...
    def __getstate__(self) -> str:
        ...
    def __init__(self, na: typing.SupportsInt | typing.SupportsIndex, nb: typing.SupportsInt | typing.SupportsIndex, nk: typing.SupportsInt | typing.SupportsIndex, r: typing.SupportsInt | typing.SupportsIndex, np: typing.SupportsInt | typing.SupportsIndex, ni: typing.SupportsInt | typing.SupportsIndex = 0, *, b: numpy.typing.ArrayLike | None = None, a: numpy.typing.ArrayLike | None = None, f: numpy.typing.ArrayLike | None = None, thresholds: numpy.typing.ArrayLike | None = None, g: numpy.typing.ArrayLike | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: str) -> None:
        ...
    def extrapolated_samples(self, u: numpy.typing.ArrayLike) -> int:
        """
        How many samples of u lie outside input_range.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            An input record.
        
        Returns
        -------
        int
            The number of samples outside input_range (0: no extrapolation).
        """
    def predict(self, u: numpy.typing.ArrayLike, y: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        One-step-ahead prediction from measured data.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        y : array_like, shape (n,)
            Measured output; y[k] is used to predict y[k + 1].
        initial : (u_past, y_past), optional
            The measured samples just before u and y (None: from rest at the operating point).
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The prediction of y[k] from u up to k and y up to k - 1. Internal variables are taken from the
            measured output where the model lets them (Hammerstein: x = y; H-W: x = q^-1(y); P-H-W: the
            backlash memory is the measured y[k - 1]).
        """
    def rescaled(self, input_scale: typing.SupportsFloat | typing.SupportsIndex, output_scale: typing.SupportsFloat | typing.SupportsIndex) -> PrandtlIshlinskiiHammerstein:
        """
        The model of y = output_scale * model(u / input_scale): the same model for u and y in other units.
        
        Parameters
        ----------
        input_scale, output_scale : float
            The input's and the output's scale, finite and > 0.
        
        Returns
        -------
        model
            A model of this class, the parameters in the new units.
        """
    def simulate(self, u: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        Free-run simulation, from rest or after a measured past.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        initial : (u_past, y_past), optional
            The measured samples just before u. They set the model's state (its internal variables are what
            the measured past says, as predict() takes them); then the model runs on u alone. The
            benchmarks' state-initialisation window of m samples is
            ``model.simulate(u[m:], initial=(u[:m], y[:m]))``. None: from rest at the operating point.
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The model's output, driven by u alone after the initial state.
        
        Raises
        ------
        ValueError
            If u or the past is not a finite 1-D array, or u_past and y_past differ in length.
        bonl.NumericalError
            If the simulation leaves the finite numbers (an unstable model).
        """
    def to_json(self, indent: typing.SupportsInt | typing.SupportsIndex = -1) -> str:
        """
        The model in bonl's JSON model format (read by bonl.load_model and by C++'s bonl::io).
        
        Parameters
        ----------
        indent : int, default -1
            Spaces per level of nesting; -1 for one line.
        
        Returns
        -------
        str
            The model file's text.
        """
    @property
    def a(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: a_1..a_na.
        """
    @a.setter
    def a(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def b(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: b_0..b_nb with b_0 = 1.
        """
    @b.setter
    def b(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def f(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: f_0..f_r, the input polynomial.
        """
    @f.setter
    def f(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def g(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: g_1..g_np, the plays' weights.
        """
    @g.setter
    def g(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def input_range(self) -> tuple[float, float]:
        """
        tuple (min, max): the inputs the model was identified on (identify() records them; (-inf, inf) unless set). simulate() gives a bonl.ExtrapolationWarning for inputs outside it.
        """
    @input_range.setter
    def input_range(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def na(self) -> int:
        """
        int: poles of the linear block (na >= 1).
        """
    @property
    def nb(self) -> int:
        """
        int: B has nb + 1 coefficients b_0..b_nb, b_0 = 1.
        """
    @property
    def ni(self) -> int:
        """
        int: integrators: poles fixed at 1 in the linear block's denominator (0..2).
        """
    @property
    def nk(self) -> int:
        """
        int: pure delay in samples.
        """
    @property
    def np(self) -> int:
        """
        int: play operators of the input hysteresis (1..32).
        """
    @property
    def num_params(self) -> int:
        """
        int: number of identified parameters.
        """
    @property
    def operating_point(self) -> tuple[float, float]:
        """
        tuple (u0, y0): the input and output at which the model rests; its blocks map u - u0 to y - y0. (0, 0) unless set. identify() keeps the structure's.
        """
    @operating_point.setter
    def operating_point(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def orders(self) -> tuple[int, ...]:
        """
        tuple of int: the orders, as ORDERS names them.
        """
    @property
    def params(self) -> dict[str, float | numpy.typing.NDArray[numpy.float64]]:
        """
        dict: every parameter block by name, as the keyword arguments of the constructor take them.
        """
    @property
    def pole_radius(self) -> float:
        """
        float: the largest pole magnitude of the linear block: below 1 the model is stable, near 1 barely damped.
        """
    @property
    def r(self) -> int:
        """
        int: degree of the input polynomials (r >= 1).
        """
    @property
    def theta(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the parameter vector in the order of eq. (19).
        """
    @theta.setter
    def theta(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def thresholds(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: r_1..r_np, the plays' thresholds: strictly increasing, > 0 (structure, not estimated).
        """
    @thresholds.setter
    def thresholds(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
class BoucWenFeedback:
    """
    Bouc-Wen feedback model: y(k) = -sum a_j y(k-j) + sum b_i u(k-nk-i) - sum_{j=1..nd} d_j h(k-j), d_1 = 1, h = w - alpha y the hysteretic part of the restoring force w(k) = w(k-1) + alpha dy - gamma |dy| w(k) - delta dy |w(k)|, dy = y(k) - y(k-1) (the Bouc-Wen law of hysteresis with nu = 1, stepped backward).
    
    Parameters
    ----------
    na : int
        poles of the linear block (na >= 1).
    nb : int
        B has nb + 1 coefficients b_0..b_nb.
    nk : int
        pure delay of the input in samples.
    nd : int
        taps of the force's block D = d_1 q^-1 + ... + d_nd q^-nd, d_1 = 1 (1..32).
    ni : int, optional
        integrators: poles fixed at 1 in the linear block's denominator (0..2); default 0.
    b : array_like, optional
        b_0..b_nb.
    a : array_like, optional
        a_1..a_na.
    alpha : float, optional
        the force's stiffness where it is zero: > 0 softens with the amplitude, < 0 stiffens.
    gamma : float, optional
        the law's |dy| w coefficient (beta gamma).
    delta : float, optional
        the law's dy |w| coefficient (beta delta).
    d : array_like, optional
        d_1..d_nd with d_1 = 1.
    """
    ORDERS: typing.ClassVar[tuple] = ('na', 'nb', 'nk', 'nd', 'ni')
    ORDER_DEFAULTS: typing.ClassVar[dict] = {'ni': 0}
    PAPER_ORDERS: typing.ClassVar[tuple] = (3, 2, 8, 2, 0)
    def __copy__(self) -> BoucWenFeedback:
        ...
    def __deepcopy__(self, memo: dict) -> BoucWenFeedback:
        ...
    def __getstate__(self) -> str:
        ...
    def __init__(self, na: typing.SupportsInt | typing.SupportsIndex, nb: typing.SupportsInt | typing.SupportsIndex, nk: typing.SupportsInt | typing.SupportsIndex, nd: typing.SupportsInt | typing.SupportsIndex, ni: typing.SupportsInt | typing.SupportsIndex = 0, *, b: numpy.typing.ArrayLike | None = None, a: numpy.typing.ArrayLike | None = None, alpha: float | None = None, gamma: float | None = None, delta: float | None = None, d: numpy.typing.ArrayLike | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: str) -> None:
        ...
    def extrapolated_samples(self, u: numpy.typing.ArrayLike) -> int:
        """
        How many samples of u lie outside input_range.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            An input record.
        
        Returns
        -------
        int
            The number of samples outside input_range (0: no extrapolation).
        """
    def predict(self, u: numpy.typing.ArrayLike, y: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        One-step-ahead prediction from measured data.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        y : array_like, shape (n,)
            Measured output; y[k] is used to predict y[k + 1].
        initial : (u_past, y_past), optional
            The measured samples just before u and y (None: from rest at the operating point).
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The prediction of y[k] from u up to k and y up to k - 1. Internal variables are taken from the
            measured output where the model lets them (Hammerstein: x = y; H-W: x = q^-1(y); P-H-W: the
            backlash memory is the measured y[k - 1]).
        """
    def rescaled(self, input_scale: typing.SupportsFloat | typing.SupportsIndex, output_scale: typing.SupportsFloat | typing.SupportsIndex) -> BoucWenFeedback:
        """
        The model of y = output_scale * model(u / input_scale): the same model for u and y in other units.
        
        Parameters
        ----------
        input_scale, output_scale : float
            The input's and the output's scale, finite and > 0.
        
        Returns
        -------
        model
            A model of this class, the parameters in the new units.
        """
    def simulate(self, u: numpy.typing.ArrayLike, initial: tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike] | None = None) -> numpy.typing.NDArray[numpy.float64]:
        """
        Free-run simulation, from rest or after a measured past.
        
        Parameters
        ----------
        u : array_like, shape (n,)
            Input sequence.
        initial : (u_past, y_past), optional
            The measured samples just before u. They set the model's state (its internal variables are what
            the measured past says, as predict() takes them); then the model runs on u alone. The
            benchmarks' state-initialisation window of m samples is
            ``model.simulate(u[m:], initial=(u[:m], y[:m]))``. None: from rest at the operating point.
        
        Returns
        -------
        numpy.ndarray, shape (n,)
            The model's output, driven by u alone after the initial state.
        
        Raises
        ------
        ValueError
            If u or the past is not a finite 1-D array, or u_past and y_past differ in length.
        bonl.NumericalError
            If the simulation leaves the finite numbers (an unstable model).
        """
    def to_json(self, indent: typing.SupportsInt | typing.SupportsIndex = -1) -> str:
        """
        The model in bonl's JSON model format (read by bonl.load_model and by C++'s bonl::io).
        
        Parameters
        ----------
        indent : int, default -1
            Spaces per level of nesting; -1 for one line.
        
        Returns
        -------
        str
            The model file's text.
        """
    @property
    def a(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: a_1..a_na.
        """
    @a.setter
    def a(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def alpha(self) -> float:
        """
        float: the force's stiffness where it is zero: > 0 softens with the amplitude, < 0 stiffens.
        """
    @alpha.setter
    def alpha(self, arg1: float) -> None:
        ...
    @property
    def b(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: b_0..b_nb.
        """
    @b.setter
    def b(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def d(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: d_1..d_nd with d_1 = 1.
        """
    @d.setter
    def d(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
    @property
    def delta(self) -> float:
        """
        float: the law's dy |w| coefficient (beta delta).
        """
    @delta.setter
    def delta(self, arg1: float) -> None:
        ...
    @property
    def gamma(self) -> float:
        """
        float: the law's |dy| w coefficient (beta gamma).
        """
    @gamma.setter
    def gamma(self, arg1: float) -> None:
        ...
    @property
    def input_range(self) -> tuple[float, float]:
        """
        tuple (min, max): the inputs the model was identified on (identify() records them; (-inf, inf) unless set). simulate() gives a bonl.ExtrapolationWarning for inputs outside it.
        """
    @input_range.setter
    def input_range(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def na(self) -> int:
        """
        int: poles of the linear block (na >= 1).
        """
    @property
    def nb(self) -> int:
        """
        int: B has nb + 1 coefficients b_0..b_nb.
        """
    @property
    def nd(self) -> int:
        """
        int: taps of the force's block D = d_1 q^-1 + ... + d_nd q^-nd, d_1 = 1 (1..32).
        """
    @property
    def ni(self) -> int:
        """
        int: integrators: poles fixed at 1 in the linear block's denominator (0..2).
        """
    @property
    def nk(self) -> int:
        """
        int: pure delay of the input in samples.
        """
    @property
    def num_params(self) -> int:
        """
        int: number of identified parameters.
        """
    @property
    def operating_point(self) -> tuple[float, float]:
        """
        tuple (u0, y0): the input and output at which the model rests; its blocks map u - u0 to y - y0. (0, 0) unless set. identify() keeps the structure's.
        """
    @operating_point.setter
    def operating_point(self, arg1: tuple[float, float]) -> None:
        ...
    @property
    def orders(self) -> tuple[int, ...]:
        """
        tuple of int: the orders, as ORDERS names them.
        """
    @property
    def params(self) -> dict[str, float | numpy.typing.NDArray[numpy.float64]]:
        """
        dict: every parameter block by name, as the keyword arguments of the constructor take them.
        """
    @property
    def pole_radius(self) -> float:
        """
        float: the largest pole magnitude of the linear block: below 1 the model is stable, near 1 barely damped.
        """
    @property
    def theta(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: the parameter vector in the order of eq. (19).
        """
    @theta.setter
    def theta(self, arg1: numpy.typing.ArrayLike) -> None:
        ...
class UpdateStatus:
    """
    What one online update did.
    
    Members:
    
      updated : theta and P were updated
    
      no_information : the sample says nothing about theta (inside the backlash gap)
    
      rejected_non_finite : u or y was NaN or infinite; the estimator's state is untouched
    
      numerical_failure : the update would have broken the covariance, or the internal variables left the finite numbers; theta and P kept, diverged is set
    """
    __members__: typing.ClassVar[dict[str, UpdateStatus]]
    no_information: typing.ClassVar[UpdateStatus]
    numerical_failure: typing.ClassVar[UpdateStatus]
    rejected_non_finite: typing.ClassVar[UpdateStatus]
    updated: typing.ClassVar[UpdateStatus]
    @typing.overload
    def __eq__(self, other: UpdateStatus) -> bool:
        ...
    @typing.overload
    def __eq__(self, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
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
    def __ne__(self, other: UpdateStatus) -> bool:
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
class WindowRefinementOptions:
    """
    The output-error method's window refinement (Estimator(..., window=...)): Levenberg-Marquardt on the
    free-run error of the newest samples, spread over the updates, its estimate swapped in where it
    predicts the newest samples better. On by default (docs/explanation/algorithm.md).
    """
    def __init__(self, *, enabled: bool = True, length: typing.SupportsInt | typing.SupportsIndex = 4000, work_per_sample: typing.SupportsInt | typing.SupportsIndex = 8, equation_error_start: bool = True) -> None:
        """
        Window refinement options, the estimator's defaults unless given.
        
        Parameters
        ----------
        enabled : bool, default True
            Whether the refinement runs.
        length : int, default 4000
            The most samples it fits at once (>= 100).
        work_per_sample : int, default 8
            Model steps of the refinement per update (>= 2), for each window.
        equation_error_start : bool, default True
            A second window beside, started from an equation-error
            recursion's estimate (identify()'s second start); doubles the refinement's work.
        
        Returns
        -------
        WindowRefinementOptions
            The options; the Estimator checks them.
        """
    @property
    def enabled(self) -> bool:
        """
        bool: whether the refinement runs
        """
    @enabled.setter
    def enabled(self, arg0: bool) -> None:
        ...
    @property
    def equation_error_start(self) -> bool:
        """
        bool: a second window beside, started from an equation-error recursion's estimate
        """
    @equation_error_start.setter
    def equation_error_start(self, arg0: bool) -> None:
        ...
    @property
    def length(self) -> int:
        """
        int: the most samples it fits at once (>= 100)
        """
    @length.setter
    def length(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def work_per_sample(self) -> int:
        """
        int: model steps of the refinement per update (>= 2), for each window
        """
    @work_per_sample.setter
    def work_per_sample(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
class WindowRefinementCounts:
    """
    What the window refinement did since the Estimator's reset().
    """
    @property
    def iterations(self) -> int:
        """
        int: Levenberg-Marquardt steps kept
        """
    @property
    def overruns(self) -> int:
        """
        int: restarts because the slices fell behind or a run left the finite numbers
        """
    @property
    def refusals(self) -> int:
        """
        int: refined estimates not swapped in (the recursion predicted the newest samples as well)
        """
    @property
    def refused_steps(self) -> int:
        """
        int: trial steps that did not simulate the window better
        """
    @property
    def reseeds(self) -> int:
        """
        int: restarts with the newest samples only (a change of the plant)
        """
    @property
    def swaps(self) -> int:
        """
        int: refined estimates swapped into the recursion
        """
    @property
    def undetermined(self) -> int:
        """
        int: refined estimates not swapped in although they predicted the newest samples better: the window's data do not determine every parameter, or the covariance would not be positive definite
        """
class EstimatorHealth:
    """
    What an Estimator's numerical safeguards did since reset().
    """
    def __repr__(self) -> str:
        ...
    @property
    def checkpoint_returns(self) -> int:
        """
        int: output_error returns to the checkpoint, which predicted far better
        """
    @property
    def consecutive_failures(self) -> int:
        """
        int: refused in a row, up to the last update
        """
    @property
    def diverged(self) -> bool:
        """
        bool: a numerical failure happened (cleared by recover() and reset())
        """
    @property
    def failures(self) -> int:
        """
        int: updates refused for numerical reasons
        """
    @property
    def forgetting_limited(self) -> int:
        """
        int: updates whose forgetting the trace ceiling reduced
        """
    @property
    def internal_restarts(self) -> int:
        """
        int: internal variables restarted because they became non-finite
        """
    @property
    def projections(self) -> int:
        """
        int: output_error updates shortened to keep the linear block stable
        """
    @property
    def recoveries(self) -> int:
        """
        int: automatic covariance resets (recover_after)
        """
    @property
    def window(self) -> WindowRefinementCounts:
        """
        WindowRefinementCounts: what the window refinement did
        """
class Estimator:
    """
    Online recursive estimator for one model.
    
    Parameters
    ----------
    model : one of bonl.MODELS
        Gives the structure; the estimate starts from zero (P-H-W: c = c0 for equation_error and
        paper, c = 0 for output_error).
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
    trace_ceiling : float, optional
        trace(P) is kept at or below trace_ceiling * trace(P(0)) by reducing the forgetting where it
        would grow P beyond that (no covariance wind-up under poor excitation). >= 1; inf turns it off
        (the paper's algorithm exactly as written). Default: 10 for output_error, 1 for the others.
    recover_after : int, default 0
        After this many refused updates in a row, reset P to p0 I automatically (keeping theta);
        0: never (check ``diverged`` and call ``recover()``).
    stability_radius : float, default 0.999
        output_error: the linear block's poles are kept inside this radius (updates shortened).
    window : WindowRefinementOptions, optional
        output_error: the window refinement, Levenberg-Marquardt on the newest samples spread over the
        updates, from the output-error recursion's estimate and from an equation-error recursion's beside.
        None: the default (on); ``bonl.WindowRefinementOptions(enabled=False)``: the recursion alone.
    normalise : bool, default True
        Work in the data's own scale, so that p0, the trace ceiling and the window's damping mean the same
        whatever the units ('paper' never: it is the paper's algorithm in the data's units). Estimator:
        the RMS of u - u0 and y - y0 is measured over the first 100 samples from the first moving input,
        then the recursion runs over them and on in coordinates where the parameters are of order one.
        identify: where it refines, on u and y divided by the powers of two nearest their RMS, the model
        returned in the data's units; the recursive estimate returned as it is ('paper',
        refine_iterations=0, ARX least squares) is the online estimator's.
    c0 : float, optional
        PseudoHammersteinWiener only (another model: ValueError): the initial backlash half-width c(0) of
        equation_error and paper, in the output's units, or where the estimator normalises a fraction of
        the output's scale (output_error starts at 0). Default: 0.01.
    backlash_hold : int, optional
        PseudoHammersteinWiener only (another model: ValueError): output_error holds c at 0 for this many
        samples after each start from rest. Default: 200.
    """
    @typing.overload
    def __init__(self, model: ARX, *, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, trace_ceiling: typing.SupportsFloat | typing.SupportsIndex | None = None, recover_after: typing.SupportsInt | typing.SupportsIndex = 0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999, window: WindowRefinementOptions | None = None, normalise: bool = True, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None) -> None:
        ...
    @typing.overload
    def __init__(self, model: Hammerstein, *, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, trace_ceiling: typing.SupportsFloat | typing.SupportsIndex | None = None, recover_after: typing.SupportsInt | typing.SupportsIndex = 0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999, window: WindowRefinementOptions | None = None, normalise: bool = True, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None) -> None:
        ...
    @typing.overload
    def __init__(self, model: HammersteinWiener, *, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, trace_ceiling: typing.SupportsFloat | typing.SupportsIndex | None = None, recover_after: typing.SupportsInt | typing.SupportsIndex = 0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999, window: WindowRefinementOptions | None = None, normalise: bool = True, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None) -> None:
        ...
    @typing.overload
    def __init__(self, model: PseudoHammersteinWiener, *, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, trace_ceiling: typing.SupportsFloat | typing.SupportsIndex | None = None, recover_after: typing.SupportsInt | typing.SupportsIndex = 0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999, window: WindowRefinementOptions | None = None, normalise: bool = True, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None) -> None:
        ...
    @typing.overload
    def __init__(self, model: Wiener, *, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, trace_ceiling: typing.SupportsFloat | typing.SupportsIndex | None = None, recover_after: typing.SupportsInt | typing.SupportsIndex = 0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999, window: WindowRefinementOptions | None = None, normalise: bool = True, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None) -> None:
        ...
    @typing.overload
    def __init__(self, model: WienerHammerstein, *, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, trace_ceiling: typing.SupportsFloat | typing.SupportsIndex | None = None, recover_after: typing.SupportsInt | typing.SupportsIndex = 0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999, window: WindowRefinementOptions | None = None, normalise: bool = True, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None) -> None:
        ...
    @typing.overload
    def __init__(self, model: NonlinearFeedback, *, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, trace_ceiling: typing.SupportsFloat | typing.SupportsIndex | None = None, recover_after: typing.SupportsInt | typing.SupportsIndex = 0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999, window: WindowRefinementOptions | None = None, normalise: bool = True, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None) -> None:
        ...
    @typing.overload
    def __init__(self, model: PrandtlIshlinskiiHammerstein, *, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, trace_ceiling: typing.SupportsFloat | typing.SupportsIndex | None = None, recover_after: typing.SupportsInt | typing.SupportsIndex = 0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999, window: WindowRefinementOptions | None = None, normalise: bool = True, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None) -> None:
        ...
    @typing.overload
    def __init__(self, model: BoucWenFeedback, *, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, trace_ceiling: typing.SupportsFloat | typing.SupportsIndex | None = None, recover_after: typing.SupportsInt | typing.SupportsIndex = 0, stability_radius: typing.SupportsFloat | typing.SupportsIndex = 0.999, window: WindowRefinementOptions | None = None, normalise: bool = True, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None) -> None:
        ...
    def catch_up(self) -> None:
        """
        Take now what the recursion has yet to: a scale measurement under way ends with what it has
        measured, and every sample kept is processed (at a record's end; start_pass does it too).
        """
    def recover(self) -> None:
        """
        Leave the diverged state: P = p0 I, theta kept (a covariance reset); the counters in health stay.
        """
    def reset(self, theta0: numpy.typing.ArrayLike | None = None) -> None:
        """
        Back to the initial estimate, P = p0 I, internal variables at rest; or restart from theta0.
        
        Parameters
        ----------
        theta0 : array_like, shape (num_params,), optional
            The estimate to restart from (a warm start: the model's parameter vector, e.g. an identified
            model's theta). ValueError for theta0 of another length.
        """
    def start_pass(self) -> None:
        """
        A new pass over a record: theta and P carry on, the forgetting schedule and internals restart.
        """
    def start_recording(self, capacity: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Record theta, the internal variable and the status of the next updates.
        
        Parameters
        ----------
        capacity : int
            How many of the newest updates to keep, >= 1 (a ring buffer, allocated here once).
        """
    def stop_recording(self) -> None:
        """
        Stop recording and free the buffer.
        """
    def trajectory(self) -> EstimatorTrajectory:
        """
        What was recorded, oldest first.
        
        Returns
        -------
        EstimatorTrajectory
            ``sample``: int64 array (k,), sample number since reset(); ``theta``: array (k, n), the estimate
            after each update; ``internal``: array (k,), the internal variable x(k) the update used (NaN for
            ARX); ``status``: list of UpdateStatus.
        """
    def update(self, u: typing.SupportsFloat | typing.SupportsIndex, y: typing.SupportsFloat | typing.SupportsIndex) -> UpdateStatus:
        """
        Process one sample.
        
        Parameters
        ----------
        u, y : float
            Input and measured output.
        
        Returns
        -------
        UpdateStatus
            A non-finite u or y is rejected (rejected_non_finite) and leaves the state untouched.
            An Estimator must not be used from two threads at once.
        """
    def update_record(self, u: numpy.typing.ArrayLike, y: numpy.typing.ArrayLike, *, prediction: bool = False, theta: bool = False) -> UpdateResults:
        """
        Process a record in one call.
        
        C++'s ``estimator.update(u, y, on_sample)``, the GIL released: the same, bit for bit, as calling
        update on each sample in turn.
        
        Parameters
        ----------
        u, y : array_like, shape (n,)
            Input and measured output, of equal length.
        prediction, theta : bool, default False
            Also return last_prediction, and theta, after every sample.
        
        Returns
        -------
        UpdateResults
            ``status``, an int8 array of ``int(UpdateStatus.<name>)`` codes (a non-finite sample is
            rejected_non_finite and leaves the state untouched), and ``prediction``, ``theta`` when asked for.
        """
    @property
    def covariance(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        numpy.ndarray: current P of the recursion (symmetric).
        """
    @property
    def data_scale(self) -> tuple[float, float]:
        """
        tuple[float, float]: the scale of u - u0 and y - y0 the recursion works in (their RMS over the samples measured; (1.0, 1.0) where not normalised or still measuring).
        """
    @property
    def diverged(self) -> bool:
        """
        bool: an update was refused for numerical reasons.
        """
    @property
    def health(self) -> EstimatorHealth:
        """
        EstimatorHealth: what the numerical safeguards did since reset().
        """
    @property
    def last_prediction(self) -> float:
        """
        float: the prediction of the last sample's y, made before the update (y - last_prediction is the innovation); for output_error the simulated output.
        """
    @property
    def measuring_scale(self) -> bool:
        """
        bool: the data's scale is still being measured (normalise=True): updates return no_information and the estimate stays where it started.
        """
    @property
    def memory(self) -> float:
        """
        float: the adaptive memory's current length 1 / (1 - lambda) in samples (NaN for a step schedule).
        """
    @property
    def model(self) -> ARX | Hammerstein | HammersteinWiener | PseudoHammersteinWiener | Wiener | WienerHammerstein | NonlinearFeedback | PrandtlIshlinskiiHammerstein | BoucWenFeedback:
        """
        The current estimate as a model.
        """
    @property
    def pending_samples(self) -> int:
        """
        int: samples kept while the scale was measured that the recursion has yet to take (two per update); theta lags the data by them.
        """
    @property
    def recording(self) -> bool:
        """
        bool: updates are being recorded.
        """
    @property
    def samples(self) -> int:
        """
        int: samples since the last pass started.
        """
    @property
    def theta(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: current estimate (eq. 19 order); with the window refinement, the window's while it predicts the newest samples about as well as the recursion's.
        """
class UpdateResults:
    """
    What Estimator.update_record returns for a record.
    """
    @property
    def prediction(self) -> numpy.typing.NDArray[numpy.float64] | None:
        """
        numpy.ndarray or None: last_prediction after each sample (when asked for)
        """
    @property
    def status(self) -> numpy.typing.NDArray[numpy.int8]:
        """
        numpy.ndarray of int8: each sample's UpdateStatus, as int(UpdateStatus.<name>)
        """
    @property
    def theta(self) -> numpy.typing.NDArray[numpy.float64] | None:
        """
        numpy.ndarray (samples, n) or None: theta after each sample (when asked for)
        """
class EstimatorTrajectory:
    """
    What Estimator.trajectory returns: the recorded updates, oldest first.
    """
    def __len__(self) -> int:
        ...
    def __repr__(self) -> str:
        ...
    @property
    def internal(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray, shape (k,): the internal variable x(k) each update used (NaN for ARX)
        """
    @property
    def sample(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        numpy.ndarray of int64, shape (k,): each update's sample number since reset()
        """
    @property
    def status(self) -> list[UpdateStatus]:
        """
        list of UpdateStatus: each update's status
        """
    @property
    def theta(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray, shape (k, n): the estimate after each update
        """
class _SelectionData:
    """
    The records and options of a selection, checked once (bonl::SelectionData); made by _selection_data.
    """
    def __getstate__(self) -> tuple[list, str, float, int, int, str, int, str, typing.Any, float | None, int, bool, typing.Any, int]:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
@typing.overload
def _refit(structure: ARX, data: _SelectionData) -> tuple[typing.Any, typing.Any]:
    """
    bonl::refit: the structure identified on all of data's records where its free run there is bounded. Returns (model or None, why not or None).
    """
@typing.overload
def _refit(structure: Hammerstein, data: _SelectionData) -> tuple[typing.Any, typing.Any]:
    """
    bonl::refit: the structure identified on all of data's records where its free run there is bounded. Returns (model or None, why not or None).
    """
@typing.overload
def _refit(structure: HammersteinWiener, data: _SelectionData) -> tuple[typing.Any, typing.Any]:
    """
    bonl::refit: the structure identified on all of data's records where its free run there is bounded. Returns (model or None, why not or None).
    """
@typing.overload
def _refit(structure: PseudoHammersteinWiener, data: _SelectionData) -> tuple[typing.Any, typing.Any]:
    """
    bonl::refit: the structure identified on all of data's records where its free run there is bounded. Returns (model or None, why not or None).
    """
@typing.overload
def _refit(structure: Wiener, data: _SelectionData) -> tuple[typing.Any, typing.Any]:
    """
    bonl::refit: the structure identified on all of data's records where its free run there is bounded. Returns (model or None, why not or None).
    """
@typing.overload
def _refit(structure: WienerHammerstein, data: _SelectionData) -> tuple[typing.Any, typing.Any]:
    """
    bonl::refit: the structure identified on all of data's records where its free run there is bounded. Returns (model or None, why not or None).
    """
@typing.overload
def _refit(structure: NonlinearFeedback, data: _SelectionData) -> tuple[typing.Any, typing.Any]:
    """
    bonl::refit: the structure identified on all of data's records where its free run there is bounded. Returns (model or None, why not or None).
    """
@typing.overload
def _refit(structure: PrandtlIshlinskiiHammerstein, data: _SelectionData) -> tuple[typing.Any, typing.Any]:
    """
    bonl::refit: the structure identified on all of data's records where its free run there is bounded. Returns (model or None, why not or None).
    """
@typing.overload
def _refit(structure: BoucWenFeedback, data: _SelectionData) -> tuple[typing.Any, typing.Any]:
    """
    bonl::refit: the structure identified on all of data's records where its free run there is bounded. Returns (model or None, why not or None).
    """
@typing.overload
def _score_candidate(structure: ARX, data: _SelectionData) -> tuple:
    """
    bonl::score_candidate: the structure identified on data's fit parts and scored by its criterion. Returns (score, fit_mse, validation_mse or None, error or None, model or None, fold_mse or None).
    """
@typing.overload
def _score_candidate(structure: Hammerstein, data: _SelectionData) -> tuple:
    """
    bonl::score_candidate: the structure identified on data's fit parts and scored by its criterion. Returns (score, fit_mse, validation_mse or None, error or None, model or None, fold_mse or None).
    """
@typing.overload
def _score_candidate(structure: HammersteinWiener, data: _SelectionData) -> tuple:
    """
    bonl::score_candidate: the structure identified on data's fit parts and scored by its criterion. Returns (score, fit_mse, validation_mse or None, error or None, model or None, fold_mse or None).
    """
@typing.overload
def _score_candidate(structure: PseudoHammersteinWiener, data: _SelectionData) -> tuple:
    """
    bonl::score_candidate: the structure identified on data's fit parts and scored by its criterion. Returns (score, fit_mse, validation_mse or None, error or None, model or None, fold_mse or None).
    """
@typing.overload
def _score_candidate(structure: Wiener, data: _SelectionData) -> tuple:
    """
    bonl::score_candidate: the structure identified on data's fit parts and scored by its criterion. Returns (score, fit_mse, validation_mse or None, error or None, model or None, fold_mse or None).
    """
@typing.overload
def _score_candidate(structure: WienerHammerstein, data: _SelectionData) -> tuple:
    """
    bonl::score_candidate: the structure identified on data's fit parts and scored by its criterion. Returns (score, fit_mse, validation_mse or None, error or None, model or None, fold_mse or None).
    """
@typing.overload
def _score_candidate(structure: NonlinearFeedback, data: _SelectionData) -> tuple:
    """
    bonl::score_candidate: the structure identified on data's fit parts and scored by its criterion. Returns (score, fit_mse, validation_mse or None, error or None, model or None, fold_mse or None).
    """
@typing.overload
def _score_candidate(structure: PrandtlIshlinskiiHammerstein, data: _SelectionData) -> tuple:
    """
    bonl::score_candidate: the structure identified on data's fit parts and scored by its criterion. Returns (score, fit_mse, validation_mse or None, error or None, model or None, fold_mse or None).
    """
@typing.overload
def _score_candidate(structure: BoucWenFeedback, data: _SelectionData) -> tuple:
    """
    bonl::score_candidate: the structure identified on data's fit parts and scored by its criterion. Returns (score, fit_mse, validation_mse or None, error or None, model or None, fold_mse or None).
    """
@typing.overload
def _select(candidates: collections.abc.Sequence[ARX], data: _SelectionData) -> tuple[list, ARX]:
    """
    C++'s bonl::select over candidates of one model class, on its own threads. Returns (table, best): the rows best first as (structure, _score_candidate's tuple), and the best refitted on all the records.
    """
@typing.overload
def _select(candidates: collections.abc.Sequence[Hammerstein], data: _SelectionData) -> tuple[list, Hammerstein]:
    """
    C++'s bonl::select over candidates of one model class, on its own threads. Returns (table, best): the rows best first as (structure, _score_candidate's tuple), and the best refitted on all the records.
    """
@typing.overload
def _select(candidates: collections.abc.Sequence[HammersteinWiener], data: _SelectionData) -> tuple[list, HammersteinWiener]:
    """
    C++'s bonl::select over candidates of one model class, on its own threads. Returns (table, best): the rows best first as (structure, _score_candidate's tuple), and the best refitted on all the records.
    """
@typing.overload
def _select(candidates: collections.abc.Sequence[PseudoHammersteinWiener], data: _SelectionData) -> tuple[list, PseudoHammersteinWiener]:
    """
    C++'s bonl::select over candidates of one model class, on its own threads. Returns (table, best): the rows best first as (structure, _score_candidate's tuple), and the best refitted on all the records.
    """
@typing.overload
def _select(candidates: collections.abc.Sequence[Wiener], data: _SelectionData) -> tuple[list, Wiener]:
    """
    C++'s bonl::select over candidates of one model class, on its own threads. Returns (table, best): the rows best first as (structure, _score_candidate's tuple), and the best refitted on all the records.
    """
@typing.overload
def _select(candidates: collections.abc.Sequence[WienerHammerstein], data: _SelectionData) -> tuple[list, WienerHammerstein]:
    """
    C++'s bonl::select over candidates of one model class, on its own threads. Returns (table, best): the rows best first as (structure, _score_candidate's tuple), and the best refitted on all the records.
    """
@typing.overload
def _select(candidates: collections.abc.Sequence[NonlinearFeedback], data: _SelectionData) -> tuple[list, NonlinearFeedback]:
    """
    C++'s bonl::select over candidates of one model class, on its own threads. Returns (table, best): the rows best first as (structure, _score_candidate's tuple), and the best refitted on all the records.
    """
@typing.overload
def _select(candidates: collections.abc.Sequence[PrandtlIshlinskiiHammerstein], data: _SelectionData) -> tuple[list, PrandtlIshlinskiiHammerstein]:
    """
    C++'s bonl::select over candidates of one model class, on its own threads. Returns (table, best): the rows best first as (structure, _score_candidate's tuple), and the best refitted on all the records.
    """
@typing.overload
def _select(candidates: collections.abc.Sequence[BoucWenFeedback], data: _SelectionData) -> tuple[list, BoucWenFeedback]:
    """
    C++'s bonl::select over candidates of one model class, on its own threads. Returns (table, best): the rows best first as (structure, _score_candidate's tuple), and the best refitted on all the records.
    """
def _selection_data(u: numpy.typing.ArrayLike | None = None, y: numpy.typing.ArrayLike | None = None, *, records: collections.abc.Sequence[tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike]] | None = None, criterion: str = 'validation', validation_fraction: typing.SupportsFloat | typing.SupportsIndex = 0.25, window: typing.Any = 0, folds: typing.Any = 5, fold_initial_state: str = 'measured', passes: typing.SupportsInt | typing.SupportsIndex = 1, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, refine_iterations: typing.SupportsInt | typing.SupportsIndex = 100, normalise: bool = True, operating_point: str | None = None, initialisation_window: typing.SupportsInt | typing.SupportsIndex = 0) -> _SelectionData:
    """
    bonl.select's records and options checked once (bonl::SelectionData): ValueError naming the bad one. The keyword arguments after fold_initial_state are identify's.
    """
@typing.overload
def identify(model: ARX, u: numpy.typing.ArrayLike | None = None, y: numpy.typing.ArrayLike | None = None, *, records: collections.abc.Sequence[tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike]] | None = None, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None, passes: typing.SupportsInt | typing.SupportsIndex = 1, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, refine_iterations: typing.SupportsInt | typing.SupportsIndex = 100, normalise: bool = True, operating_point: str | None = None, initialisation_window: typing.SupportsInt | typing.SupportsIndex = 0) -> ARX:
    """
    Identify a model's parameters from an input/output record, or from several.
    
    Parameters
    ----------
    model : one of bonl.MODELS
        Gives the structure (orders); its parameter values are not used.
    u, y : array_like, shape (n,)
        Input and measured output of one record.
    records : sequence of (u, y) pairs, optional
        Several records (experiments of the same system), by keyword, in place of u and y:
        ``identify(model, records=[(u1, y1), (u2, y2)])``. Each record is simulated from rest; no history
        is carried across records.
    passes : int, default 1
        Passes of the recursive estimator over the record(s) (the paper's step 5).
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
    refine_iterations : int, default 100
        Levenberg-Marquardt iterations of the refinement that follows the recursive stage for
        'output_error' and 'equation_error' (0: none, the recursive estimate alone). It minimises the
        free-run simulation error with the analytic Jacobian of the simulation and keeps the linear block
        stable.
    normalise : bool, default True
        Work in the data's own scale, so that p0, the trace ceiling and the window's damping mean the same
        whatever the units ('paper' never: it is the paper's algorithm in the data's units). Estimator:
        the RMS of u - u0 and y - y0 is measured over the first 100 samples from the first moving input,
        then the recursion runs over them and on in coordinates where the parameters are of order one.
        identify: where it refines, on u and y divided by the powers of two nearest their RMS, the model
        returned in the data's units; the recursive estimate returned as it is ('paper',
        refine_iterations=0, ARX least squares) is the online estimator's.
    operating_point : {None, 'mean', 'initial'}, default None
        The identified model's operating point (u0, y0): None keeps the structure's
        (Model.operating_point); 'mean' takes the mean input and output over all records; 'initial' the
        first sample of the first record (the record starts at rest there).
    initialisation_window : int, default 0
        Where identify refines: each record's free run starts after its first initialisation_window
        samples, measured, which set the model's state (``Model.simulate(u, initial=...)``), and is
        scored after them, instead of from rest: the model is fitted the way a test protocol with that
        state-initialisation window uses it (records that do not start at rest; an integrating plant,
        whose position keeps any transient of the start). Shorter than every record.
    c0 : float, optional
        PseudoHammersteinWiener only (another model: ValueError): the initial backlash half-width c(0) of
        equation_error and paper, in the output's units, or where the estimator normalises a fraction of
        the output's scale (output_error starts at 0). Default: 0.01.
    backlash_hold : int, optional
        PseudoHammersteinWiener only (another model: ValueError): output_error holds c at 0 for this many
        samples after each start from rest. Default: 200.
    
    Returns
    -------
    model
        A new model of the same type with the identified parameters, that operating point and the
        records' input range (Model.input_range).
    
    Warns
    -----
    bonl.StabilityWarning
        The identified model's largest pole has magnitude >= 0.999 (unstable or barely damped); possible
        where identify returns the recursive estimate as it is ('paper', refine_iterations=0, ARX least squares).
    bonl.ExcitationWarning
        The records' input takes fewer distinct values than the structure needs (two for every model; for an
        input polynomial of degree r, r + 1, on each side of zero where it has two segments): a constant input
        cannot excite the structure, and the identified parameters are not fixed by the data.
    
    Raises
    ------
    ValueError
        Bad orders, settings, lengths or non-finite samples.
    bonl.NumericalError
        The estimator broke down numerically.
    """
@typing.overload
def identify(model: Hammerstein, u: numpy.typing.ArrayLike | None = None, y: numpy.typing.ArrayLike | None = None, *, records: collections.abc.Sequence[tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike]] | None = None, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None, passes: typing.SupportsInt | typing.SupportsIndex = 1, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, refine_iterations: typing.SupportsInt | typing.SupportsIndex = 100, normalise: bool = True, operating_point: str | None = None, initialisation_window: typing.SupportsInt | typing.SupportsIndex = 0) -> Hammerstein:
    """
    Identify a model's parameters from an input/output record, or from several.
    
    Parameters
    ----------
    model : one of bonl.MODELS
        Gives the structure (orders); its parameter values are not used.
    u, y : array_like, shape (n,)
        Input and measured output of one record.
    records : sequence of (u, y) pairs, optional
        Several records (experiments of the same system), by keyword, in place of u and y:
        ``identify(model, records=[(u1, y1), (u2, y2)])``. Each record is simulated from rest; no history
        is carried across records.
    passes : int, default 1
        Passes of the recursive estimator over the record(s) (the paper's step 5).
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
    refine_iterations : int, default 100
        Levenberg-Marquardt iterations of the refinement that follows the recursive stage for
        'output_error' and 'equation_error' (0: none, the recursive estimate alone). It minimises the
        free-run simulation error with the analytic Jacobian of the simulation and keeps the linear block
        stable.
    normalise : bool, default True
        Work in the data's own scale, so that p0, the trace ceiling and the window's damping mean the same
        whatever the units ('paper' never: it is the paper's algorithm in the data's units). Estimator:
        the RMS of u - u0 and y - y0 is measured over the first 100 samples from the first moving input,
        then the recursion runs over them and on in coordinates where the parameters are of order one.
        identify: where it refines, on u and y divided by the powers of two nearest their RMS, the model
        returned in the data's units; the recursive estimate returned as it is ('paper',
        refine_iterations=0, ARX least squares) is the online estimator's.
    operating_point : {None, 'mean', 'initial'}, default None
        The identified model's operating point (u0, y0): None keeps the structure's
        (Model.operating_point); 'mean' takes the mean input and output over all records; 'initial' the
        first sample of the first record (the record starts at rest there).
    initialisation_window : int, default 0
        Where identify refines: each record's free run starts after its first initialisation_window
        samples, measured, which set the model's state (``Model.simulate(u, initial=...)``), and is
        scored after them, instead of from rest: the model is fitted the way a test protocol with that
        state-initialisation window uses it (records that do not start at rest; an integrating plant,
        whose position keeps any transient of the start). Shorter than every record.
    c0 : float, optional
        PseudoHammersteinWiener only (another model: ValueError): the initial backlash half-width c(0) of
        equation_error and paper, in the output's units, or where the estimator normalises a fraction of
        the output's scale (output_error starts at 0). Default: 0.01.
    backlash_hold : int, optional
        PseudoHammersteinWiener only (another model: ValueError): output_error holds c at 0 for this many
        samples after each start from rest. Default: 200.
    
    Returns
    -------
    model
        A new model of the same type with the identified parameters, that operating point and the
        records' input range (Model.input_range).
    
    Warns
    -----
    bonl.StabilityWarning
        The identified model's largest pole has magnitude >= 0.999 (unstable or barely damped); possible
        where identify returns the recursive estimate as it is ('paper', refine_iterations=0, ARX least squares).
    bonl.ExcitationWarning
        The records' input takes fewer distinct values than the structure needs (two for every model; for an
        input polynomial of degree r, r + 1, on each side of zero where it has two segments): a constant input
        cannot excite the structure, and the identified parameters are not fixed by the data.
    
    Raises
    ------
    ValueError
        Bad orders, settings, lengths or non-finite samples.
    bonl.NumericalError
        The estimator broke down numerically.
    """
@typing.overload
def identify(model: HammersteinWiener, u: numpy.typing.ArrayLike | None = None, y: numpy.typing.ArrayLike | None = None, *, records: collections.abc.Sequence[tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike]] | None = None, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None, passes: typing.SupportsInt | typing.SupportsIndex = 1, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, refine_iterations: typing.SupportsInt | typing.SupportsIndex = 100, normalise: bool = True, operating_point: str | None = None, initialisation_window: typing.SupportsInt | typing.SupportsIndex = 0) -> HammersteinWiener:
    """
    Identify a model's parameters from an input/output record, or from several.
    
    Parameters
    ----------
    model : one of bonl.MODELS
        Gives the structure (orders); its parameter values are not used.
    u, y : array_like, shape (n,)
        Input and measured output of one record.
    records : sequence of (u, y) pairs, optional
        Several records (experiments of the same system), by keyword, in place of u and y:
        ``identify(model, records=[(u1, y1), (u2, y2)])``. Each record is simulated from rest; no history
        is carried across records.
    passes : int, default 1
        Passes of the recursive estimator over the record(s) (the paper's step 5).
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
    refine_iterations : int, default 100
        Levenberg-Marquardt iterations of the refinement that follows the recursive stage for
        'output_error' and 'equation_error' (0: none, the recursive estimate alone). It minimises the
        free-run simulation error with the analytic Jacobian of the simulation and keeps the linear block
        stable.
    normalise : bool, default True
        Work in the data's own scale, so that p0, the trace ceiling and the window's damping mean the same
        whatever the units ('paper' never: it is the paper's algorithm in the data's units). Estimator:
        the RMS of u - u0 and y - y0 is measured over the first 100 samples from the first moving input,
        then the recursion runs over them and on in coordinates where the parameters are of order one.
        identify: where it refines, on u and y divided by the powers of two nearest their RMS, the model
        returned in the data's units; the recursive estimate returned as it is ('paper',
        refine_iterations=0, ARX least squares) is the online estimator's.
    operating_point : {None, 'mean', 'initial'}, default None
        The identified model's operating point (u0, y0): None keeps the structure's
        (Model.operating_point); 'mean' takes the mean input and output over all records; 'initial' the
        first sample of the first record (the record starts at rest there).
    initialisation_window : int, default 0
        Where identify refines: each record's free run starts after its first initialisation_window
        samples, measured, which set the model's state (``Model.simulate(u, initial=...)``), and is
        scored after them, instead of from rest: the model is fitted the way a test protocol with that
        state-initialisation window uses it (records that do not start at rest; an integrating plant,
        whose position keeps any transient of the start). Shorter than every record.
    c0 : float, optional
        PseudoHammersteinWiener only (another model: ValueError): the initial backlash half-width c(0) of
        equation_error and paper, in the output's units, or where the estimator normalises a fraction of
        the output's scale (output_error starts at 0). Default: 0.01.
    backlash_hold : int, optional
        PseudoHammersteinWiener only (another model: ValueError): output_error holds c at 0 for this many
        samples after each start from rest. Default: 200.
    
    Returns
    -------
    model
        A new model of the same type with the identified parameters, that operating point and the
        records' input range (Model.input_range).
    
    Warns
    -----
    bonl.StabilityWarning
        The identified model's largest pole has magnitude >= 0.999 (unstable or barely damped); possible
        where identify returns the recursive estimate as it is ('paper', refine_iterations=0, ARX least squares).
    bonl.ExcitationWarning
        The records' input takes fewer distinct values than the structure needs (two for every model; for an
        input polynomial of degree r, r + 1, on each side of zero where it has two segments): a constant input
        cannot excite the structure, and the identified parameters are not fixed by the data.
    
    Raises
    ------
    ValueError
        Bad orders, settings, lengths or non-finite samples.
    bonl.NumericalError
        The estimator broke down numerically.
    """
@typing.overload
def identify(model: PseudoHammersteinWiener, u: numpy.typing.ArrayLike | None = None, y: numpy.typing.ArrayLike | None = None, *, records: collections.abc.Sequence[tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike]] | None = None, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None, passes: typing.SupportsInt | typing.SupportsIndex = 1, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, refine_iterations: typing.SupportsInt | typing.SupportsIndex = 100, normalise: bool = True, operating_point: str | None = None, initialisation_window: typing.SupportsInt | typing.SupportsIndex = 0) -> PseudoHammersteinWiener:
    """
    Identify a model's parameters from an input/output record, or from several.
    
    Parameters
    ----------
    model : one of bonl.MODELS
        Gives the structure (orders); its parameter values are not used.
    u, y : array_like, shape (n,)
        Input and measured output of one record.
    records : sequence of (u, y) pairs, optional
        Several records (experiments of the same system), by keyword, in place of u and y:
        ``identify(model, records=[(u1, y1), (u2, y2)])``. Each record is simulated from rest; no history
        is carried across records.
    passes : int, default 1
        Passes of the recursive estimator over the record(s) (the paper's step 5).
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
    refine_iterations : int, default 100
        Levenberg-Marquardt iterations of the refinement that follows the recursive stage for
        'output_error' and 'equation_error' (0: none, the recursive estimate alone). It minimises the
        free-run simulation error with the analytic Jacobian of the simulation and keeps the linear block
        stable.
    normalise : bool, default True
        Work in the data's own scale, so that p0, the trace ceiling and the window's damping mean the same
        whatever the units ('paper' never: it is the paper's algorithm in the data's units). Estimator:
        the RMS of u - u0 and y - y0 is measured over the first 100 samples from the first moving input,
        then the recursion runs over them and on in coordinates where the parameters are of order one.
        identify: where it refines, on u and y divided by the powers of two nearest their RMS, the model
        returned in the data's units; the recursive estimate returned as it is ('paper',
        refine_iterations=0, ARX least squares) is the online estimator's.
    operating_point : {None, 'mean', 'initial'}, default None
        The identified model's operating point (u0, y0): None keeps the structure's
        (Model.operating_point); 'mean' takes the mean input and output over all records; 'initial' the
        first sample of the first record (the record starts at rest there).
    initialisation_window : int, default 0
        Where identify refines: each record's free run starts after its first initialisation_window
        samples, measured, which set the model's state (``Model.simulate(u, initial=...)``), and is
        scored after them, instead of from rest: the model is fitted the way a test protocol with that
        state-initialisation window uses it (records that do not start at rest; an integrating plant,
        whose position keeps any transient of the start). Shorter than every record.
    c0 : float, optional
        PseudoHammersteinWiener only (another model: ValueError): the initial backlash half-width c(0) of
        equation_error and paper, in the output's units, or where the estimator normalises a fraction of
        the output's scale (output_error starts at 0). Default: 0.01.
    backlash_hold : int, optional
        PseudoHammersteinWiener only (another model: ValueError): output_error holds c at 0 for this many
        samples after each start from rest. Default: 200.
    
    Returns
    -------
    model
        A new model of the same type with the identified parameters, that operating point and the
        records' input range (Model.input_range).
    
    Warns
    -----
    bonl.StabilityWarning
        The identified model's largest pole has magnitude >= 0.999 (unstable or barely damped); possible
        where identify returns the recursive estimate as it is ('paper', refine_iterations=0, ARX least squares).
    bonl.ExcitationWarning
        The records' input takes fewer distinct values than the structure needs (two for every model; for an
        input polynomial of degree r, r + 1, on each side of zero where it has two segments): a constant input
        cannot excite the structure, and the identified parameters are not fixed by the data.
    
    Raises
    ------
    ValueError
        Bad orders, settings, lengths or non-finite samples.
    bonl.NumericalError
        The estimator broke down numerically.
    """
@typing.overload
def identify(model: Wiener, u: numpy.typing.ArrayLike | None = None, y: numpy.typing.ArrayLike | None = None, *, records: collections.abc.Sequence[tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike]] | None = None, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None, passes: typing.SupportsInt | typing.SupportsIndex = 1, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, refine_iterations: typing.SupportsInt | typing.SupportsIndex = 100, normalise: bool = True, operating_point: str | None = None, initialisation_window: typing.SupportsInt | typing.SupportsIndex = 0) -> Wiener:
    """
    Identify a model's parameters from an input/output record, or from several.
    
    Parameters
    ----------
    model : one of bonl.MODELS
        Gives the structure (orders); its parameter values are not used.
    u, y : array_like, shape (n,)
        Input and measured output of one record.
    records : sequence of (u, y) pairs, optional
        Several records (experiments of the same system), by keyword, in place of u and y:
        ``identify(model, records=[(u1, y1), (u2, y2)])``. Each record is simulated from rest; no history
        is carried across records.
    passes : int, default 1
        Passes of the recursive estimator over the record(s) (the paper's step 5).
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
    refine_iterations : int, default 100
        Levenberg-Marquardt iterations of the refinement that follows the recursive stage for
        'output_error' and 'equation_error' (0: none, the recursive estimate alone). It minimises the
        free-run simulation error with the analytic Jacobian of the simulation and keeps the linear block
        stable.
    normalise : bool, default True
        Work in the data's own scale, so that p0, the trace ceiling and the window's damping mean the same
        whatever the units ('paper' never: it is the paper's algorithm in the data's units). Estimator:
        the RMS of u - u0 and y - y0 is measured over the first 100 samples from the first moving input,
        then the recursion runs over them and on in coordinates where the parameters are of order one.
        identify: where it refines, on u and y divided by the powers of two nearest their RMS, the model
        returned in the data's units; the recursive estimate returned as it is ('paper',
        refine_iterations=0, ARX least squares) is the online estimator's.
    operating_point : {None, 'mean', 'initial'}, default None
        The identified model's operating point (u0, y0): None keeps the structure's
        (Model.operating_point); 'mean' takes the mean input and output over all records; 'initial' the
        first sample of the first record (the record starts at rest there).
    initialisation_window : int, default 0
        Where identify refines: each record's free run starts after its first initialisation_window
        samples, measured, which set the model's state (``Model.simulate(u, initial=...)``), and is
        scored after them, instead of from rest: the model is fitted the way a test protocol with that
        state-initialisation window uses it (records that do not start at rest; an integrating plant,
        whose position keeps any transient of the start). Shorter than every record.
    c0 : float, optional
        PseudoHammersteinWiener only (another model: ValueError): the initial backlash half-width c(0) of
        equation_error and paper, in the output's units, or where the estimator normalises a fraction of
        the output's scale (output_error starts at 0). Default: 0.01.
    backlash_hold : int, optional
        PseudoHammersteinWiener only (another model: ValueError): output_error holds c at 0 for this many
        samples after each start from rest. Default: 200.
    
    Returns
    -------
    model
        A new model of the same type with the identified parameters, that operating point and the
        records' input range (Model.input_range).
    
    Warns
    -----
    bonl.StabilityWarning
        The identified model's largest pole has magnitude >= 0.999 (unstable or barely damped); possible
        where identify returns the recursive estimate as it is ('paper', refine_iterations=0, ARX least squares).
    bonl.ExcitationWarning
        The records' input takes fewer distinct values than the structure needs (two for every model; for an
        input polynomial of degree r, r + 1, on each side of zero where it has two segments): a constant input
        cannot excite the structure, and the identified parameters are not fixed by the data.
    
    Raises
    ------
    ValueError
        Bad orders, settings, lengths or non-finite samples.
    bonl.NumericalError
        The estimator broke down numerically.
    """
@typing.overload
def identify(model: WienerHammerstein, u: numpy.typing.ArrayLike | None = None, y: numpy.typing.ArrayLike | None = None, *, records: collections.abc.Sequence[tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike]] | None = None, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None, passes: typing.SupportsInt | typing.SupportsIndex = 1, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, refine_iterations: typing.SupportsInt | typing.SupportsIndex = 100, normalise: bool = True, operating_point: str | None = None, initialisation_window: typing.SupportsInt | typing.SupportsIndex = 0) -> WienerHammerstein:
    """
    Identify a model's parameters from an input/output record, or from several.
    
    Parameters
    ----------
    model : one of bonl.MODELS
        Gives the structure (orders); its parameter values are not used.
    u, y : array_like, shape (n,)
        Input and measured output of one record.
    records : sequence of (u, y) pairs, optional
        Several records (experiments of the same system), by keyword, in place of u and y:
        ``identify(model, records=[(u1, y1), (u2, y2)])``. Each record is simulated from rest; no history
        is carried across records.
    passes : int, default 1
        Passes of the recursive estimator over the record(s) (the paper's step 5).
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
    refine_iterations : int, default 100
        Levenberg-Marquardt iterations of the refinement that follows the recursive stage for
        'output_error' and 'equation_error' (0: none, the recursive estimate alone). It minimises the
        free-run simulation error with the analytic Jacobian of the simulation and keeps the linear block
        stable.
    normalise : bool, default True
        Work in the data's own scale, so that p0, the trace ceiling and the window's damping mean the same
        whatever the units ('paper' never: it is the paper's algorithm in the data's units). Estimator:
        the RMS of u - u0 and y - y0 is measured over the first 100 samples from the first moving input,
        then the recursion runs over them and on in coordinates where the parameters are of order one.
        identify: where it refines, on u and y divided by the powers of two nearest their RMS, the model
        returned in the data's units; the recursive estimate returned as it is ('paper',
        refine_iterations=0, ARX least squares) is the online estimator's.
    operating_point : {None, 'mean', 'initial'}, default None
        The identified model's operating point (u0, y0): None keeps the structure's
        (Model.operating_point); 'mean' takes the mean input and output over all records; 'initial' the
        first sample of the first record (the record starts at rest there).
    initialisation_window : int, default 0
        Where identify refines: each record's free run starts after its first initialisation_window
        samples, measured, which set the model's state (``Model.simulate(u, initial=...)``), and is
        scored after them, instead of from rest: the model is fitted the way a test protocol with that
        state-initialisation window uses it (records that do not start at rest; an integrating plant,
        whose position keeps any transient of the start). Shorter than every record.
    c0 : float, optional
        PseudoHammersteinWiener only (another model: ValueError): the initial backlash half-width c(0) of
        equation_error and paper, in the output's units, or where the estimator normalises a fraction of
        the output's scale (output_error starts at 0). Default: 0.01.
    backlash_hold : int, optional
        PseudoHammersteinWiener only (another model: ValueError): output_error holds c at 0 for this many
        samples after each start from rest. Default: 200.
    
    Returns
    -------
    model
        A new model of the same type with the identified parameters, that operating point and the
        records' input range (Model.input_range).
    
    Warns
    -----
    bonl.StabilityWarning
        The identified model's largest pole has magnitude >= 0.999 (unstable or barely damped); possible
        where identify returns the recursive estimate as it is ('paper', refine_iterations=0, ARX least squares).
    bonl.ExcitationWarning
        The records' input takes fewer distinct values than the structure needs (two for every model; for an
        input polynomial of degree r, r + 1, on each side of zero where it has two segments): a constant input
        cannot excite the structure, and the identified parameters are not fixed by the data.
    
    Raises
    ------
    ValueError
        Bad orders, settings, lengths or non-finite samples.
    bonl.NumericalError
        The estimator broke down numerically.
    """
@typing.overload
def identify(model: NonlinearFeedback, u: numpy.typing.ArrayLike | None = None, y: numpy.typing.ArrayLike | None = None, *, records: collections.abc.Sequence[tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike]] | None = None, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None, passes: typing.SupportsInt | typing.SupportsIndex = 1, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, refine_iterations: typing.SupportsInt | typing.SupportsIndex = 100, normalise: bool = True, operating_point: str | None = None, initialisation_window: typing.SupportsInt | typing.SupportsIndex = 0) -> NonlinearFeedback:
    """
    Identify a model's parameters from an input/output record, or from several.
    
    Parameters
    ----------
    model : one of bonl.MODELS
        Gives the structure (orders); its parameter values are not used.
    u, y : array_like, shape (n,)
        Input and measured output of one record.
    records : sequence of (u, y) pairs, optional
        Several records (experiments of the same system), by keyword, in place of u and y:
        ``identify(model, records=[(u1, y1), (u2, y2)])``. Each record is simulated from rest; no history
        is carried across records.
    passes : int, default 1
        Passes of the recursive estimator over the record(s) (the paper's step 5).
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
    refine_iterations : int, default 100
        Levenberg-Marquardt iterations of the refinement that follows the recursive stage for
        'output_error' and 'equation_error' (0: none, the recursive estimate alone). It minimises the
        free-run simulation error with the analytic Jacobian of the simulation and keeps the linear block
        stable.
    normalise : bool, default True
        Work in the data's own scale, so that p0, the trace ceiling and the window's damping mean the same
        whatever the units ('paper' never: it is the paper's algorithm in the data's units). Estimator:
        the RMS of u - u0 and y - y0 is measured over the first 100 samples from the first moving input,
        then the recursion runs over them and on in coordinates where the parameters are of order one.
        identify: where it refines, on u and y divided by the powers of two nearest their RMS, the model
        returned in the data's units; the recursive estimate returned as it is ('paper',
        refine_iterations=0, ARX least squares) is the online estimator's.
    operating_point : {None, 'mean', 'initial'}, default None
        The identified model's operating point (u0, y0): None keeps the structure's
        (Model.operating_point); 'mean' takes the mean input and output over all records; 'initial' the
        first sample of the first record (the record starts at rest there).
    initialisation_window : int, default 0
        Where identify refines: each record's free run starts after its first initialisation_window
        samples, measured, which set the model's state (``Model.simulate(u, initial=...)``), and is
        scored after them, instead of from rest: the model is fitted the way a test protocol with that
        state-initialisation window uses it (records that do not start at rest; an integrating plant,
        whose position keeps any transient of the start). Shorter than every record.
    c0 : float, optional
        PseudoHammersteinWiener only (another model: ValueError): the initial backlash half-width c(0) of
        equation_error and paper, in the output's units, or where the estimator normalises a fraction of
        the output's scale (output_error starts at 0). Default: 0.01.
    backlash_hold : int, optional
        PseudoHammersteinWiener only (another model: ValueError): output_error holds c at 0 for this many
        samples after each start from rest. Default: 200.
    
    Returns
    -------
    model
        A new model of the same type with the identified parameters, that operating point and the
        records' input range (Model.input_range).
    
    Warns
    -----
    bonl.StabilityWarning
        The identified model's largest pole has magnitude >= 0.999 (unstable or barely damped); possible
        where identify returns the recursive estimate as it is ('paper', refine_iterations=0, ARX least squares).
    bonl.ExcitationWarning
        The records' input takes fewer distinct values than the structure needs (two for every model; for an
        input polynomial of degree r, r + 1, on each side of zero where it has two segments): a constant input
        cannot excite the structure, and the identified parameters are not fixed by the data.
    
    Raises
    ------
    ValueError
        Bad orders, settings, lengths or non-finite samples.
    bonl.NumericalError
        The estimator broke down numerically.
    """
@typing.overload
def identify(model: PrandtlIshlinskiiHammerstein, u: numpy.typing.ArrayLike | None = None, y: numpy.typing.ArrayLike | None = None, *, records: collections.abc.Sequence[tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike]] | None = None, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None, passes: typing.SupportsInt | typing.SupportsIndex = 1, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, refine_iterations: typing.SupportsInt | typing.SupportsIndex = 100, normalise: bool = True, operating_point: str | None = None, initialisation_window: typing.SupportsInt | typing.SupportsIndex = 0) -> PrandtlIshlinskiiHammerstein:
    """
    Identify a model's parameters from an input/output record, or from several.
    
    Parameters
    ----------
    model : one of bonl.MODELS
        Gives the structure (orders); its parameter values are not used.
    u, y : array_like, shape (n,)
        Input and measured output of one record.
    records : sequence of (u, y) pairs, optional
        Several records (experiments of the same system), by keyword, in place of u and y:
        ``identify(model, records=[(u1, y1), (u2, y2)])``. Each record is simulated from rest; no history
        is carried across records.
    passes : int, default 1
        Passes of the recursive estimator over the record(s) (the paper's step 5).
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
    refine_iterations : int, default 100
        Levenberg-Marquardt iterations of the refinement that follows the recursive stage for
        'output_error' and 'equation_error' (0: none, the recursive estimate alone). It minimises the
        free-run simulation error with the analytic Jacobian of the simulation and keeps the linear block
        stable.
    normalise : bool, default True
        Work in the data's own scale, so that p0, the trace ceiling and the window's damping mean the same
        whatever the units ('paper' never: it is the paper's algorithm in the data's units). Estimator:
        the RMS of u - u0 and y - y0 is measured over the first 100 samples from the first moving input,
        then the recursion runs over them and on in coordinates where the parameters are of order one.
        identify: where it refines, on u and y divided by the powers of two nearest their RMS, the model
        returned in the data's units; the recursive estimate returned as it is ('paper',
        refine_iterations=0, ARX least squares) is the online estimator's.
    operating_point : {None, 'mean', 'initial'}, default None
        The identified model's operating point (u0, y0): None keeps the structure's
        (Model.operating_point); 'mean' takes the mean input and output over all records; 'initial' the
        first sample of the first record (the record starts at rest there).
    initialisation_window : int, default 0
        Where identify refines: each record's free run starts after its first initialisation_window
        samples, measured, which set the model's state (``Model.simulate(u, initial=...)``), and is
        scored after them, instead of from rest: the model is fitted the way a test protocol with that
        state-initialisation window uses it (records that do not start at rest; an integrating plant,
        whose position keeps any transient of the start). Shorter than every record.
    c0 : float, optional
        PseudoHammersteinWiener only (another model: ValueError): the initial backlash half-width c(0) of
        equation_error and paper, in the output's units, or where the estimator normalises a fraction of
        the output's scale (output_error starts at 0). Default: 0.01.
    backlash_hold : int, optional
        PseudoHammersteinWiener only (another model: ValueError): output_error holds c at 0 for this many
        samples after each start from rest. Default: 200.
    
    Returns
    -------
    model
        A new model of the same type with the identified parameters, that operating point and the
        records' input range (Model.input_range).
    
    Warns
    -----
    bonl.StabilityWarning
        The identified model's largest pole has magnitude >= 0.999 (unstable or barely damped); possible
        where identify returns the recursive estimate as it is ('paper', refine_iterations=0, ARX least squares).
    bonl.ExcitationWarning
        The records' input takes fewer distinct values than the structure needs (two for every model; for an
        input polynomial of degree r, r + 1, on each side of zero where it has two segments): a constant input
        cannot excite the structure, and the identified parameters are not fixed by the data.
    
    Raises
    ------
    ValueError
        Bad orders, settings, lengths or non-finite samples.
    bonl.NumericalError
        The estimator broke down numerically.
    """
@typing.overload
def identify(model: BoucWenFeedback, u: numpy.typing.ArrayLike | None = None, y: numpy.typing.ArrayLike | None = None, *, records: collections.abc.Sequence[tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike]] | None = None, c0: typing.SupportsFloat | typing.SupportsIndex | None = None, backlash_hold: typing.SupportsInt | typing.SupportsIndex | None = None, passes: typing.SupportsInt | typing.SupportsIndex = 1, method: str = 'output_error', forgetting: float | tuple[float, int, float] | str | None = None, p0: typing.SupportsFloat | typing.SupportsIndex | None = None, refine_iterations: typing.SupportsInt | typing.SupportsIndex = 100, normalise: bool = True, operating_point: str | None = None, initialisation_window: typing.SupportsInt | typing.SupportsIndex = 0) -> BoucWenFeedback:
    """
    Identify a model's parameters from an input/output record, or from several.
    
    Parameters
    ----------
    model : one of bonl.MODELS
        Gives the structure (orders); its parameter values are not used.
    u, y : array_like, shape (n,)
        Input and measured output of one record.
    records : sequence of (u, y) pairs, optional
        Several records (experiments of the same system), by keyword, in place of u and y:
        ``identify(model, records=[(u1, y1), (u2, y2)])``. Each record is simulated from rest; no history
        is carried across records.
    passes : int, default 1
        Passes of the recursive estimator over the record(s) (the paper's step 5).
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
    refine_iterations : int, default 100
        Levenberg-Marquardt iterations of the refinement that follows the recursive stage for
        'output_error' and 'equation_error' (0: none, the recursive estimate alone). It minimises the
        free-run simulation error with the analytic Jacobian of the simulation and keeps the linear block
        stable.
    normalise : bool, default True
        Work in the data's own scale, so that p0, the trace ceiling and the window's damping mean the same
        whatever the units ('paper' never: it is the paper's algorithm in the data's units). Estimator:
        the RMS of u - u0 and y - y0 is measured over the first 100 samples from the first moving input,
        then the recursion runs over them and on in coordinates where the parameters are of order one.
        identify: where it refines, on u and y divided by the powers of two nearest their RMS, the model
        returned in the data's units; the recursive estimate returned as it is ('paper',
        refine_iterations=0, ARX least squares) is the online estimator's.
    operating_point : {None, 'mean', 'initial'}, default None
        The identified model's operating point (u0, y0): None keeps the structure's
        (Model.operating_point); 'mean' takes the mean input and output over all records; 'initial' the
        first sample of the first record (the record starts at rest there).
    initialisation_window : int, default 0
        Where identify refines: each record's free run starts after its first initialisation_window
        samples, measured, which set the model's state (``Model.simulate(u, initial=...)``), and is
        scored after them, instead of from rest: the model is fitted the way a test protocol with that
        state-initialisation window uses it (records that do not start at rest; an integrating plant,
        whose position keeps any transient of the start). Shorter than every record.
    c0 : float, optional
        PseudoHammersteinWiener only (another model: ValueError): the initial backlash half-width c(0) of
        equation_error and paper, in the output's units, or where the estimator normalises a fraction of
        the output's scale (output_error starts at 0). Default: 0.01.
    backlash_hold : int, optional
        PseudoHammersteinWiener only (another model: ValueError): output_error holds c at 0 for this many
        samples after each start from rest. Default: 200.
    
    Returns
    -------
    model
        A new model of the same type with the identified parameters, that operating point and the
        records' input range (Model.input_range).
    
    Warns
    -----
    bonl.StabilityWarning
        The identified model's largest pole has magnitude >= 0.999 (unstable or barely damped); possible
        where identify returns the recursive estimate as it is ('paper', refine_iterations=0, ARX least squares).
    bonl.ExcitationWarning
        The records' input takes fewer distinct values than the structure needs (two for every model; for an
        input polynomial of degree r, r + 1, on each side of zero where it has two segments): a constant input
        cannot excite the structure, and the identified parameters are not fixed by the data.
    
    Raises
    ------
    ValueError
        Bad orders, settings, lengths or non-finite samples.
    bonl.NumericalError
        The estimator broke down numerically.
    """
def load_model(text: str) -> ARX | Hammerstein | HammersteinWiener | PseudoHammersteinWiener | Wiener | WienerHammerstein | NonlinearFeedback | PrandtlIshlinskiiHammerstein | BoucWenFeedback:
    """
    Read a model written by Model.to_json (or by C++'s bonl::io::to_json).
    
    Parameters
    ----------
    text : str
        The JSON text.
    
    Returns
    -------
    One of bonl.MODELS
    
    Raises
    ------
    ValueError
        The text is not valid JSON or not a valid bonl model (the message names the problem).
    """
MODELS: tuple = (ARX, Hammerstein, HammersteinWiener, PseudoHammersteinWiener, Wiener, WienerHammerstein, NonlinearFeedback, PrandtlIshlinskiiHammerstein, BoucWenFeedback)
__version__: str = '0.1.0'
