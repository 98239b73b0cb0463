#pragma once
// Errors bonl reports. Bad input (wrong orders, lengths, non-finite samples, settings out of range)
// is std::invalid_argument; numerical trouble found while computing is bonl::NumericalError.

#include <stdexcept>

namespace bonl {

/// Numerical trouble detected at run time: a diverging simulation, a covariance that lost
/// positiveness, a non-finite intermediate result. The message says where it happened.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace bonl
