// The dipper-joint plant integrated with SUNDIALS CVODE (BDF, Newton, dense direct solver), with
// the command, the pilot hysteresis, the load and the pin backlash on the command grid
// (docs/plant.md).

#include "bonl/plant/simulator.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

#include "bonl/blocks/backlash.hpp"
#include "model.hpp"

namespace bonl::plant {

namespace {

using detail::kHeadPressure;
using detail::kPosition;
using detail::kRodPressure;
using detail::kSpool;
using detail::kStateSize;
using detail::kVelocity;

std::string number(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

[[noreturn]] void bad_option(const char* name, const std::string& requirement, double value) {
  throw std::invalid_argument("bonl::plant::simulate: " + std::string(name) + ' ' + requirement + ", got " +
                              number(value));
}

void require_positive(const char* name, double value) {
  if (!(std::isfinite(value) && value > 0.0)) bad_option(name, "must be > 0 and finite", value);
}

/// What CVODE's right-hand side sees: the model and the inputs held over the current interval.
struct UserData {
  explicit UserData(const Parameters& parameters) : model(parameters) {}
  detail::Model model;
  double pilot = 0.0;
  double load = 0.0;
  std::string last_error;  ///< CVODE's last error message, for the exception
};

int rhs_callback(sunrealtype /*t*/, N_Vector y, N_Vector ydot, void* user_data) {
  const auto* data = static_cast<const UserData*>(user_data);
  const double* x = N_VGetArrayPointer_Serial(y);
  double* dx = N_VGetArrayPointer_Serial(ydot);
  data->model.rhs(x, data->pilot, data->load, dx);
  for (int i = 0; i < kStateSize; ++i) {
    if (!std::isfinite(dx[i])) return 1;  // recoverable: CVODE retries with a smaller step
  }
  return 0;
}

void error_handler(int /*error_code*/, const char* module, const char* function, char* message, void* eh_data) {
  auto* data = static_cast<UserData*>(eh_data);
  try {
    data->last_error = std::string(module) + "::" + function + ": " + message;
  } catch (...) {  // NOLINT(bugprone-empty-catch): never let an exception cross CVODE's C frames
  }
}

// RAII for the SUNDIALS objects.
struct ContextDeleter {
  void operator()(SUNContext ctx) const noexcept { SUNContext_Free(&ctx); }
};
struct VectorDeleter {
  void operator()(N_Vector v) const noexcept { N_VDestroy(v); }
};
struct MatrixDeleter {
  void operator()(SUNMatrix m) const noexcept { SUNMatDestroy(m); }
};
struct SolverDeleter {
  void operator()(SUNLinearSolver s) const noexcept { SUNLinSolFree(s); }
};
struct CvodeDeleter {
  void operator()(void* mem) const noexcept { CVodeFree(&mem); }
};
struct FreeDeleter {
  void operator()(char* p) const noexcept { std::free(p); }
};

using ContextPtr = std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter>;
using VectorPtr = std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter>;
using MatrixPtr = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter>;
using SolverPtr = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, SolverDeleter>;
using CvodePtr = std::unique_ptr<void, CvodeDeleter>;

std::string flag_name(int flag) {
  std::unique_ptr<char, FreeDeleter> name(CVodeGetReturnFlagName(flag));
  return name ? std::string(name.get()) : "flag " + std::to_string(flag);
}

/// Throws CvodeError when a CVODE call returned a negative flag.
void check(int flag, const char* call, double time, const UserData& data) {
  if (flag >= 0) return;
  std::string message = "bonl::plant::simulate: " + std::string(call) + " failed with " + flag_name(flag) +
                        " at t = " + number(time) + " s";
  if (!data.last_error.empty()) message += " (" + data.last_error + ")";
  throw CvodeError(message, flag, time);
}

void validate_options(const SimulationOptions& options, const Parameters& parameters) {
  require_positive("duration", options.duration);
  require_positive("sample_time", options.sample_time);
  require_positive("command_rate", options.command_rate);
  const double per_sample = options.sample_time * options.command_rate;
  const double whole = std::round(per_sample);
  if (!(whole >= 1.0 && std::abs(per_sample - whole) <= 1e-9 * whole))
    bad_option("sample_time", "must be an integer multiple of 1 / command_rate (" + number(1.0 / options.command_rate) + " s)",
               options.sample_time);
  const double samples = options.duration / options.sample_time;
  const double whole_samples = std::round(samples);
  if (!(whole_samples >= 1.0 && std::abs(samples - whole_samples) <= 1e-9 * whole_samples))
    bad_option("duration", "must be an integer multiple of sample_time (" + number(options.sample_time) + " s)",
               options.duration);
  const Tolerances& tol = options.tolerances;
  require_positive("tolerances.relative", tol.relative);
  require_positive("tolerances.absolute_position", tol.absolute_position);
  require_positive("tolerances.absolute_velocity", tol.absolute_velocity);
  require_positive("tolerances.absolute_pressure", tol.absolute_pressure);
  require_positive("tolerances.absolute_spool", tol.absolute_spool);
  if (tol.max_steps_per_interval < 1)
    bad_option("tolerances.max_steps_per_interval", "must be >= 1", static_cast<double>(tol.max_steps_per_interval));
  if (!std::isfinite(options.initial_position) || options.initial_position > parameters.stroke)
    bad_option("initial_position", "must be finite and <= stroke (" + number(parameters.stroke) + " m); negative means mid-stroke",
               options.initial_position);
}

/// Pilot-stage input kv * uv for a command V (plant.md 1-2, before the hysteresis).
double commanded_opening(const Parameters& p, double voltage) {
  const double e = std::clamp(voltage, 0.0, p.max_voltage) - p.neutral_voltage;
  const double magnitude = std::max(std::abs(e) - p.dead_band, 0.0);
  const double uv = e < 0.0 ? -magnitude : magnitude;
  return p.valve_gain() * uv;
}

}  // namespace

State initial_state(const Parameters& parameters, double position) {
  State s;
  s.position = position;
  s.velocity = 0.0;
  s.rod_pressure = 0.25 * parameters.supply_pressure;
  s.head_pressure = (parameters.annulus_area() * s.rod_pressure + gravity_force(parameters, position)) /
                    parameters.head_area();
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
  if (!command) throw std::invalid_argument("bonl::plant::simulate: command must not be empty");
  validate_options(options, parameters);

  const double rate = options.command_rate;
  const auto per_sample = static_cast<long>(std::lround(options.sample_time * rate));
  const auto n_intervals = static_cast<long>(std::lround(options.duration / options.sample_time));
  const long n_grid = n_intervals * per_sample;  // command-grid intervals
  const Eigen::Index n_out = n_intervals + 1;

  UserData data(parameters);
  const detail::Model& model = data.model;
  const double h0 = options.initial_position >= 0.0 ? options.initial_position : 0.5 * parameters.stroke;
  const State s0 = initial_state(parameters, h0);

  // --- SUNDIALS objects ---------------------------------------------------------------------
  SUNContext raw_ctx = nullptr;
  if (SUNContext_Create(nullptr, &raw_ctx) != 0 || raw_ctx == nullptr)
    throw CvodeError("bonl::plant::simulate: SUNContext_Create failed", 0, 0.0);
  ContextPtr ctx(raw_ctx);
  VectorPtr y(N_VNew_Serial(kStateSize, ctx.get()));
  VectorPtr abstol(N_VNew_Serial(kStateSize, ctx.get()));
  if (!y || !abstol) throw CvodeError("bonl::plant::simulate: N_VNew_Serial failed", 0, 0.0);
  double* x = N_VGetArrayPointer_Serial(y.get());
  x[kPosition] = s0.position;
  x[kVelocity] = s0.velocity;
  x[kHeadPressure] = s0.head_pressure;
  x[kRodPressure] = s0.rod_pressure;
  x[kSpool] = s0.spool;
  double* atol = N_VGetArrayPointer_Serial(abstol.get());
  const Tolerances& tol = options.tolerances;
  atol[kPosition] = tol.absolute_position;
  atol[kVelocity] = tol.absolute_velocity;
  atol[kHeadPressure] = tol.absolute_pressure;
  atol[kRodPressure] = tol.absolute_pressure;
  atol[kSpool] = tol.absolute_spool;

  CvodePtr mem(CVodeCreate(CV_BDF, ctx.get()));
  if (!mem) throw CvodeError("bonl::plant::simulate: CVodeCreate failed", 0, 0.0);
  check(CVodeSetErrHandlerFn(mem.get(), error_handler, &data), "CVodeSetErrHandlerFn", 0.0, data);
  check(CVodeInit(mem.get(), rhs_callback, 0.0, y.get()), "CVodeInit", 0.0, data);
  check(CVodeSVtolerances(mem.get(), tol.relative, abstol.get()), "CVodeSVtolerances", 0.0, data);
  MatrixPtr jac(SUNDenseMatrix(kStateSize, kStateSize, ctx.get()));
  if (!jac) throw CvodeError("bonl::plant::simulate: SUNDenseMatrix failed", 0, 0.0);
  SolverPtr solver(SUNLinSol_Dense(y.get(), jac.get(), ctx.get()));
  if (!solver) throw CvodeError("bonl::plant::simulate: SUNLinSol_Dense failed", 0, 0.0);
  check(CVodeSetLinearSolver(mem.get(), solver.get(), jac.get()), "CVodeSetLinearSolver", 0.0, data);
  check(CVodeSetUserData(mem.get(), &data), "CVodeSetUserData", 0.0, data);
  check(CVodeSetMaxNumSteps(mem.get(), tol.max_steps_per_interval), "CVodeSetMaxNumSteps", 0.0, data);

  // --- Outputs ------------------------------------------------------------------------------
  Trajectory out;
  for (Eigen::VectorXd* v : {&out.time, &out.command, &out.input, &out.position, &out.velocity, &out.head_pressure,
                             &out.rod_pressure, &out.spool, &out.pilot, &out.head_flow, &out.rod_flow, &out.joint_angle,
                             &out.joint_rate, &out.pin_angle, &out.measured_angle}) {
    v->resize(n_out);
  }

  const double hv = parameters.pilot_hysteresis;
  const double half_backlash = 0.5 * parameters.joint_backlash;
  double pilot = 0.0;
  double pin = 0.0;
  out.min_position = h0;
  out.max_position = h0;

  const double phi0 = parameters.angle_offset();
  double t = 0.0;
  for (long j = 0; j <= n_grid; ++j) {
    const double tj = static_cast<double>(j) / rate;
    const double h = x[kPosition];
    const double v = x[kVelocity];
    if (!std::isfinite(h) || !std::isfinite(v) || !std::isfinite(x[kHeadPressure]) ||
        !std::isfinite(x[kRodPressure]) || !std::isfinite(x[kSpool]))
      throw CvodeError("bonl::plant::simulate: the state became non-finite at t = " + number(tj) + " s", 0, tj);

    // Command, pilot hysteresis and load, held over [t_j, t_{j+1}).
    const double voltage = command(tj);
    if (!std::isfinite(voltage))
      throw std::invalid_argument("bonl::plant::simulate: the command is not finite at t = " + number(tj) +
                                  " s, got " + number(voltage));
    const double opening = commanded_opening(parameters, voltage);
    pilot = j == 0 ? opening : bonl::Backlash<double>::map(opening, pilot, hv);
    double load = 0.0;
    if (options.load) {
      load = options.load(tj);
      if (!std::isfinite(load))
        throw std::invalid_argument("bonl::plant::simulate: the load is not finite at t = " + number(tj) +
                                    " s, got " + number(load));
    }

    // Pin backlash on the joint angle.
    const double theta = parameters.linkage_angle(h) - phi0;
    pin = j == 0 ? theta : bonl::Backlash<double>::map(theta, pin, half_backlash);
    out.min_position = std::min(out.min_position, h);
    out.max_position = std::max(out.max_position, h);
    if (h < 0.0 || h > parameters.stroke) out.reached_end_stop = true;

    if (j % per_sample == 0) {
      const Eigen::Index k = j / per_sample;
      const detail::Flows q = model.flows(x[kHeadPressure], x[kRodPressure], x[kSpool]);
      out.time[k] = static_cast<double>(k) * options.sample_time;
      out.command[k] = voltage;
      out.input[k] = voltage - parameters.neutral_voltage;
      out.position[k] = h;
      out.velocity[k] = v;
      out.head_pressure[k] = x[kHeadPressure];
      out.rod_pressure[k] = x[kRodPressure];
      out.spool[k] = x[kSpool];
      out.pilot[k] = pilot;
      out.head_flow[k] = q.head;
      out.rod_flow[k] = q.rod;
      out.joint_angle[k] = theta;
      out.joint_rate[k] = v / parameters.moment_arm(h);
      out.pin_angle[k] = pin;
    }
    if (j == n_grid) break;

    data.pilot = pilot;
    data.load = load;
    const double t_next = static_cast<double>(j + 1) / rate;
    check(CVodeSetStopTime(mem.get(), t_next), "CVodeSetStopTime", t, data);
    const int flag = CVode(mem.get(), t_next, y.get(), &t, CV_NORMAL);
    check(flag, "CVode", t, data);
  }

  long steps = 0;
  check(CVodeGetNumSteps(mem.get(), &steps), "CVodeGetNumSteps", t, data);
  out.steps = steps;

  // Sensor noise on the measured angle.
  out.measured_angle = out.pin_angle;
  if (options.sensor_noise && parameters.sensor_noise > 0.0) {
    std::mt19937_64 engine(options.noise_seed);
    std::normal_distribution<double> standard_normal(0.0, 1.0);
    for (Eigen::Index k = 0; k < n_out; ++k) out.measured_angle[k] += parameters.sensor_noise * standard_normal(engine);
  }
  return out;
}

}  // namespace bonl::plant
