// bonl.load_model: the JSON model format shared with C++ (bonl/io/model_json.hpp).

#include <bonl/io/model_json.hpp>

#include <pybind11/stl.h>

#include <variant>

#include "bindings.hpp"

namespace bonl_python {

void bind_io(py::module_& m) {
  m.def(
      "load_model", [](const std::string& text) -> AnyModel { return bonl::io::load_model(text); }, py::arg("text"),
      R"doc(Read a model written by Model.to_json (or by C++'s bonl::io::to_json).

Parameters
----------
text : str
    The JSON text.

Returns
-------
One of bonl.MODELS

Raises
------
ValueError
    The text is not valid JSON or not a valid bonl model (the message names the problem).)doc");
}

}  // namespace bonl_python
