#pragma once
// The plant one sample at a time: an object that holds the CVODE state and advances one output
// sample per command, `measurement = plant.step(command)`, for a controller or an online estimator
// in the loop. It is the core simulate itself runs on (simulate is a loop over it), so the same
// command sequence gives the same trajectory, sample for sample (docs/explanation/plant.md, "Stepping").

#include <cstdint>
#include <memory>

#include "parameters.hpp"
#include "simulator.hpp"

namespace bonl::plant {

namespace detail {
class Integrator;
}

/// The plant at one sample time t_k = k * sample_time: the measured angle, and the true states for
/// analysis (they equal simulate's Trajectory at sample k; `pilot` is the exception, below).
struct Measurement {
  double time = 0.0;            ///< t_k [s]
  double measured_angle = 0.0;  ///< pin_angle + sensor noise: what the inclinometer reads [rad]
  double position = 0.0;        ///< h [m]
  double velocity = 0.0;        ///< v [m/s]
  double head_pressure = 0.0;   ///< p1 [Pa]
  double rod_pressure = 0.0;    ///< p2 [Pa]
  double spool = 0.0;           ///< xv [-]
  /// xc, the pilot stage's output held over the last command interval before t_k (the hysteresis'
  /// memory; 0 before the first step) [-]. simulate's pilot[k] is xc after the command V(t_k), so
  /// under a command held over each sample this is simulate's pilot[k - 1].
  double pilot = 0.0;
  double head_flow = 0.0;    ///< Q1, into the head chamber [m^3/s]
  double rod_flow = 0.0;     ///< Q2, out of the rod chamber [m^3/s]
  double joint_angle = 0.0;  ///< theta [rad]
  double joint_rate = 0.0;   ///< dtheta/dt = v / r(h) [rad/s]
  double pin_angle = 0.0;    ///< theta_m = play(theta; delta / 2), noise-free [rad]
  /// h left [0, L] at a command-grid point of the step that ended at t_k (at t_0: h0 outside it).
  bool reached_end_stop = false;
};

/// The dipper-joint plant advanced one output sample per call. From rest at t = 0 (as simulate
/// starts), `step(V)` holds the command V over [t_k, t_{k+1}) (sample_time * command_rate
/// command-grid intervals), integrates with CVODE and returns the measurement at t_{k+1}. So the
/// commands V_0, V_1, ... give the measurements at t_1, t_2, ...; the one at t_0 is what the
/// constructor and reset() return. simulate under a command held over each sample
/// (excitation::sampled(V, sample_time)) gives the same samples; its sample k pairs the state at t_k
/// with the command V_k that follows it.
///
/// The options are SimulationOptions without `duration` (the plant runs as long as it is stepped),
/// validated as simulate validates them; the load F_L(t) is read on the command grid, as in simulate;
/// the sensor noise of sample k is simulate's (the same seed, the same sequence). Movable, not
/// copyable (it owns CVODE's memory).
class SteppingPlant {
 public:
  /// Validates the parameters and the options (std::invalid_argument naming them) and starts at
  /// t = 0 from rest at options.initial_position (negative: mid-stroke).
  /// \param parameters the plant
  /// \param options the grids, tolerances, load, noise and initial position (its duration is not used)
  explicit SteppingPlant(const Parameters& parameters, const SimulationOptions& options = {});
  SteppingPlant(const SteppingPlant&) = delete;
  SteppingPlant& operator=(const SteppingPlant&) = delete;
  SteppingPlant(SteppingPlant&&) noexcept;             ///< movable (the CVODE state moves with it), not copyable
  SteppingPlant& operator=(SteppingPlant&&) noexcept;  ///< movable, not copyable \return *this
  ~SteppingPlant();

  /// Holds `command` [V] over one sample and returns the measurement at the sample's end. A
  /// non-finite command throws std::invalid_argument and leaves the plant as it was (so does a load
  /// that is not finite on the sample's first 4096 command-grid points). A CVODE failure throws
  /// CvodeError and leaves the plant failed: step() then throws std::logic_error until reset().
  /// \param command V over [t_k, t_{k+1}) [V]
  /// \return the measurement at t_{k+1}
  Measurement step(double command);

  /// Back to rest at t = 0 with options().initial_position and options().noise_seed: the same
  /// measurements again for the same commands.
  /// \return the measurement at t = 0
  Measurement reset();
  /// Back to rest at t = 0 at `initial_position` [m] (negative: mid-stroke) with `noise_seed`; both
  /// become the options' for later resets. A bad position throws std::invalid_argument and changes
  /// nothing.
  /// \param initial_position h0 [m]
  /// \param noise_seed the sensor noise's seed
  /// \return the measurement at t = 0
  Measurement reset(double initial_position, std::uint64_t noise_seed);

  /// The plant changes from the current sample on, as a machine's does in service (the oil warms and
  /// its bulk modulus drops, the pilot valve wears): the next step() runs with `parameters`, from the
  /// state the plant is in (position, velocity, pressures, spool, the hysteresis' and the backlash's
  /// memories, the noise sequence). The geometry that maps the piston position to the joint angle
  /// (stroke, pivot_to_rod_pin, pivot_to_base_pin, retracted_length) must stay as it is: another
  /// linkage is another machine. Non-physical parameters or a changed geometry throw
  /// std::invalid_argument naming them and change nothing. Later reset()s keep the new parameters.
  /// \param parameters the plant from now on
  void set_parameters(const Parameters& parameters);

  /// The latest: at time()
  /// \return the measurement, valid until the next step() or reset()
  const Measurement& measurement() const;
  double time() const;  ///< t_k [s] \return t_k [s]
  /// CVODE's internal steps since the start or reset()
  /// \return the number of steps
  long steps() const;
  /// The plant's parameters
  /// \return the parameters in force
  const Parameters& parameters() const noexcept { return m_parameters; }
  /// The simulation options it was started with
  /// \return the options, with a reset()'s position and seed
  const SimulationOptions& options() const noexcept { return m_options; }

 private:
  const detail::Integrator& integrator() const;

  Parameters m_parameters;
  SimulationOptions m_options;
  std::unique_ptr<detail::Integrator> m_integrator;
};

}  // namespace bonl::plant
