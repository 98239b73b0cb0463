#pragma once
// The experiment layer (bonl::experiment, the compiled library bonl::experiment): records measured
// on the simulated plant and the paper's experiment on them. Above the plant and the estimator.

#include "experiment/paper_experiment.hpp"
#include "experiment/records.hpp"
#include "experiment/tracking_experiment.hpp"
