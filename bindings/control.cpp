// bonl.control: the inverse models (bonl/control/): per sample, the command that makes an identified
// model follow a reference, and the commands for a whole reference. One Python class over
// InverseModel<Model> for every model of bonl::control::InvertibleModels; the others are refused with
// a ValueError that says why.

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <bonl/control.hpp>
#include <bonl/models.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

#include "bindings.hpp"
#include "conversions.hpp"
#include "estimator_options.hpp"
#include "option_docs.hpp"

namespace bonl_python {
namespace {

using bonl::control::InverseStatus;

/// The commands for a whole reference, as numpy arrays.
struct InverseRunArrays {
  Vector command;
  py::array_t<std::uint8_t> status;
};

/// step's reference: one number, or a window of the reference (an array, list or tuple).
BONL_PYTHON_TYPED(Reference, "float | numpy.typing.ArrayLike");

/// A model of InvertibleModels: Python sees the union of their classes.
using InvertibleModel = bonl::ApplyModels<bonl::control::InvertibleModels, std::variant>::type;

/// ValueError for a refused step (the inverse is untouched).
void raise_if_rejected(InverseStatus status, Eigen::Index window_size, Eigen::Index given) {
  bonl::detail::require(status != InverseStatus::RejectedNonFinite,
                        "reference must be finite (every entry of the window)");
  bonl::detail::require(status != InverseStatus::RejectedOverflow,
                        "the reference is too large: the inverse's arithmetic overflowed (nothing changed)");
  bonl::detail::require(status != InverseStatus::RejectedShortPreview,
                        "the reference window needs " + std::to_string(window_size) +
                            " samples (r(k + nk), ..., r(k + preview)), got " + std::to_string(given));
}

/// One step of `inverse` (an InverseModel or an AdaptiveInverse) on a Python reference: a window (array,
/// list or tuple) or a single number; ValueError for a refused step.
template <class Inverse>
bonl::control::InverseStep<double> step_on(Inverse& inverse, Eigen::Index window_size, const py::object& reference) {
  bonl::control::InverseStep<double> out{0.0, InverseStatus::Exact};
  Eigen::Index given = 1;
  if (py::isinstance<py::array>(reference) || py::isinstance<py::list>(reference) ||
      py::isinstance<py::tuple>(reference)) {
    const Eigen::VectorXd window = to_vector(reference, "reference");
    given = window.size();
    out = inverse.step(window);
  } else {
    out = inverse.step(to_scalar(reference, "reference"));
  }
  raise_if_rejected(out.status, window_size, given);
  return out;
}

template <class Model>
using InverseOf = bonl::control::InverseModel<Model>;

class AnyInverse {
 public:
  using Variant =
      bonl::ApplyModels<bonl::MapModels<bonl::control::InvertibleModels, InverseOf>::type, std::variant>::type;

  template <class Model>
  AnyInverse(const Model& model, const bonl::control::InverseOptions& options)
      : m_inverse(std::in_place_type<InverseOf<Model>>, model, options) {}

  bonl::control::InverseStep<double> step(const Reference& reference) {
    return std::visit([&](auto& inverse) { return step_on(inverse, inverse.window_size(), reference); }, m_inverse);
  }

  InverseRunArrays commands(const ArrayLike& reference_object) const {
    const Eigen::VectorXd reference = to_vector(reference_object, "reference");
    bonl::control::InverseRun<double> run;
    {
      py::gil_scoped_release release;
      run = std::visit([&](const auto& inverse) { return inverse.commands(reference); }, m_inverse);
    }
    py::array_t<std::uint8_t> status(static_cast<py::ssize_t>(run.status.size()));
    for (std::size_t k = 0; k < run.status.size(); ++k) status.mutable_at(k) = static_cast<std::uint8_t>(run.status[k]);
    return {to_numpy(std::move(run.command)), std::move(status)};
  }

  void reset() noexcept {
    std::visit([](auto& inverse) { inverse.reset(); }, m_inverse);
  }
  Eigen::Index nk() const {
    return std::visit([](const auto& inverse) { return inverse.nk(); }, m_inverse);
  }
  Eigen::Index preview() const {
    return std::visit([](const auto& inverse) { return inverse.preview(); }, m_inverse);
  }
  Eigen::Index window_size() const {
    return std::visit([](const auto& inverse) { return inverse.window_size(); }, m_inverse);
  }
  bool minimum_phase() const {
    return std::visit([](const auto& inverse) { return inverse.minimum_phase(); }, m_inverse);
  }
  double command_min() const {
    return std::visit([](const auto& inverse) { return inverse.command_min(); }, m_inverse);
  }
  double command_max() const {
    return std::visit([](const auto& inverse) { return inverse.command_max(); }, m_inverse);
  }
  Vector stable_factor() const {
    return std::visit(
        [](const auto& inverse) { return to_numpy(Eigen::VectorXd(inverse.linear_inverse().stable_factor())); },
        m_inverse);
  }
  Vector unstable_factor() const {
    return std::visit(
        [](const auto& inverse) { return to_numpy(Eigen::VectorXd(inverse.linear_inverse().unstable_factor())); },
        m_inverse);
  }

 private:
  Variant m_inverse;
};

bonl::control::InverseOptions inverse_options(std::optional<double> command_min, std::optional<double> command_max,
                                              double backlash_band, double backlash_band_per_c) {
  bonl::control::InverseOptions options;
  options.command_min = command_min.value_or(std::numeric_limits<double>::quiet_NaN());
  options.command_max = command_max.value_or(std::numeric_limits<double>::quiet_NaN());
  options.backlash_band = backlash_band;
  options.backlash_band_per_c = backlash_band_per_c;
  return options;
}

template <class Model>
void def_inverse_init(py::class_<AnyInverse>& cls) {
  cls.def(py::init([](const Model& model, std::optional<double> command_min, std::optional<double> command_max,
                      double backlash_band, double backlash_band_per_c) {
            return AnyInverse(model, inverse_options(command_min, command_max, backlash_band, backlash_band_per_c));
          }),
          py::arg("model"), py::kw_only(), py::arg("command_min") = py::none(), py::arg("command_max") = py::none(),
          py::arg("backlash_band") = 0.0, py::arg("backlash_band_per_c") = 0.0);
}

template <class Model>
using AdaptiveOf = bonl::control::AdaptiveInverse<Model>;

/// bonl.control.AdaptiveInverse over AdaptiveInverse<Model> for every model of InvertibleModels.
class AnyAdaptive {
 public:
  using Variant =
      bonl::ApplyModels<bonl::MapModels<bonl::control::InvertibleModels, AdaptiveOf>::type, std::variant>::type;

  template <class Model>
  AnyAdaptive(const Model& model, const bonl::control::AdaptiveInverseOptions& options)
      : m_adaptive(std::in_place_type<AdaptiveOf<Model>>, model, options) {}

  bonl::control::InverseStep<double> step(const Reference& reference) {
    return std::visit([&](auto& adaptive) { return step_on(adaptive, adaptive.inverse().window_size(), reference); },
                      m_adaptive);
  }
  bonl::UpdateStatus update(const Real& u, const Real& y) {
    const double u_value = to_scalar(u, "u");
    const double y_value = to_scalar(y, "y");
    return std::visit([&](auto& adaptive) { return adaptive.update(u_value, y_value); }, m_adaptive);
  }
  bool rederive() {
    return std::visit([](auto& adaptive) { return adaptive.rederive(); }, m_adaptive);
  }
  InvertibleModel model() const {
    return std::visit([](const auto& adaptive) { return InvertibleModel(adaptive.model()); }, m_adaptive);
  }
  InvertibleModel estimate() const {
    return std::visit([](const auto& adaptive) { return InvertibleModel(adaptive.estimator().model()); }, m_adaptive);
  }
  bonl::control::AdaptiveInverseHealth health() const {
    return std::visit([](const auto& adaptive) { return adaptive.health(); }, m_adaptive);
  }

 private:
  Variant m_adaptive;
};

template <class Model>
void def_adaptive_init(py::class_<AnyAdaptive>& cls) {
  cls.def(py::init([](const Model& model, std::optional<double> command_min, std::optional<double> command_max,
                      double backlash_band, double backlash_band_per_c, const std::string& method,
                      const Forgetting& forgetting, std::optional<double> p0, Eigen::Index rederive_every,
                      double max_covariance_trace, double stability_radius) {
            bonl::control::AdaptiveInverseOptions options;
            options.inverse = inverse_options(command_min, command_max, backlash_band, backlash_band_per_c);
            options.estimator = estimator_options({method, forgetting, p0, std::nullopt});
            options.rederive_every = rederive_every;
            options.max_covariance_trace = max_covariance_trace;
            options.stability_radius = stability_radius;
            return AnyAdaptive(model, options);
          }),
          py::arg("model"), py::kw_only(), py::arg("command_min") = py::none(), py::arg("command_max") = py::none(),
          py::arg("backlash_band") = 0.0, py::arg("backlash_band_per_c") = 0.0, py::arg("method") = "output_error",
          py::arg("forgetting") = py::none(), py::arg("p0") = py::none(), py::arg("rederive_every") = 100,
          py::arg("max_covariance_trace") = 10.0, py::arg("stability_radius") = 0.999);
}

/// For a model without an inverse: the constructor that says so (a ValueError, not pybind11's
/// "incompatible arguments").
template <class Model, class Class>
void def_no_inverse_init(Class& cls) {
  cls.def(py::init([](const Model&, const py::kwargs&) -> typename Class::type* {
            throw std::invalid_argument(std::string("bonl.control: the ") + Model::kName +
                                        " model has no inverse yet (only models with one linear block do)");
          }),
          py::arg("model"));
}

/// def_init<Model>(cls) for every model of bonl::Models: the real constructor where the model has an
/// inverse, def_no_inverse_init where it does not.
template <class Class, class DefInit>
void def_inits(Class& cls, DefInit def_init) {
  bonl::for_each_model(bonl::Models{}, [&](auto tag) {
    using Model = typename decltype(tag)::type;
    if constexpr (bonl::control::has_inverse<Model>::value) {
      def_init(cls, tag);
    } else {
      def_no_inverse_init<Model>(cls);
    }
  });
}

/// InverseModel.step's docstring, and AdaptiveInverse.step's (the step of the inverse in use).
const char* kStepDoc = R"doc(The command u(k) for the reference ahead.

Parameters
----------
reference : float or 1-D array
    r(k + nk) (a float, where window_size is 1), or the window r(k + nk), ..., r(k + preview) (at
    least window_size entries).

Returns
-------
InverseStep: ``value`` (the command) and ``status`` (InverseStatus flags). A non-finite reference or a
window too short raises ValueError and leaves the inverse untouched.)doc";

}  // namespace

void bind_control(py::module_& m) {
  py::module_ control = m.def_submodule(
      "control",
      "Inverse models: the command that makes an identified model follow a reference (docs/how-to/control.md).");

  py::enum_<InverseStatus>(control, "InverseStatus", py::arithmetic(),
                           "What an inverse reports with a command: flags, exact (0) when the model follows the "
                           "reference. Combined flags are their sum (status & InverseStatus.saturated).")
      .value("exact", InverseStatus::Exact, "the command makes the model reach the reference")
      .value("saturated", InverseStatus::Saturated,
             "the command is at the end of its range (or of the input polynomial's monotone branch)")
      .value("dead_band", InverseStatus::DeadBand,
             "the reference asks for a w between the input polynomial's two segments at u = 0: command 0")
      .value("out_of_range", InverseStatus::OutOfRange,
             "the output polynomial's monotone branch through 0 does not reach the reference: its end is used")
      .value("rejected_non_finite", InverseStatus::RejectedNonFinite,
             "a reference was NaN or infinite; the inverse is untouched")
      .value("rejected_overflow", InverseStatus::RejectedOverflow,
             "the reference is so large that the inverse's arithmetic overflowed; the inverse is untouched")
      .value("rejected_short_preview", InverseStatus::RejectedShortPreview,
             "the reference window was shorter than window_size; the inverse is untouched");

  py::class_<bonl::control::InverseStep<double>>(control, "InverseStep", "One command and what the inverse reports.")
      .def_readonly("value", &bonl::control::InverseStep<double>::value, "float: the command u(k)")
      .def_property_readonly(
          "status", [](const bonl::control::InverseStep<double>& s) { return static_cast<int>(s.status); },
          "int: the InverseStatus flags (0: exact)")
      .def("__repr__", [](const bonl::control::InverseStep<double>& s) {
        return "InverseStep(value=" + bonl::detail::format_number(s.value) +
               ", status=" + std::to_string(static_cast<int>(s.status)) + ")";
      });

  py::class_<InverseRunArrays>(control, "InverseRun", "The commands for a whole reference.")
      .def_readonly("command", &InverseRunArrays::command, "numpy.ndarray: u(k) for every sample of the reference")
      .def_readonly("status", &InverseRunArrays::status, "numpy.ndarray of uint8: each command's InverseStatus flags");

  py::class_<AnyInverse> inverse(control, "InverseModel", R"doc(The inverse of an identified model.

Per sample, given the reference output ``preview`` samples ahead, the command that makes the model
follow it: the backlash inverse (P-H-W) or the output polynomial's inverse (H-W, Wiener), the linear
block's inverse (exact where B is minimum phase, ZPETC where not), the input polynomial's inverse
(Hammerstein, H-W, P-H-W) or the input hysteresis' (Prandtl-Ishlinskii Hammerstein, its plays' memory
followed). docs/how-to/control.md.

Parameters
----------
model : one of bonl.MODELS
command_min, command_max : float, optional
    The command range (the model's input units); it must contain the operating point's u0. Default:
    the model's input_range. Models with an input polynomial need it finite.
backlash_band : float, default 0
    P-H-W: the backlash inverse's transition band (the output's units); 0 is the exact switch.
backlash_band_per_c : float, default 0
    P-H-W: added to the band, times the model's c (1: a band of c).

Raises ValueError where the model has no inverse (b_0 = 0, a zero of B at z = 1, q_1 = 0, an input
polynomial that is not monotone through 0, input hysteresis whose slope can take either sign near 0).)doc");
  def_inits(inverse, [](auto& cls, auto tag) { def_inverse_init<typename decltype(tag)::type>(cls); });
  inverse.def("step", &AnyInverse::step, py::arg("reference"), kStepDoc)
      .def("commands", &AnyInverse::commands, py::arg("reference"),
           R"doc(The commands for a whole reference r(0..N-1), from rest (this object's state is not used).

u(k) is computed from r(k + nk), ..., r(k + preview), the reference held at its last value beyond its end;
model.simulate(run.command) then follows r from k = nk on where every status is exact.

Parameters
----------
reference : array_like, shape (N,)
    r(0..N-1), in the model's output units; finite, longer than preview (else ValueError).

Returns
-------
InverseRun
    ``command``, the N commands, and ``status``, each command's InverseStatus.)doc")
      .def("reset", &AnyInverse::reset, "Back to rest, as the model's free run starts.")
      .def_property_readonly("nk", &AnyInverse::nk, "int: the model's delay")
      .def_property_readonly("preview", &AnyInverse::preview,
                             "int: how far ahead the last reference of a step lies (nk, plus ZPETC's preview)")
      .def_property_readonly("window_size", &AnyInverse::window_size,
                             "int: how many reference samples a step takes (1 when B is minimum phase)")
      .def_property_readonly("minimum_phase", &AnyInverse::minimum_phase,
                             "bool: B's zeros all inside the unit circle (the exact inverse; else ZPETC)")
      .def_property_readonly("command_min", &AnyInverse::command_min, "float: the command range's lower end")
      .def_property_readonly("command_max", &AnyInverse::command_max, "float: the command range's upper end")
      .def_property_readonly("stable_factor", &AnyInverse::stable_factor,
                             "numpy.ndarray: B_a, B's factor with the zeros inside the unit circle (b_0 included)")
      .def_property_readonly("unstable_factor", &AnyInverse::unstable_factor,
                             "numpy.ndarray: B_u, the factor with the others, leading 1 ([1.0] when minimum phase)");

  using Health = bonl::control::AdaptiveInverseHealth;
  py::class_<Health>(control, "AdaptiveInverseHealth", "What an AdaptiveInverse's guard did.")
      .def_readonly("rederivations", &Health::rederivations, "int: new inverses put in use")
      .def_readonly("refused_diverged", &Health::refused_diverged, "int: estimates refused: the estimator had diverged")
      .def_readonly("refused_covariance", &Health::refused_covariance,
                    "int: estimates refused: trace(P) above the limit")
      .def_readonly("refused_unstable", &Health::refused_unstable,
                    "int: estimates refused: a pole at or beyond stability_radius")
      .def_readonly("refused_no_inverse", &Health::refused_no_inverse,
                    "int: estimates refused: InverseModel refused the estimate")
      .def_readonly("last_refusal", &Health::last_refusal,
                    "str: why the last refused estimate was refused ('' if none)")
      .def("__repr__", [](const Health& h) {
        return "AdaptiveInverseHealth(rederivations=" + std::to_string(h.rederivations) +
               ", refused_diverged=" + std::to_string(h.refused_diverged) +
               ", refused_covariance=" + std::to_string(h.refused_covariance) +
               ", refused_unstable=" + std::to_string(h.refused_unstable) +
               ", refused_no_inverse=" + std::to_string(h.refused_no_inverse) + ")";
      });

  static const std::string adaptive_doc = R"doc(The online estimator and the inverse together.

``update(u, y)`` feeds the command applied (feedback included) and the output measured to the
estimator, warm-started from ``model``; every ``rederive_every`` samples the inverse is derived
again from the estimate, if the guard trusts it (the estimator has not diverged, trace(P) <=
max_covariance_trace * n * p0, every pole inside stability_radius, the estimate has an inverse), and
goes on from where the old one was. ``step`` is the inverse in use. docs/how-to/control.md, "Adaptive use".

Parameters
----------
model : one of bonl.MODELS
    The identified model to start from.
command_min, command_max, backlash_band, backlash_band_per_c
    As for InverseModel.
)doc" + option_docs({"method", "forgetting", "p0"}) +
                                          R"doc(rederive_every : int, default 100
max_covariance_trace : float, default 10
stability_radius : float, default 0.999

Raises ValueError for bad options or a model without an inverse.)doc";
  py::class_<AnyAdaptive> adaptive(control, "AdaptiveInverse", adaptive_doc.c_str());
  def_inits(adaptive, [](auto& cls, auto tag) { def_adaptive_init<typename decltype(tag)::type>(cls); });
  adaptive.def("step", &AnyAdaptive::step, py::arg("reference"), kStepDoc)
      .def("update", &AnyAdaptive::update, py::arg("u"), py::arg("y"),
           R"doc(One sample of the plant, to the estimator; every rederive_every samples, rederive().

Parameters
----------
u : float
    The command applied (the whole command, feedback included).
y : float
    The output measured.

Returns
-------
UpdateStatus
    The estimator's (rejected_non_finite for a NaN or infinite value: nothing changes).)doc")
      .def("rederive", &AnyAdaptive::rederive,
           R"doc(Derive the inverse from the estimate now, if the guard trusts it.

Returns
-------
bool
    Whether the new inverse is in use; if not, the last good one stays and health says why.)doc")
      .def_property_readonly("model", &AnyAdaptive::model, "The model the inverse in use was derived from.")
      .def_property_readonly("estimate", &AnyAdaptive::estimate, "The estimator's current estimate, as a model.")
      .def_property_readonly(
          "health", &AnyAdaptive::health,
          "AdaptiveInverseHealth: rederivations, the refusals by reason (refused_diverged,\n"
          "refused_covariance, refused_unstable, refused_no_inverse) and last_refusal (why, '' if none).");
}

}  // namespace bonl_python
