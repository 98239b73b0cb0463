#pragma once
// Private to src/plant: the plant's integration one output sample at a time, the one core that
// simulate (a loop over it) and SteppingPlant (one sample per step) share (docs/explanation/plant.md).

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>

#include <memory>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "bonl/plant/parameters.hpp"
#include "bonl/plant/simulator.hpp"
#include "bonl/plant/stepping_plant.hpp"
#include "model.hpp"

namespace bonl::plant::detail {

/// Validates the options the integration uses (std::invalid_argument "bonl: <where>: <option> ...,
/// got <value>"): the grids, the tolerances and the initial position; with `duration` (simulate),
/// also the duration (a positive multiple of sample_time, at most 1e8 command intervals in all),
/// without it (SteppingPlant) at most 1e8 command intervals per sample. The parameters are
/// Parameters::validate's.
void validate_options(const SimulationOptions& options, const Parameters& parameters, const char* where, bool duration);

/// One command-grid point's inputs, held over [t_j, t_{j+1}): the command, the pilot stage's output
/// after it (the play operator) and the load.
struct GridInputs {
  double voltage = 0.0;  ///< V(t_j) [V]
  double pilot = 0.0;    ///< xc [-]
  double load = 0.0;     ///< F_L(t_j) [N]
};

/// What CVODE's right-hand side sees: the model, the load held over the current stretch of the
/// command grid, and the pilot outputs with the spool openings they give. The spool's lag
/// tau_v dxv/dt = xc - xv is linear and driven only by the held pilot output, so it is solved
/// exactly, interval by interval, and CVODE integrates the other four states with xv(t) known:
/// xv(t) = xc_i + (xv_i - xc_i) exp(-(t - t_i) / tau_v) on [t_i, t_{i+1}). xv is continuous, so
/// CVODE may step across the grid points; it stops at the end of every output sample (the next
/// sample's command is not known yet) and where the load changes.
struct UserData {
  UserData(const Parameters& parameters, double command_rate)
      : model(parameters), rate(command_rate), inv_tau(model.inverse_time_constant()) {}
  Model model;
  double rate;
  double inv_tau;
  double load = 0.0;          ///< F_L over the stretch CVODE integrates now
  long first = 0;             ///< command-grid index of the chunk's start
  std::vector<double> pilot;  ///< pilot[i]: xc held on [t_{first+i}, t_{first+i+1})
  std::vector<double> spool;  ///< spool[i]: xv(t_{first+i}), exact (one more entry than pilot)
  std::vector<double> loads;  ///< loads[i]: F_L held on [t_{first+i}, t_{first+i+1})
  std::string last_error;     ///< CVODE's last error message, for the exception

  double grid_time(long j) const noexcept { return static_cast<double>(j) / rate; }

  /// xv(t) within the current chunk (clamped to it: CVODE never integrates beyond the stop).
  double spool_at(double t) const noexcept;
};

// RAII for the SUNDIALS objects.
struct ContextDeleter {
  void operator()(SUNContext ctx) const noexcept;
};
struct VectorDeleter {
  void operator()(N_Vector v) const noexcept;
};
struct MatrixDeleter {
  void operator()(SUNMatrix m) const noexcept;
};
struct SolverDeleter {
  void operator()(SUNLinearSolver s) const noexcept;
};
struct CvodeDeleter {
  void operator()(void* mem) const noexcept;
};
using ContextPtr = std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter>;
using VectorPtr = std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter>;
using MatrixPtr = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter>;
using SolverPtr = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, SolverDeleter>;
using CvodePtr = std::unique_ptr<void, CvodeDeleter>;

/// The plant from rest at t = 0, advanced one output sample at a time: the command is read at every
/// command-grid point of the sample, the pilot hysteresis and the pin backlash are evaluated there,
/// CVODE integrates across the sample and stops at its end. The state at each sample time, with
/// that sample's sensor noise drawn in order from the seed, is measurement(). Neither copyable nor
/// movable (CVODE holds pointers into it).
class Integrator {
 public:
  /// parameters and options must be valid (Parameters::validate, validate_options); `where` starts
  /// the messages of the errors it throws ("simulate", "SteppingPlant").
  Integrator(const Parameters& parameters, const SimulationOptions& options, std::string where);
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;
  Integrator(Integrator&&) = delete;
  Integrator& operator=(Integrator&&) = delete;
  ~Integrator();

  /// Integrates from the current sample time t_k to t_{k+1}, reading command(t) and the load at each
  /// command-grid point of [t_k, t_{k+1}) in order; returns the inputs of t_k's grid point. The
  /// inputs of a sample (of its first 4096 grid points when it has more) are read before CVODE
  /// runs: an exception while reading them leaves the integrator as it was. Any later one (CVODE's
  /// CvodeError, a bad load beyond the first 4096 grid points) leaves it failed: advance() then
  /// throws std::logic_error.
  GridInputs advance(const Command& command);

  /// The plant's parameters from now on, the state kept (position, velocity, pressures, spool, pilot
  /// and pin memories, noise sequence): CVODE restarts its history at the current sample time, the
  /// right-hand side having changed there. `parameters` must be valid and keep the geometry that maps
  /// the position to the angle (SteppingPlant::set_parameters checks both).
  void set_parameters(const Parameters& parameters);

  /// The inputs of the current sample time's grid point under `command` (command and load read once;
  /// nothing advances): simulate's last sample.
  GridInputs inputs_now(const Command& command);

  const Measurement& measurement() const noexcept { return m_measurement; }
  long steps() const;  ///< CVODE's internal steps
  double min_position() const noexcept { return m_min_position; }
  double max_position() const noexcept { return m_max_position; }
  bool reached_end_stop() const noexcept { return m_reached_end_stop; }

 private:
  GridInputs read_inputs(const Command& command, long j, double previous_pilot) const;
  void integrate_chunk(long intervals);
  void record(long j);
  void measure();
  void check(int flag, const char* call, double time) const;
  [[noreturn]] void fail_cvode(const std::string& what) const;

  Parameters m_parameters;
  std::function<double(double)> m_load;
  std::string m_where;
  UserData m_data;
  long m_per_sample;
  double m_sample_time;
  double m_decay;  ///< the spool's decay over one command interval, exp(-dt / tau_v)
  double m_phi0;
  bool m_noise_requested;  ///< SimulationOptions::sensor_noise
  bool m_noise;

  // State at the current sample time (and, during an advance, at the last grid point reached).
  long m_sample = 0;     ///< k
  long m_grid = 0;       ///< command-grid index of the last grid point CVODE reached
  double m_pilot = 0.0;  ///< xc held over the last command interval (0 before the first)
  double m_spool = 0.0;  ///< xv at the current sample time
  double m_theta = 0.0;  ///< joint angle at the last grid point
  double m_pin = 0.0;    ///< pin angle at the last grid point (the play operator's memory)
  double m_min_position = 0.0;
  double m_max_position = 0.0;
  bool m_reached_end_stop = false;
  bool m_step_end_stop = false;  ///< h left [0, L] during the current sample
  bool m_failed = false;
  double m_failed_at = 0.0;
  Measurement m_measurement;

  std::mt19937_64 m_engine;
  std::normal_distribution<double> m_standard_normal{0.0, 1.0};

  ContextPtr m_context;
  VectorPtr m_y;
  VectorPtr m_abstol;
  CvodePtr m_cvode;
  MatrixPtr m_jacobian;
  SolverPtr m_solver;
};

}  // namespace bonl::plant::detail
