"""The Wiener-Hammerstein model in Python (its C++ tests: tests/cpp/wiener_hammerstein.test.cpp): the
known systems of tests/data/known_systems.json are recovered by identify (from the best linear
approximation's splits) to NRMSE 1e-6 on a fresh input; the inverse is refused with a ValueError. The
piecewise-linear option: a model with hinges simulates the blocks written out by hand, keeps its knots
through its model file and refuses bad ones with a ValueError that says what was wrong."""

import numpy as np
import pytest

import bonl

from conftest import known_models, random_levels


@pytest.mark.parametrize("system_set", ["paper_orders", "small"])
def test_identify_recovers_a_known_wiener_hammerstein_system(system_set):
    truth = known_models(system_set)["WienerHammerstein"]
    u = random_levels(5000, 5, 1.0, 1)
    identified = bonl.identify(truth, u, truth.simulate(u))
    fresh = random_levels(6000, 5, 1.0, 77)
    expected = truth.simulate(fresh)
    nrmse = np.linalg.norm(expected - identified.simulate(fresh)) / np.linalg.norm(expected)
    assert nrmse <= 1e-6


def test_the_model_file_round_trips_with_both_normalised_blocks():
    truth = known_models()["WienerHammerstein"]
    back = bonl.load_model(truth.to_json())
    assert isinstance(back, bonl.WienerHammerstein)
    assert back.f[0] == 1.0 and back.b2[0] == 1.0
    np.testing.assert_array_equal(back.theta, truth.theta)


def test_the_inverse_is_refused_with_a_value_error():
    truth = known_models("small")["WienerHammerstein"]
    with pytest.raises(ValueError, match="WienerHammerstein model has no inverse"):
        bonl.control.InverseModel(truth, command_min=-1.0, command_max=1.0)
    with pytest.raises(ValueError, match="WienerHammerstein model has no inverse"):
        bonl.control.AdaptiveInverse(truth)


def _saturating(r=1):
    """The known system's blocks with the hinges of tests/cpp/wiener_hammerstein.test.cpp."""
    known = known_models()["WienerHammerstein"]
    return bonl.WienerHammerstein(3, 2, known.nk, r, 2, 3, 2, b1=known.b1, a1=known.a1, knots=[-0.3, 0.4],
                                  g=[-0.7, -0.6], b2=known.b2, a2=known.a2)


def test_a_model_with_hinges_simulates_the_blocks_written_out():
    model = _saturating()
    u = random_levels(3000, 5, 1.0, 77)
    x1 = np.zeros_like(u)
    b1, a1, b2, a2, nk = model.b1, model.a1, model.b2, model.a2, model.nk
    for k in range(len(u)):
        x1[k] = sum(b1[i] * u[k - nk - i] for i in range(3) if k - nk - i >= 0) \
            - sum(a1[j - 1] * x1[k - j] for j in range(1, 4) if k - j >= 0)
    w = x1 - 0.7 * np.minimum(0.0, x1 + 0.3) - 0.6 * np.maximum(0.0, x1 - 0.4)
    y = np.zeros_like(u)
    for k in range(len(u)):
        y[k] = sum(b2[i] * w[k - i] for i in range(3) if k - i >= 0) - sum(a2[j - 1] * y[k - j] for j in range(1, 4)
                                                                           if k - j >= 0)
    assert (x1 < -0.3).sum() > 100 and (x1 > 0.4).sum() > 100
    np.testing.assert_allclose(model.simulate(u), y, rtol=0, atol=1e-12 * np.abs(y).max())


def test_the_knots_go_through_the_model_file_and_bad_ones_are_refused():
    model = _saturating(r=2)
    back = bonl.load_model(model.to_json())
    assert back.orders == model.orders and back.ORDERS == ("na1", "nb1", "nk", "r", "nh", "na2", "nb2", "ni")
    np.testing.assert_array_equal(back.knots, [-0.3, 0.4])
    np.testing.assert_array_equal(back.theta, model.theta)
    with pytest.raises(ValueError, match="knots must be strictly increasing, got 0.4 before -0.3 at index 1"):
        model.knots = [0.4, -0.3]
    with pytest.raises(ValueError, match=r"knots must not hold 0 \(the slope at 0 is f_1 = 1\)"):
        model.knots = [0.0, 0.4]
    np.testing.assert_array_equal(model.knots, [-0.3, 0.4])
    with pytest.raises(ValueError, match="nh \\(hinges\\) must be <= 32"):
        bonl.WienerHammerstein(3, 2, 0, 1, 33, 3, 2)


def test_identify_keeps_the_structures_knots_or_places_its_own():
    truth = _saturating()
    u = random_levels(5000, 5, 1.0, 1)
    y = truth.simulate(u)
    fresh = random_levels(6000, 5, 1.0, 77)
    expected = truth.simulate(fresh)
    with_knots = bonl.identify(truth, u, y)
    np.testing.assert_allclose(with_knots.knots, truth.knots, rtol=1e-15)  # through identify's units and back
    assert np.linalg.norm(expected - with_knots.simulate(fresh)) / np.linalg.norm(expected) <= 1e-6
    placed = bonl.identify(bonl.WienerHammerstein(3, 2, truth.nk, 1, 4, 3, 2), u, y)
    assert np.all(np.diff(placed.knots) > 0) and np.all(placed.knots != 0)
    assert np.linalg.norm(expected - placed.simulate(fresh)) / np.linalg.norm(expected) <= 0.05
