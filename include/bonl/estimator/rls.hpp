#pragma once
// Recursive least squares with a forgetting factor (paper eqs. 21-23):
//   K = P phi / (lambda + phi' P phi),  theta += K (target - phi' theta),
//   P = (P - P phi phi' P / (lambda + phi' P phi)) / lambda.
// The downdate is written P -= c g g' with g = P phi and c = 1 / (lambda + phi' P phi): entry (i, j)
// is P_ij - c (g_i g_j) and (j, i) is P_ji - c (g_j g_i), equal because floating-point multiplication
// is commutative, so P stays exactly symmetric by construction without a triangular view (whose
// generic kernels cost 4x more at the paper's sizes). The paper's (I - K phi') P / lambda is the same
// matrix in exact arithmetic. (Written as h h' with h = g sqrt(c), which saves the multiplication by
// c per entry, the square root lies on the critical path and the update is slower: docs/lab/performance.md.)
// An update that would make the denominator or a diagonal entry of P non-positive, or a number
// non-finite, is refused and leaves the state untouched.
//
// Bounded covariance: with lambda < 1 and poor excitation, P grows by 1/lambda per sample in every
// direction the data do not reach (covariance wind-up: 0.98^-k overflows after ~35,000 samples).
// Forgetting is therefore reduced whenever it would lift trace(P) above `max_trace`: the divide by
// lambda becomes a divide by the largest factor that keeps the trace at the ceiling (never below 1,
// so P still never grows from the data). Directions that are excited keep being forgotten; the
// unexcited ones stop growing at the ceiling.

// Forgetting without touching P: P is stored as scale * M, so dividing P by lambda is one scalar
// multiply (scale /= lambda) instead of a pass over all n^2 entries; the downdate becomes
// M -= gain (M phi)(M phi)' with gain = scale / denominator. The scale is folded back into M (one pass)
// only when it passes 1 / epsilon, i.e. every ~1,800 samples at lambda = 0.98 and never at 1.
//
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "../detail/inlining.hpp"
#include "../detail/validate.hpp"

namespace bonl {

namespace detail {
/// Storage size of a covariance: rounded up to a multiple of 8 (4 below 5), so that every column
/// is a whole number of SIMD registers (SSE2 to AVX-512, double and float). At the paper's 14
/// parameters Eigen otherwise falls back to 2-wide packets with scalar remainders; the padding rows
/// and columns stay exactly zero (see Rls::update).
constexpr int padded_size(int n) { return n == Eigen::Dynamic ? n : (n <= 4 ? 4 : (n + 7) / 8 * 8); }

/// The scalars of an Rls's state besides M and theta.
template <typename Scalar>
struct RlsScalars {
  Scalar scale = Scalar(1);          // P = scale * M
  Scalar process_noise = Scalar(0);  // q, added to P's diagonal by every accepted update
  bool forgetting_limited = false;   // the last accepted update had its forgetting reduced
};

/// M *= scale, scale = 1 (P unchanged up to one rounding per entry, still exactly symmetric).
template <typename Storage, typename Scalar>
BONL_COLD void fold_scale(Storage& M, RlsScalars<Scalar>& state) noexcept {
  M *= state.scale;
  state.scale = Scalar(1);
}

/// After the downdate: the forgetting (P / lambda, kept in the scale) and the process noise, the
/// forgetting reduced where it would lift trace(P) above max_trace. trace_of_M is M's trace after
/// the downdate: the ceiling is applied to the trace as computed, not as trace(P) - gain |g|^2,
/// which cancels when the downdate removes most of P (a tiny lambda overshot the ceiling).
template <typename Storage, typename Scalar>
void forget(Storage& M, Eigen::Index n, Scalar trace_of_M, Scalar inverse_lambda, Scalar max_trace,
            RlsScalars<Scalar>& state) noexcept {
  Scalar trace = state.scale * trace_of_M;
  if (state.process_noise > Scalar(0)) {
    M.diagonal().head(n).array() += state.process_noise / state.scale;
    trace += Scalar(n) * state.process_noise;
  }
  Scalar growth = inverse_lambda;
  if (trace * growth > max_trace) {
    // Never grow P beyond the ceiling by forgetting; the process noise alone may take the trace a
    // hair above it (n q), which this shrinks back by as little (1 - n q / trace).
    growth = max_trace / trace;
    if (state.process_noise == Scalar(0)) growth = std::max(Scalar(1), growth);
    state.forgetting_limited = true;
  }
  if (growth != Scalar(1)) {
    state.scale *= growth;
    if (state.scale > Scalar(1) / std::numeric_limits<Scalar>::epsilon()) fold_scale(M, state);
  }
}

/// The run-time sizes' update (up to Rls::kMaxCompiledSize parameters): the same algorithm as
/// Rls::update, with every vector at the padded length kLength of M's columns, fixed at compile
/// time, and only the loops over columns depending on the number of parameters n. theta (updated
/// on success) and phi hold n entries; copied into zero-padded locals, which flattening keeps in
/// registers, their padding adds exact zeros to the products.
template <bool kGivenError, int kLength, typename Storage, typename Scalar>
BONL_FLATTEN bool rls_update_fixed_length(Storage& M, Scalar* theta, const Scalar* phi, Eigen::Index count,
                                          Scalar target_or_error, Scalar lambda, Scalar max_trace,
                                          RlsScalars<Scalar>& state) noexcept {
  using Column = Eigen::Matrix<Scalar, kLength, 1>;
  // count <= kLength always (Rls dispatches on it); the bound, known to the compiler, keeps every
  // index inside the locals (GCC warns otherwise, -Warray-bounds).
  const Eigen::Index n = std::min(count, Eigen::Index(kLength));
  // Over the whole fixed length, each entry read only below n: a loop GCC neither turns into
  // memcpy calls (a loop over the n entries became two, a sizeable share of a small update:
  // docs/lab/performance.md) nor reads past n in.
  Column padded_phi;
  Column padded_theta;
  for (Eigen::Index i = 0; i < kLength; ++i) {
    padded_phi[i] = i < n ? phi[i] : Scalar(0);
    padded_theta[i] = i < n ? theta[i] : Scalar(0);
  }
  // work = M phi, as a sum of columns, even and odd ones separately in locals: see Rls::update.
  Column even = M.col(0) * padded_phi[0];
  Column odd = Column::Zero();
  for (Eigen::Index j = 1; j + 1 < n; j += 2) {
    odd += M.col(j) * padded_phi[j];
    even += M.col(j + 1) * padded_phi[j + 1];
  }
  if (n % 2 == 0) odd += M.col(n - 1) * padded_phi[n - 1];
  const Column work = even + odd;
  const Scalar denominator = lambda + state.scale * padded_phi.dot(work);
  if (!(denominator > Scalar(0)) || !std::isfinite(denominator)) return false;
  const Scalar gain = state.scale / denominator;  // K = P phi / denominator = gain M phi
  Scalar error = target_or_error;
  if constexpr (!kGivenError) error -= padded_phi.dot(padded_theta);
  padded_theta += (error * gain) * work;
  if (!((padded_theta.array() - padded_theta.array()).sum() == Scalar(0))) return false;  // all finite
  // Each new diagonal entry must stay above a few roundings (see Rls::update). The padding entries
  // are exactly 0 (not above), so all n parameters' entries pass when n entries do; NaN passes none.
  const auto diagonal = M.diagonal().array();
  constexpr Scalar kMargin = Scalar(64) * std::numeric_limits<Scalar>::epsilon();
  if ((diagonal - gain * work.array().square() - kMargin * diagonal > Scalar(0)).count() != n) return false;
  const Scalar inverse_lambda = Scalar(1) / lambda;  // forgetting that would overflow P: see Rls::update
  if (lambda != Scalar(1) && !std::isfinite(std::min(state.scale * diagonal.sum() * inverse_lambda, max_trace))) {
    return false;
  }
  for (Eigen::Index j = 0; j < n; ++j) M.col(j) -= gain * (work * work[j]);  // exactly symmetric
  state.forgetting_limited = false;
  if (lambda != Scalar(1) || state.process_noise > Scalar(0)) {
    forget(M, n, M.diagonal().sum(), inverse_lambda, max_trace, state);
  }
  for (Eigen::Index i = 0; i < n; ++i) theta[i] = padded_theta[i];
  return true;
}

}  // namespace detail

/// Recursive least squares with a forgetting factor (eqs. 21-23): the covariance stored as scale * M
/// and downdated so that it stays exactly symmetric, its trace bounded by a ceiling (no covariance
/// wind-up), and an update that would lose positive definiteness or finiteness refused with the
/// state untouched. The header's comment gives the details; N_ fixes the size at compile time.
template <typename Scalar_ = double, int N_ = Eigen::Dynamic>
class Rls {
  static constexpr int kStorage = detail::padded_size(N_);
  using StorageVector = Eigen::Matrix<Scalar_, kStorage, 1>;
  using StorageMatrix = Eigen::Matrix<Scalar_, kStorage, kStorage>;

 public:
  using Scalar = Scalar_;                        ///< the arithmetic type
  using Vector = Eigen::Matrix<Scalar, N_, 1>;   ///< theta and the regressor phi
  using Matrix = Eigen::Matrix<Scalar, N_, N_>;  ///< the covariance P

  /// Run-time sizes up to this many parameters run a kernel with its vector lengths fixed at
  /// compile time; above it, the generic kernel.
  static constexpr int kMaxCompiledSize = 32;

  /// theta = 0, P = p0 I.
  /// \param n the number of parameters
  /// \param p0 the scale of P(0), > 0 and finite
  explicit Rls(Eigen::Index n = (N_ == Eigen::Dynamic ? 1 : N_), Scalar p0 = Scalar(1e6)) {
    detail::require_order(n, 1, "number of parameters");
    detail::require_matches_template(n, N_, "number of parameters");
    m_theta = Vector::Zero(n);
    if (N_ == Eigen::Dynamic && n > kMaxCompiledSize) {  // scratch for the generic kernel
      m_next = Vector::Zero(n);
      m_scratch = StorageVector::Zero(storage_size(n));
    }
    m_M = StorageMatrix::Zero(storage_size(n), storage_size(n));
    reset(m_theta, p0);
  }

  /// theta = theta0, P = p0 I (p0 > 0 and finite).
  /// \param theta0 the estimate to start from, size() values
  /// \param p0 the scale of P
  template <typename T>
  void reset(const Eigen::MatrixBase<T>& theta0, Scalar p0) {
    detail::require_size(theta0, m_theta.size(), "theta0");
    detail::require_finite(theta0, "theta0");
    check_p0(p0);
    m_theta = theta0;
    reset_covariance(p0);
  }

  /// P = p0 I (p0 > 0 and finite), theta kept: a covariance reset.
  /// Allocation-free when P already has its size (the message is built only when it throws).
  /// \param p0 the scale of P
  void reset_covariance(Scalar p0) {
    check_p0(p0);
    m_M.setZero();  // keeps its size: no allocation
    m_M.diagonal().template head<N_>(size()).setConstant(p0);
    m_state.scale = Scalar(1);
  }

  /// theta and P given, as they are (P symmetric positive definite of this size, theta finite: the
  /// caller's to ensure): the estimate swapped for another one, with the covariance that goes with
  /// it (the window refinement's). Allocation-free; the padding of the storage stays zero.
  /// \param theta the new estimate, size() values
  /// \param P its covariance, size() x size()
  template <typename T, typename C>
  void assign(const Eigen::MatrixBase<T>& theta, const Eigen::MatrixBase<C>& P) noexcept {
    m_theta = theta;
    m_M.topLeftCorner(size(), size()) = P;
    m_state.scale = Scalar(1);
  }

  /// One update; forgetting is reduced where it would lift trace(P) above max_trace (see the top of
  /// this file).
  /// \param phi the regressor, size() values
  /// \param target the measured target y of phi' theta
  /// \param lambda the forgetting factor, in (0, 1]
  /// \param max_trace the ceiling on trace(P); infinity: none
  /// \return true when theta and P were updated; false, with both untouched, when the update is
  /// numerically unsafe
  template <typename Phi>
  bool update(const Eigen::MatrixBase<Phi>& phi, Scalar target, Scalar lambda,
              Scalar max_trace = std::numeric_limits<Scalar>::infinity()) noexcept {
    return dispatch<false>(phi, target, lambda, max_trace);
  }

  /// The same update given the prediction error e = target - phi' theta itself: for a regressor that
  /// is a gradient (the output-error method), where there is no target.
  /// \param phi the regressor, size() values
  /// \param error the prediction error e
  /// \param lambda the forgetting factor, in (0, 1]
  /// \param max_trace the ceiling on trace(P); infinity: none
  /// \return true when theta and P were updated; false, with both untouched, when the update is
  /// numerically unsafe
  template <typename Phi>
  bool update_with_error(const Eigen::MatrixBase<Phi>& phi, Scalar error, Scalar lambda,
                         Scalar max_trace = std::numeric_limits<Scalar>::infinity()) noexcept {
    return dispatch<true>(phi, error, lambda, max_trace);
  }

  /// Process noise: every accepted update adds q I to P (a random walk of the parameters). A small q
  /// keeps P's smallest eigenvalue above the round-off of the rank-1 downdates, which otherwise
  /// drives a P whose condition number passes 1 / epsilon indefinite. q >= 0 and finite; 0 (the
  /// default) is the algorithm as written.
  /// \param q the variance added to each diagonal entry of P per update
  void set_process_noise(Scalar q) {
    detail::require(std::isfinite(q) && q >= Scalar(0), "process noise must be finite and >= 0");
    m_state.process_noise = q;
  }

  /// True when the last accepted update had its forgetting reduced by the trace ceiling.
  /// \return true or false, for the last accepted update
  bool forgetting_limited() const noexcept { return m_state.forgetting_limited; }

  const Vector& theta() const noexcept { return m_theta; }  ///< the estimate theta \return size() values
  /// For projections after an update (e.g. a constraint on one parameter).
  /// \return a reference to theta, which the caller may change
  Vector& mutable_theta() noexcept { return m_theta; }
  /// The covariance (exactly symmetric).
  /// \return a copy of P, size() x size()
  Matrix covariance() const { return m_state.scale * m_M.template topLeftCorner<N_, N_>(size(), size()); }
  Eigen::Index size() const noexcept { return m_theta.size(); }  ///< the number of parameters \return n

 private:
  static void check_p0(Scalar p0) {
    if (!(std::isfinite(p0) && p0 > Scalar(0))) {
      throw std::invalid_argument("bonl: p0 (initial covariance scale) must be finite and > 0");
    }
  }

  static Eigen::Index storage_size(Eigen::Index n) { return detail::padded_size(int(n)); }

  template <bool kGivenError, typename Phi>
  bool dispatch(const Eigen::MatrixBase<Phi>& phi, Scalar target_or_error, Scalar lambda, Scalar max_trace) noexcept {
    if constexpr (N_ == Eigen::Dynamic) {
      // Run-time sizes up to 32 parameters run the kernel of their storage length, fixed at compile
      // time: whole SIMD registers and locals in registers, what makes the fixed sizes fast. Five
      // lengths cover 1 to 32 parameters; a kernel per exact size compiled 32 of them, which came to
      // dominate the build of every translation unit using a run-time size (docs/lab/performance.md).
      // Above 32, the generic kernel.
      // One case per padded length up to kMaxCompiledSize: the constructor allocates the generic
      // kernel's scratch only above it, so a length without its case here would run on none.
      static_assert(detail::padded_size(kMaxCompiledSize) == 32,
                    "a case for every padded length up to kMaxCompiledSize");
      switch (m_M.rows()) {
        case 4: return fixed_length_update<kGivenError, 4>(phi, target_or_error, lambda, max_trace);
        case 8: return fixed_length_update<kGivenError, 8>(phi, target_or_error, lambda, max_trace);
        case 16: return fixed_length_update<kGivenError, 16>(phi, target_or_error, lambda, max_trace);
        case 24: return fixed_length_update<kGivenError, 24>(phi, target_or_error, lambda, max_trace);
        case 32: return fixed_length_update<kGivenError, 32>(phi, target_or_error, lambda, max_trace);
        default: return update<kGivenError>(m_M, m_theta, phi, target_or_error, lambda, max_trace, m_scratch, m_next);
      }
    } else {
      StorageVector work;  // on the stack; as locals they cannot alias phi, which keeps them in registers
      Vector next;
      return update<kGivenError>(m_M, m_theta, phi, target_or_error, lambda, max_trace, work, next);
    }
  }

  /// A run-time size's update with the storage length kLength fixed at compile time. The kernel
  /// takes phi's entries by pointer, so that one kernel serves every regressor type.
  template <bool kGivenError, int kLength, typename Phi>
  bool fixed_length_update(const Eigen::MatrixBase<Phi>& phi, Scalar target_or_error, Scalar lambda,
                           Scalar max_trace) noexcept {
    // m_M's data come from Eigen's allocator, aligned to EIGEN_MAX_ALIGN_BYTES.
    Eigen::Map<Eigen::Matrix<Scalar, kLength, kLength>, Eigen::AlignedMax> storage(m_M.data());
    if constexpr (bool(Phi::Flags & Eigen::DirectAccessBit) && Phi::InnerStrideAtCompileTime == 1) {
      return detail::rls_update_fixed_length<kGivenError, kLength>(storage, m_theta.data(), phi.derived().data(),
                                                                   size(), target_or_error, lambda, max_trace, m_state);
    } else {
      const Eigen::Matrix<Scalar, Eigen::Dynamic, 1, 0, kLength, 1> entries = phi;  // no allocation
      return detail::rls_update_fixed_length<kGivenError, kLength>(storage, m_theta.data(), entries.data(), size(),
                                                                   target_or_error, lambda, max_trace, m_state);
    }
  }

  /// The update of the covariance storage M and theta, for fixed sizes and for run-time sizes above
  /// kMaxCompiledSize; work has the length of M's columns, next the length of theta.
  template <bool kGivenError, typename Storage, typename Theta, typename Phi, typename Work, typename Next>
  BONL_FLATTEN bool update(Storage& M, Theta& theta, const Eigen::MatrixBase<Phi>& phi, Scalar target_or_error,
                           Scalar lambda, Scalar max_trace, Work& work, Next& next) noexcept {
    constexpr int kN = Next::RowsAtCompileTime;  // the number of parameters, where known at compile time
    const Eigen::Index n = theta.size();
    // work = M phi, as a sum of columns: vectorised axpys over whole (padded) columns, no horizontal
    // reductions. The padding rows of M are zero, so work's padding is zero too. Fixed sizes sum even
    // and odd columns separately, in locals: two dependency chains of n / 2 fused multiply-adds in
    // registers instead of one of n through `work`, a reference (a store and a reload per step).
    // Run-time sizes above kMaxCompiledSize keep the one chain: a local of run-time length would
    // allocate.
    if constexpr (kN == Eigen::Dynamic) {
      work = M.col(0) * phi[0];
      for (Eigen::Index j = 1; j < n; ++j) work += M.col(j) * phi[j];
    } else {
      Work even = M.col(0) * phi[0];  // locals: kept in registers
      Work odd = Work::Zero();
      for (Eigen::Index j = 1; j + 1 < n; j += 2) {
        odd += M.col(j) * phi[j];
        even += M.col(j + 1) * phi[j + 1];
      }
      if (n % 2 == 0) odd += M.col(n - 1) * phi[n - 1];
      work = even + odd;
    }
    const auto g = work.template head<kN>(n);
    const Scalar denominator = lambda + m_state.scale * phi.dot(g);
    if (!(denominator > Scalar(0)) || !std::isfinite(denominator)) return false;
    const Scalar gain = m_state.scale / denominator;  // K = P phi / denominator = gain M phi
    Scalar error = target_or_error;
    if constexpr (!kGivenError) error -= phi.dot(theta);
    next = theta + (error * gain) * g;
    // All finite: x - x is 0 for a finite x and NaN otherwise, so the sum is exactly 0 when every entry
    // is finite (a vectorised reduction; allFinite() tests and branches entry by entry).
    if (!((next.array() - next.array()).sum() == Scalar(0))) return false;
    // The downdate is M -= gain g g'. Each new diagonal entry M_ii - gain g_i^2 must stay above a few
    // roundings of M_ii: below that the subtraction has cancelled and what is left is round-off (a
    // direction pinned down beyond P's resolution, e.g. one input of 1e5 with P(0) = 1e6 I, left
    // P_00 = 0 exactly and "Updated"; found by fuzzing).
    const auto diagonal = M.diagonal().template head<kN>(n).array();
    constexpr Scalar kMargin = Scalar(64) * std::numeric_limits<Scalar>::epsilon();
    if (!((diagonal - gain * g.array().square() - kMargin * diagonal).minCoeff() > Scalar(0))) return false;
    // Forgetting would overflow P (possible only without a ceiling: the trace can only fall by the
    // downdate, so trace(P) / lambda bounds it). Tested with 1 / lambda, the factor P is scaled by:
    // for a denormal lambda it is infinite although trace / lambda is not (found by fuzzing).
    const Scalar inverse_lambda = Scalar(1) / lambda;
    if (lambda != Scalar(1) && !std::isfinite(std::min(m_state.scale * diagonal.sum() * inverse_lambda, max_trace))) {
      return false;
    }
    theta = next;
    // Column by column (only the n used ones): entry (i, j) is M_ij - gain (g_i g_j) and (j, i) is
    // M_ji - gain (g_j g_i), the same number because multiplication is commutative.
    for (Eigen::Index j = 0; j < n; ++j) M.col(j) -= gain * (work * work[j]);
    m_state.forgetting_limited = false;
    if (lambda != Scalar(1) || m_state.process_noise > Scalar(0)) {
      detail::forget(M, n, M.diagonal().template head<kN>(n).sum(), inverse_lambda, max_trace, m_state);
    }
    return true;
  }

  Vector m_theta;
  StorageMatrix m_M;  // P / scale in the top-left n x n corner, zero padding to padded_size(n)
  detail::RlsScalars<Scalar> m_state;
  Vector m_next;            // scratch for the generic kernel (run-time sizes above kMaxCompiledSize)
  StorageVector m_scratch;  // scratch for the generic kernel (run-time sizes above kMaxCompiledSize)
};

}  // namespace bonl
