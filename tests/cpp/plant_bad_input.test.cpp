// Bad input to the plant (bonl::plant), the P rows of docs/reference/bad_input.md; the rest of the table is
// in bad_input.test.cpp, the experiment's (P1 acquire, P16-P17) in experiment_bad_input.test.cpp. A
// separate file because only tests/cpp/plant_*.test.cpp link bonl::plant.
// Every case checks the exception's type and that its message names what was wrong; the last case
// checks that the caller's arrays are never modified.

#include <bonl/plant/excitation.hpp>
#include <bonl/plant/parameters.hpp>
#include <bonl/plant/simulator.hpp>
#include <bonl/plant/stepping_plant.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bad_input_cases.hpp"

namespace {

using Catch::Matchers::Contains;
namespace plant = bonl::plant;
namespace excitation = bonl::plant::excitation;

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

using bonl_test::Case;
using bonl_test::check_cases;

/// A short run: 0.05 s.
plant::SimulationOptions short_run() {
  plant::SimulationOptions options;
  options.duration = 0.05;
  return options;
}

void simulate_with(const plant::Parameters& parameters) {
  plant::simulate(parameters, excitation::step(3.0), short_run());
}

template <class F>
void simulate_with_options(F&& change) {
  plant::SimulationOptions options = short_run();
  change(options);
  plant::simulate(plant::Parameters{}, excitation::step(3.0), options);
}

}  // namespace

TEST_CASE("P1-P3 simulate rejects non-physical parameters, naming them", "[bad_input][plant]") {
  using P = plant::Parameters;
  const auto with = [](double P::*member, double value) {
    P p;
    p.*member = value;
    return p;
  };
  std::vector<Case> cases;
  const std::vector<std::pair<const char*, double P::*>> positive = {
      {"bore_diameter", &P::bore_diameter}, {"mass", &P::mass},
      {"bulk_modulus", &P::bulk_modulus},   {"valve_time_constant", &P::valve_time_constant},
      {"max_voltage", &P::max_voltage},     {"retracted_length", &P::retracted_length},
  };
  for (const auto& [name, member] : positive) {
    for (double bad : {0.0, -1.0, kNaN, kInf}) {
      const P p = with(member, bad);
      cases.push_back({std::string("P1 ") + name + " = " + std::to_string(bad), [p] { simulate_with(p); },
                       std::string("bonl: plant: ") + name + " must be > 0 and finite"});
    }
  }
  const std::vector<std::pair<const char*, double P::*>> non_negative = {
      {"coulomb_friction", &P::coulomb_friction},
      {"internal_leakage", &P::internal_leakage},
      {"joint_backlash", &P::joint_backlash},
      {"sensor_noise", &P::sensor_noise},
  };
  for (const auto& [name, member] : non_negative) {
    for (double bad : {-1e-9, kNaN, -kInf}) {
      const P p = with(member, bad);
      cases.push_back({std::string("P2 ") + name + " = " + std::to_string(bad), [p] { simulate_with(p); },
                       std::string("bonl: plant: ") + name + " must be >= 0 and finite"});
    }
  }
  const std::vector<std::tuple<const char*, double P::*, double, const char*>> relations = {
      {"rod as wide as the bore", &P::rod_diameter, 0.140, "rod_diameter must be < bore_diameter"},
      {"supply below return", &P::supply_pressure, 0.2e6, "supply_pressure must be > return_pressure"},
      {"neutral at the top", &P::neutral_voltage, 5.0, "neutral_voltage must be < max_voltage"},
      {"dead band past neutral", &P::dead_band, 2.5, "dead_band must be < neutral_voltage"},
      {"hysteresis of a full opening", &P::pilot_hysteresis, 1.0, "pilot_hysteresis must be < 1"},
      {"linkage too long", &P::stroke, 5.0, "stroke must satisfy retracted_length + stroke < pivot_to_rod_pin"},
      {"gravity angle NaN", &P::gravity_angle_offset, kNaN, "gravity_angle_offset must be finite"},
  };
  for (const auto& [what, member, value, message] : relations) {
    const P p = with(member, value);
    cases.push_back({std::string("P3 ") + what, [p] { simulate_with(p); }, message});
  }
  check_cases<std::invalid_argument>(cases);
}

TEST_CASE("P5-P11 simulate rejects bad options and commands, naming them", "[bad_input][plant]") {
  check_cases<std::invalid_argument>({
      {"P5 duration 0", [] { simulate_with_options([](auto& o) { o.duration = 0.0; }); },
       "bonl: simulate: duration must be > 0 and finite, got 0"},
      {"P5 duration -1", [] { simulate_with_options([](auto& o) { o.duration = -1.0; }); },
       "duration must be > 0 and finite"},
      {"P5 duration NaN", [] { simulate_with_options([](auto& o) { o.duration = kNaN; }); },
       "duration must be > 0 and finite"},
      {"P5 duration inf", [] { simulate_with_options([](auto& o) { o.duration = kInf; }); },
       "duration must be > 0 and finite"},
      {"P5 duration 0.015", [] { simulate_with_options([](auto& o) { o.duration = 0.015; }); },
       "duration must be an integer multiple of sample_time"},
      {"P6 sample_time 0", [] { simulate_with_options([](auto& o) { o.sample_time = 0.0; }); },
       "sample_time must be > 0 and finite"},
      {"P6 sample_time NaN", [] { simulate_with_options([](auto& o) { o.sample_time = kNaN; }); },
       "sample_time must be > 0 and finite"},
      {"P6 sample_time off the command grid", [] { simulate_with_options([](auto& o) { o.sample_time = 0.0015; }); },
       "sample_time must be an integer multiple of 1 / command_rate"},
      {"P6 sample_time > duration", [] { simulate_with_options([](auto& o) { o.sample_time = 0.1; }); },
       "duration must be an integer multiple of sample_time"},
      {"P7 command_rate 0", [] { simulate_with_options([](auto& o) { o.command_rate = 0.0; }); },
       "command_rate must be > 0 and finite"},
      {"P7 command_rate -inf", [] { simulate_with_options([](auto& o) { o.command_rate = -kInf; }); },
       "command_rate must be > 0 and finite"},
      {"P8 relative tolerance 0", [] { simulate_with_options([](auto& o) { o.tolerances.relative = 0.0; }); },
       "tolerances.relative must be > 0 and finite"},
      {"P8 position tolerance NaN",
       [] { simulate_with_options([](auto& o) { o.tolerances.absolute_position = kNaN; }); },
       "tolerances.absolute_position must be > 0 and finite"},
      {"P8 pressure tolerance -1",
       [] { simulate_with_options([](auto& o) { o.tolerances.absolute_pressure = -1.0; }); },
       "tolerances.absolute_pressure must be > 0 and finite"},
      {"P8 relative tolerance 1", [] { simulate_with_options([](auto& o) { o.tolerances.relative = 1.0; }); },
       "tolerances.relative must be < 1, got 1"},
      // Before: a segmentation fault (the integer grid counts overflowed), garbage arrays, or a hang.
      {"P21 duration 1e19", [] { simulate_with_options([](auto& o) { o.duration = 1e19; }); },
       "duration gives 1e+22 command intervals (duration * command_rate); at most 1e+08"},
      {"P21 duration 1e6 s at 1 kHz", [] { simulate_with_options([](auto& o) { o.duration = 1e6; }); },
       "duration gives 1e+09 command intervals"},
      {"P21 command_rate 1e300",
       [] {
         simulate_with_options([](auto& o) {
           o.command_rate = 1e300;
           o.sample_time = 1e-300;
         });
       },
       "command intervals (duration * command_rate); at most"},
      {"P8 max_steps_per_interval 0",
       [] { simulate_with_options([](auto& o) { o.tolerances.max_steps_per_interval = 0; }); },
       "tolerances.max_steps_per_interval must be >= 1"},
      {"P9 initial_position NaN", [] { simulate_with_options([](auto& o) { o.initial_position = kNaN; }); },
       "initial_position must be finite and <= stroke"},
      {"P9 initial_position beyond the stroke",
       [] { simulate_with_options([](auto& o) { o.initial_position = 1.6; }); },
       "initial_position must be finite and <= stroke (1.5 m)"},
      {"P10 empty command", [] { plant::simulate(plant::Parameters{}, plant::Command{}, short_run()); },
       "bonl: simulate: command must not be empty"},
      {"P11 command NaN after 0.02 s",
       [] {
         plant::simulate(
             plant::Parameters{}, [](double t) { return t < 0.02 ? 2.5 : kNaN; }, short_run());
       },
       "the command is not finite at t = 0.02"},
      {"P11 load inf", [] { simulate_with_options([](auto& o) { o.load = [](double) { return kInf; }; }); },
       "the load is not finite at t = 0 s, got inf"},
  });
  // A negative initial position means mid-stroke (the documented default), not an error.
  plant::SimulationOptions options = short_run();
  options.initial_position = -5.0;
  CHECK(plant::simulate(plant::Parameters{}, excitation::step(2.5), options).position[0] == 0.75);
}

TEST_CASE("P22 SteppingPlant rejects what simulate rejects, with simulate's messages", "[bad_input][plant]") {
  // Every option simulate checks except the duration (a stepping plant has none): the same message,
  // from "bonl: SteppingPlant: " instead of "bonl: simulate: ".
  const std::vector<std::function<void(plant::SimulationOptions&)>> changes = {
      [](auto& o) { o.sample_time = 0.0; },
      [](auto& o) { o.sample_time = kNaN; },
      [](auto& o) { o.sample_time = 0.0015; },
      [](auto& o) { o.command_rate = -kInf; },
      [](auto& o) { o.tolerances.relative = 1.0; },
      [](auto& o) { o.tolerances.absolute_velocity = 0.0; },
      [](auto& o) { o.tolerances.absolute_spool = kNaN; },
      [](auto& o) { o.tolerances.max_steps_per_interval = 0; },
      [](auto& o) { o.initial_position = 1.6; },
      [](auto& o) { o.initial_position = kInf; },
  };
  const auto message = [](const std::function<void()>& call) {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("nothing thrown");
  };
  for (const auto& change : changes) {
    plant::SimulationOptions options = short_run();
    change(options);
    std::string expected = message([&] { plant::simulate(plant::Parameters{}, excitation::step(3.0), options); });
    REQUIRE(expected.rfind("bonl: simulate: ", 0) == 0);
    expected.replace(0, std::string("bonl: simulate: ").size(), "bonl: SteppingPlant: ");
    CHECK(message([&] { plant::SteppingPlant(plant::Parameters{}, options); }) == expected);
  }
  plant::Parameters heavy;
  heavy.mass = -1.0;
  check_cases<std::invalid_argument>({
      {"P22 parameters", [heavy] { plant::SteppingPlant{heavy}; }, "bonl: plant: mass must be > 0 and finite"},
      {"P22 a sample of 1e9 command intervals",
       [] {
         plant::SimulationOptions options;
         options.sample_time = 1e6;
         plant::SteppingPlant(plant::Parameters{}, options);
       },
       "bonl: SteppingPlant: sample_time gives 1e+09 command intervals per sample (sample_time * command_rate); at "
       "most 1e+08"},
  });
  // The duration is not the stepping plant's: any value is ignored.
  plant::SimulationOptions options;
  options.duration = kNaN;
  CHECK(plant::SteppingPlant(plant::Parameters{}, options).time() == 0.0);
}

TEST_CASE("P23-P26 SteppingPlant refuses bad commands, loads and positions and says when it must be reset",
          "[bad_input][plant]") {
  // Each refusal of bad input leaves the plant where it was (plant_stepping_plant checks the steps after).
  plant::SteppingPlant stepping(plant::Parameters{});
  stepping.step(3.0);
  check_cases<std::invalid_argument>({
      {"P23 command NaN", [&] { stepping.step(kNaN); }, "bonl: SteppingPlant: command must be finite, got nan"},
      {"P23 command -inf", [&] { stepping.step(-kInf); }, "bonl: SteppingPlant: command must be finite, got -inf"},
      {"P24 load inf",
       [] {
         plant::SimulationOptions options;
         options.load = [](double t) { return t < 0.015 ? 0.0 : kInf; };
         plant::SteppingPlant loaded(plant::Parameters{}, options);
         loaded.step(3.0);
         loaded.step(3.0);
       },
       "bonl: SteppingPlant: the load is not finite at t = 0.015 s, got inf"},
      {"P26 reset to NaN", [&] { stepping.reset(kNaN, 1); },
       "bonl: SteppingPlant: initial_position must be finite and <= stroke"},
      {"P26 reset beyond the stroke", [&] { stepping.reset(2.0, 1); },
       "initial_position must be finite and <= stroke (1.5 m)"},
  });
  CHECK(stepping.time() == 0.01);
  plant::SimulationOptions options;
  options.tolerances.max_steps_per_interval = 1;
  plant::SteppingPlant failing(plant::Parameters{}, options);
  CHECK_THROWS_AS(failing.step(4.0), plant::CvodeError);
  plant::SteppingPlant moved_from(plant::Parameters{});
  plant::SteppingPlant(std::move(moved_from)).step(2.5);
  check_cases<std::logic_error>({
      {"P25 a step after a failed one", [&] { failing.step(2.5); },
       "bonl: SteppingPlant: a step failed at t = 0 s and left the plant between samples; reset() it"},
      {"P25 a moved-from plant", [&] { moved_from.step(2.5); },  // NOLINT(bugprone-use-after-move): the test
       "bonl: SteppingPlant: used after it was moved from"},
  });
}

TEST_CASE("P13-P15 excitation generators reject bad arguments, naming them", "[bad_input][plant]") {
  check_cases<std::invalid_argument>({
      {"P13 step level NaN", [] { excitation::step(kNaN); }, "bonl: excitation::step: level must be finite"},
      {"P13 step t_step inf", [] { excitation::step(3.0, kInf); }, "step: t_step must be finite"},
      {"P13 multisine no tones", [] { excitation::multisine({}, 0.4); }, "multisine: frequencies_hz must not be empty"},
      {"P13 multisine negative tone",
       [] {
         excitation::multisine({0.1, -1.0}, 0.4);
       },
       "frequencies_hz must be finite and >= 0, got -1 at index 1"},
      {"P13 multisine phases length",
       [] {
         excitation::multisine({0.1, 0.2}, 0.4, 2.5, {0.0});
       },
       "phases must be empty or have as many entries as frequencies_hz (2), got 1"},
      {"P13 multisine phase NaN", [] { excitation::multisine({0.1}, 0.4, 2.5, {kNaN}); },
       "phases has a non-finite value at index 0"},
      {"P13 multisine amplitude inf", [] { excitation::multisine({0.1}, kInf); },
       "multisine: amplitude must be finite"},
      {"P13 paper_multisine offset NaN", [] { excitation::paper_multisine(0.4, kNaN); },
       "paper_multisine: offset must be finite"},
      {"P13 chirp duration 0", [] { excitation::chirp(0.1, 1.0, 0.0, 0.4); }, "chirp: duration must be finite and > 0"},
      {"P13 chirp f1 < 0", [] { excitation::chirp(0.1, -1.0, 10.0, 0.4); }, "chirp: f1_hz must be finite and >= 0"},
      {"P14 smooth_random below one tone", [] { excitation::smooth_random(0.1, 0.5, 1.0, 1); },
       "smooth_random: bandwidth_hz * duration must be >= 1"},
      // Before: std::bad_alloc (10^18 tones), or a command too slow to ever finish a simulation.
      {"P14 smooth_random 10^18 tones", [] { excitation::smooth_random(1e9, 0.5, 1e9, 1); },
       "smooth_random: bandwidth_hz * duration must be <= 1000000 (one sine per tone and call)"},
      {"P14 smooth_random rms < 0", [] { excitation::smooth_random(1.0, -0.5, 10.0, 1); },
       "rms must be finite and >= 0"},
      {"P14 smooth_random duration NaN", [] { excitation::smooth_random(1.0, 0.5, kNaN, 1); },
       "duration must be finite and > 0"},
      {"P15 sampled empty", [] { excitation::sampled(Eigen::VectorXd(0), 0.01); }, "sampled: values must not be empty"},
      {"P15 sampled NaN", [] { excitation::sampled(Eigen::Vector3d(2.5, kNaN, 2.5), 0.01); },
       "sampled: values has a non-finite value at index 1"},
      {"P15 sampled ts 0", [] { excitation::sampled(Eigen::Vector3d(2.5, 3.0, 2.5), 0.0); },
       "sampled: ts must be finite and > 0"},
      {"P15 sampled t0 inf", [] { excitation::sampled(Eigen::Vector3d(2.5, 3.0, 2.5), 0.01, kInf); },
       "sampled: t0 must be finite"},
  });
  // The tone limit itself is accepted.
  CHECK(std::isfinite(excitation::smooth_random(10.0, 0.5, 1e5, 1)(0.5)));
}

TEST_CASE("A2 the plant's entry points never modify the caller's arrays", "[bad_input][plant][arrays]") {
  Eigen::VectorXd x(6);
  x << 0.0, 0.3, 0.2, 0.8, 0.5, 1.0;
  const Eigen::VectorXd before = x;
  const plant::Command held = excitation::sampled(x, 0.01);
  x[0] = 7.0;  // the command holds its own copy: changing x afterwards does not change it
  CHECK(held(0.0) == 0.0);
  x[0] = 0.0;
  CHECK(std::memcmp(x.data(), before.data(), sizeof(double) * 6) == 0);
  std::vector<double> tones = {0.1, 0.2}, phases = {0.5, 1.0};
  const std::vector<double> tones_before = tones, phases_before = phases;
  excitation::multisine(tones, 0.4, 2.5, phases);
  CHECK(tones == tones_before);
  CHECK(phases == phases_before);
}
