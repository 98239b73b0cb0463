#pragma once
// The plant's arguments as the plant's binding files share them: the parameters (plant_parameters.cpp),
// the command signals (excitation.cpp) and the simulation options (plant_simulate.cpp), taken by
// simulate (plant_simulate.cpp), SteppingPlant (plant_stepping.cpp) and the experiment (experiment.cpp).

#include <pybind11/pybind11.h>
#include <pybind11/typing.h>

#include <bonl/plant/parameters.hpp>
#include <bonl/plant/simulator.hpp>

#include <cstdint>
#include <string>

#include "conversions.hpp"

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

// How the stubs show the plant's arguments taken as Python objects (conversions.hpp's Typed).
/// simulate's command: what command_argument takes.
BONL_PYTHON_TYPED(CommandArgument,
                  "bonl._bonl.plant.Command | collections.abc.Callable[[float], float] | "
                  "tuple[numpy.typing.ArrayLike, float]");
/// The load: a command as command_argument takes it (but a pair), or None.
BONL_PYTHON_TYPED(LoadArgument, "bonl._bonl.plant.Command | collections.abc.Callable[[float], float] | None");
/// atol: a dict {state: tolerance}, or None.
BONL_PYTHON_TYPED(ToleranceArgument, "dict[str, float] | None");
/// initial_position: h0 [m], or None for mid-stroke.
using PositionArgument = py::typing::Optional<Real>;

/// A bonl.plant.Parameters, or the defaults for None; TypeError for anything else.
bonl::plant::Parameters parameters_argument(const py::object& object);
/// How the stubs show a parameters argument: Parameters or None (parameters_argument checks it).
using ParametersArgument = py::typing::Optional<bonl::plant::Parameters>;

/// h0 [m] from Python's initial_position: None is mid-stroke (-1 for C++); else a real number >= 0
/// (ValueError naming it).
double initial_position_argument(const py::object& initial_position);

/// The SimulationOptions from the keyword arguments that simulate and SteppingPlant share (all but
/// simulate's duration; plant_simulate.cpp): atol a dict by state, initial_position None for
/// mid-stroke, load a command or None. Sets calls_python when the load is a Python callable.
bonl::plant::SimulationOptions simulation_options(double sample_time, double command_rate, double rtol,
                                                  const py::object& atol, long max_steps_per_interval,
                                                  bool sensor_noise, std::uint64_t noise_seed,
                                                  const py::object& initial_position, const py::object& load,
                                                  bool& calls_python);

}  // namespace bonl_python
