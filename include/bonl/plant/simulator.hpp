#pragma once
// The dipper-joint plant integrated by SUNDIALS CVODE (BDF, Newton iteration, dense linear solver).
// The command voltage is sampled and held on a 1 kHz grid (the controller's rate), where the pilot
// stage's hysteresis and the pin backlash, both play operators, are evaluated. The held pilot output
// drives only the spool's linear lag, which is solved exactly interval by interval; the spool
// opening is therefore continuous and CVODE integrates the other four states (h, v, p1, p2) across
// the grid points, which it reports by interpolation. It stops at every output sample (where the
// next sample's command may not be known yet: sample k depends only on the commands before t_k, and
// simulate is a loop over the stepping plant's core, stepping_plant.hpp) and where a held load changes.

#include <Eigen/Core>
#include <cstdint>
#include <functional>

#include "../error.hpp"
#include "parameters.hpp"

namespace bonl::plant {

/// Command voltage V(t) [V] on the 0-5 V scale (neutral 2.5 V).
using Command = std::function<double(double)>;

/// CVODE's error tolerances and step limit.
struct Tolerances {
  double relative = 1e-6;              ///< relative tolerance
  double absolute_position = 1e-8;     ///< h [m]
  double absolute_velocity = 1e-8;     ///< v [m/s]
  double absolute_pressure = 1.0;      ///< p1, p2 [Pa]
  double absolute_spool = 1e-8;        ///< xv [-] (validated; unused: the spool's lag is solved exactly)
  long max_steps_per_interval = 5000;  ///< CVODE steps per command-grid interval
};

/// What a simulation runs: its duration and grids, CVODE's tolerances, the load, the sensor noise and
/// the initial position.
struct SimulationOptions {
  double duration = 50.0;        ///< [s]
  double sample_time = 0.01;     ///< output grid [s]; an integer multiple of 1 / command_rate
  double command_rate = 1000.0;  ///< command grid [Hz]
  Tolerances tolerances;         ///< CVODE's tolerances
  /// External load F_L(t) [N] opposing extension; empty means none.
  std::function<double(double)> load;
  /// Sensor noise on the measured angle: added with this seed when sensor_noise is true.
  bool sensor_noise = true;
  std::uint64_t noise_seed = 1;  ///< the sensor noise's seed
  /// Initial piston position [m]; negative means mid-stroke (plant.md's start).
  double initial_position = -1.0;
};

/// Everything on the output grid, sample k at time[k] = k * sample_time.
struct Trajectory {
  Eigen::VectorXd time;            ///< [s]
  Eigen::VectorXd command;         ///< V, as held on the command grid [V]
  Eigen::VectorXd input;           ///< u = V - V0, the identification input [V]
  Eigen::VectorXd position;        ///< h [m]
  Eigen::VectorXd velocity;        ///< v [m/s]
  Eigen::VectorXd head_pressure;   ///< p1 [Pa]
  Eigen::VectorXd rod_pressure;    ///< p2 [Pa]
  Eigen::VectorXd spool;           ///< xv [-]
  Eigen::VectorXd pilot;           ///< xc, the pilot stage's output (after its hysteresis) [-]
  Eigen::VectorXd head_flow;       ///< Q1, into the head chamber [m^3/s]
  Eigen::VectorXd rod_flow;        ///< Q2, out of the rod chamber [m^3/s]
  Eigen::VectorXd joint_angle;     ///< theta [rad]
  Eigen::VectorXd joint_rate;      ///< dtheta/dt = v / r(h) [rad/s]
  Eigen::VectorXd pin_angle;       ///< theta_m = play(theta; delta / 2), noise-free [rad]
  Eigen::VectorXd measured_angle;  ///< theta_m + sensor noise [rad]
  double min_position = 0.0;       ///< smallest h reached on the command grid [m]
  double max_position = 0.0;       ///< largest h reached on the command grid [m]
  bool reached_end_stop = false;   ///< h left [0, L] at some point of the command grid
  long steps = 0;                  ///< CVODE's internal steps
};

/// CVODE failed: its return flag and the time it had reached.
class CvodeError : public NumericalError {
 public:
  /// The error message, CVODE's return flag and the time [s] it had reached.
  /// \param message what failed
  /// \param flag CVODE's return flag
  /// \param time the simulated time reached [s]
  CvodeError(const std::string& message, int flag, double time) : NumericalError(message), m_flag(flag), m_time(time) {}
  int flag() const noexcept { return m_flag; }  ///< CVODE's return flag \return the flag, < 0
  /// The simulated time [s] reached when CVODE failed
  /// \return the time [s]
  double time() const noexcept { return m_time; }

 private:
  int m_flag;
  double m_time;
};

/// The plant's state: the integrated variables of plant.md.
struct State {
  double position = 0.0;       ///< piston position h [m]
  double velocity = 0.0;       ///< piston velocity v [m/s]
  double head_pressure = 0.0;  ///< head-side chamber pressure p1 [Pa]
  double rod_pressure = 0.0;   ///< rod-side chamber pressure p2 [Pa]
  double spool = 0.0;          ///< valve spool position xv [-]
};
/// Initial state of plant.md's experiment at piston position h0 = position [m]: at rest, spool
/// closed, p2 = ps / 4, p1 from the force balance A1 p1 = A2 p2 + Fs(h0).
/// \param parameters the plant
/// \param position h0 [m]
/// \return the state at t = 0
State initial_state(const Parameters& parameters, double position);

/// Right-hand side of the plant's ODE for a held pilot output xc and load F_L: d(state)/dt.
/// Exposed so that tests can check it against an independent integrator.
/// \param parameters the plant
/// \param state the state
/// \param pilot the pilot stage's output xc [-]
/// \param load the external load F_L [N]
/// \return the state's time derivative, each entry in its unit per second
State derivative(const Parameters& parameters, const State& state, double pilot, double load);

/// Spring (gravity) force at the rod, Fs(h) = m_dcg g cos(theta + theta_g) / r(h) [N].
/// \param parameters the plant
/// \param position h [m]
/// \return Fs [N]
double gravity_force(const Parameters& parameters, double position);

/// Integrates the plant under `command`. Validates parameters and options (std::invalid_argument);
/// a CVODE failure throws CvodeError with CVODE's flag and the time reached. Sample k is the state
/// at t_k with the command V(t_k) and the pilot output after it; a SteppingPlant stepped with the
/// command held over each sample gives the same samples.
/// \param parameters the plant
/// \param command V(t) [V]
/// \param options the duration, grids, tolerances, load, noise and initial position
/// \return every variable on the output grid
Trajectory simulate(const Parameters& parameters, const Command& command, const SimulationOptions& options = {});

}  // namespace bonl::plant
