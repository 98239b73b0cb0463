// Second translation unit of fuzz_estimator_update: the fixed-order kinds (see estimator_harness.hpp).

#include "estimator_harness.hpp"

namespace bonl_fuzz {

void fuzz_fixed_kind(int kind, FuzzedDataProvider& in) {
  switch (kind) {
    case 0: fuzz<bonl::PaperARX>(in); break;
    case 1: fuzz<bonl::PaperHammerstein>(in); break;
    case 2: fuzz<bonl::PaperHammersteinWiener>(in); break;
    case 3: fuzz<bonl::PaperPseudoHammersteinWiener>(in); break;
    case 4: fuzz<bonl::ARX<float, 3, 2>>(in); break;
    case 5: fuzz<bonl::Hammerstein<float, 3, 2, 3>>(in); break;
    case 6: fuzz<bonl::HammersteinWiener<float, 3, 2, 3, 3>>(in); break;
    default: fuzz<bonl::PseudoHammersteinWiener<float, 3, 2, 3>>(in); break;
  }
}

}  // namespace bonl_fuzz
