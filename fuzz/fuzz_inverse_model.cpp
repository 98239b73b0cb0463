// libFuzzer target: bytes -> bonl::control::InverseModel<Model> for a model of bonl::control::InvertibleModels at small
// run-time orders with arbitrary parameters and options, then a stream of reference windows with NaN,
// inf, huge, tiny and denormal values among ordinary ones (bonl/control/inverse_model.hpp).
//
// Contract checked (besides ASan/UBSan/LSan and no hang):
// - The constructor either builds the inverse or throws std::invalid_argument (no other exception).
// - step(window) with a window shorter than window_size() returns RejectedShortPreview, with a
//   non-finite entry RejectedNonFinite; both give a NaN command and leave the inverse untouched (a
//   copy made before steps the same as the original afterwards, bit for bit).
// - step(window) with a finite window is either RejectedOverflow (the arithmetic left the finite
//   numbers: NaN command, the inverse untouched) or not rejected, with its command in
//   [command_min, command_max] (NaN fails this).
// - continue_from(a copy) followed by the same steps gives the same commands, bit for bit.

#include <bonl/control.hpp>
#include <bonl/models.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <optional>
#include <stdexcept>
#include <vector>

#include "estimator_harness.hpp"
#include "fuzz_common.hpp"

using namespace bonl_fuzz;

namespace {

template <class Model>
void fuzz_inverse(FuzzedDataProvider& in) {
  const Orders<Model> orders = decode_orders<Model>(in);
  if (!orders_valid<Model>(orders)) return;  // the models' constructors are fuzz_estimator_update's
  Model model = bonl::make_model<Model>(orders);
  Eigen::VectorXd theta(model.num_params());
  for (Eigen::Index i = 0; i < theta.size(); ++i) theta[i] = any_double(in);
  try {
    model.set_theta(theta);
  } catch (const std::invalid_argument&) {
    return;  // a non-finite parameter: refused by the model, not the inverse's business
  }
  bonl::control::InverseOptions options;
  options.command_min = any_double(in);
  options.command_max = any_double(in);
  options.backlash_band = any_double(in);
  options.backlash_band_per_c = in.ConsumeBool() ? 0.0 : any_double(in);
  std::optional<bonl::control::InverseModel<Model>> built;
  try {
    built.emplace(model, options);
  } catch (const std::invalid_argument&) {
    return;
  }
  auto& inverse = *built;
  const double low = inverse.command_min();
  const double high = inverse.command_max();
  Eigen::VectorXd window(inverse.window_size() + 2);
  while (in.remaining_bytes() > 0) {
    const Eigen::Index length = in.ConsumeIntegralInRange<Eigen::Index>(0, window.size());
    bool finite = true;
    for (Eigen::Index i = 0; i < length; ++i) {
      window[i] = in.ConsumeIntegral<std::uint8_t>() < 224 ? in.ConsumeIntegralInRange<int>(-4000, 4000) / 1000.0
                                                           : any_double(in);
      if (i < inverse.window_size()) finite = finite && std::isfinite(window[i]);
    }
    const auto before = inverse;
    const auto step = inverse.step(window.head(length));
    const bool overflow = step.status == bonl::control::InverseStatus::RejectedOverflow;
    if (length < inverse.window_size() || !finite || overflow) {
      const auto expected = length < inverse.window_size() ? bonl::control::InverseStatus::RejectedShortPreview
                            : !finite                      ? bonl::control::InverseStatus::RejectedNonFinite
                                                           : bonl::control::InverseStatus::RejectedOverflow;
      FUZZ_CHECK(step.status == expected);
      FUZZ_CHECK(std::isnan(step.value));
      // Untouched: the copy made before and the inverse step alike from here on.
      auto twin = before;
      const Eigen::VectorXd probe = Eigen::VectorXd::Constant(inverse.window_size(), 0.25);
      const double a = twin.step(probe).value;
      auto again = inverse;
      const double b = again.step(probe).value;
      FUZZ_CHECK(same_bits(&a, &b, 1));
      continue;
    }
    FUZZ_CHECK(!bonl::control::rejected(step.status));
    if (!(step.value >= low && step.value <= high)) {
      std::fprintf(stderr, "%s: command %.17g outside [%.17g, %.17g], status %d; theta", Model::kName, step.value, low,
                   high, static_cast<int>(step.status));
      for (Eigen::Index i = 0; i < theta.size(); ++i) std::fprintf(stderr, " %.17g", theta[i]);
      std::fprintf(stderr, "; orders");
      for (const Eigen::Index order : orders) std::fprintf(stderr, " %ld", static_cast<long>(order));
      std::fprintf(stderr, "; window");
      for (Eigen::Index i = 0; i < length; ++i) std::fprintf(stderr, " %.17g", window[i]);
      std::fprintf(stderr, "\n");
      FUZZ_CHECK(false);
    }
    // A fresh inverse continued from this one goes on alike.
    if (in.ConsumeIntegral<std::uint8_t>() < 16) {
      auto continued = bonl::control::InverseModel<Model>(model, options);
      continued.continue_from(inverse);
      auto original = inverse;
      const Eigen::VectorXd probe = Eigen::VectorXd::Constant(inverse.window_size(), -0.5);
      const double a = continued.step(probe).value;
      const double b = original.step(probe).value;
      FUZZ_CHECK(same_bits(&a, &b, 1));
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const int kind = in.ConsumeIntegralInRange<int>(0, static_cast<int>(bonl::control::InvertibleModels::size) - 1);
  try {
    int index = 0;
    bonl::for_each_model(bonl::control::InvertibleModels{}, [&](auto tag) {
      if (index++ == kind) fuzz_inverse<typename decltype(tag)::type>(in);
    });
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected exception: %s\n", e.what());
    FUZZ_CHECK(false);
  }
  return 0;
}
