// bonl.plant.Parameters: the plant's parameters (docs/explanation/plant.md) from one table of fields, with
// C++'s Parameters::excavator_20t and excavator_5t.

#include <pybind11/stl.h>

#include <bonl/plant/parameters.hpp>
#include <bonl/plant/simulator.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "conversions.hpp"
#include "plant_arguments.hpp"

namespace bonl_python {

namespace plant = bonl::plant;

plant::Parameters parameters_argument(const py::object& object) {
  if (object.is_none()) return plant::Parameters{};
  if (!py::isinstance<plant::Parameters>(object)) {
    throw py::type_error("bonl: parameters must be a bonl.plant.Parameters or None, got " + type_name(object));
  }
  return object.cast<plant::Parameters>();
}

namespace {

struct ParameterField {
  const char* name;
  double plant::Parameters::*member;
  const char* doc;  // plant.md's symbol, meaning and unit
};

const std::vector<ParameterField>& parameter_fields() {
  using P = plant::Parameters;
  static const std::vector<ParameterField> fields = {
      {"bore_diameter", &P::bore_diameter, "D, cylinder bore diameter [m]."},
      {"rod_diameter", &P::rod_diameter, "d, piston rod diameter [m]."},
      {"stroke", &P::stroke, "L, cylinder stroke [m]."},
      {"dead_volume_head", &P::dead_volume_head, "V01, head-side dead plus hose volume [m^3]."},
      {"dead_volume_rod", &P::dead_volume_rod, "V02, rod-side dead plus hose volume [m^3]."},
      {"supply_pressure", &P::supply_pressure, "ps, supply pressure [Pa]."},
      {"return_pressure", &P::return_pressure, "pt, return (tank) pressure [Pa]."},
      {"bulk_modulus", &P::bulk_modulus, "beta_e, effective bulk modulus of the oil [Pa]."},
      {"oil_density", &P::oil_density, "rho, oil density [kg/m^3]."},
      {"discharge_coefficient", &P::discharge_coefficient, "Cd, orifice discharge coefficient [-]."},
      {"area_gradient", &P::area_gradient, "w, orifice area gradient of the spool [m]."},
      {"spool_travel", &P::spool_travel, "xv_max, spool travel at full opening [m]."},
      {"internal_leakage", &P::internal_leakage, "Ci, internal (cross-piston) leakage coefficient [m^3/(s Pa)]."},
      {"external_leakage", &P::external_leakage, "Ce, external leakage coefficient [m^3/(s Pa)]."},
      {"orifice_smoothing", &P::orifice_smoothing, "dp_reg, orifice square-root smoothing pressure [Pa]."},
      {"valve_time_constant", &P::valve_time_constant, "tau_v, valve (spool) time constant [s]."},
      {"dead_band", &P::dead_band, "d, input dead-band half-width [V]."},
      {"neutral_voltage", &P::neutral_voltage, "V0, neutral command voltage [V]."},
      {"max_voltage", &P::max_voltage, "Upper end of the command range; V saturates to [0, max_voltage] [V]."},
      {"pilot_hysteresis", &P::pilot_hysteresis,
       "hv, pilot-stage hysteresis half-width as a fraction of full opening [-] (the valve backlash)."},
      {"mass", &P::mass, "M, equivalent moving mass at the rod [kg]."},
      {"gravity_moment", &P::gravity_moment, "m_dcg, gravity first moment of stick plus bucket [kg m]."},
      {"gravity_angle_offset", &P::gravity_angle_offset, "theta_g, gravity angle offset [rad]."},
      {"gravity", &P::gravity, "g, gravitational acceleration [m/s^2]."},
      {"coulomb_friction", &P::coulomb_friction, "Fc, Coulomb friction force [N]."},
      {"static_friction", &P::static_friction, "Fst, static (breakaway) friction force [N]."},
      {"stribeck_velocity", &P::stribeck_velocity, "vs, Stribeck velocity [m/s]."},
      {"viscous_friction", &P::viscous_friction, "sigma_v, viscous friction coefficient [N s/m]."},
      {"friction_smoothing", &P::friction_smoothing, "eps_v, friction sign smoothing velocity [m/s]."},
      {"end_stop_stiffness", &P::end_stop_stiffness, "k_end, end-stop stiffness [N/m]."},
      {"end_stop_damping", &P::end_stop_damping, "c_end, end-stop damping [N s/m]."},
      {"pivot_to_rod_pin", &P::pivot_to_rod_pin, "a, distance from the joint pivot to the rod pin [m]."},
      {"pivot_to_base_pin", &P::pivot_to_base_pin, "b, distance from the joint pivot to the cylinder base pin [m]."},
      {"retracted_length", &P::retracted_length, "l_min, pin-to-pin cylinder length at h = 0 [m]."},
      {"joint_backlash", &P::joint_backlash, "delta, total backlash in the pins [rad]."},
      {"sensor_noise", &P::sensor_noise, "sigma_theta, inclinometer noise standard deviation [rad]."},
  };
  return fields;
}

std::string parameters_docstring() {
  std::string doc =
      "Parameters of the excavator dipper-joint plant (docs/explanation/plant.md).\n\n"
      "Valve, asymmetric cylinder, linkage and backlash of a 20 t excavator's stick cylinder by\n"
      "default (``Parameters.excavator_20t()``); ``Parameters.excavator_5t()`` gives the 5-6 t machine.\n"
      "Every value can be overridden, as a keyword argument of the constructor or by assigning the\n"
      "attribute; ``validate()`` rejects non-physical values with a ValueError that names the parameter\n"
      "(``simulate`` validates too).\n\n"
      "Parameters\n"
      "----------\n"
      "**overrides : float\n"
      "    Any of the attributes below, e.g. ``Parameters(pilot_hysteresis=0.0)``.\n\n"
      "Attributes\n"
      "----------\n";
  for (const ParameterField& field : parameter_fields()) {
    doc += std::string(field.name) + " : float\n    " + field.doc + "\n";
  }
  return doc;
}

std::string parameters_repr(const plant::Parameters& p) {
  const plant::Parameters defaults;
  std::ostringstream out;
  out.precision(17);
  out << "Parameters(";
  bool first = true;
  for (const ParameterField& field : parameter_fields()) {
    if (p.*field.member == defaults.*field.member) continue;
    out << (first ? "" : ", ") << field.name << '=' << p.*field.member;
    first = false;
  }
  out << ')';
  return out.str();
}

void set_parameter(plant::Parameters& p, const std::string& name, const py::handle& value) {
  for (const ParameterField& field : parameter_fields()) {
    if (name == field.name) {
      p.*field.member = to_scalar(value, name);
      return;
    }
  }
  throw py::type_error("bonl: Parameters() got an unexpected keyword argument '" + name + "'");
}

py::dict parameters_to_dict(const plant::Parameters& p) {
  py::dict d;
  for (const ParameterField& field : parameter_fields()) d[field.name] = p.*field.member;
  return d;
}

}  // namespace

void bind_plant_parameters(py::module_& sub) {
  py::class_<plant::Parameters> cls(sub, "Parameters", parameters_docstring().c_str());
  cls.def(py::init([](const py::kwargs& overrides) {
            plant::Parameters p;
            for (const auto& item : overrides) set_parameter(p, item.first.cast<std::string>(), item.second);
            return p;
          }),
          "Default (20 t) parameters, with any attribute overridden by keyword.\n\n"
          "Raises\n------\nTypeError\n    For a keyword that is not a parameter's name.");
  for (const ParameterField& field : parameter_fields()) {
    const auto member = field.member;
    cls.def_property(
        field.name, [member](const plant::Parameters& p) { return p.*member; },
        [member](plant::Parameters& p, double value) { p.*member = value; }, field.doc);
  }
  cls.def("validate", &plant::Parameters::validate,
          "Check that every parameter is physical.\n\n"
          "Raises\n------\nValueError\n    Naming the first non-physical parameter, its requirement and its value.")
      .def("head_area", &plant::Parameters::head_area,
           "The piston area A1 = pi D^2 / 4.\n\n"
           "Returns\n-------\nfloat\n    A1 [m^2].")
      .def("annulus_area", &plant::Parameters::annulus_area,
           "The annulus area A2 = pi (D^2 - d^2) / 4.\n\n"
           "Returns\n-------\nfloat\n    A2 [m^2].")
      .def("flow_gain", &plant::Parameters::flow_gain,
           "The flow gain Kq = Cd w xv_max sqrt(2 / rho).\n\n"
           "Returns\n-------\nfloat\n    Kq [m^3/(s sqrt(Pa))].")
      .def("valve_gain", &plant::Parameters::valve_gain,
           "The valve gain kv = 1 / (V0 - d): a full command opens the spool fully.\n\n"
           "Returns\n-------\nfloat\n    kv [1/V].")
      .def("angle_offset", &plant::Parameters::angle_offset,
           "phi0, the linkage angle at mid-stroke.\n\n"
           "Returns\n-------\nfloat\n    phi0 [rad].")
      .def("linkage_angle", &plant::Parameters::linkage_angle, py::arg("position"),
           "Linkage angle phi at piston position h (law of cosines).\n\n"
           "Parameters\n----------\nposition : float\n    h [m].\n\nReturns\n-------\nfloat\n    phi [rad].")
      .def("joint_angle", &plant::Parameters::joint_angle, py::arg("position"),
           "Joint angle theta = phi(h) - phi0.\n\n"
           "Parameters\n----------\nposition : float\n    h [m].\n\nReturns\n-------\nfloat\n    theta [rad].")
      .def("moment_arm", &plant::Parameters::moment_arm, py::arg("position"),
           "Moment arm r(h) = a b sin(phi) / l, so that dtheta/dt = v / r.\n\n"
           "Parameters\n----------\nposition : float\n    h [m].\n\nReturns\n-------\nfloat\n    r [m].")
      .def(
          "gravity_force",
          [](const plant::Parameters& p, double position) { return plant::gravity_force(p, position); },
          py::arg("position"),
          "Spring (gravity) force at the rod, Fs(h) = m_dcg g cos(theta + theta_g) / r(h).\n\n"
          "Parameters\n----------\nposition : float\n    h [m].\n\nReturns\n-------\nfloat\n    Fs [N].")
      .def("to_dict", &parameters_to_dict, "Every parameter by name.\n\nReturns\n-------\ndict[str, float]")
      .def(
          "copy", [](const plant::Parameters& p) { return p; },
          "An independent copy.\n\n"
          "Returns\n-------\nParameters\n    The copy, equal to this one.")
      .def("__copy__", [](const plant::Parameters& p) { return p; })
      .def(
          "__deepcopy__", [](const plant::Parameters& p, const py::dict&) { return p; }, py::arg("memo"))
      .def("__eq__",
           [](const plant::Parameters& a, const py::object& other) -> py::object {
             if (!py::isinstance<plant::Parameters>(other))
               return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             const auto& b = other.cast<const plant::Parameters&>();
             for (const ParameterField& field : parameter_fields()) {
               if (!(a.*field.member == b.*field.member)) return py::bool_(false);
             }
             return py::bool_(true);
           })
      .def("__repr__", &parameters_repr)
      .def(py::pickle([](const plant::Parameters& p) { return parameters_to_dict(p); },
                      [](const py::dict& d) {
                        plant::Parameters p;
                        for (const auto& item : d) set_parameter(p, item.first.cast<std::string>(), item.second);
                        return p;
                      }));
  // __eq__ without __hash__: the parameters are mutable, so unhashable.
  cls.attr("__hash__") = py::none();
  cls.def_static("excavator_20t", &plant::Parameters::excavator_20t,
                 "The 20 t excavator's stick cylinder (plant.md's defaults, as ``Parameters()``).\n\n"
                 "Returns\n-------\nParameters")
      .def_static("excavator_5t", &plant::Parameters::excavator_5t,
                  "The 5-6 t machine of plant.md.\n\nReturns\n-------\nParameters");
}

}  // namespace bonl_python
