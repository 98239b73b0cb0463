// bonl._bonl.plant: the CVODE excavator dipper-joint plant (docs/plant.md) from Python: its
// parameters, the command signals (submodule excitation), simulate, the right-hand side for
// independent checks, the experiment's signal processing and the paper's whole experiment.

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <bonl/models.hpp>
#include <bonl/plant/excitation.hpp>
#include <bonl/plant/experiment.hpp>
#include <bonl/plant/parameters.hpp>
#include <bonl/plant/simulator.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "conversions.hpp"

namespace bonl_python {

namespace {

namespace plant = bonl::plant;

// --- Arguments --------------------------------------------------------------------------------

std::string format_number(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

/// A 1-D array of finite float64 values from any array-like of real numbers (conversions.hpp), or
/// ValueError naming `name`.
Eigen::VectorXd vector_argument(const py::handle& object, const char* name) {
  const auto array = to_float64_array(object, name);
  Eigen::VectorXd out(array.shape(0));
  const double* data = array.data();
  for (Eigen::Index i = 0; i < out.size(); ++i) {
    if (!std::isfinite(data[i])) {
      throw py::value_error(std::string(name) + " must be finite, got " + format_number(data[i]) + " at index " +
                            std::to_string(i));
    }
    out[i] = data[i];
  }
  return out;
}

void require_finite_scalar(double value, const char* name) {
  if (!std::isfinite(value)) throw py::value_error(std::string(name) + " must be finite, got " + format_number(value));
}

/// Eigen vector -> numpy float64 array without copying the data (the array owns the moved vector).
py::array to_numpy(Eigen::VectorXd&& vector) { return py::cast(std::move(vector)); }
py::array to_numpy(const Eigen::VectorXd& vector) { return py::cast(Eigen::VectorXd(vector)); }

// --- Command ----------------------------------------------------------------------------------

/// A command signal V(t): a bonl::plant::Command plus what it is, and whether calling it needs
/// the GIL (it wraps a Python callable).
struct PyCommand {
  plant::Command function;
  std::string description;
  bool calls_python = false;

  double operator()(double t) const { return function(t); }
};

PyCommand cpp_command(plant::Command function, std::string description) {
  return PyCommand{std::move(function), std::move(description), false};
}

/// Wraps a Python callable f(t) -> float; `name` names it in the ValueError for a value that is not a
/// real number. pybind11's function wrapper acquires the GIL for each call and for its destruction,
/// so the Command may outlive the call that made it; the GIL is held here too while the returned
/// object is converted.
PyCommand python_command(const py::function& callable, const std::string& name) {
  auto call = callable.cast<std::function<py::object(double)>>();
  plant::Command function = [call = std::move(call), name](double t) {
    py::gil_scoped_acquire gil;
    const py::object value = call(t);
    return to_scalar(value, "the value of " + name + "(t) at t = " + format_number(t));
  };
  std::string description = "python callable";
  try {
    description = std::string(py::repr(callable));
  } catch (const py::error_already_set&) {
  }
  return PyCommand{std::move(function), std::move(description), true};
}

/// A command from what simulate accepts: a Command, a Python callable of time, or a (values, ts)
/// pair held between samples (excitation.sampled). TypeError for anything else.
PyCommand command_argument(const py::object& object, const char* name) {
  if (py::isinstance<PyCommand>(object)) return object.cast<PyCommand>();
  if (py::isinstance<py::tuple>(object) && py::len(object) == 2) {
    const py::tuple pair = object.cast<py::tuple>();
    const Eigen::VectorXd values = vector_argument(pair[0], (std::string(name) + "[0] (values)").c_str());
    const double ts = to_scalar(pair[1], std::string(name) + "[1] (ts)");
    std::ostringstream description;
    description << "sampled(" << values.size() << " values, ts=" << ts << ")";
    return cpp_command(plant::excitation::sampled(values, ts), description.str());
  }
  if (PyCallable_Check(object.ptr())) return python_command(object.cast<py::function>(), name);
  throw py::type_error(std::string(name) +
                       " must be a bonl.plant.Command, a callable f(t) -> float or a (values, ts) pair, got " +
                       std::string(py::str(py::type::handle_of(object).attr("__name__"))));
}

// --- Parameters -------------------------------------------------------------------------------

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
      "Parameters of the excavator dipper-joint plant (docs/plant.md).\n\n"
      "Valve, asymmetric cylinder, linkage and backlash of a 20 t excavator's stick cylinder by\n"
      "default; ``small_parameters()`` gives the 5-6 t machine. Every value can be overridden, as a\n"
      "keyword argument of the constructor or by assigning the attribute; ``validate()`` rejects\n"
      "non-physical values with a ValueError that names the parameter (``simulate`` validates too).\n\n"
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
  throw py::type_error("Parameters() got an unexpected keyword argument '" + name + "'");
}

py::dict parameters_to_dict(const plant::Parameters& p) {
  py::dict d;
  for (const ParameterField& field : parameter_fields()) d[field.name] = p.*field.member;
  return d;
}

plant::Parameters parameters_argument(const py::object& object) {
  if (object.is_none()) return plant::Parameters{};
  if (!py::isinstance<plant::Parameters>(object)) {
    throw py::type_error("parameters must be a bonl.plant.Parameters or None, got " +
                         std::string(py::str(py::type::handle_of(object).attr("__name__"))));
  }
  return object.cast<plant::Parameters>();
}

void bind_parameters(py::module_& sub) {
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
      .def("head_area", &plant::Parameters::head_area, "A1 = pi D^2 / 4, piston area [m^2].")
      .def("annulus_area", &plant::Parameters::annulus_area, "A2 = pi (D^2 - d^2) / 4, annulus area [m^2].")
      .def("flow_gain", &plant::Parameters::flow_gain, "Kq = Cd w xv_max sqrt(2 / rho) [m^3/(s sqrt(Pa))].")
      .def("valve_gain", &plant::Parameters::valve_gain,
           "kv = 1 / (V0 - d) [1/V]: a full command opens the spool fully.")
      .def("angle_offset", &plant::Parameters::angle_offset, "phi0, the linkage angle at mid-stroke [rad].")
      .def("linkage_angle", &plant::Parameters::linkage_angle, py::arg("position"),
           "Linkage angle phi at piston position h (law of cosines).\n\n"
           "Parameters\n----------\nposition : float\n    h [m].\n\nReturns\n-------\nfloat\n    phi [rad].")
      .def("joint_angle", &plant::Parameters::joint_angle, py::arg("position"),
           "Joint angle theta = phi(h) - phi0.\n\n"
           "Parameters\n----------\nposition : float\n    h [m].\n\nReturns\n-------\nfloat\n    theta [rad].")
      .def("moment_arm", &plant::Parameters::moment_arm, py::arg("position"),
           "Moment arm r(h) = a b sin(phi) / l, so that dtheta/dt = v / r.\n\n"
           "Parameters\n----------\nposition : float\n    h [m].\n\nReturns\n-------\nfloat\n    r [m].")
      .def("gravity_force",
           [](const plant::Parameters& p, double position) { return plant::gravity_force(p, position); },
           py::arg("position"),
           "Spring (gravity) force at the rod, Fs(h) = m_dcg g cos(theta + theta_g) / r(h).\n\n"
           "Parameters\n----------\nposition : float\n    h [m].\n\nReturns\n-------\nfloat\n    Fs [N].")
      .def("to_dict", &parameters_to_dict, "Every parameter by name.\n\nReturns\n-------\ndict[str, float]")
      .def(
          "copy", [](const plant::Parameters& p) { return p; }, "An independent copy.")
      .def("__copy__", [](const plant::Parameters& p) { return p; })
      .def("__deepcopy__", [](const plant::Parameters& p, const py::dict&) { return p; }, py::arg("memo"))
      .def("__eq__",
           [](const plant::Parameters& a, const py::object& other) -> py::object {
             if (!py::isinstance<plant::Parameters>(other)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
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

  sub.def(
      "default_parameters", []() { return plant::Parameters::excavator_20t(); },
      "The 20 t excavator's stick cylinder (plant.md's defaults).\n\nReturns\n-------\nParameters");
  sub.def(
      "small_parameters", []() { return plant::Parameters::excavator_5t(); },
      "The 5-6 t machine of plant.md.\n\nReturns\n-------\nParameters");
}

// --- Excitation -------------------------------------------------------------------------------

void bind_command(py::module_& sub) {
  py::class_<PyCommand>(sub, "Command",
                        "A command voltage V(t) [V] on the 0-5 V scale (neutral 2.5 V).\n\n"
                        "Made by the functions of ``bonl.plant.excitation`` (evaluated in C++, so ``simulate``\n"
                        "releases the GIL), or from any Python callable ``f(t) -> float``.\n\n"
                        "Parameters\n----------\nfunction : callable\n    f(t) -> float, t in seconds, V in volts.")
      .def(py::init([](const py::function& function) { return python_command(function, "command"); }),
           py::arg("function"))
      .def(
          "__call__", [](const PyCommand& c, double t) { return c(t); }, py::arg("t"),
          "V(t).\n\nParameters\n----------\nt : float\n    Time [s].\n\nReturns\n-------\nfloat\n    Command [V].")
      .def(
          "sample",
          [](const PyCommand& c, const py::object& t) {
            const Eigen::VectorXd times = vector_argument(t, "t");
            Eigen::VectorXd values(times.size());
            if (c.calls_python) {
              for (Eigen::Index i = 0; i < times.size(); ++i) values[i] = c(times[i]);
            } else {
              py::gil_scoped_release release;
              for (Eigen::Index i = 0; i < times.size(); ++i) values[i] = c(times[i]);
            }
            return to_numpy(std::move(values));
          },
          py::arg("t"),
          "V at every time of an array.\n\n"
          "Parameters\n----------\nt : array_like, 1-D\n    Finite times [s].\n\n"
          "Returns\n-------\nnumpy.ndarray\n    float64 commands [V], the same length as ``t``.\n\n"
          "Raises\n------\nValueError\n    When ``t`` is not 1-D or not finite.")
      .def_property_readonly(
          "calls_python", [](const PyCommand& c) { return c.calls_python; },
          "True when the command wraps a Python callable (``simulate`` then keeps the GIL).")
      .def("__repr__", [](const PyCommand& c) { return "Command(" + c.description + ")"; });

  py::module_ ex = sub.def_submodule("excitation",
                                     "Command signals V(t) for the plant, on the 0-5 V scale around the neutral "
                                     "voltage (bonl/plant/excitation.hpp).");
  ex.def(
      "step",
      [](double level, double t_step, double before) {
        std::ostringstream d;
        d << "step(level=" << level << ", t_step=" << t_step << ", before=" << before << ")";
        return cpp_command(plant::excitation::step(level, t_step, before), d.str());
      },
      py::arg("level"), py::arg("t_step") = 0.0, py::arg("before") = 2.5,
      "A step: ``before`` until t_step, then ``level`` (at t_step itself: ``level``).\n\n"
      "Parameters\n----------\nlevel : float\n    Voltage after the step [V].\n"
      "t_step : float, optional\n    Time of the step [s].\nbefore : float, optional\n    Voltage before it [V].\n\n"
      "Returns\n-------\nCommand");
  ex.def(
      "multisine",
      [](const std::vector<double>& frequencies_hz, double amplitude, double offset, std::vector<double> phases) {
        std::ostringstream d;
        d << "multisine(" << frequencies_hz.size() << " tones, amplitude=" << amplitude << ", offset=" << offset << ")";
        return cpp_command(plant::excitation::multisine(frequencies_hz, amplitude, offset, std::move(phases)), d.str());
      },
      py::arg("frequencies_hz"), py::arg("amplitude"), py::arg("offset") = 2.5,
      py::arg("phases") = std::vector<double>{},
      "offset + amplitude * sum_i sin(2 pi f_i t + phase_i).\n\n"
      "Parameters\n----------\nfrequencies_hz : sequence of float\n    Tones [Hz], finite and >= 0.\n"
      "amplitude : float\n    Per tone [V].\noffset : float, optional\n    [V].\n"
      "phases : sequence of float, optional\n    [rad], one per tone; empty: Schroeder's phi_k = -pi k (k + 1) / n.\n\n"
      "Returns\n-------\nCommand");
  ex.def(
      "paper_multisine",
      [](double amplitude, double offset) {
        std::ostringstream d;
        d << "paper_multisine(amplitude=" << amplitude << ", offset=" << offset << ")";
        return cpp_command(plant::excitation::paper_multisine(amplitude, offset), d.str());
      },
      py::arg("amplitude") = 0.4, py::arg("offset") = 2.5,
      "The paper's identification input: tones 0.1, 0.2, 0.4, 0.5, 1 Hz, Schroeder phases.\n\n"
      "Parameters\n----------\namplitude : float, optional\n    Per tone [V].\noffset : float, optional\n    [V].\n\n"
      "Returns\n-------\nCommand");
  ex.def(
      "smooth_random",
      [](double bandwidth_hz, double rms, double duration, std::uint64_t seed, double offset) {
        std::ostringstream d;
        d << "smooth_random(bandwidth_hz=" << bandwidth_hz << ", rms=" << rms << ", duration=" << duration
          << ", seed=" << seed << ", offset=" << offset << ")";
        return cpp_command(plant::excitation::smooth_random(bandwidth_hz, rms, duration, seed, offset), d.str());
      },
      py::arg("bandwidth_hz"), py::arg("rms"), py::arg("duration"), py::arg("seed"), py::arg("offset") = 2.5,
      "A smooth random signal band-limited to ``bandwidth_hz``.\n\n"
      "Equal sines at k / duration Hz for k = 1..floor(bandwidth_hz duration) with random phases, scaled\n"
      "so that its RMS over one period [0, duration] is exactly ``rms``, around ``offset``.\n\n"
      "Parameters\n----------\nbandwidth_hz : float\n    [Hz].\nrms : float\n    [V].\n"
      "duration : float\n    Period [s]; bandwidth_hz * duration must be >= 1.\nseed : int\n    Random phases' seed.\n"
      "offset : float, optional\n    [V].\n\nReturns\n-------\nCommand");
  ex.def(
      "chirp",
      [](double f0_hz, double f1_hz, double duration, double amplitude, double offset) {
        std::ostringstream d;
        d << "chirp(f0_hz=" << f0_hz << ", f1_hz=" << f1_hz << ", duration=" << duration << ", amplitude=" << amplitude
          << ", offset=" << offset << ")";
        return cpp_command(plant::excitation::chirp(f0_hz, f1_hz, duration, amplitude, offset), d.str());
      },
      py::arg("f0_hz"), py::arg("f1_hz"), py::arg("duration"), py::arg("amplitude"), py::arg("offset") = 2.5,
      "Linear chirp from f0 to f1 over [0, duration], then at f1 with a continuous phase.\n\n"
      "Parameters\n----------\nf0_hz, f1_hz : float\n    Start and end frequencies [Hz].\n"
      "duration : float\n    [s].\namplitude : float\n    [V].\noffset : float, optional\n    [V].\n\n"
      "Returns\n-------\nCommand");
  ex.def(
      "sampled",
      [](const py::object& values, double ts, double t0) {
        const Eigen::VectorXd v = vector_argument(values, "values");
        std::ostringstream d;
        d << "sampled(" << v.size() << " values, ts=" << ts << ", t0=" << t0 << ")";
        return cpp_command(plant::excitation::sampled(v, ts, t0), d.str());
      },
      py::arg("values"), py::arg("ts"), py::arg("t0") = 0.0,
      "A sampled sequence held between samples (zero-order hold).\n\n"
      "values[k] on [t0 + k ts, t0 + (k+1) ts); before t0 the first value, after the end the last.\n\n"
      "Parameters\n----------\nvalues : array_like, 1-D\n    Finite voltages [V].\nts : float\n    Sample time [s].\n"
      "t0 : float, optional\n    Time of the first sample [s].\n\nReturns\n-------\nCommand\n\n"
      "Raises\n------\nValueError\n    When ``values`` is empty, not 1-D or not finite, or ``ts`` is not > 0.");
  ex.attr("__all__") = py::make_tuple("step", "multisine", "paper_multisine", "smooth_random", "chirp", "sampled");
}

// --- Simulation -------------------------------------------------------------------------------

const char* const kStateOrder = "(h [m], v [m/s], p1 [Pa], p2 [Pa], xv [-])";

py::array state_to_numpy(const plant::State& s) {
  Eigen::VectorXd x(5);
  x << s.position, s.velocity, s.head_pressure, s.rod_pressure, s.spool;
  return to_numpy(std::move(x));
}

py::dict trajectory_to_dict(plant::Trajectory&& t) {
  py::dict d;
  d["time"] = to_numpy(std::move(t.time));
  d["command"] = to_numpy(std::move(t.command));
  d["input"] = to_numpy(std::move(t.input));
  d["position"] = to_numpy(std::move(t.position));
  d["velocity"] = to_numpy(std::move(t.velocity));
  d["head_pressure"] = to_numpy(std::move(t.head_pressure));
  d["rod_pressure"] = to_numpy(std::move(t.rod_pressure));
  d["spool"] = to_numpy(std::move(t.spool));
  d["pilot"] = to_numpy(std::move(t.pilot));
  d["head_flow"] = to_numpy(std::move(t.head_flow));
  d["rod_flow"] = to_numpy(std::move(t.rod_flow));
  d["joint_angle"] = to_numpy(std::move(t.joint_angle));
  d["joint_rate"] = to_numpy(std::move(t.joint_rate));
  d["pin_angle"] = to_numpy(std::move(t.pin_angle));
  d["measured_angle"] = to_numpy(std::move(t.measured_angle));
  d["min_position"] = t.min_position;
  d["max_position"] = t.max_position;
  d["reached_end_stop"] = t.reached_end_stop;
  d["steps"] = t.steps;
  return d;
}

py::dict simulate(const py::object& command, const py::object& parameters, double duration, double sample_time,
                  double command_rate, double rtol, const py::object& atol, long max_steps_per_interval,
                  bool sensor_noise, std::uint64_t noise_seed, const py::object& initial_position,
                  const py::object& load) {
  const plant::Parameters p = parameters_argument(parameters);
  const PyCommand c = command_argument(command, "command");
  plant::SimulationOptions options;
  options.duration = duration;
  options.sample_time = sample_time;
  options.command_rate = command_rate;
  options.tolerances.relative = rtol;
  options.tolerances.max_steps_per_interval = max_steps_per_interval;
  if (!atol.is_none()) {
    if (!py::isinstance<py::dict>(atol)) {
      throw py::value_error("atol must be a dict {state: tolerance} (position, velocity, pressure, spool), got " +
                            type_name(atol));
    }
    for (const auto& item : atol.cast<py::dict>()) {
      const auto key = std::string(py::str(item.first));
      const double value = to_scalar(item.second, "atol['" + key + "']");
      if (key == "position") options.tolerances.absolute_position = value;
      else if (key == "velocity") options.tolerances.absolute_velocity = value;
      else if (key == "pressure") options.tolerances.absolute_pressure = value;
      else if (key == "spool") options.tolerances.absolute_spool = value;
      else throw py::value_error("atol: unknown key '" + key + "' (position, velocity, pressure, spool)");
    }
  }
  options.sensor_noise = sensor_noise;
  options.noise_seed = noise_seed;
  if (!initial_position.is_none()) {
    const double h0 = to_scalar(initial_position, "initial_position");
    if (!(std::isfinite(h0) && h0 >= 0.0)) {
      throw py::value_error("initial_position must be finite and >= 0 (None means mid-stroke), got " + format_number(h0));
    }
    options.initial_position = h0;
  }
  bool calls_python = c.calls_python;
  if (!load.is_none()) {
    const PyCommand l = command_argument(load, "load");
    calls_python = calls_python || l.calls_python;
    options.load = l.function;
  }
  plant::Trajectory trajectory;
  if (calls_python) {
    trajectory = plant::simulate(p, c.function, options);
  } else {
    py::gil_scoped_release release;
    trajectory = plant::simulate(p, c.function, options);
  }
  return trajectory_to_dict(std::move(trajectory));
}

// --- Experiment -------------------------------------------------------------------------------

py::dict mse_dict(const plant::IdentifiedModels& m) {
  py::dict d;
  d["ARX"] = m.mse_arx;
  d["Hammerstein"] = m.mse_hammerstein;
  d["HW"] = m.mse_hammerstein_wiener;
  d["PHW"] = m.mse_phw;
  return d;
}

/// The run-time-order model with the fixed-size model's parameters (None if they are not finite).
template <typename Dynamic, typename Fixed, typename... Orders>
py::object dynamic_model(const Fixed& fixed, Orders... orders) {
  if (!fixed.theta().allFinite()) return py::none();
  Dynamic model(orders...);
  model.set_theta(fixed.theta());
  return py::cast(std::move(model));
}

py::dict models_dict(const plant::IdentifiedModels& m) {
  py::dict d;
  d["ARX"] = dynamic_model<bonl::ARXd>(m.arx, m.arx.na(), m.arx.nb(), m.arx.nk());
  const auto& h = m.hammerstein;
  d["Hammerstein"] = dynamic_model<bonl::Hammersteind>(h, h.na(), h.nb(), h.nk(), h.r());
  const auto& hw = m.hammerstein_wiener;
  d["HW"] = dynamic_model<bonl::HammersteinWienerd>(hw, hw.na(), hw.nb(), hw.nk(), hw.r(), hw.r1());
  const auto& phw = m.phw;
  d["PHW"] = dynamic_model<bonl::PseudoHammersteinWienerd>(phw, phw.na(), phw.nb(), phw.nk(), phw.r());
  return d;
}

/// The parameters by name as plain lists (Table 1, results.json), taken from each model's own
/// `params` property, so that the names have one source (bindings/models.cpp).
py::dict params_dict(const py::dict& models) {
  const py::object as_array = py::module_::import("numpy").attr("asarray");
  py::dict d;
  for (const auto& [name, model] : models) {
    if (model.is_none()) {
      d[name] = py::none();
      continue;
    }
    py::dict params;
    for (const auto& [key, value] : model.attr("params").cast<py::dict>()) params[key] = as_array(value).attr("tolist")();
    d[name] = params;
  }
  return d;
}

py::dict simulated_dict(const plant::IdentifiedModels& m) {
  py::dict d;
  d["ARX"] = to_numpy(m.simulated_arx);
  d["Hammerstein"] = to_numpy(m.simulated_hammerstein);
  d["HW"] = to_numpy(m.simulated_hammerstein_wiener);
  d["PHW"] = to_numpy(m.simulated_phw);
  return d;
}

py::dict method_dict(const plant::IdentifiedModels& m) {
  py::dict d;
  d["mse"] = mse_dict(m);
  d["models"] = models_dict(m);
  d["params"] = params_dict(d["models"].cast<py::dict>());
  d["simulated"] = simulated_dict(m);
  return d;
}

py::dict record_dict(const plant::Record& r) {
  py::dict d;
  d["time"] = to_numpy(r.time);
  d["input"] = to_numpy(r.input);
  d["velocity"] = to_numpy(r.velocity);
  d["true_velocity"] = to_numpy(r.true_velocity);
  d["angle"] = to_numpy(r.angle);
  py::dict run;
  run["min_position"] = r.trajectory.min_position;
  run["max_position"] = r.trajectory.max_position;
  run["reached_end_stop"] = r.trajectory.reached_end_stop;
  run["steps"] = r.trajectory.steps;
  d["run"] = run;
  return d;
}

py::dict errors_dict(const plant::ModelErrors& e) {
  py::dict d;
  d["ARX"] = e.arx;
  d["Hammerstein"] = e.hammerstein;
  d["HW"] = e.hammerstein_wiener;
  d["PHW"] = e.phw;
  return d;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

py::dict experiment(const py::object& parameters, const std::string& method, bool robustness) {
  if (method != "output_error" && method != "paper") {
    throw py::value_error("method must be 'output_error' or 'paper', got '" + method + "'");
  }
  const plant::Parameters p = parameters_argument(parameters);
  struct Result {
    plant::ExperimentData data;
    plant::IdentifiedModels ours, paper, ours_online, paper_online;
    std::vector<plant::ModelErrors> robust_ours, robust_paper;
    double plant_seconds = 0.0, identify_seconds = 0.0, robustness_seconds = 0.0;
  };
  Result r;
  {
    py::gil_scoped_release release;
    auto start = std::chrono::steady_clock::now();
    r.data = plant::acquire(p);
    r.plant_seconds = seconds_since(start);
    start = std::chrono::steady_clock::now();
    r.ours = plant::identify_models(r.data, bonl::Method::OutputError);
    r.paper = plant::identify_models(r.data, bonl::Method::Paper);
    r.identify_seconds = seconds_since(start);
    r.ours_online = plant::identify_models(r.data, bonl::Method::OutputError, 0);
    r.paper_online = plant::identify_models(r.data, bonl::Method::Paper, 0);
    if (robustness) {
      start = std::chrono::steady_clock::now();
      const auto commands = plant::robustness_commands(p);
      for (std::size_t i = 0; i < commands.size(); ++i) {
        // The seeds bonl_demo uses, so that the numbers match its robustness table.
        const auto record = plant::measure(p, commands[i], plant::ExperimentOptions{}, 5000 + i);
        r.robust_ours.push_back(plant::validation_errors(r.ours, record));
        r.robust_paper.push_back(plant::validation_errors(r.paper, record));
      }
      r.robustness_seconds = seconds_since(start);
    }
  }
  py::dict out;
  py::dict methods;
  methods["output_error"] = method_dict(r.ours);
  methods["paper"] = method_dict(r.paper);
  out["method"] = method;
  out["mse"] = methods[py::str(method)]["mse"];
  out["models"] = methods[py::str(method)]["models"];
  out["params"] = methods[py::str(method)]["params"];
  out["methods"] = methods;
  py::dict online;
  online["output_error"] = mse_dict(r.ours_online);
  online["paper"] = mse_dict(r.paper_online);
  out["online"] = online;
  out["identification"] = record_dict(r.data.identification);
  py::dict validation = record_dict(r.data.validation);
  py::dict simulated;
  simulated["output_error"] = methods["output_error"]["simulated"];
  simulated["paper"] = methods["paper"]["simulated"];
  validation["simulated"] = simulated;
  out["validation"] = validation;
  out["parameters"] = p;
  if (robustness) {
    py::list rows;
    for (std::size_t i = 0; i < r.robust_ours.size(); ++i) {
      rows.append(py::dict(py::arg("output_error") = errors_dict(r.robust_ours[i]),
                           py::arg("paper") = errors_dict(r.robust_paper[i])));
    }
    out["robustness"] = rows;
  }
  py::dict timing;
  timing["plant"] = r.plant_seconds;
  timing["identification"] = r.identify_seconds;
  if (robustness) timing["robustness"] = r.robustness_seconds;
  out["seconds"] = timing;
  return out;
}

}  // namespace

void bind_plant(py::module_& m) {
  py::module_ sub = m.def_submodule(
      "plant",
      "The excavator dipper-joint plant (docs/plant.md) integrated by SUNDIALS CVODE: parameters,\n"
      "command signals (submodule ``excitation``), ``simulate``, the experiment's signal processing\n"
      "and the paper's whole experiment (``experiment``).");

  bind_parameters(sub);
  bind_command(sub);

  sub.def("simulate", &simulate, py::arg("command"), py::arg("parameters") = py::none(), py::kw_only(),
          py::arg("duration") = 50.0, py::arg("sample_time") = 0.01, py::arg("command_rate") = 1000.0,
          py::arg("rtol") = 1e-6, py::arg("atol") = py::none(), py::arg("max_steps_per_interval") = 5000L,
          py::arg("sensor_noise") = true, py::arg("noise_seed") = std::uint64_t{1},
          py::arg("initial_position") = py::none(), py::arg("load") = py::none(),
          "Integrate the plant under a command with CVODE (BDF, Newton, dense solver).\n\n"
          "The command is sampled and held on the command grid (``command_rate``), where the pilot\n"
          "hysteresis and the pin backlash (play operators) are evaluated; CVODE is stopped at every\n"
          "grid point. The GIL is released unless the command or the load is a Python callable.\n\n"
          "Parameters\n----------\n"
          "command : Command or callable or tuple\n"
          "    V(t) [V]: a ``Command`` (``bonl.plant.excitation``), a Python callable f(t) -> float, or a\n"
          "    ``(values, ts)`` pair held between samples (``excitation.sampled``).\n"
          "parameters : Parameters, optional\n    The plant; None: ``default_parameters()``.\n"
          "duration : float, optional\n    [s], an integer multiple of ``sample_time``.\n"
          "sample_time : float, optional\n    Output grid [s], an integer multiple of 1 / command_rate.\n"
          "command_rate : float, optional\n    Command grid [Hz].\n"
          "rtol : float, optional\n    CVODE's relative tolerance.\n"
          "atol : dict, optional\n"
          "    Absolute tolerances by state: any of ``position`` [m] (default 1e-8), ``velocity`` [m/s]\n"
          "    (1e-8), ``pressure`` [Pa] (1.0), ``spool`` [-] (1e-8).\n"
          "max_steps_per_interval : int, optional\n    CVODE's step limit per command interval.\n"
          "sensor_noise : bool, optional\n    Add the inclinometer noise to ``measured_angle``.\n"
          "noise_seed : int, optional\n    Its seed.\n"
          "initial_position : float, optional\n    h0 [m]; None: mid-stroke.\n"
          "load : Command or callable, optional\n    External load F_L(t) [N] opposing extension; None: none.\n\n"
          "Returns\n-------\ndict\n"
          "    float64 arrays on the output grid, sample k at ``time[k] = k * sample_time``: ``time`` [s],\n"
          "    ``command`` [V], ``input`` u = V - V0 [V], ``position`` h [m], ``velocity`` v [m/s],\n"
          "    ``head_pressure`` p1 [Pa], ``rod_pressure`` p2 [Pa], ``spool`` xv [-], ``pilot`` xc [-],\n"
          "    ``head_flow`` Q1 [m^3/s], ``rod_flow`` Q2 [m^3/s], ``joint_angle`` theta [rad],\n"
          "    ``joint_rate`` [rad/s], ``pin_angle`` theta_m [rad], ``measured_angle`` [rad]; and the scalars\n"
          "    ``min_position``, ``max_position`` [m], ``reached_end_stop`` (bool), ``steps`` (CVODE's).\n\n"
          "Raises\n------\nValueError\n"
          "    For non-physical parameters or bad options, naming them.\n"
          "bonl.NumericalError\n    When CVODE fails (its flag and the time reached are in the message).");

  sub.def(
      "initial_state",
      [](const py::object& parameters, double position) {
        const plant::Parameters p = parameters_argument(parameters);
        p.validate();
        require_finite_scalar(position, "position");
        return state_to_numpy(plant::initial_state(p, position));
      },
      py::arg("parameters"), py::arg("position"),
      (std::string("Initial state of plant.md's experiment at piston position h0.\n\n"
                   "At rest, spool closed, p2 = ps / 4, p1 from the force balance A1 p1 = A2 p2 + Fs(h0).\n\n"
                   "Parameters\n----------\nparameters : Parameters or None\n    The plant.\n"
                   "position : float\n    h0 [m].\n\nReturns\n-------\nnumpy.ndarray\n    The state ") +
       kStateOrder + ".")
          .c_str());

  sub.def(
      "derivative",
      [](const py::object& parameters, const py::object& state, double pilot, double load) {
        const plant::Parameters p = parameters_argument(parameters);
        p.validate();
        const Eigen::VectorXd x = vector_argument(state, "state");
        if (x.size() != 5) {
          throw py::value_error("state must have 5 entries " + std::string(kStateOrder) + ", got " +
                                std::to_string(x.size()));
        }
        require_finite_scalar(pilot, "pilot");
        require_finite_scalar(load, "load");
        plant::State s;
        s.position = x[0];
        s.velocity = x[1];
        s.head_pressure = x[2];
        s.rod_pressure = x[3];
        s.spool = x[4];
        return state_to_numpy(plant::derivative(p, s, pilot, load));
      },
      py::arg("parameters"), py::arg("state"), py::arg("pilot"), py::arg("load") = 0.0,
      (std::string("Right-hand side of the plant's ODE, d(state)/dt, for a held pilot output and load.\n\n"
                   "Exposed so that tests can check the plant against an independent integrator.\n\n"
                   "Parameters\n----------\nparameters : Parameters or None\n    The plant.\n"
                   "state : array_like of 5\n    ") +
       kStateOrder +
       ".\npilot : float\n    xc, the pilot stage's output after its hysteresis [-].\n"
       "load : float, optional\n    F_L [N].\n\nReturns\n-------\nnumpy.ndarray\n    d(state)/dt, 5 entries.")
          .c_str());

  sub.def(
      "low_pass",
      [](const py::object& x, double cutoff_hz, double ts) {
        return to_numpy(plant::low_pass(vector_argument(x, "x"), cutoff_hz, ts));
      },
      py::arg("x"), py::arg("cutoff_hz"), py::arg("ts"),
      "First-order low-pass z[k] = z[k-1] + alpha (x[k] - z[k-1]), alpha = 1 - exp(-2 pi fc ts), z[0] = x[0].\n\n"
      "Parameters\n----------\nx : array_like, 1-D\n    Finite samples.\ncutoff_hz : float\n    fc [Hz].\n"
      "ts : float\n    Sample time [s].\n\nReturns\n-------\nnumpy.ndarray\n\n"
      "Raises\n------\nValueError\n    When ``x`` is not 1-D or not finite, or fc or ts is not > 0.");
  sub.def(
      "differentiate",
      [](const py::object& x, double ts) { return to_numpy(plant::differentiate(vector_argument(x, "x"), ts)); },
      py::arg("x"), py::arg("ts"),
      "Numerical derivative: central differences, one-sided at both ends.\n\n"
      "Parameters\n----------\nx : array_like, 1-D\n    Finite samples, at least 2.\nts : float\n    Sample time [s].\n\n"
      "Returns\n-------\nnumpy.ndarray\n\n"
      "Raises\n------\nValueError\n    When ``x`` is not 1-D, not finite or shorter than 2, or ts is not > 0.");

  sub.def("experiment", &experiment, py::arg("parameters") = py::none(), py::kw_only(),
          py::arg("method") = "output_error", py::arg("robustness") = false,
          "The paper's experiment on the plant, as ``bonl_demo`` runs it (docs/plant.md).\n\n"
          "Identification record from the paper's multi-sine, validation record from a smooth random\n"
          "signal (each 50 s at 100 Hz, 10 repeats averaged, 10 Hz low-pass, differentiated); ARX,\n"
          "Hammerstein, H-W and P-H-W identified with the paper's orders (na = 3, nb = 2, nk = 8,\n"
          "r = r1 = 3) by the output-error and the paper's methods and validated by free-run simulation;\n"
          "also the online estimates alone (recursive estimator, one pass, no refinement). The GIL is\n"
          "released during the computation.\n\n"
          "Parameters\n----------\nparameters : Parameters, optional\n    The plant; None: ``default_parameters()``.\n"
          "method : {'output_error', 'paper'}, optional\n    Whose results go to the top-level ``mse``, ``models``, ``params``.\n"
          "robustness : bool, optional\n"
          "    Also validate on the eight further trajectories of ``bonl_demo``'s robustness check.\n\n"
          "Returns\n-------\ndict\n"
          "    ``mse`` {'ARX', 'Hammerstein', 'HW', 'PHW'} validation MSE [(rad/s)^2] of ``method``;\n"
          "    ``models`` the same keys, the identified models (bonl.ARX, bonl.Hammerstein, ...);\n"
          "    ``params`` their parameters by name (lists); ``method``;\n"
          "    ``methods`` {'output_error', 'paper'} -> {``mse``, ``models``, ``params``, ``simulated``};\n"
          "    ``online`` {'output_error', 'paper'} -> the online estimates' validation MSE by model;\n"
          "    ``identification`` and ``validation`` records: ``time`` [s], ``input`` [V], ``velocity``\n"
          "    [rad/s] (what the models are fitted on), ``true_velocity`` [rad/s], ``angle`` [rad], ``run``\n"
          "    (min/max position, end stop, CVODE steps); the validation record also has ``simulated``\n"
          "    {'output_error', 'paper'} -> {'ARX': array, ...}, the models' free-run velocities;\n"
          "    ``parameters``; ``seconds`` (wall time of each stage); with ``robustness``, ``robustness``:\n"
          "    one {'output_error': mse, 'paper': mse} per trajectory.\n\n"
          "Raises\n------\nValueError\n    For non-physical parameters or an unknown method.");

  sub.attr("__all__") =
      py::make_tuple("Parameters", "default_parameters", "small_parameters", "Command", "excitation", "simulate",
                     "initial_state", "derivative", "low_pass", "differentiate", "experiment");

  // Make `from bonl._bonl.plant import *` and `import bonl._bonl.plant.excitation` work: an
  // extension's submodules are attributes, not importable modules, until sys.modules knows them.
  py::dict modules = py::module_::import("sys").attr("modules");
  modules[sub.attr("__name__")] = sub;
  modules[sub.attr("excitation").attr("__name__")] = sub.attr("excitation");
}

}  // namespace bonl_python
