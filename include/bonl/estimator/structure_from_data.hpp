#pragma once
// A structure with what its model leaves to the data placed from the records, by the rule identify()
// uses for its extra start: for a caller that identifies with one structure throughout (the paper's
// experiment), so that every method and the recursive estimate alone (Method::Paper,
// refine_iterations = 0), which never see identify's extra starts, use the same placement. A model
// that places something from the data has an overload here, beside its rule; for every other model
// the structure is returned as it is.

#include "../models/prandtl_ishlinskii_hammerstein.hpp"
#include "play_thresholds.hpp"
#include "record_view.hpp"

namespace bonl {

/// `structure` as it is: its model leaves nothing to the data.
/// \param structure the model
/// \return a copy of structure
template <class Model>
Model structure_from_data(const Model& structure, const Records<typename Model::Scalar>& /*records*/) {
  return structure;
}

/// The Prandtl-Ishlinskii Hammerstein model: its plays' thresholds placed by the data rule over the
/// records' inputs (with_thresholds_from_data, identify's extra start), its parameters untouched.
/// The records' inputs in the structure's units (the half-range does not depend on the operating point).
/// \param structure the model
/// \param records the records, each an input u and measured output y of equal length
/// \return a copy of structure with the new thresholds
template <typename Scalar, int Na, int Nb, int R, int Np>
PrandtlIshlinskiiHammerstein<Scalar, Na, Nb, R, Np> structure_from_data(
    const PrandtlIshlinskiiHammerstein<Scalar, Na, Nb, R, Np>& structure, const Records<Scalar>& records) {
  return with_thresholds_from_data(structure, records);
}

}  // namespace bonl
