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

/// The ARX model, the paper's linear reference: y(k) = -sum_{j=1..na} a_j y(k-j) + sum_{i=0..nb}
/// b_i u(k-nk-i) + e(k), b_0 free; parameters [b_0..b_nb, a_1..a_na]. Scalar_ is the arithmetic type;
/// Na_ and Nb_ fix na and nb at compile time (Eigen::Dynamic: set at run time, the common case).
/// Every model has this class's interface (docs/how-to/add_a_model.md): its
/// orders and parameters, the description kDescription, and the per-sample views KeyTerms and
/// OutputErrorTerms the estimator runs; simulate(), try_simulate(), predict() and linear_block() come
/// from a shared base (detail::ModelRuns), the operating point u0, y0 with them.
template <typename Scalar_ = double, int Na_ = Eigen::Dynamic, int Nb_ = Eigen::Dynamic>
class ARX : public detail::ModelRuns<ARX<Scalar_, Na_, Nb_>> {
 public:
  using Scalar = Scalar_;  ///< the arithmetic type (double, float)
  /// The number of parameters when the orders are fixed at compile time, else Eigen::Dynamic.
  static constexpr int kNumParams = detail::add_sizes(detail::poly_size(Nb_), Na_);
  /// ARX has no unmeasured internal variable: its regressor is made of measured data only.
  static constexpr bool kHasInternalVariables = false;
  static constexpr const char* kName = "ARX";  ///< the model's name, as model files and Python write it
  /// What the model is, once: its name, a summary, its orders with their ranges and defaults, and its
  /// parameter blocks in theta's order. JSON, the bindings, selection and the tests loop over it.
  static constexpr ModelDescription<4, 2> kDescription{
      kName,
      "ARX model y(k) = -sum a_j y(k-j) + sum_{i=0..nb} b_i u(k-nk-i).",
      {{{"na", 1, detail::kMaxOrder, Na_, "poles of the linear block (na >= 1)"},
        {"nb", 0, detail::kMaxOrder, Nb_, "B has nb + 1 coefficients b_0..b_nb"},
        {"nk", 0, detail::kMaxOrder, Eigen::Dynamic, "pure delay in samples"},
        detail::kIntegratorsOrder}},
      {{{"b", ParameterShape::Vector, 0, "b_0..b_nb (b_0 is free for ARX)", nullptr, false, {1, 0, -1, 0}},
        {"a", ParameterShape::Vector, 1, "a_1..a_na", nullptr, false, {}}}}};
  using Params = Eigen::Matrix<Scalar, kNumParams, 1>;  ///< the parameter vector theta (fixed size when the orders are)
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;  ///< a vector of run-time size (outputs, parameter blocks)
  using Linear = LinearBlock<Scalar, Na_, Nb_>;              ///< the linear block's type (linear_block() returns it)

  /// A model with the given orders, all parameters zero. Throws std::invalid_argument for an order out
  /// of range or one that differs from the compile-time order.
  /// \param na poles of the linear block, >= 1
  /// \param nb B has nb + 1 coefficients, >= 0
  /// \param nk pure delay in samples, >= 0
  /// \param ni integrators (poles fixed at 1), 0..2
  ARX(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index ni = 0) : m_na(na), m_nb(nb), m_nk(nk), m_ni(ni) {
    detail::require_order(na, 1, "na");
    detail::require_order(nb, 0, "nb");
    detail::require_order(nk, 0, "nk");
    detail::require_integrators(ni);
    detail::require_matches_template(na, Na_, "na");
    detail::require_matches_template(nb, Nb_, "nb");
    m_theta = Params::Zero(nb + 1 + na);
  }

  Eigen::Index na() const noexcept { return m_na; }  ///< the order na: poles of the linear block \return na, >= 1
  /// the order nb: B has nb + 1 coefficients b_0..b_nb
  /// \return nb, >= 0
  Eigen::Index nb() const noexcept { return m_nb; }
  Eigen::Index nk() const noexcept { return m_nk; }  ///< the order nk: pure delay in samples \return nk, >= 0
  /// the order ni: integrators (poles fixed at 1), 0, 1 or 2
  /// \return ni, 0..2
  Eigen::Index ni() const noexcept { return m_ni; }
  /// The length of theta
  /// \return the number of parameters, kNumParams when it is fixed
  Eigen::Index num_params() const noexcept { return m_theta.size(); }

  /// The orders in kDescription.orders' order (here na, nb, nk, ni), as a model file writes them.
  /// \return one entry per order of kDescription.orders
  std::array<Eigen::Index, 4> orders() const noexcept { return {m_na, m_nb, m_nk, m_ni}; }

  /// The parameter vector theta in eq. (19) order (kDescription.parameters gives its blocks).
  /// \return a reference to the model's theta, valid while the model lives
  const Params& theta() const noexcept { return m_theta; }
  /// Sets theta, the whole parameter vector. Throws std::invalid_argument unless it has num_params()
  /// finite entries.
  /// \param theta the new parameter vector, num_params() entries in eq. (19) order
  template <typename T>
  void set_theta(const Eigen::MatrixBase<T>& theta) {
    detail::assign_checked(m_theta, theta, "theta");
  }
  /// The parameter block kDescription.parameters[i]: b, a.
  /// \param i the block's index in kDescription.parameters
  /// \return a copy of the block's entries in its order (a normalised block without its fixed first entry)
  VectorX parameter(std::size_t i) const {
    if (i == 0) return b();
    if (i == 1) return a();
    detail::no_such_parameter(kName, i);
  }
  /// Sets the parameter block kDescription.parameters[i] to value (its entries in the block's order;
  /// a normalised block's fixed first entry excluded). Throws std::invalid_argument for an index past
  /// the blocks, a wrong length or a non-finite entry.
  /// \param i the block's index in kDescription.parameters
  /// \param value the block's new entries
  void set_parameter(std::size_t i, const VectorX& value) {
    if (i == 0) return set_b(value);
    if (i == 1) return set_a(value);
    detail::no_such_parameter(kName, i);
  }
  VectorX b() const { return m_theta.head(m_nb + 1); }  ///< the numerator coefficients b_0..b_nb \return nb + 1 values
  VectorX a() const { return m_theta.tail(m_na); }      ///< the denominator coefficients a_1..a_na \return na values
  /// Sets b_0..b_nb (nb + 1 finite values, else std::invalid_argument).
  /// \param b b_0..b_nb
  template <typename T>
  void set_b(const Eigen::MatrixBase<T>& b) {
    detail::assign_checked(m_theta.head(m_nb + 1), b, "b");
  }
  /// Sets a_1..a_na (na finite values, else std::invalid_argument).
  /// \param a a_1..a_na
  template <typename T>
  void set_a(const Eigen::MatrixBase<T>& a) {
    detail::assign_checked(m_theta.tail(m_na), a, "a");
  }

  /// The free run from rest of the deviations from the operating point (u - u0 to y - y0); false
  /// if it leaves the finite numbers. try_simulate() and simulate() add the operating point.
  /// \param u the input's deviations u(k) - u0, one per sample
  /// \param y resized to u's length and filled with the output's deviations y(k) - y0
  /// \return true when every output is finite, false if the run left the finite numbers (y is then partial)
  template <typename U>
  bool try_simulate_deviations(const Eigen::MatrixBase<U>& u, VectorX& y) const {
    return detail::free_run(this->linear_block(), u, y, detail::Identity{}, detail::Identity{});
  }
  /// Projects an estimate onto the model's valid set: every theta is valid.
  void constrain(Params& /*theta*/) const noexcept {}

  /// Regressor [u(k-nk), ..., u(k-nk-nb), -y(k-1), ..., -y(k-na)]; target y(k). Both methods agree:
  /// ARX has no unmeasured internal variable. With integrators the y lags are differenced and the
  /// target is y(k) less the integrators' part (detail/integrators.hpp).
  class KeyTerms {
   public:
    /// Starts the key terms of model (its orders; the parameters come with each step) for method, at
    /// rest.
    /// \param model the model whose orders the regressor has; only its orders are read
    KeyTerms(const ARX& model, KeyTermMethod /*method*/)
        : m_linear(model.na(), model.nb(), model.nk(), model.ni()), m_phi(Params::Zero(model.num_params())) {}
    /// Back to rest: the stored past inputs, outputs and internal variables are zero.
    void reset() noexcept { m_linear.reset(); }
    /// One sample: builds the regressor for y(k) from the stored past and stores u(k), y(k) for the next.
    /// \param theta the estimate to build the regressor with (the paper's method also stores the
    /// previous sample's internal variables with it)
    /// \param u the input u(k)
    /// \param y the measured output y(k); NaN: not measured, the prediction stands in
    /// \return the Regression (regressor, target, prediction, internal variable, informative), whose
    /// regressor stays valid until the next step
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
    /// Starts the free run of model at rest.
    /// \param model the model whose orders the run has; only its orders are read
    explicit OutputErrorTerms(const ARX& model)
        : m_linear(model.na(), model.nb(), model.nk(), model.num_params(), model.ni()),
          m_psi(Params::Zero(model.num_params())) {}
    /// Back to rest, sensitivities included.
    void reset() noexcept { m_linear.reset(); }
    /// One sample of the free run. Call accept() or correct() after accept() before the next step.
    /// \param theta the estimate to run with
    /// \param u the input u(k)
    /// \return the SimulationStep: the output, its sensitivity to theta (valid until the next step) and
    /// the internal variable
    SimulationStep<Scalar, Params> step(const Params& theta, Scalar u) noexcept {
      const Scalar y = m_linear.step(theta, u, m_psi);
      return {y, m_psi, y};
    }
    /// Moves the run on by the step just taken, with theta unchanged (a refinement's Jacobian pass).
    void accept() noexcept { m_linear.commit(m_psi); }
    /// Moves the stored run to first order along a change delta of the estimate: the stored
    /// sensitivities correct the stored past as if the run had used theta + delta. The online
    /// estimator calls it after accept() once its update moved theta; the window refinement calls it
    /// on a copy of a run to start that run for another theta.
    /// \param delta the change of theta since the step just accepted
    void correct(const Params& delta) noexcept { m_linear.correct(delta); }
    /// Whether the linear block's poles with theta lie inside the circle of the given radius (the
    /// output-error method keeps the estimate where this holds).
    /// \param theta the estimate whose poles are checked
    /// \param radius the circle's radius, below 1 for a margin
    /// \return true when every pole lies inside, false otherwise
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
