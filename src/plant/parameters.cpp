// Parameters of the dipper-joint plant: the 5-6 t set, validation and derived quantities
// (docs/explanation/plant.md).

#include "bonl/plant/parameters.hpp"

#include "bonl/detail/validate.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace bonl::plant {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// std::invalid_argument("bonl: plant: <name> <requirement>, got <value>").
void fail(const char* name, const std::string& requirement, double value) {
  bonl::detail::fail("plant: " + std::string(name) + ' ' + requirement + ", got " + bonl::detail::format_number(value));
}

void require_positive(const char* name, double value) {
  if (!(std::isfinite(value) && value > 0.0)) fail(name, "must be > 0 and finite", value);
}

void require_non_negative(const char* name, double value) {
  if (!(std::isfinite(value) && value >= 0.0)) fail(name, "must be >= 0 and finite", value);
}

void require_finite(const char* name, double value) {
  if (!std::isfinite(value)) fail(name, "must be finite", value);
}

}  // namespace

Parameters Parameters::excavator_5t() {
  Parameters p;
  p.bore_diameter = 0.090;
  p.rod_diameter = 0.060;
  p.stroke = 0.78;
  p.dead_volume_head = 0.5e-3;
  p.dead_volume_rod = 0.5e-3;
  p.area_gradient = 2.9e-3;
  p.internal_leakage = 2e-13;
  p.mass = 3.6e3;
  p.gravity_moment = 420.0;
  p.coulomb_friction = 600.0;
  p.static_friction = 850.0;
  p.viscous_friction = 3.0e3;
  p.pivot_to_rod_pin = 0.45;
  p.pivot_to_base_pin = 1.55;
  p.retracted_length = 1.18;
  return p;
}

void Parameters::validate() const {
  // Strictly positive: sizes, masses, material constants, time constants, smoothings.
  require_positive("bore_diameter", bore_diameter);
  require_positive("rod_diameter", rod_diameter);
  require_positive("dead_volume_head", dead_volume_head);
  require_positive("dead_volume_rod", dead_volume_rod);
  require_positive("bulk_modulus", bulk_modulus);
  require_positive("oil_density", oil_density);
  require_positive("discharge_coefficient", discharge_coefficient);
  require_positive("area_gradient", area_gradient);
  require_positive("spool_travel", spool_travel);
  require_positive("orifice_smoothing", orifice_smoothing);
  require_positive("valve_time_constant", valve_time_constant);
  require_positive("max_voltage", max_voltage);
  require_positive("mass", mass);
  require_positive("gravity", gravity);
  require_positive("stribeck_velocity", stribeck_velocity);
  require_positive("friction_smoothing", friction_smoothing);
  require_positive("pivot_to_rod_pin", pivot_to_rod_pin);
  require_positive("pivot_to_base_pin", pivot_to_base_pin);
  require_positive("retracted_length", retracted_length);

  if (!(rod_diameter < bore_diameter))
    fail("rod_diameter", "must be < bore_diameter (" + bonl::detail::format_number(bore_diameter) + ")", rod_diameter);
  require_non_negative("stroke", stroke);

  require_non_negative("return_pressure", return_pressure);
  require_finite("supply_pressure", supply_pressure);
  if (!(supply_pressure > return_pressure))
    fail("supply_pressure", "must be > return_pressure (" + bonl::detail::format_number(return_pressure) + ")",
         supply_pressure);

  require_positive("neutral_voltage", neutral_voltage);
  if (!(neutral_voltage < max_voltage))
    fail("neutral_voltage", "must be < max_voltage (" + bonl::detail::format_number(max_voltage) + ")",
         neutral_voltage);
  require_non_negative("dead_band", dead_band);
  if (!(dead_band < neutral_voltage))
    fail("dead_band", "must be < neutral_voltage (" + bonl::detail::format_number(neutral_voltage) + ")", dead_band);

  require_non_negative("internal_leakage", internal_leakage);
  require_non_negative("external_leakage", external_leakage);
  require_non_negative("coulomb_friction", coulomb_friction);
  require_non_negative("static_friction", static_friction);
  require_non_negative("viscous_friction", viscous_friction);
  require_non_negative("end_stop_stiffness", end_stop_stiffness);
  require_non_negative("end_stop_damping", end_stop_damping);
  require_non_negative("gravity_moment", gravity_moment);
  require_finite("gravity_angle_offset", gravity_angle_offset);
  require_non_negative("joint_backlash", joint_backlash);
  require_non_negative("sensor_noise", sensor_noise);
  require_non_negative("pilot_hysteresis", pilot_hysteresis);
  if (!(pilot_hysteresis < 1.0)) fail("pilot_hysteresis", "must be < 1 (a fraction of full opening)", pilot_hysteresis);

  // The linkage triangle (a, b, l) must close over the whole stroke: |a - b| < l < a + b.
  const double a = pivot_to_rod_pin;
  const double b = pivot_to_base_pin;
  if (!(std::abs(a - b) < retracted_length))
    fail("retracted_length",
         "must be > |pivot_to_rod_pin - pivot_to_base_pin| (" + bonl::detail::format_number(std::abs(a - b)) +
             ") so that the linkage closes",
         retracted_length);
  if (!(retracted_length + stroke < a + b))
    fail("stroke",
         "must satisfy retracted_length + stroke < pivot_to_rod_pin + pivot_to_base_pin (" +
             bonl::detail::format_number(a + b - retracted_length) + " here) so that the linkage closes",
         stroke);
  // The same in floating point: the gravity force and the joint rate divide by the moment arm, which
  // rounding can make 0 at an end of the stroke (a triangle closing flat) although the strict
  // inequalities above hold, e.g. |a - b| = 0 < retracted_length = 1e-300.
  const double arm_retracted = moment_arm(0.0);
  const double arm_extended = moment_arm(stroke);
  if (!(arm_retracted > 0.0 && std::isfinite(arm_retracted) && arm_extended > 0.0 && std::isfinite(arm_extended)))
    fail("retracted_length",
         "must leave the linkage a moment arm > 0 over the whole stroke in floating point (at h = 0 it is " +
             bonl::detail::format_number(arm_retracted) + " m, at h = stroke " +
             bonl::detail::format_number(arm_extended) + " m)",
         retracted_length);
  // Piston areas that underflow to 0 or overflow (the pressures are forces divided by them).
  if (!(head_area() > 0.0 && std::isfinite(head_area())))
    fail("bore_diameter", "must give a head area > 0 and finite in floating point", bore_diameter);
  if (!(annulus_area() > 0.0 && std::isfinite(annulus_area())))
    fail("rod_diameter",
         "must give an annulus area > 0 and finite in floating point (bore_diameter " +
             bonl::detail::format_number(bore_diameter) + ")",
         rod_diameter);
}

double Parameters::head_area() const { return 0.25 * kPi * bore_diameter * bore_diameter; }

double Parameters::annulus_area() const {
  return 0.25 * kPi * (bore_diameter * bore_diameter - rod_diameter * rod_diameter);
}

double Parameters::flow_gain() const {
  return discharge_coefficient * area_gradient * spool_travel * std::sqrt(2.0 / oil_density);
}

double Parameters::valve_gain() const { return 1.0 / (neutral_voltage - dead_band); }

double Parameters::linkage_angle(double h) const {
  const double a = pivot_to_rod_pin;
  const double b = pivot_to_base_pin;
  const double l = retracted_length + h;
  // Clamped so that a position outside the closing range (inside an end stop) stays defined.
  const double c = std::clamp((a * a + b * b - l * l) / (2.0 * a * b), -1.0, 1.0);
  return std::acos(c);
}

double Parameters::moment_arm(double h) const {
  // At h clamped to [0, stroke], as the force model evaluates the geometry (src/plant/model.hpp):
  // deep in an end stop the piston can pass the range where the linkage closes, where the arm is 0
  // and the joint rate v / r would be infinite.
  const double hc = h < 0.0 ? 0.0 : (h > stroke ? stroke : h);
  const double l = retracted_length + hc;
  return pivot_to_rod_pin * pivot_to_base_pin * std::sin(linkage_angle(hc)) / l;
}

}  // namespace bonl::plant
