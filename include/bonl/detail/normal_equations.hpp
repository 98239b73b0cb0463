#pragma once
// Jacobian rows gathered into the Gauss-Newton normal equations J'J and J'e a block at a time: one
// matrix product per block instead of a rank-one update per sample (about three times faster at the
// paper's 14 parameters). Shared by the offline refinement (estimator/output_error.hpp) and the
// online window refinement (estimator/window_refinement.hpp).

#include <Eigen/Core>

namespace bonl::detail {

/// normal(i0.., j0..) += rows(:, i0..)' rows(:, j0..) over one fixed-size tile, the rows summed in
/// order; on the diagonal only the tile's lower triangle is added.
template <int TileRows, int TileCols, bool Diagonal, typename Normal, typename Rows>
void add_tile(Normal& normal, const Rows& rows, Eigen::Index i0, Eigen::Index j0) {
  using Scalar = typename Normal::Scalar;
  Eigen::Matrix<Scalar, TileRows, TileCols> sum = Eigen::Matrix<Scalar, TileRows, TileCols>::Zero();
  for (Eigen::Index k = 0; k < rows.rows(); ++k) {
    sum.noalias() +=
        rows.row(k).template segment<TileRows>(i0).transpose() * rows.row(k).template segment<TileCols>(j0);
  }
  if constexpr (Diagonal) {
    normal.template block<TileRows, TileCols>(i0, j0).template triangularView<Eigen::Lower>() += sum;
  } else {
    normal.template block<TileRows, TileCols>(i0, j0) += sum;
  }
}

/// Up to this many columns known at compile time, add_rows sums J'J in 4 x 4 tiles held in
/// registers: at the paper's 14 parameters and 32 rows about twice as fast as Eigen's rank update,
/// whose packing and blocking dominate at that size (bench/, docs/lab/performance.md).
inline constexpr int kTiledColumns = 32;

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
  constexpr int n = Rows::ColsAtCompileTime;
  if constexpr (n != Eigen::Dynamic && n <= kTiledColumns) {
    constexpr int full = n / 4;  // whole tiles per side; a last, narrower one holds the rest
    constexpr int rest = n % 4;
    if constexpr (full > 0) {
      for (Eigen::Index i = 0; i < full; ++i) {
        for (Eigen::Index j = 0; j < i; ++j) add_tile<4, 4, false>(normal, rows, 4 * i, 4 * j);
        add_tile<4, 4, true>(normal, rows, 4 * i, 4 * i);
      }
      if constexpr (rest > 0) {
        for (Eigen::Index j = 0; j < full; ++j) add_tile<rest, 4, false>(normal, rows, 4 * full, 4 * j);
      }
    }
    if constexpr (rest > 0) add_tile<rest, rest, true>(normal, rows, 4 * full, 4 * full);
  } else {
    normal.template selfadjointView<Eigen::Lower>().rankUpdate(rows.transpose());
  }
  gradient.noalias() += rows.transpose() * errors;
}

}  // namespace bonl::detail
