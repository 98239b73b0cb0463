#pragma once
// Wiener-Hammerstein model: a linear block, a static nonlinearity, a second linear block
//   x1(k) = -sum_{j=1..na1} a1_j x1(k-j) + sum_{i=0..nb1} b1_i u(k-nk-i),
//   w(k)  = x1(k) + sum_{m=2..r} f_m x1(k)^m + sum_{j=1..nh} g_j h(x1(k) - knots_j),
//   y(k)  = -sum_{j=1..na2} a2_j y(k-j) + sum_{i=0..nb2} b2_i w(k-i),
// normalised to f_1 = 1 and b2_0 = 1 (the gain lives in b1; the whole delay in the first block, where
// a delay commutes with the static nonlinearity, so that b2_0 is not zero). The nonlinearity is a
// polynomial (nh = 0), piecewise linear (r = 1: slope 1 at 0, changing by g_j at the knots_j,
// for saturating circuits) or both; the hinges h are those of models/detail/hinge_terms.hpp. The knots
// are structure, not estimated: the model's own (the defaults, set_knots(), a model file), or placed
// from the data by the start from the best linear approximation.
// Parameters: b1_0..b1_nb1, a1_1..a1_na1, f_2..f_r, g_1..g_nh, b2_1..b2_nb2, a2_1..a2_na2.
// Key-term form, separating twice (w's key term x1, then y's key term w(k) with b2_0 = 1):
//   y(k) = [u lags] . b1 - [x1 lags] . a1 + sum_{m>=2} f_m x1(k)^m + sum_j g_j h(x1(k) - knots_j)
//          + [w lags] . b2 - [y lags] . a2,
// linear in theta once x1 and w are estimated. estimator/wiener_hammerstein_start.hpp starts
// identify() from the best linear approximation.

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "../blocks/linear_block.hpp"
#include "../blocks/output_polynomial.hpp"
#include "../detail/history.hpp"
#include "../detail/stability.hpp"
#include "../detail/validate.hpp"
#include "detail/hinge_terms.hpp"
#include "detail/linear_terms.hpp"
#include "detail/model_runs.hpp"
#include "detail/output_polynomial_terms.hpp"
#include "detail/simulated_lags.hpp"
#include "model_description.hpp"
#include "model_steps.hpp"

namespace bonl {

/// The Wiener-Hammerstein model: a linear block B1/A1 (with the delay), a static nonlinearity w =
/// x1 + sum_{m=2..r} f_m x1^m + sum_j g_j h(x1 - knots_j), a second linear block B2/A2 (with the
/// integrators), normalised to f_1 = 1 and b2_0 = 1. Parameters: b1_0..b1_nb1, a1_1..a1_na1,
/// f_2..f_r, g_1..g_nh, b2_1..b2_nb2, a2_1..a2_na2; the knots are structure. The file's header says
/// more.
template <typename Scalar_ = double, int Na1_ = Eigen::Dynamic, int Nb1_ = Eigen::Dynamic, int R_ = Eigen::Dynamic,
          int Nh_ = Eigen::Dynamic, int Na2_ = Eigen::Dynamic, int Nb2_ = Eigen::Dynamic>
class WienerHammerstein : public detail::ModelRuns<WienerHammerstein<Scalar_, Na1_, Nb1_, R_, Nh_, Na2_, Nb2_>> {
  static constexpr int kFirstParams = detail::add_sizes(detail::poly_size(Nb1_), Na1_);  // b1, a1
  static constexpr int kFrontParams = detail::add_sizes(
      detail::add_sizes(kFirstParams, R_ == Eigen::Dynamic ? Eigen::Dynamic : R_ - 1), Nh_);  // and f, g

 public:
  /// \copydoc ARX::Scalar
  using Scalar = Scalar_;
  /// \copydoc ARX::kNumParams
  static constexpr int kNumParams = detail::add_sizes(kFrontParams, detail::add_sizes(Nb2_, Na2_));
  /// The Wiener-Hammerstein model has unmeasured internal variables, x1 and w.
  static constexpr bool kHasInternalVariables = true;
  /// \copydoc ARX::kName
  static constexpr const char* kName = "WienerHammerstein";
  /// \copydoc ARX::kDescription
  static constexpr ModelDescription<8, 7> kDescription{
      kName,
      "Wiener-Hammerstein model: the linear block x1 = z^-nk B1/A1 u, then the static nonlinearity "
      "w = sum_{m=1..r} f_m x1^m + sum_{j=1..nh} g_j h(x1 - knots_j) (f_1 = 1; h the hinge, zero between 0 "
      "and its knot), then the linear block y = B2/A2 w (b2_0 = 1).",
      {{{"na1", 1, detail::kMaxOrder, Na1_, "poles of the first linear block (na1 >= 1)"},
        {"nb1", 0, detail::kMaxOrder, Nb1_, "B1 has nb1 + 1 coefficients b1_0..b1_nb1"},
        {"nk", 0, detail::kMaxOrder, Eigen::Dynamic, "pure delay in samples (in the first block)"},
        {"r", 1, 32, R_, "degree of the static polynomial (1..32; 1: no polynomial terms)"},
        {"nh", 0, 32, Nh_, "hinges of the static nonlinearity, knots where its slope changes (0..32; 0: none)"},
        {"na2", 1, detail::kMaxOrder, Na2_, "poles of the second linear block (na2 >= 1)"},
        {"nb2", 0, detail::kMaxOrder, Nb2_, "B2 has nb2 + 1 coefficients b2_0..b2_nb2, b2_0 = 1"},
        detail::kIntegratorsOrder}},
      {{{"b1",
         ParameterShape::Vector,
         0,
         "b1_0..b1_nb1 (free: f_1 = b2_0 = 1 fix the other gains)",
         nullptr,
         false,
         {1, 0, -1, 0}},
        {"a1", ParameterShape::Vector, 1, "a1_1..a1_na1", nullptr, false, {}},
        {"f",
         ParameterShape::Vector,
         1,
         "f_1..f_r with f_1 = 1",
         "the Wiener-Hammerstein model is normalised so that f_1 = 1",
         false,
         {1, -1, 0, 0}},
        {"knots",
         ParameterShape::Vector,
         1,
         "knots_1..knots_nh, where the slope changes: strictly increasing, none at 0 (structure, not estimated)",
         nullptr,
         false,
         {1, 0, 0, 0},
         true},
        {"g", ParameterShape::Vector, 1, "g_1..g_nh, the change of slope outward of each knot", nullptr, false, {}},
        {"b2",
         ParameterShape::Vector,
         0,
         "b2_0..b2_nb2 with b2_0 = 1",
         "the Wiener-Hammerstein model is normalised so that b2_0 = 1",
         false,
         {}},
        {"a2", ParameterShape::Vector, 1, "a2_1..a2_na2", nullptr, false, {}}}}};
  /// \copydoc ARX::Params
  using Params = Eigen::Matrix<Scalar, kNumParams, 1>;
  /// \copydoc ARX::VectorX
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  using First = LinearBlock<Scalar, Na1_, Nb1_>;   ///< the first linear block's type (first_block() returns it)
  using Second = LinearBlock<Scalar, Na2_, Nb2_>;  ///< the second linear block's type (second_block() returns it)
  using Middle = OutputPolynomial<Scalar, R_>;  ///< the static nonlinearity's polynomial part, as an output polynomial
  /// Both linear blocks' denominators: what pole_radius() and the refinement's stabilisation look at.
  static constexpr std::size_t kLinearBlocks = 2;

  using Knots =
      typename detail::HingeTerms<Scalar, Nh_>::Knots;  ///< the hinges' knots (a vector, fixed size when nh is)

  /// A model with the given orders, all parameters zero but f_1 = 1 and b2_0 = 1. The knots default to
  /// -floor(nh/2)..-1, 1..ceil(nh/2) (in the units of x1, which are y's): set them where the slope
  /// changes, or let identify() place them from the data. Throws std::invalid_argument for an order
  /// out of range or one that differs from the compile-time order.
  /// \param na1 poles of the first linear block, >= 1
  /// \param nb1 B1 has nb1 + 1 coefficients, >= 0
  /// \param nk pure delay in samples, >= 0
  /// \param r degree of the static polynomial (f_1 = 1 .. f_r), 1..32
  /// \param nh hinges of the static nonlinearity, 0..32
  /// \param na2 poles of the second linear block, >= 1
  /// \param nb2 B2 has nb2 + 1 coefficients, b2_0 = 1, >= 0
  /// \param ni integrators of the second block (poles fixed at 1), 0..2
  WienerHammerstein(Eigen::Index na1, Eigen::Index nb1, Eigen::Index nk, Eigen::Index r, Eigen::Index nh,
                    Eigen::Index na2, Eigen::Index nb2, Eigen::Index ni = 0)
      : m_na1(na1), m_nb1(nb1), m_nk(nk), m_r(r), m_nh(nh), m_na2(na2), m_nb2(nb2), m_ni(ni) {
    detail::require_order(na1, 1, "na1");
    detail::require_order(nb1, 0, "nb1");
    detail::require_order(nk, 0, "nk");
    detail::require_order(r, 1, "r (static polynomial degree)");
    detail::require(r <= 32, "r (static polynomial degree) must be <= 32");
    detail::require_order(nh, 0, "nh (hinges)");
    detail::require(nh <= 32, "nh (hinges) must be <= 32");
    detail::require_order(na2, 1, "na2");
    detail::require_order(nb2, 0, "nb2");
    detail::require_integrators(ni);
    detail::require_matches_template(na1, Na1_, "na1");
    detail::require_matches_template(nb1, Nb1_, "nb1");
    detail::require_matches_template(r, R_, "r");
    detail::require_matches_template(nh, Nh_, "nh");
    detail::require_matches_template(na2, Na2_, "na2");
    detail::require_matches_template(nb2, Nb2_, "nb2");
    m_theta = Params::Zero(nb1 + 1 + na1 + r - 1 + nh + nb2 + na2);
    m_knots = detail::HingeTerms<Scalar, Nh_>::default_knots(nh);
  }

  /// The order na1: poles of the first linear block
  /// \return na1, >= 1
  Eigen::Index na1() const noexcept { return m_na1; }
  /// The order nb1: B1 has nb1 + 1 coefficients b1_0..b1_nb1
  /// \return nb1, >= 0
  Eigen::Index nb1() const noexcept { return m_nb1; }
  /// \copydoc ARX::nk
  Eigen::Index nk() const noexcept { return m_nk; }
  /// The order r: degree of the static polynomial (f_1 = 1 .. f_r)
  /// \return r, 1..32
  Eigen::Index r() const noexcept { return m_r; }
  /// The order nh: hinges of the static nonlinearity. \return nh, 0..32
  Eigen::Index nh() const noexcept { return m_nh; }
  /// The order na2: poles of the second linear block. \return na2, >= 1
  Eigen::Index na2() const noexcept { return m_na2; }
  /// The order nb2: B2 has nb2 + 1 coefficients, b2_0 = 1
  /// \return nb2, >= 0
  Eigen::Index nb2() const noexcept { return m_nb2; }
  /// The integrators of the second block, the one at the output. \return ni, 0..2
  Eigen::Index ni() const noexcept { return m_ni; }
  /// \copydoc ARX::num_params
  Eigen::Index num_params() const noexcept { return m_theta.size(); }
  /// \copydoc ARX::orders
  std::array<Eigen::Index, 8> orders() const noexcept { return {m_na1, m_nb1, m_nk, m_r, m_nh, m_na2, m_nb2, m_ni}; }

  /// \copydoc ARX::theta
  const Params& theta() const noexcept { return m_theta; }
  /// \copydoc ARX::set_theta
  template <typename T>
  void set_theta(const Eigen::MatrixBase<T>& theta) {
    detail::assign_checked(m_theta, theta, "theta");
  }

  /// The first block's numerator b1_0..b1_nb1 (the gain lives here)
  /// \return nb1 + 1 values
  VectorX b1() const { return m_theta.head(m_nb1 + 1); }
  /// The first block's denominator a1_1..a1_na1
  /// \return na1 values
  VectorX a1() const { return m_theta.segment(first_a(), m_na1); }
  /// The static polynomial's coefficients. \return f_1..f_r with f_1 = 1
  VectorX f() const { return with_leading_one(m_theta.segment(first_f(), m_r - 1)); }
  /// The hinges' knots. \return knots_1..knots_nh, strictly increasing, none at 0, in the units of x1
  const Knots& knots() const noexcept { return m_knots; }
  VectorX g() const { return m_theta.segment(first_g(), m_nh); }  ///< the hinges' weights g_1..g_nh \return nh values
  /// The second block's numerator. \return b2_0..b2_nb2 with b2_0 = 1
  VectorX b2() const { return with_leading_one(m_theta.segment(first_b2(), m_nb2)); }
  /// The second block's denominator a2_1..a2_na2
  /// \return na2 values
  VectorX a2() const { return m_theta.segment(first_a2(), m_na2); }
  /// Sets b1_0..b1_nb1 (nb1 + 1 finite values, else std::invalid_argument).
  /// \param b1 b1_0..b1_nb1
  template <typename T>
  void set_b1(const Eigen::MatrixBase<T>& b1) {
    detail::assign_checked(m_theta.head(m_nb1 + 1), b1, "b1");
  }
  /// Sets a1_1..a1_na1 (na1 finite values, else std::invalid_argument).
  /// \param a1 a1_1..a1_na1
  template <typename T>
  void set_a1(const Eigen::MatrixBase<T>& a1) {
    detail::assign_checked(m_theta.segment(first_a(), m_na1), a1, "a1");
  }
  /// Sets f_1..f_r: r finite values with f_1 = 1 (the normalisation), else std::invalid_argument.
  /// \param f f_1..f_r
  template <typename T>
  void set_f(const Eigen::MatrixBase<T>& f) {
    set_normalised(f, m_r, first_f(), "f", "f[0] (f_1)", 2);
  }
  /// Where the slope changes: strictly increasing, none at 0 (the slope at 0 is f_1 = 1).
  /// \param knots knots_1..knots_nh, in the units of x1
  template <typename T>
  void set_knots(const Eigen::MatrixBase<T>& knots) {
    detail::HingeTerms<Scalar, Nh_>::require_valid(knots, m_nh, "the slope at 0 is f_1 = 1");
    m_knots = knots;
  }
  /// Sets the hinges' weights g_1..g_nh (nh finite values, else std::invalid_argument).
  /// \param g g_1..g_nh
  template <typename T>
  void set_g(const Eigen::MatrixBase<T>& g) {
    detail::assign_checked(m_theta.segment(first_g(), m_nh), g, "g");
  }
  /// Sets b2_0..b2_nb2: nb2 + 1 finite values with b2_0 = 1 (the normalisation), else
  /// std::invalid_argument.
  /// \param b2 b2_0..b2_nb2
  template <typename T>
  void set_b2(const Eigen::MatrixBase<T>& b2) {
    set_normalised(b2, m_nb2 + 1, first_b2(), "b2", "b2[0] (b2_0)", 5);
  }
  /// Sets a2_1..a2_na2 (na2 finite values, else std::invalid_argument).
  /// \param a2 a2_1..a2_na2
  template <typename T>
  void set_a2(const Eigen::MatrixBase<T>& a2) {
    detail::assign_checked(m_theta.segment(first_a2(), m_na2), a2, "a2");
  }

  /// The parameter block kDescription.parameters[i]: b1, a1, f, knots, g, b2, a2.
  /// \copydetails ARX::parameter
  VectorX parameter(std::size_t i) const {
    switch (i) {
      case 0: return b1();
      case 1: return a1();
      case 2: return f();
      case 3: return m_knots;
      case 4: return g();
      case 5: return b2();
      case 6: return a2();
      default: detail::no_such_parameter(kName, i);
    }
  }
  /// \copydoc ARX::set_parameter
  void set_parameter(std::size_t i, const VectorX& value) {
    switch (i) {
      case 0: return set_b1(value);
      case 1: return set_a1(value);
      case 2: return set_f(value);
      case 3: return set_knots(value);
      case 4: return set_g(value);
      case 5: return set_b2(value);
      case 6: return set_a2(value);
      default: detail::no_such_parameter(kName, i);
    }
  }

  /// identify()'s starts beside its recursive estimates: the best splits of the records' best linear
  /// approximation. wiener_hammerstein_starts belongs to the estimator, a layer above the models
  /// (estimator/wiener_hammerstein_start.hpp, in <bonl/estimator.hpp>): found by argument-dependent
  /// lookup where identify() calls this.
  /// \param structure the orders (and the structure's other settings) to start from
  /// \param records the identification records (deviations from the operating point, as identify() hands them)
  /// \return the starts, each with structure's orders and knots
  template <class RecordList>
  static std::vector<WienerHammerstein> identify_starts(const WienerHammerstein& structure, const RecordList& records) {
    return wiener_hammerstein_starts(structure, records);
  }

  /// The first linear block B1/A1, with the delay, at rest.
  /// \return a copy, with this model's b1, a1 and nk
  First first_block() const {
    First block(m_na1, m_nb1, m_nk);
    block.set_a(a1());
    block.set_b(b1());
    return block;
  }
  /// The second linear block B2/A2, with the integrators, at rest.
  /// \return a copy, with this model's b2, a2 and ni
  Second second_block() const {
    Second block(m_na2, m_nb2, 0, m_ni);
    block.set_a(a2());
    block.set_b(b2());
    return block;
  }
  /// The denominator of linear block i (0: a1, 1: a2), for the stabilisation that works on each block.
  /// \param i 0 for the first block, else the second
  /// \return a1_1..a1_na1 or a2_1..a2_na2
  VectorX denominator(std::size_t i) const { return i == 0 ? a1() : a2(); }
  /// Sets the denominator of linear block i (0: a1, else a2); throws std::invalid_argument for a wrong
  /// length or a non-finite entry.
  /// \param i 0 for the first block, else the second
  /// \param a the block's na1 or na2 denominator coefficients
  template <typename T>
  void set_denominator(std::size_t i, const Eigen::MatrixBase<T>& a) {
    if (i == 0) return set_a1(a);
    set_a2(a);
  }

  /// \copydoc ARX::try_simulate_deviations
  template <typename U>
  bool try_simulate_deviations(const Eigen::MatrixBase<U>& u, VectorX& y) const {
    First first = first_block();
    Second second = second_block();
    const VectorX fv = f();
    const detail::HingeTerms<Scalar, Nh_> hinges(m_knots, first_g());
    y.resize(u.size());
    for (Eigen::Index k = 0; k < u.size(); ++k) {
      const Scalar x1 = first.step(u[k]);
      y[k] = second.step(hinges.add_output(m_theta, x1, Middle::evaluate(fv, x1)));
      if (!std::isfinite(y[k])) return false;
    }
    return true;
  }
  /// Projects an estimate onto the model's valid set: every theta is valid.
  void constrain(Params& /*theta*/) const noexcept {}

 private:
  /// The static nonlinearity on theta: the polynomial's terms and the hinges' together.
  class MiddleTerms {
   public:
    explicit MiddleTerms(const WienerHammerstein& model)
        : m_polynomial(detail::OutputPolynomialTerms<Scalar>::starting_at(model.r(), model.first_f())),
          m_hinges(model.knots(), model.first_g()) {}
    Scalar output(const Params& theta, Scalar x) const noexcept {
      return m_hinges.add_output(theta, x, m_polynomial.output(theta, x));
    }
    template <typename Phi>
    void regress(Scalar x, Phi& phi) const noexcept {
      m_polynomial.regress(x, phi);
      m_hinges.regress(x, phi);
    }
    template <typename Psi>
    Scalar output_and_sensitivity(const Params& theta, Scalar x, Psi& psi, Scalar& slope) const noexcept {
      const Scalar w = m_polynomial.output_and_sensitivity(theta, x, psi, slope);
      m_hinges.regress(x, psi);
      slope += m_hinges.slope(theta, x);
      return m_hinges.add_output(theta, x, w);
    }
    /// The x that gives w (Newton from x_model, as the polynomial alone is inverted; a piecewise-linear
    /// part is solved exactly once Newton is on the root's piece); x_model where the slope vanishes or
    /// Newton does not settle in 30 steps.
    Scalar invert(const Params& theta, Scalar w, Scalar x_model) const noexcept {
      if (m_hinges.size() == 0) return m_polynomial.invert(theta, w, x_model);
      const Scalar scale = Scalar(1) + std::abs(w);
      Scalar x = x_model;
      for (int iteration = 0; iteration < 30; ++iteration) {
        const Scalar slope = m_polynomial.slope(theta, x) + m_hinges.slope(theta, x);
        if (!(slope > Scalar(1e-6))) return x_model;
        const Scalar step = (output(theta, x) - w) / slope;
        x -= step;
        if (!std::isfinite(x)) return x_model;
        if (std::abs(step) <= Scalar(64) * Eigen::NumTraits<Scalar>::epsilon() * scale) return x;
      }
      return x_model;
    }

   private:
    detail::OutputPolynomialTerms<Scalar> m_polynomial;
    detail::HingeTerms<Scalar, Nh_> m_hinges;
  };

 public:
  /// Key-term form: regressor [u(k-nk..k-nk-nb1), -x1(k-1..k-na1), x1(k)^2..x1(k)^r,
  /// h(x1(k) - knots_1..nh), w(k-1..k-nb2), -y(k-1..k-na2)], target y(k), with x1(k) the a-priori
  /// estimate [u lags, -x1 lags] . [b1, a1] and w(k) the static nonlinearity of it. The past x1 and
  /// w are the model's own in both methods: mapping the measured y back to w would run the inverse of
  /// B2, whose zeros may lie on the unit circle (a notch filter's do). The equation-error method
  /// stores them with the step's theta, the paper's a posteriori at the next step (eq. 24); the y
  /// lags are measured (the model's prediction where y is NaN). predict() runs the equation-error form.
  /// With integrators (in the second block) the y lags are differenced and the target is y(k) less
  /// their part.
  class KeyTerms {
   public:
    /// \copydoc ARX::KeyTerms::KeyTerms
    /// \param method KeyTermMethod::EquationError or KeyTermMethod::Paper: where the past internal variables come from
    KeyTerms(const WienerHammerstein& model, KeyTermMethod method)
        : m_first(model.na1(), model.nb1(), model.nk()), m_middle(model), m_w(model.nb2()), m_y(model.na2()),
          m_integrators(model.ni()), m_method(method), m_first_size(model.nb1() + 1 + model.na1()),
          m_second(model.first_b2()), m_nb2(model.nb2()), m_na2(model.na2()), m_phi(Params::Zero(model.num_params())) {}
    /// \copydoc ARX::KeyTerms::reset
    void reset() noexcept {
      m_first.reset();
      m_w.clear();
      m_y.clear();
      m_integrators.clear();
      m_pending = false;
    }
    /// \copydoc ARX::KeyTerms::step
    Regression<Scalar, Params> step(const Params& theta, Scalar u, Scalar y) noexcept {
      if (m_pending) store(theta, first_part(theta));
      m_first.begin(u, m_phi);
      const Scalar x1 = first_part(theta);
      const Scalar w = m_middle.output(theta, x1);
      m_middle.regress(x1, m_phi);
      for (Eigen::Index i = 0; i < m_nb2; ++i) m_phi[m_second + i] = m_w[i];
      for (Eigen::Index j = 0; j < m_na2; ++j) m_phi[m_second + m_nb2 + j] = -m_y[j];
      const Eigen::Index n2 = m_nb2 + m_na2;
      const Scalar carried = m_integrators.carried();
      const Scalar prediction = w + m_phi.tail(n2).dot(theta.tail(n2)) + carried;
      if (m_method == KeyTermMethod::EquationError) {
        m_first.end(std::isnan(y) ? x1 : measured_x1(theta, y, x1, prediction - w));
        m_w.push(w);
      } else {
        m_pending = true;
      }
      m_y.push(m_integrators.push(std::isnan(y) ? prediction : y));
      return {m_phi, y - carried, prediction, x1, true};
    }

   private:
    /// x1(k) = [u lags, -x1 lags] . [b1, a1], from the regressor's first part.
    Scalar first_part(const Params& theta) const noexcept {
      return m_phi.template head<kFirstParams>(m_first_size).dot(theta.template head<kFirstParams>(m_first_size));
    }
    /// The x1(k) the measured y(k) says: w(k) = y(k) - (the second block's part from the past,
    /// `past` = [w lags] . b2 - [y lags] . a2, the model's own w lags), mapped back through the
    /// static nonlinearity (Newton from the model's x1, the branch nearest it; where it cannot be
    /// inverted there, the model's x1). One step of B2's inverse only: the past w stay the model's,
    /// so B2's zeros, which may lie on the unit circle, are never inverted.
    Scalar measured_x1(const Params& theta, Scalar y, Scalar x1_model, Scalar past) const noexcept {
      return m_middle.invert(theta, y - past, x1_model);
    }
    /// Stores x1 and its w as the newest lags.
    void store(const Params& theta, Scalar x1) noexcept {
      m_first.end(x1);
      m_w.push(m_middle.output(theta, x1));
      m_pending = false;
    }

    detail::LinearKeyTerms<Scalar, Na1_> m_first;
    MiddleTerms m_middle;
    detail::History<Scalar> m_w;  // w(k-1..k-nb2)
    detail::History<Scalar> m_y;  // y(k-1..k-na2), differenced where there are integrators
    detail::IntegratorLags<Scalar> m_integrators;
    KeyTermMethod m_method;
    Eigen::Index m_first_size, m_second, m_nb2, m_na2;  // m_second: the index of b2_1
    Params m_phi;
    bool m_pending = false;  // the paper's method: the previous sample's x1 and w wait to be stored
  };

  /// The output-error method's view: one step of the free run with its sensitivities. The first
  /// block's as the Wiener model's (detail::LinearOutputError); dw/d[b1, a1] = w'(x1) dx1/d[b1, a1],
  /// dw/df_m = x1^m, dw/dg_j = h(x1 - knots_j); and through the second block
  ///   dy(k) = dw(k) + sum_i b2_i dw(k-i) + [w(k-i) at b2_i] + [-y(k-j) at a2_j] - sum_j a2_j dy(k-j),
  /// so the past w and their sensitivities are kept (nb2 of them) as the past y and theirs (SimulatedLags).
  class OutputErrorTerms {
   public:
    using FirstSensitivity =
        Eigen::Matrix<Scalar, kFirstParams, 1>;  ///< d x1(k) / d[b1, a1], the first block's part of the sensitivity
    using FrontSensitivity =
        Eigen::Matrix<Scalar, kFrontParams, 1>;  ///< d w(k) / d[b1, a1, f, g], the front's part of the sensitivity

    /// \copydoc ARX::OutputErrorTerms::OutputErrorTerms
    explicit OutputErrorTerms(const WienerHammerstein& model)
        : m_first(model.na1(), model.nb1(), model.nk(), model.nb1() + 1 + model.na1()), m_middle(model),
          m_y(model.na2(), model.num_params(), model.ni()), m_nb2(model.nb2()), m_na2(model.na2()),
          m_first_size(model.nb1() + 1 + model.na1()), m_front_size(m_first_size + model.r() - 1 + model.nh()),
          m_dx(FirstSensitivity::Zero(m_first_size)), m_dw(FrontSensitivity::Zero(m_front_size)),
          m_w_lags(Eigen::Matrix<Scalar, Nb2_, 1>::Zero(model.nb2())),
          m_dw_lags(Eigen::Matrix<Scalar, kFrontParams, Nb2_>::Zero(m_front_size, model.nb2())),
          m_work(Eigen::Matrix<Scalar, Na2_, 1>::Zero(model.na2())), m_psi(Params::Zero(model.num_params())) {}
    /// \copydoc ARX::OutputErrorTerms::reset
    void reset() noexcept {
      m_first.reset();
      m_y.reset();
      m_dx.setZero();
      m_w_lags.setZero();
      m_dw_lags.setZero();
    }
    /// \copydoc ARX::OutputErrorTerms::step
    SimulationStep<Scalar, Params> step(const Params& theta, Scalar u) noexcept {
      const Scalar x1 = m_first.step(theta, u, m_dx);
      Scalar slope;
      const Scalar w = m_middle.output_and_sensitivity(theta, x1, m_dw, slope);  // dw/df_m = x1^m, dw/dg_j = h_j
      m_dw.head(m_first_size) = slope * m_dx;
      const Eigen::Index second = m_front_size;
      auto front = m_psi.head(m_front_size);
      front = m_dw;
      Scalar y = w;
      for (Eigen::Index i = 0; i < m_nb2; ++i) {
        const Scalar b2 = theta[second + i];
        front += b2 * m_dw_lags.col(i);
        m_psi[second + i] = m_w_lags[i];
        y += b2 * m_w_lags[i];
      }
      y += m_y.apply(theta.segment(second + m_nb2, m_na2), m_psi, second + m_nb2);
      m_w = w;
      m_output = y;
      return {y, m_psi, x1};
    }
    /// \copydoc ARX::OutputErrorTerms::accept()
    void accept() noexcept {
      m_first.commit(m_dx);
      for (Eigen::Index i = m_nb2 - 1; i > 0; --i) {
        m_w_lags[i] = m_w_lags[i - 1];
        m_dw_lags.col(i) = m_dw_lags.col(i - 1);
      }
      if (m_nb2 > 0) {
        m_w_lags[0] = m_w;
        m_dw_lags.col(0) = m_dw;
      }
      m_y.push(m_output, m_psi);
    }
    /// \copydoc ARX::OutputErrorTerms::correct
    void correct(const Params& delta) noexcept {
      m_first.correct(delta.template head<kFirstParams>(m_first_size));
      for (Eigen::Index i = 0; i < m_nb2; ++i) m_w_lags[i] += m_dw_lags.col(i).dot(delta.head(m_front_size));
      m_y.correct(delta);
    }
    /// \copydoc ARX::OutputErrorTerms::stable
    bool stable(const Params& theta, Scalar radius) noexcept {
      return m_first.stable(theta, radius) &&
             detail::roots_inside(theta.segment(m_front_size + m_nb2, m_na2), radius, m_work);
    }

   private:
    detail::LinearOutputError<Scalar, Na1_, kFirstParams> m_first;
    MiddleTerms m_middle;
    detail::SimulatedLags<Scalar, Na2_, kNumParams> m_y;
    Eigen::Index m_nb2, m_na2, m_first_size, m_front_size;
    FirstSensitivity m_dx;                                // d x1(k) / d [b1, a1]
    FrontSensitivity m_dw;                                // d w(k) / d [b1, a1, f]
    Eigen::Matrix<Scalar, Nb2_, 1> m_w_lags;              // w(k-1..k-nb2)
    Eigen::Matrix<Scalar, kFrontParams, Nb2_> m_dw_lags;  // their sensitivities, one column each
    Eigen::Matrix<Scalar, Na2_, 1> m_work;                // for the stability test
    Params m_psi;
    Scalar m_w = Scalar(0), m_output = Scalar(0);
  };

 private:
  Eigen::Index first_a() const noexcept { return m_nb1 + 1; }
  Eigen::Index first_f() const noexcept { return m_nb1 + 1 + m_na1; }
  Eigen::Index first_g() const noexcept { return first_f() + m_r - 1; }
  Eigen::Index first_b2() const noexcept { return first_g() + m_nh; }
  Eigen::Index first_a2() const noexcept { return first_b2() + m_nb2; }

  template <typename T>
  static VectorX with_leading_one(const Eigen::MatrixBase<T>& tail) {
    VectorX out(tail.size() + 1);
    out[0] = Scalar(1);
    out.tail(tail.size()) = tail;
    return out;
  }
  /// A block whose first entry is fixed to 1 (f, b2): checked, then its other entries into theta.
  template <typename T>
  void set_normalised(const Eigen::MatrixBase<T>& value, Eigen::Index size, Eigen::Index first, const char* name,
                      const char* first_name, std::size_t block) {
    detail::require_size(value, size, name);
    detail::require_finite(value, name);
    detail::require(value[0] == 1,
                    std::string(first_name) + " must be 1: " + kDescription.parameters[block].normalised);
    m_theta.segment(first, size - 1) = value.tail(size - 1);
  }

  Params m_theta;
  Knots m_knots;
  Eigen::Index m_na1, m_nb1, m_nk, m_r, m_nh, m_na2, m_nb2, m_ni;
};

}  // namespace bonl
