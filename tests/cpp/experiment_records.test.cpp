// The records' processing (experiment/records.hpp): signal processing on hand-computed numbers and
// the averaging of the repeats.

#include "test_support.hpp"

#include <bonl/experiment/records.hpp>
#include <bonl/plant/excitation.hpp>

using namespace bonl_test;

TEST_CASE("low-pass filter and differentiation on hand-computed numbers", "[experiment]") {
  const double ts = 0.01, fc = 10.0;
  const double alpha = 1.0 - std::exp(-2.0 * 3.14159265358979323846 * fc * ts);
  const Eigen::VectorXd x = vec({1.0, 3.0, 2.0, 2.0});
  const Eigen::VectorXd z = bonl::experiment::low_pass(x, fc, ts);
  CHECK(z[0] == 1.0);
  CHECK(z[1] == Approx(1.0 + alpha * 2.0));
  CHECK(z[2] == Approx(z[1] + alpha * (2.0 - z[1])));
  const Eigen::VectorXd d = bonl::experiment::differentiate(vec({0.0, 1.0, 4.0, 9.0}), 0.5);
  CHECK(near(d, vec({2.0, 4.0, 8.0, 10.0}), 1e-15));
  CHECK_THROWS_WITH(bonl::experiment::differentiate(vec({1.0}), 0.1), Catch::Matchers::Contains("at least 2"));
  CHECK_THROWS_WITH(bonl::experiment::low_pass(x, -1.0, ts), Catch::Matchers::Contains("cutoff_hz"));
}

TEST_CASE("averaging the repeats divides the sensor noise by sqrt(repeats)", "[experiment]") {
  bonl::experiment::MeasurementOptions options;
  options.duration = 5.0;
  options.cutoff_hz = 1e6;  // no filtering: alpha = 1, z = x
  const bonl::plant::Parameters parameters;
  const auto record = bonl::experiment::measure(parameters, bonl::plant::excitation::paper_multisine(), options, 3);
  const Eigen::VectorXd noise = record.angle - record.trajectory.pin_angle;
  // 501 samples: the sample standard deviation is within about 10% of sigma / sqrt(10).
  CHECK(standard_deviation(noise) == Approx(parameters.sensor_noise / std::sqrt(10.0)).epsilon(0.1));
}
