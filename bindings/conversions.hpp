#pragma once
// numpy in, numpy out: what every binding file shares. Arrays of real numbers (bool, integer or
// floating dtype), of any stride and byte order, and plain sequences of real numbers are accepted and
// converted once to float64 (the caller's array is never written to); anything else is a ValueError
// that names the argument: None, strings, bytes, complex, datetime, structured dtypes, object arrays
// holding anything but real numbers, masked arrays with masked entries, and arrays that are not 1-D.
// The checks are the library's (bonl/detail/validate.hpp): std::invalid_argument "bonl: ...", which
// pybind11 raises as ValueError.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/typing.h>

#include <Eigen/Core>
#include <bonl/detail/validate.hpp>
#include <cmath>
#include <string>
#include <utility>

namespace bonl_python {
namespace py = pybind11;

/// A 1-D float64 array, as functions return arrays of samples (the stubs show
/// numpy.typing.NDArray[numpy.float64], not Eigen's 2-D "[m, 1]").
using Vector = py::array_t<double>;

inline bool accepts_any(PyObject*) { return true; }

/// A Python object taken as it is, to be checked by one of the conversions below (whose messages name
/// the argument), and shown in signatures and stubs as Hint::text: what the argument accepts.
template <class Hint>
class Typed : public py::object {
 public:
  PYBIND11_OBJECT_DEFAULT(Typed, py::object, accepts_any)
};

/// `using Name = Typed<...>` shown as `hint`, a string literal.
#define BONL_PYTHON_TYPED(Name, hint)          \
  struct Name##Hint {                          \
    static constexpr const char text[] = hint; \
  };                                           \
  using Name = ::bonl_python::Typed<Name##Hint>

/// A 1-D array of real numbers: to_vector / to_float64_array check it.
BONL_PYTHON_TYPED(ArrayLike, "numpy.typing.ArrayLike");
/// A real number: to_scalar checks it.
BONL_PYTHON_TYPED(Real, "float");
/// Two real numbers, (u0, y0) or (min, max).
BONL_PYTHON_TYPED(RealPair, "tuple[float, float]");
/// A record (u, y), or the measured past (u_past, y_past).
BONL_PYTHON_TYPED(Record, "tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike]");
/// Several records [(u1, y1), (u2, y2), ...].
BONL_PYTHON_TYPED(RecordList, "collections.abc.Sequence[tuple[numpy.typing.ArrayLike, numpy.typing.ArrayLike]]");

/// The name of an object's type, for messages.
inline std::string type_name(const py::handle& object) { return py::str(py::type::handle_of(object).attr("__name__")); }

/// True for the numpy dtype kinds whose values are real numbers: bool, signed and unsigned integers,
/// floating point.
inline bool is_real_kind(char kind) { return kind == 'b' || kind == 'i' || kind == 'u' || kind == 'f'; }

/// numbers.Real: int, float, bool, numpy's real scalars, fractions.Fraction, ... (looked up on each
/// call: a cached Python object in a C++ static would outlive the interpreter).
inline py::object real_number_type() { return py::module_::import("numbers").attr("Real"); }

/// `object` as a 1-D, C-contiguous float64 array; a new array unless it is one already.
/// ValueError, naming `name`, for anything that is not a 1-D array of real numbers.
inline py::array_t<double, py::array::c_style> to_float64_array(const py::handle& object, const char* name) {
  using bonl::detail::require;
  const std::string prefix(name);
  const std::string expected = prefix + " must be a 1-D array of real numbers";
  require(!object.is_none(), expected + ", got None");
  require(!py::isinstance<py::str>(object) && !py::isinstance<py::bytes>(object),
          expected + ", got " + type_name(object));
  const py::module_ numpy = py::module_::import("numpy");
  require(!(py::isinstance(object, numpy.attr("ma").attr("MaskedArray")) &&
            numpy.attr("ma").attr("is_masked")(object).cast<bool>()),
          prefix + " is a masked array with masked entries: fill them first (numpy.ma.filled)");
  py::array array;
  try {
    array = py::array::ensure(object);  // numpy.asarray: no copy for an ndarray
  } catch (const py::error_already_set&) {
    array = py::array();
  }
  if (!array) PyErr_Clear();
  require(static_cast<bool>(array), expected + ", got " + type_name(object));
  // ndim 0: a number, or an object numpy cannot see as a sequence (dict, set, generator).
  require(array.ndim() != 0, expected + ", got a single " + type_name(object));
  require(array.ndim() == 1,
          prefix + " must be 1-D, got an array with " + std::to_string(array.ndim()) + " dimensions");
  const char kind = array.dtype().kind();
  require(kind != 'c', prefix + " must be real, got a complex array (dtype " + std::string(py::str(array.dtype())) +
                           "): pass its .real or abs() explicitly");
  if (kind == 'O') {
    // numpy would convert str elements by parsing them, None to NaN and complex numbers by dropping
    // their imaginary part: every element must be a real number instead.
    const py::object real = real_number_type();
    for (py::ssize_t i = 0; i < array.shape(0); ++i) {
      const py::object item = array.attr("__getitem__")(i);
      require(py::isinstance(item, real),
              prefix + "[" + std::to_string(i) + "] must be a real number, got " + type_name(item));
    }
  } else {
    require(is_real_kind(kind), expected + ", got an array of dtype " + std::string(py::str(array.dtype())));
  }
  using Float64 = py::array_t<double, py::array::c_style | py::array::forcecast>;
  Float64 converted;
  try {
    converted = Float64::ensure(array);
  } catch (const py::error_already_set&) {
    converted = Float64();
  }
  if (!converted) PyErr_Clear();  // e.g. an object array holding an int too large for a double
  require(static_cast<bool>(converted), expected + " that a float64 can hold");
  return converted;
}

inline Eigen::VectorXd to_vector(const py::handle& object, const char* name) {
  const auto array = to_float64_array(object, name);
  return Eigen::Map<const Eigen::VectorXd>(array.data(), array.shape(0));
}

/// A real number (numbers.Real, or a 0-d array of a real dtype) as a double; ValueError naming
/// `name` for None, strings, complex numbers, sequences and anything else. Finiteness and range are
/// the C++ side's to check.
inline double to_scalar(const py::handle& object, const std::string& name) {
  bool real = py::isinstance(object, real_number_type());
  if (!real && py::isinstance<py::array>(object)) {
    const auto array = py::reinterpret_borrow<py::array>(object);
    real = array.ndim() == 0 && is_real_kind(array.dtype().kind());
  }
  bonl::detail::require(real, name + " must be a real number, got " + (object.is_none() ? "None" : type_name(object)));
  double value = 0.0;
  std::string overflow;
  try {
    value = py::float_(py::reinterpret_borrow<py::object>(object)).cast<double>();
  } catch (const py::error_already_set& e) {  // an int beyond double's range
    overflow = e.what();
  }
  bonl::detail::require(overflow.empty(), name + " must be a real number that a float64 can hold: " + overflow);
  return value;
}

/// Eigen vector -> 1-D numpy float64 array without copying the data (the array owns the moved vector).
inline Vector to_numpy(Eigen::VectorXd&& vector) { return Vector(py::cast(std::move(vector))); }
inline Vector to_numpy(const Eigen::VectorXd& vector) { return to_numpy(Eigen::VectorXd(vector)); }

}  // namespace bonl_python

namespace pybind11::detail {
template <class Hint>
struct handle_type_name<bonl_python::Typed<Hint>> {
  static constexpr auto name = const_name(Hint::text);
};
}  // namespace pybind11::detail
