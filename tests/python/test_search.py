"""The structure search (bonl.search, python/bonl/structure_search.py).
Oracles: known systems whose structure the search must find from their records alone (their fresh
records simulated to the noise); the delay and the placement rules computed by hand; a structure
that diverges beyond the measured inputs never chosen."""

import math

import numpy as np
import pytest

import bonl
from bonl import structure_search
from conftest import known_models, random_levels


def _record(model, n, seed, noise=0.0):
    u = random_levels(n, 5, 1.0, seed)
    y = model.simulate(u)
    return u, y + noise * np.std(y) * np.random.default_rng(seed + 100).standard_normal(n)


@pytest.mark.parametrize("name, tolerance", [("Hammerstein", 1e-3), ("PseudoHammersteinWiener", 1e-3),
                                             ("NonlinearFeedback", 0.02)])
def test_the_search_finds_a_known_system_from_its_records_alone(name, tolerance):
    """Noise-free: the structure's own family to rounding; the nonlinear-feedback system has knots at
    +-0.5, which the search places by its rule instead (place_from_data), so to the hinges' misfit.
    A linear model is ten times further off or more."""
    truth = known_models("small")[name]
    u, y = _record(truth, 1500, 1)
    found = bonl.search(u, y, budget=120)
    fresh, clean = _record(truth, 1500, 2)
    error = np.sqrt(np.mean((found.best.simulate(fresh) - clean) ** 2)) / np.std(clean)
    linear = np.sqrt(np.mean((found.linear.simulate(fresh) - clean) ** 2)) / np.std(clean)
    assert error < tolerance and 10 * error < linear
    assert found.held_out == "5-fold blocked cross-validation"
    assert [stage.name for stage in found.stages][-1] == "choice"
    assert all(row.score <= later.score for row, later in zip(found.table, found.table[1:]))


def test_the_choice_is_the_fewest_parameters_within_the_tolerance_of_the_best():
    truth = known_models("small")["Wiener"]
    u, y = _record(truth, 800, 3, noise=0.02)
    found = bonl.search(u, y, budget=60, families=1)
    scored = [row for row in found.table if math.isfinite(row.score)]
    best = scored[0].score
    near = [row for row in scored if row.score <= best * 1.01 ** 2]
    assert found.best.num_params == min(row.num_params for row in near)
    assert found.held_out_rms == pytest.approx(math.sqrt(min(r.score for r in near if r.num_params ==
                                                             found.best.num_params)), rel=1e-12)


def test_the_delay_is_the_first_significant_tap_no_later_than_the_rise():
    for nk in (0, 3, 7):
        truth = bonl.ARX(2, 1, nk, b=[0.4, 0.2], a=[-1.2, 0.4])
        u, y = _record(truth, 3000, 4, noise=0.01)
        assert structure_search._delay([(u, y)]) == nk
    # White noise alone: nothing significant, delay 0.
    rng = np.random.default_rng(5)
    assert structure_search._delay([(rng.standard_normal(3000), rng.standard_normal(3000))]) == 0


def test_knots_and_thresholds_are_placed_from_the_records_by_the_rule():
    u = random_levels(1000, 5, 1.0, 6)
    y = np.cumsum(u) * 0.01 + 0.5
    # The velocity: each 21 samples' straight-line fit by least squares (np.polyfit), the slope.
    span = structure_search.VELOCITY_SPAN
    sigma_v = np.std([np.polyfit(np.arange(span), y[k:k + span], 1)[0] for k in range(y.size - span + 1)])
    friction = bonl.place_from_data(bonl.NonlinearFeedback(1, 0, 1, 1, 4, 1, 1, 0, 1), [(u, y)])
    np.testing.assert_allclose(friction.knots, sigma_v * np.array([-1.0, -0.25, 0.25, 1.0]))
    sigma_y = np.std(y - 0.5)
    plays = bonl.place_from_data(bonl.NonlinearFeedback(1, 0, 1, 1, 0, 1, 0, 3), [(u, y)], y0=0.5)
    np.testing.assert_allclose(plays.thresholds, sigma_y * np.array([0.25, 0.5, 0.75]))
    three = bonl.place_from_data(bonl.NonlinearFeedback(1, 0, 1, 1, 3, 1, 1), [(u, y)])
    np.testing.assert_allclose(three.knots, sigma_v * np.array([-0.25, 0.25, 1.0]))
    other = bonl.Hammerstein(2, 1, 1, 2)
    assert bonl.place_from_data(other, [(u, y)]) is other


def test_only_an_integrators_folds_are_also_scored_with_their_state_estimated():
    """Under cross-validation every candidate with ni = 1, and no other, is scored with the folds' state
    measured and estimated; under the last quarter's scheme none is estimated."""
    truth = bonl.ARX(1, 0, 1, 1, b=[0.05], a=[-0.6])  # an integrator behind a first-order lag
    u, y = _record(truth, 1200, 9, noise=0.02)
    found = bonl.search(u, y, budget=60, families=2)
    rows = list(zip(found.table, found.settings))
    assert all(row.orders.get("ni", 0) == 1 for row, setting in rows if "fold_initial_state" in setting)
    assert any(setting.get("fold_initial_state") == "estimated" for _, setting in rows)
    scored = {(row.name, tuple(row.orders.items()), setting.get("fold_initial_state", "measured"))
              for row, setting in rows if row.orders.get("ni", 0) == 1}
    assert any((name, orders, "estimated") in scored for name, orders, state in scored if state == "measured")
    assert "fold_initial_state" not in found.setting  # the refit keeps identify's own state
    assert structure_search._fold_states(bonl.ARX(1, 0, 1, 1), False) == ("measured",)
    assert structure_search._fold_states(bonl.ARX(1, 0, 1, 0), True) == ("measured",)


def test_the_scheme_is_cross_validation_on_short_records_and_the_last_quarter_on_long_ones():
    short, medium, long = ([(np.zeros(n), np.zeros(n))] for n in (10_000, 30_000, 30_001))
    assert structure_search.scoring_scheme(short) == {"criterion": "cross_validation", "folds": 5}
    assert structure_search.scoring_scheme(medium) == {"criterion": "cross_validation", "folds": 3}
    assert structure_search.scoring_scheme(long) == {"criterion": "validation"}


def test_the_search_never_chooses_a_model_whose_free_run_diverges():
    """A softening feedback (bounded for |u| <= 1, diverging 1.25 times beyond, tests/cpp/select.test.cpp):
    every model the search returns runs bounded on the records' inputs stretched 1.25 times."""
    truth = bonl.NonlinearFeedback(1, 0, 1, 3, 0, 1, 0, b=[0.17], a=[-0.5], f=[0.0, 0.5])
    u, y = _record(truth, 1200, 7)
    found = bonl.search(u, y, budget=60)
    assert np.all(np.isfinite(found.best.simulate(1.25 * u)))


@pytest.mark.parametrize("call, message", [
    (lambda u, y: bonl.search(u), "give u and y for one record"),
    (lambda u, y: bonl.search(u, y, records=[(u, y)]), "not both"),
    (lambda u, y: bonl.search(u, y, budget=0), "budget must be a number of seconds > 0"),
    (lambda u, y: bonl.search(u, y, tolerance=1.5), r"tolerance must be in \[0, 1\)"),
    (lambda u, y: bonl.search(u, y, families=0), "families must be an integer >= 1"),
    (lambda u, y: bonl.search(u, y, operating_points=("median",)), "operating_points must be some of"),
    (lambda u, y: bonl.search(u, y, window=-1), "window must be an integer >= 0"),
    (lambda u, y: bonl.search(u, y[:10]), "must have the same length"),
    (lambda u, y: bonl.search(u, y, method="best"), "method must be"),
], ids=["no y", "both", "budget", "tolerance", "families", "operating point", "window", "lengths", "option"])
def test_bad_input_is_a_value_error(call, message):
    u, y = _record(known_models("small")["ARX"], 200, 8)
    with pytest.raises(ValueError, match=message):
        call(u, y)
