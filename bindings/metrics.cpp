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
  // The four share their arguments; each docstring is its summary, those arguments and what it returns.
  const auto doc = [](const char* summary, const char* returns) {
    return std::string(summary) +
           "\n\nParameters\n----------\ny : array_like, shape (n,)\n    The measured output.\n"
           "yhat : array_like, shape (n,)\n    Its simulation or prediction, as long as y.\n\n"
           "Returns\n-------\nfloat\n    " +
           returns;
  };
  metrics.def("mse",
              pair([](const Eigen::VectorXd& y, const Eigen::VectorXd& yhat) { return bonl::metrics::mse(y, yhat); }),
              py::arg("y"), py::arg("yhat"),
              doc("Mean squared error, mean((y - yhat)^2).", "The MSE, in y's units squared, >= 0.").c_str());
  metrics.def(
      "rmse", pair([](const Eigen::VectorXd& y, const Eigen::VectorXd& yhat) { return bonl::metrics::rmse(y, yhat); }),
      py::arg("y"), py::arg("yhat"),
      doc("Root mean squared error of yhat against y, sqrt(mean((y - yhat)^2)).", "The RMSE, in y's units, >= 0.")
          .c_str());
  metrics.def("nrmse",
              pair([](const Eigen::VectorXd& y, const Eigen::VectorXd& yhat) { return bonl::metrics::nrmse(y, yhat); }),
              py::arg("y"), py::arg("yhat"),
              doc("Normalised error ||y - yhat|| / ||y - mean(y)||.",
                  "The NRMSE, >= 0 (0 is perfect, 1 no better than y's mean).")
                  .c_str());
  metrics.def(
      "fit_percent",
      pair([](const Eigen::VectorXd& y, const Eigen::VectorXd& yhat) { return bonl::metrics::fit_percent(y, yhat); }),
      py::arg("y"), py::arg("yhat"),
      doc("Fit in percent, 100 (1 - ||y - yhat|| / ||y - mean(y)||), as the System Identification Toolbox's compare.",
          "The fit, <= 100 (100 is perfect, 0 no better than y's mean).")
          .c_str());
}

}  // namespace bonl_python
