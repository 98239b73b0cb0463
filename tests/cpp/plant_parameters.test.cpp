// Tests of include/bonl/plant/parameters.hpp: validation names the parameter, the two machines,
// the derived quantities against hand values and direct computations, the initial force balance.

#include <bonl/plant/parameters.hpp>
#include <bonl/plant/simulator.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "test_support.hpp"

using bonl::plant::Parameters;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

using Mutation = std::pair<std::string, std::function<void(Parameters&)>>;

// Each case breaks one parameter of an otherwise valid set; the message must name `first`.
std::vector<Mutation> invalid_cases() {
  std::vector<Mutation> cases;
  // Every strictly positive quantity: zero, negative and non-finite values are rejected.
  const std::vector<std::pair<std::string, double Parameters::*>> positive = {
      {"bore_diameter", &Parameters::bore_diameter},
      {"rod_diameter", &Parameters::rod_diameter},
      {"dead_volume_head", &Parameters::dead_volume_head},
      {"dead_volume_rod", &Parameters::dead_volume_rod},
      {"bulk_modulus", &Parameters::bulk_modulus},
      {"oil_density", &Parameters::oil_density},
      {"discharge_coefficient", &Parameters::discharge_coefficient},
      {"area_gradient", &Parameters::area_gradient},
      {"spool_travel", &Parameters::spool_travel},
      {"orifice_smoothing", &Parameters::orifice_smoothing},
      {"valve_time_constant", &Parameters::valve_time_constant},
      {"max_voltage", &Parameters::max_voltage},
      {"mass", &Parameters::mass},
      {"stribeck_velocity", &Parameters::stribeck_velocity},
      {"friction_smoothing", &Parameters::friction_smoothing},
      {"pivot_to_rod_pin", &Parameters::pivot_to_rod_pin},
      {"pivot_to_base_pin", &Parameters::pivot_to_base_pin},
      {"retracted_length", &Parameters::retracted_length},
      {"neutral_voltage", &Parameters::neutral_voltage},
  };
  for (const auto& [name, member] : positive) {
    for (double bad : {0.0, -1.0, kNaN, kInf}) {
      cases.emplace_back(name, [member = member, bad](Parameters& p) { p.*member = bad; });
    }
  }
  // Quantities that may be zero but not negative or non-finite.
  const std::vector<std::pair<std::string, double Parameters::*>> non_negative = {
      {"internal_leakage", &Parameters::internal_leakage}, {"external_leakage", &Parameters::external_leakage},
      {"coulomb_friction", &Parameters::coulomb_friction}, {"static_friction", &Parameters::static_friction},
      {"viscous_friction", &Parameters::viscous_friction}, {"end_stop_stiffness", &Parameters::end_stop_stiffness},
      {"end_stop_damping", &Parameters::end_stop_damping}, {"gravity_moment", &Parameters::gravity_moment},
      {"joint_backlash", &Parameters::joint_backlash},     {"sensor_noise", &Parameters::sensor_noise},
      {"pilot_hysteresis", &Parameters::pilot_hysteresis}, {"dead_band", &Parameters::dead_band},
      {"return_pressure", &Parameters::return_pressure},   {"stroke", &Parameters::stroke},
  };
  for (const auto& [name, member] : non_negative) {
    for (double bad : {-1e-9, kNaN, kInf}) {
      cases.emplace_back(name, [member = member, bad](Parameters& p) { p.*member = bad; });
    }
  }
  cases.emplace_back("rod_diameter", [](Parameters& p) { p.rod_diameter = p.bore_diameter; });
  cases.emplace_back("supply_pressure", [](Parameters& p) { p.supply_pressure = p.return_pressure; });
  cases.emplace_back("supply_pressure", [](Parameters& p) { p.supply_pressure = kNaN; });
  cases.emplace_back("dead_band", [](Parameters& p) { p.dead_band = p.neutral_voltage; });
  cases.emplace_back("neutral_voltage", [](Parameters& p) { p.neutral_voltage = p.max_voltage; });
  cases.emplace_back("pilot_hysteresis", [](Parameters& p) { p.pilot_hysteresis = 1.0; });
  cases.emplace_back("gravity_angle_offset", [](Parameters& p) { p.gravity_angle_offset = kNaN; });
  // The linkage must close over the stroke: |a - b| < l_min and l_min + L < a + b (margins of
  // 0.01 m keep the cases away from rounding at the boundary).
  cases.emplace_back("retracted_length", [](Parameters& p) {
    p.retracted_length = std::abs(p.pivot_to_rod_pin - p.pivot_to_base_pin) - 0.01;
  });
  cases.emplace_back("retracted_length",
                     [](Parameters& p) { p.pivot_to_base_pin = p.pivot_to_rod_pin + p.retracted_length + 0.01; });
  cases.emplace_back(
      "stroke", [](Parameters& p) { p.stroke = p.pivot_to_rod_pin + p.pivot_to_base_pin - p.retracted_length + 0.01; });
  cases.emplace_back(
      "stroke", [](Parameters& p) { p.pivot_to_rod_pin = p.retracted_length + p.stroke - p.pivot_to_base_pin - 0.01; });
  return cases;
}

}  // namespace

TEST_CASE("the defaults and the 5-6 t set are valid") {
  CHECK_NOTHROW(Parameters{}.validate());
  CHECK_NOTHROW(Parameters::excavator_20t().validate());
  CHECK_NOTHROW(Parameters::excavator_5t().validate());
}

TEST_CASE("validation rejects each non-physical parameter and names it") {
  for (const auto& [name, mutate] : invalid_cases()) {
    for (const Parameters& base : {Parameters::excavator_20t(), Parameters::excavator_5t()}) {
      Parameters p = base;
      mutate(p);
      INFO("parameter " << name);
      CHECK_THROWS_AS(p.validate(), std::invalid_argument);
      CHECK_THROWS_WITH(p.validate(), Catch::Contains("bonl: plant: " + name));
    }
  }
}

TEST_CASE("the message shows the offending value") {
  Parameters p;
  p.bore_diameter = -1.0;
  CHECK_THROWS_WITH(p.validate(), Catch::Contains("bore_diameter") && Catch::Contains("got -1"));
}

TEST_CASE("a zero stroke, zero frictions, leakages, backlash and noise are accepted") {
  Parameters p;
  p.stroke = 0.0;
  p.coulomb_friction = p.static_friction = p.viscous_friction = 0.0;
  p.internal_leakage = p.external_leakage = 0.0;
  p.joint_backlash = p.sensor_noise = p.pilot_hysteresis = p.dead_band = p.return_pressure = 0.0;
  CHECK_NOTHROW(p.validate());
}

TEST_CASE("the 5-6 t set is plant.md's column and differs from the 20 t set") {
  const Parameters big = Parameters::excavator_20t();
  const Parameters small = Parameters::excavator_5t();
  // Exact: these are the literal values of plant.md's table.
  CHECK(small.bore_diameter == 0.090);
  CHECK(small.rod_diameter == 0.060);
  CHECK(small.stroke == 0.78);
  CHECK(small.dead_volume_head == 0.5e-3);
  CHECK(small.dead_volume_rod == 0.5e-3);
  CHECK(small.area_gradient == 2.9e-3);
  CHECK(small.internal_leakage == 2e-13);
  CHECK(small.mass == 3.6e3);
  CHECK(small.gravity_moment == 420.0);
  CHECK(small.coulomb_friction == 600.0);
  CHECK(small.static_friction == 850.0);
  CHECK(small.viscous_friction == 3.0e3);
  CHECK(small.pivot_to_rod_pin == 0.45);
  CHECK(small.pivot_to_base_pin == 1.55);
  CHECK(small.retracted_length == 1.18);
  // The rest is shared with the 20 t machine.
  CHECK(small.supply_pressure == big.supply_pressure);
  CHECK(small.bulk_modulus == big.bulk_modulus);
  CHECK(small.valve_time_constant == big.valve_time_constant);
  CHECK(small.pilot_hysteresis == big.pilot_hysteresis);
  CHECK(small.joint_backlash == big.joint_backlash);
  CHECK(small.bore_diameter != big.bore_diameter);
  CHECK(small.head_area() < big.head_area());
}

TEST_CASE("derived areas and gains match hand values") {
  const Parameters p;
  // Hand values: pi 0.14^2 / 4 and pi (0.14^2 - 0.1^2) / 4; 1e-14 relative is rounding only.
  CHECK(bonl_test::near(p.head_area() / 0.015393804002589986, 1.0, 1e-14));
  CHECK(bonl_test::near(p.annulus_area() / 0.0075398223686155, 1.0, 1e-14));
  // Kq = 0.61 * 1.08e-2 * 5e-3 * sqrt(2 / 870) = 1.5793e-6 (hand, 5 digits: 1e-4 relative).
  CHECK(bonl_test::near(p.flow_gain() / 1.5793e-6, 1.0, 1e-4));
  // kv = 1 / (2.5 - 0.08); 1e-14 relative is rounding only.
  CHECK(bonl_test::near(p.valve_gain() * 2.42, 1.0, 1e-14));
  const Parameters s = Parameters::excavator_5t();
  CHECK(bonl_test::near(s.head_area() / (kPi * 0.0081 / 4.0), 1.0, 1e-14));
  CHECK(bonl_test::near(s.annulus_area() / (kPi * 0.0045 / 4.0), 1.0, 1e-14));
}

TEST_CASE("linkage angle and moment arm follow the law of cosines") {
  for (const Parameters& p : {Parameters::excavator_20t(), Parameters::excavator_5t()}) {
    const double a = p.pivot_to_rod_pin;
    const double b = p.pivot_to_base_pin;
    for (double fraction : {0.0, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0}) {
      const double h = fraction * p.stroke;
      const double l = p.retracted_length + h;
      const double phi = std::acos((a * a + b * b - l * l) / (2.0 * a * b));
      // Same formula, evaluated independently: rounding only (1e-13 absolute on ~1.5 rad).
      CHECK(std::abs(p.linkage_angle(h) - phi) < 1e-13);
      CHECK(std::abs(p.moment_arm(h) - a * b * std::sin(phi) / l) < 1e-13);
      // The moment arm is dl/dtheta: a central difference of theta(h) with step 1e-6 m has a
      // truncation error ~1e-12 and a rounding error ~1e-10 relative; 1e-7 relative covers both.
      const double dh = 1e-6;
      const double dtheta_dh = (p.joint_angle(h + dh) - p.joint_angle(h - dh)) / (2.0 * dh);
      CHECK(bonl_test::near(dtheta_dh * p.moment_arm(h), 1.0, 1e-7));
    }
    // phi0 is the angle at mid-stroke, so theta(L/2) = 0 exactly.
    CHECK(p.joint_angle(0.5 * p.stroke) == 0.0);
    // The joint opens as the cylinder extends.
    CHECK(p.joint_angle(p.stroke) > 0.0);
    CHECK(p.joint_angle(0.0) < 0.0);
  }
}

TEST_CASE("gravity force and the initial force balance") {
  for (const Parameters& p : {Parameters::excavator_20t(), Parameters::excavator_5t()}) {
    const double h0 = 0.5 * p.stroke;
    // theta(L/2) = 0 and theta_g = 0: Fs = m_dcg g / r; 1e-12 relative is rounding (the simulator
    // evaluates cos(theta) through cos(phi + gamma), not cos(0)).
    CHECK(bonl_test::near(bonl::plant::gravity_force(p, h0) / (p.gravity_moment * p.gravity / p.moment_arm(h0)), 1.0,
                          1e-12));
    for (double h : {0.0, 0.3 * p.stroke, h0, p.stroke}) {
      const bonl::plant::State s = bonl::plant::initial_state(p, h);
      CHECK(s.position == h);
      CHECK(s.velocity == 0.0);
      CHECK(s.spool == 0.0);
      CHECK(s.rod_pressure == 0.25 * p.supply_pressure);
      const double fs = bonl::plant::gravity_force(p, h);
      // The residual of A1 p1 = A2 p2 + Fs relative to the ~1e5 N forces: rounding (1e-12).
      const double residual = p.head_area() * s.head_pressure - p.annulus_area() * s.rod_pressure - fs;
      CHECK(std::abs(residual) < 1e-12 * p.head_area() * s.head_pressure);
      // At rest with the spool closed the piston does not accelerate; only leakage moves the
      // pressures. dv/dt below 1e-9 m/s^2 is rounding of ~1e5 N forces over M ~ 1e4 kg.
      const bonl::plant::State d = bonl::plant::derivative(p, s, 0.0, 0.0);
      CHECK(d.position == 0.0);
      CHECK(std::abs(d.velocity) < 1e-9);
      CHECK(d.spool == 0.0);
      const double leak = p.internal_leakage * (s.head_pressure - s.rod_pressure);
      // dp1/dt = -beta Ci (p1 - p2) / V1: the same formula, so rounding only.
      CHECK(bonl_test::near(d.head_pressure / (-p.bulk_modulus * leak / (p.dead_volume_head + p.head_area() * h)), 1.0,
                            1e-12));
    }
  }
}

TEST_CASE("the right-hand side follows plant.md's equations at a hand-picked state") {
  const Parameters p;
  bonl::plant::State s;
  s.position = 0.6;
  s.velocity = 0.05;
  s.head_pressure = 9e6;
  s.rod_pressure = 6e6;
  s.spool = 0.3;
  const double pilot = 0.5;
  const double load = 1000.0;
  const bonl::plant::State d = bonl::plant::derivative(p, s, pilot, load);
  const double kq = p.flow_gain();
  const auto ssqrt = [&](double dp) { return dp / std::sqrt(std::abs(dp) + p.orifice_smoothing); };
  const double q1 = kq * 0.3 * ssqrt(20e6 - 9e6);
  const double q2 = kq * 0.3 * ssqrt(6e6 - 0.3e6);
  const double leak = p.internal_leakage * 3e6;
  const double ff = (2000.0 + 800.0 * std::exp(-25.0)) * std::tanh(50.0) + 1e4 * 0.05;
  const double fs = bonl::plant::gravity_force(p, 0.6);
  const double a1 = p.head_area();
  const double a2 = p.annulus_area();
  // Direct evaluation of the same formulas in another order: rounding only (1e-12 relative).
  CHECK(d.position == 0.05);
  CHECK(bonl_test::near(d.velocity / ((a1 * 9e6 - a2 * 6e6 - ff - fs - load) / p.mass), 1.0, 1e-12));
  CHECK(bonl_test::near(d.head_pressure / (1e9 / (2e-3 + a1 * 0.6) * (q1 - a1 * 0.05 - leak)), 1.0, 1e-12));
  CHECK(bonl_test::near(d.rod_pressure / (1e9 / (2e-3 + a2 * 0.9) * (-q2 + a2 * 0.05 + leak)), 1.0, 1e-12));
  CHECK(bonl_test::near(d.spool / ((0.5 - 0.3) / 0.05), 1.0, 1e-12));

  // Spool closing (xv < 0): the head chamber drains to tank, the rod chamber fills from supply.
  s.spool = -0.2;
  const bonl::plant::State e = bonl::plant::derivative(p, s, pilot, 0.0);
  const double q1n = kq * -0.2 * ssqrt(9e6 - 0.3e6);
  CHECK(bonl_test::near(e.head_pressure / (1e9 / (2e-3 + a1 * 0.6) * (q1n - a1 * 0.05 - leak)), 1.0, 1e-12));
  const double q2n = kq * -0.2 * ssqrt(20e6 - 6e6);
  CHECK(bonl_test::near(e.rod_pressure / (1e9 / (2e-3 + a2 * 0.9) * (-q2n + a2 * 0.05 + leak)), 1.0, 1e-12));

  // End stop beyond the stroke: k_end (h - L) + c_end v more force against extension.
  s.spool = 0.0;
  s.position = p.stroke + 1e-3;
  s.velocity = 0.0;
  const bonl::plant::State inside = bonl::plant::derivative(p, s, 0.0, 0.0);
  s.position = p.stroke;
  const bonl::plant::State edge = bonl::plant::derivative(p, s, 0.0, 0.0);
  // Fs is evaluated at the clamped position, so the difference is the stop force 1e5 N alone
  // (plus rounding, 1e-9 relative).
  CHECK(bonl_test::near((edge.velocity - inside.velocity) * p.mass / 1e5, 1.0, 1e-9));
}
