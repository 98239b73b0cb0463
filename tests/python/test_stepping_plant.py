"""bonl.plant.SteppingPlant, Measurement and SteppingEnv: the plant one sample per call, against
bonl.plant.simulate (the same samples for the same commands, held over each sample; sensor noise
included), reset, refused commands that leave the plant as it was, and the gymnasium-style wrapper.
Bad input: test_bad_input.py (P22-P26)."""

import math

import numpy as np
import pytest

from bonl import plant
from bonl.plant import excitation

FIELDS = [
    "time", "measured_angle", "position", "velocity", "head_pressure", "rod_pressure", "spool", "pilot",
    "head_flow", "rod_flow", "joint_angle", "joint_rate", "pin_angle",
]  # fmt: skip


def paper_commands(n, rate):
    """The paper's multi-sine at t_k = k / rate (the times simulate reads its command at)."""
    return excitation.paper_multisine().sample(np.arange(n) / rate)


def worst_difference(stepping, commands, run):
    """Steps through `commands`; the worst of |a - b| / max(1, |b|) against simulate's samples over
    every field (the pilot against simulate's pilot one sample earlier: the pilot after the command
    held over the step)."""
    measurements = [stepping.measurement] + [stepping.step(c) for c in commands]
    worst = 0.0
    for name in FIELDS:
        got = np.array([getattr(m, name) for m in measurements])
        expected = getattr(run, name)
        if name == "pilot":
            got, expected = got[1:], expected[:-1]
        worst = max(worst, np.max(np.abs(got - expected) / np.maximum(1.0, np.abs(expected))))
    return worst


def same(a, b):
    return a.to_dict() == b.to_dict()


SHORT = paper_commands(150, 100.0)


@pytest.mark.parametrize("sensor_noise", [False, True])
def test_stepping_equals_simulate_on_the_paper_multisine_held_at_100_hz(sensor_noise):
    commands = paper_commands(5000, 100.0)
    run = plant.simulate((commands, 0.01), duration=50.0, sensor_noise=sensor_noise)
    stepping = plant.SteppingPlant(sensor_noise=sensor_noise)
    assert worst_difference(stepping, commands, run) <= 1e-12
    assert stepping.time == 50.0
    assert stepping.steps == run.steps
    noise = run.measured_angle - run.pin_angle
    assert (np.std(noise) == pytest.approx(plant.Parameters().sensor_noise, rel=0.05)) if sensor_noise else not noise.any()


def test_stepping_equals_simulate_on_the_paper_multisine_on_the_command_grid():
    commands = paper_commands(5000, 1000.0)
    run = plant.simulate(excitation.paper_multisine(), duration=5.0, sample_time=0.001)
    assert worst_difference(plant.SteppingPlant(sample_time=0.001), commands, run) <= 1e-12
    np.testing.assert_array_equal(run.command[:-1], commands)


def test_stepping_equals_simulate_with_a_python_load_that_changes_within_a_sample():
    def load(t):
        return 0.0 if t < 0.125 else 3e4 + 1e5 * max(t - 0.5, 0.0)

    run = plant.simulate((SHORT, 0.01), duration=1.5, load=load)
    assert worst_difference(plant.SteppingPlant(load=load), SHORT, run) <= 1e-12
    free = plant.simulate((SHORT, 0.01), duration=1.5)
    assert abs(free.position[-1] - run.position[-1]) > 1e-3  # the load acts


def test_measurement_fields_repr_and_copies():
    stepping = plant.SteppingPlant(initial_position=0.3, sensor_noise=False)
    start = stepping.measurement
    assert list(start.to_dict()) == FIELDS + ["reached_end_stop"]
    assert start.time == 0.0 and start.position == 0.3 and start.pilot == 0.0
    np.testing.assert_array_equal(
        [start.position, start.velocity, start.head_pressure, start.rod_pressure, start.spool],
        plant.initial_state(None, 0.3))
    assert start.measured_angle == start.pin_angle == start.joint_angle == plant.Parameters().joint_angle(0.3)
    assert repr(start).startswith("Measurement(time=0, measured_angle=")
    stepped = stepping.step(3.0)
    assert start.time == 0.0  # a measurement is a copy, not a view of the plant
    assert stepped.time == stepping.time == pytest.approx(0.01, abs=0.0)
    assert same(stepping.measurement, stepped)
    assert stepping.sample_time == 0.01 and stepping.parameters == plant.Parameters()
    assert repr(stepping) == "SteppingPlant(time=0.01, sample_time=0.01)"
    with pytest.raises(AttributeError):
        stepped.position = 1.0


def test_reset_replays_the_same_measurements_and_takes_a_position_and_seed():
    stepping = plant.SteppingPlant()
    first = [stepping.step(c) for c in SHORT]
    assert same(stepping.reset(), plant.SteppingPlant().measurement)
    assert all(same(stepping.step(c), m) for c, m in zip(SHORT, first))
    start = stepping.reset(initial_position=0.4, noise_seed=7)
    fresh = plant.SteppingPlant(initial_position=0.4, noise_seed=7)
    assert same(start, fresh.measurement) and start.position == 0.4
    assert all(same(stepping.step(c), fresh.step(c)) for c in SHORT[:50])
    again = plant.SteppingPlant(initial_position=0.4, noise_seed=7)
    assert same(stepping.reset(), again.measurement)  # reset() keeps the last position and seed
    assert same(stepping.reset(noise_seed=7), again.measurement)


def test_a_refused_command_leaves_the_plant_as_it_was():
    stepping, twin = plant.SteppingPlant(), plant.SteppingPlant()
    for c in SHORT[:40]:
        stepping.step(c)
        twin.step(c)
    before = stepping.measurement
    for bad in [math.nan, math.inf, "2.5", None, 2.5j, [2.5]]:
        with pytest.raises(ValueError, match="command must be"):
            stepping.step(bad)
    assert same(stepping.measurement, before)
    assert all(same(stepping.step(c), twin.step(c)) for c in SHORT[40:80])


def test_accepted_command_types_give_the_float_result():
    results = []
    for command in [3, 3.0, np.float32(3.0), np.array(3.0), np.int64(3), True * 3]:
        results.append(plant.SteppingPlant().step(command))
    assert all(same(r, results[0]) for r in results)


def test_a_load_that_raises_propagates_and_leaves_the_plant_as_it_was():
    calls = {"n": 0}

    def glitching(t):
        if t >= 0.204 and calls["n"] == 0:
            calls["n"] += 1
            raise KeyError("glitch")
        return 1e4 * math.sin(3.0 * t)

    stepping = plant.SteppingPlant(load=glitching)
    twin = plant.SteppingPlant(load=lambda t: 1e4 * math.sin(3.0 * t))
    assert all(same(stepping.step(c), twin.step(c)) for c in SHORT[:20])
    before = stepping.measurement
    with pytest.raises(KeyError, match="glitch"):
        stepping.step(SHORT[20])
    assert same(stepping.measurement, before)
    assert all(same(stepping.step(c), twin.step(c)) for c in SHORT[20:40])


def test_stepping_env_is_a_thin_gymnasium_style_wrapper():
    env = plant.SteppingEnv(sample_time=0.01)
    reference = plant.SteppingPlant(noise_seed=5, initial_position=0.6)
    observation, info = env.reset(seed=5, options={"initial_position": 0.6})
    assert observation.shape == (1,) and observation.dtype == np.float64
    assert observation[0] == info["measured_angle"] == reference.measurement.measured_angle
    for k, command in enumerate(SHORT[:20]):
        action = np.array([command]) if k % 2 else command
        observation, reward, terminated, truncated, info = env.step(action)
        expected = reference.step(command)
        assert info == expected.to_dict()
        assert observation[0] == expected.measured_angle
        assert (reward, terminated, truncated) == (0.0, False, False)
    # A full command drives the piston into the end stop: terminated.
    env.reset()
    assert any(env.step(5.0)[2] for _ in range(300))


def test_set_parameters_at_the_start_equals_a_plant_built_with_them_and_keeps_the_state_mid_run():
    changed = plant.Parameters(bulk_modulus=0.7e9, pilot_hysteresis=0.1)
    commands = paper_commands(150, 100.0)
    stepping = plant.SteppingPlant()
    stepping.set_parameters(changed)
    built = plant.SteppingPlant(changed)
    got = [stepping.step(c).joint_angle for c in commands]
    expected = [built.step(c).joint_angle for c in commands]
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12)
    assert stepping.parameters == changed

    # Mid-run: the state carries over; the changed plant then leaves the unchanged one.
    stepping, unchanged = plant.SteppingPlant(), plant.SteppingPlant()
    for c in commands[:100]:
        stepping.step(c), unchanged.step(c)
    before = stepping.measurement.to_dict()
    stepping.set_parameters(changed)
    assert stepping.measurement.to_dict() == before
    gap = max(abs(stepping.step(c).joint_angle - unchanged.step(c).joint_angle) for c in commands[100:])
    assert gap > 1e-4
