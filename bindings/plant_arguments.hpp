#pragma once
// The plant's arguments as the plant's binding files share them: the parameters (plant_parameters.cpp)
// and the command signals (excitation.cpp), taken by simulate (plant_simulate.cpp) and the experiment
// (experiment.cpp).

#include <pybind11/pybind11.h>

#include <bonl/plant/parameters.hpp>
#include <bonl/plant/simulator.hpp>

#include <string>

namespace bonl_python {
namespace py = pybind11;

/// A command signal V(t): a bonl::plant::Command plus what it is, and whether calling it needs
/// the GIL (it wraps a Python callable). Python's bonl.plant.Command.
struct PyCommand {
  bonl::plant::Command function;
  std::string description;
  bool calls_python = false;

  double operator()(double t) const { return function(t); }
};

/// A command from what simulate accepts: a Command, a Python callable of time, or a (values, ts)
/// pair held between samples (excitation.sampled). TypeError for anything else.
PyCommand command_argument(const py::object& object, const char* name);

/// A bonl.plant.Parameters, or the defaults for None; TypeError for anything else.
bonl::plant::Parameters parameters_argument(const py::object& object);

}  // namespace bonl_python
