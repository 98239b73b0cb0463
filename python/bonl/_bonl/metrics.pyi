"""
Error measures for simulated or predicted outputs.
"""
from __future__ import annotations
import numpy.typing
__all__: list[str] = ['fit_percent', 'mse', 'nrmse', 'rmse']
def fit_percent(y: numpy.typing.ArrayLike, yhat: numpy.typing.ArrayLike) -> float:
    """
    Fit in percent, 100 (1 - ||y - yhat|| / ||y - mean(y)||), as the System Identification Toolbox's compare.
    """
def mse(y: numpy.typing.ArrayLike, yhat: numpy.typing.ArrayLike) -> float:
    """
    Mean squared error, mean((y - yhat)^2).
    """
def nrmse(y: numpy.typing.ArrayLike, yhat: numpy.typing.ArrayLike) -> float:
    """
    Normalised error ||y - yhat|| / ||y - mean(y)|| (0 is perfect).
    """
def rmse(y: numpy.typing.ArrayLike, yhat: numpy.typing.ArrayLike) -> float:
    """
    Root mean squared error of yhat against y, sqrt(mean((y - yhat)^2)).
    """
