// bonl::experiment::run_tracking_experiment (bonl/experiment/tracking_experiment.hpp): issue 20's
// acceptance on the plant, computed here, and the experiment's pieces against independent oracles:
// the reference (its RMS, period and start), the PI design rule, bad options.

#include <bonl/experiment.hpp>
#include <bonl/plant/excitation.hpp>

#include <cmath>
#include <limits>

#include "test_support.hpp"

namespace experiment = bonl::experiment;

namespace {

const experiment::TrackingResult& result() {
  static const experiment::TrackingResult r = experiment::run_tracking_experiment();
  return r;
}

}  // namespace

TEST_CASE("P-H-W feedforward tracks with an RMS 40% below PI alone, and below the Hammerstein and ARX feedforward") {
  const auto& r = result();
  const double pi = r.run("PI").rms;
  const double phw = r.run("PseudoHammersteinWiener").rms;
  INFO("PI " << pi << ", P-H-W " << phw << ", Hammerstein " << r.run("Hammerstein").rms << ", ARX "
             << r.run("ARX").rms);
  CHECK(phw <= 0.6 * pi);
  CHECK(phw < r.run("Hammerstein").rms);
  CHECK(phw < r.run("ARX").rms);
  // Every feedforward helps; none of them runs into the command's limits on this reference.
  for (const auto& run : r.runs) {
    if (run.controller != "PI") CHECK(run.rms < pi);
    CHECK(run.command.minCoeff() >= 0.0);
    CHECK(run.command.maxCoeff() <= 5.0);
  }
}

TEST_CASE("after the plant changes the adaptive feedforward recovers within 20 s and the fixed one does not") {
  const auto& r = result();
  const auto& adaptive = r.run("PseudoHammersteinWiener (adaptive)", true);
  const auto& fixed = r.run("PseudoHammersteinWiener", true);
  INFO("adaptive " << adaptive.rms_before_change << " -> " << adaptive.rms_after_change << ", fixed "
                   << fixed.rms_before_change << " -> " << fixed.rms_after_change);
  CHECK(adaptive.rms_after_change <= 1.2 * adaptive.rms_before_change);
  CHECK(fixed.rms_after_change > 1.2 * fixed.rms_before_change);
  CHECK(adaptive.rms_after_change < fixed.rms_after_change);
  CHECK(adaptive.rederivations >= 1);
  // Before the change the fixed feedforward runs the same as without it: the same plant, noise and reference.
  CHECK(fixed.rms_before_change == r.run("PseudoHammersteinWiener").rms_before_change);
}

TEST_CASE("the reference is the smooth random signal, periodic, started smoothly") {
  experiment::TrackingOptions options;
  const Eigen::Index n = 8000;
  const Eigen::VectorXd r = experiment::tracking_reference(options, n);
  const auto signal = bonl::plant::excitation::smooth_random(0.5, 0.1, 20.0, 2020, 0.0);
  CHECK(r[0] == 0.0);
  for (Eigen::Index k : {200, 1234, 4000, 7999}) CHECK(r[k] == signal(0.01 * static_cast<double>(k)));
  const Eigen::VectorXd period = r.segment(2000, 2000);
  CHECK(std::sqrt(period.squaredNorm() / 2000.0) == Approx(0.1).epsilon(1e-9));
  CHECK(bonl_test::near(r.segment(4000, 2000), period, 1e-9));
  CHECK(r.array().abs().maxCoeff() < 0.5);  // within the plant's reach (0.5 rad/s at full command)
}

TEST_CASE("the PI follows Skogestad's SIMC rule from the ARX model's step response") {
  // The oracle: the rule applied by hand to the identified ARX model.
  const auto records = experiment::acquire(bonl::plant::Parameters{});
  const auto identified = experiment::identify_paper_models(records, bonl::Method::Paper);
  const auto& arx = identified.get<bonl::PaperARX>().model;
  const Eigen::VectorXd step = arx.simulate(Eigen::VectorXd::Ones(3000));
  const double gain = step[2999];
  double t63 = 0.0;
  for (Eigen::Index k = 0; k < step.size(); ++k) {
    if (step[k] >= 0.632 * gain) {
      t63 = 0.01 * static_cast<double>(k);
      break;
    }
  }
  const double theta = 0.08;  // nk = 8 samples
  const double T = std::max(t63 - theta, 0.01);
  const auto& r = result();
  CHECK(r.proportional_gain == Approx(T / (gain * 2.0 * theta)).epsilon(1e-6));
  CHECK(r.integral_time == Approx(std::min(T, 4.0 * 2.0 * theta)).epsilon(1e-9));
}

TEST_CASE("bad tracking options are refused naming them") {
  const auto bad = [](auto change, const char* message) {
    experiment::TrackingOptions options;
    change(options);
    CHECK_THROWS_WITH(options.validate(), Catch::Matchers::Contains(message));
    CHECK_THROWS_AS(experiment::tracking_reference(options, 10), std::invalid_argument);
  };
  bad([](auto& o) { o.period = std::numeric_limits<double>::quiet_NaN(); }, "period must be finite and > 0");
  bad([](auto& o) { o.duration = 70.0; }, "duration and change_time whole numbers of periods");
  bad([](auto& o) { o.change_time = 60.0; }, "change_time must leave a period before it and two after it");
  bad([](auto& o) { o.ramp = 25.0; }, "ramp must be in [0, period)");
  bad([](auto& o) { o.bulk_modulus_factor = -0.7; }, "bulk_modulus_factor must be finite and > 0");
  bad([](auto& o) { o.adaptive.rederive_every = 0; }, "rederive_every must be >= 1");
  bad([](auto& o) { o.backlash_band_per_c = -1.0; }, "backlash_band_per_c must be finite and >= 0");
}
