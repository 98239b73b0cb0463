#pragma once
// The keyword arguments of Estimator and identify that a model adds to the estimator's options (its
// EstimatorSettings, bonl/models/estimator_settings.hpp), documented in option_docs.hpp. None leaves a
// setting at the model's default; a setting given to a model that does not take it is a ValueError
// naming the models that do.

#include <Eigen/Core>
#include <bonl/models.hpp>

#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace bonl_python {

/// The model-specific keyword arguments, as Estimator and identify take them (None: not given).
struct ModelSettingArguments {
  std::optional<double> c0;
  std::optional<Eigen::Index> backlash_hold;
};

/// The names of the models of bonl::Models whose settings are Settings ("A or B").
template <class Settings>
std::string models_with_settings() {
  std::string names;
  bonl::for_each_model(bonl::Models{}, [&names](auto tag) {
    using Model = typename decltype(tag)::type;
    if (std::is_same_v<bonl::ModelSettings<Model>, Settings>) {
      names += std::string(names.empty() ? "" : " or ") + Model::kName;
    }
  });
  return names;
}

/// std::invalid_argument (a ValueError) for a setting given to a model whose settings lack it.
template <class Settings, class Value>
void refuse(const std::optional<Value>& given, const char* name, const char* model) {
  if (given) {
    throw std::invalid_argument(std::string("bonl: ") + name + " is an option of the " +
                                models_with_settings<Settings>() + " estimator only, not of " + model);
  }
}

/// A model without settings takes none of the keywords.
inline void fill(bonl::NoEstimatorSettings&, const ModelSettingArguments& given, const char* model) {
  refuse<bonl::BacklashEstimatorSettings>(given.c0, "c0", model);
  refuse<bonl::BacklashEstimatorSettings>(given.backlash_hold, "backlash_hold", model);
}

/// P-H-W: c0 and backlash_hold.
inline void fill(bonl::BacklashEstimatorSettings& settings, const ModelSettingArguments& given, const char*) {
  if (given.c0) settings.c0 = *given.c0;
  if (given.backlash_hold) settings.backlash_hold = *given.backlash_hold;
}

/// Model's settings from the keywords, validated (std::invalid_argument, a ValueError, naming the bad one).
template <class Model>
bonl::ModelSettings<Model> model_settings(const ModelSettingArguments& given) {
  bonl::ModelSettings<Model> settings;
  fill(settings, given, Model::kName);
  settings.validate();
  return settings;
}

}  // namespace bonl_python
