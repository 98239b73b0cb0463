#pragma once
// Parameters of the excavator dipper-joint plant (valve + asymmetric cylinder + linkage +
// backlash), as specified in docs/explanation/plant.md (copied from the project's design). Every value can be
// overridden; validate() rejects non-physical ones with a message that names the parameter.
// The comment after each member gives plant.md's symbol and unit.

namespace bonl::plant {

/// The excavator dipper-joint plant's parameters (valve, asymmetric cylinder, linkage, backlash) as
/// docs/explanation/plant.md specifies them, each member's comment giving the symbol and unit; validate() rejects
/// non-physical values with a message that names the parameter.
struct Parameters {
  // Cylinder
  double bore_diameter = 0.140;      ///< D [m]
  double rod_diameter = 0.100;       ///< d [m]
  double stroke = 1.50;              ///< L [m]
  double dead_volume_head = 2.0e-3;  ///< V01 [m^3]
  double dead_volume_rod = 2.0e-3;   ///< V02 [m^3]
  // Hydraulics
  double supply_pressure = 20e6;        ///< ps [Pa]
  double return_pressure = 0.3e6;       ///< pt [Pa]
  double bulk_modulus = 1.0e9;          ///< beta_e [Pa]
  double oil_density = 870.0;           ///< rho [kg/m^3]
  double discharge_coefficient = 0.61;  ///< Cd [-]
  double area_gradient = 1.08e-2;       ///< w [m]
  double spool_travel = 5e-3;           ///< xv_max [m]
  double internal_leakage = 5e-13;      ///< Ci [m^3/(s Pa)]
  double external_leakage = 0.0;        ///< Ce [m^3/(s Pa)]
  double orifice_smoothing = 1e5;       ///< dp_reg [Pa]
  // Valve and command
  double valve_time_constant = 0.05;  ///< tau_v [s]
  double dead_band = 0.08;            ///< d, input dead band half-width [V]
  double neutral_voltage = 2.5;       ///< V0 [V]
  double max_voltage = 5.0;           ///< command saturates to [0, max_voltage] [V]
  double pilot_hysteresis = 0.05;     ///< hv, half-width as a fraction of full opening [-]
  // Mechanics
  double mass = 1.44e4;               ///< M, equivalent moving mass at the rod [kg]
  double gravity_moment = 4.0e3;      ///< m_dcg, gravity first moment of stick + bucket [kg m]
  double gravity_angle_offset = 0.0;  ///< theta_g [rad]
  double gravity = 9.81;              ///< g [m/s^2]
  double coulomb_friction = 2.0e3;    ///< Fc [N]
  double static_friction = 2.8e3;     ///< Fst [N]
  double stribeck_velocity = 0.01;    ///< vs [m/s]
  double viscous_friction = 1.0e4;    ///< sigma_v [N s/m]
  double friction_smoothing = 1e-3;   ///< eps_v [m/s]
  double end_stop_stiffness = 1e8;    ///< k_end [N/m]
  double end_stop_damping = 1e6;      ///< c_end [N s/m]
  // Linkage
  double pivot_to_rod_pin = 0.85;   ///< a [m]
  double pivot_to_base_pin = 3.10;  ///< b [m]
  double retracted_length = 2.40;   ///< l_min, pin-to-pin length at h = 0 [m]
  // Measurement
  double joint_backlash = 3e-3;  ///< delta, total backlash in the pins [rad]
  double sensor_noise = 2e-4;    ///< sigma_theta, inclinometer noise (standard deviation) [rad]

  /// The 20 t excavator's stick cylinder (the defaults above).
  /// \return the parameters
  static Parameters excavator_20t() { return Parameters{}; }
  /// The 5-6 t machine of plant.md.
  /// \return the parameters
  static Parameters excavator_5t();

  /// Throws std::invalid_argument naming the first non-physical parameter.
  void validate() const;

  double head_area() const;     ///< A1 [m^2] \return A1 [m^2]
  double annulus_area() const;  ///< A2 [m^2] \return A2 [m^2]
  double flow_gain() const;     ///< Kq = Cd w xv_max sqrt(2 / rho) \return Kq [m^3/(s sqrt(Pa))]
  double valve_gain() const;    ///< kv = 1 / (V0 - d): a full command opens the spool fully \return kv [1/V]
  /// Linkage angle phi at piston position h (the law of cosines) [rad].
  /// \param h the piston position [m]
  /// \return phi [rad]
  double linkage_angle(double h) const;
  /// phi0: the angle zero, phi at mid-stroke.
  /// \return phi0 [rad]
  double angle_offset() const { return linkage_angle(0.5 * stroke); }
  /// Joint angle theta = phi(h) - phi0 [rad].
  /// \param h the piston position [m]
  /// \return theta [rad]
  double joint_angle(double h) const { return linkage_angle(h) - angle_offset(); }
  /// Moment arm r(h) = a b sin(phi) / l [m], so that dtheta/dt = v / r; the geometry is taken at h
  /// clamped to [0, stroke], as in the force model (outside only inside an end stop).
  /// \param h the piston position [m]
  /// \return r [m]
  double moment_arm(double h) const;
};

}  // namespace bonl::plant
