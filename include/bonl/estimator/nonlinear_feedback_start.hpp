#pragma once
// Where identify() starts a nonlinear-feedback model besides its recursive estimates: with the loop
// open. The recursive estimates fit the feedback with the measured output in the loop; in a free run
// the loop sees the model's own output, and a stiffening feedback (a cubic spring) can then diverge
// from every recursive estimate (on Silverbox with three feedback taps all of them did), which left
// the refinement nothing to start from. The open loop (the records' best linear approximation, no
// feedback) simulates like a stable linear model, so the refinement always has a finite start, and
// Levenberg-Marquardt closes the loop from there.

#include <vector>

#include "../error.hpp"
#include "best_linear_approximation.hpp"
#include "record_view.hpp"

namespace bonl {

/// identify()'s start for a NonlinearFeedback model (the model's identify_starts): the records' best
/// linear approximation as its linear block (its orders, delay and integrators), the feedback's
/// coefficients 0 and its block D = q^-1. The records are deviations from the operating point. Empty
/// where the linear least squares broke down.
template <class Model>
std::vector<Model> nonlinear_feedback_starts(const Model& structure, const Records<typename Model::Scalar>& records,
                                             int linear_iterations = 100) {
  std::vector<Model> starts;
  try {
    const auto linear = detail::best_linear_approximation(records, structure.na(), structure.nb(), structure.nk(),
                                                          linear_iterations, structure.ni());
    if (!linear.theta().allFinite()) return starts;
    Model open = structure;
    open.set_theta(Model::Params::Zero(structure.num_params()));
    open.set_b(linear.b());
    open.set_a(linear.a());
    starts.push_back(open);
  } catch (const NumericalError&) {
  }
  return starts;
}

}  // namespace bonl
