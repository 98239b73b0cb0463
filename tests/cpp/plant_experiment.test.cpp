// The experiment pipeline (plant/experiment.hpp): signal processing on hand-computed numbers, the
// records of the default experiment, and the end-to-end result: the paper's ranking of the models.

#include "test_support.hpp"

#include <cstdio>

#include <bonl/plant/excitation.hpp>
#include <bonl/plant/experiment.hpp>

using namespace bonl_test;

TEST_CASE("low-pass filter and differentiation on hand-computed numbers", "[experiment]") {
  const double ts = 0.01, fc = 10.0;
  const double alpha = 1.0 - std::exp(-2.0 * 3.14159265358979323846 * fc * ts);
  const Eigen::VectorXd x = vec({1.0, 3.0, 2.0, 2.0});
  const Eigen::VectorXd z = bonl::plant::low_pass(x, fc, ts);
  CHECK(z[0] == 1.0);
  CHECK(z[1] == Approx(1.0 + alpha * 2.0));
  CHECK(z[2] == Approx(z[1] + alpha * (2.0 - z[1])));
  const Eigen::VectorXd d = bonl::plant::differentiate(vec({0.0, 1.0, 4.0, 9.0}), 0.5);
  CHECK(near(d, vec({2.0, 4.0, 8.0, 10.0}), 1e-15));
  CHECK_THROWS_WITH(bonl::plant::differentiate(vec({1.0}), 0.1), Catch::Matchers::Contains("at least 2"));
  CHECK_THROWS_WITH(bonl::plant::low_pass(x, -1.0, ts), Catch::Matchers::Contains("cutoff_hz"));
}

TEST_CASE("averaging the repeats divides the sensor noise by sqrt(repeats)", "[experiment]") {
  bonl::plant::ExperimentOptions options;
  options.duration = 5.0;
  options.cutoff_hz = 1e6;  // no filtering: alpha = 1, z = x
  const bonl::plant::Parameters parameters;
  const auto record = bonl::plant::measure(parameters, bonl::plant::excitation::paper_multisine(), options, 3);
  const Eigen::VectorXd noise = record.angle - record.trajectory.pin_angle;
  // 501 samples: the sample standard deviation is within about 10% of sigma / sqrt(10).
  CHECK(standard_deviation(noise) == Approx(parameters.sensor_noise / std::sqrt(10.0)).epsilon(0.1));
}

TEST_CASE("the default experiment: records, end stops, and the paper's ranking", "[experiment][slow]") {
  const bonl::plant::Parameters parameters;
  const bonl::plant::ExperimentData data = bonl::plant::acquire(parameters);
  for (const auto* record : {&data.identification, &data.validation}) {
    CHECK(record->velocity.size() == 5001);
    CHECK_FALSE(record->trajectory.reached_end_stop);
    CHECK(record->trajectory.min_position > 0.0);
    CHECK(record->trajectory.max_position < parameters.stroke);
    // The processed velocity follows the plant's joint rate: the 10 Hz filter and the noise leave
    // a small part of its spread.
    CHECK(bonl::metrics::nrmse(record->true_velocity, record->velocity) < 0.2);
  }
  // The paper's ranking P-H-W < Hammerstein < ARX holds for the default method. With the paper's
  // own estimator, Hammerstein < ARX holds but its P-H-W does not beat its Hammerstein on this
  // validation record (README, "The experiment": eq. (27) feeds the gap samples the output's
  // increments), so only what holds is asserted for it, and the shortfall is printed.
  const auto ours = bonl::plant::identify_models(data, bonl::Method::OutputError);
  INFO("default: MSE P-H-W " << ours.mse_phw << ", H-W " << ours.mse_hammerstein_wiener << ", Hammerstein "
                             << ours.mse_hammerstein << ", ARX " << ours.mse_arx);
  CHECK(ours.mse_phw < ours.mse_hammerstein);
  CHECK(ours.mse_hammerstein < ours.mse_arx);
  const auto paper = bonl::plant::identify_models(data, bonl::Method::Paper);
  std::printf("paper method: MSE P-H-W %.4e, H-W %.4e, Hammerstein %.4e, ARX %.4e\n", paper.mse_phw,
              paper.mse_hammerstein_wiener, paper.mse_hammerstein, paper.mse_arx);
  CHECK(paper.mse_hammerstein < paper.mse_arx);
}

TEST_CASE("without pilot hysteresis and pin backlash the identified c is near zero", "[experiment][slow]") {
  // Bound: 1% of the validation velocity's standard deviation (0.117 rad/s); measured 2e-6 rad/s
  // with the default method. The paper method ends at 0.013 and is not held to it.
  bonl::plant::Parameters parameters;
  parameters.pilot_hysteresis = 0.0;
  parameters.joint_backlash = 0.0;
  const auto data = bonl::plant::acquire(parameters);
  const auto ours = bonl::plant::identify_models(data, bonl::Method::OutputError);
  CHECK(ours.phw.c() <= 0.01 * standard_deviation(data.validation.velocity));
}

TEST_CASE("P-H-W's advantage grows with the pilot hysteresis", "[experiment][slow]") {
  // The valve backlash is what P-H-W models: with none, P-H-W and Hammerstein are equal; at 8% of
  // full opening P-H-W's error is clearly below Hammerstein's (measured: 3.8e-4 against 8.4e-4).
  double ratio[2];
  for (int i = 0; i < 2; ++i) {
    bonl::plant::Parameters parameters;
    parameters.pilot_hysteresis = i == 0 ? 0.0 : 0.08;
    const auto models = bonl::plant::identify_models(bonl::plant::acquire(parameters), bonl::Method::OutputError);
    ratio[i] = models.mse_phw / models.mse_hammerstein;
  }
  CHECK(ratio[0] == Approx(1.0).epsilon(0.05));
  CHECK(ratio[1] < 0.6);
}
