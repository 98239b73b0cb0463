#pragma once
// numpy in, numpy out: what every binding file shares. Arrays of any dtype convertible to float64,
// any stride, and plain sequences are accepted and converted once; anything that is not a 1-D
// array of numbers is a ValueError that names the argument.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <string>

namespace bonl_python {
namespace py = pybind11;

inline Eigen::VectorXd to_vector(const py::handle& object, const char* name) {
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  Array array;
  try {
    array = Array::ensure(object);
  } catch (const py::error_already_set&) {
    array = Array();
  }
  if (!array) {
    PyErr_Clear();
    throw py::value_error(std::string(name) + " must be a 1-D array of numbers");
  }
  if (array.ndim() != 1) {
    throw py::value_error(std::string(name) + " must be 1-D, got an array with " + std::to_string(array.ndim()) +
                          " dimensions");
  }
  return Eigen::Map<const Eigen::VectorXd>(array.data(), array.shape(0));
}

}  // namespace bonl_python
