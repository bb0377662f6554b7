// The machine's ceiling for evaluating tapes: one multiply-add per clause per
// lane, over slots of BatchEvaluator's lane count held in cache, compiled by
// Highway for every SIMD level and run at the best one — the same width the
// batch evaluator dispatches to, so the ratio of the two is fair.
#pragma once

#include <cstddef>

namespace zeroset::bench {

/// Runs `clauses` multiply-adds over 8 rotating slots of batch_lanes lanes.
void straight_line_fma(float* slots, std::size_t clauses);
void straight_line_fma(double* slots, std::size_t clauses);

}  // namespace zeroset::bench
