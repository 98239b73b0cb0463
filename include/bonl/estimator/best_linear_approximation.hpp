#pragma once
// The best linear approximation (BLA) of records: the linear output-error model that simulates them
// best. The nonlinear models' identify() starts that need a linear model of the data (the
// Wiener-Hammerstein model's split, the nonlinear-feedback model's loop opened) take it from here.

#include <Eigen/Core>

#include "../models/arx.hpp"
#include "estimate_recursively.hpp"
#include "identify_options.hpp"
#include "method.hpp"
#include "output_error.hpp"
#include "record_view.hpp"

namespace bonl {
namespace detail {

/// The BLA: a linear output-error model (ARX structure: least squares by the recursive estimator,
/// then refined on the simulation error) of the records, with `ni` integrators. Throws NumericalError
/// where the least squares broke down.
template <typename Scalar>
ARX<Scalar> best_linear_approximation(const CheckedRecords<Scalar>& records, Eigen::Index na, Eigen::Index nb,
                                      Eigen::Index nk, int iterations, Eigen::Index ni = 0) {
  IdentifyOptions least_squares;
  least_squares.method = Method::EquationError;
  const ARX<Scalar> arx = estimate_recursively(ARX<Scalar>(na, nb, nk, ni), records, least_squares);
  return refine_output_error(std::vector<ARX<Scalar>>{arx}, records, iterations);
}

}  // namespace detail
}  // namespace bonl
