#pragma once
// Prandtl-Ishlinskii Hammerstein model: input hysteresis (a valve's pilot stage), then the linear block
//   w(k) = sum_{l=0..r} f_l u(k)^l + sum_{i=1..np} g_i play_{r_i}[u](k),
//   x(k) = -sum_{j=1..na} a_j x(k-j) + sum_{i=0..nb} b_i w(k-nk-i),   b_0 = 1,   y = x,
// with u the deviation from the operating point and the plays those of blocks/play_operators.hpp, at
// rest (0) before the record. The thresholds r_1 < ... < r_np are structure, not estimated, as the
// Wiener-Hammerstein model's knots are: the model's own (the defaults r_i = i / (np + 1), set_thresholds(),
// a model file), or placed from the data by identify() (identify_starts below). For fixed thresholds w
// is linear in [f, g], so the key-term form is the Hammerstein model's with a longer basis:
//   x(k) = [basis(k-nk)] . [f, g] + sum_{i=1..nb} b_i w(k-nk-i) - sum_j a_j x(k-j),
//   basis(k) = [1, u(k), ..., u(k)^r, P_1(k), ..., P_np(k)].
// The plays depend on u alone, so their memory is the input's past: run from rest over the record,
// or over the measured past before a simulation from it (simulate(u, u_past, y_past)).
// Parameters: f_0..f_r, g_1..g_np, b_1..b_nb, a_1..a_na.

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "../blocks/linear_block.hpp"
#include "../blocks/play_operators.hpp"
#include "../blocks/prandtl_ishlinskii_input.hpp"
#include "../detail/history.hpp"
#include "../detail/integrators.hpp"
#include "../detail/stability.hpp"
#include "../detail/validate.hpp"
#include "detail/hammerstein_front.hpp"
#include "detail/model_runs.hpp"
#include "detail/simulated_lags.hpp"
#include "model_description.hpp"
#include "model_steps.hpp"

namespace bonl {

/// The Prandtl-Ishlinskii Hammerstein model: the input hysteresis of a valve's pilot stage,
/// w = sum_{l=0..r} f_l u^l + sum_{i=1..np} g_i play_{r_i}[u] (PrandtlIshlinskiiInput, the plays of
/// PlayOperators at rest before the record), then the linear block (b_0 = 1); y = x. The thresholds
/// r_1 < ... < r_np are structure, not estimated: the defaults r_i = i / (np + 1), set_thresholds(), a
/// model file, or placed from the data by identify(). For fixed thresholds w is linear in [f, g], so
/// the key-term form is the Hammerstein model's with a longer basis. Parameters: f_0..f_r, g_1..g_np,
/// b_1..b_nb, a_1..a_na. Np_ fixes np at compile time like the other orders; the interface is ARX's.
template <typename Scalar_ = double, int Na_ = Eigen::Dynamic, int Nb_ = Eigen::Dynamic, int R_ = Eigen::Dynamic,
          int Np_ = Eigen::Dynamic>
class PrandtlIshlinskiiHammerstein
    : public detail::ModelRuns<PrandtlIshlinskiiHammerstein<Scalar_, Na_, Nb_, R_, Np_>> {
  static constexpr int kBasis = detail::add_sizes(detail::poly_size(R_), Np_);  // f, g

 public:
  /// \copydoc ARX::Scalar
  using Scalar = Scalar_;
  /// \copydoc ARX::kNumParams
  static constexpr int kNumParams = detail::add_sizes(kBasis, detail::add_sizes(Nb_, Na_));
  /// The Prandtl-Ishlinskii Hammerstein model has an unmeasured internal variable, w, the hysteresis'
  /// output; the paper's method also runs its own x.
  static constexpr bool kHasInternalVariables = true;
  /// The inverse for control (control/inverse_model.hpp) inverts input_block() with
  /// control/prandtl_ishlinskii_inverse.hpp: for the plays' memory, a bracketing search for the
  /// command over the clamps' breakpoints where w is monotone in u for every state of the plays (the
  /// closed-form inverse PI operator, Kuhnen 2003, covers only f = (0, f_1) and positive weights).
  static constexpr bool kInvertible = true;
  /// \copydoc ARX::kName
  static constexpr const char* kName = "PrandtlIshlinskiiHammerstein";
  /// \copydoc ARX::kDescription
  static constexpr ModelDescription<6, 5> kDescription{
      kName,
      "Prandtl-Ishlinskii Hammerstein model: input hysteresis w = sum_{l=0..r} f_l u^l + sum_{i=1..np} g_i "
      "play_{r_i}[u] (play_r[u](k) = min(max(P(k-1), u(k) - r), u(k) + r), P = 0 at rest; thresholds r_i "
      "structure), then the linear block (b_0 = 1): x(k) = -sum a_j x(k-j) + sum b_i w(k-nk-i), y = x.",
      detail::concat(
          detail::front_orders<Na_, Nb_, R_>(),
          std::array<OrderDescription, 2>{
              {{"np", 1, 32, Np_, "play operators of the input hysteresis (1..32)"}, detail::kIntegratorsOrder}}),
      {{detail::kFrontParameters[0],
        detail::kFrontParameters[1],
        {"f", ParameterShape::Vector, 0, "f_0..f_r, the input polynomial", nullptr, false, {1, 0, 0, -1}},
        {"thresholds",
         ParameterShape::Vector,
         1,
         "r_1..r_np, the plays' thresholds: strictly increasing, > 0 (structure, not estimated)",
         nullptr,
         false,
         {0, 0, 1, 0},
         true},
        {"g", ParameterShape::Vector, 1, "g_1..g_np, the plays' weights", nullptr, false, {1, 0, -1, 0}}}}};
  /// \copydoc ARX::Params
  using Params = Eigen::Matrix<Scalar, kNumParams, 1>;
  /// \copydoc ARX::VectorX
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  /// \copydoc ARX::Linear
  using Linear = LinearBlock<Scalar, Na_, Nb_>;
  using Plays = PlayOperators<Scalar, Np_>;  ///< the play operators' type
  /// The input hysteresis' type (input_block() returns it).
  using InputBlock = PrandtlIshlinskiiInput<Scalar, R_, Np_>;
  using Thresholds = typename Plays::Vector;  ///< the plays' thresholds (a vector, fixed size when np is)

  /// A model with the orders na >= 1, nb >= 0, nk >= 0, r >= 1 (degree of the input polynomial), np in
  /// 1..32 (play operators) and ni in 0..2, all parameters zero. Throws std::invalid_argument for an
  /// order out of range or one that differs from the compile-time order.
  /// The thresholds default to r_i = i / (np + 1) (in the units of u, from the operating point): set
  /// them where the hysteresis turns, or let identify() place them from the data.
  /// \param na poles of the linear block, >= 1
  /// \param nb B has nb + 1 coefficients, >= 0
  /// \param nk pure delay in samples, >= 0
  /// \param r degree of the input polynomial, >= 1
  /// \param np play operators, 1..32
  /// \param ni integrators (poles fixed at 1), 0..2
  PrandtlIshlinskiiHammerstein(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r, Eigen::Index np,
                               Eigen::Index ni = 0)
      : m_na(na), m_nb(nb), m_nk(nk), m_r(r), m_np(np), m_ni(ni) {
    detail::require_order(na, 1, "na");
    detail::require_order(nb, 0, "nb");
    detail::require_order(nk, 0, "nk");
    detail::require_order(r, 1, "r");
    detail::require_order(np, 1, "np (play operators)");  // none: the polynomial Hammerstein model
    detail::require(np <= 32, "np (play operators) must be <= 32");
    detail::require_integrators(ni);
    detail::require_matches_template(na, Na_, "na");
    detail::require_matches_template(nb, Nb_, "nb");
    detail::require_matches_template(r, R_, "r");
    detail::require_matches_template(np, Np_, "np");
    m_theta = Params::Zero(basis_size() + nb + na);
    m_thresholds = Plays::spread_thresholds(np);
  }

  /// \copydoc ARX::na
  Eigen::Index na() const noexcept { return m_na; }
  /// \copydoc ARX::nb
  Eigen::Index nb() const noexcept { return m_nb; }
  /// \copydoc ARX::nk
  Eigen::Index nk() const noexcept { return m_nk; }
  /// The order r: degree of the input polynomial (f_0..f_r)
  /// \return r, >= 1
  Eigen::Index r() const noexcept { return m_r; }
  /// The order np: play operators of the input hysteresis
  /// \return np, 1..32
  Eigen::Index np() const noexcept { return m_np; }
  /// \copydoc ARX::ni
  Eigen::Index ni() const noexcept { return m_ni; }
  /// The distinct input values the input polynomial needs (bonl::input_levels_needed()): r + 1, the
  /// points that fix a polynomial of degree r.
  /// \return r + 1
  Eigen::Index input_levels_needed() const noexcept { return m_r + 1; }
  /// \copydoc ARX::num_params
  Eigen::Index num_params() const noexcept { return m_theta.size(); }
  /// \copydoc ARX::orders
  std::array<Eigen::Index, 6> orders() const noexcept { return {m_na, m_nb, m_nk, m_r, m_np, m_ni}; }

  /// \copydoc ARX::theta
  const Params& theta() const noexcept { return m_theta; }
  /// \copydoc ARX::set_theta
  template <typename T>
  void set_theta(const Eigen::MatrixBase<T>& theta) {
    detail::assign_checked(m_theta, theta, "theta");
  }

  /// The input polynomial's coefficients f_0..f_r
  /// \return r + 1 values
  VectorX f() const { return m_theta.head(m_r + 1); }
  /// The input hysteresis w = f(u) + g . plays[u], its plays at rest: what the free run steps and
  /// the inverse for control (control/prandtl_ishlinskii_inverse.hpp) inverts.
  /// \return the block, a copy with this model's f, thresholds and g
  InputBlock input_block() const { return InputBlock(f(), m_thresholds, g()); }
  /// The plays' thresholds (structure, not estimated). \return r_1..r_np, strictly increasing, > 0,
  /// in the units of u
  const Thresholds& thresholds() const noexcept { return m_thresholds; }
  VectorX g() const { return m_theta.segment(m_r + 1, m_np); }  ///< the plays' weights g_1..g_np \return np values
  /// The numerator coefficients. \return b_0..b_nb; b_0 is 1 (the key-term normalisation)
  VectorX b() const { return detail::normalised_b<VectorX>(m_theta.segment(basis_size(), m_nb)); }
  /// \copydoc ARX::a
  VectorX a() const { return m_theta.segment(basis_size() + m_nb, m_na); }

  /// Sets f_0..f_r (r + 1 finite values, else std::invalid_argument).
  /// \param f f_0..f_r
  template <typename T>
  void set_f(const Eigen::MatrixBase<T>& f) {
    detail::assign_checked(m_theta.head(m_r + 1), f, "f");
  }
  /// The plays' thresholds: np of them, finite, > 0, strictly increasing (PlayOperators::require_valid).
  /// \param thresholds r_1..r_np, in the units of u
  template <typename T>
  void set_thresholds(const Eigen::MatrixBase<T>& thresholds) {
    Plays::require_valid(thresholds, m_np);
    m_thresholds = thresholds;
  }
  /// Sets g_1..g_np (np finite values, else std::invalid_argument).
  /// \param g g_1..g_np
  template <typename T>
  void set_g(const Eigen::MatrixBase<T>& g) {
    detail::assign_checked(m_theta.segment(m_r + 1, m_np), g, "g");
  }
  /// b_0..b_nb with b_0 = 1.
  /// \param b b_0..b_nb, nb + 1 finite values with b_0 = 1
  template <typename T>
  void set_b(const Eigen::MatrixBase<T>& b) {
    detail::assign_normalised_b(b, m_theta.segment(basis_size(), m_nb));
  }
  /// \copydoc ARX::set_a
  template <typename T>
  void set_a(const Eigen::MatrixBase<T>& a) {
    detail::assign_checked(m_theta.segment(basis_size() + m_nb, m_na), a, "a");
  }

  /// The parameter block kDescription.parameters[i]: b, a, f, thresholds, g.
  /// \copydetails ARX::parameter
  VectorX parameter(std::size_t i) const {
    switch (i) {
      case 0: return b();
      case 1: return a();
      case 2: return f();
      case 3: return m_thresholds;
      case 4: return g();
      default: detail::no_such_parameter(kName, i);
    }
  }
  /// \copydoc ARX::set_parameter
  void set_parameter(std::size_t i, const VectorX& value) {
    switch (i) {
      case 0: return set_b(value);
      case 1: return set_a(value);
      case 2: return set_f(value);
      case 3: return set_thresholds(value);
      case 4: return set_g(value);
      default: detail::no_such_parameter(kName, i);
    }
  }

  /// identify()'s start beside its recursive estimates: the structure with its thresholds placed by
  /// the data rule (PlayOperators::spread_thresholds over the records' inputs), estimated from there.
  /// prandtl_ishlinskii_starts belongs to the estimator, a layer above the models
  /// (estimator/play_thresholds.hpp, in <bonl/estimator.hpp>): found by argument-dependent lookup.
  /// \param structure the orders (and the structure's other settings) to start from
  /// \param records the identification records (deviations from the operating point, as identify() hands them)
  /// \return the starts, each with structure's orders
  template <class RecordList>
  static std::vector<PrandtlIshlinskiiHammerstein> identify_starts(const PrandtlIshlinskiiHammerstein& structure,
                                                                   const RecordList& records) {
    return prandtl_ishlinskii_starts(structure, records);
  }

  /// \copydoc ARX::try_simulate_deviations
  template <typename U>
  bool try_simulate_deviations(const Eigen::MatrixBase<U>& u, VectorX& y) const {
    InputBlock block = input_block();
    const detail::InputDeviationRange range = this->input_deviation_range();
    block.set_input_range(static_cast<Scalar>(range.low), static_cast<Scalar>(range.high));
    const auto input = [&block](Scalar v) { return block.step(v); };
    return detail::free_run(this->linear_block(), u, y, input, detail::Identity{});
  }
  /// Projects an estimate onto the model's valid set: every theta is valid.
  void constrain(Params& /*theta*/) const noexcept {}

 private:
  using Column = Eigen::Matrix<Scalar, kBasis, 1>;

  /// The input block's regressors over the lags the linear block needs: column i is basis(k-nk-i),
  /// i = 0..nb, zero before the record (the model at rest: no w there, not even f_0). The plays run
  /// on the delayed input u(k-nk), which is the same as delaying their outputs (they start at rest).
  /// Sized at construction; a push never allocates.
  class BasisLags {
   public:
    explicit BasisLags(const PrandtlIshlinskiiHammerstein& model)
        : m_plays(model.thresholds()), m_u(model.nk() + 1), m_r(model.r()), m_nk(model.nk()),
          m_columns(Eigen::Matrix<Scalar, kBasis, detail::poly_size(Nb_)>::Zero(model.basis_size(), model.nb() + 1)),
          m_column(Column::Zero(model.basis_size())) {}
    void reset() noexcept {
      m_plays.reset();
      m_u.clear();
      m_columns.setZero();
      m_k = 0;
    }
    /// Where the polynomial's basis continues linearly (linear_continuation.hpp).
    void set_input_range(const detail::InputDeviationRange& range) noexcept {
      m_low = static_cast<Scalar>(range.low);
      m_high = static_cast<Scalar>(range.high);
    }
    /// Pushes u(k): column 0 becomes basis(k-nk).
    void push(Scalar u) noexcept {
      m_u.push(u);
      m_column.setZero();
      if (m_k >= m_nk) {
        const Scalar v = m_u[m_nk];
        detail::continued_powers(v, m_r, m_low, m_high, m_column);
        m_column.tail(m_plays.size()) = m_plays.step(v);
      } else {
        ++m_k;  // only "before or after the record start" matters
      }
      for (Eigen::Index i = m_columns.cols() - 1; i > 0; --i) m_columns.col(i) = m_columns.col(i - 1);
      m_columns.col(0) = m_column;
    }
    auto column(Eigen::Index i) const noexcept { return m_columns.col(i); }
    Eigen::Index size() const noexcept { return m_columns.rows(); }

   private:
    Plays m_plays;
    detail::History<Scalar> m_u;  // u(k..k-nk): nk is a run-time order
    Eigen::Index m_r, m_nk;
    Eigen::Matrix<Scalar, kBasis, detail::poly_size(Nb_)> m_columns;
    Column m_column;
    Eigen::Index m_k = 0;
    Scalar m_low = -std::numeric_limits<Scalar>::infinity();
    Scalar m_high = std::numeric_limits<Scalar>::infinity();
  };

 public:
  /// Key-term form: y(k) = [basis(k-nk), w(k-nk-1..k-nk-nb), -x(k-1..k-na)] . theta. The past x are
  /// the measured y for the equation-error method (the model's prediction where y is NaN) and the
  /// model's own run for the paper's; the past w are recomputed with the step's theta (equation
  /// error) or kept as estimated when they entered (the paper's eq. 24). With integrators the target
  /// is y(k) less their part, known from the past x.
  class KeyTerms {
   public:
    /// \copydoc ARX::KeyTerms::KeyTerms
    /// \param method KeyTermMethod::EquationError or KeyTermMethod::Paper: where the past internal variables come from
    KeyTerms(const PrandtlIshlinskiiHammerstein& model, KeyTermMethod method)
        : m_basis(model), m_w(model.nb()), m_z(model.na()), m_integrators(model.ni()), m_method(method),
          m_nb(model.nb()), m_na(model.na()), m_phi(Params::Zero(model.num_params())) {}
    /// Where the input polynomial continues linearly (its input range as deviations from u0).
    /// \param range the range
    void set_input_range(const detail::InputDeviationRange& range) noexcept { m_basis.set_input_range(range); }
    /// \copydoc ARX::KeyTerms::reset
    void reset() noexcept {
      m_basis.reset();
      m_w.clear();
      m_z.clear();
      m_integrators.clear();
      m_pending = false;
    }
    /// \copydoc ARX::KeyTerms::step
    Regression<Scalar, Params> step(const Params& theta, Scalar u, Scalar y) noexcept {
      const Eigen::Index n = m_basis.size();
      const auto weights = theta.template head<kBasis>(n);
      if (m_pending) {  // the paper's method: the previous sample's x and w with the updated theta
        const Scalar x = m_phi.dot(theta) + m_integrators.carried();
        m_z.push(m_integrators.push(x));
        m_w.push(m_basis.column(0).dot(weights));
        m_pending = false;
      }
      m_basis.push(u);
      m_phi.template head<kBasis>(n) = m_basis.column(0);
      Scalar x = m_basis.column(0).dot(weights);
      const bool paper = m_method == KeyTermMethod::Paper;
      for (Eigen::Index i = 1; i <= m_nb; ++i) {
        const Scalar w = paper ? m_w[i - 1] : m_basis.column(i).dot(weights);
        m_phi[n + i - 1] = w;
        x += theta[n + i - 1] * w;
      }
      for (Eigen::Index j = 0; j < m_na; ++j) {
        m_phi[n + m_nb + j] = -m_z[j];
        x -= theta[n + m_nb + j] * m_z[j];
      }
      const Scalar carried = m_integrators.carried();
      x += carried;
      if (paper) {
        m_pending = true;
      } else {
        m_z.push(m_integrators.push(std::isnan(y) ? x : y));
      }
      return {m_phi, y - carried, x, x, true};
    }

   private:
    BasisLags m_basis;
    detail::History<Scalar> m_w;       // the paper's method: w(k-nk-1..k-nk-nb) as estimated
    detail::History<Scalar, Na_> m_z;  // x(k-1..k-na), differenced where there are integrators
    detail::IntegratorLags<Scalar> m_integrators;
    KeyTermMethod m_method;
    Eigen::Index m_nb, m_na;
    Params m_phi;
    bool m_pending = false;
  };

  /// The output-error method's view: one step of the free run with the current estimate and the
  /// sensitivity of x(k) to theta:
  ///   d x / d [f, g] = sum_{i=0..nb} b_i basis(k-nk-i),  d x / d b_i = w(k-nk-i),  d x / d a_j = -x(k-j),
  /// each filtered by 1 / A (SimulatedLags). The thresholds are not parameters, so the plays' values
  /// are exact for any estimate (w has no memory that depends on theta).
  class OutputErrorTerms {
   public:
    /// \copydoc ARX::OutputErrorTerms::OutputErrorTerms
    explicit OutputErrorTerms(const PrandtlIshlinskiiHammerstein& model)
        : m_basis(model), m_lags(model.na(), model.num_params(), model.ni()), m_nb(model.nb()), m_na(model.na()),
          m_psi(Params::Zero(model.num_params())), m_work(Eigen::Matrix<Scalar, Na_, 1>::Zero(model.na())) {}
    /// \copydoc ARX::OutputErrorTerms::reset
    void reset() noexcept {
      m_basis.reset();
      m_lags.reset();
      m_x = Scalar(0);
    }
    /// \copydoc ARX::OutputErrorTerms::step
    SimulationStep<Scalar, Params> step(const Params& theta, Scalar u) noexcept {
      const Eigen::Index n = m_basis.size();
      const auto weights = theta.template head<kBasis>(n);
      m_basis.push(u);
      auto d_weights = m_psi.template head<kBasis>(n);
      d_weights = m_basis.column(0);
      Scalar x = m_basis.column(0).dot(weights);
      for (Eigen::Index i = 1; i <= m_nb; ++i) {
        const Scalar b = theta[n + i - 1];
        const Scalar w = m_basis.column(i).dot(weights);
        d_weights += b * m_basis.column(i);
        m_psi[n + i - 1] = w;
        x += b * w;
      }
      x += m_lags.apply(theta.template segment<Na_>(n + m_nb, m_na), m_psi, n + m_nb);
      m_x = x;
      return {x, m_psi, x};
    }
    /// \copydoc ARX::OutputErrorTerms::accept()
    void accept() noexcept { m_lags.push(m_x, m_psi); }
    /// \copydoc ARX::OutputErrorTerms::correct
    void correct(const Params& delta) noexcept { m_lags.correct(delta); }
    /// \copydoc ARX::OutputErrorTerms::stable
    bool stable(const Params& theta, Scalar radius) noexcept {
      return detail::roots_inside(theta.template segment<Na_>(m_basis.size() + m_nb, m_na), radius, m_work);
    }

   private:
    BasisLags m_basis;
    detail::SimulatedLags<Scalar, Na_, kNumParams> m_lags;
    Eigen::Index m_nb, m_na;
    Params m_psi;
    Eigen::Matrix<Scalar, Na_, 1> m_work;  // for the stability test
    Scalar m_x = Scalar(0);
  };

 private:
  Eigen::Index basis_size() const noexcept { return m_r + 1 + m_np; }

  Params m_theta;
  Thresholds m_thresholds;
  Eigen::Index m_na, m_nb, m_nk, m_r, m_np, m_ni;
};

}  // namespace bonl
