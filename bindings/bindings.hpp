#pragma once
// One bind_* per area of the Python module bonl._bonl; module.cpp calls them in order.

#include <pybind11/pybind11.h>

namespace bonl_python {
namespace py = pybind11;

void bind_models(py::module_& m);      // models.cpp: one class per model of bonl::Models, and MODELS
void bind_estimation(py::module_& m);  // estimation.cpp: identify, Estimator, UpdateStatus
void bind_metrics(py::module_& m);     // metrics.cpp: submodule metrics (mse, rmse, nrmse, nrmse_fit)
void bind_io(py::module_& m);          // io.cpp: to_json on the models, load_model
void bind_plant(py::module_& m);       // plant.cpp: submodule plant (parameters, simulate, excitation, experiment)

}  // namespace bonl_python
