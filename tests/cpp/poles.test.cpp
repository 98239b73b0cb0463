// Poles of a model's linear block (models/poles.hpp). Oracles: denominators built from known poles
// (the product of (1 - z_i z^-1)), and the magnitude response |1 / A(e^jw)| evaluated directly.

#include "test_support.hpp"

#include <complex>

using namespace bonl_test;

namespace {

/// a_1..a_n of prod_i (1 - z_i z^-1) for real poles and complex pairs (given once, with their conjugate).
Eigen::VectorXd denominator(const std::vector<std::complex<double>>& poles) {
  std::vector<std::complex<double>> all;
  for (const auto& z : poles) {
    all.push_back(z);
    if (z.imag() != 0.0) all.push_back(std::conj(z));
  }
  Eigen::VectorXcd product = Eigen::VectorXcd::Zero(static_cast<Eigen::Index>(all.size()) + 1);
  product[0] = 1.0;
  for (std::size_t i = 0; i < all.size(); ++i)
    for (Eigen::Index j = static_cast<Eigen::Index>(i) + 1; j >= 1; --j) product[j] -= all[i] * product[j - 1];
  return product.tail(static_cast<Eigen::Index>(all.size())).real();
}

double magnitude(const Eigen::VectorXd& a, double w) {
  std::complex<double> value = 1.0;
  for (Eigen::Index j = 0; j < a.size(); ++j) value += a[j] * std::polar(1.0, -w * static_cast<double>(j + 1));
  return 1.0 / std::abs(value);
}

}  // namespace

TEST_CASE("pole_radius is the largest pole magnitude", "[poles]") {
  bonl::ARXd model(3, 0, 0);
  model.set_a(denominator({{0.5, 0.0}, {0.3, 0.8}}));  // |0.3 +- 0.8j| = 0.854
  CHECK(bonl::pole_radius(model) == Approx(std::abs(std::complex<double>(0.3, 0.8))).epsilon(1e-12));
  model.set_a(denominator({{-1.2, 0.0}, {0.3, 0.8}}));
  CHECK(bonl::pole_radius(model) == Approx(1.2).epsilon(1e-12));
}

TEST_CASE("an unstable denominator is reflected inside with the same magnitude response shape", "[poles]") {
  const Eigen::VectorXd unstable = denominator({{1.5, 0.0}, {0.9, 0.6}, {0.2, 0.0}});  // 1.5 and |0.9+0.6j| = 1.08
  const Eigen::VectorXd stable = bonl::detail::reflected_inside(unstable, 0.999);
  bonl::ARXd model(4, 0, 0);
  model.set_a(stable);
  CHECK(bonl::pole_radius(model) < 1.0);
  // |1 / A| changes by one constant factor at every frequency.
  const double ratio = magnitude(stable, 0.1) / magnitude(unstable, 0.1);
  for (double w : {0.3, 0.7, 1.3, 2.0, 3.0}) {
    CHECK(magnitude(stable, w) / magnitude(unstable, w) == Approx(ratio).epsilon(1e-9));
  }
  // Stable denominators are left as they are.
  const Eigen::VectorXd already = denominator({{0.5, 0.0}, {0.3, 0.8}});
  CHECK(bonl::detail::reflected_inside(already, 0.999) == already);
}
