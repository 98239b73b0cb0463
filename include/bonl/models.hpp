#pragma once
// The four models of the paper. Each one simulates free-run from rest (simulate), predicts one
// step ahead from measured data (predict), exposes its parameters as the eq. (19) vector (theta)
// and by name, and carries its key-term-separated regressor (KeyTerms) for bonl::Estimator.
//
// Model concept (what Estimator<Model> needs):
//   Scalar, kNumParams (or Eigen::Dynamic), Params, VectorX, kHasInternalVariables, kName;
//   num_params(), theta(), set_theta(), try_simulate(u, y), initial_estimate(c0);
//   KeyTerms(model) with reset(), begin(), predicted_output(), regress(), end(), constrain().

#include <Eigen/Core>

#include "models/arx.hpp"
#include "models/hammerstein.hpp"
#include "models/hammerstein_wiener.hpp"
#include "models/pseudo_hammerstein_wiener.hpp"

namespace bonl {

/// The paper's orders (section 5): na = 3, nb = 2, r = r1 = 3 at compile time; nk = 8 is given
/// to the constructor, e.g. PaperPseudoHammersteinWiener model(3, 2, 8, 3).
using PaperARX = ARX<double, 3, 2>;
using PaperHammerstein = Hammerstein<double, 3, 2, 3>;
using PaperHammersteinWiener = HammersteinWiener<double, 3, 2, 3, 3>;
using PaperPseudoHammersteinWiener = PseudoHammersteinWiener<double, 3, 2, 3>;

/// Run-time orders throughout.
using ARXd = ARX<double>;
using Hammersteind = Hammerstein<double>;
using HammersteinWienerd = HammersteinWiener<double>;
using PseudoHammersteinWienerd = PseudoHammersteinWiener<double>;

}  // namespace bonl
