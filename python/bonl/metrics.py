"""Error measures for simulated or predicted outputs: :func:`mse`, :func:`rmse`, :func:`nrmse` and
:func:`fit_percent` (the System Identification Toolbox's fit, in percent), spelled as in C++
(``bonl::metrics``)."""

import warnings

from ._bonl.metrics import fit_percent, mse, nrmse, rmse

__all__ = ["fit_percent", "mse", "nrmse", "rmse"]


def nrmse_fit(y, yhat):
    """Deprecated: the former name of :func:`fit_percent`."""
    warnings.warn("bonl.metrics.nrmse_fit is now bonl.metrics.fit_percent, as in C++", DeprecationWarning,
                  stacklevel=2)
    return fit_percent(y, yhat)
