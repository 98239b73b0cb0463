#pragma once
// Estimation: the recursive least-squares core, the forgetting schedule, the generic recursive
// estimator (MRLSA) over any model, output-error refinement and whole-record identification.

#include "estimator/best_linear_approximation.hpp"
#include "estimator/estimate_recursively.hpp"
#include "estimator/excitation.hpp"
#include "estimator/forgetting_schedule.hpp"
#include "estimator/identify.hpp"
#include "estimator/identify_options.hpp"
#include "estimator/method.hpp"
#include "estimator/nonlinear_feedback_start.hpp"
#include "estimator/output_error.hpp"
#include "estimator/play_thresholds.hpp"
#include "estimator/record_view.hpp"
#include "estimator/recursive_estimator.hpp"
#include "estimator/rls.hpp"
#include "estimator/select.hpp"
#include "estimator/structure_from_data.hpp"
#include "estimator/wiener_hammerstein_start.hpp"
