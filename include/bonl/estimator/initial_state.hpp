#pragma once
// Where a refinement after a state-initialisation window takes each record's state from: the
// window's measured outputs, as a protocol with that window starts its free run, or estimated with
// the parameters, as MATLAB's InitialCondition 'estimate' does.

namespace bonl {

/// How a refinement after a state-initialisation window (IdentifyOptions::initialisation_window) sets
/// each record's state at the window's end: from the window's measured outputs (Measured, the
/// default: the model is fitted the way a protocol with that window uses it), or with the window's
/// outputs that reach the state estimated beside the parameters (Estimated), for records that start
/// in motion under output noise: on an integrating plant the measured outputs' noise becomes a
/// velocity error at the start, and so a position offset for the rest of the free run, which a fit
/// from measured outputs bends its parameters to follow.
enum class InitialState { Measured, Estimated };

/// The name of an initial-state choice, as Python and the command line spell it: "measured",
/// "estimated".
/// \param state the choice
/// \return the name, a string literal
inline const char* to_string(InitialState state) { return state == InitialState::Estimated ? "estimated" : "measured"; }

}  // namespace bonl
