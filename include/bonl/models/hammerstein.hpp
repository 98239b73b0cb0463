#pragma once
// Hammerstein model: two-segment input polynomial N1 (eqs. 3-5), then the linear block
// (eqs. 6-8, b_0 = 1); y = x. Parameters in eq. (19) order: f_0..f_r, p_0..p_r, b_1..b_nb, a_1..a_na.

#include "../detail/hammerstein_front.hpp"
#include "../detail/model_runs.hpp"

namespace bonl {

template <typename Scalar_ = double, int Na_ = Eigen::Dynamic, int Nb_ = Eigen::Dynamic, int R_ = Eigen::Dynamic>
class Hammerstein : public detail::HammersteinFront<Scalar_, Na_, Nb_, R_, 0> {
  using Front = detail::HammersteinFront<Scalar_, Na_, Nb_, R_, 0>;

 public:
  using typename Front::Params;
  using typename Front::Scalar;
  using typename Front::VectorX;
  static constexpr const char* kName = "Hammerstein";

  Hammerstein(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r) : Front(na, nb, nk, r, 0) {}

  /// Free-run simulation from rest. Throws NumericalError if the output leaves the finite numbers.
  template <typename U>
  VectorX simulate(const Eigen::MatrixBase<U>& u) const {
    return detail::simulate_checked(*this, u);
  }
  template <typename U>
  bool try_simulate(const Eigen::MatrixBase<U>& u, VectorX& y) const {
    return this->simulate_front(u, y, [](Scalar x) { return x; });
  }

  /// One-step-ahead prediction: past x are the measured outputs.
  template <typename U, typename Y>
  VectorX predict(const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y) const {
    return detail::predict_one_step(*this, u, y);
  }

  Params initial_estimate(Scalar /*c0*/) const { return Params::Zero(this->num_params()); }

  /// Key-term form (eq. 14): y(k) = [basis(u(k-nk)), w lags, -x lags] . theta. The past x are the
  /// model's free run for Method::Paper and the measured y for Method::EquationError.
  class KeyTerms {
   public:
    explicit KeyTerms(const Hammerstein& model) : m_front(model.na(), model.nb(), model.nk(), model.r()) {}
    void reset() noexcept { m_front.reset(); }
    template <typename Phi>
    Scalar begin(const Params& theta, Scalar u, Method method, Phi& phi) noexcept {
      return m_front.begin(theta, u, method, phi);
    }
    Scalar predicted_output(const Params& /*theta*/, Scalar x) const noexcept { return x; }
    template <typename Phi>
    bool regress(const Params& /*theta*/, Scalar /*x*/, Scalar y, Method /*method*/, Phi& /*phi*/,
                 Scalar& target) noexcept {
      target = y;
      return true;
    }
    template <typename Phi>
    void end(const Params& theta, const Phi& phi, Scalar u, Scalar y, Method method) noexcept {
      m_front.end(theta, u, method == Method::Paper ? m_front.internal(theta, phi, method) : y, method);
    }
    void constrain(Params& /*theta*/, Method /*method*/) const noexcept {}

   private:
    detail::FrontKeyTerms<Scalar, Na_, Nb_, R_> m_front;
  };

  /// The output-error method's view (Method::OutputError): the free run one step at a time with
  /// its sensitivities; y = x, so dy/dtheta = dx/dtheta.
  class OutputErrorTerms {
   public:
    explicit OutputErrorTerms(const Hammerstein& model) : m_front(model.na(), model.nb(), model.nk(), model.r()) {}
    void reset() noexcept { m_front.reset(); }
    /// Pushes u(k); returns the simulated y(k) with `theta` and writes dy(k)/dtheta into psi.
    template <typename Psi>
    Scalar predict(const Params& theta, Scalar u, Psi& psi) noexcept {
      const Scalar x = m_front.step(theta, u);
      psi = m_front.sensitivity();
      return x;
    }
    template <typename Psi>
    void commit(const Psi& /*psi*/, Scalar /*output*/) noexcept { m_front.commit(); }
    void correct(const Params& delta) noexcept { m_front.correct(delta); }
    bool stable(const Params& theta, Scalar radius) noexcept { return m_front.stable(theta, radius); }
    void constrain(Params& /*theta*/) const noexcept {}
    template <typename Psi>
    void hold(Psi& /*psi*/) const noexcept {}
    Scalar internal() const noexcept { return m_front.x(); }

   private:
    detail::FrontOutputError<Scalar, Na_, Nb_, R_> m_front;
  };
};

}  // namespace bonl
