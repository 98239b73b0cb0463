// Links bonl from its installed CMake package: find_package(bonl CONFIG REQUIRED) + bonl::bonl.
#include <bonl/bonl.hpp>
#include <iostream>
int main() {
  // A known Hammerstein system, identified back from its own noise-free response.
  bonl::Hammerstein<double, 2, 1, 2> truth(2, 1, 1, 2);
  truth.set_f((Eigen::Vector3d() << 0.0, 1.0, 0.3).finished());
  truth.set_p((Eigen::Vector3d() << 0.0, -0.4, 0.1).finished());
  truth.set_b((Eigen::Vector2d() << 1.0, 0.5).finished());
  truth.set_a((Eigen::Vector2d() << -1.2, 0.5).finished());
  const Eigen::VectorXd u = bonl::signals::random_levels(2000, 5, 1.0, 7);
  const Eigen::VectorXd y = truth.simulate(u);
  const auto fitted = bonl::identify(bonl::Hammerstein<double, 2, 1, 2>(2, 1, 1, 2), u, y);
  std::cout << "fit " << bonl::metrics::fit_percent(y, fitted.simulate(u)) << " %\n";
  return bonl::metrics::fit_percent(y, fitted.simulate(u)) > 99.0 ? 0 : 1;
}
