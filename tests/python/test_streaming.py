"""bonl.Estimator.update over arrays: the record in one call, the GIL released, equal bit for bit to
the per-sample loop (statuses, predictions, theta after every sample, the final covariance), a
non-finite sample inside the arrays rejected exactly as in the loop, and bad arrays refused with
nothing changed."""

import threading
import time

import numpy as np
import pytest

import bonl
from conftest import known_models, random_levels

METHODS = ["output_error", "equation_error", "paper"]


def _record(model, seed):
    u = random_levels(1200, 5, 1.0, seed)
    y = model.simulate(u) + 0.01 * np.random.default_rng(seed + 1).standard_normal(u.size)
    u[250] = np.nan
    y[600] = np.inf
    return u, y


@pytest.mark.parametrize("method", METHODS)
def test_arrays_equal_the_per_sample_loop_bit_for_bit(known, method):
    _, model = known
    u, y = _record(model, 5)
    looped = bonl.Estimator(model, method=method)
    streamed = bonl.Estimator(model, method=method)
    statuses, predictions, thetas = [], [], []
    for a, b in zip(u, y):
        statuses.append(int(looped.update(float(a), float(b))))
        predictions.append(looped.last_prediction)
        thetas.append(looped.theta)
    results = streamed.update_record(u, y, prediction=True, theta=True)
    assert results.status.dtype == np.int8
    np.testing.assert_array_equal(results.status, statuses)
    np.testing.assert_array_equal(results.prediction, predictions)
    np.testing.assert_array_equal(results.theta, np.array(thetas))
    np.testing.assert_array_equal(streamed.covariance, looped.covariance)
    assert results.status[250] == int(bonl.UpdateStatus.rejected_non_finite)
    assert results.status[600] == int(bonl.UpdateStatus.rejected_non_finite)
    assert streamed.samples == looped.samples


def test_a_record_split_into_chunks_equals_it_in_one_call(known):
    _, model = known
    u, y = _record(model, 7)
    whole = bonl.Estimator(model)
    chunked = bonl.Estimator(model)
    status = whole.update_record(u, y).status
    parts = [chunked.update_record(u[a:a + 137], y[a:a + 137]).status for a in range(0, u.size, 137)]
    np.testing.assert_array_equal(np.concatenate(parts), status)
    np.testing.assert_array_equal(chunked.theta, whole.theta)


def test_only_the_statuses_unless_asked():
    model = bonl.Hammerstein(2, 1, 1, 2)
    results = bonl.Estimator(model).update_record(np.zeros(10), np.zeros(10))
    assert results.prediction is None and results.theta is None
    assert results.status.shape == (10,)


def test_other_real_dtypes_are_converted_and_0d_arrays_are_one_sample():
    model = bonl.ARX(2, 1, 0)
    u = random_levels(200, 4, 1.0, 2)
    y = bonl.ARX(2, 1, 0).simulate(u)
    as_float64 = bonl.Estimator(model)
    as_float32 = bonl.Estimator(model)
    as_float64.update_record(u.astype(np.float32).astype(np.float64), y.astype(np.float32).astype(np.float64))
    as_float32.update_record(u.astype(np.float32), y.astype(np.float32))
    np.testing.assert_array_equal(as_float32.theta, as_float64.theta)
    # In the data's units the first sample is taken at once (normalised, it is kept while the scale is measured).
    assert bonl.Estimator(model, normalise=False).update(np.array(0.5), np.array(0.1)) == bonl.UpdateStatus.updated


def test_update_takes_one_sample_and_update_record_a_record():
    # One return type per method: update an UpdateStatus, update_record an UpdateResults.
    estimator = bonl.Estimator(bonl.ARX(2, 1, 0))
    assert isinstance(estimator.update(0.5, 0.1), bonl.UpdateStatus)
    assert isinstance(estimator.update_record([0.5], [0.1]), bonl.UpdateResults)
    with pytest.raises(TypeError, match="incompatible function arguments"):
        estimator.update(np.zeros(3), np.zeros(3))
    with pytest.raises(ValueError, match="u must be a 1-D array of real numbers, got a single float"):
        estimator.update_record(0.5, 0.1)


@pytest.mark.parametrize("u, y, message", [
    (np.zeros(10), np.zeros(9), "u and y must have the same length (u has 10 samples, y 9)"),
    (np.zeros((5, 2)), np.zeros(5), "u must be 1-D"),
    (np.zeros(5), np.array(["a"] * 5), "y must be a 1-D array of real numbers"),
    (np.zeros(5, dtype=complex), np.zeros(5), "u must be real"),
])
def test_bad_arrays_are_refused_and_change_nothing(u, y, message):
    model = bonl.PseudoHammersteinWiener(2, 1, 1, 2)
    estimator = bonl.Estimator(model)
    estimator.update_record(np.linspace(-1, 1, 50), np.linspace(0, 1, 50))
    theta, covariance, samples = estimator.theta, estimator.covariance, estimator.samples
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        estimator.update_record(u, y)
    np.testing.assert_array_equal(estimator.theta, theta)
    np.testing.assert_array_equal(estimator.covariance, covariance)
    assert estimator.samples == samples


def test_the_gil_is_released_while_a_record_runs():
    # While one thread streams a long record, this thread keeps running Python. The longest pause
    # between its loop's iterations, counted from the moment the call starts, is a few switch
    # intervals (5 ms); were the GIL held by the call, it would be the whole call (checked with a
    # call that holds the GIL, a backtracking regular expression: 0.40 s of a 0.41 s call).
    model = known_models()["HammersteinWiener"]  # an output that moves: else the scale is never measured
    u = random_levels(400000, 5, 1.0, 1)
    y = model.simulate(u)
    estimator = bonl.Estimator(model, window=bonl.WindowRefinementOptions(enabled=False))  # the recursion: quicker
    started = threading.Event()
    times = {}

    def stream():
        times["start"] = time.perf_counter()
        started.set()
        estimator.update_record(u, y)
        times["end"] = time.perf_counter()

    thread = threading.Thread(target=stream)
    thread.start()
    started.wait()
    last, longest_pause = times["start"], 0.0
    while thread.is_alive():
        now = time.perf_counter()
        longest_pause, last = max(longest_pause, now - last), now
    thread.join()
    assert estimator.samples == u.size
    assert longest_pause < (times["end"] - times["start"]) / 3
