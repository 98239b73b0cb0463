#pragma once
// ARX model (the paper's linear reference):
//   y(k) = -sum_{j=1..na} a_j y(k-j) + sum_{i=0..nb} b_i u(k-nk-i) + e(k).
// b_0 is free (no normalisation). Parameter vector: [b_0..b_nb, a_1..a_na].

#include <Eigen/Core>
#include <cmath>

#include "../blocks/linear_block.hpp"
#include "../detail/validate.hpp"
#include "detail/linear_terms.hpp"
#include "detail/model_runs.hpp"
#include "model_description.hpp"
#include "model_steps.hpp"

namespace bonl {

template <typename Scalar_ = double, int Na_ = Eigen::Dynamic, int Nb_ = Eigen::Dynamic>
class ARX : public detail::ModelRuns<ARX<Scalar_, Na_, Nb_>> {
 public:
  using Scalar = Scalar_;
  static constexpr int kNumParams = detail::add_sizes(detail::poly_size(Nb_), Na_);
  /// ARX has no unmeasured internal variable: its regressor is made of measured data only.
  static constexpr bool kHasInternalVariables = false;
  static constexpr const char* kName = "ARX";
  static constexpr ModelDescription<4, 2> kDescription{
      kName,
      "ARX model y(k) = -sum a_j y(k-j) + sum_{i=0..nb} b_i u(k-nk-i).",
      {{{"na", 1, detail::kMaxOrder, Na_, "poles of the linear block (na >= 1)"},
        {"nb", 0, detail::kMaxOrder, Nb_, "B has nb + 1 coefficients b_0..b_nb"},
        {"nk", 0, detail::kMaxOrder, Eigen::Dynamic, "pure delay in samples"},
        detail::kIntegratorsOrder}},
      {{{"b", ParameterShape::Vector, 0, "b_0..b_nb (b_0 is free for ARX)", nullptr, false, {1, 0, -1, 0}},
        {"a", ParameterShape::Vector, 1, "a_1..a_na", nullptr, false, {}}}}};
  using Params = Eigen::Matrix<Scalar, kNumParams, 1>;
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  using Linear = LinearBlock<Scalar, Na_, Nb_>;

  ARX(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index ni = 0) : m_na(na), m_nb(nb), m_nk(nk), m_ni(ni) {
    detail::require_order(na, 1, "na");
    detail::require_order(nb, 0, "nb");
    detail::require_order(nk, 0, "nk");
    detail::require_integrators(ni);
    detail::require_matches_template(na, Na_, "na");
    detail::require_matches_template(nb, Nb_, "nb");
    m_theta = Params::Zero(nb + 1 + na);
  }

  Eigen::Index na() const noexcept { return m_na; }
  Eigen::Index nb() const noexcept { return m_nb; }
  Eigen::Index nk() const noexcept { return m_nk; }
  Eigen::Index ni() const noexcept { return m_ni; }
  Eigen::Index num_params() const noexcept { return m_theta.size(); }

  std::array<Eigen::Index, 4> orders() const noexcept { return {m_na, m_nb, m_nk, m_ni}; }

  const Params& theta() const noexcept { return m_theta; }
  template <typename T>
  void set_theta(const Eigen::MatrixBase<T>& theta) {
    detail::assign_checked(m_theta, theta, "theta");
  }
  /// The parameter block kDescription.parameters[i]: b, a.
  VectorX parameter(std::size_t i) const {
    if (i == 0) return b();
    if (i == 1) return a();
    detail::no_such_parameter(kName, i);
  }
  void set_parameter(std::size_t i, const VectorX& value) {
    if (i == 0) return set_b(value);
    if (i == 1) return set_a(value);
    detail::no_such_parameter(kName, i);
  }
  VectorX b() const { return m_theta.head(m_nb + 1); }
  VectorX a() const { return m_theta.tail(m_na); }
  template <typename T>
  void set_b(const Eigen::MatrixBase<T>& b) {
    detail::assign_checked(m_theta.head(m_nb + 1), b, "b");
  }
  template <typename T>
  void set_a(const Eigen::MatrixBase<T>& a) {
    detail::assign_checked(m_theta.tail(m_na), a, "a");
  }

  /// The free run from rest of the deviations from the operating point (u - u0 to y - y0); false
  /// if it leaves the finite numbers. try_simulate() and simulate() add the operating point.
  template <typename U>
  bool try_simulate_deviations(const Eigen::MatrixBase<U>& u, VectorX& y) const {
    return detail::free_run(this->linear_block(), u, y, detail::Identity{}, detail::Identity{});
  }

  /// Where the recursive estimator starts (all zero).
  Params initial_estimate(Scalar /*c0*/) const { return Params::Zero(num_params()); }
  /// Projects an estimate onto the model's valid set: every theta is valid.
  void constrain(Params& /*theta*/) const noexcept {}

  /// Regressor [u(k-nk), ..., u(k-nk-nb), -y(k-1), ..., -y(k-na)]; target y(k). Both methods agree:
  /// ARX has no unmeasured internal variable. With integrators the y lags are differenced and the
  /// target is y(k) less the integrators' part (detail/integrators.hpp).
  class KeyTerms {
   public:
    KeyTerms(const ARX& model, KeyTermMethod /*method*/)
        : m_linear(model.na(), model.nb(), model.nk(), model.ni()), m_phi(Params::Zero(model.num_params())) {}
    void reset() noexcept { m_linear.reset(); }
    Regression<Scalar, Params> step(const Params& theta, Scalar u, Scalar y) noexcept {
      m_linear.begin(u, m_phi);
      const Scalar carried = m_linear.carried();
      const Scalar prediction = m_phi.dot(theta) + carried;
      m_linear.end(std::isnan(y) ? prediction : y);  // the lags are the measured outputs
      return {m_phi, y - carried, prediction, prediction, true};
    }

   private:
    detail::LinearKeyTerms<Scalar, Na_> m_linear;
    Params m_phi;
  };

  /// The output-error method's view: ARX's parameters as the output-error model
  /// y = z^-nk B / A u, the way simulate() runs it: one step of the linear block's free run, whose
  /// sensitivities are all of psi (detail::LinearOutputError). Nothing to hold at the start.
  class OutputErrorTerms {
   public:
    explicit OutputErrorTerms(const ARX& model, Eigen::Index /*hold*/ = 0)
        : m_linear(model.na(), model.nb(), model.nk(), model.num_params(), model.ni()),
          m_psi(Params::Zero(model.num_params())) {}
    void reset() noexcept { m_linear.reset(); }
    SimulationStep<Scalar, Params> step(const Params& theta, Scalar u) noexcept {
      const Scalar y = m_linear.step(theta, u, m_psi);
      return {y, m_psi, y};
    }
    void accept() noexcept { m_linear.commit(m_psi); }
    void accept(const Params& delta) noexcept {
      accept();
      m_linear.correct(delta);
    }
    bool stable(const Params& theta, Scalar radius) noexcept { return m_linear.stable(theta, radius); }

   private:
    detail::LinearOutputError<Scalar, Na_, kNumParams> m_linear;
    Params m_psi;
  };

 private:
  Params m_theta;
  Eigen::Index m_na, m_nb, m_nk, m_ni;
};

}  // namespace bonl
