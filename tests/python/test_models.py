"""The model classes: construction by keyword, parameters by name and in eq. (19) order,
simulation, prediction, copies and pickling."""

import copy
import pickle

import numpy as np
import pytest

import bonl
from conftest import known_models, random_levels

# What tests/data/known_systems.json says the paper-order front is, written out as the oracle of the
# tests below.
FRONT = dict(
    f=[0.002, 0.06, 0.02, -0.01],
    p=[-0.003, -0.02, -0.03, 0.015],
    b=[1.0, 0.5, 0.2],
    a=[-1.7, 1.04, -0.238],
)


def test_params_by_name_and_theta_order():
    phw = known_models()["PseudoHammersteinWiener"]
    params = phw.params
    assert set(params) == {"f", "p", "b", "a", "c"}
    np.testing.assert_array_equal(params["f"], FRONT["f"])
    np.testing.assert_array_equal(params["b"], FRONT["b"])
    assert params["c"] == 0.1
    expected = np.concatenate([FRONT["f"], FRONT["p"], FRONT["b"][1:], FRONT["a"], [0.1]])
    np.testing.assert_array_equal(phw.theta, expected)
    assert phw.theta.dtype == np.float64
    hw = known_models()["HammersteinWiener"]
    np.testing.assert_array_equal(hw.params["q"], [1.0, 0.2, 0.05])
    np.testing.assert_array_equal(hw.theta[-2:], [0.2, 0.05])
    arx = known_models()["ARX"]
    np.testing.assert_array_equal(arx.theta, [0.05, 0.03, 0.02, -1.7, 1.04, -0.238])
    assert (phw.na, phw.nb, phw.nk, phw.r) == (3, 2, 8, 3)
    assert hw.r1 == 3


def test_simulation_composes_the_blocks():
    """P-H-W by hand: the two-segment polynomial, the linear block, the backlash."""
    phw = known_models()["PseudoHammersteinWiener"]
    u = random_levels(300, 4, 1.2, 7)
    f, p, a, b = (np.array(FRONT[k]) for k in "fpab")
    w = np.array([np.polyval(f[::-1], v) + (np.polyval(p[::-1], v) if v < 0 else 0.0) for v in u])
    x = np.zeros_like(u)
    y = np.zeros_like(u)
    prev = 0.0
    for k in range(len(u)):
        acc = sum(b[i] * w[k - 8 - i] for i in range(3) if k - 8 - i >= 0)
        acc -= sum(a[j - 1] * x[k - j] for j in range(1, 4) if k - j >= 0)
        x[k] = acc
        prev = acc - 0.1 if acc > prev + 0.1 else (acc + 0.1 if acc < prev - 0.1 else prev)
        y[k] = prev
    np.testing.assert_allclose(phw.simulate(u), y, rtol=0, atol=1e-13)


def test_prediction_of_the_true_model_reproduces_noise_free_data(known):
    name, model = known
    u = random_levels(800, 5, 1.0, 4)
    y = model.simulate(u)
    np.testing.assert_allclose(model.predict(u, y), y, rtol=0, atol=1e-12)


def test_any_stride_and_dtype_are_accepted():
    model = known_models()["Hammerstein"]
    u = random_levels(400, 5, 1.0, 3)
    wide = np.zeros((400, 3))
    wide[:, 1] = u
    np.testing.assert_array_equal(model.simulate(wide[:, 1]), model.simulate(u))
    np.testing.assert_array_equal(model.simulate(list(u)), model.simulate(u))
    np.testing.assert_allclose(model.simulate(u.astype(np.float32)), model.simulate(u.astype(np.float32).astype(float)))


def test_copies_and_pickles_are_independent():
    model = known_models()["PseudoHammersteinWiener"]
    clone = copy.deepcopy(model)
    clone.theta = np.zeros(model.num_params)
    assert model.params["c"] == 0.1
    restored = pickle.loads(pickle.dumps(model))
    np.testing.assert_array_equal(restored.theta, model.theta)
    assert type(restored) is bonl.PseudoHammersteinWiener


def test_unstable_model_is_reported():
    model = bonl.Hammerstein(1, 0, 0, 1, f=[0.0, 1.0], a=[-1.5])
    with pytest.raises(bonl.NumericalError):
        model.simulate(np.ones(5000))


def test_paper_orders_are_the_known_systems_at_the_papers_orders():
    # The known systems' paper_orders set (tests/data/known_systems.json) is at the paper's orders,
    # bonl::PaperOrders, every other order at its minimum: the oracle of PAPER_ORDERS.
    for name, model in known_models().items():
        model_class = type(model)
        assert model_class.PAPER_ORDERS == model.orders, name
        assert model_class(*model_class.PAPER_ORDERS).orders == model.orders, name
