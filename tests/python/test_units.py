"""Units and stability (issue 18): Model.rescaled, identify's own units (normalise), Model.pole_radius.

Oracles: the rescaled model's simulation against the scaled original's; identify on data multiplied by
powers of two against the rescaled identification of the original data (exact: both run in the same
internal units); the poles of a denominator built from known poles."""

import numpy as np
import pytest

import bonl
from conftest import known_models, random_levels

SMALL = known_models("small")


@pytest.mark.parametrize("name", sorted(SMALL))
def test_a_rescaled_model_simulates_the_scaled_model(name):
    model = SMALL[name]
    u = random_levels(400, 5, 1.0, 21)
    scaled = model.rescaled(200.0, 1e-3)
    np.testing.assert_allclose(scaled.simulate(200.0 * u), 1e-3 * model.simulate(u), rtol=1e-12, atol=1e-18)
    with pytest.raises(ValueError, match="input_scale must be finite and > 0"):
        model.rescaled(0.0, 1.0)


@pytest.mark.parametrize("name", sorted(SMALL))
def test_identify_is_exact_under_power_of_two_units(name):
    truth = SMALL[name]
    u = random_levels(1500, 5, 1.0, 22)
    y = truth.simulate(u) + 0.01 * np.random.default_rng(23).standard_normal(u.size)
    su, sy = 256.0, 1.0 / 1024.0
    original = bonl.identify(truth, u, y)
    # P-H-W's c0, the initial backlash width, is in the output's units; so is the structure's (its knots).
    settings = dict(c0=0.01 * sy) if name == "PseudoHammersteinWiener" else {}
    scaled = bonl.identify(truth.rescaled(su, sy), su * u, sy * y, **settings)
    np.testing.assert_array_equal(scaled.theta, original.rescaled(su, sy).theta)


@pytest.mark.parametrize("name", sorted(SMALL))
def test_data_in_newtons_and_metres_identify_with_the_defaults(name):
    """Input ~200 (a force in N), output ~1e-3 (a displacement in m), as the Bouc-Wen benchmark."""
    truth = SMALL[name]
    u = random_levels(3000, 5, 1.0, 24)
    y = truth.simulate(u) + 0.005 * np.random.default_rng(25).standard_normal(u.size)
    u_val = random_levels(2000, 5, 1.0, 26)
    model = bonl.identify(truth.rescaled(200.0, 1e-3), 200.0 * u, 1e-3 * y)  # the structure's knots in those units
    reference = truth.simulate(u_val)
    assert bonl.metrics.fit_percent(reference, model.simulate(200.0 * u_val) / 1e-3) >= 98.0
    assert model.pole_radius < 1.0


def test_pole_radius_is_the_largest_pole_magnitude():
    # (1 - 0.5 z^-1)(1 - 0.6 z^-1 + 0.73 z^-2): poles 0.5 and 0.3 +- 0.8j (|.| = 0.854).
    model = bonl.ARX(3, 0, 0, a=np.convolve([1.0, -0.5], [1.0, -0.6, 0.73])[1:])
    assert model.pole_radius == pytest.approx(np.hypot(0.3, 0.8), rel=1e-12)
