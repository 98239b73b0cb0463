#pragma once
// Stability of a linear block's denominator A = 1 + a_1 z^-1 + ... + a_na z^-na: are all its roots
// inside |z| < radius? Schur-Cohn test: the step-down (reverse Levinson) recursion turns the
// coefficients into reflection coefficients k_na, ..., k_1, and the roots are inside the unit circle
// exactly when every |k_p| < 1. The roots of A are inside |z| < radius when those of
// A(radius z) are inside the unit circle, i.e. with a_j replaced by a_j / radius^j.
// O(na^2), no allocation: the caller provides `work` with na entries.

#include <Eigen/Core>
#include <cmath>

namespace bonl::detail {

template <typename A, typename Work>
bool roots_inside(const Eigen::MatrixBase<A>& a, typename A::Scalar radius, Work& work) noexcept {
  using Scalar = typename A::Scalar;
  const Eigen::Index n = a.size();
  // One division per step: the estimator runs this on every output-error update.
  const Scalar inverse_radius = Scalar(1) / radius;
  Scalar scale = Scalar(1);
  for (Eigen::Index j = 0; j < n; ++j) {
    scale *= inverse_radius;
    work[j] = a[j] * scale;
  }
  for (Eigen::Index p = n; p >= 1; --p) {
    const Scalar k = work[p - 1];
    if (!(std::abs(k) < Scalar(1))) return false;  // also false for NaN
    const Scalar inverse = Scalar(1) / (Scalar(1) - k * k);
    // b_i <- (b_i - k b_{p-1-i}) / (1 - k^2) for i = 1..p-1 (1-based), updated in symmetric pairs.
    for (Eigen::Index low = 0, high = p - 2; low <= high; ++low, --high) {
      const Scalar b_low = work[low];
      const Scalar b_high = work[high];
      work[low] = (b_low - k * b_high) * inverse;
      work[high] = (b_high - k * b_low) * inverse;
    }
  }
  return true;
}

}  // namespace bonl::detail
