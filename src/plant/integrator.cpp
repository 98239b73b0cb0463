// The plant integrated with SUNDIALS CVODE (BDF, Newton, dense direct solver, exact Jacobian) one
// output sample at a time, with the command, the pilot hysteresis, the load and the pin backlash on
// the command grid (docs/explanation/plant.md). The spool's linear lag is solved exactly on the grid; CVODE
// integrates the other four states across the grid points, interpolates them there and stops at the
// end of each output sample and where the load changes.

#include "integrator.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <utility>

#include "bonl/blocks/backlash.hpp"
#include "bonl/detail/validate.hpp"

namespace bonl::plant::detail {

namespace {

/// std::invalid_argument("bonl: <where>: <name> <requirement>, got <value>").
[[noreturn]] void bad_option(const char* where, const char* name, const std::string& requirement, double value) {
  bonl::detail::fail(std::string(where) + ": " + name + ' ' + requirement + ", got " +
                     bonl::detail::format_number(value));
}

void require_positive(const char* where, const char* name, double value) {
  if (!(std::isfinite(value) && value > 0.0)) bad_option(where, name, "must be > 0 and finite", value);
}

/// Counted in doubles before anything is sized by them: a duration of 1e19 s would overflow the
/// integer counts, and 1e8 command intervals (a day at 1 kHz) already take about a minute.
constexpr double kMaxIntervals = 1e8;

/// Inputs are read ahead and CVODE integrates over at most this many command intervals at a time,
/// which bounds the buffers of a long sample.
constexpr long kMaxChunk = 4096;

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

/// The exact Jacobian (Model::mechanical_jacobian) in CVODE's dense column-major matrix.
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

struct FreeDeleter {
  void operator()(char* p) const noexcept { std::free(p); }
};

std::string flag_name(int flag) {
  std::unique_ptr<char, FreeDeleter> name(CVodeGetReturnFlagName(flag));
  return name ? std::string(name.get()) : "flag " + std::to_string(flag);
}

/// The spool's decay over one command interval, exp(-dt / tau_v).
double spool_decay(const Parameters& p, double command_rate) {
  return std::exp(-1.0 / (command_rate * p.valve_time_constant));
}

/// Pilot-stage input kv * uv for a command V (plant.md 1-2, before the hysteresis).
double commanded_opening(const Parameters& p, double voltage) {
  const double e = std::clamp(voltage, 0.0, p.max_voltage) - p.neutral_voltage;
  const double magnitude = std::max(std::abs(e) - p.dead_band, 0.0);
  const double uv = e < 0.0 ? -magnitude : magnitude;
  return p.valve_gain() * uv;
}

}  // namespace

void ContextDeleter::operator()(SUNContext ctx) const noexcept { SUNContext_Free(&ctx); }
void VectorDeleter::operator()(N_Vector v) const noexcept { N_VDestroy(v); }
void MatrixDeleter::operator()(SUNMatrix m) const noexcept { SUNMatDestroy(m); }
void SolverDeleter::operator()(SUNLinearSolver s) const noexcept { SUNLinSolFree(s); }
void CvodeDeleter::operator()(void* mem) const noexcept { CVodeFree(&mem); }

void validate_options(const SimulationOptions& options, const Parameters& parameters, const char* where,
                      bool duration) {
  if (duration) require_positive(where, "duration", options.duration);
  require_positive(where, "sample_time", options.sample_time);
  require_positive(where, "command_rate", options.command_rate);
  const double per_sample = options.sample_time * options.command_rate;
  const double whole = std::round(per_sample);
  if (!(whole >= 1.0 && std::abs(per_sample - whole) <= 1e-9 * whole))
    bad_option(where, "sample_time",
               "must be an integer multiple of 1 / command_rate (" +
                   bonl::detail::format_number(1.0 / options.command_rate) + " s)",
               options.sample_time);
  if (!duration && whole > kMaxIntervals)  // simulate's duration bounds it below
    bad_option(where, "sample_time",
               "gives " + bonl::detail::format_number(whole) +
                   " command intervals per sample (sample_time * command_rate); at most " +
                   bonl::detail::format_number(kMaxIntervals),
               options.sample_time);
  if (duration) {
    const double samples = options.duration / options.sample_time;
    const double whole_samples = std::round(samples);
    if (!(whole_samples >= 1.0 && std::abs(samples - whole_samples) <= 1e-9 * whole_samples))
      bad_option(
          where, "duration",
          "must be an integer multiple of sample_time (" + bonl::detail::format_number(options.sample_time) + " s)",
          options.duration);
    if (whole_samples * whole > kMaxIntervals)
      bad_option(where, "duration",
                 "gives " + bonl::detail::format_number(whole_samples * whole) +
                     " command intervals (duration * command_rate); at most " +
                     bonl::detail::format_number(kMaxIntervals) + " per run (simulate a long record in pieces)",
                 options.duration);
  }
  const Tolerances& tol = options.tolerances;
  require_positive(where, "tolerances.relative", tol.relative);
  if (!(tol.relative < 1.0)) bad_option(where, "tolerances.relative", "must be < 1", tol.relative);
  require_positive(where, "tolerances.absolute_position", tol.absolute_position);
  require_positive(where, "tolerances.absolute_velocity", tol.absolute_velocity);
  require_positive(where, "tolerances.absolute_pressure", tol.absolute_pressure);
  require_positive(where, "tolerances.absolute_spool", tol.absolute_spool);
  if (tol.max_steps_per_interval < 1)
    bad_option(where, "tolerances.max_steps_per_interval", "must be >= 1",
               static_cast<double>(tol.max_steps_per_interval));
  if (!std::isfinite(options.initial_position) || options.initial_position > parameters.stroke)
    bad_option(where, "initial_position",
               "must be finite and <= stroke (" + bonl::detail::format_number(parameters.stroke) +
                   " m); negative means mid-stroke",
               options.initial_position);
}

double UserData::spool_at(double t) const noexcept {
  const auto last = static_cast<long>(pilot.size()) - 1;
  const double position = std::floor(t * rate) - static_cast<double>(first);
  const long i = position <= 0.0 ? 0 : (position >= static_cast<double>(last) ? last : static_cast<long>(position));
  const double xc = pilot[static_cast<std::size_t>(i)];
  const double x0 = spool[static_cast<std::size_t>(i)];
  return xc + (x0 - xc) * std::exp(-(t - grid_time(first + i)) * inv_tau);
}

Integrator::Integrator(const Parameters& parameters, const SimulationOptions& options, std::string where)
    : m_parameters(parameters), m_load(options.load), m_where(std::move(where)),
      m_data(parameters, options.command_rate), m_per_sample(std::lround(options.sample_time * options.command_rate)),
      m_sample_time(options.sample_time), m_decay(spool_decay(parameters, options.command_rate)),
      m_phi0(parameters.angle_offset()), m_noise_requested(options.sensor_noise),
      m_noise(m_noise_requested && parameters.sensor_noise > 0.0), m_engine(options.noise_seed) {
  const double h0 = options.initial_position >= 0.0 ? options.initial_position : 0.5 * parameters.stroke;
  const State s0 = initial_state(parameters, h0);

  SUNContext raw_ctx = nullptr;
  if (SUNContext_Create(nullptr, &raw_ctx) != 0 || raw_ctx == nullptr) fail_cvode("SUNContext_Create failed");
  m_context.reset(raw_ctx);
  m_y.reset(N_VNew_Serial(kMechanicalSize, m_context.get()));
  m_abstol.reset(N_VNew_Serial(kMechanicalSize, m_context.get()));
  if (!m_y || !m_abstol) fail_cvode("N_VNew_Serial failed");
  // Fused vector operations (one loop for CVODE's linear combinations of the Nordsieck history
  // instead of a chain of pairwise sums); CVODE's own vectors are clones of y and inherit them.
  if (N_VEnableFusedOps_Serial(m_y.get(), SUNTRUE) != 0) fail_cvode("N_VEnableFusedOps_Serial failed");
  double* x = N_VGetArrayPointer_Serial(m_y.get());
  x[kPosition] = s0.position;
  x[kVelocity] = s0.velocity;
  x[kHeadPressure] = s0.head_pressure;
  x[kRodPressure] = s0.rod_pressure;
  double* atol = N_VGetArrayPointer_Serial(m_abstol.get());
  const Tolerances& tol = options.tolerances;
  atol[kPosition] = tol.absolute_position;
  atol[kVelocity] = tol.absolute_velocity;
  atol[kHeadPressure] = tol.absolute_pressure;
  atol[kRodPressure] = tol.absolute_pressure;

  m_cvode.reset(CVodeCreate(CV_BDF, m_context.get()));
  if (!m_cvode) fail_cvode("CVodeCreate failed");
  void* mem = m_cvode.get();
  check(CVodeSetErrHandlerFn(mem, error_handler, &m_data), "CVodeSetErrHandlerFn", 0.0);
  check(CVodeInit(mem, rhs_callback, 0.0, m_y.get()), "CVodeInit", 0.0);
  check(CVodeSVtolerances(mem, tol.relative, m_abstol.get()), "CVodeSVtolerances", 0.0);
  m_jacobian.reset(SUNDenseMatrix(kMechanicalSize, kMechanicalSize, m_context.get()));
  if (!m_jacobian) fail_cvode("SUNDenseMatrix failed");
  m_solver.reset(SUNLinSol_Dense(m_y.get(), m_jacobian.get(), m_context.get()));
  if (!m_solver) fail_cvode("SUNLinSol_Dense failed");
  check(CVodeSetLinearSolver(mem, m_solver.get(), m_jacobian.get()), "CVodeSetLinearSolver", 0.0);
  check(CVodeSetJacFn(mem, jacobian_callback), "CVodeSetJacFn", 0.0);
  check(CVodeSetUserData(mem, &m_data), "CVodeSetUserData", 0.0);
  check(CVodeSetMaxNumSteps(mem, tol.max_steps_per_interval), "CVodeSetMaxNumSteps", 0.0);

  m_spool = s0.spool;
  m_min_position = h0;
  m_max_position = h0;
  record(0);
  measure();
}

Integrator::~Integrator() = default;

void Integrator::fail_cvode(const std::string& what) const {
  throw CvodeError("bonl: " + m_where + ": " + what, 0, 0.0);
}

/// Throws CvodeError when a CVODE call returned a negative flag.
void Integrator::check(int flag, const char* call, double time) const {
  if (flag >= 0) return;
  std::string message = "bonl: " + m_where + ": " + call + " failed with " + flag_name(flag) +
                        " at t = " + bonl::detail::format_number(time) + " s";
  if (!m_data.last_error.empty()) message += " (" + m_data.last_error + ")";
  throw CvodeError(message, flag, time);
}

long Integrator::steps() const {
  long steps = 0;
  check(CVodeGetNumSteps(m_cvode.get(), &steps), "CVodeGetNumSteps", m_measurement.time);
  return steps;
}

GridInputs Integrator::read_inputs(const Command& command, long j, double previous_pilot) const {
  const double tj = m_data.grid_time(j);
  GridInputs in;
  in.voltage = command(tj);
  if (!std::isfinite(in.voltage))
    bonl::detail::fail(m_where + ": the command is not finite at t = " + bonl::detail::format_number(tj) + " s, got " +
                       bonl::detail::format_number(in.voltage));
  const double opening = commanded_opening(m_parameters, in.voltage);
  // The play operator starts engaged at its input's first value (plant.md).
  in.pilot = j == 0 ? opening : bonl::Backlash<double>::map(opening, previous_pilot, m_parameters.pilot_hysteresis);
  if (m_load) {
    in.load = m_load(tj);
    if (!std::isfinite(in.load))
      bonl::detail::fail(m_where + ": the load is not finite at t = " + bonl::detail::format_number(tj) + " s, got " +
                         bonl::detail::format_number(in.load));
  }
  return in;
}

void Integrator::set_parameters(const Parameters& parameters) {
  if (m_failed)
    throw std::logic_error("bonl: " + m_where + ": a step failed at t = " + bonl::detail::format_number(m_failed_at) +
                           " s and left the plant between samples; reset() it");
  // Everything derived from the parameters is computed before anything changes (none of it throws).
  const Model model(parameters);
  const double time = m_measurement.time;
  // The state is CVODE's y at the current sample time; only the history of its BDF steps goes.
  check(CVodeReInit(m_cvode.get(), time, m_y.get()), "CVodeReInit", time);
  m_parameters = parameters;
  m_data.model = model;
  m_data.inv_tau = model.inverse_time_constant();
  m_decay = spool_decay(parameters, m_data.rate);
  m_noise = m_noise_requested && parameters.sensor_noise > 0.0;
}

GridInputs Integrator::inputs_now(const Command& command) { return read_inputs(command, m_grid, m_pilot); }

GridInputs Integrator::advance(const Command& command) {
  if (m_failed)
    throw std::logic_error("bonl: " + m_where + ": a step failed at t = " + bonl::detail::format_number(m_failed_at) +
                           " s and left the plant between samples; reset() it");
  const long start = m_grid;
  const long end = start + m_per_sample;
  GridInputs first;
  double pilot = m_pilot;
  double spool = m_spool;
  while (m_grid < end) {
    // Read the chunk's inputs (which may throw) before CVODE or any state changes.
    const long intervals = std::min(end - m_grid, kMaxChunk);
    m_data.first = m_grid;
    m_data.pilot.clear();
    m_data.loads.clear();
    m_data.spool.assign(1, spool);
    for (long i = 0; i < intervals; ++i) {
      const GridInputs in = read_inputs(command, m_grid + i, pilot);
      if (m_grid + i == start) first = in;
      pilot = in.pilot;
      spool = pilot + (spool - pilot) * m_decay;  // xv(t_{j+1}), exact
      m_data.pilot.push_back(pilot);
      m_data.loads.push_back(in.load);
      m_data.spool.push_back(spool);
    }
    if (m_grid == start) m_step_end_stop = false;
    m_failed = true;
    m_failed_at = m_data.grid_time(m_grid);
    integrate_chunk(intervals);
  }
  m_failed = false;
  m_pilot = pilot;
  m_spool = spool;
  ++m_sample;
  measure();
  return first;
}

void Integrator::integrate_chunk(long intervals) {
  void* mem = m_cvode.get();
  double t = m_data.grid_time(m_grid);
  long i = 0;
  while (i < intervals) {
    // CVODE stops at the chunk's end (the sample's, at most kMaxChunk intervals on) and where the
    // load changes; the pilot enters only through the exact, continuous spool opening.
    long stop = i + 1;
    while (stop < intervals &&
           m_data.loads[static_cast<std::size_t>(stop)] == m_data.loads[static_cast<std::size_t>(i)])
      ++stop;
    m_data.load = m_data.loads[static_cast<std::size_t>(i)];
    check(CVodeSetStopTime(mem, m_data.grid_time(m_data.first + stop)), "CVodeSetStopTime", t);
    for (; i < stop; ++i) {
      check(CVode(mem, m_data.grid_time(m_data.first + i + 1), m_y.get(), &t, CV_NORMAL), "CVode", t);
      record(m_data.first + i + 1);
    }
  }
}

/// The state at grid point j (as CVODE returned it): the pin backlash, the stroke range.
void Integrator::record(long j) {
  const double* x = N_VGetArrayPointer_Serial(m_y.get());
  const double h = x[kPosition];
  const double tj = m_data.grid_time(j);
  if (!std::isfinite(h) || !std::isfinite(x[kVelocity]) || !std::isfinite(x[kHeadPressure]) ||
      !std::isfinite(x[kRodPressure]))
    throw CvodeError(
        "bonl: " + m_where + ": the state became non-finite at t = " + bonl::detail::format_number(tj) + " s", 0, tj);
  m_theta = m_parameters.linkage_angle(h) - m_phi0;
  m_pin = j == 0 ? m_theta : bonl::Backlash<double>::map(m_theta, m_pin, 0.5 * m_parameters.joint_backlash);
  m_min_position = std::min(m_min_position, h);
  m_max_position = std::max(m_max_position, h);
  if (h < 0.0 || h > m_parameters.stroke) {
    m_reached_end_stop = true;
    m_step_end_stop = true;
  }
  m_grid = j;
}

/// The measurement at the current sample time, with its sensor noise.
void Integrator::measure() {
  const double* x = N_VGetArrayPointer_Serial(m_y.get());
  Measurement& m = m_measurement;
  m.time = static_cast<double>(m_sample) * m_sample_time;
  m.position = x[kPosition];
  m.velocity = x[kVelocity];
  m.head_pressure = x[kHeadPressure];
  m.rod_pressure = x[kRodPressure];
  m.spool = m_spool;
  m.pilot = m_pilot;
  const Flows q = m_data.model.flows(m.head_pressure, m.rod_pressure, m_spool);
  m.head_flow = q.head;
  m.rod_flow = q.rod;
  m.joint_angle = m_theta;
  m.joint_rate = m.velocity / m_parameters.moment_arm(m.position);
  m.pin_angle = m_pin;
  m.measured_angle = m_pin;
  if (m_noise) m.measured_angle += m_parameters.sensor_noise * m_standard_normal(m_engine);
  m.reached_end_stop = m_step_end_stop;
}

}  // namespace bonl::plant::detail
