"""bonl.control: the inverse models from Python, against scipy.signal.lfilter for the linear inverses
and against the models' own simulation (model.simulate(commands(r)) == r) for the others; bad input is
a ValueError with the inverse untouched (docs/reference/bad_input.md, C rows)."""

import numpy as np
import pytest
from scipy import signal

import bonl
from bonl.control import InverseModel, InverseStatus
from conftest import known_models

SMALL = known_models("small")


def smooth_command(n, offset=0.2, amplitude=0.5):
    """0 at the start, rising smoothly over 100 samples to a slow sum of sines about `offset`."""
    k = np.arange(n, dtype=float)
    ramp = np.where(k < 100, 0.5 - 0.5 * np.cos(np.pi * k / 100), 1.0)
    return ramp * (offset + amplitude * (np.sin(2 * np.pi * k / 250) + 0.3 * np.sin(2 * np.pi * k / 97 + 1.0)))


def test_arx_inverse_is_a_over_b_as_lfilter():
    model = SMALL["ARX"]
    nk = model.nk
    r = np.r_[np.zeros(10), np.sin(np.arange(490) / 15.0)]
    run = InverseModel(model).commands(r)
    b = model.params["b"]
    a = np.r_[1.0, model.params["a"]]
    ahead = np.r_[r[nk:], np.full(nk, r[-1])]  # r(k + nk), held at the end
    np.testing.assert_allclose(run.command, signal.lfilter(a, b, ahead), rtol=0, atol=1e-12)
    assert not run.status.any()
    np.testing.assert_allclose(model.simulate(run.command)[nk:], r[nk:], rtol=0, atol=1e-12)


def test_zpetc_against_lfilter_and_its_zero_phase_response():
    model = bonl.ARX(2, 2, 3, b=[0.05, 0.085, -0.03], a=[-1.2, 0.35])  # B = 0.05 (1 + 2q^-1)(1 - 0.3q^-1)
    inverse = InverseModel(model)
    assert not inverse.minimum_phase
    assert (inverse.preview, inverse.window_size) == (4, 2)
    np.testing.assert_allclose(inverse.unstable_factor, [1.0, 2.0], atol=1e-12)
    np.testing.assert_allclose(inverse.stable_factor, [0.05, -0.015], atol=1e-12)
    r = np.r_[np.zeros(10), np.sin(np.arange(490) / 15.0)]
    run = inverse.commands(r)
    # u = A B_u* / (B_a B_u(1)^2) r(k + nk + s), B_u* = [2, 1]
    numerator = np.convolve([1.0, -1.2, 0.35], [2.0, 1.0]) / 9.0
    ahead = np.r_[r[4:], np.full(4, r[-1])]
    np.testing.assert_allclose(run.command, signal.lfilter(numerator, [0.05, -0.015], ahead), rtol=0, atol=1e-10)
    # y(k) = (2 r(k+1) + 5 r(k) + 2 r(k-1)) / 9: zero phase, unit gain at frequency 0
    y = model.simulate(run.command)
    filtered = signal.lfilter([2.0, 5.0, 2.0], [9.0], r)  # (2 r(j) + 5 r(j-1) + 2 r(j-2)) / 9 at j = k + 1
    np.testing.assert_allclose(y[3:-5], filtered[4:-4], rtol=0, atol=1e-10)


@pytest.mark.parametrize("name", ["Hammerstein", "HammersteinWiener", "PseudoHammersteinWiener", "Wiener",
                                  "PrandtlIshlinskiiHammerstein"])
def test_block_models_follow_a_reachable_reference(name):
    model = SMALL[name]
    r = model.simulate(smooth_command(1500))
    kwargs = {} if name == "Wiener" else {"command_min": -3.0, "command_max": 3.0}
    inverse = InverseModel(model, **kwargs)
    run = inverse.commands(r)
    settle = 10 if name == "PseudoHammersteinWiener" else 0  # from rest inside the backlash's gap
    assert not run.status[settle:-inverse.preview].any()
    y = model.simulate(run.command)
    assert np.max(np.abs(y - r)[model.nk + settle:]) <= 1e-9


def test_c3_c4_c5_step_equals_commands_and_raises_for_bad_input():
    model = SMALL["Hammerstein"]
    r = model.simulate(smooth_command(300))
    inverse = InverseModel(model, command_min=-1.0, command_max=1.0)
    run = inverse.commands(r)
    nk = model.nk
    steps = [inverse.step(r[min(k + nk, len(r) - 1)]) for k in range(50)]
    np.testing.assert_array_equal([s.value for s in steps], run.command[:50])
    assert all(s.status == int(InverseStatus.exact) for s in steps)
    # C3, C4: a non-finite reference or a short window raises, the state untouched
    with pytest.raises(ValueError, match="reference must be finite"):
        inverse.step(float("nan"))
    with pytest.raises(ValueError, match="reference window needs 1 samples"):
        inverse.step(np.zeros(0))
    assert inverse.step(r[50 + nk]).value == run.command[50]
    with pytest.raises(ValueError, match="reference has a non-finite value at index 3"):
        inverse.commands(np.r_[0.0, 0.0, 0.0, np.inf, np.zeros(10)])
    with pytest.raises(ValueError, match="longer than the inverse's preview"):
        inverse.commands(np.zeros(2))
    with pytest.raises(ValueError, match="reference must be a 1-D array"):
        inverse.commands("no")


def test_c1_c2_models_without_an_inverse_and_bad_options():
    with pytest.raises(ValueError, match="needs a finite command range"):
        InverseModel(SMALL["Hammerstein"])
    with pytest.raises(ValueError, match="contain the operating point"):
        InverseModel(SMALL["Hammerstein"], command_min=0.5, command_max=1.0)
    with pytest.raises(ValueError, match="b_0 .B's leading coefficient. is 0"):
        InverseModel(bonl.ARX(2, 1, 1, b=[0.0, 1.0], a=[-0.5, 0.1]))
    with pytest.raises(ValueError, match="zero at z = 1"):
        InverseModel(bonl.ARX(2, 1, 1, b=[1.0, -1.0], a=[-0.5, 0.1]))
    with pytest.raises(ValueError, match="transition band must be finite and >= 0"):
        InverseModel(SMALL["PseudoHammersteinWiener"], command_min=-1.0, command_max=1.0, backlash_band=-1.0)


def test_saturation_and_dead_band_are_reported():
    model = SMALL["Hammerstein"]
    inverse = InverseModel(model, command_min=-1.0, command_max=1.0)
    run = inverse.commands(3.0 * model.simulate(smooth_command(600)))
    assert (run.status & int(InverseStatus.saturated)).any()
    assert run.command.min() >= -1.0 and run.command.max() <= 1.0
    run = inverse.commands(np.r_[0.0, 0.0, np.full(200, 0.05)])  # w = 0.0054 in the dead band (0, f_0 = 0.01)
    assert (run.status == int(InverseStatus.dead_band)).any()
    assert (run.command[run.status == int(InverseStatus.dead_band)] == 0.0).all()


def test_input_range_is_the_default_command_range():
    model = SMALL["Hammerstein"]
    u = smooth_command(800)
    model.input_range = (-1.0, 1.0)
    inverse = InverseModel(model)
    assert (inverse.command_min, inverse.command_max) == (-1.0, 1.0)
    run = inverse.commands(model.simulate(u))
    np.testing.assert_allclose(run.command[: -model.nk], u[: -model.nk], rtol=0, atol=1e-9)


def test_the_adaptive_inverse_learns_a_known_system_and_keeps_its_inverse_when_not_trusted():
    """bonl.control.AdaptiveInverse against the known system (the oracle): started with the input
    polynomial 50% too large, fed the system's noise-free response, its inverse makes the system follow
    a reference; a guard that trusts nothing keeps the first inverse; bad input is refused."""
    truth = SMALL["Hammerstein"]
    params = truth.params
    wrong = bonl.Hammerstein(*truth.orders, b=params["b"], a=params["a"], f=1.5 * params["f"], p=1.5 * params["p"])
    adaptive = bonl.control.AdaptiveInverse(wrong, command_min=-3.0, command_max=3.0, method="equation_error", p0=1.0,
                                            forgetting=0.995)
    rng = np.random.default_rng(5)
    u = np.repeat(rng.uniform(-1, 1, 1200), 5)
    y = truth.simulate(u)
    for uk, yk in zip(u, y):
        adaptive.update(uk, yk)
    assert adaptive.health.rederivations == 60
    reference = truth.simulate(np.sin(np.arange(2000) / 60.0) * 0.5)
    commands = bonl.control.InverseModel(adaptive.model, command_min=-3.0, command_max=3.0).commands(reference).command
    assert np.max(np.abs(truth.simulate(commands)[200:] - reference[200:])) < 1e-4
    np.testing.assert_allclose(adaptive.estimate.theta, adaptive.model.theta, atol=1e-3)

    strict = bonl.control.AdaptiveInverse(truth, command_min=-3.0, command_max=3.0, stability_radius=0.1)
    for uk, yk in zip(u[:300], y[:300]):
        strict.update(uk, yk)
    assert strict.health.refused_unstable == 3 and strict.health.rederivations == 0
    assert "a pole of the estimate has magnitude" in strict.health.last_refusal
    np.testing.assert_array_equal(strict.model.theta, truth.theta)
    assert strict.update(float("nan"), 1.0) == bonl.UpdateStatus.rejected_non_finite
    with pytest.raises(ValueError, match="rederive_every must be >= 1"):
        bonl.control.AdaptiveInverse(truth, command_min=-3.0, command_max=3.0, rederive_every=0)
    with pytest.raises(ValueError, match="reference must be finite"):
        strict.step(float("inf"))


def test_a_reference_that_overflows_the_arithmetic_is_refused():
    model = SMALL["ARX"]
    inverse = InverseModel(model)
    twin = InverseModel(model)
    for r in np.linspace(0, 0.3, 10):
        assert inverse.step(r).value == twin.step(r).value
    with pytest.raises(ValueError, match="the reference is too large: the inverse's arithmetic overflowed"):
        inverse.step(-np.finfo(float).max)
    for r in np.linspace(0.3, 0, 10):
        assert inverse.step(r).value == twin.step(r).value
    assert int(InverseStatus.rejected_overflow) == 32
