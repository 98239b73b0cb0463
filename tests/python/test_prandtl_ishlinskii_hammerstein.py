"""The Prandtl-Ishlinskii Hammerstein model in Python (its C++ tests:
tests/cpp/prandtl_ishlinskii_hammerstein.test.cpp): the free run against the plays and the difference
equation written out in numpy; identify through Python with the thresholds given by name, recovering
the known system on a fresh input of a larger amplitude; the online estimator; the model file keeps
the thresholds; bad thresholds refused with a ValueError and the model unchanged; the inverse for control
follows a reference that reverses many times (the model's own simulation is the oracle) and refuses
input hysteresis that is not monotone."""

import numpy as np
import pytest

import bonl

from conftest import known_models, random_levels


def _plays_and_linear_block(model, u):
    """Plays from 0, w = f(u) + g . plays, then x(k) = sum_i b_i w(k-nk-i) - sum_j a_j x(k-j)."""
    state = np.zeros(len(model.thresholds))
    w = np.empty_like(u)
    for k, v in enumerate(u):
        state = np.minimum(np.maximum(state, v - model.thresholds), v + model.thresholds)
        w[k] = np.polyval(model.f[::-1], v) + model.g @ state
    x = np.zeros_like(u)
    for k in range(len(u)):
        x[k] = sum(bi * w[k - model.nk - i] for i, bi in enumerate(model.b) if k - model.nk - i >= 0)
        x[k] -= sum(aj * x[k - j] for j, aj in enumerate(model.a, start=1) if k - j >= 0)
    return x


@pytest.mark.parametrize("which", ["paper_orders", "small"])
def test_the_free_run_is_the_plays_and_the_difference_equation(which):
    model = known_models(which)["PrandtlIshlinskiiHammerstein"]
    u = random_levels(400, 5, 1.5, 5)
    np.testing.assert_allclose(model.simulate(u), _plays_and_linear_block(model, u), rtol=0, atol=1e-12)


@pytest.mark.parametrize("method", ["output_error", "equation_error"])
def test_identify_with_the_thresholds_by_name_recovers_the_known_system(method):
    truth = known_models()["PrandtlIshlinskiiHammerstein"]
    u = random_levels(4000, 5, 1.0, 3)
    structure = bonl.PrandtlIshlinskiiHammerstein(3, 2, 8, 3, 1, thresholds=[0.4])
    identified = bonl.identify(structure, u, truth.simulate(u), method=method)
    np.testing.assert_array_equal(identified.thresholds, [0.4])
    fresh = random_levels(4000, 5, 0.9, 77)  # inside the identification input's range
    assert bonl.metrics.nrmse(truth.simulate(fresh), identified.simulate(fresh)) <= 1e-6
    # Beyond it the model says so (and continues its polynomial linearly, where the truth's cubic
    # goes on: tests/cpp/linear_continuation.test.cpp checks the continuation).
    with pytest.warns(bonl.ExtrapolationWarning):
        identified.simulate(random_levels(4000, 5, 1.5, 77))


def test_the_online_estimator_converges():
    truth = known_models()["PrandtlIshlinskiiHammerstein"]
    u = random_levels(4000, 5, 1.0, 3)
    estimator = bonl.Estimator(bonl.PrandtlIshlinskiiHammerstein(*truth.orders, thresholds=truth.thresholds))
    estimator.update_record(u, truth.simulate(u))
    np.testing.assert_allclose(estimator.theta, truth.theta, rtol=0, atol=1e-8)


def test_the_model_file_keeps_the_thresholds():
    model = known_models("small")["PrandtlIshlinskiiHammerstein"]
    model.thresholds = [0.1, 0.7]
    back = bonl.load_model(model.to_json())
    assert isinstance(back, bonl.PrandtlIshlinskiiHammerstein)
    np.testing.assert_array_equal(back.thresholds, [0.1, 0.7])
    np.testing.assert_array_equal(back.theta, model.theta)
    u = random_levels(300, 5, 1.0, 8)
    np.testing.assert_array_equal(back.simulate(u), model.simulate(u))


@pytest.mark.parametrize("bad, message", [([0.5, 0.2], "strictly increasing"), ([0.0, 0.2], "must be > 0"),
                                          ([-0.1, 0.2], "must be > 0"), ([0.1, np.nan], "thresholds"),
                                          ([0.1], "thresholds")])
def test_bad_thresholds_are_refused_and_the_model_kept(bad, message):
    model = known_models("small")["PrandtlIshlinskiiHammerstein"]
    with pytest.raises(ValueError, match=message):
        model.thresholds = bad
    np.testing.assert_array_equal(model.thresholds, [0.2, 0.5])
    with pytest.raises(ValueError, match="np"):
        bonl.PrandtlIshlinskiiHammerstein(2, 1, 2, 2, 0)


def test_the_inverse_follows_a_reference_that_reverses_many_times():
    truth = known_models("small")["PrandtlIshlinskiiHammerstein"]  # weights of either sign
    k = np.arange(2000, dtype=float)
    u = np.where(k < 100, k / 100, 1.0) * (0.2 + 0.4 * np.sin(2 * np.pi * k / 250) + 0.15 * np.sin(2 * np.pi * k / 13))
    r = truth.simulate(u)
    inverse = bonl.control.InverseModel(truth, command_min=-1.0, command_max=1.0)
    run = inverse.commands(r)
    assert not run.status[:-truth.nk].any()
    np.testing.assert_allclose(truth.simulate(run.command)[truth.nk:], r[truth.nk:], rtol=0, atol=1e-9)
    np.testing.assert_allclose(run.command[:-truth.nk], u[:-truth.nk], rtol=0, atol=1e-9)
    # step by step, the plays' memory carried from sample to sample, as the whole run
    steps = [inverse.step(r[min(j + truth.nk, len(r) - 1)]).value for j in range(300)]
    np.testing.assert_array_equal(steps, run.command[:300])
    # beyond reach: the range's ends, reported
    run = inverse.commands(3.0 * r)
    saturated = (run.status & int(bonl.control.InverseStatus.saturated)) != 0
    assert saturated.any()
    np.testing.assert_array_equal(np.abs(run.command[saturated]), 1.0)


def test_input_hysteresis_that_is_not_monotone_has_no_inverse():
    model = known_models("small")["PrandtlIshlinskiiHammerstein"]
    model.g = [0.3, -0.6]  # f'(0) = 0.5: with the second play moving alone, w falls with u
    with pytest.raises(ValueError, match="not monotone in u near the operating point"):
        bonl.control.InverseModel(model, command_min=-1.0, command_max=1.0)
    with pytest.raises(ValueError, match="not monotone in u near the operating point"):
        bonl.control.AdaptiveInverse(model, command_min=-1.0, command_max=1.0)
