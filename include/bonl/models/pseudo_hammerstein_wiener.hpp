#pragma once
// Pseudo-Hammerstein-Wiener (P-H-W) model: the Hammerstein model followed by a symmetric,
// unit-slope backlash of half-width c (eqs. 10-12), starting engaged at y(-1) = 0.
// Parameters in eq. (19) order: f_0..f_r, p_0..p_r, b_1..b_nb, a_1..a_na, c.

#include <algorithm>
#include <cmath>
#include <string>

#include "../blocks/backlash.hpp"
#include "../detail/hammerstein_front.hpp"
#include "../detail/model_runs.hpp"

namespace bonl {

template <typename Scalar_ = double, int Na_ = Eigen::Dynamic, int Nb_ = Eigen::Dynamic, int R_ = Eigen::Dynamic>
class PseudoHammersteinWiener : public detail::HammersteinFront<Scalar_, Na_, Nb_, R_, 1> {
  using Front = detail::HammersteinFront<Scalar_, Na_, Nb_, R_, 1>;

 public:
  using typename Front::Params;
  using typename Front::Scalar;
  using typename Front::VectorX;
  static constexpr const char* kName = "PseudoHammersteinWiener";
  static constexpr ModelDescription<4, 5> kDescription{
      kName,
      "Pseudo-Hammerstein-Wiener model: the Hammerstein model followed by a symmetric, unit-slope "
      "backlash of half-width c. y(k) = x(k) - c if x(k) > y(k-1) + c; x(k) + c if x(k) < y(k-1) - c; "
      "else y(k-1).",
      detail::front_orders<Na_, Nb_, R_>(),
      detail::concat(detail::kFrontParameters, std::array<ParameterDescription, 1>{
                                                   {{"c", ParameterShape::Number, "backlash half-width", nullptr, true}}})};

  PseudoHammersteinWiener(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r) : Front(na, nb, nk, r, 1) {}

  std::array<Eigen::Index, 4> orders() const noexcept { return {this->na(), this->nb(), this->nk(), this->r()}; }
  /// The parameter block kDescription.parameters[i]: b, a, f, p, c (one entry).
  VectorX parameter(std::size_t i) const {
    if (i < Front::kFrontBlocks) return this->front_parameter(i);
    if (i == Front::kFrontBlocks) return VectorX::Constant(1, c());
    detail::no_such_parameter(kName, i);
  }
  void set_parameter(std::size_t i, const VectorX& value) {
    if (i < Front::kFrontBlocks) return this->set_front_parameter(i, value);
    if (i == Front::kFrontBlocks) {
      detail::require_size(value, 1, "c");
      return set_c(value[0]);
    }
    detail::no_such_parameter(kName, i);
  }

  /// Backlash half-width c (the model is valid for c >= 0).
  Scalar c() const noexcept { return this->m_theta[this->num_params() - 1]; }
  void set_c(Scalar c) {
    detail::require(std::isfinite(c) && c >= Scalar(0), "c (backlash half-width) must be finite and >= 0");
    this->m_theta[this->num_params() - 1] = c;
  }
  Backlash<Scalar> backlash() const { return Backlash<Scalar>(std::max(c(), Scalar(0))); }

  /// All parameters in the order of eq. (19); c, the last, must be >= 0 as for set_c (an estimate
  /// with c < 0 is projected first: Estimator::model() does that).
  template <typename T>
  void set_theta(const Eigen::MatrixBase<T>& theta) {
    detail::require_size(theta, this->num_params(), "theta");
    const auto c = theta[this->num_params() - 1];
    detail::require(!(c < Scalar(0)), "theta: c (the last entry, the backlash half-width) must be >= 0, got " +
                                          detail::format_number(static_cast<double>(c)));
    Front::set_theta(theta);
  }

  template <typename U>
  VectorX simulate(const Eigen::MatrixBase<U>& u) const {
    return detail::simulate_checked(*this, u);
  }
  template <typename U>
  bool try_simulate(const Eigen::MatrixBase<U>& u, VectorX& y) const {
    Backlash<Scalar> play = backlash();
    return this->simulate_front(u, y, [&play](Scalar x) { return play.step(x); });
  }

  /// One-step-ahead prediction: the backlash's memory is the measured y(k-1), and past x are the
  /// model's estimates clipped to [y - c, y + c], the band the measured output allows.
  template <typename U, typename Y>
  VectorX predict(const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y) const {
    return detail::predict_one_step(*this, u, y);
  }

  /// Zero, but c = c0 (the paper starts from c(0) = 0.01).
  Params initial_estimate(Scalar c0) const {
    Params theta = Params::Zero(this->num_params());
    theta[this->num_params() - 1] = c0;
    return theta;
  }

  /// Key-term form (eqs. 15-18): [front, s(k)] . theta = y_c(k).
  /// Paper: s = 0.5 {(1 - sgn dx) g4 - (1 + sgn dx) g3} and y_c from eq. (27), with g3, g4 from
  /// eqs. (30)-(31) and dx the change of the model's free-run x.
  /// EquationError: the a-priori x decides the regime against the measured y(k-1) (eqs. 30-31); pushing
  /// up gives y = x - c (s = -1), down y = x + c (s = +1); inside the gap y(k) = y(k-1) says nothing
  /// about theta and the sample is skipped. Past x are clipped to [y - c, y + c].
  class KeyTerms {
   public:
    explicit KeyTerms(const PseudoHammersteinWiener& model)
        : m_front(model.na(), model.nb(), model.nk(), model.r()), m_last(model.num_params() - 1) {}
    void reset() noexcept {
      m_front.reset();
      m_y_prev = Scalar(0);
      m_x_prev = Scalar(0);
    }
    template <typename Phi>
    Scalar begin(const Params& theta, Scalar u, Method method, Phi& phi) noexcept {
      const Scalar x = m_front.begin(theta, u, method, phi);
      phi[m_last] = Scalar(0);
      return x;
    }
    Scalar predicted_output(const Params& theta, Scalar x) const noexcept {
      return Backlash<Scalar>::map(x, m_y_prev, std::max(theta[m_last], Scalar(0)));
    }
    template <typename Phi>
    bool regress(const Params& theta, Scalar x, Scalar y, Method method, Phi& phi, Scalar& target) noexcept {
      if (method == Method::Paper) {
        const Scalar c = theta[m_last];
        const Scalar g3 = backlash_g3(x, m_y_prev, c);
        const Scalar g4 = backlash_g4(x, m_y_prev, c);
        const Scalar dx = x - m_x_prev;
        const Scalar sgn = dx > Scalar(0) ? Scalar(1) : (dx < Scalar(0) ? Scalar(-1) : Scalar(0));
        const Scalar y1 = x - Scalar(0.5) * c * (sgn + Scalar(1)) * g3 + Scalar(0.5) * c * (Scalar(1) - sgn) * g4;
        target = y - (m_y_prev - y1) * (g3 - Scalar(1)) * (g4 - Scalar(1));
        phi[m_last] = Scalar(0.5) * ((Scalar(1) - sgn) * g4 - (Scalar(1) + sgn) * g3);
        return true;
      }
      target = y;
      if (theta.head(m_last).isZero(0)) {
        // No model yet (the estimate's front is still all zero): the a-priori x says nothing about
        // the regime, so do not guess one; the sample informs the front as a Hammerstein sample.
        phi[m_last] = Scalar(0);
        return true;
      }
      const Scalar c = std::max(theta[m_last], Scalar(0));
      const Scalar g3 = backlash_g3(x, m_y_prev, c);
      const Scalar g4 = backlash_g4(x, m_y_prev, c);
      phi[m_last] = g4 - g3;
      return g3 + g4 > Scalar(0);
    }
    template <typename Phi>
    void end(const Params& theta, const Phi& phi, Scalar u, Scalar y, Method method) noexcept {
      const Scalar x_model = m_front.internal(theta, phi, method);
      Scalar x_lag = x_model;
      if (method == Method::EquationError) {
        const Scalar c = std::max(theta[m_last], Scalar(0));
        x_lag = std::min(std::max(x_model, y - c), y + c);
      }
      m_front.end(theta, u, x_lag, method);
      m_x_prev = x_model;
      m_y_prev = y;
    }
    void constrain(Params& theta, Method method) const noexcept {
      if (method != Method::Paper && theta[m_last] < Scalar(0)) theta[m_last] = Scalar(0);
    }

   private:
    detail::FrontKeyTerms<Scalar, Na_, Nb_, R_> m_front;
    Eigen::Index m_last;
    Scalar m_y_prev = Scalar(0);
    Scalar m_x_prev = Scalar(0);
  };

  /// The output-error method's view (Method::OutputError): the front's free run with its
  /// sensitivities, then the backlash with the model's own previous output as its memory. Driving up
  /// (x - c > y(k-1)) y = x - c, so dy/dtheta = [dx/dtheta, -1]; driving down y = x + c and
  /// [dx/dtheta, +1]; inside the gap y(k) = y(k-1) and its sensitivity is held. With c = 0 the block
  /// is the identity and counts as driving.
  ///
  /// A model at rest inside its own gap (front all zero, c > 0) has a zero gradient: nothing can
  /// move it. The estimator therefore starts P-H-W with c = 0 and holds c there for its first samples
  /// (hold()), so that the front is learnt first, as a Hammerstein model's.
  class OutputErrorTerms {
   public:
    explicit OutputErrorTerms(const PseudoHammersteinWiener& model)
        : m_front(model.na(), model.nb(), model.nk(), model.r()), m_last(model.num_params() - 1),
          m_dy(Params::Zero(model.num_params())) {}
    void reset() noexcept {
      m_front.reset();
      m_y = Scalar(0);
      m_dy.setZero();
    }
    template <typename Psi>
    Scalar predict(const Params& theta, Scalar u, Psi& psi) noexcept {
      const Scalar x = m_front.step(theta, u);
      const Scalar c = std::max(theta[m_last], Scalar(0));
      if (x - c > m_y || (c == Scalar(0) && x >= m_y)) {
        psi.head(m_last) = m_front.sensitivity();
        psi[m_last] = Scalar(-1);
        return x - c;
      }
      if (x + c < m_y) {
        psi.head(m_last) = m_front.sensitivity();
        psi[m_last] = Scalar(1);
        return x + c;
      }
      psi = m_dy;
      return m_y;
    }
    /// Stores the step: x and its sensitivity in the front, y(k) = `output` and its sensitivity psi as
    /// the backlash memory.
    template <typename Psi>
    void commit(const Psi& psi, Scalar output) noexcept {
      m_front.commit();
      m_y = output;
      m_dy = psi;
    }
    void correct(const Params& delta) noexcept {
      m_front.correct(delta.head(m_last));
      m_y += m_dy.dot(delta);
    }
    bool stable(const Params& theta, Scalar radius) noexcept { return m_front.stable(theta, radius); }
    void constrain(Params& theta) const noexcept { theta[m_last] = std::max(theta[m_last], Scalar(0)); }
    /// Zeroes the sensitivity to c, which is held (at 0) for the estimator's first samples.
    template <typename Psi>
    void hold(Psi& psi) const noexcept { psi[m_last] = Scalar(0); }
    Scalar internal() const noexcept { return m_front.x(); }

   private:
    detail::FrontOutputError<Scalar, Na_, Nb_, R_> m_front;
    Eigen::Index m_last;
    Scalar m_y = Scalar(0);  // the model's own y(k-1): the backlash memory
    Params m_dy;             // and its sensitivity
  };
};

}  // namespace bonl
