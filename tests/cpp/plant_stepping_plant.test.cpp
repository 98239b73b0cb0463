// Tests of include/bonl/plant/stepping_plant.hpp: the plant stepped one sample at a time against
// simulate (the same samples for the same command sequence: the paper's multi-sine held at 100 Hz
// and on the 1 kHz command grid, with and without sensor noise, with a load), reset, refused
// commands that leave the plant as it was, CVODE failures, moves. Bad options: plant_bad_input.

#include <bonl/plant/excitation.hpp>
#include <bonl/plant/simulator.hpp>
#include <bonl/plant/stepping_plant.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "test_support.hpp"

using bonl::plant::Measurement;
using bonl::plant::Parameters;
using bonl::plant::SimulationOptions;
using bonl::plant::SteppingPlant;
using bonl::plant::Trajectory;
namespace excitation = bonl::plant::excitation;

namespace {

/// The paper's multi-sine (excitation::paper_multisine) at t_k = k / rate, k = 0..n-1: the command
/// sequence, taken at the times simulate reads its command (the command grid's j / command_rate).
Eigen::VectorXd paper_commands(Eigen::Index n, double rate) {
  const bonl::plant::Command multisine = excitation::paper_multisine();
  Eigen::VectorXd values(n);
  for (Eigen::Index k = 0; k < n; ++k) values[k] = multisine(static_cast<double>(k) / rate);
  return values;
}

/// The largest difference between a measurement at t_k and simulate's sample k, relative to
/// max(1, |simulate's value|), over every field; the pilot against simulate's pilot[k - 1] (the
/// pilot after the command held over the step that ended at t_k).
double worst_difference(const Measurement& m, const Trajectory& r, Eigen::Index k) {
  const auto d = [](double a, double b) { return std::abs(a - b) / std::max(1.0, std::abs(b)); };
  double worst = std::max({d(m.time, r.time[k]), d(m.measured_angle, r.measured_angle[k]), d(m.position, r.position[k]),
                           d(m.velocity, r.velocity[k]), d(m.head_pressure, r.head_pressure[k]),
                           d(m.rod_pressure, r.rod_pressure[k]), d(m.spool, r.spool[k]), d(m.head_flow, r.head_flow[k]),
                           d(m.rod_flow, r.rod_flow[k]), d(m.joint_angle, r.joint_angle[k]),
                           d(m.joint_rate, r.joint_rate[k]), d(m.pin_angle, r.pin_angle[k])});
  if (k > 0) worst = std::max(worst, d(m.pilot, r.pilot[k - 1]));
  return worst;
}

/// Steps `plant` through `commands` and returns the worst difference from `r` over every sample.
double worst_difference(SteppingPlant& plant, const Eigen::VectorXd& commands, const Trajectory& r) {
  REQUIRE(r.time.size() == commands.size() + 1);
  double worst = worst_difference(plant.measurement(), r, 0);
  for (Eigen::Index k = 0; k < commands.size(); ++k) {
    worst = std::max(worst, worst_difference(plant.step(commands[k]), r, k + 1));
  }
  return worst;
}

bool same(const Measurement& a, const Measurement& b) {
  return a.time == b.time && a.measured_angle == b.measured_angle && a.position == b.position &&
         a.velocity == b.velocity && a.head_pressure == b.head_pressure && a.rod_pressure == b.rod_pressure &&
         a.spool == b.spool && a.pilot == b.pilot && a.head_flow == b.head_flow && a.rod_flow == b.rod_flow &&
         a.joint_angle == b.joint_angle && a.joint_rate == b.joint_rate && a.pin_angle == b.pin_angle &&
         a.reached_end_stop == b.reached_end_stop;
}

/// A short, varied command: the paper's multi-sine at 100 Hz.
const Eigen::VectorXd& short_commands() {
  static const Eigen::VectorXd commands = paper_commands(200, 100.0);
  return commands;
}

}  // namespace

TEST_CASE("stepping equals simulate on the paper's multi-sine held at 100 Hz, with and without noise") {
  // The paper's experiment: 50 s at Ts = 0.01 s; each sample's command held over the sample, which
  // simulate gets as excitation::sampled(commands, Ts).
  const Eigen::VectorXd commands = paper_commands(5000, 100.0);
  for (const bool noise : {false, true}) {
    SimulationOptions options;
    options.sensor_noise = noise;
    const Trajectory r = bonl::plant::simulate(Parameters{}, excitation::sampled(commands, 0.01), options);
    SteppingPlant plant(Parameters{}, options);
    const double worst = worst_difference(plant, commands, r);
    INFO("noise " << noise << ": worst relative difference " << worst);
    CHECK(worst <= 1e-12);
    CHECK(plant.time() == 50.0);
    CHECK(plant.steps() == r.steps);
    if (noise) {
      // The noise is there, with the parameters' standard deviation (5000 draws: within 5%).
      const Eigen::VectorXd e = r.measured_angle - r.pin_angle;
      CHECK(std::abs(bonl_test::standard_deviation(e) / Parameters{}.sensor_noise - 1.0) < 0.05);
    }
  }
}

TEST_CASE("stepping equals simulate on the paper's multi-sine on the 1 kHz command grid") {
  // A sample per command interval: simulate evaluates the multi-sine itself at every grid point.
  SimulationOptions options;
  options.duration = 5.0;
  options.sample_time = 0.001;
  const Eigen::VectorXd commands = paper_commands(5000, 1000.0);
  const Trajectory r = bonl::plant::simulate(Parameters{}, excitation::paper_multisine(), options);
  SteppingPlant plant(Parameters{}, options);
  const double worst = worst_difference(plant, commands, r);
  INFO("worst relative difference " << worst);
  CHECK(worst <= 1e-12);
  CHECK(r.command.head(5000) == commands);
}

TEST_CASE("stepping equals simulate under a load that changes within a sample") {
  // A load step at 0.125 s (between the samples 0.12 and 0.13 s) and a ramp from 0.5 s: CVODE stops
  // at every change, in both.
  SimulationOptions options;
  options.duration = 2.0;
  options.load = [](double t) { return t < 0.125 ? 0.0 : (t < 0.5 ? 3e4 : 3e4 + 1e5 * (t - 0.5)); };
  const Eigen::VectorXd& commands = short_commands();
  const Trajectory r = bonl::plant::simulate(Parameters{}, excitation::sampled(commands, 0.01), options);
  SteppingPlant plant(Parameters{}, options);
  const double worst = worst_difference(plant, commands, r);
  INFO("worst relative difference " << worst);
  CHECK(worst <= 1e-12);
  // ... and the load acts: without it the piston ends elsewhere.
  SimulationOptions unloaded = options;
  unloaded.load = nullptr;
  SteppingPlant free_plant(Parameters{}, unloaded);
  for (Eigen::Index k = 0; k < commands.size(); ++k) free_plant.step(commands[k]);
  CHECK(std::abs(free_plant.measurement().position - plant.measurement().position) > 1e-3);
}

TEST_CASE("the first measurement is the initial state at t = 0") {
  const Parameters p;
  SimulationOptions options;
  options.initial_position = 0.3;
  options.sensor_noise = false;
  const SteppingPlant plant(p, options);
  const Measurement& m = plant.measurement();
  const bonl::plant::State s = bonl::plant::initial_state(p, 0.3);
  CHECK(m.time == 0.0);
  CHECK(m.position == s.position);
  CHECK(m.velocity == 0.0);
  CHECK(m.head_pressure == s.head_pressure);
  CHECK(m.rod_pressure == s.rod_pressure);
  CHECK(m.spool == 0.0);
  CHECK(m.pilot == 0.0);
  CHECK(m.joint_angle == p.joint_angle(0.3));
  CHECK(m.pin_angle == m.joint_angle);
  CHECK(m.measured_angle == m.pin_angle);
  CHECK_FALSE(m.reached_end_stop);
  CHECK(plant.time() == 0.0);
}

TEST_CASE("reset starts again: the same commands give the same measurements") {
  SteppingPlant plant(Parameters{});
  std::vector<Measurement> first;
  for (Eigen::Index k = 0; k < short_commands().size(); ++k) first.push_back(plant.step(short_commands()[k]));
  const long steps = plant.steps();
  const Measurement start = plant.reset();
  CHECK(start.time == 0.0);
  CHECK(plant.time() == 0.0);
  CHECK(same(start, SteppingPlant(Parameters{}).measurement()));
  for (Eigen::Index k = 0; k < short_commands().size(); ++k) {
    CHECK(same(plant.step(short_commands()[k]), first[static_cast<std::size_t>(k)]));
  }
  CHECK(plant.steps() == steps);
}

TEST_CASE("reset to another position and seed equals a plant built with them") {
  SteppingPlant plant(Parameters{});
  plant.step(3.0);
  const Measurement start = plant.reset(0.4, 7);
  CHECK(plant.options().initial_position == 0.4);
  CHECK(plant.options().noise_seed == 7);
  SimulationOptions options;
  options.initial_position = 0.4;
  options.noise_seed = 7;
  SteppingPlant fresh(Parameters{}, options);
  CHECK(same(start, fresh.measurement()));
  CHECK(start.position == 0.4);
  for (Eigen::Index k = 0; k < 50; ++k) CHECK(same(plant.step(short_commands()[k]), fresh.step(short_commands()[k])));
  // reset() now starts from there again; a bad position changes nothing.
  CHECK(same(plant.reset(), SteppingPlant(Parameters{}, options).measurement()));
  CHECK_THROWS_AS(plant.reset(std::numeric_limits<double>::quiet_NaN(), 1), std::invalid_argument);
  CHECK(plant.options().initial_position == 0.4);
  CHECK(plant.time() == 0.0);
}

TEST_CASE("a refused command leaves the plant as it was") {
  // Two plants stepped alike; one is also given non-finite commands, which it refuses. After that
  // both go on alike, sensor noise included (no noise was drawn for the refused steps).
  SteppingPlant plant(Parameters{});
  SteppingPlant twin(Parameters{});
  for (Eigen::Index k = 0; k < 50; ++k) {
    plant.step(short_commands()[k]);
    twin.step(short_commands()[k]);
  }
  const Measurement before = plant.measurement();
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()}) {
    CHECK_THROWS_WITH(plant.step(bad), Catch::Matchers::Contains("bonl: SteppingPlant: command must be finite, got"));
    CHECK_THROWS_AS(plant.step(bad), std::invalid_argument);
  }
  CHECK(same(plant.measurement(), before));
  CHECK(plant.steps() == twin.steps());
  for (Eigen::Index k = 50; k < 100; ++k) CHECK(same(plant.step(short_commands()[k]), twin.step(short_commands()[k])));
}

TEST_CASE("a load that is not finite is refused before the plant moves") {
  // The load is NaN the first time it is read at 0.204 s (a glitch), finite after: the step that
  // reads it throws and leaves the plant as it was; the retry equals a plant that never saw it.
  const auto load = [](double t) { return 1e4 * std::sin(3.0 * t); };
  SimulationOptions glitching;
  auto glitched = std::make_shared<bool>(false);
  glitching.load = [load, glitched](double t) {
    if (t >= 0.204 && !*glitched) {
      *glitched = true;
      return std::numeric_limits<double>::quiet_NaN();
    }
    return load(t);
  };
  SimulationOptions steady;
  steady.load = load;
  SteppingPlant plant(Parameters{}, glitching);
  SteppingPlant twin(Parameters{}, steady);
  for (Eigen::Index k = 0; k < 20; ++k) CHECK(same(plant.step(short_commands()[k]), twin.step(short_commands()[k])));
  const Measurement before = plant.measurement();
  CHECK_THROWS_WITH(plant.step(short_commands()[20]),
                    Catch::Matchers::Contains("bonl: SteppingPlant: the load is not finite at t = 0.204 s, got nan"));
  CHECK(same(plant.measurement(), before));
  for (Eigen::Index k = 20; k < 40; ++k) CHECK(same(plant.step(short_commands()[k]), twin.step(short_commands()[k])));
}

TEST_CASE("a CVODE failure leaves the plant failed until reset") {
  SimulationOptions options;
  options.tolerances.max_steps_per_interval = 1;
  SteppingPlant plant(Parameters{}, options);
  bool failed = false;
  for (int k = 0; k < 100 && !failed; ++k) {
    try {
      plant.step(4.0);
    } catch (const bonl::plant::CvodeError& e) {
      failed = true;
      CHECK_THAT(std::string(e.what()),
                 Catch::Matchers::Contains("bonl: SteppingPlant: CVode failed with CV_TOO_MUCH_WORK"));
    }
  }
  REQUIRE(failed);
  CHECK_THROWS_AS(plant.step(2.5), std::logic_error);
  CHECK_THROWS_WITH(plant.step(2.5), Catch::Matchers::Contains("reset() it"));
  CHECK(plant.reset().time == 0.0);
}

TEST_CASE("an end stop reached within a step is reported with that step") {
  // Full command from mid-stroke: the piston reaches the stroke's end within 3 s (0.4 m/s).
  const Parameters p;
  SimulationOptions options;
  options.duration = 3.0;
  options.sensor_noise = false;
  const Trajectory r = bonl::plant::simulate(p, excitation::step(5.0), options);
  REQUIRE(r.reached_end_stop);
  SteppingPlant plant(p, options);
  bool any = false;
  for (int k = 0; k < 300; ++k) {
    const Measurement m = plant.step(5.0);
    if (m.position > p.stroke) CHECK(m.reached_end_stop);
    any = any || m.reached_end_stop;
  }
  CHECK(any);
}

TEST_CASE("a moved plant goes on where it was, and the moved-from one says so") {
  SteppingPlant plant(Parameters{});
  SteppingPlant twin(Parameters{});
  for (Eigen::Index k = 0; k < 30; ++k) {
    plant.step(short_commands()[k]);
    twin.step(short_commands()[k]);
  }
  SteppingPlant moved(std::move(plant));
  for (Eigen::Index k = 30; k < 60; ++k) CHECK(same(moved.step(short_commands()[k]), twin.step(short_commands()[k])));
  CHECK_THROWS_AS(plant.step(2.5), std::logic_error);  // NOLINT(bugprone-use-after-move): what it says is the test
  SteppingPlant assigned(Parameters{});
  assigned = std::move(moved);
  CHECK(same(assigned.measurement(), twin.measurement()));
}

TEST_CASE("parameters changed at t = 0 equal a plant built with them") {
  // The oracle: a plant that had the changed parameters from the start. The rest state depends on
  // neither parameter changed here (bulk modulus, pilot hysteresis), so the two start alike, and
  // CVODE's restart at t = 0 is its start.
  Parameters changed;
  changed.bulk_modulus *= 0.7;
  changed.pilot_hysteresis *= 2.0;
  SteppingPlant plant(Parameters{});
  plant.set_parameters(changed);
  SteppingPlant twin(changed);
  CHECK(same(plant.measurement(), twin.measurement()));
  double worst = 0.0;
  for (Eigen::Index k = 0; k < short_commands().size(); ++k) {
    const Measurement a = plant.step(short_commands()[k]);
    const Measurement b = twin.step(short_commands()[k]);
    worst = std::max({worst, std::abs(a.joint_angle - b.joint_angle), std::abs(a.measured_angle - b.measured_angle)});
  }
  CHECK(worst <= 1e-12);
  CHECK(plant.parameters().bulk_modulus == changed.bulk_modulus);
}

TEST_CASE("parameters changed mid-run keep the state and change the dynamics from then on") {
  SteppingPlant plant(Parameters{});
  SteppingPlant unchanged(Parameters{});
  SteppingPlant restarted(Parameters{});  // set_parameters with the same values: only CVODE's restart
  for (Eigen::Index k = 0; k < 100; ++k) {
    plant.step(short_commands()[k]);
    unchanged.step(short_commands()[k]);
    restarted.step(short_commands()[k]);
  }
  const Measurement before = plant.measurement();
  Parameters changed;
  changed.bulk_modulus *= 0.7;
  changed.pilot_hysteresis *= 2.0;
  plant.set_parameters(changed);
  restarted.set_parameters(Parameters{});
  CHECK(same(plant.measurement(), before));
  double restart_difference = 0.0;
  double change_difference = 0.0;
  for (Eigen::Index k = 100; k < 200; ++k) {
    const double reference = unchanged.step(short_commands()[k]).joint_angle;
    restart_difference =
        std::max(restart_difference, std::abs(restarted.step(short_commands()[k]).joint_angle - reference));
    change_difference = std::max(change_difference, std::abs(plant.step(short_commands()[k]).joint_angle - reference));
  }
  INFO("restart " << restart_difference << ", change " << change_difference);
  // CVODE's restart alone moves the angle by about its tolerance; the new parameters by far more.
  CHECK(restart_difference < 1e-5);
  CHECK(change_difference > 100 * restart_difference);
  CHECK(change_difference > 1e-4);
}

TEST_CASE("a doubled pilot hysteresis holds the pilot over the new width") {
  // The play operator's oracle: after a rise the pilot holds while the commanded opening comes back
  // by less than hv and follows beyond it. Coming back by 1.5 times the old hv moves the old pilot
  // and holds the new one.
  Parameters p;
  SimulationOptions options;
  options.sensor_noise = false;
  SteppingPlant old_plant(p, options);
  SteppingPlant new_plant(p, options);
  Parameters doubled = p;
  doubled.pilot_hysteresis *= 2.0;
  new_plant.set_parameters(doubled);
  const double up = 3.5;  // V: opening kv (3.5 - 2.5 - d)
  const double back = up - 1.5 * p.pilot_hysteresis / p.valve_gain();
  old_plant.step(up);
  new_plant.step(up);
  const double held = old_plant.step(up).pilot;
  CHECK(new_plant.step(up).pilot == Approx(held));
  old_plant.step(back);
  new_plant.step(back);
  CHECK(old_plant.measurement().pilot < held - 1e-3);
  CHECK(new_plant.measurement().pilot == Approx(held));
}

TEST_CASE("set_parameters refuses non-physical values and another linkage, and changes nothing") {
  SteppingPlant plant(Parameters{});
  SteppingPlant twin(Parameters{});
  for (Eigen::Index k = 0; k < 50; ++k) {
    plant.step(short_commands()[k]);
    twin.step(short_commands()[k]);
  }
  Parameters bad;
  bad.bulk_modulus = -1.0;
  CHECK_THROWS_AS(plant.set_parameters(bad), std::invalid_argument);
  bad = Parameters{};
  bad.bulk_modulus = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(plant.set_parameters(bad), std::invalid_argument);
  for (const auto member : {&Parameters::stroke, &Parameters::pivot_to_rod_pin, &Parameters::pivot_to_base_pin,
                            &Parameters::retracted_length}) {
    Parameters other;
    other.*member *= 1.01;
    CHECK_THROWS_WITH(plant.set_parameters(other), Catch::Matchers::Contains("cannot change while the plant runs"));
  }
  CHECK(plant.parameters().bulk_modulus == Parameters{}.bulk_modulus);
  for (Eigen::Index k = 50; k < 100; ++k) CHECK(same(plant.step(short_commands()[k]), twin.step(short_commands()[k])));
}
