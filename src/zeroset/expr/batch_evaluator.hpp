// BatchEvaluator<F>: f at many points per walk of the tape. Slots hold a
// fixed number of lanes in structure-of-arrays form, and each clause runs a
// SIMD loop over its lanes (expr/batch_lanes.hpp, at the CPU's best width)
// — so the interpretation cost (one op dispatch per clause) is paid once per
// `lanes` points instead of once per point.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "zeroset/expr/batch_lanes.hpp"
#include "zeroset/expr/tape.hpp"

namespace zeroset {

template <class F>
class BatchEvaluator {
public:
    static constexpr std::size_t lanes = batch_lanes;

    explicit BatchEvaluator(const Tape& tape);

    /// Switches to the original tape or one pruned from it, as Evaluator::rebind.
    void rebind(const Tape& tape);

    /// out[i] = f(x[i], y[i], z[i]) for every i; all spans of equal length.
    void evaluate(std::span<const F> x, std::span<const F> y, std::span<const F> z, std::span<F> out);

private:
    void evaluate_lanes();
    void load_constants();
    F* slot(std::uint32_t s) { return slots_.data() + static_cast<std::size_t>(s) * lanes; }

    const Tape* tape_;
    std::vector<F> slots_;  // slot-major: slot s occupies [s·lanes, (s+1)·lanes)
    // Per slot: the constant its lanes hold, while `filled` says they still
    // do. Pruned tapes of one region often put the same constants in the
    // same slots, and a rebind then fills only what changed.
    std::vector<F> constant_;
    std::vector<std::uint8_t> filled_;
};

extern template class BatchEvaluator<float>;
extern template class BatchEvaluator<double>;

}  // namespace zeroset
