#pragma once
// What a model adds to the estimator's options (EstimatorOptions are the same for every model): a
// customisation point with a default. A model with settings of its own declares
//   using EstimatorSettings = ...;   // a struct with validate() and rescaled(u_scale, y_scale)
//   Params initial_estimate(const EstimatorSettings&) const;          // optional: else all zero
//   OutputErrorTerms(const Model&, const EstimatorSettings&);         // optional: else (model)
// and Estimator<Model> and identify() take them beside the options; a model without has none.

#include <type_traits>
#include <utility>

namespace bonl {

/// The settings of a model that adds none to the estimator's options.
struct NoEstimatorSettings {
  void validate() const noexcept {}  ///< nothing to check
  /// The same (nothing depends on the data's units).
  /// \return no settings
  NoEstimatorSettings rescaled(double /*u_scale*/, double /*y_scale*/) const noexcept { return {}; }
};

namespace detail {
template <class Model, class = void>
struct EstimatorSettingsOf {
  using type = NoEstimatorSettings;
};
template <class Model>
struct EstimatorSettingsOf<Model, std::void_t<typename Model::EstimatorSettings>> {
  using type = typename Model::EstimatorSettings;
};
}  // namespace detail

/// The estimator settings Model adds to EstimatorOptions: Model::EstimatorSettings, or none.
template <class Model>
using ModelSettings = typename detail::EstimatorSettingsOf<Model>::type;

namespace detail {
template <class Model, class = void>
struct HasInitialEstimate : std::false_type {};
template <class Model>
struct HasInitialEstimate<Model, std::void_t<decltype(std::declval<const Model&>().initial_estimate(
                                     std::declval<const ModelSettings<Model>&>()))>> : std::true_type {};

/// Where the recursive estimator starts Model's parameters under `settings`: the model's
/// initial_estimate(settings), or all zero.
template <class Model>
typename Model::Params initial_estimate(const Model& model, const ModelSettings<Model>& settings) {
  if constexpr (HasInitialEstimate<Model>::value) {
    return model.initial_estimate(settings);
  } else {
    static_cast<void>(settings);
    return Model::Params::Zero(model.num_params());
  }
}

/// Model's OutputErrorTerms under `settings`: constructed from (model, settings) where the model
/// takes them, else from the model alone.
template <class Model>
typename Model::OutputErrorTerms output_error_terms(const Model& model, const ModelSettings<Model>& settings) {
  using Terms = typename Model::OutputErrorTerms;
  if constexpr (std::is_constructible_v<Terms, const Model&, const ModelSettings<Model>&>) {
    return Terms(model, settings);
  } else {
    static_cast<void>(settings);
    return Terms(model);
  }
}
}  // namespace detail

}  // namespace bonl
