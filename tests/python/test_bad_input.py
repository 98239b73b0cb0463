"""Bad input, tried everywhere: each test backs the rows of docs/reference/bad_input.md whose IDs its name
carries (M models and blocks, E estimator and identify, S metrics, J JSON model files, P plant,
Y conversions of Python arguments, A the caller's arrays). Every check asserts the exception's type
and that its message names what was wrong; fixed seeds throughout."""

import copy
import fractions
import json
import re

import numpy as np
import pytest

import bonl
from bonl import experiment, plant
from bonl.plant import excitation
from conftest import known_models

NAN, INF = float("nan"), float("inf")


def models():
    """Small known systems: na = 2, nb = 1, nk = 2, r = 2, r1 = 3 (tests/data/known_systems.json)."""
    return known_models("small")


MODEL_NAMES = sorted(models())


def signal(n, seed):
    """Random levels in [-1, 1], each held 3 samples."""
    levels = np.random.default_rng(seed).uniform(-1.0, 1.0, (n + 2) // 3)
    return np.repeat(levels, 3)[:n]


def raises(exception, message, call, *args, **kwargs):
    """call(*args, **kwargs) raises exactly `exception` (not a subclass) with `message` in its text."""
    with pytest.raises(exception) as info:
        call(*args, **kwargs)
    assert type(info.value) is exception, f"{type(info.value).__name__}: {info.value}"
    assert message in str(info.value), f"{message!r} not in {str(info.value)!r}"
    return info.value


# --- Models and blocks ---------------------------------------------------------------------------



def test_p27_bad_parameters_mid_run_change_nothing():
    stepping = plant.SteppingPlant()
    twin = plant.SteppingPlant()
    for _ in range(3):
        stepping.step(3.0), twin.step(3.0)
    raises(ValueError, "bonl: plant: bulk_modulus must be > 0 and finite, got -1", stepping.set_parameters,
           plant.Parameters(bulk_modulus=-1.0))
    raises(ValueError, "bonl: SteppingPlant: set_parameters: stroke cannot change while the plant runs (the linkage maps "
           "the position to the angle), was 1.5, got 1.4", stepping.set_parameters, plant.Parameters(stroke=1.4))
    raises(TypeError, "parameters must be a bonl.plant.Parameters", stepping.set_parameters, {})
    assert stepping.parameters == plant.Parameters()
    assert stepping.step(3.2).to_dict() == twin.step(3.2).to_dict()

@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: bonl.ARX(0, 1, 1), "na must be >= 1, got 0"),
        (lambda: bonl.ARX(-3, 1, 1), "na must be >= 1, got -3"),
        (lambda: bonl.ARX(1, -1, 1), "nb must be >= 0, got -1"),
        (lambda: bonl.ARX(1, 1, -1), "nk must be >= 0, got -1"),
        (lambda: bonl.Hammerstein(0, 1, 1, 1), "na must be >= 1, got 0"),
        (lambda: bonl.Hammerstein(1, 1, 1, 0), "r must be >= 1, got 0"),
        (lambda: bonl.HammersteinWiener(1, -2, 1, 2, 2), "nb must be >= 0, got -2"),
        (lambda: bonl.HammersteinWiener(1, 1, 1, 2, 1), "r1 (output polynomial degree) must be >= 2, got 1"),
        (lambda: bonl.PseudoHammersteinWiener(1, 1, -5, 2), "nk must be >= 0, got -5"),
        (lambda: bonl.PseudoHammersteinWiener(1, 1, 1, -1), "r must be >= 1, got -1"),
    ],
)
def test_m1_order_below_minimum(make, message):
    raises(ValueError, message, make)


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: bonl.ARX(10**6 + 1, 1, 1), "na must be <= 1000000, got 1000001"),
        (lambda: bonl.ARX(1, 1, 2**63 - 1), "nk must be <= 1000000, got 9223372036854775807"),
        (lambda: bonl.Hammerstein(10**12, 1, 1, 1), "na must be <= 1000000"),
        (lambda: bonl.HammersteinWiener(1, 1, 1, 10**12, 2), "r must be <= 1000000"),
        (lambda: bonl.PseudoHammersteinWiener(1, 2**62, 1, 1), "nb must be <= 1000000"),
        (lambda: bonl.HammersteinWiener(1, 1, 1, 2, 33), "r1 (output polynomial degree) must be <= 32"),
    ],
)
def test_m2_m3_order_above_maximum(make, message):
    # Before: MemoryError (std::bad_alloc) for 10**12, and an overflowing size for 2**63 - 1.
    raises(ValueError, message, make)


def test_m2_the_largest_order_is_accepted():
    np.testing.assert_array_equal(bonl.ARX(1, 0, 10**6).simulate([1.0, 1.0, 1.0]), [0.0, 0.0, 0.0])
    assert bonl.HammersteinWiener(1, 1, 1, 2, 32).num_params == 2 * 3 + 1 + 1 + 31


@pytest.mark.parametrize("order", [3.0, "3", None, 2**63, [3]], ids=repr)
def test_m5_an_order_that_is_not_an_integer_is_a_type_error(order):
    raises(TypeError, "incompatible constructor arguments", bonl.ARX, order, 1, 1)
    raises(TypeError, "incompatible constructor arguments", bonl.PseudoHammersteinWiener, 2, 1, 1, order)


def test_m5_integer_like_orders_are_accepted():
    # numpy integers are integers, and so are bools (True is 1): documented, not refused.
    model = bonl.ARX(np.int64(2), True, np.uint8(3))
    assert (model.na, model.nb, model.nk, model.num_params) == (2, 1, 3, 4)


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: bonl.ARX(2, 1, 2, b=[1.0]), "b must have 2 entries, got 1"),
        (lambda: bonl.ARX(2, 1, 2, a=[0.1, 0.2, 0.3]), "a must have 2 entries, got 3"),
        (lambda: bonl.Hammerstein(2, 1, 2, 2, f=[1.0, 2.0]), "f must have 3 entries, got 2"),
        (lambda: bonl.Hammerstein(2, 1, 2, 2, p=[]), "p must have 3 entries, got 0"),
        (lambda: bonl.HammersteinWiener(2, 1, 2, 2, 3, q=[1.0, 0.1]), "q must have 3 entries, got 2"),
        (lambda: bonl.PseudoHammersteinWiener(2, 1, 2, 2, b=[1.0, 0.1, 0.1]), "b must have 2 entries, got 3"),
    ],
)
def test_m6_parameter_of_the_wrong_length(make, message):
    raises(ValueError, message, make)


@pytest.mark.parametrize("name", MODEL_NAMES)
def test_m6_m7_theta_of_the_wrong_length_or_not_finite_leaves_the_model_alone(name):
    model = models()[name]
    theta = model.theta
    raises(ValueError, f"theta must have {model.num_params} entries, got 3", setattr, model, "theta", [0.0] * 3)
    bad = theta.copy()
    bad[-1] = NAN
    raises(ValueError, f"theta has a non-finite value at index {model.num_params - 1}", setattr, model, "theta", bad)
    np.testing.assert_array_equal(model.theta, theta)


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: bonl.ARX(2, 1, 2, a=[0.1, NAN]), "a has a non-finite value at index 1"),
        (lambda: bonl.ARX(2, 1, 2, b=[-INF, 0.0]), "b has a non-finite value at index 0"),
        (lambda: bonl.Hammerstein(2, 1, 2, 2, f=[0.0, 0.0, INF]), "f has a non-finite value at index 2"),
        (lambda: bonl.HammersteinWiener(2, 1, 2, 2, 3, q=[1.0, NAN, 0.0]), "q has a non-finite value at index 1"),
        (lambda: bonl.Hammerstein(2, 1, 2, 2, b=[0.5, 0.1]), "b[0] (b_0) must be 1"),
        (lambda: bonl.HammersteinWiener(2, 1, 2, 2, 3, q=[2.0, 0.0, 0.0]), "q[0] (q_1) must be 1"),
        (lambda: bonl.PseudoHammersteinWiener(2, 1, 2, 2, c=-0.1), "c (backlash half-width) must be finite and >= 0"),
        (lambda: bonl.PseudoHammersteinWiener(2, 1, 2, 2, c=NAN), "c (backlash half-width) must be finite and >= 0"),
        (lambda: bonl.PseudoHammersteinWiener(2, 1, 2, 2, c=INF), "c (backlash half-width) must be finite and >= 0"),
    ],
    ids=["M7 a NaN", "M7 b -inf", "M7 f inf", "M7 q NaN", "M8 b_0", "M8 q_1", "M9 c < 0", "M9 c NaN", "M9 c inf"],
)
def test_m7_m8_m9_parameter_values(make, message):
    raises(ValueError, message, make)


@pytest.mark.parametrize("c", ["0.1", 1j, [0.1], np.array([0.1]), object()], ids=repr)
def test_m10_c_that_is_not_a_real_number(c):
    # Before: RuntimeError "Unable to cast Python instance of type <class 'str'> to C++ type '?'".
    raises(ValueError, "c must be a real number, got ", bonl.PseudoHammersteinWiener, 2, 1, 2, 2, c=c)


@pytest.mark.parametrize("c", [np.float32(0.25), np.array(0.25), fractions.Fraction(1, 4), 0], ids=repr)
def test_m10_real_numbers_of_any_type_are_accepted_for_c(c):
    assert bonl.PseudoHammersteinWiener(2, 1, 2, 2, c=c).c == float(c)


@pytest.mark.parametrize("name", MODEL_NAMES)
def test_m12_m14_m15_simulate_and_predict_check_their_records(name):
    model = models()[name]
    u = signal(20, 3)
    y = model.simulate(u)
    bad = u.copy()
    bad[4] = NAN
    raises(ValueError, "u has a non-finite value at index 4", model.simulate, bad)
    raises(ValueError, "u has a non-finite value at index 4", model.predict, bad, y)
    bad = y.copy()
    bad[19] = -INF
    raises(ValueError, "y has a non-finite value at index 19", model.predict, u, bad)
    raises(ValueError, "u and y must have the same length, got 20 and 19", model.predict, u, y[:-1])
    raises(ValueError, "u and y must have the same length, got 0 and 20", model.predict, [], y)
    # M15: an empty record is not an error.
    assert model.simulate([]).shape == (0,)
    assert model.predict([], []).shape == (0,)


@pytest.mark.parametrize("name", MODEL_NAMES)
def test_m13_an_unstable_model_is_a_numerical_error(name):
    model = models()[name]
    if name == "WienerHammerstein":
        model.a1 = [-2.0, 0.0]  # a pole at 2 in the first block
    else:
        model.a = [-2.0, 0.0]  # a pole at 2
    error = raises(bonl.NumericalError, "simulation left the finite numbers (an unstable model?)", model.simulate, np.ones(3000))
    assert isinstance(error, ArithmeticError)
    assert np.isfinite(model.simulate(np.ones(50))).all()


# --- Estimator and identify ----------------------------------------------------------------------


@pytest.mark.parametrize("name", MODEL_NAMES)
def test_e1_e2_e3_identify_checks_the_record(name):
    model = models()[name]
    u = signal(200, 5)
    y = model.simulate(u)
    n = model.num_params
    too_short = f"the record must be longer than the number of parameters ({n})"
    raises(ValueError, "u and y must have the same length, got 200 and 199", bonl.identify, model, u, y[:-1])
    raises(ValueError, too_short + f", got {n} samples", bonl.identify, model, u[:n], y[:n])
    raises(ValueError, too_short + ", got 0 samples", bonl.identify, model, [], [])
    bad = u.copy()
    bad[3] = NAN
    raises(ValueError, "u has a non-finite value at index 3", bonl.identify, model, bad, y)
    bad = y.copy()
    bad[17] = INF
    raises(ValueError, "y has a non-finite value at index 17", bonl.identify, model, u, bad)
    assert np.isfinite(bonl.identify(model, u[: n + 1], y[: n + 1]).theta).all()


BAD_SETTINGS = [
    (dict(passes=0), "passes must be >= 1, got 0"),
    (dict(passes=-1), "passes must be >= 1, got -1"),
    (dict(refine_iterations=-1), "refine_iterations must be >= 0"),
    (dict(forgetting=(0.98, -1, 1.0)), "initial_samples must be >= 0"),
    (dict(forgetting=(0.9, 1)), "forgetting must be None, a number, a tuple (initial, initial_samples, final) or 'adaptive'"),
    (dict(forgetting=[0.9, 1, 1.0, 1.0]), "forgetting must be None, a number, a tuple"),
    (dict(forgetting="0.9"), "forgetting must be None, a number, a tuple (initial, initial_samples, final) or 'adaptive', got '0.9'"),
    # Before: RuntimeError "Unable to cast ...", and True silently taken as 1.0.
    (dict(forgetting=("a", 1, 1.0)), "initial must be a real number, got str"),
    (dict(forgetting=(0.9, 1.5, 1.0)), "initial_samples must be an integer, got float"),
    (dict(forgetting=(0.9, True, 1.0)), "initial_samples must be an integer, got bool"),
    (dict(forgetting=(0.9, 2**70, 1.0)), "initial_samples is out of range"),
    (dict(forgetting=(0.9, 10, 1 + 2j)), "final must be a real number, got complex"),
    (dict(forgetting=True), "forgetting must be a real number, got bool"),
    (dict(method="magic"), "method must be 'output_error', 'equation_error' or 'paper', got 'magic'"),
    (dict(method="Paper"), "method must be 'output_error', 'equation_error' or 'paper', got 'Paper'"),
    (dict(method="default"), "method must be 'output_error', 'equation_error' or 'paper', got 'default'"),
]
for _lambda in (0.0, -0.5, 1.01, NAN, INF):
    BAD_SETTINGS += [
        (dict(forgetting=_lambda), "forgetting factor must be in (0, 1]"),
        (dict(forgetting=(_lambda, 10, 1.0)), "forgetting factor must be in (0, 1]"),
        (dict(forgetting=(0.98, 10, _lambda)), "forgetting factor must be in (0, 1]"),
    ]
for _p0 in (0.0, -1.0, NAN, INF):
    BAD_SETTINGS.append((dict(p0=_p0), "p0 (initial covariance scale) must be finite and > 0"))
for _c0 in (-0.01, NAN, INF):
    BAD_SETTINGS.append((dict(c0=_c0), "c0 (initial backlash half-width) must be finite and >= 0"))


@pytest.mark.parametrize("settings, message", BAD_SETTINGS, ids=[repr(s) for s, _ in BAD_SETTINGS])
def test_e4_to_e10_e13_identify_and_estimator_settings(settings, message):
    model = models()["PseudoHammersteinWiener"]
    u = signal(100, 6)
    y = model.simulate(u)
    raises(ValueError, message, bonl.identify, model, u, y, **settings)
    estimator_settings = {k: v for k, v in settings.items() if k not in ("passes", "refine_iterations")}
    if estimator_settings:
        raises(ValueError, message, bonl.Estimator, model, **estimator_settings)


ESTIMATOR_ONLY_SETTINGS = [
    (dict(stability_radius=0.0), "stability_radius must be in (0, 1], got 0"),
    (dict(stability_radius=1.5), "stability_radius must be in (0, 1], got 1.5"),
    (dict(stability_radius=NAN), "stability_radius must be in (0, 1], got nan"),
    (dict(backlash_hold=-1), "backlash_hold must be >= 0"),
    (dict(trace_ceiling=0.5), "trace_ceiling must be >= 1"),
]


@pytest.mark.parametrize("settings, message", ESTIMATOR_ONLY_SETTINGS, ids=[repr(s) for s, _ in ESTIMATOR_ONLY_SETTINGS])
def test_estimator_only_settings(settings, message):
    raises(ValueError, message, bonl.Estimator, models()["PseudoHammersteinWiener"], **settings)


MODEL_SETTINGS = [dict(c0=0.02), dict(backlash_hold=100)]


@pytest.mark.parametrize("name", [n for n in MODEL_NAMES if n != "PseudoHammersteinWiener"])
@pytest.mark.parametrize("settings", MODEL_SETTINGS, ids=repr)
def test_a_models_own_setting_given_to_another_model_is_a_value_error(name, settings):
    """c0 and backlash_hold are the PseudoHammersteinWiener model's settings: another model refuses them by name."""
    model = models()[name]
    u = signal(100, 6)
    (option,) = settings
    message = f"{option} is an option of the PseudoHammersteinWiener estimator only, not of {name}"
    raises(ValueError, message, bonl.Estimator, model, **settings)
    raises(ValueError, message, bonl.identify, model, u, model.simulate(u), **settings)


def test_the_pseudo_hammerstein_wiener_estimator_starts_from_its_c0():
    model = models()["PseudoHammersteinWiener"]
    assert bonl.Estimator(model, method="paper").theta[-1] == 0.01
    assert bonl.Estimator(model, method="paper", c0=0.05).theta[-1] == 0.05
    assert bonl.Estimator(model, c0=0.05).theta[-1] == 0.0  # output_error starts at c = 0


@pytest.mark.parametrize("settings", [dict(passes=2**40), dict(p0="1e6"), dict(c0="0.01"), dict(method=None)], ids=repr)
def test_e16_settings_of_the_wrong_type_are_type_errors(settings):
    model = models()["Hammerstein"]
    u = signal(60, 6)
    raises(TypeError, "incompatible function arguments", bonl.identify, model, u, model.simulate(u), **settings)


@pytest.mark.parametrize("model", ["ARX", None, np.zeros(3), bonl.Estimator(models()["ARX"])], ids=repr)
def test_e16_a_model_argument_that_is_not_a_model(model):
    raises(TypeError, "incompatible function arguments", bonl.identify, model, np.zeros(10), np.zeros(10))
    raises(TypeError, "incompatible constructor arguments", bonl.Estimator, model)


@pytest.mark.parametrize("name", MODEL_NAMES)
@pytest.mark.parametrize("method", ["output_error", "equation_error", "paper"])
def test_e14_a_non_finite_sample_is_refused_without_a_trace(name, method):
    model = models()[name]
    u = signal(300, 7)
    y = model.simulate(u)
    clean = bonl.Estimator(model, method=method)
    disturbed = bonl.Estimator(model, method=method)
    for k in range(len(u)):
        if k % 50 == 25:
            theta, p = disturbed.theta, disturbed.covariance
            for bad_u, bad_y in ((NAN, y[k]), (u[k], INF), (-INF, NAN)):
                assert disturbed.update(bad_u, bad_y) == bonl.UpdateStatus.rejected_non_finite
            np.testing.assert_array_equal(disturbed.theta, theta)
            np.testing.assert_array_equal(disturbed.covariance, p)
            assert disturbed.samples == clean.samples
            assert disturbed.pending_samples == clean.pending_samples
        clean.update(u[k], y[k])
        disturbed.update(u[k], y[k])
    np.testing.assert_array_equal(disturbed.theta, clean.theta)


def test_e15_e16_estimator_reset_and_update_arguments():
    model = models()["HammersteinWiener"]
    estimator = bonl.Estimator(model)
    estimator.update(0.5, 0.1)
    theta, pending = estimator.theta, estimator.pending_samples
    raises(ValueError, "theta0 must have 11 entries, got 1", estimator.reset, [1.0])
    start = np.zeros(11)
    start[4] = NAN
    raises(ValueError, "theta0 has a non-finite value at index 4", estimator.reset, start)
    raises(ValueError, "theta0 must be a 1-D array of real numbers, got str", estimator.reset, "0")
    np.testing.assert_array_equal(estimator.theta, theta)
    assert estimator.pending_samples == pending and estimator.measuring_scale
    raises(TypeError, "incompatible function arguments", estimator.update, "0.5", 0.1)
    raises(TypeError, "incompatible function arguments", estimator.update, 0.5, None)


# --- Metrics -------------------------------------------------------------------------------------

METRICS = [bonl.metrics.mse, bonl.metrics.rmse, bonl.metrics.nrmse, bonl.metrics.fit_percent]


@pytest.mark.parametrize("metric", METRICS, ids=lambda f: f.__name__)
def test_s1_s2_s3_metrics_check_their_data(metric):
    y = [1.0, 2.0, 4.0]
    raises(ValueError, "y and yhat must have the same length, got 3 and 4", metric, y, [1.0, 2.0, 3.0, 4.0])
    raises(ValueError, "y must not be empty", metric, [], [])
    raises(ValueError, "yhat has a non-finite value at index 1", metric, y, [1.0, NAN, 3.0])
    raises(ValueError, "y has a non-finite value at index 2", metric, [1.0, 2.0, INF], y)
    raises(ValueError, "yhat must be a 1-D array of real numbers, got None", metric, y, None)


@pytest.mark.parametrize("y", [[1.0] * 3, [0.1] * 3, [-0.3] * 7, [1e-300] * 2], ids=repr)
@pytest.mark.parametrize("metric", [bonl.metrics.nrmse, bonl.metrics.fit_percent], ids=lambda f: f.__name__)
def test_s4_constant_y_has_no_normalised_error(metric, y):
    # Before: nrmse([0.1] * 3, [0] * 3) was 7205759403792795.0 (the mean of 0.1, 0.1, 0.1 rounds up).
    raises(ValueError, "y is constant: the normalised error is undefined", metric, y, np.zeros(len(y)))


def test_s5_s6_metrics_near_the_ends_of_the_double_range():
    # Before: nan, "y is constant", inf.
    assert bonl.metrics.nrmse([1e200, -1e200], [0.0, 0.0]) == 1.0
    assert bonl.metrics.nrmse([1e-200, -1e-200], [0.0, 0.0]) == 1.0
    assert bonl.metrics.fit_percent([3e-300, -1e-300], [1e-300, -1e-300]) == pytest.approx(100 * (1 - 2**-0.5), rel=1e-14)
    assert bonl.metrics.rmse([1e200, -1e200], [0.0, 0.0]) == pytest.approx(1e200, rel=1e-15)
    assert bonl.metrics.mse([1e200, -1e200], [0.0, 0.0]) == INF  # 1e400 is not a double
    y, yhat = signal(500, 8), signal(500, 9)
    assert bonl.metrics.nrmse(y, yhat) == pytest.approx(np.linalg.norm(y - yhat) / np.linalg.norm(y - y.mean()), rel=1e-14)
    assert bonl.metrics.rmse(y, yhat) == pytest.approx(np.sqrt(np.mean((y - yhat) ** 2)), rel=1e-15)


# --- JSON model files ----------------------------------------------------------------------------


def phw_document():
    return json.loads(models()["PseudoHammersteinWiener"].to_json())


def changed(change):
    document = phw_document()
    change(document)
    return json.dumps(document)


def hw_with(change):
    document = json.loads(models()["HammersteinWiener"].to_json())
    change(document)
    return json.dumps(document)


_TEXT = models()["PseudoHammersteinWiener"].to_json()
BAD_FILES = [
    ("J1 empty", "", "not valid JSON"),
    ("J1 truncated", _TEXT[: len(_TEXT) // 2], "not valid JSON"),
    ("J1 trailing garbage", _TEXT + "}", "not valid JSON"),
    ("J1 comment", "// model\n" + _TEXT, "not valid JSON"),
    ("J1 NaN literal", _TEXT.replace('"c":0.05', '"c":NaN'), "not valid JSON"),
    # Before: UnicodeDecodeError, the parser's message quoting the raw byte.
    ("J1 invalid UTF-8", _TEXT.encode().replace(b"bonl-model", b"bonl-\xff\xfe"), "ill-formed UTF-8 byte; last read: '\"bonl-\\xff'"),
    ("J2 array", "[]", "the document must be a JSON object, got array"),
    ("J2 string", '"model"', "the document must be a JSON object, got string"),
    ("J3 no format", changed(lambda d: d.pop("format")), "missing key format"),
    ("J3 other format", changed(lambda d: d.update(format="bonl")), 'format must be "bonl-model", got "bonl"'),
    ("J4 version 1.0", changed(lambda d: d.update(version=1.0)), "version must be an integer, got 1.0"),
    ("J4 version '1'", changed(lambda d: d.update(version="1")), 'version must be an integer, got "1"'),
    ("J4 version 3", changed(lambda d: d.update(version=3)), "version 3 is newer than this bonl reads"),
    ("J4 version 0", changed(lambda d: d.update(version=0)), "version must be between 1 and 2, got 0"),
    ("J17 operating_point without y0", changed(lambda d: d.update(operating_point={"u0": 1.0})),
     "missing key operating_point.y0"),
    ("J5 model Volterra", changed(lambda d: d.update(model="Volterra")), 'model must be one of "ARX"'),
    ("J5 model list", changed(lambda d: d.update(model=["ARX"])), 'got ["ARX"]'),
    ("J7 no params.c", changed(lambda d: d["params"].pop("c")), "missing key params.c"),
    ("J7 extra key", changed(lambda d: d.update(note="x")), "unknown key note"),
    ("J7 q in a P-H-W", changed(lambda d: d["params"].update(q=[1.0])), "unknown key params.q"),
    ("J8 duplicate key", _TEXT.replace('"na":2', '"na":2,"na":2'), 'key "na" appears more than once in an object'),
    ("J9 na 2.0", changed(lambda d: d["orders"].update(na=2.0)), "orders.na must be an integer, got 2.0"),
    ("J9 nk true", changed(lambda d: d["orders"].update(nk=True)), "orders.nk must be an integer, got true"),
    ("J9 r null", changed(lambda d: d["orders"].update(r=None)), "orders.r must be an integer, got null"),
    ("J10 na 0", changed(lambda d: d["orders"].update(na=0)), "orders.na must be between 1 and 1000000, got 0"),
    ("J10 nk 10**6 + 1", changed(lambda d: d["orders"].update(nk=10**6 + 1)), "orders.nk must be between 0 and 1000000"),
    # Before: "orders.nb must be an integer, got 1.8446744073709552e+19" (beyond 64 bits it reads as a float).
    ("J10 nb 2**64", changed(lambda d: d["orders"].update(nb=2**64)), "orders.nb must be between 0 and 1000000, got 1.8446744073709552e+19"),
    ("J10 nb -2**70", changed(lambda d: d["orders"].update(nb=-(2**70))), "orders.nb must be between 0 and 1000000"),
    ("J10 nb 1e300", changed(lambda d: d["orders"].update(nb=1e300)), "orders.nb must be between 0 and 1000000"),
    ("J10 r1 33", hw_with(lambda d: d["orders"].update(r1=33)), "orders.r1 must be between 2 and 32, got 33"),
    ("J12 params list", changed(lambda d: d.update(params=[])), "params must be an object, got []"),
    ("J12 f a number", changed(lambda d: d["params"].update(f=1)), "params.f must be an array of numbers, got 1"),
    ("J12 f short", changed(lambda d: d["params"].update(f=[0.0])), "params.f must have 3 entries, got 1"),
    ("J13 a[1] string", changed(lambda d: d["params"]["a"].__setitem__(1, "x")), 'params.a[1] must be a number, got "x"'),
    ("J13 c null", changed(lambda d: d["params"].update(c=None)), "params.c must be a number, got null"),
    ("J14 1e400", _TEXT.replace('"c":0.05', '"c":1e400'), "a number is out of double's range"),
    ("J15 b_0 0.5", changed(lambda d: d["params"]["b"].__setitem__(0, 0.5)), "params.b[0] must be 1"),
    ("J15 q_1 2", hw_with(lambda d: d["params"]["q"].__setitem__(0, 2.0)), "params.q[0] must be 1"),
    ("J15 c < 0", changed(lambda d: d["params"].update(c=-0.1)), "params.c (backlash half-width) must be >= 0, got -0.1"),
]


@pytest.mark.parametrize("text, message", [(t, m) for _, t, m in BAD_FILES], ids=[i for i, _, _ in BAD_FILES])
def test_j1_to_j15_load_model_names_the_problem(text, message):
    error = raises(ValueError, message, bonl.load_model, text)
    assert str(error).startswith("bonl: model JSON: ")


def test_j16_load_model_takes_text():
    raises(TypeError, "incompatible function arguments", bonl.load_model, None)
    raises(TypeError, "incompatible function arguments", bonl.load_model, 3)
    # bytes are read as UTF-8 text, as str is.
    model = bonl.load_model(_TEXT.encode())
    np.testing.assert_array_equal(model.theta, models()["PseudoHammersteinWiener"].theta)


# --- Plant ---------------------------------------------------------------------------------------

FIELDS = sorted(plant.Parameters().to_dict())


@pytest.mark.parametrize("name", FIELDS)
def test_p1_p2_every_parameter_nan_or_inf_is_rejected_by_name(name):
    for bad in (NAN, INF, -INF):
        p = plant.Parameters(**{name: bad})  # construction accepts it; use validates
        raises(ValueError, f"bonl: plant: {name} must be", p.validate)
        raises(ValueError, f"bonl: plant: {name} must be", plant.simulate, excitation.step(3.0), p, duration=0.01)
        raises(ValueError, f"bonl: plant: {name} must be", plant.initial_state, p, 0.75)
        raises(ValueError, f"bonl: plant: {name} must be", plant.derivative, p, [0.75, 0.0, 5e6, 5e6, 0.0], 0.0)
        raises(ValueError, f"bonl: plant: {name} must be", experiment.run_paper_experiment, p)


@pytest.mark.parametrize(
    "overrides, message",
    [
        (dict(mass=0.0), "mass must be > 0 and finite, got 0"),
        (dict(bulk_modulus=-1e9), "bulk_modulus must be > 0 and finite"),
        (dict(viscous_friction=-1.0), "viscous_friction must be >= 0 and finite"),
        (dict(rod_diameter=0.15), "rod_diameter must be < bore_diameter"),
        (dict(return_pressure=30e6), "supply_pressure must be > return_pressure"),
        (dict(dead_band=3.0), "dead_band must be < neutral_voltage"),
        (dict(neutral_voltage=6.0), "neutral_voltage must be < max_voltage"),
        (dict(pilot_hysteresis=1.5), "pilot_hysteresis must be < 1"),
        (dict(retracted_length=0.1), "retracted_length must be > |pivot_to_rod_pin - pivot_to_base_pin|"),
    ],
    ids=repr,
)
def test_p1_p2_p3_non_physical_parameters(overrides, message):
    p = plant.Parameters(**overrides)
    raises(ValueError, message, plant.simulate, excitation.step(3.0), p, duration=0.01)


@pytest.mark.parametrize("value", ["0.1", None, [0.1], 1j], ids=repr)
def test_p4_a_parameter_that_is_not_a_real_number(value):
    # Before: RuntimeError "Unable to cast Python instance of type <class 'str'> to C++ type '?'".
    raises(ValueError, "mass must be a real number, got ", plant.Parameters, mass=value)
    state = plant.Parameters().__getstate__()
    state["mass"] = value
    raises(ValueError, "mass must be a real number, got ", plant.Parameters.__new__(plant.Parameters).__setstate__, state)
    raises(TypeError, "incompatible function arguments", setattr, plant.Parameters(), "mass", value)


def test_p4_unknown_parameter_and_real_number_types():
    raises(TypeError, "Parameters() got an unexpected keyword argument 'masss'", plant.Parameters, masss=1.0)
    p = plant.Parameters(mass=np.float32(1e4), stroke=fractions.Fraction(3, 2), sensor_noise=0)
    assert (p.mass, p.stroke, p.sensor_noise) == (1e4, 1.5, 0.0)


STEP = excitation.step(3.0)
BAD_OPTIONS = [
    (dict(duration=0.0), ValueError, "duration must be > 0 and finite, got 0"),
    (dict(duration=NAN), ValueError, "duration must be > 0 and finite, got nan"),
    (dict(duration=0.015), ValueError, "duration must be an integer multiple of sample_time"),
    (dict(sample_time=-0.01), ValueError, "sample_time must be > 0 and finite"),
    (dict(sample_time=0.0015), ValueError, "sample_time must be an integer multiple of 1 / command_rate"),
    (dict(sample_time=0.1), ValueError, "duration must be an integer multiple of sample_time"),
    (dict(command_rate=0.0), ValueError, "command_rate must be > 0 and finite"),
    (dict(rtol=0.0), ValueError, "tolerances.relative must be > 0 and finite"),
    (dict(rtol=INF), ValueError, "tolerances.relative must be > 0 and finite"),
    (dict(rtol=1.0), ValueError, "tolerances.relative must be < 1, got 1"),
    # Before: a segmentation fault (the integer grid counts overflowed), garbage arrays, or a hang.
    (dict(duration=1e19), ValueError, "duration gives 1e+22 command intervals (duration * command_rate); at most 1e+08"),
    (dict(duration=1e6), ValueError, "duration gives 1e+09 command intervals"),
    (dict(sample_time=1e-300, command_rate=1e300), ValueError, "command intervals (duration * command_rate); at most"),
    (dict(atol={"position": -1.0}), ValueError, "tolerances.absolute_position must be > 0 and finite"),
    (dict(atol={"pressure": NAN}), ValueError, "tolerances.absolute_pressure must be > 0 and finite"),
    (dict(atol={"angle": 1e-9}), ValueError, "atol: unknown key 'angle' (position, velocity, pressure, spool)"),
    # Before: TypeError "cannot convert dictionary update sequence element #0 to a sequence".
    (dict(atol=[1e-9]), ValueError, "atol must be a dict {state: tolerance}"),
    # Before: RuntimeError "Unable to cast Python instance of type <class 'str'> to C++ type '?'".
    (dict(atol={"spool": "1e-9"}), ValueError, "atol['spool'] must be a real number, got str"),
    (dict(max_steps_per_interval=0), ValueError, "tolerances.max_steps_per_interval must be >= 1"),
    (dict(initial_position=-0.1), ValueError, "initial_position must be finite and >= 0 (None means mid-stroke)"),
    (dict(initial_position=NAN), ValueError, "initial_position must be finite and >= 0"),
    (dict(initial_position=1.6), ValueError, "initial_position must be finite and <= stroke (1.5 m)"),
    (dict(initial_position="0.5"), ValueError, "initial_position must be a real number, got str"),
    (dict(noise_seed=-1), TypeError, "incompatible function arguments"),
    (dict(duration="1"), TypeError, "incompatible function arguments"),
    (dict(load="x"), TypeError, "load must be a bonl.plant.Command, a callable f(t) -> float or a (values, ts) pair"),
    (dict(load=lambda t: INF), ValueError, "the load is not finite at t = 0 s, got inf"),
    # Before: RuntimeError "Unable to cast ...".
    (dict(load=lambda t: "100"), ValueError, "the value of load(t) at t = 0 must be a real number, got str"),
]


@pytest.mark.parametrize("options, exception, message", BAD_OPTIONS, ids=[repr(o) for o, _, _ in BAD_OPTIONS])
def test_p5_to_p9_simulate_options(options, exception, message):
    kwargs = dict(duration=0.05)
    kwargs.update(options)
    raises(exception, message, plant.simulate, STEP, **kwargs)


BAD_COMMANDS = [
    (None, TypeError, "command must be a bonl.plant.Command, a callable f(t) -> float or a (values, ts) pair, got NoneType"),
    (2.5, TypeError, "command must be a bonl.plant.Command, a callable f(t) -> float or a (values, ts) pair, got float"),
    ("2.5 V", TypeError, "got str"),
    (([2.5], 0.01, 0.0), TypeError, "got tuple"),
    (lambda t: NAN, ValueError, "the command is not finite at t = 0 s, got nan"),
    (lambda t: 2.5 if t < 0.02 else INF, ValueError, "the command is not finite at t = 0.02 s, got inf"),
    # Before: RuntimeError "Unable to cast Python instance of type <class 'str'> to C++ type '?'".
    (lambda t: "2.5", ValueError, "the value of command(t) at t = 0 must be a real number, got str"),
    (lambda t: None, ValueError, "the value of command(t) at t = 0 must be a real number, got None"),
    (lambda t: 2.5 + 0j, ValueError, "the value of command(t) at t = 0 must be a real number, got complex"),
    (plant.Command(lambda t: [2.5]), ValueError, "the value of command(t) at t = 0 must be a real number, got list"),
    (([2.5, NAN], 0.01), ValueError, "command[0] (values) has a non-finite value at index 1"),
    (([2.5, 3.0], 0.0), ValueError, "sampled: ts must be finite and > 0"),
    (([], 0.01), ValueError, "sampled: values must not be empty"),
    # Before: RuntimeError "Unable to cast ...", and the imaginary parts silently dropped.
    (([2.5, 3.0], "0.01"), ValueError, "command[1] (ts) must be a real number, got str"),
    ((np.array([2.5 + 1j]), 0.01), ValueError, "command[0] (values) must be real, got a complex array"),
]


@pytest.mark.parametrize("command, exception, message", BAD_COMMANDS, ids=[repr(m) for _, _, m in BAD_COMMANDS])
def test_p10_p11_p15_commands(command, exception, message):
    raises(exception, message, plant.simulate, command, duration=0.05)


def test_p11_a_callable_that_raises_propagates_its_own_exception():
    raises(ZeroDivisionError, "division by zero", plant.simulate, lambda t: 1 / 0, duration=0.05)
    raises(KeyError, "missing", plant.simulate, STEP, duration=0.05, load=lambda t: {}["missing"])


def test_p12_an_integration_cvode_cannot_finish_is_a_numerical_error():
    error = raises(bonl.NumericalError, "CVode failed", plant.simulate, STEP, duration=0.05, max_steps_per_interval=1)
    assert isinstance(error, ArithmeticError)


# The options simulate rejects, but for the duration (a stepping plant has none): SteppingPlant
# rejects them with the same exception and message (a load only when a step reads it).
STEPPING_OPTIONS = [(o, e, m) for o, e, m in BAD_OPTIONS if "duration" not in o and "duration" not in m]


@pytest.mark.parametrize("options, exception, message", STEPPING_OPTIONS, ids=[repr(o) for o, _, _ in STEPPING_OPTIONS])
def test_p22_stepping_plant_options_as_simulate(options, exception, message):
    message = message.replace("incompatible function arguments", "incompatible constructor arguments")
    error = raises(exception, message, lambda: plant.SteppingPlant(**options).step(2.5))
    assert "simulate" not in str(error)


def test_p22_stepping_plant_parameters_and_its_own_limit():
    raises(ValueError, "bonl: plant: mass must be > 0 and finite", plant.SteppingPlant, plant.Parameters(mass=-1.0))
    raises(TypeError, "parameters must be a bonl.plant.Parameters or None, got dict", plant.SteppingPlant, {})
    raises(ValueError, "sample_time gives 1e+09 command intervals per sample (sample_time * command_rate); at most 1e+08",
           plant.SteppingPlant, sample_time=1e6)
    raises(TypeError, "incompatible constructor arguments", plant.SteppingPlant, duration=1.0)


@pytest.mark.parametrize(
    "command, message",
    [(NAN, "bonl: SteppingPlant: command must be finite, got nan"), (-INF, "command must be finite, got -inf"),
     ("2.5", "bonl: command must be a real number, got str"), (None, "command must be a real number, got None"),
     (1j, "command must be a real number, got complex"), ([2.5], "command must be a real number, got list"),
     (np.array([2.5]), "command must be a real number, got ndarray")],
    ids=repr)
def test_p23_a_bad_command_is_refused_and_changes_nothing(command, message):
    stepping = plant.SteppingPlant()
    stepping.step(3.0)
    before = stepping.measurement.to_dict()
    raises(ValueError, message, stepping.step, command)
    assert stepping.measurement.to_dict() == before


@pytest.mark.parametrize(
    "load, exception, message",
    [(lambda t: INF if t >= 0.015 else 0.0, ValueError, "bonl: SteppingPlant: the load is not finite at t = 0.015 s, got inf"),
     (lambda t: "100" if t >= 0.015 else 0.0, ValueError, "the value of load(t) at t = 0.015 must be a real number, got str"),
     (lambda t: {}["missing"] if t >= 0.015 else 0.0, KeyError, "missing")],
    ids=["inf", "str", "raises"])
def test_p24_a_bad_load_within_a_step_is_refused_and_changes_nothing(load, exception, message):
    stepping = plant.SteppingPlant(load=load)
    stepping.step(3.0)
    before = stepping.measurement.to_dict()
    raises(exception, message, stepping.step, 3.0)
    assert stepping.measurement.to_dict() == before


def test_p25_a_step_after_a_cvode_failure_asks_for_a_reset():
    stepping = plant.SteppingPlant(max_steps_per_interval=1)
    raises(bonl.NumericalError, "bonl: SteppingPlant: CVode failed with CV_TOO_MUCH_WORK", stepping.step, 4.0)
    raises(RuntimeError, "a step failed at t = 0 s and left the plant between samples; reset() it", stepping.step, 2.5)
    assert stepping.reset().time == 0.0


def test_p26_a_bad_reset_changes_nothing():
    stepping = plant.SteppingPlant()
    stepping.step(3.0)
    for position, exception, message in [
        (NAN, ValueError, "initial_position must be finite and >= 0"),
        (1.6, ValueError, "bonl: SteppingPlant: initial_position must be finite and <= stroke (1.5 m)"),
        ("0.5", ValueError, "initial_position must be a real number, got str"),
    ]:
        raises(exception, message, stepping.reset, initial_position=position)
    raises(TypeError, "incompatible function arguments", stepping.reset, noise_seed=-1)
    assert stepping.time == 0.01
    raises(ValueError, "bonl: SteppingEnv.reset: unknown options ['seed'] (initial_position)",
           plant.SteppingEnv().reset, options={"seed": 1})


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: excitation.step(NAN), "step: level must be finite"),
        (lambda: excitation.step(3.0, t_step=INF), "step: t_step must be finite"),
        (lambda: excitation.multisine([], 0.4), "multisine: frequencies_hz must not be empty"),
        (lambda: excitation.multisine([0.1, -1.0], 0.4), "frequencies_hz must be finite and >= 0, got -1 at index 1"),
        (lambda: excitation.multisine([0.1, 0.2], 0.4, phases=[0.0]), "phases must be empty or have as many entries"),
        (lambda: excitation.multisine([0.1], NAN), "multisine: amplitude must be finite"),
        (lambda: excitation.paper_multisine(offset=INF), "paper_multisine: offset must be finite"),
        (lambda: excitation.chirp(0.1, 1.0, 0.0, 0.4), "chirp: duration must be finite and > 0"),
        (lambda: excitation.chirp(-0.1, 1.0, 10.0, 0.4), "chirp: f0_hz must be finite and >= 0"),
        (lambda: excitation.smooth_random(0.1, 0.5, 1.0, 1), "bandwidth_hz * duration must be >= 1"),
        # Before: MemoryError (std::bad_alloc).
        (lambda: excitation.smooth_random(1e9, 0.5, 1e9, 1), "bandwidth_hz * duration must be <= 1000000"),
        (lambda: excitation.smooth_random(1.0, -0.5, 10.0, 1), "rms must be finite and >= 0"),
        (lambda: excitation.sampled([2.5, NAN], 0.01), "values has a non-finite value at index 1"),
        (lambda: excitation.sampled([2.5], 0.01, t0=NAN), "sampled: t0 must be finite"),
    ],
)
def test_p13_p14_p15_excitation_arguments(make, message):
    raises(ValueError, message, make)


@pytest.mark.parametrize(
    "make, exception, message",
    [
        (lambda: excitation.multisine("0.1", 0.4), TypeError, "incompatible function arguments"),
        (lambda: excitation.multisine([0.1 + 1j], 0.4), TypeError, "incompatible function arguments"),
        (lambda: excitation.smooth_random(1.0, 0.5, 10.0, -1), TypeError, "incompatible function arguments"),
        (lambda: plant.Command(3), TypeError, "incompatible constructor arguments"),
    ],
)
def test_p13_p14_arguments_of_the_wrong_type(make, exception, message):
    raises(exception, message, make)


def test_p16_p18_p19_p20_processing_states_and_experiment():
    raises(ValueError, "x has a non-finite value at index 1", experiment.low_pass, [1.0, NAN], 10.0, 0.01)
    raises(ValueError, "low_pass: cutoff_hz must be finite and > 0", experiment.low_pass, [1.0, 2.0], 0.0, 0.01)
    raises(ValueError, "low_pass: ts must be finite and > 0", experiment.low_pass, [1.0, 2.0], 10.0, -0.01)
    raises(ValueError, "x has a non-finite value at index 0", experiment.differentiate, [INF, 1.0], 0.01)
    raises(ValueError, "differentiate: x needs at least 2 samples", experiment.differentiate, [1.0], 0.01)
    raises(ValueError, "differentiate: ts must be finite and > 0", experiment.differentiate, [1.0, 2.0], NAN)
    raises(ValueError, "position must be finite, got nan", plant.initial_state, None, NAN)
    raises(TypeError, "parameters must be a bonl.plant.Parameters or None, got dict", plant.initial_state, {}, 0.5)
    raises(ValueError, "state must have 5 entries", plant.derivative, None, [0.75, 0.0, 5e6, 5e6], 0.0)
    raises(ValueError, "state has a non-finite value at index 1", plant.derivative, None, [0.75, NAN, 5e6, 5e6, 0.0], 0.0)
    raises(ValueError, "pilot must be finite, got inf", plant.derivative, None, [0.75, 0.0, 5e6, 5e6, 0.0], INF)
    raises(ValueError, "load must be finite, got nan", plant.derivative, None, [0.75, 0.0, 5e6, 5e6, 0.0], 0.0, NAN)
    raises(TypeError, "parameters must be a bonl.plant.Parameters or None, got str", experiment.run_paper_experiment, "20t")
    raises(ValueError, "mass must be > 0 and finite, got -1", experiment.run_paper_experiment, plant.Parameters(mass=-1.0))
    raises(ValueError, "t has a non-finite value at index 1", STEP.sample, [0.0, NAN])
    raises(ValueError, "t must be 1-D, got an array with 2 dimensions", STEP.sample, np.zeros((2, 2)))


# --- Python conversions --------------------------------------------------------------------------


def _masked():
    return np.ma.masked_array([0.1, 0.2, 0.3], mask=[False, True, False])


def _NONE():
    return None


def _generator():
    return (x for x in [0.1, 0.2])


# (id, value, fragment of the message after "<name> ...")
BAD_ARRAYS = [
    ("Y1 None", _NONE, "must be a 1-D array of real numbers, got None"),
    ("Y2 str", lambda: "0.1", "must be a 1-D array of real numbers, got str"),
    ("Y2 bytes", lambda: b"0.1", "must be a 1-D array of real numbers, got bytes"),
    ("Y2 numeric strings", lambda: np.array(["0.1", "0.2"]), "must be a 1-D array of real numbers, got an array of dtype <U3"),
    ("Y2 list of strings", lambda: ["0.1", "0.2"], "must be a 1-D array of real numbers, got an array of dtype <U3"),
    ("Y2 bytes array", lambda: np.array([b"1"]), "must be a 1-D array of real numbers, got an array of dtype |S1"),
    ("Y3 complex", lambda: np.array([0.1 + 0j, 0.2]), "must be real, got a complex array (dtype complex128)"),
    ("Y3 complex list", lambda: [0.1, 0.2j], "must be real, got a complex array (dtype complex128)"),
    ("Y3 complex64", lambda: np.ones(3, dtype=np.complex64), "must be real, got a complex array (dtype complex64)"),
    ("Y4 object with a str", lambda: np.array([0.1, "0.2"], dtype=object), "[1] must be a real number, got str"),
    ("Y4 object with None", lambda: np.array([0.1, None], dtype=object), "[1] must be a real number, got NoneType"),
    ("Y4 object with complex", lambda: np.array([0.1, 1j], dtype=object), "[1] must be a real number, got complex"),
    ("Y4 object with np.complex128", lambda: np.array([np.complex128(1)], dtype=object), "[0] must be a real number, got complex128"),
    ("Y4 list with None", lambda: [0.1, None], "[1] must be a real number, got NoneType"),
    ("Y5 datetime64", lambda: np.array(["2020-01-01"], dtype="datetime64[D]"), "must be a 1-D array of real numbers, got an array of dtype datetime64[D]"),
    ("Y5 timedelta64", lambda: np.array([1, 2], dtype="timedelta64[s]"), "must be a 1-D array of real numbers, got an array of dtype timedelta64[s]"),
    ("Y5 structured", lambda: np.zeros(2, dtype=[("a", "f8")]), "must be a 1-D array of real numbers, got an array of dtype"),
    ("Y6 2-D", lambda: np.zeros((3, 3)), "must be 1-D, got an array with 2 dimensions"),
    ("Y6 column", lambda: np.zeros((3, 1)), "must be 1-D, got an array with 2 dimensions"),
    ("Y6 row matrix", lambda: np.asmatrix(np.zeros(3)), "must be 1-D, got an array with 2 dimensions"),
    ("Y6 nested list", lambda: [[0.1, 0.2]], "must be 1-D, got an array with 2 dimensions"),
    ("Y6 float", lambda: 0.1, "must be a 1-D array of real numbers, got a single float"),
    ("Y6 0-d array", lambda: np.array(0.1), "must be a 1-D array of real numbers, got a single ndarray"),
    ("Y6 dict", lambda: {0: 0.1}, "must be a 1-D array of real numbers, got a single dict"),
    ("Y6 set", lambda: {0.1, 0.2}, "must be a 1-D array of real numbers, got a single set"),
    ("Y6 generator", _generator, "must be a 1-D array of real numbers, got a single generator"),
    ("Y7 ragged", lambda: [[0.1], [0.1, 0.2]], "must be a 1-D array of real numbers, got list"),
    ("Y8 masked", _masked, "is a masked array with masked entries: fill them first (numpy.ma.filled)"),
    ("Y9 int beyond float64", lambda: [10**400], "must be a 1-D array of real numbers that a float64 can hold"),
]

# (entry point taking one array, the argument's name)
ARRAY_ENTRY_POINTS = [
    ("simulate", lambda x: models()["PseudoHammersteinWiener"].simulate(x), "u"),
    ("predict u", lambda x: models()["Hammerstein"].predict(x, np.zeros(3)), "u"),
    ("predict y", lambda x: models()["HammersteinWiener"].predict(np.zeros(3), x), "y"),
    ("identify y", lambda x: bonl.identify(models()["ARX"], np.zeros(3), x), "y"),
    ("constructor a", lambda x: bonl.ARX(2, 1, 2, a=x), "a"),
    ("constructor q", lambda x: bonl.HammersteinWiener(2, 1, 2, 2, 3, q=x), "q"),
    ("theta setter", lambda x: setattr(models()["Hammerstein"], "theta", x), "theta"),
    ("reset", lambda x: bonl.Estimator(models()["ARX"]).reset(x), "theta0"),
    ("metrics yhat", lambda x: bonl.metrics.nrmse(np.arange(3.0), x), "yhat"),
    ("low_pass", lambda x: experiment.low_pass(x, 10.0, 0.01), "x"),
    ("sampled", lambda x: excitation.sampled(x, 0.01), "values"),
    ("simulate (values, ts)", lambda x: plant.simulate((x, 0.01), duration=0.05), "command[0] (values)"),
    ("Command.sample", lambda x: STEP.sample(x), "t"),
    ("derivative", lambda x: plant.derivative(None, x, 0.0), "state"),
]


# Every entry point with every bad value; None means "not given" for a constructor's parameters.
ARRAY_CASES = [
    pytest.param(call, name, value, fragment, id=f"{entry}-{row}")
    for entry, call, name in ARRAY_ENTRY_POINTS
    for row, value, fragment in BAD_ARRAYS
    if not (value is _NONE and (entry.startswith("constructor") or entry == "reset"))  # None: reset() itself
]


@pytest.mark.filterwarnings("ignore:the matrix subclass:PendingDeprecationWarning")
@pytest.mark.parametrize("call, name, value, fragment", ARRAY_CASES)
def test_y1_to_y9_array_arguments_that_are_not_arrays_of_real_numbers(call, name, value, fragment):
    # Before: numeric strings were parsed, complex parts and masks dropped, None became NaN, dates
    # and structured records became numbers.
    if fragment.startswith("["):
        message = name + fragment
    else:
        message = f"{name} {fragment}"
    raises(ValueError, message, call, value())


def _variants(reference):
    """The same values as `reference` (float64, 1-D) in every layout and dtype bonl accepts."""
    n = len(reference)
    wide = np.zeros((n, 3), order="F")
    wide[:, 1] = reference
    strided = np.zeros(2 * n)
    strided[::2] = reference
    read_only = reference.copy()
    read_only.flags.writeable = False
    big_endian = reference.astype(">f8")
    return {
        "list": list(reference),
        "tuple": tuple(reference),
        "strided view": strided[::2],
        "reversed view": reference[::-1].copy()[::-1],
        "Fortran column": wide[:, 1],
        "read-only": read_only,
        "big-endian": big_endian,
        "object of floats": reference.astype(object),
        "memoryview": memoryview(reference.copy()),
        "masked, nothing masked": np.ma.masked_array(reference.copy(), mask=False),
    }


@pytest.mark.parametrize("name", MODEL_NAMES)
def test_y9_y10_y11_accepted_arrays_give_the_float64_result(name):
    model = models()[name]
    u = signal(60, 10)
    y = model.simulate(u)
    expected_sim = model.simulate(u)
    expected_pred = model.predict(u, y)
    for kind, variant in _variants(u).items():
        np.testing.assert_array_equal(model.simulate(variant), expected_sim, err_msg=kind)
        np.testing.assert_array_equal(model.predict(variant, y), expected_pred, err_msg=kind)
    # Integers, bools and narrower floats are converted exactly.
    ints = np.array([1, -2, 0, 3] * 10, dtype=np.int32)
    np.testing.assert_array_equal(model.simulate(ints), model.simulate(ints.astype(np.float64)))
    np.testing.assert_array_equal(model.simulate([True, False] * 5), model.simulate([1.0, 0.0] * 5))
    np.testing.assert_array_equal(model.simulate(np.arange(12, dtype=np.uint64)), model.simulate(np.arange(12.0)))
    f32 = (u / 3).astype(np.float32)
    np.testing.assert_array_equal(model.simulate(f32), model.simulate(f32.astype(np.float64)))
    f16 = u.astype(np.float16)
    np.testing.assert_array_equal(model.simulate(f16), model.simulate(f16.astype(np.float64)))
    fractions_u = np.array([fractions.Fraction(1, 3), fractions.Fraction(-1, 2)] * 5, dtype=object)
    np.testing.assert_array_equal(model.simulate(fractions_u), model.simulate([1 / 3, -0.5] * 5))
    # A long double beyond the double range becomes inf, which the finiteness check reports.
    beyond = np.array([0.0, 2.0], dtype=np.longdouble) * np.longdouble(np.finfo(np.float64).max)
    if np.isfinite(beyond[1]):  # long double wider than double (x86-64)
        with np.errstate(over="ignore"):  # numpy's own warning for the cast
            raises(ValueError, "u has a non-finite value at index 1", model.simulate, beyond)


# --- The caller's arrays are never modified ------------------------------------------------------


def _layouts(values):
    """`values` as several arrays a caller may hold: contiguous float64, a strided view into a larger
    array, float32, a column of a Fortran-order 2-D array, read-only, int64 (rounded)."""
    n = len(values)
    strided_base = np.full(3 * n, -7.0)
    strided_base[1::3] = values
    fortran = np.asfortranarray(np.full((n, 2), -9.0))
    fortran[:, 0] = values
    read_only = np.array(values, dtype=np.float64)
    read_only.flags.writeable = False
    return {
        "contiguous": np.array(values, dtype=np.float64),
        "strided": strided_base[1::3],
        "float32": np.array(values, dtype=np.float32),
        "fortran column": fortran[:, 0],
        "read-only": read_only,
        "int64": np.round(np.array(values) * 10).astype(np.int64),
    }


def _snapshot(array):
    base = array if array.base is None else array.base
    return (array.tobytes(), np.asarray(base).tobytes(), array.flags.writeable, array.dtype, array.strides)


def _check_untouched(arrays, snapshots):
    for kind, array in arrays.items():
        assert _snapshot(array) == snapshots[kind], kind


@pytest.mark.parametrize("name", MODEL_NAMES)
def test_a3_models_identify_estimator_and_metrics_never_modify_the_callers_arrays(name):
    model = models()[name]
    u_values = signal(90, 12)
    y_values = model.simulate(u_values) + 1e-3 * signal(90, 13)
    us, ys = _layouts(u_values), _layouts(y_values)
    thetas = _layouts(np.linspace(-0.5, 0.5, model.num_params))
    snapshots = {f"u {k}": _snapshot(v) for k, v in us.items()}
    snapshots.update({f"y {k}": _snapshot(v) for k, v in ys.items()})
    snapshots.update({f"theta {k}": _snapshot(v) for k, v in thetas.items()})
    for kind in us:
        u, y, theta = us[kind], ys[kind], thetas[kind]
        model.simulate(u)
        model.predict(u, y)
        bonl.identify(model, u, y, refine_iterations=2)
        bonl.identify(model, u, y, method="paper")
        estimator = bonl.Estimator(model)
        estimator.reset(theta)
        for metric in METRICS:
            metric(y, u)
        copy.copy(model).theta = theta
    # The array parameters in every layout; the numbers (P-H-W's c, the Bouc-Wen law's coefficients)
    # are passed as they are.
    params = {k: np.asarray(v) for k, v in model.params.items() if np.ndim(v) > 0}
    numbers = {k: v for k, v in model.params.items() if np.ndim(v) == 0}
    layouts = {k: _layouts(v) for k, v in params.items()}
    for key, by_kind in layouts.items():
        snapshots.update({f"{key} {kind}": _snapshot(v) for kind, v in by_kind.items()})
    for kind in ("contiguous", "strided", "float32", "fortran column", "read-only"):
        type(model)(*_orders(model), **{key: by_kind[kind] for key, by_kind in layouts.items()}, **numbers)
    _check_untouched({f"u {k}": v for k, v in us.items()}, snapshots)
    _check_untouched({f"y {k}": v for k, v in ys.items()}, snapshots)
    _check_untouched({f"theta {k}": v for k, v in thetas.items()}, snapshots)
    for key, by_kind in layouts.items():
        _check_untouched({f"{key} {k}": v for k, v in by_kind.items()}, snapshots)


def _orders(model):
    return list(model.orders)


def test_a4_the_plant_never_modifies_the_callers_arrays():
    values = 2.5 + 0.5 * signal(40, 14)
    commands = _layouts(values)
    states = _layouts([0.75, 0.01, 5e6, 5e6, 0.1])
    times = _layouts(np.linspace(0.0, 0.3, 7))
    tones = _layouts([0.1, 0.2, 0.5])
    snapshots = {}
    for group, arrays in (("command", commands), ("state", states), ("t", times), ("tones", tones)):
        snapshots.update({f"{group} {k}": _snapshot(v) for k, v in arrays.items()})
    for kind in commands:
        held = excitation.sampled(commands[kind], 0.01)
        held.sample(times[kind])
        plant.simulate((commands[kind], 0.01), duration=0.05, sensor_noise=False)
        experiment.low_pass(commands[kind], 10.0, 0.01)
        experiment.differentiate(commands[kind], 0.01)
        if kind != "int64":
            plant.derivative(None, states[kind], 0.0)
        excitation.multisine(tones[kind], 0.4, phases=tones[kind])
    for group, arrays in (("command", commands), ("state", states), ("t", times), ("tones", tones)):
        _check_untouched({f"{group} {k}": v for k, v in arrays.items()}, snapshots)
    # A command made from an array keeps its own copy: changing the array afterwards changes nothing.
    values_copy = commands["contiguous"]
    held = excitation.sampled(values_copy, 0.01)
    before = held.sample([0.0, 0.015])
    values_copy[:2] = 0.0
    np.testing.assert_array_equal(held.sample([0.0, 0.015]), before)
    assert re.match(r"Command\(sampled\(40 values", repr(held))


def test_m9_theta_with_negative_c():
    """The theta setter applies set_c's rule to c (before: accepted, and the JSON could not be read back);
    an Estimator whose estimate has c < 0 gives a model with c = 0, which is how it simulates."""
    model = models()["PseudoHammersteinWiener"]
    c = model.c
    theta = model.theta.copy()
    theta[-1] = -0.1
    raises(ValueError, "theta: c (the last entry, the backlash half-width) must be >= 0, got -0.1", setattr, model, "theta", theta)
    assert model.c == c
    estimator = bonl.Estimator(model)
    estimator.reset(theta)
    assert estimator.theta[-1] == -0.1
    assert estimator.model.c == 0.0
