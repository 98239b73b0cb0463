"""bonl.experiment: the records' signal processing and the paper's experiment (run_paper_experiment and
its result classes). Models are keyed by their class names, from the result's model_names."""

import math

import numpy as np
import pytest

import bonl
from bonl import experiment

#: The experiment's models, by their one name: the classes of bonl.MODELS the paper covers.
MODEL_KEYS = {"ARX", "Hammerstein", "HammersteinWiener", "PrandtlIshlinskiiHammerstein", "PseudoHammersteinWiener"}


def test_low_pass_and_differentiate_follow_plant_md():
    rng = np.random.default_rng(3)
    x = rng.normal(size=200)
    ts, fc = 0.01, 10.0
    alpha = 1 - math.exp(-2 * math.pi * fc * ts)
    z = np.empty_like(x)
    z[0] = x[0]
    for k in range(1, len(x)):
        z[k] = z[k - 1] + alpha * (x[k] - z[k - 1])
    np.testing.assert_allclose(experiment.low_pass(x, fc, ts), z, rtol=1e-13, atol=1e-15)
    np.testing.assert_allclose(experiment.differentiate(x, ts), np.gradient(x, ts), rtol=1e-12, atol=1e-12)
    with pytest.raises(ValueError, match="x"):
        experiment.low_pass(np.ones((3, 3)), fc, ts)
    with pytest.raises(ValueError, match="x"):
        experiment.differentiate([1.0, float("inf"), 2.0], ts)
    with pytest.raises(ValueError, match="cutoff_hz"):
        experiment.low_pass(x, 0.0, ts)


@pytest.fixture(scope="module")
def result():
    return experiment.run_paper_experiment()


def test_experiment_returns_both_methods_models_and_records(result):
    e = result
    assert set(e.model_names) == MODEL_KEYS
    assert set(e.methods) == {"output_error", "paper"}
    for method in ("output_error", "paper"):
        entry = e.method(method)
        assert entry.method == method and e.methods[method].method == method
        assert set(entry.mse) == MODEL_KEYS and set(entry.models) == MODEL_KEYS
        assert all(0 < v < 1e-2 for v in entry.mse.values())
        assert all(m.model is not None for m in entry.models.values())
        # Each model is its bonl class, with the parameters Table 1 shows.
        for name, m in entry.models.items():
            assert type(m.model).__name__ == name and m.name == name
            np.testing.assert_array_equal(np.asarray(m.params["b"]), m.model.b)
        proposed = entry.models["PseudoHammersteinWiener"]
        assert len(proposed.params["f"]) == 4 and isinstance(proposed.params["c"], float)
        assert proposed.label == "P-H-W" and ("c", proposed.params["c"]) in proposed.parameters
    n = 5001
    for name in ("identification", "validation"):
        record = getattr(e, name)
        for key in ("time", "input", "velocity", "true_velocity", "angle"):
            assert getattr(record, key).shape == (n,) and getattr(record, key).dtype == np.float64
        assert not record.reached_end_stop
    for method in ("output_error", "paper"):
        for key, m in e.method(method).models.items():
            assert m.simulated.shape == (n,)
            mse = np.mean((e.validation.velocity - m.simulated) ** 2)
            assert mse == pytest.approx(e.method(method).mse[key], rel=1e-9)
            assert m.mse == e.method(method).mse[key] and m.online_mse == e.method(method).online_mse[key]
    # The README's numbers with bonl's estimator: P-H-W beats every other model.
    d = e.method("output_error").mse
    assert d["PseudoHammersteinWiener"] < min(v for k, v in d.items() if k != "PseudoHammersteinWiener")
    # The plays' thresholds: the data rule over the identification input, i / (np + 1) of its half-range.
    half_range = (e.identification.input.max() - e.identification.input.min()) / 2
    for method in ("output_error", "paper"):
        plays = e.method(method).models["PrandtlIshlinskiiHammerstein"]
        np_ = len(plays.params["g"])
        np.testing.assert_allclose(plays.params["thresholds"], half_range * np.arange(1, np_ + 1) / (np_ + 1), rtol=1e-15)
        np.testing.assert_array_equal(plays.online_model.thresholds, plays.model.thresholds)
        assert plays.label == "P-I-H"
    assert e.robustness_trajectories == 0 and all(m.robustness_mse == [] for m in e.method("paper").models.values())
    assert isinstance(e.seconds, bonl.experiment.Timings)
    assert list(e.seconds.to_dict()) == ["plant", "identification", "robustness"] and e.seconds.robustness == 0.0
    assert isinstance(e.parameters, bonl.plant.Parameters)


def test_experiment_bad_method(result):
    with pytest.raises(ValueError, match="method"):
        result.method("mrlsa")
    with pytest.raises(ValueError) as info:
        result.method("ours")
    assert "bonl: method must be 'output_error' or 'paper', got 'ours'" in str(info.value)


def test_published_scores_are_the_papers_table_2():
    assert experiment.published_score("PseudoHammersteinWiener") == (0.0289, 0)
    assert experiment.published_score("ARX") == (0.1136, 75)
    assert experiment.published_score("Wiener") is None
    assert experiment.published_score("PrandtlIshlinskiiHammerstein") is None
