"""Integrators (every model's last order ni) from Python: the default, the model file, bad input, and
an integrating ARX identified from data written out here by its difference equation (the oracle),
from rest and, in a record that starts in motion, after identify's initialisation window."""

import json

import numpy as np
import pytest

import bonl


@pytest.mark.parametrize("model_class", bonl.MODELS, ids=lambda c: c.__name__)
def test_every_model_takes_ni_last_with_default_zero(model_class):
    assert model_class.ORDERS[-1] == "ni"
    assert model_class.ORDER_DEFAULTS["ni"] == 0  # (the nonlinear-feedback model also defaults its plays, np = 0)
    required = model_class.PAPER_ORDERS[:-1]
    assert model_class(*required).ni == 0
    with_one = model_class(*required, ni=1)
    assert with_one.ni == 1 and with_one.orders[-1] == 1
    back = bonl.load_model(with_one.to_json())
    assert back.orders == with_one.orders
    assert "ni" not in json.loads(model_class(*required).to_json())["orders"]  # written as before
    with pytest.raises(ValueError, match=r"ni \(integrators, poles fixed at 1\) must be 0, 1 or 2, got 3"):
        model_class(*required, ni=3)


def _integrating_arx_output(u, b, a):
    """y(k) = y(k-1) + z(k), z(k) = -a_1 z(k-1) + b_0 u(k-1) + b_1 u(k-2) from rest: nk = 1, one integrator."""
    z, y = np.zeros(u.size), np.zeros(u.size)
    for k in range(u.size):
        lag = lambda x, j: x[k - j] if k - j >= 0 else 0.0  # noqa: E731, B023 (used in this iteration)
        z[k] = -a[0] * lag(z, 1) + b[0] * lag(u, 1) + b[1] * lag(u, 2)
        y[k] = lag(y, 1) + z[k]
    return y


def test_an_integrating_arx_is_identified_from_its_difference_equation():
    rng = np.random.default_rng(5)
    u = np.repeat(rng.uniform(-1, 1, 800), 5)
    u -= u.mean()
    b, a = np.array([0.2, 0.1]), np.array([-0.6])
    y = _integrating_arx_output(u, b, a)
    truth = bonl.ARX(1, 1, 1, ni=1, b=b, a=a)
    np.testing.assert_allclose(truth.simulate(u), y, rtol=0, atol=1e-12 * np.abs(y).max())
    model = bonl.identify(bonl.ARX(1, 1, 1, ni=1), u, y)
    np.testing.assert_allclose(model.b, b, rtol=1e-9)
    np.testing.assert_allclose(model.a, a, rtol=1e-9)
    assert model.pole_radius == pytest.approx(0.6, rel=1e-9)  # the estimated A alone
    assert bonl.named_orders(model) == {"na": 1, "nb": 1, "nk": 1, "ni": 1}


def _integrating_arx_in_motion(lead, samples, seed):
    """The integrating ARX above, run from rest by its difference equation on `lead + samples` samples
    of random levels; the record is the last `samples` (it starts in motion). (u, y, b, a)."""
    rng = np.random.default_rng(seed)
    u = np.repeat(rng.uniform(-1, 1, (lead + samples) // 5 + 1), 5)[:lead + samples]
    b, a = np.array([0.2, 0.1]), np.array([-0.6])
    y = _integrating_arx_output(u, b, a)
    return u[lead:], y[lead:], b, a


def test_a_record_that_starts_in_motion_is_fitted_after_its_initialisation_window():
    u, y, b, a = _integrating_arx_in_motion(lead=300, samples=1500, seed=6)
    assert abs(y[1] - y[0]) > 1e-3  # moving at the record's start
    model = bonl.identify(bonl.ARX(1, 1, 1, ni=1), u, y, initialisation_window=5)
    np.testing.assert_allclose(model.b, b, rtol=1e-8)
    np.testing.assert_allclose(model.a, a, rtol=1e-8)
    # From rest, the start's missing motion stays in the integrated output and biases the fit.
    from_rest = bonl.identify(bonl.ARX(1, 1, 1, ni=1), u, y)
    assert np.max(np.abs(from_rest.b - b)) > 1e-3
    # select ranks by the free run as it was fitted, and passes the window on (also pickled, for Dask).
    chosen = bonl.select(bonl.grid(bonl.ARX, na=[1], nb=[1], nk=[1], ni=[1]), u, y, criterion="bic",
                         initialisation_window=5, progress=False)
    np.testing.assert_allclose(chosen.best.b, b, rtol=1e-8)
    assert chosen.table[0].fit_mse < 1e-20


@pytest.mark.parametrize("window, message", [
    (-1, r"initialisation_window must be >= 0, got -1"),
    (1500, r"initialisation_window \(1500\) must be shorter than every record; records\[0\] has 1500 samples"),
])
def test_e24_a_bad_initialisation_window_is_a_value_error(window, message):
    u, y, _, _ = _integrating_arx_in_motion(lead=10, samples=1500, seed=7)
    with pytest.raises(ValueError, match=message):
        bonl.identify(bonl.ARX(1, 1, 1, ni=1), u, y, initialisation_window=window)


def test_e24_select_refuses_a_bad_initialisation_window_before_any_candidate_runs():
    u, y, _, _ = _integrating_arx_in_motion(lead=10, samples=400, seed=8)
    with pytest.raises(ValueError, match=r"initialisation_window \(300\) must be shorter than every record; "
                                         r"records\[0\] has 300 samples"):
        bonl.select(bonl.grid(bonl.ARX, na=[1], nb=[1], nk=[1], ni=[1]), u, y, initialisation_window=300,
                    progress=False)
