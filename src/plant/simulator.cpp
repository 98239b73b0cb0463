// The dipper-joint plant integrated with SUNDIALS CVODE (BDF, Newton, dense direct solver, exact
// Jacobian), with the command, the pilot hysteresis, the load and the pin backlash on the command
// grid (docs/plant.md). The spool's linear lag is solved exactly on the grid; CVODE integrates the
// other four states across the grid points and interpolates them there.

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
#include <stdexcept>
#include <string>
#include <vector>

#include "bonl/blocks/backlash.hpp"
#include "bonl/detail/validate.hpp"
#include "model.hpp"

namespace bonl::plant {

namespace {

using detail::kHeadPressure;
using detail::kMechanicalSize;
using detail::kPosition;
using detail::kRodPressure;
using detail::kSpool;
using detail::kStateSize;
using detail::kVelocity;

/// std::invalid_argument("bonl: simulate: <name> <requirement>, got <value>").
void bad_option(const char* name, const std::string& requirement, double value) {
  bonl::detail::fail("simulate: " + std::string(name) + ' ' + requirement + ", got " +
                     bonl::detail::format_number(value));
}

void require_positive(const char* name, double value) {
  if (!(std::isfinite(value) && value > 0.0)) bad_option(name, "must be > 0 and finite", value);
}

/// What CVODE's right-hand side sees: the model, the load held over the current segment of the
/// command grid, and the segment's pilot outputs with the spool opening they give. The spool's lag
/// tau_v dxv/dt = xc - xv is linear and driven only by the held pilot output, so it is solved
/// exactly, interval by interval, and CVODE integrates the other four states with xv(t) known:
/// xv(t) = xc_i + (xv_i - xc_i) exp(-(t - t_i) / tau_v) on [t_i, t_{i+1}). xv is continuous, so
/// CVODE may step across the grid points; it stops only where the load changes.
struct UserData {
  explicit UserData(const Parameters& parameters, double command_rate)
      : model(parameters), rate(command_rate), inv_tau(model.inverse_time_constant()) {}
  detail::Model model;
  double rate;
  double inv_tau;
  double load = 0.0;
  long first = 0;               ///< command-grid index of the segment's start
  std::vector<double> pilot;    ///< pilot[i]: xc held on [t_{first+i}, t_{first+i+1})
  std::vector<double> spool;    ///< spool[i]: xv(t_{first+i}), exact (one more entry than pilot)
  std::vector<double> voltage;  ///< voltage[i]: V(t_{first+i})
  std::string last_error;       ///< CVODE's last error message, for the exception

  double grid_time(long j) const noexcept { return static_cast<double>(j) / rate; }

  /// xv(t) within the current segment (clamped to it: CVODE never integrates beyond the stop).
  double spool_at(double t) const noexcept {
    const auto last = static_cast<long>(pilot.size()) - 1;
    const double position = std::floor(t * rate) - static_cast<double>(first);
    const long i = position <= 0.0 ? 0 : (position >= static_cast<double>(last) ? last : static_cast<long>(position));
    const double xc = pilot[static_cast<std::size_t>(i)];
    const double x0 = spool[static_cast<std::size_t>(i)];
    return xc + (x0 - xc) * std::exp(-(t - grid_time(first + i)) * inv_tau);
  }
};

int rhs_callback(sunrealtype t, N_Vector y, N_Vector ydot, void* user_data) {
  const auto* data = static_cast<const UserData*>(user_data);
  const double* x = N_VGetArrayPointer_Serial(y);
  double* dx = N_VGetArrayPointer_Serial(ydot);
  data->model.mechanical_rhs(x, data->spool_at(t), data->load, dx);
  for (int i = 0; i < kMechanicalSize; ++i) {
    if (!std::isfinite(dx[i])) return 1;  // recoverable: CVODE retries with a smaller step
  }
  return 0;
}

/// The exact Jacobian (detail::Model::mechanical_jacobian) in CVODE's dense column-major matrix.
int jacobian_callback(sunrealtype t, N_Vector y, N_Vector /*fy*/, SUNMatrix jacobian, void* user_data,
                      N_Vector /*tmp1*/, N_Vector /*tmp2*/, N_Vector /*tmp3*/) {
  const auto* data = static_cast<const UserData*>(user_data);
  const double* x = N_VGetArrayPointer_Serial(y);
  double jac[kMechanicalSize][kMechanicalSize];
  data->model.mechanical_jacobian(x, data->spool_at(t), jac);
  for (int k = 0; k < kMechanicalSize; ++k) {
    double* column = SUNDenseMatrix_Column(jacobian, k);
    for (int i = 0; i < kMechanicalSize; ++i) {
      if (!std::isfinite(jac[i][k])) return 1;
      column[i] = jac[i][k];
    }
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
  std::string message = "bonl: simulate: " + std::string(call) + " failed with " + flag_name(flag) +
                        " at t = " + bonl::detail::format_number(time) + " s";
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
    bad_option("sample_time", "must be an integer multiple of 1 / command_rate (" + bonl::detail::format_number(1.0 / options.command_rate) + " s)",
               options.sample_time);
  const double samples = options.duration / options.sample_time;
  const double whole_samples = std::round(samples);
  if (!(whole_samples >= 1.0 && std::abs(samples - whole_samples) <= 1e-9 * whole_samples))
    bad_option("duration", "must be an integer multiple of sample_time (" + bonl::detail::format_number(options.sample_time) + " s)",
               options.duration);
  // Counted in doubles before anything is sized by them: a duration of 1e19 s would overflow the
  // integer counts, and 1e8 command intervals (a day at 1 kHz) already take about a minute.
  constexpr double kMaxIntervals = 1e8;
  if (whole_samples * whole > kMaxIntervals)
    bad_option("duration", "gives " + bonl::detail::format_number(whole_samples * whole) + " command intervals (duration * command_rate); at most " +
                               bonl::detail::format_number(kMaxIntervals) + " per run (simulate a long record in pieces)",
               options.duration);
  const Tolerances& tol = options.tolerances;
  require_positive("tolerances.relative", tol.relative);
  if (!(tol.relative < 1.0)) bad_option("tolerances.relative", "must be < 1", tol.relative);
  require_positive("tolerances.absolute_position", tol.absolute_position);
  require_positive("tolerances.absolute_velocity", tol.absolute_velocity);
  require_positive("tolerances.absolute_pressure", tol.absolute_pressure);
  require_positive("tolerances.absolute_spool", tol.absolute_spool);
  if (tol.max_steps_per_interval < 1)
    bad_option("tolerances.max_steps_per_interval", "must be >= 1", static_cast<double>(tol.max_steps_per_interval));
  if (!std::isfinite(options.initial_position) || options.initial_position > parameters.stroke)
    bad_option("initial_position", "must be finite and <= stroke (" + bonl::detail::format_number(parameters.stroke) + " m); negative means mid-stroke",
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
  bonl::detail::require(static_cast<bool>(command), "simulate: command must not be empty");
  validate_options(options, parameters);

  const double rate = options.command_rate;
  const auto per_sample = static_cast<long>(std::lround(options.sample_time * rate));
  const auto n_intervals = static_cast<long>(std::lround(options.duration / options.sample_time));
  const long n_grid = n_intervals * per_sample;  // command-grid intervals
  const Eigen::Index n_out = n_intervals + 1;

  UserData data(parameters, rate);
  const detail::Model& model = data.model;
  const double h0 = options.initial_position >= 0.0 ? options.initial_position : 0.5 * parameters.stroke;
  const State s0 = initial_state(parameters, h0);

  // --- SUNDIALS objects ---------------------------------------------------------------------
  SUNContext raw_ctx = nullptr;
  if (SUNContext_Create(nullptr, &raw_ctx) != 0 || raw_ctx == nullptr)
    throw CvodeError("bonl: simulate: SUNContext_Create failed", 0, 0.0);
  ContextPtr ctx(raw_ctx);
  VectorPtr y(N_VNew_Serial(kMechanicalSize, ctx.get()));
  VectorPtr abstol(N_VNew_Serial(kMechanicalSize, ctx.get()));
  if (!y || !abstol) throw CvodeError("bonl: simulate: N_VNew_Serial failed", 0, 0.0);
  // Fused vector operations (one loop for CVODE's linear combinations of the Nordsieck history
  // instead of a chain of pairwise sums); CVODE's own vectors are clones of y and inherit them.
  if (N_VEnableFusedOps_Serial(y.get(), SUNTRUE) != 0)
    throw CvodeError("bonl: simulate: N_VEnableFusedOps_Serial failed", 0, 0.0);
  double* x = N_VGetArrayPointer_Serial(y.get());
  x[kPosition] = s0.position;
  x[kVelocity] = s0.velocity;
  x[kHeadPressure] = s0.head_pressure;
  x[kRodPressure] = s0.rod_pressure;
  double* atol = N_VGetArrayPointer_Serial(abstol.get());
  const Tolerances& tol = options.tolerances;
  atol[kPosition] = tol.absolute_position;
  atol[kVelocity] = tol.absolute_velocity;
  atol[kHeadPressure] = tol.absolute_pressure;
  atol[kRodPressure] = tol.absolute_pressure;

  CvodePtr mem(CVodeCreate(CV_BDF, ctx.get()));
  if (!mem) throw CvodeError("bonl: simulate: CVodeCreate failed", 0, 0.0);
  check(CVodeSetErrHandlerFn(mem.get(), error_handler, &data), "CVodeSetErrHandlerFn", 0.0, data);
  check(CVodeInit(mem.get(), rhs_callback, 0.0, y.get()), "CVodeInit", 0.0, data);
  check(CVodeSVtolerances(mem.get(), tol.relative, abstol.get()), "CVodeSVtolerances", 0.0, data);
  MatrixPtr jac(SUNDenseMatrix(kMechanicalSize, kMechanicalSize, ctx.get()));
  if (!jac) throw CvodeError("bonl: simulate: SUNDenseMatrix failed", 0, 0.0);
  SolverPtr solver(SUNLinSol_Dense(y.get(), jac.get(), ctx.get()));
  if (!solver) throw CvodeError("bonl: simulate: SUNLinSol_Dense failed", 0, 0.0);
  check(CVodeSetLinearSolver(mem.get(), solver.get(), jac.get()), "CVodeSetLinearSolver", 0.0, data);
  check(CVodeSetJacFn(mem.get(), jacobian_callback), "CVodeSetJacFn", 0.0, data);
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
  // The spool's decay over one command interval, exp(-dt / tau_v).
  const double decay = std::exp(-1.0 / (rate * parameters.valve_time_constant));
  out.min_position = h0;
  out.max_position = h0;
  const double phi0 = parameters.angle_offset();

  // Command, pilot hysteresis and load at grid point j, held over [t_j, t_{j+1}).
  double load = 0.0;
  const auto read_inputs = [&](long j, double previous_pilot, double& voltage, double& pilot) {
    const double tj = data.grid_time(j);
    voltage = command(tj);
    if (!std::isfinite(voltage))
      bonl::detail::fail("simulate: the command is not finite at t = " + bonl::detail::format_number(tj) + " s, got " +
                         bonl::detail::format_number(voltage));
    const double opening = commanded_opening(parameters, voltage);
    pilot = j == 0 ? opening : bonl::Backlash<double>::map(opening, previous_pilot, hv);
    load = 0.0;
    if (options.load) {
      load = options.load(tj);
      if (!std::isfinite(load))
        bonl::detail::fail("simulate: the load is not finite at t = " + bonl::detail::format_number(tj) + " s, got " +
                           bonl::detail::format_number(load));
    }
  };

  // The state at grid point j (x as CVODE returned it): pin backlash, stroke range, outputs.
  double pin = 0.0;
  const auto record = [&](long j, double voltage, double pilot, double spool) {
    const double tj = data.grid_time(j);
    const double h = x[kPosition];
    const double v = x[kVelocity];
    if (!std::isfinite(h) || !std::isfinite(v) || !std::isfinite(x[kHeadPressure]) ||
        !std::isfinite(x[kRodPressure]))
      throw CvodeError("bonl: simulate: the state became non-finite at t = " + bonl::detail::format_number(tj) + " s", 0, tj);
    const double theta = parameters.linkage_angle(h) - phi0;
    pin = j == 0 ? theta : bonl::Backlash<double>::map(theta, pin, half_backlash);
    out.min_position = std::min(out.min_position, h);
    out.max_position = std::max(out.max_position, h);
    if (h < 0.0 || h > parameters.stroke) out.reached_end_stop = true;
    if (j % per_sample != 0) return;
    const Eigen::Index k = j / per_sample;
    const detail::Flows q = model.flows(x[kHeadPressure], x[kRodPressure], spool);
    out.time[k] = static_cast<double>(k) * options.sample_time;
    out.command[k] = voltage;
    out.input[k] = voltage - parameters.neutral_voltage;
    out.position[k] = h;
    out.velocity[k] = v;
    out.head_pressure[k] = x[kHeadPressure];
    out.rod_pressure[k] = x[kRodPressure];
    out.spool[k] = spool;
    out.pilot[k] = pilot;
    out.head_flow[k] = q.head;
    out.rod_flow[k] = q.rod;
    out.joint_angle[k] = theta;
    out.joint_rate[k] = v / parameters.moment_arm(h);
    out.pin_angle[k] = pin;
  };

  // Segments of the command grid: the inputs of a segment's grid points are read before CVODE
  // integrates across it, and CVODE stops at its end (a load change, or kMaxSegment intervals to
  // bound the buffers). Within a segment the pilot output enters only through the exact, continuous
  // spool opening, so CVODE needs no stop at its jumps.
  constexpr long kMaxSegment = 4096;
  double voltage = 0.0;
  double pilot = 0.0;
  read_inputs(0, 0.0, voltage, pilot);
  double spool = s0.spool;
  record(0, voltage, pilot, spool);
  double t = 0.0;
  long j = 0;
  while (j < n_grid) {
    data.first = j;
    data.load = load;
    data.pilot.assign(1, pilot);
    data.spool.assign(1, spool);
    data.voltage.assign(1, voltage);
    long end = j;
    while (true) {
      ++end;
      spool = pilot + (spool - pilot) * decay;  // xv(t_end), exact
      read_inputs(end, pilot, voltage, pilot);
      data.spool.push_back(spool);
      data.voltage.push_back(voltage);
      if (end == n_grid || end - j == kMaxSegment || load != data.load) break;
      data.pilot.push_back(pilot);
    }
    check(CVodeSetStopTime(mem.get(), data.grid_time(end)), "CVodeSetStopTime", t, data);
    for (long i = j + 1; i <= end; ++i) {
      const double ti = data.grid_time(i);
      check(CVode(mem.get(), ti, y.get(), &t, CV_NORMAL), "CVode", t, data);
      const auto local = static_cast<std::size_t>(i - j);
      record(i, data.voltage[local], i == end ? pilot : data.pilot[local], data.spool[local]);
    }
    j = end;
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
