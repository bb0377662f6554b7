// BatchEvaluator: copying points in and values out around the lane loops.
#include "zeroset/expr/batch_evaluator.hpp"

#include <algorithm>

namespace zeroset {

template <class F>
BatchEvaluator<F>::BatchEvaluator(const Tape& tape) : tape_(&tape) {
    load_constants();
}

template <class F>
void BatchEvaluator<F>::rebind(const Tape& tape) {
    tape_ = &tape;
    load_constants();
}

/// Marks the bound tape's constant slots and its clauses' outputs: those
/// are all the slots besides x, y and z that its clauses read.
template <class F>
void BatchEvaluator<F>::load_constants() {
    const std::size_t slot_count = tape_->slot_count();
    if (is_constant_.size() < slot_count) {
        slots_.resize(slot_count * lanes);
        is_constant_.resize(slot_count, 0);
        constant_.resize(slot_count);
    }
    for (const Clause& c : tape_->clauses()) is_constant_[c.out] = 0;
    for (const auto& [s, value] : tape_->constants()) {
        is_constant_[s] = 1;
        constant_[s] = static_cast<F>(value);
    }
}

template <class F>
void BatchEvaluator<F>::evaluate(std::span<const F> x, std::span<const F> y, std::span<const F> z,
                                 std::span<F> out) {
    if (out.empty()) return;
    const Inputs in = inputs();
    for (std::size_t start = 0; start < out.size(); start += lanes) {
        const std::size_t count = std::min(lanes, out.size() - start);
        std::copy_n(x.data() + start, count, in.x);
        std::copy_n(y.data() + start, count, in.y);
        std::copy_n(z.data() + start, count, in.z);
        std::copy_n(evaluate_in_place().begin(), count, out.data() + start);
    }
}

// Every lane is computed even in a partial batch: the loop count stays a
// compile-time constant (clean SIMD), and stale lanes are simply not copied out.
template <class F>
std::span<const F, BatchEvaluator<F>::lanes> BatchEvaluator<F>::evaluate_in_place() {
    const std::uint32_t result = tape_->result_slot();
    if (is_constant_[result]) {
        // f is a constant: no clause runs, and the slot's lanes are free to
        // hold it (constant slots are read by broadcast).
        std::fill_n(slot(result), lanes, constant_[result]);
    } else {
        run_batch_lanes(tape_->clauses().data(), tape_->clauses().size(), slots_.data(), constants());
    }
    return std::span<const F, lanes>(slot(result), lanes);
}

template class BatchEvaluator<float>;
template class BatchEvaluator<double>;

}  // namespace zeroset
