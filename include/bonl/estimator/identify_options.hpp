#pragma once
// What identify() is told: the recursive estimator's options, its passes, the refinement, the data's
// units, where the operating point comes from, and the refinement's window and initial state.

#include "initial_state.hpp"
#include "recursive_estimator.hpp"

namespace bonl {

/// Where identify() takes the model's operating point (u0, y0) from: the structure's (the default),
/// the mean input and output over all records, or the first sample of the first record (the record
/// starts at rest there, as the cascaded tanks' records do).
enum class OperatingPointSource { Structure, Mean, Initial };

/// The name of an operating-point source, as Python and the command line spell it: "structure", "mean",
/// "initial".
/// \param source the source
/// \return the name, a string literal
inline const char* to_string(OperatingPointSource source) {
  switch (source) {
    case OperatingPointSource::Mean: return "mean";
    case OperatingPointSource::Initial: return "initial";
    case OperatingPointSource::Structure: break;
  }
  return "structure";
}

/// What identify() is told: the recursive estimator's options (the base, whose `normalise` says
/// whether the data are normalised), its passes over the records, the refinement's iterations, where
/// the operating point comes from, and the refinement's state-initialisation window.
struct IdentifyOptions : EstimatorOptions {
  int passes = 1;               ///< passes of the recursive estimator over the record (paper's step 5)
  int refine_iterations = 100;  ///< Levenberg-Marquardt iterations of the refinement (0: none)
  OperatingPointSource operating_point =
      OperatingPointSource::Structure;  ///< where the operating point (u0, y0) comes from
  /// Where identify refines: each record's free run starts after its first initialisation_window
  /// samples, measured, which set the model's state (Model::simulate's past), and is scored after
  /// them, rather than from rest over the whole record: the model is fitted the way a protocol with a
  /// state-initialisation window of that many samples uses it (records that do not start at rest; an
  /// integrating plant, whose position keeps any transient of the start). 0: from rest.
  Eigen::Index initialisation_window = 0;
  /// After an initialisation window, where each record's state at its end comes from: the window's
  /// measured outputs (the default), or estimated beside the parameters (InitialState::Estimated,
  /// for records that start in motion under output noise; needs initialisation_window > 0).
  InitialState initial_state = InitialState::Measured;
};

}  // namespace bonl
