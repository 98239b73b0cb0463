// Tests of include/bonl/plant/simulator.hpp: the CVODE plant against conservation of mass, plant.md's
// expected behaviour, an independent fixed-step integrator, tolerance refinement, bad input and
// determinism. All runs use the 20 t defaults unless stated.

#include <bonl/blocks/backlash.hpp>
#include <bonl/plant/excitation.hpp>
#include <bonl/plant/simulator.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <random>
#include <string>

#include "../../src/plant/model.hpp"  // private to bonl_plant: the exact Jacobian it hands CVODE
#include "test_support.hpp"

using bonl::plant::Parameters;
using bonl::plant::SimulationOptions;
using bonl::plant::Trajectory;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The paper's multi-sine: 2.5 + 0.4 sum_k sin(2 pi f_k t + phi_k), phi_k = -pi k (k + 1) / 5.
double paper_multisine(double t) {
  constexpr double frequencies[5] = {0.1, 0.2, 0.4, 0.5, 1.0};
  double sum = 0.0;
  for (int k = 1; k <= 5; ++k) sum += std::sin(2.0 * kPi * frequencies[k - 1] * t - kPi * k * (k + 1) / 5.0);
  return 2.5 + 0.4 * sum;
}

/// The default experiment (50 s multi-sine at 100 Hz from mid-stroke), computed once.
const Trajectory& default_run() {
  static const Trajectory run = bonl::plant::simulate(Parameters{}, paper_multisine);
  return run;
}

bool all_finite(const Trajectory& r) {
  for (const Eigen::VectorXd* v :
       {&r.time, &r.command, &r.input, &r.position, &r.velocity, &r.head_pressure, &r.rod_pressure, &r.spool, &r.pilot,
        &r.head_flow, &r.rod_flow, &r.joint_angle, &r.joint_rate, &r.pin_angle, &r.measured_angle}) {
    if (!v->allFinite()) return false;
  }
  return true;
}

/// Mean piston speed over [t0, t1] from the positions (a finite difference of h).
double mean_speed(const Trajectory& r, double t0, double t1, double sample_time) {
  const auto k0 = static_cast<Eigen::Index>(std::lround(t0 / sample_time));
  const auto k1 = static_cast<Eigen::Index>(std::lround(t1 / sample_time));
  return (r.position[k1] - r.position[k0]) / (t1 - t0);
}

Trajectory constant_command(double voltage, double duration, double sample_time = 0.01) {
  SimulationOptions options;
  options.duration = duration;
  options.sample_time = sample_time;
  options.sensor_noise = false;
  return bonl::plant::simulate(
      Parameters{}, [voltage](double) { return voltage; }, options);
}

/// Worst differences between CVODE's trajectory `r` (1 ms output grid, no sensor noise) and RK4 on
/// derivative() with 100 steps per 1 ms command interval, the pilot play evaluated the same way
/// (engaged at t = 0) and the load held per interval: an oracle independent of CVODE.
struct Rk4Differences {
  double position = 0.0, velocity = 0.0, head_pressure = 0.0;
};
template <typename Command, typename Load>
Rk4Differences rk4_differences(const Parameters& p, Command command, Load load, const Trajectory& r, int intervals) {
  bonl::plant::State s = bonl::plant::initial_state(p, 0.5 * p.stroke);
  const auto opening = [&](double v) {
    const double e = std::clamp(v, 0.0, p.max_voltage) - p.neutral_voltage;
    return std::copysign(std::max(std::abs(e) - p.dead_band, 0.0), e) * p.valve_gain();
  };
  const auto axpy = [](const bonl::plant::State& x, double a, const bonl::plant::State& d) {
    bonl::plant::State y;
    y.position = x.position + a * d.position;
    y.velocity = x.velocity + a * d.velocity;
    y.head_pressure = x.head_pressure + a * d.head_pressure;
    y.rod_pressure = x.rod_pressure + a * d.rod_pressure;
    y.spool = x.spool + a * d.spool;
    return y;
  };
  double pilot = opening(command(0.0));
  const int substeps = 100;
  const double h = 1e-3 / substeps;
  Rk4Differences worst;
  for (int j = 0; j < intervals; ++j) {
    if (j > 0) pilot = bonl::Backlash<double>::map(opening(command(j * 1e-3)), pilot, p.pilot_hysteresis);
    const double f = load(j * 1e-3);
    for (int i = 0; i < substeps; ++i) {
      const auto k1 = bonl::plant::derivative(p, s, pilot, f);
      const auto k2 = bonl::plant::derivative(p, axpy(s, 0.5 * h, k1), pilot, f);
      const auto k3 = bonl::plant::derivative(p, axpy(s, 0.5 * h, k2), pilot, f);
      const auto k4 = bonl::plant::derivative(p, axpy(s, h, k3), pilot, f);
      s = axpy(axpy(axpy(axpy(s, h / 6.0, k1), h / 3.0, k2), h / 3.0, k3), h / 6.0, k4);
    }
    worst.position = std::max(worst.position, std::abs(s.position - r.position[j + 1]));
    worst.velocity = std::max(worst.velocity, std::abs(s.velocity - r.velocity[j + 1]));
    worst.head_pressure = std::max(worst.head_pressure, std::abs(s.head_pressure - r.head_pressure[j + 1]));
  }
  return worst;
}

}  // namespace

TEST_CASE("the default experiment has the output grid and stays physical") {
  const Trajectory& r = default_run();
  REQUIRE(r.time.size() == 5001);
  CHECK(r.time[0] == 0.0);
  CHECK(r.time[5000] == 50.0);
  CHECK(r.time[1234] == 1234 * 0.01);
  CHECK(all_finite(r));
  // The command is the multi-sine sampled at the output times (1e-12: one evaluation of the same formula).
  CHECK(std::abs(r.command[777] - paper_multisine(7.77)) < 1e-12);
  CHECK(std::abs(r.input[777] - (r.command[777] - 2.5)) < 1e-15);
  const Parameters p;
  // Pressures: above -0.5 MPa (the smoothed orifice lets a chamber dip slightly below tank only
  // under cavitating conditions, which this run should not reach) and below ps + 1 MPa (the
  // chambers can exceed ps only through inertia, bounded by the end stops).
  CHECK(r.head_pressure.minCoeff() > -0.5e6);
  CHECK(r.rod_pressure.minCoeff() > -0.5e6);
  CHECK(r.head_pressure.maxCoeff() < p.supply_pressure + 1e6);
  CHECK(r.rod_pressure.maxCoeff() < p.supply_pressure + 1e6);
  // The spool and the pilot stay within full opening.
  CHECK(r.spool.cwiseAbs().maxCoeff() <= 1.0);
  CHECK(r.pilot.cwiseAbs().maxCoeff() <= 1.0);
  // Joint speed: plant.md measured about +-0.3 rad/s without pilot hysteresis; hysteresis only
  // lowers the opening, so 0.4 rad/s bounds it with margin, and the motion must be real (> 0.1).
  CHECK(r.joint_rate.cwiseAbs().maxCoeff() < 0.4);
  CHECK(r.joint_rate.cwiseAbs().maxCoeff() > 0.1);
  // The joint rate is v / r(h) sample by sample (rounding only).
  CHECK(std::abs(r.joint_rate[2500] - r.velocity[2500] / p.moment_arm(r.position[2500])) < 1e-15);
  // The spool's lag is solved exactly on the command grid, so CVODE steps across the grid points
  // (the held command enters only through the continuous spool opening) and stops only at the 5000
  // output samples: measured 23403 steps for the 50 000 command intervals (12938 when it did not stop
  // at the samples). 30 000 guards that, and a run with a step per interval would fail.
  CHECK(r.steps > 1000);
  CHECK(r.steps < 30000);
}

TEST_CASE("the default experiment never reaches an end stop") {
  const Trajectory& r = default_run();
  const Parameters p;
  CHECK_FALSE(r.reached_end_stop);
  CHECK(r.min_position > 0.0);
  CHECK(r.max_position < p.stroke);
  // plant.md reports 0.66-1.08 m without the pilot hysteresis; with it the range shifts by a few
  // cm (measured 0.65-1.13 m), so 0.1 m inside each end of the stroke is a safe margin.
  CHECK(r.min_position > 0.1);
  CHECK(r.max_position < p.stroke - 0.1);
  CHECK(r.position.minCoeff() >= r.min_position);
  CHECK(r.position.maxCoeff() <= r.max_position);
}

TEST_CASE("the chamber mass balance closes") {
  SimulationOptions options;
  options.sample_time = 0.001;
  options.sensor_noise = false;
  const Parameters p;
  const Trajectory r = bonl::plant::simulate(p, paper_multisine, options);
  const double dt = options.sample_time;
  const double a1 = p.head_area();
  const double a2 = p.annulus_area();
  const double beta = p.bulk_modulus;
  double flow1 = 0.0, flow2 = 0.0, magnitude1 = 0.0, magnitude2 = 0.0, compress1 = 0.0, compress2 = 0.0;
  for (Eigen::Index k = 0; k + 1 < r.time.size(); ++k) {
    const auto net1 = [&](Eigen::Index i) {
      return r.head_flow[i] - p.internal_leakage * (r.head_pressure[i] - r.rod_pressure[i]) -
             p.external_leakage * r.head_pressure[i];
    };
    const auto net2 = [&](Eigen::Index i) {
      return r.rod_flow[i] - p.internal_leakage * (r.head_pressure[i] - r.rod_pressure[i]) +
             p.external_leakage * r.rod_pressure[i];
    };
    flow1 += 0.5 * dt * (net1(k) + net1(k + 1));
    flow2 += 0.5 * dt * (net2(k) + net2(k + 1));
    magnitude1 += 0.5 * dt * (std::abs(r.head_flow[k]) + std::abs(r.head_flow[k + 1]));
    magnitude2 += 0.5 * dt * (std::abs(r.rod_flow[k]) + std::abs(r.rod_flow[k + 1]));
    const double v1 = p.dead_volume_head + a1 * 0.5 * (r.position[k] + r.position[k + 1]);
    const double v2 = p.dead_volume_rod + a2 * (p.stroke - 0.5 * (r.position[k] + r.position[k + 1]));
    compress1 += v1 / beta * (r.head_pressure[k + 1] - r.head_pressure[k]);
    compress2 += v2 / beta * (r.rod_pressure[k + 1] - r.rod_pressure[k]);
  }
  const Eigen::Index n = r.time.size() - 1;
  const double dh = r.position[n] - r.position[0];
  // Head side: int (Q1 - Ci (p1 - p2) - Ce p1) dt = A1 dh + int V1 / beta dp1.
  const double residual1 = std::abs(flow1 - (a1 * dh + compress1)) / magnitude1;
  // Rod side: int (Q2 - Ci (p1 - p2) + Ce p2) dt = A2 dh - int V2 / beta dp2.
  const double residual2 = std::abs(flow2 - (a2 * dh - compress2)) / magnitude2;
  INFO("residuals " << residual1 << ", " << residual2 << " of " << magnitude1 << ", " << magnitude2 << " m^3");
  // Trapezoid quadrature at 1 ms of signals whose fastest content is the ~7 Hz hydraulic mode
  // errs by up to ~(2 pi 7 Hz * 1 ms)^2 / 12 ~ 2e-4 of the local flow, which mostly cancels over
  // the 50 s; CVODE's rtol 1e-6 adds ~1e-6. Measured 2.3e-6 (head) and 1.4e-6 (rod) of the
  // integrated |flow|: the bound 2e-5 is ~10x that, and ~1e-3 would flag a missing term.
  CHECK(residual1 < 2e-5);
  CHECK(residual2 < 2e-5);
  CHECK(magnitude1 > 1e-3);  // the run moves a real volume of oil
}

TEST_CASE("commands inside the dead band give no motion") {
  const Trajectory up = constant_command(2.55, 5.0);
  const Trajectory down = constant_command(2.45, 5.0);
  // Inside the dead band the pilot output is exactly zero, so both runs are the same run.
  CHECK(up.pilot.cwiseAbs().maxCoeff() == 0.0);
  CHECK(up.spool.cwiseAbs().maxCoeff() == 0.0);
  CHECK(up.position == down.position);
  // Only leakage (Ci (p1 - p2) ~ 1e-6 m^3/s) moves the piston, against static friction: measured
  // 1.0e-4 m of creep in 5 s. 5e-4 m bounds it; the smallest opening beyond the dead band
  // (2.6 V) moves it ~1.5 cm in the same time.
  const double drift = (up.position.array() - up.position[0]).abs().maxCoeff();
  INFO("drift " << drift << " m");
  CHECK(drift < 5e-4);
}

TEST_CASE("full extension is faster than full retraction") {
  const Trajectory extend = constant_command(5.0, 1.5);
  const Trajectory retract = constant_command(0.0, 1.5);
  // Steady speeds over [0.8, 1.2] s, after the valve (tau 0.05 s) and the hydraulic transient and
  // before either end stop (0.75 m away at ~0.4 m/s).
  const double v_out = mean_speed(extend, 0.8, 1.2, 0.01);
  const double v_in = mean_speed(retract, 0.8, 1.2, 0.01);
  INFO("extension " << v_out << " m/s, retraction " << v_in << " m/s");
  // plant.md: about +0.4 m/s; the pilot hysteresis caps the opening at 1 - hv = 0.95.
  CHECK(v_out > 0.35);
  CHECK(v_out < 0.45);
  // plant.md: -0.25 to -0.32 m/s; gravity (Fs ~ 47 kN at mid-stroke) helps retraction, measured
  // -0.33 m/s, so the band is widened to -0.36.
  CHECK(v_in < -0.25);
  CHECK(v_in > -0.36);
  const Parameters p;
  const double area_ratio = p.head_area() / p.annulus_area();
  const double ratio = v_out / -v_in;
  // A meter-in/meter-out valve with pt = 0 and no load gives v_out / |v_in| = sqrt(A1 / A2); a load
  // opposing extension (gravity here) and pt > 0 push it towards 1 and further, so the ratio lies
  // between 0.8 sqrt(A1 / A2) and 1.1 A1 / A2.
  CHECK(ratio > 1.0);
  CHECK(ratio > 0.8 * std::sqrt(area_ratio));
  CHECK(ratio < 1.1 * area_ratio);
}

TEST_CASE("small steps give increasing speeds, shifted by the dead band") {
  const double d = Parameters{}.dead_band;
  double speed[3];
  const double volts[3] = {2.6, 2.65, 2.7};
  for (int i = 0; i < 3; ++i) {
    const Trajectory r = constant_command(volts[i], 4.0);
    // Mean speed over [1, 4] s: long enough to average the low-speed stick-slip oscillation.
    speed[i] = mean_speed(r, 1.0, 4.0, 0.01);
    // The play starts engaged at the step: xc is kv (V - 2.5 - d) from t = 0 (rounding only).
    CHECK(std::abs(r.pilot[0] - (volts[i] - 2.5 - d) / (2.5 - d)) < 1e-15);
  }
  INFO("speeds " << speed[0] << ", " << speed[1] << ", " << speed[2] << " m/s");
  CHECK(speed[0] > 0.0);
  CHECK(speed[1] > speed[0]);
  CHECK(speed[2] > speed[1]);
  // Not proportional to V - 2.5 (that ratio would be 1.5 and 2): the dead band removes 0.08 V.
  CHECK(speed[1] / speed[0] > 1.5 * 1.5);
  CHECK(speed[2] / speed[0] > 2.0 * 1.5);
  // Beyond the dead band the speed follows the opening kv (V - 2.5 - d): with the play engaged
  // from t = 0 the pilot output is exactly that, and at steady speed the meter-in/meter-out drops
  // keep (ps - p1) / (p2 - pt) = (A1 / A2)^2 whatever the opening, so Q ~ xv. Only friction's
  // velocity dependence (Stribeck, viscous: < 1 kN of the ~50 kN load) bends it. Measured ratios
  // 3.50 and 5.98 against 3.5 and 6 (0.3 %); 3 % bounds them with margin. The plant's input
  // nonlinearity is the dead band (and the hysteresis, the saturation), not a curved gain.
  const double r1 = speed[1] / speed[0];
  const double r2 = speed[2] / speed[0];
  CHECK(std::abs(r1 / 3.5 - 1.0) < 0.03);
  CHECK(std::abs(r2 / 6.0 - 1.0) < 0.03);
}

TEST_CASE("the pin angle lags the joint angle on a reversal") {
  SimulationOptions options;
  options.duration = 2.0;
  options.sample_time = 0.001;  // the backlash grid, so every play step is visible
  options.sensor_noise = false;
  const Parameters p;
  const double half = 0.5 * p.joint_backlash;
  const Trajectory r = bonl::plant::simulate(
      p, [](double t) { return t < 1.0 ? 3.5 : 1.5; }, options);
  const Eigen::VectorXd& theta = r.joint_angle;
  const Eigen::VectorXd& pin = r.pin_angle;
  CHECK(pin[0] == theta[0]);  // starts engaged at theta(0)
  CHECK(r.measured_angle == r.pin_angle);
  // Play invariants on every sample: |theta - theta_m| <= delta / 2, and theta_m moves only when
  // engaged, |theta - theta_m| = delta / 2. 1e-14 rad is rounding of angles ~0.1 rad.
  for (Eigen::Index k = 1; k < theta.size(); ++k) {
    CHECK(std::abs(theta[k] - pin[k]) <= half + 1e-14);
    if (pin[k] != pin[k - 1]) CHECK(std::abs(std::abs(theta[k] - pin[k]) - half) < 1e-14);
  }
  // The reversal: theta's largest value.
  Eigen::Index top = 0;
  const double theta_max = theta.maxCoeff(&top);
  REQUIRE(top > 900);  // after the command reverses at 1 s, with the valve's lag
  REQUIRE(top < 1500);
  CHECK(std::abs(theta_max - pin[top] - half) < 1e-14);  // engaged while extending
  // After the reversal the pin stays put until theta has come back by delta.
  Eigen::Index k = top + 1;
  while (k < theta.size() && theta[k] > theta_max - p.joint_backlash) {
    CHECK(pin[k] == pin[top]);
    ++k;
  }
  const Eigen::Index lag = k - top;
  INFO("the pin stood still for " << lag << " ms");
  CHECK(lag > 3);  // at ~0.4 rad/s, delta = 3e-3 rad takes > 7 ms; at least a few samples
  REQUIRE(k + 10 < theta.size());
  for (Eigen::Index i = k; i < k + 10; ++i) CHECK(std::abs(pin[i] - (theta[i] + half)) < 1e-14);
}

TEST_CASE("the plant agrees with an independent fixed-step integrator") {
  // RK4 on derivative() with 100 steps per command interval (rk4_differences), no load.
  const Parameters p;
  SimulationOptions options;
  options.duration = 1.0;
  options.sample_time = 0.001;
  options.sensor_noise = false;
  const auto command = [](double t) { return 2.5 + 1.2 * std::sin(2.0 * kPi * 2.0 * t); };
  const Trajectory r = bonl::plant::simulate(p, command, options);
  const Rk4Differences worst = rk4_differences(
      p, command, [](double) { return 0.0; }, r, 1000);
  INFO("worst differences: h " << worst.position << " m, v " << worst.velocity << " m/s, p1 " << worst.head_pressure
                               << " Pa");
  // Measured: h 2.2e-6 m, v 4.9e-5 m/s, p1 1.0e3 Pa, i.e. ~1e-4 relative: CVODE at rtol 1e-6 over
  // 1000 held intervals (RK4 at 10 us is far more accurate). Bounds 5x above: 1e-5 m on h (0.1 m
  // of motion), 2.5e-4 m/s on v (~0.3 m/s), 5e3 Pa on p1 (~1e7 Pa).
  CHECK(worst.position < 1e-5);
  CHECK(worst.velocity < 2.5e-4);
  CHECK(worst.head_pressure < 5e3);
}

TEST_CASE("tightening the tolerances ten-fold barely changes the result") {
  SimulationOptions tight;
  tight.tolerances.relative = 1e-7;
  tight.tolerances.absolute_position = 1e-9;
  tight.tolerances.absolute_velocity = 1e-9;
  tight.tolerances.absolute_pressure = 0.1;
  tight.tolerances.absolute_spool = 1e-9;
  const Trajectory& loose = default_run();
  const Trajectory fine = bonl::plant::simulate(Parameters{}, paper_multisine, tight);
  const double angle = (fine.joint_angle - loose.joint_angle).cwiseAbs().maxCoeff();
  const double rate = (fine.joint_rate - loose.joint_rate).cwiseAbs().maxCoeff();
  INFO("max differences: angle " << angle << " rad, rate " << rate << " rad/s; steps " << loose.steps << " -> "
                                 << fine.steps);
  // Measured: 4.2e-4 rad and 4.5e-4 rad/s (and 4e-6 rad, 1.3e-5 rad/s between rtol 1e-7 and 1e-9).
  // At rtol 1e-6 CVODE controls h's local error relative to |h| ~ 0.75 m, and the position
  // integrates those errors into a slow drift of the angle (~8e-6 rad/s): it is the velocity, the
  // identified output, that stays accurate to ~0.15 % of its 0.3 rad/s range. Bounds: 1e-3 on both,
  // about 2x the measured values.
  CHECK(angle < 1e-3);
  CHECK(rate < 1e-3);
  CHECK(fine.steps > loose.steps);
}

TEST_CASE("a CVODE failure becomes CvodeError") {
  SimulationOptions options;
  options.duration = 0.1;
  options.tolerances.relative = 1e-12;
  options.tolerances.absolute_pressure = 1e-9;
  options.tolerances.max_steps_per_interval = 1;
  try {
    bonl::plant::simulate(
        Parameters{}, [](double t) { return t < 0.05 ? 2.5 : 5.0; }, options);
    FAIL("expected CvodeError");
  } catch (const bonl::plant::CvodeError& e) {
    INFO(e.what());
    CHECK(e.flag() == -1);  // CV_TOO_MUCH_WORK in cvode.h
    CHECK(std::string(e.what()).find("CV_TOO_MUCH_WORK") != std::string::npos);
    CHECK(std::string(e.what()).find("t = ") != std::string::npos);
    CHECK(e.time() >= 0.0);
    CHECK(e.time() <= 0.1);
  }
  // It is a bonl::NumericalError.
  CHECK_THROWS_AS(bonl::plant::simulate(
                      Parameters{}, [](double) { return 5.0; }, options),
                  bonl::NumericalError);
}

TEST_CASE("a non-finite command is invalid input that names the time") {
  SimulationOptions options;
  options.duration = 1.0;
  const auto nan_at_half = [](double t) { return t >= 0.5 ? std::numeric_limits<double>::quiet_NaN() : 3.0; };
  CHECK_THROWS_AS(bonl::plant::simulate(Parameters{}, nan_at_half, options), std::invalid_argument);
  CHECK_THROWS_WITH(bonl::plant::simulate(Parameters{}, nan_at_half, options), Catch::Contains("t = 0.5"));
}

TEST_CASE("invalid options and parameters throw invalid_argument naming them") {
  const auto run = [](const SimulationOptions& options) {
    return bonl::plant::simulate(
        Parameters{}, [](double) { return 2.5; }, options);
  };
  const auto expect = [&](SimulationOptions options, const std::string& name) {
    INFO(name);
    CHECK_THROWS_AS(run(options), std::invalid_argument);
    CHECK_THROWS_WITH(run(options), Catch::Contains(name));
  };
  SimulationOptions o;
  o.duration = 0.0;
  expect(o, "duration");
  o = {};
  o.duration = std::numeric_limits<double>::quiet_NaN();
  expect(o, "duration");
  o = {};
  o.duration = 1.005;  // not a multiple of sample_time
  expect(o, "duration");
  o = {};
  o.sample_time = -0.01;
  expect(o, "sample_time");
  o = {};
  o.sample_time = 0.0015;  // not a multiple of 1 ms
  expect(o, "sample_time");
  o = {};
  o.sample_time = 0.0005;  // shorter than the command grid
  expect(o, "sample_time");
  o = {};
  o.command_rate = 0.0;
  expect(o, "command_rate");
  o = {};
  o.tolerances.relative = 0.0;
  expect(o, "tolerances.relative");
  o = {};
  o.tolerances.absolute_position = -1.0;
  expect(o, "tolerances.absolute_position");
  o = {};
  o.tolerances.absolute_velocity = 0.0;
  expect(o, "tolerances.absolute_velocity");
  o = {};
  o.tolerances.absolute_pressure = std::numeric_limits<double>::infinity();
  expect(o, "tolerances.absolute_pressure");
  o = {};
  o.tolerances.absolute_spool = 0.0;
  expect(o, "tolerances.absolute_spool");
  o = {};
  o.tolerances.max_steps_per_interval = 0;
  expect(o, "max_steps_per_interval");
  o = {};
  o.initial_position = 2.0;  // beyond the 1.5 m stroke
  expect(o, "initial_position");
  CHECK_THROWS_WITH(bonl::plant::simulate(Parameters{}, bonl::plant::Command{}, {}), Catch::Contains("command"));
  Parameters bad;
  bad.mass = -1.0;
  CHECK_THROWS_WITH(bonl::plant::simulate(bad, [](double) { return 2.5; }, {}), Catch::Contains("mass"));
}

TEST_CASE("a chosen initial position, the 5 t machine and the load") {
  SimulationOptions options;
  options.duration = 1.0;
  options.initial_position = 0.3;
  options.sensor_noise = false;
  const Trajectory r = bonl::plant::simulate(
      Parameters{}, [](double) { return 2.5; }, options);
  CHECK(r.position[0] == 0.3);
  CHECK(r.joint_angle[0] == Parameters{}.joint_angle(0.3));
  // A load opposing extension slows an extension run: 2e4 N is ~ a fifth of the available force.
  SimulationOptions loaded;
  loaded.duration = 1.0;
  loaded.sensor_noise = false;
  loaded.load = [](double) { return 2e4; };
  const auto three_volts = [](double) { return 3.5; };
  SimulationOptions unloaded = loaded;
  unloaded.load = nullptr;
  const Trajectory free_run = bonl::plant::simulate(Parameters{}, three_volts, unloaded);
  const Trajectory load_run = bonl::plant::simulate(Parameters{}, three_volts, loaded);
  CHECK(load_run.position[100] < free_run.position[100]);
  CHECK(load_run.position[100] > load_run.position[0]);  // still extends
  // The 5 t machine runs the default experiment without NaN or end stop.
  const Trajectory small = bonl::plant::simulate(Parameters::excavator_5t(), paper_multisine);
  CHECK(all_finite(small));
  CHECK_FALSE(small.reached_end_stop);
}

TEST_CASE("sensor noise is deterministic per seed") {
  SimulationOptions options;
  options.duration = 5.0;
  const Trajectory a = bonl::plant::simulate(Parameters{}, paper_multisine, options);
  const Trajectory b = bonl::plant::simulate(Parameters{}, paper_multisine, options);
  options.noise_seed = 2;
  const Trajectory c = bonl::plant::simulate(Parameters{}, paper_multisine, options);
  // Bit-identical for the same seed, in every field.
  CHECK(a.measured_angle == b.measured_angle);
  CHECK(a.joint_angle == b.joint_angle);
  CHECK(a.head_pressure == b.head_pressure);
  CHECK(a.steps == b.steps);
  // Another seed: the same plant, other noise.
  CHECK(c.pin_angle == a.pin_angle);
  CHECK(c.measured_angle != a.measured_angle);
  const Eigen::VectorXd noise = a.measured_angle - a.pin_angle;
  const double sigma = bonl_test::standard_deviation(noise);
  // 501 samples: the sample standard deviation is within ~3% (1 sigma) of 2e-4; 15% is ~5 sigma.
  CHECK(std::abs(sigma / Parameters{}.sensor_noise - 1.0) < 0.15);
  CHECK(std::abs(noise.mean()) < 4.0 * 2e-4 / std::sqrt(501.0));  // zero mean, 4 standard errors
  // Without sensor noise the measured angle is the pin angle.
  options.sensor_noise = false;
  const Trajectory quiet = bonl::plant::simulate(Parameters{}, paper_multisine, options);
  CHECK(quiet.measured_angle == quiet.pin_angle);
}

TEST_CASE("the spool opening is the exact response of its lag to the held pilot output") {
  // tau_v dxv/dt = xc - xv with xc held on the command grid: xv = xc (1 - exp(-(t - t0) / tau_v))
  // after a step of xc at t0 from rest. The play starts engaged at 2.5 V (xc = 0) and the step to
  // 3.5 V moves it by kv (1 - d) - hv.
  const Parameters p;
  SimulationOptions options;
  options.duration = 0.5;
  options.sample_time = 0.001;
  options.sensor_noise = false;
  const Trajectory r = bonl::plant::simulate(p, bonl::plant::excitation::step(3.5, 0.2), options);
  const double xc = (1.0 - p.dead_band) / (2.5 - p.dead_band) - p.pilot_hysteresis;
  double worst = 0.0;
  for (Eigen::Index k = 0; k < r.time.size(); ++k) {
    const double t = r.time[k];
    const double expected = t < 0.2 - 1e-12 ? 0.0 : xc * -std::expm1(-(t - 0.2) / p.valve_time_constant);
    CHECK(std::abs(r.pilot[k] - (t < 0.2 - 1e-12 ? 0.0 : xc)) < 1e-15);
    worst = std::max(worst, std::abs(r.spool[k] - expected));
  }
  INFO("worst spool error " << worst);
  CHECK(worst < 1e-14);  // rounding of the interval-by-interval recurrence only
  CHECK(r.spool[r.time.size() - 1] > 0.99 * xc);
}

TEST_CASE("a sample depends only on the commands before it") {
  // CVODE stops at every output sample, where the next sample's command is not known yet (a
  // SteppingPlant's situation): sample k is the same number whatever the command does from t_k on.
  SimulationOptions options;
  options.duration = 2.0;
  options.sensor_noise = false;
  const auto switched = [](double t) { return t < 1.0 ? paper_multisine(t) : 4.0; };
  const Trajectory a = bonl::plant::simulate(Parameters{}, paper_multisine, options);
  const Trajectory b = bonl::plant::simulate(Parameters{}, switched, options);
  for (Eigen::Index k = 0; k <= 100; ++k) {
    CHECK(a.position[k] == b.position[k]);
    CHECK(a.velocity[k] == b.velocity[k]);
    CHECK(a.head_pressure[k] == b.head_pressure[k]);
    CHECK(a.spool[k] == b.spool[k]);
    CHECK(a.pin_angle[k] == b.pin_angle[k]);
  }
  CHECK(a.pilot[100] != b.pilot[100]);  // the pilot and the command of sample k are those at t_k
  CHECK(std::abs(a.position[200] - b.position[200]) > 1e-3);
}

TEST_CASE("the output grid moves the trajectory only within the tolerances") {
  // The finer grid stops CVODE ten times as often; the spool is exact on the command grid either way.
  SimulationOptions fine;
  fine.duration = 2.0;
  fine.sample_time = 0.001;
  fine.sensor_noise = false;
  SimulationOptions coarse = fine;
  coarse.sample_time = 0.01;
  const Trajectory a = bonl::plant::simulate(Parameters{}, paper_multisine, fine);
  const Trajectory b = bonl::plant::simulate(Parameters{}, paper_multisine, coarse);
  REQUIRE(b.time.size() == 201);
  double position = 0.0, pressure = 0.0, pin = 0.0;
  for (Eigen::Index k = 0; k < b.time.size(); ++k) {
    CHECK(a.spool[10 * k] == b.spool[k]);
    position = std::max(position, std::abs(a.position[10 * k] - b.position[k]));
    pressure = std::max(pressure, std::abs(a.head_pressure[10 * k] - b.head_pressure[k]));
    pin = std::max(pin, std::abs(a.pin_angle[10 * k] - b.pin_angle[k]));
  }
  INFO("position " << position << " m, head pressure " << pressure << " Pa, pin angle " << pin << " rad");
  // Measured 3.1e-7 m, 185 Pa and 3.7e-7 rad (5.8e-7 m, 185 Pa, 8.1e-7 rad over the 50 s experiment):
  // the global error of rtol = 1e-6, well inside what the RK4 oracle above allows (1e-5 m, 5 kPa).
  CHECK(position < 2e-6);
  CHECK(pressure < 1e3);
  CHECK(pin < 2e-6);
  CHECK(a.steps > b.steps);
}

TEST_CASE("a load that changes on the command grid is held, with CVODE stopped at each change") {
  // The RK4 oracle of the test above with a load stepping at 0.3 s and ramping from 0.6 s.
  const Parameters p;
  SimulationOptions options;
  options.duration = 1.0;
  options.sample_time = 0.001;
  options.sensor_noise = false;
  const auto load = [](double t) { return t < 0.3 ? 0.0 : (t < 0.6 ? 3e4 : 3e4 - 5e4 * (t - 0.6)); };
  options.load = load;
  const auto command = [](double t) { return 2.5 + 1.2 * std::sin(2.0 * kPi * 2.0 * t); };
  const Trajectory r = bonl::plant::simulate(p, command, options);
  const Rk4Differences worst = rk4_differences(p, command, load, r, 1000);
  INFO("worst differences: h " << worst.position << " m, v " << worst.velocity << " m/s");
  // The same bounds as without the load.
  CHECK(worst.position < 1e-5);
  CHECK(worst.velocity < 2.5e-4);
}

TEST_CASE("the Jacobian handed to CVODE matches finite differences of the right-hand side") {
  using bonl::plant::detail::kMechanicalSize;
  for (const Parameters& p : {Parameters{}, Parameters::excavator_5t()}) {
    const bonl::plant::detail::Model model(p);
    std::mt19937_64 engine(11);
    const auto uniform = [&engine](double lo, double hi) {
      return std::uniform_real_distribution<double>(lo, hi)(engine);
    };
    const auto check_at = [&](const double(&x)[kMechanicalSize], double xv) {
      double jac[kMechanicalSize][kMechanicalSize];
      model.mechanical_jacobian(x, xv, jac);
      for (int k = 0; k < kMechanicalSize; ++k) {
        // Central differences with a step relative to the state's scale (h, v ~ 1; p ~ 1e7).
        const double scale = k >= 2 ? 1e7 : (k == 1 ? 0.1 : 1.0);
        const double step = 1e-6 * scale;
        double up[kMechanicalSize], down[kMechanicalSize], f_up[kMechanicalSize], f_down[kMechanicalSize];
        std::copy(std::begin(x), std::end(x), up);
        std::copy(std::begin(x), std::end(x), down);
        up[k] += step;
        down[k] -= step;
        model.mechanical_rhs(up, xv, 1e3, f_up);
        model.mechanical_rhs(down, xv, 1e3, f_down);
        for (int i = 0; i < kMechanicalSize; ++i) {
          const double fd = (f_up[i] - f_down[i]) / (2.0 * step);
          INFO("d f" << i << " / d x" << k << " at h " << x[0] << ", v " << x[1] << ", xv " << xv);
          CHECK(std::abs(jac[i][k] - fd) <= 1e-5 * std::abs(fd) + 1e-9 * std::abs(jac[i][k]) + 1e-12);
        }
      }
    };
    for (int n = 0; n < 200; ++n) {
      // Inside the stroke, |v| beyond the friction smoothing (its tanh is too steep for a fixed
      // step), both spool directions.
      const double v = (uniform(0.005, 0.4)) * (n % 2 == 0 ? 1.0 : -1.0);
      const double x[kMechanicalSize] = {uniform(0.05, 0.95) * p.stroke, v, uniform(0.5e6, 19.5e6),
                                         uniform(0.5e6, 19.5e6)};
      check_at(x, uniform(-1.0, 1.0));
    }
    // At rest, inside the end stops, and with the spool closed.
    check_at({0.5 * p.stroke, 0.0, 1e7, 5e6}, 0.0);
    check_at({-1e-3, 0.02, 1e7, 5e6}, 0.3);
    check_at({p.stroke + 1e-3, -0.02, 1e7, 5e6}, -0.3);
  }
}
