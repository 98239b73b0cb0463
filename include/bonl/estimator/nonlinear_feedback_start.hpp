#pragma once
// Where identify() starts a feedback model (nonlinear feedback, Bouc-Wen feedback) besides its
// recursive estimates: with the loop open. The recursive estimates fit the feedback with the measured output in the
// loop; in a free run the loop sees the model's own output, and a stiffening feedback (a cubic spring) can then diverge
// from every recursive estimate (on Silverbox with three feedback taps all of them did), which left
// the refinement nothing to start from. The open loop (the records' best linear approximation, no
// feedback) simulates like a stable linear model, so the refinement always has a finite start, and
// Levenberg-Marquardt closes the loop from there.
//
// A drive whose position integrates a velocity that the feedback sees (ni = 1, nv = 1) also starts
// from its velocity: the same structure without the integrator, the feedback of its own output,
// identified on the records' first differences. Its free-run error does not integrate, so it is not
// dominated by the drift that any error of the velocity's level adds up to in the position; the
// position model with the velocity model's parameters simulates the same differences, integrated.

#include <Eigen/Core>

#include <cstddef>
#include <vector>

#include "../error.hpp"
#include "best_linear_approximation.hpp"
#include "identify.hpp"
#include "record_view.hpp"

namespace bonl {

/// identify()'s start with the loop open, for a feedback model (NonlinearFeedback, BoucWenFeedback:
/// the model's identify_starts): the records' best linear approximation as its linear block (its
/// orders, delay and integrators), every other coefficient 0 (the feedback's block D = q^-1). The
/// records are deviations from the operating point. None where the fit broke down numerically.
/// \param structure the orders (and any structure of the feedback: knots, thresholds)
/// \param records the identification records, deviations from the operating point, checked
/// \param linear_iterations the Levenberg-Marquardt iterations of the best linear approximation
/// \return the start, or none
template <class Model>
std::vector<Model> open_loop_starts(const Model& structure, const CheckedRecords<typename Model::Scalar>& records,
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

/// identify()'s start for a NonlinearFeedback model (the model's identify_starts): the loop open
/// (open_loop_starts); and with ni = 1 and nv = 1 the velocity model identified on the records' first
/// differences. A start whose fit broke down numerically is left out.
/// \param structure the orders, knots and thresholds
/// \param records the identification records, deviations from the operating point, checked
/// \param linear_iterations the Levenberg-Marquardt iterations of the best linear approximation
/// \return the starts, possibly none
template <class Model>
std::vector<Model> nonlinear_feedback_starts(const Model& structure,
                                             const CheckedRecords<typename Model::Scalar>& records,
                                             int linear_iterations = 100) {
  std::vector<Model> starts = open_loop_starts(structure, records, linear_iterations);
  if (structure.ni() == 1 && structure.nv() == 1) {
    // The first differences from rest (y(-1) = 0: the records are deviations from the operating point).
    using VectorX = typename Model::VectorX;
    std::vector<VectorX> inputs, differences;
    for (const auto& record : records) {
      VectorX dy = record.y;
      dy.tail(dy.size() - 1) -= record.y.head(dy.size() - 1);
      inputs.emplace_back(record.u);
      differences.push_back(std::move(dy));
    }
    Records<typename Model::Scalar> velocity_records;
    for (std::size_t i = 0; i < inputs.size(); ++i) velocity_records.emplace_back(inputs[i], differences[i]);
    Model velocity(structure.na(), structure.nb(), structure.nk(), structure.r(), structure.nh(), structure.nd(), 0, 0);
    velocity.set_knots(structure.knots());
    try {
      velocity = identify(velocity, velocity_records);  // new numbers (the outputs' differences): checked there
      Model position = structure;
      position.set_theta(velocity.theta());
      starts.push_back(position);
    } catch (const NumericalError&) {
    }
  }
  return starts;
}

}  // namespace bonl
