#pragma once
// What an inverse reports with each command: a set of flags, Exact (none) when the command makes the
// model follow the reference. A per-sample step is noexcept and returns its status instead of
// throwing; a refused sample (RejectedNonFinite, RejectedShortPreview, RejectedOverflow) leaves the
// inverse untouched.

#include <cstdint>

namespace bonl::control {

/// What an inverse reports with each command: a set of flags (combine them with |, test them with
/// has()), Exact when there is none. A per-sample step is noexcept and returns its status instead of
/// throwing; a rejected sample (rejected()) leaves the inverse untouched.
enum class InverseStatus : std::uint8_t {
  Exact = 0,                  ///< the command makes the model reach the reference (within rounding)
  Saturated = 1,              ///< the command is at the end of its range (or of the input block's
                              ///< monotone branch) and gives less than the reference asks
  DeadBand = 2,               ///< the reference asks for a w between the input polynomial's two segments at
                              ///< u = 0 (f_0 and g_0), which no command reaches: the command is 0
  OutOfRange = 4,             ///< the output polynomial's monotone branch through 0 does not reach the
                              ///< reference: its end is used
  RejectedNonFinite = 8,      ///< a reference in the window was NaN or infinite; the inverse is untouched
  RejectedShortPreview = 16,  ///< the reference window is shorter than window_size(); the inverse is untouched
  RejectedOverflow = 32,      ///< the reference is so large that the inverse's arithmetic left the finite
                              ///< numbers (e.g. 1e308 through a model that amplifies it); the inverse is untouched
};

/// The flags of a and of b together.
/// \param a a status
/// \param b another
/// \return the union of their flags
constexpr InverseStatus operator|(InverseStatus a, InverseStatus b) noexcept {
  return static_cast<InverseStatus>(static_cast<std::uint8_t>(a) | static_cast<std::uint8_t>(b));
}
/// Adds b's flags to a; returns a.
/// \param a the status to add to
/// \param b the flags to add
/// \return a
constexpr InverseStatus& operator|=(InverseStatus& a, InverseStatus b) noexcept { return a = a | b; }
/// Does `status` carry every flag of `flags`? has(status, InverseStatus::Exact) is status == Exact.
/// \param status the status to test
/// \param flags the flags it must carry
/// \return true when it carries them all
constexpr bool has(InverseStatus status, InverseStatus flags) noexcept {
  if (flags == InverseStatus::Exact) return status == InverseStatus::Exact;
  return (static_cast<std::uint8_t>(status) & static_cast<std::uint8_t>(flags)) == static_cast<std::uint8_t>(flags);
}
/// A refused sample: the inverse did not advance and the command is not meaningful.
/// \param status a step's status
/// \return true for a refused sample (a Rejected* flag)
constexpr bool rejected(InverseStatus status) noexcept {
  return (static_cast<std::uint8_t>(status) & (static_cast<std::uint8_t>(InverseStatus::RejectedNonFinite) |
                                               static_cast<std::uint8_t>(InverseStatus::RejectedShortPreview) |
                                               static_cast<std::uint8_t>(InverseStatus::RejectedOverflow))) != 0;
}

/// One value an inverse produced and what it reports about it.
template <typename Scalar>
struct InverseStep {
  Scalar value;          ///< the command u(k) (InverseModel), or the block's input (a block inverse)
  InverseStatus status;  ///< Exact, or the flags that say where and why it is not
};

}  // namespace bonl::control
