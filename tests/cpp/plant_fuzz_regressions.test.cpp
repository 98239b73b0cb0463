// Reproducers of what the libFuzzer targets (fuzz/, docs/lab/fuzzing.md) found in the plant, reduced
// to plain inputs. (The plant_ prefix links bonl::plant.)

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

#include "bonl/plant/parameters.hpp"
#include "bonl/plant/simulator.hpp"

using bonl::plant::Parameters;

namespace {

std::string message_of(const Parameters& p) {
  try {
    p.validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// fuzz_plant_parameters: a valve fast enough to drive the piston through an end stop and past the
// range where the linkage closes (h < |a - b| - l_min) gave joint_rate = v / 0 = -inf. Without end
// stops the plain 5 t machine does it at full retraction from h = 0 within 0.5 s.
TEST_CASE("joint rate stays finite when the piston leaves the linkage's closing range") {
  Parameters p = Parameters::excavator_5t();
  p.end_stop_stiffness = 0.0;
  p.end_stop_damping = 0.0;
  bonl::plant::SimulationOptions options;
  options.duration = 1.0;
  options.initial_position = 0.0;
  const double closes_from = std::abs(p.pivot_to_rod_pin - p.pivot_to_base_pin) - p.retracted_length;  // -0.08 m
  const auto run = bonl::plant::simulate(
      p, [](double) { return 0.0; }, options);
  REQUIRE(run.position.minCoeff() < closes_from);  // the case in question happened
  CHECK(run.joint_rate.allFinite());
  // Inside the stroke nothing changed: r(h) = a b sin(phi) / l.
  const double h = 0.3 * p.stroke;
  const double l = p.retracted_length + h;
  CHECK(p.moment_arm(h) == p.pivot_to_rod_pin * p.pivot_to_base_pin * std::sin(p.linkage_angle(h)) / l);
  // Outside, the arm is the one at the nearer end of the stroke, as in the force model.
  CHECK(p.moment_arm(-1.0) == p.moment_arm(0.0));
  CHECK(p.moment_arm(p.stroke + 1.0) == p.moment_arm(p.stroke));
}

// Found while fixing the above: the closing inequality |a - b| < l_min can hold while the law of
// cosines rounds the triangle flat at h = 0, a moment arm of exactly 0 that the gravity force
// divides by (an infinite initial pressure, reported by CVODE at t = 0 without naming a parameter).
TEST_CASE("validate rejects a linkage whose moment arm rounds to 0 at an end of the stroke") {
  Parameters p;
  p.pivot_to_rod_pin = 1.0;
  p.pivot_to_base_pin = 1.0;
  p.retracted_length = 1e-300;  // > |a - b| = 0, but cos(phi) rounds to 1
  p.stroke = 1.0;
  REQUIRE(p.moment_arm(0.0) == 0.0);
  CHECK(message_of(p).rfind("bonl: plant: retracted_length must leave the linkage a moment arm > 0", 0) == 0);
  p.retracted_length = 1e-3;  // the same linkage, away from the flat triangle, is fine
  CHECK(message_of(p).empty());
}

TEST_CASE("validate rejects piston areas that underflow or overflow") {
  Parameters p;
  p.bore_diameter = 1e-170;  // D^2 underflows to 0
  p.rod_diameter = 1e-171;
  REQUIRE(p.head_area() == 0.0);
  CHECK(message_of(p).rfind("bonl: plant: bore_diameter must give a head area > 0", 0) == 0);
  p = Parameters{};
  p.bore_diameter = 1e200;  // D^2 overflows
  REQUIRE(std::isinf(p.head_area()));
  CHECK(message_of(p).rfind("bonl: plant: bore_diameter must give a head area > 0", 0) == 0);
  p = Parameters{};
  p.bore_diameter = 2.3e-162;  // D^2 and d^2 round to the same denormal
  p.rod_diameter = 2.2e-162;
  REQUIRE(p.head_area() > 0.0);
  REQUIRE(p.annulus_area() == 0.0);
  CHECK(message_of(p).rfind("bonl: plant: rod_diameter must give an annulus area > 0", 0) == 0);
  // The defaults and the 5 t set stay valid.
  CHECK(message_of(Parameters::excavator_20t()).empty());
  CHECK(message_of(Parameters::excavator_5t()).empty());
}
