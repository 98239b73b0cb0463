"""Every bad input gives a ValueError whose message names the problem; arrays are never modified."""

import numpy as np
import pytest

import bonl
from conftest import known_models, random_levels


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: bonl.ARX(0, 1, 1), "na"),
        (lambda: bonl.ARX(1, -1, 1), "nb"),
        (lambda: bonl.ARX(1, 1, -1), "nk"),
        (lambda: bonl.Hammerstein(1, 1, 1, 0), "r"),
        (lambda: bonl.HammersteinWiener(1, 1, 1, 2, 1), "r1"),
        (lambda: bonl.Hammerstein(3, 2, 8, 3, f=[1.0, 2.0]), "f"),
        (lambda: bonl.Hammerstein(3, 2, 8, 3, b=[0.5, 0.1, 0.1]), "b_0"),
        (lambda: bonl.HammersteinWiener(3, 2, 8, 3, 3, q=[2.0, 0.0, 0.0]), "q_1"),
        (lambda: bonl.PseudoHammersteinWiener(3, 2, 8, 3, c=-0.1), "c"),
        (lambda: bonl.ARX(2, 1, 1, a=[0.1, float("nan")]), "non-finite"),
        (lambda: bonl.ARX(2, 1, 1, a=[[0.1, 0.2]]), "a must be 1-D"),
        (lambda: bonl.ARX(2, 1, 1, a="abc"), "a must be"),
    ],
)
def test_bad_construction(make, message):
    with pytest.raises(ValueError, match=message):
        make()


def test_bad_records_and_settings():
    model = known_models()["Hammerstein"]
    u = random_levels(300, 3, 1.0, 1)
    y = model.simulate(u)
    with pytest.raises(ValueError, match="same length"):
        bonl.identify(model, u, y[:-1])
    bad = y.copy()
    bad[17] = np.nan
    with pytest.raises(ValueError, match="y has a non-finite value at index 17"):
        bonl.identify(model, u, bad)
    with pytest.raises(ValueError, match="longer than the number of parameters"):
        bonl.identify(model, u[:10], y[:10])
    with pytest.raises(ValueError, match="passes"):
        bonl.identify(model, u, y, passes=0)
    with pytest.raises(ValueError, match="method"):
        bonl.identify(model, u, y, method="magic")
    for forgetting in (0.0, 1.5, -1.0, (0.98, 10, 1.2)):
        with pytest.raises(ValueError, match="forgetting factor"):
            bonl.identify(model, u, y, forgetting=forgetting)
    with pytest.raises(ValueError, match="forgetting must be"):
        bonl.identify(model, u, y, forgetting=(0.9, 1))
    with pytest.raises(ValueError, match="p0"):
        bonl.identify(model, u, y, p0=-1.0)
    with pytest.raises(ValueError, match="u must be 1-D"):
        model.simulate(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="u has a non-finite value at index 2"):
        model.simulate([0.0, 1.0, np.inf])
    with pytest.raises(ValueError, match="constant"):
        bonl.metrics.nrmse(np.ones(3), np.zeros(3))
    with pytest.raises(ValueError, match="same length"):
        bonl.metrics.mse(np.ones(3), np.zeros(4))
    with pytest.raises(ValueError, match="forgetting factor"):
        bonl.Estimator(model, forgetting=2.0)


def test_callers_arrays_are_never_modified():
    model = known_models()["PseudoHammersteinWiener"]
    u = random_levels(500, 5, 1.0, 2)
    y = model.simulate(u)
    u_before, y_before = u.copy(), y.copy()
    model.predict(u, y)
    bonl.identify(model, u, y, refine_iterations=2)
    bonl.metrics.mse(y, u)
    np.testing.assert_array_equal(u, u_before)
    np.testing.assert_array_equal(y, y_before)
