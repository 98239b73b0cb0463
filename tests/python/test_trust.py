"""Models that say where they can be trusted (issue 18): the input range identify records, the
ExtrapolationWarning of simulate outside it, the StabilityWarning of identify for a barely damped or
unstable model, the ExcitationWarning of identify for records that cannot excite the structure.
Oracles: the records' own min and max; a first-order system with a known pole; inputs whose distinct
values are known by construction, against the r + 1 points that fix a polynomial of degree r."""

import warnings

import numpy as np
import pytest

import bonl
from conftest import known_models, random_levels

SMALL = known_models("small")


@pytest.mark.parametrize("name", sorted(SMALL))
def test_identify_records_the_input_range_and_simulate_warns_outside_it(name):
    truth = SMALL[name]
    u1, u2 = random_levels(800, 5, 0.8, 61), random_levels(800, 5, 0.5, 62) + 0.6
    model = bonl.identify(truth, records=[(u1, truth.simulate(u1)), (u2, truth.simulate(u2))])
    assert model.input_range == (min(u1.min(), u2.min()), max(u1.max(), u2.max()))
    assert bonl.load_model(model.to_json()).input_range == model.input_range
    inside = random_levels(200, 5, 0.5, 63)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        model.simulate(inside)  # no warning
    outside = inside.copy()
    outside[[10, 20, 30]] = model.input_range[1] + 1.0
    with pytest.warns(bonl.ExtrapolationWarning, match="3 of 200 samples of u lie outside the input range"):
        model.simulate(outside)
    assert (model.extrapolated_samples(inside), model.extrapolated_samples(outside)) == (0, 3)
    assert issubclass(bonl.ExtrapolationWarning, UserWarning)


def test_identify_warns_for_a_barely_damped_model():
    u = random_levels(2000, 5, 1.0, 64)
    y = np.zeros_like(u)
    for k in range(1, u.size):  # y(k) = 0.9995 y(k-1) + u(k-1): the pole at 0.9995
        y[k] = 0.9995 * y[k - 1] + u[k - 1]
    with pytest.warns(bonl.StabilityWarning, match="barely damped: its largest pole has magnitude 0.9995"):
        model = bonl.identify(bonl.ARX(1, 0, 1), u, y, method="equation_error", forgetting=1.0)
    assert model.pole_radius == pytest.approx(0.9995, abs=1e-6)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        bonl.identify(bonl.ARX(1, 0, 1), u, np.convolve(u, 0.5 ** np.arange(30))[: u.size])  # pole 0.5: no warning


def test_a_bad_input_range_is_a_value_error():
    model = SMALL["ARX"]
    with pytest.raises(ValueError, match="the input range must be min <= max"):
        model.input_range = (1.0, -1.0)
    with pytest.raises(ValueError, match="input_range must be a pair"):
        model.input_range = 1.0
    assert model.input_range == (-np.inf, np.inf)


@pytest.mark.parametrize("name", sorted(SMALL))
def test_identify_warns_that_a_constant_input_cannot_excite_the_structure(name):
    truth = SMALL[name]
    u = np.full(600, 0.5)
    # Two distinct values for every model; r + 1 on each side of zero for a two-segment input
    # polynomial (Hammerstein, H-W, P-H-W), r + 1 for the Prandtl-Ishlinskii model's one.
    two_segments = {"Hammerstein", "HammersteinWiener", "PseudoHammersteinWiener"}
    needed = 2 * (truth.r + 1) if name in two_segments else truth.r + 1 if name == "PrandtlIshlinskiiHammerstein" else 2
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bonl.StabilityWarning)
        with pytest.warns(bonl.ExcitationWarning) as caught:
            bonl.identify(truth, u, truth.simulate(u))
    assert [str(w.message) for w in caught if w.category is bonl.ExcitationWarning] == [
        f"the input takes 1 value (it is constant) but a {name} model needs at least {needed} to be determined: it "
        "cannot excite the structure, and the identified parameters are not fixed by the data"
    ]
    assert issubclass(bonl.ExcitationWarning, UserWarning)


def test_identify_warns_for_too_few_levels_over_several_records():
    truth = SMALL["Hammerstein"]  # r = 2: two segments of degree 2, three values on each side of zero
    u1, u2 = np.repeat([0.5, -0.5], 300), np.repeat([0.5, 1.0], 300)  # 3 distinct values together
    with pytest.warns(bonl.ExcitationWarning, match="the input takes 3 distinct values but a Hammerstein model needs at least 6"):
        bonl.identify(truth, records=[(u1, truth.simulate(u1)), (u2, truth.simulate(u2))])


@pytest.mark.parametrize("name", sorted(SMALL))
def test_an_exciting_record_gives_no_excitation_warning(name):
    truth = SMALL[name]
    u = random_levels(800, 5, 1.0, 65)
    with warnings.catch_warnings():
        warnings.simplefilter("error", bonl.ExcitationWarning)
        bonl.identify(truth, u, truth.simulate(u))
