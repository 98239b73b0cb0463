#pragma once
// What the three block models share: the Hammerstein front (two-segment input polynomial, then
// the linear block with b_0 = 1), its parameters in eq. (19) order, its free-run simulation, and the
// key-term regressor of its linear-in-parameters form (eq. 14), and its one-step simulation with
// sensitivities for the output-error method. Users never name this header.

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>

#include "../../blocks/linear_block.hpp"
#include "../../blocks/two_segment_polynomial.hpp"
#include "../../detail/history.hpp"
#include "../../detail/integrators.hpp"
#include "../../detail/stability.hpp"
#include "../../detail/validate.hpp"
#include "../model_description.hpp"
#include "../model_steps.hpp"
#include "model_runs.hpp"
#include "simulated_lags.hpp"

namespace bonl::detail {

/// The front's orders and parameter blocks, as the block models describe them (each model appends its
/// own orders, and kIntegratorsOrder last).
template <int Na, int Nb, int R>
constexpr std::array<OrderDescription, 4> front_orders() {
  return {{{"na", 1, kMaxOrder, Na, "poles of the linear block (na >= 1)"},
           {"nb", 0, kMaxOrder, Nb, "B has nb + 1 coefficients b_0..b_nb, b_0 = 1"},
           {"nk", 0, kMaxOrder, Eigen::Dynamic, "pure delay in samples"},
           {"r", 1, kMaxOrder, R, "degree of the input polynomials (r >= 1)"}}};
}
inline constexpr const char* kFrontNormalisation = "block models are normalised so that b_0 = 1";
inline constexpr std::array<ParameterDescription, 4> kFrontParameters{
    {{"b", ParameterShape::Vector, 0, "b_0..b_nb with b_0 = 1", kFrontNormalisation, false, {}},
     {"a", ParameterShape::Vector, 1, "a_1..a_na", nullptr, false, {}},
     {"f", ParameterShape::Vector, 0, "f_0..f_r, the input polynomial for u >= 0", nullptr, false, {1, 0, 0, -1}},
     {"p",
      ParameterShape::Vector,
      0,
      "p_0..p_r, its change for u < 0 (p_l = g_l - f_l)",
      nullptr,
      false,
      {1, 0, 0, -1}}}};

/// b_0..b_nb of a block model's linear block from theta's b_1..b_nb (`tail`): b_0 = 1, the normalisation.
template <typename VectorX, typename Tail>
VectorX normalised_b(const Tail& tail) {
  VectorX b(tail.size() + 1);
  b[0] = 1;
  b.tail(tail.size()) = tail;
  return b;
}
/// A block model's set_b: b (nb + 1 entries, finite, b_0 = 1) checked, then b_1..b_nb into `into`
/// (theta's nb entries); otherwise std::invalid_argument and `into` untouched.
template <typename B, typename Into>
void assign_normalised_b(const Eigen::MatrixBase<B>& b, Into&& into) {
  require_size(b, into.size() + 1, "b");
  require_finite(b, "b");
  require(b[0] == 1, std::string("b[0] (b_0) must be 1: the ") + kFrontNormalisation);
  into = b.tail(into.size());
}

/// Parameter count of the front: f_0..f_r, p_0..p_r, b_1..b_nb, a_1..a_na.
constexpr int front_params(int na, int nb, int r) {
  return (na == Eigen::Dynamic || nb == Eigen::Dynamic || r == Eigen::Dynamic) ? Eigen::Dynamic : 2 * (r + 1) + nb + na;
}

template <typename Scalar_, int Na_, int Nb_, int R_, int Extra_>
class HammersteinFront {
 public:
  using Scalar = Scalar_;
  static constexpr int kFrontParams = front_params(Na_, Nb_, R_);
  static constexpr int kNumParams = add_sizes(kFrontParams, Extra_);
  static constexpr bool kHasInternalVariables = true;
  using Params = Eigen::Matrix<Scalar, kNumParams, 1>;
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  using InputBlock = TwoSegmentPolynomial<Scalar, R_>;
  using Linear = LinearBlock<Scalar, Na_, Nb_>;

  Eigen::Index na() const noexcept { return m_na; }
  Eigen::Index nb() const noexcept { return m_nb; }
  Eigen::Index nk() const noexcept { return m_nk; }
  Eigen::Index r() const noexcept { return m_r; }
  Eigen::Index ni() const noexcept { return m_ni; }
  Eigen::Index num_params() const noexcept { return m_theta.size(); }
  Eigen::Index front_size() const noexcept { return 2 * (m_r + 1) + m_nb + m_na; }
  /// Distinct input values the two-segment polynomial needs: r + 1 on each side of zero (input_levels_needed()).
  Eigen::Index input_levels_needed() const noexcept { return 2 * (m_r + 1); }

  /// Parameters in the order of eq. (19).
  const Params& theta() const noexcept { return m_theta; }
  template <typename T>
  void set_theta(const Eigen::MatrixBase<T>& theta) {
    assign_checked(m_theta, theta, "theta");
  }

  VectorX f() const { return m_theta.segment(0, m_r + 1); }
  VectorX p() const { return m_theta.segment(m_r + 1, m_r + 1); }
  /// b_0..b_nb; b_0 is 1 (the key-term normalisation).
  VectorX b() const { return normalised_b<VectorX>(m_theta.segment(2 * (m_r + 1), m_nb)); }
  VectorX a() const { return m_theta.segment(2 * (m_r + 1) + m_nb, m_na); }

  template <typename T>
  void set_f(const Eigen::MatrixBase<T>& f) {
    assign_checked(m_theta.segment(0, m_r + 1), f, "f");
  }
  template <typename T>
  void set_p(const Eigen::MatrixBase<T>& p) {
    assign_checked(m_theta.segment(m_r + 1, m_r + 1), p, "p");
  }
  /// b_0..b_nb with b_0 = 1.
  template <typename T>
  void set_b(const Eigen::MatrixBase<T>& b) {
    assign_normalised_b(b, m_theta.segment(2 * (m_r + 1), m_nb));
  }
  template <typename T>
  void set_a(const Eigen::MatrixBase<T>& a) {
    assign_checked(m_theta.segment(2 * (m_r + 1) + m_nb, m_na), a, "a");
  }

  /// The front's parameter blocks in the order the block models describe them: b, a, f, p.
  static constexpr std::size_t kFrontBlocks = 4;
  VectorX front_parameter(std::size_t i) const {
    switch (i) {
      case 0: return b();
      case 1: return a();
      case 2: return f();
      default: return p();
    }
  }
  void set_front_parameter(std::size_t i, const VectorX& value) {
    switch (i) {
      case 0: return set_b(value);
      case 1: return set_a(value);
      case 2: return set_f(value);
      default: return set_p(value);
    }
  }

  /// Projects an estimate onto the model's valid set; the front's is all of R^n (P-H-W adds c >= 0).
  void constrain(Params& /*theta*/) const noexcept {}

  InputBlock input_block() const { return InputBlock(f(), p()); }

 protected:
  HammersteinFront(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r, Eigen::Index extra,
                   Eigen::Index ni) {
    require_order(na, 1, "na");
    require_order(nb, 0, "nb");
    require_order(nk, 0, "nk");
    require_order(r, 1, "r");
    require_integrators(ni);
    require_matches_template(na, Na_, "na");
    require_matches_template(nb, Nb_, "nb");
    require_matches_template(r, R_, "r");
    m_na = na;
    m_nb = nb;
    m_nk = nk;
    m_r = r;
    m_ni = ni;
    m_theta = Params::Zero(front_size() + extra);
  }

  /// Free run from rest: w = N1(u), continued linearly beyond `range` (the input range the model was
  /// identified on, as deviations from u0: TwoSegmentPolynomial's header), x = L(w) with L = `linear`
  /// (the model's linear_block()), y = output(x) (free_run).
  template <typename U, typename OutputMap>
  bool simulate_front(const Eigen::MatrixBase<U>& u, VectorX& y, Linear linear, OutputMap&& output,
                      const InputDeviationRange& range) const {
    const VectorX fv = f();
    const VectorX pv = p();
    const Scalar low = static_cast<Scalar>(range.low), high = static_cast<Scalar>(range.high);
    return free_run(
        std::move(linear), u, y, [&](Scalar v) { return InputBlock::evaluate(fv, pv, v, low, high); }, output);
  }

  Params m_theta;
  Eigen::Index m_na = 0;
  Eigen::Index m_nb = 0;
  Eigen::Index m_nk = 0;
  Eigen::Index m_r = 0;
  Eigen::Index m_ni = 0;
};

/// The front's part of the key-term regressor (eq. 14 with eq. 7's signs):
///   [basis(u(k-nk)), w(k-nk-1), ..., w(k-nk-nb), -x(k-1), ..., -x(k-na)],
/// so that x(k) = regressor . theta_front. With integrators the lags are z = (1 - q^-1)^ni x and
/// x(k) = regressor . theta_front + carried() (detail/integrators.hpp). Before the record starts, u, w and x are zero
/// (the model is at rest), which is what the free-run simulation assumes too.
/// Orders fixed in the template (the paper's 3, 2, 3) make every loop here a fixed, unrolled
/// sequence and the x history a shift register; Eigen::Dynamic takes them from the constructor.
/// A sample's x lag is stored by store() (the equation-error method: from the measured output, in
/// the same step) or store_a_posteriori() (the paper's: at the start of the next step).
template <typename Scalar, int Na = Eigen::Dynamic, int Nb = Eigen::Dynamic, int R = Eigen::Dynamic>
class FrontKeyTerms {
  static constexpr int kCoeffs = poly_size(R);  // r + 1
  static constexpr int kFront = front_params(Na, Nb, R);

 public:
  FrontKeyTerms(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r, KeyTermMethod method,
                Eigen::Index ni)
      : m_na(na), m_nb(nb), m_nk(nk), m_r(r), m_method(method), m_u(nk + nb + 1), m_w(nk + nb + 1), m_z(na),
        m_integrators(ni) {}

  void reset() noexcept {
    m_u.clear();
    m_w.clear();
    m_z.clear();
    m_integrators.clear();
    m_k = 0;
    m_pending = false;
  }

  /// The paper's method: the previous sample's x and w wait for store_a_posteriori().
  bool pending() const noexcept { return m_pending; }

  /// The input range beyond which the input block continues linearly (TwoSegmentPolynomial's header),
  /// as deviations from u0: a model's simulation after a measured past and its prediction set it to
  /// the range the model was identified on (run_after_past); the estimator leaves it infinite.
  /// \param range the range, (-inf, inf) for none
  void set_input_range(const InputDeviationRange& range) noexcept {
    m_low = static_cast<Scalar>(range.low);
    m_high = static_cast<Scalar>(range.high);
  }

  /// The integrators' part of x(k) (0 without integrators): what a model takes off its target.
  Scalar carried() const noexcept { return m_integrators.carried(); }

  /// The paper's method (eq. 24): stores the previous sample's x = phi . theta and w = N1(u) with
  /// `theta`, the estimate updated since; `phi` is that sample's regressor. Returns that x.
  template <typename Theta, typename Phi>
  Scalar store_a_posteriori(const Theta& theta, const Phi& phi) noexcept {
    const Eigen::Index n = 2 * (r() + 1) + nb() + na();
    Scalar x = phi.template head<kFront>(n).dot(theta.template head<kFront>(n));
    if (m_integrators.size() > 0) x += m_integrators.carried();
    m_z.push(m_integrators.push(x));
    m_w.push(TwoSegmentPolynomial<Scalar>::evaluate(coefficients(theta, 0), coefficients(theta, r() + 1), m_u[0], m_low,
                                                    m_high));
    advance();
    m_pending = false;
    return x;
  }

  /// Pushes u(k), writes the front's regressor into phi.head(front size) and returns
  /// x(k) = regressor . theta over those entries. x is summed from the values as they are written,
  /// not by reading phi back: a vector load of entries just stored one by one stalls on
  /// store-to-load forwarding (docs/lab/performance.md).
  template <typename Theta, typename Phi>
  Scalar begin(const Theta& theta, Scalar u, Phi& phi) noexcept {
    m_u.push(u);
    const Eigen::Index n_fp = 2 * (r() + 1);
    const auto f = coefficients(theta, 0);
    const auto p = coefficients(theta, r() + 1);
    Scalar x = Scalar(0);
    if (m_k >= m_nk) {
      x = TwoSegmentPolynomial<Scalar>::basis(m_u[m_nk], f, p, phi, m_low, m_high);
    } else {
      for (Eigen::Index l = 0; l < n_fp; ++l) phi[l] = Scalar(0);
    }
    const bool paper = m_method == KeyTermMethod::Paper;
    for (Eigen::Index i = 1; i <= nb(); ++i) {
      Scalar w = Scalar(0);
      if (m_k - m_nk - i >= 0) {
        // Paper: w as estimated when it entered (eq. 24). Equation error: recomputed with the
        // newest f, p, so that the regressor is consistent with the parameters being estimated.
        w = paper ? m_w[m_nk + i - 1] : TwoSegmentPolynomial<Scalar>::evaluate(f, p, m_u[m_nk + i], m_low, m_high);
      }
      phi[n_fp + i - 1] = w;
      x += theta[n_fp + i - 1] * w;
    }
    for (Eigen::Index j = 1; j <= na(); ++j) {
      phi[n_fp + nb() + j - 1] = -m_z[j - 1];
      x -= theta[n_fp + nb() + j - 1] * m_z[j - 1];
    }
    if (m_integrators.size() > 0) x += m_integrators.carried();
    m_pending = paper;
    return x;
  }

  /// The equation-error method: stores x(k), the lag later regressors use (what the measured output says).
  void store(Scalar x_lag) noexcept {
    m_z.push(m_integrators.push(x_lag));
    advance();
  }

 private:
  // The orders as constants where the template fixes them, so that the compiler unrolls.
  Eigen::Index na() const noexcept { return Na == Eigen::Dynamic ? m_na : Na; }
  Eigen::Index nb() const noexcept { return Nb == Eigen::Dynamic ? m_nb : Nb; }
  Eigen::Index r() const noexcept { return R == Eigen::Dynamic ? m_r : R; }

  void advance() noexcept {
    if (m_k < m_nk + nb() + 1) ++m_k;  // only "before or after the record start" matters
  }

  /// f (start 0) or p (start r + 1): r + 1 entries of theta, of fixed size when R is.
  template <typename Theta>
  auto coefficients(const Theta& theta, Eigen::Index start) const noexcept {
    return theta.template segment<kCoeffs>(start, r() + 1);
  }

  Eigen::Index m_na = 0, m_nb = 0, m_nk = 0, m_r = 0;
  KeyTermMethod m_method;
  History<Scalar> m_u, m_w;  // capacity nk + nb + 1: nk is a run-time order
  History<Scalar, Na> m_z;   // z(k-1..k-na): x itself where there are no integrators
  IntegratorLags<Scalar> m_integrators;
  Eigen::Index m_k = 0;
  bool m_pending = false;
  Scalar m_low = -std::numeric_limits<Scalar>::infinity();
  Scalar m_high = std::numeric_limits<Scalar>::infinity();
};

/// The front for the output-error method: one step of its free-run simulation with the current
/// estimate, x(k) = sum_{i=0..nb} b_i w(k-nk-i) - sum_j a_j x(k-j) with w = N1(u; f, p) recomputed from
/// the stored u (w has no memory of its own, so it is exact for the current f, p), and the sensitivity
/// of x(k) to the front's parameters:
///   d x / d f_l = sum_i b_i u(k-nk-i)^l,  d x / d p_l = sum_i b_i h(u) u(k-nk-i)^l,
///   d x / d b_i = w(k-nk-i),  d x / d a_j = -x(k-j),
/// each filtered by 1 / A (SimulatedLags). Before the record starts u, w and x are zero, as in simulate().
template <typename Scalar, int Na = Eigen::Dynamic, int Nb = Eigen::Dynamic, int R = Eigen::Dynamic>
class FrontOutputError {
  static constexpr int kCoeffs = poly_size(R);
  static constexpr int kFront = front_params(Na, Nb, R);

 public:
  using Sensitivity = Eigen::Matrix<Scalar, kFront, 1>;

  FrontOutputError() = default;
  FrontOutputError(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r, Eigen::Index ni)
      : m_na(na), m_nb(nb), m_nk(nk), m_r(r), m_u(nk + nb + 1), m_lags(na, 2 * (r + 1) + nb + na, ni),
        m_dx(Sensitivity::Zero(2 * (r + 1) + nb + na)), m_work(Eigen::Matrix<Scalar, Na, 1>::Zero(na)) {}

  void reset() noexcept {
    m_u.clear();
    m_lags.reset();
    m_dx.setZero();
    m_x = Scalar(0);
    m_k = 0;
  }

  /// Pushes u(k) and simulates one step with `theta` (whose first entries are the front's): returns
  /// x(k); sensitivity() is then d x(k) / d theta_front. Nothing is stored until commit().
  template <typename Theta>
  Scalar step(const Theta& theta, Scalar u) noexcept {
    m_u.push(u);
    const Eigen::Index n_fp = 2 * (r() + 1);
    const auto f = theta.template segment<kCoeffs>(0, r() + 1);
    const auto p = theta.template segment<kCoeffs>(r() + 1, r() + 1);
    // A fixed-size clear where the degree is fixed: GCC clears a run-time-sized head with `rep stos`,
    // whose start-up cost was about a quarter of this step's time at the paper's orders.
    if constexpr (kCoeffs != Eigen::Dynamic) {
      m_dx.template head<2 * kCoeffs>().setZero();
    } else {
      m_dx.head(n_fp).setZero();
    }
    Scalar x = Scalar(0);
    for (Eigen::Index i = 0; i <= nb(); ++i) {
      Scalar w = Scalar(0);
      if (m_k - m_nk - i >= 0) {
        const Scalar u_lag = m_u[m_nk + i];
        const Scalar b = i == 0 ? Scalar(1) : theta[n_fp + i - 1];
        const Scalar h = input_switch(u_lag);
        Scalar power = Scalar(1);
        for (Eigen::Index l = 0; l <= r(); ++l) {
          m_dx[l] += b * power;
          m_dx[r() + 1 + l] += b * h * power;
          w += power * (f[l] + h * p[l]);
          power *= u_lag;
        }
        x += b * w;
      }
      if (i > 0) m_dx[n_fp + i - 1] = w;
    }
    x += m_lags.apply(theta.template segment<Na>(n_fp + nb(), na()), m_dx, n_fp + nb());
    m_x = x;
    return x;
  }

  /// d x(k) / d theta_front of the last step().
  const Sensitivity& sensitivity() const noexcept { return m_dx; }
  /// x(k) of the last step().
  Scalar x() const noexcept { return m_x; }

  /// Stores the last step's x(k) and its sensitivity as the newest lag.
  void commit() noexcept {
    m_lags.push(m_x, m_dx);
    if (m_k < m_nk + nb() + 1) ++m_k;  // only "before or after the record start" matters
  }
  /// After the estimate's front moved by `delta`: the stored lags to first order (SimulatedLags).
  template <typename Delta>
  void correct(const Delta& delta) noexcept {
    m_lags.correct(delta);
  }

  /// Is the linear block's denominator in `theta` stable, all poles inside |z| < radius?
  template <typename Theta>
  bool stable(const Theta& theta, Scalar radius) noexcept {
    return roots_inside(theta.template segment<Na>(2 * (r() + 1) + nb(), na()), radius, m_work);
  }

 private:
  Eigen::Index na() const noexcept { return Na == Eigen::Dynamic ? m_na : Na; }
  Eigen::Index nb() const noexcept { return Nb == Eigen::Dynamic ? m_nb : Nb; }
  Eigen::Index r() const noexcept { return R == Eigen::Dynamic ? m_r : R; }

  Eigen::Index m_na = 0, m_nb = 0, m_nk = 0, m_r = 0;
  History<Scalar> m_u;  // capacity nk + nb + 1: nk is a run-time order
  SimulatedLags<Scalar, Na, kFront> m_lags;
  Sensitivity m_dx;
  Eigen::Matrix<Scalar, Na, 1> m_work;  // for the stability test
  Scalar m_x = Scalar(0);
  Eigen::Index m_k = 0;
};

}  // namespace bonl::detail
