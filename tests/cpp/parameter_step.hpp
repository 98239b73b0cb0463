#pragma once
// The parameter step of the tracking tests (issue 16): the input gain +30% and the backlash
// half-width doubled. Chosen by the parameter blocks' names (models/model_description.hpp), so it
// works for every model: the input polynomial f, p where the model has one, else the numerator b (b1);
// c where there is a backlash. The Wiener-Hammerstein model's gain is b1. Used by tests/cpp and
// examples/online_accuracy.

#include <cstddef>
#include <string>

namespace bonl_test {

template <class Model>
Model with_parameter_step(const Model& model) {
  const auto& blocks = Model::kDescription.parameters;
  bool has_input_polynomial = false;  // an f that carries the gain (the Wiener-Hammerstein model's is normalised)
  for (const auto& block : blocks) {
    has_input_polynomial = has_input_polynomial || (std::string(block.name) == "f" && !block.normalised);
  }
  Model out = model;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const std::string name = blocks[i].name;
    const bool gain = has_input_polynomial ? (name == "f" || name == "p") : (name == "b" || name == "b1");
    if (gain || name == "c") out.set_parameter(i, model.parameter(i) * (name == "c" ? 2.0 : 1.3));
  }
  return out;
}

}  // namespace bonl_test
