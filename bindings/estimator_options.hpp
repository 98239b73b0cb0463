#pragma once
// The estimator's keyword arguments as Estimator, identify and control.AdaptiveInverse take them,
// identify's as identify and bonl.select (selection.cpp) take them, and the records identify and
// bonl.select read (estimation.cpp defines them): one parsing, one set of messages.

#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <bonl/estimator/identify_options.hpp>
#include <bonl/estimator/recursive_estimator.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "conversions.hpp"

namespace bonl_python {
namespace py = pybind11;

/// The keyword arguments Estimator and identify share; None leaves an option at its method's default.
struct OptionArguments {
  std::string method;
  py::object forgetting;
  std::optional<double> p0;
  std::optional<double> trace_ceiling;
  Eigen::Index recover_after = 0;
  double stability_radius = 0.999;
  bonl::WindowRefinementOptions window = {};
  bool normalise = true;
};

/// The options, validated (std::invalid_argument, a ValueError, naming the bad one).
bonl::EstimatorOptions estimator_options(const OptionArguments& arguments);

/// identify's keyword arguments (bonl.select passes them on), in the order identify takes them.
struct IdentifyArguments {
  int passes;
  std::string method;
  py::object forgetting;
  std::optional<double> p0;
  int refine_iterations;
  bool normalise;
  py::object operating_point;
  Eigen::Index initialisation_window;
};

/// The options, validated (std::invalid_argument, a ValueError, naming the bad one).
bonl::IdentifyOptions identify_options(const IdentifyArguments& arguments);

/// scope.def(name, f, extra..., identify's keyword arguments with their defaults): f takes the
/// parameters `extra` names, then IdentifyArguments' in its order.
template <class Scope, typename Func, typename... Extra>
void def_with_identify_arguments(Scope& scope, const char* name, Func&& f, const Extra&... extra) {
  scope.def(name, std::forward<Func>(f), extra..., py::arg("passes") = 1, py::arg("method") = "output_error",
            py::arg("forgetting") = py::none(), py::arg("p0") = py::none(), py::arg("refine_iterations") = 100,
            py::arg("normalise") = true, py::arg("operating_point") = py::none(), py::arg("initialisation_window") = 0);
}

/// The records of identify and select: (u, y) for one record, or records=[(u1, y1), ...] for several
/// (u and y None), each checked by its index; `usage` shows both forms in the messages.
void read_records(const py::object& u, const py::object& y, const py::object& records, const char* usage,
                  std::vector<Eigen::VectorXd>& inputs, std::vector<Eigen::VectorXd>& outputs);

// --- How the stubs show the options taken as Python objects (conversions.hpp's Typed) ---
/// forgetting=: None, a number, (initial, initial_samples, final) or 'adaptive'.
BONL_PYTHON_TYPED(Forgetting, "float | tuple[float, int, float] | str | None");
/// identify's operating_point=: None, 'mean' or 'initial'.
BONL_PYTHON_TYPED(OperatingPointSource, "str | None");
// --- end of the stubs' types ---

}  // namespace bonl_python
