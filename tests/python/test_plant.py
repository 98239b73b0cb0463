"""bonl.plant: parameters, excitation and simulate (the experiment on the plant: test_experiment.py).

The plant is checked against an independent integrator: its right-hand side written again below
straight from docs/explanation/plant.md (plain Python, not bonl's derivative), integrated with scipy's Radau
interval by interval on the 1 kHz command grid, with the pilot-stage play operator reproduced.
"""

import copy
import math
import pickle
import threading
import time

import numpy as np
import pytest

from bonl import plant
from bonl.plant import excitation

FIELDS = [
    "bore_diameter", "rod_diameter", "stroke", "dead_volume_head", "dead_volume_rod", "supply_pressure",
    "return_pressure", "bulk_modulus", "oil_density", "discharge_coefficient", "area_gradient", "spool_travel",
    "internal_leakage", "external_leakage", "orifice_smoothing", "valve_time_constant", "dead_band",
    "neutral_voltage", "max_voltage", "pilot_hysteresis", "mass", "gravity_moment", "gravity_angle_offset",
    "gravity", "coulomb_friction", "static_friction", "stribeck_velocity", "viscous_friction",
    "friction_smoothing", "end_stop_stiffness", "end_stop_damping", "pivot_to_rod_pin", "pivot_to_base_pin",
    "retracted_length", "joint_backlash", "sensor_noise",
]  # fmt: skip

TRAJECTORY_ARRAYS = [
    "time", "command", "input", "position", "velocity", "head_pressure", "rod_pressure", "spool", "pilot",
    "head_flow", "rod_flow", "joint_angle", "joint_rate", "pin_angle", "measured_angle",
]  # fmt: skip
TRAJECTORY_SCALARS = ["min_position", "max_position", "reached_end_stop", "steps"]


# --- Parameters ------------------------------------------------------------------------------


def test_parameters_every_member_is_a_read_write_property_with_symbol_and_unit():
    p = plant.Parameters()
    assert set(p.to_dict()) == set(FIELDS)
    for i, name in enumerate(FIELDS):
        value = 1.0 + 0.125 * i
        setattr(p, name, value)
        assert getattr(p, name) == value
        doc = getattr(plant.Parameters, name).__doc__
        assert "[" in doc and "]" in doc, name  # the unit
        assert name in plant.Parameters.__doc__
    assert p.to_dict() == {name: 1.0 + 0.125 * i for i, name in enumerate(FIELDS)}


def test_parameters_defaults_and_small_machine_follow_plant_md():
    p = plant.Parameters.excavator_20t()
    assert p == plant.Parameters()
    assert (p.bore_diameter, p.rod_diameter, p.stroke, p.mass) == (0.140, 0.100, 1.50, 1.44e4)
    assert p.head_area() == pytest.approx(math.pi * 0.140**2 / 4, rel=1e-15)
    assert p.annulus_area() == pytest.approx(math.pi * (0.140**2 - 0.100**2) / 4, rel=1e-15)
    assert p.valve_gain() == pytest.approx(1 / (2.5 - 0.08), rel=1e-15)
    assert p.flow_gain() == pytest.approx(0.61 * 1.08e-2 * 5e-3 * math.sqrt(2 / 870), rel=1e-15)
    assert p.joint_angle(0.75) == pytest.approx(0.0, abs=1e-15)
    s = plant.Parameters.excavator_5t()
    assert (s.bore_diameter, s.rod_diameter, s.stroke, s.mass, s.area_gradient) == (0.090, 0.060, 0.78, 3.6e3, 2.9e-3)
    s.validate()
    p.validate()


def test_parameters_keywords_copy_pickle_repr():
    p = plant.Parameters(pilot_hysteresis=0.02, mass=1e4)
    assert (p.pilot_hysteresis, p.mass) == (0.02, 1e4)
    assert repr(p) == "Parameters(pilot_hysteresis=0.02, mass=10000)"
    q = copy.copy(p)
    q.mass = 2e4
    assert p.mass == 1e4
    assert copy.deepcopy(p) == p
    assert pickle.loads(pickle.dumps(p)) == p
    assert p != plant.Parameters()
    with pytest.raises(TypeError, match="bore"):
        plant.Parameters(bore=0.1)


@pytest.mark.parametrize(
    "name, value",
    [
        ("bore_diameter", -0.1),
        ("rod_diameter", 0.2),  # >= bore
        ("mass", float("nan")),
        ("pilot_hysteresis", 1.0),
        ("supply_pressure", 0.1e6),  # < return pressure
        ("sensor_noise", -1e-4),
        ("stroke", 5.0),  # the linkage would not close
    ],
)
def test_parameters_validation_names_the_parameter(name, value):
    p = plant.Parameters()
    setattr(p, name, value)
    with pytest.raises(ValueError, match=name):
        p.validate()
    with pytest.raises(ValueError, match=name):
        plant.simulate(excitation.step(2.5), p, duration=0.1)


# --- Excitation ------------------------------------------------------------------------------


def paper_multisine_reference(t, amplitude=0.4, offset=2.5):
    """plant.md: tones 0.1, 0.2, 0.4, 0.5, 1 Hz, Schroeder phases phi_k = -pi k (k + 1) / n."""
    f = [0.1, 0.2, 0.4, 0.5, 1.0]
    n = len(f)
    return offset + amplitude * sum(math.sin(2 * math.pi * fk * t - math.pi * k * (k + 1) / n) for k, fk in enumerate(f, 1))


def test_excitation_values():
    t = np.linspace(-1.0, 20.0, 2101)
    step = excitation.step(3.0, t_step=1.0)
    assert step(0.999) == 2.5 and step(1.0) == 3.0
    np.testing.assert_array_equal(step.sample(t), np.where(t < 1.0, 2.5, 3.0))
    paper = excitation.paper_multisine()
    np.testing.assert_allclose(paper.sample(t), [paper_multisine_reference(x) for x in t], rtol=0, atol=1e-12)
    ms = excitation.multisine([0.3, 0.7], 0.2, offset=2.0, phases=[0.1, -0.4])
    np.testing.assert_allclose(
        ms.sample(t), 2.0 + 0.2 * (np.sin(2 * np.pi * 0.3 * t + 0.1) + np.sin(2 * np.pi * 0.7 * t - 0.4)), atol=1e-12
    )
    chirp = excitation.chirp(0.1, 2.0, 10.0, 0.5)
    inside = t[(t >= 0) & (t <= 10)]
    np.testing.assert_allclose(
        chirp.sample(inside), 2.5 + 0.5 * np.sin(2 * np.pi * (0.1 * inside + 1.9 * inside**2 / 20.0)), atol=1e-9
    )
    held = excitation.sampled([1.0, 2.0, 3.0], 0.5, t0=1.0)
    assert [held(x) for x in (0.0, 1.0, 1.49, 1.5, 2.0, 9.0)] == [1.0, 1.0, 1.0, 2.0, 3.0, 3.0]
    rnd = excitation.smooth_random(1.0, 0.3, 50.0, 7)
    grid = np.arange(0, 50.0, 0.005)
    assert np.sqrt(np.mean((rnd.sample(grid) - 2.5) ** 2)) == pytest.approx(0.3, rel=1e-9)
    assert "paper_multisine" in repr(paper)
    assert not paper.calls_python


def test_excitation_bad_arguments_are_value_errors_naming_them():
    with pytest.raises(ValueError, match="values"):
        excitation.sampled([1.0, float("nan")], 0.01)
    with pytest.raises(ValueError, match="values"):
        excitation.sampled(np.ones((2, 2)), 0.01)
    with pytest.raises(ValueError, match="values"):
        excitation.sampled([], 0.01)
    with pytest.raises(ValueError, match="ts"):
        excitation.sampled([1.0], 0.0)
    with pytest.raises(ValueError, match="frequencies_hz"):
        excitation.multisine([], 0.4)
    with pytest.raises(ValueError, match="phases"):
        excitation.multisine([0.1, 0.2], 0.4, phases=[0.0])
    with pytest.raises(ValueError, match="bandwidth_hz"):
        excitation.smooth_random(0.01, 0.3, 50.0, 1)
    with pytest.raises(ValueError, match="t"):
        excitation.step(3.0).sample([0.0, float("inf")])


def test_command_wraps_a_python_callable():
    cmd = plant.Command(lambda t: 2.5 + t)
    assert cmd.calls_python
    assert cmd(0.5) == 3.0
    np.testing.assert_array_equal(cmd.sample([0.0, 1.0]), [2.5, 3.5])


# --- simulate --------------------------------------------------------------------------------


def test_simulate_returns_a_trajectory_with_the_documented_fields_shapes_and_dtypes():
    run = plant.simulate(excitation.paper_multisine(), duration=2.0, sample_time=0.02)
    assert isinstance(run, plant.Trajectory) and len(run) == 101
    assert list(run.to_dict()) == TRAJECTORY_ARRAYS + TRAJECTORY_SCALARS
    for key in TRAJECTORY_ARRAYS:
        values = getattr(run, key)
        assert isinstance(values, np.ndarray) and values.dtype == np.float64 and values.shape == (101,), key
        assert np.all(np.isfinite(values)), key
        np.testing.assert_array_equal(run.to_dict()[key], values)
    np.testing.assert_allclose(run.time, 0.02 * np.arange(101), rtol=0, atol=1e-12)
    np.testing.assert_allclose(run.input, run.command - 2.5, atol=1e-15)
    np.testing.assert_allclose(run.command, [paper_multisine_reference(t) for t in run.time], atol=1e-12)
    assert isinstance(run.reached_end_stop, bool) and not run.reached_end_stop
    assert isinstance(run.steps, int) and run.steps > 0
    assert run.min_position <= run.position.min() and run.max_position >= run.position.max()
    assert run.position[0] == 0.75  # mid-stroke
    p = plant.Parameters.excavator_20t()
    np.testing.assert_allclose(run.joint_rate, run.velocity / [p.moment_arm(h) for h in run.position], rtol=1e-12)
    noisy = run.measured_angle - run.pin_angle
    assert 0.5e-4 < noisy.std() < 4e-4  # sigma_theta = 2e-4 rad
    quiet = plant.simulate(excitation.paper_multisine(), duration=2.0, sample_time=0.02, sensor_noise=False)
    np.testing.assert_array_equal(quiet.measured_angle, quiet.pin_angle)


def test_simulate_accepts_callables_and_sampled_sequences_alike():
    step = plant.simulate(excitation.step(2.9, t_step=0.2), duration=1.0)
    python = plant.simulate(lambda t: 2.9 if t >= 0.2 else 2.5, duration=1.0)
    values = np.where(np.arange(100) * 0.01 >= 0.2 - 1e-12, 2.9, 2.5)
    pair = plant.simulate((values, 0.01), duration=1.0)
    held = plant.simulate(excitation.sampled(values, 0.01), duration=1.0)
    for run in (python, pair, held):
        for key in TRAJECTORY_ARRAYS:
            np.testing.assert_array_equal(getattr(run, key), getattr(step, key), err_msg=key)
    assert step.velocity[-1] > 0.01  # 2.9 V extends


def test_simulate_load_and_initial_position():
    free = plant.simulate(excitation.step(3.5), duration=1.0, initial_position=0.3)
    loaded = plant.simulate(excitation.step(3.5), duration=1.0, initial_position=0.3, load=lambda t: 1e5)
    assert free.position[0] == loaded.position[0] == 0.3
    assert loaded.velocity[-1] < free.velocity[-1]


def test_simulate_bad_arguments():
    cmd = excitation.step(2.5)
    with pytest.raises(ValueError, match="duration"):
        plant.simulate(cmd, duration=-1.0)
    with pytest.raises(ValueError, match="sample_time"):
        plant.simulate(cmd, sample_time=0.0105)
    with pytest.raises(ValueError, match="initial_position"):
        plant.simulate(cmd, initial_position=float("nan"))
    with pytest.raises(ValueError, match="command is not finite"):
        plant.simulate(lambda t: float("nan"), duration=0.1)
    with pytest.raises(ZeroDivisionError):
        plant.simulate(lambda t: 1 / 0, duration=0.1)
    with pytest.raises(TypeError, match="command"):
        plant.simulate("2.5 V", duration=0.1)
    with pytest.raises(ValueError, match="atol"):
        plant.simulate(cmd, duration=0.1, atol={"angle": 1e-9})


def test_simulate_releases_the_gil_for_a_cpp_command():
    stamps = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            stamps.append(time.perf_counter())
            time.sleep(0.001)

    thread = threading.Thread(target=count)
    thread.start()
    try:
        start = time.perf_counter()
        # 500 s of simulated time: long enough (~0.3 s at a real-time factor of ~1500) for the
        # counting thread to run while the simulation holds no GIL.
        plant.simulate(excitation.paper_multisine(), duration=500.0)
        end = time.perf_counter()
    finally:
        stop.set()
        thread.join()
    assert end - start > 0.05
    margin = 0.2 * (end - start)
    assert any(start + margin < s < end - margin for s in stamps)


# --- initial_state, derivative and the independent integrator --------------------------------


class ReferencePlant:
    """plant.md's equations 1-6, written again in plain Python (nothing from bonl but the values)."""

    def __init__(self, p):
        self.p = p
        self.A1 = math.pi * p.bore_diameter**2 / 4
        self.A2 = math.pi * (p.bore_diameter**2 - p.rod_diameter**2) / 4
        self.Kq = p.discharge_coefficient * p.area_gradient * p.spool_travel * math.sqrt(2 / p.oil_density)
        self.kv = 1 / (p.neutral_voltage - p.dead_band)
        self.phi0 = self.phi(p.stroke / 2)

    def phi(self, h):
        a, b, c = self.p.pivot_to_rod_pin, self.p.pivot_to_base_pin, self.p.retracted_length + h
        return math.acos((a * a + b * b - c * c) / (2 * a * b))

    def spring_force(self, h):
        # plant.md leaves the geometry outside the stroke open; bonl evaluates Fs at h clamped to
        # [0, L] (src/plant/model.hpp), which matters only inside an end stop.
        p = self.p
        h = min(max(h, 0.0), p.stroke)
        phi = self.phi(h)
        r = p.pivot_to_rod_pin * p.pivot_to_base_pin * math.sin(phi) / (p.retracted_length + h)
        return p.gravity_moment * p.gravity * math.cos(phi - self.phi0 + p.gravity_angle_offset) / r

    def opening(self, voltage):
        """kv * uv: saturation and dead band (plant.md 1), before the pilot hysteresis."""
        p = self.p
        e = min(max(voltage, 0.0), p.max_voltage) - p.neutral_voltage
        return self.kv * math.copysign(max(abs(e) - p.dead_band, 0.0), e)

    def initial_state(self, h0):
        p2 = self.p.supply_pressure / 4
        return [h0, 0.0, (self.A2 * p2 + self.spring_force(h0)) / self.A1, p2, 0.0]

    def rhs(self, x, pilot, load=0.0):
        p = self.p
        h, v, p1, p2, xv = x

        def ssqrt(dp):
            return dp / math.sqrt(abs(dp) + p.orifice_smoothing)

        if xv >= 0:
            q1, q2 = self.Kq * xv * ssqrt(p.supply_pressure - p1), self.Kq * xv * ssqrt(p2 - p.return_pressure)
        else:
            q1, q2 = self.Kq * xv * ssqrt(p1 - p.return_pressure), self.Kq * xv * ssqrt(p.supply_pressure - p2)
        v1 = p.dead_volume_head + self.A1 * h
        v2 = p.dead_volume_rod + self.A2 * (p.stroke - h)
        leak = p.internal_leakage * (p1 - p2)
        friction = (p.coulomb_friction + (p.static_friction - p.coulomb_friction) * math.exp(-((v / p.stribeck_velocity) ** 2))) * math.tanh(
            v / p.friction_smoothing
        ) + p.viscous_friction * v
        if h < 0:
            end = p.end_stop_stiffness * h + p.end_stop_damping * v
        elif h > p.stroke:
            end = p.end_stop_stiffness * (h - p.stroke) + p.end_stop_damping * v
        else:
            end = 0.0
        return [
            v,
            (self.A1 * p1 - self.A2 * p2 - friction - self.spring_force(h) - end - load) / p.mass,
            p.bulk_modulus / v1 * (q1 - self.A1 * v - leak - p.external_leakage * p1),
            p.bulk_modulus / v2 * (-q2 + self.A2 * v + leak - p.external_leakage * p2),
            (pilot - xv) / p.valve_time_constant,
        ]


def play(x, y_prev, half_width):
    """The play (backlash) operator: the output follows the input once it leaves the band."""
    if x > y_prev + half_width:
        return x - half_width
    if x < y_prev - half_width:
        return x + half_width
    return y_prev


@pytest.mark.parametrize("parameters", [plant.Parameters.excavator_20t(), plant.Parameters.excavator_5t()], ids=["20t", "5t"])
def test_derivative_matches_plant_md_at_random_states(parameters):
    ref = ReferencePlant(parameters)
    rng = np.random.default_rng(2024)
    for _ in range(200):
        x = [
            rng.uniform(0.05, 0.95) * parameters.stroke,
            rng.uniform(-0.4, 0.4),
            rng.uniform(0.5e6, 19.5e6),
            rng.uniform(0.5e6, 19.5e6),
            rng.uniform(-1, 1),
        ]
        pilot, load = rng.uniform(-1, 1), rng.uniform(-1e4, 1e4)
        mine = np.array(ref.rhs(x, pilot, load))
        theirs = plant.derivative(parameters, x, pilot, load)
        assert theirs.shape == (5,) and theirs.dtype == np.float64
        # Relative to the size of the terms each derivative sums (so a near-cancellation is fair).
        h, v, p1, p2, xv = x
        scale = np.array(
            [
                abs(v),
                (ref.A1 * p1 + ref.A2 * p2) / parameters.mass,
                parameters.bulk_modulus / parameters.dead_volume_head * abs(ref.A1 * v),
                parameters.bulk_modulus / parameters.dead_volume_rod * abs(ref.A2 * v),
                1 / parameters.valve_time_constant,
            ]
        )
        np.testing.assert_array_less(np.abs(mine - theirs), 1e-9 * np.maximum(np.abs(mine), scale) + 1e-300)
    # Outside the stroke too (the end stops; the linkage still closes a little beyond it).
    for h in (-1e-3, parameters.stroke + 1e-3):
        x = [h, 0.01, 10e6, 5e6, 0.2]
        np.testing.assert_allclose(plant.derivative(parameters, x, 0.1), ref.rhs(x, 0.1), rtol=1e-9)


def test_initial_state_balances_the_forces():
    p = plant.Parameters.excavator_20t()
    ref = ReferencePlant(p)
    x0 = plant.initial_state(p, 0.6)
    np.testing.assert_allclose(x0, ref.initial_state(0.6), rtol=1e-13)
    d = plant.derivative(p, x0, 0.0)
    assert d[0] == 0.0 and abs(d[1]) < 1e-9 and d[4] == 0.0
    with pytest.raises(ValueError, match="state"):
        plant.derivative(p, [0.75, 0.0, 1e7, 5e6], 0.0)
    with pytest.raises(ValueError, match="state"):
        plant.derivative(p, [0.75, 0.0, 1e7, 5e6, float("nan")], 0.0)


def test_cvode_agrees_with_an_independent_radau_integrator():
    """3 s of the paper's multi-sine, integrated by scipy's Radau from the equations above.

    The reference reproduces the 1 kHz sample-and-hold and the pilot-stage play operator and
    integrates each 1 ms interval separately, as the simulator does. Tolerance: about 5 times the
    global error CVODE leaves at rtol 1e-9 (measured 1.1e-8 m, 1.5e-7 m/s, 7.5 Pa, 1.8e-7, and
    falling about tenfold per decade of rtol from 1e-6 down), while the reference's own error is
    negligible (Radau at rtol 1e-9 and 1e-10 agree to 3e-12 m and 5e-3 Pa); a run at rtol 1e-6
    misses these bounds by a factor of about 1000.
    """
    from scipy.integrate import solve_ivp

    p = plant.Parameters.excavator_20t()
    ref = ReferencePlant(p)
    duration, rate, per_sample = 3.0, 1000.0, 10
    atol = {"position": 1e-12, "velocity": 1e-12, "pressure": 1e-5, "spool": 1e-12}
    run = plant.simulate(
        excitation.paper_multisine(), p, duration=duration, sample_time=per_sample / rate, rtol=1e-9, atol=atol,
        sensor_noise=False,
    )  # fmt: skip

    x = ref.initial_state(p.stroke / 2)
    atol_vector = [atol["position"], atol["velocity"], atol["pressure"], atol["pressure"], atol["spool"]]
    samples, pilots = [], []
    pilot = 0.0
    n_grid = int(round(duration * rate))
    for j in range(n_grid + 1):
        t0 = j / rate
        opening = ref.opening(paper_multisine_reference(t0))
        pilot = opening if j == 0 else play(opening, pilot, p.pilot_hysteresis)
        if j % per_sample == 0:
            samples.append(list(x))
            pilots.append(pilot)
        if j == n_grid:
            break
        sol = solve_ivp(
            lambda t, y, xc=pilot: ref.rhs(y, xc), (t0, (j + 1) / rate), x, method="Radau", rtol=1e-9, atol=atol_vector
        )
        assert sol.success, sol.message
        x = sol.y[:, -1]
    samples = np.array(samples)

    np.testing.assert_allclose(run.pilot, pilots, rtol=0, atol=1e-14)
    # The run moves the piston by tens of mm at up to ~0.1 m/s with pressures of several MPa.
    assert np.ptp(run.position) > 0.01 and np.ptp(run.head_pressure) > 1e6
    tolerances = {"position": 5e-8, "velocity": 1e-6, "head_pressure": 50.0, "rod_pressure": 50.0, "spool": 1e-6}
    for i, key in enumerate(["position", "velocity", "head_pressure", "rod_pressure", "spool"]):
        np.testing.assert_allclose(getattr(run, key), samples[:, i], rtol=0, atol=tolerances[key], err_msg=key)
