#pragma once
// The parameter step of the tracking tests: the input gain +30% and the backlash half-width
// doubled. Chosen by the parameter blocks' names (models/model_description.hpp), so it works for every
// model: the linear numerator b (b1) where its first coefficient is free, else the input block's
// coefficients (the polynomial f, p and the plays' weights g, which the normalised numerator leaves
// the gain to); c where there is a backlash. Used by tests/cpp and examples/online_accuracy.

#include <cstddef>
#include <string>

namespace bonl_test {

template <class Model>
Model with_parameter_step(const Model& model) {
  const auto& blocks = Model::kDescription.parameters;
  bool free_numerator = false;  // b or b1 with b_0 estimated: the gain is the numerator's
  for (const auto& block : blocks) {
    const std::string name = block.name;
    free_numerator = free_numerator || ((name == "b" || name == "b1") && !block.normalised);
  }
  Model out = model;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const std::string name = blocks[i].name;
    const bool gain = free_numerator ? (name == "b" || name == "b1") : (name == "f" || name == "p" || name == "g");
    if (gain || name == "c") out.set_parameter(i, model.parameter(i) * (name == "c" ? 2.0 : 1.3));
  }
  return out;
}

}  // namespace bonl_test
