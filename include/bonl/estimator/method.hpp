#pragma once

namespace bonl {

/// How the recursive estimator estimates the models' unmeasured internal variables.
enum class Method {
  /// Paper eqs. (21)-(31) as written: internal variables from the model's own free run
  /// (a priori with theta(k-1) to build the regressor, a posteriori with theta(k) to store), and the
  /// backlash switching of eqs. (30)-(31) with sgn(dx) of eq. (26). Kept as the reference.
  Paper,
  /// bonl's estimator. Recursive stage: internal variables are projected onto what the measured
  /// output allows (x = y for Hammerstein, x = q^-1(y) for H-W, x clipped to [y - c, y + c] for
  /// P-H-W), samples inside the backlash gap carry no information about theta and are skipped, and
  /// past w are recomputed with the newest theta. Whole-record identification then refines the
  /// recursive estimates by minimising the free-run simulation error (see identify.hpp).
  Default,
};

inline const char* to_string(Method method) noexcept { return method == Method::Paper ? "paper" : "default"; }

}  // namespace bonl
