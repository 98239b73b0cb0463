#pragma once
// Nonlinear-feedback (Lur'e) model: a linear block driven by the input and by a static nonlinearity of
// the output fed back through a second, delayed linear block over the same denominator:
//   y(k) = -sum_{j=1..na} a_j y(k-j) + sum_{i=0..nb} b_i u(k-nk-i) + sum_{j=1..nd} d_j f(s(k-j)),
//   f(s) = sum_{m=2..r} f_m s^m + sum_{l=1..nh} g_l h(s - knots_l),    d_1 = 1,
// where s is the output (nv = 0: a stiffening spring, as in a Duffing oscillator) or its first
// difference s(k) = y(k) - y(k-1) (nv = 1: a velocity, where friction lives). The feedback starts one
// sample back, so there is no algebraic loop. f has no constant or linear term (the linear feedback
// is the denominator's) and is zero with zero slope at s = 0, so the model's linearisation at rest is
// B / A, whose poles the estimator keeps inside the stability radius. The hinges h are those of the
// Wiener-Hammerstein model (models/detail/hinge_terms.hpp): with them f can be piecewise linear, a
// saturation or a friction curve; their knots are structure, not estimated. d_1 = 1 fixes the scale
// between D and f.
// Hysteresis in the loop (a bolted joint's restoring force, a cylinder's friction): f may also hold
// a Prandtl-Ishlinskii operator of s, sum_{i=1..np} w_i play_{r_i}[s] (blocks/play_operators.hpp),
// whose plays remember the past of s; their thresholds are structure as the knots are, their weights
// w_i linear parameters. Then x(k-j) = f(s)(k-j) is the operator's value at k-j, and the plays are
// part of the simulated state, run from rest (or over a measured past) with s.
// Parameters: b_0..b_nb, a_1..a_na, f_2..f_r, g_1..g_nh, w_1..w_np, d_2..d_nd.
// Key-term form (f(s(k-1)) separated from D, whose first coefficient is 1):
//   y(k) = [u lags] . b - [y lags] . a + sum_m f_m s(k-1)^m + sum_l g_l h(s(k-1) - knots_l)
//          + sum_{j=2..nd} d_j x(k-j),   x(k-j) = f(s(k-j)),
// linear in theta once the internal variables x(k-j) are computed; they are the nonlinearity of the
// measured output's past, with the step's theta, for both key-term methods. A free run whose feedback
// makes it leave the finite numbers is reported as every model's is (try_simulate() false).
// With ni integrators the denominator is A (1 - q^-1)^ni (detail/integrators.hpp): with nv = 1 and
// ni = 1 that is a drive's position integrating a velocity that friction acts on.

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "../blocks/linear_block.hpp"
#include "../blocks/play_operators.hpp"
#include "../detail/history.hpp"
#include "../detail/integrators.hpp"
#include "../detail/stability.hpp"
#include "../detail/validate.hpp"
#include "detail/hinge_terms.hpp"
#include "detail/model_runs.hpp"
#include "model_description.hpp"
#include "model_steps.hpp"

namespace bonl {

/// The nonlinear-feedback (Lur'e) model: a linear block driven by the input and by a static
/// nonlinearity f of the output (nv = 0) or of its first difference (nv = 1), fed back through a
/// second, delayed linear block D over the same denominator: y(k) = -sum a_j y(k-j) + sum b_i
/// u(k-nk-i) + sum_{j=1..nd} d_j f(s(k-j)), d_1 = 1, with f a polynomial from s^2 to s^r, nh hinges
/// and np play operators (hysteresis). Parameters: b_0..b_nb, a_1..a_na, f_2..f_r, g_1..g_nh,
/// w_1..w_np, d_2..d_nd; the knots and thresholds are structure. The file's header says more.
template <typename Scalar_ = double, int Na_ = Eigen::Dynamic, int Nb_ = Eigen::Dynamic, int R_ = Eigen::Dynamic,
          int Nh_ = Eigen::Dynamic, int Nd_ = Eigen::Dynamic, int Np_ = Eigen::Dynamic>
class NonlinearFeedback : public detail::ModelRuns<NonlinearFeedback<Scalar_, Na_, Nb_, R_, Nh_, Nd_, Np_>> {
  static constexpr int kLinearParams = detail::add_sizes(detail::poly_size(Nb_), Na_);  // b, a
  static constexpr int kFeedbackParams =
      detail::add_sizes(detail::add_sizes(R_ == Eigen::Dynamic ? Eigen::Dynamic : R_ - 1, Nh_), Np_);  // f, g, w

 public:
  /// \copydoc ARX::Scalar
  using Scalar = Scalar_;
  /// \copydoc ARX::kNumParams
  static constexpr int kNumParams = detail::add_sizes(detail::add_sizes(kLinearParams, kFeedbackParams),
                                                      Nd_ == Eigen::Dynamic ? Eigen::Dynamic : Nd_ - 1);
  /// The nonlinear-feedback model has unmeasured internal variables, the fed-back x(k-j) = f(s(k-j)).
  static constexpr bool kHasInternalVariables = true;
  /// No inverse for control yet: it would subtract the feedback of the reference's past from the
  /// linear block's inverse (control/inverse_model.hpp).
  static constexpr bool kInvertible = false;
  /// \copydoc ARX::kName
  static constexpr const char* kName = "NonlinearFeedback";
  /// \copydoc ARX::kDescription
  static constexpr ModelDescription<9, 8> kDescription{
      kName,
      "Nonlinear-feedback (Lur'e) model: y(k) = -sum a_j y(k-j) + sum b_i u(k-nk-i) + sum_{j=1..nd} d_j f(s(k-j)), "
      "f(s) = sum_{m=2..r} f_m s^m + sum_{l=1..nh} g_l h(s - knots_l) (h the hinge, zero between 0 and its knot) "
      "+ sum_{i=1..np} w_i play_{r_i}[s] (play operators, hysteresis with memory), "
      "d_1 = 1, s = y (nv = 0) or y(k) - y(k-1) (nv = 1).",
      {{{"na", 1, detail::kMaxOrder, Na_, "poles of the linear block (na >= 1)"},
        {"nb", 0, detail::kMaxOrder, Nb_, "B has nb + 1 coefficients b_0..b_nb"},
        {"nk", 0, detail::kMaxOrder, Eigen::Dynamic, "pure delay of the input in samples"},
        {"r", 1, 32, R_, "degree of the feedback polynomial (1..32; 1: no polynomial terms)"},
        {"nh", 0, 32, Nh_, "hinges of the feedback nonlinearity, knots where its slope changes (0..32; 0: none)"},
        {"nd", 1, 32, Nd_, "taps of the feedback block D = d_1 q^-1 + ... + d_nd q^-nd, d_1 = 1 (1..32)"},
        {"nv", 0, 1, Eigen::Dynamic, "what the nonlinearity sees: 0 the output y, 1 its first difference (a velocity)"},
        {"np", 0, 32, Np_, "play operators of the feedback's hysteresis (0..32; 0: none)", 0},
        detail::kIntegratorsOrder}},
      {{{"b", ParameterShape::Vector, 0, "b_0..b_nb", nullptr, false, {1, 0, -1, 0}},
        {"a", ParameterShape::Vector, 1, "a_1..a_na", nullptr, false, {}},
        {"f",
         ParameterShape::Vector,
         2,
         "f_2..f_r, the feedback polynomial's coefficients (none for r = 1)",
         nullptr,
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
        {"thresholds",
         ParameterShape::Vector,
         1,
         "r_1..r_np, the plays' thresholds: strictly increasing, > 0 (structure, not estimated)",
         nullptr,
         false,
         {1, 0, 0, 0},
         true},
        {"w", ParameterShape::Vector, 1, "w_1..w_np, the plays' weights", nullptr, false, {}},
        {"d",
         ParameterShape::Vector,
         1,
         "d_1..d_nd with d_1 = 1",
         "the nonlinear-feedback model is normalised so that d_1 = 1",
         false,
         {}}}}};
  /// \copydoc ARX::Params
  using Params = Eigen::Matrix<Scalar, kNumParams, 1>;
  /// \copydoc ARX::VectorX
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  /// \copydoc ARX::Linear
  using Linear = LinearBlock<Scalar, Na_, Nb_>;
  using Knots =
      typename detail::HingeTerms<Scalar, Nh_>::Knots;  ///< the hinges' knots (a vector, fixed size when nh is)
  using Plays = PlayOperators<Scalar, Np_>;             ///< the play operators' type
  using Thresholds = typename Plays::Vector;            ///< the plays' thresholds (a vector, fixed size when np is)

  /// A model with the given orders, all parameters zero but d_1 = 1. The knots default to
  /// -floor(nh/2)..-1, 1..ceil(nh/2) and the thresholds to i / (np + 1) (in the units of s): set them
  /// where the feedback's slope changes and its loops turn. Throws std::invalid_argument for an order
  /// out of range or one that differs from the compile-time order.
  /// \param na poles of the linear block, >= 1
  /// \param nb B has nb + 1 coefficients, >= 0
  /// \param nk pure delay in samples, >= 0
  /// \param r degree of the feedback polynomial (f_2..f_r), 1..32
  /// \param nh hinges of the feedback, 0..32
  /// \param nd taps of the feedback's block D (d_1 = 1), 1..32
  /// \param nv 0, the output is fed back; 1, its first difference
  /// \param np play operators in the feedback, 0..32
  /// \param ni integrators (poles fixed at 1), 0..2
  NonlinearFeedback(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r, Eigen::Index nh, Eigen::Index nd,
                    Eigen::Index nv, Eigen::Index np = 0, Eigen::Index ni = 0)
      : m_na(na), m_nb(nb), m_nk(nk), m_r(r), m_nh(nh), m_nd(nd), m_nv(nv), m_np(np), m_ni(ni) {
    detail::require_order(na, 1, "na");
    detail::require_order(nb, 0, "nb");
    detail::require_order(nk, 0, "nk");
    detail::require_order(r, 1, "r (feedback polynomial degree)");
    detail::require(r <= 32, "r (feedback polynomial degree) must be <= 32");
    detail::require_order(nh, 0, "nh (hinges)");
    detail::require(nh <= 32, "nh (hinges) must be <= 32");
    detail::require_order(nd, 1, "nd (feedback taps)");
    detail::require(nd <= 32, "nd (feedback taps) must be <= 32");
    detail::require(nv == 0 || nv == 1,
                    "nv must be 0 (the output is fed back) or 1 (its first difference), got " + std::to_string(nv));
    detail::require_order(np, 0, "np (plays)");
    detail::require(np <= 32, "np (plays) must be <= 32");
    detail::require_integrators(ni);
    detail::require_matches_template(na, Na_, "na");
    detail::require_matches_template(nb, Nb_, "nb");
    detail::require_matches_template(r, R_, "r");
    detail::require_matches_template(nh, Nh_, "nh");
    detail::require_matches_template(nd, Nd_, "nd");
    detail::require_matches_template(np, Np_, "np");
    m_theta = Params::Zero(nb + 1 + na + r - 1 + nh + np + nd - 1);
    m_knots = detail::HingeTerms<Scalar, Nh_>::default_knots(nh);
    m_thresholds = Plays::spread_thresholds(np);
  }

  /// \copydoc ARX::na
  Eigen::Index na() const noexcept { return m_na; }
  /// \copydoc ARX::nb
  Eigen::Index nb() const noexcept { return m_nb; }
  /// \copydoc ARX::nk
  Eigen::Index nk() const noexcept { return m_nk; }
  /// The order r: degree of the feedback polynomial (f_2..f_r)
  /// \return r, 1..32
  Eigen::Index r() const noexcept { return m_r; }
  Eigen::Index nh() const noexcept { return m_nh; }  ///< the order nh: hinges of the feedback \return nh, 0..32
  /// the order nd: taps of the feedback's block D (d_1 = 1)
  /// \return nd, 1..32
  Eigen::Index nd() const noexcept { return m_nd; }
  /// The order nv: 0, the output is fed back; 1, its first difference
  /// \return nv, 0 or 1
  Eigen::Index nv() const noexcept { return m_nv; }
  Eigen::Index np() const noexcept { return m_np; }  ///< the order np: play operators in the feedback \return np, 0..32
  /// \copydoc ARX::ni
  Eigen::Index ni() const noexcept { return m_ni; }
  /// \copydoc ARX::num_params
  Eigen::Index num_params() const noexcept { return m_theta.size(); }
  /// \copydoc ARX::orders
  std::array<Eigen::Index, 9> orders() const noexcept { return {m_na, m_nb, m_nk, m_r, m_nh, m_nd, m_nv, m_np, m_ni}; }

  /// identify()'s start beside its recursive estimates: the loop open, the records' best linear
  /// approximation as the linear block. nonlinear_feedback_starts belongs to the estimator, a layer
  /// above the models (estimator/nonlinear_feedback_start.hpp, in <bonl/estimator.hpp>): found by
  /// argument-dependent lookup where identify() calls this.
  /// \param structure the orders, knots and thresholds to start from
  /// \param records the identification records (deviations from the operating point, as identify() hands them)
  /// \return the starts, each a model with structure's orders, knots and thresholds
  template <class RecordList>
  static std::vector<NonlinearFeedback> identify_starts(const NonlinearFeedback& structure, const RecordList& records) {
    return nonlinear_feedback_starts(structure, records);
  }

  /// \copydoc ARX::theta
  const Params& theta() const noexcept { return m_theta; }
  /// \copydoc ARX::set_theta
  template <typename T>
  void set_theta(const Eigen::MatrixBase<T>& theta) {
    detail::assign_checked(m_theta, theta, "theta");
  }

  /// \copydoc ARX::b
  VectorX b() const { return m_theta.head(m_nb + 1); }
  /// \copydoc ARX::a
  VectorX a() const { return m_theta.segment(first_a(), m_na); }
  /// The feedback polynomial's coefficients. \return f_2..f_r, r - 1 values
  VectorX f() const { return m_theta.segment(first_f(), m_r - 1); }
  /// The hinges' knots. \return knots_1..knots_nh, strictly increasing, none at 0, in the units of s
  const Knots& knots() const noexcept { return m_knots; }
  VectorX g() const { return m_theta.segment(first_g(), m_nh); }  ///< the hinges' weights g_1..g_nh \return nh values
  /// The plays' thresholds. \return r_1..r_np, strictly increasing, > 0, in the units of s
  const Thresholds& thresholds() const noexcept { return m_thresholds; }
  /// The plays' weights. \return w_1..w_np
  VectorX w() const { return m_theta.segment(first_w(), m_np); }
  /// The feedback's block D. \return d_1..d_nd with d_1 = 1
  VectorX d() const {
    VectorX out(m_nd);
    out[0] = Scalar(1);
    out.tail(m_nd - 1) = m_theta.segment(first_d(), m_nd - 1);
    return out;
  }
  /// \copydoc ARX::set_b
  template <typename T>
  void set_b(const Eigen::MatrixBase<T>& b) {
    detail::assign_checked(m_theta.head(m_nb + 1), b, "b");
  }
  /// \copydoc ARX::set_a
  template <typename T>
  void set_a(const Eigen::MatrixBase<T>& a) {
    detail::assign_checked(m_theta.segment(first_a(), m_na), a, "a");
  }
  /// Sets f_2..f_r (r - 1 finite values, else std::invalid_argument).
  /// \param f f_2..f_r
  template <typename T>
  void set_f(const Eigen::MatrixBase<T>& f) {
    detail::assign_checked(m_theta.segment(first_f(), m_r - 1), f, "f");
  }
  /// Where the slope changes: strictly increasing, none at 0 (f has slope 0 at 0).
  /// \param knots knots_1..knots_nh, in the units of s
  template <typename T>
  void set_knots(const Eigen::MatrixBase<T>& knots) {
    detail::HingeTerms<Scalar, Nh_>::require_valid(knots, m_nh, "the feedback has slope 0 at 0");
    m_knots = knots;
  }
  /// Sets the hinges' weights g_1..g_nh (nh finite values, else std::invalid_argument).
  /// \param g g_1..g_nh
  template <typename T>
  void set_g(const Eigen::MatrixBase<T>& g) {
    detail::assign_checked(m_theta.segment(first_g(), m_nh), g, "g");
  }
  /// Where the plays' loops turn: strictly increasing, > 0 (in the units of s).
  /// \param thresholds r_1..r_np, in the units of s
  template <typename T>
  void set_thresholds(const Eigen::MatrixBase<T>& thresholds) {
    Plays::require_valid(thresholds, m_np);
    m_thresholds = thresholds;
  }
  /// Sets the plays' weights w_1..w_np (np finite values, else std::invalid_argument).
  /// \param w w_1..w_np
  template <typename T>
  void set_w(const Eigen::MatrixBase<T>& w) {
    detail::assign_checked(m_theta.segment(first_w(), m_np), w, "w");
  }
  /// Sets d_1..d_nd: nd finite values with d_1 = 1 (the normalisation), else std::invalid_argument.
  /// \param d d_1..d_nd
  template <typename T>
  void set_d(const Eigen::MatrixBase<T>& d) {
    detail::require_size(d, m_nd, "d");
    detail::require_finite(d, "d");
    detail::require(d[0] == 1, std::string("d[0] (d_1) must be 1: ") + kDescription.parameters[7].normalised);
    m_theta.segment(first_d(), m_nd - 1) = d.tail(m_nd - 1);
  }

  /// The parameter block kDescription.parameters[i]: b, a, f, knots, g, thresholds, w, d.
  /// \copydetails ARX::parameter
  VectorX parameter(std::size_t i) const {
    switch (i) {
      case 0: return b();
      case 1: return a();
      case 2: return f();
      case 3: return m_knots;
      case 4: return g();
      case 5: return m_thresholds;
      case 6: return w();
      case 7: return d();
      default: detail::no_such_parameter(kName, i);
    }
  }
  /// \copydoc ARX::set_parameter
  void set_parameter(std::size_t i, const VectorX& value) {
    switch (i) {
      case 0: return set_b(value);
      case 1: return set_a(value);
      case 2: return set_f(value);
      case 3: return set_knots(value);
      case 4: return set_g(value);
      case 5: return set_thresholds(value);
      case 6: return set_w(value);
      case 7: return set_d(value);
      default: detail::no_such_parameter(kName, i);
    }
  }

  /// \copydoc ARX::try_simulate_deviations
  template <typename U>
  bool try_simulate_deviations(const Eigen::MatrixBase<U>& u, VectorX& y) const {
    const Feedback feedback(*this);
    PlayHistory plays(*this);
    detail::History<Scalar> u_lags(m_nk + m_nb + 1);
    detail::History<Scalar> y_lags(lags());
    detail::History<Scalar> z_lags(m_na);  // the denominator's past: y differenced ni times
    detail::IntegratorLags<Scalar> integrators(m_ni);
    y.resize(u.size());
    for (Eigen::Index k = 0; k < u.size(); ++k) {
      u_lags.push(u[k]);
      plays.step(feedback.s(y_lags, 0));
      Scalar out = Scalar(0);
      for (Eigen::Index i = 0; i <= m_nb; ++i) out += m_theta[i] * u_lags[m_nk + i];
      for (Eigen::Index j = 0; j < m_na; ++j) out -= m_theta[first_a() + j] * z_lags[j];
      for (Eigen::Index j = 0; j < m_nd; ++j) {
        out += tap(m_theta, j) * (feedback.output(m_theta, feedback.s(y_lags, j)) + plays.output(m_theta, j));
      }
      if (m_ni > 0) out += integrators.carried();
      y[k] = out;
      if (!std::isfinite(out)) return false;
      y_lags.push(out);
      z_lags.push(integrators.push(out));
    }
    return true;
  }
  /// Projects an estimate onto the model's valid set: every theta is valid.
  void constrain(Params& /*theta*/) const noexcept {}

 private:
  /// The feedback nonlinearity f on theta (its polynomial and its hinges) and the signal s it sees.
  class Feedback {
   public:
    explicit Feedback(const NonlinearFeedback& model)
        : m_hinges(model.knots(), model.first_g()), m_first_f(model.first_f()), m_r(model.r()), m_nv(model.nv()) {}
    /// s(k-1-j) from the stored outputs y(k-1), y(k-2), ... (newest first).
    template <class Lags>
    Scalar s(const Lags& y, Eigen::Index j) const noexcept {
      return m_nv == 0 ? y[j] : y[j] - y[j + 1];
    }
    template <typename Theta>
    Scalar output(const Theta& theta, Scalar s) const noexcept {
      Scalar power = s, out = Scalar(0);
      for (Eigen::Index m = 2; m <= m_r; ++m) {
        power *= s;
        out += theta[m_first_f + m - 2] * power;
      }
      return m_hinges.add_output(theta, s, out);
    }
    /// df/ds at s (the hinges' one-sided slope beyond a knot).
    template <typename Theta>
    Scalar slope(const Theta& theta, Scalar s) const noexcept {
      Scalar power = Scalar(1), out = Scalar(0);
      for (Eigen::Index m = 2; m <= m_r; ++m) {
        power *= s;  // s^(m-1)
        out += Scalar(m) * theta[m_first_f + m - 2] * power;
      }
      return out + m_hinges.slope(theta, s);
    }
    /// weight * df/d[f, g] added into out's f and g entries: weight s^m and weight h_l(s).
    template <typename Out>
    void add_regressor(Scalar s, Scalar weight, Out& out) const noexcept {
      Scalar power = s;
      for (Eigen::Index m = 2; m <= m_r; ++m) {
        power *= s;
        out[m_first_f + m - 2] += weight * power;
      }
      m_hinges.add_regressor(s, weight, out);
    }

   private:
    detail::HingeTerms<Scalar, Nh_> m_hinges;
    Eigen::Index m_first_f, m_r, m_nv;
  };

  /// The feedback's plays and their values at the taps: step(s(k-1)) moves them, then past(j) is
  /// P(k-1-j), j = 0..nd-1 (zero before the record: rest), and output(theta, j) sum_i w_i P_i(k-1-j).
  class PlayHistory {
   public:
    using Past = Eigen::Matrix<Scalar, Np_, Nd_>;
    explicit PlayHistory(const NonlinearFeedback& model)
        : m_plays(model.thresholds()), m_past(Past::Zero(model.np(), model.nd())), m_first_w(model.first_w()) {}
    void reset() noexcept {
      m_plays.reset();
      m_past.setZero();
    }
    /// Moves the plays with s(k-1) and the history one tap back.
    void step(Scalar s) noexcept {
      if (m_past.rows() == 0) return;
      for (Eigen::Index j = m_past.cols() - 1; j > 0; --j) m_past.col(j) = m_past.col(j - 1);
      m_past.col(0) = m_plays.step(s);
    }
    template <typename Theta>
    Scalar output(const Theta& theta, Eigen::Index j) const noexcept {
      Scalar out = Scalar(0);
      for (Eigen::Index i = 0; i < m_past.rows(); ++i) out += theta[m_first_w + i] * m_past(i, j);
      return out;
    }
    /// weight * P(k-1-j) added into out's w entries.
    template <typename Out>
    void add_regressor(Eigen::Index j, Scalar weight, Out& out) const noexcept {
      for (Eigen::Index i = 0; i < m_past.rows(); ++i) out[m_first_w + i] += weight * m_past(i, j);
    }
    Eigen::Index size() const noexcept { return m_past.rows(); }
    /// P_i(k-1), the plays' values after the last step (before the first: 0, rest).
    Scalar value(Eigen::Index i) const noexcept { return m_past(i, 0); }

   private:
    Plays m_plays;
    Past m_past;
    Eigen::Index m_first_w;
  };

 public:
  /// Key-term form: regressor [u(k-nk..k-nk-nb), -y(k-1..k-na), s(k-1)^2..s(k-1)^r,
  /// h(s(k-1) - knots_1..nh), x(k-2..k-nd)], x(k-j) = f(s(k-j)) with the step's theta; target y(k).
  /// The past y are the measured outputs for both methods (the model's prediction where y is NaN),
  /// so the internal variables are the nonlinearity of the measured past. predict() runs it. With
  /// integrators the a-entries hold the differenced past and the target is y(k) less their part.
  class KeyTerms {
   public:
    /// \copydoc ARX::KeyTerms::KeyTerms
    KeyTerms(const NonlinearFeedback& model, KeyTermMethod /*method*/)
        : m_feedback(model), m_u(model.nk() + model.nb() + 1), m_y(model.lags()), m_z(model.na()),
          m_integrators(model.ni()), m_na(model.na()), m_nb(model.nb()), m_nk(model.nk()), m_nd(model.nd()),
          m_first_f(model.first_f()), m_feedback_size(model.r() - 1 + model.nh() + model.np()),
          m_first_d(model.first_d()), m_plays(model), m_phi(Params::Zero(model.num_params())) {}
    /// \copydoc ARX::KeyTerms::reset
    void reset() noexcept {
      m_u.clear();
      m_y.clear();
      m_z.clear();
      m_integrators.clear();
      m_plays.reset();
    }
    /// \copydoc ARX::KeyTerms::step
    Regression<Scalar, Params> step(const Params& theta, Scalar u, Scalar y) noexcept {
      m_u.push(u);
      for (Eigen::Index i = 0; i <= m_nb; ++i) m_phi[i] = m_u[m_nk + i];
      for (Eigen::Index j = 0; j < m_na; ++j) m_phi[m_nb + 1 + j] = -m_z[j];
      m_phi.segment(m_first_f, m_feedback_size).setZero();
      const Scalar s1 = m_feedback.s(m_y, 0);
      m_plays.step(s1);
      m_feedback.add_regressor(s1, Scalar(1), m_phi);
      m_plays.add_regressor(0, Scalar(1), m_phi);
      for (Eigen::Index j = 1; j < m_nd; ++j) {
        m_phi[m_first_d + j - 1] = m_feedback.output(theta, m_feedback.s(m_y, j)) + m_plays.output(theta, j);
      }
      const Scalar carried = m_integrators.carried();
      const Scalar prediction = m_phi.dot(theta) + carried;
      const Scalar lag = std::isnan(y) ? prediction : y;
      m_y.push(lag);
      m_z.push(m_integrators.push(lag));
      return {m_phi, y - carried, prediction, m_feedback.output(theta, s1) + m_plays.output(theta, 0), true};
    }

   private:
    Feedback m_feedback;
    detail::History<Scalar> m_u, m_y;
    detail::History<Scalar> m_z;  // the denominator's past: y differenced ni times
    detail::IntegratorLags<Scalar> m_integrators;
    Eigen::Index m_na, m_nb, m_nk, m_nd, m_first_f, m_feedback_size, m_first_d;
    PlayHistory m_plays;  // the plays of the measured s
    Params m_phi;
  };

  /// The output-error method's view: one step of the free run with its sensitivities,
  ///   dy(k) = [u lags at b] + [-y lags at a] + sum_j d_j df/d[f, g](s(k-j)) + [x(k-j) at d_j]
  ///           - sum_j a_j dy(k-j) + sum_j d_j f'(s(k-j)) ds(k-j),
  /// ds the sensitivity of s (of y, or of y's first difference). The past outputs and their
  /// sensitivities are kept as far back as the denominator and the feedback reach. With integrators
  /// the denominator's past is z = (1 - q^-1)^ni y, kept with its sensitivities beside y's, and
  /// y(k) and dy(k) carry the integrators' part of the past y and dy.
  class OutputErrorTerms {
   public:
    /// \copydoc ARX::OutputErrorTerms::OutputErrorTerms
    explicit OutputErrorTerms(const NonlinearFeedback& model)
        : m_feedback(model), m_u(model.nk() + model.nb() + 1), m_na(model.na()), m_nb(model.nb()), m_nk(model.nk()),
          m_nd(model.nd()), m_nv(model.nv()), m_first_f(model.first_f()),
          m_feedback_size(model.r() - 1 + model.nh() + model.np()), m_first_d(model.first_d()),
          m_first_w(model.first_w()), m_ni(model.ni()), m_plays(model),
          m_dplays(PlaySensitivities::Zero(model.num_params(), model.np())),
          m_dplayed(SensitivityLags::Zero(model.num_params(), model.np() > 0 ? model.nd() : 0)),
          m_before(Thresholds::Zero(model.np())), m_y(VectorX::Zero(model.lags())),
          m_dy(SensitivityLags::Zero(model.num_params(), model.lags())), m_z(VectorX::Zero(model.na())),
          m_dz(SensitivityLags::Zero(model.num_params(), model.na())),
          m_work(Eigen::Matrix<Scalar, Na_, 1>::Zero(model.na())), m_psi(Params::Zero(model.num_params())) {}
    /// \copydoc ARX::OutputErrorTerms::reset
    void reset() noexcept {
      m_u.clear();
      m_y.setZero();
      m_dy.setZero();
      m_z.setZero();
      m_dz.setZero();
      m_plays.reset();
      m_dplays.setZero();
      m_dplayed.setZero();
    }
    /// \copydoc ARX::OutputErrorTerms::step
    SimulationStep<Scalar, Params> step(const Params& theta, Scalar u) noexcept {
      m_u.push(u);
      Scalar y = Scalar(0);
      for (Eigen::Index i = 0; i <= m_nb; ++i) {
        m_psi[i] = m_u[m_nk + i];
        y += theta[i] * m_psi[i];
      }
      for (Eigen::Index j = 0; j < m_na; ++j) {
        m_psi[m_nb + 1 + j] = -m_z[j];
        y -= theta[m_nb + 1 + j] * m_z[j];
      }
      m_psi.segment(m_first_f, m_feedback_size).setZero();
      step_plays(theta);
      Scalar x1 = Scalar(0);
      for (Eigen::Index j = 0; j < m_nd; ++j) {
        const Scalar dj = j == 0 ? Scalar(1) : theta[m_first_d + j - 1];
        const Scalar s = m_feedback.s(m_y, j);
        const Scalar x = m_feedback.output(theta, s) + m_plays.output(theta, j);
        if (j == 0) x1 = x;
        if (j > 0) m_psi[m_first_d + j - 1] = x;
        y += dj * x;
        m_feedback.add_regressor(s, dj, m_psi);
        m_plays.add_regressor(j, dj, m_psi);
      }
      // Through the loop: the denominator's past and the feedback's slope at each past s.
      for (Eigen::Index j = 0; j < m_na; ++j) m_psi -= theta[m_nb + 1 + j] * m_dz.col(j);
      if (m_ni > 0) {
        y += detail::carried<Scalar>(m_ni, m_y);
        detail::add_carried_sensitivity(m_ni, m_dy, Scalar(1), m_psi);
      }
      for (Eigen::Index j = 0; j < m_nd; ++j) {
        const Scalar dj = j == 0 ? Scalar(1) : theta[m_first_d + j - 1];
        const Scalar gain = dj * m_feedback.slope(theta, m_feedback.s(m_y, j));
        if (gain == Scalar(0)) continue;
        m_psi += gain * m_dy.col(j);
        if (m_nv == 1) m_psi -= gain * m_dy.col(j + 1);
      }
      for (Eigen::Index j = 0; j < m_dplayed.cols(); ++j) {
        m_psi += (j == 0 ? Scalar(1) : theta[m_first_d + j - 1]) * m_dplayed.col(j);
      }
      m_output = y;
      return {y, m_psi, x1};
    }
    /// \copydoc ARX::OutputErrorTerms::accept()
    void accept() noexcept {
      for (Eigen::Index j = m_z.size() - 1; j > 0; --j) {
        m_z[j] = m_z[j - 1];
        m_dz.col(j) = m_dz.col(j - 1);
      }
      m_z[0] = m_output;  // z(k) = y(k) - carried(k), read before the y lags move
      m_dz.col(0) = m_psi;
      if (m_ni > 0) {
        m_z[0] -= detail::carried<Scalar>(m_ni, m_y);
        detail::add_carried_sensitivity(m_ni, m_dy, Scalar(-1), m_dz.col(0));
      }
      for (Eigen::Index j = m_y.size() - 1; j > 0; --j) {
        m_y[j] = m_y[j - 1];
        m_dy.col(j) = m_dy.col(j - 1);
      }
      m_y[0] = m_output;
      m_dy.col(0) = m_psi;
    }
    /// After the estimate moved by delta: the stored outputs to first order (as SimulatedLags does).
    /// \param delta the change of theta since the step just accepted
    void correct(const Params& delta) noexcept {
      for (Eigen::Index j = 0; j < m_y.size(); ++j) m_y[j] += m_dy.col(j).dot(delta);
      for (Eigen::Index j = 0; j < m_z.size(); ++j) m_z[j] += m_dz.col(j).dot(delta);
    }
    /// \copydoc ARX::OutputErrorTerms::stable
    bool stable(const Params& theta, Scalar radius) noexcept {
      return detail::roots_inside(theta.template segment<Na_>(m_nb + 1, m_na), radius, m_work);
    }

   private:
    using SensitivityLags = Eigen::Matrix<Scalar, kNumParams, Eigen::Dynamic>;
    using PlaySensitivities = Eigen::Matrix<Scalar, kNumParams, Np_>;

    /// Moves the plays with s(k-1) and their sensitivities: a play that moved follows s, so its
    /// sensitivity is ds(k-1); one that held keeps its own. m_dplayed.col(j) is then
    /// sum_i w_i dP_i(k-1-j), the plays' part of the feedback's sensitivity at tap j + 1.
    void step_plays(const Params& theta) noexcept {
      if constexpr (Np_ == 0) {  // no plays at compile time: nothing to move (nor to compile)
        static_cast<void>(theta);
      } else {
        if (m_plays.size() == 0) return;
        for (Eigen::Index i = 0; i < m_plays.size(); ++i) m_before[i] = m_plays.value(i);
        m_plays.step(m_feedback.s(m_y, 0));
        for (Eigen::Index i = 0; i < m_plays.size(); ++i) {
          if (m_plays.value(i) == m_before[i]) continue;
          m_dplays.col(i) = m_dy.col(0);
          if (m_nv == 1) m_dplays.col(i) -= m_dy.col(1);
        }
        for (Eigen::Index j = m_dplayed.cols() - 1; j > 0; --j) m_dplayed.col(j) = m_dplayed.col(j - 1);
        m_dplayed.col(0).noalias() = m_dplays * theta.segment(m_first_w, m_plays.size());
      }
    }

    Feedback m_feedback;
    detail::History<Scalar> m_u;
    Eigen::Index m_na, m_nb, m_nk, m_nd, m_nv, m_first_f, m_feedback_size, m_first_d, m_first_w, m_ni;
    PlayHistory m_plays;                   // the plays of the simulated s
    PlaySensitivities m_dplays;            // dP_i(k-1) / dtheta, one column per play
    SensitivityLags m_dplayed;             // sum_i w_i dP_i(k-1-j) / dtheta, j = 0..nd-1
    Thresholds m_before;                   // the plays' values before the step
    VectorX m_y;                           // y(k-1), y(k-2), ...: the simulated outputs, newest first
    SensitivityLags m_dy;                  // their sensitivities, one column each
    VectorX m_z;                           // z(k-1..k-na): the denominator's past, y differenced ni times
    SensitivityLags m_dz;                  // their sensitivities
    Eigen::Matrix<Scalar, Na_, 1> m_work;  // for the stability test
    Params m_psi;
    Scalar m_output = Scalar(0);
  };

 private:
  Eigen::Index first_a() const noexcept { return m_nb + 1; }
  Eigen::Index first_f() const noexcept { return m_nb + 1 + m_na; }
  Eigen::Index first_g() const noexcept { return first_f() + m_r - 1; }
  Eigen::Index first_w() const noexcept { return first_g() + m_nh; }
  Eigen::Index first_d() const noexcept { return first_w() + m_np; }
  /// How many past outputs a step reads besides the denominator's (kept apart, differenced): the
  /// feedback's nd (and one more for a first difference) and the integrators' ni.
  Eigen::Index lags() const noexcept { return std::max(m_nd + m_nv, m_ni); }
  /// d_{j+1} on theta (d_1 = 1).
  Scalar tap(const Params& theta, Eigen::Index j) const noexcept {
    return j == 0 ? Scalar(1) : theta[first_d() + j - 1];
  }

  Params m_theta;
  Knots m_knots;
  Thresholds m_thresholds;
  Eigen::Index m_na, m_nb, m_nk, m_r, m_nh, m_nd, m_nv, m_np, m_ni;
};

}  // namespace bonl
