// Selection in Python: bonl.select (python/bonl/selection.py) checks its data once into a
// _SelectionData and runs C++'s bonl::score_candidate on each candidate (_score_candidate, the GIL
// released) on its executors, then bonl::refit on the best (_refit); _select is C++'s whole
// bonl::select, which tests compare it with.

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <bonl/estimator.hpp>
#include <bonl/models.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "conversions.hpp"
#include "estimator_options.hpp"

namespace bonl_python {
namespace {

/// The records (owned) and options of a selection, checked once by bonl::SelectionData, and the
/// arguments they came from, for pickling (a Dask worker receives it with each candidate).
struct SelectionArguments {
  std::vector<Eigen::VectorXd> inputs, outputs;
  std::string criterion;
  double validation_fraction;
  Eigen::Index window;
  int folds;
  std::string fold_initial_state;
  IdentifyArguments identify;
  std::optional<bonl::SelectionData<double>> data;  // views inputs and outputs
};

bonl::SelectionCriterion criterion_from_string(const std::string& name) {
  for (const auto criterion : {bonl::SelectionCriterion::Validation, bonl::SelectionCriterion::AIC,
                               bonl::SelectionCriterion::BIC, bonl::SelectionCriterion::CrossValidation}) {
    if (name == bonl::to_string(criterion)) return criterion;
  }
  bonl::detail::fail("select: criterion must be one of validation, aic, bic, cross_validation, got '" + name + "'");
}

bonl::InitialState initial_state_from_string(const std::string& name) {
  for (const auto state : {bonl::InitialState::Measured, bonl::InitialState::Estimated}) {
    if (name == bonl::to_string(state)) return state;
  }
  bonl::detail::fail("select: fold_initial_state must be 'measured' or 'estimated', got '" + name + "'");
}

/// window= and folds=: an integer (Python's or numpy's, not a bool); its range bonl::SelectionData
/// checks.
Eigen::Index integer_from(const py::object& value, const char* name, const char* range) {
  bonl::detail::require(!py::isinstance<py::bool_>(value) && PyIndex_Check(value.ptr()),
                        std::string("select: ") + name + " must be an integer " + range + ", got " +
                            std::string(py::str(py::repr(value))));
  return value.cast<Eigen::Index>();
}

std::unique_ptr<SelectionArguments> make_selection(std::vector<Eigen::VectorXd> inputs,
                                                   std::vector<Eigen::VectorXd> outputs, const std::string& criterion,
                                                   double validation_fraction, Eigen::Index window, int folds,
                                                   const std::string& fold_initial_state,
                                                   const IdentifyArguments& identify) {
  auto held = std::make_unique<SelectionArguments>(SelectionArguments{std::move(inputs),
                                                                      std::move(outputs),
                                                                      criterion,
                                                                      validation_fraction,
                                                                      window,
                                                                      folds,
                                                                      fold_initial_state,
                                                                      identify,
                                                                      {}});
  bonl::SelectOptions options;
  options.criterion = criterion_from_string(criterion);
  options.validation_fraction = validation_fraction;
  options.window = window;
  options.folds = folds;
  options.fold_initial_state = initial_state_from_string(fold_initial_state);
  options.identify = identify_options(identify);
  bonl::Records<double> records;
  for (std::size_t i = 0; i < held->inputs.size(); ++i) records.emplace_back(held->inputs[i], held->outputs[i]);
  held->data.emplace(records, options);
  return held;
}

/// A row as bonl.select reads it: (score, fit_mse, validation_mse or None, error or None, model or None,
/// fold_mse or None).
template <class Model>
py::tuple row_tuple(const bonl::SelectionCandidate<Model>& row) {
  const bool validation = row.model && !std::isnan(row.validation_mse);
  return py::make_tuple(row.score, row.fit_mse, validation ? py::cast(row.validation_mse) : py::none(),
                        row.error.empty() ? py::none() : py::cast(row.error),
                        row.model ? py::cast(*row.model) : py::none(),
                        row.fold_mse.empty() ? py::none() : py::cast(row.fold_mse));
}

template <class Model>
void def_selection(py::module_& m) {
  m.def(
      "_score_candidate",
      [](const Model& structure, const SelectionArguments& selection) {
        const auto row = [&] {
          py::gil_scoped_release release;
          return bonl::score_candidate(structure, *selection.data);
        }();
        return row_tuple(row);
      },
      py::arg("structure"), py::arg("data"),
      "bonl::score_candidate: the structure identified on data's fit parts and scored by its criterion. "
      "Returns (score, fit_mse, validation_mse or None, error or None, model or None, fold_mse or None).");
  m.def(
      "_refit",
      [](const Model& structure, const SelectionArguments& selection) {
        std::string why;
        const auto model = [&] {
          py::gil_scoped_release release;
          return bonl::refit(structure, *selection.data, why);
        }();
        return py::make_tuple(model ? py::cast(*model) : py::none(), why.empty() ? py::none() : py::cast(why));
      },
      py::arg("structure"), py::arg("data"),
      "bonl::refit: the structure identified on all of data's records where its free run there is bounded. "
      "Returns (model or None, why not or None).");
  m.def(
      "_select",
      [](const std::vector<Model>& candidates, const SelectionArguments& selection) {
        auto result = [&] {
          py::gil_scoped_release release;
          return bonl::select(candidates, *selection.data);
        }();
        py::list table;
        for (const auto& row : result.table) table.append(py::make_tuple(row.structure, row_tuple(row)));
        return py::make_tuple(table, result.best);
      },
      py::arg("candidates"), py::arg("data"),
      "C++'s bonl::select over candidates of one model class, on its own threads. Returns (table, best): the "
      "rows best first as (structure, _score_candidate's tuple), and the best refitted on all the records.");
}

}  // namespace

void bind_selection(py::module_& m) {
  py::class_<SelectionArguments> cls(m, "_SelectionData",
                                     "The records and options of a selection, checked once (bonl::SelectionData); "
                                     "made by _selection_data.");
  cls.def(py::pickle(
      [](const SelectionArguments& s) {
        py::list records;
        for (std::size_t i = 0; i < s.inputs.size(); ++i) {
          records.append(py::make_tuple(to_numpy(s.inputs[i]), to_numpy(s.outputs[i])));
        }
        const IdentifyArguments& a = s.identify;
        return py::make_tuple(records, s.criterion, s.validation_fraction, s.window, s.folds, s.fold_initial_state,
                              a.passes, a.method, a.forgetting, a.p0, a.refine_iterations, a.normalise,
                              a.operating_point, a.initialisation_window);
      },
      [](const py::tuple& t) {
        std::vector<Eigen::VectorXd> inputs, outputs;
        read_records(py::none(), py::none(), t[0], "", inputs, outputs);
        return make_selection(std::move(inputs), std::move(outputs), t[1].cast<std::string>(), t[2].cast<double>(),
                              t[3].cast<Eigen::Index>(), t[4].cast<int>(), t[5].cast<std::string>(),
                              {t[6].cast<int>(), t[7].cast<std::string>(), t[8], t[9].cast<std::optional<double>>(),
                               t[10].cast<int>(), t[11].cast<bool>(), t[12], t[13].cast<Eigen::Index>()});
      }));
  def_with_identify_arguments(
      m, "_selection_data",
      [](const py::typing::Optional<ArrayLike>& u, const py::typing::Optional<ArrayLike>& y,
         const py::typing::Optional<RecordList>& records, const std::string& criterion, double validation_fraction,
         const py::object& window, const py::object& folds, const std::string& fold_initial_state, int passes,
         const std::string& method, const Forgetting& forgetting, std::optional<double> p0, int refine_iterations,
         bool normalise, const OperatingPointSource& operating_point, Eigen::Index initialisation_window) {
        std::vector<Eigen::VectorXd> inputs, outputs;
        read_records(u, y, records,
                     "select(candidates, u, y) for one record, select(candidates, records=[(u1, y1), (u2, y2), ...]) "
                     "for several",
                     inputs, outputs);
        const Eigen::Index fold_count = integer_from(folds, "folds", ">= 2");
        bonl::detail::require(
            fold_count <= std::numeric_limits<int>::max(),
            "select: folds must be an integer >= 2 that fits an int, got " + std::to_string(fold_count));
        return make_selection(
            std::move(inputs), std::move(outputs), criterion, validation_fraction,
            integer_from(window, "window", ">= 0"), static_cast<int>(fold_count), fold_initial_state,
            {passes, method, forgetting, p0, refine_iterations, normalise, operating_point, initialisation_window});
      },
      py::arg("u") = py::none(), py::arg("y") = py::none(), py::kw_only(), py::arg("records") = py::none(),
      py::arg("criterion") = "validation", py::arg("validation_fraction") = 0.25, py::arg("window") = 0,
      py::arg("folds") = 5, py::arg("fold_initial_state") = "measured",
      "bonl.select's records and options checked once (bonl::SelectionData): ValueError naming the bad one. "
      "The keyword arguments after fold_initial_state are identify's.");
  bonl::for_each_model(bonl::Models{}, [&m](auto tag) { def_selection<typename decltype(tag)::type>(m); });
}

}  // namespace bonl_python
