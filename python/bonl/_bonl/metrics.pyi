"""
Error measures for simulated or predicted outputs.
"""
from __future__ import annotations
import numpy.typing
__all__: list[str] = ['fit_percent', 'mse', 'nrmse', 'rmse']
def fit_percent(y: numpy.typing.ArrayLike, yhat: numpy.typing.ArrayLike) -> float:
    """
    Fit in percent, 100 (1 - ||y - yhat|| / ||y - mean(y)||), as the System Identification Toolbox's compare.
    
    Parameters
    ----------
    y : array_like, shape (n,)
        The measured output.
    yhat : array_like, shape (n,)
        Its simulation or prediction, as long as y.
    
    Returns
    -------
    float
        The fit, <= 100 (100 is perfect, 0 no better than y's mean).
    """
def mse(y: numpy.typing.ArrayLike, yhat: numpy.typing.ArrayLike) -> float:
    """
    Mean squared error, mean((y - yhat)^2).
    
    Parameters
    ----------
    y : array_like, shape (n,)
        The measured output.
    yhat : array_like, shape (n,)
        Its simulation or prediction, as long as y.
    
    Returns
    -------
    float
        The MSE, in y's units squared, >= 0.
    """
def nrmse(y: numpy.typing.ArrayLike, yhat: numpy.typing.ArrayLike) -> float:
    """
    Normalised error ||y - yhat|| / ||y - mean(y)||.
    
    Parameters
    ----------
    y : array_like, shape (n,)
        The measured output.
    yhat : array_like, shape (n,)
        Its simulation or prediction, as long as y.
    
    Returns
    -------
    float
        The NRMSE, >= 0 (0 is perfect, 1 no better than y's mean).
    """
def rmse(y: numpy.typing.ArrayLike, yhat: numpy.typing.ArrayLike) -> float:
    """
    Root mean squared error of yhat against y, sqrt(mean((y - yhat)^2)).
    
    Parameters
    ----------
    y : array_like, shape (n,)
        The measured output.
    yhat : array_like, shape (n,)
        Its simulation or prediction, as long as y.
    
    Returns
    -------
    float
        The RMSE, in y's units, >= 0.
    """
