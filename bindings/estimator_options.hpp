#pragma once
// The estimator's keyword arguments as Estimator, identify and control.AdaptiveInverse take them
// (estimation.cpp defines them): one parsing, one set of messages.

#include <pybind11/pybind11.h>

#include <bonl/estimator/recursive_estimator.hpp>

#include <optional>
#include <string>

namespace bonl_python {
namespace py = pybind11;

/// The keyword arguments Estimator and identify share; None leaves an option at its method's default.
struct OptionArguments {
  std::string method;
  py::object forgetting;
  std::optional<double> p0;
  double c0;
  std::optional<double> trace_ceiling;
  Eigen::Index recover_after = 0;
  double stability_radius = 0.999;
  Eigen::Index backlash_hold = 200;
};

/// The options, validated (std::invalid_argument, a ValueError, naming the bad one).
bonl::EstimatorOptions estimator_options(const OptionArguments& arguments);

}  // namespace bonl_python
