#pragma once
// The three recursive estimation methods. Names are spelled the same in C++ (to_string,
// method_from_string), Python (method="...") and on the command line.

#include <stdexcept>
#include <string>

namespace bonl {

/// How the recursive estimator treats the models' unmeasured internal variables.
enum class Method {
  /// bonl's default: a recursive prediction-error method on the free-run (output) error. Per sample
  /// the model is simulated one step with the current estimate, its output's sensitivities to theta
  /// are propagated through each block, and one Gauss-Newton step is taken (docs/explanation/algorithm.md).
  /// Not biased by white output noise; exact on noise-free data.
  OutputError,
  /// The equation-error method: internal variables projected onto what the measured output allows
  /// (x = y for Hammerstein, x = q^-1(y) for H-W, x clipped to [y - c, y + c] for P-H-W), samples
  /// inside the backlash gap skipped, past w recomputed with the newest theta. ARX: least squares.
  /// Fast and linear, but output noise in the regressor biases it.
  EquationError,
  /// Paper eqs. (21)-(31) as written: internal variables from the model's own free run
  /// (a priori with theta(k-1) to build the regressor, a posteriori with theta(k) to store), and the
  /// backlash switching of eqs. (30)-(31) with sgn(dx) of eq. (26). Kept as the reference.
  Paper,
};

/// The name of a method, as Python, model files and the command line spell it ("output_error",
/// "equation_error", "paper").
/// \param method the method
/// \return the name, a string literal
inline const char* to_string(Method method) noexcept {
  switch (method) {
    case Method::OutputError: return "output_error";
    case Method::EquationError: return "equation_error";
    case Method::Paper: return "paper";
  }
  return "unknown";
}

/// The method named `name` ("output_error", "equation_error" or "paper"); std::invalid_argument
/// naming the choices otherwise.
/// \param name the method's name
/// \return the method
inline Method method_from_string(const std::string& name) {
  for (Method method : {Method::OutputError, Method::EquationError, Method::Paper}) {
    if (name == to_string(method)) return method;
  }
  throw std::invalid_argument("bonl: method must be 'output_error', 'equation_error' or 'paper', got '" + name + "'");
}

}  // namespace bonl
