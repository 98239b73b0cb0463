// libFuzzer target: bytes -> bonl::plant::Parameters (every field) -> validate(), then a 5 ms
// simulation (bonl/plant/parameters.hpp, simulator.hpp).
//
// The input picks a start (the 20 t set, the 5 t set, or every field decoded from the bytes) and
// then up to 8 edits of single fields: an arbitrary double (special values favoured), the field
// scaled by a power of two, another field's value, or the field moved by a few ulps. That keeps
// most inputs near the boundaries of validity instead of far outside it.
//
// Contract checked (besides ASan/UBSan/LSan and no hang):
// - validate() accepts, or throws std::invalid_argument "bonl: plant: <field> ..." naming a field;
//   nothing else escapes.
// - Accepted parameters are all finite.
// - simulate() (5 command intervals of 1 ms, at most 500 CVODE steps each, a command cycling
//   through 4 voltages, a constant load) with rejected parameters or a bad initial position throws
//   std::invalid_argument. Otherwise it returns a trajectory whose every number is finite, or
//   throws bonl::NumericalError (CvodeError: extreme but valid parameters may defeat the
//   integrator, which is to be reported, not hidden), or std::invalid_argument when the command or
//   the load turns out non-finite; never anything else.

#include <bonl/plant/parameters.hpp>
#include <bonl/plant/simulator.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "fuzz_common.hpp"

namespace {

using bonl::plant::Parameters;

struct Field {
  const char* name;
  double Parameters::*member;
};

#define BONL_FIELD(name) \
  Field { #name, &Parameters::name }
constexpr std::array<Field, 36> kFields = {
    BONL_FIELD(bore_diameter),
    BONL_FIELD(rod_diameter),
    BONL_FIELD(stroke),
    BONL_FIELD(dead_volume_head),
    BONL_FIELD(dead_volume_rod),
    BONL_FIELD(supply_pressure),
    BONL_FIELD(return_pressure),
    BONL_FIELD(bulk_modulus),
    BONL_FIELD(oil_density),
    BONL_FIELD(discharge_coefficient),
    BONL_FIELD(area_gradient),
    BONL_FIELD(spool_travel),
    BONL_FIELD(internal_leakage),
    BONL_FIELD(external_leakage),
    BONL_FIELD(orifice_smoothing),
    BONL_FIELD(valve_time_constant),
    BONL_FIELD(dead_band),
    BONL_FIELD(neutral_voltage),
    BONL_FIELD(max_voltage),
    BONL_FIELD(pilot_hysteresis),
    BONL_FIELD(mass),
    BONL_FIELD(gravity_moment),
    BONL_FIELD(gravity_angle_offset),
    BONL_FIELD(gravity),
    BONL_FIELD(coulomb_friction),
    BONL_FIELD(static_friction),
    BONL_FIELD(stribeck_velocity),
    BONL_FIELD(viscous_friction),
    BONL_FIELD(friction_smoothing),
    BONL_FIELD(end_stop_stiffness),
    BONL_FIELD(end_stop_damping),
    BONL_FIELD(pivot_to_rod_pin),
    BONL_FIELD(pivot_to_base_pin),
    BONL_FIELD(retracted_length),
    BONL_FIELD(joint_backlash),
    BONL_FIELD(sensor_noise),
};
#undef BONL_FIELD
static_assert(sizeof(Parameters) == kFields.size() * sizeof(double),
              "bonl::plant::Parameters changed: list every field in kFields of fuzz/fuzz_plant_parameters.cpp");

Parameters decode(FuzzedDataProvider& in) {
  Parameters p;
  switch (in.ConsumeIntegralInRange<int>(0, 2)) {
    case 0: p = Parameters::excavator_20t(); break;
    case 1: p = Parameters::excavator_5t(); break;
    default:
      for (const Field& f : kFields) p.*f.member = bonl_fuzz::any_double(in);
      break;
  }
  const int edits = in.ConsumeIntegralInRange<int>(0, 8);
  for (int e = 0; e < edits; ++e) {
    double& value = p.*kFields[in.ConsumeIntegralInRange<std::size_t>(0, kFields.size() - 1)].member;
    switch (in.ConsumeIntegralInRange<int>(0, 3)) {
      case 0: value = bonl_fuzz::any_double(in); break;
      case 1: value = std::ldexp(in.ConsumeBool() ? -value : value, in.ConsumeIntegralInRange<int>(-1100, 1100)); break;
      case 2: value = p.*kFields[in.ConsumeIntegralInRange<std::size_t>(0, kFields.size() - 1)].member; break;
      default: {
        const bool up = in.ConsumeBool();
        for (int k = in.ConsumeIntegralInRange<int>(1, 4); k > 0; --k)
          value = std::nextafter(
              value, up ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity());
        break;
      }
    }
  }
  return p;
}

/// With BONL_FUZZ_VERBOSE set (when reproducing a finding): every field as decoded.
void print(const Parameters& p) {
  static const bool verbose = std::getenv("BONL_FUZZ_VERBOSE") != nullptr;
  if (!verbose) return;
  for (const Field& f : kFields) std::fprintf(stderr, "  %s = %.17g\n", f.name, p.*f.member);
}

/// validate(): true when accepted; a rejection must be an invalid_argument naming a field.
/// With BONL_FUZZ_STATS set: how the inputs ended, printed at exit (docs/lab/fuzzing.md quotes them).
struct Outcomes {
  long rejected = 0, accepted = 0, simulated = 0, invalid_argument = 0, numerical_error = 0;
  ~Outcomes() {
    if (std::getenv("BONL_FUZZ_STATS") == nullptr) return;
    std::fprintf(stderr,
                 "outcomes: validate rejected %ld, accepted %ld; simulate returned %ld, threw invalid_argument %ld, "
                 "NumericalError %ld\n",
                 rejected, accepted, simulated, invalid_argument, numerical_error);
  }
} outcomes;

bool validates(const Parameters& p) {
  try {
    p.validate();
    return true;
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    const std::string prefix = "bonl: plant: ";
    bool names_field = false;
    if (message.rfind(prefix, 0) == 0) {
      for (const Field& f : kFields) names_field = names_field || message.rfind(prefix + f.name + ' ', 0) == 0;
    }
    if (!names_field) std::fprintf(stderr, "validate's message names no parameter: %s\n", message.c_str());
    FUZZ_CHECK(names_field);
    return false;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "validate threw something other than std::invalid_argument: %s\n", e.what());
    FUZZ_CHECK(false);
  }
  return false;
}

/// Accepted parameters are all finite (validate checks each one).
void check_accepted(const Parameters& p) {
  for (const Field& f : kFields) {
    if (!std::isfinite(p.*f.member)) std::fprintf(stderr, "accepted a non-finite %s\n", f.name);
    FUZZ_CHECK(std::isfinite(p.*f.member));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const Parameters p = decode(in);
  print(p);
  const bool accepted = validates(p);
  if (accepted) check_accepted(p);
  ++(accepted ? outcomes.accepted : outcomes.rejected);

  // A very short simulation: 5 command intervals, a command cycling through up to 4 voltages.
  bonl::plant::SimulationOptions options;
  options.duration = 0.005;
  options.sample_time = 0.001;
  options.tolerances.max_steps_per_interval = 500;
  options.sensor_noise = in.ConsumeBool();
  if (in.ConsumeBool()) options.initial_position = bonl_fuzz::any_double(in);
  std::array<double, 4> voltages{};
  bool finite_command = true;
  for (double& v : voltages) {
    v = in.ConsumeBool() ? 2.5 + 2.5 * bonl_fuzz::any_double(in) : bonl_fuzz::any_double(in);
    finite_command = finite_command && std::isfinite(v);
  }
  bool finite_load = true;
  if (in.ConsumeBool()) {
    const double load = bonl_fuzz::any_double(in) * 1e4;
    finite_load = std::isfinite(load);
    options.load = [load](double) { return load; };
  }
  const bool good_position = std::isfinite(options.initial_position) && options.initial_position <= p.stroke;
  // Checked before integrating: the parameters and the options. The command and the load are
  // functions of time, checked as the integration reaches each time (a non-finite state at t = 0,
  // from extreme but valid parameters, is found first).
  const bool must_reject = !accepted || !good_position;
  const bool may_reject = must_reject || !finite_command || !finite_load;
  if (std::getenv("BONL_FUZZ_VERBOSE") != nullptr) {
    std::fprintf(stderr, "  voltages = %.17g %.17g %.17g %.17g, load %s, initial_position = %.17g, noise %d\n",
                 voltages[0], voltages[1], voltages[2], voltages[3], options.load ? "set" : "none",
                 options.initial_position, int(options.sensor_noise));
  }
  const auto command = [voltages](double t) { return voltages[static_cast<std::size_t>(std::lround(t * 1000.0)) % 4]; };

  try {
    const bonl::plant::Trajectory out = bonl::plant::simulate(p, command, options);
    FUZZ_CHECK(!may_reject);
    ++outcomes.simulated;
    const std::pair<const char*, const Eigen::VectorXd*> columns[] = {{"time", &out.time},
                                                                      {"command", &out.command},
                                                                      {"input", &out.input},
                                                                      {"position", &out.position},
                                                                      {"velocity", &out.velocity},
                                                                      {"head_pressure", &out.head_pressure},
                                                                      {"rod_pressure", &out.rod_pressure},
                                                                      {"spool", &out.spool},
                                                                      {"pilot", &out.pilot},
                                                                      {"head_flow", &out.head_flow},
                                                                      {"rod_flow", &out.rod_flow},
                                                                      {"joint_angle", &out.joint_angle},
                                                                      {"joint_rate", &out.joint_rate},
                                                                      {"pin_angle", &out.pin_angle},
                                                                      {"measured_angle", &out.measured_angle}};
    for (const auto& [name, v] : columns) {
      FUZZ_CHECK(v->size() == 6);
      for (Eigen::Index k = 0; k < v->size(); ++k) {
        if (!std::isfinite((*v)[k])) std::fprintf(stderr, "simulate returned %s[%ld] = %g\n", name, long(k), (*v)[k]);
        FUZZ_CHECK(std::isfinite((*v)[k]));
      }
    }
    FUZZ_CHECK(std::isfinite(out.min_position) && std::isfinite(out.max_position));
    FUZZ_CHECK(out.min_position <= out.max_position);
  } catch (const std::invalid_argument& e) {
    ++outcomes.invalid_argument;
    if (!may_reject) std::fprintf(stderr, "simulate rejected valid input: %s\n", e.what());
    FUZZ_CHECK(may_reject);
  } catch (const bonl::NumericalError& e) {
    ++outcomes.numerical_error;
    if (must_reject) {  // bad parameters and options are reported as such, before any integration
      std::fprintf(stderr,
                   "simulate: NumericalError instead of invalid_argument (accepted %d, initial position %d): %s\n",
                   accepted, good_position, e.what());
    }
    FUZZ_CHECK(!must_reject);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "simulate threw something other than invalid_argument / NumericalError: %s\n", e.what());
    FUZZ_CHECK(false);
  }
  return 0;
}
