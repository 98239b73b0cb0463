#pragma once
// Hammerstein model: two-segment input polynomial N1 (eqs. 3-5), then the linear block
// (eqs. 6-8, b_0 = 1); y = x. Parameters in eq. (19) order: f_0..f_r, p_0..p_r, b_1..b_nb, a_1..a_na.

#include <cmath>

#include "detail/hammerstein_front.hpp"
#include "detail/model_runs.hpp"

namespace bonl {

/// The Hammerstein model: the two-segment input polynomial N1 (eqs. 3-5), then the linear block
/// (eqs. 6-8, b_0 = 1); y = x. Parameters in eq. (19) order: f_0..f_r, p_0..p_r, b_1..b_nb,
/// a_1..a_na. The orders, theta and the blocks' accessors come from the shared front; the interface is
/// ARX's.
template <typename Scalar_ = double, int Na_ = Eigen::Dynamic, int Nb_ = Eigen::Dynamic, int R_ = Eigen::Dynamic>
class Hammerstein : public detail::HammersteinFront<Scalar_, Na_, Nb_, R_, 0>,
                    public detail::ModelRuns<Hammerstein<Scalar_, Na_, Nb_, R_>> {
  using Front = detail::HammersteinFront<Scalar_, Na_, Nb_, R_, 0>;

 public:
  using typename Front::Params;
  using typename Front::Scalar;
  using typename Front::VectorX;
  /// \copydoc ARX::kName
  static constexpr const char* kName = "Hammerstein";
  /// \copydoc ARX::kDescription
  static constexpr ModelDescription<5, 4> kDescription{
      kName,
      "Hammerstein model: two-segment input polynomial, then the linear block (b_0 = 1). "
      "w = sum_l f_l u^l + h(u) sum_l p_l u^l (h(u) = 1 for u < 0), "
      "x(k) = -sum a_j x(k-j) + sum b_i w(k-nk-i), y = x.",
      detail::concat(detail::front_orders<Na_, Nb_, R_>(), std::array<OrderDescription, 1>{detail::kIntegratorsOrder}),
      detail::kFrontParameters};

  /// A model with the orders na >= 1, nb >= 1, nk >= 0, r >= 0 (degree of each segment of the input
  /// polynomial) and ni in 0..2, all parameters zero. Throws std::invalid_argument for an order out of
  /// range or one that differs from the compile-time order.
  /// \param na poles of the linear block, >= 1
  /// \param nb B has nb + 1 coefficients, b_0 = 1, >= 1
  /// \param nk pure delay in samples, >= 0
  /// \param r degree of each segment of the input polynomial, >= 0
  /// \param ni integrators (poles fixed at 1), 0..2
  Hammerstein(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r, Eigen::Index ni = 0)
      : Front(na, nb, nk, r, 0, ni) {}

  /// \copydoc ARX::orders
  std::array<Eigen::Index, 5> orders() const noexcept {
    return {this->na(), this->nb(), this->nk(), this->r(), this->ni()};
  }
  /// The parameter block kDescription.parameters[i]: b, a, f, p.
  /// \copydetails ARX::parameter
  VectorX parameter(std::size_t i) const {
    if (i >= 4) detail::no_such_parameter(kName, i);
    return this->front_parameter(i);
  }
  /// \copydoc ARX::set_parameter
  void set_parameter(std::size_t i, const VectorX& value) {
    if (i >= 4) detail::no_such_parameter(kName, i);
    this->set_front_parameter(i, value);
  }

  /// \copydoc ARX::try_simulate_deviations
  template <typename U>
  bool try_simulate_deviations(const Eigen::MatrixBase<U>& u, VectorX& y) const {
    return this->simulate_front(
        u, y, this->linear_block(), [](Scalar x) { return x; }, this->input_deviation_range());
  }

  /// Key-term form (eq. 14): y(k) = [basis(u(k-nk)), w lags, -x lags] . theta. The past x are the
  /// measured y for the equation-error method and the model's own run for the paper's. With
  /// integrators the target is y(k) less their part, known from the past x.
  class KeyTerms {
   public:
    /// \copydoc ARX::KeyTerms::KeyTerms
    /// \param method KeyTermMethod::EquationError or KeyTermMethod::Paper: where the past internal variables come from
    KeyTerms(const Hammerstein& model, KeyTermMethod method)
        : m_front(model.na(), model.nb(), model.nk(), model.r(), method, model.ni()), m_method(method),
          m_phi(Params::Zero(model.num_params())) {}
    /// Where the input block continues linearly (FrontKeyTerms::set_input_range).
    /// \param range the input range as deviations from u0
    void set_input_range(const detail::InputDeviationRange& range) noexcept { m_front.set_input_range(range); }
    /// \copydoc ARX::KeyTerms::reset
    void reset() noexcept { m_front.reset(); }
    /// \copydoc ARX::KeyTerms::step
    Regression<Scalar, Params> step(const Params& theta, Scalar u, Scalar y) noexcept {
      if (m_front.pending()) m_front.store_a_posteriori(theta, m_phi);
      const Scalar carried = m_front.carried();
      const Scalar x = m_front.begin(theta, u, m_phi);
      if (m_method == KeyTermMethod::EquationError) m_front.store(std::isnan(y) ? x : y);
      return {m_phi, y - carried, x, x, true};
    }

   private:
    detail::FrontKeyTerms<Scalar, Na_, Nb_, R_> m_front;
    KeyTermMethod m_method;
    Params m_phi;
  };

  /// The output-error method's view: the free run one step at a time with its sensitivities;
  /// y = x, so dy/dtheta = dx/dtheta. Nothing to hold at the start.
  class OutputErrorTerms {
   public:
    /// \copydoc ARX::OutputErrorTerms::OutputErrorTerms
    explicit OutputErrorTerms(const Hammerstein& model)
        : m_front(model.na(), model.nb(), model.nk(), model.r(), model.ni()) {}
    /// \copydoc ARX::OutputErrorTerms::reset
    void reset() noexcept { m_front.reset(); }
    /// \copydoc ARX::OutputErrorTerms::step
    SimulationStep<Scalar, Params> step(const Params& theta, Scalar u) noexcept {
      const Scalar x = m_front.step(theta, u);
      return {x, m_front.sensitivity(), x};
    }
    /// \copydoc ARX::OutputErrorTerms::accept()
    void accept() noexcept { m_front.commit(); }
    /// \copydoc ARX::OutputErrorTerms::correct
    void correct(const Params& delta) noexcept { m_front.correct(delta); }
    /// \copydoc ARX::OutputErrorTerms::stable
    bool stable(const Params& theta, Scalar radius) noexcept { return m_front.stable(theta, radius); }

   private:
    detail::FrontOutputError<Scalar, Na_, Nb_, R_> m_front;
  };
};

}  // namespace bonl
