// Second translation unit of fuzz_estimator_update: model kinds 6-11 (see estimator_harness.hpp).

#include "estimator_harness.hpp"

namespace bonl_fuzz {

void fuzz_kinds_6_to_11(int kind, FuzzedDataProvider& in, const Orders& o) {
  switch (kind) {
    case 6: fuzz<bonl::PaperHammersteinWiener>(in, o); break;
    case 7: fuzz<bonl::PaperPseudoHammersteinWiener>(in, o); break;
    case 8: fuzz<bonl::ARX<float, 3, 2>>(in, o); break;
    case 9: fuzz<bonl::Hammerstein<float, 3, 2, 3>>(in, o); break;
    case 10: fuzz<bonl::HammersteinWiener<float, 3, 2, 3, 3>>(in, o); break;
    default: fuzz<bonl::PseudoHammersteinWiener<float, 3, 2, 3>>(in, o); break;
  }
}

}  // namespace bonl_fuzz
