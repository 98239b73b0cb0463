#pragma once
// Hammerstein-Wiener (H-W) model: the Hammerstein model followed by the output polynomial
// y = sum_{m=1..r1} q_m x^m (eq. 9), normalised to q_1 = 1 (and b_0 = 1).
// Parameters: eq. (19) front (f, p, b_1..b_nb, a), then q_2..q_r1.

#include <algorithm>

#include "../blocks/output_polynomial.hpp"
#include "../detail/hammerstein_front.hpp"
#include "../detail/model_runs.hpp"

namespace bonl {

template <typename Scalar_ = double, int Na_ = Eigen::Dynamic, int Nb_ = Eigen::Dynamic, int R_ = Eigen::Dynamic,
          int R1_ = Eigen::Dynamic>
class HammersteinWiener : public detail::HammersteinFront<Scalar_, Na_, Nb_, R_, (R1_ == Eigen::Dynamic ? Eigen::Dynamic : R1_ - 1)> {
  using Front = detail::HammersteinFront<Scalar_, Na_, Nb_, R_, (R1_ == Eigen::Dynamic ? Eigen::Dynamic : R1_ - 1)>;

 public:
  using typename Front::Params;
  using typename Front::Scalar;
  using typename Front::VectorX;
  using OutputBlock = OutputPolynomial<Scalar, R1_>;
  static constexpr const char* kName = "Hammerstein-Wiener";

  HammersteinWiener(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r, Eigen::Index r1)
      : Front(na, nb, nk, r, checked_r1(r1) - 1), m_r1(r1) {}

  Eigen::Index r1() const noexcept { return m_r1; }

  /// q_1..q_r1 with q_1 = 1.
  VectorX q() const {
    VectorX q(m_r1);
    q[0] = Scalar(1);
    q.tail(m_r1 - 1) = this->m_theta.tail(m_r1 - 1);
    return q;
  }
  template <typename T>
  void set_q(const Eigen::MatrixBase<T>& q) {
    detail::require_size(q, m_r1, "q");
    detail::require_finite(q, "q");
    detail::require(q[0] == Scalar(1), "q[0] (q_1) must be 1: the H-W model is normalised so that q_1 = 1");
    this->m_theta.tail(m_r1 - 1) = q.tail(m_r1 - 1);
  }
  OutputBlock output_block() const {
    OutputBlock block(m_r1);
    block.set_q(q());
    return block;
  }

  template <typename U>
  VectorX simulate(const Eigen::MatrixBase<U>& u) const {
    return detail::simulate_checked(*this, u);
  }
  template <typename U>
  bool try_simulate(const Eigen::MatrixBase<U>& u, VectorX& y) const {
    const VectorX qv = q();
    return this->simulate_front(u, y, [&qv](Scalar x) { return OutputBlock::evaluate(qv, x); });
  }

  /// One-step-ahead prediction: past x are the measured outputs mapped back through q^-1 (the
  /// branch nearest the model's own estimate); where q cannot be inverted, the model's estimate.
  template <typename U, typename Y>
  VectorX predict(const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y) const {
    return detail::predict_one_step(*this, u, y);
  }

  Params initial_estimate(Scalar /*c0*/) const { return Params::Zero(this->num_params()); }

  /// Key-term form: y(k) = x(k) + sum_{m>=2} q_m x(k)^m with x(k) the front's key-term expression,
  /// i.e. regressor [front, x^2(k), ..., x^r1(k)] with x(k) the a-priori estimate.
  class KeyTerms {
   public:
    explicit KeyTerms(const HammersteinWiener& model)
        : m_front(model.na(), model.nb(), model.nk(), model.r()), m_r1(model.r1()), m_n(model.num_params()) {}
    void reset() noexcept { m_front.reset(); }
    template <typename Phi>
    Scalar begin(const Params& theta, Scalar u, Method method, Phi& phi) noexcept {
      return m_front.begin(theta, u, method, phi);
    }
    Scalar predicted_output(const Params& theta, Scalar x) const noexcept {
      Scalar y = x;
      Scalar power = x;
      for (Eigen::Index m = 2; m <= m_r1; ++m) {
        power *= x;
        y += theta[m_n - m_r1 + m - 1] * power;
      }
      return y;
    }
    template <typename Phi>
    bool regress(const Params& /*theta*/, Scalar x, Scalar y, Method /*method*/, Phi& phi, Scalar& target) noexcept {
      Scalar power = x;
      for (Eigen::Index m = 2; m <= m_r1; ++m) {
        power *= x;
        phi[m_n - m_r1 + m - 1] = power;
      }
      target = y;
      return true;
    }
    template <typename Phi>
    void end(const Params& theta, const Phi& phi, Scalar u, Scalar y, Method method) noexcept {
      const Scalar x_model = m_front.internal(theta, phi, method);
      Scalar x_lag = x_model;
      if (method == Method::EquationError) {
        // q_1 = 1 sits outside theta: invert x + sum_{m>=2} q_m x^m = y.
        Scalar q_buffer[32];
        const Eigen::Index r1 = std::min<Eigen::Index>(m_r1, 32);
        q_buffer[0] = Scalar(1);
        for (Eigen::Index m = 2; m <= r1; ++m) q_buffer[m - 1] = theta[m_n - m_r1 + m - 1];
        Eigen::Map<const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>> q(q_buffer, r1);
        OutputBlock::invert(q, y, x_model, x_lag);
      }
      m_front.end(theta, u, x_lag, method);
    }
    void constrain(Params& /*theta*/, Method /*method*/) const noexcept {}

   private:
    detail::FrontKeyTerms<Scalar, Na_, Nb_, R_> m_front;
    Eigen::Index m_r1;
    Eigen::Index m_n;
  };

  /// The output-error method's view (Method::OutputError): the front's free run with its
  /// sensitivities, then y = x + sum_{m>=2} q_m x^m, so dy/dtheta_front = q'(x) dx/dtheta_front and
  /// dy/dq_m = x^m.
  class OutputErrorTerms {
   public:
    explicit OutputErrorTerms(const HammersteinWiener& model)
        : m_front(model.na(), model.nb(), model.nk(), model.r()), m_r1(model.r1()), m_n(model.num_params()) {}
    void reset() noexcept { m_front.reset(); }
    template <typename Psi>
    Scalar predict(const Params& theta, Scalar u, Psi& psi) noexcept {
      const Scalar x = m_front.step(theta, u);
      Scalar y = x;
      Scalar slope = Scalar(1);
      Scalar power = x;  // x^(m-1), then x^m
      for (Eigen::Index m = 2; m <= m_r1; ++m) {
        const Eigen::Index index = m_n - m_r1 + m - 1;
        slope += Scalar(m) * theta[index] * power;
        power *= x;
        y += theta[index] * power;
        psi[index] = power;
      }
      psi.head(m_n - m_r1 + 1) = slope * m_front.sensitivity();
      return y;
    }
    template <typename Psi>
    void commit(const Psi& /*psi*/, Scalar /*output*/) noexcept { m_front.commit(); }
    void correct(const Params& delta) noexcept { m_front.correct(delta.head(m_n - m_r1 + 1)); }
    bool stable(const Params& theta, Scalar radius) noexcept { return m_front.stable(theta, radius); }
    void constrain(Params& /*theta*/) const noexcept {}
    template <typename Psi>
    void hold(Psi& /*psi*/) const noexcept {}
    Scalar internal() const noexcept { return m_front.x(); }

   private:
    detail::FrontOutputError<Scalar, Na_, Nb_, R_> m_front;
    Eigen::Index m_r1;
    Eigen::Index m_n;
  };

 private:
  static Eigen::Index checked_r1(Eigen::Index r1) {
    detail::require_order(r1, 2, "r1 (output polynomial degree)");
    detail::require(r1 <= 32, "r1 (output polynomial degree) must be <= 32");
    detail::require_matches_template(r1, R1_, "r1");
    return r1;
  }

  Eigen::Index m_r1;
};

}  // namespace bonl
