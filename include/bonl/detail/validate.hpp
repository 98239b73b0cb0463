#pragma once
// Argument checks shared by the public entry points. Each throws std::invalid_argument with a
// message that names the offending argument, so a caller knows what to fix.

#include <Eigen/Core>
#include <cmath>
#include <stdexcept>
#include <string>

namespace bonl::detail {

inline void require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument("bonl: " + message);
}

/// Largest order (na, nb, nk, r, r1, a number of parameters) bonl accepts. Far beyond any
/// identification problem; it keeps sizes such as nk + nb + 1 or 2 (r + 1) + nb + na from
/// overflowing, and turns an absurd order into a clear error instead of std::bad_alloc.
inline constexpr Eigen::Index kMaxOrder = 1000000;

inline void require_order(Eigen::Index value, Eigen::Index minimum, const char* name) {
  require(value >= minimum, std::string(name) + " must be >= " + std::to_string(minimum) + ", got " +
                                std::to_string(value));
  require(value <= kMaxOrder, std::string(name) + " must be <= " + std::to_string(kMaxOrder) + ", got " +
                                  std::to_string(value));
}

/// A compile-time order, when fixed, must equal the run-time one given to the constructor.
inline void require_matches_template(Eigen::Index value, int fixed, const char* name) {
  require(fixed == Eigen::Dynamic || value == fixed,
          std::string(name) + " = " + std::to_string(value) +
              " does not match the compile-time order " + std::to_string(fixed));
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
  require(values.size() == size, std::string(name) + " must have " + std::to_string(size) +
                                     " entries, got " + std::to_string(values.size()));
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
  require(a.size() == b.size(), std::string(a_name) + " and " + b_name +
                                    " must have the same length, got " + std::to_string(a.size()) +
                                    " and " + std::to_string(b.size()));
}

/// Adds two compile-time sizes; Eigen::Dynamic is absorbing.
constexpr int add_sizes(int a, int b) { return (a == Eigen::Dynamic || b == Eigen::Dynamic) ? Eigen::Dynamic : a + b; }

/// Number of coefficients of a degree-r polynomial (r + 1), Dynamic-aware.
constexpr int poly_size(int degree) { return degree == Eigen::Dynamic ? Eigen::Dynamic : degree + 1; }

}  // namespace bonl::detail
