#pragma once
// A model in other units: the model of y = sy * M(u / su), from the units its description gives each
// parameter block (ParameterUnits). identify() fits a model to data divided by su and sy and returns
// it in the data's own units with this.

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <string>

#include "../detail/validate.hpp"

namespace bonl {

/// The model of y = output_scale * model(u / input_scale), its operating point and input range included. Both scales
/// must be finite and > 0.
/// \param model the model M, in the scaled units
/// \param input_scale su: the returned model feeds u / su to M
/// \param output_scale sy: the returned model's output is sy times M's
/// \return a copy of model with its parameters in the unscaled units
template <class Model>
Model rescaled(const Model& model, double input_scale, double output_scale) {
  detail::require(std::isfinite(input_scale) && input_scale > 0.0,
                  "input_scale must be finite and > 0, got " + detail::format_number(input_scale));
  detail::require(std::isfinite(output_scale) && output_scale > 0.0,
                  "output_scale must be finite and > 0, got " + detail::format_number(output_scale));
  using Scalar = typename Model::Scalar;
  Model out = model;
  for (std::size_t i = 0; i < Model::kDescription.parameters.size(); ++i) {
    const auto& block = Model::kDescription.parameters[i];
    typename Model::VectorX value = model.parameter(i);
    for (Eigen::Index j = 0; j < value.size(); ++j) {
      const int index = block.first_index + static_cast<int>(j);
      const int y_power = block.units.y_power + block.units.y_power_per_index * index;
      const int u_power = block.units.u_power + block.units.u_power_per_index * index;
      value[j] *= static_cast<Scalar>(std::pow(output_scale, y_power) * std::pow(input_scale, u_power));
    }
    out.set_parameter(i, value);
  }
  out.set_operating_point(model.u0() * input_scale, model.y0() * output_scale);
  out.set_input_range(model.input_min() * input_scale, model.input_max() * input_scale);
  return out;
}

}  // namespace bonl
