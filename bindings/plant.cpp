// bonl._bonl.plant: the CVODE excavator dipper-joint plant (docs/explanation/plant.md) from Python. The
// submodule itself; its parts are bound by plant_parameters.cpp (Parameters), excitation.cpp
// (Command, the submodule excitation), plant_simulate.cpp (simulate, initial_state, derivative) and
// plant_stepping.cpp (SteppingPlant, Measurement).

#include "bindings.hpp"

namespace bonl_python {

void bind_plant(py::module_& m) {
  py::module_ sub = m.def_submodule(
      "plant",
      "The excavator dipper-joint plant (docs/explanation/plant.md) integrated by SUNDIALS CVODE: parameters,\n"
      "command signals (submodule ``excitation``), ``simulate`` and ``SteppingPlant`` (one sample per\n"
      "call); the paper's experiment on it is ``bonl.experiment``.");

  bind_plant_parameters(sub);
  bind_excitation(sub);
  bind_plant_simulate(sub);
  bind_plant_stepping(sub);

  sub.attr("__all__") = py::make_tuple("Parameters", "Command", "excitation", "simulate", "Trajectory", "initial_state",
                                       "derivative", "SteppingPlant", "Measurement");

  // Make `from bonl._bonl.plant import *` and `import bonl._bonl.plant.excitation` work: an
  // extension's submodules are attributes, not importable modules, until sys.modules knows them.
  py::dict modules = py::module_::import("sys").attr("modules");
  modules[sub.attr("__name__")] = sub;
  modules[sub.attr("excitation").attr("__name__")] = sub.attr("excitation");
}

}  // namespace bonl_python
