#pragma once
// Argument checks shared by the public entry points. Each throws std::invalid_argument with a
// message that names the offending argument, so a caller knows what to fix.

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace bonl::detail {

/// A number for a message: shortest of fixed and scientific, up to 6 significant digits ("0.5", "-0.1",
/// "1e+22"), unlike std::to_string's "0.500000".
inline std::string format_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

/// Bad input: std::invalid_argument with the library's one prefix, "bonl: ".
[[noreturn]] inline void fail(const std::string& message) { throw std::invalid_argument("bonl: " + message); }

inline void require(bool condition, const std::string& message) {
  if (!condition) fail(message);
}

/// A number that must be finite: "<name> must be finite, got <value>".
inline void require_finite(double value, const std::string& name) {
  require(std::isfinite(value), name + " must be finite, got " + format_number(value));
}

/// Largest order (na, nb, nk, r, r1, a number of parameters) bonl accepts. Far beyond any
/// identification problem; it keeps sizes such as nk + nb + 1 or 2 (r + 1) + nb + na from
/// overflowing, and turns an absurd order into a clear error instead of std::bad_alloc.
inline constexpr Eigen::Index kMaxOrder = 1000000;

inline void require_order(Eigen::Index value, Eigen::Index minimum, const char* name) {
  require(value >= minimum,
          std::string(name) + " must be >= " + std::to_string(minimum) + ", got " + std::to_string(value));
  require(value <= kMaxOrder,
          std::string(name) + " must be <= " + std::to_string(kMaxOrder) + ", got " + std::to_string(value));
}

/// A compile-time order, when fixed, must equal the run-time one given to the constructor.
inline void require_matches_template(Eigen::Index value, int fixed, const char* name) {
  require(fixed == Eigen::Dynamic || value == fixed, std::string(name) + " = " + std::to_string(value) +
                                                         " does not match the compile-time order " +
                                                         std::to_string(fixed));
}

template <typename Derived>
void require_finite(const Eigen::DenseBase<Derived>& values, const char* name) {
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (!std::isfinite(static_cast<double>(values.derived().coeff(i)))) {
      throw std::invalid_argument("bonl: " + std::string(name) + " has a non-finite value at index " +
                                  std::to_string(i));
    }
  }
}

template <typename Derived>
void require_size(const Eigen::DenseBase<Derived>& values, Eigen::Index size, const char* name) {
  require(values.size() == size,
          std::string(name) + " must have " + std::to_string(size) + " entries, got " + std::to_string(values.size()));
}

/// The first index where `values` is 0 or not above the entry before it (strictly increasing, no 0:
/// a ParameterDescription's `increasing`, the Wiener-Hammerstein model's knots); -1 where there is none.
template <typename Derived>
Eigen::Index first_not_increasing_or_zero(const Eigen::DenseBase<Derived>& values) {
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    const auto value = values.derived().coeff(i);
    if (value == 0 || (i > 0 && !(values.derived().coeff(i - 1) < value))) return i;
  }
  return -1;
}

/// target = value, after checking that value has target's size and only finite entries. target may
/// be a block of a larger vector (a segment of theta).
template <typename Target, typename Value>
void assign_checked(Target&& target, const Eigen::MatrixBase<Value>& value, const char* name) {
  require_size(value, target.size(), name);
  require_finite(value, name);
  target = value;
}

template <typename A, typename B>
void require_same_length(const Eigen::DenseBase<A>& a, const char* a_name, const Eigen::DenseBase<B>& b,
                         const char* b_name) {
  require(a.size() == b.size(), std::string(a_name) + " and " + b_name + " must have the same length, got " +
                                    std::to_string(a.size()) + " and " + std::to_string(b.size()));
}

/// An identification record: u and y of equal length, longer than the number of parameters, finite.
template <typename U, typename Y>
void require_record(const Eigen::DenseBase<U>& u, const Eigen::DenseBase<Y>& y, Eigen::Index num_params) {
  require_same_length(u, "u", y, "y");
  require(u.size() > num_params, "the record must be longer than the number of parameters (" +
                                     std::to_string(num_params) + "), got " + std::to_string(u.size()) + " samples");
  require_finite(u, "u");
  require_finite(y, "y");
}

/// Adds two compile-time sizes; Eigen::Dynamic is absorbing.
constexpr int add_sizes(int a, int b) { return (a == Eigen::Dynamic || b == Eigen::Dynamic) ? Eigen::Dynamic : a + b; }

/// Number of coefficients of a degree-r polynomial (r + 1), Dynamic-aware.
constexpr int poly_size(int degree) { return degree == Eigen::Dynamic ? Eigen::Dynamic : degree + 1; }

}  // namespace bonl::detail
