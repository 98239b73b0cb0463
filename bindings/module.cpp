#include "bindings.hpp"

PYBIND11_MODULE(_bonl, m) {
  m.doc() = "bonl: identification of block-oriented nonlinear models (C++ core).";
  m.attr("__version__") = BONL_VERSION_STRING;
  bonl_python::bind_models(m);
  bonl_python::bind_estimation(m);
  bonl_python::bind_metrics(m);
  bonl_python::bind_io(m);
  bonl_python::bind_plant(m);
}
