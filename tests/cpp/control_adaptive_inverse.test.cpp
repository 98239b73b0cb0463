// bonl::control::AdaptiveInverse (bonl/control/adaptive_inverse.hpp): started from a wrong model and
// fed a known system's data, its inverse makes the known system follow a reference (the known system
// is the oracle); a re-derived inverse goes on from where the old one was; the guard keeps the last
// good inverse for each reason it names; bad input changes nothing.

#include <bonl/control.hpp>

#include <cmath>
#include <limits>

#include "test_support.hpp"

using namespace bonl_test;
using bonl::control::AdaptiveInverse;
using bonl::control::AdaptiveInverseOptions;
using bonl::control::InverseModel;
using bonl::control::InverseOptions;

namespace {

constexpr double kPi = 3.141592653589793;

/// A smooth reference-like command about 0 (both input segments), `n` samples.
Eigen::VectorXd smooth(Eigen::Index n, double amplitude, double period) {
  Eigen::VectorXd u(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double t = static_cast<double>(k);
    u[k] = amplitude * (std::sin(2 * kPi * t / period) + 0.4 * std::sin(2 * kPi * t / (0.37 * period) + 1.0));
  }
  return u;
}

AdaptiveInverseOptions adaptive_options(double p0 = 1.0) {
  AdaptiveInverseOptions options;
  options.inverse.command_min = -3.0;
  options.inverse.command_max = 3.0;
  options.estimator.method = bonl::Method::EquationError;
  options.estimator.p0 = p0;
  options.estimator.forgetting = bonl::ForgettingSchedule::constant(0.995);
  options.max_covariance_trace = 1e6;
  return options;
}

/// max |truth.simulate(commands) - reference| from `from` on, the commands from `inverse` (a copy
/// started from rest).
template <class Model>
double follow_error(const Model& truth, InverseModel<Model> inverse, const Eigen::VectorXd& reference,
                    Eigen::Index from) {
  const auto run = inverse.commands(reference);
  const Eigen::VectorXd y = truth.simulate(run.command);
  return (y - reference).tail(reference.size() - from).cwiseAbs().maxCoeff();
}

/// Started from `wrong` and fed `truth`'s noise-free response to random levels, the adaptive inverse
/// makes `truth` follow a reference (the known system is the oracle). The equation-error estimate
/// converges geometrically, its internal x computed from the running estimate: after 6000 samples
/// theta is within about 1e-6. Before, the wrong model's inverse is off by more than `off_before`.
template <class Model>
void check_learns(const Model& truth, const Model& wrong, double off_before) {
  AdaptiveInverse<Model> adaptive(wrong, adaptive_options());
  const Eigen::VectorXd reference = truth.simulate(smooth(3000, 0.5, 400.0));
  const double before = follow_error(truth, adaptive.inverse(), reference, 200);
  const Eigen::VectorXd u = bonl::signals::random_levels(6000, 5, 1.0, 11);
  const Eigen::VectorXd y = truth.simulate(u);
  for (Eigen::Index k = 0; k < u.size(); ++k) adaptive.update(u[k], y[k]);
  const double after = follow_error(truth, adaptive.inverse(), reference, 200);
  INFO(Model::kName << ": before " << before << ", after " << after);
  CHECK(adaptive.health().rederivations == 60);
  CHECK(near(adaptive.model().theta(), truth.theta(), 1e-5));
  CHECK(before > off_before);
  CHECK(after <= 1e-5);
}

}  // namespace

TEST_CASE("started from a wrong model, the adaptive inverse learns the known system's inverse") {
  // The input block 50% too large: the commands come out about 2/3 of the truth's.
  const auto hammerstein = known_system<bonl::Hammersteind>("small");
  bonl::Hammersteind wrong = hammerstein;
  wrong.set_f(hammerstein.f() * 1.5);
  wrong.set_p(hammerstein.p() * 1.5);
  check_learns(hammerstein, wrong, 0.5);
  // The input hysteresis (polynomial and plays' weights); the re-derived inverses take over the
  // plays' memory.
  const auto hysteresis = known_system<bonl::PrandtlIshlinskiiHammersteind>("small");
  bonl::PrandtlIshlinskiiHammersteind wrong_hysteresis = hysteresis;
  wrong_hysteresis.set_f(hysteresis.f() * 1.5);
  wrong_hysteresis.set_g(hysteresis.g() * 1.5);
  check_learns(hysteresis, wrong_hysteresis, 0.5);
}

TEST_CASE("a re-derived inverse goes on from where the old one was") {
  // The same model derived again and continued from the old inverse gives the old inverse's
  // commands, bit for bit; started from rest it does not.
  const auto model = known_system<bonl::PseudoHammersteinWienerd>("small");
  InverseOptions options;
  options.command_min = -3.0;
  options.command_max = 3.0;
  options.backlash_band_per_c = 1.0;
  InverseModel<bonl::PseudoHammersteinWienerd> old_inverse(model, options);
  const Eigen::VectorXd reference = model.simulate(smooth(600, 0.5, 200.0));
  for (Eigen::Index k = 0; k < 300; ++k) old_inverse.step(reference[k + model.nk()]);
  InverseModel<bonl::PseudoHammersteinWienerd> continued(model, options);
  continued.continue_from(old_inverse);
  InverseModel<bonl::PseudoHammersteinWienerd> from_rest(model, options);
  double from_rest_difference = 0.0;
  for (Eigen::Index k = 300; k < 590; ++k) {
    const double r = reference[k + model.nk()];
    const double expected = old_inverse.step(r).value;
    CHECK(continued.step(r).value == expected);
    from_rest_difference = std::max(from_rest_difference, std::abs(from_rest.step(r).value - expected));
  }
  CHECK(from_rest_difference > 1e-3);
}

TEST_CASE("the guard keeps the last good inverse and says why") {
  using Model = bonl::Hammersteind;
  const Model truth = known_system<Model>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(400, 5, 1.0, 12);
  const Eigen::VectorXd y = truth.simulate(u);

  SECTION("a covariance above the limit") {
    // P(0) = p0 I is at the limit (1x): 200 updates without forgetting shrink it, then 300 samples of
    // a constant command under forgetting 0.9 (no information) let it grow back above it.
    AdaptiveInverseOptions options = adaptive_options();
    options.max_covariance_trace = 1.0;
    options.estimator.trace_ceiling = std::numeric_limits<double>::infinity();
    options.estimator.forgetting = bonl::ForgettingSchedule{};
    options.estimator.forgetting->initial = 1.0;
    options.estimator.forgetting->initial_samples = 200;
    options.estimator.forgetting->final = 0.9;
    AdaptiveInverse<Model> adaptive(truth, options);
    for (Eigen::Index k = 0; k < 200; ++k) adaptive.update(u[k], y[k]);
    const Eigen::Index good = adaptive.health().rederivations;
    CHECK(good >= 1);
    for (Eigen::Index k = 0; k < 300; ++k) adaptive.update(0.0, 0.0);
    CHECK(adaptive.health().refused_covariance >= 1);
    CHECK_THAT(adaptive.health().last_refusal, Catch::Matchers::Contains("trace(P) = "));
  }
  SECTION("a linear block with a pole beyond the radius") {
    AdaptiveInverseOptions options = adaptive_options();
    options.stability_radius = 0.1;  // the known system's poles are larger
    AdaptiveInverse<Model> adaptive(truth, options);
    for (Eigen::Index k = 0; k < 300; ++k) adaptive.update(u[k], y[k]);
    CHECK(adaptive.health().rederivations == 0);
    CHECK(adaptive.health().refused_unstable == 3);
    CHECK_THAT(adaptive.health().last_refusal, Catch::Matchers::Contains("a pole of the estimate has magnitude"));
    CHECK(adaptive.model().theta() == truth.theta());
  }
  SECTION("an estimate without an inverse") {
    // The system turns into w = u^2 on both sides (w falls with u for u < 0): its estimate has no
    // inverse; the monotone model it started from stays in use.
    Model square = truth;
    square.set_parameter(2, vec({0.0, 0.0, 1.0}));  // f: w = u^2 for u >= 0
    square.set_parameter(3, vec({0.0, 0.0, 0.0}));  // p = 0: g = f, w = u^2 for u < 0 too
    const Eigen::VectorXd y_square = square.simulate(u);
    AdaptiveInverse<Model> adaptive(truth, adaptive_options());
    for (Eigen::Index k = 0; k < u.size(); ++k) adaptive.update(u[k], y_square[k]);
    CHECK(adaptive.health().refused_no_inverse >= 1);
    CHECK_THAT(adaptive.health().last_refusal, Catch::Matchers::Contains("has no inverse"));
  }
}

TEST_CASE("a non-finite sample changes nothing, and bad options are refused") {
  using Model = bonl::Hammersteind;
  const Model truth = known_system<Model>("small");
  AdaptiveInverse<Model> adaptive(truth, adaptive_options());
  const auto theta = adaptive.estimator().theta();
  CHECK(adaptive.update(std::numeric_limits<double>::quiet_NaN(), 1.0) == bonl::UpdateStatus::RejectedNonFinite);
  CHECK(adaptive.update(1.0, std::numeric_limits<double>::infinity()) == bonl::UpdateStatus::RejectedNonFinite);
  CHECK(adaptive.estimator().theta() == theta);
  CHECK(adaptive.estimator().samples() == 0);

  AdaptiveInverseOptions bad = adaptive_options();
  bad.rederive_every = 0;
  CHECK_THROWS_WITH(AdaptiveInverse<Model>(truth, bad),
                    Catch::Matchers::Contains("rederive_every must be >= 1, got 0"));
  bad = adaptive_options();
  bad.max_covariance_trace = 0.5;
  CHECK_THROWS_WITH(AdaptiveInverse<Model>(truth, bad),
                    Catch::Matchers::Contains("max_covariance_trace must be finite and >= 1"));
  bad = adaptive_options();
  bad.stability_radius = 1.5;
  CHECK_THROWS_WITH(AdaptiveInverse<Model>(truth, bad),
                    Catch::Matchers::Contains("stability_radius must be in (0, 1]"));
  bad = adaptive_options();
  bad.inverse.command_min = bad.inverse.command_max = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(AdaptiveInverse<Model>(truth, bad), Catch::Matchers::Contains("needs a finite command range"));
}
