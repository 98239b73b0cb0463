"""Error measures for simulated or predicted outputs: :func:`mse`, :func:`rmse`, :func:`nrmse` and
:func:`nrmse_fit` (the System Identification Toolbox's fit, in percent)."""

from ._bonl.metrics import mse, nrmse, nrmse_fit, rmse

__all__ = ["mse", "nrmse", "nrmse_fit", "rmse"]
