#pragma once
// The building blocks of the block-oriented models: input two-segment polynomial, play operators and the
// Prandtl-Ishlinskii input (input hysteresis), linear dynamic block with pure delay, output polynomial and backlash.

#include "blocks/backlash.hpp"
#include "blocks/linear_block.hpp"
#include "blocks/output_polynomial.hpp"
#include "blocks/play_operators.hpp"
#include "blocks/prandtl_ishlinskii_input.hpp"
#include "blocks/two_segment_polynomial.hpp"
