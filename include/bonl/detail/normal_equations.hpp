#pragma once
// Jacobian rows gathered into the Gauss-Newton normal equations J'J and J'e a block at a time: one
// matrix product per block instead of a rank-one update per sample (about three times faster at the
// paper's 14 parameters). Shared by the offline refinement (estimator/output_error.hpp) and the
// online window refinement (estimator/window_refinement.hpp).

#include <Eigen/Core>

namespace bonl::detail {

/// normal += rows' rows (its lower triangle only) and gradient += rows' errors. An empty block adds
/// nothing and is not handed to Eigen: its rank update of an empty block divides by zero (SIGFPE)
/// from about 48 columns on, which a record whose length is a multiple of the block size reached.
/// \param normal J'J so far, n x n; its lower triangle is updated
/// \param gradient J'e so far, n entries
/// \param rows the block's Jacobian rows, one per sample, n columns
/// \param errors the block's errors, one per row
template <typename Normal, typename Gradient, typename Rows, typename Errors>
void add_rows(Normal& normal, Gradient& gradient, const Rows& rows, const Errors& errors) {
  if (rows.rows() == 0) return;
  normal.template selfadjointView<Eigen::Lower>().rankUpdate(rows.transpose());
  gradient.noalias() += rows.transpose() * errors;
}

}  // namespace bonl::detail
