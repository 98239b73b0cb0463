#pragma once
// The hinges of the Wiener-Hammerstein model's static nonlinearity, its piecewise-linear part:
//   sum_{j=1..nh} g_j h(x - knot_j),  h = max(0, x - knot) for knot > 0 (right of the knot),
//                                        min(0, x - knot) for knot < 0 (left of it),
// each zero on the side of its knot where 0 lies, so that the nonlinearity keeps w(0) = 0 and slope
// f_1 = 1 at 0 (hence no knot at 0: the slope there is the normalisation's). The slope changes by g_j
// outward of knot j. The hinges are homogeneous of degree one, h_{s knot}(s x) = s h_knot(x) for
// s > 0, so the model in other units is the same model with its knots scaled as x (rescaled()). The
// g_j are entries of theta (from index `first` on); the knots are structure, copied in at construction.

#include <Eigen/Core>

#include <algorithm>
#include <string>

#include "../../detail/validate.hpp"

namespace bonl::detail {

template <typename Scalar, int Nh = Eigen::Dynamic>
class HingeTerms {
 public:
  using Knots = Eigen::Matrix<Scalar, Nh, 1>;

  HingeTerms(const Knots& knots, Eigen::Index first) : m_knots(knots), m_first(first) {}

  /// A model's knots before they are set: -floor(nh/2)..-1, 1..ceil(nh/2) (in the units of what the
  /// hinges see).
  static Knots default_knots(Eigen::Index nh) {
    Knots knots(nh);
    for (Eigen::Index j = 0; j < nh; ++j) {
      const Eigen::Index position = j - nh / 2;  // -floor(nh/2)..ceil(nh/2) - 1; 0 and up move up one
      knots[j] = static_cast<Scalar>(position < 0 ? position : position + 1);
    }
    return knots;
  }
  /// What a model's set_knots() accepts: nh finite entries, strictly increasing, none at 0
  /// (`why_not_zero` says why, in the model's terms); otherwise std::invalid_argument.
  template <typename T>
  static void require_valid(const Eigen::MatrixBase<T>& knots, Eigen::Index nh, const char* why_not_zero) {
    require_size(knots, nh, "knots");
    require_finite(knots, "knots");
    const Eigen::Index j = first_not_increasing_or_zero(knots);
    if (j >= 0 && knots[j] == 0) {
      fail(std::string("knots must not hold 0 (") + why_not_zero + "), got 0 at index " + std::to_string(j));
    }
    if (j >= 0) {
      fail("knots must be strictly increasing, got " + format_number(double(knots[j - 1])) + " before " +
           format_number(double(knots[j])) + " at index " + std::to_string(j));
    }
  }

  /// h(x - knot): zero between 0 and the knot, x - knot beyond it.
  static Scalar hinge(Scalar x, Scalar knot) noexcept {
    return knot > Scalar(0) ? std::max(Scalar(0), x - knot) : std::min(Scalar(0), x - knot);
  }
  /// Is x beyond the knot (where the hinge's slope is 1)?
  static bool beyond(Scalar x, Scalar knot) noexcept { return knot > Scalar(0) ? x > knot : x < knot; }

  Eigen::Index size() const noexcept { return m_knots.size(); }

  /// w plus the hinges' part at x.
  template <typename Theta>
  Scalar add_output(const Theta& theta, Scalar x, Scalar w) const noexcept {
    for (Eigen::Index j = 0; j < m_knots.size(); ++j) w += theta[m_first + j] * hinge(x, m_knots[j]);
    return w;
  }
  /// The slope of the hinges' part at x (its one-sided value beyond a knot).
  template <typename Theta>
  Scalar slope(const Theta& theta, Scalar x) const noexcept {
    Scalar slope = Scalar(0);
    for (Eigen::Index j = 0; j < m_knots.size(); ++j) {
      if (beyond(x, m_knots[j])) slope += theta[m_first + j];
    }
    return slope;
  }
  /// The regressor's (and the output-error sensitivity's) g entries: h_j(x).
  template <typename Phi>
  void regress(Scalar x, Phi& phi) const noexcept {
    for (Eigen::Index j = 0; j < m_knots.size(); ++j) phi[m_first + j] = hinge(x, m_knots[j]);
  }
  /// weight * h_j(x) added into out's g entries (a sum of hinge regressors over several x).
  template <typename Out>
  void add_regressor(Scalar x, Scalar weight, Out& out) const noexcept {
    for (Eigen::Index j = 0; j < m_knots.size(); ++j) out[m_first + j] += weight * hinge(x, m_knots[j]);
  }

 private:
  Knots m_knots;
  Eigen::Index m_first;  // the index of g_1 in theta
};

}  // namespace bonl::detail
