#pragma once
// Where identify() starts a Wiener-Hammerstein model: from the best linear approximation (BLA), after
// J. Sjoberg and J. Schoukens, "Initializing Wiener-Hammerstein models based on partitioning of the
// best linear approximation", Automatica 48(2):353-359, 2012.
//   1. The BLA: a linear output-error model z^-nk B/A with na1 + na2 poles and nb1 + nb2 zeros
//      (least squares, then Levenberg-Marquardt on the simulation error). For Gaussian-like inputs it
//      is G1 G2 times a constant (Bussgang), so its poles and zeros are the two blocks' together.
//   2. Every split of its poles and zeros between the blocks (na1 poles and nb1 zeros to the first,
//      a complex pair together; where no split can keep every pair, as for an odd na1 with only
//      pairs, the pair nearest the real axis is made two real roots at its real part) is scored: with
//      G1 and G2 fixed, y = sum_m c_m G2(x1^m) + sum_j d_j G2(h(x1 - knot_j)) with x1 = G1 u is linear
//      in the nonlinearity's coefficients, so least squares gives them and the residual is the
//      split's score. A model with hinges (nh > 0) has its knots placed at the quantiles
//      j / (nh + 1) of the split's nonzero x1, so that every slope change is fitted on as many
//      samples (as regression splines place theirs: Hastie, Tibshirani and Friedman, The Elements of
//      Statistical Learning, 2nd ed., 2009, sec. 5.2 and 9.1); the structure's own knots are not used.
//   3. The best splits, normalised (f_1 = 1, b2_0 = 1, the gain in b1), are starts of identify()'s
//      refinement on the simulation error, beside the recursive estimates (which keep the structure's
//      knots). The refinement keeps each start's knots.
// Nothing here is random: the result is a function of the data.

#include <Eigen/Core>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <optional>
#include <vector>

#include "../detail/validate.hpp"
#include "../error.hpp"
#include "../models/arx.hpp"
#include "../models/detail/hinge_terms.hpp"
#include "../models/poles.hpp"
#include "../models/wiener_hammerstein.hpp"
#include "best_linear_approximation.hpp"
#include "estimate_recursively.hpp"
#include "identify_options.hpp"
#include "method.hpp"
#include "output_error.hpp"
#include "record_view.hpp"

namespace bonl {

/// One scored split of the BLA (wiener_hammerstein_splits).
template <class Model>
struct WienerHammersteinSplit {
  Model model;        ///< the start: the split's blocks and the nonlinearity fitted by least squares
  double cost = 0.0;  ///< its mean squared residual on the records (free run, each from rest)
};

/// How many of the best splits identify() refines, beside the recursive estimates (wiener_hammerstein_starts).
inline constexpr std::size_t kWienerHammersteinStarts = 3;

namespace detail {

using Complex = std::complex<double>;

/// The roots grouped so that a complex pair stays together: each group one real root or a pair.
inline std::vector<std::vector<Complex>> root_groups(const Eigen::Matrix<Complex, Eigen::Dynamic, 1>& roots) {
  std::vector<std::vector<Complex>> groups;
  std::vector<bool> used(static_cast<std::size_t>(roots.size()), false);
  for (Eigen::Index i = 0; i < roots.size(); ++i) {
    if (used[i]) continue;
    used[i] = true;
    const Complex root = roots[i];
    if (std::abs(root.imag()) <= 1e-9 * std::max(1.0, std::abs(root))) {
      groups.push_back({Complex(root.real(), 0.0)});
      continue;
    }
    // Its conjugate: the nearest unused root (eigenvalues of a real matrix come in exact pairs).
    Eigen::Index partner = -1;
    for (Eigen::Index j = 0; j < roots.size(); ++j) {
      if (used[j]) continue;
      if (partner < 0 || std::abs(roots[j] - std::conj(root)) < std::abs(roots[partner] - std::conj(root))) partner = j;
    }
    if (partner < 0) {
      groups.push_back({Complex(root.real(), 0.0)});
      continue;
    }
    used[partner] = true;
    groups.push_back({root, std::conj(root)});
  }
  return groups;
}

/// Every subset of the groups holding `count` roots, as a mask over the groups.
inline std::vector<std::vector<bool>> subsets_of_size(const std::vector<std::vector<Complex>>& groups,
                                                      Eigen::Index count) {
  std::vector<std::vector<bool>> subsets;
  const std::size_t n = groups.size();
  if (n > 20) return subsets;  // 2^20 splits: no BLA of a sensible order has that many groups
  for (std::size_t mask = 0; mask < (std::size_t(1) << n); ++mask) {
    Eigen::Index size = 0;
    std::vector<bool> chosen(n);
    for (std::size_t g = 0; g < n; ++g) {
      chosen[g] = (mask >> g) & 1U;
      if (chosen[g]) size += static_cast<Eigen::Index>(groups[g].size());
    }
    if (size == count) subsets.push_back(chosen);
  }
  return subsets;
}

/// root_groups(roots), with complex pairs broken where no subset holds `count` roots (every root in
/// pairs and `count` odd): the pair nearest the real axis becomes two real roots at its real part,
/// then the next, until a subset of `count` roots exists.
inline std::vector<std::vector<Complex>> splittable_groups(const Eigen::Matrix<Complex, Eigen::Dynamic, 1>& roots,
                                                           Eigen::Index count) {
  auto groups = root_groups(roots);
  while (subsets_of_size(groups, count).empty()) {
    std::size_t pair = groups.size();
    for (std::size_t g = 0; g < groups.size(); ++g) {
      if (groups[g].size() == 2 &&
          (pair == groups.size() || std::abs(groups[g][0].imag()) < std::abs(groups[pair][0].imag()))) {
        pair = g;
      }
    }
    if (pair == groups.size()) break;
    const Complex real_part(groups[pair][0].real(), 0.0);
    groups[pair] = {real_part};
    groups.insert(groups.begin() + static_cast<std::ptrdiff_t>(pair) + 1, std::vector<Complex>{real_part});
  }
  return groups;
}

/// [c_1..c_n] of prod (1 - root z^-1) over the chosen (or, with `chosen` false, the other) groups.
inline Eigen::VectorXd coefficients_of(const std::vector<std::vector<Complex>>& groups, const std::vector<bool>& mask,
                                       bool chosen) {
  Eigen::Matrix<Complex, Eigen::Dynamic, 1> roots(0);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (mask[g] != chosen) continue;
    for (const Complex& root : groups[g]) {
      roots.conservativeResize(roots.size() + 1);
      roots[roots.size() - 1] = root;
    }
  }
  return monic_from_roots(roots).tail(roots.size());
}

/// The knots of nh hinges at the quantiles j / (nh + 1), j = 1..nh, of the nonzero entries of x;
/// none where they are not strictly increasing (too few distinct values); empty for nh = 0.
template <typename Vector>
std::optional<Vector> quantile_knots(const Vector& x, Eigen::Index nh) {
  if (nh == 0) return Vector(0);  // a polynomial alone: nothing to sort
  std::vector<typename Vector::Scalar> values;
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    if (x[k] != 0) values.push_back(x[k]);
  }
  if (static_cast<Eigen::Index>(values.size()) <= nh) return std::nullopt;
  std::sort(values.begin(), values.end());
  Vector knots(nh);
  const double last = static_cast<double>(values.size() - 1);
  for (Eigen::Index j = 0; j < nh; ++j) {
    knots[j] = values[static_cast<std::size_t>(std::floor(last * double(j + 1) / double(nh + 1)))];
  }
  if (first_not_increasing_or_zero(knots) >= 0) return std::nullopt;  // too few distinct values
  return knots;
}

}  // namespace detail

/// The splits of the records' best linear approximation between the blocks of `structure` (a
/// WienerHammerstein model; its parameter values and knots are not used), each with its static
/// nonlinearity fitted by least squares (the knots at the quantiles of the split's x1), best first.
/// The records are deviations from the operating point (identify() hands them so). Empty where the
/// BLA's least squares broke down, its b_0 = 0 or not finite, or every fit is degenerate (no linear
/// term).
/// \param structure the orders and knot count
/// \param records the identification records, deviations from the operating point, checked
/// \param linear_iterations the Levenberg-Marquardt iterations of the best linear approximation
/// \return the splits, best first; possibly empty
template <class Model>
std::vector<WienerHammersteinSplit<Model>> wiener_hammerstein_splits(
    const Model& structure, const CheckedRecords<typename Model::Scalar>& records, int linear_iterations = 100) {
  using Scalar = typename Model::Scalar;
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  using MatrixX = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  const Eigen::Index na1 = structure.na1(), nb1 = structure.nb1(), na2 = structure.na2(), nb2 = structure.nb2();
  const Eigen::Index r = structure.r(), nh = structure.nh();
  std::vector<WienerHammersteinSplit<Model>> splits;
  std::optional<ARX<Scalar>> bla;
  try {
    // With the structure's integrators (the second block's): its estimated poles are split.
    bla = detail::best_linear_approximation(records, na1 + na2, nb1 + nb2, structure.nk(), linear_iterations,
                                            structure.ni());
  } catch (const NumericalError&) {
    return splits;  // no BLA to split: identify() keeps its recursive starts
  }
  const VectorX a = bla->a(), b = bla->b();
  if (!a.allFinite() || !b.allFinite() || b[0] == Scalar(0)) return splits;

  const Eigen::VectorXd a_double = a.template cast<double>();
  const Eigen::VectorXd zeros_poly = (b.tail(b.size() - 1) / b[0]).template cast<double>();
  const auto pole_groups = detail::splittable_groups(denominator_poles(a_double), na1);
  const auto zero_groups = detail::splittable_groups(denominator_poles(zeros_poly), nb1);
  const auto pole_subsets = detail::subsets_of_size(pole_groups, na1);
  const auto zero_subsets = detail::subsets_of_size(zero_groups, nb1);

  const VectorX y = detail::stacked_outputs(records.records());
  const Eigen::Index samples = y.size();
  MatrixX regressors(samples, r + nh);
  VectorX x1(samples);
  for (const auto& poles : pole_subsets) {
    for (const auto& zeros : zero_subsets) {
      typename Model::First first(na1, nb1, structure.nk());
      typename Model::Second second(na2, nb2, 0, structure.ni());
      first.set_a(detail::coefficients_of(pole_groups, poles, true).template cast<Scalar>());
      second.set_a(detail::coefficients_of(pole_groups, poles, false).template cast<Scalar>());
      VectorX b1(nb1 + 1), b2(nb2 + 1);
      b1[0] = b[0];
      b1.tail(nb1) = b[0] * detail::coefficients_of(zero_groups, zeros, true).template cast<Scalar>();
      b2[0] = Scalar(1);
      b2.tail(nb2) = detail::coefficients_of(zero_groups, zeros, false).template cast<Scalar>();
      first.set_b(b1);
      // x1 = G1 u, each record from rest; divided by its RMS, so that the powers' columns are of
      // comparable size for the least squares.
      Eigen::Index row = 0;
      for (const auto& record : records) {
        first.reset();
        for (Eigen::Index k = 0; k < record.u.size(); ++k) x1[row++] = first.step(record.u[k]);
      }
      Scalar squares = Scalar(0);
      for (Eigen::Index k = 0; k < samples; ++k) squares += std::pow(x1[k], 2);
      const Scalar scale = std::sqrt(squares / Scalar(samples));
      if (!(scale > Scalar(0)) || !std::isfinite(scale)) continue;
      const std::optional<VectorX> knots = detail::quantile_knots<VectorX>(x1 / scale, nh);  // of x1 / scale
      if (!knots) continue;
      // Column m - 1: G2 applied to (x1 / scale)^m; column r + j: to its hinge j; each record from rest.
      second.set_b(b2);
      row = 0;
      for (const auto& record : records) {
        std::vector<typename Model::Second> columns(static_cast<std::size_t>(r + nh), second);
        for (Eigen::Index k = 0; k < record.u.size(); ++k, ++row) {
          const Scalar scaled = x1[row] / scale;
          Scalar power = Scalar(1);
          for (Eigen::Index m = 0; m < r; ++m) {
            power *= scaled;
            regressors(row, m) = columns[static_cast<std::size_t>(m)].step(power);
          }
          for (Eigen::Index j = 0; j < nh; ++j) {
            const Scalar hinge = detail::HingeTerms<Scalar>::hinge(scaled, (*knots)[j]);
            regressors(row, r + j) = columns[static_cast<std::size_t>(r + j)].step(hinge);
          }
        }
      }
      if (!regressors.allFinite()) continue;
      VectorX c = regressors.colPivHouseholderQr().solve(y);
      if (!c.allFinite() || std::abs(c[0]) < Scalar(1e-12) * (c.cwiseAbs().maxCoeff() + Scalar(1e-300))) continue;
      const double cost = static_cast<double>((y - regressors * c).squaredNorm()) / static_cast<double>(samples);
      for (Eigen::Index m = 0; m < r; ++m) c[m] /= std::pow(scale, Scalar(m + 1));  // for x1 itself
      // Normalised: x1' = c_1 x1 (the gain into b1), f_m = c_m / c_1^m; the hinges, homogeneous,
      // d_j h(x1 / scale - k_j) = g_j h(x1' - knot_j) with knot_j = c_1 scale k_j and
      // g_j = d_j / (c_1 scale) (in reverse order where c_1 < 0).
      Model model = structure;
      if (nh > 0) {
        VectorX knot(nh), g(nh);
        for (Eigen::Index j = 0; j < nh; ++j) {
          const Eigen::Index from = c[0] > Scalar(0) ? j : nh - 1 - j;
          knot[j] = c[0] * scale * (*knots)[from];
          g[j] = c[r + from] / (c[0] * scale);
        }
        if (!knot.allFinite() || !g.allFinite() || detail::first_not_increasing_or_zero(knot) >= 0) continue;
        model.set_knots(knot);
        model.set_g(g);
      }
      model.set_b1(c[0] * b1);
      model.set_a1(first.a());
      VectorX f(r);
      f[0] = Scalar(1);
      for (Eigen::Index m = 2; m <= r; ++m) f[m - 1] = c[m - 1] / std::pow(c[0], Scalar(m));
      model.set_f(f);
      model.set_b2(b2);
      model.set_a2(second.a());
      splits.push_back({model, cost});
    }
  }
  std::stable_sort(splits.begin(), splits.end(),
                   [](const auto& first, const auto& second) { return first.cost < second.cost; });
  return splits;
}

/// identify()'s starts for a WienerHammerstein model beside its recursive estimates (the model's
/// identify_starts): the best kWienerHammersteinStarts splits, best first. Its recursive estimates
/// alone depend on where they happen to go.
/// \param structure the orders and knot count
/// \param records the identification records, deviations from the operating point, checked
/// \return at most kWienerHammersteinStarts models, best first
template <class Model>
std::vector<Model> wiener_hammerstein_starts(const Model& structure,
                                             const CheckedRecords<typename Model::Scalar>& records) {
  const auto splits = wiener_hammerstein_splits(structure, records);
  std::vector<Model> starts;
  for (std::size_t i = 0; i < splits.size() && i < kWienerHammersteinStarts; ++i) starts.push_back(splits[i].model);
  return starts;
}

}  // namespace bonl
