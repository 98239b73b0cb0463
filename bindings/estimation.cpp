// Estimation in Python: bonl.identify (whole record) and bonl.Estimator (online, one sample at a time).

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <bonl/estimator.hpp>
#include <bonl/models.hpp>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "conversions.hpp"
#include "estimator_options.hpp"
#include "model_settings.hpp"
#include "option_docs.hpp"

namespace bonl_python {
namespace {

/// None: the method's default schedule; a number: constant; a tuple (initial, initial_samples,
/// final); "adaptive": the adaptive memory.
constexpr const char* kForgettingForms =
    "forgetting must be None, a number, a tuple (initial, initial_samples, final) or 'adaptive'";

/// A real number (not a bool, a string or a complex), or a ValueError naming `what`.
double forgetting_factor(const py::handle& value, const char* what) {
  bool real = !py::isinstance<py::bool_>(value) && !py::isinstance<py::str>(value);
  double factor = 0.0;
  if (real) {
    try {
      factor = value.cast<double>();
    } catch (const py::cast_error&) {
      real = false;
    }
  }
  bonl::detail::require(
      real, std::string(kForgettingForms) + "; " + what + " must be a real number, got " + type_name(value));
  return factor;
}

std::optional<bonl::ForgettingSchedule> parse_forgetting(const py::object& forgetting) {
  if (forgetting.is_none()) return std::nullopt;
  if (py::isinstance<py::str>(forgetting)) {
    const auto name = forgetting.cast<std::string>();
    bonl::detail::require(name == "adaptive", std::string(kForgettingForms) + ", got '" + name + "'");
    return bonl::ForgettingSchedule::adaptive_memory();
  }
  if (py::isinstance<py::tuple>(forgetting) || py::isinstance<py::list>(forgetting)) {
    const auto items = forgetting.cast<py::sequence>();
    bonl::detail::require(items.size() == 3, kForgettingForms);
    const py::object samples = items[1];
    // An integer (Python or numpy), not a bool or a float that happens to be whole.
    bonl::detail::require(
        !py::isinstance<py::bool_>(samples) && PyIndex_Check(samples.ptr()),
        std::string(kForgettingForms) + "; initial_samples must be an integer, got " + type_name(samples));
    Eigen::Index initial_samples = 0;
    bool in_range = true;
    try {
      initial_samples = samples.cast<Eigen::Index>();
    } catch (const py::cast_error&) {
      in_range = false;
    }
    bonl::detail::require(in_range, std::string(kForgettingForms) + "; initial_samples is out of range, got " +
                                        std::string(py::str(samples)));
    bonl::ForgettingSchedule schedule;
    schedule.initial = forgetting_factor(items[0], "initial");
    schedule.initial_samples = initial_samples;
    schedule.final = forgetting_factor(items[2], "final");
    return schedule;
  }
  return bonl::ForgettingSchedule::constant(forgetting_factor(forgetting, "forgetting"));
}

}  // namespace

bonl::EstimatorOptions estimator_options(const OptionArguments& arguments) {
  bonl::EstimatorOptions options;
  options.method = bonl::method_from_string(arguments.method);  // std::invalid_argument: a ValueError
  options.forgetting = parse_forgetting(arguments.forgetting);
  options.p0 = arguments.p0;
  options.trace_ceiling = arguments.trace_ceiling;
  options.recover_after = arguments.recover_after;
  options.stability_radius = arguments.stability_radius;
  options.window = arguments.window;
  options.normalise = arguments.normalise;
  options.validate();
  return options;
}

namespace {

const char* kIdentifyHead = R"doc(Identify a model's parameters from an input/output record, or from several.

Parameters
----------
model : one of bonl.MODELS
    Gives the structure (orders); its parameter values are not used.
u, y : array_like, shape (n,)
    Input and measured output of one record.
records : sequence of (u, y) pairs, optional
    Several records (experiments of the same system), by keyword, in place of u and y:
    ``identify(model, records=[(u1, y1), (u2, y2)])``. Each record is simulated from rest; no history
    is carried across records.
)doc";

const char* kIdentifyTail = R"doc(
Returns
-------
model
    A new model of the same type with the identified parameters, that operating point and the
    records' input range (Model.input_range).

Warns
-----
bonl.StabilityWarning
    The identified model's largest pole has magnitude >= 0.999 (unstable or barely damped); possible
    where identify returns the recursive estimate as it is ('paper', refine_iterations=0, ARX least squares).
bonl.ExcitationWarning
    The records' input takes fewer distinct values than the structure needs (two for every model; for an
    input polynomial of degree r, r + 1, on each side of zero where it has two segments): a constant input
    cannot excite the structure, and the identified parameters are not fixed by the data.

Raises
------
ValueError
    Bad orders, settings, lengths or non-finite samples.
bonl.NumericalError
    The estimator broke down numerically.)doc";

/// identify's docstring: its options' entries from option_docs.hpp's table.
const char* identify_doc() {
  static const std::string doc = std::string(kIdentifyHead) +
                                 option_docs({"passes", "method", "forgetting", "p0", "refine_iterations", "normalise",
                                              "operating_point", "initialisation_window", "c0", "backlash_hold"}) +
                                 kIdentifyTail;
  return doc.c_str();
}

/// identify(..., operating_point=None | 'mean' | 'initial').
bonl::OperatingPointSource operating_point_source(const py::object& value) {
  if (value.is_none()) return bonl::OperatingPointSource::Structure;
  if (py::isinstance<py::str>(value)) {
    const std::string name = value.cast<std::string>();
    for (const auto source : {bonl::OperatingPointSource::Mean, bonl::OperatingPointSource::Initial}) {
      if (name == bonl::to_string(source)) return source;
    }
  }
  throw std::invalid_argument("bonl: operating_point must be None (the structure's), 'mean' or 'initial', got " +
                              std::string(py::str(py::repr(value))));
}

template <class Model>
void def_identify(py::module_& m) {
  def_with_identify_arguments(
      m, "identify",
      [](const Model& model, const py::typing::Optional<ArrayLike>& u, const py::typing::Optional<ArrayLike>& y,
         const py::typing::Optional<RecordList>& records, std::optional<double> c0,
         std::optional<Eigen::Index> backlash_hold, int passes, const std::string& method, const Forgetting& forgetting,
         std::optional<double> p0, int refine_iterations, bool normalise, const OperatingPointSource& operating_point,
         Eigen::Index initialisation_window) {
        const bonl::IdentifyOptions options = identify_options(
            {passes, method, forgetting, p0, refine_iterations, normalise, operating_point, initialisation_window});
        const auto settings = model_settings<Model>({c0, backlash_hold});
        std::vector<Eigen::VectorXd> inputs, outputs;
        read_records(u, y, records,
                     "identify(model, u, y) for one record, identify(model, records=[(u1, y1), (u2, y2), ...]) for "
                     "several",
                     inputs, outputs);
        // Checked once, here: one record by the names u and y, several by records[i].
        const bonl::CheckedRecords<double> checked = [&] {
          if (records.is_none()) return bonl::CheckedRecords<double>(inputs[0], outputs[0], model.num_params());
          bonl::Records<double> views;
          for (std::size_t i = 0; i < inputs.size(); ++i) views.emplace_back(inputs[i], outputs[i]);
          return bonl::CheckedRecords<double>(views, model.num_params());
        }();
        // Before identifying: where the records cannot excite the structure the estimator may also break
        // down, and the warning says why.
        const std::string shortfall = bonl::excitation_shortfall(model, checked);
        if (!shortfall.empty()) warn(excitation_warning(), shortfall);
        Model identified = [&] {
          py::gil_scoped_release release;
          return bonl::identify(model, checked, options, settings);
        }();
        const double radius = bonl::pole_radius(identified);
        if (radius >= 0.999) {
          warn(stability_warning(), std::string("the identified ") + Model::kName + " model is " +
                                        (radius >= 1.0 ? "unstable" : "barely damped") +
                                        ": its largest pole has magnitude " + bonl::detail::format_number(radius) +
                                        " (Model.pole_radius); its free run may drift or diverge");
        }
        return identified;
      },
      py::arg("model"), py::arg("u") = py::none(), py::arg("y") = py::none(), py::kw_only(),
      py::arg("records") = py::none(), py::arg("c0") = py::none(), py::arg("backlash_hold") = py::none(),
      identify_doc());
}

/// What Estimator.update_record returns: one status code per sample and, where asked, the
/// prediction and theta after each sample.
struct UpdateResults {
  py::array_t<std::int8_t> status;
  std::optional<Vector> prediction;
  std::optional<py::array_t<double>> theta;
};

/// What Estimator.trajectory returns: bonl::EstimatorTrajectory as numpy arrays, one row per update.
struct EstimatorTrajectory {
  py::array_t<std::int64_t> sample;
  py::array_t<double> theta;
  Vector internal;
  std::vector<bonl::UpdateStatus> status;
};

/// One Python class over the estimators of every model of bonl::Models.
class AnyEstimator {
 public:
  using Variant = bonl::ApplyModels<bonl::MapModels<bonl::Models, bonl::Estimator>::type, std::variant>::type;

  template <class Model>
  AnyEstimator(const Model& model, const bonl::EstimatorOptions& options, const bonl::ModelSettings<Model>& settings)
      : m_estimator(std::in_place_type<bonl::Estimator<Model>>, model, options, settings) {}

  bonl::UpdateStatus update(double u, double y) noexcept {
    return std::visit([&](auto& estimator) { return estimator.update(u, y); }, m_estimator);
  }
  /// A record, the GIL released while it runs: bonl::Estimator::update over the arrays, which equals
  /// the per-sample loop bit for bit.
  UpdateResults update_record(const ArrayLike& u_object, const ArrayLike& y_object, bool want_prediction,
                              bool want_theta) {
    const auto u = to_float64_array(u_object, "u");
    const auto y = to_float64_array(y_object, "y");
    // Unequal lengths: bonl::Estimator::update refuses them before the first sample.
    const py::ssize_t samples = std::min(u.shape(0), y.shape(0));
    const py::ssize_t params = theta().size();
    UpdateResults results{py::array_t<std::int8_t>(samples), std::nullopt, std::nullopt};
    py::array_t<double> prediction(want_prediction ? samples : 0);
    py::array_t<double> theta_rows(std::vector<py::ssize_t>{want_theta ? samples : 0, params});
    std::int8_t* status_out = results.status.mutable_data();
    double* prediction_out = want_prediction ? prediction.mutable_data() : nullptr;
    double* theta_out = want_theta ? theta_rows.mutable_data() : nullptr;
    const Eigen::Map<const Eigen::VectorXd> u_in(u.data(), u.shape(0));
    const Eigen::Map<const Eigen::VectorXd> y_in(y.data(), y.shape(0));
    {
      py::gil_scoped_release release;
      std::visit(
          [&](auto& estimator) {
            estimator.update(u_in, y_in, [&](Eigen::Index k, bonl::UpdateStatus status) {
              status_out[k] = static_cast<std::int8_t>(status);
              if (prediction_out) prediction_out[k] = estimator.last_prediction();
              if (theta_out) Eigen::Map<Eigen::VectorXd>(theta_out + k * params, params) = estimator.theta();
            });
          },
          m_estimator);
    }
    if (want_prediction) results.prediction = std::move(prediction);
    if (want_theta) results.theta = std::move(theta_rows);
    return results;
  }
  Vector theta() const {
    return std::visit([](const auto& estimator) { return to_numpy(Eigen::VectorXd(estimator.theta())); }, m_estimator);
  }
  Eigen::MatrixXd covariance() const {
    return std::visit([](const auto& estimator) { return Eigen::MatrixXd(estimator.covariance()); }, m_estimator);
  }
  AnyModel model() const {
    return std::visit([](const auto& estimator) { return AnyModel(estimator.model()); }, m_estimator);
  }
  Eigen::Index samples() const {
    return std::visit([](const auto& estimator) { return estimator.samples(); }, m_estimator);
  }
  bool diverged() const {
    return std::visit([](const auto& estimator) { return estimator.diverged(); }, m_estimator);
  }
  /// bonl::Estimator::reset(), or reset(theta0) for theta0 not None.
  void reset(const py::typing::Optional<ArrayLike>& theta0) {
    if (theta0.is_none()) {
      std::visit([](auto& estimator) { estimator.reset(); }, m_estimator);
      return;
    }
    const Eigen::VectorXd start = to_vector(theta0, "theta0");
    std::visit([&](auto& estimator) { estimator.reset(start); }, m_estimator);
  }
  void start_pass() {
    std::visit([](auto& estimator) { estimator.start_pass(); }, m_estimator);
  }
  double last_prediction() const {
    return std::visit([](const auto& estimator) { return estimator.last_prediction(); }, m_estimator);
  }
  bonl::EstimatorHealth health() const {
    return std::visit([](const auto& estimator) { return estimator.health(); }, m_estimator);
  }
  void recover() {
    std::visit([](auto& estimator) { estimator.recover(); }, m_estimator);
  }
  double memory() const {
    return std::visit([](const auto& estimator) { return estimator.memory(); }, m_estimator);
  }
  bool measuring_scale() const {
    return std::visit([](const auto& estimator) { return estimator.measuring_scale(); }, m_estimator);
  }
  Eigen::Index pending_samples() const {
    return std::visit([](const auto& estimator) { return estimator.pending_samples(); }, m_estimator);
  }
  std::pair<double, double> data_scale() const {
    const auto scale = std::visit([](const auto& estimator) { return estimator.data_scale(); }, m_estimator);
    return {scale.u, scale.y};
  }
  void catch_up() {
    std::visit([](auto& estimator) { estimator.catch_up(); }, m_estimator);
  }
  void start_recording(Eigen::Index capacity) {
    std::visit([&](auto& estimator) { estimator.start_recording(capacity); }, m_estimator);
  }
  void stop_recording() {
    std::visit([](auto& estimator) { estimator.stop_recording(); }, m_estimator);
  }
  bool recording() const {
    return std::visit([](const auto& estimator) { return estimator.recording(); }, m_estimator);
  }
  EstimatorTrajectory trajectory() const {
    const auto recorded = std::visit([](const auto& estimator) { return estimator.trajectory(); }, m_estimator);
    static_assert(sizeof(Eigen::Index) == sizeof(std::int64_t));
    EstimatorTrajectory out;
    out.sample = py::array_t<std::int64_t>(static_cast<py::ssize_t>(recorded.sample.size()),
                                           reinterpret_cast<const std::int64_t*>(recorded.sample.data()));
    out.theta = py::cast(Eigen::MatrixXd(recorded.theta.transpose()));
    out.internal = Vector(static_cast<py::ssize_t>(recorded.internal.size()), recorded.internal.data());
    out.status = recorded.status;
    return out;
  }

 private:
  Variant m_estimator;
};

template <class Model>
void def_estimator_init(py::class_<AnyEstimator>& cls) {
  cls.def(py::init([](const Model& model, const std::string& method, const Forgetting& forgetting,
                      std::optional<double> p0, std::optional<double> trace_ceiling, Eigen::Index recover_after,
                      double stability_radius, std::optional<bonl::WindowRefinementOptions> window, bool normalise,
                      std::optional<double> c0, std::optional<Eigen::Index> backlash_hold) {
            const bonl::EstimatorOptions options =
                estimator_options({method, forgetting, p0, trace_ceiling, recover_after, stability_radius,
                                   window.value_or(bonl::WindowRefinementOptions{}), normalise});
            return AnyEstimator(model, options, model_settings<Model>({c0, backlash_hold}));
          }),
          py::arg("model"), py::kw_only(), py::arg("method") = "output_error", py::arg("forgetting") = py::none(),
          py::arg("p0") = py::none(), py::arg("trace_ceiling") = py::none(), py::arg("recover_after") = 0,
          py::arg("stability_radius") = 0.999, py::arg("window") = py::none(), py::arg("normalise") = true,
          py::arg("c0") = py::none(), py::arg("backlash_hold") = py::none());
}

}  // namespace

bonl::IdentifyOptions identify_options(const IdentifyArguments& arguments) {
  bonl::IdentifyOptions options;
  static_cast<bonl::EstimatorOptions&>(options) =
      estimator_options({arguments.method, arguments.forgetting, arguments.p0, std::nullopt});
  options.passes = arguments.passes;
  options.refine_iterations = arguments.refine_iterations;
  options.normalise = arguments.normalise;
  options.operating_point = operating_point_source(arguments.operating_point);
  options.initialisation_window = arguments.initialisation_window;
  return options;
}

void read_records(const py::object& u, const py::object& y, const py::object& records, const char* usage,
                  std::vector<Eigen::VectorXd>& inputs, std::vector<Eigen::VectorXd>& outputs) {
  if (records.is_none()) {
    bonl::detail::require(!u.is_none(), std::string("u and y, or records, must be given (") + usage + ")");
    bonl::detail::require(!y.is_none(), std::string("y must be a 1-D array of real numbers, got None (") + usage + ")");
    inputs.push_back(to_vector(u, "u"));
    outputs.push_back(to_vector(y, "y"));
    return;
  }
  bonl::detail::require(u.is_none() && y.is_none(), std::string("give u and y, or records, not both (") + usage + ")");
  bonl::detail::require(
      !py::isinstance<py::array>(records) && py::isinstance<py::sequence>(records) && !py::isinstance<py::str>(records),
      "records must be a list of pairs (u, y), got " + type_name(records) + " (" + usage + ")");
  const py::sequence list = records.cast<py::sequence>();
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string name = "records[" + std::to_string(i) + "]";
    const py::object item = list[i];
    bonl::detail::require(!py::isinstance<py::array>(item) && py::isinstance<py::sequence>(item) &&
                              !py::isinstance<py::str>(item) && py::len(item) == 2,
                          name + " must be a pair (u, y): " + usage);
    const py::sequence pair = item.cast<py::sequence>();
    inputs.push_back(to_vector(pair[0], (name + ".u").c_str()));
    outputs.push_back(to_vector(pair[1], (name + ".y").c_str()));
  }
}

void bind_estimation(py::module_& m) {
  py::enum_<bonl::UpdateStatus>(m, "UpdateStatus", "What one online update did.")
      .value("updated", bonl::UpdateStatus::Updated, "theta and P were updated")
      .value("no_information", bonl::UpdateStatus::NoInformation,
             "the sample says nothing about theta (inside the backlash gap)")
      .value("rejected_non_finite", bonl::UpdateStatus::RejectedNonFinite,
             "u or y was NaN or infinite; the estimator's state is untouched")
      .value("numerical_failure", bonl::UpdateStatus::NumericalFailure,
             "the update would have broken the covariance, or the internal variables left the finite numbers; "
             "theta and P kept, diverged is set");

  py::class_<bonl::WindowRefinementOptions>(
      m, "WindowRefinementOptions",
      "The output-error method's window refinement (Estimator(..., window=...)): Levenberg-Marquardt on the\n"
      "free-run error of the newest samples, spread over the updates, its estimate swapped in where it\n"
      "predicts the newest samples better. On by default (docs/explanation/algorithm.md).")
      .def(py::init([](bool enabled, Eigen::Index length, Eigen::Index work_per_sample, bool equation_error_start) {
             bonl::WindowRefinementOptions options;
             options.enabled = enabled;
             options.length = length;
             options.work_per_sample = work_per_sample;
             options.equation_error_start = equation_error_start;
             return options;
           }),
           py::kw_only(), py::arg("enabled") = true, py::arg("length") = 4000, py::arg("work_per_sample") = 8,
           py::arg("equation_error_start") = true,
           "Window refinement options, the estimator's defaults unless given.\n\n"
           "Parameters\n----------\nenabled : bool, default True\n    Whether the refinement runs.\n"
           "length : int, default 4000\n    The most samples it fits at once (>= 100).\n"
           "work_per_sample : int, default 8\n    Model steps of the refinement per update (>= 2), for each window.\n"
           "equation_error_start : bool, default True\n    A second window beside, started from an equation-error\n"
           "    recursion's estimate (identify()'s second start); doubles the refinement's work.\n\n"
           "Returns\n-------\nWindowRefinementOptions\n    The options; the Estimator checks them.")
      .def_readwrite("enabled", &bonl::WindowRefinementOptions::enabled, "bool: whether the refinement runs")
      .def_readwrite("length", &bonl::WindowRefinementOptions::length, "int: the most samples it fits at once (>= 100)")
      .def_readwrite("work_per_sample", &bonl::WindowRefinementOptions::work_per_sample,
                     "int: model steps of the refinement per update (>= 2), for each window")
      .def_readwrite("equation_error_start", &bonl::WindowRefinementOptions::equation_error_start,
                     "bool: a second window beside, started from an equation-error recursion's estimate");

  py::class_<bonl::WindowRefinementCounts>(m, "WindowRefinementCounts",
                                           "What the window refinement did since the Estimator's reset().")
      .def_readonly("iterations", &bonl::WindowRefinementCounts::iterations, "int: Levenberg-Marquardt steps kept")
      .def_readonly("refused_steps", &bonl::WindowRefinementCounts::refused_steps,
                    "int: trial steps that did not simulate the window better")
      .def_readonly("swaps", &bonl::WindowRefinementCounts::swaps, "int: refined estimates swapped into the recursion")
      .def_readonly("refusals", &bonl::WindowRefinementCounts::refusals,
                    "int: refined estimates not swapped in (the recursion predicted the newest samples as well)")
      .def_readonly("undetermined", &bonl::WindowRefinementCounts::undetermined,
                    "int: refined estimates not swapped in although they predicted the newest samples better: the "
                    "window's data do not determine every parameter, or the covariance would not be positive definite")
      .def_readonly("reseeds", &bonl::WindowRefinementCounts::reseeds,
                    "int: restarts with the newest samples only (a change of the plant)")
      .def_readonly("overruns", &bonl::WindowRefinementCounts::overruns,
                    "int: restarts because the slices fell behind or a run left the finite numbers");

  py::class_<bonl::EstimatorHealth>(m, "EstimatorHealth", "What an Estimator's numerical safeguards did since reset().")
      .def_readonly("window", &bonl::EstimatorHealth::window, "WindowRefinementCounts: what the window refinement did")
      .def_readonly("diverged", &bonl::EstimatorHealth::diverged,
                    "bool: a numerical failure happened (cleared by recover() and reset())")
      .def_readonly("failures", &bonl::EstimatorHealth::failures, "int: updates refused for numerical reasons")
      .def_readonly("consecutive_failures", &bonl::EstimatorHealth::consecutive_failures,
                    "int: refused in a row, up to the last update")
      .def_readonly("forgetting_limited", &bonl::EstimatorHealth::forgetting_limited,
                    "int: updates whose forgetting the trace ceiling reduced")
      .def_readonly("recoveries", &bonl::EstimatorHealth::recoveries,
                    "int: automatic covariance resets (recover_after)")
      .def_readonly("internal_restarts", &bonl::EstimatorHealth::internal_restarts,
                    "int: internal variables restarted because they became non-finite")
      .def_readonly("projections", &bonl::EstimatorHealth::projections,
                    "int: output_error updates shortened to keep the linear block stable")
      .def_readonly("checkpoint_returns", &bonl::EstimatorHealth::checkpoint_returns,
                    "int: output_error returns to the checkpoint, which predicted far better")
      .def("__repr__", [](const bonl::EstimatorHealth& h) {
        return "EstimatorHealth(diverged=" + std::string(h.diverged ? "True" : "False") +
               ", failures=" + std::to_string(h.failures) +
               ", consecutive_failures=" + std::to_string(h.consecutive_failures) +
               ", forgetting_limited=" + std::to_string(h.forgetting_limited) +
               ", recoveries=" + std::to_string(h.recoveries) +
               ", internal_restarts=" + std::to_string(h.internal_restarts) +
               ", projections=" + std::to_string(h.projections) +
               ", checkpoint_returns=" + std::to_string(h.checkpoint_returns) + ")";
      });

  bonl::for_each_model(bonl::Models{}, [&m](auto tag) { def_identify<typename decltype(tag)::type>(m); });

  static const std::string estimator_doc =
      "Online recursive estimator for one model.\n\nParameters\n----------\nmodel : one of bonl.MODELS\n"
      "    Gives the structure; the estimate starts from zero (P-H-W: c = c0 for equation_error and\n"
      "    paper, c = 0 for output_error).\n" +
      option_docs({"method", "forgetting", "p0", "trace_ceiling", "recover_after", "stability_radius", "window",
                   "normalise", "c0", "backlash_hold"});
  py::class_<AnyEstimator> estimator(m, "Estimator", estimator_doc.c_str());
  bonl::for_each_model(bonl::Models{},
                       [&estimator](auto tag) { def_estimator_init<typename decltype(tag)::type>(estimator); });
  py::class_<UpdateResults>(m, "UpdateResults", "What Estimator.update_record returns for a record.")
      .def_readonly("status", &UpdateResults::status,
                    "numpy.ndarray of int8: each sample's UpdateStatus, as int(UpdateStatus.<name>)")
      .def_readonly("prediction", &UpdateResults::prediction,
                    "numpy.ndarray or None: last_prediction after each sample (when asked for)")
      .def_readonly("theta", &UpdateResults::theta,
                    "numpy.ndarray (samples, n) or None: theta after each sample (when asked for)");
  py::class_<EstimatorTrajectory>(m, "EstimatorTrajectory",
                                  "What Estimator.trajectory returns: the recorded updates, oldest first.")
      .def_readonly("sample", &EstimatorTrajectory::sample,
                    "numpy.ndarray of int64, shape (k,): each update's sample number since reset()")
      .def_readonly("theta", &EstimatorTrajectory::theta, "numpy.ndarray, shape (k, n): the estimate after each update")
      .def_readonly("internal", &EstimatorTrajectory::internal,
                    "numpy.ndarray, shape (k,): the internal variable x(k) each update used (NaN for ARX)")
      .def_readonly("status", &EstimatorTrajectory::status, "list of UpdateStatus: each update's status")
      .def("__len__", [](const EstimatorTrajectory& t) { return t.status.size(); })
      .def("__repr__", [](const EstimatorTrajectory& t) {
        return "EstimatorTrajectory(" + std::to_string(t.status.size()) + " updates)";
      });
  estimator
      .def("update", &AnyEstimator::update, py::arg("u"), py::arg("y"), R"doc(Process one sample.

Parameters
----------
u, y : float
    Input and measured output.

Returns
-------
UpdateStatus
    A non-finite u or y is rejected (rejected_non_finite) and leaves the state untouched.
    An Estimator must not be used from two threads at once.)doc")
      .def("update_record", &AnyEstimator::update_record, py::arg("u"), py::arg("y"), py::kw_only(),
           py::arg("prediction") = false, py::arg("theta") = false, R"doc(Process a record in one call.

C++'s ``estimator.update(u, y, on_sample)``, the GIL released: the same, bit for bit, as calling
update on each sample in turn.

Parameters
----------
u, y : array_like, shape (n,)
    Input and measured output, of equal length.
prediction, theta : bool, default False
    Also return last_prediction, and theta, after every sample.

Returns
-------
UpdateResults
    ``status``, an int8 array of ``int(UpdateStatus.<name>)`` codes (a non-finite sample is
    rejected_non_finite and leaves the state untouched), and ``prediction``, ``theta`` when asked for.)doc")
      .def_property_readonly("theta", &AnyEstimator::theta,
                             "numpy.ndarray: current estimate (eq. 19 order); with the window refinement, the "
                             "window's while it predicts the newest samples about as well as the recursion's.")
      .def_property_readonly("covariance", &AnyEstimator::covariance,
                             "numpy.ndarray: current P of the recursion (symmetric).")
      .def_property_readonly("model", &AnyEstimator::model, "The current estimate as a model.")
      .def_property_readonly("samples", &AnyEstimator::samples, "int: samples since the last pass started.")
      .def_property_readonly("diverged", &AnyEstimator::diverged, "bool: an update was refused for numerical reasons.")
      .def("reset", &AnyEstimator::reset, py::arg("theta0") = py::none(),
           R"doc(Back to the initial estimate, P = p0 I, internal variables at rest; or restart from theta0.

Parameters
----------
theta0 : array_like, shape (num_params,), optional
    The estimate to restart from (a warm start: the model's parameter vector, e.g. an identified
    model's theta). ValueError for theta0 of another length.)doc")
      .def("start_pass", &AnyEstimator::start_pass,
           "A new pass over a record: theta and P carry on, the forgetting schedule and internals restart.")
      .def_property_readonly("last_prediction", &AnyEstimator::last_prediction,
                             "float: the prediction of the last sample's y, made before the update "
                             "(y - last_prediction is the innovation); for output_error the simulated output.")
      .def_property_readonly("memory", &AnyEstimator::memory,
                             "float: the adaptive memory's current length 1 / (1 - lambda) in samples (NaN for a "
                             "step schedule).")
      .def_property_readonly("health", &AnyEstimator::health,
                             "EstimatorHealth: what the numerical safeguards did since reset().")
      .def_property_readonly("measuring_scale", &AnyEstimator::measuring_scale,
                             "bool: the data's scale is still being measured (normalise=True): updates return "
                             "no_information and the estimate stays where it started.")
      .def_property_readonly("pending_samples", &AnyEstimator::pending_samples,
                             "int: samples kept while the scale was measured that the recursion has yet to take "
                             "(two per update); theta lags the data by them.")
      .def_property_readonly("data_scale", &AnyEstimator::data_scale,
                             "tuple[float, float]: the scale of u - u0 and y - y0 the recursion works in (their RMS "
                             "over the samples measured; (1.0, 1.0) where not normalised or still measuring).")
      .def("catch_up", &AnyEstimator::catch_up,
           "Take now what the recursion has yet to: a scale measurement under way ends with what it has\n"
           "measured, and every sample kept is processed (at a record's end; start_pass does it too).")
      .def("recover", &AnyEstimator::recover,
           "Leave the diverged state: P = p0 I, theta kept (a covariance reset); the counters in health stay.")
      .def("start_recording", &AnyEstimator::start_recording, py::arg("capacity"),
           R"doc(Record theta, the internal variable and the status of the next updates.

Parameters
----------
capacity : int
    How many of the newest updates to keep, >= 1 (a ring buffer, allocated here once).)doc")
      .def("stop_recording", &AnyEstimator::stop_recording, "Stop recording and free the buffer.")
      .def_property_readonly("recording", &AnyEstimator::recording, "bool: updates are being recorded.")
      .def("trajectory", &AnyEstimator::trajectory, R"doc(What was recorded, oldest first.

Returns
-------
EstimatorTrajectory
    ``sample``: int64 array (k,), sample number since reset(); ``theta``: array (k, n), the estimate
    after each update; ``internal``: array (k,), the internal variable x(k) the update used (NaN for
    ARX); ``status``: list of UpdateStatus.)doc");
}

}  // namespace bonl_python
