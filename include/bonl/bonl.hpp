#pragma once
// bonl: identification of block-oriented nonlinear (BONL) models, after Yan et al., "Nonlinear
// modeling and identification of the electro-hydraulic control system of an excavator arm using
// BONL model". Umbrella header.

#include "blocks.hpp"
#include "control.hpp"
#include "error.hpp"
#include "estimator.hpp"
#include "metrics.hpp"
#include "models.hpp"
#include "signals.hpp"
#include "version.hpp"
