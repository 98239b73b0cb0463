#pragma once
// Where identify() places the plays of a Prandtl-Ishlinskii Hammerstein model when their thresholds
// are not the structure's: the data rule PlayOperators::spread_thresholds, r_i = i / (np + 1) of the
// half-range (max - min) / 2 of the records' inputs (deviations from the operating point). Evenly
// spread over the range the plays can turn in, as the Wiener-Hammerstein knots are spread over the
// data's quantiles; a play whose threshold is beyond the half-range never turns and would estimate
// nothing. The structure's own thresholds (given by the user or a model file) stay one of identify's
// starts: its recursive estimates keep them, and the refinement returns whichever start simulates
// the records better.

#include <Eigen/Core>

#include <algorithm>
#include <limits>
#include <vector>

#include "../error.hpp"
#include "estimate_recursively.hpp"
#include "identify_options.hpp"
#include "record_view.hpp"

namespace bonl {

/// The thresholds the data rule gives np plays over the records' inputs.
/// \param structure the model; only its np is read
/// \param records the records, each an input u and measured output y of equal length
/// \return r_1..r_np, in the units of u
template <class Model>
typename Model::Thresholds play_thresholds_from_data(const Model& structure,
                                                     const Records<typename Model::Scalar>& records) {
  using Scalar = typename Model::Scalar;
  Scalar low = std::numeric_limits<Scalar>::infinity(), high = -low;
  for (const auto& record : records) {
    if (record.u.size() == 0) continue;
    low = std::min(low, record.u.minCoeff());
    high = std::max(high, record.u.maxCoeff());
  }
  return Model::Plays::spread_thresholds(structure.np(), (high - low) / Scalar(2));
}

/// `structure` with its plays' thresholds placed by the data rule over the records' inputs, its
/// parameters untouched.
/// \param structure the model
/// \param records the records, each an input u and measured output y of equal length
/// \return a copy of structure with the new thresholds
template <class Model>
Model with_thresholds_from_data(const Model& structure, const Records<typename Model::Scalar>& records) {
  Model placed = structure;
  placed.set_thresholds(play_thresholds_from_data(structure, records));
  return placed;
}

/// identify()'s start for a PrandtlIshlinskiiHammerstein model beside its recursive estimates (the
/// model's identify_starts): the structure with the data rule's thresholds, estimated recursively
/// (Method::OutputError). None where the structure already has those thresholds (its own recursive
/// estimates are that start) or the recursion broke down.
/// \param structure the model's orders and thresholds
/// \param records the identification records, deviations from the operating point, checked
/// \return zero or one start
template <class Model>
std::vector<Model> prandtl_ishlinskii_starts(const Model& structure,
                                             const CheckedRecords<typename Model::Scalar>& records) {
  std::vector<Model> starts;
  const Model ruled = with_thresholds_from_data(structure, records.records());
  if (ruled.thresholds() == structure.thresholds()) return starts;
  try {
    starts.push_back(estimate_recursively(ruled, records, IdentifyOptions{}));
  } catch (const NumericalError&) {
  }
  return starts;
}

}  // namespace bonl
