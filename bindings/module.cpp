#include <string>

#include "bindings.hpp"

PYBIND11_MODULE(_bonl, m) {
  m.doc() = "bonl: identification of block-oriented nonlinear models (C++ core).";
  m.attr("__version__") = BONL_VERSION_STRING;
  bonl_python::bind_models(m);
  bonl_python::bind_estimation(m);
  bonl_python::bind_selection(m);
  bonl_python::bind_metrics(m);
  bonl_python::bind_io(m);
  bonl_python::bind_plant(m);
  bonl_python::bind_experiment(m);
  bonl_python::bind_control(m);
  // What `from bonl._bonl import *` (python/bonl/__init__.py) takes: every public name, so that a model
  // added to bonl::Models reaches the bonl namespace with no edit on the Python side.
  namespace py = pybind11;
  py::list names;
  for (const auto& item : m.attr("__dict__").cast<py::dict>()) {
    const std::string name = py::str(item.first);
    if (!name.empty() && name[0] != '_') names.append(name);
  }
  names.attr("sort")();
  m.attr("__all__") = names;
}
