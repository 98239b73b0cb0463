"""The Wiener-Hammerstein model in Python (its C++ tests: tests/cpp/wiener_hammerstein.test.cpp): the
known systems of tests/data/known_systems.json are recovered by identify (from the best linear
approximation's splits) to NRMSE 1e-6 on a fresh input; the inverse is refused with a ValueError."""

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
