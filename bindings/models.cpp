// The models in Python, one class per entry of bonl::Models (the run-time-order C++ models), each
// bound from its description alone: constructor, orders, parameter blocks, params, repr, pickling.
// bonl.MODELS is the tuple of the classes, in the list's order.

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <string>
#include <utility>

#include <bonl/io/model_json.hpp>
#include <bonl/models.hpp>

#include "bindings.hpp"
#include "conversions.hpp"

namespace bonl_python {
namespace {

const char* kSimulateDoc = R"doc(Free-run simulation, from rest or after a measured past.

Parameters
----------
u : array_like, shape (n,)
    Input sequence.
initial : (u_past, y_past), optional
    The measured samples just before u. They set the model's state (its internal variables are what
    the measured past says, as predict() takes them); then the model runs on u alone. The
    benchmarks' state-initialisation window of m samples is
    ``model.simulate(u[m:], initial=(u[:m], y[:m]))``. None: from rest at the operating point.

Returns
-------
numpy.ndarray, shape (n,)
    The model's output, driven by u alone after the initial state.

Raises
------
ValueError
    If u or the past is not a finite 1-D array, or u_past and y_past differ in length.
bonl.NumericalError
    If the simulation leaves the finite numbers (an unstable model).)doc";

const char* kPredictDoc = R"doc(One-step-ahead prediction from measured data.

Parameters
----------
u : array_like, shape (n,)
    Input sequence.
y : array_like, shape (n,)
    Measured output; y[k] is used to predict y[k + 1].
initial : (u_past, y_past), optional
    The measured samples just before u and y (None: from rest at the operating point).

Returns
-------
numpy.ndarray, shape (n,)
    The prediction of y[k] from u up to k and y up to k - 1. Internal variables are taken from the
    measured output where the model lets them (Hammerstein: x = y; H-W: x = q^-1(y); P-H-W: the
    backlash memory is the measured y[k - 1]).)doc";

py::handle g_extrapolation_warning;  // created in bind_models, kept for the module's life
py::handle g_stability_warning;
py::handle g_excitation_warning;

/// The ExtrapolationWarning for simulate() on inputs outside the model's input range, if any are.
template <class Model>
void warn_if_extrapolating(const Model& model, const Eigen::VectorXd& u) {
  const Eigen::Index outside = model.extrapolated_samples(u);
  if (outside == 0) return;
  warn(extrapolation_warning(),
       std::to_string(outside) + " of " + std::to_string(u.size()) + " samples of u lie outside the input range [" +
           bonl::detail::format_number(model.input_min()) + ", " + bonl::detail::format_number(model.input_max()) +
           "] the model was identified on (u from " + bonl::detail::format_number(u.minCoeff()) + " to " +
           bonl::detail::format_number(u.maxCoeff()) + "): its output there is an extrapolation");
}

/// A pair of real numbers (first, second), or a ValueError naming `what` and its entries.
std::pair<double, double> read_pair(const py::object& value, const char* what, const char* first, const char* second) {
  bonl::detail::require(!py::isinstance<py::str>(value) && py::isinstance<py::sequence>(value) && py::len(value) == 2,
                        std::string(what) + " must be a pair (" + first + ", " + second + "), got " + type_name(value));
  const py::sequence pair = value.cast<py::sequence>();
  return {to_scalar(pair[0], first), to_scalar(pair[1], second)};
}

/// initial=(u_past, y_past): the measured recent past, or None (rest): (u_past, y_past) as vectors.
std::pair<Eigen::VectorXd, Eigen::VectorXd> read_initial(const py::object& initial) {
  if (initial.is_none()) return {Eigen::VectorXd(0), Eigen::VectorXd(0)};
  bonl::detail::require(
      !py::isinstance<py::array>(initial) && py::isinstance<py::sequence>(initial) &&
          !py::isinstance<py::str>(initial) && py::len(initial) == 2,
      "initial must be None or a pair (u_past, y_past) of the measured recent past, got " + type_name(initial));
  const py::sequence pair = initial.cast<py::sequence>();
  return {to_vector(pair[0], "u_past"), to_vector(pair[1], "y_past")};
}

/// Methods every model shares.
template <class Model>
void bind_common(py::class_<Model>& cls) {
  cls.def(
         "simulate",
         [](const Model& model, const ArrayLike& u, const py::typing::Optional<Record>& initial) {
           const Eigen::VectorXd input = to_vector(u, "u");
           const auto [u_past, y_past] = read_initial(initial);
           warn_if_extrapolating(model, input);
           Eigen::VectorXd output;
           {
             py::gil_scoped_release release;
             output = u_past.size() == 0 && y_past.size() == 0 ? Eigen::VectorXd(model.simulate(input))
                                                               : Eigen::VectorXd(model.simulate(input, u_past, y_past));
           }
           return to_numpy(std::move(output));
         },
         py::arg("u"), py::arg("initial") = py::none(), kSimulateDoc)
      .def(
          "predict",
          [](const Model& model, const ArrayLike& u, const ArrayLike& y, const py::typing::Optional<Record>& initial) {
            const Eigen::VectorXd input = to_vector(u, "u");
            const Eigen::VectorXd output = to_vector(y, "y");
            const auto [u_past, y_past] = read_initial(initial);
            Eigen::VectorXd prediction;
            {
              py::gil_scoped_release release;
              prediction = model.predict(input, output, u_past, y_past);
            }
            return to_numpy(std::move(prediction));
          },
          py::arg("u"), py::arg("y"), py::arg("initial") = py::none(), kPredictDoc)
      .def_property(
          "operating_point", [](const Model& model) { return std::make_pair(model.u0(), model.y0()); },
          [](Model& model, const RealPair& point) {
            const auto [u0, y0] = read_pair(point, "operating_point", "u0", "y0");
            model.set_operating_point(u0, y0);
          },
          "tuple (u0, y0): the input and output at which the model rests; its blocks map u - u0 to y - y0. "
          "(0, 0) unless set. identify() keeps the structure's.")
      .def_property(
          "input_range", [](const Model& model) { return std::make_pair(model.input_min(), model.input_max()); },
          [](Model& model, const RealPair& range) {
            const auto [min, max] = read_pair(range, "input_range", "min", "max");
            model.set_input_range(min, max);
          },
          "tuple (min, max): the inputs the model was identified on (identify() records them; (-inf, inf) "
          "unless set). simulate() gives a bonl.ExtrapolationWarning for inputs outside it.")
      .def(
          "extrapolated_samples",
          [](const Model& model, const ArrayLike& u) { return model.extrapolated_samples(to_vector(u, "u")); },
          py::arg("u"), R"doc(How many samples of u lie outside input_range.

Parameters
----------
u : array_like, shape (n,)
    An input record.

Returns
-------
int
    The number of samples outside input_range (0: no extrapolation).)doc")
      .def_property(
          "theta", [](const Model& model) { return to_numpy(Eigen::VectorXd(model.theta())); },
          [](Model& model, const ArrayLike& theta) { model.set_theta(to_vector(theta, "theta")); },
          "numpy.ndarray: the parameter vector in the order of eq. (19).")
      .def_property_readonly("num_params", &Model::num_params, "int: number of identified parameters.")
      .def_property_readonly(
          "pole_radius", [](const Model& model) { return bonl::pole_radius(model); },
          "float: the largest pole magnitude of the linear block: below 1 the model is stable, near 1 barely "
          "damped.")
      .def(
          "rescaled",
          [](const Model& model, double input_scale, double output_scale) {
            return bonl::rescaled(model, input_scale, output_scale);
          },
          py::arg("input_scale"), py::arg("output_scale"),
          R"doc(The model of y = output_scale * model(u / input_scale): the same model for u and y in other units.

Parameters
----------
input_scale, output_scale : float
    The input's and the output's scale, finite and > 0.

Returns
-------
model
    A model of this class, the parameters in the new units.)doc")
      .def(
          "to_json", [](const Model& model, int indent) { return bonl::io::to_json(model, indent); },
          py::arg("indent") = -1,
          R"doc(The model in bonl's JSON model format (read by bonl.load_model and by C++'s bonl::io).

Parameters
----------
indent : int, default -1
    Spaces per level of nesting; -1 for one line.

Returns
-------
str
    The model file's text.)doc")
      .def(py::pickle([](const Model& model) { return bonl::io::to_json(model); },
                      [](const std::string& text) { return bonl::io::model_from_json<Model>(text); }))
      .def("__copy__", [](const Model& model) { return Model(model); })
      .def(
          "__deepcopy__", [](const Model& model, const py::dict&) { return Model(model); }, py::arg("memo"));
}

/// The class docstring: the model's summary, then its constructor's arguments, from its description.
template <class Model>
std::string class_doc() {
  constexpr auto& description = Model::kDescription;
  std::string doc = std::string(description.summary) + "\n\nParameters\n----------\n";
  for (const bonl::OrderDescription& order : description.orders) {
    const bool optional = order.default_value != bonl::OrderDescription::kRequired;
    doc += std::string(order.name) + (optional ? " : int, optional\n    " : " : int\n    ") + order.meaning +
           (optional ? "; default " + std::to_string(order.default_value) : std::string()) + ".\n";
  }
  for (const bonl::ParameterDescription& parameter : description.parameters) {
    doc += std::string(parameter.name) +
           (parameter.shape == bonl::ParameterShape::Number ? " : float, optional\n    "
                                                            : " : array_like, optional\n    ") +
           parameter.meaning + (parameter.non_negative ? ", >= 0" : "") + ".\n";
  }
  return doc;
}

/// A parameter block as Python shows it: a float for a one-number block, else a numpy array.
py::object parameter_to_python(const bonl::ParameterDescription& parameter, const Eigen::VectorXd& value) {
  if (parameter.shape == bonl::ParameterShape::Number) return py::float_(value[0]);
  return py::cast(value);
}

Eigen::VectorXd parameter_from_python(const bonl::ParameterDescription& parameter, const py::handle& value) {
  if (parameter.shape == bonl::ParameterShape::Number)
    return Eigen::VectorXd::Constant(1, to_scalar(value, parameter.name));
  return to_vector(value, parameter.name);
}

template <std::size_t>
using OrderArgument = Eigen::Index;
/// The constructor's keyword argument for parameter block P: a number or an array, or None.
template <class Model, std::size_t P>
using ParameterArgument = py::typing::Optional<
    std::conditional_t<Model::kDescription.parameters[P].shape == bonl::ParameterShape::Number, Real, ArrayLike>>;

/// The constructor's argument for order O: required, or with its default (the integrators ni).
template <class Model, std::size_t O>
auto order_argument() {
  constexpr const bonl::OrderDescription& order = Model::kDescription.orders[O];
  if constexpr (order.default_value == bonl::OrderDescription::kRequired) {
    return py::arg(order.name);
  } else {
    return py::arg_v(order.name, order.default_value);
  }
}

/// Model(order_0, ..., *, parameter_0=None, ...): the orders positional, the parameter blocks by keyword.
template <class Model, std::size_t... O, std::size_t... P>
void def_init(py::class_<Model>& cls, std::index_sequence<O...>, std::index_sequence<P...>) {
  constexpr auto& description = Model::kDescription;
  cls.def(py::init([](OrderArgument<O>... orders, const ParameterArgument<Model, P>&... values) {
            Model model = bonl::make_model<Model>({orders...});
            const py::object* given[] = {&values...};
            for (std::size_t i = 0; i < sizeof...(P); ++i) {
              if (!given[i]->is_none()) {
                model.set_parameter(i, parameter_from_python(description.parameters[i], *given[i]));
              }
            }
            return model;
          }),
          order_argument<Model, O>()..., py::kw_only(), (py::arg(description.parameters[P].name) = py::none())...);
}

/// One model class, entirely from the model's description.
template <class Model>
void bind_model(py::module_& m) {
  constexpr auto& description = Model::kDescription;
  constexpr std::size_t kOrders = description.orders.size();
  constexpr std::size_t kParameters = description.parameters.size();
  static const std::string doc = class_doc<Model>();
  py::class_<Model> cls(m, description.name, doc.c_str());
  def_init(cls, std::make_index_sequence<kOrders>{}, std::make_index_sequence<kParameters>{});
  py::list order_names;
  for (const bonl::OrderDescription& order : description.orders) order_names.append(order.name);
  cls.attr("ORDERS") = py::tuple(order_names);  // the constructor's order arguments, in order
  py::dict order_defaults;                      // the orders a call or a file may leave out, and their values
  for (const bonl::OrderDescription& order : description.orders) {
    if (order.default_value != bonl::OrderDescription::kRequired) order_defaults[order.name] = order.default_value;
  }
  cls.attr("ORDER_DEFAULTS") = order_defaults;
  // The orders of the structure at the paper's orders (bonl::PaperOrders, an order it does not name at
  // its minimum): what the benchmarks and the fixed-order variants use.
  cls.attr("PAPER_ORDERS") = py::tuple(py::cast(bonl::make_model_at<Model, bonl::PaperOrders>().orders()));
  cls.def_property_readonly(
      "orders", [](const Model& model) { return py::typing::Tuple<py::int_, py::ellipsis>(py::cast(model.orders())); },
      "tuple of int: the orders, as ORDERS names them.");
  for (std::size_t i = 0; i < kOrders; ++i) {
    const bonl::OrderDescription& order = description.orders[i];
    cls.def_property_readonly(
        order.name, [i](const Model& model) { return model.orders()[i]; },
        (std::string("int: ") + order.meaning + ".").c_str());
  }
  for (std::size_t i = 0; i < kParameters; ++i) {
    const bonl::ParameterDescription& parameter = description.parameters[i];
    const std::string doc =
        std::string(parameter.shape == bonl::ParameterShape::Number ? "float: " : "numpy.ndarray: ") +
        parameter.meaning + ".";
    // A number block is a float, an array block a 1-D array, in Python and in the stubs.
    if (parameter.shape == bonl::ParameterShape::Number) {
      cls.def_property(
          parameter.name, [i](const Model& model) { return model.parameter(i)[0]; },
          [i](Model& model, const Real& value) {
            model.set_parameter(i, parameter_from_python(description.parameters[i], value));
          },
          doc.c_str());
    } else {
      cls.def_property(
          parameter.name, [i](const Model& model) { return to_numpy(Eigen::VectorXd(model.parameter(i))); },
          [i](Model& model, const ArrayLike& value) {
            model.set_parameter(i, parameter_from_python(description.parameters[i], value));
          },
          doc.c_str());
    }
  }
  cls.def_property_readonly(
         "params",
         [](const Model& model) {
           py::typing::Dict<py::str, py::typing::Union<py::float_, Vector>> params;
           for (std::size_t i = 0; i < kParameters; ++i) {
             params[description.parameters[i].name] =
                 parameter_to_python(description.parameters[i], model.parameter(i));
           }
           return params;
         },
         "dict: every parameter block by name, as the keyword arguments of the constructor take them.")
      .def("__repr__", [](const Model& model) {
        std::string text = std::string(description.name) + "(";
        const auto orders = model.orders();
        for (std::size_t i = 0; i < kOrders; ++i) {
          text += (i == 0 ? "" : ", ") + std::string(description.orders[i].name) + "=" + std::to_string(orders[i]);
        }
        return text + ")";
      });
  bind_common(cls);
}

}  // namespace

py::handle extrapolation_warning() { return g_extrapolation_warning; }
py::handle stability_warning() { return g_stability_warning; }
py::handle excitation_warning() { return g_excitation_warning; }

void warn(py::handle category, const std::string& message) {
  if (PyErr_WarnEx(category.ptr(), message.c_str(), 1) != 0) throw py::error_already_set();
}

void bind_models(py::module_& m) {
  py::register_exception<bonl::NumericalError>(m, "NumericalError", PyExc_ArithmeticError);
  // Released never: the classes live as long as the interpreter.
  g_extrapolation_warning = PyErr_NewExceptionWithDoc(
      "bonl.ExtrapolationWarning",
      "A model was simulated on inputs outside the range it was identified on (Model.input_range).", PyExc_UserWarning,
      nullptr);
  g_stability_warning = PyErr_NewExceptionWithDoc(
      "bonl.StabilityWarning",
      "identify() returned a model whose linear block is unstable or barely damped (Model.pole_radius >= 0.999).",
      PyExc_UserWarning, nullptr);
  g_excitation_warning = PyErr_NewExceptionWithDoc(
      "bonl.ExcitationWarning",
      "identify() was given records whose input takes fewer distinct values than the model's structure needs "
      "(a constant input; two levels for a polynomial of degree 2): the identified parameters are not fixed by "
      "the data.",
      PyExc_UserWarning, nullptr);
  if (!g_extrapolation_warning || !g_stability_warning || !g_excitation_warning) throw py::error_already_set();
  m.attr("ExtrapolationWarning") = g_extrapolation_warning;
  m.attr("StabilityWarning") = g_stability_warning;
  m.attr("ExcitationWarning") = g_excitation_warning;
  py::list classes;
  bonl::for_each_model(bonl::Models{}, [&](auto tag) {
    using Model = typename decltype(tag)::type;
    bind_model<Model>(m);
    classes.append(m.attr(Model::kName));
  });
  m.attr("MODELS") = py::tuple(classes);
}

}  // namespace bonl_python
