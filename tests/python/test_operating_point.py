"""Operating point and initial state (issue 18).

Oracles: a model with an operating point is the zero-point model on the deviations (bit for bit);
after a measured past as long as the model's memory the simulation continues the model's own
noise-free record (to round-off; within the backlash width for P-H-W)."""

import numpy as np
import pytest

import bonl
from conftest import known_models, random_levels

SMALL = known_models("small")


@pytest.mark.parametrize("name", sorted(SMALL))
def test_the_operating_point_shifts_input_and_output(name):
    at_zero = SMALL[name]
    model = bonl.load_model(at_zero.to_json())
    model.operating_point = (2.5, -1.25)
    u = random_levels(300, 5, 1.0, 41) + 2.5
    np.testing.assert_array_equal(model.simulate(u), at_zero.simulate(u - 2.5) - 1.25)
    y = model.simulate(u) + 0.01 * np.random.default_rng(42).standard_normal(u.size)
    identified = bonl.identify(model, u, y)
    assert identified.operating_point == (2.5, -1.25)
    np.testing.assert_array_equal(identified.theta, bonl.identify(at_zero, u - 2.5, y + 1.25).theta)


@pytest.mark.parametrize("source", ["mean", "initial"])
def test_identify_takes_the_operating_point_from_the_records(source):
    truth = SMALL["Hammerstein"]
    u = random_levels(300, 5, 1.0, 43) + 1.5
    y = truth.simulate(u) + 3.0
    point = (float(np.sum(u)) / u.size, float(np.sum(y)) / y.size) if source == "mean" else (u[0], y[0])
    identified = bonl.identify(truth, u, y, operating_point=source, refine_iterations=5)
    assert identified.operating_point == pytest.approx(point, rel=1e-15)  # numpy and Eigen sum in other orders
    by_hand = bonl.load_model(truth.to_json())
    by_hand.operating_point = identified.operating_point
    np.testing.assert_array_equal(identified.theta, bonl.identify(by_hand, u, y, refine_iterations=5).theta)
    with pytest.raises(ValueError, match="operating_point must be None .* 'mean' or 'initial', got 'median'"):
        bonl.identify(truth, u, y, operating_point="median")


@pytest.mark.parametrize("name", sorted(SMALL))
def test_simulation_after_a_measured_past_continues_the_record(name):
    model = SMALL[name]
    u = random_levels(600, 5, 1.0, 43)
    y = model.simulate(u)
    m = 20
    continued = model.simulate(u[m:], initial=(u[:m], y[:m]))
    bound = model.c + 1e-12 if name == "PseudoHammersteinWiener" else 1e-10 * np.max(np.abs(y))
    assert np.max(np.abs(continued - y[m:])) <= bound
    np.testing.assert_allclose(model.predict(u[m:], y[m:], initial=(u[:m], y[:m])), model.predict(u, y)[m:],
                               rtol=0, atol=1e-12)


def test_a_bad_initial_state_is_a_value_error():
    model = SMALL["ARX"]
    u = random_levels(50, 5, 1.0, 44)
    with pytest.raises(ValueError, match="initial must be None or a pair"):
        model.simulate(u, initial=np.zeros(4))
    with pytest.raises(ValueError, match="u_past and y_past must have the same length, got 5 and 4"):
        model.simulate(u, initial=(np.zeros(5), np.zeros(4)))
    with pytest.raises(ValueError, match="y_past has a non-finite value at index 1"):
        model.simulate(u, initial=(np.zeros(2), [0.0, np.nan]))
    with pytest.raises(ValueError, match="operating_point must be a pair"):
        model.operating_point = 1.0
    with pytest.raises(ValueError, match="u0"):
        model.operating_point = (np.inf, 0.0)
    assert model.operating_point == (0.0, 0.0)
