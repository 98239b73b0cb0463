#pragma once
// Hammerstein-Wiener (H-W) model: the Hammerstein model followed by the output polynomial
// y = sum_{m=1..r1} q_m x^m (eq. 9), normalised to q_1 = 1 (and b_0 = 1).
// Parameters: eq. (19) front (f, p, b_1..b_nb, a), then q_2..q_r1.

#include <algorithm>
#include <cmath>

#include "../blocks/output_polynomial.hpp"
#include "detail/hammerstein_front.hpp"
#include "detail/model_runs.hpp"
#include "detail/output_polynomial_terms.hpp"

namespace bonl {

/// The Hammerstein-Wiener (H-W) model: the Hammerstein model followed by the output polynomial
/// y = sum_{m=1..r1} q_m x^m (eq. 9), normalised to q_1 = 1 (and b_0 = 1). Parameters: the eq. (19)
/// front (f, p, b_1..b_nb, a), then q_2..q_r1; q(), set_q() and output_block() come from a shared base.
template <typename Scalar_ = double, int Na_ = Eigen::Dynamic, int Nb_ = Eigen::Dynamic, int R_ = Eigen::Dynamic,
          int R1_ = Eigen::Dynamic>
class HammersteinWiener
    : public detail::HammersteinFront<Scalar_, Na_, Nb_, R_, (R1_ == Eigen::Dynamic ? Eigen::Dynamic : R1_ - 1)>,
      public detail::ModelRuns<HammersteinWiener<Scalar_, Na_, Nb_, R_, R1_>>,
      public detail::OutputPolynomialParameters<HammersteinWiener<Scalar_, Na_, Nb_, R_, R1_>> {
  using Front = detail::HammersteinFront<Scalar_, Na_, Nb_, R_, (R1_ == Eigen::Dynamic ? Eigen::Dynamic : R1_ - 1)>;

 public:
  using typename Front::Params;
  using typename Front::Scalar;
  using typename Front::VectorX;
  using OutputBlock = OutputPolynomial<Scalar, R1_>;  ///< the output polynomial's type (output_block() returns it)
  /// \copydoc ARX::kName
  static constexpr const char* kName = "HammersteinWiener";
  /// \copydoc ARX::kDescription
  static constexpr ModelDescription<6, 5> kDescription{
      kName, "Hammerstein-Wiener model: the Hammerstein model followed by y = sum_{m=1..r1} q_m x^m (q_1 = 1).",
      detail::concat(detail::front_orders<Na_, Nb_, R_>(),
                     std::array<OrderDescription, 2>{
                         {{"r1", 2, 32, R1_, "degree of the output polynomial (2..32)"}, detail::kIntegratorsOrder}}),
      detail::concat(detail::kFrontParameters,
                     std::array<ParameterDescription, 1>{{{"q",
                                                           ParameterShape::Vector,
                                                           1,
                                                           "q_1..q_r1 with q_1 = 1",
                                                           "the H-W model is normalised so that q_1 = 1",
                                                           false,
                                                           {1, -1, 0, 0}}}})};

  /// A model with the orders na >= 1, nb >= 1, nk >= 0, r >= 0, r1 in 2..32 (degree of the output
  /// polynomial) and ni in 0..2; the parameters zero but q_1 = 1. Throws std::invalid_argument for an
  /// order out of range or one that differs from the compile-time order.
  /// \param na poles of the linear block, >= 1
  /// \param nb B has nb + 1 coefficients, b_0 = 1, >= 1
  /// \param nk pure delay in samples, >= 0
  /// \param r degree of each segment of the input polynomial, >= 0
  /// \param r1 degree of the output polynomial, 2..32
  /// \param ni integrators (poles fixed at 1), 0..2
  HammersteinWiener(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r, Eigen::Index r1,
                    Eigen::Index ni = 0)
      : Front(na, nb, nk, r, checked_r1(r1) - 1, ni), m_r1(r1) {}

  /// The order r1: degree of the output polynomial
  /// \return r1, 2..32
  Eigen::Index r1() const noexcept { return m_r1; }
  /// \copydoc ARX::orders
  std::array<Eigen::Index, 6> orders() const noexcept {
    return {this->na(), this->nb(), this->nk(), this->r(), m_r1, this->ni()};
  }
  /// The parameter block kDescription.parameters[i]: b, a, f, p, q.
  /// \copydetails ARX::parameter
  VectorX parameter(std::size_t i) const {
    if (i < Front::kFrontBlocks) return this->front_parameter(i);
    if (i == Front::kFrontBlocks) return this->q();
    detail::no_such_parameter(kName, i);
  }
  /// \copydoc ARX::set_parameter
  void set_parameter(std::size_t i, const VectorX& value) {
    if (i < Front::kFrontBlocks) return this->set_front_parameter(i, value);
    if (i == Front::kFrontBlocks) return this->set_q(value);
    detail::no_such_parameter(kName, i);
  }

  /// \copydoc ARX::try_simulate_deviations
  template <typename U>
  bool try_simulate_deviations(const Eigen::MatrixBase<U>& u, VectorX& y) const {
    const VectorX qv = this->q();
    return this->simulate_front(
        u, y, this->linear_block(), [&qv](Scalar x) { return OutputBlock::evaluate(qv, x); },
        this->input_deviation_range());
  }

  /// Key-term form: y(k) = x(k) + sum_{m>=2} q_m x(k)^m with x(k) the front's key-term expression,
  /// i.e. regressor [front, x^2(k), ..., x^r1(k)] with x(k) the a-priori estimate. The past x: the
  /// equation-error method maps the measured y back through q^-1 (the branch nearest the model's own
  /// estimate; where q cannot be inverted, the model's estimate), the paper's keeps the model's own.
  /// predict() runs the equation-error form.
  class KeyTerms {
   public:
    /// \copydoc ARX::KeyTerms::KeyTerms
    /// \param method KeyTermMethod::EquationError or KeyTermMethod::Paper: where the past internal variables come from
    KeyTerms(const HammersteinWiener& model, KeyTermMethod method)
        : m_front(model.na(), model.nb(), model.nk(), model.r(), method, model.ni()),
          m_output(model.r1(), model.num_params()), m_method(method), m_phi(Params::Zero(model.num_params())) {}
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
      const Scalar prediction = m_output.output(theta, x);
      m_output.regress(x, m_phi);
      if (m_method == KeyTermMethod::EquationError) m_front.store(std::isnan(y) ? x : m_output.invert(theta, y, x));
      return {m_phi, y - carried, prediction, x, true};
    }

   private:
    detail::FrontKeyTerms<Scalar, Na_, Nb_, R_> m_front;
    detail::OutputPolynomialTerms<Scalar> m_output;
    KeyTermMethod m_method;
    Params m_phi;
  };

  /// The output-error method's view: the front's free run with its sensitivities, then
  /// y = x + sum_{m>=2} q_m x^m, so dy/dtheta_front = q'(x) dx/dtheta_front and dy/dq_m = x^m.
  /// Nothing to hold at the start.
  class OutputErrorTerms {
   public:
    /// \copydoc ARX::OutputErrorTerms::OutputErrorTerms
    explicit OutputErrorTerms(const HammersteinWiener& model)
        : m_front(model.na(), model.nb(), model.nk(), model.r(), model.ni()), m_output(model.r1(), model.num_params()),
          m_front_size(model.num_params() - model.r1() + 1), m_psi(Params::Zero(model.num_params())) {}
    /// \copydoc ARX::OutputErrorTerms::reset
    void reset() noexcept { m_front.reset(); }
    /// \copydoc ARX::OutputErrorTerms::step
    SimulationStep<Scalar, Params> step(const Params& theta, Scalar u) noexcept {
      Scalar slope;
      const Scalar x = m_front.step(theta, u);
      const Scalar y = m_output.output_and_sensitivity(theta, x, m_psi, slope);
      m_psi.head(m_front_size) = slope * m_front.sensitivity();
      return {y, m_psi, x};
    }
    /// \copydoc ARX::OutputErrorTerms::accept()
    void accept() noexcept { m_front.commit(); }
    /// \copydoc ARX::OutputErrorTerms::correct
    void correct(const Params& delta) noexcept { m_front.correct(delta.head(m_front_size)); }
    /// \copydoc ARX::OutputErrorTerms::stable
    bool stable(const Params& theta, Scalar radius) noexcept { return m_front.stable(theta, radius); }

   private:
    detail::FrontOutputError<Scalar, Na_, Nb_, R_> m_front;
    detail::OutputPolynomialTerms<Scalar> m_output;
    Eigen::Index m_front_size;
    Params m_psi;
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
