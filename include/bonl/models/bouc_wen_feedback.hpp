#pragma once
// Bouc-Wen feedback model: a linear block driven by the input, and the hysteretic part h of a
// restoring force w that the Bouc-Wen law makes of the output, fed back through a second, delayed
// linear block over the same denominator:
//   y(k) = -sum_{j=1..na} a_j y(k-j) + sum_{i=0..nb} b_i u(k-nk-i) - sum_{j=1..nd} d_j h(k-j),  d_1 = 1,
//   h(k) = w(k) - alpha y(k),  w(k) = w(k-1) + alpha dy(k) - gamma |dy(k)| w(k) - delta dy(k) |w(k)|,
//   dy(k) = y(k) - y(k-1).
// The second line is the Bouc-Wen law w' = alpha y' - beta (gamma |y'| w + delta y' |w|) with nu = 1
// (rate-independent hysteresis: a structure's bolted joint, a damper, a cylinder's friction), stepped
// backward (implicit Euler) once per sample, beta taken into gamma and delta:
//   w(k) = (w(k-1) + alpha dy) / (1 + gamma |dy| + delta dy s),  s = sign(w(k-1) + alpha dy),
// which stays between w(k-1) + alpha dy and the law's saturation however large the step (a forward
// step overshoots once gamma |dy| > 1 and then grows without bound). Its slope dw/dy = alpha - gamma
// sign(dy) w - delta |w| depends on the force itself, which is what a Prandtl-Ishlinskii operator's
// plays cannot hold (their loops are congruent, their slope set by the distance from the last
// reversal alone).
// Only the hysteretic part h = w - alpha y is fed back: it is zero with zero slope at rest, so A is
// the model's linearisation there, and alpha acts only through the law's saturation. Fed back whole,
// w's linear part alpha y duplicates A's: alpha's key-term regressor -dy(k-1) is a_1's less a_2's
// (with an integrator, a_1's itself), and the recursions drifted along that direction under noise.
// The feedback starts one sample back, so there is no algebraic loop; h is subtracted, as a restoring
// force is, and d_1 = 1 fixes the scale between D and h.
// Parameters: b_0..b_nb, a_1..a_na, alpha, gamma, delta, d_2..d_nd.
// Key-term form, with h(k-1) written out by the law:
//   y(k) + h(k-2) = [u lags] . b - [y lags] . a + gamma |dy(k-1)| w(k-1) + delta dy(k-1) |w(k-1)|
//                   - sum_{j=2..nd} d_j h(k-j),
// linear in b, a, gamma, delta and d once the internal variables w(k-1), h(k-2), ... are computed;
// they are the law run over the measured output's past, with the step's theta, for both key-term
// methods. alpha enters through them alone, so its regressor is the prediction's slope along the run
// (KeyTerms).
// The output-error sensitivities run through the law (Law's partial derivatives). A free run whose
// force leaves the finite numbers is reported as every model's is (try_simulate() false). With ni
// integrators the denominator is A (1 - q^-1)^ni (detail/integrators.hpp).

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "../blocks/linear_block.hpp"
#include "../detail/history.hpp"
#include "../detail/integrators.hpp"
#include "../detail/stability.hpp"
#include "../detail/validate.hpp"
#include "detail/model_runs.hpp"
#include "estimator_settings.hpp"
#include "model_description.hpp"
#include "model_steps.hpp"

namespace bonl {

/// The Bouc-Wen feedback model: a linear block driven by the input and by the hysteretic part h of a
/// restoring force w of the output, fed back through a second, delayed linear block D over the same
/// denominator: y(k) = -sum a_j y(k-j) + sum b_i u(k-nk-i) - sum_{j=1..nd} d_j h(k-j), d_1 = 1,
/// h = w - alpha y, with w(k) = w(k-1) + alpha dy - gamma |dy| w(k) - delta dy |w(k)|,
/// dy = y(k) - y(k-1) (the Bouc-Wen law with nu = 1, stepped backward). A is the linearisation at
/// rest. Parameters: b_0..b_nb, a_1..a_na, alpha, gamma, delta, d_2..d_nd. The file's header says more.
template <typename Scalar_ = double, int Na_ = Eigen::Dynamic, int Nb_ = Eigen::Dynamic, int Nd_ = Eigen::Dynamic>
class BoucWenFeedback : public detail::ModelRuns<BoucWenFeedback<Scalar_, Na_, Nb_, Nd_>> {
  static constexpr int kLinearParams = detail::add_sizes(detail::poly_size(Nb_), Na_);  // b, a

 public:
  /// \copydoc ARX::Scalar
  using Scalar = Scalar_;
  /// \copydoc ARX::kNumParams
  static constexpr int kNumParams =
      detail::add_sizes(detail::add_sizes(kLinearParams, 3), Nd_ == Eigen::Dynamic ? Eigen::Dynamic : Nd_ - 1);
  /// The Bouc-Wen feedback model has an unmeasured internal variable, the restoring force w.
  static constexpr bool kHasInternalVariables = true;
  /// No inverse for control yet: it would subtract the force the reference's past makes from the
  /// linear block's inverse (control/inverse_model.hpp).
  static constexpr bool kInvertible = false;
  /// \copydoc ARX::kName
  static constexpr const char* kName = "BoucWenFeedback";
  /// \copydoc ARX::kDescription
  static constexpr ModelDescription<5, 6> kDescription{
      kName,
      "Bouc-Wen feedback model: y(k) = -sum a_j y(k-j) + sum b_i u(k-nk-i) - sum_{j=1..nd} d_j h(k-j), d_1 = 1, "
      "h = w - alpha y the hysteretic part of the restoring force w(k) = w(k-1) + alpha dy - gamma |dy| w(k) "
      "- delta dy |w(k)|, dy = y(k) - y(k-1) (the Bouc-Wen law of hysteresis with nu = 1, stepped backward).",
      {{{"na", 1, detail::kMaxOrder, Na_, "poles of the linear block (na >= 1)"},
        {"nb", 0, detail::kMaxOrder, Nb_, "B has nb + 1 coefficients b_0..b_nb"},
        {"nk", 0, detail::kMaxOrder, Eigen::Dynamic, "pure delay of the input in samples"},
        {"nd", 1, 32, Nd_, "taps of the force's block D = d_1 q^-1 + ... + d_nd q^-nd, d_1 = 1 (1..32)"},
        detail::kIntegratorsOrder}},
      {{{"b", ParameterShape::Vector, 0, "b_0..b_nb", nullptr, false, {1, 0, -1, 0}},
        {"a", ParameterShape::Vector, 1, "a_1..a_na", nullptr, false, {}},
        {"alpha",
         ParameterShape::Number,
         0,
         "the force's stiffness where it is zero: > 0 softens with the amplitude, < 0 stiffens",
         nullptr,
         false,
         {}},
        {"gamma",
         ParameterShape::Number,
         0,
         "the law's |dy| w coefficient (beta gamma)",
         nullptr,
         false,
         {-1, 0, 0, 0}},
        {"delta",
         ParameterShape::Number,
         0,
         "the law's dy |w| coefficient (beta delta)",
         nullptr,
         false,
         {-1, 0, 0, 0}},
        {"d",
         ParameterShape::Vector,
         1,
         "d_1..d_nd with d_1 = 1",
         "the Bouc-Wen feedback model is normalised so that d_1 = 1",
         false,
         {}}}}};
  /// \copydoc ARX::Params
  using Params = Eigen::Matrix<Scalar, kNumParams, 1>;
  /// \copydoc ARX::VectorX
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  /// \copydoc ARX::Linear
  using Linear = LinearBlock<Scalar, Na_, Nb_>;

  /// A model with the given orders, all parameters zero but d_1 = 1. Throws std::invalid_argument for
  /// an order out of range or one that differs from the compile-time order.
  /// \param na poles of the linear block, >= 1
  /// \param nb B has nb + 1 coefficients, >= 0
  /// \param nk pure delay in samples, >= 0
  /// \param nd taps of the force's block D (d_1 = 1), 1..32
  /// \param ni integrators (poles fixed at 1), 0..2
  BoucWenFeedback(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index nd, Eigen::Index ni = 0)
      : m_na(na), m_nb(nb), m_nk(nk), m_nd(nd), m_ni(ni) {
    detail::require_order(na, 1, "na");
    detail::require_order(nb, 0, "nb");
    detail::require_order(nk, 0, "nk");
    detail::require_order(nd, 1, "nd (force taps)");
    detail::require(nd <= 32, "nd (force taps) must be <= 32");
    detail::require_integrators(ni);
    detail::require_matches_template(na, Na_, "na");
    detail::require_matches_template(nb, Nb_, "nb");
    detail::require_matches_template(nd, Nd_, "nd");
    m_theta = Params::Zero(nb + 1 + na + 3 + nd - 1);
  }

  /// \copydoc ARX::na
  Eigen::Index na() const noexcept { return m_na; }
  /// \copydoc ARX::nb
  Eigen::Index nb() const noexcept { return m_nb; }
  /// \copydoc ARX::nk
  Eigen::Index nk() const noexcept { return m_nk; }
  /// The order nd: taps of the force's block D (d_1 = 1)
  /// \return nd, 1..32
  Eigen::Index nd() const noexcept { return m_nd; }
  /// \copydoc ARX::ni
  Eigen::Index ni() const noexcept { return m_ni; }
  /// \copydoc ARX::num_params
  Eigen::Index num_params() const noexcept { return m_theta.size(); }
  /// \copydoc ARX::orders
  std::array<Eigen::Index, 5> orders() const noexcept { return {m_na, m_nb, m_nk, m_nd, m_ni}; }

  /// identify()'s starts beside its recursive estimates: the loop open, the records' best linear
  /// approximation as the linear block (estimator/nonlinear_feedback_start.hpp, found by
  /// argument-dependent lookup where identify() calls this), with no hysteresis and with some. With
  /// gamma = delta = 0, h = 0 whatever alpha is: the start simulates like the linear model, but
  /// along gamma = 0 only alpha gamma matters, and Levenberg-Marquardt runs along that ridge to a
  /// large alpha and a vanishing gamma (measured on the known system's multisine: the refined start
  /// stayed at the linear model's error). The other starts put the law's knee where the output is,
  /// gamma = 1 and 3 over the records' RMS output, and give the hysteresis a quarter of the linear
  /// block's static stiffness A(1): more made the free run of a lightly damped block run off. With
  /// integrators the linearisation holds no stiffness and alpha < 0 adds it; alpha > 0 would let the
  /// output run off.
  /// \param structure the orders to start from
  /// \param records the identification records (deviations from the operating point, as identify() hands them)
  /// \return the starts, or none
  template <class RecordList>
  static std::vector<BoucWenFeedback> identify_starts(const BoucWenFeedback& structure, const RecordList& records) {
    std::vector<BoucWenFeedback> starts;
    Scalar squares = Scalar(0);
    Eigen::Index samples = 0;
    for (const auto& record : records) {
      squares += record.y.squaredNorm();
      samples += record.y.size();
    }
    const Scalar rms = std::sqrt(squares / Scalar(std::max<Eigen::Index>(samples, 1)));
    for (const BoucWenFeedback& open : open_loop_starts(structure, records)) {
      BoucWenFeedback linear = open;
      linear.set_alpha(kStartAlpha);
      starts.push_back(linear);
      const Scalar stiffness = std::abs(Scalar(1) + open.a().sum());  // A(1)
      if (!(rms > Scalar(0)) || !std::isfinite(stiffness)) continue;
      for (const Scalar knee : {Scalar(1), Scalar(3)}) {
        BoucWenFeedback start = open;
        start.set_alpha((structure.ni() > 0 ? Scalar(-0.25) : Scalar(0.25)) * stiffness);
        start.set_gamma(knee / rms);
        starts.push_back(start);
      }
    }
    return starts;
  }

  /// Where the equation-error and paper recursions start: all zero but alpha = kStartAlpha. At
  /// alpha = 0 the force is zero and has no slope in gamma and delta, and at gamma = delta = 0 the
  /// fed-back h has none in alpha: from all zero nothing of the law would move.
  /// \return the first estimate
  Params initial_estimate(const NoEstimatorSettings& /*settings*/) const {
    Params theta = Params::Zero(num_params());
    theta[first_law()] = kStartAlpha;
    return theta;
  }

  /// \copydoc ARX::theta
  const Params& theta() const noexcept { return m_theta; }
  /// \copydoc ARX::set_theta
  template <typename T>
  void set_theta(const Eigen::MatrixBase<T>& theta) {
    detail::assign_checked(m_theta, theta, "theta");
  }

  /// \copydoc ARX::b
  VectorX b() const { return m_theta.head(m_nb + 1); }
  /// \copydoc ARX::a
  VectorX a() const { return m_theta.segment(first_a(), m_na); }
  /// The force's stiffness where it is zero. \return alpha
  Scalar alpha() const noexcept { return m_theta[first_law()]; }
  /// The law's coefficient of |dy| w (beta gamma of the Bouc-Wen law). \return gamma
  Scalar gamma() const noexcept { return m_theta[first_law() + 1]; }
  /// The law's coefficient of dy |w| (beta delta of the Bouc-Wen law). \return delta
  Scalar delta() const noexcept { return m_theta[first_law() + 2]; }
  /// The force's block D. \return d_1..d_nd with d_1 = 1
  VectorX d() const {
    VectorX out(m_nd);
    out[0] = Scalar(1);
    out.tail(m_nd - 1) = m_theta.segment(first_d(), m_nd - 1);
    return out;
  }
  /// \copydoc ARX::set_b
  template <typename T>
  void set_b(const Eigen::MatrixBase<T>& b) {
    detail::assign_checked(m_theta.head(m_nb + 1), b, "b");
  }
  /// \copydoc ARX::set_a
  template <typename T>
  void set_a(const Eigen::MatrixBase<T>& a) {
    detail::assign_checked(m_theta.segment(first_a(), m_na), a, "a");
  }
  /// Sets alpha (finite, else std::invalid_argument). \param alpha the force's stiffness where it is zero
  void set_alpha(Scalar alpha) { set_law(0, alpha, "alpha"); }
  /// Sets gamma (finite, else std::invalid_argument). \param gamma the law's coefficient of |dy| w
  void set_gamma(Scalar gamma) { set_law(1, gamma, "gamma"); }
  /// Sets delta (finite, else std::invalid_argument). \param delta the law's coefficient of dy |w|
  void set_delta(Scalar delta) { set_law(2, delta, "delta"); }
  /// Sets d_1..d_nd: nd finite values with d_1 = 1 (the normalisation), else std::invalid_argument.
  /// \param d d_1..d_nd
  template <typename T>
  void set_d(const Eigen::MatrixBase<T>& d) {
    detail::require_size(d, m_nd, "d");
    detail::require_finite(d, "d");
    detail::require(d[0] == 1, std::string("d[0] (d_1) must be 1: ") + kDescription.parameters[5].normalised);
    m_theta.segment(first_d(), m_nd - 1) = d.tail(m_nd - 1);
  }

  /// The parameter block kDescription.parameters[i]: b, a, alpha, gamma, delta, d.
  /// \copydetails ARX::parameter
  VectorX parameter(std::size_t i) const {
    switch (i) {
      case 0: return b();
      case 1: return a();
      case 2:
      case 3:
      case 4: return VectorX::Constant(1, m_theta[first_law() + static_cast<Eigen::Index>(i) - 2]);
      case 5: return d();
      default: detail::no_such_parameter(kName, i);
    }
  }
  /// \copydoc ARX::set_parameter
  void set_parameter(std::size_t i, const VectorX& value) {
    switch (i) {
      case 0: return set_b(value);
      case 1: return set_a(value);
      case 2:
      case 3:
      case 4: {
        const char* name = kDescription.parameters[i].name;
        detail::require_size(value, 1, name);
        return set_law(static_cast<Eigen::Index>(i) - 2, value[0], name);
      }
      case 5: return set_d(value);
      default: detail::no_such_parameter(kName, i);
    }
  }

  /// \copydoc ARX::try_simulate_deviations
  template <typename U>
  bool try_simulate_deviations(const Eigen::MatrixBase<U>& u, VectorX& y) const {
    const Law law(*this);
    const Scalar alpha = this->alpha();
    detail::History<Scalar> u_lags(m_nk + m_nb + 1);
    detail::History<Scalar> force(m_nd);    // w(k-1), w(k-2), ...
    detail::History<Scalar> outputs(m_nd);  // y(k-1), y(k-2), ...: h = w - alpha y
    detail::History<Scalar> z_lags(m_na);   // the denominator's past: y differenced ni times
    detail::IntegratorLags<Scalar> integrators(m_ni);
    y.resize(u.size());
    for (Eigen::Index k = 0; k < u.size(); ++k) {
      u_lags.push(u[k]);
      Scalar out = Scalar(0);
      for (Eigen::Index i = 0; i <= m_nb; ++i) out += m_theta[i] * u_lags[m_nk + i];
      for (Eigen::Index j = 0; j < m_na; ++j) out -= m_theta[first_a() + j] * z_lags[j];
      for (Eigen::Index j = 0; j < m_nd; ++j) out -= tap(m_theta, j) * (force[j] - alpha * outputs[j]);
      if (m_ni > 0) out += integrators.carried();
      y[k] = out;
      const Scalar next = law.next(m_theta, force[0], out - outputs[0]);
      if (!std::isfinite(out) || !std::isfinite(next)) return false;
      force.push(next);
      outputs.push(out);
      z_lags.push(integrators.push(out));
    }
    return true;
  }

  /// \copydoc ARX::constrain
  void constrain(Params& /*theta*/) const noexcept {}

 private:
  // The slope of |x|: 0 at 0, where |x| has no slope (the one-sided ones are -1 and 1).
  static Scalar sign(Scalar x) noexcept { return Scalar((x > 0) - (x < 0)); }

  /// The Bouc-Wen law on theta, stepped backward (implicit Euler): the next force solves
  ///   w(k) = w(k-1) + alpha dy - gamma |dy| w(k-1)' - delta dy |w(k)|  with w(k-1)' = w(k), i.e.
  ///   w(k) = (w(k-1) + alpha dy) / (1 + gamma |dy| + delta dy s),  s = sign(w(k-1) + alpha dy),
  /// which stays between w(k-1) + alpha dy and the law's saturation however large the step (the
  /// forward step overshoots once gamma |dy| > 1 and then grows without bound), and keeps the key
  /// terms linear: w(k) = w(k-1) + alpha dy - gamma |dy| w(k) - delta dy |w(k)|, with w(k) the
  /// internal variable. The denominator is held at kFloor = 0.5 where a hardening law (|delta| >
  /// gamma) and a large step would take it below, so that one step at most doubles the force: with
  /// 1e-3 a recursion's early estimate multiplied it by up to 1000 per sample, and the paper
  /// method's covariance broke down within 21 samples on the known system under 5 % noise. Where
  /// gamma >= |delta|, the usual Bouc-Wen law, the denominator is at least 1 and never held.
  class Law {
   public:
    explicit Law(const BoucWenFeedback& model) : m_first(model.first_law()) {}
    /// w(k) from w(k-1) and dy(k).
    template <typename Theta>
    Scalar next(const Theta& theta, Scalar w, Scalar dy) const noexcept {
      return (w + theta[m_first] * dy) / denominator(theta, w, dy);
    }
    /// d w(k) / d w(k-1).
    template <typename Theta>
    Scalar by_force(const Theta& theta, Scalar w, Scalar dy) const noexcept {
      return Scalar(1) / denominator(theta, w, dy);
    }
    /// d w(k) / d dy(k), at w(k) = next.
    template <typename Theta>
    Scalar by_step(const Theta& theta, Scalar w, Scalar dy, Scalar next) const noexcept {
      const Scalar den = denominator(theta, w, dy);
      if (den == kFloor) return theta[m_first] / den;
      return (theta[m_first] -
              next * (theta[m_first + 1] * sign(dy) + theta[m_first + 2] * sign(w + theta[m_first] * dy))) /
             den;
    }
    /// weight * d w(k) / d [alpha, gamma, delta] added into out's entries, at w(k) = next.
    template <typename Theta, typename Out>
    void add_sensitivity(const Theta& theta, Scalar w, Scalar dy, Scalar next, Scalar weight, Out& out) const noexcept {
      const Scalar den = denominator(theta, w, dy);
      out[m_first] += weight * dy / den;
      if (den == kFloor) return;
      out[m_first + 1] -= weight * std::abs(dy) * next / den;
      out[m_first + 2] -= weight * dy * std::abs(next) / den;
    }
    /// weight * the key-term regressor of [alpha, gamma, delta] with the step's w(k) = next:
    /// [dy, -|dy| next, -dy |next|].
    template <typename Out>
    void add_regressor(Scalar dy, Scalar next, Scalar weight, Out& out) const noexcept {
      out[m_first] += weight * dy;
      out[m_first + 1] -= weight * std::abs(dy) * next;
      out[m_first + 2] -= weight * dy * std::abs(next);
    }

   private:
    static constexpr Scalar kFloor = Scalar(0.5);
    template <typename Theta>
    Scalar denominator(const Theta& theta, Scalar w, Scalar dy) const noexcept {
      const Scalar den =
          Scalar(1) + theta[m_first + 1] * std::abs(dy) + theta[m_first + 2] * dy * sign(w + theta[m_first] * dy);
      return den > kFloor ? den : kFloor;
    }
    Eigen::Index m_first;
  };

 public:
  /// Key-term form: regressor [u(k-nk..k-nk-nb), -y(k-1..k-na), s_alpha, |dy(k-1)| w(k-1),
  /// dy(k-1) |w(k-1)|, -h(k-2..k-nd)], target y(k) + h(k-2) (less s_alpha alpha), with the law run
  /// over the measured outputs with the step's theta (the model's prediction where y is NaN) and
  /// w(k-1) its backward step. alpha enters only through that run, so its entry s_alpha is the
  /// prediction's slope along it (d w / d alpha carried along the run), and the target holds the
  /// same slope times the step's alpha: the error is the prediction's, and the recursion moves alpha
  /// as a prediction-error method would. predict() runs it. With integrators the a-entries hold the
  /// differenced past and the target is less their part.
  class KeyTerms {
   public:
    /// \copydoc ARX::KeyTerms::KeyTerms
    KeyTerms(const BoucWenFeedback& model, KeyTermMethod /*method*/)
        : m_law(model), m_u(model.nk() + model.nb() + 1), m_y(std::max<Eigen::Index>(model.nd(), 2)), m_z(model.na()),
          m_force(model.nd()), m_slope(model.nd()), m_integrators(model.ni()), m_na(model.na()), m_nb(model.nb()),
          m_nk(model.nk()), m_nd(model.nd()), m_first_law(model.first_law()), m_first_d(model.first_d()),
          m_phi(Params::Zero(model.num_params())) {}
    /// \copydoc ARX::KeyTerms::reset
    void reset() noexcept {
      m_u.clear();
      m_y.clear();
      m_z.clear();
      m_force.clear();
      m_slope.clear();
      m_integrators.clear();
    }
    /// \copydoc ARX::KeyTerms::step
    Regression<Scalar, Params> step(const Params& theta, Scalar u, Scalar y) noexcept {
      m_u.push(u);
      for (Eigen::Index i = 0; i <= m_nb; ++i) m_phi[i] = m_u[m_nk + i];
      for (Eigen::Index j = 0; j < m_na; ++j) m_phi[m_nb + 1 + j] = -m_z[j];
      // w(k-1) by the backward step from w(k-2) and the measured dy(k-1), and its slope in alpha.
      const Scalar alpha = theta[m_first_law], gamma = theta[m_first_law + 1], delta = theta[m_first_law + 2];
      const Scalar w2 = m_force[0], y2 = m_y[1], dy1 = m_y[0] - m_y[1];
      const Scalar w1 = m_law.next(theta, w2, dy1);
      const Scalar s1 = m_law.by_force(theta, w2, dy1) * (m_slope[0] + dy1);
      const Scalar h2 = w2 - alpha * y2, s2 = m_slope[0] - y2;  // h(k-2) and its slope in alpha
      m_phi.segment(m_first_law, 3).setZero();
      m_law.add_regressor(dy1, w1, Scalar(-1), m_phi);
      m_force.push(w1);
      m_slope.push(s1);
      // The prediction's slope in alpha: -dh(k-2) + d(gamma |dy| w1 + delta dy |w1|) - sum_j d_j dh(k-j).
      Scalar slope = -s2 + (gamma * std::abs(dy1) + delta * dy1 * sign(w1)) * s1;
      for (Eigen::Index j = 1; j < m_nd; ++j) {
        m_phi[m_first_d + j - 1] = -(m_force[j] - alpha * m_y[j]);
        slope -= theta[m_first_d + j - 1] * (m_slope[j] - m_y[j]);
      }
      m_phi[m_first_law] = slope;
      const Scalar carried = m_integrators.carried() - h2 - slope * alpha;
      const Scalar prediction = m_phi.dot(theta) + carried;
      const Scalar lag = std::isnan(y) ? prediction : y;
      m_y.push(lag);
      m_z.push(m_integrators.push(lag));
      return {m_phi, y - carried, prediction, m_force[0], true};
    }

   private:
    Law m_law;
    detail::History<Scalar> m_u, m_y;  // m_y: y(k-1), y(k-2), ..., measured
    detail::History<Scalar> m_z;       // the denominator's past: y differenced ni times
    detail::History<Scalar> m_force;   // w(k-1), w(k-2), ... of the measured past
    detail::History<Scalar> m_slope;   // their slopes in alpha
    detail::IntegratorLags<Scalar> m_integrators;
    Eigen::Index m_na, m_nb, m_nk, m_nd, m_first_law, m_first_d;
    Params m_phi;
  };

  /// The output-error method's view: one step of the free run with its sensitivities,
  ///   dy(k) = [u lags at b] + [-y lags at a] + [-w(k-j) at d_j] - sum_j a_j dy(k-j) - sum_j d_j dw(k-j),
  /// and the force's, dw(k) = (d w(k) / d w(k-1)) dw(k-1) + (d w(k) / d dy(k)) (dy(k) - dy(k-1)) + its
  /// parameters' entries (the law's partial derivatives, Law). With integrators the denominator's
  /// past is z = (1 - q^-1)^ni y, kept with its sensitivities beside y's, and y(k) and dy(k) carry
  /// the integrators' part of the past y and dy.
  class OutputErrorTerms {
   public:
    /// \copydoc ARX::OutputErrorTerms::OutputErrorTerms
    explicit OutputErrorTerms(const BoucWenFeedback& model)
        : m_law(model), m_u(model.nk() + model.nb() + 1), m_na(model.na()), m_nb(model.nb()), m_nk(model.nk()),
          m_nd(model.nd()), m_first_d(model.first_d()), m_ni(model.ni()), m_first_law(model.first_law()),
          m_y(VectorX::Zero(std::max({model.ni(), model.nd(), Eigen::Index(1)}))),
          m_dy(SensitivityLags::Zero(model.num_params(), std::max({model.ni(), model.nd(), Eigen::Index(1)}))),
          m_z(VectorX::Zero(model.na())), m_dz(SensitivityLags::Zero(model.num_params(), model.na())),
          m_w(VectorX::Zero(model.nd())), m_dw(SensitivityLags::Zero(model.num_params(), model.nd())),
          m_work(Eigen::Matrix<Scalar, Na_, 1>::Zero(model.na())), m_psi(Params::Zero(model.num_params())),
          m_dw_next(Params::Zero(model.num_params())) {}
    /// \copydoc ARX::OutputErrorTerms::reset
    void reset() noexcept {
      m_u.clear();
      m_y.setZero();
      m_dy.setZero();
      m_z.setZero();
      m_dz.setZero();
      m_w.setZero();
      m_dw.setZero();
    }
    /// \copydoc ARX::OutputErrorTerms::step
    SimulationStep<Scalar, Params> step(const Params& theta, Scalar u) noexcept {
      m_u.push(u);
      Scalar y = Scalar(0);
      for (Eigen::Index i = 0; i <= m_nb; ++i) {
        m_psi[i] = m_u[m_nk + i];
        y += theta[i] * m_psi[i];
      }
      for (Eigen::Index j = 0; j < m_na; ++j) {
        m_psi[m_nb + 1 + j] = -m_z[j];
        y -= theta[m_nb + 1 + j] * m_z[j];
      }
      m_psi.segment(m_nb + 1 + m_na, 3).setZero();
      // The fed-back h(k-j) = w(k-j) - alpha y(k-j): alpha's direct entry is sum_j d_j y(k-j).
      const Scalar alpha = theta[m_first_law];
      for (Eigen::Index j = 0; j < m_nd; ++j) {
        const Scalar d = j == 0 ? Scalar(1) : theta[m_first_d + j - 1];
        y -= d * (m_w[j] - alpha * m_y[j]);
        if (j > 0) m_psi[m_first_d + j - 1] = -(m_w[j] - alpha * m_y[j]);
        m_psi[m_first_law] += d * m_y[j];
      }
      // Through the loop: the denominator's past and the fed-back h's.
      for (Eigen::Index j = 0; j < m_na; ++j) m_psi -= theta[m_nb + 1 + j] * m_dz.col(j);
      for (Eigen::Index j = 0; j < m_nd; ++j)
        m_psi -= (j == 0 ? Scalar(1) : theta[m_first_d + j - 1]) * (m_dw.col(j) - alpha * m_dy.col(j));
      if (m_ni > 0) {
        y += detail::carried<Scalar>(m_ni, m_y);
        detail::add_carried_sensitivity(m_ni, m_dy, Scalar(1), m_psi);
      }
      // The force this step makes, for the steps after it (accept() stores it).
      const Scalar w = m_w[0], dy = y - m_y[0];
      m_w_next = m_law.next(theta, w, dy);
      m_dw_next =
          m_law.by_force(theta, w, dy) * m_dw.col(0) + m_law.by_step(theta, w, dy, m_w_next) * (m_psi - m_dy.col(0));
      m_law.add_sensitivity(theta, w, dy, m_w_next, Scalar(1), m_dw_next);
      m_output = y;
      return {y, m_psi, w};
    }
    /// \copydoc ARX::OutputErrorTerms::accept()
    void accept() noexcept {
      for (Eigen::Index j = m_z.size() - 1; j > 0; --j) {
        m_z[j] = m_z[j - 1];
        m_dz.col(j) = m_dz.col(j - 1);
      }
      if (m_z.size() > 0) {
        m_z[0] = m_output;  // z(k) = y(k) - carried(k), read before the y lags move
        m_dz.col(0) = m_psi;
        if (m_ni > 0) {
          m_z[0] -= detail::carried<Scalar>(m_ni, m_y);
          detail::add_carried_sensitivity(m_ni, m_dy, Scalar(-1), m_dz.col(0));
        }
      }
      for (Eigen::Index j = m_y.size() - 1; j > 0; --j) {
        m_y[j] = m_y[j - 1];
        m_dy.col(j) = m_dy.col(j - 1);
      }
      m_y[0] = m_output;
      m_dy.col(0) = m_psi;
      for (Eigen::Index j = m_w.size() - 1; j > 0; --j) {
        m_w[j] = m_w[j - 1];
        m_dw.col(j) = m_dw.col(j - 1);
      }
      m_w[0] = m_w_next;
      m_dw.col(0) = m_dw_next;
    }
    /// After the estimate moved by delta: the stored outputs and forces to first order (as
    /// SimulatedLags does).
    /// \param delta the change of theta since the step just accepted
    void correct(const Params& delta) noexcept {
      for (Eigen::Index j = 0; j < m_y.size(); ++j) m_y[j] += m_dy.col(j).dot(delta);
      for (Eigen::Index j = 0; j < m_z.size(); ++j) m_z[j] += m_dz.col(j).dot(delta);
      for (Eigen::Index j = 0; j < m_w.size(); ++j) m_w[j] += m_dw.col(j).dot(delta);
    }
    /// \copydoc ARX::OutputErrorTerms::stable
    bool stable(const Params& theta, Scalar radius) noexcept {
      return detail::roots_inside(theta.template segment<Na_>(m_nb + 1, m_na), radius, m_work);
    }

   private:
    using SensitivityLags = Eigen::Matrix<Scalar, kNumParams, Eigen::Dynamic>;

    Law m_law;
    detail::History<Scalar> m_u;
    Eigen::Index m_na, m_nb, m_nk, m_nd, m_first_d, m_ni, m_first_law;
    VectorX m_y;           // y(k-1), y(k-2), ...: the simulated outputs, newest first (dy(k), h, the integrators)
    SensitivityLags m_dy;  // their sensitivities, one column each
    VectorX m_z;           // z(k-1..k-na): the denominator's past, y differenced ni times
    SensitivityLags m_dz;  // their sensitivities
    VectorX m_w;           // w(k-1..k-nd): the simulated force
    SensitivityLags m_dw;  // its sensitivities
    Eigen::Matrix<Scalar, Na_, 1> m_work;  // for the stability test
    Params m_psi;
    Params m_dw_next;  // dw(k), stored by accept()
    Scalar m_w_next = Scalar(0);
    Scalar m_output = Scalar(0);
  };

 private:
  Eigen::Index first_a() const noexcept { return m_nb + 1; }
  Eigen::Index first_law() const noexcept { return m_nb + 1 + m_na; }
  Eigen::Index first_d() const noexcept { return first_law() + 3; }
  /// d_{j+1} on theta (d_1 = 1).
  Scalar tap(const Params& theta, Eigen::Index j) const noexcept {
    return j == 0 ? Scalar(1) : theta[first_d() + j - 1];
  }
  void set_law(Eigen::Index i, Scalar value, const char* name) {
    detail::require(std::isfinite(value), std::string(name) + " must be finite, got " + detail::format_number(value));
    m_theta[first_law() + i] = value;
  }

  // alpha where the key-term recursions start (relative to A's leading 1: h feeds back in the output's
  // units). With gamma = delta = 0 it changes nothing the model simulates; it lets the law's
  // coefficients move.
  static constexpr Scalar kStartAlpha = Scalar(0.1);

  Params m_theta;
  Eigen::Index m_na, m_nb, m_nk, m_nd, m_ni;
};

}  // namespace bonl
