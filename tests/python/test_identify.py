"""Identification of known systems from Python, judged by free-run simulation on a fresh input
(the bounds are those of tests/cpp/identify.test.cpp, where they are justified)."""

import threading

import numpy as np
import pytest

import bonl
from conftest import known_models, random_levels


def _record(model, seed, noise=0.0):
    u = random_levels(5000, 5, 1.0, seed)
    y = model.simulate(u)
    if noise:
        y = y + np.random.default_rng(seed + 100).normal(0.0, noise * y.std(), y.size)
    return u, y


def test_default_method_recovers_noise_free_systems(known):
    name, truth = known
    u, y = _record(truth, 1)
    fitted = bonl.identify(truth, u, y)
    assert type(fitted) is type(truth)
    u_val, _ = _record(truth, 2)
    y_val = truth.simulate(u_val)
    assert bonl.metrics.nrmse(y_val, fitted.simulate(u_val)) <= 0.01
    np.testing.assert_allclose(fitted.theta, truth.theta, rtol=1e-6, atol=1e-6)
    if name == "PseudoHammersteinWiener":
        assert abs(fitted.params["c"] - 0.1) <= 0.002


@pytest.mark.parametrize("noise", [0.01, 0.05])
def test_noisy_default_beats_paper(noise):
    truth = known_models()["PseudoHammersteinWiener"]
    u, y = _record(truth, 1, noise)
    u_val, _ = _record(truth, 2)
    y_val = truth.simulate(u_val)
    ours = bonl.identify(truth, u, y)
    paper = bonl.identify(truth, u, y, method="paper")
    ours_error = bonl.metrics.nrmse(y_val, ours.simulate(u_val))
    assert ours_error <= 0.25 * noise
    assert ours_error <= bonl.metrics.nrmse(y_val, paper.simulate(u_val))


def test_settings_are_passed_through():
    truth = known_models()["ARX"]
    u, y = _record(truth, 5, 0.01)
    # In the data's units (normalise=False), so that P(0) = p0 I is the batch solution's regulariser.
    a = bonl.identify(truth, u, y, method="equation_error", forgetting=1.0, p0=10.0, normalise=False)
    b = bonl.identify(truth, u, y, method="equation_error", forgetting=(1.0, 0, 1.0), p0=10.0, normalise=False)
    c = bonl.identify(truth, u, y, method="equation_error", normalise=False)
    np.testing.assert_array_equal(a.theta, b.theta)
    assert not np.array_equal(a.theta, c.theta)
    # ARX's least squares with lambda = 1 equals the regularised batch solution.
    phi = np.zeros((u.size, 6))
    for k in range(u.size):
        phi[k, :3] = [u[k - 8 - i] if k - 8 - i >= 0 else 0.0 for i in range(3)]
        phi[k, 3:] = [-y[k - j] if k - j >= 0 else 0.0 for j in range(1, 4)]
    batch = np.linalg.solve(phi.T @ phi + np.eye(6) / 10.0, phi.T @ y)
    np.testing.assert_allclose(a.theta, batch, rtol=1e-8)


def test_whole_record_calls_release_the_gil():
    """Four identifications in four threads give the results of the serial runs."""
    truth = known_models()["PseudoHammersteinWiener"]
    records = [_record(truth, seed, 0.01) for seed in range(4)]
    serial = [bonl.identify(truth, u, y).theta for u, y in records]
    results = [None] * 4

    def work(i):
        u, y = records[i]
        results[i] = bonl.identify(truth, u, y).theta

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for got, expected in zip(results, serial):
        np.testing.assert_array_equal(got, expected)


def test_several_records_identify_one_model_each_from_rest(known):
    # Two records, each simulated from rest: identification over both recovers the system (the C++
    # test "several records identify one model" explains the bound); the same samples joined into one
    # record would carry the first record's end into the second's start.
    name, truth = known
    u1, y1 = _record(truth, 1)
    u2, y2 = _record(truth, 3)
    fitted = bonl.identify(truth, records=[(u1[:2500], y1[:2500]), (u2[:2500], y2[:2500])])
    u_val, _ = _record(truth, 2)
    assert bonl.metrics.nrmse(truth.simulate(u_val), fitted.simulate(u_val)) <= 1e-6


def test_one_record_as_a_list_identifies_exactly_as_u_y():
    truth = known_models()["PseudoHammersteinWiener"]
    u, y = _record(truth, 1, 0.01)
    np.testing.assert_array_equal(bonl.identify(truth, records=[(u, y)], refine_iterations=5).theta,
                                  bonl.identify(truth, u, y, refine_iterations=5).theta)


@pytest.mark.parametrize("records, message", [
    (lambda u, y: u, r"records must be a list of pairs \(u, y\), got ndarray"),
    (lambda u, y: [], "records must hold at least one record"),
    (lambda u, y: [(u, y), u], r"records\[1\] must be a pair \(u, y\)"),
    (lambda u, y: [(u, y), (u, y, y)], r"records\[1\] must be a pair \(u, y\)"),
    (lambda u, y: [(u, y), (u, y[:10])], r"records\[1\].u and records\[1\].y must have the same length"),
    (lambda u, y: [(u, y), (u, np.where(np.arange(u.size) == 3, np.nan, y))],
     r"records\[1\].y has a non-finite value at index 3"),
    (lambda u, y: [(u[:3], y[:3]), (u[:3], y[:3])], "the records must be longer together than the number of parameters"),
], ids=["an array", "empty", "not a pair", "a triple", "lengths", "NaN", "too short"])
def test_bad_records_are_a_value_error_naming_the_record(records, message):
    truth = known_models()["ARX"]
    u, y = _record(truth, 1)
    with pytest.raises(ValueError, match=message):
        bonl.identify(truth, records=records(u, y))


@pytest.mark.parametrize("call, message", [
    (lambda truth, u, y: bonl.identify(truth, u),
     r"y must be a 1-D array of real numbers, got None \(identify\(model, u, y\) for one record, "
     r"identify\(model, records=\[\(u1, y1\), \(u2, y2\), ...\]\) for several\)"),
    (lambda truth, u, y: bonl.identify(truth, [(u, y)]), r"y must be a 1-D array of real numbers, got None"),
    (lambda truth, u, y: bonl.identify(truth), r"u and y, or records, must be given"),
    (lambda truth, u, y: bonl.identify(truth, u, y, records=[(u, y)]), r"give u and y, or records, not both"),
    (lambda truth, u, y: bonl.identify(truth, y=y, records=[(u, y)]), r"give u and y, or records, not both"),
], ids=["no y", "records as u", "nothing", "both", "y and records"])
def test_one_record_is_u_and_y_several_are_records_never_both(call, message):
    truth = known_models()["ARX"]
    u, y = _record(truth, 1)
    with pytest.raises(ValueError, match=message):
        call(truth, u, y)
