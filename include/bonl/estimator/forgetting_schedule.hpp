#pragma once
// Forgetting factor over time. The paper uses 0.98 for the first 200 samples (forget the poor
// start quickly) and 1 afterwards (least sensitive to disturbances).

#include <Eigen/Core>
#include <cmath>
#include <string>

#include "../detail/validate.hpp"

namespace bonl {

struct ForgettingSchedule {
  double initial = 0.98;               ///< lambda for samples 0 .. initial_samples - 1
  Eigen::Index initial_samples = 200;  ///< how long `initial` applies
  double final = 1.0;                  ///< lambda afterwards

  static ForgettingSchedule paper() { return {}; }
  static ForgettingSchedule constant(double lambda) { return {lambda, 0, lambda}; }

  double at(Eigen::Index sample) const noexcept { return sample < initial_samples ? initial : final; }

  void validate() const {
    const auto in_range = [](double lambda) { return std::isfinite(lambda) && lambda > 0.0 && lambda <= 1.0; };
    detail::require(in_range(initial), "forgetting factor must be in (0, 1], got " + std::to_string(initial));
    detail::require(in_range(final), "forgetting factor must be in (0, 1], got " + std::to_string(final));
    detail::require(initial_samples >= 0, "forgetting schedule: initial_samples must be >= 0");
  }
};

}  // namespace bonl
