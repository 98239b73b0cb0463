// bonl.experiment: the paper's experiment on the plant (bonl/experiment.hpp) from Python:
// run_paper_experiment and its result classes (PaperExperimentResult, MethodResult, ModelResult,
// Record), and the records' signal processing (low_pass, differentiate).

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <bonl/experiment.hpp>
#include <bonl/models.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "conversions.hpp"
#include "plant_arguments.hpp"

namespace bonl_python {

namespace {

namespace experiment = bonl::experiment;

constexpr bool same_name(const char* a, const char* b) { return *a == *b && (*a == '\0' || same_name(a + 1, b + 1)); }

/// True when bonl::Models has a model called like Model (the Python class of that name).
template <class Model, class... Bound>
constexpr bool has_python_class(bonl::ModelList<Bound...>) {
  return (same_name(Bound::kName, Model::kName) || ...);
}

/// The identified model as its Python class: the run-time-order model of bonl::Models with the same
/// name, with the same orders and parameters; None when they are not finite.
template <class Model>
std::optional<AnyModel> python_model(const Model& model) {
  static_assert(has_python_class<Model>(bonl::Models{}), "every model of PaperModels needs its class in bonl::Models");
  std::optional<AnyModel> out;
  bonl::for_each_model(bonl::Models{}, [&](auto tag) {
    using Bound = typename decltype(tag)::type;
    if constexpr (same_name(Bound::kName, Model::kName)) {
      if (model.theta().allFinite()) {
        Bound bound = bonl::make_model<Bound>(model.orders());
        bound.set_theta(Eigen::VectorXd(model.theta()));
        out = AnyModel(std::move(bound));
      }
    }
  });
  return out;
}

/// One model of a method's result, as Python sees it (ModelResult).
struct PyModelResult {
  std::string name;
  std::string label;
  std::optional<AnyModel> model;
  std::optional<AnyModel> online_model;
  experiment::ModelScores scores;
  std::vector<std::pair<std::string, double>> table;
  py::typing::Dict<py::str, py::typing::Union<py::float_, py::typing::List<py::float_>>> params;
};

template <class Model>
PyModelResult python_result(const experiment::ModelResult<Model>& r) {
  PyModelResult out{r.kName,
                    experiment::paper_label(r.kName),
                    python_model(r.model),
                    python_model(r.online_model),
                    r,
                    experiment::labelled_parameters(r.model),
                    {}};
  for (std::size_t i = 0; i < Model::kDescription.parameters.size(); ++i) {
    const bonl::ParameterDescription& parameter = Model::kDescription.parameters[i];
    const Eigen::VectorXd value = r.model.parameter(i);
    if (parameter.shape == bonl::ParameterShape::Number) {
      out.params[parameter.name] = value[0];
    } else {
      out.params[parameter.name] = std::vector<double>(value.data(), value.data() + value.size());
    }
  }
  return out;
}

/// name -> f(model result), in PaperModels' order.
template <class Value, class F>
py::typing::Dict<py::str, Value> by_model(const experiment::MethodResult& m, F&& f) {
  py::typing::Dict<py::str, Value> d;
  m.for_each([&](const auto& r) { d[r.kName] = f(r); });
  return d;
}

const experiment::MethodResult& method_named(const experiment::PaperExperimentResult& result, const std::string& name) {
  std::string names;
  for (std::size_t i = 0; i < result.methods.size(); ++i) {
    const std::string method = bonl::to_string(result.methods[i].method);
    if (method == name) return result.methods[i];
    names += (i == 0 ? "" : i + 1 == result.methods.size() ? " or " : ", ") + ("'" + method + "'");
  }
  bonl::detail::fail("method must be " + names + ", got '" + name + "'");
}

void bind_record(py::module_& sub) {
  using experiment::Record;
  py::class_<Record>(sub, "Record",
                     "One processed record of the experiment, on the output grid (bonl/experiment/records.hpp).")
      .def_property_readonly(
          "time", [](const Record& r) { return to_numpy(r.time); }, "numpy.ndarray: [s].")
      .def_property_readonly(
          "input", [](const Record& r) { return to_numpy(r.input); },
          "numpy.ndarray: u = V - V0 [V], the identification input.")
      .def_property_readonly(
          "angle", [](const Record& r) { return to_numpy(r.angle); },
          "numpy.ndarray: the averaged, low-passed measured angle [rad].")
      .def_property_readonly(
          "velocity", [](const Record& r) { return to_numpy(r.velocity); },
          "numpy.ndarray: y, its numerical derivative [rad/s]: what the models are fitted on.")
      .def_property_readonly(
          "true_velocity", [](const Record& r) { return to_numpy(r.true_velocity); },
          "numpy.ndarray: the plant's joint rate, noise-free and unfiltered [rad/s].")
      .def_property_readonly(
          "min_position", [](const Record& r) { return r.trajectory.min_position; },
          "float: smallest piston position of the plant's run [m].")
      .def_property_readonly(
          "max_position", [](const Record& r) { return r.trajectory.max_position; },
          "float: largest piston position of the plant's run [m].")
      .def_property_readonly(
          "reached_end_stop", [](const Record& r) { return r.trajectory.reached_end_stop; },
          "bool: the piston left the stroke during the run.")
      .def_property_readonly(
          "steps", [](const Record& r) { return r.trajectory.steps; }, "int: CVODE's internal steps for the run.")
      .def("__repr__", [](const Record& r) { return "Record(" + std::to_string(r.time.size()) + " samples)"; });
}

void bind_model_result(py::module_& sub) {
  py::class_<PyModelResult>(sub, "ModelResult",
                            "One model of one method: the identified model, the online estimate and their scores.")
      .def_readonly("name", &PyModelResult::name, "str: the model's name (its class name, e.g. 'HammersteinWiener').")
      .def_readonly("label", &PyModelResult::label, "str: how the paper's tables write it (e.g. 'H-W').")
      .def_readonly("model", &PyModelResult::model,
                    "The identified model (identify(): the recursive estimate refined), as its bonl class; None if\n"
                    "its parameters are not finite.")
      .def_readonly("online_model", &PyModelResult::online_model,
                    "The recursive estimator's model alone after one pass (no refinement); None if not finite.")
      .def_property_readonly(
          "mse", [](const PyModelResult& r) { return r.scores.mse; },
          "float: validation MSE of the velocity, free-run [(rad/s)^2]; inf when unstable.")
      .def_property_readonly(
          "simulated", [](const PyModelResult& r) { return to_numpy(r.scores.simulated); },
          "numpy.ndarray: the free-run validation velocity [rad/s]; NaN when unstable.")
      .def_property_readonly(
          "online_mse", [](const PyModelResult& r) { return r.scores.online_mse; },
          "float: the online estimate's validation MSE [(rad/s)^2].")
      .def_property_readonly(
          "robustness_mse", [](const PyModelResult& r) { return r.scores.robustness_mse; },
          "list of float: validation MSE on each robustness trajectory (empty when not run).")
      .def_property_readonly(
          "seconds", [](const PyModelResult& r) { return r.scores.seconds; }, "float: wall time of identify() [s].")
      .def_property_readonly(
          "online_seconds", [](const PyModelResult& r) { return r.scores.online_seconds; },
          "float: wall time of the one-pass recursive estimate [s].")
      .def_readonly("parameters", &PyModelResult::table,
                    "list of (str, float): the parameters as the rows of the paper's Table 1, ('b0', b_0), ...")
      .def_readonly("params", &PyModelResult::params,
                    "dict: every parameter block by name (lists of float, a float for a one-number block).")
      .def("__repr__", [](const PyModelResult& r) {
        return "ModelResult(" + r.name + ", mse=" + bonl::detail::format_number(r.scores.mse) + ")";
      });
}

void bind_method_result(py::module_& sub) {
  using experiment::MethodResult;
  py::class_<MethodResult>(sub, "MethodResult", "One estimator method's results, for every model of the experiment.")
      .def_property_readonly(
          "method", [](const MethodResult& m) { return bonl::to_string(m.method); }, "str: 'output_error' or 'paper'.")
      .def_property_readonly(
          "models",
          [](const MethodResult& m) {
            return by_model<PyModelResult>(m, [](const auto& r) { return python_result(r); });
          },
          "dict[str, ModelResult]: by model name, in the order of the paper's equations (ARX first).")
      .def_property_readonly(
          "mse", [](const MethodResult& m) { return by_model<py::float_>(m, [](const auto& r) { return r.mse; }); },
          "dict[str, float]: validation MSE by model name [(rad/s)^2].")
      .def_property_readonly(
          "online_mse",
          [](const MethodResult& m) { return by_model<py::float_>(m, [](const auto& r) { return r.online_mse; }); },
          "dict[str, float]: the online estimates' validation MSE by model name [(rad/s)^2].")
      .def("__repr__",
           [](const MethodResult& m) { return std::string("MethodResult(") + bonl::to_string(m.method) + ")"; });
}

void bind_result(py::module_& sub) {
  using experiment::PaperExperimentResult;
  using experiment::Timings;
  py::class_<Timings>(sub, "Timings", "The wall time of each stage of the paper's experiment [s].")
      .def_readonly("plant", &Timings::plant, "float: simulation and processing of the two records [s].")
      .def_readonly("identification", &Timings::identification,
                    "float: identification and validation, both methods, identify() and online [s].")
      .def_readonly("robustness", &Timings::robustness, "float: the robustness check (0 when it was not run) [s].")
      .def(
          "to_dict",
          [](const Timings& t) {
            py::typing::Dict<py::str, py::float_> d;
            d["plant"] = t.plant;
            d["identification"] = t.identification;
            d["robustness"] = t.robustness;
            return d;
          },
          "Every stage by name.\n\nReturns\n-------\ndict[str, float]");
  py::class_<PaperExperimentResult>(
      sub, "PaperExperimentResult",
      "Everything the paper's experiment gives (run_paper_experiment): the plant, the two records, both\n"
      "methods' results for every model, and the wall times.")
      .def_property_readonly(
          "parameters", [](const PaperExperimentResult& r) { return r.parameters; },
          "bonl.plant.Parameters: the plant the experiment ran on.")
      .def_property_readonly(
          "identification", [](const PaperExperimentResult& r) { return &r.records.identification; },
          py::return_value_policy::reference_internal, "Record: the identification record (the paper's multi-sine).")
      .def_property_readonly(
          "validation", [](const PaperExperimentResult& r) { return &r.records.validation; },
          py::return_value_policy::reference_internal, "Record: the validation record (a smooth random signal).")
      .def_property_readonly(
          "methods",
          [](const py::object& self) {
            const auto& r = self.cast<const PaperExperimentResult&>();
            py::typing::Dict<py::str, experiment::MethodResult> d;
            for (const experiment::MethodResult& m : r.methods) {
              d[bonl::to_string(m.method)] = py::cast(&m, py::return_value_policy::reference_internal, self);
            }
            return d;
          },
          "dict[str, MethodResult]: {'output_error': ..., 'paper': ...}.")
      .def("method", &method_named, py::arg("name"), py::return_value_policy::reference_internal,
           "One method's results.\n\nParameters\n----------\nname : str\n    'output_error' or 'paper'.\n\n"
           "Returns\n-------\nMethodResult\n\nRaises\n------\nValueError\n    For a method the experiment did not run.")
      .def_property_readonly(
          "model_names",
          [](const PaperExperimentResult& r) {
            py::list names;
            r.methods.front().for_each([&](const auto& m) { names.append(m.kName); });
            return py::typing::Tuple<py::str, py::ellipsis>(names);
          },
          "tuple of str: the experiment's models, in the order of the paper's equations (ARX first).")
      .def_readonly("robustness_trajectories", &PaperExperimentResult::robustness_trajectories,
                    "int: trajectories of the robustness check (0 when it was not run).")
      .def_readonly("seconds", &PaperExperimentResult::seconds,
                    "Timings: wall time of each stage [s]: plant (records), identification (both methods,\n"
                    "identify() and online), robustness.")
      .def("__repr__", [](const PaperExperimentResult& r) {
        return "PaperExperimentResult(" + std::to_string(r.methods.size()) + " methods, " +
               std::to_string(r.robustness_trajectories) + " robustness trajectories)";
      });
}

}  // namespace

void bind_tracking(py::module_& sub) {
  py::class_<experiment::TrackingRun>(sub, "TrackingRun", "One controller's run of ``run_tracking_experiment``.")
      .def_readonly("controller", &experiment::TrackingRun::controller,
                    "str: 'PI', a model's name (PI plus its inverse as feedforward), or '<model> (adaptive)'.")
      .def_readonly("label", &experiment::TrackingRun::label,
                    "str: as the tables write it: 'PI', 'PI + P-H-W', 'PI + P-H-W (adaptive)'.")
      .def_readonly("plant_changes", &experiment::TrackingRun::plant_changes, "bool: the plant changed at change_time.")
      .def_readonly("rms", &experiment::TrackingRun::rms,
                    "float: RMS of reference - joint rate over [period, duration] [rad/s].")
      .def_readonly("rms_before_change", &experiment::TrackingRun::rms_before_change,
                    "float: the same over the period before change_time.")
      .def_readonly("rms_after_change", &experiment::TrackingRun::rms_after_change,
                    "float: the same over [change_time + period, change_time + 2 period].")
      .def_property_readonly(
          "command", [](const experiment::TrackingRun& r) { return to_numpy(r.command); },
          "numpy.ndarray: V(k) applied [V].")
      .def_property_readonly(
          "feedforward", [](const experiment::TrackingRun& r) { return to_numpy(r.feedforward); },
          "numpy.ndarray: the feedforward's part of the command [V] (0 for PI).")
      .def_property_readonly(
          "joint_rate", [](const experiment::TrackingRun& r) { return to_numpy(r.joint_rate); },
          "numpy.ndarray: the plant's true joint rate [rad/s].")
      .def_readonly("inexact", &experiment::TrackingRun::inexact,
                    "int: feedforward samples whose InverseStatus was not Exact.")
      .def_readonly("rederivations", &experiment::TrackingRun::rederivations,
                    "int: adaptive: inverses derived from the estimate.")
      .def_readonly("refused", &experiment::TrackingRun::refused, "int: adaptive: estimates the guard refused.")
      .def("__repr__", [](const experiment::TrackingRun& r) {
        return "TrackingRun(controller='" + r.controller + "', plant_changes=" + (r.plant_changes ? "True" : "False") +
               ", rms=" + bonl::detail::format_number(r.rms) + ")";
      });
  py::class_<experiment::TrackingResult>(sub, "TrackingResult", "What ``run_tracking_experiment`` gives.")
      .def_property_readonly(
          "time", [](const experiment::TrackingResult& r) { return to_numpy(r.time); }, "numpy.ndarray: t_k [s].")
      .def_property_readonly(
          "reference", [](const experiment::TrackingResult& r) { return to_numpy(r.reference); },
          "numpy.ndarray: the reference joint velocity [rad/s].")
      .def_readonly("proportional_gain", &experiment::TrackingResult::proportional_gain,
                    "float: the PI's Kc [V/(rad/s)].")
      .def_readonly("integral_time", &experiment::TrackingResult::integral_time, "float: the PI's tau_I [s].")
      .def_readonly("runs", &experiment::TrackingResult::runs,
                    "list of TrackingRun: PI and each model's feedforward; then PI, P-H-W and adaptive P-H-W under the "
                    "plant change.")
      .def("run", &experiment::TrackingResult::run, py::arg("controller"), py::arg("plant_changes") = false,
           py::return_value_policy::reference_internal,
           R"doc(The run of a controller, with or without the plant change.

Parameters
----------
controller : str
    Its label, e.g. "PI + P-H-W".
plant_changes : bool, default False
    True: the run with the plant change at 40 s.

Returns
-------
TrackingRun
    The run.

Raises
------
ValueError
    When there is no such run.)doc")
      .def_property_readonly(
          "tracking_rms",
          [](const experiment::TrackingResult& r) {
            py::typing::Dict<py::str, py::float_> d;
            for (const auto& run : r.runs)
              if (!run.plant_changes) d[py::str(run.controller)] = run.rms;
            return d;
          },
          "dict: controller name -> tracking RMS, for the runs without the plant change (bonl_demo --control --json).");

  sub.def(
      "run_tracking_experiment",
      [](const ParametersArgument& parameters, const std::string& method, std::uint64_t reference_seed,
         std::uint64_t noise_seed) {
        const bonl::plant::Parameters p = parameters_argument(parameters);
        experiment::TrackingOptions options;
        options.method = bonl::method_from_string(method);
        options.reference_seed = reference_seed;
        options.noise_seed = noise_seed;
        py::gil_scoped_release release;
        return experiment::run_tracking_experiment(p, options);
      },
      py::arg("parameters") = py::none(), py::kw_only(), py::arg("method") = "paper",
      py::arg("reference_seed") = std::uint64_t{2020}, py::arg("noise_seed") = std::uint64_t{99},
      "The tracking experiment, as ``bonl_demo --control`` runs it (docs/how-to/control.md).\n\n"
      "The paper experiment's models are identified on the plant; then the plant, stepped with its sensor\n"
      "noise, tracks a reference joint velocity under a PI loop alone (SIMC from the ARX model), the PI\n"
      "loop plus each model's inverse as feedforward, and, while the plant changes at 40 s (pilot\n"
      "hysteresis doubled, bulk modulus -30%), the PI alone, the P-H-W feedforward and the adaptive P-H-W\n"
      "feedforward (bonl.control.AdaptiveInverse in C++). The GIL is released.\n\n"
      "Parameters\n----------\nparameters : bonl.plant.Parameters, optional\n    The plant; None: the default.\n"
      "method : str, optional\n    Which method's models feed forward: 'paper' (default) or 'output_error'.\n"
      "reference_seed, noise_seed : int, optional\n    The reference's and the sensor noise's seeds.\n\n"
      "Returns\n-------\nTrackingResult\n\nRaises\n------\nValueError\n"
      "    For non-physical parameters, an unknown method, or a model without an inverse.");
}

void bind_experiment(py::module_& m) {
  py::module_ sub = m.def_submodule(
      "experiment",
      "The paper's experiment on the simulated plant (bonl/experiment.hpp): ``run_paper_experiment`` and its\n"
      "result, and the records' signal processing (``low_pass``, ``differentiate``).");
  bind_record(sub);
  bind_model_result(sub);
  bind_method_result(sub);
  bind_result(sub);
  bind_tracking(sub);

  sub.def(
      "run_paper_experiment",
      [](const ParametersArgument& parameters, bool robustness) {
        const bonl::plant::Parameters p = parameters_argument(parameters);
        experiment::PaperExperimentOptions options;
        options.robustness = robustness;
        py::gil_scoped_release release;
        return experiment::run_paper_experiment(p, options);
      },
      py::arg("parameters") = py::none(), py::kw_only(), py::arg("robustness") = false,
      "The paper's experiment on the plant, as ``bonl_demo`` runs it (docs/explanation/plant.md).\n\n"
      "Identification record from the paper's multi-sine, validation record from a smooth random\n"
      "signal (each 50 s at 100 Hz, 10 repeats averaged, 10 Hz low-pass, differentiated); every model of\n"
      "the experiment (ARX, Hammerstein, HammersteinWiener, PseudoHammersteinWiener, and beside them the\n"
      "PrandtlIshlinskiiHammerstein, which the paper does not have) identified with the paper's orders\n"
      "(na = 3, nb = 2, nk = 8, r = r1 = 3; np = 3 plays, their thresholds spread over the identification\n"
      "input's half-range) by the output-error and the paper's methods and validated by free-run\n"
      "simulation; also the online estimates (the estimator with its defaults, one pass, no offline refinement). The\n"
      "GIL is released during the computation.\n\n"
      "Parameters\n----------\nparameters : bonl.plant.Parameters, optional\n"
      "    The plant; None: ``bonl.plant.Parameters.excavator_20t()``.\n"
      "robustness : bool, optional\n"
      "    Also validate on the eight further trajectories of ``bonl_demo``'s robustness check.\n\n"
      "Returns\n-------\nPaperExperimentResult\n\n"
      "Raises\n------\nValueError\n    For non-physical parameters.");

  sub.def(
      "published_score",
      [](const std::string& name) -> std::optional<std::pair<double, int>> {
        const auto score = experiment::published_score(name);
        if (!score) return std::nullopt;
        return std::make_pair(score->mse, score->proposed_lower_percent);
      },
      py::arg("name"),
      "The paper's Table 2 (the real excavator) for a model, for comparison.\n\n"
      "Parameters\n----------\nname : str\n    The model's name, e.g. 'HammersteinWiener'.\n\n"
      "Returns\n-------\ntuple of (float, int) or None\n"
      "    Its validation MSE as published [(rad/s)^2] and how much lower the proposed model's\n"
      "    (PseudoHammersteinWiener) is, in percent, as the paper states it (0 for the proposed model);\n"
      "    None for a model the paper does not report.");

  sub.def(
      "low_pass",
      [](const ArrayLike& x, double cutoff_hz, double ts) {
        return to_numpy(experiment::low_pass(to_vector(x, "x"), cutoff_hz, ts));
      },
      py::arg("x"), py::arg("cutoff_hz"), py::arg("ts"),
      "First-order low-pass z[k] = z[k-1] + alpha (x[k] - z[k-1]), alpha = 1 - exp(-2 pi fc ts), z[0] = x[0].\n\n"
      "Parameters\n----------\nx : array_like, 1-D\n    Finite samples.\ncutoff_hz : float\n    fc [Hz].\n"
      "ts : float\n    Sample time [s].\n\nReturns\n-------\nnumpy.ndarray\n\n"
      "Raises\n------\nValueError\n    When ``x`` is not 1-D or not finite, or fc or ts is not > 0.");
  sub.def(
      "differentiate",
      [](const ArrayLike& x, double ts) { return to_numpy(experiment::differentiate(to_vector(x, "x"), ts)); },
      py::arg("x"), py::arg("ts"),
      "Numerical derivative: central differences, one-sided at both ends.\n\n"
      "Parameters\n----------\nx : array_like, 1-D\n    Finite samples, at least 2.\nts : float\n    Sample time "
      "[s].\n\n"
      "Returns\n-------\nnumpy.ndarray\n\n"
      "Raises\n------\nValueError\n    When ``x`` is not 1-D, not finite or shorter than 2, or ts is not > 0.");

  sub.attr("__all__") = py::make_tuple("run_paper_experiment", "PaperExperimentResult", "MethodResult", "ModelResult",
                                       "Record", "Timings", "run_tracking_experiment", "TrackingResult", "TrackingRun",
                                       "published_score", "low_pass", "differentiate");
  // `import bonl._bonl.experiment` works once sys.modules knows the submodule.
  py::module_::import("sys").attr("modules")[sub.attr("__name__")] = sub;
}

}  // namespace bonl_python
