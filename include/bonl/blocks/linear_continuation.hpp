#pragma once
// A polynomial block fitted on the inputs a model was identified on, [low, high], says nothing beyond
// them (a cubic turns over or grows as u^3): the input blocks continue linearly from the edge there,
//   N(u) = N(e) + N'(e) (u - e),   e the edge u passed.
// The continued block is still linear in its coefficients: its basis is
//   c_l(u) = e^l + l e^(l-1) (u - e),   l = 0..r,
// so the key terms stay as they are. Inside the range (and with the infinite range, (-inf, inf),
// that a model has before it is identified) the basis is the powers u^l.

#include <Eigen/Core>

namespace bonl::detail {

/// Is u beyond [low, high] (a NaN never is)?
/// \param u the input
/// \param low the range's low end
/// \param high the range's high end
/// \return u < low or u > high
template <typename Scalar>
constexpr bool beyond_range(Scalar u, Scalar low, Scalar high) noexcept {
  return u < low || u > high;
}

/// The basis of a degree-r polynomial continued linearly beyond [low, high] (the file's header):
/// out[l] = c_l(u) for l = 0..r, the powers u^l inside the range.
/// \param u the input
/// \param r the degree, >= 0
/// \param low the range's low end (-inf: none)
/// \param high the range's high end (inf: none)
/// \param out set to r + 1 entries
template <typename Scalar, typename Out>
void continued_powers(Scalar u, Eigen::Index r, Scalar low, Scalar high, Out& out) noexcept {
  const bool beyond = beyond_range(u, low, high);
  const Scalar edge = beyond ? (u > high ? high : low) : u;
  const Scalar step = u - edge;                    // 0 inside: the powers of u
  Scalar power = Scalar(1), previous = Scalar(0);  // e^l and e^(l-1)
  for (Eigen::Index l = 0; l <= r; ++l) {
    out[l] = power + static_cast<Scalar>(l) * previous * step;
    previous = power;
    power *= edge;
  }
}

}  // namespace bonl::detail
