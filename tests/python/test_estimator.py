"""bonl.Estimator: online updates, their status, and rejection of non-finite samples."""

import warnings

import numpy as np
import pytest

import bonl
from conftest import known_models, random_levels


def test_online_updates_track_whole_record_recursion():
    truth = known_models()["Hammerstein"]
    u = random_levels(3000, 5, 1.0, 1)
    y = truth.simulate(u)
    estimator = bonl.Estimator(truth)
    statuses = [estimator.update(float(a), float(b)) for a, b in zip(u, y)]
    # The first 99 samples are kept while the data's scale is measured (no_information), then taken.
    assert all(s == bonl.UpdateStatus.no_information for s in statuses[:99])
    assert all(s == bonl.UpdateStatus.updated for s in statuses[99:])
    assert estimator.samples == 3000
    model = estimator.model
    assert type(model) is bonl.Hammerstein
    # After one pass the output-error recursion is within 1% in simulation (noise-free: much closer,
    # tests/cpp/output_error.test.cpp).
    u_val = random_levels(3000, 5, 1.0, 2)
    assert bonl.metrics.nrmse(truth.simulate(u_val), model.simulate(u_val)) < 0.01
    p = estimator.covariance
    np.testing.assert_array_equal(p, p.T)


def test_non_finite_samples_are_rejected_without_trace():
    truth = known_models()["PseudoHammersteinWiener"]
    u = random_levels(1000, 5, 1.0, 3)
    y = truth.simulate(u)
    clean = bonl.Estimator(truth)
    disturbed = bonl.Estimator(truth)
    for k in range(u.size):
        if k % 97 == 50:
            theta = disturbed.theta
            assert disturbed.update(float("nan"), float(y[k])) == bonl.UpdateStatus.rejected_non_finite
            assert disturbed.update(float(u[k]), float("inf")) == bonl.UpdateStatus.rejected_non_finite
            np.testing.assert_array_equal(disturbed.theta, theta)
        clean.update(float(u[k]), float(y[k]))
        disturbed.update(float(u[k]), float(y[k]))
    np.testing.assert_array_equal(clean.theta, disturbed.theta)
    np.testing.assert_array_equal(clean.covariance, disturbed.covariance)
    assert not disturbed.diverged


def test_gap_samples_carry_no_information_and_reset_restarts():
    truth = known_models()["PseudoHammersteinWiener"]
    u = random_levels(2000, 5, 1.0, 4)
    y = truth.simulate(u)
    estimator = bonl.Estimator(truth, method="equation_error")
    statuses = [estimator.update(float(a), float(b)) for a, b in zip(u, y)]
    assert bonl.UpdateStatus.no_information in statuses
    estimator.reset()
    assert estimator.samples == 0
    np.testing.assert_array_equal(estimator.theta, np.r_[np.zeros(13), 0.01])
    # The output-error method updates on gap samples too (the held sensitivity), and starts at c = 0.
    output_error = bonl.Estimator(truth, normalise=False)
    assert all(output_error.update(float(a), float(b)) == bonl.UpdateStatus.updated for a, b in zip(u, y))
    output_error.reset()
    np.testing.assert_array_equal(output_error.theta, np.zeros(14))
    estimator.reset(truth.theta)
    np.testing.assert_array_equal(estimator.theta, truth.theta)


def test_window_refinement_is_an_option_of_the_output_error_estimator():
    # On by default; it refines over the newest samples and counts what it did. Median over 3 seeds of
    # 2% noise: closer to identify() than the recursion alone. The C++ suite checks every model.
    truth = bonl.ARX(2, 1, 1, a=[-1.5, 0.7], b=[1.0, 0.5])
    u_check = np.repeat(np.random.default_rng(4).uniform(-1, 1, 800), 5)

    def error(model):
        return bonl.metrics.nrmse(truth.simulate(u_check), model.simulate(u_check))

    errors = {"plain": [], "window": [], "identify": []}
    for seed in (3, 5, 7):
        rng = np.random.default_rng(seed)
        u = np.repeat(rng.uniform(-1, 1, 800), 5)
        clean = truth.simulate(u)
        y = clean + rng.normal(0.0, 0.02 * clean.std(), u.size)
        plain = bonl.Estimator(truth, window=bonl.WindowRefinementOptions(enabled=False))
        windowed = bonl.Estimator(truth)
        for estimator in (plain, windowed):
            estimator.update_record(u, y)
        assert plain.health.window.swaps == 0
        assert windowed.health.window.swaps > 0 and windowed.health.window.iterations > 0
        errors["plain"].append(error(plain.model))
        errors["window"].append(error(windowed.model))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", bonl.ExtrapolationWarning)
            errors["identify"].append(error(bonl.identify(truth, u, y)))
    median = {name: float(np.median(values)) for name, values in errors.items()}
    assert median["window"] <= median["plain"]
    assert median["window"] <= 1.5 * median["identify"]
    with pytest.raises(ValueError, match="window length must be >= 100 samples, got 99"):
        bonl.Estimator(truth, window=bonl.WindowRefinementOptions(length=99))
    with pytest.raises(ValueError, match="window work_per_sample must be >= 2 model steps, got 1"):
        bonl.Estimator(truth, window=bonl.WindowRefinementOptions(work_per_sample=1))


def test_the_same_machine_in_other_units_gives_the_same_model_in_those_units():
    # The estimator measures the data's scale over its first samples (measuring_scale, data_scale) and
    # works in it; rescaled back (the models' units, Model.rescaled), the estimate from the data in
    # other units simulates as the one from the data as they are. The C++ suite checks every model.
    truth = known_models()["PseudoHammersteinWiener"]
    u = random_levels(4000, 5, 1.0, 11)
    y = truth.simulate(u)
    u_check = random_levels(2000, 5, 1.0, 12)
    original = bonl.Estimator(truth)
    original.update_record(u, y)
    assert original.data_scale == pytest.approx((np.sqrt(np.mean(u[:100] ** 2)), np.sqrt(np.mean(y[:100] ** 2))))
    for fu, fy in ((1e-3, 1e4), (1e4, 1e-3)):
        scaled = bonl.Estimator(truth.rescaled(fu, fy))
        statuses = scaled.update_record(u * fu, y * fy).status
        assert (statuses[:99] == int(bonl.UpdateStatus.no_information)).all()
        assert scaled.pending_samples == 0 and not scaled.measuring_scale
        back = scaled.model.rescaled(1 / fu, 1 / fy)
        assert bonl.metrics.nrmse(original.model.simulate(u_check), back.simulate(u_check)) < 1e-9
    # In the data's units as they are: normalise=False, from the first sample.
    raw = bonl.Estimator(truth, normalise=False)
    assert raw.update(float(u[0]), float(y[0])) == bonl.UpdateStatus.updated
    assert raw.data_scale == (1.0, 1.0)
