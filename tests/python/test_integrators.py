"""Integrators (every model's last order ni) from Python: the default, the model file, bad input, and
an integrating ARX identified from data written out here by its difference equation (the oracle)."""

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


def test_an_integrating_arx_is_identified_from_its_difference_equation():
    rng = np.random.default_rng(5)
    u = np.repeat(rng.uniform(-1, 1, 800), 5)
    u -= u.mean()
    b, a = np.array([0.2, 0.1]), np.array([-0.6])
    # y(k) = y(k-1) + z(k), z(k) = -a_1 z(k-1) + b_0 u(k-1) + b_1 u(k-2): nk = 1, one integrator.
    z, y = np.zeros(u.size), np.zeros(u.size)
    for k in range(u.size):
        lag = lambda x, j: x[k - j] if k - j >= 0 else 0.0  # noqa: E731, B023 (used in this iteration)
        z[k] = -a[0] * lag(z, 1) + b[0] * lag(u, 1) + b[1] * lag(u, 2)
        y[k] = lag(y, 1) + z[k]
    truth = bonl.ARX(1, 1, 1, ni=1, b=b, a=a)
    np.testing.assert_allclose(truth.simulate(u), y, rtol=0, atol=1e-12 * np.abs(y).max())
    model = bonl.identify(bonl.ARX(1, 1, 1, ni=1), u, y)
    np.testing.assert_allclose(model.b, b, rtol=1e-9)
    np.testing.assert_allclose(model.a, a, rtol=1e-9)
    assert model.pole_radius == pytest.approx(0.6, rel=1e-9)  # the estimated A alone
    assert bonl.named_orders(model) == {"na": 1, "nb": 1, "nk": 1, "ni": 1}
