#pragma once
// Wiener model: the linear block (with delay), then the output polynomial
//   x(k) = -sum_{j=1..na} a_j x(k-j) + sum_{i=0..nb} b_i u(k-nk-i),   y(k) = sum_{m=1..r1} q_m x(k)^m,
// normalised to q_1 = 1 (the gain lives in B, so b_0 is free).
// Parameters: b_0..b_nb, a_1..a_na, q_2..q_r1. Key-term form as the H-W model without the input
// polynomial: y(k) = x(k) + sum_{m>=2} q_m x(k)^m with x(k) = [u lags, -x lags] . [b, a].

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstddef>

#include "../blocks/linear_block.hpp"
#include "../blocks/output_polynomial.hpp"
#include "../detail/validate.hpp"
#include "detail/linear_terms.hpp"
#include "detail/model_runs.hpp"
#include "detail/output_polynomial_terms.hpp"
#include "model_description.hpp"
#include "model_steps.hpp"

namespace bonl {

/// The Wiener model: the linear block (with delay), then the output polynomial: x(k) = -sum_{j=1..na}
/// a_j x(k-j) + sum_{i=0..nb} b_i u(k-nk-i), y(k) = sum_{m=1..r1} q_m x(k)^m, normalised to q_1 = 1
/// (the gain lives in B, so b_0 is free). Parameters: b_0..b_nb, a_1..a_na, q_2..q_r1; q(), set_q()
/// and output_block() come from a shared base.
template <typename Scalar_ = double, int Na_ = Eigen::Dynamic, int Nb_ = Eigen::Dynamic, int R1_ = Eigen::Dynamic>
class Wiener : public detail::ModelRuns<Wiener<Scalar_, Na_, Nb_, R1_>>,
               public detail::OutputPolynomialParameters<Wiener<Scalar_, Na_, Nb_, R1_>> {
  static constexpr int kLinearParams = detail::add_sizes(detail::poly_size(Nb_), Na_);  // b_0..b_nb, a

 public:
  /// \copydoc ARX::Scalar
  using Scalar = Scalar_;
  /// \copydoc ARX::kNumParams
  static constexpr int kNumParams = detail::add_sizes(kLinearParams, R1_ == Eigen::Dynamic ? Eigen::Dynamic : R1_ - 1);
  /// The Wiener model has an unmeasured internal variable, x: its key terms estimate it.
  static constexpr bool kHasInternalVariables = true;
  /// \copydoc ARX::kName
  static constexpr const char* kName = "Wiener";
  /// \copydoc ARX::kDescription
  static constexpr ModelDescription<5, 3> kDescription{
      kName,
      "Wiener model: the linear block x(k) = -sum a_j x(k-j) + sum_{i=0..nb} b_i u(k-nk-i), then "
      "y = sum_{m=1..r1} q_m x^m (q_1 = 1).",
      {{{"na", 1, detail::kMaxOrder, Na_, "poles of the linear block (na >= 1)"},
        {"nb", 0, detail::kMaxOrder, Nb_, "B has nb + 1 coefficients b_0..b_nb"},
        {"nk", 0, detail::kMaxOrder, Eigen::Dynamic, "pure delay in samples"},
        {"r1", 2, 32, R1_, "degree of the output polynomial (2..32)"},
        detail::kIntegratorsOrder}},
      {{{"b",
         ParameterShape::Vector,
         0,
         "b_0..b_nb (b_0 is free: q_1 = 1 fixes the gain)",
         nullptr,
         false,
         {1, 0, -1, 0}},
        {"a", ParameterShape::Vector, 1, "a_1..a_na", nullptr, false, {}},
        {"q",
         ParameterShape::Vector,
         1,
         "q_1..q_r1 with q_1 = 1",
         "the Wiener model is normalised so that q_1 = 1",
         false,
         {1, -1, 0, 0}}}}};
  /// \copydoc ARX::Params
  using Params = Eigen::Matrix<Scalar, kNumParams, 1>;
  /// \copydoc ARX::VectorX
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  /// \copydoc ARX::Linear
  using Linear = LinearBlock<Scalar, Na_, Nb_>;
  using OutputBlock = OutputPolynomial<Scalar, R1_>;  ///< the output polynomial's type (output_block() returns it)

  /// A model with the orders na >= 1, nb >= 0, nk >= 0, r1 in 2..32 (degree of the output polynomial)
  /// and ni in 0..2; the parameters zero but q_1 = 1. Throws std::invalid_argument for an order out of
  /// range or one that differs from the compile-time order.
  /// \param na poles of the linear block, >= 1
  /// \param nb B has nb + 1 coefficients, >= 0
  /// \param nk pure delay in samples, >= 0
  /// \param r1 degree of the output polynomial, 2..32
  /// \param ni integrators (poles fixed at 1), 0..2
  Wiener(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r1, Eigen::Index ni = 0)
      : m_na(na), m_nb(nb), m_nk(nk), m_r1(r1), m_ni(ni) {
    detail::require_order(na, 1, "na");
    detail::require_order(nb, 0, "nb");
    detail::require_order(nk, 0, "nk");
    detail::require_integrators(ni);
    detail::require_order(r1, 2, "r1 (output polynomial degree)");
    detail::require(r1 <= 32, "r1 (output polynomial degree) must be <= 32");
    detail::require_matches_template(na, Na_, "na");
    detail::require_matches_template(nb, Nb_, "nb");
    detail::require_matches_template(r1, R1_, "r1");
    m_theta = Params::Zero(nb + 1 + na + r1 - 1);
  }

  /// \copydoc ARX::na
  Eigen::Index na() const noexcept { return m_na; }
  /// \copydoc ARX::nb
  Eigen::Index nb() const noexcept { return m_nb; }
  /// \copydoc ARX::nk
  Eigen::Index nk() const noexcept { return m_nk; }
  /// The order r1: degree of the output polynomial
  /// \return r1, 2..32
  Eigen::Index r1() const noexcept { return m_r1; }
  /// \copydoc ARX::ni
  Eigen::Index ni() const noexcept { return m_ni; }
  /// \copydoc ARX::num_params
  Eigen::Index num_params() const noexcept { return m_theta.size(); }
  /// \copydoc ARX::orders
  std::array<Eigen::Index, 5> orders() const noexcept { return {m_na, m_nb, m_nk, m_r1, m_ni}; }

  /// \copydoc ARX::theta
  const Params& theta() const noexcept { return m_theta; }
  /// \copydoc ARX::set_theta
  template <typename T>
  void set_theta(const Eigen::MatrixBase<T>& theta) {
    detail::assign_checked(m_theta, theta, "theta");
  }

  /// The numerator coefficients b_0..b_nb (b_0 free)
  /// \return nb + 1 values
  VectorX b() const { return m_theta.head(m_nb + 1); }
  /// \copydoc ARX::a
  VectorX a() const { return m_theta.segment(m_nb + 1, m_na); }
  /// \copydoc ARX::set_b
  template <typename T>
  void set_b(const Eigen::MatrixBase<T>& b) {
    detail::assign_checked(m_theta.head(m_nb + 1), b, "b");
  }
  /// \copydoc ARX::set_a
  template <typename T>
  void set_a(const Eigen::MatrixBase<T>& a) {
    detail::assign_checked(m_theta.segment(m_nb + 1, m_na), a, "a");
  }

  /// The parameter block kDescription.parameters[i]: b, a, q.
  /// \copydetails ARX::parameter
  VectorX parameter(std::size_t i) const {
    if (i == 0) return b();
    if (i == 1) return a();
    if (i == 2) return this->q();
    detail::no_such_parameter(kName, i);
  }
  /// \copydoc ARX::set_parameter
  void set_parameter(std::size_t i, const VectorX& value) {
    if (i == 0) return set_b(value);
    if (i == 1) return set_a(value);
    if (i == 2) return this->set_q(value);
    detail::no_such_parameter(kName, i);
  }

  /// \copydoc ARX::try_simulate_deviations
  template <typename U>
  bool try_simulate_deviations(const Eigen::MatrixBase<U>& u, VectorX& y) const {
    const VectorX qv = this->q();
    return detail::free_run(this->linear_block(), u, y, detail::Identity{},
                            [&qv](Scalar x) { return OutputBlock::evaluate(qv, x); });
  }
  /// Projects an estimate onto the model's valid set: every theta is valid.
  void constrain(Params& /*theta*/) const noexcept {}

  /// Key-term form: regressor [u(k-nk..k-nk-nb), -x(k-1..k-na), x(k)^2..x(k)^r1], target y(k), with
  /// x(k) the a-priori estimate [u lags, -x lags] . [b, a]. The past x: the equation-error method maps
  /// the measured y back through q^-1 (the branch nearest the model's own estimate; where q cannot
  /// be inverted, the model's estimate), the paper's method keeps the model's estimates (eq. 24:
  /// stored a posteriori, at the next step). predict() runs the equation-error form. With integrators
  /// the x lags are differenced and the target is y(k) less their part of x(k).
  class KeyTerms {
   public:
    /// \copydoc ARX::KeyTerms::KeyTerms
    /// \param method KeyTermMethod::EquationError or KeyTermMethod::Paper: where the past internal variables come from
    KeyTerms(const Wiener& model, KeyTermMethod method)
        : m_linear(model.na(), model.nb(), model.nk(), model.ni()), m_output(model.r1(), model.num_params()),
          m_method(method), m_linear_size(model.nb() + 1 + model.na()), m_phi(Params::Zero(model.num_params())) {}
    /// \copydoc ARX::KeyTerms::reset
    void reset() noexcept {
      m_linear.reset();
      m_pending = false;
    }
    /// \copydoc ARX::KeyTerms::step
    Regression<Scalar, Params> step(const Params& theta, Scalar u, Scalar y) noexcept {
      if (m_pending) m_linear.end(linear_part(theta));
      m_linear.begin(u, m_phi);
      const Scalar carried = m_linear.carried();
      const Scalar x = linear_part(theta);
      const Scalar prediction = m_output.output(theta, x);
      m_output.regress(x, m_phi);
      if (m_method == KeyTermMethod::EquationError) {
        m_linear.end(std::isnan(y) ? x : m_output.invert(theta, y, x));
      } else {
        m_pending = true;
      }
      return {m_phi, y - carried, prediction, x, true};
    }

   private:
    /// x(k) = [u lags, -x lags] . [b, a] (and the integrators' part).
    Scalar linear_part(const Params& theta) const noexcept {
      return m_phi.template head<kLinearParams>(m_linear_size).dot(theta.template head<kLinearParams>(m_linear_size)) +
             m_linear.carried();
    }

    detail::LinearKeyTerms<Scalar, Na_> m_linear;
    detail::OutputPolynomialTerms<Scalar> m_output;
    KeyTermMethod m_method;
    Eigen::Index m_linear_size;
    Params m_phi;
    bool m_pending = false;  // the paper's method: the previous sample's x waits to be stored
  };

  /// The output-error method's view: one step of the linear block's free run with its
  /// sensitivities (detail::LinearOutputError, as ARX's), then y = x + sum_{m>=2} q_m x^m, so
  /// dy/d[b, a] = q'(x) dx/d[b, a] and dy/dq_m = x^m. Nothing to hold at the start.
  class OutputErrorTerms {
   public:
    using Sensitivity =
        Eigen::Matrix<Scalar, kLinearParams, 1>;  ///< d x(k) / d[b, a], the linear block's part of the sensitivity

    /// \copydoc ARX::OutputErrorTerms::OutputErrorTerms
    explicit OutputErrorTerms(const Wiener& model)
        : m_linear(model.na(), model.nb(), model.nk(), model.nb() + 1 + model.na(), model.ni()),
          m_output(model.r1(), model.num_params()), m_dx(Sensitivity::Zero(model.nb() + 1 + model.na())),
          m_psi(Params::Zero(model.num_params())) {}
    /// \copydoc ARX::OutputErrorTerms::reset
    void reset() noexcept {
      m_linear.reset();
      m_dx.setZero();
    }
    /// \copydoc ARX::OutputErrorTerms::step
    SimulationStep<Scalar, Params> step(const Params& theta, Scalar u) noexcept {
      Scalar slope;
      const Scalar x = m_linear.step(theta, u, m_dx);
      const Scalar y = m_output.output_and_sensitivity(theta, x, m_psi, slope);
      m_psi.head(m_dx.size()) = slope * m_dx;
      return {y, m_psi, x};
    }
    /// \copydoc ARX::OutputErrorTerms::accept()
    void accept() noexcept { m_linear.commit(m_dx); }
    /// \copydoc ARX::OutputErrorTerms::correct
    void correct(const Params& delta) noexcept { m_linear.correct(delta.template head<kLinearParams>(m_dx.size())); }
    /// \copydoc ARX::OutputErrorTerms::stable
    bool stable(const Params& theta, Scalar radius) noexcept { return m_linear.stable(theta, radius); }

   private:
    detail::LinearOutputError<Scalar, Na_, kLinearParams> m_linear;
    detail::OutputPolynomialTerms<Scalar> m_output;
    Sensitivity m_dx;
    Params m_psi;
  };

 private:
  Params m_theta;
  Eigen::Index m_na, m_nb, m_nk, m_r1, m_ni;
};

}  // namespace bonl
