#pragma once
// The models: the four of the paper, the Wiener model, the Wiener-Hammerstein model, the
// nonlinear-feedback (Lur'e) model and the Prandtl-Ishlinskii Hammerstein model (input hysteresis).
// Each one simulates free-run from rest (simulate), predicts one step ahead from measured data
// (predict), exposes its parameters as the eq. (19) vector (theta) and by name, and carries its
// key-term-separated regressor (KeyTerms) for bonl::Estimator.
//
// Model concept (what Estimator<Model> needs):
//   Scalar, kNumParams (or Eigen::Dynamic), Params, VectorX, kHasInternalVariables, kName;
//   num_params(), theta(), set_theta(), try_simulate_deviations(u, y) (the free run of u - u0 to
//   y - y0; detail::ModelRuns adds the operating point), constrain(theta);
//   KeyTerms(model, KeyTermMethod) and OutputErrorTerms(model), each with reset() and one
//   step() per sample (models/model_steps.hpp); optionally settings of its own beside the
//   estimator's options (EstimatorSettings, models/estimator_settings.hpp);
// and describes itself (kDescription, orders(), parameter(i), set_parameter(i, v): model_description.hpp),
// which is all the JSON format, the Python bindings, the fuzz harness and the tests need: adding a
// model is its header and one entry in bonl::Models below.

#include <Eigen/Core>

#include <array>

#include "models/arx.hpp"
#include "models/bouc_wen_feedback.hpp"
#include "models/fixed_orders.hpp"
#include "models/hammerstein.hpp"
#include "models/hammerstein_wiener.hpp"
#include "models/model_description.hpp"
#include "models/model_steps.hpp"
#include "models/nonlinear_feedback.hpp"
#include "models/poles.hpp"
#include "models/prandtl_ishlinskii_hammerstein.hpp"
#include "models/pseudo_hammerstein_wiener.hpp"
#include "models/rescale.hpp"
#include "models/wiener.hpp"
#include "models/wiener_hammerstein.hpp"

namespace bonl {

// The models in double, run-time orders throughout.
using ARXd = ARX<double>;                                                    ///< ARX in double
using Hammersteind = Hammerstein<double>;                                    ///< Hammerstein in double
using HammersteinWienerd = HammersteinWiener<double>;                        ///< HammersteinWiener in double
using PseudoHammersteinWienerd = PseudoHammersteinWiener<double>;            ///< PseudoHammersteinWiener in double
using Wienerd = Wiener<double>;                                              ///< Wiener in double
using WienerHammersteind = WienerHammerstein<double>;                        ///< WienerHammerstein in double
using NonlinearFeedbackd = NonlinearFeedback<double>;                        ///< NonlinearFeedback in double
using PrandtlIshlinskiiHammersteind = PrandtlIshlinskiiHammerstein<double>;  ///< PrandtlIshlinskiiHammerstein in double
using BoucWenFeedbackd = BoucWenFeedback<double>;                            ///< BoucWenFeedback in double

/// Every model, at run-time orders in double: what a model file can hold, what Python binds, what
/// the property suites run over. A new model is one entry here.
using Models = ModelList<ARXd, Hammersteind, HammersteinWienerd, PseudoHammersteinWienerd, Wienerd, WienerHammersteind,
                         NonlinearFeedbackd, PrandtlIshlinskiiHammersteind, BoucWenFeedbackd>;

/// The orders of the fixed-order variants (WithOrders), by name: the paper's (section 5), na = 3,
/// nb = 2, r = r1 = 3 and nk = 8 (a run-time order: the structures of the benchmarks and of the
/// tests' known systems); both blocks of the Wiener-Hammerstein model as the paper's linear block; no
/// hinges (nh = 0) and two feedback taps (nd = 2) for the models after the paper. An order not named
/// here is at its minimum: the plays np, none in the nonlinear-feedback model, one in the
/// Prandtl-Ishlinskii Hammerstein model.
struct PaperOrders {
  /// The table: each order by name and its value.
  static constexpr std::array<OrderValue, 11> kOrders{{{"na", 3},
                                                       {"nb", 2},
                                                       {"nk", 8},
                                                       {"r", 3},
                                                       {"r1", 3},
                                                       {"na1", 3},
                                                       {"nb1", 2},
                                                       {"na2", 3},
                                                       {"nb2", 2},
                                                       {"nh", 0},
                                                       {"nd", 2}}};
};

/// Every model at the paper's orders fixed at compile time, in double: what the fixed-size tests,
/// fuzzing and benchmarks run over (ModelsWithScalar gives them in float).
using PaperOrderModels = ModelsWithOrders<Models, PaperOrders>::type;

/// The paper's models at its orders at compile time (ARX<double, 3, 2>, Hammerstein<double, 3, 2, 3>,
/// ...); nk = 8 is given to the constructor, e.g. PaperPseudoHammersteinWiener model(3, 2, 8, 3).
using PaperARX = WithOrders<ARXd, PaperOrders>;                  ///< ARX at the paper's orders
using PaperHammerstein = WithOrders<Hammersteind, PaperOrders>;  ///< Hammerstein at the paper's orders
using PaperHammersteinWiener =
    WithOrders<HammersteinWienerd, PaperOrders>;  ///< HammersteinWiener at the paper's orders
using PaperPseudoHammersteinWiener =
    WithOrders<PseudoHammersteinWienerd, PaperOrders>;  ///< PseudoHammersteinWiener at the paper's orders
using PaperWiener = WithOrders<Wienerd, PaperOrders>;   ///< Wiener at the paper's orders

}  // namespace bonl
