// Second translation unit of fuzz_estimator_update: the fixed-order kinds (see estimator_harness.hpp).

#include "estimator_harness.hpp"

namespace bonl_fuzz {

void fuzz_fixed_kind(int kind, FuzzedDataProvider& in) {
  constexpr int kModels = static_cast<int>(bonl::Models::size);
  if (kind < kModels) {
    fuzz_model_at(bonl::PaperOrderModels{}, kind, in);
  } else {
    fuzz_model_at(bonl::ModelsWithScalar<bonl::PaperOrderModels, float>::type{}, kind - kModels, in);
  }
}

}  // namespace bonl_fuzz
