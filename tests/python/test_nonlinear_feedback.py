"""The nonlinear-feedback (Lur'e) model in Python (its C++ tests: tests/cpp/nonlinear_feedback.test.cpp):
the free run against the difference equation written out in numpy; the known systems of
tests/data/known_systems.json recovered by identify to NRMSE 1e-6 on a fresh input of a larger
amplitude (one with play operators in the loop); the model file round trip; bad orders, d_1, knots and
thresholds refused with a ValueError that says
what was wrong; the inverse refused."""

import numpy as np
import pytest

import bonl

from conftest import known_models, random_levels


def _by_hand(model, u):
    """y(k) = b . u lags - a . y lags + sum_j d_j f(s(k-j)), the oracle keeping its own past."""
    b, a, f, g, d, knots = model.b, model.a, model.f, model.g, model.d, model.knots
    thresholds, w = model.thresholds, model.w
    nk, nv = model.nk, model.nv

    def nonlinearity(s):
        out = sum(f[i] * s ** (i + 2) for i in range(len(f)))
        for knot, slope in zip(knots, g):
            out += slope * (max(0.0, s - knot) if knot > 0 else min(0.0, s - knot))
        return out

    y = np.zeros_like(u)
    past = lambda k: y[k] if k >= 0 else 0.0  # noqa: E731
    plays = np.zeros((len(u), len(thresholds)))  # the plays of s(k), from rest
    played = lambda k: plays[k] if k >= 0 else np.zeros(len(thresholds))  # noqa: E731
    for k in range(len(u)):
        if k >= 1:
            s = past(k - 1) if nv == 0 else past(k - 1) - past(k - 2)
            plays[k - 1] = np.minimum(np.maximum(played(k - 2), s - thresholds), s + thresholds)
        out = sum(b[i] * u[k - nk - i] for i in range(len(b)) if k - nk - i >= 0)
        out -= sum(a[j - 1] * past(k - j) for j in range(1, len(a) + 1))
        for j in range(1, len(d) + 1):
            s = past(k - j) if nv == 0 else past(k - j) - past(k - j - 1)
            out += d[j - 1] * (nonlinearity(s) + float(np.dot(w, played(k - j))))
        y[k] = out
    return y


def _friction():
    """tests/cpp/known_systems.hpp's friction_feedback(): hinges on the velocity."""
    return bonl.NonlinearFeedback(2, 1, 1, 3, 2, 2, 1, b=[0.2, 0.1], a=[-1.5, 0.56], f=[0.0, -0.5],
                                  knots=[-0.05, 0.05], g=[-0.4, -0.4], d=[1.0, 0.3])


def _hysteretic():
    """tests/cpp/known_systems.hpp's hysteretic_feedback(): play operators of the output in the loop."""
    return bonl.NonlinearFeedback(2, 1, 1, 3, 0, 2, 0, 3, b=[0.2, 0.1], a=[-1.6, 0.7], f=[0.0, -0.002],
                                  thresholds=[0.2, 0.5, 1.0], w=[-0.06, -0.05, -0.04], d=[1.0, 0.4])


def _known(which):
    return {"friction": _friction, "hysteretic": _hysteretic}.get(
        which, lambda: known_models(which)["NonlinearFeedback"])()


@pytest.mark.parametrize("which", ["paper_orders", "small", "friction", "hysteretic"])
def test_the_free_run_is_the_difference_equation_written_out(which):
    model = _known(which)
    u = random_levels(400, 5, 1.0, 5)
    np.testing.assert_allclose(model.simulate(u), _by_hand(model, u), rtol=0, atol=1e-12)


@pytest.mark.parametrize("which", ["paper_orders", "small", "friction", "hysteretic"])
def test_identify_recovers_a_known_nonlinear_feedback_system(which):
    truth = _known(which)
    u = random_levels(4000, 5, 1.0, 3)
    structure = bonl.NonlinearFeedback(*truth.orders, knots=truth.knots, thresholds=truth.thresholds)
    identified = bonl.identify(structure, u, truth.simulate(u))
    fresh = random_levels(4000, 5, 1.5, 77)  # larger than the identification input
    expected = truth.simulate(fresh)
    nrmse = np.linalg.norm(expected - identified.simulate(fresh)) / np.linalg.norm(expected - expected.mean())
    assert nrmse <= 1e-6


def test_the_model_file_round_trips():
    truth = _friction()
    back = bonl.load_model(truth.to_json())
    assert isinstance(back, bonl.NonlinearFeedback)
    assert back.d[0] == 1.0 and back.nv == 1
    np.testing.assert_array_equal(back.knots, truth.knots)
    np.testing.assert_array_equal(back.theta, truth.theta)
    hysteretic = _hysteretic()
    back = bonl.load_model(hysteretic.to_json())
    assert back.np == 3
    np.testing.assert_array_equal(back.thresholds, hysteretic.thresholds)
    np.testing.assert_array_equal(back.w, hysteretic.w)


def test_bad_thresholds_are_refused_and_the_model_kept():
    model = _hysteretic()
    with pytest.raises(ValueError, match="strictly increasing"):
        model.thresholds = [0.5, 0.2, 1.0]
    with pytest.raises(ValueError, match="must be > 0"):
        model.thresholds = [-0.1, 0.5, 1.0]
    with pytest.raises(ValueError, match="np"):
        bonl.NonlinearFeedback(2, 1, 1, 3, 0, 2, 0, 33)
    np.testing.assert_array_equal(model.thresholds, [0.2, 0.5, 1.0])


def test_bad_orders_and_parameters_are_refused_with_a_value_error():
    with pytest.raises(ValueError, match="nv must be 0"):
        bonl.NonlinearFeedback(3, 2, 0, 3, 0, 1, 2)
    with pytest.raises(ValueError, match="nd"):
        bonl.NonlinearFeedback(3, 2, 0, 3, 0, 0, 0)
    model = _friction()
    with pytest.raises(ValueError, match=r"d\[0\] \(d_1\) must be 1"):
        model.d = [2.0, 0.3]
    with pytest.raises(ValueError, match="strictly increasing"):
        model.knots = [0.05, -0.05]
    np.testing.assert_array_equal(model.knots, [-0.05, 0.05])
    np.testing.assert_array_equal(model.d, [1.0, 0.3])


def test_the_inverse_is_refused_with_a_value_error():
    truth = known_models("small")["NonlinearFeedback"]
    with pytest.raises(ValueError, match="NonlinearFeedback model has no inverse"):
        bonl.control.InverseModel(truth, command_min=-1.0, command_max=1.0)
