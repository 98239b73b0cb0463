#pragma once
// Private to src/plant: the plant's right-hand side with every derived constant precomputed, so
// that CVODE's calls allocate nothing and call no std::function (docs/explanation/plant.md, equations 3-6).

#include <algorithm>
#include <cmath>

#include "bonl/plant/parameters.hpp"

namespace bonl::plant::detail {

/// Indices of the state vector handed to CVODE.
enum StateIndex : int { kPosition = 0, kVelocity = 1, kHeadPressure = 2, kRodPressure = 3, kSpool = 4, kStateSize = 5 };
/// CVODE integrates the first four (h, v, p1, p2); the spool's linear lag is solved exactly.
inline constexpr int kMechanicalSize = 4;

struct Flows {
  double head = 0.0;  ///< Q1, into the head chamber
  double rod = 0.0;   ///< Q2, out of the rod chamber
};

class Model {
 public:
  explicit Model(const Parameters& p)
      : m_A1(p.head_area()), m_A2(p.annulus_area()), m_L(p.stroke), m_V01(p.dead_volume_head), m_V02(p.dead_volume_rod),
        m_ps(p.supply_pressure), m_pt(p.return_pressure), m_beta(p.bulk_modulus), m_Kq(p.flow_gain()),
        m_Ci(p.internal_leakage), m_Ce(p.external_leakage), m_dp_reg(p.orifice_smoothing),
        m_inv_tau(1.0 / p.valve_time_constant), m_inv_M(1.0 / p.mass), m_mg(p.gravity_moment * p.gravity),
        m_Fc(p.coulomb_friction), m_Fst(p.static_friction), m_inv_vs(1.0 / p.stribeck_velocity),
        m_sigma(p.viscous_friction), m_inv_eps(1.0 / p.friction_smoothing), m_k_end(p.end_stop_stiffness),
        m_c_end(p.end_stop_damping), m_a(p.pivot_to_rod_pin), m_b(p.pivot_to_base_pin), m_lmin(p.retracted_length) {
    // cos(theta + theta_g) = cos(phi + gamma) with gamma = theta_g - phi0.
    const double gamma = p.gravity_angle_offset - p.angle_offset();
    m_cos_gamma = std::cos(gamma);
    m_sin_gamma = std::sin(gamma);
  }

  /// Fs(h), with the geometry evaluated at h clamped to [0, L] (outside only inside an end stop).
  double gravity_force(double h) const noexcept {
    const double hc = std::clamp(h, 0.0, m_L);
    const double l = m_lmin + hc;
    const double c = std::clamp((m_a * m_a + m_b * m_b - l * l) / (2.0 * m_a * m_b), -1.0, 1.0);
    const double s = std::sqrt(1.0 - c * c);
    const double r = m_a * m_b * s / l;
    const double cos_theta_g = c * m_cos_gamma - s * m_sin_gamma;
    return m_mg * cos_theta_g / r;
  }

  double ssqrt(double dp) const noexcept { return dp / std::sqrt(std::abs(dp) + m_dp_reg); }

  Flows flows(double p1, double p2, double xv) const noexcept {
    Flows q;
    if (xv >= 0.0) {
      q.head = m_Kq * xv * ssqrt(m_ps - p1);
      q.rod = m_Kq * xv * ssqrt(p2 - m_pt);
    } else {
      q.head = m_Kq * xv * ssqrt(p1 - m_pt);
      q.rod = m_Kq * xv * ssqrt(m_ps - p2);
    }
    return q;
  }

  double friction(double v) const noexcept {
    const double ratio = v * m_inv_vs;
    return (m_Fc + (m_Fst - m_Fc) * std::exp(-ratio * ratio)) * std::tanh(v * m_inv_eps) + m_sigma * v;
  }

  double end_stop(double h, double v) const noexcept {
    if (h < 0.0) return m_k_end * h + m_c_end * v;
    if (h > m_L) return m_k_end * (h - m_L) + m_c_end * v;
    return 0.0;
  }

  double head_volume(double h) const noexcept { return m_V01 + m_A1 * h; }
  double rod_volume(double h) const noexcept { return m_V02 + m_A2 * (m_L - h); }

  /// d/dt of the hydro-mechanical states (h, v, p1, p2), the first kMechanicalSize entries of x and
  /// dx, for a spool opening xv and load F_L (plant.md 3-5).
  void mechanical_rhs(const double* x, double xv, double load, double* dx) const noexcept {
    const double h = x[kPosition];
    const double v = x[kVelocity];
    const double p1 = x[kHeadPressure];
    const double p2 = x[kRodPressure];
    const Flows q = flows(p1, p2, xv);
    const double leak = m_Ci * (p1 - p2);
    dx[kPosition] = v;
    dx[kVelocity] = (m_A1 * p1 - m_A2 * p2 - friction(v) - gravity_force(h) - end_stop(h, v) - load) * m_inv_M;
    dx[kHeadPressure] = m_beta / head_volume(h) * (q.head - m_A1 * v - leak - m_Ce * p1);
    dx[kRodPressure] = m_beta / rod_volume(h) * (-q.rod + m_A2 * v + leak - m_Ce * p2);
  }

  /// d(state)/dt for a held pilot output xc and load F_L; x and dx have kStateSize entries.
  void rhs(const double* x, double pilot, double load, double* dx) const noexcept {
    mechanical_rhs(x, x[kSpool], load, dx);
    dx[kSpool] = (pilot - x[kSpool]) * m_inv_tau;
  }

  /// The Jacobian of mechanical_rhs with respect to (h, v, p1, p2) at spool opening xv:
  /// jac[i][k] = d(dx[i]) / d(x[k]). Exact, including the branches' one-sided derivatives (the
  /// end stops switch on for h < 0 and h > L; the geometry is frozen outside [0, L] as in
  /// gravity_force).
  void mechanical_jacobian(const double* x, double xv, double jac[kMechanicalSize][kMechanicalSize]) const noexcept {
    const double h = x[kPosition];
    const double v = x[kVelocity];
    const double p1 = x[kHeadPressure];
    const double p2 = x[kRodPressure];
    // Orifices: d(ssqrt(D))/dD = (|D| / 2 + dp_reg) / (|D| + dp_reg)^(3/2).
    double dq1_dp1 = 0.0;
    double dq2_dp2 = 0.0;
    double q1 = 0.0;
    double q2 = 0.0;
    if (xv >= 0.0) {
      q1 = m_Kq * xv * ssqrt(m_ps - p1);
      q2 = m_Kq * xv * ssqrt(p2 - m_pt);
      dq1_dp1 = -m_Kq * xv * ssqrt_slope(m_ps - p1);
      dq2_dp2 = m_Kq * xv * ssqrt_slope(p2 - m_pt);
    } else {
      q1 = m_Kq * xv * ssqrt(p1 - m_pt);
      q2 = m_Kq * xv * ssqrt(m_ps - p2);
      dq1_dp1 = m_Kq * xv * ssqrt_slope(p1 - m_pt);
      dq2_dp2 = -m_Kq * xv * ssqrt_slope(m_ps - p2);
    }
    const double leak = m_Ci * (p1 - p2);
    const double g1 = m_beta / head_volume(h);
    const double g2 = m_beta / rod_volume(h);
    double end_h = 0.0;
    double end_v = 0.0;
    if (h < 0.0 || h > m_L) {
      end_h = m_k_end;
      end_v = m_c_end;
    }
    jac[kPosition][kPosition] = 0.0;
    jac[kPosition][kVelocity] = 1.0;
    jac[kPosition][kHeadPressure] = 0.0;
    jac[kPosition][kRodPressure] = 0.0;
    jac[kVelocity][kPosition] = -(gravity_force_slope(h) + end_h) * m_inv_M;
    jac[kVelocity][kVelocity] = -(friction_slope(v) + end_v) * m_inv_M;
    jac[kVelocity][kHeadPressure] = m_A1 * m_inv_M;
    jac[kVelocity][kRodPressure] = -m_A2 * m_inv_M;
    // d(beta / V1)/dh = -beta A1 / V1^2 = -g1 A1 / V1; d(beta / V2)/dh = +g2 A2 / V2.
    jac[kHeadPressure][kPosition] = -g1 * m_A1 / head_volume(h) * (q1 - m_A1 * v - leak - m_Ce * p1);
    jac[kHeadPressure][kVelocity] = -g1 * m_A1;
    jac[kHeadPressure][kHeadPressure] = g1 * (dq1_dp1 - m_Ci - m_Ce);
    jac[kHeadPressure][kRodPressure] = g1 * m_Ci;
    jac[kRodPressure][kPosition] = g2 * m_A2 / rod_volume(h) * (-q2 + m_A2 * v + leak - m_Ce * p2);
    jac[kRodPressure][kVelocity] = g2 * m_A2;
    jac[kRodPressure][kHeadPressure] = g2 * m_Ci;
    jac[kRodPressure][kRodPressure] = g2 * (-dq2_dp2 - m_Ci - m_Ce);
  }

  /// dFs/dh: zero outside [0, L], where gravity_force freezes the geometry.
  double gravity_force_slope(double h) const noexcept {
    if (h < 0.0 || h > m_L) return 0.0;
    const double l = m_lmin + h;
    const double c = (m_a * m_a + m_b * m_b - l * l) / (2.0 * m_a * m_b);
    if (!(c > -1.0 && c < 1.0)) return 0.0;
    const double dc = -l / (m_a * m_b);
    const double s = std::sqrt(1.0 - c * c);
    const double ds = -c / s * dc;
    const double r = m_a * m_b * s / l;
    const double dr = m_a * m_b * (ds * l - s) / (l * l);
    const double cos_theta_g = c * m_cos_gamma - s * m_sin_gamma;
    const double dcos = dc * m_cos_gamma - ds * m_sin_gamma;
    return m_mg * (dcos * r - cos_theta_g * dr) / (r * r);
  }

  double ssqrt_slope(double dp) const noexcept {
    const double m = std::abs(dp) + m_dp_reg;
    return (0.5 * std::abs(dp) + m_dp_reg) / (m * std::sqrt(m));
  }

  double friction_slope(double v) const noexcept {
    const double ratio = v * m_inv_vs;
    const double e = std::exp(-ratio * ratio);
    const double th = std::tanh(v * m_inv_eps);
    return (m_Fst - m_Fc) * e * (-2.0 * ratio * m_inv_vs) * th +
           (m_Fc + (m_Fst - m_Fc) * e) * (1.0 - th * th) * m_inv_eps + m_sigma;
  }

  double inverse_time_constant() const noexcept { return m_inv_tau; }

 private:
  double m_A1, m_A2, m_L, m_V01, m_V02, m_ps, m_pt, m_beta, m_Kq, m_Ci, m_Ce, m_dp_reg, m_inv_tau, m_inv_M, m_mg, m_Fc,
      m_Fst, m_inv_vs, m_sigma, m_inv_eps, m_k_end, m_c_end, m_a, m_b, m_lmin;
  double m_cos_gamma = 1.0;
  double m_sin_gamma = 0.0;
};

}  // namespace bonl::plant::detail
