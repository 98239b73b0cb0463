// bonl.metrics: how identified models are judged.

#include <bonl/metrics.hpp>

#include "bindings.hpp"
#include "conversions.hpp"

namespace bonl_python {

void bind_metrics(py::module_& m) {
  py::module_ metrics = m.def_submodule("metrics", "Error measures for simulated or predicted outputs.");
  const auto pair = [](double (*f)(const Eigen::VectorXd&, const Eigen::VectorXd&)) {
    return [f](const ArrayLike& y, const ArrayLike& yhat) { return f(to_vector(y, "y"), to_vector(yhat, "yhat")); };
  };
  metrics.def(
      "mse", pair([](const Eigen::VectorXd& y, const Eigen::VectorXd& yhat) { return bonl::metrics::mse(y, yhat); }),
      py::arg("y"), py::arg("yhat"), "Mean squared error, mean((y - yhat)^2).");
  metrics.def(
      "rmse", pair([](const Eigen::VectorXd& y, const Eigen::VectorXd& yhat) { return bonl::metrics::rmse(y, yhat); }),
      py::arg("y"), py::arg("yhat"), "Root mean squared error of yhat against y, sqrt(mean((y - yhat)^2)).");
  metrics.def(
      "nrmse",
      pair([](const Eigen::VectorXd& y, const Eigen::VectorXd& yhat) { return bonl::metrics::nrmse(y, yhat); }),
      py::arg("y"), py::arg("yhat"), "Normalised error ||y - yhat|| / ||y - mean(y)|| (0 is perfect).");
  metrics.def(
      "fit_percent",
      pair([](const Eigen::VectorXd& y, const Eigen::VectorXd& yhat) { return bonl::metrics::fit_percent(y, yhat); }),
      py::arg("y"), py::arg("yhat"),
      "Fit in percent, 100 (1 - ||y - yhat|| / ||y - mean(y)||), as the System Identification Toolbox's compare.");
}

}  // namespace bonl_python
