// bonl.plant.simulate, initial_state and derivative: the CVODE plant (bonl/plant/simulator.hpp) from
// Python, with its Trajectory (numpy arrays); and the options it shares with SteppingPlant.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <bonl/plant/simulator.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "conversions.hpp"
#include "plant_arguments.hpp"

namespace bonl_python {

namespace plant = bonl::plant;

double initial_position_argument(const py::object& initial_position) {
  if (initial_position.is_none()) return -1.0;
  const double h0 = to_scalar(initial_position, "initial_position");
  bonl::detail::require(
      std::isfinite(h0) && h0 >= 0.0,
      "initial_position must be finite and >= 0 (None means mid-stroke), got " + bonl::detail::format_number(h0));
  return h0;
}

plant::SimulationOptions simulation_options(double sample_time, double command_rate, double rtol,
                                            const py::object& atol, long max_steps_per_interval, bool sensor_noise,
                                            std::uint64_t noise_seed, const py::object& initial_position,
                                            const py::object& load, bool& calls_python) {
  plant::SimulationOptions options;
  options.sample_time = sample_time;
  options.command_rate = command_rate;
  options.tolerances.relative = rtol;
  options.tolerances.max_steps_per_interval = max_steps_per_interval;
  if (!atol.is_none()) {
    bonl::detail::require(
        py::isinstance<py::dict>(atol),
        "atol must be a dict {state: tolerance} (position, velocity, pressure, spool), got " + type_name(atol));
    for (const auto& item : atol.cast<py::dict>()) {
      const auto key = std::string(py::str(item.first));
      const double value = to_scalar(item.second, "atol['" + key + "']");
      if (key == "position")
        options.tolerances.absolute_position = value;
      else if (key == "velocity")
        options.tolerances.absolute_velocity = value;
      else if (key == "pressure")
        options.tolerances.absolute_pressure = value;
      else if (key == "spool")
        options.tolerances.absolute_spool = value;
      else
        bonl::detail::fail("atol: unknown key '" + key + "' (position, velocity, pressure, spool)");
    }
  }
  options.sensor_noise = sensor_noise;
  options.noise_seed = noise_seed;
  options.initial_position = initial_position_argument(initial_position);
  if (!load.is_none()) {
    const PyCommand l = command_argument(load, "load");
    calls_python = calls_python || l.calls_python;
    options.load = l.function;
  }
  return options;
}

namespace {

const char* const kStateOrder = "(h [m], v [m/s], p1 [Pa], p2 [Pa], xv [-])";

Vector state_to_numpy(const plant::State& s) {
  Eigen::VectorXd x(5);
  x << s.position, s.velocity, s.head_pressure, s.rod_pressure, s.spool;
  return to_numpy(std::move(x));
}

/// The Trajectory's arrays, in order, with their docstrings: the attributes and to_dict.
struct TrajectoryField {
  const char* name;
  Eigen::VectorXd plant::Trajectory::*member;
  const char* doc;
};
const TrajectoryField kTrajectoryFields[] = {
    {"time", &plant::Trajectory::time, "numpy.ndarray: t_k = k * sample_time [s]."},
    {"command", &plant::Trajectory::command, "numpy.ndarray: V, as held on the command grid [V]."},
    {"input", &plant::Trajectory::input, "numpy.ndarray: u = V - V0, the identification input [V]."},
    {"position", &plant::Trajectory::position, "numpy.ndarray: h [m]."},
    {"velocity", &plant::Trajectory::velocity, "numpy.ndarray: v [m/s]."},
    {"head_pressure", &plant::Trajectory::head_pressure, "numpy.ndarray: p1 [Pa]."},
    {"rod_pressure", &plant::Trajectory::rod_pressure, "numpy.ndarray: p2 [Pa]."},
    {"spool", &plant::Trajectory::spool, "numpy.ndarray: xv [-]."},
    {"pilot", &plant::Trajectory::pilot, "numpy.ndarray: xc, the pilot stage's output (after its hysteresis) [-]."},
    {"head_flow", &plant::Trajectory::head_flow, "numpy.ndarray: Q1, into the head chamber [m^3/s]."},
    {"rod_flow", &plant::Trajectory::rod_flow, "numpy.ndarray: Q2, out of the rod chamber [m^3/s]."},
    {"joint_angle", &plant::Trajectory::joint_angle, "numpy.ndarray: theta [rad]."},
    {"joint_rate", &plant::Trajectory::joint_rate, "numpy.ndarray: dtheta/dt = v / r(h) [rad/s]."},
    {"pin_angle", &plant::Trajectory::pin_angle, "numpy.ndarray: theta_m = play(theta; delta / 2), noise-free [rad]."},
    {"measured_angle", &plant::Trajectory::measured_angle, "numpy.ndarray: theta_m + sensor noise [rad]."},
};

/// One array of a Trajectory, as a float64 array that views the Trajectory's memory (no copy; the
/// array keeps the Trajectory alive).
Vector trajectory_array(const py::object& self, Eigen::VectorXd plant::Trajectory::*member) {
  const Eigen::VectorXd& values = self.cast<const plant::Trajectory&>().*member;
  return Vector(static_cast<py::ssize_t>(values.size()), values.data(), self);
}

void bind_trajectory(py::module_& sub) {
  py::class_<plant::Trajectory> cls(sub, "Trajectory",
                                    "What ``simulate`` returns: float64 arrays on the output grid, sample k at "
                                    "``time[k] = k * sample_time``,\nand the run's summary (``min_position``, "
                                    "``max_position``, ``reached_end_stop``, ``steps``).");
  for (const TrajectoryField& field : kTrajectoryFields) {
    const auto member = field.member;
    cls.def_property_readonly(
        field.name, [member](const py::object& self) { return trajectory_array(self, member); }, field.doc);
  }
  cls.def_readonly("min_position", &plant::Trajectory::min_position,
                   "float: smallest h reached on the command grid [m].")
      .def_readonly("max_position", &plant::Trajectory::max_position,
                    "float: largest h reached on the command grid [m].")
      .def_readonly("reached_end_stop", &plant::Trajectory::reached_end_stop,
                    "bool: h left [0, L] at some point of the command grid.")
      .def_readonly("steps", &plant::Trajectory::steps, "int: CVODE's internal steps.")
      .def(
          "to_dict",
          [](const py::object& self) {
            py::typing::Dict<py::str, py::typing::Union<Vector, py::float_, py::bool_, py::int_>> d;
            for (const TrajectoryField& field : kTrajectoryFields) d[field.name] = trajectory_array(self, field.member);
            const auto& t = self.cast<const plant::Trajectory&>();
            d["min_position"] = t.min_position;
            d["max_position"] = t.max_position;
            d["reached_end_stop"] = t.reached_end_stop;
            d["steps"] = t.steps;
            return d;
          },
          "Every field by name (the arrays view this Trajectory's).\n\nReturns\n-------\n"
          "dict[str, numpy.ndarray | float | bool | int]")
      .def("__len__", [](const plant::Trajectory& t) { return t.time.size(); })
      .def("__repr__", [](const plant::Trajectory& t) {
        return "Trajectory(" + std::to_string(t.time.size()) +
               " samples, reached_end_stop=" + (t.reached_end_stop ? "True" : "False") + ")";
      });
}

plant::Trajectory simulate(const CommandArgument& command, const ParametersArgument& parameters, double duration,
                           double sample_time, double command_rate, double rtol, const ToleranceArgument& atol,
                           long max_steps_per_interval, bool sensor_noise, std::uint64_t noise_seed,
                           const PositionArgument& initial_position, const LoadArgument& load) {
  const plant::Parameters p = parameters_argument(parameters);
  const PyCommand c = command_argument(command, "command");
  bool calls_python = c.calls_python;
  plant::SimulationOptions options = simulation_options(sample_time, command_rate, rtol, atol, max_steps_per_interval,
                                                        sensor_noise, noise_seed, initial_position, load, calls_python);
  options.duration = duration;
  plant::Trajectory trajectory;
  if (calls_python) {
    trajectory = plant::simulate(p, c.function, options);
  } else {
    py::gil_scoped_release release;
    trajectory = plant::simulate(p, c.function, options);
  }
  return trajectory;
}

}  // namespace

void bind_plant_simulate(py::module_& sub) {
  bind_trajectory(sub);
  sub.def("simulate", &simulate, py::arg("command"), py::arg("parameters") = py::none(), py::kw_only(),
          py::arg("duration") = 50.0, py::arg("sample_time") = 0.01, py::arg("command_rate") = 1000.0,
          py::arg("rtol") = 1e-6, py::arg("atol") = py::none(), py::arg("max_steps_per_interval") = 5000L,
          py::arg("sensor_noise") = true, py::arg("noise_seed") = std::uint64_t{1},
          py::arg("initial_position") = py::none(), py::arg("load") = py::none(),
          "Integrate the plant under a command with CVODE (BDF, Newton, dense solver).\n\n"
          "The command is sampled and held on the command grid (``command_rate``), where the pilot\n"
          "hysteresis and the pin backlash (play operators) are evaluated; CVODE stops at every output\n"
          "sample, so sample k depends only on the commands before ``time[k]`` (``SteppingPlant`` steps\n"
          "the same integration). The GIL is released unless the command or the load is a Python callable.\n\n"
          "Parameters\n----------\n"
          "command : Command or callable or tuple\n"
          "    V(t) [V]: a ``Command`` (``bonl.plant.excitation``), a Python callable f(t) -> float, or a\n"
          "    ``(values, ts)`` pair held between samples (``excitation.sampled``).\n"
          "parameters : Parameters, optional\n    The plant; None: ``Parameters.excavator_20t()``.\n"
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
          "Returns\n-------\nTrajectory\n"
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
      [](const ParametersArgument& parameters, double position) {
        const plant::Parameters p = parameters_argument(parameters);
        p.validate();
        bonl::detail::require_finite(position, "position");
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
      [](const ParametersArgument& parameters, const ArrayLike& state, double pilot, double load) {
        const plant::Parameters p = parameters_argument(parameters);
        p.validate();
        const Eigen::VectorXd x = to_vector(state, "state");
        bonl::detail::require(x.size() == 5, "state must have 5 entries " + std::string(kStateOrder) + ", got " +
                                                 std::to_string(x.size()));
        bonl::detail::require_finite(x, "state");
        bonl::detail::require_finite(pilot, "pilot");
        bonl::detail::require_finite(load, "load");
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
}

}  // namespace bonl_python
