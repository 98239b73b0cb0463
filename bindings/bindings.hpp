#pragma once
// One bind_* per area of the Python module bonl._bonl; module.cpp calls the top-level ones in order,
// bind_plant the plant's parts.

#include <pybind11/pybind11.h>

#include <bonl/models.hpp>

#include <string>
#include <variant>

namespace bonl_python {
namespace py = pybind11;

/// Any model of bonl::Models (C++'s bonl::io::AnyModel): Python sees the union of the model classes.
using AnyModel = bonl::ApplyModels<bonl::Models, std::variant>::type;

void bind_models(py::module_& m);      // models.cpp: one class per model of bonl::Models, MODELS, the warnings
void bind_estimation(py::module_& m);  // estimation.cpp: identify, Estimator, UpdateStatus
void bind_selection(py::module_& m);   // selection.cpp: what bonl.select runs (C++'s bonl::score_candidate, select)
void bind_metrics(py::module_& m);     // metrics.cpp: submodule metrics (mse, rmse, nrmse, nrmse_fit)
void bind_io(py::module_& m);          // io.cpp: to_json on the models, load_model
void bind_plant(py::module_& m);       // plant.cpp: submodule plant, with the four below
void bind_experiment(py::module_& m);  // experiment.cpp: submodule experiment (run_paper_experiment, its result)
void bind_control(py::module_& m);     // control.cpp: submodule control (InverseModel, InverseStatus)

// The parts of the submodule plant:
void bind_plant_parameters(py::module_& plant);  // plant_parameters.cpp: Parameters
void bind_excitation(py::module_& plant);        // excitation.cpp: Command, submodule excitation
void bind_plant_simulate(py::module_& plant);    // plant_simulate.cpp: simulate, Trajectory, initial_state, derivative
void bind_plant_stepping(py::module_& plant);    // plant_stepping.cpp: SteppingPlant, Measurement

/// The warnings bonl gives (models.cpp creates them): a model simulated on inputs outside the range it
/// was identified on; an identified model that is unstable or barely damped; records whose input
/// cannot excite the model's structure.
py::handle extrapolation_warning();
py::handle stability_warning();
py::handle excitation_warning();
/// Issues a warning of `category` from the calling Python code; raises if a filter makes it an error.
void warn(py::handle category, const std::string& message);

}  // namespace bonl_python
