// The inverse models' per-sample step allocates nothing and is noexcept (bonl/control/inverse_model.hpp),
// for every model, fixed and run-time orders, minimum-phase and ZPETC. Allocations are counted as in
// allocation.test.cpp, at the C allocator (counting_allocator.hpp).

#include <bonl/control.hpp>

#include "counting_allocator.hpp"
#include "test_support.hpp"

using namespace bonl_test;
using bonl::control::InverseModel;

namespace {
template <class Model>
void check_steps_allocate_nothing(const Model& model) {
  INFO(Model::kName);
  bonl::control::InverseOptions options;
  options.command_min = -1.0;
  options.command_max = 1.0;
  options.backlash_band = 0.01;
  InverseModel<Model> inverse(model, options);
  Eigen::VectorXd window = Eigen::VectorXd::Zero(inverse.window_size());
  static_assert(noexcept(inverse.step(window)), "InverseModel::step must be noexcept");
  static_assert(noexcept(inverse.step(0.0)), "InverseModel::step must be noexcept");
  const long before = allocations();
  double sum = 0.0;
  for (Eigen::Index k = 0; k < 2000; ++k) {
    for (Eigen::Index i = 0; i < window.size(); ++i) window[i] = 0.3 * std::sin(0.01 * static_cast<double>(k + i));
    sum += inverse.step(window).value;
    if (window.size() == 1) sum += inverse.step(window[0]).value;
  }
  inverse.step(std::nan(""));
  inverse.reset();
  CHECK(allocations() - before == 0);
  CHECK(std::isfinite(sum));
}
}  // namespace

TEST_CASE("the inverse models step without allocating") {
  check_steps_allocate_nothing(known_system<bonl::ARXd>("small"));
  check_steps_allocate_nothing(known_system<bonl::Hammersteind>("small"));
  check_steps_allocate_nothing(known_system<bonl::HammersteinWienerd>("small"));
  check_steps_allocate_nothing(known_system<bonl::PseudoHammersteinWienerd>("small"));
  check_steps_allocate_nothing(known_system<bonl::Wienerd>("small"));
  check_steps_allocate_nothing(known_system<bonl::PrandtlIshlinskiiHammersteind>("small"));
  check_steps_allocate_nothing(known_arx());
  check_steps_allocate_nothing(known_hammerstein());
  check_steps_allocate_nothing(known_hammerstein_wiener());
  check_steps_allocate_nothing(known_phw());
  check_steps_allocate_nothing(known_system<bonl::PaperWiener>());
  check_steps_allocate_nothing(
      known_system<bonl::WithOrders<bonl::PrandtlIshlinskiiHammersteind, bonl::PaperOrders>>());
  // ZPETC: a zero of B outside the unit circle.
  auto nonminimum = known_system<bonl::PseudoHammersteinWienerd>("small");
  nonminimum.set_b(vec({1.0, 1.5}));
  check_steps_allocate_nothing(nonminimum);
}

TEST_CASE("the adaptive inverse steps and updates without allocating between its derivations") {
  // Fixed orders (the paper's P-H-W): the estimator's update allocates nothing; only the derivation
  // every rederive_every samples does (docs/how-to/control.md).
  const auto model = known_phw();
  bonl::control::AdaptiveInverseOptions options;
  options.inverse.command_min = -1.0;
  options.inverse.command_max = 1.0;
  options.inverse.backlash_band_per_c = 1.0;
  options.rederive_every = 1000;
  bonl::control::AdaptiveInverse<bonl::PaperPseudoHammersteinWiener> adaptive(model, options);
  const long before = allocations();
  double sum = 0.0;
  for (Eigen::Index k = 0; k < 999; ++k) {
    const double u = adaptive.step(0.3 * std::sin(0.01 * static_cast<double>(k))).value;
    adaptive.update(u, 0.1 * std::sin(0.01 * static_cast<double>(k - 8)));
    sum += u;
  }
  CHECK(allocations() - before == 0);
  // Every sample from the first moving command on was taken, the scale's measurement caught up on: the
  // first command, sin(0), is 0 and the model at rest there (Estimator::kScaleSamples).
  CHECK(adaptive.estimator().samples() == 998);
  CHECK(adaptive.estimator().pending_samples() == 0);
  CHECK(std::isfinite(sum));
}
