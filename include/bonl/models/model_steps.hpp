#pragma once
// What a model gives the recursive estimator each sample. Every model has two per-sample views of
// itself, each one call per sample that returns what it produced:
//   KeyTerms(model, KeyTermMethod)  step(theta, u, y) -> Regression: its key-term regressor (eq. 14
//                                   and its kin) with the internal variables estimated as the method says;
//   OutputErrorTerms(model)         step(theta, u) -> SimulationStep: one step of its free run with the
//                                   output's sensitivity to theta; accept() stores the step, and
//                                   correct(delta) moves the stored run to first order along a change
//                                   delta of the estimate (after an update, or to reuse a run's state
//                                   for another theta).
// The estimator (estimator/recursive_estimator.hpp) chooses the view from its Method; the models know
// nothing of the estimator.

#include <Eigen/Core>

#include "estimator_settings.hpp"

namespace bonl {

/// How a model's KeyTerms estimate its unmeasured internal variables (x, w).
enum class KeyTermMethod {
  /// From the measured output: x = y (Hammerstein), q^-1(y) (H-W, Wiener), x clipped to
  /// [y - c, y + c] (P-H-W), with w recomputed from the stored u with the theta of the step; the
  /// backlash's gap samples are not informative. Every step uses the theta it is given only.
  /// A y that is NaN is a sample whose output was not measured: the model's own prediction stands
  /// in for it, so that the step is one step of the free run (simulate() after an initial past).
  EquationError,
  /// The paper's eqs. (21)-(31): x and w from the model's own run, each stored a posteriori with
  /// the estimate updated since (eq. 24). So step k first stores sample k-1's x and w with the
  /// theta it is given (the estimate after update k-1), then builds sample k's regressor with it.
  Paper,
};

/// One sample's key-term regression: regressor . theta should equal target.
template <typename Scalar, typename Params>
struct Regression {
  const Params& regressor;  ///< phi(k), owned by the KeyTerms (valid until their next step)
  Scalar target;            ///< what phi(k) . theta should equal (y(k), or the paper's y_c(k))
  Scalar prediction;        ///< y(k) as the theta of the step predicts it
  Scalar internal;          ///< the model's a-priori internal variable x(k) (ARX: the prediction)
  bool informative;         ///< false: y(k) says nothing about theta (inside the backlash's gap)
};

/// One sample of a model's free run with the current estimate.
template <typename Scalar, typename Params>
struct SimulationStep {
  Scalar output;              ///< the simulated y(k)
  const Params& sensitivity;  ///< d y(k) / d theta, owned by the OutputErrorTerms (valid until their next step)
  Scalar internal;            ///< the simulated internal variable x(k) (ARX: the output)
};

}  // namespace bonl
