#pragma once
// Inverse models for control: per sample, the command that makes an identified model follow
// a reference output. The blocks' inverses (backlash, output polynomial, linear block with ZPETC where B
// is not minimum phase, two-segment input polynomial, Prandtl-Ishlinskii input hysteresis) and
// InverseModel<Model>, which composes them for ARX, Hammerstein, H-W, P-H-W, Wiener and the
// Prandtl-Ishlinskii Hammerstein model; AdaptiveInverse<Model>, the online estimator and the inverse
// together, re-derived as the estimate changes. docs/how-to/control.md explains each.

#include "control/adaptive_inverse.hpp"
#include "control/backlash_inverse.hpp"
#include "control/input_polynomial_inverse.hpp"
#include "control/inverse_model.hpp"
#include "control/inverse_status.hpp"
#include "control/linear_inverse.hpp"
#include "control/output_polynomial_inverse.hpp"
#include "control/prandtl_ishlinskii_inverse.hpp"
