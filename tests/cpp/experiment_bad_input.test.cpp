// Bad input to the experiment's records (bonl::experiment), the P1 (acquire) and P16-P17 rows of
// docs/reference/bad_input.md; the plant's rows are in plant_bad_input.test.cpp. Every case checks the
// exception's type and that its message names what was wrong; the last case checks that the
// caller's arrays are never modified.

#include <bonl/experiment/records.hpp>
#include <bonl/plant/excitation.hpp>

#include <catch2/catch.hpp>
#include <cstring>
#include <limits>

#include "bad_input_cases.hpp"

namespace {

namespace experiment = bonl::experiment;
namespace excitation = bonl::plant::excitation;

const double kNaN = std::numeric_limits<double>::quiet_NaN();

using bonl_test::check_cases;

}  // namespace

TEST_CASE("P1 acquire rejects non-physical parameters before it runs anything", "[bad_input][experiment]") {
  bonl::plant::Parameters negative_mass;
  negative_mass.mass = -1.0;
  check_cases<std::invalid_argument>({
      {"P1 acquire", [negative_mass] { experiment::acquire(negative_mass); },
       "bonl: plant: mass must be > 0 and finite, got -1"},
  });
}

TEST_CASE("P16-P17 the experiment's processing and options reject bad input", "[bad_input][experiment]") {
  const Eigen::VectorXd x = Eigen::Vector4d(0.0, 1.0, kNaN, 3.0);
  const auto measure_with = [](auto change) {
    experiment::MeasurementOptions options;
    options.duration = 0.05;
    change(options);
    experiment::measure(bonl::plant::Parameters{}, excitation::step(3.0), options, 1);
  };
  check_cases<std::invalid_argument>({
      {"P16 low_pass cutoff 0", [] { experiment::low_pass(Eigen::Vector2d(1.0, 2.0), 0.0, 0.01); },
       "low_pass: cutoff_hz must be finite and > 0"},
      {"P16 low_pass ts NaN", [] { experiment::low_pass(Eigen::Vector2d(1.0, 2.0), 10.0, kNaN); },
       "low_pass: ts must be finite and > 0"},
      {"P16 low_pass NaN sample", [&] { experiment::low_pass(x, 10.0, 0.01); }, "x has a non-finite value at index 2"},
      {"P16 differentiate one sample", [] { experiment::differentiate(Eigen::VectorXd::Ones(1), 0.01); },
       "differentiate: x needs at least 2 samples"},
      {"P16 differentiate ts 0", [] { experiment::differentiate(Eigen::Vector2d(1.0, 2.0), 0.0); },
       "differentiate: ts must be finite and > 0"},
      // Before: NaN derivatives, silently.
      {"P16 differentiate NaN sample", [&] { experiment::differentiate(x, 0.01); },
       "x has a non-finite value at index 2"},
      {"P17 duration 0", [&] { measure_with([](auto& o) { o.duration = 0.0; }); }, "experiment: duration must be > 0"},
      {"P17 sample_time NaN", [&] { measure_with([](auto& o) { o.sample_time = kNaN; }); },
       "experiment: sample_time must be > 0"},
      {"P17 repeats 0", [&] { measure_with([](auto& o) { o.repeats = 0; }); },
       "experiment: repeats must be >= 1, got 0"},
      {"P17 cutoff -1", [&] { measure_with([](auto& o) { o.cutoff_hz = -1.0; }); },
       "experiment: cutoff_hz must be > 0"},
      {"P17 tolerances", [&] { measure_with([](auto& o) { o.tolerances.relative = -1.0; }); },
       "tolerances.relative must be > 0 and finite"},
  });
}

TEST_CASE("A2 the experiment's processing never modifies the caller's arrays", "[bad_input][experiment][arrays]") {
  Eigen::VectorXd x(6);
  x << 0.0, 0.3, 0.2, 0.8, 0.5, 1.0;
  const Eigen::VectorXd before = x;
  const Eigen::VectorXd filtered = experiment::low_pass(x, 10.0, 0.01);
  const Eigen::VectorXd derivative = experiment::differentiate(x, 0.01);
  CHECK(std::memcmp(x.data(), before.data(), sizeof(double) * 6) == 0);
  CHECK(filtered[0] == 0.0);
  CHECK(derivative[0] == Approx(30.0));
}
