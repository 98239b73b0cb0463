// bonl.plant.SteppingPlant and Measurement: the plant one sample at a time
// (bonl/plant/stepping_plant.hpp) from Python. A step is short (microseconds), so it keeps the GIL.

#include <pybind11/stl.h>

#include <bonl/plant/stepping_plant.hpp>

#include <cstdint>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "conversions.hpp"
#include "plant_arguments.hpp"

namespace bonl_python {

namespace plant = bonl::plant;

namespace {

/// The Measurement's fields, in order, with their docstrings: the attributes, to_dict and repr.
struct Field {
  const char* name;
  double plant::Measurement::*member;
  const char* doc;
};
const Field kFields[] = {
    {"time", &plant::Measurement::time, "float: t_k [s]."},
    {"measured_angle", &plant::Measurement::measured_angle,
     "float: pin_angle plus the sensor noise: what the inclinometer reads [rad]."},
    {"position", &plant::Measurement::position, "float: h, the piston position [m]."},
    {"velocity", &plant::Measurement::velocity, "float: v [m/s]."},
    {"head_pressure", &plant::Measurement::head_pressure, "float: p1 [Pa]."},
    {"rod_pressure", &plant::Measurement::rod_pressure, "float: p2 [Pa]."},
    {"spool", &plant::Measurement::spool, "float: xv, the spool opening [-]."},
    {"pilot", &plant::Measurement::pilot,
     "float: xc, the pilot stage's output held over the last command interval before t_k (0 before the\n"
     "first step) [-]: simulate's ``pilot[k - 1]`` under a command held over each sample."},
    {"head_flow", &plant::Measurement::head_flow, "float: Q1, into the head chamber [m^3/s]."},
    {"rod_flow", &plant::Measurement::rod_flow, "float: Q2, out of the rod chamber [m^3/s]."},
    {"joint_angle", &plant::Measurement::joint_angle, "float: theta [rad]."},
    {"joint_rate", &plant::Measurement::joint_rate, "float: dtheta/dt = v / r(h) [rad/s]."},
    {"pin_angle", &plant::Measurement::pin_angle, "float: theta_m = play(theta; delta / 2), noise-free [rad]."},
};

py::dict measurement_to_dict(const plant::Measurement& m) {
  py::dict d;
  for (const Field& f : kFields) d[f.name] = m.*(f.member);
  d["reached_end_stop"] = m.reached_end_stop;
  return d;
}

void bind_measurement(py::module_& sub) {
  py::class_<plant::Measurement> cls(sub, "Measurement",
                                     "The plant at one sample time t_k, as ``SteppingPlant.step`` returns it: the\n"
                                     "measured angle, and the true states for analysis (simulate's sample k).");
  for (const Field& f : kFields) cls.def_readonly(f.name, f.member, f.doc);
  cls.def_readonly("reached_end_stop", &plant::Measurement::reached_end_stop,
                   "bool: h left [0, L] at a command-grid point of the step that ended at t_k.")
      .def("to_dict", &measurement_to_dict, "Every field by name.\n\nReturns\n-------\ndict[str, float | bool]")
      .def("__repr__", [](const plant::Measurement& m) {
        return "Measurement(time=" + bonl::detail::format_number(m.time) +
               ", measured_angle=" + bonl::detail::format_number(m.measured_angle) +
               ", position=" + bonl::detail::format_number(m.position) + ")";
      });
}

const char* const kSteppingPlantDoc =
    R"doc(The plant advanced one sample per call: ``measurement = plant.step(command)``.

From rest at t = 0, ``step(V)`` holds the command V [V] over one sample (``sample_time``, on the
``command_rate`` grid), integrates with CVODE and returns the ``Measurement`` at the sample's end:
the commands V_0, V_1, ... give the measurements at t_1, t_2, ...; the one at t_0 is ``measurement``
after construction or ``reset()``. ``simulate`` under the same commands held over each sample
(``(values, sample_time)``) gives the same samples, sensor noise included: its sample k pairs the
state at t_k with the command V_k that follows it. simulate is a loop over the same integration.

Parameters
----------
parameters : Parameters, optional
    The plant; None: ``Parameters.excavator_20t()``.
sample_time, command_rate, rtol, atol, max_steps_per_interval, sensor_noise, noise_seed, initial_position, load
    As for ``simulate`` (which has ``duration`` too: a stepping plant runs as long as it is stepped),
    validated the same way.

Raises
------
ValueError
    For non-physical parameters or bad options, naming them.

Examples
--------
>>> from bonl import plant
>>> p = plant.SteppingPlant()
>>> start = p.measurement                  # at t = 0, from rest at mid-stroke
>>> m = p.step(3.0)                        # 3 V held for 0.01 s
>>> m.time, m.measured_angle               # doctest: +SKIP
(0.01, ...)
)doc";

const char* const kStepDoc = R"doc(Hold ``command`` over one sample and return the measurement at its end.

Parameters
----------
command : float
    V [V] on the 0-5 V scale (neutral 2.5 V).

Returns
-------
Measurement
    At ``time + sample_time``.

Raises
------
ValueError
    For a command that is not a finite real number, or a load that is not finite within the step;
    the plant is left as it was.
bonl.NumericalError
    When CVODE fails; the plant is then left failed (``RuntimeError`` until ``reset()``).)doc";

const char* const kResetDoc = R"doc(Back to rest at t = 0.

Parameters
----------
initial_position : float, optional
    h0 [m]; None: the plant's (the constructor's or the last reset's).
noise_seed : int, optional
    The sensor noise's seed; None: the plant's. The same seed and commands give the same measurements.

Returns
-------
Measurement
    At t = 0.

Raises
------
ValueError
    For a bad ``initial_position``; the plant is left as it was.)doc";

const char* const kSetParametersDoc = R"doc(Change the plant from the current sample on, keeping its state.

As a machine changes in service (the oil warms and its bulk modulus drops, the pilot valve wears):
the next ``step`` runs with ``parameters`` from the state the plant is in (position, velocity,
pressures, spool, the hysteresis' and the backlash's memories, the noise sequence). Later ``reset()``\s
keep the new parameters.

Parameters
----------
parameters : Parameters
    The new parameters. The linkage's geometry (``stroke``, ``pivot_to_rod_pin``,
    ``pivot_to_base_pin``, ``retracted_length``) must stay as it is.

Raises
------
ValueError
    For non-physical parameters or a changed geometry, naming them; the plant is left as it was.)doc";

}  // namespace

void bind_plant_stepping(py::module_& sub) {
  bind_measurement(sub);
  py::class_<plant::SteppingPlant>(sub, "SteppingPlant", kSteppingPlantDoc)
      .def(py::init([](const ParametersArgument& parameters, double sample_time, double command_rate, double rtol,
                       const ToleranceArgument& atol, long max_steps_per_interval, bool sensor_noise,
                       std::uint64_t noise_seed, const PositionArgument& initial_position, const LoadArgument& load) {
             bool calls_python = false;
             return plant::SteppingPlant(
                 parameters_argument(parameters),
                 simulation_options(sample_time, command_rate, rtol, atol, max_steps_per_interval, sensor_noise,
                                    noise_seed, initial_position, load, calls_python));
           }),
           py::arg("parameters") = py::none(), py::kw_only(), py::arg("sample_time") = 0.01,
           py::arg("command_rate") = 1000.0, py::arg("rtol") = 1e-6, py::arg("atol") = py::none(),
           py::arg("max_steps_per_interval") = 5000L, py::arg("sensor_noise") = true,
           py::arg("noise_seed") = std::uint64_t{1}, py::arg("initial_position") = py::none(),
           py::arg("load") = py::none())
      .def(
          "step",
          [](plant::SteppingPlant& self, const Real& command) { return self.step(to_scalar(command, "command")); },
          py::arg("command"), kStepDoc)
      .def(
          "reset",
          [](plant::SteppingPlant& self, const PositionArgument& initial_position,
             std::optional<std::uint64_t> noise_seed) {
            if (initial_position.is_none() && !noise_seed) return self.reset();
            return self.reset(initial_position.is_none() ? self.options().initial_position
                                                         : initial_position_argument(initial_position),
                              noise_seed.value_or(self.options().noise_seed));
          },
          py::arg("initial_position") = py::none(), py::arg("noise_seed") = py::none(), kResetDoc)
      .def(
          "set_parameters",
          [](plant::SteppingPlant& self, const ParametersArgument& parameters) {
            self.set_parameters(parameters_argument(parameters));
          },
          py::arg("parameters"), kSetParametersDoc)
      .def_property_readonly(
          "measurement", [](const plant::SteppingPlant& self) { return self.measurement(); },
          "Measurement: the latest, at ``time`` (a copy).")
      .def_property_readonly("time", &plant::SteppingPlant::time, "float: t_k, the latest measurement's time [s].")
      .def_property_readonly("steps", &plant::SteppingPlant::steps,
                             "int: CVODE's internal steps since the start or reset.")
      .def_property_readonly(
          "sample_time", [](const plant::SteppingPlant& self) { return self.options().sample_time; },
          "float: the time one step advances [s].")
      .def_property_readonly(
          "parameters", [](const plant::SteppingPlant& self) { return self.parameters(); },
          "Parameters: a copy of the plant's parameters.")
      .def("__repr__", [](const plant::SteppingPlant& self) {
        return "SteppingPlant(time=" + bonl::detail::format_number(self.time()) +
               ", sample_time=" + bonl::detail::format_number(self.options().sample_time) + ")";
      });
}

}  // namespace bonl_python
