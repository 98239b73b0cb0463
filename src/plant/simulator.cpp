// The dipper-joint plant's simulation: a loop over the integration core that SteppingPlant steps too
// (integrator.hpp), recording every output sample; and the plant's right-hand side for tests.

#include "bonl/plant/simulator.hpp"

#include <Eigen/Core>
#include <cmath>

#include "bonl/detail/validate.hpp"
#include "integrator.hpp"
#include "model.hpp"

namespace bonl::plant {

using detail::kHeadPressure;
using detail::kPosition;
using detail::kRodPressure;
using detail::kSpool;
using detail::kStateSize;
using detail::kVelocity;

State initial_state(const Parameters& parameters, double position) {
  State s;
  s.position = position;
  s.velocity = 0.0;
  s.rod_pressure = 0.25 * parameters.supply_pressure;
  s.head_pressure =
      (parameters.annulus_area() * s.rod_pressure + gravity_force(parameters, position)) / parameters.head_area();
  s.spool = 0.0;
  return s;
}

double gravity_force(const Parameters& parameters, double position) {
  return detail::Model(parameters).gravity_force(position);
}

State derivative(const Parameters& parameters, const State& state, double pilot, double load) {
  const double x[kStateSize] = {state.position, state.velocity, state.head_pressure, state.rod_pressure, state.spool};
  double dx[kStateSize] = {};
  detail::Model(parameters).rhs(x, pilot, load, dx);
  State d;
  d.position = dx[kPosition];
  d.velocity = dx[kVelocity];
  d.head_pressure = dx[kHeadPressure];
  d.rod_pressure = dx[kRodPressure];
  d.spool = dx[kSpool];
  return d;
}

Trajectory simulate(const Parameters& parameters, const Command& command, const SimulationOptions& options) {
  parameters.validate();
  bonl::detail::require(static_cast<bool>(command), "simulate: command must not be empty");
  detail::validate_options(options, parameters, "simulate", true);
  const auto n_samples = static_cast<Eigen::Index>(std::lround(options.duration / options.sample_time));

  // The trajectory's arrays that are the measurement's fields at t_k; the others are the inputs of t_k.
  struct Column {
    Eigen::VectorXd Trajectory::*array;
    double Measurement::*field;
  };
  static constexpr Column kColumns[] = {
      {&Trajectory::time, &Measurement::time},
      {&Trajectory::position, &Measurement::position},
      {&Trajectory::velocity, &Measurement::velocity},
      {&Trajectory::head_pressure, &Measurement::head_pressure},
      {&Trajectory::rod_pressure, &Measurement::rod_pressure},
      {&Trajectory::spool, &Measurement::spool},
      {&Trajectory::head_flow, &Measurement::head_flow},
      {&Trajectory::rod_flow, &Measurement::rod_flow},
      {&Trajectory::joint_angle, &Measurement::joint_angle},
      {&Trajectory::joint_rate, &Measurement::joint_rate},
      {&Trajectory::pin_angle, &Measurement::pin_angle},
      {&Trajectory::measured_angle, &Measurement::measured_angle},
  };
  Trajectory out;
  for (const Column& c : kColumns) (out.*c.array).resize(n_samples + 1);
  for (Eigen::VectorXd* v : {&out.command, &out.input, &out.pilot}) v->resize(n_samples + 1);
  // Sample k: the state at t_k (measured before the advance) with the inputs of t_k that follow it.
  const auto store = [&](Eigen::Index k, const Measurement& m, const detail::GridInputs& in) {
    for (const Column& c : kColumns) (out.*c.array)[k] = m.*c.field;
    out.command[k] = in.voltage;
    out.input[k] = in.voltage - parameters.neutral_voltage;
    out.pilot[k] = in.pilot;
  };

  detail::Integrator plant(parameters, options, "simulate");
  for (Eigen::Index k = 0; k < n_samples; ++k) {
    const Measurement before = plant.measurement();
    store(k, before, plant.advance(command));
  }
  store(n_samples, plant.measurement(), plant.inputs_now(command));
  out.min_position = plant.min_position();
  out.max_position = plant.max_position();
  out.reached_end_stop = plant.reached_end_stop();
  out.steps = plant.steps();
  return out;
}

}  // namespace bonl::plant
