"""bonl.metrics on hand-computed numbers."""

import numpy as np
import pytest

import bonl


def test_hand_computed():
    y = np.array([1.0, 2.0, 3.0, 4.0])
    yhat = np.array([1.0, 2.5, 2.0, 4.0])
    assert bonl.metrics.mse(y, yhat) == pytest.approx(1.25 / 4)
    assert bonl.metrics.rmse(y, yhat) == pytest.approx(np.sqrt(1.25 / 4))
    assert bonl.metrics.nrmse(y, yhat) == pytest.approx(np.sqrt(1.25 / 5))
    assert bonl.metrics.fit_percent(y, yhat) == pytest.approx(50.0)
    assert bonl.metrics.fit_percent(y, y) == 100.0


def test_the_former_name_nrmse_fit_warns_and_gives_fit_percent():
    y = np.array([1.0, 2.0, 3.0, 4.0])
    yhat = np.array([1.0, 2.5, 2.0, 4.0])
    with pytest.warns(DeprecationWarning, match="fit_percent"):
        assert bonl.metrics.nrmse_fit(y, yhat) == bonl.metrics.fit_percent(y, yhat)
