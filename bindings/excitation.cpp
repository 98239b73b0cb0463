// bonl.plant.Command and the submodule bonl.plant.excitation: command signals V(t) for the plant,
// evaluated in C++ (bonl/plant/excitation.hpp) or wrapping a Python callable.

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <bonl/plant/excitation.hpp>

#include <cstdint>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "conversions.hpp"
#include "plant_arguments.hpp"

namespace bonl_python {

namespace plant = bonl::plant;

namespace {

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
    return to_scalar(value, "the value of " + name + "(t) at t = " + bonl::detail::format_number(t));
  };
  std::string description = "python callable";
  try {
    description = std::string(py::repr(callable));
  } catch (const py::error_already_set&) {
  }
  return PyCommand{std::move(function), std::move(description), true};
}

}  // namespace

/// A command from what simulate accepts: a Command, a Python callable of time, or a (values, ts)
/// pair held between samples (excitation.sampled). TypeError for anything else.
PyCommand command_argument(const py::object& object, const char* name) {
  if (py::isinstance<PyCommand>(object)) return object.cast<PyCommand>();
  if (py::isinstance<py::tuple>(object) && py::len(object) == 2) {
    const py::tuple pair = object.cast<py::tuple>();
    const std::string values_name = std::string(name) + "[0] (values)";
    const Eigen::VectorXd values = to_vector(pair[0], values_name.c_str());
    bonl::detail::require_finite(values, values_name.c_str());
    const double ts = to_scalar(pair[1], std::string(name) + "[1] (ts)");
    std::ostringstream description;
    description << "sampled(" << values.size() << " values, ts=" << ts << ")";
    return cpp_command(plant::excitation::sampled(values, ts), description.str());
  }
  if (PyCallable_Check(object.ptr())) return python_command(object.cast<py::function>(), name);
  throw py::type_error("bonl: " + std::string(name) +
                       " must be a bonl.plant.Command, a callable f(t) -> float or a (values, ts) pair, got " +
                       std::string(py::str(py::type::handle_of(object).attr("__name__"))));
}

namespace {}  // namespace

void bind_excitation(py::module_& sub) {
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
          [](const PyCommand& c, const ArrayLike& t) {
            const Eigen::VectorXd times = to_vector(t, "t");
            bonl::detail::require_finite(times, "t");
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
      [](const ArrayLike& values, double ts, double t0) {
        const Eigen::VectorXd v = to_vector(values, "values");
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

}  // namespace bonl_python
